//! The OPEN-R life cycle as the robot runs it (object-model 2.1, 2.8.1; robot-api 8.2.3):
//! the system objects Init and Start first; then Init in every user object; the
//! connections of CONNECT.CFG one at a time, the effector and the speaker asserting
//! ready at each; then Start in every user object, in OBJECT.CFG order, none awaited (a
//! DoStart may block). At the end, Stop in every object, then Destroy.
//!
//! Every answer is awaited with a real-time watchdog (`--watchdog`, default 5 s): an
//! Init or a connection that takes longer is reported and still awaited (until a
//! signal), a Stop or Destroy that takes longer is given up. A signal ends any wait.
//! Each object that did not answer is a failure of the run, named with what it was
//! running.
use std::sync::atomic::Ordering;
use std::sync::mpsc::{Receiver, RecvTimeoutError};
use std::sync::Arc;
use std::time::{Duration, Instant};

use openr_sys::Selector;

use crate::cfg;
use crate::error::{Error, Result};
use crate::object::ObjectSlot;
use crate::runtime::{Runtime, FIRST_OID};

const OREASON_BOOT: u32 = 0;
const OREASON_SHUTDOWN: u32 = 1;
const SEL_INIT: Selector = Selector(0);
const SEL_START: Selector = Selector(1);
const SEL_STOP: Selector = Selector(2);
const SEL_DESTROY: Selector = Selector(3);

/// What the boot sequence or the shutdown could not get: one line per object.
#[derive(Debug, Default)]
pub struct Failures(pub Vec<String>);

/// The boot was cut short by a signal.
#[derive(Debug)]
pub struct Interrupted(pub i32);

/// `DoInit`, … for the four hooks, else the selector.
pub fn entry_name(sel: Selector) -> String {
    match sel {
        SEL_INIT => "DoInit".into(),
        SEL_START => "DoStart".into(),
        SEL_STOP => "DoStop".into(),
        SEL_DESTROY => "DoDestroy".into(),
        Selector::UNDEF => "a message".into(),
        s => format!("the entry for selector {s}"),
    }
}

fn hook_name(sel: Selector) -> &'static str {
    ["Init", "Start", "Stop", "Destroy"][sel.0 as usize]
}

/// How long a caller waits.
#[derive(Clone, Copy, PartialEq)]
enum Patience {
    /// Until answered or a signal (a warning once the watchdog has passed).
    Boot,
    /// At most the watchdog.
    Shutdown,
}

/// Waits for the answer on `rx`. `Ok(None)`: none came (watchdog, shutdown).
fn await_answer(
    rt: &Runtime,
    rx: &Receiver<Vec<u8>>,
    watchdog: Duration,
    patience: Patience,
    late: impl Fn(Duration),
) -> std::result::Result<Option<Vec<u8>>, Interrupted> {
    let start = Instant::now();
    let mut warned = false;
    loop {
        match rx.recv_timeout(Duration::from_millis(20)) {
            Ok(answer) => return Ok(Some(answer)),
            Err(RecvTimeoutError::Disconnected) => return Ok(None),
            Err(RecvTimeoutError::Timeout) => {}
        }
        let sig = rt.signal.load(Ordering::Acquire);
        if sig != 0 && patience == Patience::Boot {
            return Err(Interrupted(sig));
        }
        if start.elapsed() >= watchdog {
            if patience == Patience::Shutdown {
                return Ok(None);
            }
            if !warned {
                late(start.elapsed());
                warned = true;
            }
        }
    }
}

/// What object `slot` is running, for a failure message.
fn doing(rt: &Runtime, slot: &ObjectSlot, asked: Selector) -> String {
    match rt.sched.running(slot.index) {
        Some(sel) if sel != asked => format!("it is still running {}", entry_name(sel)),
        _ => format!("it is still running {}", entry_name(asked)),
    }
}

/// Runs one life-cycle hook as a call, once every object is idle (so the run does not
/// depend on timing), and reports a non-success status.
fn hook(
    rt: &Runtime,
    slot: &ObjectSlot,
    sel: Selector,
    watchdog: Duration,
    patience: Patience,
    failures: &mut Failures,
) -> std::result::Result<(), Interrupted> {
    let module = slot.module.get().expect("loaded");
    let what = hook_name(sel);
    let reason = if sel <= SEL_START { OREASON_BOOT } else { OREASON_SHUTDOWN };
    rt.sched.boot_turn();
    let rx = rt.call_start(slot.oid, sel, module.reason_message(reason));
    rt.sched.release();
    let Ok(rx) = rx else { return Ok(()) };
    let late = |waited: Duration| {
        rt.diag.warn(&format!("object `{}` has not answered {what} for {:.1} s ({}); still waiting", slot.name(), waited.as_secs_f64(), doing(rt, slot, sel)))
    };
    let answer = await_answer(rt, &rx, watchdog, patience, late).inspect_err(|Interrupted(sig)| {
        failures.0.push(format!("object `{}` did not answer {what}: {} when signal {sig} came", slot.name(), doing(rt, slot, sel)));
    })?;
    match answer {
        Some(reply) if !reply.is_empty() => {
            let status = module.status_of(&reply);
            if status != 0 {
                rt.diag.warn(&format!("object `{}`: Do{what} returned status {status}", slot.name()));
            }
        }
        Some(_) => {}
        None if slot.is_stopped() => {}
        None => failures.0.push(format!("object `{}` did not answer {what} within {:.1} s: {}", slot.name(), watchdog.as_secs_f64(), doing(rt, slot, sel))),
    }
    Ok(())
}

/// The boot sequence up to the Starts. Objects that answered Init are in `booted`.
pub fn boot(
    rt: &Runtime,
    all: &[Arc<ObjectSlot>],
    connect: (&std::path::Path, &[cfg::Connection]),
    lenient: bool,
    watchdog: Duration,
    booted: &mut Vec<Arc<ObjectSlot>>,
    failures: &mut Failures,
) -> Result<std::result::Result<(), Interrupted>> {
    let (system, user): (Vec<_>, Vec<_>) = all.iter().partition(|s| s.oid < FIRST_OID);
    for slot in &system {
        if let Err(i) = hook(rt, slot, SEL_INIT, watchdog, Patience::Boot, failures) {
            return Ok(Err(i));
        }
        booted.push((*slot).clone());
    }
    for slot in &system {
        if let Err(i) = hook(rt, slot, SEL_START, watchdog, Patience::Boot, failures) {
            return Ok(Err(i));
        }
    }
    for slot in &user {
        if let Err(i) = hook(rt, slot, SEL_INIT, watchdog, Patience::Boot, failures) {
            return Ok(Err(i));
        }
        booted.push((*slot).clone());
    }
    if connect.1.iter().any(|c| c.subject == crate::vr::CAMERA_SERVICE) {
        rt.vr.want_camera();
    }
    if connect.1.iter().any(|c| c.subject == crate::vr::MIC_SERVICE) {
        rt.vr.want_mic();
    }
    if let Err(i) = connect_all(rt, connect.0, connect.1, lenient, watchdog, failures)? {
        return Ok(Err(i));
    }
    rt.sched.boot_turn();
    for slot in &user {
        // Start is not awaited: a DoStart may block (on console input, say).
        let module = slot.module.get().expect("loaded");
        let _ = rt.send(slot.oid, SEL_START, module.reason_message(OREASON_BOOT));
    }
    rt.sched.release();
    Ok(Ok(()))
}

/// Stop in every object, then Destroy, each awaited at most the watchdog.
pub fn shutdown(rt: &Runtime, booted: &[Arc<ObjectSlot>], watchdog: Duration, failures: &mut Failures) {
    let mut gone = Vec::new();
    for sel in [SEL_STOP, SEL_DESTROY] {
        for slot in booted {
            if slot.is_stopped() || gone.contains(&slot.index) {
                continue;
            }
            if rt.console.waits_for_input(slot.index) {
                // Single-threaded, it cannot take a message while it waits (the robot's
                // objects neither): no Stop/Destroy, no watchdog to wait out.
                if sel == SEL_STOP {
                    rt.diag.info(&format!("object `{}` waits for console input: not stopped", slot.name()));
                }
                continue;
            }
            let before = failures.0.len();
            let _ = hook(rt, slot, sel, watchdog, Patience::Shutdown, failures);
            if failures.0.len() > before {
                gone.push(slot.index); // no Destroy for an object stuck in DoStop
            }
        }
    }
}

/// The connection phase: one CONNECT.CFG line at a time (object-model 2.8.1).
fn connect_all(
    rt: &Runtime,
    path: &std::path::Path,
    conns: &[cfg::Connection],
    lenient: bool,
    watchdog: Duration,
    failures: &mut Failures,
) -> Result<std::result::Result<(), Interrupted>> {
    let mut made = Vec::new();
    for c in conns {
        let (subject, observer) = (rt.service(&c.subject), rt.service(&c.observer));
        let (Some(subject), Some(observer)) = (subject, observer) else {
            let missing = if rt.service(&c.subject).is_none() { &c.subject } else { &c.observer };
            let mut names = rt.service_names();
            names.sort();
            let msg = format!("unknown service `{missing}`; registered services: {}", if names.is_empty() { "none".to_string() } else { names.join(", ") });
            if lenient {
                rt.diag.warn(&format!("{}:{}: {msg} (line skipped)", path.display(), c.line));
                continue;
            }
            return Err(Error::config(path, Some(c.line), msg));
        };
        let Some(obs_slot) = rt.object(observer.oid) else { continue };
        let module = obs_slot.module.get().expect("loaded");
        let msg = module.connect_message(0, subject.oid, subject.selector, &c.subject);
        rt.sched.boot_turn();
        let rx = rt.call_start(observer.oid, observer.selector, msg);
        rt.sched.release();
        let late = |waited: Duration| {
            rt.diag.warn(&format!("{}:{}: the connection has not been answered for {:.1} s; still waiting", path.display(), c.line, waited.as_secs_f64()))
        };
        let answer = match rx {
            Ok(rx) => match await_answer(rt, &rx, watchdog, Patience::Boot, late) {
                Ok(a) => a,
                Err(i) => {
                    failures.0.push(format!(
                        "{}:{}: the connection was not answered when signal {} came (observer `{}`)",
                        path.display(),
                        c.line,
                        i.0,
                        obs_slot.name()
                    ));
                    return Ok(Err(i));
                }
            },
            Err(_) => None,
        };
        match answer {
            Some(reply) => {
                let status = if reply.is_empty() { 0 } else { module.status_of(&reply) };
                if status != 0 {
                    rt.diag.warn(&format!("{}:{}: connection refused (status {status})", path.display(), c.line));
                } else {
                    rt.diag.info(&format!("connected {} -> {}", c.subject, c.observer));
                    made.push((subject.clone(), observer.clone()));
                    if observer.oid < FIRST_OID {
                        rt.vr.connected(rt, observer.oid, watchdog);
                    }
                }
            }
            None => rt.diag.warn(&format!("{}:{}: connection failed (no answer)", path.display(), c.line)),
        }
    }
    rt.links.set(made);
    Ok(Ok(()))
}
