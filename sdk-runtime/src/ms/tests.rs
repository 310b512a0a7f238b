use std::fs;
use std::os::unix::fs::symlink;

use super::*;

fn stick() -> (tempfile::TempDir, MsDir) {
    let d = tempfile::tempdir().unwrap();
    fs::create_dir_all(d.path().join("OPEN-R/MW/CONF")).unwrap();
    fs::write(d.path().join("OPEN-R/MW/CONF/OBJECT.CFG"), "x").unwrap();
    let ms = MsDir::new(d.path()).unwrap();
    (d, ms)
}

/// A program stick over a base tree with MW/DATA/P, SYSTEM/CONF/WLANDFLT.TXT and its
/// own OBJECT.CFG.
fn overlay() -> (tempfile::TempDir, MsDir) {
    let d = tempfile::tempdir().unwrap();
    let (prog, base) = (d.path().join("prog"), d.path().join("base"));
    fs::create_dir_all(prog.join("OPEN-R/MW/CONF")).unwrap();
    fs::write(prog.join("OPEN-R/MW/CONF/OBJECT.CFG"), "program").unwrap();
    for dir in ["OPEN-R/MW/CONF", "OPEN-R/MW/DATA/P", "OPEN-R/SYSTEM/CONF"] {
        fs::create_dir_all(base.join(dir)).unwrap();
    }
    fs::write(base.join("OPEN-R/MW/CONF/OBJECT.CFG"), "base").unwrap();
    fs::write(base.join("OPEN-R/SYSTEM/CONF/WLANDFLT.TXT"), "SSID=AIBONET\n").unwrap();
    let ms = MsDir::new(&prog).unwrap().with_base(&base).unwrap();
    (d, ms)
}

#[test]
fn case_insensitive_lookup() {
    let (_d, ms) = stick();
    let p = ms.resolve("/MS/open-r/mw/conf/object.cfg", Access::Read).unwrap();
    assert_eq!(p, ms.root().join("OPEN-R/MW/CONF/OBJECT.CFG"));
    assert_eq!(ms.resolve("/ms/OPEN-R", Access::Read).unwrap(), ms.root().join("OPEN-R"));
    assert_eq!(ms.resolve("/MS", Access::Read).unwrap(), ms.root());
}

#[test]
fn new_names_are_upper_case_and_eight_dot_three() {
    let (_d, ms) = stick();
    assert_eq!(ms.resolve("/MS/OPEN-R/MW/log.txt", Access::Write).unwrap(), ms.root().join("OPEN-R/MW/LOG.TXT"));
    assert_eq!(ms.resolve("/MS/OPEN-R/longfilename.txt", Access::Write), Err(Refusal::NotEightDotThree));
}

#[test]
fn escapes_and_foreign_paths_are_refused() {
    let (_d, ms) = stick();
    assert_eq!(ms.resolve("/MS/../../etc/passwd", Access::Read), Err(Refusal::Escapes));
    assert_eq!(ms.resolve("/MS/OPEN-R/../../x", Access::Write), Err(Refusal::Escapes));
    assert!(ms.resolve("/MS/OPEN-R/../OPEN-R/MW", Access::Read).is_ok());
    assert_eq!(ms.resolve("/etc/passwd", Access::Read), Err(Refusal::NotOnStick));
    assert_eq!(ms.resolve("relative.txt", Access::Read), Err(Refusal::NotOnStick));
    assert_eq!(ms.resolve("/MSX/a", Access::Read), Err(Refusal::NotOnStick));
    let host = format!("{}/../../etc/passwd", ms.root().display());
    assert_eq!(ms.resolve(&host, Access::Read), Err(Refusal::NotOnStick), "the stick's host path is no /MS path");
    assert_eq!(ms.resolve("/MS/", Access::Remove), Err(Refusal::Escapes), "rmdir /MS");
}

#[test]
fn links_out_of_the_stick_are_refused_for_new_names_too() {
    let (d, ms) = stick();
    let outside = tempfile::tempdir().unwrap();
    fs::write(outside.path().join("OLD.TXT"), "host").unwrap();
    symlink(outside.path(), d.path().join("OUTDIR")).unwrap();
    symlink("/nonexistent/dir", d.path().join("DANGLING")).unwrap();
    symlink(outside.path().join("NEW.TXT"), d.path().join("NEWLINK.TXT")).unwrap();
    for access in [Access::Read, Access::Write, Access::Remove] {
        for p in ["/MS/OUTDIR/OLD.TXT", "/MS/OUTDIR/NEW.TXT", "/MS/outdir/sub/NEW.TXT", "/MS/DANGLING/NEW.TXT", "/MS/DANGLING", "/MS/NEWLINK.TXT", "/MS/OUTDIR"]
        {
            assert_eq!(ms.resolve(p, access), Err(Refusal::Escapes), "{p} {access:?}");
        }
    }
    assert_eq!(fs::read_dir(outside.path()).unwrap().count(), 1, "nothing created outside");
}

#[test]
fn links_inside_the_stick_are_followed_and_leave_no_link_in_the_path() {
    let (d, ms) = stick();
    symlink(d.path().join("OPEN-R/MW"), d.path().join("OPEN-R/SHORT")).unwrap();
    let p = ms.resolve("/MS/OPEN-R/SHORT/CONF/NEW.TXT", Access::Write).unwrap();
    assert_eq!(p, ms.root().join("OPEN-R/MW/CONF/NEW.TXT"));
    // A link out whose target links back in is still out: its directory is outside.
    let outside = tempfile::tempdir().unwrap();
    symlink(d.path().join("OPEN-R/MW/CONF/OBJECT.CFG"), outside.path().join("BACK.CFG")).unwrap();
    symlink(outside.path(), d.path().join("OUT")).unwrap();
    assert_eq!(ms.resolve("/MS/OUT/BACK.CFG", Access::Remove), Err(Refusal::Escapes));
}

#[test]
fn reads_fall_through_to_the_base_tree_and_the_program_wins() {
    let (_d, ms) = overlay();
    let cfg = ms.existing("/MS/OPEN-R/MW/CONF/OBJECT.CFG").unwrap();
    assert_eq!(fs::read_to_string(cfg).unwrap(), "program");
    let wlan = ms.existing("/MS/OPEN-R/SYSTEM/CONF/wlandflt.txt").unwrap();
    assert_eq!(wlan, ms.base().unwrap().join("OPEN-R/SYSTEM/CONF/WLANDFLT.TXT"));
    assert!(ms.existing("/MS/OPEN-R/MW/DATA/P").unwrap().is_dir());
    assert!(ms.existing_in_program("/MS/OPEN-R/SYSTEM/CONF/WLANDFLT.TXT").is_none());
    // Listings merge where both layers have the directory.
    assert_eq!(ms.lower_dir("/MS/OPEN-R"), Some(ms.base().unwrap().join("OPEN-R")));
    assert_eq!(ms.lower_dir("/MS/OPEN-R/SYSTEM"), None, "the program has none: the base's is listed alone");
}

#[test]
fn writes_land_in_the_program_and_never_in_the_base_tree() {
    let (_d, ms) = overlay();
    let base = ms.base().unwrap().to_path_buf();
    // mkdir of a directory the base has: handed the base path (EEXIST, nothing made).
    assert_eq!(ms.resolve("/MS/OPEN-R/SYSTEM", Access::Write).unwrap(), base.join("OPEN-R/SYSTEM"));
    // A new file in a directory only the base tree has: the directory is made.
    let log = ms.resolve("/MS/OPEN-R/MW/DATA/P/LOG.TXT", Access::Write).unwrap();
    assert_eq!(log, ms.root().join("OPEN-R/MW/DATA/P/LOG.TXT"));
    assert!(ms.root().join("OPEN-R/MW/DATA/P").is_dir());
    // A base file opened for writing is copied first.
    let wlan = ms.resolve("/MS/OPEN-R/SYSTEM/CONF/WLANDFLT.TXT", Access::Write).unwrap();
    assert_eq!(wlan, ms.root().join("OPEN-R/SYSTEM/CONF/WLANDFLT.TXT"));
    assert_eq!(fs::read_to_string(&wlan).unwrap(), "SSID=AIBONET\n");
    // Removing what only the base has is refused.
    fs::write(base.join("OPEN-R/SYSTEM/CONF/EMON.CFG"), "x").unwrap();
    assert_eq!(ms.resolve("/MS/OPEN-R/SYSTEM/CONF/EMON.CFG", Access::Remove), Err(Refusal::InBaseTree));
    // A missing parent in both layers stays missing (ENOENT from the call).
    let p = ms.resolve("/MS/OPEN-R/NOPE/X.TXT", Access::Write).unwrap();
    assert!(p.starts_with(ms.root()) && !p.parent().unwrap().exists());
}

#[test]
fn eight_dot_three_rules() {
    for ok in ["A", "OBJECT.CFG", "ERS-7.BIN", "12345678.123", "A_B$.X"] {
        assert!(is_eight_dot_three(ok), "{ok}");
    }
    for bad in ["", "123456789", "A.ABCD", "A.", "A B", "A.B.C", ".X"] {
        assert!(!is_eight_dot_three(bad), "{bad}");
    }
}
