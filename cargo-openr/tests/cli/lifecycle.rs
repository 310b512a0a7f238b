//! Failures never look like success: an object stuck in a life-cycle function or a
//! panicking Rust object fails the run, named with what it was doing; signals end
//! every phase, the boot included; at `--speed max` a busy object does not stop time.
use std::path::Path;
use std::time::Duration;

use crate::support::{build, cargo_openr_in, run_ms, sdk_root, spawn_ms, Built};

/// The stuck program, spinning in `hook` (DoInit, DoStart or DoStop).
fn stuck_in(hook: &str) -> Built {
    let p = build("stuck");
    std::fs::write(p.ms().join("OPEN-R/MW/DATA/P/STUCK.TXT"), format!("{hook}\n")).unwrap();
    p
}

#[test]
fn an_object_that_never_answers_stop_fails_the_run_by_name() {
    let p = stuck_in("DoStop");
    let out = run_ms(&p.ms(), &["--speed", "max", "--for", "1s", "--watchdog", "1s"]);
    assert!(out.stdout.contains("Stuck : spinning in DoStop"), "{}", out.stdout);
    assert!(out.code.is_some_and(|c| c != 0), "exit {:?}\n{}", out.code, out.stderr);
    assert!(out.stderr.contains("object `stuck` did not answer Stop within 1.0 s: it is still running DoStop"), "{}", out.stderr);
}

#[test]
fn a_busy_do_start_at_max_speed_does_not_stop_virtual_time() {
    let p = stuck_in("DoStart");
    let out = run_ms(&p.ms(), &["--speed", "max", "--for", "1s", "--watchdog", "1s"]);
    assert!(out.stdout.contains("Stuck : spinning in DoStart"), "{}", out.stdout);
    assert!(out.stderr.contains("object `stuck` has been running DoStart for more than the watchdog's time"), "{}", out.stderr);
    assert!(out.stderr.contains("(time limit reached; 125 frames"), "--for 1s ran its 125 frames:\n{}", out.stderr);
    assert!(out.code.is_some_and(|c| c != 0), "exit {:?}\n{}", out.code, out.stderr);
    assert!(out.stderr.contains("object `stuck` did not answer Stop within 1.0 s: it is still running DoStart"), "{}", out.stderr);
}

#[test]
fn sigterm_ends_a_boot_stuck_in_do_init_naming_the_object() {
    let p = stuck_in("DoInit");
    let mut run = spawn_ms(&p.ms(), &["--speed", "max", "--for", "1s", "--watchdog", "1s"], &[]);
    assert!(run.wait_for("Stuck : spinning in DoInit", Duration::from_secs(30)), "{}", run.stderr());
    let out = run.stop();
    assert!(out.code.is_some_and(|c| c != 0), "SIGTERM must end the run by itself, non-zero: exit {:?}\n{}", out.code, out.stderr);
    assert!(out.stderr.contains("object `stuck` did not answer Init: it is still running DoInit when signal 15 came"), "{}", out.stderr);
}

#[test]
fn a_panicking_rust_object_fails_the_run_naming_it() {
    let tmp = tempfile::tempdir().unwrap();
    let out = cargo_openr_in(tmp.path(), &["new", "panic-dog", "--template", "rust-object"], &[]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let dir = tmp.path().join("panic-dog");
    let lib = dir.join("PanicDogSubject/src/lib.rs");
    let src = std::fs::read_to_string(&lib).unwrap();
    let at = src.find("fn ready(").expect("the template has a ready function");
    let body = at + src[at..].find('{').unwrap() + 1;
    let patched = format!("{}\n        panic!(\"the ball is gone\");\n{}", &src[..body], &src[body..]);
    std::fs::write(&lib, patched).unwrap();
    let target = Path::new(env!("CARGO_TARGET_TMPDIR")).join("build-rust-objects");
    let root = sdk_root().to_str().unwrap().to_string();
    let built = cargo_openr_in(&dir, &["build", "--sdk", &root], &[("CARGO_TARGET_DIR", target.to_str().unwrap())]);
    assert!(built.status.success(), "{}", String::from_utf8_lossy(&built.stderr));
    let out = run_ms(&dir.join("MS"), &["--speed", "max", "--for", "1s"]);
    assert!(out.code.is_some_and(|c| c != 0), "a panic is not a success: exit {:?}\n{}\n{}", out.code, out.stdout, out.stderr);
    assert!(out.stderr.contains("the ball is gone"), "the panic message:\n{}", out.stderr);
    // The crash report names the object (its ocf name) and what it was running.
    assert!(
        out.stderr.contains("object `panicDogSubject` (/MS/OPEN-R/MW/OBJS/PANICDOS.BIN) crashed with SIGABRT"),
        "the object is named:\n{}\n{}",
        out.stdout,
        out.stderr
    );
}

#[test]
fn a_panic_inside_the_runtime_stops_at_the_call_and_fails_the_run() {
    // MicRate calls OPENR::GetRobotDesign in DoInit; the hook makes the runtime's side panic.
    let b = build("micrate");
    let run = spawn_ms(&b.ms(), &["--speed", "max", "--for", "1s"], &[("OPENR_INJECT_PANIC", "robot_design")]);
    let out = run.wait(Duration::from_secs(120));
    assert!(
        out.stderr.contains("error: internal error in cargo-openr: the runtime's `robot_design` (called by object `micRate`) panicked: injected"),
        "{}",
        out.stderr
    );
    // the call returned its failure value and the program went on to its end
    assert!(out.stderr.contains("time limit reached"), "{}", out.stderr);
    assert!(out.stderr.contains("1 call(s) into the runtime panicked"), "{}", out.stderr);
    assert!(out.code.is_some_and(|c| c != 0), "exit {:?}\n{}", out.code, out.stderr);
}

#[test]
fn openr_fatal_powers_the_robot_off_without_stop_and_fails_the_run() {
    let b = build("fatal");
    let out = run_ms(&b.ms(), &["--speed", "max", "--for", "5s"]);
    assert!(out.stdout.contains("Params : can't open /MS/OPEN-R/MW/DATA/P/PARAMS.TXT"), "{}", out.stdout);
    assert!(
        out.stderr.contains("error: object `params` called OPENR::Fatal(ofatalMEMORY_STICK: the memory-stick error sound); the robot powers off"),
        "{}",
        out.stderr
    );
    // nothing of the object runs after the call: not the rest of DoStart, not DoStop
    assert!(!out.stdout.contains("still running after Fatal") && !out.stdout.contains("Params : DoStop"), "{}", out.stdout);
    assert!(out.stderr.contains("(OPENR::Fatal;"), "{}", out.stderr);
    assert!(out.stderr.contains("the program called OPENR::Fatal(0x0) and the robot powered off"), "{}", out.stderr);
    assert!(out.code.is_some_and(|c| c != 0), "exit {:?}", out.code);

    // with its parameters the same program runs to the time limit and stops cleanly
    std::fs::create_dir_all(b.ms().join("OPEN-R/MW/DATA/P")).unwrap();
    std::fs::write(b.ms().join("OPEN-R/MW/DATA/P/PARAMS.TXT"), "0.5\n1.25\n-3\n").unwrap();
    let out = run_ms(&b.ms(), &["--speed", "max", "--for", "1s"]);
    assert!(out.stdout.contains("Params : 3 parameters loaded") && out.stdout.contains("Params : DoStop"), "{}", out.stdout);
    assert_eq!(out.code, Some(0), "{}", out.stderr);
}

#[test]
fn the_runtime_reports_through_the_shell_in_its_colours() {
    let b = build("fatal");
    let out = run_ms(&b.ms(), &["--speed", "max", "--for", "5s", "--color", "always"]);
    assert!(out.stderr.contains("\x1b[1;31merror:\x1b[0m object `params` called OPENR::Fatal("), "{:?}", out.stderr);
    let plain = run_ms(&b.ms(), &["--speed", "max", "--for", "5s", "--color", "never"]);
    assert!(plain.stderr.contains("\nerror: object `params` called OPENR::Fatal(") && !plain.stderr.contains('\x1b'), "{:?}", plain.stderr);
}
