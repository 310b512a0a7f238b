//! A [`Host`] that records what the stack sends and says, and serves stick files from a list;
//! a [`Robot`] that submits requests as libantMCOOP does.
#![allow(dead_code)] // each test file uses part of it

use std::ffi::c_void;
use std::net::TcpListener;
use std::sync::mpsc::{self, Receiver, Sender};
use std::sync::{Arc, Mutex};
use std::time::Duration;

use openr_ipstack::{EndpointId, Host, Net, NetOptions, NetResult, Report, Request, Selector};

pub const PROTO_ENV: i32 = 0;
pub const PROTO_TCP: i32 = 1;
pub const ENV_CREATE_ENDPOINT: i32 = -1;

pub struct Recorder {
    sent: Mutex<Sender<(usize, u32, Vec<u8>)>>,
    /// What `send` was given, in order.
    pub replies: Mutex<Receiver<(usize, u32, Vec<u8>)>>,
    lines: Mutex<Vec<String>>,
    stick: Vec<(&'static str, &'static str)>,
}

impl Recorder {
    pub fn new(stick: Vec<(&'static str, &'static str)>) -> Recorder {
        let (tx, rx) = mpsc::channel();
        Recorder { sent: Mutex::new(tx), replies: Mutex::new(rx), lines: Mutex::new(Vec::new()), stick }
    }

    /// Every warning (`warning: …`), info and trace line so far.
    pub fn lines(&self) -> Vec<String> {
        self.lines.lock().unwrap().clone()
    }
}

impl Report for Recorder {
    fn warn(&self, msg: &str) {
        self.lines.lock().unwrap().push(format!("warning: {msg}"));
    }
    fn info(&self, line: &str) {
        self.lines.lock().unwrap().push(line.to_string());
    }
    fn trace(&self, line: &str) {
        self.lines.lock().unwrap().push(line.to_string());
    }
}

impl Host for Recorder {
    fn send(&self, oid: usize, selector: Selector, message: Vec<u8>) {
        let _ = self.sent.lock().unwrap().send((oid, selector.0, message));
    }
    fn read_stick(&self, path: &str) -> Option<String> {
        self.stick.iter().find(|(p, _)| *p == path).map(|(_, t)| t.to_string())
    }
}

/// A guard against a hang, not a speed assumption.
pub const PATIENCE: Duration = Duration::from_secs(20);

pub struct Robot {
    pub net: &'static Net,
    pub host: Arc<Recorder>,
}

pub fn robot(opts: NetOptions, stick: Vec<(&'static str, &'static str)>) -> Robot {
    let host = Arc::new(Recorder::new(stick));
    let net = Net::start(&opts, host.clone()).expect("the stack starts");
    Robot { net, host }
}

/// The object's `encode`: the test's "message" is the result struct itself.
pub unsafe extern "C" fn encode(blob: *mut c_void, res: *const NetResult) {
    // SAFETY: `blob` is a message of `size_of::<NetResult>()` bytes (see `submit`), `res` a valid result.
    unsafe { blob.cast::<NetResult>().write_unaligned(*res) };
}

pub fn request(proto: i32, op: i32) -> Request {
    // SAFETY: all-zero is a valid value of this plain C struct (null pointers, zero numbers).
    let mut r: Request = unsafe { std::mem::zeroed() };
    (r.proto, r.op) = (proto, op);
    r
}

pub fn decode(blob: &[u8]) -> NetResult {
    assert_eq!(blob.len(), std::mem::size_of::<NetResult>());
    // SAFETY: `blob` holds a whole NetResult written by `encode`.
    unsafe { blob.as_ptr().cast::<NetResult>().read_unaligned() }
}

impl Robot {
    /// Submits `req`; `Some((oid, selector))` answers later to that object, `None` waits.
    pub fn submit(&self, req: &Request, to: Option<(usize, u32)>) -> (i32, NetResult) {
        let mut blob = vec![0u8; std::mem::size_of::<NetResult>()];
        let (oid, selector) = to.unwrap_or((0, 0));
        // SAFETY: `req` is a valid request; `blob` is the message `encode` writes into.
        let rc = unsafe { self.net.submit(req, blob.as_mut_ptr().cast(), blob.len(), encode, oid as *mut c_void, Selector(selector), to.is_none()) };
        (rc, decode(&blob))
    }

    pub fn call(&self, req: &Request) -> NetResult {
        let (rc, r) = self.submit(req, None);
        assert_eq!(rc, 0);
        r
    }

    pub fn reply(&self) -> (usize, u32, NetResult) {
        let (oid, selector, blob) = self.host.replies.lock().unwrap().recv_timeout(PATIENCE).expect("a reply is sent");
        (oid, selector, decode(&blob))
    }

    pub fn tcp_endpoint(&self) -> EndpointId {
        let mut req = request(PROTO_ENV, ENV_CREATE_ENDPOINT);
        req.value = PROTO_TCP;
        let r = self.call(&req);
        assert_eq!(r.error, 0);
        assert_eq!(self.net.endpoint_protocol(r.endpoint), PROTO_TCP);
        r.endpoint
    }
}

/// A robot port whose host ports with offsets 1 and 2 are free now.
pub fn free_robot_port() -> u16 {
    loop {
        let p = TcpListener::bind("127.0.0.1:0").unwrap().local_addr().unwrap().port();
        if p < 65000 && (1..=2).all(|o| TcpListener::bind(("127.0.0.1", p + o)).is_ok()) {
            return p;
        }
    }
}
