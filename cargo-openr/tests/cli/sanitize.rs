//! Sanitizers: `cargo openr build --sanitize KIND` (and `OPENR_SANITIZE=KIND make
//! install`) instrument the objects, and `cargo openr run` starts such a stick with the
//! sanitizer's runtime preloaded by itself; each report names the source line.
//! `testdata/programs/sanitizers`: a signed overflow at Sloppy.cc:25, a heap overrun at :35.
use std::fs;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use crate::support::{cargo_openr_in, copy_tree, repo, run, run_ms, sdk_root};

fn text(out: &Output) -> String {
    format!("{}{}", String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr))
}

fn program() -> (tempfile::TempDir, PathBuf) {
    let tmp = tempfile::tempdir().unwrap();
    let dir = tmp.path().join("sanitizers");
    copy_tree(&repo().join("testdata/programs/sanitizers"), &dir);
    (tmp, dir)
}

fn openr_build(dir: &Path, sanitize: &str) {
    let out = cargo_openr_in(dir, &["build", "--sanitize", sanitize, "--sdk", sdk_root().to_str().unwrap()], &[]);
    assert!(out.status.success(), "{}", text(&out));
}

fn run_1s(dir: &Path) -> crate::support::RunOutput {
    run_ms(&dir.join("MS"), &["--for", "1s", "--speed", "max", "--sdk", sdk_root().to_str().unwrap()])
}

#[test]
fn the_bugs_are_silent_without_a_sanitizer() {
    let (_tmp, dir) = program();
    let (ok, log) = run(Command::new("make").arg(format!("OPENRSDK_ROOT={}", sdk_root().display())).arg("install").current_dir(&dir));
    assert!(ok, "{log}");
    let r = run_1s(&dir);
    assert_eq!(r.code, Some(0), "{}\n{}", r.stdout, r.stderr);
    assert!(r.stdout.contains("Sloppy : robot ERS-7M3"), "{}", r.stdout);
}

#[test]
fn address_sanitizer_reports_the_overrun_at_its_line_and_fails_the_run() {
    let (_tmp, dir) = program();
    openr_build(&dir, "address");
    let r = run_1s(&dir);
    assert_ne!(r.code, Some(0), "{}\n{}", r.stdout, r.stderr);
    assert!(r.stderr.contains("with the address sanitizer runtime preloaded"), "{}", r.stderr);
    assert!(r.stderr.contains("ERROR: AddressSanitizer: heap-buffer-overflow"), "{}", r.stderr);
    let frame0 = r.stderr.lines().skip_while(|l| !l.starts_with("WRITE of size 1")).nth(1).unwrap_or_default();
    assert!(frame0.contains("in Sloppy::DoStart(OSystemEvent const&)") && frame0.ends_with("Sloppy/Sloppy.cc:35"), "{}", r.stderr);
    assert!(!r.stdout.contains("Sloppy : robot"), "the run stopped at the overrun: {}", r.stdout);
    // The SDK libraries' frames name sources that exist in the installed root.
    let lib_frame = r.stderr.lines().find(|l| l.contains("in OObject::Start")).unwrap_or_else(|| panic!("{}", r.stderr));
    let src = lib_frame.rsplit(' ').next().unwrap().rsplit_once(':').unwrap().0;
    assert!(Path::new(src).is_file() && src.starts_with(sdk_root().to_str().unwrap()), "{lib_frame}");
}

#[test]
fn undefined_behaviour_sanitizer_reports_the_overflow_at_its_line() {
    let (_tmp, dir) = program();
    openr_build(&dir, "undefined");
    let r = run_1s(&dir);
    assert_ne!(r.code, Some(0), "halt_on_error by default: {}\n{}", r.stdout, r.stderr);
    assert!(r.stderr.contains("Sloppy/Sloppy.cc:25:10: runtime error: signed integer overflow: 2147483647 + 1"), "{}", r.stderr);
    assert!(r.stderr.contains("in Sloppy::DoInit(OSystemEvent const&)"), "{}", r.stderr);
}

#[test]
fn a_makefile_build_takes_the_sanitizer_from_openr_sanitize() {
    let (_tmp, dir) = program();
    let make = |value: &str| {
        Command::new("make")
            .arg(format!("OPENRSDK_ROOT={}", sdk_root().display()))
            .arg("install")
            .env("OPENR_SANITIZE", value)
            .current_dir(&dir)
            .output()
            .unwrap()
    };
    let bad = make("memory");
    assert_ne!(bad.status.code(), Some(0));
    assert!(text(&bad).contains("OPENR_SANITIZE=memory: expected address, undefined or thread"), "{}", text(&bad));
    assert!(!dir.join("MS/OPEN-R/MW/OBJS/SLOPPY.BIN").exists(), "nothing installed");
    let out = make("address");
    assert!(out.status.success(), "{}", text(&out));
    // The Makefile strips the .bin; under OPENR_SANITIZE the strip keeps the line tables.
    let r = run_1s(&dir);
    assert_ne!(r.code, Some(0));
    assert!(r.stderr.contains("heap-buffer-overflow") && r.stderr.contains("Sloppy/Sloppy.cc:35"), "{}", r.stderr);
    let _ = fs::remove_dir_all(dir.join("target"));
}
