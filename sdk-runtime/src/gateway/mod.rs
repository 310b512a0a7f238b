//! The TCP gateways of Remote Processing OPEN-R (remote-processing 1.3, 7.2, 7.3;
//! docs/rp-protocol.md): the robot's `TCPGateway` (`/MS/OPEN-R/SYSTEM/OBJS/TCPGW.BIN`,
//! configured by ROBOTGW.CFG) and the host's `tcpGateway` (started for an MS with a
//! HOSTGW.CFG). Each line of the file is a service of the gateway object, registered
//! under its name verbatim, and one TCP channel to the other side's line of the same
//! port.
//!
//! The gateway is an OPEN-R object written in Rust (the `openr` crate) and built into
//! the runtime, as the virtual robot is: `TCPGW.BIN` in the SDK root's base trees is a
//! one-line file naming it ([`MAGIC`]), so OBJECT.CFG lists it as on the robot.
//!
//! Flow control is end to end: a gateway observer asserts ready to its local subjects
//! only when the far observer asserted ready (a READY frame), and a gateway subject
//! forwards its local observers' ASSERT/DEASSERT; so a subject that sends from `Ready()`
//! is paced by the far observer exactly as on one robot.
mod link;
pub mod proxy;
mod setup;
pub mod wire;

use std::sync::{Arc, Mutex, OnceLock};

use openr::{Context, NotifyEvent, Object, Observer, ReadyEvent, Subject};

use crate::runtime::Runtime;
use link::Link;

/// First bytes of a built-in object's `.BIN`; the rest of the line names it.
pub const MAGIC: &[u8] = openr_wrappers::rp::BUILTIN_MAGIC;
pub const ROBOT_GATEWAY: &str = "robot-gateway";
pub const HOST_GATEWAY: &str = "host-gateway";

/// The built-in object a `.BIN` stands for, if it is one.
pub fn builtin_name(image: &[u8]) -> Option<&str> {
    let rest = image.strip_prefix(MAGIC)?;
    std::str::from_utf8(rest).ok().map(str::trim)
}

pub use setup::{channels, module, Channel, Peer};

/// The gateway of one run (a run has at most one, as the robot has one TCPGateway).
#[derive(Default)]
pub struct State {
    setup: OnceLock<Setup>,
    failures: Mutex<Vec<String>>,
    /// The host's `tcpGateway` (else the robot's `TCPGateway`).
    host: std::sync::atomic::AtomicBool,
    /// The host gateway's `!ROBOT_PROXY` line, when it has one.
    client: OnceLock<Arc<Link>>,
    /// The proxy was found unreachable (said once).
    unreachable: std::sync::atomic::AtomicBool,
    /// The robot's design as its proxy answered.
    design: OnceLock<std::ffi::CString>,
}

/// The calling thread's run's gateway.
fn state() -> Option<&'static State> {
    Runtime::get().map(|rt| &rt.gateway)
}

fn setup() -> Option<&'static Setup> {
    state()?.setup.get()
}

/// What the gateway was set up with.
struct Setup {
    links: Vec<Arc<Link>>,
    /// Taken by the object's Start: what each line's thread does.
    targets: Mutex<Vec<Option<setup::Target>>>,
    oid: OnceLock<usize>,
}

/// What the gateway found wrong in the run of `rt` (the run fails with them): refused
/// pairings, and host channels that never reached the robot.
pub fn failures(rt: &Runtime) -> Vec<String> {
    let state = &rt.gateway;
    let mut out = state.failures.lock().unwrap_or_else(|p| p.into_inner()).clone();
    if let Some(s) = state.setup.get().filter(|_| state.host.load(std::sync::atomic::Ordering::Acquire)) {
        // A proxy nobody called is no failure (HelloWorld-stubgen/RP has one, unused).
        for l in s.links.iter().filter(|l| l.hello.suffix != b'P' && !l.ever_connected.load(std::sync::atomic::Ordering::Acquire)) {
            if !out.iter().any(|f| f.starts_with(&l.place)) {
                out.push(format!("{}: channel {} never reached the robot", l.place, l.hello.port));
            }
        }
    }
    out
}

fn rt() -> Option<&'static Runtime> {
    Runtime::get()
}

fn note(msg: &str) {
    if let Some(rt) = rt().filter(|rt| !rt.diag.quiet) {
        rt.diag.report.note(msg);
    }
}

fn warn(msg: &str) {
    if let Some(rt) = rt() {
        rt.diag.warn(msg);
    }
}

fn error(msg: &str) {
    if let Some(rt) = rt() {
        rt.diag.error(msg);
    }
}

/// An error that fails the run.
fn fail(msg: &str) {
    error(msg);
    if let Some(state) = state() {
        state.failures.lock().unwrap_or_else(|p| p.into_inner()).push(msg.to_string());
    }
}

/// Queues an event for the gateway object: `u32 len, kind:u8, channel:u16, payload`.
fn post(channel: usize, kind: u8, payload: &[u8]) {
    let (Some(rt), Some(oid)) = (rt(), setup().and_then(|s| s.oid.get())) else { return };
    let mut m = Vec::with_capacity(7 + payload.len());
    m.extend_from_slice(&((3 + payload.len()) as u32).to_le_bytes());
    m.push(kind);
    m.extend_from_slice(&(channel as u16).to_le_bytes());
    m.extend_from_slice(payload);
    let _ = rt.send(*oid, openr::SEL_EVENT, m);
}

/// Starts the thread of every line `which` picks that has not started yet.
fn spawn_targets(setup: &Setup, which: impl Fn(&Link) -> bool) {
    let mut targets = setup.targets.lock().unwrap_or_else(|p| p.into_inner());
    for (link, target) in setup.links.iter().zip(targets.iter_mut()) {
        if which(link) {
            if let Some(t) = target.take() {
                setup::spawn(link.clone(), t);
            }
        }
    }
}

/// One line's service in the object.
enum End {
    Sub(Subject<[u8]>),
    Obs(Observer<[u8]>),
    Proxy,
}

struct Gateway {
    ends: Vec<End>,
}

impl Gateway {
    fn link(&self, k: usize) -> Option<&'static Arc<Link>> {
        setup()?.links.get(k)
    }
}

impl Object for Gateway {
    fn init(ctx: &mut Context) -> Self {
        let Some(setup) = setup() else { return Gateway { ends: Vec::new() } };
        if let Some(me) = crate::object::current() {
            let _ = setup.oid.set(me.oid);
        }
        // The proxy first: host objects call OPENR:: from their DoInit already.
        spawn_targets(setup, |l| l.hello.suffix == b'P');
        let ends = setup
            .links
            .iter()
            .map(|l| match l.hello.suffix {
                b'S' => End::Sub(ctx.subject::<[u8]>(&l.hello.name)),
                b'O' => {
                    let o = ctx.observer::<[u8]>(&l.hello.name);
                    let (skip, min, max) = l.buf_ctrl;
                    o.set_buf_ctrl_param(ctx, skip, min, max);
                    End::Obs(o)
                }
                _ => End::Proxy,
            })
            .collect();
        Gateway { ends }
    }

    /// The channels open now: the program is connected and running.
    fn start(&mut self, _ctx: &mut Context) {
        if let Some(setup) = setup() {
            spawn_targets(setup, |_| true);
        }
    }

    /// Readiness belongs to the far side: nothing to withdraw here.
    fn stop(&mut self, _ctx: &mut Context) {}

    fn ready(&mut self, _ctx: &mut Context, event: ReadyEvent) {
        let Some(k) = self.ends.iter().position(|e| matches!(e, End::Sub(s) if s.is(&event))) else { return };
        if let Some(link) = self.link(k) {
            link.send(if event.is_assert() { wire::READY_ASSERT } else { wire::READY_DEASSERT }, &[]);
        }
    }

    fn notify(&mut self, _ctx: &mut Context, event: NotifyEvent) {
        let Some(k) = self.ends.iter().position(|e| matches!(e, End::Obs(o) if o.is(&event))) else { return };
        let Some(link) = self.link(k) else { return };
        // Not connected: the data is dropped and no READY goes back; the far side's
        // READY on (re)connection starts the flow again.
        for r in event.regions() {
            if !link.send(wire::DATA, r.bytes()) {
                break;
            }
        }
    }

    fn event(&mut self, ctx: &mut Context, data: &[u8]) {
        let (Some(&kind), Some(ch)) = (data.first(), data.get(1..3)) else { return };
        let k = u16::from_le_bytes([ch[0], ch[1]]) as usize;
        let payload = &data[3..];
        let (Some(end), Some(link)) = (self.ends.get(k), self.link(k)) else { return };
        match (kind, end) {
            (link::EV_CONNECTED, End::Sub(s)) if s.ready_observers(ctx) > 0 => {
                link.send(wire::READY_ASSERT, &[]);
            }
            (link::EV_DATA, End::Sub(s)) => {
                s.send(ctx, payload);
            }
            (link::EV_READY, End::Obs(o)) if o.subjects(ctx) > 0 => {
                if payload.first() == Some(&1) {
                    o.assert_ready(ctx);
                } else {
                    o.deassert_ready(ctx);
                }
            }
            _ => {}
        }
    }
}

/// The gateway's entry table, as `openr::object!` would export it.
static ENTRY_TABLE: [openr::abi::EntryRow; openr::ENTRY_ROWS] = openr::entry_table::<Gateway>();
