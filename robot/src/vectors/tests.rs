//! Byte-exact tests of the vector layouts against the robot's (robot-api 6.2-6.5).
use super::*;

fn u32at(b: &[u8], o: usize) -> u32 {
    rd_u32(b, o).unwrap()
}

#[test]
fn command_vector_init_n3_exact() {
    let n = 3;
    assert_eq!(command_vector_size(n), 672);
    assert_eq!(region_size(command_vector_size(n)), 4096);
    let mut b = vec![0xAAu8; 4096];
    command_vector_init(&mut b, n).unwrap();
    let hdr = [0, 0, 0, 4096, 1024, 192, 32, 3, 0, 0xFFFF_FFFF, 0, 0, 0];
    for (i, v) in hdr.iter().enumerate() {
        assert_eq!(u32at(&b, 4 * i), *v, "header field {i}");
    }
    assert!(b[52..192].iter().all(|&x| x == 0));
    for i in 0..3 {
        let o = 192 + 32 * i;
        assert_eq!(
            [u32at(&b, o), u32at(&b, o + 4), u32at(&b, o + 8), u32at(&b, o + 12), u32at(&b, o + 16), u32at(&b, o + 20), u32at(&b, o + 24)],
            [0, 0xFFFF_FFFF, 0xFFFF_FFFF, 0, 8, (288 + 128 * i) as u32, 128]
        );
    }
    // data blocks: 288, 416, 544; end 672
    assert_eq!(u32at(&b, 192 + 20), 192 + 32 * 3);
    assert!(b[288..672].iter().all(|&x| x == 0));
    assert!(command_vector_init(&mut b[..671], 3).is_err());
}

#[test]
fn parse_joint_led_ear_slots() {
    let mut b = vec![0u8; command_vector_size(4)];
    command_vector_init(&mut b, 4).unwrap();
    let j: Vec<[u8; 8]> = (0..16).map(|k| joint2_frame(k * 1000)).collect();
    command_vector_push(&mut b, odata::JOINT_COMMAND2, 0x101, &j).unwrap();
    command_vector_push(&mut b, odata::LED_COMMAND2, 0x10a, &[held_frame(1, 64), held_frame(0, 64)]).unwrap();
    command_vector_push(&mut b, odata::LED_COMMAND3, 0x110, &[led3_frame(255, 1, 0)]).unwrap();
    command_vector_push(&mut b, odata::JOINT_COMMAND4, 0x104, &[held_frame(1, 16), held_frame(0, 240)]).unwrap();
    let v = parse_command_vector(&b).unwrap();
    assert_eq!(v.slots.len(), 4);
    assert_eq!(v.slots[0].values.duration_frames(), 16);
    assert_eq!(v.slots[0].values.at(15), Some(FrameCommand::Joint(15000)));
    assert_eq!(v.slots[0].values.at(16), None);
    assert_eq!(v.slots[1].values.duration_frames(), 128);
    assert_eq!(v.slots[1].values.at(63), Some(FrameCommand::Led2(true)));
    assert_eq!(v.slots[1].values.at(64), Some(FrameCommand::Led2(false)));
    // period 0 counts as 1
    assert_eq!(v.slots[2].values.duration_frames(), 1);
    assert_eq!(v.slots[2].values.at(0), Some(FrameCommand::Led3(Led3Value { intensity: 255, mode: 1 })));
    assert_eq!(v.slots[3].values.duration_frames(), 256);
    assert_eq!(v.duration_frames(), 256);
    write_command_frame_number(&mut b, 2, 77).unwrap();
    assert_eq!(u32at(&b, 192 + 64 + 8), 77);
}

#[test]
fn led_8_values_period_64_is_512_frames() {
    let vals = CommandValues::Led2((0..8).map(|k| Held { value: k % 2, period: 64 }).collect());
    assert_eq!(vals.duration_frames(), 512);
    assert_eq!(vals.duration_frames() as u64 * 8, 4096);
    let legacy = CommandValues::LegacyLed(vec![Held { value: 1, period: 4 }]);
    assert_eq!(legacy.duration_frames(), 64);
}

#[test]
fn malformed_command_vectors_are_errors() {
    let mut b = vec![0u8; command_vector_size(2)];
    command_vector_init(&mut b, 2).unwrap();
    command_vector_push(&mut b, odata::JOINT_COMMAND2, 0x101, &[joint2_frame(1)]).unwrap();
    assert!(parse_command_vector(&b[..100]).is_err());
    let mut c = b.clone();
    wr_u32(&mut c, 16, 1025).unwrap();
    assert!(matches!(parse_command_vector(&c), Err(VectorError::WrongType { .. })));
    let mut c = b.clone();
    wr_u32(&mut c, 32, 3).unwrap();
    assert!(matches!(parse_command_vector(&c), Err(VectorError::TooManyData { .. })));
    let mut c = b.clone();
    wr_u32(&mut c, 192 + 12, 17).unwrap();
    assert!(matches!(parse_command_vector(&c), Err(VectorError::TooManyFrames { .. })));
    let mut c = b.clone();
    wr_u32(&mut c, 192 + 20, 0xFFFF_FFF0).unwrap();
    assert!(matches!(parse_command_vector(&c), Err(VectorError::SlotOutOfBounds { .. })));
    let mut c = b.clone();
    wr_u32(&mut c, 44, 100).unwrap();
    wr_u32(&mut c, 48, 29).unwrap();
    assert!(matches!(parse_command_vector(&c), Err(VectorError::BadOptional { .. })));
    // max_num_data huge but buffer short
    let mut c = b.clone();
    wr_u32(&mut c, 28, 0xFFFF_FFFF).unwrap();
    wr_u32(&mut c, 32, 0xFFFF_FFFF).unwrap();
    assert!(parse_command_vector(&c).is_err());
    // unknown type and numFrames 0 do not reject the vector
    let mut c = b.clone();
    wr_u32(&mut c, 192, 257).unwrap();
    let v = parse_command_vector(&c).unwrap();
    assert_eq!(v.slots[0].values, CommandValues::Unsupported(257));
    let mut c = b.clone();
    wr_u32(&mut c, 192 + 12, 0).unwrap();
    assert!(parse_command_vector(&c).unwrap().slots.is_empty());
    // fuzz-ish: every truncation is an error or ok, never a panic
    for len in 0..b.len() {
        let _ = parse_command_vector(&b[..len]);
    }
}

#[test]
fn sensor_vector_layout() {
    assert_eq!(sensor_vector_size(34), 192 + 288 * 34);
    assert_eq!(sensor_data_offset(34, 0), 192 + 32 * 34);
    assert_eq!(sensor_data_offset(34, 33), 192 + 32 * 34 + 256 * 33);
    let jv = JointValue { value: -1, signal: 512, pwm_duty: -20, ref_value: 123456, ref_signal: 600 };
    let sv = SensorValue { value: 9_806_650, signal: 7 };
    let entries = vec![
        SensorEntry { data_type: 18, primitive: 0x100, frames: [FrameValue::Joint(jv); 4] },
        SensorEntry { data_type: 9, primitive: 0x101, frames: [FrameValue::Sensor(sv); 4] },
    ];
    let b = build_sensor_vector(5, &entries, Some((2, &[9, 8, 7]))).unwrap();
    assert_eq!(b.len(), 192 + 288 * 2);
    assert_eq!(u32at(&b, 16), 1025);
    assert_eq!(u32at(&b, 20), 192);
    assert_eq!(u32at(&b, 24), 32);
    assert_eq!(u32at(&b, 28), 2);
    assert_eq!(u32at(&b, 32), 2);
    assert_eq!(u32at(&b, 36), 0xFFFF_FFFF);
    assert_eq!((u32at(&b, 44), u32at(&b, 48)), (2, 3));
    assert_eq!(&b[66..69], &[9, 8, 7]);
    let i1 = 192 + 32;
    assert_eq!(
        [u32at(&b, i1), u32at(&b, i1 + 4), u32at(&b, i1 + 8), u32at(&b, i1 + 12), u32at(&b, i1 + 16), u32at(&b, i1 + 20), u32at(&b, i1 + 24)],
        [9, 0x101, 5, 4, 16, (192 + 64 + 256) as u32, 256]
    );
    let e0 = read_sensor_entry(&b, 0).unwrap();
    assert_eq!(e0.frames.len(), 4);
    assert_eq!(JointValue::from_bytes(&e0.frames[3]), jv);
    // OJointValue byte offsets: value 0, signal 4, pwmDuty 6, refValue 8, refSignal 12
    let d0 = 192 + 64;
    assert_eq!(&b[d0 + 4..d0 + 6], &512u16.to_le_bytes());
    assert_eq!(&b[d0 + 6..d0 + 8], &(-20i16).to_le_bytes());
    assert_eq!(&b[d0 + 8..d0 + 12], &123456i32.to_le_bytes());
    assert_eq!(SensorValue::from_bytes(&read_sensor_entry(&b, 1).unwrap().frames[0]), sv);
    assert!(read_sensor_entry(&b, 2).is_err());
    let mut fresh = vec![1u8; sensor_vector_size(34)];
    sensor_vector_init(&mut fresh, 34).unwrap();
    assert_eq!(u32at(&fresh, 32), 0);
    assert_eq!(u32at(&fresh, 192 + 4), 0xFFFF_FFFF);
    assert_eq!(u32at(&fresh, 192 + 16), 16);
}

#[test]
fn sound_vector_init_exact() {
    // 2 slots of 1000 bytes: slot 1024
    let size = sound_vector_size(2, 1000);
    assert_eq!(size, 192 + (1024 + 64) * 2);
    let mut b = vec![0xFFu8; region_size(size)];
    sound_vector_init(&mut b, 2, 1000, "ERS-7").unwrap();
    assert_eq!(u32at(&b, 16), 1026);
    assert_eq!(u32at(&b, 24), 64);
    assert_eq!(u32at(&b, 28), 2);
    assert_eq!(u32at(&b, 32), 0);
    let o = 192 + 64;
    assert_eq!(u32at(&b, o), 16);
    assert_eq!(u32at(&b, o + 4), 0xFFFF_FFFF);
    assert_eq!(u32at(&b, o + 12), 1024);
    assert_eq!(u32at(&b, o + 16), 192 + 128 + 1024);
    assert_eq!(u32at(&b, o + 20), 1000);
    assert_eq!(u32at(&b, o + 24), 1000);
    assert_eq!(rd_u16(&b, o + 28).unwrap(), 1);
    assert_eq!(rd_u16(&b, o + 30).unwrap(), 1);
    assert_eq!(rd_u16(&b, o + 32).unwrap(), 16000);
    assert_eq!(rd_u16(&b, o + 34).unwrap(), 16);
    assert_eq!(u32at(&b, o + 36), 0);
    sound_vector_init(&mut b, 2, 1000, "ERS-210").unwrap();
    assert_eq!(rd_u16(&b, o + 32).unwrap(), 8000);
    wr_u32(&mut b, 32, 1).unwrap();
    let v = parse_sound_vector(&b).unwrap();
    assert_eq!(v.slots.len(), 1);
    assert_eq!(v.slots[0].data_offset, 320);
    write_sound_frame_number(&mut b, 0, 9).unwrap();
    assert_eq!(u32at(&b, 192 + 8), 9);
    let mic = build_mic_vector(0x123, 42, &[1u8; 1024]).unwrap();
    let m = parse_sound_vector(&mic).unwrap();
    assert_eq!((m.slots[0].channel, m.slots[0].sampling_rate, m.slots[0].data_size), (2, 16000, 1024));
    assert_eq!(u32at(&mic, 192 + 8), 42);
    assert_eq!(u32at(&mic, 192 + 36), 1024);
}
