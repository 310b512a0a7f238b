//! DNS endpoints (network-api 5): lookups run on worker threads, against the robot's
//! configured servers (DNS_SERVER_n / SetServerAddresses, plain DNS over UDP) or, when
//! none is configured, the host's resolver (getaddrinfo / getnameinfo).
use std::ffi::{CStr, CString};
use std::net::{Ipv4Addr, UdpSocket};
use std::time::Duration;

use super::codes::PROTO_DNS;
use super::stack::State;
use super::{EndpointId, Net, NetResult, Pending};

mod code {
    pub const SUCCESS: i32 = 0;
    pub const FAIL: i32 = 1;
    pub const HOST_NOT_FOUND: i32 = 2;
    pub const TRY_AGAIN: i32 = 3;
    pub const NO_RECOVERY: i32 = 4;
    pub const NO_DATA: i32 = 5;
    pub const CONNECTION_CLOSED: i32 = 6;
    pub const CONNECTION_BUSY: i32 = 7;
    pub const INDEX_INVALID: i32 = 8;
    pub const OPERATION_INVALID: i32 = 10;
    pub const OPERATION_UNKNOWN: i32 = 11;
}

const OP_SET_SERVERS: i32 = 0;
const OP_GET_SERVERS: i32 = 1;
const OP_SET_DOMAIN: i32 = 2;
const OP_GET_DOMAIN: i32 = 3;
const OP_BY_NAME: i32 = 4;
const OP_BY_ADDR: i32 = 5;
const OP_GET_ADDRESS: i32 = 6;
const OP_GET_ALIAS: i32 = 7;
const OP_CLOSE: i32 = 8;

const LOCALHOST: u32 = 0x7f00_0001;

#[derive(Debug, Clone, PartialEq, Eq)]
pub struct HostEntry {
    /// Official name first, then the other names.
    pub names: Vec<String>,
    pub addrs: Vec<u32>,
    pub server: u32,
}

#[derive(Default)]
pub struct DnsEp {
    inflight: Option<Pending>,
    last: Option<HostEntry>,
}

fn dns_ep(st: &mut State, id: EndpointId) -> Option<&mut DnsEp> {
    match st.eps.get_mut(&id) {
        Some(super::stack::Endpoint::Dns(d)) => Some(d),
        _ => None,
    }
}

pub(crate) fn dns_op(st: &mut State, net: &'static Net, p: Pending) {
    let req = p.req;
    let id = req.endpoint;
    let Some(ep) = dns_ep(st, id) else { return p.fail(code::CONNECTION_CLOSED) };
    if ep.inflight.is_some() && req.op != OP_CLOSE {
        return p.fail(code::CONNECTION_BUSY);
    }
    match req.op {
        OP_SET_SERVERS => {
            let n = req.value.clamp(0, 3) as usize;
            st.dns_servers = Some(req.addr_list[..n].to_vec());
            p.fail(code::SUCCESS)
        }
        OP_GET_SERVERS => {
            let mut servers = st.configured_dns_servers();
            if servers.is_empty() {
                servers = resolv_conf_servers();
            }
            let mut r = NetResult::new(&req, code::SUCCESS);
            r.nscount = servers.len().min(3) as i32;
            for (slot, a) in r.addr_list.iter_mut().zip(servers) {
                *slot = a;
            }
            p.complete(r)
        }
        OP_SET_DOMAIN => {
            st.domain = Some(req.name());
            p.fail(code::SUCCESS)
        }
        OP_GET_DOMAIN => match st.default_domain() {
            Some(d) => {
                let mut r = NetResult::new(&req, code::SUCCESS);
                r.set_name(&d);
                p.complete(r)
            }
            None => p.fail(code::FAIL),
        },
        OP_BY_NAME | OP_BY_ADDR => start_lookup(st, net, id, p),
        OP_GET_ADDRESS | OP_GET_ALIAS => {
            let Some(last) = ep.last.as_ref() else { return p.fail(code::OPERATION_INVALID) };
            let i = req.value;
            let mut r = NetResult::new(&req, code::SUCCESS);
            if req.op == OP_GET_ADDRESS {
                let Some(&a) = usize::try_from(i).ok().and_then(|i| last.addrs.get(i)) else { return p.fail(code::INDEX_INVALID) };
                r.host_address = a;
                r.host_valid = 1;
            } else {
                let Some(n) = usize::try_from(i).ok().and_then(|i| last.names.get(i)) else { return p.fail(code::INDEX_INVALID) };
                r.set_name(n);
            }
            p.complete(r)
        }
        OP_CLOSE => {
            if let Some(q) = dns_ep(st, id).and_then(|ep| ep.inflight.take()) {
                failed(q, code::CONNECTION_CLOSED, 0);
            }
            st.eps.remove(&id);
            st.remember_closed(id, PROTO_DNS);
            p.fail(code::SUCCESS)
        }
        _ => p.fail(code::OPERATION_UNKNOWN),
    }
}

/// GetHostByName / GetHostByAddr: the lookup runs on a thread of its own; its reply comes
/// through [`finish`].
fn start_lookup(st: &mut State, net: &'static Net, id: EndpointId, p: Pending) {
    let req = p.req;
    let servers = st.configured_dns_servers();
    let domain = st.default_domain();
    let port_of = |addr: u32| net.config.remote_port(addr, 53, "DNS server");
    let ports: Vec<(u32, u16)> = servers.iter().map(|&a| (a, port_of(a))).collect();
    let Some(ep) = dns_ep(st, id) else { return p.fail(code::CONNECTION_CLOSED) };
    ep.inflight = Some(p);
    let spawned = std::thread::Builder::new().name("ipstack-dns".into()).spawn(move || {
        let outcome = if req.op == OP_BY_NAME { lookup_name(&ports, domain.as_deref(), &req.name()) } else { lookup_addr(&ports, req.addr) };
        let mut st = net.lock();
        finish(&mut st, id, outcome);
    });
    if spawned.is_err() {
        if let Some(p) = dns_ep(st, id).and_then(|ep| ep.inflight.take()) {
            p.fail(code::FAIL);
        }
    }
}

/// A lookup that failed: counts written (0), `name`/`host_address` untouched (5.5).
fn failed(p: Pending, err: i32, server: u32) {
    let mut r = NetResult::new(&p.req, err);
    r.server_address = server;
    p.complete(r)
}

fn finish(st: &mut State, id: EndpointId, outcome: Result<HostEntry, (i32, u32)>) {
    let Some(ep) = dns_ep(st, id) else { return };
    let Some(p) = ep.inflight.take() else { return }; // closed meanwhile: already answered
    match outcome {
        Ok(h) => {
            let mut r = NetResult::new(&p.req, code::SUCCESS);
            r.set_name(&h.names[0]);
            r.server_address = h.server;
            r.host_address = h.addrs[0];
            r.host_valid = 1;
            r.n_address = h.addrs.len() as i32;
            r.n_alias = h.names.len() as i32;
            ep.last = Some(h);
            p.complete(r)
        }
        Err((e, server)) => {
            ep.last = None;
            failed(p, e, server)
        }
    }
}

fn resolv_conf_servers() -> Vec<u32> {
    std::fs::read_to_string("/etc/resolv.conf")
        .unwrap_or_default()
        .lines()
        .filter_map(|l| l.trim().strip_prefix("nameserver"))
        .filter_map(|a| a.trim().parse::<Ipv4Addr>().ok())
        .map(u32::from)
        .take(3)
        .collect()
}

/// Forward lookup. Samples append a trailing '.', which host resolvers reject for local
/// names: strip one (5.5).
pub fn lookup_name(servers: &[(u32, u16)], domain: Option<&str>, name: &str) -> Result<HostEntry, (i32, u32)> {
    let name = name.strip_suffix('.').unwrap_or(name);
    let first = servers.first().map_or(LOCALHOST, |s| s.0);
    if name.is_empty() {
        return Err((code::HOST_NOT_FOUND, first));
    }
    if let Ok(ip) = name.parse::<Ipv4Addr>() {
        return Ok(HostEntry { names: vec![name.to_string()], addrs: vec![ip.into()], server: first });
    }
    if servers.is_empty() {
        return host_lookup_name(name);
    }
    // a name without a dot is tried with the default domain first, then alone
    let mut candidates = Vec::new();
    if let Some(d) = domain.filter(|d| !name.contains('.') && !d.is_empty()) {
        candidates.push(format!("{name}.{}", d.trim_end_matches('.')));
    }
    candidates.push(name.to_string());
    let mut last = Err((code::HOST_NOT_FOUND, first));
    for qname in candidates {
        last = match query_servers(servers, &qname, 1) {
            Ok((server, answer)) if answer.addrs.is_empty() => Err((code::NO_DATA, server)),
            Ok((server, answer)) => {
                // official name = the end of the CNAME chain; the others are aliases
                let mut names = vec![answer.cname.clone().unwrap_or_else(|| qname.clone())];
                if answer.cname.is_some() {
                    names.push(qname);
                }
                let mut addrs = answer.addrs;
                addrs.dedup();
                return Ok(HostEntry { names, addrs, server });
            }
            Err(e) => Err(e),
        };
    }
    last
}

/// Reverse lookup.
pub fn lookup_addr(servers: &[(u32, u16)], addr: u32) -> Result<HostEntry, (i32, u32)> {
    if servers.is_empty() {
        return host_lookup_addr(addr);
    }
    let o = addr.to_be_bytes();
    let qname = format!("{}.{}.{}.{}.in-addr.arpa", o[3], o[2], o[1], o[0]);
    let (server, answer) = query_servers(servers, &qname, 12)?;
    match answer.ptr {
        Some(n) => Ok(HostEntry { names: vec![n], addrs: vec![addr], server }),
        None => Err((code::NO_DATA, server)),
    }
}

fn host_lookup_name(name: &str) -> Result<HostEntry, (i32, u32)> {
    let Ok(c) = CString::new(name) else { return Err((code::HOST_NOT_FOUND, LOCALHOST)) };
    // SAFETY: zeroed addrinfo hints are valid; getaddrinfo's list is freed below.
    unsafe {
        let mut hints: libc::addrinfo = std::mem::zeroed();
        hints.ai_family = libc::AF_INET;
        hints.ai_socktype = libc::SOCK_STREAM;
        hints.ai_flags = libc::AI_CANONNAME;
        let mut res: *mut libc::addrinfo = std::ptr::null_mut();
        let rc = libc::getaddrinfo(c.as_ptr(), std::ptr::null(), &hints, &mut res);
        if rc != 0 {
            let e = match rc {
                libc::EAI_NONAME => code::HOST_NOT_FOUND,
                libc::EAI_AGAIN => code::TRY_AGAIN,
                libc::EAI_FAIL => code::NO_RECOVERY,
                libc::EAI_NODATA | -9 => code::NO_DATA, // -9: EAI_ADDRFAMILY,
                _ => code::FAIL,
            };
            return Err((e, LOCALHOST));
        }
        let mut addrs = Vec::new();
        let mut official = name.to_string();
        let mut cur = res;
        while !cur.is_null() {
            let ai = &*cur;
            if !ai.ai_canonname.is_null() && cur == res {
                official = CStr::from_ptr(ai.ai_canonname).to_string_lossy().into_owned();
            }
            if ai.ai_family == libc::AF_INET && !ai.ai_addr.is_null() {
                let sa = &*(ai.ai_addr as *const libc::sockaddr_in);
                let a = u32::from_be(sa.sin_addr.s_addr);
                if !addrs.contains(&a) {
                    addrs.push(a);
                }
            }
            cur = ai.ai_next;
        }
        libc::freeaddrinfo(res);
        if addrs.is_empty() {
            return Err((code::NO_DATA, LOCALHOST));
        }
        let mut names = vec![official.clone()];
        if official != name {
            names.push(name.to_string());
        }
        Ok(HostEntry { names, addrs, server: LOCALHOST })
    }
}

fn host_lookup_addr(addr: u32) -> Result<HostEntry, (i32, u32)> {
    let sa = super::sys::sockaddr(addr, 0);
    let mut host = [0 as libc::c_char; 256];
    // SAFETY: valid sockaddr and output buffer.
    let rc = unsafe {
        libc::getnameinfo(
            (&sa as *const libc::sockaddr_in).cast(),
            std::mem::size_of::<libc::sockaddr_in>() as u32,
            host.as_mut_ptr(),
            host.len() as u32,
            std::ptr::null_mut(),
            0,
            libc::NI_NAMEREQD,
        )
    };
    if rc != 0 {
        return Err((if rc == libc::EAI_AGAIN { code::TRY_AGAIN } else { code::HOST_NOT_FOUND }, LOCALHOST));
    }
    // SAFETY: getnameinfo wrote a NUL-terminated name.
    let name = unsafe { CStr::from_ptr(host.as_ptr()) }.to_string_lossy().into_owned();
    Ok(HostEntry { names: vec![name], addrs: vec![addr], server: LOCALHOST })
}

// ---------------------------------------------------------------- DNS over UDP

#[derive(Debug, Default)]
pub struct Answer {
    pub addrs: Vec<u32>,
    pub cname: Option<String>,
    pub ptr: Option<String>,
}

/// Asks each server in turn (two tries each); an authoritative "no such name" ends
/// the search.
fn query_servers(servers: &[(u32, u16)], qname: &str, qtype: u16) -> Result<(u32, Answer), (i32, u32)> {
    let mut last_err = (code::TRY_AGAIN, servers[0].0);
    for &(addr, port) in servers {
        for _ in 0..2 {
            match query(addr, port, qname, qtype) {
                Ok((0, ans)) => return Ok((addr, ans)),
                Ok((3, _)) => return Err((code::HOST_NOT_FOUND, addr)),
                Ok((2, _)) => last_err = (code::TRY_AGAIN, addr),
                Ok(_) => return Err((code::NO_RECOVERY, addr)),
                Err(_) => last_err = (code::TRY_AGAIN, addr),
            }
        }
    }
    Err(last_err)
}

fn query(addr: u32, port: u16, qname: &str, qtype: u16) -> std::io::Result<(u8, Answer)> {
    static NEXT_ID: std::sync::atomic::AtomicU16 = std::sync::atomic::AtomicU16::new(0x4a11);
    let id = NEXT_ID.fetch_add(1, std::sync::atomic::Ordering::Relaxed) ^ (std::process::id() as u16);
    let packet = build_query(id, qname, qtype);
    let sock = UdpSocket::bind((Ipv4Addr::UNSPECIFIED, 0))?;
    sock.set_read_timeout(Some(Duration::from_millis(1500)))?;
    sock.connect((Ipv4Addr::from(addr), port))?;
    sock.send(&packet)?;
    let mut buf = [0u8; 1500];
    loop {
        let n = sock.recv(&mut buf)?;
        if let Some(parsed) = parse_response(&buf[..n], id) {
            return Ok(parsed);
        }
    }
}

pub fn build_query(id: u16, qname: &str, qtype: u16) -> Vec<u8> {
    let mut p = Vec::with_capacity(32 + qname.len());
    p.extend_from_slice(&id.to_be_bytes());
    p.extend_from_slice(&[0x01, 0x00, 0, 1, 0, 0, 0, 0, 0, 0]);
    for label in qname.trim_end_matches('.').split('.').filter(|l| !l.is_empty()) {
        let l = &label.as_bytes()[..label.len().min(63)];
        p.push(l.len() as u8);
        p.extend_from_slice(l);
    }
    p.push(0);
    p.extend_from_slice(&qtype.to_be_bytes());
    p.extend_from_slice(&1u16.to_be_bytes());
    p
}

/// Reads a (possibly compressed) name at `pos`; returns it and the position after it.
pub fn read_name(msg: &[u8], mut pos: usize) -> Option<(String, usize)> {
    let mut labels: Vec<String> = Vec::new();
    let mut end = None;
    for _ in 0..64 {
        let len = *msg.get(pos)? as usize;
        if len & 0xc0 == 0xc0 {
            let ptr = ((len & 0x3f) << 8) | *msg.get(pos + 1)? as usize;
            end.get_or_insert(pos + 2);
            pos = ptr;
            continue;
        }
        if len == 0 {
            return Some((labels.join("."), end.unwrap_or(pos + 1)));
        }
        labels.push(String::from_utf8_lossy(msg.get(pos + 1..pos + 1 + len)?).into_owned());
        pos += 1 + len;
    }
    None
}

/// (rcode, answer) of a response to query `id`; None if it is not one.
pub fn parse_response(msg: &[u8], id: u16) -> Option<(u8, Answer)> {
    if msg.len() < 12 || u16::from_be_bytes([msg[0], msg[1]]) != id || msg[2] & 0x80 == 0 {
        return None;
    }
    let rcode = msg[3] & 0x0f;
    let qd = u16::from_be_bytes([msg[4], msg[5]]);
    let an = u16::from_be_bytes([msg[6], msg[7]]);
    let mut pos = 12;
    for _ in 0..qd {
        pos = read_name(msg, pos)?.1 + 4;
    }
    let mut ans = Answer::default();
    for _ in 0..an {
        let (_, p) = read_name(msg, pos)?;
        let rtype = u16::from_be_bytes([*msg.get(p)?, *msg.get(p + 1)?]);
        let rdlen = u16::from_be_bytes([*msg.get(p + 8)?, *msg.get(p + 9)?]) as usize;
        let rdata = p + 10;
        msg.get(rdata..rdata + rdlen)?;
        match rtype {
            1 if rdlen == 4 => ans.addrs.push(u32::from_be_bytes([msg[rdata], msg[rdata + 1], msg[rdata + 2], msg[rdata + 3]])),
            5 => ans.cname = Some(read_name(msg, rdata)?.0),
            12 => ans.ptr = Some(read_name(msg, rdata)?.0),
            _ => {}
        }
        pos = rdata + rdlen;
    }
    Some((rcode, ans))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn query_round_trip() {
        let q = build_query(7, "aibo.example.", 1);
        assert_eq!(read_name(&q, 12).unwrap().0, "aibo.example");
        // a response: header, the question, one compressed A answer
        let mut r = q.clone();
        r[2] = 0x81;
        r[3] = 0x80;
        r[7] = 1;
        r.extend_from_slice(&[0xc0, 12, 0, 1, 0, 1, 0, 0, 0, 60, 0, 4, 10, 0, 1, 2]);
        let (rc, a) = parse_response(&r, 7).unwrap();
        assert_eq!(rc, 0);
        assert_eq!(a.addrs, vec![0x0a000102]);
        assert!(parse_response(&r, 8).is_none());
    }

    #[test]
    fn literal_and_trailing_dot() {
        let h = lookup_name(&[], None, "127.0.0.1.").unwrap();
        assert_eq!(h.addrs, vec![LOCALHOST]);
        let h = lookup_name(&[], None, "localhost.").unwrap();
        assert!(h.addrs.contains(&LOCALHOST));
    }
}
