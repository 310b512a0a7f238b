//! `cargo openr build`: every `new` template (hello, subject-observer, walk, rust-object) builds without make and runs; no-op and
//! touched rebuilds; `compile_commands.json` replays; JSON lines; compiler errors.
use std::fs;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use crate::support::{cargo_openr_in, run, run_ms, sdk_root};

fn text(out: &Output) -> String {
    format!("{}{}", String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr))
}

/// One cargo target directory for every Rust object these tests build (debug profile).
fn rust_target() -> PathBuf {
    Path::new(env!("CARGO_TARGET_TMPDIR")).join("build-rust-objects")
}

fn build(dir: &Path, extra: &[&str]) -> Output {
    let root = sdk_root().to_str().unwrap().to_string();
    let target = rust_target();
    let mut args = vec!["build", "--sdk", root.as_str()];
    args.extend_from_slice(extra);
    cargo_openr_in(dir, &args, &[("CARGO_TARGET_DIR", target.to_str().unwrap())])
}

/// `cargo openr new test-dog --template T`, then `cargo openr build`; returns the project.
fn new_and_build(template: &str) -> (tempfile::TempDir, PathBuf, Output) {
    let tmp = tempfile::tempdir().unwrap();
    let out = cargo_openr_in(tmp.path(), &["new", "test-dog", "--template", template], &[]);
    assert!(out.status.success(), "new --template {template}: {}", text(&out));
    let dir = tmp.path().join("test-dog");
    let out = build(&dir, &[]);
    assert!(out.status.success(), "build of the new {template} project: {}", text(&out));
    (tmp, dir, out)
}

fn run_1s(dir: &Path) -> String {
    let r = run_ms(&dir.join("MS"), &["--for", "1s", "--sdk", sdk_root().to_str().unwrap()]);
    assert_eq!(r.code, Some(0), "run: {}\n{}", r.stdout, r.stderr);
    r.stdout
}

fn compiling_lines(out: &Output) -> Vec<String> {
    String::from_utf8_lossy(&out.stderr).lines().filter(|l| l.trim_start().starts_with("Compiling")).map(str::to_string).collect()
}

#[test]
fn hello_builds_runs_and_second_build_is_a_no_op() {
    let (_tmp, dir, first) = new_and_build("hello");
    assert_eq!(compiling_lines(&first), ["   Compiling TestDog (C++)"], "{}", text(&first));
    assert!(String::from_utf8_lossy(&first.stderr).contains("    Finished "), "{}", text(&first));
    let stdout = run_1s(&dir);
    assert!(stdout.contains("!!! Hello from TestDog !!!"), "{stdout}");

    let again = build(&dir, &["--message-format", "json"]);
    assert!(again.status.success(), "{}", text(&again));
    assert!(compiling_lines(&again).is_empty(), "{}", text(&again));
    let lines: Vec<serde_json::Value> =
        String::from_utf8_lossy(&again.stdout).lines().map(|l| serde_json::from_str(l).unwrap_or_else(|e| panic!("not JSON: {l}: {e}"))).collect();
    assert!(lines.iter().all(|v| v["reason"] != "compiling"), "{lines:?}");
    assert!(lines.iter().any(|v| v["reason"] == "compiler-artifact" && v["fresh"] == true), "{lines:?}");
    assert_eq!(lines.last().unwrap()["reason"], "build-finished");
}

#[test]
fn subject_observer_touch_rebuilds_one_object_and_compile_commands_replay() {
    let (_tmp, dir, first) = new_and_build("subject-observer");
    assert_eq!(compiling_lines(&first).len(), 2, "{}", text(&first));
    let stdout = run_1s(&dir);
    assert!(stdout.contains("TestDogObserver : received \"hello 1 from TestDogSubject\""), "{stdout}");

    // Make the touch visible to a coarse mtime.
    std::thread::sleep(std::time::Duration::from_millis(20));
    let src = dir.join("TestDogObserver/TestDogObserver.cc");
    let f = fs::OpenOptions::new().append(true).open(&src).unwrap();
    f.set_modified(std::time::SystemTime::now()).unwrap();
    let again = build(&dir, &[]);
    assert!(again.status.success(), "{}", text(&again));
    assert_eq!(compiling_lines(&again), ["   Compiling TestDogObserver (C++)"], "{}", text(&again));

    let cc: Vec<serde_json::Value> = serde_json::from_str(&fs::read_to_string(dir.join("compile_commands.json")).unwrap()).unwrap();
    assert_eq!(cc.len(), 4, "{cc:?}");
    for e in &cc {
        let args: Vec<&str> = e["arguments"].as_array().unwrap().iter().map(|a| a.as_str().unwrap()).collect();
        let (ok, log) = run(Command::new(args[0]).args(&args[1..]).arg("-fsyntax-only").current_dir(e["directory"].as_str().unwrap()));
        assert!(ok, "replaying {args:?}: {log}");
    }
}

#[test]
fn walk_builds_and_runs() {
    let (_tmp, dir, _) = new_and_build("walk");
    let stdout = run_1s(&dir);
    assert!(stdout.contains("TestDog : posture 0 (stand)"), "{stdout}");
}

#[test]
fn compile_error_shows_file_and_line_and_fails() {
    let tmp = tempfile::tempdir().unwrap();
    let out = cargo_openr_in(tmp.path(), &["new", "test-dog"], &[]);
    assert!(out.status.success(), "{}", text(&out));
    let dir = tmp.path().join("test-dog");
    let src = dir.join("TestDog/TestDog.cc");
    let mut code = fs::read_to_string(&src).unwrap();
    code.push_str("\nint broken() { return undeclared_thing; }\n");
    fs::write(&src, code).unwrap();
    let out = build(&dir, &[]);
    assert!(!out.status.success(), "{}", text(&out));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("TestDog.cc:") && err.contains("undeclared_thing"), "{err}");
    assert!(err.contains("error: could not compile `TestDog` (C++)"), "{err}");

    let out = build(&dir, &["--message-format", "json"]);
    assert!(!out.status.success());
    let lines: Vec<serde_json::Value> = String::from_utf8_lossy(&out.stdout).lines().map(|l| serde_json::from_str(l).unwrap()).collect();
    assert!(lines.iter().any(|v| v["reason"] == "compiler-message" && v["message"]["rendered"].as_str().unwrap().contains("undeclared_thing")));
    assert_eq!(lines.last().unwrap()["success"], false);
}

#[test]
fn rust_object_template_builds_and_runs() {
    let (_tmp, dir, first) = new_and_build("rust-object");
    assert!(dir.join("MS/OPEN-R/MW/OBJS/TESTDOGS.BIN").is_file() && dir.join("MS/OPEN-R/MW/OBJS/TESTDOGO.BIN").is_file());
    assert!(compiling_lines(&first).contains(&"   Compiling TestDogObserver (C++)".to_string()), "{}", text(&first));
    let stdout = run_1s(&dir);
    let received: Vec<&str> = stdout.lines().filter(|l| l.starts_with("TestDogObserver : received")).collect();
    assert_eq!(received, (1..=3).map(|i| format!("TestDogObserver : received \"hello {i} from TestDogSubject\"")).collect::<Vec<_>>(), "{stdout}");
    let again = build(&dir, &["--message-format", "json"]);
    assert!(again.status.success(), "{}", text(&again));
    assert!(compiling_lines(&again).is_empty(), "{}", text(&again));
    for l in String::from_utf8_lossy(&again.stdout).lines() {
        let v: serde_json::Value = serde_json::from_str(l).unwrap_or_else(|e| panic!("not JSON: {l}: {e}"));
        assert_ne!(v["reason"], "compiling", "{l}");
    }
}
