//! Endpoint state and the operations of the environment, TCP and UDP endpoints
//! (network-api 2–4), plus the poll thread that finishes what would block.
use std::collections::{BTreeMap, HashMap, VecDeque};
use std::os::fd::{AsRawFd, OwnedFd, RawFd};
use std::time::{Duration, Instant};

use super::config::{self, NetConfig};
use super::sys;
use super::{dns, Net, NetResult, Pending};

pub const PROTO_ENV: i32 = 0;
pub const PROTO_INIT: i32 = 100;
pub const PROTO_TCP: i32 = 1;
pub const PROTO_UDP: i32 = 2;
pub const PROTO_DNS: i32 = 4;

/// `antModuleRef.module` of every endpoint (never null: null means the environment).
const MODULE_MAGIC: usize = 0x414e_5400;
/// How long a failed Listen waits before its error reply: samples retry at once in a
/// tight loop (3.4).
const LISTEN_RETRY_DELAY: Duration = Duration::from_secs(1);

/// antError
pub mod ant {
    pub const SUCCESS: i32 = 0;
    pub const FAIL: i32 = 1;
    pub const NOMEMORY: i32 = 2;
    pub const INVALIDPTR: i32 = 3;
    pub const REGISTRY_NO_KEY: i32 = 23;
    pub const REGISTRY_INVALID_KEY: i32 = 25;
    pub const ENDPOINT_NOFACTORY: i32 = 27;
}

/// TCPEndpointError (3.1)
pub mod tcp {
    pub const SUCCESS: i32 = 0;
    pub const FAIL: i32 = 1;
    pub const CONNECTION_CLOSED: i32 = 2;
    pub const CONNECTION_RESET: i32 = 3;
    pub const CONNECTION_TIMEOUT: i32 = 4;
    pub const CONNECTION_BUSY: i32 = 5;
    pub const ADDRESSINUSE: i32 = 6;
    pub const ADDRESSERROR: i32 = 7;
    pub const PORT_UNREACHABLE: i32 = 8;
    pub const HOST_UNREACHABLE: i32 = 10;
    pub const NETWORK_UNREACHABLE: i32 = 11;
    pub const MESSAGE_TOO_LONG: i32 = 12;
    pub const WOULDBLOCK: i32 = 15;
    pub const BUFFER_INVALID: i32 = 16;
    pub const OPERATION_INVALID: i32 = 17;
    pub const OPERATION_UNKNOWN: i32 = 18;
}

/// UDPEndpointError (4.1) — not the TCP numbers.
pub mod udp {
    pub const SUCCESS: i32 = 0;
    pub const FAIL: i32 = 1;
    pub const CONNECTION_CLOSED: i32 = 2;
    pub const CONNECTION_BUSY: i32 = 3;
    pub const ADDRESSINUSE: i32 = 4;
    pub const ADDRESSERROR: i32 = 5;
    pub const PORT_UNREACHABLE: i32 = 6;
    pub const HOST_UNREACHABLE: i32 = 8;
    pub const NETWORK_UNREACHABLE: i32 = 9;
    pub const MESSAGE_TOO_LONG: i32 = 10;
    pub const BUFFER_INVALID: i32 = 13;
    pub const OPERATION_INVALID: i32 = 14;
    pub const OPERATION_UNKNOWN: i32 = 15;
    pub const WOULDBLOCK: i32 = 16;
}

/// Linux errno → TCPEndpointError (7).
pub fn tcp_error(e: i32) -> i32 {
    match e {
        libc::ECONNREFUSED => tcp::PORT_UNREACHABLE,
        libc::ETIMEDOUT => tcp::CONNECTION_TIMEOUT,
        libc::ECONNRESET | libc::EPIPE | libc::ECONNABORTED => tcp::CONNECTION_RESET,
        libc::EADDRINUSE => tcp::ADDRESSINUSE,
        libc::EADDRNOTAVAIL | libc::EACCES | libc::EPERM | libc::EINVAL => tcp::ADDRESSERROR,
        libc::EHOSTUNREACH => tcp::HOST_UNREACHABLE,
        libc::ENETUNREACH => tcp::NETWORK_UNREACHABLE,
        libc::EMSGSIZE => tcp::MESSAGE_TOO_LONG,
        _ => tcp::FAIL,
    }
}

/// Linux errno → UDPEndpointError (7).
pub fn udp_error(e: i32) -> i32 {
    match e {
        libc::ECONNREFUSED => udp::PORT_UNREACHABLE,
        libc::EADDRINUSE => udp::ADDRESSINUSE,
        libc::EADDRNOTAVAIL | libc::EACCES | libc::EPERM | libc::EINVAL => udp::ADDRESSERROR,
        libc::EHOSTUNREACH => udp::HOST_UNREACHABLE,
        libc::ENETUNREACH => udp::NETWORK_UNREACHABLE,
        libc::EMSGSIZE => udp::MESSAGE_TOO_LONG,
        _ => udp::FAIL,
    }
}

mod op {
    pub const ENV_CREATE_ENDPOINT: i32 = -1;
    pub const ENV_CREATE_BUFFER: i32 = -2;
    pub const ENV_DESTROY_BUFFER: i32 = -3;
    pub const INIT_SET: i32 = -1;
    pub const INIT_START: i32 = -2;
    pub const INIT_GET: i32 = -3;

    pub const TCP_BIND: i32 = 1;
    pub const TCP_LISTEN: i32 = 2;
    pub const TCP_CONNECT: i32 = 3;
    pub const TCP_SEND: i32 = 4;
    pub const TCP_RECEIVE: i32 = 5;
    pub const TCP_CLOSE: i32 = 6;
    pub const TCP_SET_BLOCKING: i32 = 7;
    pub const TCP_READY_READ: i32 = 8;
    pub const TCP_READY_WRITE: i32 = 9;
    pub const TCP_ADDRESS: i32 = 13;

    pub const UDP_BIND: i32 = 0;
    pub const UDP_CONNECT: i32 = 1;
    pub const UDP_SEND: i32 = 2;
    pub const UDP_RECEIVE: i32 = 3;
    pub const UDP_CLOSE: i32 = 4;
    pub const UDP_SET_BLOCKING: i32 = 9;
    pub const UDP_READY_READ: i32 = 10;
    pub const UDP_READY_WRITE: i32 = 11;
    pub const UDP_ADDRESS: i32 = 12;
    pub const UDP_RESET_CONNECT: i32 = 13;
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum TcpPhase {
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

pub struct TcpEp {
    phase: TcpPhase,
    fd: Option<OwnedFd>,
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
}

pub struct UdpEp {
    fd: Option<OwnedFd>,
    robot_lport: u16,
    connected: bool,
    nonblocking: bool,
    send: Option<(Pending, usize, usize, Option<(u32, u16)>)>,
    recv: Option<(Pending, usize, usize)>,
}

pub enum Endpoint {
    Tcp(TcpEp),
    Udp(UdpEp),
    Dns(dns::DnsEp),
}

struct Listener {
    fd: OwnedFd,
    waiters: VecDeque<u32>,
}

#[derive(Clone)]
enum RegValue {
    Str(String),
    Int(i32),
}

pub struct State {
    next_id: u32,
    pub eps: HashMap<u32, Endpoint>,
    /// Protocols of closed endpoints, so late messages get that protocol's CLOSED code.
    tombstones: HashMap<u32, i32>,
    listeners: HashMap<(u32, u16), Listener>,
    /// Live shared buffers: region id → (base, size).
    buffers: BTreeMap<u32, (usize, usize)>,
    next_region: u32,
    registry: Option<BTreeMap<String, RegValue>>,
    pub dns_servers: Option<Vec<u32>>,
    pub domain: Option<String>,
}

/// What the poll thread watches.
#[derive(Clone, Copy)]
enum Token {
    Listener((u32, u16)),
    Ep(u32),
}

impl State {
    pub fn new() -> State {
        State {
            next_id: 1,
            eps: HashMap::new(),
            tombstones: HashMap::new(),
            listeners: HashMap::new(),
            buffers: BTreeMap::new(),
            next_region: 1,
            registry: None,
            dns_servers: None,
            domain: None,
        }
    }

    pub fn remember_closed(&mut self, id: u32, proto: i32) {
        self.tombstones.insert(id, proto);
    }

    pub fn protocol_of(&self, id: u32) -> i32 {
        match self.eps.get(&id) {
            Some(Endpoint::Tcp(_)) => PROTO_TCP,
            Some(Endpoint::Udp(_)) => PROTO_UDP,
            Some(Endpoint::Dns(_)) => PROTO_DNS,
            None => self.tombstones.get(&id).copied().unwrap_or(-1),
        }
    }

    fn registry(&mut self) -> &mut BTreeMap<String, RegValue> {
        self.registry.get_or_insert_with(|| config::wlan_settings().into_iter().map(|(k, v)| (k, RegValue::Str(v))).collect())
    }

    pub fn registry_value(&mut self, key: &str) -> Option<String> {
        match self.registry().get(key)? {
            RegValue::Str(s) => Some(s.clone()),
            RegValue::Int(i) => Some(i.to_string()),
        }
    }

    /// The robot's own (virtual) address, ETHER_IP.
    fn robot_ip(&mut self) -> u32 {
        self.registry_value("ETHER_IP").and_then(|s| config::parse_ip(&s)).unwrap_or(0)
    }

    /// DNS servers: SetServerAddresses, else DNS_SERVER_1..3 of the robot's settings.
    pub fn configured_dns_servers(&mut self) -> Vec<u32> {
        if let Some(s) = &self.dns_servers {
            return s.clone();
        }
        (1..=3).filter_map(|i| self.registry_value(&format!("DNS_SERVER_{i}"))).filter_map(|s| config::parse_ip(&s)).collect()
    }

    pub fn default_domain(&mut self) -> Option<String> {
        if let Some(d) = &self.domain {
            return Some(d.clone());
        }
        self.registry_value("DNS_DEFDNAME").filter(|d| !d.is_empty())
    }

    /// Whether `[ptr, ptr+len)` lies inside one live shared buffer (and len > 0).
    fn valid_buffer(&self, ptr: *mut u8, len: i32) -> bool {
        if len <= 0 || ptr.is_null() {
            return false;
        }
        let (p, n) = (ptr as usize, len as usize);
        self.buffers.range(..).any(|(_, &(base, size))| p >= base && p.checked_add(n).is_some_and(|end| end <= base + size))
    }

    fn tcp(&mut self, id: u32) -> Option<&mut TcpEp> {
        match self.eps.get_mut(&id) {
            Some(Endpoint::Tcp(t)) => Some(t),
            _ => None,
        }
    }

    fn udp(&mut self, id: u32) -> Option<&mut UdpEp> {
        match self.eps.get_mut(&id) {
            Some(Endpoint::Udp(u)) => Some(u),
            _ => None,
        }
    }

    fn poll_set(&self) -> (Vec<libc::pollfd>, Vec<Token>, Option<Instant>) {
        let mut fds = Vec::new();
        let mut toks = Vec::new();
        let mut deadline: Option<Instant> = None;
        for (key, l) in &self.listeners {
            if !l.waiters.is_empty() {
                fds.push(libc::pollfd { fd: l.fd.as_raw_fd(), events: libc::POLLIN, revents: 0 });
                toks.push(Token::Listener(*key));
            }
        }
        for (&id, ep) in &self.eps {
            let (fd, ev): (Option<RawFd>, libc::c_short) = match ep {
                Endpoint::Tcp(t) => {
                    if let Some((at, _)) = t.listen_error {
                        deadline = Some(deadline.map_or(at, |d| d.min(at)));
                    }
                    let mut ev = 0;
                    if t.connect.is_some() || t.send.is_some() {
                        ev |= libc::POLLOUT;
                    }
                    if t.recv.is_some() {
                        ev |= libc::POLLIN;
                    }
                    (t.fd.as_ref().map(|f| f.as_raw_fd()), ev)
                }
                Endpoint::Udp(u) => {
                    let mut ev = 0;
                    if u.send.is_some() {
                        ev |= libc::POLLOUT;
                    }
                    if u.recv.is_some() {
                        ev |= libc::POLLIN;
                    }
                    (u.fd.as_ref().map(|f| f.as_raw_fd()), ev)
                }
                Endpoint::Dns(_) => (None, 0),
            };
            if let (Some(fd), true) = (fd, ev != 0) {
                fds.push(libc::pollfd { fd, events: ev, revents: 0 });
                toks.push(Token::Ep(id));
            }
        }
        (fds, toks, deadline)
    }

    fn fire_delayed(&mut self) {
        let now = Instant::now();
        let due: Vec<u32> = self
            .eps
            .iter()
            .filter_map(|(&id, ep)| match ep {
                Endpoint::Tcp(t) if t.listen_error.is_some_and(|(at, _)| at <= now) => Some(id),
                _ => None,
            })
            .collect();
        for id in due {
            let t = self.tcp(id).expect("listed above");
            let (_, err) = t.listen_error.take().expect("listed above");
            t.phase = TcpPhase::New;
            if let Some(p) = t.listen.take() {
                p.fail(err);
            }
        }
    }
}

/// Entry point of every request (caller's thread).
pub fn handle(net: &'static Net, p: Pending) {
    let mut st = net.lock();
    let req = p.req;
    match req.proto {
        PROTO_INIT => init_op(&mut st, p),
        PROTO_ENV => env_op(&mut st, p),
        PROTO_TCP => tcp_op(&mut st, &net.config, p),
        PROTO_UDP => udp_op(&mut st, &net.config, p),
        PROTO_DNS => dns::dns_op(&mut st, net, p),
        // an endpoint that never existed: CLOSED is 2 in both TCP and UDP numbering
        _ => p.fail(tcp::CONNECTION_CLOSED),
    }
    drop(st);
    net.wake();
}

fn init_op(st: &mut State, p: Pending) {
    let req = p.req;
    let key = req.name().trim_end_matches('\0').to_ascii_uppercase();
    match req.op {
        op::INIT_SET => {
            if key.is_empty() {
                return p.fail(ant::REGISTRY_INVALID_KEY);
            }
            let v = if req.value2 == -1 { RegValue::Int(req.value) } else { RegValue::Str(req.str_value()) };
            st.registry().insert(key, v);
            p.fail(ant::SUCCESS)
        }
        op::INIT_START => p.fail(ant::SUCCESS),
        op::INIT_GET => {
            let Some(v) = st.registry().get(&key).cloned() else { return p.fail(ant::REGISTRY_NO_KEY) };
            let mut r = NetResult::new(&req, ant::SUCCESS);
            match v {
                RegValue::Int(i) => {
                    r.param_type = -1;
                    r.i32_ = i;
                }
                RegValue::Str(s) => {
                    r.param_type = -2;
                    let n = s.len().min(32);
                    r.str_[..n].copy_from_slice(&s.as_bytes()[..n]);
                }
            }
            p.complete(r)
        }
        _ => p.fail(ant::FAIL),
    }
}

fn env_op(st: &mut State, p: Pending) {
    let req = p.req;
    match req.op {
        op::ENV_CREATE_ENDPOINT => {
            let ep = match req.value {
                PROTO_TCP => Endpoint::Tcp(TcpEp {
                    phase: TcpPhase::New,
                    fd: None,
                    nonblocking: false,
                    bound: None,
                    robot_lport: 0,
                    listen: None,
                    listen_key: None,
                    listen_error: None,
                    connect: None,
                    send: None,
                    recv: None,
                    closing: None,
                    eof: false,
                    sticky: None,
                }),
                PROTO_UDP => Endpoint::Udp(UdpEp { fd: None, robot_lport: 0, connected: false, nonblocking: false, send: None, recv: None }),
                PROTO_DNS => Endpoint::Dns(dns::DnsEp::default()),
                _ => return p.fail(ant::ENDPOINT_NOFACTORY),
            };
            let id = st.next_id;
            st.next_id += 1;
            st.eps.insert(id, ep);
            let mut r = NetResult::new(&req, ant::SUCCESS);
            r.module = MODULE_MAGIC as *mut _;
            r.endpoint = id;
            p.complete(r)
        }
        op::ENV_CREATE_BUFFER => {
            let size = req.value as u32 as usize;
            if size == 0 || size > 64 << 20 {
                return p.fail(ant::NOMEMORY);
            }
            // The manual: sizes are rounded up to whole 4 KiB pages.
            let rounded = size.div_ceil(4096) * 4096;
            let layout = std::alloc::Layout::from_size_align(rounded, 4096).expect("valid layout");
            // SAFETY: non-zero size.
            let base = unsafe { std::alloc::alloc_zeroed(layout) };
            if base.is_null() {
                return p.fail(ant::NOMEMORY);
            }
            let region = st.next_region;
            st.next_region += 1;
            st.buffers.insert(region, (base as usize, rounded));
            let mut r = NetResult::new(&req, ant::SUCCESS);
            r.region = region;
            r.base = base.cast();
            r.buf_size = rounded as u32;
            p.complete(r)
        }
        op::ENV_DESTROY_BUFFER => match st.buffers.get(&req.region) {
            Some(&(base, size)) if base == req.region_base as usize => {
                st.buffers.remove(&req.region);
                let layout = std::alloc::Layout::from_size_align(size, 4096).expect("valid layout");
                // SAFETY: allocated above with this layout, removed from the table once.
                unsafe { std::alloc::dealloc(base as *mut u8, layout) };
                p.fail(ant::SUCCESS)
            }
            _ => p.fail(ant::INVALIDPTR),
        },
        _ => p.fail(ant::FAIL),
    }
}

// ---------------------------------------------------------------- TCP

fn tcp_op(st: &mut State, cfg: &NetConfig, p: Pending) {
    let req = p.req;
    let id = req.endpoint;
    if st.tcp(id).is_none() {
        return p.fail(tcp::CONNECTION_CLOSED);
    }
    if st.tcp(id).unwrap().closing.is_some() {
        return p.fail(tcp::CONNECTION_CLOSED);
    }
    match req.op {
        op::TCP_BIND => {
            let t = st.tcp(id).unwrap();
            if t.phase != TcpPhase::New {
                return p.fail(tcp::OPERATION_INVALID);
            }
            t.bound = Some((req.laddr, req.lport as u16));
            let mut r = NetResult::new(&req, tcp::SUCCESS);
            r.laddr = cfg.local_addr(req.laddr, 0);
            r.lport = req.lport;
            p.complete(r)
        }
        op::TCP_LISTEN => tcp_listen(st, cfg, id, p),
        op::TCP_CONNECT => tcp_connect(st, cfg, id, p),
        op::TCP_SEND => {
            let valid = st.valid_buffer(req.buffer, req.size);
            let t = st.tcp(id).unwrap();
            if t.send.is_some() {
                return p.fail(tcp::CONNECTION_BUSY);
            }
            if t.phase != TcpPhase::Active {
                return p.fail(tcp::OPERATION_INVALID);
            }
            if !valid {
                return p.fail(tcp::BUFFER_INVALID);
            }
            if let Some(e) = t.sticky {
                return p.fail(e);
            }
            t.send = Some(SendOp { p, buf: req.buffer as usize, size: req.size as usize, done: 0 });
            tcp_progress(st, id);
        }
        op::TCP_RECEIVE => {
            let valid = st.valid_buffer(req.buffer, req.size);
            let t = st.tcp(id).unwrap();
            if t.recv.is_some() {
                return p.fail(tcp::CONNECTION_BUSY);
            }
            if t.phase != TcpPhase::Active {
                return p.fail(tcp::OPERATION_INVALID);
            }
            if !valid || req.size_min > req.size {
                return p.fail(tcp::BUFFER_INVALID);
            }
            let min = req.size_min.max(1) as usize;
            t.recv = Some(RecvOp { p, buf: req.buffer as usize, min, max: req.size as usize, got: 0 });
            tcp_progress(st, id);
        }
        op::TCP_CLOSE => {
            let abort = req.flags & 1 != 0;
            let t = st.tcp(id).unwrap();
            if !abort && t.send.is_some() {
                // Flush first; the Close reply comes after the send's (1.10).
                t.closing = Some(p);
                return;
            }
            tcp_finish_close(st, id, p, abort);
        }
        op::TCP_SET_BLOCKING => {
            st.tcp(id).unwrap().nonblocking = req.flags & 1 == 0;
            p.fail(tcp::SUCCESS)
        }
        op::TCP_READY_READ | op::TCP_READY_WRITE => {
            let t = st.tcp(id).unwrap();
            let Some(fd) = t.fd.as_ref().filter(|_| t.phase == TcpPhase::Active) else { return p.fail(tcp::OPERATION_INVALID) };
            let ev = if req.op == op::TCP_READY_READ { libc::POLLIN } else { libc::POLLOUT };
            let mut r = NetResult::new(&req, tcp::SUCCESS);
            r.ready = sys::ready(fd.as_raw_fd(), ev) as i32;
            p.complete(r)
        }
        op::TCP_ADDRESS => {
            let t = st.tcp(id).unwrap();
            let Some(fd) = t.fd.as_ref().filter(|_| t.phase == TcpPhase::Active) else { return p.fail(tcp::OPERATION_INVALID) };
            let (la, lp) = sys::local_addr(fd.as_raw_fd());
            let (fa, fp) = sys::peer_addr(fd.as_raw_fd());
            let mut r = NetResult::new(&req, tcp::SUCCESS);
            r.laddr = la;
            r.lport = if t.robot_lport != 0 { t.robot_lport.into() } else { lp.into() };
            (r.faddr, r.fport) = robot_peer(cfg, fa, fp);
            p.complete(r)
        }
        _ => p.fail(tcp::OPERATION_UNKNOWN),
    }
}

fn tcp_listen(st: &mut State, cfg: &NetConfig, id: u32, p: Pending) {
    let req = p.req;
    let bound = st.tcp(id).unwrap().bound;
    let t = st.tcp(id).unwrap();
    match t.phase {
        TcpPhase::New => {}
        TcpPhase::Listening => return p.fail(tcp::CONNECTION_BUSY),
        _ => return p.fail(tcp::OPERATION_INVALID),
    }
    let robot_port = if req.lport != 0 { req.lport as u16 } else { bound.map_or(0, |b| b.1) };
    let robot_addr = bound.map_or(0, |b| b.0);
    let robot_ip = st.robot_ip();
    let host_addr = cfg.local_addr(robot_addr, robot_ip);
    let key = match cfg.local_port(robot_port, "TCP listen") {
        None => Err(tcp::ADDRESSERROR),
        Some(host_port) => {
            if host_port != 0 && st.listeners.contains_key(&(host_addr, host_port)) {
                Ok((host_addr, host_port))
            } else {
                open_listener(host_addr, host_port).map(|fd| {
                    let key = (host_addr, sys::local_addr(fd.as_raw_fd()).1);
                    st.listeners.insert(key, Listener { fd, waiters: VecDeque::new() });
                    key
                })
            }
        }
    };
    let t = st.tcp(id).unwrap();
    t.phase = TcpPhase::Listening;
    t.listen = Some(p);
    match key {
        Ok(key) => {
            t.robot_lport = if robot_port != 0 { robot_port } else { key.1 };
            t.listen_key = Some(key);
            st.listeners.get_mut(&key).expect("just made").waiters.push_back(id);
            accept_ready(st, cfg, key);
        }
        Err(e) => t.listen_error = Some((Instant::now() + LISTEN_RETRY_DELAY, e)),
    }
}

fn open_listener(addr: u32, port: u16) -> Result<OwnedFd, i32> {
    let fd = sys::socket(libc::SOCK_STREAM).map_err(|_| tcp::FAIL)?;
    sys::reuse_addr(fd.as_raw_fd());
    sys::bind(fd.as_raw_fd(), addr, port).map_err(tcp_error)?;
    sys::listen(fd.as_raw_fd(), 16).map_err(tcp_error)?;
    Ok(fd)
}

/// Hands waiting connections of a listener to its Listen endpoints, FIFO.
fn accept_ready(st: &mut State, cfg: &NetConfig, key: (u32, u16)) {
    loop {
        let Some(l) = st.listeners.get_mut(&key) else { return };
        let Some(&id) = l.waiters.front() else { return };
        let conn = match sys::accept(l.fd.as_raw_fd()) {
            Ok(c) => c,
            Err(libc::EINTR | libc::ECONNABORTED) => continue,
            Err(_) => return, // EAGAIN: nobody yet
        };
        l.waiters.pop_front();
        let (la, _) = sys::local_addr(conn.as_raw_fd());
        let (fa, fp) = sys::peer_addr(conn.as_raw_fd());
        sys::set_int_opt(conn.as_raw_fd(), libc::IPPROTO_TCP, libc::TCP_NODELAY, 1);
        let Some(t) = st.tcp(id) else { continue };
        t.fd = Some(conn);
        t.phase = TcpPhase::Active;
        t.listen_key = None;
        let p = t.listen.take().expect("a waiter has a pending listen");
        let mut r = NetResult::new(&p.req, tcp::SUCCESS);
        r.laddr = la;
        r.lport = t.robot_lport.into();
        (r.faddr, r.fport) = robot_peer(cfg, fa, fp);
        p.complete(r);
    }
}

fn tcp_connect(st: &mut State, cfg: &NetConfig, id: u32, p: Pending) {
    let req = p.req;
    let bound = st.tcp(id).unwrap().bound;
    if st.tcp(id).unwrap().phase != TcpPhase::New {
        return p.fail(if st.tcp(id).unwrap().phase == TcpPhase::Connecting { tcp::CONNECTION_BUSY } else { tcp::OPERATION_INVALID });
    }
    // Linux would take 0.0.0.0 for this host; on the robot it is no address (11.4).
    if req.addr == 0 || req.port == 0 {
        return p.fail(tcp::ADDRESSERROR);
    }
    let Ok(fd) = sys::socket(libc::SOCK_STREAM) else { return p.fail(tcp::FAIL) };
    sys::set_int_opt(fd.as_raw_fd(), libc::IPPROTO_TCP, libc::TCP_NODELAY, 1);
    let robot_lport = if req.lport != 0 { req.lport as u16 } else { bound.map_or(0, |b| b.1) };
    let mut reported_lport = 0;
    if robot_lport != 0 {
        // TinyFTPD connects from port 20: bind the (remapped) port if we can, else
        // fall back to an ephemeral one (3.4).
        let ok = cfg.local_port(robot_lport, "TCP connect source").is_some_and(|hp| {
            sys::reuse_addr(fd.as_raw_fd());
            sys::bind(fd.as_raw_fd(), 0, hp).is_ok()
        });
        if ok {
            reported_lport = robot_lport;
        } else if !cfg.quiet {
            eprintln!("net: cannot connect from robot port {robot_lport}; using an ephemeral port");
        }
    }
    let (daddr, dport) = cfg.remote(req.addr, req.port as u16, "TCP connect");
    let t = st.tcp(id).unwrap();
    t.robot_lport = reported_lport;
    match sys::connect(fd.as_raw_fd(), daddr, dport) {
        Ok(done) => {
            t.fd = Some(fd);
            t.phase = TcpPhase::Connecting;
            t.connect = Some(p);
            if done {
                tcp_progress(st, id);
            }
        }
        Err(e) => p.fail(tcp_error(e)),
    }
}

/// Advances everything pending on a TCP endpoint without blocking.
fn tcp_progress(st: &mut State, id: u32) {
    let Some(t) = st.tcp(id) else { return };
    let Some(fd) = t.fd.as_ref().map(|f| f.as_raw_fd()) else { return };
    // connect
    if t.phase == TcpPhase::Connecting {
        if !sys::ready(fd, libc::POLLOUT) {
            return;
        }
        let p = t.connect.take().expect("connecting has a pending connect");
        match sys::so_error(fd) {
            0 => {
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
            e => {
                // A failed connect leaves a fresh endpoint (the object may retry or close).
                t.fd = None;
                t.phase = TcpPhase::New;
                p.fail(tcp_error(e));
                return;
            }
        }
    }
    // send
    if let Some(s) = t.send.as_mut() {
        let mut outcome = None;
        while s.done < s.size {
            match sys::send(fd, (s.buf + s.done) as *const u8, s.size - s.done) {
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
        if let Some(code) = outcome {
            let s = t.send.take().unwrap();
            if code != tcp::SUCCESS && code != tcp::WOULDBLOCK {
                t.sticky.get_or_insert(code);
            }
            s.p.fail(code);
            if let Some(close) = t.closing.take() {
                tcp_finish_close(st, id, close, false);
                return;
            }
        }
    }
    let Some(t) = st.tcp(id) else { return };
    // receive: greedy, up to max; wait only while below min (3.4)
    if let Some(r) = t.recv.as_mut() {
        let mut failure = None;
        if t.eof {
            // nothing more will come
        } else if let Some(e) = t.sticky {
            failure = Some(e);
        } else {
            while r.got < r.max {
                match sys::recv(fd, (r.buf + r.got) as *mut u8, r.max - r.got) {
                    Ok(0) => {
                        t.eof = true;
                        break;
                    }
                    Ok(n) => r.got += n,
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
        if let Some((code, n)) = done {
            let r = t.recv.take().unwrap();
            let mut res = NetResult::new(&r.p.req, code);
            res.size = n as i32;
            r.p.complete(res);
        }
    }
}

fn tcp_finish_close(st: &mut State, id: u32, p: Pending, abort: bool) {
    let Some(Endpoint::Tcp(mut t)) = st.eps.remove(&id) else { return p.fail(tcp::CONNECTION_CLOSED) };
    st.tombstones.insert(id, PROTO_TCP);
    // Everything pending is answered before the Close reply (1.10).
    if let Some(s) = t.send.take() {
        s.p.fail(tcp::CONNECTION_CLOSED);
    }
    if let Some(r) = t.recv.take() {
        r.p.fail(tcp::CONNECTION_CLOSED);
    }
    if let Some(c) = t.connect.take() {
        c.fail(tcp::CONNECTION_CLOSED);
    }
    if let Some(l) = t.listen.take() {
        l.fail(tcp::CONNECTION_CLOSED);
    }
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
                match sys::recv(fd.as_raw_fd(), sink.as_mut_ptr(), sink.len()) {
                    Ok(n) if n > 0 => continue,
                    _ => break,
                }
            }
        }
        drop(fd);
    }
    p.fail(tcp::SUCCESS);
}

// ---------------------------------------------------------------- UDP

fn udp_op(st: &mut State, cfg: &NetConfig, p: Pending) {
    let req = p.req;
    let id = req.endpoint;
    if st.udp(id).is_none() {
        return p.fail(udp::CONNECTION_CLOSED);
    }
    match req.op {
        op::UDP_BIND => {
            let robot_ip = st.robot_ip();
            let u = st.udp(id).unwrap();
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
        op::UDP_CONNECT | op::UDP_RESET_CONNECT => {
            let u = st.udp(id).unwrap();
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
        op::UDP_SEND => {
            let valid = st.valid_buffer(req.buffer, req.size);
            let u = st.udp(id).unwrap();
            if u.send.is_some() {
                return p.fail(udp::CONNECTION_BUSY);
            }
            if u.fd.is_none() {
                return p.fail(udp::OPERATION_INVALID);
            }
            if !valid {
                return p.fail(udp::BUFFER_INVALID);
            }
            let to = if u.connected {
                None
            } else if req.addr == 0 || req.port == 0 {
                return p.fail(udp::ADDRESSERROR);
            } else {
                Some(cfg.remote(req.addr, req.port as u16, "UDP send"))
            };
            u.send = Some((p, req.buffer as usize, req.size as usize, to));
            udp_progress(st, cfg, id);
        }
        op::UDP_RECEIVE => {
            let valid = st.valid_buffer(req.buffer, req.size);
            let u = st.udp(id).unwrap();
            if u.recv.is_some() {
                return p.fail(udp::CONNECTION_BUSY);
            }
            if u.fd.is_none() {
                return p.fail(udp::OPERATION_INVALID);
            }
            if !valid {
                return p.fail(udp::BUFFER_INVALID);
            }
            u.recv = Some((p, req.buffer as usize, req.size as usize));
            udp_progress(st, cfg, id);
        }
        op::UDP_CLOSE => {
            let Some(Endpoint::Udp(mut u)) = st.eps.remove(&id) else { unreachable!() };
            st.tombstones.insert(id, PROTO_UDP);
            if let Some((r, ..)) = u.recv.take() {
                r.fail(udp::CONNECTION_CLOSED);
            }
            if let Some((s, ..)) = u.send.take() {
                s.fail(udp::CONNECTION_CLOSED);
            }
            drop(u);
            p.fail(udp::SUCCESS)
        }
        op::UDP_SET_BLOCKING => {
            st.udp(id).unwrap().nonblocking = req.flags & 1 == 0;
            p.fail(udp::SUCCESS)
        }
        op::UDP_READY_READ | op::UDP_READY_WRITE => {
            let u = st.udp(id).unwrap();
            let Some(fd) = u.fd.as_ref() else { return p.fail(udp::OPERATION_INVALID) };
            let ev = if req.op == op::UDP_READY_READ { libc::POLLIN } else { libc::POLLOUT };
            let mut r = NetResult::new(&req, udp::SUCCESS);
            r.ready = sys::ready(fd.as_raw_fd(), ev) as i32;
            p.complete(r)
        }
        op::UDP_ADDRESS => {
            let u = st.udp(id).unwrap();
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
        _ => p.fail(udp::OPERATION_UNKNOWN),
    }
}

fn udp_progress(st: &mut State, cfg: &NetConfig, id: u32) {
    let Some(u) = st.udp(id) else { return };
    let Some(fd) = u.fd.as_ref().map(|f| f.as_raw_fd()) else { return };
    if let Some((_, buf, size, to)) = u.send.as_ref() {
        let code = match sys::sendto(fd, *buf as *const u8, *size, *to) {
            Ok(_) => Some(udp::SUCCESS),
            Err(libc::EAGAIN | libc::EINTR) => u.nonblocking.then_some(udp::WOULDBLOCK),
            Err(e) => Some(udp_error(e)),
        };
        if let Some(code) = code {
            u.send.take().unwrap().0.fail(code);
        }
    }
    if let Some((_, buf, size)) = u.recv.as_ref() {
        let out = match sys::recvfrom(fd, *buf as *mut u8, *size) {
            Ok((n, (fa, fp))) => Some((udp::SUCCESS, n, fa, fp)),
            Err(libc::EAGAIN | libc::EINTR) => u.nonblocking.then_some((udp::WOULDBLOCK, 0, 0, 0)),
            Err(e) => Some((udp_error(e), 0, 0, 0)),
        };
        if let Some((code, n, fa, fp)) = out {
            let (p, ..) = u.recv.take().unwrap();
            let mut r = NetResult::new(&p.req, code);
            r.size = n as i32;
            (r.faddr, r.fport) = robot_peer(cfg, fa, fp);
            p.complete(r);
        }
    }
}

// ---------------------------------------------------------------- poll thread

pub fn poll_loop(net: &'static Net) {
    loop {
        let (mut fds, toks, deadline) = net.lock().poll_set();
        fds.push(libc::pollfd { fd: net.wake_fd.as_raw_fd(), events: libc::POLLIN, revents: 0 });
        let timeout = deadline.map_or(-1, |d| d.saturating_duration_since(Instant::now()).as_millis().min(60_000) as i32 + 1);
        // SAFETY: `fds` is a valid array of pollfd.
        let n = unsafe { libc::poll(fds.as_mut_ptr(), fds.len() as libc::nfds_t, timeout) };
        if n < 0 {
            if sys::errno() == libc::EINTR {
                continue;
            }
            std::thread::sleep(Duration::from_millis(10));
            continue;
        }
        if fds.last().is_some_and(|w| w.revents != 0) {
            net.drain_wake();
        }
        let mut st = net.lock();
        for (pfd, tok) in fds.iter().zip(toks.iter()) {
            if pfd.revents == 0 {
                continue;
            }
            match *tok {
                Token::Listener(key) => accept_ready(&mut st, &net.config, key),
                Token::Ep(id) => match st.eps.get(&id) {
                    Some(Endpoint::Tcp(_)) => tcp_progress(&mut st, id),
                    Some(Endpoint::Udp(_)) => udp_progress(&mut st, &net.config, id),
                    _ => {}
                },
            }
        }
        st.fire_delayed();
    }
}

/// The robot's view of a peer address and port (`--net-map` and the port remap undone),
/// as the result fields want them.
fn robot_peer(cfg: &NetConfig, addr: u32, port: u16) -> (u32, u32) {
    let (a, p) = cfg.robot_peer(addr, port);
    (a, p.into())
}
