//! The compiler wrapper's legacy repair: gcc-3.3 code g++ 12 rejects builds unmodified
//! from a repaired private copy, with a note per repair naming the user's file and line;
//! diagnostics, `__FILE__`, debug info (gdb) and dependency files name the user's files;
//! errors of no legacy class fail exactly as before.
use std::fs;
use std::path::{Path, PathBuf};
use std::process::Command;

use crate::support::{copy_tree, exe, repo, run, run_ms, sdk_root};

const PROGRAM: &str = "legacy-repair";

fn source(file: &str) -> String {
    fs::read_to_string(repo().join("testdata/programs").join(PROGRAM).join("OldCode").join(file)).unwrap()
}

/// The 1-based line of `file` (in the program's sources) that is `snippet`, else the
/// first that contains it.
fn line_of(file: &str, snippet: &str) -> usize {
    let text = source(file);
    let exact = text.lines().position(|l| l == snippet);
    exact.or_else(|| text.lines().position(|l| l.contains(snippet))).unwrap_or_else(|| panic!("{snippet:?} not in {file}")) + 1
}

/// A scratch copy of the program and a private TMPDIR for the compilers.
struct Scratch {
    dir: tempfile::TempDir,
    tmp: tempfile::TempDir,
}

impl Scratch {
    fn new() -> Scratch {
        let s = Scratch { dir: tempfile::tempdir().unwrap(), tmp: tempfile::tempdir().unwrap() };
        copy_tree(&repo().join("testdata/programs").join(PROGRAM), &s.project());
        s
    }
    fn project(&self) -> PathBuf {
        self.dir.path().join(PROGRAM)
    }
    fn make(&self, extra: &[&str]) -> (bool, String) {
        run(Command::new("make")
            .arg(format!("OPENRSDK_ROOT={}", sdk_root().display()))
            .args(extra)
            .arg("install")
            .env("TMPDIR", self.tmp.path())
            .current_dir(self.project()))
    }
    /// Nothing of the repair is left in TMPDIR.
    fn assert_no_shadow_left(&self) {
        let left: Vec<_> = fs::read_dir(self.tmp.path()).unwrap().flatten().map(|e| e.file_name()).collect();
        assert!(left.is_empty(), "left behind in TMPDIR: {left:?}");
    }
}

/// Every note of a repair at `file:line`, for assertions.
fn notes_at<'a>(log: &'a str, file: &str, line: usize) -> Vec<&'a str> {
    let prefix = format!("{file}:{line}:");
    log.lines().filter(|l| l.starts_with(&prefix) && l.contains(": note: [cargo-openr] repaired ")).collect()
}

#[test]
fn gcc33_code_builds_unmodified_with_a_note_per_repair_and_runs() {
    let s = Scratch::new();
    let (ok, log) = s.make(&[]);
    assert!(ok, "the program builds:\n{log}");
    let expected = [
        ("RingBuffer.h", "typedef RingTraits<T>::size_type size_type;", "implicit typename"),
        ("RingBuffer.h", "RingBuffer(RingTraits<T>::size_type n)", "implicit typename"),
        ("RingBuffer.h", "void Push(RingTraits<T>::const_reference v)", "implicit typename"),
        ("RingBuffer.h", "for (RingTraits<T>::storage_type::const_iterator", "implicit typename"),
        ("RingBuffer.h", "size_type Count() const { return count; }", "a name from a dependent base class"),
        ("RingBuffer.h", "T peak = data[0];", "a name from a dependent base class"),
        ("Stats.cc", "return (i < num)", "old for-scope"),
        ("OldCode.cc", "cout << \"OldCode : registry \"", "friend injection"),
        ("Gain.h", "struct Range<short> {", "explicit specialization without `template <>`"),
        ("Gain.h", "short Clip<short>(short v);", "explicit specialization without `template <>`"),
        ("Gain.cc", "short Clip<short>(short v)", "explicit specialization without `template <>`"),
        ("Tracker.h", "void Track(double x", "a parameter name repeated in one declaration"),
        ("Tracker.h", "void Limit(double max", "a parameter name repeated in one declaration"),
        ("Clock.cc", "int ::GetNowMSec();", "a first declaration with a qualified name `::f`"),
        ("Clock.cc", "int ::GetNowMSec()", "a first declaration with a qualified name `::f`"),
        ("OldCode.cc", "ios::in | ios::nocreate", "the pre-standard open mode `ios::nocreate`"),
        ("Pixels.c", "((unsigned char*)p)++;", "a cast used as an lvalue"),
        ("Pixels.c", "*((unsigned char*)row)++ = value;", "a cast used as an lvalue"),
        ("Pixels.c", "((unsigned char*)row) += step - 1;", "a cast used as an lvalue"),
        ("Label.cc", "memcpy(buf, part, 4);", "`memcpy` used without its header"),
        ("Label.cc", "sprintf(buf + 4, \"-%d\", abs(value));", "used without its header"),
        ("Label.cc", "return reader.As<int>(s);", "a member template of a dependent type called without `template`"),
        ("Label.cc", "template Span<int>;", "an explicit instantiation `template A<int>;` without `class`"),
        ("Label.cc", "return std::string(strlwr(buf));", "`strlwr` used without its header"),
    ];
    for (file, snippet, class) in expected {
        let line = line_of(file, snippet);
        let notes = notes_at(&log, file, line);
        assert!(notes.iter().any(|n| n.contains(class)), "a note `{file}:{line}:…: note: [cargo-openr] repaired {class}`:\n{log}");
    }
    // MIPS inline assembly is left out by the SDK's gcc plugin, which says so.
    let asm_line = line_of("Cycles.cc", "    __asm__ __volatile__(\"mfc0 %0, $9\" : \"=r\"(count));");
    assert!(
        log.lines().any(|l| l.starts_with(&format!("Cycles.cc:{asm_line}:"))
            && l.contains("note: [cargo-openr] MIPS inline assembly left out: the PC cannot run it; its outputs are 0")),
        "{log}"
    );
    // All nine implicit typenames of the header are named, each on its own line.
    let typename_lines: std::collections::BTreeSet<&str> =
        log.lines().filter(|l| l.starts_with("RingBuffer.h:") && l.contains("repaired implicit typename")).map(|l| l.split(':').nth(1).unwrap()).collect();
    assert!(typename_lines.len() >= 9, "{typename_lines:?}\n{log}");
    // What -fpermissive accepts is warned about, never repaired.
    assert!(!log.lines().any(|l| l.starts_with("Permissive.") && l.contains("repaired")), "{log}");
    for warning in ["extra qualification", "default argument given for parameter 2", "no declarations were found by argument-dependent lookup"] {
        assert!(log.lines().any(|l| l.starts_with("Permissive.") && l.contains("warning:") && l.contains(warning)), "{warning}:\n{log}");
    }
    // A warning inside the repaired header names the header and its line.
    let warn = format!("RingBuffer.h:{}:", line_of("RingBuffer.h", "inline char* RingName()"));
    assert!(log.lines().any(|l| l.starts_with(&warn) && l.contains("warning:")), "{warn}… warning:\n{log}");
    assert!(!log.contains("cargo-openr-repair"), "no diagnostic names the private copy:\n{log}");
    for f in fs::read_dir(repo().join("testdata/programs").join(PROGRAM).join("OldCode")).unwrap().flatten() {
        let copy = fs::read(s.project().join("OldCode").join(f.file_name())).unwrap();
        assert_eq!(copy, fs::read(f.path()).unwrap(), "{:?} is unchanged", f.file_name());
    }
    s.assert_no_shadow_left();

    let out = run_ms(&s.project().join("MS"), &["--for", "1s", "--speed", "max"]);
    assert_eq!(out.code, Some(0), "{}\n{}", out.stdout, out.stderr);
    let lines = out.lines_starting("OldCode :");
    assert_eq!(
        lines,
        [
            "OldCode : 5 samples",
            "OldCode : ring newest 12 sum 32 peak 12 count 4",
            "OldCode : ring header RingBuffer.h",
            "OldCode : first 7 at 3, first 99 at -1, above 5: 3",
            "OldCode : registry 2 -> 1",
            "OldCode : clip 100 0 1234 max 32767",
            "OldCode : track pan -1.5 tilt 10",
            "OldCode : clock ok",
            "OldCode : row sum 60",
            "OldCode : label head-42 value 42",
            "OldCode : cycle counter 0",
            "OldCode : servo 3 scaled 42 four 20 servos 1",
            "OldCode : stop",
        ],
        "{}",
        out.stderr
    );
}

#[test]
fn a_repaired_header_keeps_its_file_and_line_for_gdb() {
    let s = Scratch::new();
    let (ok, log) = s.make(&["STRIP=true"]);
    assert!(ok, "{log}");
    s.assert_no_shadow_left();
    let obj = s.project().join("OldCode/OldCode.o");
    let raw = fs::read(&obj).unwrap();
    assert!(!raw.windows(18).any(|w| w == b"cargo-openr-repair"), "the object names no private copy");
    let (ok, info) = run(Command::new("readelf").arg("--debug-dump=info").arg(&obj));
    assert!(ok, "{info}");
    let name = info.lines().find(|l| l.contains("DW_AT_name")).unwrap_or("");
    assert!(name.trim_end().ends_with(": OldCode.cc"), "the unit is OldCode.cc: {name}");
    let (_, lines) = run(Command::new("readelf").arg("--debug-dump=line").arg(&obj));
    assert!(lines.contains("RingBuffer.h"), "the line table names the header:\n{lines}");

    // PeakRing::Peak is repaired (names from its dependent base); at -O2 it is inlined
    // into DoStart, where gdb resolves the line of its head.
    let line = line_of("RingBuffer.h", "T Peak() const {");
    let (_, out) = run(Command::new("timeout")
        .arg("120")
        .arg("gdb")
        .args(["-batch", "-nx", "-ex", "set breakpoint pending on", "-ex"])
        .arg(format!("break RingBuffer.h:{line}"))
        .args(["-ex", "run", "-ex", "bt 3", "-ex", "kill", "--args"])
        .arg(exe())
        .arg("run")
        .arg(s.project().join("MS"))
        .args(["--for", "1s", "--speed", "max"])
        .env("OPENRSDK_ROOT", sdk_root()));
    assert!(out.contains("Breakpoint 1, "), "the breakpoint is hit:\n{out}");
    // At the head, or a line or two into it: the wrapper's alignment check
    // (-fsanitize=alignment) may come first in the inlined code.
    let hit = out.lines().skip_while(|l| !l.contains("Breakpoint 1, ")).take(3).collect::<Vec<_>>().join("\n");
    let at = (line..line + 3).map(|l| format!("RingBuffer.h:{l}")).find(|at| hit.contains(at) || out.contains(&format!("at {at}")));
    assert!(at.is_some(), "stopped at RingBuffer.h:{line} (or just after):\n{out}");
    assert!(hit.contains("PeakRing<int>::Peak"), "in PeakRing::Peak:\n{out}");
    assert!(out.contains(" at OldCode.cc:"), "called from OldCode.cc:\n{out}");
    assert!(!out.contains("cargo-openr-repair"), "{out}");
}

#[test]
fn dependency_files_and_compile_commands_name_the_user_files() {
    let s = Scratch::new();
    let out = Command::new(exe()).args(["build", "--sdk"]).arg(sdk_root()).arg("--path").arg(s.project()).env("TMPDIR", s.tmp.path()).output().unwrap();
    let log = format!("{}{}", String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr));
    assert!(out.status.success(), "{log}");
    assert!(log.contains("repaired implicit typename"), "{log}");
    let cc = fs::read_to_string(s.project().join("compile_commands.json")).unwrap();
    assert!(cc.contains("OldCode.cc") && !cc.contains("cargo-openr-repair"), "{cc}");
    let mut deps = Vec::new();
    find_files(&s.project().join("target"), "d", &mut deps);
    let all: String = deps.iter().map(|d| fs::read_to_string(d).unwrap()).collect();
    assert!(all.contains("RingBuffer.h") && all.contains("Tracker.h"), "{deps:?}: {all}");
    assert!(!all.contains("cargo-openr-repair"), "{all}");
    s.assert_no_shadow_left();
}

fn find_files(dir: &Path, ext: &str, out: &mut Vec<PathBuf>) {
    for e in fs::read_dir(dir).into_iter().flatten().flatten() {
        let p = e.path();
        if p.is_dir() {
            find_files(&p, ext, out);
        } else if p.extension().is_some_and(|x| x == ext) {
            out.push(p);
        }
    }
}

/// Runs the SDK's g++ and the host g++ with the wrapper's flags on `unit` in `dir`:
/// (wrapper exit code, wrapper stderr, host exit code, host stderr).
fn both_compilers(dir: &Path, tmp: &Path, unit: &str) -> (Option<i32>, String, Option<i32>, String) {
    let wrapper = Command::new(sdk_root().join("bin/mipsel-linux-g++")).args(["-c", unit, "-o", "w.o"]).env("TMPDIR", tmp).current_dir(dir).output().unwrap();
    let host = Command::new("g++").args(openr_wrappers::cxx_flags()).args(["-c", unit, "-o", "h.o"]).current_dir(dir).output().unwrap();
    let text = |b: &[u8]| String::from_utf8_lossy(b).into_owned();
    (wrapper.status.code(), text(&wrapper.stderr), host.status.code(), text(&host.stderr))
}

#[test]
fn an_error_of_no_legacy_class_fails_exactly_as_before() {
    let dir = tempfile::tempdir().unwrap();
    let tmp = tempfile::tempdir().unwrap();
    fs::write(dir.path().join("Box.h"), "struct Box { int width; };\n").unwrap();
    // Not a legacy class: no repair is tried at all.
    fs::write(dir.path().join("plain.cc"), "#include \"Box.h\"\nint area(Box b) { return b.width * b.height; }\n").unwrap();
    // A legacy class and a real error: repaired as far as it goes, then the original output.
    fs::write(
        dir.path().join("mixed.cc"),
        "#include \"Box.h\"\ntemplate <class T> struct Holder { T::size_type n; };\nint area(Box b) { return b.width * b.height; }\n",
    )
    .unwrap();
    for unit in ["plain.cc", "mixed.cc"] {
        let (wcode, werr, hcode, herr) = both_compilers(dir.path(), tmp.path(), unit);
        assert_eq!(wcode, hcode, "{unit}: same exit status\n{werr}");
        assert_ne!(wcode, Some(0));
        assert!(werr.starts_with(&herr), "{unit}: g++'s own output first, unchanged:\n--- wrapper\n{werr}\n--- g++\n{herr}");
        let rest = &werr[herr.len()..];
        assert!(rest.lines().all(|l| l.contains(": note: [cargo-openr] ")), "{unit}: only notes after it:\n{rest}");
        assert!(!werr.contains("[cargo-openr] repaired"), "{unit}: nothing claims a repair:\n{werr}");
        if unit == "plain.cc" {
            assert_eq!(werr, herr, "plain.cc: byte for byte");
        }
        assert!(!dir.path().join("w.o").exists(), "{unit}: no object file");
        let left: Vec<_> = fs::read_dir(tmp.path()).unwrap().flatten().map(|e| e.file_name()).collect();
        assert!(left.is_empty(), "{unit}: left behind in TMPDIR: {left:?}");
    }
    assert_eq!(fs::read_to_string(dir.path().join("Box.h")).unwrap(), "struct Box { int width; };\n");
}

/// A host compiler that logs each run's arguments to `log`, then runs g++.
fn logging_compiler(dir: &Path, log: &Path) -> PathBuf {
    use std::os::unix::fs::PermissionsExt;
    let script = dir.join("logging-g++");
    fs::write(&script, format!("#!/bin/sh\necho \"$@\" >> '{}'\nexec g++ \"$@\"\n", log.display())).unwrap();
    fs::set_permissions(&script, fs::Permissions::from_mode(0o755)).unwrap();
    script
}

#[test]
fn a_unit_that_compiles_runs_the_host_compiler_once_with_the_usual_flags() {
    let dir = tempfile::tempdir().unwrap();
    let log = dir.path().join("runs.log");
    let gxx = logging_compiler(dir.path(), &log);
    fs::write(dir.path().join("ok.cc"), "int f() { return 1; }\n").unwrap();
    fs::write(dir.path().join("old.cc"), "template <class T> struct H { T::size_type n; };\nH<int>* h;\n").unwrap();
    let compile = |unit: &str| {
        Command::new(sdk_root().join("bin/mipsel-linux-g++")).args(["-c", unit]).env("OPENR_HOST_CXX", &gxx).current_dir(dir.path()).output().unwrap()
    };
    let out = compile("ok.cc");
    assert!(out.status.success() && out.stderr.is_empty(), "{}", String::from_utf8_lossy(&out.stderr));
    let runs = fs::read_to_string(&log).unwrap();
    assert_eq!(runs.lines().count(), 1, "one g++ run: {runs}");
    assert!(!runs.contains("-fdiagnostics") && !runs.contains("-fsyntax-only"), "{runs}");
    // The repair path does run more (preprocessing, rounds, the compile): what the log
    // shows for a unit that needs it.
    fs::remove_file(&log).unwrap();
    let out = compile("old.cc");
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let runs = fs::read_to_string(&log).unwrap();
    assert!(runs.lines().count() >= 4, "{runs}");
    assert!(dir.path().join("old.o").exists() && dir.path().join("ok.o").exists());
}
