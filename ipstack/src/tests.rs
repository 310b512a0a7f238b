//! The stack from inside: what tests/ cannot reach — whether a socket ever went into the
//! epoll set, an epoll set the kernel refuses (every epoll_ctl and epoll_wait fails), and
//! the socket options of an endpoint's socket.
use std::io::{Read, Write};
use std::net::{Ipv4Addr, TcpListener};
use std::os::fd::{AsRawFd, RawFd};
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

/// Submits `req` as a call whose reply goes to `tx`, without waiting for it (the replies
/// of several requests then come on one channel, in the order the stack gives them).
fn submit(net: &'static Net, req: Request, tx: &mpsc::SyncSender<NetResult>) {
    stack::handle(net, Pending { req, target: Target::Sync(tx.clone()), encode, net });
}

/// A TCP Send of `size` bytes at `buf`.
fn send(ep: EndpointId, buf: *mut u8, size: usize) -> Request {
    let mut req = request(PROTO_TCP, op::TCP_SEND, ep);
    (req.buffer, req.size) = (buf.cast(), size as i32);
    req
}

/// The byte at offset `i` of the data the tests send.
fn pattern(i: usize) -> u8 {
    (i % 251) as u8
}

/// A shared buffer of `size` bytes holding [`pattern`].
fn patterned_buffer(net: &'static Net, size: usize) -> *mut u8 {
    let buf = shared_buffer_of(net, size as i32);
    for i in 0..size {
        // SAFETY: `buf` is a live shared buffer of at least `size` bytes no operation uses yet.
        unsafe { *buf.add(i) = pattern(i) };
    }
    buf
}

/// The TCP_NODELAY of socket `fd`, as the kernel has it.

fn nodelay(fd: RawFd) -> bool {
    super::sys::int_opt(fd, libc::IPPROTO_TCP, libc::TCP_NODELAY).expect("getsockopt TCP_NODELAY") != 0
}

/// The descriptor of TCP endpoint `ep`'s socket.
fn tcp_fd(net: &'static Net, ep: EndpointId) -> RawFd {
    net.lock().tcp(ep).and_then(|t| t.raw_fd()).expect("a connected endpoint")
}

/// A loopback listener whose connections get a small receive window, so that a Send of
/// a few hundred KiB fills the connection (the host's autotuning would allow tens of MiB).
fn small_window_listener() -> TcpListener {
    let server = TcpListener::bind((Ipv4Addr::LOCALHOST, 0)).unwrap();
    super::sys::set_int_opt(server.as_raw_fd(), libc::SOL_SOCKET, libc::SO_RCVBUF, 4096);
    server
}

/// What the peer reads until the stream ends, and how it ended: `None` for an orderly
/// close (FIN), else the error (a reset).
fn read_to_end(peer: &mut std::net::TcpStream) -> (Vec<u8>, Option<std::io::ErrorKind>) {
    peer.set_read_timeout(Some(PATIENCE)).unwrap();
    let mut got = Vec::new();
    let mut chunk = [0u8; 65536];
    loop {
        match peer.read(&mut chunk) {
            Ok(0) => return (got, None),
            Ok(n) => got.extend_from_slice(&chunk[..n]),
            Err(e) => return (got, Some(e.kind())),
        }
    }
}

/// The warnings about a socket the epoll set refused.
/// The warning that endpoint `ep`'s socket could not be armed (the refusing poller's EINVAL).
fn refusal(ep: EndpointId) -> String {
    format!("warning: net: cannot watch the socket of TCP endpoint {} (epoll_ctl: Invalid argument (os error 22))", ep.0)
}

/// A stack on `poller` with a 1 MiB patterned buffer and a TCP endpoint connected to a
/// peer that reads slowly (small window): (stack, its warnings, buffer, endpoint, peer).
fn big_send_setup(poller: Poller) -> (&'static Net, Arc<Lines>, *mut u8, EndpointId, std::net::TcpStream) {
    let (net, lines) = start(poller);
    let buf = patterned_buffer(net, BIG);
    let server = small_window_listener();
    let (ep, res) = connected(net, &server);
    assert_eq!(res.error, tcp::SUCCESS, "a connect done at once arms nothing");
    let (peer, _) = server.accept().unwrap();
    (net, lines, buf, ep, peer)
}

/// The peer of an endpoint closed in error: a reset after a part of the data, in order
/// (3.4, 3.5: it cannot take the part for the whole).
fn assert_reset_after_a_part(peer: &mut std::net::TcpStream) {
    let (got, end) = read_to_end(peer);
    assert_eq!(end, Some(std::io::ErrorKind::ConnectionReset), "the Close of the endpoint in error resets");
    assert!(got.len() < BIG, "the whole Send went out: it never had to wait");
    assert!(got.iter().enumerate().all(|(i, &b)| b == pattern(i)), "a part of the data, in order");
}

/// The Send that fills a slow peer's socket.
const BIG: usize = 1 << 20;

fn refused(lines: &Lines) -> Vec<String> {
    lines.get().into_iter().filter(|l| l.contains("cannot watch the socket")).collect()
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
    for want in [refusal(ep), format!("warning: net: cannot watch the socket of UDP endpoint {} (epoll_ctl: Invalid argument (os error 22))", u.0)] {
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

/// A stream of 8 KiB Sends (ftpd's RETR) arrives whole and in order, and a joined stream
/// is back to TCP_NODELAY once the Sends stop (the poll thread's timer) — nothing is
/// left waiting for an ACK.
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
    // However this machine's timing let the Sends join, the stream is joined now and the
    // poll thread's timer, alone, must push it.
    {
        let mut st = net.lock();
        let now = Instant::now();
        st.tcp(ep).unwrap().join_stream(now);
        st.schedule(now + super::stream::PUSH_AFTER);
    }
    assert!(!nodelay(tcp_fd(net, ep)), "joined");
    let deadline = Instant::now() + PATIENCE;
    while net.lock().tcp(ep).unwrap().joining() {
        assert!(Instant::now() < deadline, "the stream was never pushed");
        std::thread::sleep(Duration::from_millis(1));
    }
    assert!(nodelay(tcp_fd(net, ep)), "pushed by the poll thread");
    assert_eq!(call(net, request(PROTO_TCP, op::TCP_CLOSE, ep)).error, tcp::SUCCESS);
    let all = reader.join().unwrap().expect("the peer reads to the end");
    assert_eq!(all.len(), CHUNK * CHUNKS);
    assert!(all.chunks(CHUNK).enumerate().all(|(k, c)| c.iter().all(|&b| b == (k % 251) as u8)), "in order");
    assert!(lines.get().is_empty(), "{:?}", lines.get());
}

/// A Send whose socket is full and cannot be armed fails at once (TCP_FAIL, said by a
/// warning) instead of waiting forever; the endpoint is then in error (3.5: ABORTING):
/// its next Send and Receive fail the same way without touching the socket, and Close
/// still succeeds. The peer got a part of the data, in order, never more.
#[test]
fn a_send_whose_socket_cannot_be_armed_fails_and_the_endpoint_is_in_error() {
    let (net, lines, buf, ep, mut peer) = big_send_setup(Poller::refusing().unwrap());
    super::sys::set_int_opt(tcp_fd(net, ep), libc::SOL_SOCKET, libc::SO_SNDBUF, 4096);

    // The first operation that has to wait: its socket takes a part of the 1 MiB and is full.
    let res = call(net, send(ep, buf, BIG));
    assert_eq!((res.op, res.error), (op::TCP_SEND, tcp::FAIL));
    assert_eq!(refused(&lines), [refusal(ep)]);

    let res = call(net, send(ep, buf, 1));
    assert_eq!((res.op, res.error), (op::TCP_SEND, tcp::FAIL), "the error sticks");
    let res = call(net, receive(PROTO_TCP, op::TCP_RECEIVE, ep, buf));
    assert_eq!((res.op, res.error, res.size), (op::TCP_RECEIVE, tcp::FAIL, 0), "the error sticks");
    assert_eq!(refused(&lines).len(), 1, "nothing else was armed");
    assert_eq!(call(net, request(PROTO_TCP, op::TCP_CLOSE, ep)).error, tcp::SUCCESS);
    assert_eq!(call(net, send(ep, buf, 1)).error, tcp::CONNECTION_CLOSED, "the endpoint is gone");

    assert_reset_after_a_part(&mut peer);
}

/// A loopback listener whose accept queue is full (backlog 0 and one connection nobody
/// accepts): the kernel drops the SYNs of a further connect, which stays in progress.
fn full_listener() -> (TcpListener, std::net::TcpStream) {
    let server = TcpListener::bind((Ipv4Addr::LOCALHOST, 0)).unwrap();
    // SAFETY: plain syscall on a live listening socket (listen again sets its backlog).
    assert_eq!(unsafe { libc::listen(server.as_raw_fd(), 0) }, 0);
    let queued = std::net::TcpStream::connect(server.local_addr().unwrap()).unwrap();
    (server, queued)
}

/// A Connect still in progress whose socket cannot be armed fails (TCP_FAIL, said by a
/// warning) instead of waiting forever, and leaves a fresh endpoint: it may connect
/// again, and closes.
#[test]
fn a_pending_connect_whose_socket_cannot_be_armed_fails_and_may_be_tried_again() {
    let (net, lines) = start(Poller::refusing().unwrap());
    let (full, _queued) = full_listener();
    let ep = endpoint(net, PROTO_TCP);
    let mut req = request(PROTO_TCP, op::TCP_CONNECT, ep);
    (req.addr, req.port) = (LOOPBACK, full.local_addr().unwrap().port().into());
    let res = call(net, req);
    assert_eq!((res.op, res.error), (op::TCP_CONNECT, tcp::FAIL), "a connect done at once would say SUCCESS");
    assert_eq!(refused(&lines), [refusal(ep)]);
    assert_eq!(call(net, request(PROTO_TCP, op::TCP_ADDRESS, ep)).error, tcp::OPERATION_INVALID, "not connected");
    assert_eq!(call(net, send(ep, shared_buffer(net), 1)).error, tcp::OPERATION_INVALID, "not connected");

    let server = TcpListener::bind((Ipv4Addr::LOCALHOST, 0)).unwrap();
    let mut req = request(PROTO_TCP, op::TCP_CONNECT, ep);
    (req.addr, req.port) = (LOOPBACK, server.local_addr().unwrap().port().into());
    let res = call(net, req);
    assert_eq!((res.op, res.error), (op::TCP_CONNECT, tcp::SUCCESS), "the endpoint is new again");
    let (_, peer) = server.accept().unwrap();
    assert_eq!(res.lport, u32::from(peer.port()));
    assert_eq!(call(net, request(PROTO_TCP, op::TCP_CLOSE, ep)).error, tcp::SUCCESS);
    assert_eq!(refused(&lines).len(), 1);
}

/// A graceful Close waits behind a Send that waits for room. When the socket, writable
/// again, has taken what it can and cannot be armed again, the Send fails (TCP_FAIL) and
/// then the Close is answered (TCP_SUCCESS), in that order (1.10); nothing hangs, the
/// endpoint is gone and the peer got a part of the data, in order.
#[test]
fn a_close_behind_a_send_is_answered_after_it_when_the_socket_cannot_be_armed_again() {
    let (net, lines, buf, ep, mut peer) = big_send_setup(Poller::new().unwrap());
    // The endpoint's socket, by a descriptor of ours: the stack closes its own meanwhile.
    // SAFETY: dup of the endpoint's live descriptor; the copy is ours.
    let same = super::sys::owned(unsafe { libc::dup(tcp_fd(net, ep)) }).unwrap();
    super::sys::set_int_opt(same.as_raw_fd(), libc::SOL_SOCKET, libc::SO_SNDBUF, 4096);

    let (tx, rx) = mpsc::sync_channel(2);
    submit(net, send(ep, buf, BIG), &tx);
    assert!(rx.try_recv().is_err(), "the Send waits for room");
    assert!(net.lock().tcp(ep).unwrap().ever_armed(), "its socket is armed");
    submit(net, request(PROTO_TCP, op::TCP_CLOSE, ep), &tx);
    assert!(rx.try_recv().is_err(), "the Close waits for the Send");

    net.poller.refuse_from_now();
    // Room: the kernel says the socket is writable (a bigger send buffer wakes its
    // waiters), the poll thread writes until it is full again and has to re-arm it.
    super::sys::set_int_opt(same.as_raw_fd(), libc::SOL_SOCKET, libc::SO_SNDBUF, 65536);
    let first = rx.recv_timeout(PATIENCE).expect("the Send's reply");
    assert_eq!((first.op, first.error), (op::TCP_SEND, tcp::FAIL));
    let second = rx.recv_timeout(PATIENCE).expect("the Close's reply");
    assert_eq!((second.op, second.error), (op::TCP_CLOSE, tcp::SUCCESS));
    assert_eq!(refused(&lines), [refusal(ep)]);
    assert_eq!(call(net, send(ep, buf, 1)).error, tcp::CONNECTION_CLOSED, "the endpoint is gone");
    assert_eq!(net.endpoint_protocol(ep), PROTO_TCP);

    drop(same);
    assert_reset_after_a_part(&mut peer);
}

/// A UDP Send whose socket cannot take the datagram now and cannot be armed fails
/// (UDP_FAIL, said by a warning) instead of waiting forever; nothing of it is sent and
/// the endpoint still closes.
///
/// A UDP socket on loopback never says EAGAIN (the loopback device frees the datagram's
/// memory while it is sent), so the endpoint's descriptor is made a stand-in: a
/// connected datagram socket whose send buffer is full, which says EAGAIN as a UDP
/// socket does whose interface queue is full.
#[test]
fn a_udp_send_whose_socket_cannot_be_armed_fails() {
    use std::os::unix::net::UnixDatagram;
    let (net, lines) = start(Poller::refusing().unwrap());
    let buf = patterned_buffer(net, 100);
    let u = endpoint(net, PROTO_UDP);
    let mut bind = request(PROTO_UDP, op::UDP_BIND, u);
    bind.addr = LOOPBACK;
    assert_eq!(call(net, bind).error, udp::SUCCESS);
    let peer = std::net::UdpSocket::bind((Ipv4Addr::LOCALHOST, 0)).unwrap();
    let mut connect = request(PROTO_UDP, op::UDP_CONNECT, u);
    (connect.addr, connect.port) = (LOOPBACK, peer.local_addr().unwrap().port().into());
    assert_eq!(call(net, connect).error, udp::SUCCESS, "a connected endpoint sends without an address");

    let (stand_in, other) = UnixDatagram::pair().unwrap();
    stand_in.set_nonblocking(true).unwrap();
    const FILLER: [u8; 64] = [0xaa; 64];
    let full = (0..100_000).any(|_| matches!(stand_in.send(&FILLER), Err(e) if e.kind() == std::io::ErrorKind::WouldBlock));
    assert!(full, "the stand-in's buffer fills");
    let fd = net.lock().udp(u).and_then(|u| u.raw_fd()).unwrap();
    // SAFETY: `fd` is the endpoint's live socket descriptor; dup2 makes the same number
    // the stand-in's (the endpoint closes it with its own socket's number, as before).
    assert_eq!(unsafe { libc::dup2(stand_in.as_raw_fd(), fd) }, fd);

    let mut send = request(PROTO_UDP, op::UDP_SEND, u);
    (send.buffer, send.size) = (buf.cast(), 100);
    let res = call(net, send);
    assert_eq!((res.op, res.error), (op::UDP_SEND, udp::FAIL));
    assert_eq!(refused(&lines), [format!("warning: net: cannot watch the socket of UDP endpoint {} (epoll_ctl: Invalid argument (os error 22))", u.0)]);
    other.set_nonblocking(true).unwrap();
    let mut dgram = [0u8; 200];
    while let Ok(n) = other.recv(&mut dgram) {
        assert_eq!(dgram[..n], FILLER, "only the fillers were sent");
    }
    assert_eq!(call(net, request(PROTO_UDP, op::UDP_CLOSE, u)).error, udp::SUCCESS);
}

/// A Receive and a Close push out what the kernel holds back of a stream of big Sends
/// (see `stream`): TCP_NODELAY, off in the middle of a stream, is on again at once.
#[test]
fn a_receive_and_a_close_push_a_stream_out() {
    let (net, lines) = start(Poller::new().unwrap());
    let buf = shared_buffer(net);
    let server = TcpListener::bind((Ipv4Addr::LOCALHOST, 0)).unwrap();
    let (ep, res) = connected(net, &server);
    assert_eq!(res.error, tcp::SUCCESS);
    let (mut peer, _) = server.accept().unwrap();
    let fd = tcp_fd(net, ep);
    assert!(nodelay(fd), "an endpoint's socket has TCP_NODELAY");

    let t0 = Instant::now();
    net.lock().tcp(ep).unwrap().join_stream(t0);
    assert!(!nodelay(fd), "in a stream");
    peer.write_all(b"x").unwrap();
    let res = call(net, receive(PROTO_TCP, op::TCP_RECEIVE, ep, buf));
    assert_eq!((res.error, res.size), (tcp::SUCCESS, 1));
    assert!(nodelay(fd), "a Receive pushes");

    net.lock().tcp(ep).unwrap().join_stream(t0 + Duration::from_millis(10));
    assert!(!nodelay(fd), "in a stream again");
    // The same socket, open beyond the endpoint's Close.
    // SAFETY: dup of the endpoint's live descriptor; the copy is ours.
    let same = super::sys::owned(unsafe { libc::dup(fd) }).unwrap();
    assert_eq!(call(net, request(PROTO_TCP, op::TCP_CLOSE, ep)).error, tcp::SUCCESS);
    assert!(nodelay(same.as_raw_fd()), "a Close pushes");
    assert!(lines.get().is_empty(), "{:?}", lines.get());
}
