//! The edit-build-debug loop around `cargo openr build`: profiles (`-O0 -g` dev,
//! `-O2 -g` release) and extra flags, a `compile_commands.json` that clangd checks with
//! no error, and one tree built by `make install` and `cargo openr build` in any order.
use std::fs;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use crate::support::{cargo_openr_in, copy_tree, repo, run, run_ms, sdk_root};

fn text(out: &Output) -> String {
    format!("{}{}", String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr))
}

/// A scratch copy of a program of `testdata/programs/`.
fn program(name: &str) -> (tempfile::TempDir, PathBuf) {
    let tmp = tempfile::tempdir().unwrap();
    let dir = tmp.path().join(name);
    copy_tree(&repo().join("testdata/programs").join(name), &dir);
    (tmp, dir)
}

fn openr_build(dir: &Path, extra: &[&str], env: &[(&str, &str)]) -> Output {
    let mut args = vec!["build", "--sdk", sdk_root().to_str().unwrap()];
    args.extend_from_slice(extra);
    let out = cargo_openr_in(dir, &args, env);
    assert!(out.status.success(), "cargo openr build {extra:?}: {}", text(&out));
    out
}

fn make_install(dir: &Path) {
    let (ok, log) = run(Command::new("make").arg(format!("OPENRSDK_ROOT={}", sdk_root().display())).arg("install").current_dir(dir));
    assert!(ok, "make install in {}: {log}", dir.display());
}

/// The DW_AT_producer strings of an object file (the compiler and its options).
fn producers(obj: &Path) -> String {
    let (ok, log) = run(Command::new("readelf").arg("--debug-dump=info").arg(obj));
    assert!(ok, "readelf {}: {log}", obj.display());
    log.lines().filter(|l| l.contains("DW_AT_producer")).collect::<Vec<_>>().join("\n")
}

fn compile_commands(dir: &Path) -> Vec<serde_json::Value> {
    serde_json::from_str(&fs::read_to_string(dir.join("compile_commands.json")).unwrap()).unwrap()
}

fn arguments(entry: &serde_json::Value) -> Vec<String> {
    entry["arguments"].as_array().unwrap().iter().map(|a| a.as_str().unwrap().to_string()).collect()
}

#[test]
fn dev_builds_are_o0_release_builds_o2_and_extra_flags_reach_the_compiler() {
    let (_tmp, dir) = program("legacy");
    let obj = dir.join("target/openr/Legacy/Legacy.o");
    openr_build(&dir, &[], &[]);
    let p = producers(&obj);
    assert!(p.contains(" -O0") && p.contains(" -g"), "dev profile: {p}");
    let out = openr_build(&dir, &["--release"], &[]);
    assert!(String::from_utf8_lossy(&out.stderr).contains("Compiling Legacy"), "a profile switch recompiles: {}", text(&out));
    let p = producers(&obj);
    assert!(p.contains(" -O2") && !p.contains(" -O0"), "release profile: {p}");

    // openr.toml < environment < command line, as for every other setting.
    fs::write(dir.join("openr.toml"), "cxxflags = \"-DFROM_TOML=1\"\nldflags = \"-lm\"\n").unwrap();
    openr_build(&dir, &[], &[]);
    let args = arguments(&compile_commands(&dir)[1]);
    assert!(args.iter().any(|a| a == "-DFROM_TOML=1"), "{args:?}");
    openr_build(&dir, &[], &[("OPENR_CXXFLAGS", "-DFROM_ENV=1")]);
    let args = arguments(&compile_commands(&dir)[1]);
    assert!(args.iter().any(|a| a == "-DFROM_ENV=1") && !args.iter().any(|a| a == "-DFROM_TOML=1"), "{args:?}");
    openr_build(&dir, &["--cxxflags", "-DFROM_CLI=1 -Wall"], &[("OPENR_CXXFLAGS", "-DFROM_ENV=1")]);
    let args = arguments(&compile_commands(&dir)[1]);
    assert!(args.iter().any(|a| a == "-DFROM_CLI=1") && args.iter().any(|a| a == "-Wall") && !args.iter().any(|a| a == "-DFROM_ENV=1"), "{args:?}");

    // A bad extra flag is the compiler's error, named, and the build fails.
    let out = cargo_openr_in(&dir, &["build", "--sdk", sdk_root().to_str().unwrap(), "--cxxflags", "-fno-such-flag"], &[]);
    assert_eq!(out.status.code(), Some(1), "{}", text(&out));
    assert!(text(&out).contains("-fno-such-flag"), "{}", text(&out));
}

#[test]
fn make_install_and_cargo_openr_build_share_one_tree_in_either_order() {
    let (_tmp, dir) = program("legacy");
    make_install(&dir);
    // make left LegacyStub.cc, def.h and legacy.snap.cc in the object's directory.
    assert!(dir.join("Legacy/legacy.snap.cc").exists() || dir.join("Legacy/LegacyStub.cc").exists());
    openr_build(&dir, &[], &[]);
    make_install(&dir);
    openr_build(&dir, &["--release"], &[]);
    let r = run_ms(&dir.join("MS"), &["--for", "1s", "--speed", "max", "--sdk", sdk_root().to_str().unwrap()]);
    assert_eq!(r.code, Some(0), "{}\n{}", r.stdout, r.stderr);
    assert!(r.stdout.contains("Legacy : "), "{}", r.stdout);
}

/// clangd from Debian (`tools/deps.sh` installs it).
fn clangd() -> PathBuf {
    which::which("clangd").unwrap_or_else(|_| panic!("clangd is not installed: run tools/deps.sh (apt-get install clangd)"))
}

#[test]
fn clangd_checks_every_unit_of_the_compile_database_with_no_error() {
    let clangd = clangd();
    // tcp-echo casts ANT's `void*` continuation to int (an error to clang without the
    // project's .clangd); legacy uses the backward headers and gcc 3.3 idioms.
    for name in ["tcp-echo", "legacy", "objcomm"] {
        let (_tmp, dir) = program(name);
        openr_build(&dir, &[], &[]);
        let cc = compile_commands(&dir);
        assert!(cc.len() >= 2, "{name}: {cc:?}");
        for e in &cc {
            let args = arguments(e);
            assert!(!args[0].contains("mipsel"), "{name}: the database must name the host compiler: {args:?}");
            assert!(args.iter().any(|a| a == "-std=gnu++98"), "{name}: the wrapper's dialect: {args:?}");
            let file = e["file"].as_str().unwrap();
            let (ok, log) = run(Command::new(&clangd).arg(format!("--check={file}")).arg(format!("--compile-commands-dir={}", dir.display())));
            assert!(ok && log.contains("All checks completed, 0 errors"), "{name}: clangd --check={file}:\n{log}");
        }
    }
}

#[test]
fn json_compiler_messages_carry_spans_and_colour_follows_color() {
    let (_tmp, dir) = program("legacy");
    let src = dir.join("Legacy/Legacy.cc");
    let text_before = fs::read_to_string(&src).unwrap();
    // An unused variable (a warning with its -W option) and a call of an undeclared
    // function (an error) at known lines at the end of the unit.
    let lines = text_before.lines().count();
    fs::write(&src, format!("{text_before}\nstatic int warned() {{ int unused_x; return 0; }}\nstatic void broken() {{ no_such_function(1); }}\n")).unwrap();
    let (warn_line, err_line) = (lines as u64 + 2, lines as u64 + 3);
    let out = cargo_openr_in(&dir, &["build", "--sdk", sdk_root().to_str().unwrap(), "--message-format", "json", "--cxxflags", "-Wall"], &[]);
    assert_eq!(out.status.code(), Some(1), "{}", text(&out));
    let records: Vec<serde_json::Value> =
        String::from_utf8_lossy(&out.stdout).lines().map(|l| serde_json::from_str(l).unwrap_or_else(|e| panic!("{l}: {e}"))).collect();
    let messages: Vec<&serde_json::Value> = records.iter().filter(|r| r["reason"] == "compiler-message").map(|r| &r["message"]).collect();
    let error = messages
        .iter()
        .find(|m| m["level"] == "error" && m["message"].as_str().unwrap().contains("no_such_function"))
        .unwrap_or_else(|| panic!("{messages:#?}"));
    let span = &error["spans"][0];
    assert!(span["file_name"].as_str().unwrap().ends_with("Legacy.cc"), "{span}");
    assert_eq!(span["line_start"], err_line, "{span}");
    assert!(span["column_start"].as_u64().unwrap() > 1, "{span}");
    assert!(error["rendered"].as_str().unwrap().contains("no_such_function(1)"), "the source excerpt: {error}");
    let warning =
        messages.iter().find(|m| m["level"] == "warning" && m["message"].as_str().unwrap().contains("unused_x")).unwrap_or_else(|| panic!("{messages:#?}"));
    assert_eq!(warning["code"]["code"], "-Wunused-variable", "{warning}");
    assert_eq!(warning["spans"][0]["line_start"], warn_line, "{warning}");
    assert!(!String::from_utf8_lossy(&out.stdout).contains('\x1b'), "no colour in JSON");
    assert_eq!(records.last().unwrap()["reason"], "build-finished");

    // --color always: cargo's green status verbs and gcc's own colours; never: none.
    let out = cargo_openr_in(&dir, &["--color", "always", "build", "--sdk", sdk_root().to_str().unwrap()], &[]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("\x1b[1;32m   Compiling\x1b[0m"), "{err}");
    assert!(err.contains("\x1b[1;31merror\x1b[0m: could not compile"), "{err}");
    assert!(err.matches('\x1b').count() > 4, "gcc's colours pass through: {err}");
    let out = cargo_openr_in(&dir, &["build", "--color", "never", "--sdk", sdk_root().to_str().unwrap()], &[("CARGO_TERM_COLOR", "always")]);
    assert!(!String::from_utf8_lossy(&out.stderr).contains('\x1b'), "{}", text(&out));
    let out = cargo_openr_in(&dir, &["build", "--sdk", sdk_root().to_str().unwrap()], &[("CARGO_TERM_COLOR", "always")]);
    assert!(String::from_utf8_lossy(&out.stderr).contains('\x1b'), "{}", text(&out));
}

/// A clean `cargo openr build` with `-j N`: its JSON lines and the installed `.BIN`s.
fn clean_build_json(dir: &Path, jobs: &str) -> (String, Vec<(String, u64)>) {
    let _ = fs::remove_dir_all(dir.join("target"));
    let objs = dir.join("MS/OPEN-R/MW/OBJS");
    let _ = fs::remove_dir_all(&objs);
    let out = openr_build(dir, &["-j", jobs, "--message-format", "json"], &[]);
    let mut bins: Vec<(String, u64)> =
        fs::read_dir(&objs).unwrap().map(|e| e.unwrap()).map(|e| (e.file_name().to_string_lossy().into_owned(), e.metadata().unwrap().len())).collect();
    bins.sort();
    (String::from_utf8_lossy(&out.stdout).into_owned(), bins)
}

#[test]
fn parallel_builds_give_the_same_output_in_the_same_order() {
    let (_tmp, dir) = program("blinkleds");
    let (one, bins_one) = clean_build_json(&dir, "1");
    let (many, bins_many) = clean_build_json(&dir, "8");
    assert!(bins_one.len() >= 3, "{bins_one:?}");
    assert_eq!(one, many, "-j 1 and -j 8 print the same records in the same order");
    assert_eq!(bins_one.iter().map(|b| &b.0).collect::<Vec<_>>(), bins_many.iter().map(|b| &b.0).collect::<Vec<_>>());
    let r = run_ms(&dir.join("MS"), &["--for", "1s", "--speed", "max", "--sdk", sdk_root().to_str().unwrap()]);
    assert_eq!(r.code, Some(0), "{}\n{}", r.stdout, r.stderr);

    // -j 0 is refused by the parser, not taken as "no limit".
    let out = cargo_openr_in(&dir, &["build", "-j", "0", "--sdk", sdk_root().to_str().unwrap()], &[]);
    assert_eq!(out.status.code(), Some(2), "{}", text(&out));
}

#[test]
fn verbose_builds_show_each_compiler_and_linker_command() {
    let (_tmp, dir) = program("legacy");
    let out = openr_build(&dir, &["-v"], &[]);
    let err = String::from_utf8_lossy(&out.stderr);
    let compiles: Vec<&str> = err.lines().filter(|l| l.trim_start().starts_with("Running `") && l.contains("mipsel-linux-g++")).collect();
    assert_eq!(compiles.len(), 2, "the stub and Legacy.cc: {err}");
    assert!(compiles.iter().any(|l| l.contains(" -O0 -g ") && l.contains("-c ") && l.ends_with("Legacy/Legacy.cc`")), "{err}");
    assert!(err.lines().any(|l| l.contains("-shared") && l.contains("legacy.bin")), "mkbin's link command: {err}");
    let quiet = openr_build(&dir, &[], &[]);
    assert!(!String::from_utf8_lossy(&quiet.stderr).contains("Running `"), "{}", text(&quiet));
}

#[test]
fn c_units_are_compiled_as_c() {
    // legacy-repair's OldCode object has Pixels.c beside its C++ units.
    let (_tmp, dir) = program("legacy-repair");
    let out = openr_build(&dir, &["-v"], &[]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.lines().any(|l| l.contains("mipsel-linux-gcc ") && l.ends_with("Pixels.c`")), "{err}");
    let obj = dir.join("target/openr").join("OldCode").join("Pixels.o");
    let (ok, syms) = run(Command::new("nm").arg(&obj));
    assert!(ok, "{syms}");
    assert!(syms.lines().any(|l| l.ends_with(" T SumRow")), "C linkage, not a mangled name: {syms}");
}

#[test]
fn stubgen_warnings_reach_the_build_output() {
    // dup-subname's stub.cfg uses the SubName Stdin twice, which stubgen2 warns about.
    // (Its sources need the Makefile's def.h patch, which `cargo openr build` does not
    // run: the build fails after the warning, as the warning says it may.)
    let (_tmp, dir) = program("dup-subname");
    let build = || cargo_openr_in(&dir, &["build", "--sdk", sdk_root().to_str().unwrap()], &[]);
    let out = build();
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("stubgen2: ") && err.contains("stub.cfg:14: warning: SubName 'Stdin'"), "{err}");
    let again = build();
    assert!(!String::from_utf8_lossy(&again.stderr).contains("stubgen2: "), "only when the stub is regenerated: {}", text(&again));
}
