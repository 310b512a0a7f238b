//! The effector of `OVirtualRobotComm.Effector.OCommandVectorData.O`: per-connection
//! FIFO queues of command vectors and their frame timing (robot-api 8.2).
//!
//! Why it exists: samples pace themselves entirely by the effector's ASSERT-READY, which
//! must arrive once per *completed* vector; they prime two vectors and expect them to
//! play back to back, LEDs and ears to hold values for `period` frames, `wait` and sync
//! keys to delay starts. This module is that timing, as pure logic driven by
//! [`Effector::step`] once per 8 ms frame; the wiring releases the region and sends
//! ASSERT-READY for each [`Completed`] it reports, and writes `OCommandInfo.frameNumber`
//! for each [`Started`].
//!
//! Rules implemented:
//! * Each connection has a FIFO; only its head plays. A vector enqueued before a step
//!   starts in that step (its `frameNumber`); when its longest slot ends it completes in
//!   its last frame, and the next vector starts in the following frame (back to back).
//! * Slot duration: JOINT_COMMAND2/3 `numFrames`; JOINT_COMMAND4 / LED_COMMAND2/3 the sum
//!   of `period`s (0 counts as 1); legacy LED_COMMAND `period × 16`. numFrames 0 slots
//!   do nothing. A vector with no playable slot completes in its start frame.
//! * `wait` delays the start by that many frames once the vector reaches the head.
//! * A sync key part holds the head until all parts arrived ([`super::sync`]).
//! * Slots whose command type does not fit the primitive (e.g. JOINT_COMMAND2 to a
//!   Joint4 ear) or name an unknown primitive are ignored but still count towards the
//!   vector's duration, so the sender's pacing is unchanged; unsupported command types
//!   (legacy joint/camera, raw) last 0 frames.
//! * Several connections play concurrently; when two command the same primitive in one
//!   frame the later-arriving vector wins; immediate commands (`ControlPrimitive
//!   *_SET_COMMAND`) win over both.
//! * Joint targets are clamped to the software range, then (ERS-7) to the combined
//!   limits of ers7-model 4.2/4.3 using the same frame's target of the joint they depend
//!   on. A [`ClampEvent`] is reported when clamping starts or the requested value
//!   changes while clamped (not every frame of a constant out-of-range command).
//! * Held state: a primitive whose commands ran out keeps its last target.

use std::collections::{BTreeMap, VecDeque};

use rustc_hash::FxHashMap as HashMap;

use super::model::{PrimitiveId, PrimitiveKind, RobotModel};
use super::sync::{PartState, SyncKeys, SYNC_KEY_UNDEF};
use super::vectors::{CommandValues, CommandVector, FrameCommand, Led3Value};

/// Caller-chosen identifier of a queued vector (e.g. the region it lives in).
pub type Token = u64;
/// One subject → effector connection.
pub type ConnectionId = u32;

/// Why a slot is not executed.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum IgnoreReason {
    UnknownPrimitive,
    TypeMismatch { command: &'static str, kind: PrimitiveKind },
    Unsupported(u32),
}

/// A slot that is ignored (reported once, at enqueue time).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Ignored {
    pub slot: usize,
    pub primitive: PrimitiveId,
    pub reason: IgnoreReason,
}

/// A slot as queued.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct QueuedSlot {
    pub index: usize,
    pub primitive: PrimitiveId,
    pub values: CommandValues,
    /// False for ignored slots.
    pub active: bool,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum State {
    Pending { wait_left: u32 },
    Holding,
    Playing { start: u64 },
}

#[derive(Clone, Debug)]
struct Queued {
    token: Token,
    seq: u64,
    slots: Vec<QueuedSlot>,
    duration: u32,
    sync_key: u32,
    optional: Option<(u32, Vec<u8>)>,
    state: State,
}

/// The final command of one primitive in one frame.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Applied {
    pub primitive: PrimitiveId,
    /// After clamping.
    pub command: FrameCommand,
    /// As commanded.
    pub requested: FrameCommand,
    /// The vector it came from (None for immediate commands).
    pub source: Option<(ConnectionId, Token)>,
}

/// A vector that started this frame; write `frame` into `OCommandInfo[slot].frameNumber`
/// for every slot listed.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Started {
    pub connection: ConnectionId,
    pub token: Token,
    pub frame: u32,
    pub duration: u32,
    pub slots: Vec<QueuedSlot>,
}

/// A vector whose output finished this frame: release its region, then ASSERT-READY.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Completed {
    pub connection: ConnectionId,
    pub token: Token,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ClampRule {
    /// Single-joint software range (ers7-model 4.1).
    Range,
    /// J1-dependent J2 / tilt1-dependent tilt2 (ers7-model 4.2, 4.3).
    Combined,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ClampEvent {
    pub primitive: PrimitiveId,
    pub requested: i32,
    pub clamped: i32,
    pub rule: ClampRule,
}

/// Everything the effector did in one frame.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct EffectorFrame {
    pub applied: Vec<Applied>,
    pub started: Vec<Started>,
    pub completed: Vec<Completed>,
    pub clamps: Vec<ClampEvent>,
    /// Sync roots released this frame: (root key, timed out).
    pub sync_released: Vec<(u32, bool)>,
    /// `optional` bytes of the newest vector playing in this frame (robot-api 8.2.6):
    /// `(optOffset, bytes)`; captured before completed vectors leave their queues.
    pub optional: Option<(u32, Vec<u8>)>,
}

/// The effector.
#[derive(Clone, Debug)]
pub struct Effector {
    model: RobotModel,
    queues: BTreeMap<ConnectionId, VecDeque<Queued>>,
    seq: u64,
    targets: HashMap<PrimitiveId, FrameCommand>,
    immediate: Vec<(PrimitiveId, FrameCommand)>,
    clamping: HashMap<PrimitiveId, i32>,
}

fn fits(values: &CommandValues, kind: PrimitiveKind) -> Result<(), IgnoreReason> {
    let ok = match values {
        CommandValues::Joint2(_) => kind == PrimitiveKind::Joint2,
        CommandValues::Joint3(_) => kind == PrimitiveKind::Joint3,
        CommandValues::Joint4(_) => kind == PrimitiveKind::Joint4,
        CommandValues::Led2(_) => kind == PrimitiveKind::Led2,
        CommandValues::Led3(_) => kind == PrimitiveKind::Led3,
        CommandValues::LegacyLed(_) => matches!(kind, PrimitiveKind::Led2 | PrimitiveKind::Led3),
        CommandValues::Unsupported(t) => return Err(IgnoreReason::Unsupported(*t)),
    };
    if ok {
        Ok(())
    } else {
        Err(IgnoreReason::TypeMismatch { command: values.type_name(), kind })
    }
}

impl Effector {
    pub fn new(model: RobotModel) -> Effector {
        Effector { model, queues: BTreeMap::new(), seq: 0, targets: HashMap::default(), immediate: Vec::new(), clamping: HashMap::default() }
    }

    /// Queues a parsed vector on `connection` (one call per data item of a NOTIFY, in
    /// order). Returns the slots that will be ignored.
    pub fn enqueue(&mut self, connection: ConnectionId, vector: &CommandVector, token: Token) -> Vec<Ignored> {
        let mut ignored = Vec::new();
        let slots: Vec<QueuedSlot> = vector
            .slots
            .iter()
            .map(|s| {
                let verdict = match self.model.primitive(s.primitive) {
                    None => Err(IgnoreReason::UnknownPrimitive),
                    Some(p) => fits(&s.values, p.kind),
                };
                if let Err(reason) = &verdict {
                    ignored.push(Ignored { slot: s.index, primitive: s.primitive, reason: reason.clone() });
                }
                QueuedSlot { index: s.index, primitive: s.primitive, values: s.values.clone(), active: verdict.is_ok() }
            })
            .collect();
        let optional = vector.optional.clone().map(|b| (vector.header.opt_offset, b));
        self.seq += 1;
        self.queues.entry(connection).or_default().push_back(Queued {
            token,
            seq: self.seq,
            duration: vector.duration_frames(),
            slots,
            sync_key: vector.header.sync_key,
            optional,
            state: State::Pending { wait_left: vector.header.wait },
        });
        ignored
    }

    /// An immediate single-frame command (`ControlPrimitive` *_SET_COMMAND, robot-api
    /// 5.1), applied in the next step with priority over queued vectors.
    pub fn immediate(&mut self, primitive: PrimitiveId, command: FrameCommand) {
        self.immediate.push((primitive, command));
    }

    /// Vectors queued on `connection` (including the one playing).
    pub fn queue_len(&self, connection: ConnectionId) -> usize {
        self.queues.get(&connection).map_or(0, VecDeque::len)
    }

    /// Drops every vector of `connection` (the subject went away); returns their tokens
    /// so the wiring can release the regions.
    pub fn drop_connection(&mut self, connection: ConnectionId) -> Vec<Token> {
        self.queues.remove(&connection).map(|q| q.into_iter().map(|v| v.token).collect()).unwrap_or_default()
    }

    /// The held target of a primitive (last commanded value after clamping).
    pub fn target(&self, primitive: PrimitiveId) -> Option<FrameCommand> {
        self.targets.get(&primitive).copied()
    }

    /// The `optional` bytes of the most recently queued vector that is playing now
    /// (robot-api 8.2.6): `(optOffset, bytes)`.
    pub fn current_optional(&self) -> Option<(u32, &[u8])> {
        self.queues
            .values()
            .filter_map(|q| q.front())
            .filter(|v| matches!(v.state, State::Playing { .. }))
            .filter_map(|v| v.optional.as_ref().map(|(o, b)| (v.seq, *o, b.as_slice())))
            .max_by_key(|x| x.0)
            .map(|(_, o, b)| (o, b))
    }

    /// Executes one frame: `now` = frames since boot (monotonic), `frame` = frame number.
    pub fn step(&mut self, now: u64, frame: u32, sync: &mut SyncKeys) -> EffectorFrame {
        let mut out = EffectorFrame::default();
        self.count_down(now, sync);
        out.sync_released = sync.resolve(now);
        self.start_heads(now, frame, sync, &mut out);
        let cmds = self.frame_commands(now);
        let mut applied = self.adapt(&cmds);
        self.combined_limits(&mut applied, &mut out);
        for a in &applied {
            self.targets.insert(a.primitive, a.command);
        }
        out.applied = applied;
        out.optional = self.current_optional().map(|(o, b)| (o, b.to_vec()));
        self.complete(now, &mut out);
        out
    }

    /// 1. wait countdown; sync arrival.
    fn count_down(&mut self, now: u64, sync: &mut SyncKeys) {
        for q in self.queues.values_mut() {
            let Some(head) = q.front_mut() else { continue };
            if let State::Pending { wait_left } = head.state {
                if wait_left > 0 {
                    head.state = State::Pending { wait_left: wait_left - 1 };
                } else if head.sync_key != SYNC_KEY_UNDEF && sync.state(head.sync_key) == PartState::Waiting {
                    sync.arrive(head.sync_key, now);
                    head.state = State::Holding;
                } else {
                    head.state = State::Playing { start: now };
                }
            }
        }
    }

    /// 3. start: released holders and vectors whose wait ended this frame.
    fn start_heads(&mut self, now: u64, frame: u32, sync: &mut SyncKeys, out: &mut EffectorFrame) {
        for (&conn, q) in self.queues.iter_mut() {
            let Some(head) = q.front_mut() else { continue };
            match head.state {
                State::Holding => match sync.state(head.sync_key) {
                    PartState::Waiting => continue,
                    PartState::Released => {
                        sync.take(head.sync_key);
                        head.state = State::Playing { start: now };
                    }
                    PartState::Unknown => head.state = State::Playing { start: now },
                },
                State::Playing { start } if start == now => {}
                _ => continue,
            }
            out.started.push(Started { connection: conn, token: head.token, frame, duration: head.duration, slots: head.slots.clone() });
        }
    }

    /// 4. this frame's commands, later-arriving vectors overriding earlier ones, then
    /// the immediate commands.
    fn frame_commands(&mut self, now: u64) -> BTreeMap<PrimitiveId, (FrameCommand, Option<(ConnectionId, Token)>)> {
        let mut playing: Vec<(u64, ConnectionId, &Queued)> =
            self.queues.iter().filter_map(|(&c, q)| q.front().map(|v| (v.seq, c, v))).filter(|(_, _, v)| matches!(v.state, State::Playing { .. })).collect();
        playing.sort_by_key(|x| x.0);
        let mut cmds = BTreeMap::new();
        for (_, conn, v) in &playing {
            let State::Playing { start } = v.state else { continue };
            let k = u32::try_from(now - start).unwrap_or(u32::MAX);
            for s in v.slots.iter().filter(|s| s.active) {
                if let Some(c) = s.values.at(k) {
                    cmds.insert(s.primitive, (c, Some((*conn, v.token))));
                }
            }
        }
        for (id, c) in self.immediate.drain(..) {
            if self.model.primitive(id).is_some() {
                cmds.insert(id, (c, None));
            }
        }
        cmds
    }

    /// 5. adapt to the primitive (range clamp, a two-state LED on a three-state one).
    fn adapt(&self, cmds: &BTreeMap<PrimitiveId, (FrameCommand, Option<(ConnectionId, Token)>)>) -> Vec<Applied> {
        let mut applied: Vec<Applied> = Vec::with_capacity(cmds.len());
        for (&id, &(requested, source)) in cmds {
            let Some(p) = self.model.primitive(id) else { continue };
            let command = match (requested, p.kind, p.joint) {
                (FrameCommand::Joint(v), _, Some(j)) => FrameCommand::Joint(j.clamp(v)),
                (FrameCommand::Led2(on), PrimitiveKind::Led3, _) => FrameCommand::Led3(Led3Value { intensity: if on { 255 } else { 0 }, mode: 0xFFFF }),
                (c, _, _) => c,
            };
            applied.push(Applied { primitive: id, command, requested, source });
        }
        applied
    }

    /// Combined limits against this frame's (or the held) target of the other joint;
    /// a clamp is reported once until the request changes.
    fn combined_limits(&mut self, applied: &mut [Applied], out: &mut EffectorFrame) {
        let current: HashMap<PrimitiveId, i32> = applied
            .iter()
            .filter_map(|a| match a.command {
                FrameCommand::Joint(v) => Some((a.primitive, v)),
                _ => None,
            })
            .collect();
        for a in applied.iter_mut() {
            let (FrameCommand::Joint(requested), FrameCommand::Joint(v)) = (a.requested, a.command) else { continue };
            let mut rule = if v != requested { Some(ClampRule::Range) } else { None };
            let mut value = v;
            if let Some(min) = self.combined_min_for(a.primitive, &current) {
                if value < min {
                    value = min;
                    rule = Some(ClampRule::Combined);
                }
            }
            a.command = FrameCommand::Joint(value);
            match rule {
                Some(rule) => {
                    if self.clamping.get(&a.primitive) != Some(&requested) {
                        out.clamps.push(ClampEvent { primitive: a.primitive, requested, clamped: value, rule });
                        self.clamping.insert(a.primitive, requested);
                    }
                }
                None => {
                    self.clamping.remove(&a.primitive);
                }
            }
        }
    }

    /// The combined lower limit of `id` given the other joint's target this frame (or
    /// the one it holds).
    fn combined_min_for(&self, id: PrimitiveId, current: &HashMap<PrimitiveId, i32>) -> Option<i32> {
        let p = self.model.primitive(id)?;
        let dep = self.model.combined_dependency(p.part).and_then(|d| self.model.by_part(d)).map(|d| d.id)?;
        let other = current.get(&dep).copied().or(match self.targets.get(&dep) {
            Some(FrameCommand::Joint(t)) => Some(*t),
            _ => None,
        })?;
        self.model.combined_min(p.part, other)
    }

    /// 6. completion: vectors whose last frame was this one leave their queue.
    fn complete(&mut self, now: u64, out: &mut EffectorFrame) {
        for (&conn, q) in self.queues.iter_mut() {
            let done = match q.front() {
                Some(Queued { state: State::Playing { start }, duration, .. }) => now - start + 1 >= *duration as u64,
                _ => false,
            };
            if done {
                if let Some(v) = q.pop_front() {
                    out.completed.push(Completed { connection: conn, token: v.token });
                }
            }
        }
        self.queues.retain(|_, q| !q.is_empty());
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{oradians, Design, Leg, Part};
    use crate::vectors::*;

    fn model() -> RobotModel {
        RobotModel::new(Design::Ers7)
    }
    fn id(m: &RobotModel, part: Part) -> u32 {
        m.by_part(part).map(|p| p.id).unwrap()
    }
    fn vector(slots: &[(u32, u32, Vec<[u8; 8]>)], wait: u32, key: u32) -> CommandVector {
        let mut b = vec![0u8; command_vector_size(slots.len().max(1))];
        command_vector_init(&mut b, slots.len().max(1)).unwrap();
        for (t, p, f) in slots {
            command_vector_push(&mut b, *t, *p, f).unwrap();
        }
        b[40..44].copy_from_slice(&wait.to_le_bytes());
        b[36..40].copy_from_slice(&key.to_le_bytes());
        parse_command_vector(&b).unwrap()
    }
    fn joint_vec(p: u32, n: usize, v: i32) -> CommandVector {
        vector(&[(odata::JOINT_COMMAND2, p, (0..n).map(|_| joint2_frame(v)).collect())], 0, SYNC_KEY_UNDEF)
    }
    /// Runs frames 1..=n, returning (frame, completed tokens) pairs.
    fn run(e: &mut Effector, s: &mut SyncKeys, from: u64, n: u64) -> Vec<(u64, EffectorFrame)> {
        (from..from + n).map(|t| (t, e.step(t, t as u32, s))).collect()
    }

    #[test]
    fn sixteen_frame_vector_completes_after_16_frames_and_primed_pair_plays_back_to_back() {
        let m = model();
        let tilt = id(&m, Part::NeckTilt1);
        let mut e = Effector::new(m);
        let mut s = SyncKeys::new();
        e.enqueue(7, &joint_vec(tilt, 16, -1000), 1);
        e.enqueue(7, &joint_vec(tilt, 16, -2000), 2);
        let frames = run(&mut e, &mut s, 1, 40);
        let done: Vec<(u64, Token)> = frames.iter().flat_map(|(t, f)| f.completed.iter().map(move |c| (*t, c.token))).collect();
        assert_eq!(done, vec![(16, 1), (32, 2)]);
        let starts: Vec<(u32, Token)> = frames.iter().flat_map(|(_, f)| f.started.iter().map(|s| (s.frame, s.token))).collect();
        assert_eq!(starts, vec![(1, 1), (17, 2)]);
        assert_eq!(frames[15].1.applied[0].command, FrameCommand::Joint(-1000));
        assert_eq!(frames[16].1.applied[0].command, FrameCommand::Joint(-2000));
        assert!(frames[32].1.applied.is_empty());
        assert_eq!(e.target(tilt), Some(FrameCommand::Joint(-2000)));
        assert_eq!(e.queue_len(7), 0);
    }

    #[test]
    fn led_8_values_period_64_lasts_512_frames() {
        let m = model();
        let l1 = m.open_primitive("PRM:/r1/c1/c2/c3/l1-LED2:l1").unwrap();
        let mut e = Effector::new(m);
        let mut s = SyncKeys::new();
        let frames: Vec<[u8; 8]> = (0..8).map(|k| held_frame(k % 2, 64)).collect();
        e.enqueue(1, &vector(&[(odata::LED_COMMAND2, l1, frames)], 0, SYNC_KEY_UNDEF), 9);
        let out = run(&mut e, &mut s, 1, 600);
        let done: Vec<u64> = out.iter().filter(|(_, f)| !f.completed.is_empty()).map(|(t, _)| *t).collect();
        assert_eq!(done, vec![512]);
        assert_eq!(out[63].1.applied[0].command, FrameCommand::Led2(false));
        assert_eq!(out[64].1.applied[0].command, FrameCommand::Led2(true));
    }

    #[test]
    fn wait_delays_start() {
        let m = model();
        let tilt = id(&m, Part::NeckTilt1);
        let mut e = Effector::new(m);
        let mut s = SyncKeys::new();
        let v = vector(&[(odata::JOINT_COMMAND2, tilt, vec![joint2_frame(-5); 4])], 3, SYNC_KEY_UNDEF);
        e.enqueue(1, &v, 1);
        let out = run(&mut e, &mut s, 1, 10);
        assert_eq!(out.iter().position(|(_, f)| !f.started.is_empty()), Some(3)); // frame 4
        assert_eq!(out.iter().position(|(_, f)| !f.completed.is_empty()), Some(6));
        // frame 7
    }

    #[test]
    fn ignored_slots_and_empty_vectors() {
        let m = model();
        let ear = id(&m, Part::Ear(true));
        let pan = id(&m, Part::NeckPan);
        let mut e = Effector::new(m);
        let mut s = SyncKeys::new();
        let v = vector(
            &[
                (odata::JOINT_COMMAND2, ear, vec![joint2_frame(0); 4]),
                (odata::JOINT_COMMAND2, pan, vec![joint2_frame(10); 2]),
                (odata::JOINT_COMMAND2, 0xDEAD, vec![joint2_frame(10); 2]),
            ],
            0,
            SYNC_KEY_UNDEF,
        );
        let ign = e.enqueue(1, &v, 1);
        assert_eq!(ign.len(), 2);
        assert!(matches!(ign[0].reason, IgnoreReason::TypeMismatch { .. }));
        assert_eq!(ign[1].reason, IgnoreReason::UnknownPrimitive);
        let out = run(&mut e, &mut s, 1, 5);
        // duration = 4 (the ignored ear slot still paces the vector)
        assert_eq!(out[3].1.completed.len(), 1);
        assert!(out[0].1.applied.iter().all(|a| a.primitive == pan));
        // empty vector completes in its start frame
        let mut b = vec![0u8; command_vector_size(2)];
        command_vector_init(&mut b, 2).unwrap();
        e.enqueue(2, &parse_command_vector(&b).unwrap(), 5);
        let f = e.step(6, 6, &mut s);
        assert_eq!(f.completed, vec![Completed { connection: 2, token: 5 }]);
    }

    #[test]
    fn clamps_out_of_range_and_combined() {
        let m = model();
        let tail = id(&m, Part::TailTilt);
        let mouth = id(&m, Part::Mouth);
        let j1 = id(&m, Part::LegJ1(Leg::LeftRear));
        let j2 = id(&m, Part::LegJ2(Leg::LeftRear));
        let mut e = Effector::new(m);
        let mut s = SyncKeys::new();
        let v = vector(
            &[
                (odata::JOINT_COMMAND2, tail, vec![joint2_frame(0); 3]),
                (odata::JOINT_COMMAND2, mouth, vec![joint2_frame(0); 3]),
                (odata::JOINT_COMMAND2, j1, vec![joint2_frame(oradians(-120.0)); 3]),
                (odata::JOINT_COMMAND2, j2, vec![joint2_frame(oradians(-10.0)); 3]),
            ],
            0,
            SYNC_KEY_UNDEF,
        );
        e.enqueue(1, &v, 1);
        let out = run(&mut e, &mut s, 1, 3);
        let f1 = &out[0].1;
        let get = |p| f1.applied.iter().find(|a| a.primitive == p).map(|a| a.command);
        assert_eq!(get(tail), Some(FrameCommand::Joint(87266)));
        assert_eq!(get(mouth), Some(FrameCommand::Joint(-52359)));
        assert_eq!(get(j2), Some(FrameCommand::Joint(0))); // rear J1 −120 → min J2 0
        assert_eq!(f1.clamps.len(), 3);
        assert!(f1.clamps.iter().any(|c| c.primitive == j2 && c.rule == ClampRule::Combined));
        assert!(f1.clamps.iter().any(|c| c.primitive == tail && c.requested == 0 && c.clamped == 87266 && c.rule == ClampRule::Range));
        // constant out-of-range command: reported once
        assert!(out[1].1.clamps.is_empty() && out[2].1.clamps.is_empty());
    }

    #[test]
    fn later_vector_wins_and_immediate_wins_over_all() {
        let m = model();
        let pan = id(&m, Part::NeckPan);
        let mut e = Effector::new(m);
        let mut s = SyncKeys::new();
        e.enqueue(1, &joint_vec(pan, 4, 100), 1);
        e.enqueue(2, &joint_vec(pan, 4, 200), 2);
        let f = e.step(1, 1, &mut s);
        assert_eq!(f.applied[0].command, FrameCommand::Joint(200));
        assert_eq!(f.applied[0].source, Some((2, 2)));
        e.immediate(pan, FrameCommand::Joint(300));
        let f = e.step(2, 2, &mut s);
        assert_eq!(f.applied[0].command, FrameCommand::Joint(300));
        assert_eq!(f.applied[0].source, None);
    }

    #[test]
    fn sync_key_starts_parts_together_and_times_out() {
        let m = model();
        let pan = id(&m, Part::NeckPan);
        let tilt = id(&m, Part::NeckTilt1);
        let mut e = Effector::new(m);
        let mut s = SyncKeys::new();
        let k = s.new_key().unwrap();
        let (a, b) = s.divide(k).unwrap();
        let va = vector(&[(odata::JOINT_COMMAND2, pan, vec![joint2_frame(1); 4])], 0, a);
        let vb = vector(&[(odata::JOINT_COMMAND2, tilt, vec![joint2_frame(-1); 4])], 2, b);
        e.enqueue(1, &va, 1);
        let out = run(&mut e, &mut s, 1, 2);
        assert!(out.iter().all(|(_, f)| f.started.is_empty()));
        e.enqueue(2, &vb, 2); // arrives at frame 3, waits 2 → ready at frame 5
        let out = run(&mut e, &mut s, 3, 6);
        let starts: Vec<(u64, usize)> = out.iter().map(|(t, f)| (*t, f.started.len())).collect();
        assert_eq!(starts, vec![(3, 0), (4, 0), (5, 2), (6, 0), (7, 0), (8, 0)]);
        assert_eq!(out[5].1.completed.len(), 2);
        assert_eq!(out[2].1.sync_released, vec![(k, false)]);
        assert_eq!(s.live_keys(), 0);
        // timeout: second part never comes
        let k = s.new_key().unwrap();
        let (a, _b) = s.divide(k).unwrap();
        e.enqueue(1, &vector(&[(odata::JOINT_COMMAND2, pan, vec![joint2_frame(1); 1])], 0, a), 3);
        let out = run(&mut e, &mut s, 100, 130);
        let started_at = out.iter().find(|(_, f)| !f.started.is_empty()).map(|(t, _)| *t);
        assert_eq!(started_at, Some(100 + 125));
        // unknown key: starts immediately
        e.enqueue(1, &vector(&[(odata::JOINT_COMMAND2, pan, vec![joint2_frame(1); 1])], 0, 999), 4);
        assert_eq!(e.step(300, 300, &mut s).started.len(), 1);
    }

    #[test]
    fn optional_bytes_of_playing_vector() {
        let m = model();
        let pan = id(&m, Part::NeckPan);
        let mut e = Effector::new(m);
        let mut s = SyncKeys::new();
        let mut b = vec![0u8; command_vector_size(1)];
        command_vector_init(&mut b, 1).unwrap();
        command_vector_push(&mut b, odata::JOINT_COMMAND2, pan, &[joint2_frame(0); 2]).unwrap();
        b[44..48].copy_from_slice(&4u32.to_le_bytes());
        b[48..52].copy_from_slice(&2u32.to_le_bytes());
        b[68] = 0xAB;
        b[69] = 0xCD;
        e.enqueue(1, &parse_command_vector(&b).unwrap(), 1);
        assert_eq!(e.current_optional(), None);
        assert_eq!(e.step(1, 1, &mut s).optional, Some((4, vec![0xAB, 0xCD])));
        assert_eq!(e.current_optional(), Some((4, &[0xAB, 0xCD][..])));
        assert_eq!(e.step(2, 2, &mut s).optional, Some((4, vec![0xAB, 0xCD])));
        assert_eq!(e.current_optional(), None);
        assert_eq!(e.step(3, 3, &mut s).optional, None);
        assert_eq!(e.drop_connection(1), Vec::<Token>::new());
    }
}
