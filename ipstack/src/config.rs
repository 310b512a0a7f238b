//! Network configuration of this robot: where endpoints bind, the port offset that
//! keeps two robots on one host apart (network-api 11.2), the privileged-port remap
//! (11.3) and the wireless-LAN settings (WLANCONF.TXT / WLANDFLT.TXT, 2.4).
use std::collections::{BTreeMap, HashMap, HashSet};
use std::net::Ipv4Addr;
use std::sync::{Arc, Mutex};

use super::{Host, Report};

/// Explicit remaps, `robot=host` pairs separated by commas (`21=2121,123=40123`), read
/// by `cargo openr run` into [`NetOptions::port_map`].
pub const ENV_PORT_MAP: &str = "OPENR_NET_PORT_MAP";

/// The network settings of a run (`RunOptions::net`): `--net-bind`, `--port-offset`,
/// `--net-map`, `OPENR_NET_PORT_MAP`, `OPENR_NET_TRACE`.
#[derive(Debug, Clone, Default)]
pub struct NetOptions {
    /// Host address for the robot's own address (127.0.0.1 when `None`).
    pub bind: Option<Ipv4Addr>,
    /// Added to every local port (network-api 11.2).
    pub port_offset: u16,
    /// Destination remaps.
    pub addr_map: Vec<AddrMap>,
    /// Explicit robot → host port remaps.
    pub port_map: HashMap<u16, u16>,
    /// Every request and reply as a line of [`Report::trace`].
    pub trace: bool,
}

/// `OPENR_NET_TRACE=1` (not `0`): [`NetOptions::trace`], read by `cargo openr run`.
pub const ENV_TRACE: &str = "OPENR_NET_TRACE";

/// One `--net-map` entry: connections and datagrams the robot sends to `robot` (all
/// ports, or `robot_port` only) go to `host` (its port, or `host_port`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct AddrMap {
    pub robot: u32,
    pub robot_port: Option<u16>,
    pub host: u32,
    pub host_port: Option<u16>,
}

/// Parses one `--net-map` entry; the error says what was expected.
pub fn parse_addr_map(s: &str) -> Result<AddrMap, String> {
    let bad = || format!("`{s}`: expected ROBOT_IP=HOST_IP or ROBOT_IP:PORT=HOST_IP:PORT (e.g. 10.0.1.2=127.0.0.1)");
    let (a, b) = s.trim().split_once('=').ok_or_else(bad)?;
    let side = |t: &str| -> Result<(u32, Option<u16>), String> {
        match t.split_once(':') {
            Some((ip, port)) => Ok((parse_ip(ip).ok_or_else(bad)?, Some(port.trim().parse::<u16>().ok().filter(|p| *p != 0).ok_or_else(bad)?))),
            None => Ok((parse_ip(t).ok_or_else(bad)?, None)),
        }
    };
    let ((robot, robot_port), (host, host_port)) = (side(a)?, side(b)?);
    if robot_port.is_none() && host_port.is_some() {
        return Err(format!("`{s}`: a host port needs a robot port (ROBOT_IP:PORT=HOST_IP:PORT)"));
    }
    Ok(AddrMap { robot, robot_port, host, host_port })
}

impl std::fmt::Display for AddrMap {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let side = |ip: u32, port: Option<u16>| match port {
            Some(p) => format!("{}:{p}", Ipv4Addr::from(ip)),
            None => Ipv4Addr::from(ip).to_string(),
        };
        write!(f, "{}={}", side(self.robot, self.robot_port), side(self.host, self.host_port))
    }
}

/// Where a privileged robot port lands by default: 10000 + port (21 → 10021).
pub const PRIVILEGED_BASE: u32 = 10000;

pub struct NetConfig {
    /// Host address endpoints bind to when the robot says IP_ADDR_ANY (or its own
    /// address): 127.0.0.1 unless `--net-bind`.
    pub bind: u32,
    pub offset: u32,
    pub map: HashMap<u16, u16>,
    pub addr_map: Vec<AddrMap>,
    /// Where the remapped ports are announced and warnings go.
    pub(crate) report: Arc<dyn Report>,
    announced: Mutex<HashSet<(u16, u16, &'static str)>>,
}

impl NetConfig {
    pub fn new(opts: &NetOptions, report: Arc<dyn Report>) -> NetConfig {
        NetConfig {
            bind: u32::from(opts.bind.unwrap_or(Ipv4Addr::LOCALHOST)),
            offset: opts.port_offset.into(),
            map: opts.port_map.clone(),
            addr_map: opts.addr_map.clone(),
            report,
            announced: Mutex::new(HashSet::new()),
        }
    }

    /// The host port for a robot port: explicit map, else privileged ports moved to
    /// 10000 + p; without the offset. 0 (any) stays 0.
    fn remap(&self, port: u16) -> u32 {
        if port == 0 {
            return 0;
        }
        if let Some(&p) = self.map.get(&port) {
            return p.into();
        }
        if port < 1024 {
            PRIVILEGED_BASE + u32::from(port)
        } else {
            port.into()
        }
    }

    /// Host port of a local bind/listen: remap + this robot's offset; None when the
    /// result does not fit.
    pub fn local_port(&self, port: u16, what: &'static str) -> Option<u16> {
        if port == 0 {
            return Some(0);
        }
        let host = u16::try_from(self.remap(port) + self.offset).ok()?;
        if host != port {
            self.announce(port, host, what);
        }
        Some(host)
    }

    /// Host port of a destination: only servers on this host (loopback) are moved, and
    /// only by the remap (a peer robot's ports are its own business).
    pub fn remote_port(&self, addr: u32, port: u16, what: &'static str) -> u16 {
        if !super::sys::is_loopback(addr) {
            return port;
        }
        let host = u16::try_from(self.remap(port)).unwrap_or(port);
        if host != port {
            self.announce(port, host, what);
        }
        host
    }

    /// Host address and port of a destination the robot names: the `--net-map` entry
    /// for it (a port-specific one first), then the loopback port remap.
    pub fn remote(&self, addr: u32, port: u16, what: &'static str) -> (u32, u16) {
        let entry = self
            .addr_map
            .iter()
            .find(|m| m.robot == addr && m.robot_port == Some(port))
            .or_else(|| self.addr_map.iter().find(|m| m.robot == addr && m.robot_port.is_none()));
        match entry {
            Some(m) => match m.host_port {
                Some(hp) => (m.host, hp),
                None => (m.host, self.remote_port(m.host, port, what)),
            },
            None => (addr, self.remote_port(addr, port, what)),
        }
    }

    /// The robot's view of a peer (inverse of `remote`): a mapped host is reported
    /// as the robot address it stands for.
    pub fn robot_peer(&self, addr: u32, port: u16) -> (u32, u16) {
        for m in &self.addr_map {
            match (m.robot_port, m.host_port) {
                (Some(rp), Some(hp)) if m.host == addr && hp == port => return (m.robot, rp),
                (Some(rp), None) if m.host == addr && self.remote_port(addr, rp, "") == port => return (m.robot, rp),
                _ => {}
            }
        }
        let robot_port = self.robot_peer_port(addr, port);
        match self.addr_map.iter().find(|m| m.host == addr && m.robot_port.is_none()) {
            Some(m) => (m.robot, robot_port),
            None => (addr, robot_port),
        }
    }

    /// The robot's view of a peer's port (inverse of `remote_port`).
    pub fn robot_peer_port(&self, addr: u32, port: u16) -> u16 {
        if !super::sys::is_loopback(addr) {
            return port;
        }
        if let Some((&robot, _)) = self.map.iter().find(|(_, &h)| h == port) {
            return robot;
        }
        if (PRIVILEGED_BASE..PRIVILEGED_BASE + 1024).contains(&u32::from(port)) && !self.map.values().any(|&h| h == port) {
            let robot = (u32::from(port) - PRIVILEGED_BASE) as u16;
            if !self.map.contains_key(&robot) {
                return robot;
            }
        }
        port
    }

    /// Host address for a local bind of `addr` (robot view).
    pub fn local_addr(&self, addr: u32, robot_ip: u32) -> u32 {
        if addr == 0 || addr == robot_ip {
            self.bind
        } else {
            addr
        }
    }

    fn announce(&self, robot: u16, host: u16, what: &'static str) {
        let mut seen = self.announced.lock().unwrap_or_else(|p| p.into_inner());
        if seen.insert((robot, host, what)) {
            self.report.info(&format!("net: robot port {robot} ({what}) is host port {host}"));
        }
    }
}

pub fn parse_port_map(s: &str) -> HashMap<u16, u16> {
    s.split([',', ' '])
        .filter_map(|pair| {
            let (a, b) = pair.split_once('=')?;
            Some((a.trim().parse().ok()?, b.trim().parse().ok()?))
        })
        .collect()
}

/// The shipped defaults of WLANDFLT.TXT (network-api 2.4).
pub use openr_sdk_payload::WLAN_DEFAULTS;

/// Parses `KEY=VALUE` lines (`#` comments, blanks ignored).
pub fn parse_wlan(text: &str) -> BTreeMap<String, String> {
    text.lines()
        .map(|l| l.split('#').next().unwrap_or("").trim())
        .filter_map(|l| l.split_once('='))
        .map(|(k, v)| (k.trim().to_ascii_uppercase(), v.trim().to_string()))
        .filter(|(k, _)| !k.is_empty())
        .collect()
}

/// The robot's wireless settings: defaults, overridden by WLANDFLT.TXT, overridden by
/// WLANCONF.TXT (both in /MS/OPEN-R/SYSTEM/CONF).
pub fn wlan_settings(host: &dyn Host) -> BTreeMap<String, String> {
    let mut m: BTreeMap<String, String> = WLAN_DEFAULTS.iter().map(|(k, v)| (k.to_string(), v.to_string())).collect();
    for file in ["/MS/OPEN-R/SYSTEM/CONF/WLANDFLT.TXT", "/MS/OPEN-R/SYSTEM/CONF/WLANCONF.TXT"] {
        if let Some(text) = host.read_stick(file) {
            m.extend(parse_wlan(&text));
        }
    }
    m
}

pub fn parse_ip(s: &str) -> Option<u32> {
    s.trim().parse::<Ipv4Addr>().ok().map(u32::from)
}
