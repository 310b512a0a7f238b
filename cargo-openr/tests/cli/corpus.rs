//! Every program of `testdata/programs/` builds unmodified with `make OPENRSDK_ROOT=…
//! install`, and every installed `.BIN` is what the loader expects: a gzip of an x86-64
//! ELF shared object exporting the entry symbols.
use std::fs;
use std::io::Read;
use std::path::{Path, PathBuf};
use std::process::Command;

use object::{Object, ObjectSymbol};

use crate::support::{copy_tree, repo, run, sdk_root};

/// The `.BIN` paths an OBJECT.CFG lists (all robot-design sections), as written.
fn listed_objects(object_cfg: &Path) -> Vec<String> {
    let text = fs::read_to_string(object_cfg).unwrap();
    text.lines()
        .map(|l| l.trim())
        .filter(|l| !l.is_empty() && !l.starts_with('#') && !l.starts_with('['))
        .map(|l| l.split_whitespace().next().unwrap().to_string())
        .collect()
}

/// Resolves `/MS/...` case-insensitively inside `ms`.
fn resolve(ms: &Path, path: &str) -> Option<PathBuf> {
    let rest = path.strip_prefix("/MS/").or_else(|| path.strip_prefix("/ms/"))?;
    let mut cur = ms.to_path_buf();
    for comp in rest.split('/').filter(|c| !c.is_empty()) {
        let found = fs::read_dir(&cur).ok()?.flatten().find(|e| e.file_name().to_string_lossy().eq_ignore_ascii_case(comp))?;
        cur = found.path();
    }
    Some(cur)
}

fn find_ci(dir: &Path, name: &str) -> Option<PathBuf> {
    fs::read_dir(dir).ok()?.flatten().find(|e| e.file_name().to_string_lossy().eq_ignore_ascii_case(name)).map(|e| e.path())
}

/// Checks one installed object; returns a description of what is wrong.
fn check_bin(path: &Path) -> Result<(), String> {
    let raw = fs::read(path).map_err(|e| e.to_string())?;
    if !raw.starts_with(&[0x1f, 0x8b]) {
        return Err("not gzip-compressed".into());
    }
    let mut elf = Vec::new();
    flate2::read::GzDecoder::new(&raw[..]).read_to_end(&mut elf).map_err(|e| format!("bad gzip: {e}"))?;
    check_elf(&elf)
}

/// An x86-64 ELF shared object exporting the entry symbols.
fn check_elf(elf: &[u8]) -> Result<(), String> {
    let file = object::File::parse(elf).map_err(|e| format!("not ELF: {e}"))?;
    if file.architecture() != object::Architecture::X86_64 {
        return Err(format!("architecture {:?}", file.architecture()));
    }
    if file.kind() != object::ObjectKind::Dynamic {
        return Err(format!("kind {:?}, expected a shared object", file.kind()));
    }
    for sym in ["ObjectEntryTable", "PrologueEntry"] {
        if !file.dynamic_symbols().any(|s| s.is_definition() && s.name() == Ok(sym)) {
            return Err(format!("{sym} not in .dynsym"));
        }
    }
    Ok(())
}

fn programs() -> Vec<PathBuf> {
    let mut v: Vec<PathBuf> =
        fs::read_dir(repo().join("testdata/programs")).unwrap().flatten().map(|e| e.path()).filter(|p| p.join("Makefile").is_file()).collect();
    v.sort();
    v
}

/// Builds one program in a scratch copy; returns (objects checked, failures).
fn build_program(src: &Path, root: &Path) -> (usize, Vec<String>) {
    let name = src.file_name().unwrap().to_string_lossy().into_owned();
    let tmp = tempfile::tempdir().unwrap();
    let dir = tmp.path().join(&name);
    copy_tree(src, &dir);
    let (ok, log) = run(Command::new("make").arg(format!("OPENRSDK_ROOT={}", root.display())).arg("install").current_dir(&dir));
    if !ok {
        return (0, vec![format!("{name}: `make install` failed:\n{log}")]);
    }
    // A remote-processing program whose robot side is only the gateway has its robot
    // stick in RP/robot/MS.
    let ms = if dir.join("MS").is_dir() { dir.join("MS") } else { dir.join("RP/robot/MS") };
    let conf = resolve(&ms, "/MS/OPEN-R/MW/CONF").and_then(|c| find_ci(&c, "OBJECT.CFG"));
    let Some(object_cfg) = conf else {
        return (0, vec![format!("{name}: no MS/OPEN-R/MW/CONF/OBJECT.CFG")]);
    };
    let mut failures = Vec::new();
    let listed = listed_objects(&object_cfg);
    if listed.is_empty() {
        failures.push(format!("{name}: OBJECT.CFG lists no object"));
    }
    // System objects (TCPGW.BIN) come from the SDK root's base tree, not from the program.
    for bin in listed.iter().filter(|b| !b.to_ascii_uppercase().starts_with("/MS/OPEN-R/SYSTEM/")) {
        match resolve(&ms, bin) {
            None => failures.push(format!("{name}: {bin} listed in OBJECT.CFG was not installed")),
            Some(p) => {
                if let Err(e) = check_bin(&p) {
                    failures.push(format!("{name}: {bin}: {e}"));
                }
            }
        }
    }
    // Remote-processing programs also install host objects into RP/host/MS: native
    // shared objects copied without gzip (remote-processing 2.6).
    let host_ms = dir.join("RP/host/MS");
    let host_cfg = host_ms.join("OPEN-R/MW/CONF/OBJECT.CFG");
    let host_listed = if host_cfg.is_file() { listed_objects(&host_cfg) } else { Vec::new() };
    for bin in &host_listed {
        match resolve(&host_ms, bin) {
            None => failures.push(format!("{name}: host {bin} listed in RP/host OBJECT.CFG was not installed")),
            Some(p) => {
                if let Err(e) = check_elf(&fs::read(&p).unwrap_or_default()) {
                    failures.push(format!("{name}: host {bin}: {e}"));
                }
            }
        }
    }
    (listed.len() + host_listed.len(), failures)
}

#[test]
fn every_program_of_the_corpus_builds_unmodified() {
    let root = sdk_root();
    let programs = programs();
    assert!(!programs.is_empty(), "testdata/programs is empty");
    // Two builds at a time (the machines have two cores); each make is serial, as Sony's
    // Makefiles require.
    let results: Vec<(usize, Vec<String>)> = std::thread::scope(|s| {
        let chunks: Vec<Vec<&PathBuf>> = (0..2).map(|w| programs.iter().skip(w).step_by(2).collect()).collect();
        let handles: Vec<_> = chunks.into_iter().map(|chunk| s.spawn(move || chunk.into_iter().map(|p| build_program(p, root)).collect::<Vec<_>>())).collect();
        handles.into_iter().flat_map(|h| h.join().unwrap()).collect()
    });
    let objects: usize = results.iter().map(|r| r.0).sum();
    let failures: Vec<&String> = results.iter().flat_map(|r| &r.1).collect();
    eprintln!("corpus: {} programs, {objects} objects listed, {} failures", programs.len(), failures.len());
    assert!(failures.is_empty(), "{}", failures.iter().map(|s| s.as_str()).collect::<Vec<_>>().join("\n\n"));
}
