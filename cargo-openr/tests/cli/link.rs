//! Link-time errors (testdata/link-errors): an object referencing a symbol nothing
//! defines fails in mkbin, under `make` and under `cargo openr build`, naming the symbol
//! demangled, the object and the `.bin`, and installs nothing.
use std::fs;
use std::path::Path;
use std::process::Command;

use crate::support::{build, cargo_openr_in, copy_tree, repo, run, sdk_root};

/// A copy of `testdata/link-errors/<name>` in a scratch directory.
fn copy(name: &str) -> (tempfile::TempDir, std::path::PathBuf) {
    let tmp = tempfile::tempdir().unwrap();
    let dir = tmp.path().join(name);
    copy_tree(&repo().join("testdata/link-errors").join(name), &dir);
    (tmp, dir)
}

fn files_in(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = fs::read_dir(dir).unwrap().flatten().map(|e| e.file_name().to_string_lossy().into_owned()).collect();
    v.sort();
    v
}

#[test]
fn make_install_fails_on_an_undefined_helper_and_installs_nothing() {
    let (_tmp, dir) = copy("missing-helper");
    let (ok, log) = run(Command::new("make").arg(format!("OPENRSDK_ROOT={}", sdk_root().display())).arg("install").current_dir(&dir));
    assert!(!ok, "make install must fail:\n{log}");
    assert!(log.contains("undefined reference to `missing_helper(int)'"), "ld's own line, demangled:\n{log}");
    assert!(
        log.contains(
            "mkbin: cannot link counter.bin:\n  undefined symbol `missing_helper(int)`, referenced from Counter.o in Counter::DoStart(OSystemEvent const&) at "
        ),
        "mkbin's summary names the .bin, the symbol, the object and the function:\n{log}"
    );
    assert!(log.contains("Counter.cc:26") && log.contains("hint: no object, archive or library of the link defines it"), "{log}");
    assert!(!log.contains("_Z14missing_helperi"), "no mangled name:\n{log}");
    assert_eq!(files_in(&dir.join("MS/OPEN-R/MW/OBJS")), [".keep"], "no .BIN installed");
    let left: Vec<String> = files_in(&dir.join("Counter")).into_iter().filter(|f| f.starts_with("counter.")).collect();
    assert_eq!(left, ["counter.ocf"], "no .bin, .partial or .snap.* left after the failed link");
}

#[test]
fn cargo_openr_build_reports_the_undefined_helper_in_json() {
    let (_tmp, dir) = copy("missing-helper");
    let root = sdk_root().to_str().unwrap().to_string();
    let out = cargo_openr_in(&dir, &["build", "--sdk", &root, "--message-format", "json"], &[]);
    assert!(!out.status.success());
    let stdout = String::from_utf8_lossy(&out.stdout);
    let lines: Vec<serde_json::Value> = stdout.lines().map(|l| serde_json::from_str(l).unwrap()).collect();
    let rendered: Vec<&str> = lines.iter().filter(|v| v["reason"] == "compiler-message").filter_map(|v| v["message"]["rendered"].as_str()).collect();
    let msg = rendered.iter().find(|r| r.contains("missing_helper(int)")).unwrap_or_else(|| panic!("no message names the symbol:\n{stdout}"));
    assert!(msg.contains("counter.bin:") && msg.contains("referenced from") && msg.contains("Counter.o"), "{msg}");
    assert!(msg.contains("undefined reference to `missing_helper(int)'"), "the linker's lines are in the message:\n{msg}");
    assert_eq!(lines.last().unwrap()["success"], false, "{stdout}");
    assert!(!dir.join("MS/OPEN-R/MW/OBJS/COUNTER.BIN").exists());

    let out = cargo_openr_in(&dir, &["build", "--sdk", &root], &[]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success() && err.contains("missing_helper(int)") && err.contains("could not link `Counter` (C++)"), "{err}");
}

#[test]
fn a_successful_link_keeps_the_intermediates_sony_kept() {
    let built = build("hello");
    let obj = built.dir.path().join("hello/HelloWorld");
    assert!(obj.join("helloWorld.snap.cc").is_file() && obj.join("helloWorld.snap.o").is_file(), "{:?}", files_in(&obj));
    assert!(!obj.join("helloWorld.bin.partial").exists());
}

fn mkbin_with_ocf(ocf: &[u8]) -> (bool, String, tempfile::TempDir) {
    let dir = tempfile::tempdir().unwrap();
    fs::write(dir.path().join("x.ocf"), ocf).unwrap();
    let (ok, log) = run(Command::new(sdk_root().join("OPEN_R/bin/mkbin")).args(["-o", "x.bin", "x.o", "x.ocf"]).current_dir(dir.path()));
    (ok, log, dir)
}

#[test]
fn mkbin_rejects_bad_ocf_bytes_words_and_sizes_with_file_and_line() {
    let (ok, log, _d) = mkbin_with_ocf(b"# Sch\xf6n\nobject x 3072 16384 128 cache tlb user\n");
    assert!(!ok && log.contains("mkbin: x.ocf:1: ocf format error: byte 0xf6 at column 6 is not text"), "{log}");
    let (ok, log, _d) = mkbin_with_ocf(b"object x 3072 16384 128\ncache tlb usr\n");
    assert!(!ok && log.contains("mkbin: x.ocf:2: ocf format error: MODE must be `user` or `kernel`, found `usr`"), "{log}");
    let (ok, log, d) = mkbin_with_ocf(b"object x\n18446744073709551615K 16384 128 cache tlb user\n");
    assert!(!ok && log.contains("mkbin: x.ocf:2: ocf format error: STACK `18446744073709551615K` is too large"), "{log}");
    assert_eq!(files_in(d.path()), ["x.ocf"], "nothing written for a bad ocf");
}

/// A call the Rust object declares `extern "C"` and nobody defines.
const RUST_MISSING: &str = r#"
extern "C" {
    fn missing_helper(step: i32) -> i32;
}

#[no_mangle]
pub extern "C" fn uses_missing_helper() -> i32 {
    unsafe { missing_helper(1) }
}
"#;

#[test]
fn cargo_openr_build_refuses_a_rust_object_with_an_undefined_extern() {
    let tmp = tempfile::tempdir().unwrap();
    // Named apart from build.rs's `test-dog`: both share the Rust target directory.
    let out = cargo_openr_in(tmp.path(), &["new", "helper-dog", "--template", "rust-object"], &[]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let dir = tmp.path().join("helper-dog");
    let lib = dir.join("HelperDogSubject/src/lib.rs");
    let original = fs::read_to_string(&lib).unwrap_or_else(|e| panic!("{}: {e}", lib.display()));
    fs::write(&lib, format!("{original}{RUST_MISSING}")).unwrap();
    let root = sdk_root().to_str().unwrap().to_string();
    let target = Path::new(env!("CARGO_TARGET_TMPDIR")).join("build-rust-objects");
    let env = [("CARGO_TARGET_DIR", target.to_str().unwrap())];
    let out = cargo_openr_in(&dir, &["build", "--sdk", &root, "--message-format", "json"], &env);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(!out.status.success(), "{stdout}");
    let msg = stdout
        .lines()
        .filter_map(|l| serde_json::from_str::<serde_json::Value>(l).ok())
        .filter_map(|v| v["message"]["rendered"].as_str().map(str::to_string))
        .find(|r| r.contains("undefined symbol missing_helper"))
        .unwrap_or_else(|| panic!("no message names missing_helper:\n{stdout}"));
    assert!(msg.contains("the cdylib would not load") && msg.contains("hint:"), "{msg}");
    // The template's Cargo.toml names it `bin = "HELPERDS.BIN"`.
    let toml = fs::read_to_string(dir.join("HelperDogSubject/Cargo.toml")).unwrap();
    assert!(toml.contains("bin = \"HELPERDS.BIN\""), "{toml}");
    let bin = dir.join("MS/OPEN-R/MW/OBJS/HELPERDS.BIN");
    assert!(!bin.exists(), "the Rust object was installed");

    fs::write(&lib, original).unwrap();
    let out = cargo_openr_in(&dir, &["build", "--sdk", &root], &env);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert!(bin.is_file(), "installed once the extern is gone");
}
