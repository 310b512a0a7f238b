//! UDP endpoints (network-api 4): Bind, Connect, Send, Receive and Close on host datagram
//! sockets; a Send or Receive that would block waits for the poll thread.
use std::os::fd::{AsRawFd, OwnedFd, RawFd};

use super::codes::{op, udp, udp_error, PROTO_UDP};
use super::config::NetConfig;
use super::poller::{self, Armed, Token};
use super::stack::{robot_peer, Endpoint, State};
use super::{sys, EndpointId, NetResult, Pending};

#[derive(Default)]
pub struct UdpEp {
    fd: Option<OwnedFd>,
    /// Whether `fd` is armed in the poll thread's epoll set, and for what.
    armed: Armed,
    robot_lport: u16,
    connected: bool,
    nonblocking: bool,
    /// (reply, buffer, size, destination unless connected)
    send: Option<(Pending, usize, usize, Option<(u32, u16)>)>,
    /// (reply, buffer, size)
    recv: Option<(Pending, usize, usize)>,
}

impl UdpEp {
    /// Its socket reported readiness: the kernel disarmed it (one-shot).
    pub(super) fn fired(&mut self) {
        self.armed.fired();
    }

    /// Its socket's descriptor (for the tests' stand-in sockets).
    #[cfg(test)]
    pub(super) fn raw_fd(&self) -> Option<RawFd> {
        self.fd.as_ref().map(|f| f.as_raw_fd())
    }

    /// Whether a pending Send or Receive reads or writes `[base, base+size)`.
    pub(super) fn uses_buffer(&self, base: usize, size: usize) -> bool {
        let inside = |p: usize| p >= base && p < base + size;
        self.send.as_ref().is_some_and(|s| inside(s.1)) || self.recv.as_ref().is_some_and(|r| inside(r.1))
    }
}

/// Entry point of every UDP request.
pub(super) fn udp_op(st: &mut State, cfg: &NetConfig, p: Pending) {
    let req = p.req;
    let id = req.endpoint;
    // Read before the endpoint is borrowed: whether the buffer is a shared one (Send,
    // Receive) and the robot's own address (Bind).
    let valid = st.valid_buffer(req.buffer, req.size);
    let robot_ip = if req.op == op::UDP_BIND { st.robot_ip() } else { 0 };
    let Some(u) = st.udp(id) else { return p.fail(udp::CONNECTION_CLOSED) };
    match req.op {
        op::UDP_BIND => bind(u, cfg, robot_ip, p),
        op::UDP_CONNECT | op::UDP_RESET_CONNECT => connect(u, cfg, p),
        op::UDP_SEND => {
            if send(u, cfg, valid, p) {
                progress(st, cfg, id);
            }
        }
        op::UDP_RECEIVE => {
            if receive(u, valid, p) {
                progress(st, cfg, id);
            }
        }
        op::UDP_CLOSE => close(st, id, p),
        op::UDP_SET_BLOCKING => {
            u.nonblocking = req.flags & 1 == 0;
            p.fail(udp::SUCCESS)
        }
        op::UDP_READY_READ | op::UDP_READY_WRITE => {
            let Some(fd) = u.fd.as_ref() else { return p.fail(udp::OPERATION_INVALID) };
            let ev = if req.op == op::UDP_READY_READ { libc::POLLIN } else { libc::POLLOUT };
            let mut r = NetResult::new(&req, udp::SUCCESS);
            r.ready = sys::ready(fd.as_raw_fd(), ev) as i32;
            p.complete(r)
        }
        op::UDP_ADDRESS => address(u, cfg, p),
        _ => p.fail(udp::OPERATION_UNKNOWN),
    }
}

fn bind(u: &mut UdpEp, cfg: &NetConfig, robot_ip: u32, p: Pending) {
    let req = p.req;
    if u.fd.is_some() {
        return p.fail(udp::OPERATION_INVALID);
    }
    let host_addr = cfg.local_addr(req.addr, robot_ip);
    let Some(host_port) = cfg.local_port(req.port as u16, "UDP bind") else { return p.fail(udp::ADDRESSERROR) };
    let Ok(fd) = sys::socket(libc::SOCK_DGRAM) else { return p.fail(udp::FAIL) };
    if let Err(e) = sys::bind(fd.as_raw_fd(), host_addr, host_port) {
        return p.fail(udp_error(e));
    }
    let (la, lp) = sys::local_addr(fd.as_raw_fd());
    u.robot_lport = if req.port != 0 { req.port as u16 } else { lp };
    u.fd = Some(fd);
    let mut r = NetResult::new(&req, udp::SUCCESS);
    r.laddr = la;
    r.lport = u.robot_lport.into();
    p.complete(r)
}

/// Connect, or (ResetConnect) forget the peer.
fn connect(u: &mut UdpEp, cfg: &NetConfig, p: Pending) {
    let req = p.req;
    let Some(fd) = u.fd.as_ref().map(|f| f.as_raw_fd()) else { return p.fail(udp::OPERATION_INVALID) };
    let res = if req.op == op::UDP_CONNECT {
        if req.addr == 0 {
            return p.fail(udp::ADDRESSERROR);
        }
        let (a, port) = cfg.remote(req.addr, req.port as u16, "UDP connect");
        sys::connect(fd, a, port).map(|_| ())
    } else {
        sys::disconnect(fd)
    };
    match res {
        Ok(()) => {
            u.connected = req.op == op::UDP_CONNECT;
            p.fail(udp::SUCCESS)
        }
        Err(e) => p.fail(udp_error(e)),
    }
}

/// Parks a Send; true when it was accepted (the caller then makes progress).
fn send(u: &mut UdpEp, cfg: &NetConfig, valid: bool, p: Pending) -> bool {
    let req = p.req;
    let refusal = if u.send.is_some() {
        Some(udp::CONNECTION_BUSY)
    } else if u.fd.is_none() {
        Some(udp::OPERATION_INVALID)
    } else if !valid {
        Some(udp::BUFFER_INVALID)
    } else if !u.connected && (req.addr == 0 || req.port == 0) {
        Some(udp::ADDRESSERROR)
    } else {
        None
    };
    if let Some(e) = refusal {
        p.fail(e);
        return false;
    }
    let to = (!u.connected).then(|| cfg.remote(req.addr, req.port as u16, "UDP send"));
    u.send = Some((p, req.buffer as usize, req.size as usize, to));
    true
}

/// Parks a Receive; true when it was accepted (the caller then makes progress).
fn receive(u: &mut UdpEp, valid: bool, p: Pending) -> bool {
    let req = p.req;
    let refusal = if u.recv.is_some() {
        Some(udp::CONNECTION_BUSY)
    } else if u.fd.is_none() {
        Some(udp::OPERATION_INVALID)
    } else if !valid {
        Some(udp::BUFFER_INVALID)
    } else {
        None
    };
    if let Some(e) = refusal {
        p.fail(e);
        return false;
    }
    u.recv = Some((p, req.buffer as usize, req.size as usize));
    true
}

fn close(st: &mut State, id: EndpointId, p: Pending) {
    let Some(Endpoint::Udp(mut u)) = st.eps.remove(&id) else { return p.fail(udp::CONNECTION_CLOSED) };
    st.remember_closed(id, PROTO_UDP);
    if let Some((r, ..)) = u.recv.take() {
        r.fail(udp::CONNECTION_CLOSED);
    }
    if let Some((s, ..)) = u.send.take() {
        s.fail(udp::CONNECTION_CLOSED);
    }
    drop(u);
    p.fail(udp::SUCCESS)
}

fn address(u: &mut UdpEp, cfg: &NetConfig, p: Pending) {
    let req = p.req;
    let Some(fd) = u.fd.as_ref() else { return p.fail(udp::OPERATION_INVALID) };
    let (la, _) = sys::local_addr(fd.as_raw_fd());
    let mut r = NetResult::new(&req, udp::SUCCESS);
    r.laddr = la;
    r.lport = u.robot_lport.into();
    if u.connected {
        let (fa, fp) = sys::peer_addr(fd.as_raw_fd());
        (r.faddr, r.fport) = robot_peer(cfg, fa, fp);
    }
    p.complete(r)
}

/// Sends and receives what the socket allows without blocking, then arms the socket for
/// what still waits (if the epoll set refuses, that fails instead, with a warning).
pub(super) fn progress(st: &mut State, cfg: &NetConfig, id: EndpointId) {
    let poller = st.poller;
    let Some(u) = st.udp(id) else { return };
    let Some(fd) = u.fd.as_ref().map(|f| f.as_raw_fd()) else { return };
    advance(u, cfg, fd);
    let want = if u.recv.is_some() { poller::IN } else { 0 } | if u.send.is_some() { poller::OUT } else { 0 };
    let Err(e) = poller.arm(fd, Token::Ep(id), &mut u.armed, want) else { return };
    if let Some((p, ..)) = u.send.take() {
        p.fail(udp::FAIL);
    }
    if let Some((p, ..)) = u.recv.take() {
        p.fail(udp::FAIL);
    }
    st.host.warn(&format!("net: cannot watch the socket of UDP endpoint {} (epoll_ctl: {})", id.0, std::io::Error::from_raw_os_error(e)));
}

fn advance(u: &mut UdpEp, cfg: &NetConfig, fd: RawFd) {
    if let Some((_, buf, size, to)) = u.send.as_ref() {
        // SAFETY: the range was checked inside a live shared buffer when the request came (`State::valid_buffer`), and the IPStack refuses to destroy a buffer while an operation on it is pending (ENV_DESTROY_BUFFER).
        let code = match unsafe { sys::sendto(fd, *buf as *const u8, *size, *to) } {
            Ok(_) => Some(udp::SUCCESS),
            Err(libc::EAGAIN | libc::EINTR) => u.nonblocking.then_some(udp::WOULDBLOCK),
            Err(e) => Some(udp_error(e)),
        };
        if let Some(code) = code {
            if let Some((p, ..)) = u.send.take() {
                p.fail(code);
            }
        }
    }
    if let Some((_, buf, size)) = u.recv.as_ref() {
        // SAFETY: the range was checked inside a live shared buffer when the request came (`State::valid_buffer`), and the IPStack refuses to destroy a buffer while an operation on it is pending (ENV_DESTROY_BUFFER).
        let out = match unsafe { sys::recvfrom(fd, *buf as *mut u8, *size) } {
            Ok((n, (fa, fp))) => Some((udp::SUCCESS, n, fa, fp)),
            Err(libc::EAGAIN | libc::EINTR) => u.nonblocking.then_some((udp::WOULDBLOCK, 0, 0, 0)),
            Err(e) => Some((udp_error(e), 0, 0, 0)),
        };
        if let Some((code, n, fa, fp)) = out {
            if let Some((p, ..)) = u.recv.take() {
                let mut r = NetResult::new(&p.req, code);
                r.size = n as i32;
                (r.faddr, r.fport) = robot_peer(cfg, fa, fp);
                p.complete(r);
            }
        }
    }
}
