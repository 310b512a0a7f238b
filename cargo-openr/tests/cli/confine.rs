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
    assert_eq!(fs::read_to_string(p.ms().join("OPEN-R/MW/DATA/P/OK.TXT")).unwrap(), "written through INSIDE\n");
}

#[test]
fn the_runtime_exports_every_interposer() {
    let exe = Path::new(crate::support::exe());
    let missing = openr_wrappers::mkbin::missing_dynamic_symbols(exe, sdk_runtime::interpose::SYMBOLS).unwrap();
    assert!(missing.is_empty(), "not in the dynamic symbol table of cargo-openr: {missing:?}");
}
