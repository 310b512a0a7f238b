//! From the CFG file to a loaded gateway: ROBOTGW.CFG / HOSTGW.CFG read and checked
//! (every error names the file and line), the robot's ports bound before any object
//! starts, addresses mapped by `--net-bind` / `--port-offset` / `--net-map`, and the
//! built-in object's [`Module`].
use std::collections::HashMap;
use std::net::{Ipv4Addr, SocketAddrV4, TcpListener};
use std::path::Path;
use std::sync::atomic::Ordering;
use std::sync::{Arc, Mutex, OnceLock};

use openr_wrappers::rp::gwcfg::{self, GwLine};

use super::link::{self, Link};
use super::wire::Hello;
use super::{Setup, HOST_GATEWAY, ROBOT_GATEWAY};
use crate::error::{ErrorKind, Result};
use crate::loader::Module;
use crate::runtime::Runtime;
use openr_ipstack::NetConfig;

/// What a line's thread does once the gateway starts.
pub enum Target {
    Listen(TcpListener),
    Connect(SocketAddrV4),
}

pub fn spawn(link: Arc<Link>, target: Target) {
    let name = format!("openr-gw-{}", link.hello.port);
    let _ = crate::runtime::spawn(name, move || match target {
        Target::Listen(l) => link::serve(link, l),
        Target::Connect(a) => link::connect(link, a),
    });
}

/// The module of built-in object `name` (`robot-gateway`, `host-gateway`) loaded from
/// `bin`: reads its CFG file and prepares every channel.
pub fn module(name: &str, bin: &Path) -> Result<Module> {
    let err = |m: String| crate::error::Error::from(ErrorKind::Runtime(m));
    let rt = Runtime::get().ok_or_else(|| err("the gateway needs a running runtime".into()))?;
    let (host, file) = match name {
        ROBOT_GATEWAY => (false, "ROBOTGW.CFG"),
        HOST_GATEWAY => (true, "HOSTGW.CFG"),
        _ => return Err(crate::error::Error::load(bin, format!("names built-in object `{name}`, which this runtime does not have"))),
    };
    let state = &rt.gateway;
    if state.setup.get().is_some() {
        return Err(crate::error::Error::load(bin, "a second TCP gateway in one run (the robot has one TCPGateway)"));
    }
    state.host.store(host, Ordering::Release);
    let path = rt.ms.existing(&format!("/MS/OPEN-R/MW/CONF/{file}"));
    let lines = match &path {
        Some(p) => gwcfg::read(p).map_err(|e| err(e.to_string()))?,
        None => {
            rt.diag.warn(&format!("{}: no MS/OPEN-R/MW/CONF/{file}: the gateway has no channels", bin.display()));
            Vec::new()
        }
    };
    let shown = path.as_deref().map_or_else(|| file.to_string(), |p| p.display().to_string());
    let net = NetConfig::new(&crate::net::options(), Arc::new(crate::net::RuntimeHost::current()));
    let (links, targets) = prepare(&shown, &lines, host, &net).map_err(err)?;
    if let Some(p) = links.iter().find(|l| l.hello.suffix == b'P').filter(|_| host) {
        let _ = state.client.set(p.clone());
    }
    warn_shared_services(rt, &links);
    let targets = Mutex::new(targets.into_iter().map(Some).collect());
    let _ = state.setup.set(Setup { links, targets, oid: OnceLock::new() });
    Ok(Module::builtin(&super::ENTRY_TABLE, if host { "tcpGateway" } else { "TCPGateway" }))
}

type Prepared = (Vec<Arc<Link>>, Vec<Target>);

/// Where a line's channel goes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Peer {
    /// Host: connect to the robot at this address (the line's, or `!ROBOT_PROXY`'s).
    Connect(Ipv4Addr),
    /// Robot: listen; `addr_given` if the line has an address anyway (it is ignored).
    Listen { addr_given: bool },
}

/// One line of a gateway file as the channel it makes.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Channel<'a> {
    pub line: usize,
    /// The service name; the proxy's is `TCPGateway.Proxy.AperiosMessage.P`.
    pub name: &'a str,
    /// `b'S'`, `b'O'` or `b'P'`.
    pub suffix: u8,
    pub port: u16,
    pub peer: Peer,
    pub options: &'a [String],
}

impl Channel<'_> {
    /// The line's `dskip=`, `dmin=`, `dmax=` as the gateway observer's buffer control
    /// (d_skip, d_min, d_max), defaults (0, 1, 1); unknown keys are left to `warnings`.
    pub fn buf_ctrl(&self) -> std::result::Result<(usize, usize, usize), String> {
        let (mut skip, mut min, mut max) = (0, 1, 1);
        for o in self.options {
            let (key, value) = o.split_once('=').unwrap_or((o, ""));
            let slot = match key {
                "dskip" => &mut skip,
                "dmin" => &mut min,
                "dmax" => &mut max,
                _ => continue,
            };
            *slot = value.parse().map_err(|_| format!("`{o}`: expected a whole number after `{key}=`"))?;
        }
        if min == 0 || max < min {
            return Err(format!("dmin={min} dmax={max}: expected 1 <= dmin <= dmax"));
        }
        Ok((skip, min, max))
    }

    /// What the gateway warns about this line at start (and `cargo openr check` too).
    pub fn warnings(&self) -> Vec<String> {
        let mut out = Vec::new();
        for o in self.options {
            let key = o.split('=').next().unwrap_or("");
            if !matches!(key, "dskip" | "dmin" | "dmax") {
                out.push(format!("unknown option `{o}` ignored (known: dskip, dmin, dmax)"));
            }
        }
        match self.buf_ctrl() {
            Err(e) => out.push(format!("{e}; the defaults dskip=0 dmin=1 dmax=1 are used")),
            Ok(b) if b != (0, 1, 1) && self.suffix != b'O' => out.push("dskip, dmin and dmax are an observer's (a `.O` line's); ignored here".into()),
            Ok(_) => {}
        }
        if self.peer == (Peer::Listen { addr_given: true }) {
            out.push("the robot listens, the address on this line is ignored".into());
        }
        out
    }
}

/// The lines of a gateway file (HOSTGW.CFG when `host`) as channels, checked as a whole
/// without opening anything, so that `cargo openr check` refuses what a run would: one
/// proxy line, each service once, one channel per port (and robot, on the host), an
/// address for every host line, no more lines than the gateway has service slots. The
/// first problem as (line, message).
pub fn channels(lines: &[GwLine], host: bool) -> std::result::Result<Vec<Channel<'_>>, (usize, String)> {
    let proxy_addr = lines.iter().find_map(|l| match l {
        GwLine::Proxy { addr, .. } => *addr,
        _ => None,
    });
    let mut seen_ports: HashMap<(Option<Ipv4Addr>, u16), usize> = HashMap::new();
    let mut seen_names: HashMap<&str, usize> = HashMap::new();
    let (mut subjects, mut observers, mut proxies) = (0, 0, 0);
    let mut out = Vec::new();
    for l in lines {
        let (line, name, port, addr, options) = match l {
            GwLine::Proxy { line, port, addr } => (*line, "TCPGateway.Proxy.AperiosMessage.P", *port, *addr, &[][..]),
            GwLine::Service { line, name, port, addr, options } => (*line, name.as_str(), *port, *addr, &options[..]),
        };
        let err = |m: String| (line, m);
        let suffix = *name.as_bytes().last().unwrap_or(&b'P');
        match suffix {
            b'S' => subjects += 1,
            b'O' => observers += 1,
            _ => proxies += 1,
        }
        if proxies > 1 && suffix == b'P' {
            return Err(err("a second proxy line (one per gateway)".into()));
        }
        if subjects > openr::MAX_SUBJECTS || observers > openr::MAX_OBSERVERS {
            return Err(err(format!("more than {} subject or observer lines (the gateway has as many service slots)", openr::MAX_SUBJECTS)));
        }
        if let Some(prev) = seen_names.insert(name, line).filter(|_| suffix != b'P') {
            return Err(err(format!("service {name} is already line {prev}: each line is its own service")));
        }
        let key = (if host { addr.or(proxy_addr) } else { None }, port);
        if let Some(prev) = seen_ports.insert(key, line) {
            return Err(err(format!("port {port} is already line {prev}: one channel per port{}", if host { " and robot" } else { "" })));
        }
        let peer = if host {
            Peer::Connect(addr.or(proxy_addr).ok_or_else(|| err("no robot address, and no `!ROBOT_PROXY` line to take it from".into()))?)
        } else {
            Peer::Listen { addr_given: addr.is_some() }
        };
        out.push(Channel { line, name, suffix, port, peer, options });
    }
    Ok(out)
}

/// Checks the lines as a whole and makes each one's link and target.
fn prepare(file: &str, lines: &[GwLine], host: bool, net: &NetConfig) -> std::result::Result<Prepared, String> {
    let channels = channels(lines, host).map_err(|(line, m)| format!("{file}:{line}: {m}"))?;
    let (mut links, mut targets) = (Vec::new(), Vec::new());
    for c in channels {
        let (port, place) = (c.port, format!("{file}:{}", c.line));
        for w in c.warnings() {
            super::warn(&format!("{place}: {w}"));
        }
        let hello = Hello { suffix: c.suffix, port, name: c.name.to_string(), place: place.clone() };
        let target = match c.peer {
            Peer::Connect(ip) => {
                let (a, p) = net.remote(u32::from(ip), port, "gateway channel");
                Target::Connect(SocketAddrV4::new(Ipv4Addr::from(a), p))
            }
            Peer::Listen { .. } => {
                let p = net.local_port(port, "gateway channel").ok_or_else(|| format!("{place}: port {port} moved by --port-offset does not fit"))?;
                let at = SocketAddrV4::new(Ipv4Addr::from(net.bind), p);
                let l = TcpListener::bind(at).map_err(|e| format!("{place}: cannot listen on {at} for channel {port}: {e}"))?;
                Target::Listen(l)
            }
        };
        let mut link = Link::new(links.len(), place, hello);
        if c.suffix == b'O' {
            link.buf_ctrl = c.buf_ctrl().unwrap_or((0, 1, 1));
        }
        links.push(Arc::new(link));
        targets.push(target);
    }
    Ok((links, targets))
}

/// A gateway service named in more than one CONNECT.CFG line carries several logical
/// connections on one channel (Sony's ObjectComm-multi RP2-BAD / RP3-BAD): said at start.
fn warn_shared_services(rt: &Runtime, links: &[Arc<Link>]) {
    let design = rt.design.to_string_lossy().into_owned();
    let Ok((path, conns, _)) = crate::cfg::connect_cfg(&rt.ms, &design) else { return };
    for l in links.iter().filter(|l| l.hello.suffix != b'P') {
        let uses: Vec<usize> = conns.iter().filter(|c| c.subject == l.hello.name || c.observer == l.hello.name).map(|c| c.line).collect();
        if uses.len() > 1 {
            let lines: Vec<String> = uses.iter().map(usize::to_string).collect();
            rt.diag.warn(&format!(
                "{}:{}: gateway service {} (port {}, {}) is in {} connections (lines {}): one channel carries one subject-observer \
                 connection; here every observer gets what every subject sends, and their readiness is mixed",
                path.display(),
                uses[0],
                l.hello.name,
                l.hello.port,
                l.place,
                uses.len(),
                lines.join(", ")
            ));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The host side's refusal of `text` (no socket is opened on the host side).
    fn host_error(text: &str) -> String {
        let lines = gwcfg::parse("HOSTGW.CFG", text).expect("the line syntax is fine");
        let net = NetConfig::new(&Default::default(), Arc::new(crate::net::RuntimeHost(None)));
        match prepare("HOSTGW.CFG", &lines, true, &net) {
            Ok(_) => panic!("accepted:\n{text}"),
            Err(e) => e,
        }
    }

    #[test]
    fn a_host_file_that_cannot_make_its_channels_is_refused_at_its_line() {
        let e = host_error("!ROBOT_PROXY 59001 127.0.0.1\n!ROBOT_PROXY 59002 127.0.0.1\n");
        assert_eq!(e, "HOSTGW.CFG:2: a second proxy line (one per gateway)");
        let e = host_error("A.B.char.S 59002 127.0.0.1\nA.B.char.S 59003 127.0.0.1\n");
        assert_eq!(e, "HOSTGW.CFG:2: service A.B.char.S is already line 1: each line is its own service");
        let e = host_error("A.B.char.S 59002 127.0.0.1\nA.C.char.O 59002 127.0.0.1\n");
        assert_eq!(e, "HOSTGW.CFG:2: port 59002 is already line 1: one channel per port and robot");
        let e = host_error("A.B.char.S 59002\n");
        assert_eq!(e, "HOSTGW.CFG:1: no robot address, and no `!ROBOT_PROXY` line to take it from");
        let many: String = (0..=openr::MAX_SUBJECTS).map(|k| format!("A.S{k}.char.S {} 127.0.0.1\n", 59100 + k)).collect();
        assert!(host_error(&many).ends_with("the gateway has as many service slots)"), "{}", host_error(&many));
        // Two robots may use the same port.
        let lines = gwcfg::parse("HOSTGW.CFG", "A.B.char.S 59002 127.0.0.1\nA.C.char.O 59002 127.0.0.2\n").unwrap();
        assert!(prepare("HOSTGW.CFG", &lines, true, &NetConfig::new(&Default::default(), Arc::new(crate::net::RuntimeHost(None)))).is_ok());
    }

    #[test]
    fn an_observer_lines_options_are_its_buffer_control_and_bad_ones_are_said() {
        let text = "A.In.char.O 59001 127.0.0.1 dmax=8 dmin=2 dskip=1\nA.Out.char.S 59002 127.0.0.1 dmax=4\n\
                    A.Bad.char.O 59003 127.0.0.1 dmax=x\nA.Low.char.O 59004 127.0.0.1 dmin=3 dmax=2\nA.Odd.char.O 59005 127.0.0.1 dfoo=1\n";
        let lines = gwcfg::parse("HOSTGW.CFG", text).unwrap();
        let ch = channels(&lines, true).unwrap();
        assert_eq!(ch[0].buf_ctrl(), Ok((1, 2, 8)));
        assert!(ch[0].warnings().is_empty(), "{:?}", ch[0].warnings());
        assert_eq!(ch[1].warnings(), ["dskip, dmin and dmax are an observer's (a `.O` line's); ignored here"]);
        assert_eq!(ch[2].warnings(), ["`dmax=x`: expected a whole number after `dmax=`; the defaults dskip=0 dmin=1 dmax=1 are used"]);
        assert_eq!(ch[3].warnings(), ["dmin=3 dmax=2: expected 1 <= dmin <= dmax; the defaults dskip=0 dmin=1 dmax=1 are used"]);
        assert_eq!(ch[4].buf_ctrl(), Ok((0, 1, 1)));
        assert_eq!(ch[4].warnings(), ["unknown option `dfoo=1` ignored (known: dskip, dmin, dmax)"]);
        let (links, _) = prepare("HOSTGW.CFG", &lines, true, &NetConfig::new(&Default::default(), Arc::new(crate::net::RuntimeHost(None)))).unwrap();
        let bufs: Vec<_> = links.iter().map(|l| l.buf_ctrl).collect();
        assert_eq!(bufs, [(1, 2, 8), (0, 1, 1), (0, 1, 1), (0, 1, 1), (0, 1, 1)], "only an observer line's valid options apply");
    }
}
