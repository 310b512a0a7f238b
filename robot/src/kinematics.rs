//! The robot's actuated state: servo joints, ear plungers and LEDs, advanced one 8 ms
//! frame at a time.
//!
//! Why it exists: `GetJointValue` and the sensor vectors must report plausible joint
//! readings (value, signal, pwmDuty, refValue, refSignal — ers7-model 4.9) that follow
//! the effector's targets the way a servo would, go limp when gains are disabled or
//! motor power is off (LMasterRSlave7 moves limp legs by hand, PIDControl7 records
//! pwmDuty), and LEDs/ears must keep the state the last command left them in.
//!
//! Servo model (deliberately simple; an inference, not Sony data): a joint is *driven* when motor power is on,
//! its gain is enabled and the loaded P gain is non-zero. A driven joint moves toward
//! its reference by at most `max_speed × 8 ms` per frame (ers7-model 4.8) and stops
//! exactly on it. `pwmDuty` is a PID of the error expressed in 10-bit signal counts
//! with the coefficients of robot-api 11 (`GAIN / 2^(16−SHIFT)`), clamped to ±1023;
//! 0 when not driven. A limp joint keeps its angle (no gravity model) unless moved by
//! hand ([`Body::move_by_hand`]). `signal`/`refSignal` map the software range linearly
//! onto 0..1023. The reference (`refValue`) is the clamped commanded target; before
//! any command it is the boot angle.
//!
//! Boot state: the "sleep" posture of ers7-model 4.7 (ERS-7; ERS-2xx joints start at
//! 0 clamped into range), every gain disabled with the standard gains registered and
//! loaded, motor power off, LEDs off, ears in STATE0, face mode A.

use std::collections::BTreeMap;

use super::effector::Applied;
use super::model::{Design, Gain, JointSpec, Part, PrimitiveId, PrimitiveKind, RobotModel, POSTURE_PARTS, POSTURE_SLEEP};
use super::vectors::{FrameCommand, JointValue};

/// `oled3_MODE_A` / `_B` / `_UNDEF`.
pub const LED3_MODE_A: u16 = 0;
pub const LED3_MODE_B: u16 = 1;
pub const LED3_MODE_UNDEF: u16 = 0xFFFF;
/// Frames an ear may stay in STATE1 before a warning (≈1 s, ers7-model 8).
pub const EAR_HOLD_WARN_FRAMES: u64 = 125;

/// Gain bookkeeping of one joint (robot-api 4.3, 11).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct GainState {
    pub enabled: bool,
    /// The set loaded into the servo (kept while disabled; reported as zeros then).
    pub loaded: Gain,
    /// `RegisterDefaultJointGain` set (initially the standard table).
    pub registered: Gain,
}

/// One servo joint.
#[derive(Clone, Debug, PartialEq)]
pub struct JointState {
    pub spec: JointSpec,
    /// Measured angle, µrad.
    pub angle: f64,
    /// Commanded (clamped) target, µrad.
    pub reference: i32,
    pub pwm: i16,
    pub gain: GainState,
    integral: f64,
    prev_err: f64,
}

impl JointState {
    fn signal_of(&self, urad: f64) -> u16 {
        let range = (self.spec.max - self.spec.min) as f64;
        if range <= 0.0 {
            return 0;
        }
        ((urad - self.spec.min as f64) / range * 1023.0).round().clamp(0.0, 1023.0) as u16
    }

    /// The `OJointValue` for the current frame.
    pub fn value(&self) -> JointValue {
        JointValue {
            value: self.angle.round() as i32,
            signal: self.signal_of(self.angle),
            pwm_duty: self.pwm,
            ref_value: self.reference,
            ref_signal: self.signal_of(self.reference as f64),
        }
    }
}

/// State of an LED primitive.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LedState {
    Led2 { on: bool },
    Led3 { intensity: u8, mode: u16 },
}

/// An observable state change produced by [`Body::apply`] / [`Body::step`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Change {
    Led {
        primitive: PrimitiveId,
        state: LedState,
    },
    /// The face panel switched between mode A and B (ers7-model 7.2).
    FaceMode {
        mode: u16,
    },
    Ear {
        primitive: PrimitiveId,
        state: u32,
    },
    /// An ear has been in STATE1 for [`EAR_HOLD_WARN_FRAMES`] frames.
    EarHeldTooLong {
        primitive: PrimitiveId,
    },
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Ear {
    state: u32,
    since: u64,
}

/// Joints, ears and LEDs.
#[derive(Clone, Debug)]
pub struct Body {
    model: RobotModel,
    joints: crate::id_map::IdMap<JointState>,
    ears: BTreeMap<PrimitiveId, Ear>,
    leds: BTreeMap<PrimitiveId, LedState>,
    face_mode: u16,
    motor_power: bool,
}

impl Body {
    pub fn new(model: RobotModel) -> Body {
        let mut joints = crate::id_map::IdMap::default();
        let mut ears = BTreeMap::new();
        let mut leds = BTreeMap::new();
        for p in model.primitives() {
            if let Some(spec) = p.joint {
                let boot = if model.design() == Design::Ers7 {
                    POSTURE_PARTS.iter().position(|&q| q == p.part).map_or(0.0, |i| super::model::oradians(POSTURE_SLEEP[i]) as f64)
                } else {
                    0.0
                };
                let angle = boot.clamp(spec.min as f64, spec.max as f64);
                let g = spec.default_gain;
                joints.insert(
                    p.id,
                    JointState {
                        spec,
                        angle,
                        reference: angle.round() as i32,
                        pwm: 0,
                        gain: GainState { enabled: false, loaded: g, registered: g },
                        integral: 0.0,
                        prev_err: 0.0,
                    },
                );
            }
            match p.kind {
                PrimitiveKind::Joint3 | PrimitiveKind::Joint4 => {
                    ears.insert(p.id, Ear { state: 0, since: 0 });
                }
                PrimitiveKind::Led2 => {
                    leds.insert(p.id, LedState::Led2 { on: false });
                }
                PrimitiveKind::Led3 => {
                    leds.insert(p.id, LedState::Led3 { intensity: 0, mode: LED3_MODE_UNDEF });
                }
                _ => {}
            }
        }
        Body { model, joints, ears, leds, face_mode: LED3_MODE_A, motor_power: false }
    }

    pub fn model(&self) -> &RobotModel {
        &self.model
    }

    pub fn motor_power(&self) -> bool {
        self.motor_power
    }

    /// `SetMotorPower`: off makes every joint limp (pwm 0) regardless of gains.
    pub fn set_motor_power(&mut self, on: bool) {
        self.motor_power = on;
    }

    pub fn joint(&self, id: PrimitiveId) -> Option<&JointState> {
        self.joints.get(&id)
    }

    pub fn joint_mut(&mut self, id: PrimitiveId) -> Option<&mut JointState> {
        self.joints.get_mut(&id)
    }

    pub fn joint_ids(&self) -> impl Iterator<Item = PrimitiveId> + '_ {
        self.joints.keys()
    }

    /// `OJointValue` of a Joint2 primitive.
    pub fn joint_value(&self, id: PrimitiveId) -> Option<JointValue> {
        self.joints.get(&id).map(JointState::value)
    }

    /// Angle of a part's joint, µrad.
    pub fn angle(&self, part: Part) -> Option<f64> {
        self.model.by_part(part).and_then(|p| self.joints.get(&p.id)).map(|j| j.angle)
    }

    /// Places joints directly (scene setup, tests): angles in degrees, clamped to the
    /// software range; the reference follows.
    pub fn set_posture_deg(&mut self, parts: &[Part], degrees: &[f64]) {
        for (part, deg) in parts.iter().zip(degrees) {
            if let Some(id) = self.model.by_part(*part).map(|p| p.id) {
                if let Some(j) = self.joints.get_mut(&id) {
                    let a = (super::model::oradians(*deg) as f64).clamp(j.spec.min as f64, j.spec.max as f64);
                    j.angle = a;
                    j.reference = a.round() as i32;
                }
            }
        }
    }

    /// Moves a limp joint by hand (back-drivable joints, ers7-model 4.9). Returns false
    /// when the joint is driven (the servo resists) or unknown.
    pub fn move_by_hand(&mut self, id: PrimitiveId, urad: i32) -> bool {
        let driven = self.is_driven(id);
        match self.joints.get_mut(&id) {
            Some(j) if !driven => {
                j.angle = urad as f64;
                true
            }
            _ => false,
        }
    }

    pub fn is_driven(&self, id: PrimitiveId) -> bool {
        self.joints.get(&id).is_some_and(|j| self.motor_power && j.gain.enabled && j.gain.loaded.p > 0)
    }

    pub fn led(&self, id: PrimitiveId) -> Option<LedState> {
        self.leds.get(&id).copied()
    }

    /// The face panel's A/B mode (mode of the most recent face LED3 frame with A or B).
    pub fn face_mode(&self) -> u16 {
        self.face_mode
    }

    /// Current ear state (ojoint4 STATE0/1).
    pub fn ear(&self, id: PrimitiveId) -> Option<u32> {
        self.ears.get(&id).map(|e| e.state)
    }

    /// Applies one frame's effector output; returns LED/ear/face-mode changes.
    pub fn apply(&mut self, applied: &[Applied], now: u64) -> Vec<Change> {
        let mut changes = Vec::new();
        for a in applied {
            match a.command {
                FrameCommand::Joint(v) => {
                    if let Some(j) = self.joints.get_mut(&a.primitive) {
                        j.reference = v;
                    }
                }
                FrameCommand::State(s) => {
                    if s > 1 {
                        continue; // STATE_UNDEF and junk leave the ear alone
                    }
                    if let Some(e) = self.ears.get_mut(&a.primitive) {
                        if e.state != s {
                            *e = Ear { state: s, since: now };
                            changes.push(Change::Ear { primitive: a.primitive, state: s });
                        }
                    }
                }
                FrameCommand::Led2(on) => self.set_led(a.primitive, LedState::Led2 { on }, &mut changes),
                FrameCommand::Led3(v) => {
                    let face = matches!(self.model.primitive(a.primitive).map(|p| p.part), Some(Part::FaceLight(_)));
                    if face && (v.mode == LED3_MODE_A || v.mode == LED3_MODE_B) && v.mode != self.face_mode {
                        self.face_mode = v.mode;
                        changes.push(Change::FaceMode { mode: v.mode });
                    }
                    let intensity = v.intensity.clamp(0, 255) as u8;
                    self.set_led(a.primitive, LedState::Led3 { intensity, mode: v.mode }, &mut changes);
                }
            }
        }
        changes
    }

    fn set_led(&mut self, id: PrimitiveId, state: LedState, changes: &mut Vec<Change>) {
        if let Some(s) = self.leds.get_mut(&id) {
            if *s != state {
                *s = state;
                changes.push(Change::Led { primitive: id, state });
            }
        }
    }

    /// Advances the servos by one 8 ms frame; reports ears held in STATE1 too long.
    pub fn step(&mut self, now: u64) -> Vec<Change> {
        let power = self.motor_power;
        for j in self.joints.values_mut() {
            let driven = power && j.gain.enabled && j.gain.loaded.p > 0;
            if !driven {
                j.pwm = 0;
                j.integral = 0.0;
                j.prev_err = 0.0;
                continue;
            }
            let range = ((j.spec.max - j.spec.min) as f64).max(1.0);
            let err = j.reference as f64 - j.angle;
            let err_counts = err / range * 1023.0;
            let (kp, ki, kd) = j.gain.loaded.coefficients();
            j.integral = (j.integral + err_counts).clamp(-1e6, 1e6);
            let pwm = kp * err_counts + ki * j.integral + kd * (err_counts - j.prev_err);
            j.prev_err = err_counts;
            j.pwm = pwm.round().clamp(-1023.0, 1023.0) as i16;
            let max_step = j.spec.max_step();
            j.angle += err.clamp(-max_step, max_step);
        }
        self.ears
            .iter()
            .filter(|(_, e)| e.state == 1 && now.saturating_sub(e.since) == EAR_HOLD_WARN_FRAMES)
            .map(|(&id, _)| Change::EarHeldTooLong { primitive: id })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{oradians, Leg};
    use crate::vectors::Led3Value;

    fn body() -> Body {
        Body::new(RobotModel::new(Design::Ers7))
    }
    fn cmd(id: PrimitiveId, c: FrameCommand) -> Applied {
        Applied { primitive: id, command: c, requested: c, source: None }
    }
    fn enable_all(b: &mut Body) {
        let ids: Vec<_> = b.joint_ids().collect();
        for id in ids {
            if let Some(j) = b.joint_mut(id) {
                j.gain.enabled = true;
            }
        }
    }

    #[test]
    fn boots_in_sleep_posture_limp() {
        let b = body();
        let m = b.model().clone();
        let lr = m.by_part(Part::LegJ1(Leg::LeftRear)).map(|p| p.id).unwrap_or(0);
        let v = b.joint_value(lr).unwrap();
        assert_eq!(v.value, oradians(-119.0));
        assert_eq!(v.ref_value, oradians(-119.0));
        assert_eq!(v.pwm_duty, 0);
        assert!(!b.is_driven(lr));
        assert!(!b.motor_power());
        // signal is the linear map of the range onto 0..1023
        let tail = m.by_part(Part::TailTilt).map(|p| p.id).unwrap_or(0);
        assert_eq!(b.joint_value(tail).map(|v| v.signal), Some(0));
    }

    #[test]
    fn joint_at_max_speed_takes_expected_frames() {
        let mut b = body();
        let tilt1 = b.model().by_part(Part::NeckTilt1).map(|p| p.id).unwrap_or(0);
        b.set_posture_deg(&[Part::NeckTilt1], &[0.0]);
        b.set_motor_power(true);
        enable_all(&mut b);
        // 0 → −75°: 1308996 µrad at 3.185 rad/s = 25480 µrad/frame → 52 frames
        b.apply(&[cmd(tilt1, FrameCommand::Joint(-1308996))], 0);
        let mut frames = 0;
        while b.joint_value(tilt1).map(|v| v.value) != Some(-1308996) && frames < 1000 {
            b.step(frames);
            frames += 1;
            if frames == 1 {
                let v = b.joint_value(tilt1).unwrap();
                assert_eq!(v.value, -25480);
                assert!(v.pwm_duty < 0);
                assert_eq!(v.ref_value, -1308996);
            }
        }
        assert_eq!(frames, 52);
    }

    #[test]
    fn limp_when_gain_disabled_or_power_off() {
        let mut b = body();
        let pan = b.model().by_part(Part::NeckPan).map(|p| p.id).unwrap_or(0);
        b.apply(&[cmd(pan, FrameCommand::Joint(500000))], 0);
        b.step(0);
        // power off, gains disabled: holds, records the reference
        assert_eq!(b.joint_value(pan).map(|v| (v.value, v.ref_value, v.pwm_duty)), Some((0, 500000, 0)));
        enable_all(&mut b);
        b.step(1);
        assert_eq!(b.joint_value(pan).map(|v| v.value), Some(0));
        b.set_motor_power(true);
        b.step(2);
        assert!(b.joint_value(pan).is_some_and(|v| v.value > 0 && v.pwm_duty > 0));
        assert!(!b.move_by_hand(pan, 123));
        if let Some(j) = b.joint_mut(pan) {
            j.gain.enabled = false;
        }
        assert!(b.move_by_hand(pan, 123));
        b.step(3);
        assert_eq!(b.joint_value(pan).map(|v| (v.value, v.pwm_duty)), Some((123, 0)));
    }

    #[test]
    fn leds_ears_and_face_mode() {
        let mut b = body();
        let m = b.model().clone();
        let l1 = m.open_primitive("PRM:/r1/c1/c2/c3/l1-LED2:l1").unwrap_or(0);
        let la = m.open_primitive("PRM:/r1/c1/c2/c3/la-LED3:la").unwrap_or(0);
        let lu = m.open_primitive("PRM:/lu-LED3:lu").unwrap_or(0);
        let ear = m.by_part(Part::Ear(true)).map(|p| p.id).unwrap_or(0);
        let ch = b.apply(&[cmd(l1, FrameCommand::Led2(true))], 1);
        assert_eq!(ch, vec![Change::Led { primitive: l1, state: LedState::Led2 { on: true } }]);
        assert!(b.apply(&[cmd(l1, FrameCommand::Led2(true))], 2).is_empty());
        let ch = b.apply(&[cmd(la, FrameCommand::Led3(Led3Value { intensity: 300, mode: LED3_MODE_B }))], 3);
        assert_eq!(ch[0], Change::FaceMode { mode: LED3_MODE_B });
        assert_eq!(b.led(la), Some(LedState::Led3 { intensity: 255, mode: LED3_MODE_B }));
        // back lights ignore the mode
        b.apply(&[cmd(lu, FrameCommand::Led3(Led3Value { intensity: 10, mode: LED3_MODE_A }))], 4);
        assert_eq!(b.face_mode(), LED3_MODE_B);
        let ch = b.apply(&[cmd(ear, FrameCommand::State(1))], 10);
        assert_eq!(ch, vec![Change::Ear { primitive: ear, state: 1 }]);
        assert!(b.apply(&[cmd(ear, FrameCommand::State(0xFFFF_FFFF))], 11).is_empty());
        assert_eq!(b.ear(ear), Some(1));
        assert_eq!(b.step(10 + EAR_HOLD_WARN_FRAMES), vec![Change::EarHeldTooLong { primitive: ear }]);
    }
}
