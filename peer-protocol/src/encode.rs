//! The payloads the runtime builds from the virtual robot: FRAME (every frame's effector
//! output) and WELCOME (the answer to HELLO: the robot's clock, camera, microphone and
//! primitive table). Their layouts are docs/robot-protocol.md's tables.
use openr_robot::kinematics::LedState;
use openr_robot::scene::value_range;
use openr_robot::{PendingFrame, VirtualRobot};

use crate::class_of;
use crate::wire::*;

/// The FRAME payload of a frame in progress (flags without READINGS_EXPECTED, which the
/// runtime sets for the clock owner's copy).
pub fn frame_payload(robot: &VirtualRobot, f: &PendingFrame) -> Vec<u8> {
    let mut flags = 0u8;
    if f.sensor_due() {
        flags |= FRAME_SENSOR_DUE;
    }
    if f.camera_due() {
        flags |= FRAME_CAMERA_DUE;
    }
    if f.mic_due() {
        flags |= FRAME_MIC_DUE;
    }
    if f.camera_next() {
        flags |= FRAME_CAMERA_NEXT;
    }
    let body = robot.body();
    let model = robot.model();
    let mut o = Out::default();
    o.u64(f.time_ms()).u8(flags).u8(body.motor_power() as u8).u8(body.face_mode() as u8).u8(0);
    let joints: Vec<_> = model.joints().filter_map(|p| body.joint(p.id).map(|j| (p.id, j))).collect();
    o.u16(joints.len() as u16);
    for (id, j) in joints {
        o.u32(id).i32(j.reference).i32(j.angle.round() as i32);
        o.u16(j.gain.loaded.p).u16(j.gain.loaded.i).u16(j.gain.loaded.d).u8(j.gain.enabled as u8).u8(0);
    }
    let leds: Vec<_> = model.primitives().iter().filter_map(|p| body.led(p.id).map(|s| (p.id, s))).collect();
    o.u16(leds.len() as u16);
    for (id, s) in leds {
        match s {
            LedState::Led2 { on } => o.u32(id).u8(on as u8).u8(2).u16(0),
            LedState::Led3 { intensity, mode } => o.u32(id).u8(intensity).u8(3).u16(mode),
        };
    }
    let ears: Vec<_> = model.primitives().iter().filter_map(|p| body.ear(p.id).map(|s| (p.id, s))).collect();
    o.u16(ears.len() as u16);
    for (id, s) in ears {
        o.u32(id).u32(s);
    }
    o.0
}

/// The WELCOME payload for a peer granted the roles `granted` (and the clock when
/// `clock`); `mic` is the microphone's (rate, channels, bits).
pub fn welcome_payload(robot: &VirtualRobot, granted: u32, clock: bool, mic: (u32, u16, u16)) -> Vec<u8> {
    let model = robot.model();
    let (w, h) = (robot.camera().rgb.width, robot.camera().rgb.height);
    let (frame, time_ms) = (robot.clock().frame(), robot.clock().time_ms());
    let design = model.design();
    let mut o = Out::default();
    o.u16(VERSION).u16(REVISION).u32(granted).u32(if clock { FLAG_CLOCK } else { 0 });
    o.u32(8000).u32(frame).u64(time_ms);
    o.u16(w as u16).u16(h as u16).u16(design.camera_fps() as u16);
    o.u16(design.mic_period_frames() as u16).u16(design.mic_block_bytes() as u16).u32(mic.0).u16(mic.1).u16(mic.2);
    o.str(design.name());
    o.u16(model.primitives().len() as u16);
    for p in model.primitives() {
        let (min, max) = p.joint.map_or((0, 0), |j| (j.min, j.max));
        o.u32(p.id).u16(class_of(p.kind)).i16(p.sensor_index.map_or(-1, |i| i as i16)).i32(min).i32(max).str(p.locator);
    }
    // Revision 2: what a simulator would otherwise copy from the model.
    let extra: Vec<_> = model
        .primitives()
        .iter()
        .filter_map(|p| {
            let range = value_range(p.part);
            let gain = p.joint.map(|j| j.default_gain);
            (range.is_some() || gain.is_some()).then(|| (p.id, range.unwrap_or((0, 0)), gain.unwrap_or_default()))
        })
        .collect();
    o.u16(extra.len() as u16);
    for (id, (lo, hi), g) in extra {
        o.u32(id).i32(lo).i32(hi).u16(g.p).u16(g.i).u16(g.d);
    }
    o.0
}
