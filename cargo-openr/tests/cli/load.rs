//! Before anything is `dlopen`ed: `run` and `check` refuse a damaged `.BIN` with its path
//! (no signal death inside the dynamic loader), and `check` test-loads each object the
//! way `run` will, so a symbol nobody defines is found before the robot boots.
use std::fs;
use std::io::{Read, Write};
use std::path::Path;
use std::process::Command;

use crate::support::{build, cargo_openr, copy_tree, repo, run, run_ms, sdk_root};

fn gunzip(path: &Path) -> Vec<u8> {
    let mut elf = Vec::new();
    flate2::read::GzDecoder::new(&fs::read(path).unwrap()[..]).read_to_end(&mut elf).unwrap();
    elf
}

fn gzip_to(path: &Path, elf: &[u8]) {
    let mut gz = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::default());
    gz.write_all(elf).unwrap();
    fs::write(path, gz.finish().unwrap()).unwrap();
}

fn u16_at(b: &[u8], at: usize) -> usize {
    u16::from_le_bytes([b[at], b[at + 1]]) as usize
}

fn u64_at(b: &[u8], at: usize) -> u64 {
    u64::from_le_bytes(b[at..at + 8].try_into().unwrap())
}

/// `(what, image)`: the same object damaged four ways.
fn damaged(elf: &[u8]) -> Vec<(&'static str, Vec<u8>)> {
    let truncated = elf[..elf.len() * 2 / 3].to_vec();
    let mut phoff_past_end = elf.to_vec();
    phoff_past_end[32..40].copy_from_slice(&(elf.len() as u64 - 16).to_le_bytes());
    let mut mips = elf.to_vec();
    mips[18] = 8;
    // Every value of the dynamic section replaced by garbage (tags kept).
    let mut garbage = elf.to_vec();
    let phoff = u64_at(elf, 32) as usize;
    let dynamic = (0..u16_at(elf, 56)).map(|i| phoff + 56 * i).find(|p| elf[*p] == 2 && elf[*p + 1..*p + 4] == [0, 0, 0]).unwrap();
    let (off, size) = (u64_at(elf, dynamic + 8) as usize, u64_at(elf, dynamic + 32) as usize);
    for e in (off..off + size).step_by(16) {
        if u64_at(elf, e) != 0 {
            garbage[e + 8..e + 16].copy_from_slice(&0x7fff_dead_beefu64.to_le_bytes());
        }
    }
    vec![("truncated", truncated), ("program headers past the end", phoff_past_end), ("MIPS", mips), ("garbage dynamic section", garbage)]
}

#[test]
fn run_and_check_refuse_damaged_objects_with_their_path() {
    let built = build("hello");
    let ms = built.ms();
    let bin = ms.join("OPEN-R/MW/OBJS/HELLO.BIN");
    let good = gunzip(&bin);
    let sdk = sdk_root().to_str().unwrap().to_string();
    let expected = ["loadable segment", "the program header table (offset", "built for machine 8 (MIPS", "outside the file's loadable segments"];
    for ((what, elf), want) in damaged(&good).into_iter().zip(expected) {
        gzip_to(&bin, &elf);
        let r = run_ms(&ms, &["--for", "1s", "--sdk", &sdk]);
        assert!(matches!(r.code, Some(c) if c != 0), "{what}: run must exit non-zero, not by a signal: {:?}\n{}", r.code, r.stderr);
        assert!(r.stderr.contains(&format!("{}: damaged or foreign object file: ", bin.display())), "{what}: {}", r.stderr);
        assert!(r.stderr.contains(want), "{what}: expected `{want}` in:\n{}", r.stderr);
        assert!(!r.stdout.contains("Hello World"), "{what}: nothing ran");

        let out = cargo_openr(&["ms", "verify", ms.to_str().unwrap()]);
        let text = String::from_utf8_lossy(&out.stdout).into_owned() + &String::from_utf8_lossy(&out.stderr);
        assert!(matches!(out.status.code(), Some(c) if c != 0), "{what}: ms verify: {text}");
        assert!(text.contains("error[E0003]") && text.contains("HELLO.BIN") && text.contains(want), "{what}: {text}");
    }
}

/// `testdata/link-errors/missing-helper` linked the way mkbin did before it required
/// every symbol to be defined: a `.BIN` that links and installs, but cannot load.
fn install_unresolved_counter() -> (tempfile::TempDir, std::path::PathBuf) {
    let tmp = tempfile::tempdir().unwrap();
    let dir = tmp.path().join("missing-helper");
    copy_tree(&repo().join("testdata/link-errors/missing-helper"), &dir);
    let root = sdk_root();
    let obj = dir.join("Counter");
    let (ok, log) = run(Command::new("make").arg(format!("OPENRSDK_ROOT={}", root.display())).args(["CounterStub.o", "Counter.o"]).current_dir(&obj));
    assert!(ok, "{log}");
    let (ok, log) = run(Command::new("g++")
        .args(["-shared", "-fPIC", "-Wl,-Bsymbolic", "-o", "counter.bin", "CounterStub.o", "Counter.o"])
        .arg(format!("-L{}", root.join("OPEN_R/lib").display()))
        .args(["-Wl,--start-group", "-lOPENR", "-lObjectComm", "-lmcoopstub", "-Wl,--end-group", "-ldl"])
        .current_dir(&obj));
    assert!(ok, "{log}");
    let elf = fs::read(obj.join("counter.bin")).unwrap();
    gzip_to(&dir.join("MS/OPEN-R/MW/OBJS/COUNTER.BIN"), &elf);
    (tmp, dir)
}

#[test]
fn check_test_loads_each_object_and_names_an_undefined_symbol() {
    let (_tmp, dir) = install_unresolved_counter();
    let out = cargo_openr(&["check", dir.to_str().unwrap()]);
    let text = String::from_utf8_lossy(&out.stdout).into_owned() + &String::from_utf8_lossy(&out.stderr);
    assert!(matches!(out.status.code(), Some(c) if c != 0), "{text}");
    assert!(text.contains("error[E0003]: `/MS/OPEN-R/MW/OBJS/COUNTER.BIN` ("), "{text}");
    assert!(text.contains("COUNTER.BIN) would not load: undefined symbol missing_helper(int) (_Z14missing_helperi)"), "{text}");
    assert!(text.contains("OBJECT.CFG:1"), "{text}");

    let out = cargo_openr(&["check", dir.to_str().unwrap(), "--message-format", "json"]);
    let json = String::from_utf8_lossy(&out.stdout);
    assert!(json.lines().any(|l| l.contains("\"E0003\"") && l.contains("missing_helper(int)")), "{json}");

    let r = run_ms(&dir.join("MS"), &["--for", "1s", "--sdk", sdk_root().to_str().unwrap()]);
    assert!(matches!(r.code, Some(c) if c != 0), "{:?} {}", r.code, r.stderr);
    assert!(
        r.stderr.contains("COUNTER.BIN") && r.stderr.contains("`missing_helper(int)` (_Z14missing_helperi)"),
        "run names the symbol demangled:\n{}",
        r.stderr
    );
}

#[test]
fn check_passes_objects_that_load() {
    let built = build("objcomm");
    let out = cargo_openr(&["check", built.dir.path().join("objcomm").to_str().unwrap()]);
    let text = String::from_utf8_lossy(&out.stdout).into_owned() + &String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success() && !text.contains("E0003"), "{text}");
}
