//! Virtual time: `--speed max` runs are reproducible, `--for` counts virtual time, and
//! the control socket pauses, steps and resumes the robot.
use std::io::{BufRead, BufReader, Write};
use std::os::unix::net::UnixStream;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use crate::support::{build, exe, run_ms, sdk_root};

#[test]
fn runs_at_max_speed_are_byte_identical() {
    let p = build("movelegs");
    let dir = tempfile::tempdir().unwrap();
    let mut outputs = Vec::new();
    for i in 0..2 {
        let trace = dir.path().join(format!("t{i}.jsonl"));
        let out = run_ms(&p.ms(), &["--speed", "max", "--for", "6s", "--trace", trace.to_str().unwrap()]);
        assert_eq!(out.code, Some(0), "{}", out.stderr);
        outputs.push((out.stdout, std::fs::read_to_string(&trace).unwrap()));
    }
    assert_eq!(outputs[0].0, outputs[1].0, "same console output");
    assert!(outputs[0].1 == outputs[1].1, "same trace, byte for byte");
    let last: serde_json::Value = serde_json::from_str(outputs[0].1.lines().last().unwrap()).unwrap();
    let t = last["t_ms"].as_u64().unwrap();
    assert!((5900..=6000).contains(&t), "--for 6s is virtual time: the trace ends at {t} ms");
    assert!(outputs[0].0.contains("MovingLegs : done"), "the whole program ran:\n{}", outputs[0].0);
}

fn ask(conn: &mut UnixStream, reader: &mut BufReader<UnixStream>, cmd: &str) -> String {
    writeln!(conn, "{cmd}").unwrap();
    let mut line = String::new();
    reader.read_line(&mut line).unwrap();
    line.trim().to_string()
}

fn t_ms(answer: &str) -> u64 {
    answer.split_whitespace().find_map(|w| w.strip_prefix("t_ms=")).and_then(|v| v.parse().ok()).unwrap_or_else(|| panic!("no t_ms in {answer:?}"))
}

#[test]
fn control_socket_pauses_steps_and_resumes() {
    let p = build("movelegs");
    let dir = tempfile::tempdir().unwrap();
    let sock = dir.path().join("control.sock");
    let mut child = Command::new(exe())
        .env("OPENRSDK_ROOT", sdk_root())
        .args(["run", "-q", "--control", sock.to_str().unwrap()])
        .arg(p.ms())
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let start = Instant::now();
    let mut conn = loop {
        match UnixStream::connect(&sock) {
            Ok(c) => break c,
            Err(_) if start.elapsed() < Duration::from_secs(30) => std::thread::sleep(Duration::from_millis(20)),
            Err(e) => panic!("no control socket: {e}"),
        }
    };
    let mut reader = BufReader::new(conn.try_clone().unwrap());
    let paused = ask(&mut conn, &mut reader, "pause");
    assert!(paused.starts_with("ok t_ms="), "{paused}");
    std::thread::sleep(Duration::from_millis(100));
    let status = ask(&mut conn, &mut reader, "status");
    assert!(status.contains("paused=true"), "{status}");
    assert_eq!(t_ms(&status), t_ms(&paused), "no virtual time passes while paused");
    let stepped = ask(&mut conn, &mut reader, "step 10");
    assert_eq!(t_ms(&stepped), t_ms(&paused) + 80, "10 frames of 8 ms: {stepped}");
    assert!(ask(&mut conn, &mut reader, "speed fast").starts_with("error: "));
    let tiny = ask(&mut conn, &mut reader, "speed 1e-300");
    assert!(tiny.starts_with("error: ") && tiny.contains("0.01 to 1000"), "{tiny}");
    assert!(ask(&mut conn, &mut reader, "jump").starts_with("error: unknown command"));
    assert_eq!(ask(&mut conn, &mut reader, "speed max"), "ok");
    assert!(ask(&mut conn, &mut reader, "resume").starts_with("ok"));
    std::thread::sleep(Duration::from_millis(200));
    let later = ask(&mut conn, &mut reader, "status");
    assert!(t_ms(&later) > t_ms(&stepped), "time runs again: {later}");
    assert_eq!(ask(&mut conn, &mut reader, "shutdown"), "ok");
    let status = loop {
        if let Some(st) = child.try_wait().unwrap() {
            break st;
        }
        assert!(start.elapsed() < Duration::from_secs(60), "runtime did not stop");
        std::thread::sleep(Duration::from_millis(20));
    };
    assert!(status.success());
}

#[test]
fn numeric_options_out_of_range_are_refused_by_name() {
    let p = build("hello");
    let ms = p.ms();
    let run = |args: &[&str], env: &[(&str, &str)]| {
        let out = Command::new(exe()).env("OPENRSDK_ROOT", sdk_root()).envs(env.iter().copied()).arg("run").arg(&ms).args(args).output().unwrap();
        (out.status.code(), String::from_utf8_lossy(&out.stderr).into_owned())
    };
    for speed in ["1e-300", "0.001", "5000", "inf"] {
        let (code, err) = run(&["--speed", speed, "--for", "1s"], &[]);
        assert!(code.is_some_and(|c| c != 0), "--speed {speed} ran: {err}");
        assert!(err.contains("--speed") && err.contains("0.01 to 1000"), "--speed {speed}: {err}");
        assert!(!err.contains("panicked"), "{err}");
    }
    let (code, err) = run(&["--for", "1s"], &[("OPENR_SPEED", "1e-300")]);
    assert!(code.is_some_and(|c| c != 0) && err.contains("OPENR_SPEED") && err.contains("0.01 to 1000"), "{err}");
    let (code, err) = run(&["--for", "1e300s"], &[]);
    assert!(code.is_some_and(|c| c != 0) && err.contains("--for") && err.contains("too long"), "{err}");
    assert!(!err.contains("panicked"), "{err}");
}

/// movelegs and blinkleds in one Memory Stick: six subjects of the one effector, like
/// MovingLegs7 (connection ids are given by whose first vector arrives first).
fn legs_and_leds() -> (crate::support::Built, crate::support::Built, std::path::PathBuf) {
    let (legs, leds) = (build("movelegs"), build("blinkleds"));
    let ms = legs.dir.path().join("legs-and-leds/MS");
    let conf = ms.join("OPEN-R/MW/CONF");
    std::fs::create_dir_all(&conf).unwrap();
    crate::support::copy_tree(&legs.ms().join("OPEN-R/MW/OBJS"), &ms.join("OPEN-R/MW/OBJS"));
    crate::support::copy_tree(&leds.ms().join("OPEN-R/MW/OBJS"), &ms.join("OPEN-R/MW/OBJS"));
    for cfg in ["OBJECT.CFG", "CONNECT.CFG"] {
        let text = [&legs, &leds].iter().map(|p| std::fs::read_to_string(p.ms().join("OPEN-R/MW/CONF").join(cfg)).unwrap()).collect::<Vec<_>>().join("\n");
        std::fs::write(conf.join(cfg), text).unwrap();
    }
    (legs, leds, ms)
}

#[test]
fn multi_object_programs_are_byte_identical_over_20_runs() {
    let multi = build("objcomm-multi");
    let leds = build("blinkleds");
    let (_legs, _leds, combo) = legs_and_leds();
    let dir = tempfile::tempdir().unwrap();
    for (name, ms) in [("objcomm-multi", multi.ms()), ("blinkleds", leds.ms()), ("movelegs+blinkleds", combo)] {
        let mut distinct = std::collections::BTreeSet::new();
        let mut first = None;
        for i in 0..20 {
            let trace = dir.path().join(format!("{name}{i}.jsonl"));
            let out = run_ms(&ms, &["--speed", "max", "--for", "1s", "--trace", trace.to_str().unwrap()]);
            assert_eq!(out.code, Some(0), "{name}: {}", out.stderr);
            let run = (out.stdout, std::fs::read(&trace).unwrap());
            first.get_or_insert_with(|| run.clone());
            distinct.insert(run);
        }
        let (stdout, trace) = first.unwrap();
        assert!(stdout.lines().count() >= 4 && (name == "objcomm-multi" || trace.len() > 1000), "{name} ran:\n{stdout}");
        assert_eq!(distinct.len(), 1, "{name}: 20 runs at --speed max gave {} different outputs", distinct.len());
    }
}

#[test]
fn objects_that_are_never_idle_still_see_time_pass() {
    let p = build("pingpong");
    let out = run_ms(&p.ms(), &["--speed", "max", "--for", "2s"]);
    assert_eq!(out.code, Some(0), "{}", out.stderr);
    assert!(out.stderr.contains("(time limit reached; 250 frames"), "--for 2s is 250 frames:\n{}", out.stderr);
    let warnings: Vec<&str> = out.stderr.lines().filter(|l| l.contains("never all idle")).collect();
    assert_eq!(warnings.len(), 1, "one warning:\n{}", out.stderr);
    assert!(warnings[0].contains("`ping`") && warnings[0].contains("`pong`"), "it names the busy objects: {}", warnings[0]);
    // The system time goes on while they play: each report later than the one before.
    let times: Vec<u64> = out.lines_starting("Ping : ").iter().filter_map(|l| l.strip_suffix(" ms")?.rsplit(' ').next()?.parse().ok()).collect();
    assert!(times.len() >= 3 && times.windows(2).all(|w| w[1] > w[0]) && *times.last().unwrap() <= 2000, "{times:?}\n{}", out.stdout);
    let again = run_ms(&p.ms(), &["--speed", "max", "--for", "2s"]);
    assert_eq!(again.stdout, out.stdout, "frames come after a counted number of messages: the same every run");
}
