//! The alignment trap as `mipsel-linux-g++`/`gcc` build it: with the SDK root's gcc
//! plugin each access is checked against the robot's alignment and a failed check never
//! returns; without the plugin (a compiler it was not built for, `OPENR_ALIGNMENT_TRAP=ubsan`)
//! gcc's own check calls a handler that returns. `testdata/align-trap/cases.cc` makes
//! one misaligned access per case and brings its own handlers, which say which one ran.
use std::path::{Path, PathBuf};
use std::process::Command;

use crate::support::sdk_root;

fn testdata(file: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../testdata/align-trap").join(file)
}

/// Builds `file` with the root's `tool` and `flags` (and `env`) into `dir/name`.
fn build(root: &Path, tool: &str, file: &str, flags: &[&str], env: &[(&str, &str)], dir: &Path, name: &str) -> PathBuf {
    let exe = dir.join(name);
    let mut cmd = Command::new(root.join("bin").join(tool));
    cmd.args(flags).arg("-o").arg(&exe).arg(testdata(file)).envs(env.iter().copied());
    let (ok, log) = crate::support::run(&mut cmd);
    assert!(ok, "{tool} {flags:?} {env:?}: {log}");
    exe
}

/// `(exit code, stdout)` of case `n`.
fn case(exe: &Path, n: u32) -> (Option<i32>, String) {
    let out = Command::new(exe).arg(n.to_string()).output().unwrap();
    (out.status.code(), String::from_utf8_lossy(&out.stdout).into_owned())
}

fn assert_stops(exe: &Path, n: u32, what: &str) {
    let (code, out) = case(exe, n);
    assert_eq!((code, out.as_str()), (Some(3), format!("stopped {what}\n").as_str()), "case {n} of {}", exe.display());
}

fn assert_goes(exe: &Path, n: u32) {
    let (code, out) = case(exe, n);
    assert_eq!(code, Some(0), "case {n} of {}: {out}", exe.display());
    assert!(out.ends_with(&format!("case {n} went through, the handler returned 0 times\n")), "case {n} of {}: {out}", exe.display());
}

/// A compiler that is g++ but not the binary the root's plugin was built for.
fn other_gxx(dir: &Path) -> PathBuf {
    use std::os::unix::fs::PermissionsExt;
    let script = dir.join("other-g++");
    std::fs::write(&script, "#!/bin/sh\nexec g++ \"$@\"\n").unwrap();
    std::fs::set_permissions(&script, std::fs::Permissions::from_mode(0o755)).unwrap();
    script
}

#[test]
fn the_plugin_stops_exactly_what_the_robot_would_and_never_returns() {
    let root = sdk_root();
    let dir = tempfile::tempdir().unwrap();
    // -fchecking=2: gcc verifies the CFG, SSA and loop tree the plugin changed.
    let exe = build(root, "mipsel-linux-g++", "cases.cc", &["-O2", "-fchecking=2"], &[], dir.path(), "o2");
    assert_stops(&exe, 1, "'volatile int' at 2 mod 8");
    assert_stops(&exe, 2, "'volatile short int' at 1 mod 8");
    assert_stops(&exe, 3, "'volatile float' at 2 mod 8");
    assert_stops(&exe, 4, "'volatile double' at 4 mod 8");
    assert_stops(&exe, 6, "'volatile long int' at 2 mod 8");
    // gcc checks `p->pan` against the struct (4 on the robot); the robot's sdc1 wants
    // the double itself 8-byte aligned, its int neighbour 4.
    assert_stops(&exe, 11, "'double' at 4 mod 8");
    assert_goes(&exe, 12);
    // A double the type says is 4-aligned (packed) is none of ldc1's business; an array's
    // at a varying index, and a long double (a double on the robot), are.
    assert_goes(&exe, 13);
    assert_stops(&exe, 14, "'double' at 4 mod 8");
    assert_stops(&exe, 15, "'volatile long double' at 4 mod 8");
    // An empty asm template is no MIPS and stays (a compiler barrier here).
    let (code, out) = case(&exe, 17);
    assert_eq!((code, out.as_str()), (Some(0), "sum 45\ncase 17 went through, the handler returned 0 times\n"));
    // Words of the robot at a 4-byte address: a long, a long long, a pointer, a struct
    // of words, a member summed in a loop. The handler is not even called.
    for n in [5, 7, 8, 9, 10] {
        assert_goes(&exe, n);
    }
    let (_, out) = case(&exe, 10);
    assert!(out.starts_with("sum 6400\n"), "{out}");
    // Unoptimised code and C go through the same pass.
    let o0 = build(root, "mipsel-linux-g++", "cases.cc", &["-O0", "-fchecking=2"], &[], dir.path(), "o0");
    assert_stops(&o0, 1, "'volatile int' at 2 mod 8");
    assert_goes(&o0, 5);
    let c = build(root, "mipsel-linux-gcc", "cases.c", &["-O3", "-fchecking=2"], &[], dir.path(), "c");
    assert_stops(&c, 1, "'volatile int' at 2 mod 8");
    let (code, out) = case(&c, 5);
    assert_eq!((code, out.as_str()), (Some(0), "case 5 went through\n"));
    assert_stops(&c, 11, "'double' at 4 mod 8");
}

#[test]
fn the_plugin_leaves_mips_assembly_out_and_says_so() {
    let dir = tempfile::tempdir().unwrap();
    let exe = dir.path().join("mips-asm");
    let out =
        Command::new(sdk_root().join("bin/mipsel-linux-g++")).args(["-O2", "-fchecking=2", "-o"]).arg(&exe).arg(testdata("mips-asm.cc")).output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{err}");
    // One note per statement, at its line.
    for line in [9, 10, 11] {
        let note =
            |l: &&str| l.contains(&format!("mips-asm.cc:{line}:")) && l.contains("note: [cargo-openr] MIPS inline assembly left out: the PC cannot run it");
        assert!(err.lines().any(|l| note(&l)), "line {line}: {err}");
    }
    let run = Command::new(&exe).output().unwrap();
    assert_eq!(String::from_utf8_lossy(&run.stdout), "count 0 kept 5\n");
}

#[test]
fn the_flags_that_make_the_check_fatal_are_honoured_with_the_plugin_too() {
    use std::os::unix::process::ExitStatusExt;
    let dir = tempfile::tempdir().unwrap();
    // -fno-sanitize-recover: the PC's alignment is fatal, an 8-byte long at 4 included.
    let exe = build(sdk_root(), "mipsel-linux-g++", "cases.cc", &["-O2", "-fno-sanitize-recover=alignment"], &[], dir.path(), "fatal");
    assert_stops(&exe, 5, "'volatile long int' at 4 mod 8");
    assert_stops(&exe, 1, "'volatile int' at 2 mod 8");
    // -fsanitize-undefined-trap-on-error: a trap instruction instead of the handler.
    let exe = build(sdk_root(), "mipsel-linux-g++", "cases.cc", &["-O2", "-fsanitize-undefined-trap-on-error"], &[], dir.path(), "trap");
    let out = Command::new(&exe).arg("1").output().unwrap();
    assert_eq!((out.status.signal(), out.stdout.as_slice()), (Some(libc::SIGILL), &b""[..]), "{out:?}");
    assert_goes(&exe, 5);
}

#[test]
fn without_the_plugin_mips_assembly_fails_with_a_note_that_says_why() {
    let dir = tempfile::tempdir().unwrap();
    let unit = dir.path().join("cycles.cc");
    std::fs::write(&unit, "unsigned f()\n{\n    unsigned c;\n    __asm__ __volatile__(\"mfc0 %0, $9\" : \"=r\"(c));\n    return c;\n}\n").unwrap();
    let other = other_gxx(dir.path());
    let out = Command::new(sdk_root().join("bin/mipsel-linux-g++"))
        .args(["-O2", "-c", "-o"])
        .arg(dir.path().join("cycles.o"))
        .arg(&unit)
        .env("OPENR_HOST_CXX", &other)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success(), "{err}");
    assert!(
        err.lines().any(|l| l.ends_with("cycles.cc:4: note: [cargo-openr] no such instruction: `mfc0 %eax,$9': MIPS inline assembly the PC cannot run; the SDK's gcc plugin leaves it out, but this root has none for this compiler (`cargo openr doctor` says why); or put it under `#ifdef __mips__`")),
        "{err}"
    );
}

#[test]
fn without_the_plugin_gcc_checks_the_pc_alignment_and_its_handler_returns() {
    let root = sdk_root();
    let dir = tempfile::tempdir().unwrap();
    let other = other_gxx(dir.path());
    let builds = [
        build(root, "mipsel-linux-g++", "cases.cc", &["-O2"], &[("OPENR_ALIGNMENT_TRAP", "ubsan")], dir.path(), "ubsan"),
        build(root, "mipsel-linux-g++", "cases.cc", &["-O2"], &[("OPENR_HOST_CXX", other.to_str().unwrap())], dir.path(), "other"),
    ];
    for exe in &builds {
        // libmcoopstub's handler decides there (it faults case 1, not case 5).
        let (code, out) = case(exe, 1);
        assert_eq!(code, Some(0), "{out}");
        assert!(out.starts_with("went on after 'volatile int' at 2 mod 8\n"), "{}: {out}", exe.display());
        // In the loop: at least once per pixel summed (6400), where the plugin never calls.
        let (_, out) = case(exe, 10);
        let calls: u32 = out.rsplit("returned ").next().and_then(|t| t.trim_end().strip_suffix(" times")).and_then(|n| n.parse().ok()).unwrap_or(0);
        assert!(out.contains("went on after 'struct Counter' at 4 mod 8\n") && calls >= 6400, "{out}");
    }
}

/// A g++ that behaves as `script` says first (a shell `case` on its arguments), then is
/// the host's g++. Each one is a compiler of its own for the root (its own identity).
fn gxx_that(dir: &Path, name: &str, script: &str) -> PathBuf {
    use std::os::unix::fs::PermissionsExt;
    let path = dir.join(name);
    std::fs::write(&path, format!("#!/bin/sh\n{script}\nexec g++ \"$@\"\n")).unwrap();
    std::fs::set_permissions(&path, std::fs::Permissions::from_mode(0o755)).unwrap();
    path
}

/// The root's plugins and notes (`libexec/openr-align/*.so`, `*.missing` texts).
fn plugins(root: &Path) -> (usize, Vec<String>) {
    let mut so = 0;
    let mut notes = Vec::new();
    for e in std::fs::read_dir(root.join("libexec/openr-align")).unwrap().flatten() {
        let p = e.path();
        match p.extension().and_then(|x| x.to_str()) {
            Some("so") => so += 1,
            Some("missing") => notes.push(std::fs::read_to_string(&p).unwrap()),
            _ => {}
        }
    }
    notes.sort();
    (so, notes)
}

/// `cargo openr <args>` with `OPENR_HOST_CXX=gxx`: (success, stderr).
fn with_gxx(gxx: &Path, args: &[&str]) -> (bool, String) {
    let out = Command::new(crate::support::exe()).args(args).env("OPENR_HOST_CXX", gxx).output().unwrap();
    (out.status.success(), format!("{}{}", String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr)))
}

#[test]
fn a_root_says_why_it_has_no_plugin_and_builds_it_when_it_can() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let root = d.join("sdk");
    let root_s = root.to_str().unwrap();
    // Headers missing at first, there once `headers-ok` exists: the same compiler.
    let late = gxx_that(
        d,
        "late-g++",
        &format!("[ \"$1\" = -print-file-name=plugin ] && [ ! -e {0}/headers-ok ] && {{ echo /nonexistent/plugin; exit 0; }}", d.display()),
    );
    let (ok, log) = with_gxx(&late, &["sdk", "install", "--prefix", root_s]);
    assert!(ok, "{log}");
    let (so, notes) = plugins(&root);
    assert_eq!(so, 0, "{notes:?}");
    assert!(notes.len() == 1 && notes[0].contains("has no plugin headers (apt-get install gcc-"), "{notes:?}");
    // Objects still build, on gcc's own check.
    let exe = build(&root, "mipsel-linux-g++", "cases.cc", &["-O2"], &[("OPENR_HOST_CXX", late.to_str().unwrap())], d, "late1");
    assert!(case(&exe, 1).1.starts_with("went on after 'volatile int'"));
    let (_, json) = with_gxx(&late, &["doctor", "--format", "json", "--sdk", root_s]);
    let v: serde_json::Value = serde_json::from_str(json.lines().next().unwrap_or_default()).unwrap_or_else(|e| panic!("{e}: {json}"));
    let f = v["findings"].as_array().unwrap().iter().find(|f| f["name"] == "alignment trap plugin").cloned().unwrap_or_default();
    assert_eq!(f["ok"], false, "{v}");
    assert!(f["detail"].as_str().unwrap_or_default().contains("has no plugin headers"), "{f}");
    assert!(f["fix"].as_str().unwrap_or_default().starts_with("apt-get install gcc-"), "{f}");
    // The headers are there now: the next use of the root builds the plugin.
    std::fs::write(d.join("headers-ok"), "").unwrap();
    let (ok, log) = with_gxx(&late, &["sdk", "install", "--prefix", root_s]);
    assert!(ok, "{log}");
    let exe = build(&root, "mipsel-linux-g++", "cases.cc", &["-O2"], &[("OPENR_HOST_CXX", late.to_str().unwrap())], d, "late2");
    assert_stops(&exe, 1, "'volatile int' at 2 mod 8");

    // A plugin that does not build: said once, not tried again at every use.
    let log_file = d.join("shared.log");
    let broken =
        gxx_that(d, "broken-g++", &format!("case \" $* \" in *\" -shared \"*) echo x >> {}; echo 'error: simulated' >&2; exit 1;; esac", log_file.display()));
    for _ in 0..2 {
        let (ok, log) = with_gxx(&broken, &["sdk", "install", "--prefix", root_s]);
        assert!(ok, "{log}");
        assert!(!log.contains("warning") && !log.contains("error"), "a root without the plugin is not an error: {log}");
    }
    assert_eq!(std::fs::read_to_string(&log_file).unwrap(), "x\n", "built once");
    // One that builds but does not load: the compiler is tried with it before it is kept.
    let refusing = gxx_that(d, "refusing-g++", "case \"$*\" in *-fplugin=*) echo 'cc1plus: error: cannot load plugin' >&2; exit 1;; esac");
    let (ok, log) = with_gxx(&refusing, &["sdk", "install", "--prefix", root_s]);
    assert!(ok, "{log}");
    let exe = build(&root, "mipsel-linux-g++", "cases.cc", &["-O2"], &[("OPENR_HOST_CXX", refusing.to_str().unwrap())], d, "refusing");
    assert!(case(&exe, 1).1.starts_with("went on after 'volatile int'"));
    let (_, notes) = plugins(&root);
    assert!(notes.iter().any(|n| n.contains("the alignment plugin does not build with") && n.contains("broken-g++")), "{notes:?}");
    assert!(notes.iter().any(|n| n.contains("refusing-g++ does not load the alignment plugin: cc1plus: error: cannot load plugin")), "{notes:?}");
    // Each compiler keeps its own: the working one still has its plugin.
    let exe = build(&root, "mipsel-linux-g++", "cases.cc", &["-O2"], &[("OPENR_HOST_CXX", late.to_str().unwrap())], d, "late3");
    assert_stops(&exe, 1, "'volatile int' at 2 mod 8");

    // A root the plugin cannot be written into is used as it is, with a warning.
    let plugins_dir = root.join("libexec/openr-align");
    std::fs::remove_dir_all(&plugins_dir).unwrap();
    std::fs::write(&plugins_dir, "not a directory").unwrap();
    let other = gxx_that(d, "blocked-g++", "");
    let (ok, log) = with_gxx(&other, &["sdk", "install", "--prefix", root_s]);
    assert!(ok, "{log}");
    assert!(log.contains(&format!("warning: cannot build the alignment trap's gcc plugin into {root_s}:")) && log.contains("gcc's own, slower check"), "{log}");
}
