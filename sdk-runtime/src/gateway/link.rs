//! The TCP side of one gateway line: the robot listens and takes a new host whenever one
//! connects (the old connection, if any, is dropped: the host restarted), the host
//! connects and reconnects until the run ends. Each connection begins with a HELLO each
//! way; a subject must meet an observer (or a proxy a proxy), else both ends refuse.
//!
//! Threads: one per line (accept or connect loop) and one reader per robot connection.
//! Readers post what arrives to the gateway object ([`super::post`]); the object writes
//! frames itself ([`Link::send`]). Proxy connections carry calls instead (proxy.rs).
use std::net::{Shutdown, SocketAddrV4, TcpListener, TcpStream};
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::{Arc, Condvar, Mutex, MutexGuard};
use std::time::{Duration, Instant};

use super::wire::{self, Hello};

/// Posted to the gateway object (`super::post`).
pub const EV_CONNECTED: u8 = 1;
pub const EV_LOST: u8 = 2;
pub const EV_DATA: u8 = 3;
pub const EV_READY: u8 = 4;

/// How often an unreachable robot is said to be unreachable again.
const RETRY_LOG: Duration = Duration::from_secs(5);
const RETRY: Duration = Duration::from_millis(200);
/// A far side that neither reads nor answers in this long is dropped.
const IO_TIMEOUT: Duration = Duration::from_secs(10);

pub struct Link {
    pub channel: usize,
    /// `…/ROBOTGW.CFG:3`: where the line is, for every message about it.
    pub place: String,
    pub hello: Hello,
    /// An observer line's dskip/dmin/dmax (`SetBufCtrlParam` of the gateway's observer).
    pub buf_ctrl: (usize, usize, usize),
    conn: Mutex<Option<(u64, TcpStream)>>,
    changed: Condvar,
    next_id: AtomicU64,
    pub ever_connected: AtomicBool,
}

impl Link {
    pub fn new(channel: usize, place: String, hello: Hello) -> Link {
        Link {
            channel,
            place,
            hello,
            buf_ctrl: (0, 1, 1),
            conn: Mutex::new(None),
            changed: Condvar::new(),
            next_id: AtomicU64::new(1),
            ever_connected: AtomicBool::new(false),
        }
    }

    fn lock(&self) -> MutexGuard<'_, Option<(u64, TcpStream)>> {
        self.conn.lock().unwrap_or_else(|p| p.into_inner())
    }

    /// Makes `s` the channel's connection (a previous one is shut down); its id.
    fn install(&self, s: &TcpStream) -> Option<u64> {
        let clone = s.try_clone().ok()?;
        let id = self.next_id.fetch_add(1, Ordering::Relaxed);
        if let Some((_, old)) = self.lock().replace((id, clone)) {
            let _ = old.shutdown(Shutdown::Both);
        }
        self.ever_connected.store(true, Ordering::Release);
        self.changed.notify_all();
        Some(id)
    }

    /// Forgets connection `id` if it is still the channel's; whether it was.
    fn clear(&self, id: u64) -> bool {
        let mut g = self.lock();
        let current = g.as_ref().is_some_and(|(i, _)| *i == id);
        if current {
            if let Some((_, s)) = g.take() {
                let _ = s.shutdown(Shutdown::Both);
            }
            self.changed.notify_all();
        }
        current
    }

    /// Writes one frame if connected; a failed write drops the connection (its reader
    /// then reports it lost).
    pub fn send(&self, kind: u8, payload: &[u8]) -> bool {
        let mut g = self.lock();
        let Some((_, s)) = g.as_mut() else { return false };
        if wire::write_frame(s, kind, payload).is_ok() {
            return true;
        }
        if let Some((_, s)) = g.take() {
            let _ = s.shutdown(Shutdown::Both);
        }
        false
    }

    /// A request/reply exchange on a proxy connection, waiting up to `wait` for one to
    /// be up. None when there is none or it broke.
    pub fn exchange(&self, kind: u8, payload: &[u8], wait: Duration) -> Option<(u8, Vec<u8>)> {
        let start = Instant::now();
        let mut g = self.lock();
        while g.is_none() {
            let left = wait.checked_sub(start.elapsed())?;
            g = self.changed.wait_timeout(g, left).unwrap_or_else(|p| p.into_inner()).0;
        }
        let (_, s) = g.as_mut()?;
        let _ = s.set_read_timeout(Some(IO_TIMEOUT));
        let answer = wire::write_frame(s, kind, payload).and_then(|()| wire::read_frame(s));
        match answer {
            Ok(a) => Some(a),
            Err(_) => {
                if let Some((_, s)) = g.take() {
                    let _ = s.shutdown(Shutdown::Both);
                }
                self.changed.notify_all();
                None
            }
        }
    }

    /// Blocks until connection `id` is gone.
    fn wait_gone(&self, id: u64) {
        let mut g = self.lock();
        while g.as_ref().is_some_and(|(i, _)| *i == id) {
            g = self.changed.wait(g).unwrap_or_else(|p| p.into_inner());
        }
    }

    /// HELLO both ways and the pairing check; the far side's HELLO, or why not.
    fn handshake(&self, s: &mut TcpStream) -> Result<Hello, String> {
        let port = self.hello.port;
        let place = &self.place;
        let _ = s.set_nodelay(true);
        let _ = s.set_read_timeout(Some(IO_TIMEOUT));
        let _ = s.set_write_timeout(Some(IO_TIMEOUT));
        wire::write_frame(s, wire::HELLO, &self.hello.encode()).map_err(|e| format!("{place}: channel {port}: cannot send HELLO: {e}"))?;
        let (kind, payload) = wire::read_frame(s).map_err(|e| format!("{place}: channel {port}: no HELLO from the far side ({e})"))?;
        if kind == wire::ERROR {
            return Err(format!("{place}: channel {port}: refused by the far side: {}", String::from_utf8_lossy(&payload)));
        }
        if kind != wire::HELLO {
            return Err(format!("{place}: channel {port}: the far side is not a cargo-openr gateway (frame type {kind} before HELLO)"));
        }
        let far = Hello::decode(&payload).map_err(|e| format!("{place}: channel {port}: {e}"))?;
        if let Some(why) = mismatch(&self.hello, &far) {
            let _ = wire::write_frame(s, wire::ERROR, why.as_bytes());
            return Err(format!("{place}: channel {port}: {why}"));
        }
        if self.hello.suffix != b'P' && far.data_type() != self.hello.data_type() {
            super::warn(&format!(
                "{place}: channel {port}: data type `{}` here, `{}` at the far side ({}); the bytes are passed on unchanged",
                self.hello.data_type(),
                far.data_type(),
                far.place
            ));
        }
        let _ = s.set_read_timeout(None);
        Ok(far)
    }
}

/// Why two lines cannot form a channel, if they cannot.
fn mismatch(ours: &Hello, far: &Hello) -> Option<String> {
    let what = |s: u8| match s {
        b'S' => "a subject (.S)",
        b'O' => "an observer (.O)",
        _ => "the OPEN-R API proxy",
    };
    let ok = matches!((ours.suffix, far.suffix), (b'S', b'O') | (b'O', b'S') | (b'P', b'P'));
    (!ok).then(|| {
        let both = if ours.suffix == far.suffix && ours.suffix != b'P' { " too" } else { "" };
        format!(
            "{} is {} and the far side's {} ({}) is {}{both}: a channel joins a subject on one side to an observer on the other, the proxy to the proxy",
            ours.name,
            what(ours.suffix),
            far.name,
            far.place,
            what(far.suffix)
        )
    })
}

/// Robot: accepts hosts on `listener` for good.
pub fn serve(link: Arc<Link>, listener: TcpListener) {
    for stream in listener.incoming() {
        let Ok(mut s) = stream else { continue };
        let peer = s.peer_addr().map_or_else(|_| "?".into(), |a| a.to_string());
        match link.handshake(&mut s) {
            Ok(far) => {
                let Some(id) = link.install(&s) else { continue };
                super::note(&format!("{}: channel {}: host {peer} connected ({} at {})", link.place, link.hello.port, far.name, far.place));
                let link = link.clone();
                let _ = crate::runtime::spawn("openr-gw-read", move || {
                    if link.hello.suffix == b'P' {
                        super::proxy::serve_calls(&mut s);
                        link.clear(id);
                    } else {
                        super::post(link.channel, EV_CONNECTED, &[]);
                        read_loop(&link, id, s);
                    }
                    super::note(&format!("{}: channel {}: host {peer} gone; listening for it again", link.place, link.hello.port));
                });
            }
            Err(why) => super::error(&why),
        }
    }
}

/// Host: connects to `addr`, reconnects when the connection drops; returns only when
/// the robot refuses the pairing (a configuration error, recorded as a failure).
pub fn connect(link: Arc<Link>, addr: SocketAddrV4) {
    let mut unreachable_since: Option<(Instant, Instant)> = None;
    loop {
        let mut s = match TcpStream::connect_timeout(&addr.into(), IO_TIMEOUT) {
            Ok(s) => s,
            Err(e) => {
                let now = Instant::now();
                match unreachable_since {
                    None => {
                        super::warn(&format!("{}: robot {addr} not reachable ({e}); retrying", link.place));
                        unreachable_since = Some((now, now));
                    }
                    Some((first, logged)) if now - logged >= RETRY_LOG => {
                        super::warn(&format!("{}: robot {addr} still not reachable after {} s ({e}); retrying", link.place, (now - first).as_secs()));
                        unreachable_since = Some((first, now));
                    }
                    _ => {}
                }
                std::thread::sleep(RETRY);
                continue;
            }
        };
        unreachable_since = None;
        let far = match link.handshake(&mut s) {
            Ok(far) => far,
            Err(why) => {
                super::fail(&why);
                return;
            }
        };
        let Some(id) = link.install(&s) else { continue };
        super::note(&format!("{}: channel {}: connected to robot {addr} ({} at {})", link.place, link.hello.port, far.name, far.place));
        if link.hello.suffix == b'P' {
            link.wait_gone(id);
        } else {
            super::post(link.channel, EV_CONNECTED, &[]);
            read_loop(&link, id, s);
        }
        super::warn(&format!("{}: channel {}: connection to robot {addr} lost; reconnecting", link.place, link.hello.port));
    }
}

/// Posts what the far side sends until the connection ends, then reports it lost.
fn read_loop(link: &Link, id: u64, mut s: TcpStream) {
    loop {
        match wire::read_frame(&mut s) {
            Ok((wire::DATA, p)) => super::post(link.channel, EV_DATA, &p),
            Ok((wire::READY_ASSERT, _)) => super::post(link.channel, EV_READY, &[1]),
            Ok((wire::READY_DEASSERT, _)) => super::post(link.channel, EV_READY, &[0]),
            Ok((kind, _)) => {
                super::warn(&format!("{}: channel {}: unexpected frame type {kind}; closing the connection", link.place, link.hello.port));
                break;
            }
            Err(_) => break,
        }
    }
    if link.clear(id) {
        super::post(link.channel, EV_LOST, &[]);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn hello(suffix: u8, name: &str) -> Hello {
        Hello { suffix, port: 59002, name: name.into(), place: "ROBOTGW.CFG:2".into() }
    }

    #[test]
    fn a_subject_pairs_only_with_an_observer() {
        assert_eq!(mismatch(&hello(b'S', "A.x.char.S"), &hello(b'O', "B.y.char.O")), None);
        assert_eq!(mismatch(&hello(b'P', "P"), &hello(b'P', "P")), None);
        let why = mismatch(&hello(b'S', "A.x.char.S"), &hello(b'S', "B.y.char.S")).unwrap();
        assert!(why.starts_with("A.x.char.S is a subject (.S) and the far side's B.y.char.S (ROBOTGW.CFG:2) is a subject (.S) too"), "{why}");
        assert!(mismatch(&hello(b'O', "A.x.char.O"), &hello(b'P', "P")).is_some());
    }

    /// Our side's handshake against a far side that answers with `frames` (real loopback
    /// sockets); its error.
    fn handshake_against(frames: Vec<(u8, Vec<u8>)>) -> String {
        let l = TcpListener::bind("127.0.0.1:0").unwrap();
        let addr = l.local_addr().unwrap();
        let far = std::thread::spawn(move || {
            let (mut s, _) = l.accept().unwrap();
            let _ = wire::read_frame(&mut s);
            for (kind, p) in frames {
                wire::write_frame(&mut s, kind, &p).unwrap();
            }
        });
        let link = Link::new(0, "HOSTGW.CFG:2".into(), hello(b'S', "A.x.char.S"));
        let mut s = TcpStream::connect(addr).unwrap();
        let e = link.handshake(&mut s).unwrap_err();
        far.join().unwrap();
        e
    }

    #[test]
    fn a_far_side_that_is_not_a_gateway_or_refuses_is_named() {
        let e = handshake_against(vec![(wire::DATA, b"x".to_vec())]);
        assert_eq!(e, "HOSTGW.CFG:2: channel 59002: the far side is not a cargo-openr gateway (frame type 2 before HELLO)");
        let e = handshake_against(vec![(wire::ERROR, b"no such line".to_vec())]);
        assert_eq!(e, "HOSTGW.CFG:2: channel 59002: refused by the far side: no such line");
        let e = handshake_against(vec![(wire::HELLO, vec![9, b'O', 0, 0])]);
        assert_eq!(e, "HOSTGW.CFG:2: channel 59002: gateway protocol version 9 (this side speaks 1)");
        let e = handshake_against(vec![]);
        assert!(e.starts_with("HOSTGW.CFG:2: channel 59002: no HELLO from the far side"), "{e}");
    }
}
