//! The `OPENR::` robot calls from Rust (`openr::robot`): `examples/rust-walk`, built by
//! `cargo openr build`, opens the left front leg's J1, powers the motors, sets the
//! standard gains and moves the joint to +30° and back to 0° with command vectors sent
//! through a `Subject<CommandVector>` to `OVirtualRobotComm.Effector`.
use std::path::Path;

use serde_json::Value;

use crate::support::{cargo_openr_in, copy_tree, read_trace, repo, run_ms, sdk_root};

const LF_J1: &str = "PRM:/r2/c1-Joint2:21";

/// A scratch copy of `examples/rust-walk` whose `openr` dependency is this checkout's
/// (a project of its own, as `cargo openr new --template rust-object` makes them).
fn copy_rust_walk(tmp: &Path) -> std::path::PathBuf {
    let dir = tmp.join("rust-walk");
    copy_tree(&repo().join("examples/rust-walk"), &dir);
    let _ = std::fs::remove_dir_all(dir.join("MS/OPEN-R/MW/OBJS"));
    let _ = std::fs::remove_dir_all(dir.join("target"));
    let manifest = dir.join("Cargo.toml");
    let toml = std::fs::read_to_string(&manifest).unwrap();
    let openr = repo().join("openr");
    let fixed = toml.replace("path = \"../../openr\"", &format!("path = {:?}", openr.to_str().unwrap()));
    assert_ne!(fixed, toml, "examples/rust-walk/Cargo.toml no longer names ../../openr");
    std::fs::write(&manifest, format!("{fixed}\n[workspace]\n")).unwrap();
    dir
}

#[test]
fn rust_object_moves_lf_j1_to_30_degrees_and_back_with_command_vectors() {
    let tmp = tempfile::tempdir().unwrap();
    let dir = copy_rust_walk(tmp.path());
    let target = Path::new(env!("CARGO_TARGET_TMPDIR")).join("rust-robot-target");
    let root = sdk_root().to_str().unwrap().to_string();
    let out = cargo_openr_in(&dir, &["build", "--sdk", root.as_str()], &[("CARGO_TARGET_DIR", target.to_str().unwrap())]);
    assert!(out.status.success(), "build: {}\n{}", String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr));
    assert!(dir.join("MS/OPEN-R/MW/OBJS/RWALK.BIN").is_file());

    let trace_path = tmp.path().join("trace.jsonl");
    let run = run_ms(&dir.join("MS"), &["--for", "3s", "--speed", "max", "--sdk", root.as_str(), "--trace", trace_path.to_str().unwrap()]);
    assert_eq!(run.code, Some(0), "run\nstdout:\n{}\nstderr:\n{}", run.stdout, run.stderr);
    let ctx = format!("stdout:\n{}\nstderr:\n{}", run.stdout, run.stderr);
    assert_eq!(run.lines_starting("RustWalk : ERS-7 LF J1 at ").len(), 1, "{ctx}");
    assert_eq!(run.lines_starting("RustWalk : LF J1 reached 30 degrees"), ["RustWalk : LF J1 reached 30 degrees"], "{ctx}");
    assert_eq!(run.lines_starting("RustWalk : LF J1 back at 0 degrees"), ["RustWalk : LF J1 back at 0 degrees"], "{ctx}");
    assert!(!run.stdout.contains("failed"), "{ctx}");

    let trace = read_trace(&trace_path);
    let of = |k: &'static str| trace.iter().filter(move |r| r["kind"] == k);
    // the Rust object's one connection to the effector carries JOINT_COMMAND2 slots for LF J1
    let starts: Vec<&Value> = of("vector_start").collect();
    assert!(starts.len() >= 10, "{} vector_start records", starts.len());
    let conns: std::collections::BTreeSet<u64> = starts.iter().map(|r| r["conn"].as_u64().unwrap()).collect();
    assert_eq!(conns.len(), 1, "connections: {conns:?}");
    for v in &starts {
        let slot = &v["slots"][0];
        assert_eq!((slot["locator"].as_str(), slot["type"].as_str()), (Some(LF_J1), Some("JOINT_COMMAND2")), "{v}");
        assert_eq!(slot["values"].as_array().unwrap().len(), 16, "{v}");
    }
    // the joint gets to 30° (within a degree), later back to 0°
    let angles: Vec<f64> = of("sensor").map(|r| r["joints"][LF_J1].as_f64().unwrap_or_else(|| panic!("no {LF_J1} in {r}"))).collect();
    let at_30 = angles.iter().position(|&a| (29.0..=31.0).contains(&a)).unwrap_or_else(|| panic!("LF J1 never near 30°: {angles:?}"));
    assert!(angles[at_30..].iter().any(|&a| a <= 1.0), "LF J1 not back to 0° after 30°: {angles:?}");
    assert!(angles.iter().all(|&a| a >= -1.0), "LF J1 overshot below 0°: {angles:?}");
}
