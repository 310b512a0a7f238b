//! The reference client decodes what the runtime encodes: `tools/robot_peer.py`'s
//! `parse_welcome` and `parse_frame` read this crate's WELCOME and FRAME payloads of every
//! design, and what they find is what the robot model says (the table of constants is
//! checked by the crate's unit test; this checks the layouts the Python side hand-codes).
use std::path::Path;
use std::process::Command;

use openr_peer_protocol::encode::{frame_payload, welcome_payload};
use openr_peer_protocol::wire::{FRAME_READINGS_EXPECTED, REVISION, ROLE_CAMERA, ROLE_JOINTS, VERSION};
use openr_peer_protocol::{class_of, role_of};
use openr_robot::model::Design;
use openr_robot::scene::value_range;
use openr_robot::VirtualRobot;
use serde_json::Value;

const DECODE: &str = r#"
import json, sys
sys.path.insert(0, sys.argv[1])
import robot_peer as rp
kind, frame, data = sys.argv[2], int(sys.argv[3]), bytes.fromhex(sys.stdin.read())
print(json.dumps(rp.parse_welcome(data) if kind == "welcome" else rp.parse_frame(frame, data)))
"#;

/// What robot_peer.py makes of `payload` (a WELCOME or a FRAME of frame `frame`).
fn python_decodes(kind: &str, frame: u32, payload: &[u8]) -> Value {
    use std::io::Write;
    let tools = Path::new(env!("CARGO_MANIFEST_DIR")).join("../tools");
    let mut child = Command::new("python3")
        .args(["-c", DECODE])
        .arg(&tools)
        .args([kind, &frame.to_string()])
        .stdin(std::process::Stdio::piped())
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .expect("run python3 (tools/deps.sh installs it)");
    let hex: String = payload.iter().map(|b| format!("{b:02x}")).collect();
    child.stdin.take().unwrap().write_all(hex.as_bytes()).unwrap();
    let out = child.wait_with_output().unwrap();
    assert!(out.status.success(), "robot_peer.py could not decode the {kind}: {}", String::from_utf8_lossy(&out.stderr));
    serde_json::from_slice(&out.stdout).expect("robot_peer.py printed JSON")
}

const CLASS_NAMES: [&str; 11] = ["joint", "ear", "led2", "led3", "accel", "switch", "psd", "camera", "mic", "speaker", "other"];

#[test]
fn robot_peer_py_reads_every_designs_welcome_as_the_model_says() {
    for design in Design::ALL {
        let robot = VirtualRobot::new(design);
        let w = python_decodes("welcome", 0, &welcome_payload(&robot, ROLE_JOINTS | ROLE_CAMERA, true, (16000, 2, 16)));
        let name = design.name();
        assert_eq!((w["version"].as_u64(), w["revision"].as_u64()), (Some(VERSION.into()), Some(REVISION.into())), "{name}");
        assert_eq!(w["roles"], serde_json::json!(["joints", "camera"]), "{name}");
        assert_eq!(w["clock"], true, "{name}");
        assert_eq!(w["design"], name);
        assert_eq!(w["frame_period_us"].as_u64(), Some(8000), "{name}");
        let (frame, time_ms) = (robot.clock().frame(), robot.clock().time_ms());
        assert_eq!((w["last_frame"].as_u64(), w["time_ms"].as_u64()), (Some(frame as u64), Some(time_ms)), "{name}");
        assert_eq!(w["mic_period_frames"].as_u64(), Some(design.mic_period_frames() as u64), "{name}");
        assert_eq!(w["mic_block_bytes"].as_u64(), Some(design.mic_block_bytes() as u64), "{name}");
        let (cw, ch) = (robot.camera().rgb.width, robot.camera().rgb.height);
        assert_eq!((w["camera_width"].as_u64(), w["camera_height"].as_u64()), (Some(cw as u64), Some(ch as u64)), "{name}");
        assert_eq!(w["camera_fps"].as_u64(), Some(design.camera_fps() as u64), "{name}");
        assert_eq!((w["mic_rate"].as_u64(), w["mic_channels"].as_u64(), w["mic_bits"].as_u64()), (Some(16000), Some(2), Some(16)), "{name}");
        let model = robot.model();
        let prims = w["primitives"].as_array().expect("a primitive table");
        assert_eq!(prims.len(), model.primitives().len(), "{name}");
        let mut ranges = 0;
        for (p, py) in model.primitives().iter().zip(prims) {
            let at = format!("{name} {}", p.locator);
            assert_eq!(py["id"].as_u64(), Some(p.id as u64), "{at}");
            assert_eq!(py["locator"], p.locator, "{at}");
            assert_eq!(py["class"], CLASS_NAMES[class_of(p.kind) as usize - 1], "{at}");
            assert_eq!(py["sensor_index"].as_i64(), Some(p.sensor_index.map_or(-1, |i| i as i64)), "{at}");
            if let Some(j) = p.joint {
                assert_eq!((py["min_urad"].as_i64(), py["max_urad"].as_i64()), (Some(j.min as i64), Some(j.max as i64)), "{at}");
            }
            if role_of(p.kind) == Some(ROLE_JOINTS) {
                let g = p.joint.expect("a joint has a gain").default_gain;
                assert_eq!(py["standard_gain"], serde_json::json!([g.p, g.i, g.d]), "{at}");
            }
            if let Some((lo, hi)) = value_range(p.part).filter(|&r| r != (0, 0)) {
                ranges += 1;
                assert_eq!((py["value_min"].as_i64(), py["value_max"].as_i64()), (Some(lo as i64), Some(hi as i64)), "{at}");
            }
        }
        assert!(ranges > 0, "{name}: no sensor value range was sent");
    }
}

#[test]
fn robot_peer_py_reads_a_frame_as_the_robot_left_it() {
    for design in Design::ALL {
        let name = design.name();
        let mut robot = VirtualRobot::new(design);
        for _ in 0..3 {
            robot.step_frame();
        }
        let pending = robot.begin_frame();
        let mut payload = frame_payload(&robot, &pending);
        payload[8] |= FRAME_READINGS_EXPECTED;
        let f = python_decodes("frame", pending.frame(), &payload);
        assert_eq!(f["frame"].as_u64(), Some(pending.frame() as u64), "{name}");
        assert_eq!(f["time_ms"].as_u64(), Some(pending.time_ms()), "{name}");
        assert_eq!(f["sensor_due"], pending.sensor_due(), "{name}");
        assert_eq!(f["camera_due"], pending.camera_due(), "{name}");
        assert_eq!(f["readings_expected"], true, "{name}");
        let body = robot.body();
        let joints: Vec<_> = robot.model().joints().filter_map(|p| body.joint(p.id).map(|j| (p.id, j))).collect();
        let py = f["joints"].as_array().expect("a joint list");
        assert_eq!(py.len(), joints.len(), "{name}");
        assert!(!joints.is_empty(), "{name}");
        for ((id, j), py) in joints.iter().zip(py) {
            assert_eq!(py["id"].as_u64(), Some(*id as u64), "{name}");
            assert_eq!(py["target"].as_i64(), Some(j.reference as i64), "{name} {id:#x}");
            assert_eq!(py["measured"].as_i64(), Some(j.angle.round() as i64), "{name} {id:#x}");
            let g = j.gain.loaded;
            assert_eq!(py["gain"], serde_json::json!([g.p, g.i, g.d]), "{name} {id:#x}");
            assert_eq!(py["enabled"], j.gain.enabled, "{name} {id:#x}");
        }
        let leds = robot.model().primitives().iter().filter(|p| body.led(p.id).is_some()).count();
        assert_eq!(f["leds"].as_array().map(|l| l.len()), Some(leds), "{name}");
        let ears = robot.model().primitives().iter().filter(|p| body.ear(p.id).is_some()).count();
        assert_eq!(f["ears"].as_array().map(|e| e.len()), Some(ears), "{name}");
        robot.end_frame(pending);
    }
}
