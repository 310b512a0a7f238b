//! The external robot protocol (docs/robot-protocol.md): peers attached on
//! `--robot-socket` drive the clock in lockstep, supply joint readings, may come and go
//! without the runtime losing a frame, and bad input gets an ERROR and a closed
//! connection while the robot keeps running. Unix sockets in temp dirs only.
use std::collections::HashMap;
use std::io::{Read, Write};
use std::os::unix::net::UnixStream;
use std::path::Path;
use std::process::Command;
use std::time::Duration;

use serde_json::Value;

use crate::support::{build, connect_unix, read_trace, repo, spawn_ms, wait_for_path, RunOutput};

const HELLO: u16 = 1;
const WELCOME: u16 = 2;
const FRAME: u16 = 3;
const READINGS: u16 = 4;
const IMAGE: u16 = 5;
const MIC: u16 = 6;
const ERROR: u16 = 10;
const ROLE_JOINTS: u32 = 1;
const ROLE_CAMERA: u32 = 16;
const ROLE_MIC: u32 = 32;
const FLAG_CLOCK: u32 = 1;
const LF_J1: &str = "PRM:/r2/c1-Joint2:21";

fn message(kind: u16, version: u16, length: u32, frame: u32, payload: &[u8]) -> Vec<u8> {
    let mut m = b"ORP1".to_vec();
    m.extend_from_slice(&version.to_le_bytes());
    m.extend_from_slice(&kind.to_le_bytes());
    m.extend_from_slice(&length.to_le_bytes());
    m.extend_from_slice(&frame.to_le_bytes());
    m.extend_from_slice(payload);
    m
}

fn send(s: &mut UnixStream, kind: u16, frame: u32, payload: &[u8]) {
    s.write_all(&message(kind, 1, payload.len() as u32, frame, payload)).unwrap();
}

/// The next message, or None at the end of the stream.
fn recv(s: &mut UnixStream) -> Option<(u16, u32, Vec<u8>)> {
    let mut h = [0u8; 16];
    if s.read_exact(&mut h).is_err() {
        return None;
    }
    assert_eq!(&h[..4], b"ORP1");
    assert_eq!(u16::from_le_bytes([h[4], h[5]]), 1);
    let kind = u16::from_le_bytes([h[6], h[7]]);
    let len = u32::from_le_bytes([h[8], h[9], h[10], h[11]]) as usize;
    let frame = u32::from_le_bytes([h[12], h[13], h[14], h[15]]);
    let mut p = vec![0u8; len];
    s.read_exact(&mut p).unwrap();
    Some((kind, frame, p))
}

fn hello(roles: u32, flags: u32) -> Vec<u8> {
    let mut p = Vec::new();
    p.extend_from_slice(&roles.to_le_bytes());
    p.extend_from_slice(&flags.to_le_bytes());
    p.extend_from_slice(&4u16.to_le_bytes());
    p.extend_from_slice(b"test");
    p
}

fn u16_at(p: &[u8], i: usize) -> u16 {
    u16::from_le_bytes([p[i], p[i + 1]])
}
fn u32_at(p: &[u8], i: usize) -> u32 {
    u32::from_le_bytes([p[i], p[i + 1], p[i + 2], p[i + 3]])
}

/// The WELCOME's primitive table: locator → ID.
fn welcome_ids(p: &[u8]) -> HashMap<String, u32> {
    let mut i = 2 + 2 + 4 + 4 + 4 + 4 + 8 + 6 + 2 + 2 + 4 + 2 + 2;
    let n = u16_at(p, i) as usize;
    i += 2 + n;
    let count = u16_at(p, i);
    i += 2;
    let mut ids = HashMap::new();
    for _ in 0..count {
        let id = u32_at(p, i);
        i += 4 + 2 + 2 + 4 + 4;
        let n = u16_at(p, i) as usize;
        ids.insert(String::from_utf8(p[i + 2..i + 2 + n].to_vec()).unwrap(), id);
        i += 2 + n;
    }
    ids
}

/// A FRAME's joints: (ID, target µrad) and its flags.
fn frame_joints(p: &[u8]) -> (u8, Vec<(u32, i32)>) {
    let n = u16_at(p, 12) as usize;
    (p[8], (0..n).map(|k| (u32_at(p, 14 + 20 * k), u32_at(p, 18 + 20 * k) as i32)).collect())
}

fn readings(joints: &[(u32, i32)]) -> Vec<u8> {
    let mut p = (joints.len() as u16).to_le_bytes().to_vec();
    for (id, v) in joints {
        p.extend_from_slice(&id.to_le_bytes());
        p.extend_from_slice(&v.to_le_bytes());
    }
    p.extend_from_slice(&0u16.to_le_bytes());
    p
}

fn deg(urad: i64) -> f64 {
    urad as f64 / 1e6 * 180.0 / std::f64::consts::PI
}

fn sensors(trace: &[Value]) -> Vec<&Value> {
    trace.iter().filter(|r| r["kind"] == "sensor").collect()
}

fn first_frame(r: &Value) -> u64 {
    r["first_frame"].as_u64().unwrap()
}

/// The sensor records cover every frame: first_frame 1, 5, 9, … without a gap.
fn assert_no_gaps(trace: &[Value], frames: u64) {
    let firsts: Vec<u64> = sensors(trace).iter().map(|r| first_frame(r)).collect();
    let expected: Vec<u64> = (0..frames / 4).map(|k| 1 + 4 * k).collect();
    assert_eq!(firsts, expected, "sensor vectors must cover frames 1..{frames} without a gap");
}

/// A lockstep run of movelegs with tools/robot_peer.py attached from the start:
/// (stdout, trace text, the peer's WELCOME line, its recorded FRAMEs).
fn python_lockstep_run(dir: &Path, tag: &str, secs: u32) -> (RunOutput, String, Value, Vec<Value>) {
    let b = build("movelegs");
    let sock = dir.join(format!("{tag}.sock"));
    let trace = dir.join(format!("{tag}.jsonl"));
    let record = dir.join(format!("{tag}-frames.jsonl"));
    let for_arg = format!("{secs}s");
    let run = spawn_ms(
        &b.ms(),
        &["--speed", "max", "--for", &for_arg, "--trace", trace.to_str().unwrap(), "--robot-socket", sock.to_str().unwrap(), "--robot-wait"],
        &[],
    );
    assert!(wait_for_path(&sock, Duration::from_secs(60)), "no robot socket");
    let peer =
        Command::new("python3").arg(repo().join("tools/robot_peer.py")).arg(&sock).args(["--record", record.to_str().unwrap()]).output().expect("python3");
    let out = run.wait(Duration::from_secs(120));
    assert_eq!(out.code, Some(0), "{}\n{}", out.stdout, out.stderr);
    assert!(peer.status.success(), "peer failed: {}", String::from_utf8_lossy(&peer.stderr));
    let welcome: Value = serde_json::from_str(String::from_utf8_lossy(&peer.stdout).lines().next().unwrap()).unwrap();
    let frames = read_trace(&record);
    (out, std::fs::read_to_string(&trace).unwrap(), welcome, frames)
}

#[test]
fn lockstep_python_peer_drives_the_clock_and_supplies_the_joint_angles() {
    let dir = tempfile::tempdir().unwrap();
    let (out, trace_text, welcome, frames) = python_lockstep_run(dir.path(), "a", 3);
    assert_eq!(welcome["design"], "ERS-7");
    assert_eq!(welcome["clock"], true);
    assert_eq!(welcome["camera_width"], 416);
    assert_eq!(welcome["primitives"].as_array().unwrap().iter().filter(|p| p["class"] == "joint").count(), 18);
    // 3 s of virtual time = 375 frames, each sent exactly once, in order
    let numbers: Vec<u64> = frames.iter().map(|f| f["frame"].as_u64().unwrap()).collect();
    assert_eq!(numbers, (1..=375).collect::<Vec<u64>>());
    assert!(frames.iter().all(|f| f["readings_expected"] == true));
    assert!(out.stderr.contains("375 frames"), "{}", out.stderr);
    assert_eq!(welcome["revision"], 2);
    // revision 2: the sensor value ranges and standard gains, so a simulator copies none
    let prim = |loc: &str| welcome["primitives"].as_array().unwrap().iter().find(|p| p["locator"] == loc).unwrap().clone();
    let accel = prim("PRM:/a1-Sensor:a1");
    assert_eq!((accel["value_min"].as_i64(), accel["value_max"].as_i64()), (Some(-19_613_300), Some(19_613_300)), "{accel}");
    let far = prim("PRM:/r1/c1/c2/c3/p2-Sensor:p2");
    assert_eq!((far["value_min"].as_i64(), far["value_max"].as_i64()), (Some(200_000), Some(1_500_000)), "{far}");
    assert_eq!(prim("PRM:/r2/c1-Joint2:21")["standard_gain"], serde_json::json!([0x1C, 0x08, 0x01]));
    assert!(prim("PRM:/b1-Sensor:b1").get("value_min").is_none() && prim("PRM:/b1-Sensor:b1").get("standard_gain").is_none());
    // 30 pictures a second, each announced by the frame before it (flag bit 4)
    let due: Vec<u64> = frames.iter().filter(|f| f["camera_due"] == true).map(|f| f["frame"].as_u64().unwrap()).collect();
    let announced: Vec<u64> = frames.iter().filter(|f| f["camera_next"] == true).map(|f| f["frame"].as_u64().unwrap() + 1).collect();
    assert_eq!(due.len(), 90, "{due:?}");
    assert_eq!(announced[..90], due[..], "camera_next must come one frame before camera_due");
    let locator: HashMap<u64, String> =
        welcome["primitives"].as_array().unwrap().iter().map(|p| (p["id"].as_u64().unwrap(), p["locator"].as_str().unwrap().to_string())).collect();
    // the trace's joint readings are the targets the peer echoed back (newest frame of each vector)
    let trace: Vec<Value> = trace_text.lines().map(|l| serde_json::from_str(l).unwrap()).collect();
    assert_no_gaps(&trace, 375);
    for s in sensors(&trace) {
        let newest = &frames[(first_frame(s) + 3 - 1) as usize];
        for j in newest["joints"].as_array().unwrap() {
            let loc = &locator[&j["id"].as_u64().unwrap()];
            let want = deg(j["target"].as_i64().unwrap());
            let got = s["joints"][loc.as_str()].as_f64().unwrap();
            assert!((got - want).abs() < 0.002, "frame {}: {loc} reads {got}, the peer reported {want}", first_frame(s) + 3);
        }
    }
    // ... and so are the angles the program prints (whole degrees, truncated)
    let lines = out.lines_starting("Sensors : frame");
    assert!(lines.len() >= 10, "{}", out.stdout);
    let lf: Vec<u64> = ["PRM:/r2/c1-Joint2:21", "PRM:/r2/c1/c2-Joint2:22", "PRM:/r2/c1/c2/c3-Joint2:23"]
        .iter()
        .map(|l| *locator.iter().find(|(_, v)| v == l).unwrap().0)
        .collect();
    for l in lines {
        let w: Vec<&str> = l.split_whitespace().collect();
        let n: usize = w[3].parse().unwrap();
        let f = &frames[n - 1];
        for (k, id) in [6, 8, 10].into_iter().zip(&lf) {
            let j = f["joints"].as_array().unwrap().iter().find(|j| j["id"].as_u64() == Some(*id)).unwrap();
            let printed: i64 = w[k].parse().unwrap();
            assert_eq!(printed, deg(j["target"].as_i64().unwrap()).trunc() as i64, "{l}");
        }
    }
}

#[test]
fn lockstep_runs_with_the_same_peer_are_byte_identical() {
    let dir = tempfile::tempdir().unwrap();
    let (out1, trace1, _, frames1) = python_lockstep_run(dir.path(), "r1", 2);
    let (out2, trace2, _, frames2) = python_lockstep_run(dir.path(), "r2", 2);
    assert_eq!(frames1.len(), 250);
    assert!(trace1 == trace2, "same trace, byte for byte");
    assert_eq!(out1.stdout, out2.stdout);
    assert_eq!(frames1, frames2, "same FRAMEs sent");
}

#[test]
fn a_peer_attaching_mid_run_and_leaving_loses_no_frame() {
    let b = build("movelegs");
    let dir = tempfile::tempdir().unwrap();
    let sock = dir.path().join("robot.sock");
    let trace = dir.path().join("trace.jsonl");
    let run = spawn_ms(&b.ms(), &["--speed", "4", "--for", "6s", "--trace", trace.to_str().unwrap(), "--robot-socket", sock.to_str().unwrap()], &[]);
    let mut s = connect_unix(&sock, Duration::from_secs(60));
    std::thread::sleep(Duration::from_millis(300)); // let the robot run first
    s.set_read_timeout(Some(Duration::from_secs(30))).unwrap();
    send(&mut s, HELLO, 0, &hello(ROLE_JOINTS, FLAG_CLOCK));
    let (kind, _, w) = recv(&mut s).unwrap();
    assert_eq!(kind, WELCOME);
    assert_eq!(u32_at(&w, 4), ROLE_JOINTS, "joints granted");
    assert_eq!(u32_at(&w, 8), FLAG_CLOCK, "clock granted");
    let j1 = welcome_ids(&w)[LF_J1];
    // hold the left front J1 at 0 rad for 100 frames whatever the program commands
    let mut got = Vec::new();
    while got.len() < 100 {
        let (kind, n, p) = recv(&mut s).expect("FRAME");
        assert_eq!(kind, FRAME);
        assert!(frame_joints(&p).0 & 8 != 0, "READINGS expected from the clock owner");
        got.push(n as u64);
        send(&mut s, READINGS, n, &readings(&[(j1, 0)]));
    }
    drop(s); // gone without BYE
    let out = run.wait(Duration::from_secs(120));
    assert_eq!(out.code, Some(0), "{}\n{}", out.stdout, out.stderr);
    let (first, last) = (got[0], got[99]);
    assert!(first > 1, "attached mid-run (frame {first})");
    assert_eq!(got, (first..=last).collect::<Vec<u64>>(), "consecutive FRAMEs");
    let trace = read_trace(&trace);
    assert_no_gaps(&trace, 750);
    let j1_at = |r: &Value| r["joints"][LF_J1].as_f64().unwrap();
    let recs = sensors(&trace);
    let held: Vec<_> = recs.iter().filter(|r| (first..=last).contains(&(first_frame(r) + 3))).collect();
    assert!(held.len() >= 20);
    assert!(held.iter().all(|r| j1_at(r) == 0.0), "the peer's reading replaces the model's");
    assert!(recs.iter().any(|r| first_frame(r) + 3 < first && j1_at(r) != 0.0), "built-in before");
    // after it left, the built-in servo continues from where the peer left the joint
    let after: Vec<_> = recs.iter().filter(|r| first_frame(r) + 3 > last).collect();
    assert!(j1_at(after[0]).abs() < 25.0, "continues from 0: {}", j1_at(after[0]));
    assert!(after.iter().any(|r| j1_at(r).abs() > 5.0), "and follows the commands again");
}

/// Connects, optionally says HELLO, sends `bytes`, expects an ERROR with `code` and EOF;
/// returns the ERROR's message.
fn expect_error(sock: &Path, greet: Option<(u32, u32)>, bytes: &[u8], code: u16) -> String {
    let mut s = connect_unix(sock, Duration::from_secs(60));
    s.set_read_timeout(Some(Duration::from_secs(30))).unwrap();
    if let Some((roles, flags)) = greet {
        send(&mut s, HELLO, 0, &hello(roles, flags));
        assert_eq!(recv(&mut s).unwrap().0, WELCOME);
    }
    refused(&mut s, bytes, code)
}

/// Sends `bytes` on an attached connection, expects an ERROR with `code` (only FRAMEs
/// before it) and then EOF; returns the ERROR's message.
fn refused(s: &mut UnixStream, bytes: &[u8], code: u16) -> String {
    s.write_all(bytes).unwrap();
    let text = loop {
        let (kind, _, p) = recv(s).unwrap_or_else(|| panic!("no ERROR {code}"));
        if kind == ERROR {
            let n = u16_at(&p, 2) as usize;
            let text = String::from_utf8(p[4..4 + n].to_vec()).unwrap();
            assert_eq!(u16_at(&p, 0), code, "{text}");
            assert_eq!(p.len(), 4 + n, "ERROR payload: code u16, message str");
            break text;
        }
        assert_eq!(kind, FRAME, "only FRAMEs before the ERROR");
    };
    // then the connection is closed: only FRAMEs already in flight can't follow an ERROR
    let mut rest = Vec::new();
    let _ = s.read_to_end(&mut rest);
    assert!(rest.is_empty(), "nothing after the ERROR ({} bytes)", rest.len());
    text
}

/// Attaches with HELLO claiming `roles` (and the clock when `flags` asks) and returns the
/// connection and its WELCOME once all of it is granted. A peer refused just before may
/// still hold a role for a moment (its detach follows its closed socket): retried.
fn attach(sock: &Path, roles: u32, flags: u32) -> (UnixStream, Vec<u8>) {
    for _ in 0..200 {
        let mut s = connect_unix(sock, Duration::from_secs(60));
        s.set_read_timeout(Some(Duration::from_secs(30))).unwrap();
        send(&mut s, HELLO, 0, &hello(roles, flags));
        let (kind, _, w) = recv(&mut s).expect("WELCOME");
        assert_eq!(kind, WELCOME);
        if u32_at(&w, 4) == roles && u32_at(&w, 8) == flags & FLAG_CLOCK {
            return (s, w);
        }
        drop(s);
        std::thread::sleep(Duration::from_millis(25));
    }
    panic!("roles {roles:#x} / flags {flags:#x} never granted");
}

#[test]
fn bad_input_gets_an_error_and_a_closed_connection_and_the_robot_runs_on() {
    let b = build("movelegs");
    let dir = tempfile::tempdir().unwrap();
    let sock = dir.path().join("robot.sock");
    let run = spawn_ms(&b.ms(), &["--speed", "1", "--for", "4s", "--robot-socket", sock.to_str().unwrap()], &[]);
    // malformed header (no magic) before HELLO
    expect_error(&sock, None, b"GARBAGE-GARBAGE!", 1);
    // wrong version, after HELLO
    expect_error(&sock, Some((0, 0)), &message(READINGS, 7, 0, 0, &[]), 2);
    // oversized length
    expect_error(&sock, Some((0, 0)), &message(READINGS, 1, u32::MAX, 0, &[]), 3);
    // anything but HELLO first
    expect_error(&sock, None, &message(READINGS, 1, 4, 0, &[0, 0, 0, 0]), 7);
    // a truncated HELLO
    expect_error(&sock, None, &message(HELLO, 1, 2, 0, &[1, 0]), 5);
    // an unknown message type
    expect_error(&sock, Some((0, 0)), &message(99, 1, 0, 0, &[]), 4);
    // READINGS for the wrong frame from the clock owner
    {
        let mut s = connect_unix(&sock, Duration::from_secs(60));
        s.set_read_timeout(Some(Duration::from_secs(30))).unwrap();
        send(&mut s, HELLO, 0, &hello(ROLE_JOINTS, FLAG_CLOCK));
        assert_eq!(recv(&mut s).unwrap().0, WELCOME);
        let (kind, n, _) = recv(&mut s).unwrap();
        assert_eq!(kind, FRAME);
        send(&mut s, READINGS, n + 5, &readings(&[]));
        let (kind, _, p) = recv(&mut s).unwrap();
        assert_eq!((kind, u16_at(&p, 0)), (ERROR, 6), "{}", String::from_utf8_lossy(&p));
        assert!(recv(&mut s).is_none(), "closed after the ERROR");
    }
    let out = run.wait(Duration::from_secs(60));
    assert_eq!(out.code, Some(0), "{}\n{}", out.stdout, out.stderr);
    assert!(out.stderr.contains("500 frames"), "every frame ran: {}", out.stderr);
    assert!(out.stdout.contains("MovingLegs : "), "{}", out.stdout);
}

/// Asks the control socket (`--control`) one command; returns its answer line.
fn control(conn: &mut UnixStream, cmd: &str) -> String {
    use std::io::BufRead;
    writeln!(conn, "{cmd}").unwrap();
    let mut line = String::new();
    std::io::BufReader::new(conn.try_clone().unwrap()).read_line(&mut line).unwrap();
    line.trim().to_string()
}

fn image(w: u16, h: u16, rgb: usize) -> Vec<u8> {
    let mut p = w.to_le_bytes().to_vec();
    p.extend_from_slice(&h.to_le_bytes());
    p.resize(4 + rgb, 0x80);
    p
}

/// READINGS with `joints` in the joint section and `sensors` in the sensor section.
fn readings2(joints: &[(u32, i32)], sensors: &[(u32, i32)]) -> Vec<u8> {
    let mut p = readings(joints);
    p.truncate(p.len() - 2);
    p.extend_from_slice(&(sensors.len() as u16).to_le_bytes());
    for (id, v) in sensors {
        p.extend_from_slice(&id.to_le_bytes());
        p.extend_from_slice(&v.to_le_bytes());
    }
    p
}

fn msg(kind: u16, frame: u32, payload: &[u8]) -> Vec<u8> {
    message(kind, 1, payload.len() as u32, frame, payload)
}

#[test]
fn role_payload_order_and_overflow_errors_name_the_problem() {
    let b = build("movelegs");
    let dir = tempfile::tempdir().unwrap();
    let sock = dir.path().join("robot.sock");
    let ctl = dir.path().join("control.sock");
    let run = spawn_ms(&b.ms(), &["--speed", "1", "--robot-socket", sock.to_str().unwrap(), "--control", ctl.to_str().unwrap()], &[]);
    // the primitive table, from a peer claiming nothing
    let ids = {
        let (_s, w) = attach(&sock, 0, 0);
        welcome_ids(&w)
    };
    let (j1, accel, led) = (ids[LF_J1], ids["PRM:/a1-Sensor:a1"], ids["PRM:/r1/c1/c2/c3/ln-LED3:ln"]);
    let unknown = 0xDEAD_BEEF;
    assert!(!ids.values().any(|&v| v == unknown));
    let mut said: Vec<(u16, String)> = Vec::new();
    let mut check = |code: u16, got: String, want: &str| {
        assert_eq!(got, want, "ERROR {code}");
        said.push((code, got));
    };

    // 8: role not held
    let t = expect_error(&sock, Some((0, 0)), &msg(IMAGE, 0, &image(416, 320, 416 * 320 * 3)), 8);
    check(8, t, "IMAGE without the camera role");
    let t = expect_error(&sock, Some((0, 0)), &msg(MIC, 0, &[0; 1024]), 8);
    check(8, t, "MIC without the mic role");
    let t = expect_error(&sock, Some((0, 0)), &msg(READINGS, 0, &readings2(&[], &[(accel, 9_800_000)])), 8);
    check(8, t, "READINGS: PRM:/a1-Sensor:a1 needs the accel role, which this peer does not hold");
    let t = expect_error(&sock, Some((0, 0)), &msg(READINGS, 0, &readings(&[(j1, 0)])), 8);
    check(8, t, &format!("READINGS: {LF_J1} needs the joints role, which this peer does not hold"));

    // 5: malformed payloads
    let want_image = format!("IMAGE must be u16 width 416, u16 height 320, then {} RGB bytes", 416 * 320 * 3);
    let (mut s, _) = attach(&sock, ROLE_CAMERA, 0);
    let t = refused(&mut s, &msg(IMAGE, 0, &image(208, 160, 208 * 160 * 3)), 5);
    check(5, t, &want_image);
    let (mut s, _) = attach(&sock, ROLE_CAMERA, 0);
    let t = refused(&mut s, &msg(IMAGE, 0, &image(416, 320, 416 * 320 * 3 - 1)), 5);
    check(5, t, &want_image);
    let (mut s, _) = attach(&sock, ROLE_MIC, 0);
    let t = refused(&mut s, &msg(MIC, 0, &[0; 1022]), 5);
    check(5, t, "MIC: 16-bit stereo PCM (a multiple of 4 bytes)");
    let (mut s, _) = attach(&sock, ROLE_JOINTS, 0);
    let t = refused(&mut s, &msg(READINGS, 0, &readings(&[(unknown, 0)])), 5);
    check(5, t, "READINGS: unknown primitive ID 0xdeadbeef");
    let (mut s, _) = attach(&sock, ROLE_JOINTS, 0);
    let t = refused(&mut s, &msg(READINGS, 0, &readings2(&[], &[(j1, 0)])), 5);
    check(5, t, &format!("READINGS: {LF_J1} ({j1:#x}) listed in the wrong section"));
    let t = expect_error(&sock, Some((0, 0)), &msg(READINGS, 0, &readings2(&[], &[(led, 1)])), 5);
    check(5, t, &format!("READINGS: PRM:/r1/c1/c2/c3/ln-LED3:ln ({led:#x}) has no readings"));

    // 9: at most 1 MiB of microphone sound queued (exactly 1 MiB is accepted)
    let (mut s, _) = attach(&sock, ROLE_MIC, 0);
    s.write_all(&msg(MIC, 0, &vec![0; 1 << 20])).unwrap();
    let t = refused(&mut s, &msg(MIC, 0, &vec![0; 64 << 10]), 9);
    check(9, t, "MIC: more than 1048576 bytes queued");

    // 7: a second HELLO
    let t = expect_error(&sock, Some((0, 0)), &msg(HELLO, 0, &hello(0, 0)), 7);
    check(7, t, "HELLO twice");

    // 6: READINGS from the clock owner while no frame awaits them (the robot paused)
    let mut c = connect_unix(&ctl, Duration::from_secs(60));
    c.set_read_timeout(Some(Duration::from_secs(30))).unwrap();
    assert!(control(&mut c, "pause").starts_with("ok t_ms="));
    let (mut s, w) = attach(&sock, ROLE_JOINTS, FLAG_CLOCK);
    let last = u32_at(&w, 16);
    assert!(last > 0, "frames ran before the pause");
    let t = refused(&mut s, &msg(READINGS, last, &readings(&[])), 6);
    check(6, t, &format!("READINGS for frame {last} while no frame awaits readings (last FRAME sent: {last})"));
    let before = control(&mut c, "status");
    assert!(control(&mut c, "resume").starts_with("ok"));

    // the robot ran on: the clock advances after the resume, and every refusal was logged
    let t_ms = |a: &str| a.split_whitespace().find_map(|w| w.strip_prefix("t_ms=")).and_then(|v| v.parse::<u64>().ok()).unwrap_or_else(|| panic!("{a}"));
    let started = std::time::Instant::now();
    while t_ms(&control(&mut c, "status")) <= t_ms(&before) {
        assert!(started.elapsed() < Duration::from_secs(30), "the robot did not run on after the errors");
        std::thread::sleep(Duration::from_millis(20));
    }
    let out = run.stop();
    assert_eq!(out.code, Some(0), "{}\n{}", out.stdout, out.stderr);
    assert!(!out.stderr.contains("panicked"), "{}", out.stderr);
    for (code, text) in said {
        let line = format!("robot peer `test`: {text} (error {code}; connection closed)");
        assert!(out.stderr.contains(&line), "stderr lacks {line:?}:\n{}", out.stderr);
    }
}

#[test]
fn a_peer_that_stops_reading_is_dropped_and_the_run_reaches_its_end() {
    let b = build("movelegs");
    let dir = tempfile::tempdir().unwrap();
    let sock = dir.path().join("robot.sock");
    let run = spawn_ms(&b.ms(), &["--speed", "max", "--for", "600s", "--robot-socket", sock.to_str().unwrap()], &[]);
    // HELLO, WELCOME, then this peer never reads again: its FRAMEs pile up
    let (silent, _) = attach(&sock, 0, 0);
    let out = run.wait(Duration::from_secs(120));
    drop(silent);
    assert_eq!(out.code, Some(0), "{}\n{}", out.stdout, out.stderr);
    assert!(out.stderr.contains("time limit reached; 75000 frames"), "virtual time went on: {}", out.stderr);
    assert!(out.stderr.contains("warning: robot peer `test` dropped after frame ") && out.stderr.contains("it stopped reading"), "{}", out.stderr);
}

#[test]
fn shutdown_ends_a_run_whose_peers_stopped_reading_and_bad_control_lines_get_an_error() {
    let b = build("movelegs");
    let dir = tempfile::tempdir().unwrap();
    let sock = dir.path().join("robot.sock");
    let ctl = dir.path().join("control.sock");
    let run = spawn_ms(&b.ms(), &["--speed", "max", "--robot-socket", sock.to_str().unwrap(), "--control", ctl.to_str().unwrap()], &[]);
    let (silent, _) = attach(&sock, 0, 0);
    // the clock owner too: it neither reads its FRAMEs nor answers them
    let (owner, _) = attach(&sock, ROLE_JOINTS, FLAG_CLOCK);
    let mut c = connect_unix(&ctl, Duration::from_secs(60));
    c.set_read_timeout(Some(Duration::from_secs(30))).unwrap();
    // a line that is not UTF-8 is answered, and the connection stays usable
    c.write_all(b"sta\xfftus\n").unwrap();
    let mut answers = std::io::BufReader::new(c.try_clone().unwrap());
    let mut line = String::new();
    std::io::BufRead::read_line(&mut answers, &mut line).unwrap();
    assert_eq!(line, "error: the command line is not UTF-8 text (invalid byte at 3)\n");
    line.clear();
    c.write_all(b"status\n").unwrap();
    std::io::BufRead::read_line(&mut answers, &mut line).unwrap();
    assert!(line.starts_with("ok t_ms="), "{line}");
    // an endless line is cut off
    let mut long = connect_unix(&ctl, Duration::from_secs(60));
    long.set_read_timeout(Some(Duration::from_secs(30))).unwrap();
    let _ = long.write_all(&vec![b'x'; 64 << 10]);
    let mut rest = String::new();
    let _ = long.read_to_string(&mut rest);
    assert_eq!(rest, "error: command line longer than 1024 bytes (connection closed)\n");
    line.clear();
    c.write_all(b"shutdown\n").unwrap();
    std::io::BufRead::read_line(&mut answers, &mut line).unwrap();
    assert_eq!(line, "ok\n");
    let out = run.wait(Duration::from_secs(60));
    drop((silent, owner));
    assert_eq!(out.code, Some(0), "{}\n{}", out.stdout, out.stderr);
    assert!(out.stderr.contains("OPENR::Shutdown"), "{}", out.stderr);
}
