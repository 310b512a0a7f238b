//! The virtual robot in the running system: [`robot::VirtualRobot`] behind the OPENR::
//! hardware calls, a frame thread that advances it every 8 ms, and the traffic with the
//! system objects (`OVirtualRobotComm`, built from `cxx/system/`), which speak the
//! subject/observer protocol with user objects.
//!
//! Effector: the system object hands each received command vector to [`VrService::submit`]
//! and keeps the region; when the robot reports the vector done, an `OPENR_VR_DONE` event
//! tells the object to release that region and ASSERT-READY its subject. Sensor: every
//! 4th frame the robot's sensor vector is copied into a fresh shared region and sent to
//! the object as an `OPENR_VR_DATA` event, which publishes it to the observers.
use std::collections::HashMap;
use std::fs::File;
use std::io::{BufWriter, Write};
use std::sync::Mutex;

use crate::clock::{Speed, FRAME};
use crate::robot::{self, vectors, VirtualRobot};
use crate::runtime::Runtime;

pub const SERVICE_EFFECTOR: usize = openr_sys::VR_EFFECTOR as usize;
pub const SERVICE_SENSOR: usize = openr_sys::VR_SENSOR as usize;
pub const SERVICE_IMAGE: usize = openr_sys::VR_IMAGE as usize;
pub const SERVICE_SPEAKER: usize = openr_sys::VR_SPEAKER as usize;
pub const SERVICE_MIC: usize = openr_sys::VR_MIC as usize;
use openr_sys::{openr_vr_event as VrEvent, MemId, Selector, VR_CONNECTED as EVENT_CONNECTED, VR_DATA as EVENT_DATA, VR_DONE as EVENT_DONE};

fn event_bytes(ev: &VrEvent) -> Vec<u8> {
    // SAFETY: a repr(C) struct of plain integers without padding (16 + 8 bytes).
    unsafe { std::slice::from_raw_parts((ev as *const VrEvent).cast::<u8>(), std::mem::size_of::<VrEvent>()) }.to_vec()
}

#[derive(Default)]
struct Wiring {
    /// Per service: the system object (oid, event selector) that provides it.
    providers: [Option<(usize, Selector)>; 5],
    /// Subject (oid, selector) → the robot's connection id.
    connections: HashMap<(usize, Selector), u32>,
    /// Playing vectors: token → (base address, size) of the region the object keeps.
    playing: HashMap<u64, (usize, usize)>,
}

pub struct VrService {
    pub robot: Mutex<VirtualRobot>,
    wiring: Mutex<Wiring>,
    trace: Option<Mutex<BufWriter<File>>>,
    speaker: Mutex<crate::audio::Speaker>,
    mic: Mutex<crate::audio::Mic>,
    /// Images are rendered only when a CONNECT.CFG line names the camera service.
    camera_wanted: std::sync::atomic::AtomicBool,
    /// Mic blocks are published only when a CONNECT.CFG line names the mic service
    /// (otherwise the audio object would wake every 32 ms for nothing).
    mic_wanted: std::sync::atomic::AtomicBool,
    /// Frames run, and those that started more than a frame late (real-time speeds).
    pub frames: std::sync::atomic::AtomicU64,
    pub late_frames: std::sync::atomic::AtomicU64,
    /// External robot peers (docs/robot-protocol.md).
    pub peers: crate::peer::Hub,
    /// In-process observers shown each frame (`--record`); set before the first frame.
    pub observers: std::sync::OnceLock<crate::observe::Observers>,
}

/// The camera's service name: rendering is skipped unless something observes it.
pub const CAMERA_SERVICE: &str = "OVirtualRobotComm.FbkImageSensor.OFbkImageVectorData.S";
/// The mic's: its blocks are published only when something observes it.
pub const MIC_SERVICE: &str = "OVirtualRobotAudioComm.Mic.OSoundVectorData.S";

impl VrService {
    pub fn new(mut robot: VirtualRobot, trace: Option<File>, speaker: crate::audio::Speaker, mic: crate::audio::Mic) -> VrService {
        robot.set_trace(trace.is_some());
        VrService {
            robot: Mutex::new(robot),
            wiring: Mutex::new(Wiring::default()),
            trace: trace.map(|f| Mutex::new(BufWriter::new(f))),
            speaker: Mutex::new(speaker),
            mic: Mutex::new(mic),
            camera_wanted: std::sync::atomic::AtomicBool::new(false),
            mic_wanted: std::sync::atomic::AtomicBool::new(false),
            frames: std::sync::atomic::AtomicU64::new(0),
            late_frames: std::sync::atomic::AtomicU64::new(0),
            peers: crate::peer::Hub::default(),
            observers: std::sync::OnceLock::new(),
        }
    }

    pub fn want_camera(&self) {
        self.camera_wanted.store(true, std::sync::atomic::Ordering::Release);
    }

    pub fn want_mic(&self) {
        self.mic_wanted.store(true, std::sync::atomic::Ordering::Release);
    }

    /// A sound vector received by the speaker.
    pub fn submit_sound(&self, base: usize, size: usize) -> Result<u64, String> {
        self.speaker.lock().unwrap_or_else(|p| p.into_inner()).submit(base, size)
    }

    pub fn robot(&self) -> std::sync::MutexGuard<'_, VirtualRobot> {
        self.robot.lock().unwrap_or_else(|p| p.into_inner())
    }

    fn wiring(&self) -> std::sync::MutexGuard<'_, Wiring> {
        self.wiring.lock().unwrap_or_else(|p| p.into_inner())
    }

    pub fn attach(&self, service: usize, oid: usize, selector: Selector) -> bool {
        match self.wiring().providers.get_mut(service) {
            Some(slot) => {
                *slot = Some((oid, selector));
                true
            }
            None => false,
        }
    }

    /// The service manager connected a subject to an observer of system object `oid`:
    /// the object asserts ready to it (robot-api 8.2.3, 8.5), and has done so when this
    /// returns, so the Ready is queued at the subject before its Start. False when `oid`
    /// provides no service of the robot.
    pub fn connected(&self, rt: &Runtime, oid: usize, timeout: std::time::Duration) -> bool {
        let provider = self.wiring().providers.iter().flatten().find(|p| p.0 == oid).copied();
        let Some((oid, sel)) = provider else { return false };
        let ev = VrEvent { kind: EVENT_CONNECTED, service: 0, token: 0, mem_id: MemId::default(), size: 0 };
        rt.sched.boot_turn();
        rt.call_with(oid, sel, event_bytes(&ev), Some(timeout), || rt.sched.release()).is_ok()
    }

    /// A command vector received by the effector from subject (oid, selector).
    pub fn submit(&self, subject: (usize, Selector), base: usize, size: usize) -> Result<u64, robot::VectorError> {
        let conn = {
            let mut w = self.wiring();
            let next = w.connections.len() as u32 + 1;
            *w.connections.entry(subject).or_insert(next)
        };
        // SAFETY: the system object keeps the region alive until we report it done.
        let bytes = unsafe { std::slice::from_raw_parts(base as *const u8, size) };
        let token = self.robot().submit_command(conn, bytes)?;
        self.wiring().playing.insert(token, (base, size));
        Ok(token)
    }

    /// Runs one frame and delivers what it produced. With robot peers attached, the
    /// frame's effector output goes to them between the commands and the sensors, and
    /// what they supplied (readings, a camera picture) replaces the model's.
    pub fn step(&self, rt: &Runtime) {
        let pending = self.robot().begin_frame();
        let amplifier = self.robot().motor_power();
        let played = self.speaker.lock().unwrap_or_else(|p| p.into_inner()).step(pending.frame(), amplifier, |m| rt.diag.warn(m));
        if self.peers.active() {
            let payload = crate::peer::frame_payload(&self.robot(), &pending);
            let inbound = self.peers.exchange(rt, &pending, &payload, &played.started);
            inbound.apply(&mut self.robot());
        }
        let out = self.robot().end_frame(pending);
        for s in &out.started {
            if let Some(&(base, size)) = self.wiring().playing.get(&s.token) {
                // SAFETY: still held by the system object (not reported done yet).
                let bytes = unsafe { std::slice::from_raw_parts_mut(base as *mut u8, size) };
                let _ = robot::write_frame_numbers(bytes, s);
            }
        }
        let effector = self.wiring().providers[SERVICE_EFFECTOR];
        for c in &out.completed {
            self.wiring().playing.remove(&c.token);
            if let Some((oid, sel)) = effector {
                let ev = VrEvent { kind: EVENT_DONE, service: SERVICE_EFFECTOR as u32, token: c.token, mem_id: MemId::default(), size: 0 };
                let _ = rt.send(oid, sel, event_bytes(&ev));
            }
        }
        let sensor = out.sensor_vector.is_some();
        if let Some(vector) = out.sensor_vector {
            self.publish_slice(rt, SERVICE_SENSOR, &vector);
        }
        let picture = out.camera_due && self.camera_wanted.load(std::sync::atomic::Ordering::Acquire);
        if picture {
            let mut robot = self.robot();
            let size = robot.image_vector_size();
            if !self.publish(rt, SERVICE_IMAGE, size, |region| robot.render_image_into(out.frame, region)) {
                // No region to deliver in: the camera still takes its picture (field counter).
                robot.render_image(out.frame, &mut Vec::new());
            }
        }
        if let Some((oid, sel)) = self.wiring().providers[SERVICE_SPEAKER] {
            for token in played.done {
                let ev = VrEvent { kind: EVENT_DONE, service: SERVICE_SPEAKER as u32, token, mem_id: MemId::default(), size: 0 };
                let _ = rt.send(oid, sel, event_bytes(&ev));
            }
        }
        if out.mic_due && self.wiring().providers[SERVICE_MIC].is_some() {
            let len = self.robot().model().design().mic_block_bytes();
            let block = if self.peers.has_role(crate::peer::wire::ROLE_MIC) {
                self.peers.mic_block(len)
            } else {
                self.mic.lock().unwrap_or_else(|p| p.into_inner()).next_block(len)
            };
            // The sound goes on (a mic file or peer is read at the robot's pace) whether
            // or not an object listens.
            let mic_id = self.robot().primitive_of(crate::robot::model::Part::Mic).unwrap_or(0);
            if self.mic_wanted.load(std::sync::atomic::Ordering::Acquire) {
                if let Ok(v) = vectors::build_mic_vector(mic_id, out.frame, &block) {
                    self.publish_slice(rt, SERVICE_MIC, &v);
                }
            }
        }
        if let Some(t) = &self.trace {
            let mut w = t.lock().unwrap_or_else(|p| p.into_inner());
            for r in &out.trace {
                let _ = writeln!(w, "{}", r.to_json());
            }
        }
        if let Some(observers) = self.observers.get() {
            let frame = crate::observe::Frame { frame: out.frame, t_ms: out.time_ms, picture, sensor, sounds: &played.started };
            for o in &observers.0 {
                o.frame(rt, &frame);
            }
        }
    }

    /// Copies a finished vector into a new shared region and publishes it.
    fn publish_slice(&self, rt: &Runtime, service: usize, vector: &[u8]) {
        self.publish(rt, service, vector.len(), |region| region.copy_from_slice(vector));
    }

    /// Has `fill` write a vector of `len` bytes (every one of them: the region is not
    /// zeroed, it may hold an earlier vector) into a new shared region (a region is
    /// never rewritten while an observer may hold it, robot-api 7) and hands it, with
    /// the region's one reference, to the system object providing `service`. False when
    /// nobody provides the service or no region could be had (`fill` is not called).
    fn publish(&self, rt: &Runtime, service: usize, len: usize, fill: impl FnOnce(&mut [u8])) -> bool {
        let Some((oid, sel)) = self.wiring().providers[service] else { return false };
        let Some((mem_id, base)) = rt.shm.alloc_dirty(len) else { return false };
        // SAFETY: a fresh region of len bytes, ours until it is sent.
        let region = unsafe { std::slice::from_raw_parts_mut(base, len) };
        fill(region);
        let _ = vectors::set_region_fields(region, mem_id.0, 0, len as u32);
        let ev = VrEvent { kind: EVENT_DATA, service: service as u32, token: 0, mem_id, size: len as u32 };
        if rt.send(oid, sel, event_bytes(&ev)).is_err() {
            rt.shm.unref(mem_id);
        }
        true
    }

    pub fn flush_trace(&self) {
        if let Some(t) = &self.trace {
            let _ = t.lock().unwrap_or_else(|p| p.into_inner()).flush();
        }
    }
}

/// The frame thread: runs robot frames at the clock's speed. In real time (or a factor
/// of it) a frame that cannot start on time is counted and reported, never replayed; at
/// `max` each frame starts as soon as every object has handled everything sent to it
/// (or after `sched::FRAME_WORK` messages when they never do), so no sensor frame is
/// ever dropped. Due timers fire after each frame.
pub fn run_frames(rt: &'static Runtime) -> ! {
    rt.vr.peers.wait_for_clock_owner(rt);
    let mut pacer: Option<crate::pace::Pacer> = None;
    let mut late = 0u64;
    let mut late_reported = 0u64;
    let mut busy_reported = false;
    loop {
        let turn = rt.clock.speed() == Speed::Max;
        if turn {
            // The turn first, then the clock: at the end of virtual time the objects
            // stand still at the same message every run.
            let busy = rt.sched.frame_turn(|| rt.frames_allowed());
            if !busy.is_empty() && !busy_reported {
                report_busy(rt, &busy);
                busy_reported = true;
            }
            if !rt.clock.try_runnable() {
                if rt.clock.at_limit() {
                    rt.sched.hand_over();
                } else {
                    rt.sched.release();
                }
                rt.clock.park_until_runnable();
                continue;
            }
        } else {
            rt.clock.wait_runnable();
        }
        match rt.clock.speed() {
            Speed::Max => pacer = None,
            Speed::Factor(f) => {
                let period = FRAME.div_f64(f);
                let pacer = match &mut pacer {
                    Some(p) if p.period() == period => p,
                    _ => pacer.insert(crate::pace::Pacer::new(period)),
                };
                if pacer.wait() == crate::pace::Frame::Late {
                    late += 1;
                    rt.vr.late_frames.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                    if late >= late_reported * 2 + 1 {
                        rt.diag.warn(&format!("virtual robot: {late} frame(s) started late (the host could not keep up)"));
                        late_reported = late;
                    }
                }
            }
        }
        rt.vr.step(rt);
        rt.vr.frames.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
        let now = rt.clock.advance();
        rt.sched.wake_sleepers(now);
        rt.timers.fire_due(now, |dest, sel, msg| {
            let _ = rt.send(dest, sel, msg);
        });
        if turn {
            rt.sched.release();
        }
        report_stuck(rt);
    }
}

/// Once per run: the objects that kept the robot from ever being idle (they message
/// each other without end), so frames start every FRAME_WORK messages.
fn report_busy(rt: &Runtime, busy: &[(usize, u64)]) {
    let objects = rt.all_objects();
    let names: Vec<String> = busy.iter().filter_map(|&(i, n)| objects.get(i).map(|s| format!("`{}` ({n})", s.name()))).collect();
    rt.diag.warn(&format!(
        "virtual robot: the objects are never all idle; a frame starts after every {} messages (messages handled since the last frame: {})",
        crate::sched::FRAME_WORK,
        names.join(", ")
    ));
}

/// Objects whose one message outran the watchdog: named once each.
fn report_stuck(rt: &Runtime) {
    for (i, sel) in rt.sched.take_stuck() {
        let Some(slot) = rt.all_objects().get(i).cloned() else { continue };
        rt.diag.warn(&format!(
            "object `{}` has been running {} for more than the watchdog's time: it runs on its own, virtual time goes on without it",
            slot.name(),
            crate::lifecycle::entry_name(sel)
        ));
    }
}
