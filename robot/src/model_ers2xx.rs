//! Primitive tables of the secondary designs ERS-210 and ERS-220 (ers7-model 13).
//!
//! Kept apart from `model.rs` so the ERS-7 tables stay readable. Head tilt maps to
//! [`Part::NeckTilt1`], head pan to [`Part::NeckPan`]. Limits are the single-joint
//! software ranges of 13.3 (the 14-region roll/mouth chart is not modelled).

use super::model::{oradians, Gain, JointSpec, Leg, Part, PrimitiveKind, SensorKind};

type Row = (&'static str, PrimitiveKind, Part);

fn legs(v: &mut Vec<Row>) {
    use PrimitiveKind::*;
    const LEGS: [(Leg, [&str; 4]); 4] = [
        (Leg::LeftFront, ["PRM:/r2/c1-Joint2:j1", "PRM:/r2/c1/c2-Joint2:j2", "PRM:/r2/c1/c2/c3-Joint2:j3", "PRM:/r2/c1/c2/c3/c4-Sensor:s4"]),
        (Leg::LeftRear, ["PRM:/r3/c1-Joint2:j1", "PRM:/r3/c1/c2-Joint2:j2", "PRM:/r3/c1/c2/c3-Joint2:j3", "PRM:/r3/c1/c2/c3/c4-Sensor:s4"]),
        (Leg::RightFront, ["PRM:/r4/c1-Joint2:j1", "PRM:/r4/c1/c2-Joint2:j2", "PRM:/r4/c1/c2/c3-Joint2:j3", "PRM:/r4/c1/c2/c3/c4-Sensor:s4"]),
        (Leg::RightRear, ["PRM:/r5/c1-Joint2:j1", "PRM:/r5/c1/c2-Joint2:j2", "PRM:/r5/c1/c2/c3-Joint2:j3", "PRM:/r5/c1/c2/c3/c4-Sensor:s4"]),
    ];
    for (leg, l) in LEGS {
        v.push((l[0], Joint2, Part::LegJ1(leg)));
        v.push((l[1], Joint2, Part::LegJ2(leg)));
        v.push((l[2], Joint2, Part::LegJ3(leg)));
        v.push((l[3], Sensor(SensorKind::Switch), Part::PawSwitch(leg)));
    }
}

fn common_head(v: &mut Vec<Row>) {
    use PrimitiveKind::*;
    v.extend_from_slice(&[
        ("PRM:/r1/c1-Joint2:j1", Joint2, Part::NeckTilt1),
        ("PRM:/r1/c1/c2-Joint2:j2", Joint2, Part::NeckPan),
        ("PRM:/r1/c1/c2/c3-Joint2:j3", Joint2, Part::HeadRoll),
    ]);
}

fn common_devices(v: &mut Vec<Row>) {
    use PrimitiveKind::*;
    use SensorKind::*;
    v.extend_from_slice(&[
        ("PRM:/r1/c1/c2/c3/f1-Sensor:f1", Sensor(Pressure), Part::HeadPressure(1)),
        ("PRM:/r1/c1/c2/c3/f2-Sensor:f2", Sensor(Pressure), Part::HeadPressure(2)),
        ("PRM:/r1/c1/c2/c3/c4/s5-Sensor:s5", Sensor(Switch), Part::ChinSwitch),
        ("PRM:/r1/c1/c2/c3/p1-Sensor:p1", Sensor(Psd), Part::PsdHead),
        ("PRM:/r1/c1/c2/c3/m1-Mic:M1", Mic, Part::Mic),
        ("PRM:/r1/c1/c2/c3/s1-Speaker:S1", Speaker, Part::Speaker),
        ("PRM:/r1/c1/c2/c3/i1-FbkImageSensor:F1", FbkImageSensor, Part::Camera),
    ]);
}

fn accel_thermo_back(v: &mut Vec<Row>) {
    use PrimitiveKind::*;
    use SensorKind::*;
    v.extend_from_slice(&[
        ("PRM:/r6/t1-Sensor:t1", Sensor(Thermometer), Part::Thermometer),
        ("PRM:/r6/s1-Sensor:s1", Sensor(Switch), Part::BackSwitch),
        ("PRM:/a1-Sensor:a1", Sensor(Accelerometer), Part::Accel(0)),
        ("PRM:/a2-Sensor:a2", Sensor(Accelerometer), Part::Accel(1)),
        ("PRM:/a3-Sensor:a3", Sensor(Accelerometer), Part::Accel(2)),
    ]);
}

pub(super) fn ers210_rows() -> Vec<Row> {
    use PrimitiveKind::*;
    let mut v = Vec::new();
    common_head(&mut v);
    v.extend_from_slice(&[
        ("PRM:/r1/c1/c2/c3/c4-Joint2:j4", Joint2, Part::Mouth),
        ("PRM:/r1/c1/c2/c3/e1-Joint3:j5", Joint3, Part::Ear(true)),
        ("PRM:/r1/c1/c2/c3/e2-Joint3:j6", Joint3, Part::Ear(false)),
    ]);
    common_devices(&mut v);
    for loc in [
        "PRM:/r1/c1/c2/c3/l1-LED2:l1",
        "PRM:/r1/c1/c2/c3/l2-LED2:l2",
        "PRM:/r1/c1/c2/c3/l3-LED2:l3",
        "PRM:/r1/c1/c2/c3/l4-LED2:l4",
        "PRM:/r1/c1/c2/c3/l5-LED2:l5",
        "PRM:/r1/c1/c2/c3/l6-LED2:l6",
        "PRM:/r1/c1/c2/c3/l7-LED2:l7",
    ] {
        v.push((loc, Led2, Part::Light));
    }
    legs(&mut v);
    v.extend_from_slice(&[
        ("PRM:/r6/c1-Joint2:j1", Joint2, Part::TailPan),
        ("PRM:/r6/c2-Joint2:j2", Joint2, Part::TailTilt),
        ("PRM:/r6/l1-LED2:l1", Led2, Part::Light),
        ("PRM:/r6/l2-LED2:l2", Led2, Part::Light),
    ]);
    accel_thermo_back(&mut v);
    v
}

pub(super) fn ers220_rows() -> Vec<Row> {
    use PrimitiveKind::*;
    use SensorKind::*;
    let mut v = Vec::new();
    common_head(&mut v);
    common_devices(&mut v);
    for loc in [
        "PRM:/r1/c1/c2/c3/l1-LED2:l1",
        "PRM:/r1/c1/c2/c3/l2-LED2:l2",
        "PRM:/r1/c1/c2/c3/l3-LED2:l3",
        "PRM:/r1/c1/c2/c3/l4-LED2:l4",
        "PRM:/r1/c1/c2/c3/l5-LED2:l5",
        "PRM:/r1/c1/c2/c3/l6-LED2:l6",
        "PRM:/r1/c1/c2/c3/l7-LED2:l7",
        "PRM:/r1/c1/c2/c3/l8-LED2:l8",
        "PRM:/r1/c1/c2/c3/l9-LED2:l9",
        "PRM:/r1/c1/c2/c3/la-LED2:la",
        "PRM:/r1/c1/c2/c3/lb-LED2:lb",
    ] {
        v.push((loc, Led2, Part::Light));
    }
    legs(&mut v);
    v.extend_from_slice(&[
        ("PRM:/r6/s2-Sensor:s2", Sensor(Switch), Part::TailSwitch(2)),
        ("PRM:/r6/s3-Sensor:s3", Sensor(Switch), Part::TailSwitch(3)),
        ("PRM:/r6/s4-Sensor:s4", Sensor(Switch), Part::TailSwitch(4)),
    ]);
    for loc in [
        "PRM:/r6/l1-LED2:l1",
        "PRM:/r6/l2-LED2:l2",
        "PRM:/r6/l3-LED2:l3",
        "PRM:/r6/l4-LED2:l4",
        "PRM:/r6/l5-LED2:l5",
        "PRM:/r6/l6-LED2:l6",
        "PRM:/r6/l7-LED2:l7",
        "PRM:/r6/l8-LED2:l8",
        "PRM:/r6/l9-LED2:l9",
    ] {
        v.push((loc, Led2, Part::Light));
    }
    accel_thermo_back(&mut v);
    v
}

/// ERS-210 sensor order (ers7-model 13.4).
pub const ERS210_SENSOR_ORDER: [&str; 31] = [
    "PRM:/r1/c1-Joint2:j1",
    "PRM:/r1/c1/c2-Joint2:j2",
    "PRM:/r1/c1/c2/c3-Joint2:j3",
    "PRM:/r1/c1/c2/c3/f1-Sensor:f1",
    "PRM:/r1/c1/c2/c3/f2-Sensor:f2",
    "PRM:/r1/c1/c2/c3/p1-Sensor:p1",
    "PRM:/r1/c1/c2/c3/c4-Joint2:j4",
    "PRM:/r1/c1/c2/c3/c4/s5-Sensor:s5",
    "PRM:/r2/c1-Joint2:j1",
    "PRM:/r2/c1/c2-Joint2:j2",
    "PRM:/r2/c1/c2/c3-Joint2:j3",
    "PRM:/r2/c1/c2/c3/c4-Sensor:s4",
    "PRM:/r3/c1-Joint2:j1",
    "PRM:/r3/c1/c2-Joint2:j2",
    "PRM:/r3/c1/c2/c3-Joint2:j3",
    "PRM:/r3/c1/c2/c3/c4-Sensor:s4",
    "PRM:/r4/c1-Joint2:j1",
    "PRM:/r4/c1/c2-Joint2:j2",
    "PRM:/r4/c1/c2/c3-Joint2:j3",
    "PRM:/r4/c1/c2/c3/c4-Sensor:s4",
    "PRM:/r5/c1-Joint2:j1",
    "PRM:/r5/c1/c2-Joint2:j2",
    "PRM:/r5/c1/c2/c3-Joint2:j3",
    "PRM:/r5/c1/c2/c3/c4-Sensor:s4",
    "PRM:/r6/c1-Joint2:j1",
    "PRM:/r6/c2-Joint2:j2",
    "PRM:/r6/t1-Sensor:t1",
    "PRM:/r6/s1-Sensor:s1",
    "PRM:/a1-Sensor:a1",
    "PRM:/a2-Sensor:a2",
    "PRM:/a3-Sensor:a3",
];

/// ERS-220 sensor order (ers7-model 13.4).
pub const ERS220_SENSOR_ORDER: [&str; 31] = [
    "PRM:/r1/c1-Joint2:j1",
    "PRM:/r1/c1/c2-Joint2:j2",
    "PRM:/r1/c1/c2/c3-Joint2:j3",
    "PRM:/r1/c1/c2/c3/p1-Sensor:p1",
    "PRM:/r1/c1/c2/c3/f1-Sensor:f1",
    "PRM:/r1/c1/c2/c3/f2-Sensor:f2",
    "PRM:/r1/c1/c2/c3/c4/s5-Sensor:s5",
    "PRM:/r2/c1-Joint2:j1",
    "PRM:/r2/c1/c2-Joint2:j2",
    "PRM:/r2/c1/c2/c3-Joint2:j3",
    "PRM:/r2/c1/c2/c3/c4-Sensor:s4",
    "PRM:/r3/c1-Joint2:j1",
    "PRM:/r3/c1/c2-Joint2:j2",
    "PRM:/r3/c1/c2/c3-Joint2:j3",
    "PRM:/r3/c1/c2/c3/c4-Sensor:s4",
    "PRM:/r4/c1-Joint2:j1",
    "PRM:/r4/c1/c2-Joint2:j2",
    "PRM:/r4/c1/c2/c3-Joint2:j3",
    "PRM:/r4/c1/c2/c3/c4-Sensor:s4",
    "PRM:/r5/c1-Joint2:j1",
    "PRM:/r5/c1/c2-Joint2:j2",
    "PRM:/r5/c1/c2/c3-Joint2:j3",
    "PRM:/r5/c1/c2/c3/c4-Sensor:s4",
    "PRM:/r6/t1-Sensor:t1",
    "PRM:/r6/s1-Sensor:s1",
    "PRM:/r6/s2-Sensor:s2",
    "PRM:/r6/s3-Sensor:s3",
    "PRM:/r6/s4-Sensor:s4",
    "PRM:/a1-Sensor:a1",
    "PRM:/a2-Sensor:a2",
    "PRM:/a3-Sensor:a3",
];

/// ERS-210/220 software limits (13.3), third-party speed limits and standard gains.
pub(super) fn joint_spec(_design: super::model::Design, part: Part) -> Option<JointSpec> {
    let s = |lo: f64, hi: f64, speed: f64, g: Gain| JointSpec { min: oradians(lo), max: oradians(hi), max_speed: speed, default_gain: g };
    Some(match part {
        Part::NeckTilt1 => s(-82.0, 43.0, 2.105, Gain::std(0x0A, 0x08, 0x0C)),
        Part::NeckPan => s(-89.6, 89.6, 3.011, Gain::std(0x0D, 0x08, 0x0B)),
        Part::HeadRoll => s(-29.0, 29.0, 3.011, Gain::std(0x0A, 0x08, 0x0C)),
        Part::Mouth => s(-47.0, -3.0, 4.374, Gain::std(0x0E, 0x08, 0x10)),
        Part::LegJ1(_) => s(-117.0, 117.0, 2.814, Gain::std(0x16, 0x04, 0x08)),
        Part::LegJ2(_) => s(-11.0, 89.0, 2.498, Gain::std(0x14, 0x04, 0x06)),
        Part::LegJ3(_) => s(-27.0, 147.0, 2.836, Gain::std(0x23, 0x04, 0x05)),
        Part::TailPan => s(-22.0, 22.0, 4.472, Gain::std(0x0A, 0x00, 0x18)),
        Part::TailTilt => s(-22.0, 22.0, 4.472, Gain::std(0x07, 0x00, 0x11)),
        _ => return None,
    })
}

#[cfg(test)]
mod tests {
    use super::super::model::{Design, PrimitiveKind, RobotModel};

    #[test]
    fn counts_and_order() {
        let m210 = RobotModel::new(Design::Ers210);
        assert_eq!(m210.sensor_count(), 31);
        assert_eq!(m210.joints().count(), 18);
        assert_eq!(m210.primitives().iter().filter(|p| p.kind == PrimitiveKind::Joint3).count(), 2);
        let l: Vec<&str> = m210.sensor_entries().map(|p| p.locator).collect();
        assert_eq!(l, super::ERS210_SENSOR_ORDER.to_vec());
        let m220 = RobotModel::new(Design::Ers220);
        assert_eq!(m220.sensor_count(), 31);
        assert_eq!(m220.joints().count(), 15);
        let l: Vec<&str> = m220.sensor_entries().map(|p| p.locator).collect();
        assert_eq!(l, super::ERS220_SENSOR_ORDER.to_vec());
    }
}
