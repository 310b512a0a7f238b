//! `cargo openr run --sim mujoco`: the programs of testdata/programs, unmodified, drive
//! ERS-7s in MuJoCo (sim/mujoco). Needs what tools/deps.sh installs (the test command
//! runs it first). Observed: the runtime's --trace (commands, joint readings,
//! accelerometer), the programs' output and saved images, and the peer's ground truth
//! (`--sim-arg=--state=FILE`: trunk, camera and ball poses of every frame).
use std::collections::BTreeMap;
use std::fs;
use std::path::Path;

use serde_json::Value;

use crate::support::{build, copy_tree, read_trace, run_ms, Built, RunOutput};

const LF_J1: &str = "PRM:/r2/c1-Joint2:21";
const PAN: &str = "PRM:/r1/c1/c2-Joint2:12";

fn sim(ms: &Path, args: &[&str]) -> RunOutput {
    let mut all = vec!["--sim", "mujoco", "--speed", "max"];
    all.extend_from_slice(args);
    let out = run_ms(ms, &all);
    assert_eq!(out.code, Some(0), "{}\n{}", out.stdout, out.stderr);
    out
}

/// Joint targets per frame, from the trace's command vectors (frame -> degrees).
fn targets(trace: &[Value], locator: &str) -> BTreeMap<u64, f64> {
    let mut out = BTreeMap::new();
    for r in trace.iter().filter(|r| r["kind"] == "vector_start") {
        let start = r["frame"].as_u64().unwrap();
        for slot in r["slots"].as_array().unwrap().iter().filter(|s| s["locator"] == locator && s["ignored"] == false) {
            for (i, v) in slot["values"].as_array().unwrap().iter().enumerate() {
                out.insert(start + i as u64, v.as_f64().unwrap());
            }
        }
    }
    out
}

/// The joint's angle read back in each sensor record (frame -> degrees).
fn readings(trace: &[Value], locator: &str) -> BTreeMap<u64, f64> {
    trace.iter().filter(|r| r["kind"] == "sensor").filter_map(|r| Some((r["frame"].as_u64()?, r["joints"][locator].as_f64()?))).collect()
}

/// (largest, RMS) difference between reading and target over frames in `from..to`.
fn tracking_error(trace: &[Value], locator: &str, from: u64, to: u64) -> (f64, f64) {
    let t = targets(trace, locator);
    let errs: Vec<f64> =
        readings(trace, locator).into_iter().filter(|(f, _)| (from..to).contains(f)).filter_map(|(f, v)| Some((v - t.get(&f)?).abs())).collect();
    assert!(errs.len() > 20, "too few readings of {locator} with a target in frames {from}..{to}");
    let max = errs.iter().cloned().fold(0.0, f64::max);
    (max, (errs.iter().map(|e| e * e).sum::<f64>() / errs.len() as f64).sqrt())
}

fn state(path: &Path) -> Vec<Value> {
    read_trace(path)
}

fn accel(trace: &[Value], from_ms: u64, to_ms: u64) -> Vec<[f64; 3]> {
    trace
        .iter()
        .filter(|r| r["kind"] == "sensor" && (from_ms..to_ms).contains(&r["t_ms"].as_u64().unwrap()))
        .map(|r| {
            let a = r["accel"].as_array().unwrap();
            [a[0].as_f64().unwrap(), a[1].as_f64().unwrap(), a[2].as_f64().unwrap()]
        })
        .collect()
}

fn mean(v: &[[f64; 3]], axis: usize) -> f64 {
    v.iter().map(|a| a[axis]).sum::<f64>() / v.len() as f64
}

#[test]
fn movelegs_moves_the_simulated_legs_within_the_servo_tracking_error() {
    let b = build("movelegs");
    let dir = tempfile::tempdir().unwrap();
    let trace = dir.path().join("t.jsonl");
    let out = sim(&b.ms(), &["--for", "6s", "--trace", trace.to_str().unwrap()]);
    assert!(out.stdout.contains("MovingLegs : done, holding the base posture"), "{}", out.stdout);
    let t = read_trace(&trace);
    // The swing (frames 129..640: J1 ±20° at 1 Hz) is followed by every leg's J1 and
    // the joints it does not move hold their posture.
    for leg in ["2", "3", "4", "5"] {
        let j1 = format!("PRM:/r{leg}/c1-Joint2:{leg}1");
        let (max, rms) = tracking_error(&t, &j1, 160, 640);
        assert!(max < 10.0 && rms < 5.0, "{j1}: max {max:.1}°, RMS {rms:.1}° off its targets");
        let j3 = format!("PRM:/r{leg}/c1/c2/c3-Joint2:{leg}3");
        let (max, _) = tracking_error(&t, &j3, 160, 640);
        assert!(max < 6.0, "{j3}: {max:.1}° off its posture");
    }
    // The swing really happened in the readings: 40° peak to peak commanded.
    let lf: Vec<f64> = readings(&t, LF_J1).into_iter().filter(|(f, _)| (200..640).contains(f)).map(|(_, v)| v).collect();
    let span = lf.iter().cloned().fold(f64::MIN, f64::max) - lf.iter().cloned().fold(f64::MAX, f64::min);
    assert!(span > 30.0, "LF J1 swung only {span:.1}° peak to peak");
}

#[test]
fn movehead_turns_the_simulated_head() {
    let b = build("movehead");
    let dir = tempfile::tempdir().unwrap();
    let trace = dir.path().join("t.jsonl");
    let out = sim(&b.ms(), &["--for", "6s", "--trace", trace.to_str().unwrap()]);
    assert!(out.stdout.contains("MovingHead : done, 5 postures"), "{}", out.stdout);
    let t = read_trace(&trace);
    let (max, rms) = tracking_error(&t, PAN, 140, 700);
    assert!(max < 15.0 && rms < 6.0, "pan: max {max:.1}°, RMS {rms:.1}° off its targets");
    let pan = readings(&t, PAN);
    let (lo, hi) = pan.values().fold((f64::MAX, f64::MIN), |(lo, hi), v| (lo.min(*v), hi.max(*v)));
    assert!(lo < -50.0 && hi > 50.0, "the head should visit pan -60° and +60°: read {lo:.1}..{hi:.1}");
}

#[test]
fn a_standing_robot_stays_up_and_a_pushed_one_reports_it_through_the_accelerometer() {
    let b = build("movelegs");
    let dir = tempfile::tempdir().unwrap();
    let (trace, truth) = (dir.path().join("t.jsonl"), dir.path().join("s.jsonl"));
    let state_arg = format!("--sim-arg=--state={}", truth.display());
    // movelegs stands from frame 640 (5.12 s) on: 10 s more of holding its posture.
    sim(&b.ms(), &["--for", "15.5s", "--trace", trace.to_str().unwrap(), &state_arg]);
    let heights: Vec<f64> =
        state(&truth).iter().filter(|s| s["time_ms"].as_u64().unwrap() >= 5300).map(|s| s["robots"][0]["pos"][2].as_f64().unwrap()).collect();
    assert!(heights.len() > 1200, "{} ground-truth frames after 5.3 s", heights.len());
    let (lo, hi) = heights.iter().fold((f64::MAX, f64::MIN), |(lo, hi), h| (lo.min(*h), hi.max(*h)));
    assert!(lo > 0.09 && hi < 0.18 && hi - lo < 0.01, "trunk height {lo:.3}..{hi:.3} m while standing 10 s");
    let standing = accel(&read_trace(&trace), 5300, 15500);
    assert!(mean(&standing, 2) > 8.5, "upright: a3 (up) should read ~g, got {:.2}", mean(&standing, 2));

    // The same run, shoved sideways at 6 s: the robot falls on its side.
    let trace = dir.path().join("pushed.jsonl");
    sim(&b.ms(), &["--for", "9s", "--trace", trace.to_str().unwrap(), "--sim-arg=--push=6:0,80,0"]);
    let t = read_trace(&trace);
    let before = accel(&t, 5300, 6000);
    let after = accel(&t, 8000, 9000);
    assert!(mean(&before, 2) > 8.5, "before the push a3 = {:.2}", mean(&before, 2));
    assert!(mean(&after, 2).abs() < 4.0 && mean(&after, 1).abs() > 7.0, "lying on its side: a2 = {:.2}, a3 = {:.2} m/s²", mean(&after, 1), mean(&after, 2));
}

/// movehead's head postures with imagesave's camera observer in one Memory Stick.
pub(crate) fn head_camera_ms() -> (Built, Built) {
    let head = build("movehead");
    let cam = build("imagesave");
    let conf = head.ms().join("OPEN-R/MW/CONF");
    copy_tree(&cam.ms().join("OPEN-R/MW/OBJS"), &head.ms().join("OPEN-R/MW/OBJS"));
    let mut objects = fs::read_to_string(conf.join("OBJECT.CFG")).unwrap();
    objects.push_str("/MS/OPEN-R/MW/OBJS/IMGSAVE.BIN\n");
    fs::write(conf.join("OBJECT.CFG"), objects).unwrap();
    let mut connect = fs::read_to_string(conf.join("CONNECT.CFG")).unwrap();
    connect.push_str(&fs::read_to_string(cam.ms().join("OPEN-R/MW/CONF/CONNECT.CFG")).unwrap());
    fs::write(conf.join("CONNECT.CFG"), connect).unwrap();
    (head, cam)
}

/// Centroid (x, y) and pixel count of the orange pixels of a saved layer-H BMP.
fn orange_blob(bmp: &[u8]) -> (f64, f64, usize) {
    let (w, h) = (208usize, 160usize);
    let (mut sx, mut sy, mut n) = (0.0, 0.0, 0usize);
    for y in 0..h {
        for x in 0..w {
            let o = 54 + ((h - 1 - y) * w + x) * 3;
            let (r, g, b) = (bmp[o + 2] as i32, bmp[o + 1] as i32, bmp[o] as i32);
            // Orange: green well under red (the yellow goal has g ≈ 0.85 r), no blue.
            if r > 150 && g * 100 < r * 65 && g * 100 > r * 25 && b < 60 {
                sx += x as f64;
                sy += y as f64;
                n += 1;
            }
        }
    }
    (sx / n.max(1) as f64, sy / n.max(1) as f64, n)
}

#[test]
fn a_ball_in_front_of_the_camera_shows_up_where_geometry_says() {
    let (head, _cam) = head_camera_ms();
    let dir = tempfile::tempdir().unwrap();
    let truth = dir.path().join("s.jsonl");
    let out = sim(&head.ms(), &["--for", "1.2s", "--sim-arg=--ball=0.8,0.1", &format!("--sim-arg=--state={}", truth.display())]);
    let saved = out.lines_starting("ImageSave : saved /MS/IMG2.BMP frame ");
    let frame: u64 = saved.first().unwrap_or_else(|| panic!("no IMG2.BMP saved:\n{}", out.stdout)).rsplit(' ').next().unwrap().parse().unwrap();
    let s = state(&truth).into_iter().find(|s| s["frame"] == frame).expect("ground truth of the image's frame");
    // Project the ball's centre with the camera pose (MuJoCo camera: looks along -z, x
    // right, y up) and the ERS-7's 45.2° vertical field of view, onto layer H (208 × 160).
    let f = |v: &Value| v.as_f64().unwrap();
    let cam = &s["robots"][0]["picture"]; // the camera when the picture was exposed
    let (p, m): (Vec<f64>, Vec<f64>) = (cam["pos"].as_array().unwrap().iter().map(f).collect(), cam["xmat"].as_array().unwrap().iter().map(f).collect());
    let ball: Vec<f64> = s["ball"].as_array().unwrap().iter().map(f).collect();
    let d: Vec<f64> = (0..3).map(|i| ball[i] - p[i]).collect();
    let c: Vec<f64> = (0..3).map(|j| (0..3).map(|i| m[3 * i + j] * d[i]).sum()).collect();
    let focal = 80.0 / (45.2f64.to_radians() / 2.0).tan();
    let (u, v) = (104.0 + focal * c[0] / -c[2], 80.0 - focal * c[1] / -c[2]);
    assert!((10.0..198.0).contains(&u) && (10.0..150.0).contains(&v), "the ball should be well inside the picture: ({u:.1}, {v:.1})");
    let (x, y, n) = orange_blob(&fs::read(head.ms().join("IMG2.BMP")).unwrap());
    // A 85 mm ball at this distance is ~20 px across: ~300 px of it.
    let radius = focal * 0.0425 / -c[2];
    let area = std::f64::consts::PI * radius * radius;
    assert!(n as f64 > 0.5 * area && (n as f64) < 1.6 * area, "{n} orange pixels, the ball covers {area:.0}");
    // Pixel x spans [x, x + 1) of the projection's coordinates: its centre is x + 0.5.
    let (x, y) = (x + 0.5, y + 0.5);
    assert!((x - u).abs() < 1.5 && (y - v).abs() < 1.5, "ball seen at ({x:.1}, {y:.1}), geometry says ({u:.1}, {v:.1})");
}

#[test]
fn the_same_seed_gives_byte_identical_traces() {
    let b = build("movelegs");
    let dir = tempfile::tempdir().unwrap();
    let run = |tag: &str, seed: &str| {
        let trace = dir.path().join(format!("{tag}.jsonl"));
        sim(&b.ms(), &["--for", "2.5s", "--seed", seed, "--trace", trace.to_str().unwrap()]);
        fs::read(&trace).unwrap()
    };
    let (a, b2, c) = (run("a", "7"), run("b", "7"), run("c", "8"));
    assert!(a.len() > 10_000);
    assert!(a == b2, "two runs with seed 7 differ");
    // The seed reaches the simulation (sensor noise): another seed, another trace.
    assert!(a != c, "seeds 7 and 8 gave the same trace");
}

/// `--pipeline`: the peer answers each frame with the state it begins with and steps
/// while the runtime works. Still reproducible, still tracking, and not the same run.
#[test]
fn a_pipelined_simulation_is_reproducible_and_still_tracks_the_commands() {
    let b = build("movelegs");
    let dir = tempfile::tempdir().unwrap();
    let run = |tag: &str, extra: &[&str]| {
        let trace = dir.path().join(format!("{tag}.jsonl"));
        let mut args = vec!["--for", "6s", "--trace", trace.to_str().unwrap()];
        args.extend_from_slice(extra);
        sim(&b.ms(), &args);
        fs::read(&trace).unwrap()
    };
    let (a, a2, plain) = (run("a", &["--sim-arg=--pipeline"]), run("b", &["--sim-arg=--pipeline"]), run("c", &[]));
    assert!(a == a2, "two pipelined runs differ");
    assert!(a != plain, "--pipeline changed nothing");
    let t = read_trace(&dir.path().join("a.jsonl"));
    let (max, rms) = tracking_error(&t, LF_J1, 160, 640);
    assert!(max < 10.0 && rms < 5.0, "pipelined LF J1: max {max:.1}°, RMS {rms:.1}° off its targets");
}

#[test]
fn several_robots_run_their_own_programs_and_collide() {
    let legs = build("movelegs");
    let head = build("movehead");
    let dir = tempfile::tempdir().unwrap();
    // Two robots 0.45 m apart nose to nose; robot 0 is shoved into robot 1 at 1.5 s.
    let scene = dir.path().join("duel.xml");
    let stock = fs::read_to_string(crate::support::repo().join("sim/mujoco/scene.xml")).unwrap();
    let sites = "<site name=\"start0\" pos=\"0 0 0\"/>\n<site name=\"start1\" pos=\"0.45 0 0\" euler=\"0 0 180\"/>\n</worldbody>";
    fs::write(&scene, stock.replace("</worldbody>", sites).replace("pos=\"0.5 0 0.0425\"", "pos=\"1.5 1 0.0425\"")).unwrap();
    let (trace, truth) = (dir.path().join("t.jsonl"), dir.path().join("s.jsonl"));
    let out = sim(
        &legs.ms(),
        &[
            head.ms().to_str().unwrap(),
            "--for",
            "6s",
            "--scene",
            scene.to_str().unwrap(),
            "--trace",
            trace.to_str().unwrap(),
            &format!("--sim-arg=--state={}", truth.display()),
            "--sim-arg=--push=1.5:60,0,0@0",
        ],
    );
    assert!(out.stdout.contains("[robot 0] MovingLegs : done"), "{}", out.stdout);
    assert!(out.stdout.contains("[robot 1] MovingHead : done, 5 postures"), "{}", out.stdout);
    // Each runtime traces its own robot: robot 0 commands legs only, robot 1 the head only.
    let (t0, t1) = (read_trace(&trace), read_trace(&dir.path().join("t.r1.jsonl")));
    assert!(!targets(&t0, LF_J1).is_empty() && targets(&t0, PAN).is_empty(), "robot 0 runs movelegs");
    assert!(targets(&t1, LF_J1).is_empty() && !targets(&t1, PAN).is_empty(), "robot 1 runs movehead");
    assert!(readings(&t1, PAN).values().any(|v| v.abs() > 50.0), "robot 1 turns its head");
    // The trunks (0.19 m long) never pass through each other, and robot 1 is pushed back.
    let s = state(&truth);
    let x = |s: &Value, k: usize| s["robots"][k]["pos"][0].as_f64().unwrap();
    let gap = s.iter().map(|s| x(s, 1) - x(s, 0)).fold(f64::MAX, f64::min);
    assert!(gap > 0.15, "robot 0 went through robot 1: trunk centres {gap:.3} m apart");
    let (start, end) = (x(&s[0], 1), x(s.last().unwrap(), 1));
    assert!(end - start > 0.03, "robot 1 should be pushed back by the collision: x {start:.3} -> {end:.3}");
}

#[test]
fn simulator_errors_are_clear_and_nothing_hangs() {
    let b = build("hello");
    let ms = b.ms();
    let dir = tempfile::tempdir().unwrap();
    let bad_scene = dir.path().join("bad.xml");
    fs::write(&bad_scene, "<mujoco>\n  <worldbody>\n    <geom type=\"sphere\" size=\"oops\"/>\n  </worldbody>\n</mujoco>\n").unwrap();
    let cases: Vec<(Vec<String>, &str)> = vec![
        (vec!["--scene".into(), "/nonexistent/field.xml".into()], "--scene /nonexistent/field.xml: no such file"),
        (vec!["--scene".into(), bad_scene.display().to_string()], "bad.xml: not a MuJoCo scene"),
        (vec!["--robots".into(), "0".into()], "give 1 to 30 robots"),
        (vec!["--sim-arg=--push=soon".into()], "--push soon: expected TIME:FX,FY,FZ"),
        (vec!["--robot-wait".into()], "attaches the simulator itself"),
    ];
    for (extra, want) in cases {
        let mut args = vec!["--sim", "mujoco", "--for", "1s"];
        args.extend(extra.iter().map(String::as_str));
        let out = run_ms(&ms, &args);
        assert_ne!(out.code, Some(0), "{extra:?} should fail");
        assert!(out.stderr.contains(want), "{extra:?}: expected `{want}` in:\n{}", out.stderr);
        assert!(!out.stderr.contains("Traceback") && !out.stderr.contains("panicked"), "{}", out.stderr);
    }
    let out = run_ms(&ms, &["--seed", "3"]);
    assert!(out.code != Some(0) && out.stderr.contains("--seed needs a simulated world: add `--sim mujoco`"), "{}", out.stderr);
    // A robot whose runtime fails stops the world at once (the peer would wait for it).
    let started = std::time::Instant::now();
    let out = run_ms(&dir.path().join("no-such-ms"), &["--sim", "mujoco", "--for", "1s"]);
    assert_ne!(out.code, Some(0));
    assert!(out.stderr.contains("robot 0: the runtime failed") && out.stderr.contains("No such file"), "{}", out.stderr);
    assert!(started.elapsed() < std::time::Duration::from_secs(20), "took {:?}", started.elapsed());
    // No MuJoCo where cargo-openr looks, or no usable GL: say what installs it.
    for env in [("OPENR_PYTHON", "/nonexistent/python3"), ("MUJOCO_GL", "nonsense")] {
        let out = crate::support::spawn_ms(&ms, &["--sim", "mujoco", "--for", "1s"], &[env]).wait(std::time::Duration::from_secs(60));
        assert_ne!(out.code, Some(0), "{env:?}");
        assert!(out.stderr.contains("the MuJoCo simulator cannot start") && out.stderr.contains("tools/deps.sh"), "{env:?}: {}", out.stderr);
        assert!(!out.stderr.contains("Traceback"), "{}", out.stderr);
    }
}

/// The Python that `cargo openr run --sim mujoco` uses (ops/sim.rs python()).
fn sim_python() -> std::path::PathBuf {
    // As `ops::sim::python` looks for it (and tools/deps.sh makes it): $OPENR_PYTHON,
    // else the venv under $XDG_CACHE_HOME (~/.cache), else python3.
    if let Some(p) = std::env::var_os("OPENR_PYTHON").filter(|p| !p.is_empty()) {
        return p.into();
    }
    let cache = std::env::var_os("XDG_CACHE_HOME").filter(|v| !v.is_empty()).map(std::path::PathBuf::from);
    let cache = cache.unwrap_or_else(|| Path::new(&std::env::var_os("HOME").unwrap()).join(".cache"));
    let venv = cache.join("cargo-openr/mujoco-venv/bin/python");
    if venv.is_file() {
        venv
    } else {
        "python3".into()
    }
}

/// A runtime that answers the peer's HELLO with something that is not the protocol: the
/// peer says what it expected and what came, and exits 2 (no traceback, no hang).
#[test]
fn a_bad_message_header_stops_the_peer_with_what_came() {
    let err = peer_answered_with(Some(b"HTTP/1.1 200 OK\r\n\r\n"));
    let want = "robot 0: bad message header: expected magic b'ORP1' version 1, got magic b'HTTP' version 12591 (bytes 48 54 54 50 2f 31";
    assert!(err.contains(want), "expected `{want}` in:\n{err}");
}

#[test]
fn a_runtime_leaving_before_its_welcome_stops_the_peer_with_what_happened() {
    let err = peer_answered_with(None);
    let want = "robot 0: the runtime closed the connection before its WELCOME";
    assert!(err.contains(want), "expected `{want}` in:\n{err}");
}

/// Starts the peer on a socket of the test's, reads its HELLO and answers `reply` (or
/// closes the connection): the peer must stop with exit code 2 and no traceback; its
/// stderr.
fn peer_answered_with(reply: Option<&[u8]>) -> String {
    use std::io::{Read, Write};
    use std::os::unix::net::UnixListener;
    use std::time::{Duration, Instant};
    let dir = tempfile::tempdir().unwrap();
    let sock = dir.path().join("r.sock");
    let listener = UnixListener::bind(&sock).unwrap();
    listener.set_nonblocking(true).unwrap();
    let mut peer = std::process::Command::new(sim_python())
        .arg(crate::support::repo().join("sim/mujoco/peer.py"))
        .args([sock.to_str().unwrap(), "--no-camera", "--quiet"])
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let deadline = Instant::now() + Duration::from_secs(60);
    let mut conn = loop {
        match listener.accept() {
            Ok((c, _)) => break c,
            Err(_) if Instant::now() < deadline && peer.try_wait().unwrap().is_none() => std::thread::sleep(Duration::from_millis(20)),
            Err(e) => panic!("the peer did not attach: {e}; {:?}", peer.wait_with_output()),
        }
    };
    conn.set_nonblocking(false).unwrap();
    conn.set_read_timeout(Some(Duration::from_secs(30))).unwrap();
    let mut head = [0u8; 16]; // the HELLO's header, then its payload
    conn.read_exact(&mut head).unwrap();
    assert_eq!(&head[..4], b"ORP1");
    let mut hello = vec![0u8; u32::from_le_bytes(head[8..12].try_into().unwrap()) as usize];
    conn.read_exact(&mut hello).unwrap();
    match reply {
        Some(bytes) => conn.write_all(bytes).unwrap(),
        None => drop(conn),
    }
    let out = peer.wait_with_output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(!err.contains("Traceback"), "{err}");
    err
}

/// The peer's buffered reader (sim/mujoco/wire.py) against a real socket pair: split
/// messages, compaction, growth past 64 KiB, bad header, EOF (sim/mujoco/test_wire.py;
/// plain Python, no MuJoCo needed).
#[test]
fn the_peer_reads_the_protocol_from_any_split_of_the_stream() {
    let repo = crate::support::repo();
    let out = std::process::Command::new("python3")
        .args(["-m", "unittest", "-v", "sim/mujoco/test_wire.py"])
        .current_dir(&repo)
        .env("PYTHONPATH", format!("{}:{}", repo.join("sim/mujoco").display(), repo.join("tools").display()))
        .output()
        .expect("python3 runs");
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{err}");
    assert!(err.contains("Ran 5 tests"), "{err}");
}
