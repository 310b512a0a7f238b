//! The runtime's side of the IPStack (the `openr-ipstack` crate): the net table objects
//! find (`openr_runtime_net_v1`), the run's network settings, and [`RuntimeHost`],
//! through which the stack queues replies to objects, reads the stick's settings files
//! and reports.
use std::ffi::{c_char, c_void};
use std::sync::{Arc, OnceLock};

use openr_ipstack::{EncodeFn, Net, NetOptions, Request};
use openr_sys::{EndpointId, Selector};

use crate::runtime::{Report, Runtime};

/// A run's network settings and its IPStack.
pub struct NetState {
    options: NetOptions,
    stack: OnceLock<&'static Net>,
}

impl NetState {
    /// The settings of a run, given before any object loads (the IPStack starts on first
    /// use and reads them then).
    pub fn new(options: NetOptions) -> NetState {
        NetState { options, stack: OnceLock::new() }
    }

    pub fn options(&self) -> &NetOptions {
        &self.options
    }
}

/// The calling thread's network settings (defaults outside a run): the TCP gateways of
/// Remote Processing use them without starting the IPStack.
pub fn options() -> NetOptions {
    Runtime::get().map(|rt| rt.net.options.clone()).unwrap_or_default()
}

/// The calling thread's IPStack, started on first use (its poll thread included); a
/// call outside any run gets a stack of its own, with the default settings.
pub fn net() -> &'static Net {
    static DETACHED: OnceLock<&'static Net> = OnceLock::new();
    let start = |options: &NetOptions, rt| Net::start(options, Arc::new(RuntimeHost(rt))).expect("start the IPStack (eventfd, its thread)");
    match Runtime::get() {
        Some(rt) => rt.net.stack.get_or_init(|| start(&rt.net.options, Some(rt))),
        None => DETACHED.get_or_init(|| start(&NetOptions::default(), None)),
    }
}

/// The stack's view of its runtime (none: replies are dropped, the stick's files are not
/// there, messages go to stderr).
pub struct RuntimeHost(pub Option<&'static Runtime>);

impl RuntimeHost {
    /// The calling thread's runtime's.
    pub fn current() -> RuntimeHost {
        RuntimeHost(Runtime::get())
    }
}

impl openr_ipstack::Report for RuntimeHost {
    fn warn(&self, msg: &str) {
        if let Some(rt) = self.0 {
            rt.diag.warn(msg);
        }
    }
    fn info(&self, line: &str) {
        match self.0 {
            Some(rt) => rt.diag.line(line),
            None => crate::runtime::PlainStderr.line(line),
        }
    }
    fn trace(&self, line: &str) {
        match self.0 {
            Some(rt) => rt.diag.report.line(line),
            None => crate::runtime::PlainStderr.line(line),
        }
    }
}

impl openr_ipstack::Host for RuntimeHost {
    fn send(&self, oid: usize, selector: Selector, message: Vec<u8>) {
        if let Some(rt) = self.0 {
            let _ = rt.send(oid, selector, message);
        }
    }
    fn read_stick(&self, path: &str) -> Option<String> {
        self.0?.ms.existing(path).and_then(|p| std::fs::read_to_string(p).ok())
    }
}

pub use openr_sys::openr_net_api as NetApi;

/// The table libantMCOOP / libERA201D1 find with `dlsym(RTLD_DEFAULT,
/// "openr_runtime_net_v1")`; exported by the `cargo-openr` binary (its build.rs).
/// Declared once in `openr-sys`; entries call the functions below and stop panics.
#[no_mangle]
#[used]
pub static openr_runtime_net_v1: NetApi = openr_sys::net_table!(crate::net, crate::host_api::panicked);

pub(crate) fn endpoint_protocol(endpoint: EndpointId) -> i32 {
    net().endpoint_protocol(endpoint)
}

pub(crate) unsafe fn submit(req: *const Request, blob: *mut c_void, size: usize, encode: EncodeFn, oid: *mut c_void, selector: Selector, sync: i32) -> i32 {
    // SAFETY: the caller's (libantMCOOP's) pointers, as the table's contract says.
    unsafe { net().submit(req, blob, size, encode, oid, selector, sync != 0) }
}

pub(crate) unsafe fn config_value(key: *const c_char, out: *mut c_char, cap: usize) -> i32 {
    // SAFETY: the caller's pointers, as the table's contract says.
    unsafe { net().config_value(key, out, cap) }
}

pub(crate) fn robot_number() -> u32 {
    net().robot_number()
}
