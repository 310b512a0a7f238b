//! Helpers shared by the integration tests (included with `mod common;`).
#![allow(dead_code)]

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use stubgen::StubCfg;

pub fn good(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../testdata/stubcfg/good").join(name)
}

/// Parse a good fixture and generate its files: (cfg, file name -> contents).
pub fn generate_fixture(name: &str) -> (StubCfg, BTreeMap<String, String>) {
    let cfg = stubgen::parse_files(&[good(name)]).unwrap_or_else(|e| panic!("{e}"));
    let files = stubgen::generate(&cfg).unwrap_or_else(|e| panic!("{e}"));
    (cfg, files.into_iter().collect())
}

/// The rows `{selector, (::Entry)::name}` of the `__GNUC__` ObjectEntryTable, without the
/// terminator.
pub fn gnuc_table(stub_cc: &str) -> Vec<(u64, String)> {
    let gnuc = &stub_cc[stub_cc.find("#if defined(__GNUC__)\n\n").expect("GNUC branch")..];
    let gnuc = &gnuc[..gnuc.find("#else").expect("#else")];
    let table = &gnuc[gnuc.find("ObjectEntry ObjectEntryTable[] = {").expect("table")..];
    let mut rows = Vec::new();
    for line in table.lines().skip(1) {
        let line = line.trim();
        if line == "{::UNDEF, ENTRY_UNDEF}" {
            return rows;
        }
        let inner = line.strip_prefix('{').and_then(|l| l.strip_suffix("},")).unwrap_or_else(|| panic!("row {line:?}"));
        let (sel, entry) = inner.split_once(", (::Entry)::").unwrap_or_else(|| panic!("row {line:?}"));
        rows.push((sel.parse().unwrap(), entry.to_owned()));
    }
    panic!("no terminator in\n{table}");
}

/// Expected table rows for S subjects, O observers and the given extras.
pub fn expected_table(s: u64, o: u64, extras: &[&str]) -> Vec<(u64, String)> {
    let mut rows: Vec<(u64, String)> = (0..4).map(|i| (i, format!("_hookstub{i}"))).collect();
    for i in 0..s {
        rows.push((4 + i, format!("_controlstub{i}")));
        rows.push((4 + s + i, format!("_readystub{i}")));
    }
    for j in 0..o {
        rows.push((4 + 2 * s + j, format!("_connectstub{j}")));
        rows.push((4 + 2 * s + o + j, format!("_notifystub{j}")));
    }
    let basic = 4 + 2 * (s + o);
    for (k, x) in extras.iter().enumerate() {
        rows.push((basic + k as u64, format!("_{x}stub")));
    }
    rows
}

/// Does `text` contain these lines consecutively (each compared after trimming)?
pub fn has_lines(text: &str, lines: &[&str]) -> bool {
    let all: Vec<&str> = text.lines().map(str::trim).collect();
    all.windows(lines.len()).any(|w| w == lines)
}
