//! `cargo openr run --gdb` and `--valgrind`: the run re-executes itself under the tool
//! with the SDK root's gdb commands or valgrind suppressions, and reports what the
//! objects do wrong — not what the runtime does on purpose.
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use crate::support::{cargo_openr_in, copy_tree, repo, run, run_ms, sdk_root};

fn text(out: &Output) -> String {
    format!("{}{}", String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr))
}

fn program(name: &str, cargo_build: bool) -> (tempfile::TempDir, PathBuf) {
    let tmp = tempfile::tempdir().unwrap();
    let dir = tmp.path().join(name);
    copy_tree(&repo().join("testdata/programs").join(name), &dir);
    let out = if cargo_build {
        cargo_openr_in(&dir, &["build", "--sdk", sdk_root().to_str().unwrap()], &[])
    } else {
        Command::new("make").arg(format!("OPENRSDK_ROOT={}", sdk_root().display())).arg("install").current_dir(&dir).output().unwrap()
    };
    assert!(out.status.success(), "{}", text(&out));
    (tmp, dir)
}

fn run_under(dir: &Path, extra: &[&str]) -> crate::support::RunOutput {
    let mut args = vec!["--for", "1s", "--speed", "max", "--sdk", sdk_root().to_str().unwrap()];
    args.extend_from_slice(extra);
    run_ms(&dir.join("MS"), &args)
}

#[test]
fn memcheck_with_the_shipped_suppressions_passes_a_clean_program() {
    let (_tmp, dir) = program("hello", false);
    let r = run_under(&dir, &["--valgrind"]);
    assert_eq!(r.code, Some(0), "{}\n{}", r.stdout, r.stderr);
    assert!(r.stderr.contains("ERROR SUMMARY: 0 errors from 0 contexts"), "{}", r.stderr);
    assert!(!r.stderr.contains("definitely lost: ") || r.stderr.contains("definitely lost: 0 bytes in 0 blocks"), "{}", r.stderr);
    assert!(r.stdout.contains("Hello"), "the program ran under memcheck: {}", r.stdout);
}

#[test]
fn memcheck_still_reports_an_objects_own_error_at_its_line() {
    let (_tmp, dir) = program("sanitizers", true);
    let r = run_under(&dir, &["--valgrind=memcheck"]);
    assert_eq!(r.code, Some(1), "memcheck's error exit: {}\n{}", r.stdout, r.stderr);
    let report = r.stderr.split("Invalid write of size 1").nth(1).unwrap_or_else(|| panic!("{}", r.stderr));
    let first = report.lines().nth(1).unwrap_or_default();
    assert!(first.contains("Sloppy::DoStart") && first.contains("Sloppy.cc:35"), "{first}\n{}", r.stderr);
}

#[test]
fn gdb_breaks_on_do_start_by_name_and_prints_a_local_of_a_dev_build() {
    let (_tmp, dir) = program("sanitizers", true);
    let mut extra = vec!["--gdb", "--tool-arg=-batch"];
    for c in ["break Sloppy::DoStart", "run", "next", "next", "print name", "kill"] {
        extra.push("--tool-arg");
        extra.push(Box::leak(format!("--eval-command={c}").into_boxed_str()));
    }
    let r = run_under(&dir, &extra);
    let all = format!("{}{}", r.stdout, r.stderr);
    assert!(all.contains("hit Breakpoint 1, Sloppy::DoStart"), "{all}");
    assert!(all.lines().any(|l| l.starts_with("$1 = ") && l.ends_with("\"ERS-7M3\"")), "the local `name` after the strcpy: {all}");
    assert!(!all.contains("optimized out"), "{all}");
}

#[test]
fn a_missing_valgrind_tool_is_the_tools_own_error() {
    let (_tmp, dir) = program("hello", false);
    let r = run_under(&dir, &["--valgrind=nosuchtool"]);
    assert_ne!(r.code, Some(0), "{}", r.stderr);
    assert!(r.stderr.contains("nosuchtool"), "{}", r.stderr);
    // --gdb and --valgrind together are refused by the parser.
    let out = Command::new(crate::support::exe()).args(["run", "--gdb", "--valgrind", dir.join("MS").to_str().unwrap()]).output().unwrap();
    assert_eq!(out.status.code(), Some(2), "{}", text(&out));
    let _ = run;
}

#[test]
fn a_core_dump_is_opt_in_after_the_report() {
    use std::os::unix::process::ExitStatusExt;
    let (_tmp, dir) = program("crash", false);
    std::fs::write(dir.join("MS/OPEN-R/MW/CONF/CRASH.CFG"), "1\n").unwrap();
    let cores = |d: &Path| std::fs::read_dir(d).unwrap().flatten().filter(|e| e.file_name().to_string_lossy().starts_with("core")).count();
    let run_in = |cwd: &Path, core: Option<&str>| {
        let mut c = Command::new(crate::support::exe());
        c.args(["run", "--for", "5s", "--speed", "max", "--sdk", sdk_root().to_str().unwrap()]).arg(dir.join("MS")).current_dir(cwd);
        if let Some(v) = core {
            c.env("OPENR_CORE_DUMP", v);
        }
        c.output().unwrap()
    };
    let plain = tempfile::tempdir().unwrap();
    let out = run_in(plain.path(), None);
    assert_eq!(out.status.code(), Some(128 + 11), "{}", text(&out));
    assert_eq!(cores(plain.path()), 0);
    let with_core = tempfile::tempdir().unwrap();
    let out = run_in(with_core.path(), Some("1"));
    assert_eq!(out.status.signal(), Some(libc::SIGSEGV), "dies of the signal itself: {}", text(&out));
    assert!(text(&out).contains("error: object `crash`") && text(&out).contains("backtrace:"), "the report comes first: {}", text(&out));
    let pattern = std::fs::read_to_string("/proc/sys/kernel/core_pattern").unwrap_or_default();
    if !pattern.starts_with('|') && !pattern.contains('/') {
        assert_eq!(cores(with_core.path()), 1, "core_pattern {pattern:?}: a core file in the working directory");
    }
}
