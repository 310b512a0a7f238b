//! The robot's surroundings and the non-joint sensors derived from them: body posture
//! (pitch/roll, paw contacts) from the leg angles, gravity on the accelerometer, the
//! distance sensors against the floor and an optional wall, and touch/switch inputs
//! set by the user or a test.
//!
//! Why it exists: programs react to sensors (SensorObserver7 prints them, ImageCapture
//! uses the chin switch as a shutter, walking code reads paw switches and the
//! accelerometer); a virtual robot must give physically sensible values without a
//! physics engine.
//!
//! Model (inferred; ers7-model 5 and 12 for units and dimensions):
//! * Leg geometry in the body's side plane: upper link 69.5 mm, lower link 71.5 mm
//!   (front) / 76.5 mm (rear); J1 = 0 points the upper link straight down, positive
//!   swings it forward; the lower link is at J1 + J3; abduction J2 shortens the
//!   vertical reach by cos J2. Front and rear J1 axes are 130 mm apart.
//! * Standing: the body rests on the deepest paw of each end and of each side. Pitch
//!   (+ = nose up / leaning backward, as MTN body pitch) from the front/rear depths
//!   over their distance; roll (+ = leaning right) from the left/right depths over
//!   120 mm. A paw touches the floor when it is no more than 10 mm above that support
//!   plane (so a lifted leg, e.g. in a walk, loses contact).
//! * Lying: if the legs reach less than the belly (45 mm below the J1 axes) the body
//!   rests on the floor level; paws within 10 mm of the floor touch it.
//! * `lifted`: held in the air — no paw touches, posture level (plus the extra tilt).
//! * Accelerometer (µm/s², a1 front +, a2 right +, a3 up +): the reaction to gravity,
//!   a1 = g·sin(pitch), a2 = −g·sin(roll)·cos(pitch), a3 = g·cos(pitch)·cos(roll);
//!   level standing gives (0, 0, +9806650).
//! * Chest PSD: beam 30° below the body's horizontal from the J1-axis height; reads
//!   the nearer of floor and wall; device refresh every 5 frames (40 ms). Range
//!   100000..900000 µm, saturating.
//! * Head PSDs: head pitch = body pitch + tilt1 + tilt2, yaw = pan, sensor height =
//!   J1-axis height + 19.5 + 80·cos(tilt1 + pitch) mm; floor and wall as for the
//!   chest. Near (50000..500000 µm) reads on even frame numbers, far (200000..1500000)
//!   on odd ones; in the other sensor's frame `signal` = 0 and `value` repeats the
//!   last reading (ers7-model 5.3). The ~50 ms device period is not modelled.
//! * Touch pads: `value` = `signal` = 60 touched, 0 released; switches 1/0; ERS-2xx
//!   pressure 500000 µN pressed; thermometer from `temperature_c`.
//! * `wall_mm` is the horizontal distance from the sensors to a wall ahead (the same
//!   for head and chest — the small offset between them is ignored).

use rustc_hash::FxHashMap as HashMap;
use std::f64::consts::PI;

use super::kinematics::Body;
use super::model::{Leg, Part, PrimitiveId, PrimitiveKind, SensorKind};
use super::render::CameraWorld;
use super::vectors::SensorValue;

/// Standard gravity, µm/s².
pub const G_UM_S2: f64 = 9_806_650.0;
/// Accelerometer range, µm/s²: ±2 g (ers7-model 5.4).
pub const ACCEL_MAX: i32 = 19_613_300;
/// Measuring ranges (min, max) of the distance sensors, µm (ers7-model 5.3): the ERS-7
/// head's near and far PSDs, and its chest PSD (also the ERS-210/220 head PSD).
pub const PSD_HEAD_NEAR: (i32, i32) = (50_000, 500_000);
pub const PSD_HEAD_FAR: (i32, i32) = (200_000, 1_500_000);
pub const PSD_CHEST: (i32, i32) = (100_000, 900_000);

/// The range of a sensor's `value` where the model clips it: accelerometers (µm/s²) and
/// distance sensors (µm).
pub fn value_range(part: Part) -> Option<(i32, i32)> {
    match part {
        Part::Accel(_) => Some((-ACCEL_MAX, ACCEL_MAX)),
        _ => psd_range(part),
    }
}

/// The measuring range of a distance sensor, µm.
pub fn psd_range(part: Part) -> Option<(i32, i32)> {
    match part {
        Part::PsdHeadNear => Some(PSD_HEAD_NEAR),
        Part::PsdHeadFar => Some(PSD_HEAD_FAR),
        Part::PsdHead | Part::PsdChest => Some(PSD_CHEST),
        _ => None,
    }
}

const UPPER: f64 = 69.5;
const LOWER_FRONT: f64 = 71.5;
const LOWER_REAR: f64 = 76.5;
const HIP_SPACING: f64 = 130.0;
const BODY_WIDTH: f64 = 120.0;
const BELLY: f64 = 45.0;
const CONTACT_TOL: f64 = 10.0;

/// User-controlled environment and inputs.
#[derive(Clone, Debug, PartialEq)]
pub struct Scene {
    /// Held in the air: paws off the floor.
    pub lifted: bool,
    /// Horizontal distance (mm) from the distance sensors to a wall ahead.
    pub wall_mm: Option<f64>,
    pub head_touch: bool,
    pub back_touch_front: bool,
    pub back_touch_middle: bool,
    pub back_touch_rear: bool,
    pub chin_switch: bool,
    /// Position of the wireless-LAN slide switch (b1).
    pub wlan_switch: bool,
    /// ERS-2xx back switch and ERS-220 tail switches 2..4.
    pub back_switch: bool,
    pub tail_switches: [bool; 3],
    /// ERS-2xx head pressure sensors f1 (back) / f2 (front).
    pub head_pressure: [bool; 2],
    pub temperature_c: f64,
    /// Extra tilt of the ground/holder, degrees (added to the posture).
    pub extra_pitch_deg: f64,
    pub extra_roll_deg: f64,
    /// What the camera sees: ball, field, colours (see [`super::render`]).
    pub camera: CameraWorld,
}

impl Default for Scene {
    fn default() -> Scene {
        Scene {
            lifted: false,
            wall_mm: None,
            head_touch: false,
            back_touch_front: false,
            back_touch_middle: false,
            back_touch_rear: false,
            chin_switch: false,
            wlan_switch: false,
            back_switch: false,
            tail_switches: [false; 3],
            head_pressure: [false; 2],
            temperature_c: 30.0,
            extra_pitch_deg: 0.0,
            extra_roll_deg: 0.0,
            camera: CameraWorld::default(),
        }
    }
}

/// Body attitude and contacts.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Posture {
    /// rad, + = nose up.
    pub pitch: f64,
    /// rad, + = leaning right.
    pub roll: f64,
    /// Height of the J1 axes above the floor, mm.
    pub height_mm: f64,
    /// Indexed by [`Leg::index`].
    pub paw_contact: [bool; 4],
}

fn rad(urad: f64) -> f64 {
    urad / 1_000_000.0
}

/// Paw position relative to its J1 axis: (forward mm, depth below mm).
fn paw(body: &Body, leg: Leg) -> (f64, f64) {
    let a = |p| body.angle(p).map_or(0.0, rad);
    let (j1, j2, j3) = (a(Part::LegJ1(leg)), a(Part::LegJ2(leg)), a(Part::LegJ3(leg)));
    let lower = if leg.is_front() { LOWER_FRONT } else { LOWER_REAR };
    let x = UPPER * j1.sin() + lower * (j1 + j3).sin();
    let z = (UPPER * j1.cos() + lower * (j1 + j3).cos()) * j2.cos();
    (x, z)
}

/// Computes the posture from the leg angles and the scene.
pub fn posture(body: &Body, scene: &Scene) -> Posture {
    let extra_p = scene.extra_pitch_deg * PI / 180.0;
    let extra_r = scene.extra_roll_deg * PI / 180.0;
    let paws = Leg::ALL.map(|l| paw(body, l));
    if scene.lifted {
        return Posture { pitch: extra_p, roll: extra_r, height_mm: f64::INFINITY, paw_contact: [false; 4] };
    }
    // the body rests on the deepest paw of each end and each side
    let deepest = |legs: [Leg; 2]| legs.iter().map(|l| paws[l.index()].1).fold(f64::MIN, f64::max);
    let mean_x = |legs: [Leg; 2]| legs.iter().map(|l| paws[l.index()].0).sum::<f64>() / 2.0;
    let z_front = deepest([Leg::LeftFront, Leg::RightFront]);
    let z_rear = deepest([Leg::LeftRear, Leg::RightRear]);
    let z_left = deepest([Leg::LeftFront, Leg::LeftRear]);
    let z_right = deepest([Leg::RightFront, Leg::RightRear]);
    let height = (z_front + z_rear) / 2.0;
    if height < BELLY {
        let contact = paws.map(|(_, z)| z >= BELLY - CONTACT_TOL);
        return Posture { pitch: extra_p, roll: extra_r, height_mm: BELLY, paw_contact: contact };
    }
    let baseline = (HIP_SPACING + mean_x([Leg::LeftFront, Leg::RightFront]) - mean_x([Leg::LeftRear, Leg::RightRear])).max(20.0);
    let pitch = (z_front - z_rear).atan2(baseline);
    let roll = (z_left - z_right).atan2(BODY_WIDTH);
    // support plane through those paws; a paw more than CONTACT_TOL above it is in the air
    let contact = Leg::ALL.map(|l| {
        let fr = if l.is_front() { z_front - height } else { z_rear - height };
        let side = (z_left - z_right) / 2.0;
        let expected = height + fr + if l.is_left() { side } else { -side };
        paws[l.index()].1 >= expected - CONTACT_TOL
    });
    Posture { pitch: pitch + extra_p, roll: roll + extra_r, height_mm: height, paw_contact: contact }
}

/// Accelerometer readings (a1, a2, a3) in µm/s² for a posture.
pub fn gravity(p: &Posture) -> [i32; 3] {
    let a1 = G_UM_S2 * p.pitch.sin();
    let a2 = -G_UM_S2 * p.roll.sin() * p.pitch.cos();
    let a3 = G_UM_S2 * p.pitch.cos() * p.roll.cos();
    [a1, a2, a3].map(|v| v.round().clamp(-ACCEL_MAX as f64, ACCEL_MAX as f64) as i32)
}

/// Distance (mm) along a beam from `height` mm above the floor, pointing `down` rad
/// below the horizontal and `yaw` rad sideways, to the floor or the wall.
fn beam_distance(height: f64, down: f64, yaw: f64, wall: Option<f64>) -> f64 {
    let floor = if down > 1e-3 && height.is_finite() { height / down.sin() } else { f64::INFINITY };
    let horiz = down.cos() * yaw.cos();
    let wall = match wall {
        Some(w) if horiz > 1e-3 => w.max(0.0) / horiz,
        _ => f64::INFINITY,
    };
    floor.min(wall)
}

fn psd_value(mm: f64, (lo_um, hi_um): (i32, i32)) -> SensorValue {
    let um = if mm.is_finite() { (mm * 1000.0).round().clamp(lo_um as f64, hi_um as f64) as i32 } else { hi_um };
    // raw A/D: larger for nearer objects (PSD output falls with distance), never 0
    let signal = ((lo_um as f64 / um as f64) * 4000.0).round().clamp(1.0, 4095.0) as u16;
    SensorValue { value: um, signal }
}

fn switch(on: bool) -> SensorValue {
    SensorValue { value: on as i32, signal: on as u16 }
}

fn touch(on: bool) -> SensorValue {
    let v = if on { 60 } else { 0 };
    SensorValue { value: v, signal: v as u16 }
}

/// The raw `signal` the model reports with a sensor `value` measured outside the model
/// (an external robot peer): the same mappings as the synthesized readings.
pub fn signal_for(part: Part, value: i32) -> u16 {
    match part {
        Part::PsdHeadNear => psd_value(value as f64 / 1000.0, PSD_HEAD_NEAR).signal,
        Part::PsdHeadFar => psd_value(value as f64 / 1000.0, PSD_HEAD_FAR).signal,
        Part::PsdHead | Part::PsdChest => psd_value(value as f64 / 1000.0, PSD_CHEST).signal,
        Part::Accel(_) => (value as f64 / ACCEL_MAX as f64 * 32767.0 + 32768.0).round().clamp(0.0, 65535.0) as u16,
        Part::HeadPressure(_) => {
            if value > 0 {
                512
            } else {
                0
            }
        }
        _ => value.clamp(0, 65535) as u16,
    }
}

/// Stateful sensor synthesis (PSD alternation and refresh).
#[derive(Clone, Debug, Default)]
pub struct SensorSynth {
    last_near: Option<SensorValue>,
    last_far: Option<SensorValue>,
    last_chest: Option<SensorValue>,
    chest_age: u32,
}

impl SensorSynth {
    pub fn new() -> SensorSynth {
        SensorSynth::default()
    }

    /// Every non-joint sensor's value for frame number `frame`.
    pub fn sample(&mut self, body: &Body, scene: &Scene, frame: u32) -> HashMap<PrimitiveId, SensorValue> {
        let mut out = HashMap::default();
        self.sample_into(body, scene, frame, &mut out);
        out
    }

    /// [`SensorSynth::sample`] into `out` (emptied first; its room is kept from frame to
    /// frame).
    pub fn sample_into(&mut self, body: &Body, scene: &Scene, frame: u32, out: &mut HashMap<PrimitiveId, SensorValue>) {
        let p = posture(body, scene);
        let acc = gravity(&p);
        let a = |part| body.angle(part).map_or(0.0, rad);
        let (tilt1, pan, tilt2) = (a(Part::NeckTilt1), a(Part::NeckPan), a(Part::NeckTilt2));
        let head_height = p.height_mm + 19.5 + 80.0 * (tilt1 + p.pitch).cos();
        let head_mm = beam_distance(head_height, -(p.pitch + tilt1 + tilt2), pan, scene.wall_mm);
        let chest_mm = beam_distance(p.height_mm, PI / 6.0 - p.pitch, 0.0, scene.wall_mm);

        let near_now = psd_value(head_mm, PSD_HEAD_NEAR);
        let far_now = psd_value(head_mm, PSD_HEAD_FAR);
        let near_turn = frame % 2 == 0;
        let repeat = |last: Option<SensorValue>, now: SensorValue| SensorValue { value: last.unwrap_or(now).value, signal: 0 };
        let near = if near_turn { near_now } else { repeat(self.last_near, near_now) };
        let far = if near_turn { repeat(self.last_far, far_now) } else { far_now };
        if near_turn {
            self.last_near = Some(near_now);
        } else {
            self.last_far = Some(far_now);
        }
        let chest = match self.last_chest {
            Some(c) if self.chest_age < 4 => {
                self.chest_age += 1;
                c
            }
            _ => {
                let c = psd_value(chest_mm, PSD_CHEST);
                self.last_chest = Some(c);
                self.chest_age = 0;
                c
            }
        };

        out.clear();
        for prim in body.model().primitives() {
            let PrimitiveKind::Sensor(kind) = prim.kind else { continue };
            let v = match (prim.part, kind) {
                (Part::PawSwitch(l), _) => switch(p.paw_contact[l.index()]),
                (Part::ChinSwitch, _) => switch(scene.chin_switch),
                (Part::WlanSwitch, _) => switch(scene.wlan_switch),
                (Part::BackSwitch, _) => switch(scene.back_switch),
                (Part::TailSwitch(n), _) => switch(scene.tail_switches.get(n.saturating_sub(2) as usize).copied().unwrap_or(false)),
                (Part::HeadTouch, _) => touch(scene.head_touch),
                (Part::BackTouchFront, _) => touch(scene.back_touch_front),
                (Part::BackTouchMiddle, _) => touch(scene.back_touch_middle),
                (Part::BackTouchRear, _) => touch(scene.back_touch_rear),
                (Part::HeadPressure(n), _) => {
                    let on = scene.head_pressure.get(n.saturating_sub(1) as usize).copied().unwrap_or(false);
                    SensorValue { value: if on { 500_000 } else { 0 }, signal: if on { 512 } else { 0 } }
                }
                (Part::PsdHeadNear, _) => near,
                (Part::PsdHeadFar, _) => far,
                (Part::PsdHead, _) => psd_value(head_mm, PSD_CHEST),
                (Part::PsdChest, _) => chest,
                (Part::Accel(i), _) => {
                    let v = acc.get(i as usize).copied().unwrap_or(0);
                    let signal = (v as f64 / ACCEL_MAX as f64 * 32767.0 + 32768.0).round().clamp(0.0, 65535.0) as u16;
                    SensorValue { value: v, signal }
                }
                (Part::Thermometer, _) | (_, SensorKind::Thermometer) => {
                    SensorValue { value: (scene.temperature_c * 1_000_000.0) as i32, signal: (scene.temperature_c * 10.0).clamp(0.0, 65535.0) as u16 }
                }
                _ => SensorValue::default(),
            };
            out.insert(prim.id, v);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{Design, RobotModel, POSTURE_PARTS, POSTURE_SIT, POSTURE_SLEEP, POSTURE_STAND};

    fn body(posture: &[f64; 18]) -> Body {
        let mut b = Body::new(RobotModel::new(Design::Ers7));
        b.set_posture_deg(&POSTURE_PARTS, posture);
        b
    }
    fn deg(r: f64) -> f64 {
        r * 180.0 / PI
    }

    #[test]
    fn standing_is_nearly_level_on_four_paws() {
        let b = body(&POSTURE_STAND);
        let p = posture(&b, &Scene::default());
        assert!(deg(p.pitch) < 0.0 && deg(p.pitch) > -4.0, "pitch {}", deg(p.pitch)); // spec: −1°
        assert!(deg(p.roll).abs() < 1e-9);
        assert_eq!(p.paw_contact, [true; 4]);
        let acc = gravity(&p);
        assert!(acc[0] < 0 && acc[0] > -700_000);
        assert_eq!(acc[1], 0);
        assert!(acc[2] > 9_790_000 && acc[2] <= 9_806_650);
        let level = gravity(&Posture { pitch: 0.0, roll: 0.0, height_mm: 100.0, paw_contact: [true; 4] });
        assert_eq!(level, [0, 0, 9_806_650]);
    }

    #[test]
    fn sitting_pitches_nose_up_and_lifted_has_no_contact() {
        let b = body(&POSTURE_SIT);
        let p = posture(&b, &Scene::default());
        assert!(deg(p.pitch) > 15.0 && deg(p.pitch) < 45.0, "pitch {}", deg(p.pitch));
        assert!(gravity(&p)[0] > 0);
        let lifted = posture(&b, &Scene { lifted: true, ..Scene::default() });
        assert_eq!(lifted.paw_contact, [false; 4]);
        // lying: body on the floor, level
        let s = posture(&body(&POSTURE_SLEEP), &Scene::default());
        assert_eq!(s.pitch, 0.0);
        assert_eq!(s.height_mm, BELLY);
        // roll: right side lower → leaning right → a2 negative
        let r = Posture { pitch: 0.0, roll: 0.2, height_mm: 100.0, paw_contact: [true; 4] };
        assert!(gravity(&r)[1] < 0);
    }

    #[test]
    fn lifted_leg_loses_contact() {
        let mut b = body(&POSTURE_STAND);
        b.set_posture_deg(&[Part::LegJ1(Leg::LeftFront), Part::LegJ3(Leg::LeftFront)], &[60.0, 90.0]);
        let p = posture(&b, &Scene::default());
        assert!(!p.paw_contact[Leg::LeftFront.index()]);
        assert!(p.paw_contact[Leg::RightRear.index()]);
    }

    #[test]
    fn psd_alternation_ranges_and_touch() {
        let b = body(&POSTURE_STAND);
        let m = b.model().clone();
        let id = |l: &str| m.open_primitive(l).unwrap_or(0);
        let near = id("PRM:/r1/c1/c2/c3/p1-Sensor:p1");
        let far = id("PRM:/r1/c1/c2/c3/p2-Sensor:p2");
        let chest = id("PRM:/p1-Sensor:p1");
        let mut s = SensorSynth::new();
        let scene = Scene { wall_mm: Some(300.0), head_touch: true, ..Scene::default() };
        let f2 = s.sample(&b, &scene, 2);
        let f3 = s.sample(&b, &scene, 3);
        let f4 = s.sample(&b, &scene, 4);
        assert!(f2[&near].signal != 0);
        assert_eq!(f3[&near].signal, 0);
        assert_eq!(f3[&near].value, f2[&near].value);
        assert!(f3[&far].signal != 0);
        assert_eq!(f4[&far].signal, 0);
        assert_eq!(f4[&far].value, f3[&far].value);
        // the head looks slightly up at a wall 300 mm ahead: both read about 0.3 m
        assert!((300_000..330_000).contains(&f2[&near].value), "{}", f2[&near].value);
        assert!((300_000..330_000).contains(&f3[&far].value));
        assert!((100_000..=900_000).contains(&f2[&chest].value));
        // nothing ahead, head level: saturate at the far end
        let open = s.sample(&b, &Scene::default(), 6);
        assert_eq!(open[&near].value, 500_000);
        assert_eq!(f2[&id("PRM:/r1/c1/c2/c3/t1-Sensor:t1")], SensorValue { value: 60, signal: 60 });
        assert_eq!(f2[&id("PRM:/t2-Sensor:t2")], SensorValue { value: 0, signal: 0 });
        assert_eq!(f2[&id("PRM:/r2/c1/c2/c3/c4-Sensor:24")], SensorValue { value: 1, signal: 1 });
        // wall close: near saturates at 5 cm
        let close = s.sample(&b, &Scene { wall_mm: Some(10.0), ..Scene::default() }, 8);
        assert_eq!(close[&near].value, 50_000);
    }
}
