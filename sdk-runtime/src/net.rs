//! The runtime's side of the IPStack (the `openr-ipstack` crate): the net table objects
//! find (`openr_runtime_net_v1`), the run's network settings, and [`RuntimeHost`],
//! through which the stack queues replies to objects, reads the stick's settings files
//! and reports.
use std::ffi::{c_char, c_void};
use std::sync::{Arc, OnceLock};

use openr_ipstack::{EncodeFn, Net, NetOptions, Request};

use crate::runtime::Runtime;

pub const ABI_VERSION: u32 = openr_sys::NET_ABI_VERSION;

static NET: OnceLock<&'static Net> = OnceLock::new();
static OPTIONS: OnceLock<NetOptions> = OnceLock::new();

/// The run's network settings, given before any object loads (the IPStack starts on
/// first use and reads them then).
pub fn configure(opts: NetOptions) {
    let _ = OPTIONS.set(opts);
}

/// The run's network settings (defaults before `configure`): the TCP gateways of
/// Remote Processing use them without starting the IPStack.
pub fn options() -> NetOptions {
    OPTIONS.get().cloned().unwrap_or_default()
}

/// The IPStack of this process, started on first use (its poll thread included).
pub fn net() -> &'static Net {
    NET.get_or_init(|| Net::start(OPTIONS.get_or_init(Default::default), Arc::new(RuntimeHost)).expect("start the IPStack (eventfd, its thread)"))
}

/// The stack's view of the running runtime (none yet, or none any more: replies are
/// dropped, the stick's files are not there, messages go to stderr).
pub struct RuntimeHost;

impl openr_ipstack::Report for RuntimeHost {
    fn warn(&self, msg: &str) {
        if let Some(rt) = Runtime::get() {
            rt.diag.warn(msg);
        }
    }
    fn info(&self, line: &str) {
        if !Runtime::get().is_some_and(|rt| rt.diag.quiet) {
            eprintln!("{line}");
        }
    }
    fn trace(&self, line: &str) {
        eprintln!("{line}");
    }
}

impl openr_ipstack::Host for RuntimeHost {
    fn send(&self, oid: usize, selector: u32, message: Vec<u8>) {
        if let Some(rt) = Runtime::get() {
            let _ = rt.send(oid, selector, message);
        }
    }
    fn read_stick(&self, path: &str) -> Option<String> {
        Runtime::get()?.ms.existing(path).and_then(|p| std::fs::read_to_string(p).ok())
    }
}

pub use openr_sys::openr_net_api as NetApi;

/// The table libantMCOOP / libERA201D1 find with `dlsym(RTLD_DEFAULT,
/// "openr_runtime_net_v1")`; exported by the `cargo-openr` binary (its build.rs).
/// Declared once in `openr-sys`; entries call the functions below and stop panics.
#[no_mangle]
#[used]
pub static openr_runtime_net_v1: NetApi = openr_sys::net_table!(crate::net, crate::host_api::panicked);

/// Keeps the table in the final link; call it from anything that always runs.
pub fn init() -> *const NetApi {
    std::hint::black_box(&openr_runtime_net_v1)
}

pub(crate) fn endpoint_protocol(endpoint: u32) -> i32 {
    net().endpoint_protocol(endpoint)
}

pub(crate) unsafe fn submit(req: *const Request, blob: *mut c_void, size: usize, encode: EncodeFn, oid: *mut c_void, selector: u32, sync: i32) -> i32 {
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
