//! The static description of the emulated robot: every primitive (locator, kind, ID),
//! joint limits, speed limits, default gains and the order of the sensor frame.
//!
//! Why it exists: `OPENR::OpenPrimitive` must map a locator to an ID that is the same in
//! every object and equals the `primitiveID` the system writes into sensor and image
//! infos (robot-api 0.1, 4.1); the effector must know each primitive's kind to ignore
//! mismatched command slots (robot-api 8.2.3) and its software limits to clamp targets
//! (ers7-model 4.1-4.4); the sensor subject needs the fixed entry order
//! (ers7-model 6). Everything here is pure data derived from ers7-model 2-8 and 13.
//!
//! Primitive IDs are `PRIMITIVE_ID_BASE + index in the design's table`: stable for a
//! given design, never 0 (`oprimitiveUNDEF`, passed by mistake by a sample) and never
//! 0xFFFFFFFF (`oprimitiveID_UNDEF`).
//!
//! Designs: the ERS-7 is the primary model. The ERS-210 and ERS-220 tables of
//! ers7-model 13 are provided too (locators, single-joint limits, gains, sensor order);
//! their head-roll/mouth region chart is not modelled (single-joint ranges only, as
//! ers7-model 13.3 allows), and their physical scene reuses the ERS-7 geometry.

use std::f64::consts::PI;

/// `OPrimitiveID`.
pub type PrimitiveId = u32;
/// `oprimitiveID_UNDEF`.
pub const PRIMITIVE_ID_UNDEF: PrimitiveId = 0xFFFF_FFFF;
/// First ID handed out; IDs are `PRIMITIVE_ID_BASE + table index`.
pub const PRIMITIVE_ID_BASE: PrimitiveId = 0x0000_0100;
/// `ovrPATH_MAX`: maximum locator length.
pub const LOCATOR_MAX: usize = 127;

/// `micro(radians(deg))` exactly as the OPEN-R inline helper `oradians()` computes it
/// (truncation toward zero, robot-api 3.2).
pub fn oradians(deg: f64) -> i32 {
    (PI * deg / 180.0 * 1_000_000.0) as i32
}

/// µrad → degrees.
pub fn degrees(urad: f64) -> f64 {
    urad / 1_000_000.0 * 180.0 / PI
}

/// Robot designs (`GetRobotDesign` strings).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Design {
    Ers7,
    Ers210,
    Ers220,
}

impl Design {
    pub const ALL: [Design; 3] = [Design::Ers7, Design::Ers210, Design::Ers220];

    pub fn name(self) -> &'static str {
        match self {
            Design::Ers7 => "ERS-7",
            Design::Ers210 => "ERS-210",
            Design::Ers220 => "ERS-220",
        }
    }
    pub fn from_name(name: &str) -> Option<Design> {
        Design::ALL.into_iter().find(|d| d.name() == name)
    }
    /// Camera frames per second (robot-api 8.4).
    pub fn camera_fps(self) -> u32 {
        match self {
            Design::Ers7 => 30,
            _ => 25,
        }
    }
    /// Microphone block period in 8 ms frames (robot-api 8.6: 16 ms ERS-7, 32 ms 2xx).
    pub fn mic_period_frames(self) -> u32 {
        match self {
            Design::Ers7 => 2,
            _ => 4,
        }
    }
    /// Bytes of one microphone block: its period of 16 kHz 16-bit stereo (robot-api 8.6:
    /// 1024 bytes every 16 ms on the ERS-7, 2048 every 32 ms on the ERS-2xx).
    pub fn mic_block_bytes(self) -> usize {
        self.mic_period_frames() as usize * 512
    }
}

/// `OSensorType`-like classification of a Sensor primitive.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SensorKind {
    /// Paw, chin, wireless-LAN, back and tail switches: value oswitchON/OFF.
    Switch,
    /// ERS-7 electrostatic touch pads: raw A/D 0..~80 in value and signal.
    Touch,
    /// ERS-2xx head pressure sensors (µN).
    Pressure,
    /// Distance sensors (µm).
    Psd,
    /// Acceleration (µm/s²).
    Accelerometer,
    /// ERS-2xx thermometer (µ°C).
    Thermometer,
}

/// Primitive type (`OPrimitiveType`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum PrimitiveKind {
    Joint2,
    Joint3,
    Joint4,
    Led2,
    Led3,
    Sensor(SensorKind),
    Speaker,
    Mic,
    FbkImageSensor,
}

impl PrimitiveKind {
    /// `oprimitive…` type code (robot-api 6.1).
    pub fn type_code(self) -> u32 {
        match self {
            PrimitiveKind::Sensor(_) => 6,
            PrimitiveKind::Speaker => 7,
            PrimitiveKind::Mic => 8,
            PrimitiveKind::FbkImageSensor => 9,
            PrimitiveKind::Joint2 => 11,
            PrimitiveKind::Led2 => 12,
            PrimitiveKind::Joint3 => 13,
            PrimitiveKind::Joint4 => 14,
            PrimitiveKind::Led3 => 16,
        }
    }
    pub fn is_joint(self) -> bool {
        matches!(self, PrimitiveKind::Joint2 | PrimitiveKind::Joint3 | PrimitiveKind::Joint4)
    }
    /// `ODataType` the sensor subject writes into `OSensorFrameInfo.type` (robot-api 6.4).
    pub fn sensor_data_type(self) -> u32 {
        match self {
            PrimitiveKind::Joint2 | PrimitiveKind::Joint3 => 18, // odataJOINT_VALUE
            PrimitiveKind::Sensor(SensorKind::Switch) => 14,
            PrimitiveKind::Sensor(SensorKind::Touch) => 1,
            PrimitiveKind::Sensor(SensorKind::Pressure) => 8,
            PrimitiveKind::Sensor(SensorKind::Psd) => 2,
            PrimitiveKind::Sensor(SensorKind::Accelerometer) => 9,
            PrimitiveKind::Sensor(SensorKind::Thermometer) => 11,
            _ => 0,
        }
    }
}

/// Legs, named by port: r2 left front, r3 left rear, r4 right front, r5 right rear.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Leg {
    LeftFront,
    LeftRear,
    RightFront,
    RightRear,
}

impl Leg {
    pub const ALL: [Leg; 4] = [Leg::LeftFront, Leg::LeftRear, Leg::RightFront, Leg::RightRear];
    pub fn is_front(self) -> bool {
        matches!(self, Leg::LeftFront | Leg::RightFront)
    }
    pub fn is_left(self) -> bool {
        matches!(self, Leg::LeftFront | Leg::LeftRear)
    }
    pub fn index(self) -> usize {
        match self {
            Leg::LeftFront => 0,
            Leg::LeftRear => 1,
            Leg::RightFront => 2,
            Leg::RightRear => 3,
        }
    }
}

/// Which physical thing a primitive is; drives the physics/scene model.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Part {
    NeckTilt1,
    NeckPan,
    NeckTilt2,
    /// ERS-2xx head roll.
    HeadRoll,
    Mouth,
    LegJ1(Leg),
    LegJ2(Leg),
    LegJ3(Leg),
    TailTilt,
    TailPan,
    /// Ear plunger / ear joint; `true` = left.
    Ear(bool),
    PawSwitch(Leg),
    ChinSwitch,
    WlanSwitch,
    /// ERS-2xx back switch.
    BackSwitch,
    /// ERS-220 tail switches 2..4.
    TailSwitch(u8),
    HeadTouch,
    /// ERS-7 back touch pads.
    BackTouchFront,
    BackTouchMiddle,
    BackTouchRear,
    /// ERS-2xx head pressure sensors 1 (back) / 2 (front).
    HeadPressure(u8),
    PsdHeadNear,
    PsdHeadFar,
    PsdChest,
    /// ERS-2xx single head PSD.
    PsdHead,
    /// 0 = a1 front-back, 1 = a2 right-left, 2 = a3 up-down.
    Accel(u8),
    Thermometer,
    /// LED2 head/indicator/eye/tail lights.
    Light,
    /// ERS-7 face light n (1..14): LED3 whose A/B mode matters.
    FaceLight(u8),
    /// ERS-7 back lights: LED3 whose mode is ignored.
    BackLight,
    Camera,
    Mic,
    Speaker,
}

/// PID gain set (`SetJointGain` words).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Gain {
    pub p: u16,
    pub i: u16,
    pub d: u16,
    pub p_shift: u16,
    pub i_shift: u16,
    pub d_shift: u16,
}

impl Gain {
    /// Gains with the fixed shifts 0x0E/0x02/0x0F (robot-api 11).
    pub const fn std(p: u16, i: u16, d: u16) -> Gain {
        Gain { p, i, d, p_shift: 0x0E, i_shift: 0x02, d_shift: 0x0F }
    }
    /// Effective coefficients `GAIN / 2^(16 − SHIFT)` (robot-api 11, third-party source).
    pub fn coefficients(&self) -> (f64, f64, f64) {
        let f = |g: u16, s: u16| g as f64 / 2f64.powi(16 - s.min(16) as i32);
        (f(self.p, self.p_shift), f(self.i, self.i_shift), f(self.d, self.d_shift))
    }
}

/// Servo joint data.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct JointSpec {
    /// Software limits, µrad (clamping range).
    pub min: i32,
    pub max: i32,
    /// Speed limit, rad/s (ers7-model 4.8).
    pub max_speed: f64,
    /// Registered default gains (the MI standard table).
    pub default_gain: Gain,
}

impl JointSpec {
    /// Largest change of angle in one 8 ms frame, µrad.
    pub fn max_step(&self) -> f64 {
        self.max_speed * 0.008 * 1_000_000.0
    }
    pub fn clamp(&self, v: i32) -> i32 {
        v.clamp(self.min, self.max)
    }
}

/// One primitive of the design.
#[derive(Clone, Debug, PartialEq)]
pub struct Primitive {
    pub id: PrimitiveId,
    pub locator: &'static str,
    pub kind: PrimitiveKind,
    pub part: Part,
    /// Servo data for Joint2 (and ERS-210 Joint3 ears: None).
    pub joint: Option<JointSpec>,
    /// Index in the sensor frame (ers7-model 6), if any.
    pub sensor_index: Option<usize>,
}

/// A robot design's full primitive table.
#[derive(Clone, Debug)]
pub struct RobotModel {
    design: Design,
    prims: Vec<Primitive>,
    /// Table indices in sensor-frame order.
    sensor_order: Vec<usize>,
    /// Table index of each part's first primitive (`by_part` runs a dozen times a frame).
    parts: rustc_hash::FxHashMap<Part, usize>,
}

type Row = (&'static str, PrimitiveKind, Part);

impl RobotModel {
    pub fn new(design: Design) -> RobotModel {
        let (rows, order): (Vec<Row>, &[&str]) = match design {
            Design::Ers7 => (ers7_rows(), &ERS7_SENSOR_ORDER),
            Design::Ers210 => (super::model_ers2xx::ers210_rows(), &super::model_ers2xx::ERS210_SENSOR_ORDER),
            Design::Ers220 => (super::model_ers2xx::ers220_rows(), &super::model_ers2xx::ERS220_SENSOR_ORDER),
        };
        let mut prims: Vec<Primitive> = rows
            .into_iter()
            .enumerate()
            .map(|(i, (locator, kind, part))| Primitive {
                id: PRIMITIVE_ID_BASE + i as u32,
                locator,
                kind,
                part,
                joint: if kind == PrimitiveKind::Joint2 { joint_spec(design, part) } else { None },
                sensor_index: None,
            })
            .collect();
        let mut sensor_order = Vec::with_capacity(order.len());
        for (si, loc) in order.iter().enumerate() {
            // The order tables are written from the same spec tables; a miss is a bug
            // in this file, caught by the unit tests, so skip rather than panic.
            if let Some(idx) = prims.iter().position(|p| p.locator == *loc) {
                prims[idx].sensor_index = Some(si);
                sensor_order.push(idx);
            }
        }
        let mut parts = rustc_hash::FxHashMap::default();
        for (i, p) in prims.iter().enumerate() {
            parts.entry(p.part).or_insert(i);
        }
        RobotModel { design, prims, sensor_order, parts }
    }

    pub fn design(&self) -> Design {
        self.design
    }

    /// `OpenPrimitive`: whole-locator match (ers7-model 0.4).
    pub fn open_primitive(&self, locator: &str) -> Option<PrimitiveId> {
        self.prims.iter().find(|p| p.locator == locator).map(|p| p.id)
    }

    pub fn primitive(&self, id: PrimitiveId) -> Option<&Primitive> {
        let idx = id.checked_sub(PRIMITIVE_ID_BASE)? as usize;
        self.prims.get(idx)
    }

    pub fn by_part(&self, part: Part) -> Option<&Primitive> {
        self.parts.get(&part).and_then(|&i| self.prims.get(i))
    }

    pub fn primitives(&self) -> &[Primitive] {
        &self.prims
    }

    /// Locator of an ID, for traces and diagnostics.
    pub fn locator(&self, id: PrimitiveId) -> Option<&'static str> {
        self.primitive(id).map(|p| p.locator)
    }

    /// Primitives in sensor-frame order (34 on ERS-7, 31 on ERS-2xx).
    pub fn sensor_entries(&self) -> impl Iterator<Item = &Primitive> + '_ {
        self.sensor_order.iter().filter_map(move |&i| self.prims.get(i))
    }

    pub fn sensor_count(&self) -> usize {
        self.sensor_order.len()
    }

    /// All Joint2 primitives.
    pub fn joints(&self) -> impl Iterator<Item = &Primitive> + '_ {
        self.prims.iter().filter(|p| p.joint.is_some())
    }

    /// Combined-limit clamp of ers7-model 4.2/4.3 (ERS-7 only): the lowest allowed value of
    /// `part` given the target of the joint it depends on (`other_target`, µrad).
    /// Returns None when `part` has no combined limit.
    pub fn combined_min(&self, part: Part, other_target: i32) -> Option<i32> {
        if self.design != Design::Ers7 {
            return None;
        }
        let other_deg = degrees(other_target as f64);
        match part {
            Part::LegJ2(leg) => Some(oradians(min_j2_deg(leg.is_front(), other_deg))),
            Part::NeckTilt2 => Some(oradians(min_tilt2_deg(other_deg))),
            _ => None,
        }
    }

    /// The joint whose target a combined limit of `part` depends on.
    pub fn combined_dependency(&self, part: Part) -> Option<Part> {
        if self.design != Design::Ers7 {
            return None;
        }
        match part {
            Part::LegJ2(leg) => Some(Part::LegJ1(leg)),
            Part::NeckTilt2 => Some(Part::NeckTilt1),
            _ => None,
        }
    }
}

/// Minimum J2 (deg) for a J1 angle (deg), ers7-model 4.2. J1 is rounded to whole degrees
/// and the first printed row containing it wins (the printed rows overlap in places).
pub fn min_j2_deg(front: bool, j1_deg: f64) -> f64 {
    const FRONT: [(i32, i32, i32); 17] = [
        (-115, -76, -1),
        (-75, -54, -2),
        (-55, -46, -3),
        (-45, -36, -4),
        (-35, -31, -5),
        (-30, -26, -6),
        (-25, -21, -7),
        (-20, -16, -8),
        (-15, -11, -9),
        (-10, 20, -10),
        (21, 25, -9),
        (26, 30, -8),
        (29, 40, -7),
        (41, 45, -6),
        (46, 50, -5),
        (51, 55, -4),
        (56, 65, -3),
    ];
    const FRONT_LAST: (i32, i32, i32) = (64, 130, -2);
    const REAR: [(i32, i32, i32); 21] = [
        (71, 115, 0),
        (61, 70, -1),
        (51, 60, -2),
        (46, 50, -3),
        (41, 45, -4),
        (36, 40, -5),
        (31, 35, -6),
        (26, 30, -7),
        (21, 25, -8),
        (16, 20, -9),
        (-10, 15, -10),
        (-15, -11, -9),
        (-20, -16, -8),
        (-25, -21, -7),
        (-30, -26, -6),
        (-35, -31, -5),
        (-40, -36, -4),
        (-45, -41, -3),
        (-55, -46, -2),
        (-70, -56, -1),
        (-130, -71, 0),
    ];
    let j1 = j1_deg.round() as i32;
    let hit = |rows: &[(i32, i32, i32)]| rows.iter().find(|r| r.0 <= j1 && j1 <= r.1).map(|r| r.2);
    let found = if front { hit(&FRONT).or_else(|| hit(&[FRONT_LAST])) } else { hit(&REAR) };
    match found {
        Some(v) => v as f64,
        // Beyond the printed J1 range (cannot happen after J1 clamping): use the row at
        // that end of the table.
        None if front => {
            if j1 < -115 {
                -1.0
            } else {
                -2.0
            }
        }
        None => 0.0,
    }
}

/// Minimum neck tilt2 (deg) for a tilt1 angle (deg), ers7-model 4.3: tilt1 −75..−39 →
/// tilt2 ≥ +5; −40..0 → ≥ −5 (first row wins in the overlap).
pub fn min_tilt2_deg(tilt1_deg: f64) -> f64 {
    let t = tilt1_deg.round() as i32;
    if t <= -39 {
        5.0
    } else {
        -5.0
    }
}

fn joint_spec(design: Design, part: Part) -> Option<JointSpec> {
    match design {
        Design::Ers7 => ers7_joint_spec(part),
        _ => super::model_ers2xx::joint_spec(design, part),
    }
}

fn spec(min_deg: f64, max_deg: f64, max_speed: f64, g: Gain) -> JointSpec {
    JointSpec { min: oradians(min_deg), max: oradians(max_deg), max_speed, default_gain: g }
}

/// ERS-7 limits (4.1), speed limits (4.8, rad/s) and standard gains (4.5).
fn ers7_joint_spec(part: Part) -> Option<JointSpec> {
    Some(match part {
        Part::NeckTilt1 => spec(-75.0, 0.0, 3.185, Gain::std(0x0A, 0x04, 0x02)),
        Part::NeckPan => spec(-88.0, 88.0, 10.057, Gain::std(0x08, 0x02, 0x04)),
        Part::NeckTilt2 => spec(-15.0, 45.0, 5.781, Gain::std(0x08, 0x04, 0x02)),
        Part::Mouth => spec(-55.0, -3.0, 10.145, Gain::std(0x08, 0x00, 0x04)),
        Part::LegJ1(leg) if leg.is_front() => spec(-115.0, 130.0, 4.865, Gain::std(0x1C, 0x08, 0x01)),
        Part::LegJ1(_) => spec(-130.0, 115.0, 4.865, Gain::std(0x1C, 0x08, 0x01)),
        Part::LegJ2(_) => spec(-10.0, 88.0, 5.280, Gain::std(0x14, 0x04, 0x01)),
        Part::LegJ3(_) => spec(-25.0, 122.0, 5.280, Gain::std(0x1C, 0x08, 0x01)),
        Part::TailTilt => spec(5.0, 60.0, 15.163, Gain::std(0x0A, 0x04, 0x04)),
        Part::TailPan => spec(-45.0, 45.0, 15.163, Gain::std(0x0A, 0x04, 0x04)),
        _ => return None,
    })
}

/// ERS-7 sensor-frame order (ers7-model 6).
pub const ERS7_SENSOR_ORDER: [&str; 34] = [
    "PRM:/r1/c1/c2/c3/c4-Joint2:14",
    "PRM:/r1/c1/c2/c3/c4/s5-Sensor:s5",
    "PRM:/r1/c1/c2/c3-Joint2:13",
    "PRM:/r1/c1/c2/c3/t1-Sensor:t1",
    "PRM:/r1/c1/c2/c3/p1-Sensor:p1",
    "PRM:/r1/c1/c2/c3/p2-Sensor:p2",
    "PRM:/r1/c1/c2-Joint2:12",
    "PRM:/r1/c1-Joint2:11",
    "PRM:/r2/c1/c2/c3/c4-Sensor:24",
    "PRM:/r2/c1/c2/c3-Joint2:23",
    "PRM:/r2/c1/c2-Joint2:22",
    "PRM:/r2/c1-Joint2:21",
    "PRM:/r3/c1/c2/c3/c4-Sensor:34",
    "PRM:/r3/c1/c2/c3-Joint2:33",
    "PRM:/r3/c1/c2-Joint2:32",
    "PRM:/r3/c1-Joint2:31",
    "PRM:/r4/c1/c2/c3/c4-Sensor:44",
    "PRM:/r4/c1/c2/c3-Joint2:43",
    "PRM:/r4/c1/c2-Joint2:42",
    "PRM:/r4/c1-Joint2:41",
    "PRM:/r5/c1/c2/c3/c4-Sensor:54",
    "PRM:/r5/c1/c2/c3-Joint2:53",
    "PRM:/r5/c1/c2-Joint2:52",
    "PRM:/r5/c1-Joint2:51",
    "PRM:/r6/c1-Joint2:61",
    "PRM:/r6/c2-Joint2:62",
    "PRM:/a1-Sensor:a1",
    "PRM:/a2-Sensor:a2",
    "PRM:/a3-Sensor:a3",
    "PRM:/p1-Sensor:p1",
    "PRM:/b1-Sensor:b1",
    "PRM:/t2-Sensor:t2",
    "PRM:/t3-Sensor:t3",
    "PRM:/t4-Sensor:t4",
];

/// ERS-7 primitive table in ers7-model 3 order (the order fixes the IDs).
fn ers7_rows() -> Vec<Row> {
    use PrimitiveKind::*;
    use SensorKind::*;
    let mut v: Vec<Row> = vec![
        ("PRM:/r1/c1-Joint2:11", Joint2, Part::NeckTilt1),
        ("PRM:/r1/c1/c2-Joint2:12", Joint2, Part::NeckPan),
        ("PRM:/r1/c1/c2/c3-Joint2:13", Joint2, Part::NeckTilt2),
        ("PRM:/r1/c1/c2/c3/c4-Joint2:14", Joint2, Part::Mouth),
        ("PRM:/r1/c1/c2/c3/e5-Joint4:15", Joint4, Part::Ear(true)),
        ("PRM:/r1/c1/c2/c3/e6-Joint4:16", Joint4, Part::Ear(false)),
        ("PRM:/r1/c1/c2/c3/t1-Sensor:t1", Sensor(Touch), Part::HeadTouch),
        ("PRM:/r1/c1/c2/c3/p1-Sensor:p1", Sensor(Psd), Part::PsdHeadNear),
        ("PRM:/r1/c1/c2/c3/p2-Sensor:p2", Sensor(Psd), Part::PsdHeadFar),
        ("PRM:/r1/c1/c2/c3/c4/s5-Sensor:s5", Sensor(Switch), Part::ChinSwitch),
        ("PRM:/r1/c1/c2/c3/l1-LED2:l1", Led2, Part::Light),
        ("PRM:/r1/c1/c2/c3/l2-LED2:l2", Led2, Part::Light),
        ("PRM:/r1/c1/c2/c3/l3-LED2:l3", Led2, Part::Light),
        ("PRM:/r1/c1/c2/c3/l4-LED2:l4", Led2, Part::Light),
        ("PRM:/r1/c1/c2/c3/l5-LED2:l5", Led2, Part::Light),
        ("PRM:/r1/c1/c2/c3/l6-LED2:l6", Led2, Part::Light),
    ];
    const FACE: [&str; 14] = [
        "PRM:/r1/c1/c2/c3/la-LED3:la",
        "PRM:/r1/c1/c2/c3/lb-LED3:lb",
        "PRM:/r1/c1/c2/c3/lc-LED3:lc",
        "PRM:/r1/c1/c2/c3/ld-LED3:ld",
        "PRM:/r1/c1/c2/c3/le-LED3:le",
        "PRM:/r1/c1/c2/c3/lf-LED3:lf",
        "PRM:/r1/c1/c2/c3/lg-LED3:lg",
        "PRM:/r1/c1/c2/c3/lh-LED3:lh",
        "PRM:/r1/c1/c2/c3/li-LED3:li",
        "PRM:/r1/c1/c2/c3/lj-LED3:lj",
        "PRM:/r1/c1/c2/c3/lk-LED3:lk",
        "PRM:/r1/c1/c2/c3/ll-LED3:ll",
        "PRM:/r1/c1/c2/c3/lm-LED3:lm",
        "PRM:/r1/c1/c2/c3/ln-LED3:ln",
    ];
    for (n, loc) in FACE.iter().enumerate() {
        v.push((loc, Led3, Part::FaceLight(n as u8 + 1)));
    }
    v.extend_from_slice(&[("PRM:/r1/c1/c2/c3/i1-FbkImageSensor:F1", FbkImageSensor, Part::Camera), ("PRM:/r1/c1/c2/c3/m1-Mic:M1", Mic, Part::Mic)]);
    const LEGS: [(Leg, [&str; 4]); 4] = [
        (Leg::LeftFront, ["PRM:/r2/c1-Joint2:21", "PRM:/r2/c1/c2-Joint2:22", "PRM:/r2/c1/c2/c3-Joint2:23", "PRM:/r2/c1/c2/c3/c4-Sensor:24"]),
        (Leg::LeftRear, ["PRM:/r3/c1-Joint2:31", "PRM:/r3/c1/c2-Joint2:32", "PRM:/r3/c1/c2/c3-Joint2:33", "PRM:/r3/c1/c2/c3/c4-Sensor:34"]),
        (Leg::RightFront, ["PRM:/r4/c1-Joint2:41", "PRM:/r4/c1/c2-Joint2:42", "PRM:/r4/c1/c2/c3-Joint2:43", "PRM:/r4/c1/c2/c3/c4-Sensor:44"]),
        (Leg::RightRear, ["PRM:/r5/c1-Joint2:51", "PRM:/r5/c1/c2-Joint2:52", "PRM:/r5/c1/c2/c3-Joint2:53", "PRM:/r5/c1/c2/c3/c4-Sensor:54"]),
    ];
    for (leg, locs) in LEGS {
        v.push((locs[0], Joint2, Part::LegJ1(leg)));
        v.push((locs[1], Joint2, Part::LegJ2(leg)));
        v.push((locs[2], Joint2, Part::LegJ3(leg)));
        v.push((locs[3], Sensor(Switch), Part::PawSwitch(leg)));
    }
    v.extend_from_slice(&[
        ("PRM:/r6/c1-Joint2:61", Joint2, Part::TailTilt),
        ("PRM:/r6/c2-Joint2:62", Joint2, Part::TailPan),
        ("PRM:/s1-Speaker:S1", Speaker, Part::Speaker),
        ("PRM:/p1-Sensor:p1", Sensor(Psd), Part::PsdChest),
        ("PRM:/b1-Sensor:b1", Sensor(Switch), Part::WlanSwitch),
        ("PRM:/t2-Sensor:t2", Sensor(Touch), Part::BackTouchRear),
        ("PRM:/t3-Sensor:t3", Sensor(Touch), Part::BackTouchMiddle),
        ("PRM:/t4-Sensor:t4", Sensor(Touch), Part::BackTouchFront),
        ("PRM:/lu-LED3:lu", Led3, Part::BackLight),
        ("PRM:/lv-LED3:lv", Led3, Part::BackLight),
        ("PRM:/lw-LED3:lw", Led3, Part::BackLight),
        ("PRM:/lx-LED3:lx", Led3, Part::BackLight),
        ("PRM:/ly-LED3:ly", Led3, Part::BackLight),
        ("PRM:/lz-LED3:lz", Led3, Part::BackLight),
        ("PRM:/a1-Sensor:a1", Sensor(Accelerometer), Part::Accel(0)),
        ("PRM:/a2-Sensor:a2", Sensor(Accelerometer), Part::Accel(1)),
        ("PRM:/a3-Sensor:a3", Sensor(Accelerometer), Part::Accel(2)),
    ]);
    v
}

/// Reference postures of ers7-model 4.7, degrees in the order tilt1, pan, tilt2, mouth,
/// LF J1 J2 J3, LR J1 J2 J3, RF J1 J2 J3, RR J1 J2 J3, tail tilt, tail pan.
pub const POSTURE_SLEEP: [f64; 18] = [-25.0, 0.0, 25.0, -5.0, 59.0, 0.0, 30.0, -119.0, 4.0, 122.0, 59.0, 0.0, 30.0, -119.0, 4.0, 122.0, 5.0, 0.0];
pub const POSTURE_STAND: [f64; 18] = [-20.0, 0.0, 25.0, -5.0, -5.0, 3.0, 30.0, -5.0, 3.0, 30.0, -5.0, 3.0, 30.0, -5.0, 3.0, 30.0, 5.0, 0.0];
pub const POSTURE_SIT: [f64; 18] = [-40.0, 0.0, 5.0, -5.0, -25.0, -4.0, 20.0, -78.0, 20.0, 110.0, -25.0, -4.0, 20.0, -78.0, 20.0, 110.0, 5.0, 0.0];

/// The parts in the order of the posture tables above.
pub const POSTURE_PARTS: [Part; 18] = [
    Part::NeckTilt1,
    Part::NeckPan,
    Part::NeckTilt2,
    Part::Mouth,
    Part::LegJ1(Leg::LeftFront),
    Part::LegJ2(Leg::LeftFront),
    Part::LegJ3(Leg::LeftFront),
    Part::LegJ1(Leg::LeftRear),
    Part::LegJ2(Leg::LeftRear),
    Part::LegJ3(Leg::LeftRear),
    Part::LegJ1(Leg::RightFront),
    Part::LegJ2(Leg::RightFront),
    Part::LegJ3(Leg::RightFront),
    Part::LegJ1(Leg::RightRear),
    Part::LegJ2(Leg::RightRear),
    Part::LegJ3(Leg::RightRear),
    Part::TailTilt,
    Part::TailPan,
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ers7_counts() {
        let m = RobotModel::new(Design::Ers7);
        let count = |k: PrimitiveKind| m.primitives().iter().filter(|p| p.kind == k).count();
        assert_eq!(count(PrimitiveKind::Joint2), 18);
        assert_eq!(count(PrimitiveKind::Joint4), 2);
        assert_eq!(count(PrimitiveKind::Led2), 6);
        assert_eq!(count(PrimitiveKind::Led3), 20);
        assert_eq!(m.sensor_count(), 34);
        assert_eq!(m.joints().count(), 18);
    }

    #[test]
    fn ids_are_global_valid_and_unique() {
        for d in [Design::Ers7, Design::Ers210, Design::Ers220] {
            let m = RobotModel::new(d);
            let mut ids: Vec<u32> = m.primitives().iter().map(|p| p.id).collect();
            assert!(ids.iter().all(|&i| i != 0 && i != PRIMITIVE_ID_UNDEF));
            ids.sort();
            ids.dedup();
            assert_eq!(ids.len(), m.primitives().len());
            let mut locs: Vec<&str> = m.primitives().iter().map(|p| p.locator).collect();
            locs.sort();
            locs.dedup();
            assert_eq!(locs.len(), m.primitives().len(), "{d:?} duplicate locator");
            assert!(m.primitives().iter().all(|p| p.locator.len() <= LOCATOR_MAX && p.locator.starts_with("PRM:/")));
            for p in m.primitives() {
                assert_eq!(m.open_primitive(p.locator), Some(p.id));
                assert_eq!(m.primitive(p.id).map(|q| q.locator), Some(p.locator));
            }
            assert!(m.primitive(0).is_none());
            assert!(m.primitive(PRIMITIVE_ID_UNDEF).is_none());
        }
    }

    #[test]
    fn two_p1_locators_are_distinct() {
        let m = RobotModel::new(Design::Ers7);
        let chest = m.open_primitive("PRM:/p1-Sensor:p1").map(|id| m.primitive(id).map(|p| p.part));
        let head = m.open_primitive("PRM:/r1/c1/c2/c3/p1-Sensor:p1").map(|id| m.primitive(id).map(|p| p.part));
        assert_eq!(chest, Some(Some(Part::PsdChest)));
        assert_eq!(head, Some(Some(Part::PsdHeadNear)));
        assert_eq!(m.open_primitive("p1"), None);
        assert_eq!(m.open_primitive("PRM:/r2/c1-Joint2:j1"), None);
    }

    #[test]
    fn sensor_order_matches_spec() {
        let m = RobotModel::new(Design::Ers7);
        let locs: Vec<&str> = m.sensor_entries().map(|p| p.locator).collect();
        assert_eq!(locs, ERS7_SENSOR_ORDER.to_vec());
        let p = m.by_part(Part::LegJ1(Leg::LeftFront)).map(|p| p.sensor_index);
        assert_eq!(p, Some(Some(11)));
        assert_eq!(m.by_part(Part::Accel(2)).and_then(|p| p.sensor_index), Some(28));
        assert_eq!(m.by_part(Part::Ear(true)).and_then(|p| p.sensor_index), None);
    }

    #[test]
    fn limits_in_urad_match_table() {
        let m = RobotModel::new(Design::Ers7);
        let j = |part| m.by_part(part).and_then(|p| p.joint).map(|j| (j.min, j.max));
        assert_eq!(j(Part::NeckTilt1), Some((-1308996, 0)));
        assert_eq!(j(Part::NeckPan), Some((-1535889, 1535889)));
        assert_eq!(j(Part::NeckTilt2), Some((-261799, 785398)));
        assert_eq!(j(Part::Mouth), Some((-959931, -52359)));
        assert_eq!(j(Part::LegJ1(Leg::LeftFront)), Some((-2007128, 2268928)));
        assert_eq!(j(Part::LegJ1(Leg::RightFront)), Some((-2007128, 2268928)));
        assert_eq!(j(Part::LegJ1(Leg::LeftRear)), Some((-2268928, 2007128)));
        assert_eq!(j(Part::LegJ2(Leg::RightRear)), Some((-174532, 1535889)));
        assert_eq!(j(Part::LegJ3(Leg::LeftRear)), Some((-436332, 2129301)));
        assert_eq!(j(Part::TailTilt), Some((87266, 1047197)));
        assert_eq!(j(Part::TailPan), Some((-785398, 785398)));
        assert_eq!(oradians(120.0), 2094395);
        assert_eq!(oradians(-119.0), -2076941);
    }

    #[test]
    fn gains_and_speeds() {
        let m = RobotModel::new(Design::Ers7);
        let g = m.by_part(Part::LegJ2(Leg::LeftFront)).and_then(|p| p.joint).map(|j| j.default_gain);
        assert_eq!(g, Some(Gain { p: 0x14, i: 0x04, d: 0x01, p_shift: 0x0E, i_shift: 0x02, d_shift: 0x0F }));
        let (p, i, d) = Gain::std(0x10, 0x04, 0x01).coefficients();
        assert!((p - 4.0).abs() < 1e-9 && (i - 4.0 / 16384.0).abs() < 1e-12 && (d - 0.5).abs() < 1e-9);
        let s = m.by_part(Part::NeckTilt1).and_then(|p| p.joint).map(|j| j.max_step());
        assert!(s.is_some_and(|s| (s - 25480.0).abs() < 1e-6));
    }

    #[test]
    fn two_joint_limits() {
        assert_eq!(min_j2_deg(true, -100.0), -1.0);
        assert_eq!(min_j2_deg(true, 0.0), -10.0);
        assert_eq!(min_j2_deg(true, 29.0), -8.0); // overlap 26..30 / 29..40: first row
        assert_eq!(min_j2_deg(true, 120.0), -2.0);
        assert_eq!(min_j2_deg(false, 100.0), 0.0);
        assert_eq!(min_j2_deg(false, -120.0), 0.0);
        assert_eq!(min_j2_deg(false, 0.0), -10.0);
        assert_eq!(min_j2_deg(false, -50.0), -2.0);
        assert_eq!(min_tilt2_deg(-60.0), 5.0);
        assert_eq!(min_tilt2_deg(-20.0), -5.0);
        let m = RobotModel::new(Design::Ers7);
        assert_eq!(m.combined_min(Part::LegJ2(Leg::LeftRear), oradians(-120.0)), Some(0));
        assert_eq!(m.combined_min(Part::Mouth, 0), None);
    }

    #[test]
    fn design_names() {
        for d in [Design::Ers7, Design::Ers210, Design::Ers220] {
            assert_eq!(Design::from_name(d.name()), Some(d));
        }
        assert_eq!(Design::from_name("ERS-110"), None);
    }
}
