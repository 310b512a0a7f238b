//! The IPStack: ANT endpoints (TCP, UDP, DNS) on host sockets (network-api 1–5, 8, 10).
//!
//! Objects reach it through `openr_runtime_net_v1` (`cxx/openr_net.h`), never through
//! the object message loop: libantMCOOP decodes each ANT message into a flat
//! [`Request`] and hands over a copy of the whole message plus an `encode` function.
//! Requests are tried at once on the caller's thread (non-blocking syscalls); what
//! would block is parked and finished by one poll thread; DNS lookups run on worker
//! threads. Replies are encoded into the message copy and queued to the object's
//! (oid, selector) with [`Runtime::send`](crate::runtime::Runtime::send), so objects
//! only ever run them from their own message loop. Every completion happens under
//! one lock, which gives the ordering of 1.10: per object in completion order, per
//! endpoint FIFO, everything pending before a Close reply.
#![deny(unsafe_op_in_unsafe_fn)]

mod codes;
pub mod config;
pub mod dns;
mod stack;
mod sys;
mod tcp;
mod udp;

use std::ffi::{c_char, c_void, CStr};
use std::os::fd::{AsRawFd, FromRawFd, OwnedFd};
use std::sync::mpsc;
use std::sync::{Mutex, OnceLock};

use config::NetConfig;
use stack::State;

pub const ABI_VERSION: u32 = openr_sys::NET_ABI_VERSION;

/// `struct openr_net_request` / `openr_net_result` (openr-sys).
pub use openr_sys::{openr_net_request as Request, openr_net_result as NetResult};

pub use openr_sys::openr_net_encode_fn as EncodeFn;

/// Where a completed operation's reply goes.
pub enum Target {
    /// `Send`: the encoded message copy is queued to (oid, selector).
    Async { oid: usize, selector: u32, blob: Vec<u8> },
    /// `Call`: the caller waits on this channel and encodes into its own message.
    Sync(mpsc::SyncSender<NetResult>),
}

/// An operation waiting for its reply.
pub struct Pending {
    pub req: Request,
    pub target: Target,
    pub encode: EncodeFn,
}

impl Pending {
    /// Delivers the reply (exactly once).
    pub fn complete(self, res: NetResult) {
        if trace() {
            eprintln!(
                "net: reply proto {} op {} endpoint {} -> error {} size {} ({})",
                res.proto,
                res.op,
                self.req.endpoint,
                res.error,
                res.size,
                if matches!(self.target, Target::Sync(_)) { "call" } else { "send" }
            );
        }
        match self.target {
            Target::Async { oid, selector, mut blob } => {
                // SAFETY: `encode` comes from the object's library and writes only inside
                // a message of the size it declared, which `blob` has.
                unsafe { (self.encode)(blob.as_mut_ptr().cast(), &res) };
                if let Some(rt) = crate::runtime::Runtime::get() {
                    let _ = rt.send(oid, selector, blob);
                }
            }
            Target::Sync(tx) => {
                let _ = tx.send(res);
            }
        }
    }

    pub fn fail(self, error: i32) {
        let res = NetResult::new(&self.req, error);
        self.complete(res);
    }
}

/// `OPENR_NET_TRACE=1`: every request and reply on stderr.
pub fn trace() -> bool {
    static T: OnceLock<bool> = OnceLock::new();
    *T.get_or_init(|| std::env::var_os("OPENR_NET_TRACE").is_some_and(|v| v != "0"))
}

/// The IPStack of this process.
pub struct Net {
    pub state: Mutex<State>,
    pub config: NetConfig,
    wake_fd: OwnedFd,
}

static NET: OnceLock<Net> = OnceLock::new();
static OPTIONS: OnceLock<config::NetOptions> = OnceLock::new();

/// The run's network settings, given before any object loads (the IPStack starts on
/// first use and reads them then).
pub fn configure(opts: config::NetOptions) {
    let _ = OPTIONS.set(opts);
}

/// The run's network settings (defaults before `configure`): the TCP gateways of
/// Remote Processing use them without starting the IPStack.
pub fn options() -> config::NetOptions {
    OPTIONS.get().cloned().unwrap_or_default()
}

/// The IPStack, started on first use (its poll thread included).
pub fn net() -> &'static Net {
    let mut started = false;
    let n = NET.get_or_init(|| {
        started = true;
        let quiet = crate::runtime::Runtime::get().is_some_and(|rt| rt.diag.quiet);
        // SAFETY: plain syscall; a fresh descriptor we own.
        let fd = unsafe { libc::eventfd(0, libc::EFD_NONBLOCK | libc::EFD_CLOEXEC) };
        assert!(fd >= 0, "eventfd failed");
        // SAFETY: `fd` is the fresh eventfd just created (checked non-negative), owned by nothing else.
        let wake_fd = unsafe { OwnedFd::from_raw_fd(fd) };
        Net { state: Mutex::new(State::new()), config: NetConfig::new(OPTIONS.get_or_init(Default::default), quiet), wake_fd }
    });
    if started {
        std::thread::Builder::new().name("ipstack".into()).spawn(|| stack::poll_loop(net())).expect("spawn the IPStack thread");
    }
    n
}

impl Net {
    pub fn lock(&self) -> std::sync::MutexGuard<'_, State> {
        self.state.lock().unwrap_or_else(|p| p.into_inner())
    }

    /// Makes the poll thread rebuild its descriptor set.
    pub fn wake(&self) {
        let one: u64 = 1;
        // SAFETY: writes 8 bytes from `one`.
        unsafe { libc::write(self.wake_fd.as_raw_fd(), (&one as *const u64).cast(), 8) };
    }

    fn drain_wake(&self) {
        let mut v: u64 = 0;
        // SAFETY: reads 8 bytes into `v`.
        unsafe { libc::read(self.wake_fd.as_raw_fd(), (&mut v as *mut u64).cast(), 8) };
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
    net().lock().protocol_of(endpoint)
}

pub(crate) unsafe fn submit(req: *const Request, blob: *mut c_void, size: usize, encode: EncodeFn, oid: *mut c_void, selector: u32, sync: i32) -> i32 {
    if req.is_null() || blob.is_null() {
        return -1;
    }
    // SAFETY: a request struct filled by libantMCOOP.
    let req = unsafe { *req };
    let net = net();
    if trace() {
        eprintln!("net: request proto {} op {} endpoint {} size {} ({})", req.proto, req.op, req.endpoint, req.size, if sync != 0 { "call" } else { "send" });
    }
    if sync != 0 {
        let (tx, rx) = mpsc::sync_channel(1);
        stack::handle(net, Pending { req, target: Target::Sync(tx), encode });
        match rx.recv() {
            Ok(res) => {
                // SAFETY: `blob` is the caller's message of `size` bytes; `encode` writes inside it.
                unsafe { encode(blob, &res) };
                0
            }
            Err(_) => -1,
        }
    } else {
        // SAFETY: `blob` has `size` readable bytes (the message's real type).
        let copy = unsafe { std::slice::from_raw_parts(blob.cast::<u8>(), size) }.to_vec();
        stack::handle(net, Pending { req, target: Target::Async { oid: oid as usize, selector, blob: copy }, encode });
        0
    }
}

pub(crate) unsafe fn config_value(key: *const c_char, out: *mut c_char, cap: usize) -> i32 {
    if key.is_null() || out.is_null() || cap == 0 {
        return -1;
    }
    // SAFETY: a NUL-terminated key from the object.
    let key = unsafe { CStr::from_ptr(key) }.to_string_lossy().to_ascii_uppercase();
    let Some(v) = net().lock().registry_value(&key) else { return -1 };
    let n = v.len().min(cap - 1);
    // SAFETY: `out` has room for `cap` bytes.
    unsafe {
        std::ptr::copy_nonoverlapping(v.as_ptr(), out.cast::<u8>(), n);
        *out.add(n) = 0;
    }
    0
}

pub(crate) fn robot_number() -> u32 {
    net().config.offset
}
