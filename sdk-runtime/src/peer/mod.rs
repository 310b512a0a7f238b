//! The external robot protocol (docs/robot-protocol.md): peers — a physics simulator,
//! a recorder, a bridge to a real robot — attach on a Unix socket (`--robot-socket`)
//! or a loopback TCP port (`--robot-tcp`), receive every frame's effector output and
//! may supply sensor readings, camera pictures and microphone sound, and one of them
//! may own the clock (lockstep: frame N completes only once that peer sent its
//! READINGS for frame N).
//!
//! Threads: one accept thread per listening socket, one reader thread per connection
//! (parses, validates, answers HELLO and errors, files what the peer supplies in the
//! [`Hub`]). The frame thread calls [`Hub::exchange`] in the middle of each frame (after
//! the commands, before the sensors) to send FRAME / SPEAKER and to collect what the
//! peers supplied. A peer that disconnects leaves the robot where it last reported it;
//! the built-in model continues from there.
//!
//! The protocol itself — framing, constants, payload codecs and checks, the per-peer
//! send queue — is the `openr-peer-protocol` crate; this module is its runtime side.
mod messages;

pub use openr_peer_protocol::{outbox, payload, wire};

use std::collections::VecDeque;
use std::io::{Read, Write};
use std::net::{Shutdown, SocketAddr, TcpListener, TcpStream};
use std::os::unix::net::{UnixListener, UnixStream};
use std::path::{Path, PathBuf};
use std::sync::{Arc, Condvar, Mutex, MutexGuard};

use crate::audio::{Format, MIC_FORMAT};
use crate::error::{Error, ErrorKind, Result};
use crate::robot::{PendingFrame, PrimitiveId, Readings, VirtualRobot};
use crate::runtime::Runtime;
pub use openr_peer_protocol::encode::frame_payload;
use openr_peer_protocol::role_of;
use wire::*;

/// Where peers attach.
#[derive(Debug, Clone, Default)]
pub struct PeerOptions {
    pub socket: Option<PathBuf>,
    /// Loopback address only.
    pub tcp: Option<SocketAddr>,
    /// Run no frame before a peer owning the clock has attached.
    pub wait: bool,
}

/// Microphone sound a peer may queue ahead (16 s).
const MIC_QUEUE_MAX: usize = 1 << 20;

enum Conn {
    Unix(UnixStream),
    Tcp(TcpStream),
}

impl Conn {
    fn try_clone(&self) -> std::io::Result<Conn> {
        Ok(match self {
            Conn::Unix(s) => Conn::Unix(s.try_clone()?),
            Conn::Tcp(s) => Conn::Tcp(s.try_clone()?),
        })
    }
    fn shutdown(&self) {
        self.shutdown_how(Shutdown::Both);
    }
    fn shutdown_how(&self, how: Shutdown) {
        let _ = match self {
            Conn::Unix(s) => s.shutdown(how),
            Conn::Tcp(s) => s.shutdown(how),
        };
    }
    fn set_write_timeout(&self, d: std::time::Duration) {
        let _ = match self {
            Conn::Unix(s) => s.set_write_timeout(Some(d)),
            Conn::Tcp(s) => s.set_write_timeout(Some(d)),
        };
    }
}

impl Read for Conn {
    fn read(&mut self, b: &mut [u8]) -> std::io::Result<usize> {
        match self {
            Conn::Unix(s) => s.read(b),
            Conn::Tcp(s) => s.read(b),
        }
    }
}

impl Write for Conn {
    fn write(&mut self, b: &[u8]) -> std::io::Result<usize> {
        match self {
            Conn::Unix(s) => s.write(b),
            Conn::Tcp(s) => s.write(b),
        }
    }
    fn flush(&mut self) -> std::io::Result<()> {
        Ok(())
    }
}

struct Peer {
    id: u64,
    name: String,
    roles: u32,
    /// The socket, for shutting its reading side (the writer thread owns a clone).
    conn: Conn,
    out: Arc<outbox::Outbox>,
}

impl Peer {
    /// Queues a message for the peer's writer thread (waits at most `PATIENCE` when
    /// the peer is behind); the error says why the peer must go.
    fn send(&self, kind: u16, frame: u32, payload: &[u8]) -> std::result::Result<(), String> {
        self.out.push(message(kind, frame, payload), outbox::PATIENCE).map_err(|r| match r {
            outbox::Refused::Closed => "the connection broke".to_string(),
            outbox::Refused::Stalled => format!("it stopped reading (nothing taken for {} s)", outbox::PATIENCE.as_secs()),
        })
    }

    /// A last message (ERROR, BYE): queued if there is room, then the queue closes and
    /// the writer ends after sending it.
    fn send_last(&self, kind: u16, frame: u32, payload: &[u8]) {
        let _ = self.out.push(message(kind, frame, payload), std::time::Duration::ZERO);
        self.out.close();
    }
}

#[derive(Default)]
struct State {
    peers: Vec<Arc<Peer>>,
    next_id: u64,
    clock: Option<u64>,
    /// Owner of each role bit.
    roles: [Option<u64>; 7],
    /// (clock owner, frame) whose READINGS the frame thread waits for.
    awaiting: Option<(u64, u32)>,
    lockstep: Option<Readings>,
    /// READINGS of peers not owning the clock, applied at the next frame.
    pending: Vec<Readings>,
    image: Option<Vec<u8>>,
    mic: VecDeque<u8>,
    /// Roles given up since the last frame (their outside values are dropped).
    released: u32,
    last_frame: u32,
    time_ms: u64,
    closed: bool,
    /// The run is ending: the frame thread no longer waits for the clock owner.
    ending: bool,
}

/// Peers attached to the robot.
#[derive(Default)]
pub struct Hub {
    st: Mutex<State>,
    cv: Condvar,
    active: std::sync::atomic::AtomicBool,
    wait: std::sync::atomic::AtomicBool,
}

/// What the peers supplied for one frame.
pub struct Inbound {
    readings: Vec<Readings>,
    image: Option<Vec<u8>>,
    released: u32,
}

impl Hub {
    fn lock(&self) -> MutexGuard<'_, State> {
        self.st.lock().unwrap_or_else(|p| p.into_inner())
    }

    /// True while at least one peer is attached (or ever was: cheap check per frame).
    pub fn active(&self) -> bool {
        self.active.load(std::sync::atomic::Ordering::Acquire)
    }

    /// Does an attached peer hold `role`?
    pub fn has_role(&self, role: u32) -> bool {
        self.active() && self.lock().roles[role.trailing_zeros() as usize].is_some()
    }

    /// Frame thread, before the first frame: with `--robot-wait`, blocks until a peer
    /// owns the clock.
    pub fn wait_for_clock_owner(&self, rt: &Runtime) {
        if !self.wait.load(std::sync::atomic::Ordering::Acquire) {
            return;
        }
        rt.diag.info("virtual robot: waiting for a robot peer to take the clock");
        let mut st = self.lock();
        while st.clock.is_none() && !st.closed {
            st = self.cv.wait(st).unwrap_or_else(|p| p.into_inner());
        }
    }

    /// The next microphone block from the peer holding the mic role (silence when it
    /// sent too little).
    pub fn mic_block(&self, len: usize) -> Vec<u8> {
        let mut st = self.lock();
        let n = st.mic.len().min(len);
        let mut block: Vec<u8> = st.mic.drain(..n).collect();
        block.resize(len, 0);
        block
    }

    /// Frame thread, between the commands and the sensors of a frame: sends SPEAKER
    /// (what starts playing now) and FRAME to every peer, waits for the clock owner's
    /// READINGS of this frame (lockstep: however long it takes, or until it leaves),
    /// and returns what the peers supplied.
    pub fn exchange(&self, rt: &Runtime, frame: &PendingFrame, frame_payload: &[u8], speaker: &[(Format, Vec<u8>)]) -> Inbound {
        let n = frame.frame();
        let (peers, owner) = {
            let mut st = self.lock();
            st.last_frame = n;
            st.time_ms = frame.time_ms();
            let owner = st.clock;
            st.awaiting = owner.map(|o| (o, n));
            st.lockstep = None;
            (st.peers.clone(), owner)
        };
        let flags_at = 8; // offset of the flags byte in the FRAME payload
        for p in &peers {
            let mut res = Ok(());
            if p.roles & ROLE_SPEAKER != 0 {
                for (f, pcm) in speaker {
                    let mut o = Out::default();
                    o.u32(f.rate).u16(f.bits).u16(f.channels).bytes(pcm);
                    res = res.and_then(|_| p.send(SPEAKER, n, &o.0));
                }
            }
            let res = res.and_then(|_| {
                if Some(p.id) == owner {
                    let mut payload = frame_payload.to_vec();
                    payload[flags_at] |= FRAME_READINGS_EXPECTED;
                    p.send(FRAME, n, &payload)
                } else {
                    p.send(FRAME, n, frame_payload)
                }
            });
            if let Err(why) = res {
                if why.starts_with("it stopped reading") {
                    let role = if Some(p.id) == owner { " (it owned the clock: the built-in robot's clock runs on)" } else { "" };
                    rt.diag.warn(&format!("robot peer `{}` dropped after frame {n}: {why}{role}", p.name));
                }
                self.detach(rt, p.id, &why);
            }
        }
        let mut st = self.lock();
        if let Some(o) = owner {
            while st.lockstep.is_none() && st.clock == Some(o) && !st.closed && !st.ending {
                st = self.cv.wait(st).unwrap_or_else(|p| p.into_inner());
            }
        }
        st.awaiting = None;
        let mut readings = std::mem::take(&mut st.pending);
        readings.extend(st.lockstep.take());
        Inbound { readings, image: st.image.take(), released: std::mem::take(&mut st.released) }
    }

    /// Removes a peer (idempotent): its roles and the clock return to the built-in robot.
    fn detach(&self, rt: &Runtime, id: u64, why: &str) {
        let mut st = self.lock();
        let Some(pos) = st.peers.iter().position(|p| p.id == id) else { return };
        let p = st.peers.remove(pos);
        // The writer sends what is queued (an ERROR, say) and closes the socket; a
        // peer that does not read makes its write time out. Reading ends now.
        p.out.close();
        p.conn.shutdown_how(Shutdown::Read);
        {
            let s = &mut *st;
            for (bit, owner) in s.roles.iter_mut().enumerate() {
                if *owner == Some(id) {
                    *owner = None;
                    s.released |= 1 << bit;
                }
            }
        }
        if st.clock == Some(id) {
            st.clock = None;
        }
        if st.roles[ROLE_MIC.trailing_zeros() as usize].is_none() {
            st.mic.clear();
        }
        let frame = st.last_frame;
        drop(st);
        self.cv.notify_all();
        rt.diag.info(&format!("robot peer `{}` detached after frame {frame} ({why}); the built-in robot takes over", p.name));
    }

    /// The run is ending (shutdown, signal): a frame waiting for a clock owner that
    /// never answers completes without its READINGS, so the frame thread gives up its
    /// turn and the Stop/Destroy sequence can run.
    pub fn stop_lockstep(&self) {
        self.lock().ending = true;
        self.cv.notify_all();
    }

    /// End of the run: BYE to every peer, connections closed.
    pub fn close_all(&self, reason: &str) {
        let peers = {
            let mut st = self.lock();
            st.closed = true;
            std::mem::take(&mut st.peers)
        };
        self.cv.notify_all();
        let frame = self.lock().last_frame;
        for p in &peers {
            let mut o = Out::default();
            o.str(reason);
            p.send_last(BYE, frame, &o.0);
        }
        // BYE reaches the peers that read before the process ends (a silent one costs
        // at most the write timeout).
        for p in &peers {
            p.out.wait_done(outbox::WRITE_TIMEOUT);
            p.conn.shutdown();
        }
    }
}

impl Inbound {
    /// Applies the readings, the camera picture and the release of roles to the robot.
    pub fn apply(self, robot: &mut VirtualRobot) {
        if self.released != 0 {
            let ids: Vec<PrimitiveId> = robot
                .model()
                .primitives()
                .iter()
                .filter(|p| role_of(p.kind).is_some_and(|r| r & self.released != 0 && r != ROLE_JOINTS))
                .map(|p| p.id)
                .collect();
            robot.clear_sensor_overrides(Some(&ids));
            if self.released & ROLE_CAMERA != 0 {
                let _ = robot.set_camera_rgb(None);
            }
        }
        for r in &self.readings {
            // validated by the reader thread
            let _ = robot.apply_readings(r);
        }
        if let Some(rgb) = self.image {
            let _ = robot.set_camera_rgb(Some(rgb));
        }
    }
}

fn welcome_payload(rt: &Runtime, granted: u32, clock: bool) -> Vec<u8> {
    openr_peer_protocol::encode::welcome_payload(&rt.vr.robot(), granted, clock, MIC_FORMAT)
}

/// Binds the sockets of `opts` and serves them on threads of their own.
pub fn serve(rt: &'static Runtime, opts: &PeerOptions) -> Result<()> {
    let hub = &rt.vr.peers;
    hub.wait.store(opts.wait, std::sync::atomic::Ordering::Release);
    if opts.wait && opts.socket.is_none() && opts.tcp.is_none() {
        return Err(ErrorKind::Runtime("--robot-wait needs --robot-socket or --robot-tcp".into()).into());
    }
    if let Some(path) = &opts.socket {
        let _ = std::fs::remove_file(path);
        let l = UnixListener::bind(path).map_err(|e| Error::io(path, e))?;
        spawn_acceptor(rt, path, move || l.accept().map(|(s, _)| Conn::Unix(s)))?;
        rt.diag.info(&format!("robot peers attach at {}", path.display()));
    }
    if let Some(addr) = opts.tcp {
        if !addr.ip().is_loopback() {
            return Err(ErrorKind::Runtime(format!("--robot-tcp {addr}: only loopback addresses (127.0.0.1, ::1) are allowed")).into());
        }
        let l = TcpListener::bind(addr).map_err(|e| ErrorKind::Runtime(format!("--robot-tcp {addr}: {e}")))?;
        let bound = l.local_addr().map_or(addr.to_string(), |a| a.to_string());
        spawn_acceptor(rt, Path::new(&bound), move || {
            l.accept().map(|(s, _)| {
                let _ = s.set_nodelay(true);
                Conn::Tcp(s)
            })
        })?;
        rt.diag.info(&format!("robot peers attach at tcp {bound}"));
    }
    Ok(())
}

fn spawn_acceptor(rt: &'static Runtime, what: &Path, accept: impl Fn() -> std::io::Result<Conn> + Send + 'static) -> Result<()> {
    crate::runtime::spawn("openr-peer-listen", move || loop {
        match accept() {
            Ok(c) => {
                let _ = crate::runtime::spawn("openr-peer", move || connection(rt, c));
            }
            Err(_) => std::thread::sleep(std::time::Duration::from_millis(10)),
        }
    })
    .map_err(|e| Error::io(what, e))?;
    Ok(())
}

/// Sends ERROR and closes.
fn refuse(conn: &Mutex<Conn>, frame: u32, code: u16, text: &str, rt: &Runtime) {
    rt.diag.warn(&format!("robot peer: {text} (error {code}; connection closed)"));
    let mut c = conn.lock().unwrap_or_else(|p| p.into_inner());
    let _ = c.write_all(&message(ERROR, frame, &error(code, text)));
    c.shutdown();
}

/// One connection's reader thread.
fn connection(rt: &'static Runtime, conn: Conn) {
    let hub = &rt.vr.peers;
    conn.set_write_timeout(outbox::WRITE_TIMEOUT);
    let Ok(mut reader) = conn.try_clone() else { return };
    let mut reader = std::io::BufReader::new(&mut reader);
    // Before HELLO the connection has no Peer: errors go straight to the socket.
    let early = Mutex::new(conn);
    let (header, payload) = match read_message(&mut reader) {
        Ok(Some(Ok(m))) => m,
        Ok(Some(Err(Refusal(code, text)))) => return refuse(&early, 0, code, &text, rt),
        _ => return,
    };
    if header.kind != HELLO {
        return refuse(&early, 0, E_BAD_STATE, &format!("the first message must be HELLO (type {HELLO}), not type {}", header.kind), rt);
    }
    let hello = match parse_hello(&payload) {
        Ok(h) => h,
        Err(e) => return refuse(&early, 0, E_BAD_PAYLOAD, &format!("HELLO: {e}"), rt),
    };
    let conn = early.into_inner().unwrap_or_else(|p| p.into_inner());
    let Ok(mut writer) = conn.try_clone() else { return };
    let out = Arc::new(outbox::Outbox::default());
    {
        let out = out.clone();
        let spawned = crate::runtime::spawn("openr-peer-write", move || {
            let end = writer.try_clone().ok();
            // Only the writing side: a stalled peer is detached (with a warning) by the
            // next message the frame thread cannot queue, not by its reader seeing EOF.
            out.run_writer(&mut writer, move || {
                if let Some(c) = end {
                    c.shutdown_how(Shutdown::Write);
                }
            })
        });
        if spawned.is_err() {
            return;
        }
    }
    let Some(peer) = attach(rt, &hello, conn, out) else { return };
    hub.cv.notify_all();
    let why = messages::serve_peer(rt, &peer, &mut reader);
    hub.detach(rt, peer.id, &why);
}

/// Grants what the HELLO asks for that is free, sends the WELCOME and lists the peer;
/// None when the WELCOME cannot be sent (nothing is then held).
fn attach(rt: &Runtime, hello: &Hello, conn: Conn, out: Arc<outbox::Outbox>) -> Option<Arc<Peer>> {
    let hub = &rt.vr.peers;
    let mut st = hub.lock();
    let id = st.next_id;
    st.next_id += 1;
    let mut granted = 0;
    for bit in 0..ROLE_NAMES.len() {
        if hello.roles & (1 << bit) != 0 && st.roles[bit].is_none() {
            st.roles[bit] = Some(id);
            granted |= 1 << bit;
        }
    }
    let clock = hello.flags & FLAG_CLOCK != 0 && st.clock.is_none();
    let name = if hello.name.is_empty() { format!("peer{id}") } else { hello.name.clone() };
    let peer = Arc::new(Peer { id, name, roles: granted, conn, out });
    // WELCOME goes out before the peer is listed: no FRAME can precede it.
    let welcome = welcome_payload(rt, granted, clock);
    if peer.send(WELCOME, st.last_frame, &welcome).is_err() {
        peer.out.close();
        for r in st.roles.iter_mut() {
            if *r == Some(id) {
                *r = None;
            }
        }
        return None;
    }
    if clock {
        st.clock = Some(id);
    }
    st.peers.push(peer.clone());
    hub.active.store(true, std::sync::atomic::Ordering::Release);
    let roles: Vec<&str> = (0..ROLE_NAMES.len()).filter(|b| granted & (1 << b) != 0).map(|b| ROLE_NAMES[b]).collect();
    rt.diag.info(&format!(
        "robot peer `{}` attached after frame {} (roles: {}{})",
        peer.name,
        st.last_frame,
        if roles.is_empty() { "none".to_string() } else { roles.join(", ") },
        if clock { "; owns the clock" } else { "" }
    ));
    Some(peer)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::robot::model::Design;

    fn robot() -> VirtualRobot {
        VirtualRobot::new(Design::Ers7)
    }

    #[test]
    fn readings_replace_joint_angles_and_sensors_until_released() {
        let mut r = robot();
        let j = r.open_primitive("PRM:/r2/c1-Joint2:21").unwrap();
        let acc = r.open_primitive("PRM:/a1-Sensor:a1").unwrap();
        let chin = r.open_primitive("PRM:/r2/c1/c2/c3/c4-Sensor:24").ok();
        assert!(chin.is_some());
        for _ in 0..3 {
            r.step_frame();
        }
        let p = r.begin_frame();
        assert_eq!(p.frame(), 4);
        assert!(p.sensor_due());
        let payload = frame_payload(&r, &p);
        assert_eq!(payload.len(), 8 + 4 + 2 + 18 * 20 + 2 + 8 * payload_count(&payload, 1) + 2 + 8 * payload_count(&payload, 2));
        let mut sensors = vec![(acc, 1_234_567)];
        if let Some(c) = chin {
            sensors.push((c, 1));
        }
        let inbound = Inbound { readings: vec![Readings { joints: vec![(j, 300_000)], sensors }], image: None, released: 0 };
        inbound.apply(&mut r);
        let out = r.end_frame(p);
        assert_eq!(r.joint_value(j).unwrap().value, 300_000);
        assert_eq!(r.sensor_value(acc).unwrap().value, 1_234_567);
        assert!(out.sensor_vector.is_some());
        // the built-in servo continues from the reported angle; the override stays
        r.step_frame();
        assert_eq!(r.sensor_value(acc).unwrap().value, 1_234_567);
        // released: synthesized again (gravity on a3 only when lying)
        let p = r.begin_frame();
        Inbound { readings: vec![], image: None, released: ROLE_ACCEL }.apply(&mut r);
        r.end_frame(p);
        assert_ne!(r.sensor_value(acc).unwrap().value, 1_234_567);
        assert_eq!(r.apply_readings(&Readings { joints: vec![(acc, 0)], sensors: vec![] }), Err(acc));
    }

    /// LED (which = 1) or ear (which = 2) count of a FRAME payload.
    fn payload_count(p: &[u8], which: usize) -> usize {
        let joints = u16::from_le_bytes([p[12], p[13]]) as usize;
        let at = 14 + joints * 20;
        let leds = u16::from_le_bytes([p[at], p[at + 1]]) as usize;
        if which == 1 {
            return leds;
        }
        let at = at + 2 + leds * 8;
        u16::from_le_bytes([p[at], p[at + 1]]) as usize
    }

    #[test]
    fn an_outside_picture_becomes_the_camera_image() {
        let mut r = robot();
        let (w, h) = (r.camera().rgb.width, r.camera().rgb.height);
        assert!(r.set_camera_rgb(Some(vec![0; 10])).is_err());
        let pink = [250u8, 90, 160].repeat(w * h);
        Inbound { readings: vec![], image: Some(pink.clone()), released: 0 }.apply(&mut r);
        let mut img = Vec::new();
        r.render_image(1, &mut img);
        assert_eq!(img.len(), r.image_layout().size());
        let centre = r.camera_rgb().pixel(w / 2, h / 2);
        assert_eq!(centre, [250, 90, 160]);
        Inbound { readings: vec![], image: None, released: ROLE_CAMERA }.apply(&mut r);
        r.render_image(2, &mut img);
        assert_ne!(r.camera_rgb().data, pink, "the scene again");
    }
}
