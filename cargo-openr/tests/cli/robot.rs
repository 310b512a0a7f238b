//! Robot-capability programs of `testdata/programs/` run on the built-in ERS-7: what
//! they do on the robot is checked from the `--trace` file (virtual time: `t_ms`,
//! `frame`) and from what they print — never from wall-clock time.
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::time::Duration;

use serde_json::Value;

use crate::support::{build, read_trace, run_ms, run_ms_with_stdin, Built, RunOutput};

const FRAME_MS: u64 = 8;

/// Builds `name`, runs it for `secs` seconds with a trace; returns the run and records.
fn traced_run(name: &str, secs: u32) -> (Built, RunOutput, Vec<Value>) {
    let built = build(name);
    let (out, trace) = run_traced(&built.ms(), secs, None);
    (built, out, trace)
}

fn run_traced(ms: &Path, secs: u32, stdin: Option<&[(Duration, &[u8])]>) -> (RunOutput, Vec<Value>) {
    let trace_path: PathBuf = ms.parent().unwrap().join("trace.jsonl");
    let for_arg = format!("{secs}s");
    let args = ["--for", for_arg.as_str(), "--trace", trace_path.to_str().unwrap()];
    let out = match stdin {
        // Console input arrives in real time: those runs keep real-time speed.
        Some(input) => run_ms_with_stdin(ms, &args, input),
        // Virtual time: a busy machine cannot make frames late and move the trace.
        None => run_ms(ms, &[&args[..], &["--speed", "max"]].concat()),
    };
    assert_eq!(out.code, Some(0), "run failed\nstdout:\n{}\nstderr:\n{}", out.stdout, out.stderr);
    let trace = read_trace(&trace_path);
    assert!(!trace.is_empty(), "empty trace");
    (out, trace)
}

fn kind<'a>(trace: &'a [Value], k: &str) -> Vec<&'a Value> {
    trace.iter().filter(|r| r["kind"] == k).collect()
}

fn t_ms(r: &Value) -> u64 {
    r["t_ms"].as_u64().unwrap()
}

fn frame(r: &Value) -> u64 {
    r["frame"].as_u64().unwrap()
}

fn f(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

/// `led` records of one LED: (t_ms, value) with value = `on` (0/1) or `intensity`.
fn led_changes(trace: &[Value], locator: &str) -> Vec<(u64, i64)> {
    kind(trace, "led")
        .into_iter()
        .filter(|r| r["locator"] == locator)
        .map(|r| {
            let v = match r.get("on") {
                Some(on) => on.as_bool().unwrap() as i64,
                None => r["intensity"].as_i64().unwrap(),
            };
            (t_ms(r), v)
        })
        .collect()
}

fn diffs(times: &[u64]) -> Vec<u64> {
    times.windows(2).map(|w| w[1] - w[0]).collect()
}

/// Software limits of the ERS-7 joints in degrees (ers7-model 4.1), by locator.
fn joint_limits(locator: &str) -> (f64, f64) {
    let n = locator.rsplit(':').next().unwrap();
    match n {
        "11" => (-75.0, 0.0),
        "12" => (-88.0, 88.0),
        "13" => (-15.0, 45.0),
        "14" => (-55.0, -3.0),
        "21" | "41" => (-115.0, 130.0),
        "31" | "51" => (-130.0, 115.0),
        "22" | "32" | "42" | "52" => (-10.0, 88.0),
        "23" | "33" | "43" | "53" => (-25.0, 122.0),
        "61" => (5.0, 60.0),
        "62" => (-45.0, 45.0),
        _ => panic!("unknown joint {locator}"),
    }
}

/// Every joint of every sensor record stays within its software limits.
fn assert_within_limits(trace: &[Value]) {
    let sensors = kind(trace, "sensor");
    assert!(!sensors.is_empty(), "no sensor records");
    for r in sensors {
        let joints = r["joints"].as_object().unwrap();
        assert_eq!(joints.len(), 18, "ERS-7 has 18 joints: {r}");
        for (loc, v) in joints {
            let (lo, hi) = joint_limits(loc);
            let a = f(v);
            assert!(a >= lo - 0.01 && a <= hi + 0.01, "{loc} at {a} deg outside {lo}..{hi} in frame {}", frame(r));
        }
    }
}

fn joint(r: &Value, suffix: &str) -> f64 {
    let joints = r["joints"].as_object().unwrap();
    let (_, v) = joints.iter().find(|(k, _)| k.ends_with(&format!(":{suffix}"))).unwrap_or_else(|| panic!("no joint :{suffix} in {r}"));
    f(v)
}

fn last_sensor(trace: &[Value]) -> &Value {
    kind(trace, "sensor").into_iter().last().expect("no sensor record")
}

const HEAD_LED: &str = "PRM:/r1/c1/c2/c3/l";
const LEFT_EAR: &str = "PRM:/r1/c1/c2/c3/e5-Joint4:15";
const RIGHT_EAR: &str = "PRM:/r1/c1/c2/c3/e6-Joint4:16";

#[test]
fn blinkleds_lights_and_ears_follow_the_periods_the_objects_set() {
    let (_b, out, trace) = traced_run("blinkleds", 7);
    for who in ["BlinkingHeadLED", "BlinkingFaceLED", "BlinkingBackLED", "MovingEar"] {
        assert!(out.stdout.contains(&format!("{who} : ")), "{who} did not start:\n{}", out.stdout);
    }
    // four objects, four connections to the one effector
    let conns: std::collections::BTreeSet<u64> = kind(&trace, "vector_start").iter().map(|r| r["conn"].as_u64().unwrap()).collect();
    assert_eq!(conns.len(), 4, "connections: {conns:?}");

    // head LED2: l1 toggles every 64 frames (512 ms), l4 every 1024 ms, l5 every 2048 ms;
    // l2 / l6 are the inverses of l1 / l5 (they change in the same frame)
    let head = |n: u32| led_changes(&trace, &format!("{HEAD_LED}{n}-LED2:l{n}"));
    for (n, period) in [(1, 512), (2, 512), (3, 512), (4, 1024), (5, 2048), (6, 2048)] {
        let ch = head(n);
        assert!(ch.len() >= 2 + 6 * 512 / period as usize / 2, "l{n}: too few changes {ch:?}");
        let times: Vec<u64> = ch.iter().map(|c| c.0).collect();
        assert!(diffs(&times).iter().all(|&d| d == period), "l{n} toggles at {:?}, expected every {period} ms", diffs(&times));
        assert!(ch.windows(2).all(|w| w[0].1 != w[1].1), "l{n} does not alternate: {ch:?}");
    }
    let (l1, l2) = (head(1), head(2));
    for (a, b) in l1.iter().zip(l2.iter().skip_while(|x| x.0 < l1[0].0)) {
        assert_eq!(a.0, b.0, "l1 and l2 change together");
        assert_ne!(a.1, b.1, "l2 is the inverse of l1");
    }

    // face LED3: the panel switches A -> B -> A every 256 frames (2.048 s)
    let modes: Vec<(u64, i64)> = kind(&trace, "face_mode").iter().map(|r| (t_ms(r), r["mode"].as_i64().unwrap())).collect();
    assert!(modes.len() >= 2, "face modes {modes:?}");
    assert_eq!(modes[0].1, 1, "first switch goes to face B: {modes:?}");
    assert!(modes.windows(2).all(|w| w[1].0 - w[0].0 == 256 * FRAME_MS && w[0].1 != w[1].1), "face modes {modes:?}");
    // every face light ramps 0 -> 255 -> 0: full range, one step per frame
    for c in "abcdefghijklmn".chars() {
        let ch = led_changes(&trace, &format!("{HEAD_LED}{c}-LED3:l{c}"));
        assert_eq!(ch.iter().map(|x| x.1).max(), Some(255), "l{c} never at full intensity");
        assert!(ch.iter().skip(1).any(|x| x.1 == 0), "l{c} never back to 0");
        assert!(ch.iter().all(|x| (0..=255).contains(&x.1)));
    }

    // back LED3: colour and white lights take turns every 32 frames (256 ms)
    for (colour, white) in [("u", "v"), ("w", "x"), ("y", "z")] {
        let c = led_changes(&trace, &format!("PRM:/l{colour}-LED3:l{colour}"));
        let w = led_changes(&trace, &format!("PRM:/l{white}-LED3:l{white}"));
        assert!(c.len() >= 20, "l{colour}: {c:?}");
        let times: Vec<u64> = c.iter().map(|x| x.0).collect();
        assert!(diffs(&times).iter().all(|&d| d == 32 * FRAME_MS), "l{colour} changes at {:?}", diffs(&times));
        assert!(c.iter().all(|x| x.1 == 0 || x.1 == 255), "l{colour}: {c:?}");
        // whenever the colour light changes, the white one takes the other value
        let white_at: BTreeMap<u64, i64> = w.iter().copied().collect();
        for (t, v) in c.iter().skip(1) {
            assert_eq!(white_at.get(t).copied(), Some(255 - v), "l{white} at {t} ms while l{colour} = {v}");
        }
    }

    // ears: one flick (STATE1 for 16 frames) per 256-frame vector, left and right in turn
    let ears: Vec<(u64, String, i64)> =
        kind(&trace, "ear").iter().map(|r| (t_ms(r), r["locator"].as_str().unwrap().to_string(), r["state"].as_i64().unwrap())).collect();
    let ups: Vec<&(u64, String, i64)> = ears.iter().filter(|e| e.2 == 1).collect();
    assert!(ups.len() >= 3, "ear flicks {ears:?}");
    assert_eq!(ups[0].1, LEFT_EAR, "the left ear goes first");
    for w in ups.windows(2) {
        assert_eq!(w[1].0 - w[0].0, 256 * FRAME_MS, "flicks {ears:?}");
        assert_ne!(w[0].1, w[1].1, "ears alternate: {ears:?}");
    }
    // every flick comes down within the 7 s run (the last goes up at 6152 ms)
    for up in &ups {
        let down =
            ears.iter().find(|e| e.1 == up.1 && e.2 == 0 && e.0 > up.0).unwrap_or_else(|| panic!("{} up at {} ms never comes down: {ears:?}", up.1, up.0));
        assert_eq!(down.0 - up.0, 16 * FRAME_MS, "{} held {} ms", up.1, down.0 - up.0);
    }
    assert!(ears.iter().any(|e| e.1 == RIGHT_EAR));
    assert!(kind(&trace, "ear_held").is_empty(), "no ear stays up for 1 s");
    assert_eq!(kind(&trace, "motor_power").len(), 1, "motor power switched on once (SetMotorPower is idempotent)");
}

/// Postures of movehead (tilt1, pan, tilt2, mouth), degrees.
const HEAD_POSTURES: [[f64; 4]; 4] = [[-10.0, 0.0, 20.0, -3.0], [-20.0, 60.0, 30.0, -3.0], [-30.0, 0.0, 10.0, -3.0], [-20.0, -60.0, 30.0, -3.0]];
const HEAD: [&str; 4] = ["11", "12", "13", "14"];

#[test]
fn movehead_reaches_each_posture_and_opens_the_mouth_between_them() {
    let (_b, out, trace) = traced_run("movehead", 8);
    let holds = out.lines_starting("MovingHead : holding posture");
    assert_eq!(holds.len(), 5, "{}", out.stdout);
    assert!(out.stdout.contains("MovingHead : done, 5 postures"), "{}", out.stdout);

    // the standard head gains of ers7-model 4.5
    let gains: BTreeMap<String, (i64, i64, i64)> = kind(&trace, "gain")
        .iter()
        .map(|r| (r["locator"].as_str().unwrap().to_string(), (r["p"].as_i64().unwrap(), r["i"].as_i64().unwrap(), r["d"].as_i64().unwrap())))
        .collect();
    assert_eq!(gains.get("PRM:/r1/c1-Joint2:11"), Some(&(0x0a, 0x04, 0x02)));
    assert_eq!(gains.get("PRM:/r1/c1/c2-Joint2:12"), Some(&(0x08, 0x02, 0x04)));
    assert_eq!(gains.get("PRM:/r1/c1/c2/c3-Joint2:13"), Some(&(0x08, 0x04, 0x02)));
    assert_eq!(gains.get("PRM:/r1/c1/c2/c3/c4-Joint2:14"), Some(&(0x08, 0x00, 0x04)));
    assert!(kind(&trace, "clamp").is_empty(), "movehead stays in range: {:?}", kind(&trace, "clamp"));
    assert_within_limits(&trace);

    // every hold vector (all 16 frames of the 4 joints constant) ends with the head there
    let sensors = kind(&trace, "sensor");
    let mut reached = Vec::new();
    for v in kind(&trace, "vector_start") {
        let slots = v["slots"].as_array().unwrap();
        assert_eq!(slots.len(), 4);
        // JOINT_COMMAND2 values: one target (degrees) per frame
        let targets: Vec<f64> = slots.iter().map(|s| f(&s["values"][0])).collect();
        let constant = slots.iter().all(|s| s["values"].as_array().unwrap().iter().all(|x| (f(x) - f(&s["values"][0])).abs() < 1e-9));
        let Some(p) = HEAD_POSTURES.iter().position(|p| p.iter().zip(&targets).all(|(a, b)| (a - b).abs() < 0.01)) else { continue };
        if !constant {
            continue;
        }
        let (start, end) = (frame(v), frame(v) + v["duration_frames"].as_u64().unwrap() - 1);
        let Some(s) = sensors.iter().filter(|s| frame(s) >= start && frame(s) <= end).last() else { continue };
        for (j, name) in HEAD.iter().enumerate() {
            let a = joint(s, name);
            assert!((a - targets[j]).abs() < 0.5, "posture {p}: joint {name} at {a}, commanded {} (frame {})", targets[j], frame(s));
        }
        reached.push(p);
    }
    reached.dedup();
    assert_eq!(reached, vec![0, 1, 2, 3, 0], "postures reached in order");

    // the mouth opens to about -30 deg on the way and is closed (-3) at every posture
    let mouth_min = sensors.iter().map(|s| joint(s, "14")).fold(f64::MAX, f64::min);
    assert!(mouth_min <= -29.0, "mouth opened only to {mouth_min}");
    let pan: Vec<f64> = sensors.iter().map(|s| joint(s, "12")).collect();
    assert!(pan.iter().any(|&p| p >= 59.5) && pan.iter().any(|&p| p <= -59.5), "pan swings to both sides");
}

/// Standard ERS-7 leg gains per joint kind, with the fixed shifts.
const STD_LEG_GAIN: [&str; 3] = ["0x1c 0x08 0x01 0x0e 0x02 0x0f", "0x14 0x04 0x01 0x0e 0x02 0x0f", "0x1c 0x08 0x01 0x0e 0x02 0x0f"];
const LEG_NAMES: [&str; 12] = ["LF-J1", "LF-J2", "LF-J3", "LR-J1", "LR-J2", "LR-J3", "RF-J1", "RF-J2", "RF-J3", "RR-J1", "RR-J2", "RR-J3"];
const O_GAIN_DISABLED: i32 = 4108;
const O_INVALID_PRIMITIVE_ID: i32 = 4096;

#[test]
fn pidgains_prints_the_gains_it_set_and_only_enabled_legs_move() {
    let (_b, out, trace) = traced_run("pidgains", 4);
    let zeros = "0x00 0x00 0x00 0x00 0x00 0x00";
    let gets = out.lines_starting("PIDGains : get ");
    let mut expected = vec![format!("PIDGains : get LF-J1 status {O_GAIN_DISABLED} gain {zeros}")];
    for (i, name) in LEG_NAMES.iter().enumerate() {
        let gain = if i == 0 { "0x0c 0x02 0x08 0x0e 0x02 0x0f" } else { STD_LEG_GAIN[i % 3] };
        expected.push(format!("PIDGains : get {name} status 0 gain {gain}"));
    }
    for name in &LEG_NAMES[6..] {
        expected.push(format!("PIDGains : get {name} status {O_GAIN_DISABLED} gain {zeros}"));
    }
    expected.push(format!("PIDGains : get UNDEF status {O_INVALID_PRIMITIVE_ID} gain {zeros}"));
    assert_eq!(gets, expected, "\n{}", out.stdout);
    assert!(out.stdout.contains(&format!("PIDGains : set before enable LF-J1 status {O_GAIN_DISABLED}")), "{}", out.stdout);
    assert!(out.stdout.contains(&format!("PIDGains : set after disable RF-J1 status {O_GAIN_DISABLED}")), "{}", out.stdout);
    assert!(out.stdout.contains(&format!("PIDGains : enable UNDEF status {O_INVALID_PRIMITIVE_ID}")), "{}", out.stdout);
    for name in LEG_NAMES {
        assert!(out.stdout.contains(&format!("PIDGains : enable {name} status 0 set status 0")), "{name}\n{}", out.stdout);
    }
    for name in &LEG_NAMES[6..] {
        assert!(out.stdout.contains(&format!("PIDGains : disable {name} status 0")), "{name}\n{}", out.stdout);
    }
    assert!(out.stdout.contains("PIDGains : done"), "{}", out.stdout);

    // the trace's last gain record per joint agrees
    let mut last_gain: BTreeMap<String, &Value> = BTreeMap::new();
    for r in kind(&trace, "gain") {
        last_gain.insert(r["locator"].as_str().unwrap().to_string(), r);
    }
    let lf_j1 = last_gain["PRM:/r2/c1-Joint2:21"];
    assert_eq!((lf_j1["enabled"].as_bool(), lf_j1["p"].as_i64(), lf_j1["i"].as_i64(), lf_j1["d"].as_i64()), (Some(true), Some(12), Some(2), Some(8)));
    let lr_j2 = last_gain["PRM:/r3/c1/c2-Joint2:32"];
    assert_eq!((lr_j2["enabled"].as_bool(), lr_j2["p"].as_i64(), lr_j2["i"].as_i64(), lr_j2["d"].as_i64()), (Some(true), Some(0x14), Some(4), Some(1)));
    for loc in ["PRM:/r4/c1-Joint2:41", "PRM:/r4/c1/c2/c3-Joint2:43", "PRM:/r5/c1/c2-Joint2:52"] {
        assert_eq!(last_gain[loc]["enabled"].as_bool(), Some(false), "{loc}");
    }

    // every leg was sent to J1 0 / J2 10 / J3 60: the left legs are there, the limp right
    // legs still in the boot (sleep) posture
    let s = last_sensor(&trace);
    for (n, target) in [("21", 0.0), ("22", 10.0), ("23", 60.0), ("31", 0.0), ("32", 10.0), ("33", 60.0)] {
        assert!((joint(s, n) - target).abs() < 0.5, "left joint {n} at {} not {target}", joint(s, n));
    }
    for (n, sleep) in [("41", 59.0), ("42", 0.0), ("43", 30.0), ("51", -119.0), ("52", 4.0), ("53", 122.0)] {
        assert!((joint(s, n) - sleep).abs() < 0.5, "limp right joint {n} moved to {}", joint(s, n));
    }
    assert_within_limits(&trace);
}

/// A printed frame of sensorkey: joints (suffix → degrees), accel, paws.
#[derive(Debug, Default)]
struct PrintedFrame {
    joints: BTreeMap<String, f64>,
    accel: Vec<f64>,
    paws: Vec<bool>,
}

fn parse_sensorkey(stdout: &str) -> (Vec<(u64, u64)>, BTreeMap<u64, PrintedFrame>) {
    let mut vectors = Vec::new();
    let mut frames: BTreeMap<u64, PrintedFrame> = BTreeMap::new();
    for line in stdout.lines() {
        let Some(rest) = line.strip_prefix("SensorKey : ") else { continue };
        let w: Vec<&str> = rest.split_whitespace().collect();
        if w[0] == "vector" {
            // vector N first frame F frames 4
            vectors.push((w[1].parse().unwrap(), w[4].parse().unwrap()));
        } else if w[0] == "frame" {
            let fr: u64 = w[1].parse().unwrap();
            let e = frames.entry(fr).or_default();
            match w[2] {
                "joint" => {
                    for pair in w[3..].chunks(2) {
                        e.joints.insert(pair[0].to_string(), pair[1].parse().unwrap());
                    }
                }
                "switch" => e.paws = w[6..10].iter().map(|x| *x == "1").collect(),
                "accel" => e.accel = w[3..6].iter().map(|x| x.parse().unwrap()).collect(),
                other => panic!("unexpected line {line:?} ({other})"),
            }
        }
    }
    (vectors, frames)
}

#[test]
fn sensorkey_waits_for_return_and_prints_what_the_robot_sensed() {
    // sensorkey alone does not move; run it together with movehead's object so that
    // the printed joint angles change from vector to vector
    let b = build("sensorkey");
    let head = build("movehead");
    let ms = b.ms();
    let objs = ms.join("OPEN-R/MW/OBJS");
    std::fs::copy(head.ms().join("OPEN-R/MW/OBJS/MVHEAD.BIN"), objs.join("MVHEAD.BIN")).unwrap();
    let conf = ms.join("OPEN-R/MW/CONF");
    let append = |file: &str, text: &str| {
        let mut s = std::fs::read_to_string(conf.join(file)).unwrap();
        s.push_str(text);
        std::fs::write(conf.join(file), s).unwrap();
    };
    append("OBJECT.CFG", "/MS/OPEN-R/MW/OBJS/MVHEAD.BIN\n");
    append("CONNECT.CFG", "MovingHead.Move.OCommandVectorData.S OVirtualRobotComm.Effector.OCommandVectorData.O\n");

    // one RETURN at once, two more after 1.5 s, then end of input
    let input: [(Duration, &[u8]); 2] = [(Duration::ZERO, b"\n"), (Duration::from_millis(1500), b"\n\n")];
    let (out, trace) = run_traced(&ms, 4, Some(&input));
    assert!(out.stdout.contains("SensorKey : 34 entries, 34 of 34 sensors found"), "{}", out.stdout);
    // the robot's console has no end of input: after the third line it waits for a fourth
    assert!(!out.stdout.contains("SensorKey : end of input"), "{}", out.stdout);
    assert_eq!(out.lines_starting("SensorKey : hit RETURN key").len(), 4, "{}", out.stdout);
    let (vectors, frames) = parse_sensorkey(&out.stdout);
    assert_eq!(vectors.iter().map(|v| v.0).collect::<Vec<_>>(), vec![1, 2, 3], "{}", out.stdout);
    // the second vector was delivered right after the first; the third is the newest one
    // after the 1.5 s wait for the key, not the backlog
    assert!(vectors[1].1 > vectors[0].1);
    assert!(vectors[2].1 >= vectors[1].1 + 12, "vector after the wait starts at frame {} (previous {})", vectors[2].1, vectors[1].1);
    for (_, first) in &vectors {
        for k in 0..4 {
            let fr = frames.get(&(first + k)).unwrap_or_else(|| panic!("frame {} not printed", first + k));
            assert_eq!(fr.joints.len(), 18, "{fr:?}");
            assert_eq!(fr.accel.len(), 3);
            assert_eq!(fr.paws.len(), 4);
        }
    }

    // each printed vector's newest frame is a sensor record of the trace: same angles
    let sensors = kind(&trace, "sensor");
    for (_, first) in &vectors {
        let newest = first + 3;
        let rec = sensors.iter().find(|r| frame(r) == newest).unwrap_or_else(|| panic!("no sensor record for frame {newest}"));
        assert_eq!(rec["first_frame"].as_u64(), Some(*first));
        let printed = &frames[&newest];
        for (loc, v) in rec["joints"].as_object().unwrap() {
            let n = loc.rsplit(':').next().unwrap();
            let p = printed.joints[n];
            assert!((p - f(v)).abs() < 0.002, "frame {newest} joint {n}: printed {p}, trace {v}");
        }
        for (i, a) in rec["accel"].as_array().unwrap().iter().enumerate() {
            assert!((printed.accel[i] - f(a)).abs() < 0.002, "frame {newest} accel {i}: printed {}, trace {a}", printed.accel[i]);
        }
        let paws: Vec<bool> = rec["paws"].as_array().unwrap().iter().map(|p| p.as_bool().unwrap()).collect();
        assert_eq!(printed.paws, paws, "frame {newest} paws");
    }
    // the head had moved between the first and the last printed vector
    let (a, z) = (&frames[&(vectors[0].1 + 3)], &frames[&(vectors[2].1 + 3)]);
    assert!(HEAD.iter().any(|n| (a.joints[*n] - z.joints[*n]).abs() > 1.0), "head did not move: {a:?} {z:?}");
}

#[test]
fn badcommands_are_clamped_or_ignored_and_the_robot_keeps_going() {
    let (_b, out, trace) = traced_run("badcommands", 5);
    assert!(out.stdout.contains("BadCommands : OpenPrimitive PRM:/r9/c1-Joint2:91 status 6 id 0xffffffff"), "{}", out.stdout);
    assert!(out.stdout.contains("BadCommands : done, 24 vectors sent, 24 ready"), "{}\n{}", out.stdout, out.stderr);
    assert_eq!(kind(&trace, "vector_start").len(), 24);
    assert_eq!(kind(&trace, "vector_done").len(), 24);

    // clamps: (locator suffix, requested, clamped, rule)
    let clamps: Vec<(String, f64, f64, String)> = kind(&trace, "clamp")
        .iter()
        .map(|r| {
            let loc = r["locator"].as_str().unwrap();
            (loc.rsplit(':').next().unwrap().to_string(), f(&r["requested_deg"]), f(&r["clamped_deg"]), r["rule"].as_str().unwrap().to_string())
        })
        .collect();
    let expect = [
        ("11", 30.0, 0.0, "range"),
        ("12", 120.0, 88.0, "range"),
        ("13", 60.0, 45.0, "range"),
        ("14", 10.0, -3.0, "range"),
        ("61", 0.0, 5.0, "range"),
        ("12", -120.0, -88.0, "range"),
        ("13", -15.0, 5.0, "combined"),
        ("14", -80.0, -55.0, "range"),
        ("61", 90.0, 60.0, "range"),
    ];
    for (n, req, cl, rule) in expect {
        assert!(
            clamps.iter().any(|c| c.0 == n && (c.1 - req).abs() < 0.01 && (c.2 - cl).abs() < 0.01 && c.3 == rule),
            "no clamp of {n} {req} -> {cl} ({rule}) in {clamps:?}"
        );
    }
    assert_eq!(clamps.len(), expect.len(), "a clamp is reported once per requested value: {clamps:?}");
    assert_within_limits(&trace);
    // while clamped, the joints went to the clamped values
    let sensors = kind(&trace, "sensor");
    let at = |fr: u64| sensors.iter().filter(|s| frame(s) <= fr).last().copied().unwrap();
    let range_end = at(128);
    for (n, v) in [("11", 0.0), ("12", 88.0), ("13", 45.0), ("14", -3.0), ("61", 5.0)] {
        assert!((joint(range_end, n) - v).abs() < 0.5, "joint {n} at {} not {v}", joint(range_end, n));
    }
    let combined_end = at(256);
    for (n, v) in [("11", -60.0), ("12", -88.0), ("13", 5.0), ("14", -55.0), ("61", 60.0)] {
        assert!((joint(combined_end, n) - v).abs() < 0.5, "joint {n} at {} not {v}", joint(combined_end, n));
    }
    let end = last_sensor(&trace);
    for (n, v) in [("11", -10.0), ("12", 0.0), ("13", 10.0), ("14", -10.0), ("61", 30.0)] {
        assert!((joint(end, n) - v).abs() < 0.5, "joint {n} at {} not {v}", joint(end, n));
    }

    // the slot with the UNDEF ID and the JOINT_COMMAND2 slot for an ear are ignored,
    // the slot never Set() (numFrames 0) is not there; the rest of the vector plays
    for v in kind(&trace, "vector_start") {
        assert_eq!(v["duration_frames"].as_u64(), Some(16));
        let slots = v["slots"].as_array().unwrap();
        let idx: Vec<u64> = slots.iter().map(|s| s["index"].as_u64().unwrap()).collect();
        assert_eq!(idx, vec![0, 1, 2, 3, 4, 5, 6], "{v}");
        for s in &slots[..5] {
            assert_eq!(s["ignored"].as_bool(), Some(false), "{s}");
        }
        assert!(slots[5]["locator"].is_null() && slots[5]["ignored"].as_bool() == Some(true), "{}", slots[5]);
        assert_eq!(slots[5]["primitive"].as_u64(), Some(0xFFFF_FFFF));
        assert_eq!(slots[6]["locator"].as_str(), Some(LEFT_EAR));
        assert_eq!(slots[6]["ignored"].as_bool(), Some(true));
    }
    assert!(kind(&trace, "ear").is_empty(), "a JOINT_COMMAND2 to an ear must not move it");
}

#[test]
fn movelegs_reaches_its_base_posture() {
    let (_b, out, trace) = traced_run("movelegs", 7);
    assert!(out.stdout.contains("MovingLegs : done, holding the base posture"), "{}", out.stdout);
    assert_within_limits(&trace);
    // base posture of MovingLegs.h (J1 J2 J3 per leg), reached after the 1 s adjustment and
    // held at the end (the swing's last frame stops 1 deg short of it: J1 within 1 deg)
    let base = [
        ("21", 30.0),
        ("22", 10.0),
        ("23", 30.0),
        ("31", -30.0),
        ("32", 10.0),
        ("33", 30.0),
        ("41", 30.0),
        ("42", 10.0),
        ("43", 30.0),
        ("51", -30.0),
        ("52", 10.0),
        ("53", 30.0),
    ];
    let s = last_sensor(&trace);
    for (n, v) in base {
        assert!((joint(s, n) - v).abs() < 1.0, "joint {n} at {} not {v} (frame {})", joint(s, n), frame(s));
    }
    // ... exactly where the last command left each joint
    let last = kind(&trace, "vector_start").into_iter().last().unwrap();
    for slot in last["slots"].as_array().unwrap() {
        let n = slot["locator"].as_str().unwrap().rsplit(':').next().unwrap();
        let commanded = f(slot["values"].as_array().unwrap().last().unwrap());
        assert!((joint(s, n) - commanded).abs() < 0.01, "joint {n} at {} not at its last target {commanded}", joint(s, n));
    }
    // ... already after the 1 s adjustment (frames 1..128)
    let sensors = kind(&trace, "sensor");
    let adjusted = sensors.iter().find(|r| frame(r) >= 128).unwrap();
    for (n, v) in base {
        assert!((joint(adjusted, n) - v).abs() < 1.5, "after adjusting, joint {n} at {} not {v}", joint(adjusted, n));
    }
    // the printed readings of the left front leg agree (to the degree) with the trace
    let lines = out.lines_starting("Sensors : frame");
    assert!(lines.len() >= 8, "{}", out.stdout);
    for l in lines {
        let w: Vec<&str> = l.split_whitespace().collect();
        let fr: u64 = w[3].parse().unwrap();
        let rec = sensors.iter().find(|r| frame(r) == fr).unwrap_or_else(|| panic!("no sensor record for frame {fr}"));
        for (k, n) in [(6, "21"), (8, "22"), (10, "23")] {
            let printed: f64 = w[k].parse().unwrap();
            // the program truncates to whole degrees
            assert!((printed - joint(rec, n)).abs() < 1.001, "{l}: joint {n} is {}", joint(rec, n));
        }
    }
}

#[test]
fn imagesave_sees_the_ers7_layers_at_30_fps_and_writes_bmps() {
    let b = build("imagesave");
    let ms = b.ms();
    let out = run_ms(&ms, &["--for", "3s"]);
    assert_eq!(out.code, Some(0), "{}\n{}", out.stdout, out.stderr);
    assert!(out.stdout.contains("ImageSave : 4 layers, camera ID matches"), "{}", out.stdout);
    for layer in [
        "ImageSave : layer H type 24 208x160 skip 1040 size 199680",
        "ImageSave : layer M type 24 104x80 skip 520 size 49920",
        "ImageSave : layer L type 24 52x40 skip 260 size 12480",
        "ImageSave : layer C type 20 104x80 skip 0 size 8320",
    ] {
        assert!(out.stdout.contains(layer), "missing {layer:?}\n{}", out.stdout);
    }
    // 30 images/s on the 8 ms frame counter: consecutive images 4 or 5 frames apart,
    // field counter +1 per image
    let images: Vec<(u64, u64)> = out
        .lines_starting("ImageSave : image ")
        .iter()
        .map(|l| {
            let w: Vec<&str> = l.split_whitespace().collect();
            (w[5].parse().unwrap(), w[7].parse().unwrap())
        })
        .collect();
    assert_eq!(images.len(), 10, "{}", out.stdout);
    for w in images.windows(2) {
        assert!(matches!(w[1].0 - w[0].0, 4 | 5), "image frames {images:?}");
        assert_eq!(w[1].1, w[0].1 + 1, "field counters {images:?}");
    }
    // three 208x160 24-bit BMPs, not a uniform colour
    for i in 0..3 {
        assert!(out.stdout.contains(&format!("ImageSave : saved /MS/IMG{i}.BMP")), "{}", out.stdout);
        let bmp = std::fs::read(ms.join(format!("IMG{i}.BMP"))).unwrap();
        let le32 = |o: usize| u32::from_le_bytes([bmp[o], bmp[o + 1], bmp[o + 2], bmp[o + 3]]);
        assert_eq!(&bmp[..2], b"BM");
        assert_eq!(bmp.len(), 54 + 208 * 160 * 3);
        assert_eq!(le32(2) as usize, bmp.len());
        assert_eq!((le32(18), le32(22), u16::from_le_bytes([bmp[28], bmp[29]])), (208, 160, 24));
        let first = &bmp[54..57];
        assert!(bmp[54..].chunks(3).any(|px| px != first), "IMG{i}.BMP is one colour");
    }
}

fn wav_data(bytes: &[u8]) -> (u16, u32, u16, &[u8]) {
    assert_eq!(&bytes[..4], b"RIFF");
    assert_eq!(&bytes[8..16], b"WAVEfmt ");
    let le16 = |o: usize| u16::from_le_bytes([bytes[o], bytes[o + 1]]);
    let le32 = |o: usize| u32::from_le_bytes([bytes[o], bytes[o + 1], bytes[o + 2], bytes[o + 3]]);
    assert_eq!(le16(20), 1, "PCM");
    let mut pos = 12;
    while pos + 8 <= bytes.len() {
        let size = le32(pos + 4) as usize;
        if &bytes[pos..pos + 4] == b"data" {
            return (le16(22), le32(24), le16(34), &bytes[pos + 8..(pos + 8 + size).min(bytes.len())]);
        }
        pos += 8 + size + (size & 1);
    }
    panic!("no data chunk");
}

#[test]
fn soundplay_streams_the_wav_gaplessly_to_the_speaker() {
    let b = build("soundplay");
    let ms = b.ms();
    let played = ms.parent().unwrap().join("speaker.wav");
    // virtual time: a busy machine cannot make a buffer start late
    let out = run_ms(&ms, &["--speed", "max", "--for", "2s", "--speaker-wav", played.to_str().unwrap()]);
    assert_eq!(out.code, Some(0), "{}\n{}", out.stdout, out.stderr);
    assert!(out.stdout.contains("SoundPlay : design data SNDPLAY_WAV, 16044 bytes"), "{}", out.stdout);
    assert!(out.stdout.contains("SoundPlay : 16000 Hz 16 bit 1 ch, 16000 bytes of PCM"), "{}", out.stdout);
    assert!(out.stdout.contains("SoundPlay : mute 0 power 0 volume 0 type 0 unmute 0"), "{}", out.stdout);
    assert!(out.stdout.contains("SoundPlay : done, 16 buffers"), "{}", out.stdout);
    // 32 ms per buffer: the speaker starts each one 4 frames after the previous one
    let starts: Vec<u64> = out.lines_starting("SoundPlay : buffer ").iter().map(|l| l.split_whitespace().last().unwrap().parse().unwrap()).collect();
    assert_eq!(starts.len(), 16, "{}", out.stdout);
    assert!(starts.windows(2).all(|w| w[1] - w[0] == 4), "buffer start frames {starts:?}");
    // what the speaker played: the tone, followed by the zero padding of the last buffer
    let tone = std::fs::read(ms.join("OPEN-R/MW/DATA/P/TONE.WAV")).unwrap();
    let (_, _, _, tone_pcm) = wav_data(&tone);
    let heard = std::fs::read(&played).unwrap();
    let (channels, rate, bits, pcm) = wav_data(&heard);
    assert_eq!((channels, rate, bits), (1, 16000, 16));
    let at = pcm.windows(tone_pcm.len()).position(|w| w == tone_pcm).expect("the tone is in the speaker output");
    assert!(pcm[at + tone_pcm.len()..].iter().all(|&x| x == 0), "only silence after the tone");
}

#[test]
fn soundrec_records_the_microphone_into_a_wav() {
    let b = build("soundrec");
    let ms = b.ms();
    let (pcm, wav) = stereo_test_wav(2);
    let mic = ms.parent().unwrap().join("mic.wav");
    std::fs::write(&mic, &wav).unwrap();

    let out = run_ms(&ms, &["--for", "2s", "--mic-wav", mic.to_str().unwrap()]);
    assert_eq!(out.code, Some(0), "{}\n{}", out.stdout, out.stderr);
    assert!(out.stdout.contains("SoundRec : saved /MS/RECORD.WAV, 64000 bytes in 63 blocks"), "{}", out.stdout);
    // ERS-7 mic: 16 ms blocks (2 frames) of 1024 bytes, 16 kHz 16-bit stereo
    let blocks: Vec<Vec<String>> = out.lines_starting("SoundRec : block ").iter().map(|l| l.split_whitespace().map(str::to_string).collect()).collect();
    assert_eq!(blocks.len(), 5, "{}", out.stdout);
    for b in &blocks {
        assert_eq!(&b[6..], ["rate", "16000", "bits", "16", "ch", "2", "size", "1024", "id", "mic"], "{b:?}");
    }
    let frames: Vec<u64> = blocks.iter().map(|b| b[5].parse().unwrap()).collect();
    assert!(frames.windows(2).all(|w| w[1] - w[0] == 2), "block frames {frames:?}");
    let rec = std::fs::read(ms.join("RECORD.WAV")).expect("RECORD.WAV written on the stick");
    let (channels, r, bits, data) = wav_data(&rec);
    assert_eq!((channels, r, bits, data.len()), (2, 16000, 16, 64000));
    // the recording is a piece of the microphone signal
    assert!(pcm.windows(1024).any(|w| w == &data[..1024]), "recorded samples are not the mic input");
}

/// `seconds` of a stereo test signal (300 Hz left, 500 Hz right) for the microphones:
/// the PCM and the WAV file holding it.
fn stereo_test_wav(seconds: u32) -> (Vec<u8>, Vec<u8>) {
    let rate = 16000u32;
    let mut pcm = Vec::new();
    for i in 0..rate * seconds {
        let t = i as f64 / rate as f64;
        pcm.extend_from_slice(&((6000.0 * (2.0 * std::f64::consts::PI * 300.0 * t).sin()) as i16).to_le_bytes());
        pcm.extend_from_slice(&((3000.0 * (2.0 * std::f64::consts::PI * 500.0 * t).sin()) as i16).to_le_bytes());
    }
    let mut wav = Vec::new();
    wav.extend_from_slice(b"RIFF");
    wav.extend_from_slice(&(36 + pcm.len() as u32).to_le_bytes());
    wav.extend_from_slice(b"WAVEfmt ");
    for v in [
        16u32.to_le_bytes().to_vec(),
        1u16.to_le_bytes().to_vec(),
        2u16.to_le_bytes().to_vec(),
        rate.to_le_bytes().to_vec(),
        (rate * 4).to_le_bytes().to_vec(),
        4u16.to_le_bytes().to_vec(),
        16u16.to_le_bytes().to_vec(),
    ] {
        wav.extend_from_slice(&v);
    }
    wav.extend_from_slice(b"data");
    wav.extend_from_slice(&(pcm.len() as u32).to_le_bytes());
    wav.extend_from_slice(&pcm);
    (pcm, wav)
}

#[test]
fn the_microphones_deliver_16_khz_stereo_on_every_design() {
    let b = build("micrate");
    let ms = b.ms();
    let (pcm, wav) = stereo_test_wav(5);
    let mic = ms.parent().unwrap().join("mic.wav");
    std::fs::write(&mic, &wav).unwrap();
    // ERS-2xx: 2048-byte blocks every 32 ms (robot-api 8.6); ERS-7: 1024 every 16 ms
    for (design, block) in [("ERS-210", 2048), ("ERS-7", 1024)] {
        let _ = std::fs::remove_file(ms.join("MIC.RAW"));
        let out = run_ms(&ms, &["--design", design, "--for", "4100ms", "--speed", "max", "--mic-wav", mic.to_str().unwrap()]);
        assert_eq!(out.code, Some(0), "{}\n{}", out.stdout, out.stderr);
        assert!(out.stdout.contains(&format!("MicRate : measuring the microphones of {design}")), "{}", out.stdout);
        assert!(out.stdout.contains(&format!("MicRate : block size {block}\n")), "{design}:\n{}", out.stdout);
        assert!(out.stdout.contains("MicRate : 256000 bytes in 4000 ms of sound: 64000 bytes/s"), "{design}:\n{}", out.stdout);
        // no gap and no repeat: what was recorded is the start of the mic signal
        let raw = std::fs::read(ms.join("MIC.RAW")).expect("MIC.RAW written");
        assert_eq!(raw.len(), 256000 + block, "{design}");
        assert!(raw == pcm[..raw.len()], "{design}: the recording is not the mic input from its start");
    }
}
