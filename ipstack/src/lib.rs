//! The robot's IPStack: ANT endpoints (TCP, UDP, DNS) on host sockets (network-api 1–5,
//! 8, 10, 11).
//!
//! Objects reach it through the runtime's `openr_runtime_net_v1` table
//! (`sdk-payload/cxx/openr_net.h`), never through the object message loop: libantMCOOP
//! decodes each ANT message into a flat [`Request`] and hands over a copy of the whole
//! message plus an `encode` function. Requests are tried at once on the caller's thread
//! (non-blocking syscalls); what would block is parked and finished by one poll thread
//! (epoll, woken only by the sockets that parked operations wait on);
//! DNS lookups run on worker threads. Replies are encoded into the message copy and
//! handed to [`Host::send`] for the object's (oid, selector), so objects only ever run
//! them from their own message loop. Every completion happens under one lock, which
//! gives the ordering of 1.10: per object in completion order, per endpoint FIFO,
//! everything pending before a Close reply.
//!
//! The stack knows nothing of the runtime that hosts it: [`Net::start`] takes the run's
//! [`NetOptions`] and a [`Host`] (delivery, the memory stick's settings files, and the
//! [`Report`] its warnings and log lines go to).
#![deny(unsafe_op_in_unsafe_fn)]

mod codes;
pub mod config;
pub mod dns;
mod poller;
mod stack;
mod stream;
mod sys;
mod tcp;
#[cfg(test)]
mod tests;
mod udp;

use std::ffi::{c_char, c_void, CStr};
use std::sync::mpsc;
use std::sync::{Arc, Mutex};

pub use config::{NetConfig, NetOptions};
use poller::Poller;
use stack::State;

/// `struct openr_net_request` / `openr_net_result` (openr-sys).
pub use openr_sys::{openr_net_request as Request, openr_net_result as NetResult};

pub use openr_sys::openr_net_encode_fn as EncodeFn;
pub use openr_sys::{EndpointId, Selector};

/// Where the stack's messages go; the host decides what `--quiet` hides.
pub trait Report: Send + Sync {
    /// Something a program asked for was refused or changed (`warning: …`).
    fn warn(&self, msg: &str);
    /// A line of the stack's log that `--quiet` hides (`net: robot port 21 … is host port …`).
    fn info(&self, line: &str);
    /// A line of the request trace ([`NetOptions::trace`]), always shown.
    fn trace(&self, line: &str);
}

/// What the stack needs from the runtime that hosts it.
pub trait Host: Report {
    /// Queues `message` (the object's message with the reply encoded into it) to
    /// (oid, selector); a message for an object that is gone is dropped.
    fn send(&self, oid: usize, selector: Selector, message: Vec<u8>);
    /// The text of the robot's file `path` (`/MS/OPEN-R/…`), if the stick has it.
    fn read_stick(&self, path: &str) -> Option<String>;
}

/// Where a completed operation's reply goes.
enum Target {
    /// `Send`: the encoded message copy is queued to (oid, selector).
    Async { oid: usize, selector: Selector, blob: Vec<u8> },
    /// `Call`: the caller waits on this channel and encodes into its own message.
    Sync(mpsc::SyncSender<NetResult>),
}

/// An operation waiting for its reply.
struct Pending {
    req: Request,
    target: Target,
    encode: EncodeFn,
    net: &'static Net,
}

impl Pending {
    /// Delivers the reply (exactly once).
    fn complete(self, res: NetResult) {
        if self.net.trace {
            self.net.host.trace(&format!(
                "net: reply proto {} op {} endpoint {} -> error {} size {} ({})",
                res.proto,
                res.op,
                self.req.endpoint,
                res.error,
                res.size,
                if matches!(self.target, Target::Sync(_)) { "call" } else { "send" }
            ));
        }
        match self.target {
            Target::Async { oid, selector, mut blob } => {
                // SAFETY: `encode` comes from the object's library and writes only inside
                // a message of the size it declared, which `blob` has.
                unsafe { (self.encode)(blob.as_mut_ptr().cast(), &res) };
                self.net.host.send(oid, selector, blob);
            }
            Target::Sync(tx) => {
                let _ = tx.send(res);
            }
        }
    }

    fn fail(self, error: i32) {
        let res = NetResult::new(&self.req, error);
        self.complete(res);
    }
}

/// One robot's IPStack.
pub struct Net {
    state: Mutex<State>,
    config: NetConfig,
    host: Arc<dyn Host>,
    trace: bool,
    poller: &'static Poller,
}

impl Net {
    /// Starts a stack and its poll thread; both live for the rest of the process (a
    /// runtime starts one, on an object's first request).
    pub fn start(opts: &NetOptions, host: Arc<dyn Host>) -> std::io::Result<&'static Net> {
        Net::start_on(Poller::new()?, opts, host)
    }

    /// As [`Net::start`], on a given epoll set (the tests give one the kernel refuses).
    fn start_on(poller: Poller, opts: &NetOptions, host: Arc<dyn Host>) -> std::io::Result<&'static Net> {
        let poller: &'static Poller = Box::leak(Box::new(poller));
        let net: &'static Net = Box::leak(Box::new(Net {
            state: Mutex::new(State::new(host.clone(), poller)),
            config: NetConfig::new(opts, host.clone()),
            host,
            trace: opts.trace,
            poller,
        }));
        std::thread::Builder::new().name("ipstack".into()).spawn(move || stack::poll_loop(net))?;
        Ok(net)
    }

    fn lock(&self) -> std::sync::MutexGuard<'_, State> {
        self.state.lock().unwrap_or_else(|p| p.into_inner())
    }

    /// The protocol of an endpoint (`OPENR_NET_TCP`…), a closed one's too; -1 if unknown.
    pub fn endpoint_protocol(&self, endpoint: EndpointId) -> i32 {
        self.lock().protocol_of(endpoint)
    }

    /// One request of an object (`openr_net_api.submit`). `sync`: the caller waits and
    /// the reply is encoded into `blob` itself; else a copy of `blob` is answered to
    /// (oid, selector) later. 0 on success, -1 for a null request or message.
    ///
    /// # Safety
    /// `req` is null or a valid request; `blob` is null or `size` bytes of the caller's
    /// message, which `encode` writes a reply into.
    pub unsafe fn submit(
        &'static self,
        req: *const Request,
        blob: *mut c_void,
        size: usize,
        encode: EncodeFn,
        oid: *mut c_void,
        selector: Selector,
        sync: bool,
    ) -> i32 {
        if req.is_null() || blob.is_null() {
            return -1;
        }
        // SAFETY: a request struct filled by libantMCOOP.
        let req = unsafe { *req };
        if self.trace {
            self.host.trace(&format!(
                "net: request proto {} op {} endpoint {} size {} ({})",
                req.proto,
                req.op,
                req.endpoint,
                req.size,
                if sync { "call" } else { "send" }
            ));
        }
        if sync {
            let (tx, rx) = mpsc::sync_channel(1);
            stack::handle(self, Pending { req, target: Target::Sync(tx), encode, net: self });
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
            stack::handle(self, Pending { req, target: Target::Async { oid: oid as usize, selector, blob: copy }, encode, net: self });
            0
        }
    }

    /// A key of the robot's settings registry (`ETHER_IP`…), any case.
    pub fn registry_value(&self, key: &str) -> Option<String> {
        self.lock().registry_value(&key.to_ascii_uppercase())
    }

    /// `openr_net_api.config_value`: the registry value of `key` into `out`, cut to
    /// `cap - 1` bytes and NUL-terminated; 0, or -1 for no such key.
    ///
    /// # Safety
    /// `key` is null or NUL-terminated; `out` is null or has room for `cap` bytes.
    pub unsafe fn config_value(&self, key: *const c_char, out: *mut c_char, cap: usize) -> i32 {
        if key.is_null() || out.is_null() || cap == 0 {
            return -1;
        }
        // SAFETY: a NUL-terminated key from the object.
        let key = unsafe { CStr::from_ptr(key) }.to_string_lossy().into_owned();
        let Some(v) = self.registry_value(&key) else { return -1 };
        let n = v.len().min(cap - 1);
        // SAFETY: `out` has room for `cap` bytes.
        unsafe {
            std::ptr::copy_nonoverlapping(v.as_ptr(), out.cast::<u8>(), n);
            *out.add(n) = 0;
        }
        0
    }

    /// This robot's number on the host: its port offset (network-api 11.2).
    pub fn robot_number(&self) -> u32 {
        self.config.offset
    }
}
