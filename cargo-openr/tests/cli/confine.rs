//! Objects see the Memory Stick and nothing else (object-model 1.5; issue 18).
use std::fs;
use std::os::unix::fs::symlink;
use std::path::Path;

use crate::support::{build, run_ms};

/// Every route `testdata/programs/escape` tries, and the errno that must refuse it.
const ROUTES: &[(&str, &str)] = &[
    ("fopen(OUTDIR/NEW1.TXT, w)", "EACCES"),
    ("fopen(OUTDIR/NEW2.TXT, a)", "EACCES"),
    ("open(OUTDIR/NEW3.TXT, O_CREAT)", "EACCES"),
    ("creat(OUTDIR/NEW4.TXT)", "EACCES"),
    ("ofstream(OUTDIR/NEW5.TXT)", "EACCES"),
    ("mkdir(OUTDIR/NEWDIR)", "EACCES"),
    ("rename(DATA/P/VICTIM.TXT, OUTDIR/..)", "EACCES"),
    ("fopen(DANGLING/NEW6.TXT, w)", "EACCES"),
    ("fopen(LINKFILE.TXT, w) (dangling)", "EACCES"),
    ("fopen(OUTDIR/SECRET.TXT, r)", "EACCES"),
    ("ifstream(OUTDIR/SECRET.TXT)", "EACCES"),
    ("stat(OUTDIR/SECRET.TXT)", "EACCES"),
    ("unlink(OUTDIR/SECRET.TXT)", "EACCES"),
    ("ifstream(<stick>/../../../../etc/passwd)", "EACCES"),
    ("fopen(<stick>/../../../../etc/passwd)", "EACCES"),
    ("fopen(/MS/../etc/passwd)", "EACCES"),
    ("ifstream(/etc/passwd)", "ENOENT"),
    ("openat(AT_FDCWD, /etc/passwd)", "ENOENT"),
    ("openat(dirfd, ../../../../etc/passwd)", "EACCES"),
    ("scandir(/etc)", "ENOENT"),
    ("opendir(/etc)", "ENOENT"),
    ("stat(/etc/passwd)", "ENOENT"),
    ("access(/etc/passwd)", "ENOENT"),
    ("realpath(/etc/passwd)", "ENOENT"),
    ("realpath(/MS/OUTDIR)", "EACCES"),
    ("symlink(/etc/passwd, <outside>/HOSTLINK)", "ENOENT"),
    ("symlink(/etc, /MS/OPEN-R/ETC)", "EPERM"),
    ("link(<outside>/SECRET.TXT, /MS/HARD.TXT)", "ENOENT"),
    ("chmod(<outside>/SECRET.TXT)", "ENOENT"),
    ("truncate(<outside>/SECRET.TXT)", "ENOENT"),
    ("utime(<outside>/SECRET.TXT)", "ENOENT"),
    ("unlink(<outside>/SECRET.TXT)", "ENOENT"),
    ("rename(<outside>/SECRET.TXT, /MS/S.TXT)", "ENOENT"),
    ("mkdir(<outside>/NEWDIR)", "ENOENT"),
    ("chdir(/MS/OPEN-R)", "EACCES"),
    ("mkstemp(/tmp/escapeXXXXXX)", "ENOSYS"),
    ("tmpfile()", "ENOSYS"),
    ("own thread: ifstream(/etc/passwd)", "ENOENT"),
    ("own thread: fopen(<outside>/SECRET.TXT)", "ENOENT"),
    ("own thread: fopen(OUTDIR/NEW8.TXT, w)", "EACCES"),
];

const SECRET: &str = "host file: must stay as it is\n";

/// The escape program's stick with its links, and the host directory they lead to.
fn escape_stick() -> (crate::support::Built, tempfile::TempDir) {
    let p = build("escape");
    let ms = p.ms().canonicalize().unwrap();
    let outside = tempfile::tempdir().unwrap();
    fs::write(outside.path().join("SECRET.TXT"), SECRET).unwrap();
    symlink(outside.path(), ms.join("OUTDIR")).unwrap();
    symlink(outside.path().join("MISSING"), ms.join("DANGLING")).unwrap();
    symlink(outside.path().join("NEW7.TXT"), ms.join("LINKFILE.TXT")).unwrap();
    symlink(ms.join("OPEN-R/MW/DATA/P"), ms.join("INSIDE")).unwrap();
    let cfg = format!("{}\n{}\n", ms.display(), outside.path().display());
    fs::write(ms.join("OPEN-R/MW/CONF/ESCAPE.CFG"), cfg).unwrap();
    (p, outside)
}

#[test]
fn every_way_out_of_the_memory_stick_is_refused() {
    let (p, outside) = escape_stick();
    let out = run_ms(&p.ms(), &["--for", "1s", "--speed", "max"]);
    assert_eq!(out.code, Some(0), "{}\n{}", out.stdout, out.stderr);
    assert!(out.stdout.contains("Escape : done"), "{}", out.stdout);
    let mut wrong = Vec::new();
    for (route, errno) in ROUTES {
        let line = out.lines_starting("Escape : ").into_iter().find(|l| l[9..].trim_start().starts_with(route));
        let want = format!("refused ({errno})");
        match line {
            Some(l) if l.ends_with(&want) => {}
            other => wrong.push(format!("{route}: want {want}, got {other:?}")),
        }
    }
    assert!(wrong.is_empty(), "routes not refused as they must be:\n  {}\n\nstdout:\n{}", wrong.join("\n  "), out.stdout);
    assert_eq!(out.lines_starting("Escape : ").iter().filter(|l| l.contains("NOT REFUSED")).count(), 0, "{}", out.stdout);

    // Nothing appeared, moved or changed outside; the stick kept its file.
    let names: Vec<String> = fs::read_dir(outside.path()).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
    assert_eq!(names, ["SECRET.TXT"], "files made outside the stick");
    assert_eq!(fs::read_to_string(outside.path().join("SECRET.TXT")).unwrap(), SECRET);
    assert!(p.ms().join("OPEN-R/MW/DATA/P/VICTIM.TXT").is_file());
    assert!(fs::symlink_metadata(p.ms().join("OPEN-R/ETC")).is_err(), "no link made in the stick");
    assert!(!Path::new(&p.ms().join("HARD.TXT")).exists());
}

#[test]
fn the_stick_still_works_through_inner_links_and_own_threads() {
    let (p, _outside) = escape_stick();
    let out = run_ms(&p.ms(), &["--for", "1s", "--speed", "max"]);
    assert!(out.stdout.contains("Escape : own thread: ifstream(/MS/.../ESCAPE.CFG) ok"), "{}", out.stdout);
    assert!(out.stdout.contains("Escape : link inside the stick, write and read ok"), "{}", out.stdout);
    // realpath names /MS paths, as stored, never the host path behind them.
    assert!(out.stdout.contains("Escape : realpath(/ms/open-r/../OPEN-R/mw/conf/escape.cfg) = /MS/OPEN-R/MW/CONF/ESCAPE.CFG"), "{}", out.stdout);
    assert!(out.stdout.contains("Escape : realpath(/MS/INSIDE) = /MS/OPEN-R/MW/DATA/P"), "{}", out.stdout);
    assert_eq!(fs::read_to_string(p.ms().join("OPEN-R/MW/DATA/P/OK.TXT")).unwrap(), "written through INSIDE\n");
}

#[test]
fn the_runtime_exports_every_interposer() {
    let exe = Path::new(crate::support::exe());
    let interposers = [sdk_runtime::interpose::SYMBOLS, sdk_runtime::interpose::PROCESS_SYMBOLS, sdk_runtime::interpose::PROCESS_SYMBOLS7].concat();
    assert!(interposers.contains(&"posix_spawn") && interposers.contains(&"dlopen"), "{interposers:?}");
    let missing = openr_wrappers::mkbin::missing_dynamic_symbols(exe, &interposers).unwrap();
    assert!(missing.is_empty(), "not in the dynamic symbol table of cargo-openr: {missing:?}");
}

// ---- the images of the objects (issue 18.3) ----

/// `cargo openr run <ms> --for 1s` with `TMPDIR=tmp` (and objects loaded through files
/// when `files`): (exit code, stderr).
fn run_with_tmpdir(ms: &Path, tmp: &Path, files: bool) -> (Option<i32>, String) {
    let mut cmd = std::process::Command::new(crate::support::exe());
    cmd.env("OPENRSDK_ROOT", crate::support::sdk_root()).env("TMPDIR", tmp).env_remove("OPENR_SCRATCH_FILES");
    if files {
        cmd.env("OPENR_SCRATCH_FILES", "1");
    }
    let mut child = cmd
        .args(["run", "--for", "1s", "--speed", "max"])
        .arg(ms)
        .stdin(std::process::Stdio::null())
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let start = std::time::Instant::now();
    let status = loop {
        if let Some(st) = child.try_wait().unwrap() {
            break st;
        }
        if start.elapsed() > std::time::Duration::from_secs(60) {
            let _ = child.kill();
            panic!("cargo openr run {} hung for 60 s", ms.display());
        }
        std::thread::sleep(std::time::Duration::from_millis(10));
    };
    let mut err = String::new();
    std::io::Read::read_to_string(&mut child.stderr.take().unwrap(), &mut err).unwrap();
    (status.code(), err)
}

fn entries(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = fs::read_dir(dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
    v.sort();
    v
}

#[test]
fn loading_follows_no_link_planted_in_tmpdir_and_leaves_nothing() {
    let p = build("hello");
    let tmp = tempfile::tempdir().unwrap();
    let victim = tempfile::tempdir().unwrap();
    fs::write(victim.path().join("KEEP"), "victim").unwrap();
    // The old scratch path was $TMPDIR/cargo-openr-<pid>: plant it for the next pids.
    let last: u32 = fs::read_to_string("/proc/sys/kernel/ns_last_pid").unwrap().trim().parse().unwrap();
    for pid in last + 1..last + 2000 {
        symlink(victim.path(), tmp.path().join(format!("cargo-openr-{pid}"))).unwrap();
    }
    let planted = entries(tmp.path());
    for files in [false, true] {
        let (code, err) = run_with_tmpdir(&p.ms(), tmp.path(), files);
        assert_eq!(code, Some(0), "files={files}: {err}");
        assert_eq!(entries(victim.path()), ["KEEP"], "files={files}: written through a planted link");
        assert_eq!(fs::read_to_string(victim.path().join("KEEP")).unwrap(), "victim");
        assert_eq!(entries(tmp.path()), planted, "files={files}: the run left something in TMPDIR");
    }
}

#[test]
fn a_crashing_run_leaves_no_scratch_directory() {
    let p = build("crash");
    fs::write(p.ms().join("OPEN-R/MW/CONF/CRASH.CFG"), "1\n").unwrap();
    for files in [false, true] {
        let tmp = tempfile::tempdir().unwrap();
        let (code, err) = run_with_tmpdir(&p.ms(), tmp.path(), files);
        assert_ne!(code, Some(0), "files={files}: the crash fails the run: {err}");
        assert!(err.contains("error: object `crash`"), "files={files}: {err}");
        assert_eq!(entries(tmp.path()), Vec::<String>::new(), "files={files}: left behind in TMPDIR");
    }
}

#[test]
fn loading_through_files_needs_a_usable_tmpdir_and_says_so() {
    let p = build("hello");
    let tmp = tempfile::tempdir().unwrap();
    let missing = tmp.path().join("NO-SUCH-DIR");
    let (code, err) = run_with_tmpdir(&p.ms(), &missing, true);
    assert_ne!(code, Some(0));
    // The system objects load first.
    assert!(err.contains("VRCOMM.BIN: cannot place its image for loading: cannot make a private directory in"), "{err}");
    assert!(err.contains("NO-SUCH-DIR: No such file or directory"), "{err}");
    assert!(!err.contains("panicked"), "{err}");
    // From memory (the default) no directory is needed at all.
    let (code, err) = run_with_tmpdir(&p.ms(), &missing, false);
    assert_eq!(code, Some(0), "{err}");
}

// ---- processes, signals and the loader (issue 18: no way to the host) ----

/// What `testdata/programs/hostcalls` tries, from its object and from a thread it starts.
const HOST_CALLS: &[(&str, &str)] = &[
    ("system(cmd)", "ENOSYS"),
    ("popen(cmd)", "ENOSYS"),
    ("fork()", "ENOSYS"),
    ("posix_spawn(/bin/sh)", "ENOSYS"),
    ("posix_spawnp(sh)", "ENOSYS"),
    ("kill(parent, 0)", "ENOSYS"),
    ("ptrace(PEEKDATA, parent)", "ENOSYS"),
    ("dlopen(libc.so.6)", "ENOSYS"),
    ("execve(/bin/sh)", "ENOSYS"),
    ("execv(/bin/sh)", "ENOSYS"),
    ("execvp(sh)", "ENOSYS"),
    ("execl(/bin/sh)", "ENOSYS"),
    ("execlp(sh)", "ENOSYS"),
];

#[test]
fn objects_start_no_host_process_signal_none_and_load_no_library() {
    let p = build("hostcalls");
    let outside = tempfile::tempdir().unwrap();
    fs::write(p.ms().join("OPEN-R/MW/CONF/HOSTCALL.CFG"), format!("{}\n", outside.path().display())).unwrap();
    let out = run_ms(&p.ms(), &["--for", "1s", "--speed", "max"]);
    assert_eq!(out.code, Some(0), "{}\n{}", out.stdout, out.stderr);
    assert!(out.stdout.contains("HostCalls : done"), "{}", out.stdout);
    let lines = out.lines_starting("HostCalls : ");
    let mut wrong = Vec::new();
    for who in ["", "own thread: "] {
        for (call, errno) in HOST_CALLS {
            let line = lines.iter().find(|l| l["HostCalls : ".len()..].strip_prefix(who).is_some_and(|r| r.starts_with(call)));
            let want = format!("refused ({errno})");
            match line {
                Some(l) if l.ends_with(&want) => {}
                other => wrong.push(format!("{who}{call}: want {want}, got {other:?}")),
            }
        }
        let why = format!("HostCalls : {who}dlerror: dlopen: OPEN-R objects cannot load libraries");
        assert!(out.stdout.contains(&why), "{who}: dlerror says why\n{}", out.stdout);
    }
    assert!(wrong.is_empty(), "calls not refused:\n  {}\n\nstdout:\n{}", wrong.join("\n  "), out.stdout);
    assert!(out.stdout.contains("HostCalls : system(NULL) = 0"), "no shell on the robot\n{}", out.stdout);
    let made: Vec<_> = fs::read_dir(outside.path()).unwrap().map(|e| e.unwrap().file_name()).collect();
    assert!(made.is_empty(), "host commands ran: {made:?}");
    // One warning per call, naming the object (the thread's calls are not repeated).
    for call in ["system", "popen", "fork", "posix_spawn", "kill", "dlopen", "execve", "execl"] {
        let warning = format!("warning: object `hostcall` called {call}(), which the robot does not have");
        assert_eq!(out.stderr.matches(&warning).count(), 1, "{warning}\n{}", out.stderr);
    }
}
