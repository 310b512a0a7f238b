//! The SDK root's tools, run the way Makefiles run them: by path, from the object's
//! build directory.
use std::fs;
use std::path::{Path, PathBuf};
use std::process::Command;

use crate::support::{build, run, run_ms, sdk_root};

fn tool(rel: &str) -> PathBuf {
    sdk_root().join(rel)
}

fn files_in(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = fs::read_dir(dir).unwrap().flatten().map(|e| e.file_name().to_string_lossy().into_owned()).collect();
    v.sort();
    v
}

/// A minimal object: hand-written stub (object-model 3) that also calls fopen.
const STUB: &str = r#"
#include <MCOOP.h>
#include <ObjectEntryTable.h>
#include <apsys.h>
#include <OPENR/OObject.h>
#include <stdio.h>
class Tiny : public OObject { public: Tiny() {} };
Tiny Self;
extern "C" void InitStub(OReasonMessage* m) { FILE* f = fopen("/MS/OPEN-R/X.TXT", "r"); if (f) fclose(f); Return(); }
GEN_ENTRY(InitEntry, InitStub);
GEN_ENTRY(PrologueEntry, Prologue);
ObjectEntry ObjectEntryTable[] = { {oentryINIT, (Entry)InitEntry}, {UNDEF, (Entry) ENTRY_UNDEF} };
"#;

fn compile(dir: &Path, name: &str, src: &str) {
    fs::write(dir.join(name), src).unwrap();
    let inc = sdk_root().join("OPEN_R/include");
    let (ok, log) = run(Command::new(tool("bin/mipsel-linux-g++"))
        .args(["-O2", "-g", "-I."])
        .arg(format!("-I{}", inc.join("R4000").display()))
        .arg(format!("-I{}", inc.display()))
        .args(["-c", name])
        .current_dir(dir));
    assert!(ok, "compiling {name} failed:\n{log}");
}

fn mkbin(dir: &Path, args: &[&str]) -> (bool, String) {
    run(Command::new(tool("OPEN_R/bin/mkbin")).arg("-p").arg(sdk_root()).args(args).current_dir(dir))
}

#[test]
fn mkbin_links_a_shared_object_with_wrapped_libc_calls() {
    let dir = tempfile::tempdir().unwrap();
    compile(dir.path(), "Tiny.cc", STUB);
    fs::write(dir.path().join("tiny.ocf"), "object tiny 3072 16384 128 cache tlb user\n").unwrap();
    let (ok, log) = mkbin(dir.path(), &["-v", "-o", "tiny.bin", "Tiny.o", "tiny.ocf", "-lObjectComm", "-lOPENR"]);
    assert!(ok, "{log}");
    assert!(log.contains("mkbin version 1.3") && log.contains("-Wl,-Bsymbolic"), "-v shows the commands:\n{log}");
    let (ok, log) = run(Command::new(tool("bin/mipsel-linux-strip")).arg("tiny.bin").current_dir(dir.path()));
    assert!(ok, "{log}");
    let missing = openr_wrappers_missing(&dir.path().join("tiny.bin"), &["ObjectEntryTable", "PrologueEntry", "InitEntry", "__wrap_fopen", "openr_ocf_name"]);
    assert!(missing.is_empty(), "missing from .dynsym after strip: {missing:?}");
}

fn openr_wrappers_missing(path: &Path, names: &[&str]) -> Vec<String> {
    use object::{Object, ObjectSymbol};
    let data = fs::read(path).unwrap();
    let file = object::File::parse(&*data).unwrap();
    names.iter().filter(|n| !file.dynamic_symbols().any(|s| s.is_definition() && s.name() == Ok(**n))).map(|n| n.to_string()).collect()
}

#[test]
fn mkbin_without_an_ocf_fails_and_writes_nothing() {
    let dir = tempfile::tempdir().unwrap();
    compile(dir.path(), "Tiny.cc", STUB);
    let (ok, log) = mkbin(dir.path(), &["-o", "tiny.bin", "Tiny.o"]);
    assert!(!ok);
    assert!(log.contains("mkbin: no object configuration: tiny.ocf does not exist"), "{log}");
    assert_eq!(files_in(dir.path()), ["Tiny.cc", "Tiny.o"]);
}

#[test]
fn mkbin_reports_a_malformed_ocf_with_file_and_line() {
    let dir = tempfile::tempdir().unwrap();
    compile(dir.path(), "Tiny.cc", STUB);
    fs::write(dir.path().join("tiny.ocf"), "# header\nobject tiny 3072 16384\n").unwrap();
    let (ok, log) = mkbin(dir.path(), &["-o", "tiny.bin", "Tiny.o", "tiny.ocf"]);
    assert!(!ok);
    assert!(log.contains("mkbin: tiny.ocf:2: ocf format error: expected 7 values"), "{log}");
    assert!(!dir.path().join("tiny.bin").exists());
}

#[test]
fn mkbin_rejects_an_object_without_entry_table() {
    let dir = tempfile::tempdir().unwrap();
    compile(dir.path(), "plain.cc", "int plain(int x) { return x + 1; }\n");
    fs::write(dir.path().join("plain.ocf"), "object plain 3072 16384 128 cache tlb user\n").unwrap();
    let (ok, log) = mkbin(dir.path(), &["-o", "plain.bin", "plain.o", "plain.ocf"]);
    assert!(!ok);
    assert!(log.contains("symbol ObjectEntryTable not found"), "{log}");
    let left: Vec<String> = files_in(dir.path()).into_iter().filter(|f| f.contains(".bin")).collect();
    assert!(left.is_empty(), "no output or partial file left: {left:?}");
}

#[test]
fn run_refuses_an_entry_table_without_its_undef_row() {
    // Two rows and no {UNDEF, ENTRY_UNDEF}: the table is read only as far as its symbol's
    // size, not on into whatever the linker put after it.
    let dir = tempfile::tempdir().unwrap();
    let unterminated =
        STUB.replace("{UNDEF, (Entry) ENTRY_UNDEF} };", "{oentryINIT, (Entry)InitEntry} };\nObjectEntry Next[] = { {UNDEF, (Entry) ENTRY_UNDEF} };");
    compile(dir.path(), "Tiny.cc", &unterminated);
    fs::write(dir.path().join("tiny.ocf"), "object tiny 3072 16384 128 cache tlb user\n").unwrap();
    let (ok, log) = mkbin(dir.path(), &["-o", "tiny.bin", "Tiny.o", "tiny.ocf", "-lObjectComm", "-lOPENR"]);
    assert!(ok, "{log}");
    let p = build("hello");
    let bin = p.ms().join("OPEN-R/MW/OBJS/HELLO.BIN");
    fs::copy(dir.path().join("tiny.bin"), &bin).unwrap();
    let out = run_ms(&p.ms(), &["--for", "100ms", "--speed", "max"]);
    assert!(matches!(out.code, Some(c) if c != 0), "{:?}\n{}", out.code, out.stderr);
    assert!(out.stderr.contains("its ObjectEntryTable (2 rows) does not end with the {UNDEF, ENTRY_UNDEF} row"), "{}", out.stderr);
}

#[test]
fn mkbin_shows_the_failing_link_command() {
    let dir = tempfile::tempdir().unwrap();
    fs::write(dir.path().join("x.ocf"), "object x 3072 16384 128 cache tlb user\n").unwrap();
    let (ok, log) = mkbin(dir.path(), &["-o", "x.bin", "missing.o", "x.ocf"]);
    assert!(!ok);
    assert!(log.contains("mkbin: running the following command failed") && log.contains("missing.o"), "{log}");
    assert!(!dir.path().join("x.bin").exists());
}

#[test]
fn mkbin_rejects_two_ocf_files() {
    let dir = tempfile::tempdir().unwrap();
    let (ok, log) = mkbin(dir.path(), &["a.ocf", "-m", "b.ocf"]);
    assert!(!ok);
    assert!(log.contains("mkbin: .ocf multiply specified"), "{log}");
}

#[test]
fn compiler_wrapper_neutralises_mips_asm_and_keeps_host_macros() {
    let dir = tempfile::tempdir().unwrap();
    let src = "#ifdef __mips__\n#error __mips__ must not be defined\n#endif\n\
               int use_unusable_coprocessor() { int r = 0; asm(\"mfc0 $2, $12\"); return r; }\n\
               void* p; int lossy() { return (int)p; }\n";
    fs::write(dir.path().join("Crash.cc"), src).unwrap();
    let (ok, log) = run(Command::new(tool("bin/mipsel-linux-g++")).args(["-c", "Crash.cc"]).current_dir(dir.path()));
    assert!(ok, "{log}");
    fs::write(dir.path().join("old.c"), "int counter;\nint f() { asm(\"nop\"); return counter; }\n").unwrap();
    let (ok, log) = run(Command::new(tool("bin/mipsel-linux-gcc")).args(["-O2", "-c", "old.c"]).current_dir(dir.path()));
    assert!(ok, "{log}");
}

#[test]
fn gzcp_gzips_and_checks_its_arguments() {
    let dir = tempfile::tempdir().unwrap();
    fs::write(dir.path().join("a.bin"), b"\x7fELF payload").unwrap();
    let (ok, log) = run(Command::new(tool("OPEN_R/bin/gzcp")).args(["a.bin", "A.BIN"]).current_dir(dir.path()));
    assert!(ok, "{log}");
    let gz = fs::read(dir.path().join("A.BIN")).unwrap();
    let mut out = Vec::new();
    std::io::Read::read_to_end(&mut flate2::read::GzDecoder::new(&gz[..]), &mut out).unwrap();
    assert_eq!(out, b"\x7fELF payload");

    let (ok, log) = run(Command::new(tool("OPEN_R/bin/gzcp")).arg("a.bin").current_dir(dir.path()));
    assert!(!ok && log.contains("usage: gzcp SOURCE DESTINATION"), "{log}");
    let (ok, log) = run(Command::new(tool("OPEN_R/bin/gzcp")).args(["nope.bin", "B.BIN"]).current_dir(dir.path()));
    assert!(!ok && log.contains("gzcp: nope.bin:"), "{log}");
    assert!(!dir.path().join("B.BIN").exists());
}

#[test]
fn stubgen2_from_the_root_fails_cleanly_on_a_bad_stub_cfg() {
    let dir = tempfile::tempdir().unwrap();
    fs::write(
        dir.path().join("stub.cfg"),
        "ObjectName : Bad\nNumOfOSubject : 2\nNumOfOObserver : 1\n\
         Service : \"Bad.Out.char.S\", null, Ready()\nService : \"Bad.In.char.O\", null, Notify()\n",
    )
    .unwrap();
    let (ok, log) = run(Command::new(tool("OPEN_R/bin/stubgen2")).arg("stub.cfg").current_dir(dir.path()));
    assert!(!ok);
    assert!(log.contains("stubgen2: stub.cfg:2:") && log.contains("numOfOSubject"), "{log}");
    assert_eq!(files_in(dir.path()), ["stub.cfg"], "no partial output");
}

#[test]
fn a_tool_outside_an_sdk_root_says_so() {
    let dir = tempfile::tempdir().unwrap();
    let fake = dir.path().join("mkbin");
    fs::copy(crate::support::exe(), &fake).unwrap();
    let (ok, log) = run(Command::new(&fake).arg("x.o"));
    assert!(!ok);
    assert!(log.contains("mkbin: cannot find the SDK root"), "{log}");
}

#[test]
fn compiler_wrapper_explains_what_only_gcc_3_3_accepted() {
    let dir = tempfile::tempdir().unwrap();
    // With an error of no legacy class beside them (line 7) the legacy repair gives up,
    // and the notes say what to change.
    fs::write(
        dir.path().join("Old.cc"),
        "struct A { void m(int a, int a); };\nint g()\n{\n    for (int i = 0; i < 3; i++) {}\n    return i;\n}\nint h() { return 1 +; }\n",
    )
    .unwrap();
    let (ok, log) = run(Command::new(tool("bin/mipsel-linux-g++")).args(["-c", "Old.cc"]).current_dir(dir.path()));
    assert!(!ok);
    assert!(log.contains("Old.cc:1:") && log.contains("note: [cargo-openr] gcc 3.3 accepted the same parameter name twice"), "{log}");
    assert!(log.contains("Old.cc:5:") && log.contains("note: [cargo-openr] `i` is declared in an earlier `for` statement"), "{log}");
}

#[test]
fn a_missing_host_compiler_is_named_with_where_it_was_looked_for() {
    let dir = tempfile::tempdir().unwrap();
    fs::write(dir.path().join("a.cc"), "int f() { return 1; }\n").unwrap();
    let out =
        Command::new(tool("bin/mipsel-linux-g++")).args(["-c", "a.cc"]).env("OPENR_HOST_CXX", "nonexistent-gxx").current_dir(dir.path()).output().unwrap();
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("host tool `nonexistent-gxx` (named by OPENR_HOST_CXX) not found; install it with `apt-get install g++`"), "{err}");
    assert!(!dir.path().join("a.o").exists());
}
