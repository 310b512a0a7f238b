//! End-to-end tests of the [`VirtualRobot`] facade.

use super::model::oradians;
use super::vectors::*;
use super::*;

fn robot() -> VirtualRobot {
    VirtualRobot::new(Design::Ers7)
}

fn joint_vector(id: PrimitiveId, targets: &[i32]) -> Vec<u8> {
    let mut b = vec![0u8; command_vector_size(1)];
    command_vector_init(&mut b, 1).unwrap();
    let frames: Vec<[u8; 8]> = targets.iter().map(|&t| joint2_frame(t)).collect();
    command_vector_push(&mut b, odata::JOINT_COMMAND2, id, &frames).unwrap();
    b
}

#[test]
fn open_primitive_and_status_codes() {
    let mut r = robot();
    let tilt = r.open_primitive("PRM:/r1/c1-Joint2:11").unwrap();
    assert_eq!(r.open_primitive("PRM:/r1/c1-Joint2:11"), Ok(tilt));
    assert_eq!(r.open_primitive("PRM:/nothing"), Err(O_NOT_FOUND));
    assert_eq!(r.close_primitive(tilt), O_SUCCESS);
    assert_eq!(r.close_primitive(0), O_INVALID_PRIMITIVE_ID);
    assert!(VirtualRobot::from_design_name("ERS-7").is_some());
    assert!(VirtualRobot::from_design_name("ERS-111").is_none());
}

#[test]
fn gain_return_codes() {
    let mut r = robot();
    let pan = r.open_primitive("PRM:/r1/c1/c2-Joint2:12").unwrap();
    let led = r.open_primitive("PRM:/r1/c1/c2/c3/l1-LED2:l1").unwrap();
    let ear = r.open_primitive("PRM:/r1/c1/c2/c3/e5-Joint4:15").unwrap();
    let g = Gain::std(0x0A, 0x04, 0x02);
    // the SoccerLion200 mistake: oprimitiveUNDEF (0) must fail harmlessly
    assert_eq!(r.set_default_joint_gain(0), O_INVALID_PRIMITIVE_ID);
    assert_eq!(r.enable_joint_gain(0), O_INVALID_PRIMITIVE_ID);
    assert_eq!(r.enable_joint_gain(led), O_INVALID_PRIMITIVE_ID);
    assert_eq!(r.enable_joint_gain(ear), O_SUCCESS);
    assert_eq!(r.set_joint_gain(pan, g), O_GAIN_DISABLED);
    assert_eq!(r.get_joint_gain(pan), Err(O_GAIN_DISABLED));
    assert_eq!(r.get_default_joint_gain(pan), Ok(Gain::std(0x08, 0x02, 0x04)));
    assert_eq!(r.enable_joint_gain(pan), O_SUCCESS);
    assert_eq!(r.get_joint_gain(pan), Ok(Gain::std(0x08, 0x02, 0x04)));
    assert_eq!(r.set_joint_gain(pan, g), O_SUCCESS);
    assert_eq!(r.get_joint_gain(pan), Ok(g));
    assert_eq!(r.set_default_joint_gain(pan), O_SUCCESS);
    assert_eq!(r.get_joint_gain(pan), Ok(Gain::std(0x08, 0x02, 0x04)));
    assert_eq!(r.register_default_joint_gain(pan, g), O_SUCCESS);
    assert_eq!(r.get_default_joint_gain(pan), Ok(g));
    // UNDEF = every opened joint
    let tilt = r.open_primitive("PRM:/r1/c1-Joint2:11").unwrap();
    assert_eq!(r.disable_joint_gain(PRIMITIVE_ID_UNDEF), O_SUCCESS);
    assert_eq!(r.get_joint_gain(tilt), Err(O_GAIN_DISABLED));
    assert_eq!(r.enable_joint_gain(PRIMITIVE_ID_UNDEF), O_SUCCESS);
    assert!(r.get_joint_gain(tilt).is_ok() && r.get_joint_gain(pan).is_ok());
    let unopened = r.model().open_primitive("PRM:/r6/c1-Joint2:61").unwrap();
    assert_eq!(r.get_joint_gain(unopened), Err(O_GAIN_DISABLED));
    assert_eq!(r.get_joint_gain(led), Err(O_INVALID_PRIMITIVE_ID));
    // sync keys through the facade
    let k = r.new_sync_key().unwrap();
    assert!(r.divide_sync_key(k).is_ok());
    assert_eq!(r.cancel_sync_key(k), O_SUCCESS);
    assert_eq!(r.cancel_sync_key(k), O_INVALID_SYNC_KEY);
}

#[test]
fn readings_valid_from_boot() {
    let r = robot();
    let lf = r.primitive_of(model::Part::LegJ1(model::Leg::LeftFront)).unwrap();
    assert_eq!(r.joint_value(lf).map(|v| v.value), Ok(oradians(59.0)));
    let a3 = r.model().open_primitive("PRM:/a3-Sensor:a3").unwrap();
    assert_eq!(r.sensor_value(a3).map(|v| v.value), Ok(9_806_650)); // lying level
    assert_eq!(r.sensor_value(lf), Err(O_INVALID_PRIMITIVE_ID));
    assert_eq!(r.joint_value(a3), Err(O_INVALID_PRIMITIVE_ID));
}

#[test]
fn sample_style_motion_flow() {
    let mut r = robot();
    let tilt = r.open_primitive("PRM:/r1/c1-Joint2:11").unwrap();
    assert_eq!(r.set_motor_power(true), O_SUCCESS);
    // hold the current angle first, as the samples do, then enable the gain and move
    let now = r.joint_value(tilt).unwrap().value;
    let mut hold = joint_vector(tilt, &[now; 16]);
    let t1 = r.submit_command(1, &hold).unwrap();
    let target = oradians(-40.0);
    let t2 = r.submit_command(1, &joint_vector(tilt, &[target; 16])).unwrap();
    assert_eq!(r.enable_joint_gain(tilt), O_SUCCESS);
    let mut outs = Vec::new();
    for _ in 0..32 {
        outs.push(r.step_frame());
    }
    // starts/completions back to back
    assert_eq!(outs[0].started.len(), 1);
    write_frame_numbers(&mut hold, &outs[0].started[0]).unwrap();
    assert_eq!(u32::from_le_bytes([hold[200], hold[201], hold[202], hold[203]]), 1);
    let done: Vec<(u32, Token)> = outs.iter().flat_map(|o| o.completed.iter().map(move |c| (o.frame, c.token))).collect();
    assert_eq!(done, vec![(16, t1), (32, t2)]);
    // tilt1 −25° → −40°: 261799 µrad at 25480 µrad/frame = 11 frames
    assert_eq!(outs[16 + 10].frame, 27);
    assert_eq!(r.joint_value(tilt).map(|v| v.value), Ok(target));
    // a sensor vector every 4 frames, continuing frame numbers
    let firsts: Vec<u32> = outs.iter().filter_map(|o| o.sensor_vector.as_ref()).map(|v| read_sensor_entry(v, 0).unwrap().frame_number).collect();
    assert_eq!(firsts, vec![1, 5, 9, 13, 17, 21, 25, 29]);
    let last = outs[31].sensor_vector.as_ref().unwrap();
    let h = VectorHeader::read(last).unwrap();
    assert_eq!((h.vector_type, h.num_data, h.max_num_data, h.total_size as usize), (1025, 34, 34, sensor_vector_size(34)));
    let e = read_sensor_entry(last, 7).unwrap(); // neck tilt1 is entry 7
    assert_eq!(e.primitive, tilt);
    assert_eq!(e.data_type, 18);
    let newest = JointValue::from_bytes(&e.frames[3]);
    assert_eq!(newest, r.joint_value(tilt).unwrap());
    assert_eq!(newest.ref_value, target);
    // trace lines
    let lines: Vec<String> = outs.iter().flat_map(|o| o.trace.iter().map(|t| t.to_json())).collect();
    assert!(lines.iter().any(|l| l.contains("\"kind\":\"motor_power\"") && l.contains("\"on\":true")));
    assert!(lines.iter().any(|l| l.contains("\"kind\":\"gain\"")));
    assert_eq!(lines.iter().filter(|l| l.contains("\"kind\":\"vector_start\"")).count(), 2);
    assert_eq!(lines.iter().filter(|l| l.contains("\"kind\":\"vector_done\"")).count(), 2);
    assert_eq!(lines.iter().filter(|l| l.contains("\"kind\":\"sensor\"")).count(), 8);
    assert!(lines.iter().all(|l| l.starts_with("{\"t_ms\":") && l.ends_with('}')));
    assert!(lines.iter().any(|l| l.contains("\"t_ms\":256,\"frame\":32")));
}

#[test]
fn leds_clamps_optional_and_bad_vectors_in_trace() {
    let mut r = robot();
    let l1 = r.open_primitive("PRM:/r1/c1/c2/c3/l1-LED2:l1").unwrap();
    let tail = r.open_primitive("PRM:/r6/c1-Joint2:61").unwrap();
    let mut b = vec![0u8; command_vector_size(2)];
    command_vector_init(&mut b, 2).unwrap();
    command_vector_push(&mut b, odata::LED_COMMAND2, l1, &[held_frame(1, 2), held_frame(0, 2)]).unwrap();
    command_vector_push(&mut b, odata::JOINT_COMMAND2, tail, &[joint2_frame(0); 4]).unwrap();
    b[44..48].copy_from_slice(&0u32.to_le_bytes());
    b[48..52].copy_from_slice(&3u32.to_le_bytes());
    b[64..67].copy_from_slice(b"abc");
    r.submit_command(5, &b).unwrap();
    let outs: Vec<FrameOutput> = (0..4).map(|_| r.step_frame()).collect();
    let kinds: Vec<String> = outs.iter().flat_map(|o| o.trace.iter().map(|t| t.to_json())).collect();
    assert!(kinds.iter().any(|l| l.contains("\"kind\":\"led\"") && l.contains("\"on\":true") && l.contains("\"frame\":1")));
    assert!(kinds.iter().any(|l| l.contains("\"kind\":\"led\"") && l.contains("\"on\":false") && l.contains("\"frame\":3")));
    assert_eq!(kinds.iter().filter(|l| l.contains("\"kind\":\"clamp\"")).count(), 1);
    assert!(kinds.iter().any(|l| l.contains("\"requested_deg\":0,\"clamped_deg\":5")));
    let sv = outs[3].sensor_vector.as_ref().unwrap();
    let h = VectorHeader::read(sv).unwrap();
    assert_eq!(h.optional(sv).unwrap(), Some(&b"abc"[..]));
    assert_eq!(r.body().joint(tail).map(|j| j.reference), Some(87266));
    assert!(matches!(r.submit_command(5, &b[..150]), Err(VectorError::TooShort { .. })));
    assert_eq!(r.immediate_command(l1, FrameCommand::Joint(0)), O_INVALID_ARG);
    assert_eq!(r.immediate_command(l1, FrameCommand::Led2(true)), O_SUCCESS);
    r.step_frame();
    assert_eq!(r.body().led(l1), Some(kinematics::LedState::Led2 { on: true }));
}

#[test]
fn scene_inputs_reach_sensor_values() {
    let mut r = robot();
    let chin = r.model().open_primitive("PRM:/r1/c1/c2/c3/c4/s5-Sensor:s5").unwrap();
    let back = r.model().open_primitive("PRM:/t3-Sensor:t3").unwrap();
    r.scene_mut().chin_switch = true;
    r.scene_mut().back_touch_middle = true;
    let out = r.step_frame();
    assert_eq!(r.sensor_value(chin).map(|v| v.value), Ok(1));
    assert!(r.sensor_value(back).is_ok_and(|v| v.value >= 14));
    assert!(out.sensor_vector.is_none());
    let mut cams = 0;
    for _ in 0..124 {
        if r.step_frame().camera_due {
            cams += 1;
        }
    }
    assert_eq!(r.clock().time_ms(), 1000);
    assert_eq!(cams, 30);
    r.set_trace(false);
    assert!(r.step_frame().trace.is_empty());
}

#[test]
fn secondary_designs_run() {
    for d in [Design::Ers210, Design::Ers220] {
        let mut r = VirtualRobot::new(d);
        let ids: Vec<PrimitiveId> = r.model().joints().map(|p| p.id).collect();
        for id in &ids {
            let loc = r.model().locator(*id).unwrap();
            r.open_primitive(loc).unwrap();
        }
        r.set_motor_power(true);
        assert_eq!(r.enable_joint_gain(PRIMITIVE_ID_UNDEF), O_SUCCESS);
        r.submit_command(1, &joint_vector(ids[0], &[oradians(-10.0); 4])).unwrap();
        let outs: Vec<FrameOutput> = (0..8).map(|_| r.step_frame()).collect();
        let v = outs[3].sensor_vector.as_ref().unwrap();
        assert_eq!(VectorHeader::read(v).unwrap().num_data, 31);
        assert_eq!(outs.iter().filter(|o| o.mic_due).count(), 2); // 32 ms blocks
    }
}

#[test]
fn garbage_vectors_never_panic() {
    let mut r = robot();
    let tilt = r.model().open_primitive("PRM:/r1/c1-Joint2:11").unwrap();
    let good = joint_vector(tilt, &[0; 16]);
    let mut seed: u64 = 0x1234_5678;
    for round in 0..2000 {
        let mut b = good.clone();
        for _ in 0..(1 + round % 8) {
            seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            let at = (seed >> 33) as usize % b.len();
            b[at] = (seed >> 16) as u8;
        }
        let cut = if round % 5 == 0 { (seed >> 40) as usize % b.len() } else { b.len() };
        let _ = r.submit_command(round % 3, &b[..cut]);
        let _ = parse_sound_vector(&b[..cut]);
        let _ = read_sensor_entry(&b[..cut], 0);
        if round % 50 == 0 {
            r.step_frame();
        }
    }
    for _ in 0..200 {
        r.step_frame();
    }
}
