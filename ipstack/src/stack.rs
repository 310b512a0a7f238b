//! Endpoint table and the environment (network-api 2): endpoint and shared-buffer
//! creation, the robot's settings registry, the entry point of every request, and the poll
//! thread that finishes what would block.
use std::collections::{BTreeMap, HashMap};
use std::sync::Arc;
use std::time::{Duration, Instant};

use super::codes::{ant, op, tcp, PROTO_DNS, PROTO_ENV, PROTO_INIT, PROTO_TCP, PROTO_UDP};
use super::config::{self, NetConfig};
use super::poller::{Poller, Token};
use super::tcp::{Listener, TcpEp};
use super::udp::UdpEp;
use super::{dns, EndpointId, Host, Net, NetResult, Pending};

/// `antModuleRef.module` of every endpoint (never null: null means the environment).
const MODULE_MAGIC: usize = 0x414e_5400;

pub enum Endpoint {
    Tcp(TcpEp),
    Udp(UdpEp),
    Dns(dns::DnsEp),
}

impl Endpoint {
    fn uses_buffer(&self, base: usize, size: usize) -> bool {
        match self {
            Endpoint::Tcp(t) => t.uses_buffer(base, size),
            Endpoint::Udp(u) => u.uses_buffer(base, size),
            Endpoint::Dns(_) => false,
        }
    }
}

/// Endpoint ids are numbers the stack hands out in sequence: Fx spreads them well
/// enough, without SipHash's cost on every request of a streaming object.
pub(super) type IdMap<V> = rustc_hash::FxHashMap<EndpointId, V>;

#[derive(Clone)]
enum RegValue {
    Str(String),
    Int(i32),
}

pub struct State {
    next_id: u32,
    pub(super) eps: IdMap<Endpoint>,
    /// Protocols of closed endpoints, so late messages get that protocol's CLOSED code.
    tombstones: IdMap<i32>,
    pub(super) listeners: HashMap<(u32, u16), Listener>,
    /// Live shared buffers: region id → (base, size).
    buffers: BTreeMap<u32, (usize, usize)>,
    next_region: u32,
    registry: Option<BTreeMap<String, RegValue>>,
    pub dns_servers: Option<Vec<u32>>,
    pub domain: Option<String>,
    /// Where the robot's settings files are and warnings go.
    pub(super) host: Arc<dyn Host>,
    /// The poll thread's epoll set, which parked operations arm their sockets in.
    pub(super) poller: &'static Poller,
    /// The earliest delayed Listen error, accept retry or look at a stream (may be stale:
    /// an early wake-up is harmless).
    next_deadline: Option<Instant>,
}

/// The TCP endpoint `id` of a table (a borrow of the table alone, so that the rest of
/// [`State`] stays usable beside it).
pub(super) fn tcp_in(eps: &mut IdMap<Endpoint>, id: EndpointId) -> Option<&mut TcpEp> {
    match eps.get_mut(&id) {
        Some(Endpoint::Tcp(t)) => Some(t),
        _ => None,
    }
}

impl State {
    pub fn new(host: Arc<dyn Host>, poller: &'static Poller) -> State {
        State {
            next_id: 1,
            eps: IdMap::default(),
            tombstones: IdMap::default(),
            listeners: HashMap::new(),
            buffers: BTreeMap::new(),
            next_region: 1,
            registry: None,
            dns_servers: None,
            domain: None,
            host,
            poller,
            next_deadline: None,
        }
    }

    pub fn remember_closed(&mut self, id: EndpointId, proto: i32) {
        self.tombstones.insert(id, proto);
    }

    pub fn protocol_of(&self, id: EndpointId) -> i32 {
        match self.eps.get(&id) {
            Some(Endpoint::Tcp(_)) => PROTO_TCP,
            Some(Endpoint::Udp(_)) => PROTO_UDP,
            Some(Endpoint::Dns(_)) => PROTO_DNS,
            None => self.tombstones.get(&id).copied().unwrap_or(-1),
        }
    }

    fn registry(&mut self) -> &mut BTreeMap<String, RegValue> {
        let host = &self.host;
        self.registry.get_or_insert_with(|| config::wlan_settings(&**host).into_iter().map(|(k, v)| (k, RegValue::Str(v))).collect())
    }

    pub fn registry_value(&mut self, key: &str) -> Option<String> {
        match self.registry().get(key)? {
            RegValue::Str(s) => Some(s.clone()),
            RegValue::Int(i) => Some(i.to_string()),
        }
    }

    /// The robot's own (virtual) address, ETHER_IP.
    pub(super) fn robot_ip(&mut self) -> u32 {
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
    pub(super) fn valid_buffer(&self, ptr: *mut u8, len: i32) -> bool {
        if len <= 0 || ptr.is_null() {
            return false;
        }
        let (p, n) = (ptr as usize, len as usize);
        self.buffers.range(..).any(|(_, &(base, size))| p >= base && p.checked_add(n).is_some_and(|end| end <= base + size))
    }

    pub(super) fn tcp(&mut self, id: EndpointId) -> Option<&mut TcpEp> {
        tcp_in(&mut self.eps, id)
    }

    pub(super) fn udp(&mut self, id: EndpointId) -> Option<&mut UdpEp> {
        match self.eps.get_mut(&id) {
            Some(Endpoint::Udp(u)) => Some(u),
            _ => None,
        }
    }

    /// Makes the poll thread wake by `at` (a delayed Listen error, an accept to retry).
    pub(super) fn schedule(&mut self, at: Instant) {
        if keep_earliest(&mut self.next_deadline, at) {
            self.poller.wake();
        }
    }

    /// Answers the failed Listens whose delay is over and retries the failed accepts whose
    /// delay is; the poll thread's next timeout.
    fn fire_delayed(&mut self, cfg: &NetConfig) -> Option<Instant> {
        let now = Instant::now();
        if self.next_deadline.is_some_and(|d| d <= now) {
            self.next_deadline = None;
            for ep in self.eps.values_mut() {
                if let Endpoint::Tcp(t) = ep {
                    t.fire_listen_error(now);
                    for at in [t.listen_due(), t.check_stream(now)].into_iter().flatten() {
                        keep_earliest(&mut self.next_deadline, at);
                    }
                }
            }
            if let Some(at) = super::tcp::retry_accepts(self, cfg, now) {
                keep_earliest(&mut self.next_deadline, at);
            }
        }
        self.next_deadline
    }
}

/// Makes `at` the deadline if it is earlier than `deadline`'s; whether it was.
fn keep_earliest(deadline: &mut Option<Instant>, at: Instant) -> bool {
    let earlier = deadline.is_none_or(|d| at < d);
    if earlier {
        *deadline = Some(at);
    }
    earlier
}

/// Entry point of every request (caller's thread).
pub fn handle(net: &'static Net, p: Pending) {
    let mut st = net.lock();
    let req = p.req;
    match req.proto {
        PROTO_INIT => init_op(&mut st, p),
        PROTO_ENV => env_op(&mut st, p),
        PROTO_TCP => super::tcp::tcp_op(&mut st, &net.config, p),
        PROTO_UDP => super::udp::udp_op(&mut st, &net.config, p),
        PROTO_DNS => dns::dns_op(&mut st, net, p),
        // an endpoint that never existed: CLOSED is 2 in both TCP and UDP numbering
        _ => p.fail(tcp::CONNECTION_CLOSED),
    }
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
                PROTO_TCP => Endpoint::Tcp(TcpEp::default()),
                PROTO_UDP => Endpoint::Udp(UdpEp::default()),
                PROTO_DNS => Endpoint::Dns(dns::DnsEp::default()),
                _ => return p.fail(ant::ENDPOINT_NOFACTORY),
            };
            let id = EndpointId(st.next_id);
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
            // The kernel may still read or write it for a pending operation: freeing it
            // now would corrupt the heap. The buffer stays; the program is told.
            Some(&(base, size)) if base == req.region_base as usize && st.eps.values().any(|e| e.uses_buffer(base, size)) => {
                st.host.warn(&format!(
                    "net: shared buffer {} destroyed while a Send or Receive on it is pending: refused (antFAIL), it stays allocated",
                    req.region
                ));
                p.fail(ant::FAIL)
            }
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

// ---------------------------------------------------------------- poll thread

pub fn poll_loop(net: &'static Net) {
    // SAFETY: all-zero is a valid epoll_event (plain data).
    let mut events = vec![unsafe { std::mem::zeroed::<libc::epoll_event>() }; 64];
    let mut timeout = -1;
    let mut warned = false;
    loop {
        let n = match net.poller.wait(&mut events, timeout) {
            Ok(n) => n,
            Err(libc::EINTR) => 0,
            Err(e) => {
                // Said once: it would repeat every pause, and parked operations stall.
                if !std::mem::replace(&mut warned, true) {
                    net.host.warn(&format!("net: the poll thread's epoll_wait failed: {}", std::io::Error::from_raw_os_error(e)));
                }
                std::thread::sleep(Duration::from_millis(100));
                0
            }
        };
        let mut st = net.lock();
        for ev in &events[..n] {
            match Token::decode(ev.u64) {
                Token::Wake => net.poller.drain_wake(),
                Token::Listener(key) => super::tcp::accept_ready(&mut st, &net.config, key),
                // The socket reported readiness and is disarmed: progress.
                Token::Ep(id) => match st.eps.get_mut(&id) {
                    Some(Endpoint::Tcp(t)) => {
                        t.fired();
                        super::tcp::progress(&mut st, id);
                    }
                    Some(Endpoint::Udp(u)) => {
                        u.fired();
                        super::udp::progress(&mut st, &net.config, id);
                    }
                    _ => {}
                },
            }
        }
        timeout = st.fire_delayed(&net.config).map_or(-1, |d| d.saturating_duration_since(Instant::now()).as_millis().min(60_000) as i32 + 1);
    }
}

/// The robot's view of a peer address and port (`--net-map` and the port remap undone),
/// as the result fields want them.
pub(super) fn robot_peer(cfg: &NetConfig, addr: u32, port: u16) -> (u32, u32) {
    let (a, p) = cfg.robot_peer(addr, port);
    (a, p.into())
}
