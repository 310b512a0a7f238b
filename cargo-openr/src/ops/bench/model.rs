//! The robot model's share of a kinematic frame (issue 19, goal 2): one ERS-7 8 ms frame
//! of `VirtualRobot` (effector, servos, sensor synthesis and, every fourth frame, the
//! sensor vector) in this process, with the legs swinging as movelegs swings them, so
//! the whole-run figure of `frames` can be split into the model and the rest (messages,
//! turns, the clock).
use std::time::Instant;

use sdk_runtime::robot::model::{Design, Leg, Part, POSTURE_PARTS, POSTURE_STAND};
use sdk_runtime::robot::VirtualRobot;

use super::stats::Table;

/// Median host time (µs) of one frame over `n` frames, every leg's J1 and J3 placed on a
/// ±30° swing before each frame (the servos then move toward it, the paws touch and
/// leave the floor, the posture and the accelerometers change).
fn frame_us(n: u32) -> f64 {
    let mut r = VirtualRobot::new(Design::Ers7);
    r.set_trace(false);
    r.body_mut().set_posture_deg(&POSTURE_PARTS, &POSTURE_STAND);
    let mut times = Vec::with_capacity(n as usize);
    for f in 0..n {
        let swing = 30.0 * (f as f64 * 0.05).sin();
        for leg in Leg::ALL {
            r.body_mut().set_posture_deg(&[Part::LegJ1(leg), Part::LegJ3(leg)], &[swing, 60.0 + swing]);
        }
        let t = Instant::now();
        std::hint::black_box(r.step_frame());
        times.push(t.elapsed().as_nanos() as f64);
    }
    times.sort_by(f64::total_cmp);
    times[times.len() / 2] / 1000.0
}

pub fn model(tab: &mut Table, reference: &str) {
    tab.push("kinematic frame, robot model only (in process, legs swinging)", frame_us(20_000), "µs", Some(reference));
}
