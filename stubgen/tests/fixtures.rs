//! Table-driven checks of `testdata/stubcfg/{good,bad}` and of every `stub.cfg` under
//! `testdata/programs`.

use std::path::{Path, PathBuf};

use stubgen::parse_files;

fn testdata() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../testdata")
}

fn cfg_files(dir: &Path) -> Vec<PathBuf> {
    let mut v: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "cfg"))
        .collect();
    v.sort();
    v
}

#[test]
fn good_fixtures_parse_and_generate() {
    let files = cfg_files(&testdata().join("stubcfg/good"));
    assert!(files.len() >= 9, "{files:?}");
    for path in files {
        let cfg = parse_files(std::slice::from_ref(&path)).unwrap_or_else(|e| panic!("{e}"));
        let out = stubgen::generate(&cfg).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        assert_eq!(out.len(), 4);
    }
}

/// The `// expect-line:` and `// expect:` comment lines of a bad fixture.
fn expectation(text: &str) -> Option<(usize, String)> {
    let mut line = None;
    let mut msg = None;
    for l in text.lines() {
        if let Some(v) = l.strip_prefix("// expect-line: ") {
            line = Some(v.trim().parse().unwrap());
        } else if let Some(v) = l.strip_prefix("// expect: ") {
            msg = Some(v.to_owned());
        }
    }
    Some((line?, msg?))
}

#[test]
fn bad_fixtures_fail_with_the_expected_message() {
    let files = cfg_files(&testdata().join("stubcfg/bad"));
    assert!(files.len() >= 30, "{files:?}");
    let mut failures = Vec::new();
    for path in files {
        let text = String::from_utf8_lossy(&std::fs::read(&path).unwrap()).into_owned();
        let Err(err) = parse_files(std::slice::from_ref(&path)) else {
            failures.push(format!("{}: accepted", path.display()));
            continue;
        };
        let (line, msg) = match expectation(&text) {
            Some(x) => x,
            // Only the empty fixtures cannot carry an expectation.
            None => (1, "empty stub.cfg".to_owned()),
        };
        let display_ok = err.to_string() == format!("{}:{}: {}", path.display(), line, err.message());
        if err.file() != Some(path.as_path()) || err.line() != Some(line) || !err.message().starts_with(&msg) || !display_ok {
            failures.push(format!("{err}\n    expected line {line}: {msg}"));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

fn find_stub_cfgs(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(rd) = std::fs::read_dir(dir) else {
        return;
    };
    for e in rd.flatten() {
        let p = e.path();
        if p.is_dir() {
            find_stub_cfgs(&p, out);
        } else if p.file_name().is_some_and(|n| n == "stub.cfg") {
            out.push(p);
        }
    }
}

#[test]
fn every_program_stub_cfg_in_testdata_is_accepted() {
    let mut found = Vec::new();
    find_stub_cfgs(&testdata().join("programs"), &mut found);
    if found.is_empty() {
        eprintln!("note: no stub.cfg under testdata/programs yet; nothing to check");
    }
    for path in found {
        let cfg = parse_files(std::slice::from_ref(&path)).unwrap_or_else(|e| panic!("{e}"));
        stubgen::generate(&cfg).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    }
}
