//! The legacy-repair step of `mipsel-linux-g++`/`-gcc`: when g++ rejects a unit with
//! errors of the classes gcc 3.3 accepted ([`rules`]), the unit and its user headers are
//! copied into a private directory ([`shadow`]), repaired there with g++'s fix-its and
//! our rewrites, round after round (syntax-only runs) until g++ accepts them, and the
//! shadow unit is compiled to the user's `-o`. Each repair is reported as a
//! `file:line:col: note: [cargo-openr] …` of the user's file; diagnostics, `__FILE__`,
//! debug info and `-MD` files name the user's files. The user's files are never written.
//!
//! Nothing of this runs when g++ accepts the unit the first time.
mod args;
mod cast_lvalue;
mod diag;
mod headers;
mod rules;
mod shadow;
mod text;

use std::collections::HashSet;
use std::ffi::OsString;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

use rules::Edit;
use shadow::Shadow;

/// Enough for a header with a dozen legacy spots even under `-fmax-errors=1`.
const MAX_ROUNDS: usize = 24;

/// A repaired compile: the notes and the final compile's stderr, its exit code.
pub(crate) struct Repaired {
    pub stderr: String,
    pub code: i32,
}

/// Tries the repair of the failed compile `host + args`, whose stderr was `first`.
/// `None`: nothing to repair, or the repaired unit still fails — the caller reports the
/// original failure. The private directory is gone when this returns.
pub(crate) fn attempt(exe: &Path, host: &[&str], args: &[OsString], first: &str) -> Option<Repaired> {
    let repairable = |level: &str, msg: &str| match level {
        "error" => rules::may_repair(msg) || headers::missing(msg).is_some(),
        "warning" => rules::is_missing_template_keyword(msg),
        _ => false,
    };
    if !first.lines().filter_map(diag::split_diag).any(|(_, level, msg)| repairable(level, msg)) {
        return None;
    }
    let log = std::env::var_os("OPENR_REPAIR_LOG").is_some();
    let Some(unit) = args::unit(args) else {
        log.then(|| eprintln!("[cargo-openr] repair: not a compile of one unit"));
        return None;
    };
    let dir = PrivateDir::new()?;
    let mut shadow = shadow_of(exe, host, args, unit, &dir.0, log)?;
    let mut notes = Notes::default();
    let mut moves = Moves::default();
    // C headers the unit is compiled with first (`headers`), through one private header.
    let mut first_includes: Vec<String> = Vec::new();
    let first_h = dir.0.join("included-first.h");
    for _ in 0..MAX_ROUNDS {
        shadow.write().ok()?;
        let first = if first_includes.is_empty() { None } else { Some(first_h.as_path()) };
        let out = quiet(exe, host, &with_first(first, args::round(args, unit, &shadow.files[0].path)));
        if out.status.success() {
            let shift = if first.is_some() { 2 } else { 0 };
            return finish(exe, host, &with_first(first, args.to_vec()), unit + shift, &shadow, first, notes);
        }
        let stderr = String::from_utf8_lossy(&out.stderr);
        if log {
            eprintln!("[cargo-openr] repair round in {}:\n{stderr}", dir.0.display());
        }
        let had = first_includes.len();
        let edits = choose(&diag::errors(&stderr), &shadow, &moves, &mut notes, &mut first_includes, log);
        let included = first_includes.len() > had;
        if included {
            let text: String = first_includes.iter().map(|h| include_line(h)).collect();
            std::fs::write(&first_h, text).ok()?;
        }
        if edits.is_empty() && !included {
            return None;
        }
        apply(&mut shadow, edits, &mut moves);
    }
    None
}

/// The `#include` of a header to include first: a C header of the host, or the SDK
/// root's header of the robot's C library by its path (the unit's include path may
/// not name the root).
fn include_line(header: &str) -> String {
    let root = std::env::current_exe().ok().and_then(|e| crate::root::root_from_exe(&e));
    match root {
        Some(root) if header == headers::NEWLIB => format!("#include \"{}\"\n", root.join("OPEN_R/include").join(header).display()),
        _ => format!("#include <{header}>\n"),
    }
}

/// `-include <first>` in front of `args`, when there is a header to include first.
fn with_first(first: Option<&Path>, args: Vec<OsString>) -> Vec<OsString> {
    first.into_iter().flat_map(|f| [OsString::from("-include"), f.as_os_str().to_owned()]).chain(args).collect()
}

/// Whether error `d` is a C library name used undeclared in a user file (`headers`) --
/// a function only where it is called, so that a variable of the unit's own called
/// `index` or `time` is never taken for libc's: its header is added to `first` (and
/// noted) unless it is there already.
fn header_first(d: &diag::Diag, shadow: &Shadow, first: &mut Vec<String>, notes: &mut Notes) -> bool {
    let Some((name, header)) = headers::missing(&d.msg) else { return false };
    if first.contains(&header) {
        return true; // included already: nothing more for this name
    }
    let wanted = needs_header(d, shadow, &name);
    if let Some(file) = wanted {
        let text = format!(
            "{}: note: [cargo-openr] repaired `{name}` used without its header (gcc 3.3's C++ headers included the C library's on the way; gcc 4.3 stopped): compiled with `#include <{header}>` first, in a private copy (your file is unchanged)",
            d.loc
        );
        notes.0.push((file, d.loc.line, d.loc.col, text));
        first.push(header);
    }
    wanted.is_some()
}

/// The user file in which error `d` names `name` as libc's would be used: as written
/// there, and called if it is a function. Its index.
fn needs_header(d: &diag::Diag, shadow: &Shadow, name: &str) -> Option<usize> {
    let file = shadow.find(&d.loc.file)?;
    let src = &shadow.files[file].src;
    let at = src.offset(d.loc.line, d.loc.col)?;
    let bare = name.trim_start_matches("std::");
    if src.ident_at(at) != bare {
        return None;
    }
    let called = src.code.get(at + bare.len()..).and_then(|rest| rest.iter().find(|b| !b.is_ascii_whitespace())) == Some(&b'(');
    (called || !headers::is_function(bare)).then_some(file)
}

/// The shadow copies of the unit's user files, from the include tree of a preprocessing run.
fn shadow_of(exe: &Path, host: &[&str], args: &[OsString], unit: usize, dir: &Path, log: bool) -> Option<Shadow> {
    let cwd = std::env::current_dir().ok()?;
    let root = std::env::current_exe().ok().and_then(|e| crate::root::root_from_exe(&e));
    let pre = dir.join("unit.ii");
    let run = quiet(exe, host, &args::preprocess(args, unit, &pre));
    let Some(text) = std::fs::read_to_string(&pre).ok().filter(|_| run.status.success()) else {
        log.then(|| eprintln!("[cargo-openr] repair: preprocessing failed:\n{}", String::from_utf8_lossy(&run.stderr)));
        return None;
    };
    let _ = std::fs::remove_file(&pre);
    let graph = shadow::include_graph(&text);
    let shadow = Shadow::new(&graph, &cwd, root.as_deref(), dir);
    if shadow.is_none() && log {
        eprintln!("[cargo-openr] repair: cannot read the unit {}", graph.first().map_or("", |n| &n.name));
    }
    shadow
}

/// The notes of the repairs made: (file, line, column, text), each location once.
#[derive(Default)]
struct Notes(Vec<(usize, usize, usize, String)>);

/// The edits of one round. Errors after one we do not know may be its consequences, and
/// so may later errors on a line just repaired: those g++ names as a legacy class are
/// repaired, the others wait for the next round.
/// A C library name used without its header, that no rule repairs, is compiled with the
/// header included first (added to `first`), under the same condition.
fn choose(errors: &[diag::Diag], shadow: &Shadow, moves: &Moves, notes: &mut Notes, first: &mut Vec<String>, log: bool) -> Vec<Edit> {
    let mut edits: Vec<Edit> = Vec::new();
    let mut lines = HashSet::new();
    let mut clean = true;
    for d in errors {
        let r = match rules::repair(d, shadow) {
            _ if lines.contains(&(d.loc.file.clone(), d.loc.line)) => None,
            Some(r) if clean || rules::names_its_class(&d.msg) => Some(r),
            _ => None,
        };
        let Some(r) = r else {
            if clean && !lines.contains(&(d.loc.file.clone(), d.loc.line)) && header_first(d, shadow, first, notes) {
                continue;
            }
            clean = false;
            continue;
        };
        lines.insert((d.loc.file.clone(), d.loc.line));
        if log {
            eprintln!("[cargo-openr] repair {}: {:?} {:?}", d.loc, r.class, r.edits);
        }
        let overlaps = |e: &Edit| edits.iter().any(|o| o.file == e.file && o.from < e.to.max(e.from + 1) && e.from < o.to.max(o.from + 1));
        if r.edits.iter().any(overlaps) {
            continue;
        }
        let loc = diag::Loc { col: moves.original_col(&d.loc), ..d.loc.clone() };
        let file = shadow.find(&loc.file).unwrap_or(0);
        if !notes.0.iter().any(|n| (n.0, n.1, n.2) == (file, loc.line, loc.col)) {
            let text = format!("{loc}: note: [cargo-openr] repaired {}: compiled {}, in a private copy (your file is unchanged)", r.class.what(), r.how);
            notes.0.push((file, loc.line, loc.col, text));
        }
        edits.extend(r.edits);
    }
    edits
}

/// The real compile of the repaired shadow unit (stdout is the user's).
fn finish(exe: &Path, host: &[&str], args: &[OsString], unit: usize, shadow: &Shadow, first: Option<&Path>, mut notes: Notes) -> Option<Repaired> {
    let out = Command::new(exe).args(host).args(args::final_compile(args, unit, &shadow.files[0].path)).stderr(Stdio::piped()).output().ok()?;
    if !out.status.success() {
        return None;
    }
    if let Some(d) = args::depfile(args, unit) {
        shadow.fix_depfile(&d, first);
    }
    notes.0.sort();
    let mut stderr: String = notes.0.into_iter().map(|n| n.3 + "\n").collect();
    stderr.push_str(&String::from_utf8_lossy(&out.stderr));
    Some(Repaired { stderr, code: out.status.code().unwrap_or(1) })
}

/// How the edits moved columns, to report the user's columns: per (file name, line),
/// (column, length change) of each edit in the order applied.
#[derive(Default)]
struct Moves(std::collections::HashMap<(String, usize), Vec<(usize, isize)>>);

impl Moves {
    fn original_col(&self, loc: &diag::Loc) -> usize {
        let mut col = loc.col as isize;
        for &(c, delta) in self.0.get(&(loc.file.clone(), loc.line)).into_iter().flatten().rev() {
            if col >= c as isize + delta.max(0) {
                col -= delta;
            } else if col >= c as isize {
                col = c as isize;
            }
        }
        col.max(1) as usize
    }
}

/// Applies edits (none overlapping) to the shadow files' texts.
fn apply(shadow: &mut Shadow, mut edits: Vec<Edit>, moves: &mut Moves) {
    edits.sort_by_key(|e| std::cmp::Reverse((e.file, e.from)));
    for e in edits {
        let f = &mut shadow.files[e.file];
        let line = f.src.line_of(e.from);
        if !f.src.text[e.from..e.to].contains('\n') {
            let col = e.from - f.src.offset(line, 1).unwrap_or(0) + 1;
            let delta = e.text.len() as isize - (e.to - e.from) as isize;
            moves.0.entry((f.name.clone(), line)).or_default().push((col, delta));
        }
        let mut t = std::mem::take(&mut f.src.text);
        t.replace_range(e.from..e.to, &e.text);
        f.src = text::Source::new(t);
    }
}

/// A g++ run whose output is only read: English messages, nothing on the user's stdout.
fn quiet(exe: &Path, host: &[&str], args: &[OsString]) -> std::process::Output {
    Command::new(exe)
        .args(host)
        .args(args)
        .env_remove("LC_ALL")
        .env_remove("LANGUAGE")
        .env("LC_MESSAGES", "C")
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .output()
        .unwrap_or_else(|e| std::process::Output {
            status: std::os::unix::process::ExitStatusExt::from_raw(1 << 8),
            stdout: Vec::new(),
            stderr: e.to_string().into_bytes(),
        })
}

/// A `mkdtemp` directory (mode 0700), removed with everything in it when dropped.
struct PrivateDir(PathBuf);

impl PrivateDir {
    fn new() -> Option<PrivateDir> {
        use std::os::unix::ffi::OsStringExt;
        let template = std::env::temp_dir().join("cargo-openr-repair-XXXXXX");
        let mut bytes = OsString::from(template).into_vec();
        bytes.push(0);
        // SAFETY: `bytes` is a NUL-terminated template that mkdtemp rewrites in place.
        let p = unsafe { libc::mkdtemp(bytes.as_mut_ptr().cast()) };
        if p.is_null() {
            return None;
        }
        bytes.pop();
        Some(PrivateDir(PathBuf::from(OsString::from_vec(bytes))))
    }
}

impl Drop for PrivateDir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}
