//! The Memory Stick a run boots: the program's MS over a base tree of the SDK root, as
//! a robot's stick is made (object-model 1.5; issue 14.2).
use std::fs;
use std::path::{Path, PathBuf};

use crate::support::{build, run_ms, sdk_root};

const LOG: &str = "SaveLog : saved 3 lines to /MS/OPEN-R/MW/DATA/P/LOG.TXT";

/// Every file and directory under `dir` with its size, sorted.
fn listing(dir: &Path) -> Vec<(PathBuf, u64)> {
    let mut out = Vec::new();
    let mut todo = vec![dir.to_path_buf()];
    while let Some(d) = todo.pop() {
        for e in fs::read_dir(&d).unwrap() {
            let e = e.unwrap();
            let meta = e.metadata().unwrap();
            if meta.is_dir() {
                todo.push(e.path());
            }
            out.push((e.path(), meta.len()));
        }
    }
    out.sort();
    out
}

fn base_trees() -> Vec<(PathBuf, u64)> {
    let open_r = sdk_root().join("OPEN_R");
    [listing(&open_r.join("MS_ERS7")), listing(&open_r.join("MS_ERS200"))].concat()
}

#[test]
fn a_program_saves_into_a_directory_only_the_base_tree_has() {
    let p = build("savelog");
    assert!(!p.ms().join("OPEN-R/MW/DATA").exists(), "the program's MS has no DATA/P of its own");
    let before = base_trees();
    let out = run_ms(&p.ms(), &["--for", "1s", "--speed", "max"]);
    assert_eq!(out.code, Some(0), "{}\n{}", out.stdout, out.stderr);
    assert!(out.stdout.contains(LOG), "{}", out.stdout);
    let log = fs::read_to_string(p.ms().join("OPEN-R/MW/DATA/P/LOG.TXT")).unwrap();
    assert_eq!(log, "joint 1 error 10\njoint 2 error 20\njoint 3 error 30\n");
    // Reads fall through to the base tree (WCONSOLE has the WLAN defaults).
    assert!(out.stdout.contains("SaveLog : /MS/OPEN-R/SYSTEM/CONF/WLANDFLT.TXT says HOSTNAME=AIBO"), "{}", out.stdout);
    assert!(out.stdout.contains("SaveLog : /MS/OPEN-R holds MW SYSTEM\n"), "a listing shows both layers:\n{}", out.stdout);
    assert_eq!(base_trees(), before, "the run wrote into the SDK root's base trees");
    assert!(!p.ms().join("OPEN-R/SYSTEM").exists(), "reading a base file copies nothing");
}

#[test]
fn the_base_tree_is_chosen_with_base_or_openr_toml() {
    let p = build("savelog");
    let out = run_ms(&p.ms(), &["--for", "1s", "--speed", "max", "--base", "none"]);
    assert_eq!(out.code, Some(0), "{}", out.stderr);
    assert!(out.stdout.contains("SaveLog : can't open /MS/OPEN-R/MW/DATA/P/LOG.TXT"), "the program's MS alone:\n{}", out.stdout);
    assert!(!p.ms().join("OPEN-R/MW/DATA").exists());
    assert!(out.stdout.contains("SaveLog : /MS/OPEN-R holds MW\n"), "{}", out.stdout);

    // BASIC has no wireless settings; the project file picks it.
    fs::write(p.dir.path().join("savelog/openr.toml"), "base = \"basic/memprot\"\n").unwrap();
    let out = run_ms(&p.ms(), &["--for", "1s", "--speed", "max"]);
    assert!(out.stdout.contains(LOG), "{}", out.stdout);
    assert!(out.stdout.contains("SaveLog : no /MS/OPEN-R/SYSTEM/CONF/WLANDFLT.TXT"), "{}", out.stdout);
    // ERS-210/220 sticks come from MS_ERS200 (the same trees, for now).
    let out = run_ms(&p.ms(), &["--for", "1s", "--speed", "max", "--design", "ERS-210", "--base", "WCONSOLE/memprot"]);
    assert!(out.stdout.contains(LOG) && out.stdout.contains("says HOSTNAME=AIBO"), "{}\n{}", out.stdout, out.stderr);
    // The command line wins over the file.
    let out = run_ms(&p.ms(), &["--for", "1s", "--speed", "max", "--base", "WLAN"]);
    assert!(out.stdout.contains("WLANDFLT.TXT says HOSTNAME=AIBO"), "{}", out.stdout);
}

#[test]
fn a_bad_base_is_refused_with_where_it_came_from() {
    let p = build("savelog");
    let out = run_ms(&p.ms(), &["--for", "1s", "--base", "FULL"]);
    assert_ne!(out.code, Some(0));
    assert!(out.stderr.contains("command line (--base): base `FULL`: expected BASIC, WLAN or WCONSOLE"), "{}", out.stderr);
    let toml = p.dir.path().join("savelog/openr.toml");
    fs::write(&toml, "# stick\nbase = \"WLAN/fast\"\n").unwrap();
    let out = run_ms(&p.ms(), &["--for", "1s"]);
    assert_ne!(out.code, Some(0));
    assert!(out.stderr.contains(&format!("{}:2: base `WLAN/fast`", toml.display())), "{}", out.stderr);
    assert!(!out.stderr.contains("panicked"), "{}", out.stderr);
}
