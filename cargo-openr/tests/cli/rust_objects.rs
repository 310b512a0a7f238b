//! Objects written in Rust (`openr` crate) beside C++ objects: `examples/mixed` builds
//! its C++ half with the SDK-root Makefile convention and its Rust half with cargo, and
//! the two exchange strings both ways through the subject/observer protocol.
use std::path::Path;
use std::process::Command;

use crate::support::{copy_tree, repo, run, run_ms, sdk_root};

/// Builds `examples/mixed` in a scratch copy: the Rust object in debug, into a target
/// directory of its own (the test run's `cargo` holds the workspace's).
fn build_mixed(tmp: &Path) -> std::path::PathBuf {
    let dir = tmp.join("mixed");
    copy_tree(&repo().join("examples/mixed"), &dir);
    let _ = std::fs::remove_dir_all(dir.join("MS/OPEN-R/MW/OBJS"));
    let target = Path::new(env!("CARGO_TARGET_TMPDIR")).join("rust-objects-target");
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
    let (ok, log) = run(Command::new("make")
        .arg(format!("OPENRSDK_ROOT={}", sdk_root().display()))
        .arg(format!("WORKSPACE={}", repo().display()))
        .arg(format!("CARGO_TARGET_DIR={}", target.display()))
        .arg(format!("CARGO={cargo}"))
        .arg("PROFILE=debug")
        .arg("install")
        .current_dir(&dir));
    assert!(ok, "building examples/mixed failed:\n{log}");
    dir.join("MS")
}

#[test]
fn rust_and_cxx_objects_exchange_messages_both_ways() {
    let tmp = tempfile::tempdir().unwrap();
    let ms = build_mixed(tmp.path());
    // Virtual time: a busy machine must not make frames "late" (the test asserts no warning).
    let out = run_ms(&ms, &["--for", "2s", "--speed", "max"]);
    assert_eq!(out.code, Some(0), "stdout:\n{}\nstderr:\n{}", out.stdout, out.stderr);
    let from_cxx = out.lines_starting("RustPeer::Notify()");
    let from_rust = out.lines_starting("CxxPeer::Notify()");
    assert_eq!(
        from_cxx,
        ["RustPeer::Notify() hello 1 from C++", "RustPeer::Notify() hello 2 from C++", "RustPeer::Notify() hello 3 from C++"],
        "C++ subject -> Rust observer\nstderr:\n{}",
        out.stderr
    );
    assert_eq!(
        from_rust,
        ["CxxPeer::Notify() hello 1 from Rust", "CxxPeer::Notify() hello 2 from Rust", "CxxPeer::Notify() hello 3 from Rust"],
        "Rust subject -> C++ observer\nstderr:\n{}",
        out.stderr
    );
    assert!(!out.stderr.contains("warning"), "stderr:\n{}", out.stderr);
}
