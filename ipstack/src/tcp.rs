//! TCP endpoints (network-api 3): Bind, Listen, Connect, Send, Receive and Close on host
//! stream sockets, tried at once and finished by the poll thread when they would block.
use std::collections::{HashMap, VecDeque};
use std::os::fd::{AsRawFd, OwnedFd, RawFd};
use std::time::{Duration, Instant};

use super::codes::{op, tcp, tcp_error, PROTO_TCP};
use super::config::NetConfig;
use super::poller::{self, Armed, Poller, Token};
use super::stack::{robot_peer, tcp_in, Endpoint, State};
use super::{sys, EndpointId, NetResult, Pending};

/// How long a failed Listen waits before its error reply: samples retry at once in a
/// tight loop (3.4).
const LISTEN_RETRY_DELAY: Duration = Duration::from_secs(1);

/// How long a listener whose accept failed (no descriptor left: EMFILE, ENFILE) waits
/// before it tries again: the connection stays queued, but its readiness edge has passed,
/// so no event would come for it until another connection.
const ACCEPT_RETRY_DELAY: Duration = Duration::from_millis(50);

#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
enum TcpPhase {
    #[default]
    New,
    Listening,
    Connecting,
    Active,
}

struct SendOp {
    p: Pending,
    buf: usize,
    size: usize,
    done: usize,
}

struct RecvOp {
    p: Pending,
    buf: usize,
    min: usize,
    max: usize,
    got: usize,
}

#[derive(Default)]
pub struct TcpEp {
    phase: TcpPhase,
    fd: Option<OwnedFd>,
    /// Whether `fd` is armed in the poll thread's epoll set, and for what.
    armed: Armed,
    nonblocking: bool,
    /// Bind op: local (robot address, robot port) for a later Listen/Connect.
    bound: Option<(u32, u16)>,
    /// The robot's port number of the local side (reported as lPort).
    robot_lport: u16,
    listen: Option<Pending>,
    listen_key: Option<(u32, u16)>,
    /// A failed listen answers after a delay: (when, error).
    listen_error: Option<(Instant, i32)>,
    connect: Option<Pending>,
    send: Option<SendOp>,
    recv: Option<RecvOp>,
    /// A graceful Close waiting for the pending send to flush.
    closing: Option<Pending>,
    eof: bool,
    /// An error seen while bytes were being delivered: reported by the next receive.
    sticky: Option<i32>,
    /// Whether big Sends come back to back (TCP_NODELAY off meanwhile).
    stream: crate::stream::Stream,
}

/// A host listening socket, shared by every Listen endpoint on its (address, port); in the
/// epoll set for readable from its creation on.
pub struct Listener {
    fd: OwnedFd,
    waiters: VecDeque<EndpointId>,
    /// When to try accepting again after a failed accept.
    retry: Option<Instant>,
    /// The failure was said (once until an accept gets through again).
    said: bool,
}

impl TcpEp {
    /// Whether a pending Send or Receive reads or writes `[base, base+size)`.
    pub(super) fn uses_buffer(&self, base: usize, size: usize) -> bool {
        let inside = |p: usize| p >= base && p < base + size;
        self.send.as_ref().is_some_and(|s| inside(s.buf)) || self.recv.as_ref().is_some_and(|r| inside(r.buf))
    }

    /// When a delayed Listen error is due.
    pub(super) fn listen_due(&self) -> Option<Instant> {
        self.listen_error.map(|(at, _)| at)
    }

    /// Sends at once what the kernel holds back of a stream (see `stream`).
    fn push_stream(&mut self) {
        if let Some(fd) = self.fd.as_ref() {
            self.stream.push(fd.as_raw_fd());
        }
    }

    /// The poll thread's look at a streaming endpoint (see `stream`): when to look again.
    pub(super) fn check_stream(&mut self, now: Instant) -> Option<Instant> {
        let fd = self.fd.as_ref()?.as_raw_fd();
        self.stream.check(fd, now)
    }

    /// Whether TCP_NODELAY is off (a stream of big Sends).
    #[cfg(test)]
    pub(super) fn joining(&self) -> bool {
        self.stream.joining()
    }

    /// Whether the socket was ever put in the epoll set.
    #[cfg(test)]
    pub(super) fn ever_armed(&self) -> bool {
        self.armed.in_set()
    }

    /// Its socket's descriptor (for the tests' socket options).
    #[cfg(test)]
    pub(super) fn raw_fd(&self) -> Option<RawFd> {
        self.fd.as_ref().map(|f| f.as_raw_fd())
    }

    /// Puts it in the middle of a stream, TCP_NODELAY off, as two big Sends back to back
    /// at `now` would (see `stream`).
    #[cfg(test)]
    pub(super) fn join_stream(&mut self, now: Instant) {
        let fd = self.raw_fd().expect("a connected endpoint");
        self.stream.join(fd, now);
    }

    /// Its socket reported readiness: the kernel disarmed it (one-shot).
    pub(super) fn fired(&mut self) {
        self.armed.fired();
    }

    /// A new socket (or none): not in the epoll set yet.
    fn attach(&mut self, fd: Option<OwnedFd>) {
        self.fd = fd;
        self.armed = Armed::default();
    }

    /// Answers a failed Listen once its delay is over; the endpoint may listen again.
    pub(super) fn fire_listen_error(&mut self, now: Instant) {
        let Some((_, err)) = self.listen_error.filter(|&(at, _)| at <= now) else { return };
        self.listen_error = None;
        self.phase = TcpPhase::New;
        if let Some(p) = self.listen.take() {
            p.fail(err);
        }
    }
}

/// Entry point of every TCP request.
pub(super) fn tcp_op(st: &mut State, cfg: &NetConfig, p: Pending) {
    let req = p.req;
    let id = req.endpoint;
    // Read before the endpoint is borrowed: whether the buffer is a shared one (Send,
    // Receive) and the robot's own address (Listen).
    let valid = st.valid_buffer(req.buffer, req.size);
    let robot_ip = if req.op == op::TCP_LISTEN { st.robot_ip() } else { 0 };
    let poller = st.poller;
    let Some(t) = tcp_in(&mut st.eps, id).filter(|t| t.closing.is_none()) else { return p.fail(tcp::CONNECTION_CLOSED) };
    match req.op {
        op::TCP_BIND => bind(t, cfg, p),
        op::TCP_LISTEN => {
            if let Some(key) = listen(t, &mut st.listeners, poller, cfg, robot_ip, id, p) {
                accept_ready(st, cfg, key);
            } else if let Some(at) = st.tcp(id).and_then(|t| t.listen_due()) {
                st.schedule(at);
            }
        }
        op::TCP_CONNECT => {
            if connect(t, cfg, p) {
                progress(st, id);
            }
        }
        op::TCP_SEND => {
            if send(t, valid, p) {
                let size = req.size as usize;
                let look = t.fd.as_ref().and_then(|fd| t.stream.before_send(fd.as_raw_fd(), size, Instant::now()));
                if let Some(at) = look {
                    st.schedule(at);
                }
                progress(st, id);
            }
        }
        op::TCP_RECEIVE => {
            if receive(t, valid, p) {
                // The program waits for an answer: nothing it sent may wait for an ACK.
                t.push_stream();
                progress(st, id);
            }
        }
        op::TCP_CLOSE => {
            t.push_stream();
            let abort = req.flags & 1 != 0;
            if !abort && t.send.is_some() {
                // Flush first; the Close reply comes after the send's (1.10).
                t.closing = Some(p);
            } else {
                finish_close(st, id, p, abort);
            }
        }
        op::TCP_SET_BLOCKING => {
            t.nonblocking = req.flags & 1 == 0;
            p.fail(tcp::SUCCESS)
        }
        op::TCP_READY_READ | op::TCP_READY_WRITE => ready(t, p),
        op::TCP_ADDRESS => address(t, cfg, p),
        _ => p.fail(tcp::OPERATION_UNKNOWN),
    }
}

fn bind(t: &mut TcpEp, cfg: &NetConfig, p: Pending) {
    let req = p.req;
    if t.phase != TcpPhase::New {
        return p.fail(tcp::OPERATION_INVALID);
    }
    t.bound = Some((req.laddr, req.lport as u16));
    let mut r = NetResult::new(&req, tcp::SUCCESS);
    r.laddr = cfg.local_addr(req.laddr, 0);
    r.lport = req.lport;
    p.complete(r)
}

/// Queues the endpoint on its listener; the key to accept on, unless the Listen failed
/// (its error is then answered after [`LISTEN_RETRY_DELAY`]).
fn listen(
    t: &mut TcpEp,
    listeners: &mut HashMap<(u32, u16), Listener>,
    poller: &Poller,
    cfg: &NetConfig,
    robot_ip: u32,
    id: EndpointId,
    p: Pending,
) -> Option<(u32, u16)> {
    match t.phase {
        TcpPhase::New => {}
        TcpPhase::Listening => {
            p.fail(tcp::CONNECTION_BUSY);
            return None;
        }
        _ => {
            p.fail(tcp::OPERATION_INVALID);
            return None;
        }
    }
    let req = p.req;
    let robot_port = if req.lport != 0 { req.lport as u16 } else { t.bound.map_or(0, |b| b.1) };
    let robot_addr = t.bound.map_or(0, |b| b.0);
    let host_addr = cfg.local_addr(robot_addr, robot_ip);
    let key = match cfg.local_port(robot_port, "TCP listen") {
        None => Err(tcp::ADDRESSERROR),
        Some(host_port) => shared_listener(listeners, poller, cfg, host_addr, host_port),
    };
    t.phase = TcpPhase::Listening;
    t.listen = Some(p);
    match key {
        Ok(key) => {
            t.robot_lport = if robot_port != 0 { robot_port } else { key.1 };
            t.listen_key = Some(key);
            listeners.entry(key).and_modify(|l| l.waiters.push_back(id));
            Some(key)
        }
        Err(e) => {
            t.listen_error = Some((Instant::now() + LISTEN_RETRY_DELAY, e));
            None
        }
    }
}

/// The listener on (addr, port): the one already open there, else a new socket (port 0:
/// an ephemeral port, keyed by the port it got).
fn shared_listener(listeners: &mut HashMap<(u32, u16), Listener>, poller: &Poller, cfg: &NetConfig, addr: u32, port: u16) -> Result<(u32, u16), i32> {
    if port != 0 && listeners.contains_key(&(addr, port)) {
        return Ok((addr, port));
    }
    let fd = open_listener(addr, port)?;
    let key = (addr, sys::local_addr(fd.as_raw_fd()).1);
    // Armed once: connections that come while no Listen waits stay queued for the next
    // Listen, which accepts at once (`accept_ready`).
    if let Err(e) = poller.add_listener(fd.as_raw_fd(), key) {
        cfg.report.warn(&format!("net: cannot watch a listening socket (epoll_ctl: {})", std::io::Error::from_raw_os_error(e)));
        return Err(tcp::FAIL);
    }
    listeners.insert(key, Listener { fd, waiters: VecDeque::new(), retry: None, said: false });
    Ok(key)
}

fn open_listener(addr: u32, port: u16) -> Result<OwnedFd, i32> {
    let fd = sys::socket(libc::SOCK_STREAM).map_err(|_| tcp::FAIL)?;
    sys::reuse_addr(fd.as_raw_fd());
    sys::bind(fd.as_raw_fd(), addr, port).map_err(tcp_error)?;
    sys::listen(fd.as_raw_fd(), 16).map_err(tcp_error)?;
    Ok(fd)
}

/// Hands waiting connections of a listener to its Listen endpoints, FIFO.
pub(super) fn accept_ready(st: &mut State, cfg: &NetConfig, key: (u32, u16)) {
    loop {
        let Some(l) = st.listeners.get_mut(&key) else { return };
        let Some(&id) = l.waiters.front() else { return };
        let conn = match sys::accept(l.fd.as_raw_fd()) {
            Ok(c) => c,
            Err(libc::EINTR | libc::ECONNABORTED) => continue,
            Err(libc::EAGAIN) => return, // nobody yet
            Err(e) => {
                // The waiter stays first in line; the poll thread tries again later.
                let at = Instant::now() + ACCEPT_RETRY_DELAY;
                l.retry = Some(at);
                if !std::mem::replace(&mut l.said, true) {
                    let err = std::io::Error::from_raw_os_error(e);
                    st.host.warn(&format!("net: cannot accept a connection on host port {} ({err}); trying again", key.1));
                }
                st.schedule(at);
                return;
            }
        };
        l.said = false;
        l.waiters.pop_front();
        let (la, _) = sys::local_addr(conn.as_raw_fd());
        let (fa, fp) = sys::peer_addr(conn.as_raw_fd());
        sys::set_int_opt(conn.as_raw_fd(), libc::IPPROTO_TCP, libc::TCP_NODELAY, 1);
        // A waiter always has its Listen pending (Close takes it off the queue).
        let Some((t, p)) = st.tcp(id).and_then(|t| t.listen.take().map(|p| (t, p))) else { continue };
        t.attach(Some(conn));
        t.phase = TcpPhase::Active;
        t.listen_key = None;
        let mut r = NetResult::new(&p.req, tcp::SUCCESS);
        r.laddr = la;
        r.lport = t.robot_lport.into();
        (r.faddr, r.fport) = robot_peer(cfg, fa, fp);
        p.complete(r);
    }
}

/// Tries the listeners whose accept failed again once their delay is over; the earliest
/// retry still to come.
pub(super) fn retry_accepts(st: &mut State, cfg: &NetConfig, now: Instant) -> Option<Instant> {
    let mut due = Vec::new();
    for (&key, l) in st.listeners.iter_mut() {
        if l.retry.is_some_and(|at| at <= now) {
            l.retry = None;
            due.push(key);
        }
    }
    for key in due {
        accept_ready(st, cfg, key);
    }
    st.listeners.values().filter_map(|l| l.retry).min()
}

/// Starts a connect, answered at once if the socket connected at once; true when it is
/// pending (the caller then makes progress, which finishes it or arms the socket).
fn connect(t: &mut TcpEp, cfg: &NetConfig, p: Pending) -> bool {
    let req = p.req;
    if t.phase != TcpPhase::New {
        p.fail(if t.phase == TcpPhase::Connecting { tcp::CONNECTION_BUSY } else { tcp::OPERATION_INVALID });
        return false;
    }
    // Linux would take 0.0.0.0 for this host; on the robot it is no address (11.4).
    if req.addr == 0 || req.port == 0 {
        p.fail(tcp::ADDRESSERROR);
        return false;
    }
    let Ok(fd) = sys::socket(libc::SOCK_STREAM) else {
        p.fail(tcp::FAIL);
        return false;
    };
    sys::set_int_opt(fd.as_raw_fd(), libc::IPPROTO_TCP, libc::TCP_NODELAY, 1);
    let robot_lport = if req.lport != 0 { req.lport as u16 } else { t.bound.map_or(0, |b| b.1) };
    t.robot_lport = bind_source_port(cfg, &fd, robot_lport);
    let (daddr, dport) = cfg.remote(req.addr, req.port as u16, "TCP connect");
    match sys::connect(fd.as_raw_fd(), daddr, dport) {
        // Connected at once or in progress (a non-blocking TCP connect on Linux always
        // says EINPROGRESS, loopback included): progress() answers it when the socket is
        // writable, without arming it when it already is.
        Ok(_) => {
            t.attach(Some(fd));
            t.phase = TcpPhase::Connecting;
            t.connect = Some(p);
            true
        }
        Err(e) => {
            p.fail(tcp_error(e));
            false
        }
    }
}

/// TinyFTPD connects from port 20: binds the (remapped) robot port if it can, else leaves
/// the socket to an ephemeral one (3.4). The robot port to report, 0 for ephemeral.
fn bind_source_port(cfg: &NetConfig, fd: &OwnedFd, robot_lport: u16) -> u16 {
    if robot_lport == 0 {
        return 0;
    }
    let ok = cfg.local_port(robot_lport, "TCP connect source").is_some_and(|hp| {
        sys::reuse_addr(fd.as_raw_fd());
        sys::bind(fd.as_raw_fd(), 0, hp).is_ok()
    });
    if ok {
        return robot_lport;
    }
    cfg.report.warn(&format!("net: cannot connect from robot port {robot_lport}; using an ephemeral port"));
    0
}

/// Parks a Send; true when it was accepted (the caller then makes progress).
fn send(t: &mut TcpEp, valid: bool, p: Pending) -> bool {
    let req = p.req;
    let refusal = if t.send.is_some() {
        Some(tcp::CONNECTION_BUSY)
    } else if t.phase != TcpPhase::Active {
        Some(tcp::OPERATION_INVALID)
    } else if !valid {
        Some(tcp::BUFFER_INVALID)
    } else {
        t.sticky
    };
    if let Some(e) = refusal {
        p.fail(e);
        return false;
    }
    t.send = Some(SendOp { p, buf: req.buffer as usize, size: req.size as usize, done: 0 });
    true
}

/// Parks a Receive; true when it was accepted (the caller then makes progress).
fn receive(t: &mut TcpEp, valid: bool, p: Pending) -> bool {
    let req = p.req;
    let refusal = if t.recv.is_some() {
        Some(tcp::CONNECTION_BUSY)
    } else if t.phase != TcpPhase::Active {
        Some(tcp::OPERATION_INVALID)
    } else if !valid || req.size_min > req.size {
        Some(tcp::BUFFER_INVALID)
    } else {
        None
    };
    if let Some(e) = refusal {
        p.fail(e);
        return false;
    }
    let min = req.size_min.max(1) as usize;
    t.recv = Some(RecvOp { p, buf: req.buffer as usize, min, max: req.size as usize, got: 0 });
    true
}

fn ready(t: &mut TcpEp, p: Pending) {
    let req = p.req;
    let Some(fd) = t.fd.as_ref().filter(|_| t.phase == TcpPhase::Active) else { return p.fail(tcp::OPERATION_INVALID) };
    let ev = if req.op == op::TCP_READY_READ { libc::POLLIN } else { libc::POLLOUT };
    let mut r = NetResult::new(&req, tcp::SUCCESS);
    r.ready = sys::ready(fd.as_raw_fd(), ev) as i32;
    p.complete(r)
}

fn address(t: &mut TcpEp, cfg: &NetConfig, p: Pending) {
    let req = p.req;
    let Some(fd) = t.fd.as_ref().filter(|_| t.phase == TcpPhase::Active) else { return p.fail(tcp::OPERATION_INVALID) };
    let (la, lp) = sys::local_addr(fd.as_raw_fd());
    let (fa, fp) = sys::peer_addr(fd.as_raw_fd());
    let mut r = NetResult::new(&req, tcp::SUCCESS);
    r.laddr = la;
    r.lport = if t.robot_lport != 0 { t.robot_lport.into() } else { lp.into() };
    (r.faddr, r.fport) = robot_peer(cfg, fa, fp);
    p.complete(r)
}

/// Advances everything pending on a TCP endpoint without blocking, then arms its socket
/// for what still waits. If the epoll set refuses, that would wait forever: it fails
/// instead, and a warning says why.
pub(super) fn progress(st: &mut State, id: EndpointId) {
    let poller = st.poller;
    let Some(t) = tcp_in(&mut st.eps, id) else { return };
    if let Some(close) = advance(t) {
        return finish_close(st, id, close, false);
    }
    // A failed connect has closed the socket.
    let Some(fd) = t.fd.as_ref().map(|f| f.as_raw_fd()) else { return };
    let mut want = 0;
    if t.recv.is_some() {
        want |= poller::IN;
    }
    if t.send.is_some() || t.connect.is_some() {
        want |= poller::OUT;
    }
    let Err(e) = poller.arm(fd, Token::Ep(id), &mut t.armed, want) else { return };
    if t.connect.is_some() {
        // A fresh endpoint the object may connect again.
        t.attach(None);
        t.phase = TcpPhase::New;
    }
    if t.send.is_some() || t.recv.is_some() {
        t.sticky.get_or_insert(tcp::FAIL);
    }
    // A Connect never waits beside a Send or a Receive (they need an active endpoint).
    fail_pending(t, tcp::FAIL);
    let closing = t.closing.take();
    st.host.warn(&format!("net: cannot watch the socket of TCP endpoint {} (epoll_ctl: {})", id.0, std::io::Error::from_raw_os_error(e)));
    if let Some(close) = closing {
        finish_close(st, id, close, false);
    }
}

/// Connects, sends and receives as far as the socket allows; a graceful Close that is
/// due now (its Send was answered).
fn advance(t: &mut TcpEp) -> Option<Pending> {
    let fd = t.fd.as_ref()?.as_raw_fd();
    if t.phase == TcpPhase::Connecting && !finish_connect(t, fd) {
        return None;
    }
    if push_send(t, fd) {
        if let Some(close) = t.closing.take() {
            return Some(close);
        }
    }
    pull_receive(t, fd);
    None
}

/// Answers a pending Connect once the socket is writable; false while it is not done
/// (or when it failed, leaving a fresh endpoint the object may retry or close).
fn finish_connect(t: &mut TcpEp, fd: RawFd) -> bool {
    if !sys::ready(fd, libc::POLLOUT) {
        return false;
    }
    // Connecting always has its Connect pending (set together in `connect`).
    let Some(p) = t.connect.take() else { return false };
    match sys::so_error(fd) {
        0 => {
            connected(t, fd, p);
            true
        }
        e => {
            t.attach(None);
            t.phase = TcpPhase::New;
            p.fail(tcp_error(e));
            false
        }
    }
}

/// Answers a Connect whose socket is connected: the endpoint is active.
fn connected(t: &mut TcpEp, fd: RawFd, p: Pending) {
    t.phase = TcpPhase::Active;
    let (la, lp) = sys::local_addr(fd);
    let mut r = NetResult::new(&p.req, tcp::SUCCESS);
    r.laddr = la;
    r.lport = if t.robot_lport != 0 { t.robot_lport.into() } else { lp.into() };
    if t.robot_lport == 0 {
        t.robot_lport = lp;
    }
    // The robot's view: the address it connected to (before --net-map).
    r.faddr = p.req.addr;
    r.fport = p.req.port;
    p.complete(r);
}

/// Writes what the socket takes of a pending Send; true when the Send was answered.
fn push_send(t: &mut TcpEp, fd: RawFd) -> bool {
    let Some(s) = t.send.as_mut() else { return false };
    let mut outcome = None;
    while s.done < s.size {
        // SAFETY: the range was checked inside a live shared buffer when the request came (`State::valid_buffer`), and the IPStack refuses to destroy a buffer while an operation on it is pending (ENV_DESTROY_BUFFER).
        match unsafe { sys::send(fd, (s.buf + s.done) as *const u8, s.size - s.done) } {
            Ok(n) => s.done += n,
            Err(libc::EINTR) => {}
            Err(libc::EAGAIN) => {
                if t.nonblocking && s.done == 0 {
                    outcome = Some(tcp::WOULDBLOCK);
                }
                break;
            }
            Err(e) => {
                outcome = Some(tcp_error(e));
                break;
            }
        }
    }
    if s.done == s.size {
        outcome = Some(tcp::SUCCESS);
    }
    let Some(code) = outcome else { return false };
    let Some(s) = t.send.take() else { return false };
    if code == tcp::SUCCESS {
        t.stream.sent(s.size, Instant::now());
    }
    if code != tcp::SUCCESS && code != tcp::WOULDBLOCK {
        t.sticky.get_or_insert(code);
    }
    s.p.fail(code);
    true
}

/// Reads into a pending Receive: greedy, up to max; it waits only while below min (3.4).
fn pull_receive(t: &mut TcpEp, fd: RawFd) {
    let Some(r) = t.recv.as_mut() else { return };
    let mut failure = None;
    if t.eof {
        // nothing more will come
    } else if let Some(e) = t.sticky {
        failure = Some(e);
    } else {
        while r.got < r.max {
            let want = r.max - r.got;
            // SAFETY: the range was checked inside a live shared buffer when the request came (`State::valid_buffer`), and the IPStack refuses to destroy a buffer while an operation on it is pending (ENV_DESTROY_BUFFER).
            match unsafe { sys::recv(fd, (r.buf + r.got) as *mut u8, want) } {
                Ok(0) => {
                    t.eof = true;
                    break;
                }
                Ok(n) => {
                    r.got += n;
                    // A short read emptied the socket: the Receive completes without the
                    // read that would say EAGAIN. Below min it reads on, to EAGAIN or EOF:
                    // a FIN queued behind the data is then seen now, not after a wait.
                    if n < want && r.got >= r.min {
                        break;
                    }
                }
                Err(libc::EINTR) => {}
                Err(libc::EAGAIN) => break,
                Err(e) => {
                    failure = Some(tcp_error(e));
                    break;
                }
            }
        }
    }
    let done = if r.got >= r.min {
        Some((tcp::SUCCESS, r.got))
    } else if t.eof || failure.is_some() {
        if r.got > 0 {
            // bytes first; an error is reported by the next receive
            if let Some(e) = failure {
                t.sticky = Some(e);
            }
            Some((tcp::SUCCESS, r.got))
        } else {
            let code = failure.unwrap_or(tcp::CONNECTION_CLOSED);
            if failure.is_some() {
                t.sticky = Some(code);
            }
            Some((code, 0))
        }
    } else if t.nonblocking {
        Some(if r.got > 0 { (tcp::SUCCESS, r.got) } else { (tcp::WOULDBLOCK, 0) })
    } else {
        None
    };
    let Some((code, n)) = done else { return };
    if let Some(r) = t.recv.take() {
        let mut res = NetResult::new(&r.p.req, code);
        res.size = n as i32;
        r.p.complete(res);
    }
}

/// Answers what is pending on the endpoint but a Close with `code`: the Send, the
/// Receive, the Connect, the Listen, in that order.
fn fail_pending(t: &mut TcpEp, code: i32) {
    if let Some(s) = t.send.take() {
        s.p.fail(code);
    }
    if let Some(r) = t.recv.take() {
        r.p.fail(code);
    }
    if let Some(c) = t.connect.take() {
        c.fail(code);
    }
    if let Some(l) = t.listen.take() {
        l.fail(code);
    }
}

fn finish_close(st: &mut State, id: EndpointId, p: Pending, abort: bool) {
    let Some(Endpoint::Tcp(mut t)) = st.eps.remove(&id) else { return p.fail(tcp::CONNECTION_CLOSED) };
    // A connection in error is aborting (3.5): its Close resets it like an abort (3.4),
    // so the peer does not take the part it got for a whole stream.
    let abort = abort || t.sticky.is_some();
    st.remember_closed(id, PROTO_TCP);
    // Everything pending is answered before the Close reply (1.10).
    fail_pending(&mut t, tcp::CONNECTION_CLOSED);
    if let Some(key) = t.listen_key.take() {
        if let Some(l) = st.listeners.get_mut(&key) {
            l.waiters.retain(|&w| w != id);
        }
    }
    if let Some(fd) = t.fd.take() {
        if abort {
            sys::linger_abort(fd.as_raw_fd());
        } else {
            // Unread input would turn the close into a reset: drop it first.
            let mut sink = [0u8; 4096];
            for _ in 0..64 {
                // SAFETY: `sink` is a local array of `sink.len()` bytes.
                match unsafe { sys::recv(fd.as_raw_fd(), sink.as_mut_ptr(), sink.len()) } {
                    Ok(n) if n > 0 => continue,
                    _ => break,
                }
            }
        }
        drop(fd);
    }
    p.fail(tcp::SUCCESS);
}
