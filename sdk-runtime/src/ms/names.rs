//! FAT names and `/MS` path syntax.
use std::ffi::OsString;
use std::path::Path;

use super::Refusal;

/// The components of `/MS/rest` after normalisation (`.` and empty components dropped,
/// `..` applied); `..` above `/MS` escapes. `MS` is case-insensitive like every FAT name.
pub(super) fn normalise(path: &str) -> Result<Vec<&str>, Refusal> {
    let rest = strip_ms_prefix(path).ok_or(Refusal::NotOnStick)?;
    let mut comps = Vec::new();
    for c in rest.split('/') {
        match c {
            "" | "." => {}
            ".." => {
                comps.pop().ok_or(Refusal::Escapes)?;
            }
            c => comps.push(c),
        }
    }
    Ok(comps)
}

/// `/MS/rest` → `rest`; `/MS` → "".
fn strip_ms_prefix(path: &str) -> Option<&str> {
    let p = path.strip_prefix('/')?;
    let (first, rest) = p.split_once('/').unwrap_or((p, ""));
    first.eq_ignore_ascii_case("MS").then_some(rest)
}

/// The name under which `dir` holds `name` (case-insensitively), if it does.
pub(super) fn find_entry(dir: &Path, name: &str) -> Option<OsString> {
    let exact = dir.join(name);
    if exact.symlink_metadata().is_ok() {
        return Some(name.into());
    }
    std::fs::read_dir(dir).ok()?.flatten().map(|e| e.file_name()).find(|n| n.to_string_lossy().eq_ignore_ascii_case(name))
}

/// FAT 8.3: base ≤ 8, optional extension ≤ 3, allowed characters only.
pub fn is_eight_dot_three(name: &str) -> bool {
    let ok_char = |c: char| c.is_ascii_alphanumeric() || "$&#{}~%'()-@^`!_".contains(c);
    let (base, ext) = name.split_once('.').unwrap_or((name, ""));
    (1..=8).contains(&base.len()) && ext.len() <= 3 && !(name.contains('.') && ext.is_empty()) && base.chars().all(ok_char) && ext.chars().all(ok_char)
}
