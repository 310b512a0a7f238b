//! The stack from inside: what tests/ cannot reach — whether a socket ever went into the
//! epoll set, and an epoll set the kernel refuses (every epoll_ctl and epoll_wait fails).
use std::net::{Ipv4Addr, TcpListener};
use std::sync::{mpsc, Arc, Mutex};
use std::time::{Duration, Instant};

use super::codes::{op, tcp, udp, PROTO_ENV, PROTO_TCP, PROTO_UDP};
use super::poller::Poller;
use super::{stack, EndpointId, Host, Net, NetOptions, NetResult, Pending, Report, Request, Selector, Target};

/// A guard against a hang, not a speed assumption.
const PATIENCE: Duration = Duration::from_secs(20);

const LOOPBACK: u32 = 0x7f00_0001;

/// Keeps what the stack says; replies all go to calls (never `send`).
#[derive(Default)]
struct Lines(Mutex<Vec<String>>);

impl Report for Lines {
    fn warn(&self, msg: &str) {
        self.0.lock().unwrap().push(format!("warning: {msg}"));
    }
    fn info(&self, line: &str) {
        self.0.lock().unwrap().push(line.to_string());
    }
    fn trace(&self, line: &str) {
        self.0.lock().unwrap().push(line.to_string());
    }
}

impl Host for Lines {
    fn send(&self, _: usize, _: Selector, _: Vec<u8>) {
        panic!("a test only calls");
    }
    fn read_stick(&self, _: &str) -> Option<String> {
        None
    }
}

impl Lines {
    fn get(&self) -> Vec<String> {
        self.0.lock().unwrap().clone()
    }
}

unsafe extern "C" fn encode(_: *mut std::ffi::c_void, _: *const NetResult) {}

fn start(poller: Poller) -> (&'static Net, Arc<Lines>) {
    let lines = Arc::new(Lines::default());
    (Net::start_on(poller, &NetOptions::default(), lines.clone()).unwrap(), lines)
}

fn request(proto: i32, op: i32, endpoint: EndpointId) -> Request {
    // SAFETY: all-zero is a valid value of this plain C struct (null pointers, zero numbers).
    let mut r: Request = unsafe { std::mem::zeroed() };
    (r.proto, r.op, r.endpoint) = (proto, op, endpoint);
    r
}

/// Submits `req` as a call and waits for its reply (at most PATIENCE).
fn call(net: &'static Net, req: Request) -> NetResult {
    let (tx, rx) = mpsc::sync_channel(1);
    stack::handle(net, Pending { req, target: Target::Sync(tx), encode, net });
    rx.recv_timeout(PATIENCE).expect("a reply")
}

fn endpoint(net: &'static Net, proto: i32) -> EndpointId {
    let mut req = request(PROTO_ENV, op::ENV_CREATE_ENDPOINT, EndpointId(0));
    req.value = proto;
    call(net, req).endpoint
}

/// An active TCP endpoint connected to `server`.
fn connected(net: &'static Net, server: &TcpListener) -> (EndpointId, NetResult) {
    let ep = endpoint(net, PROTO_TCP);
    let mut req = request(PROTO_TCP, op::TCP_CONNECT, ep);
    (req.addr, req.port) = (LOOPBACK, server.local_addr().unwrap().port().into());
    (ep, call(net, req))
}

fn shared_buffer(net: &'static Net) -> *mut u8 {
    shared_buffer_of(net, 100)
}

fn shared_buffer_of(net: &'static Net, size: i32) -> *mut u8 {
    let mut req = request(PROTO_ENV, op::ENV_CREATE_BUFFER, EndpointId(0));
    req.value = size;
    call(net, req).base.cast()
}

fn receive(proto: i32, op: i32, ep: EndpointId, buf: *mut u8) -> Request {
    let mut req = request(proto, op, ep);
    (req.buffer, req.size, req.size_min) = (buf.cast(), 100, 1);
    req
}

#[test]
fn a_loopback_connect_completes_without_arming_its_socket() {
    let (net, lines) = start(Poller::new().unwrap());
    let server = TcpListener::bind((Ipv4Addr::LOCALHOST, 0)).unwrap();
    let (ep, res) = connected(net, &server);
    assert_eq!((res.op, res.error), (op::TCP_CONNECT, tcp::SUCCESS));
    assert_eq!((res.faddr, res.fport), (LOOPBACK, u32::from(server.local_addr().unwrap().port())));
    let (_, peer) = server.accept().unwrap();
    assert_eq!(res.lport, u32::from(peer.port()), "the port it connected from");
    assert!(!net.lock().tcp(ep).unwrap().ever_armed(), "nothing waited: the socket never went into the epoll set");
    assert!(lines.get().is_empty(), "{:?}", lines.get());
}

/// Operations that would wait for an event fail at once when their socket cannot be
/// armed (they would wait forever), and a warning says why; the TCP endpoint's next
/// Send is refused with the same error, and it still closes.
#[test]
fn operations_fail_and_say_why_when_the_epoll_set_refuses_their_socket() {
    let (net, lines) = start(Poller::refusing().unwrap());
    let buf = shared_buffer(net);
    let server = TcpListener::bind((Ipv4Addr::LOCALHOST, 0)).unwrap();
    let (ep, res) = connected(net, &server);
    assert_eq!(res.error, tcp::SUCCESS, "a connect done at once arms nothing");
    let res = call(net, receive(PROTO_TCP, op::TCP_RECEIVE, ep, buf));
    assert_eq!((res.op, res.error, res.size), (op::TCP_RECEIVE, tcp::FAIL, 0));
    let mut send = receive(PROTO_TCP, op::TCP_SEND, ep, buf);
    send.size = 1;
    assert_eq!(call(net, send).error, tcp::FAIL);
    assert_eq!(call(net, request(PROTO_TCP, op::TCP_CLOSE, ep)).error, tcp::SUCCESS);

    let u = endpoint(net, PROTO_UDP);
    let mut bind = request(PROTO_UDP, op::UDP_BIND, u);
    bind.addr = LOOPBACK;
    assert_eq!(call(net, bind).error, udp::SUCCESS);
    let res = call(net, receive(PROTO_UDP, op::UDP_RECEIVE, u, buf));
    assert_eq!((res.op, res.error, res.size), (op::UDP_RECEIVE, udp::FAIL, 0));

    let lines = lines.get();
    for want in [
        format!("warning: net: cannot watch the socket of TCP endpoint {} (epoll_ctl: Invalid argument (os error 22))", ep.0),
        format!("warning: net: cannot watch the socket of UDP endpoint {} (epoll_ctl: Invalid argument (os error 22))", u.0),
    ] {
        assert!(lines.contains(&want), "{want:?} not in {lines:?}");
    }
}

/// A listening socket the epoll set refuses fails its Listen after the usual delay: the
/// poll thread's timer still runs while its epoll_wait fails, and says that failure once.
#[test]
fn a_failing_epoll_wait_is_said_once_and_a_refused_listen_still_fails_on_time() {
    let (net, lines) = start(Poller::refusing().unwrap());
    let start = Instant::now();
    let res = call(net, request(PROTO_TCP, op::TCP_LISTEN, endpoint(net, PROTO_TCP)));
    assert_eq!((res.op, res.error), (op::TCP_LISTEN, tcp::FAIL));
    assert!(start.elapsed() >= Duration::from_secs(1), "the error waits LISTEN_RETRY_DELAY");
    let lines = lines.get();
    let said = |what: &str| lines.iter().filter(|l| l.contains(what)).count();
    assert_eq!(said("warning: net: the poll thread's epoll_wait failed: Invalid argument (os error 22)"), 1, "{lines:?}");
    assert_eq!(said("warning: net: cannot watch a listening socket (epoll_ctl: Invalid argument (os error 22))"), 1, "{lines:?}");
}

/// A stream of 8 KiB Sends (ftpd's RETR) arrives whole and in order, and however the
/// kernel was let join them (see `stream`), the endpoint is back to TCP_NODELAY once the
/// Sends stop (the poll thread's look) — nothing is left waiting for an ACK.
#[test]
fn a_stream_of_big_sends_arrives_whole_and_is_pushed_when_it_stops() {
    use std::io::Read;
    const CHUNK: usize = 8192;
    const CHUNKS: usize = 256;
    let (net, lines) = start(Poller::new().unwrap());
    let buf = shared_buffer_of(net, CHUNK as i32);
    let server = TcpListener::bind((Ipv4Addr::LOCALHOST, 0)).unwrap();
    let (ep, res) = connected(net, &server);
    assert_eq!(res.error, tcp::SUCCESS);
    let (mut peer, _) = server.accept().unwrap();
    peer.set_read_timeout(Some(PATIENCE)).unwrap();
    let reader = std::thread::spawn(move || {
        let mut all = Vec::new();
        peer.read_to_end(&mut all).map(|_| all)
    });
    for k in 0..CHUNKS {
        // SAFETY: `buf` is a live shared buffer of CHUNK bytes, not in use (the last Send was answered).
        unsafe { std::ptr::write_bytes(buf, (k % 251) as u8, CHUNK) };
        let mut send = request(PROTO_TCP, op::TCP_SEND, ep);
        (send.buffer, send.size) = (buf.cast(), CHUNK as i32);
        assert_eq!(call(net, send).error, tcp::SUCCESS);
    }
    let deadline = Instant::now() + PATIENCE;
    while net.lock().tcp(ep).unwrap().joining() {
        assert!(Instant::now() < deadline, "the stream was never pushed");
        std::thread::sleep(Duration::from_millis(1));
    }
    assert_eq!(call(net, request(PROTO_TCP, op::TCP_CLOSE, ep)).error, tcp::SUCCESS);
    let all = reader.join().unwrap().expect("the peer reads to the end");
    assert_eq!(all.len(), CHUNK * CHUNKS);
    assert!(all.chunks(CHUNK).enumerate().all(|(k, c)| c.iter().all(|&b| b == (k % 251) as u8)), "in order");
    assert!(lines.get().is_empty(), "{:?}", lines.get());
}
