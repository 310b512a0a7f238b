//! The Memory Stick as objects see it (object-model 1.5): absolute `/MS/...` paths,
//! case-insensitive FAT 8.3 names stored upper case, nothing outside the stick.
use std::ffi::OsString;
use std::io;
use std::path::{Path, PathBuf};

/// A host directory standing for `/MS`.
#[derive(Debug, Clone)]
pub struct MsDir {
    root: PathBuf,
}

/// Why a path was refused; maps to the errno an object sees.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Refusal {
    /// Not under `/MS/` (relative, or another root): ENOENT, as on the robot.
    NotOnStick,
    /// `..` above `/MS`, or a link leading out of the stick: EACCES.
    Escapes,
    /// A new name that is not 8.3: ENAMETOOLONG.
    NotEightDotThree,
}

impl Refusal {
    pub fn errno(self) -> i32 {
        match self {
            Refusal::NotOnStick => libc::ENOENT,
            Refusal::Escapes => libc::EACCES,
            Refusal::NotEightDotThree => libc::ENAMETOOLONG,
        }
    }
}

impl MsDir {
    pub fn new(root: impl Into<PathBuf>) -> io::Result<MsDir> {
        let root = root.into().canonicalize()?;
        Ok(MsDir { root })
    }

    pub fn root(&self) -> &Path {
        &self.root
    }

    /// Maps an object path to a host path. Each existing component is matched
    /// case-insensitively; a missing last component (with `create`) or any missing
    /// component is named in upper case, so `open` then fails or creates as on FAT.
    pub fn resolve(&self, path: &str, create: bool) -> Result<PathBuf, Refusal> {
        let rest = strip_ms_prefix(path).ok_or(Refusal::NotOnStick)?;
        let comps: Vec<&str> = rest.split('/').filter(|c| !c.is_empty() && *c != ".").collect();
        let mut cur = self.root.clone();
        let mut depth = 0usize;
        for (i, comp) in comps.iter().enumerate() {
            if *comp == ".." {
                if depth == 0 {
                    return Err(Refusal::Escapes);
                }
                cur.pop();
                depth -= 1;
                continue;
            }
            let last = i + 1 == comps.len();
            match find_entry(&cur, comp) {
                Some(name) => cur.push(name),
                None => {
                    if create && last && !is_eight_dot_three(comp) {
                        return Err(Refusal::NotEightDotThree);
                    }
                    cur.push(comp.to_ascii_uppercase());
                }
            }
            depth += 1;
        }
        // A symbolic link inside the stick must not lead out of it.
        if let Ok(real) = cur.canonicalize() {
            if !real.starts_with(&self.root) {
                return Err(Refusal::Escapes);
            }
        }
        Ok(cur)
    }

    /// Resolves a path that must exist (configuration files, objects).
    pub fn existing(&self, path: &str) -> Option<PathBuf> {
        self.resolve(path, false).ok().filter(|p| p.exists())
    }
}

/// `/MS/rest` → `rest` (the `MS` is case-insensitive like every FAT name); `/MS` → "".
fn strip_ms_prefix(path: &str) -> Option<&str> {
    let p = path.strip_prefix('/')?;
    let (first, rest) = p.split_once('/').unwrap_or((p, ""));
    first.eq_ignore_ascii_case("MS").then_some(rest)
}

fn find_entry(dir: &Path, name: &str) -> Option<OsString> {
    let exact = dir.join(name);
    if exact.symlink_metadata().is_ok() {
        return Some(name.into());
    }
    std::fs::read_dir(dir)
        .ok()?
        .flatten()
        .map(|e| e.file_name())
        .find(|n| n.to_string_lossy().eq_ignore_ascii_case(name))
}

/// FAT 8.3: base ≤ 8, optional extension ≤ 3, allowed characters only.
pub fn is_eight_dot_three(name: &str) -> bool {
    let ok_char = |c: char| c.is_ascii_alphanumeric() || "$&#{}~%'()-@^`!_".contains(c);
    let (base, ext) = name.split_once('.').unwrap_or((name, ""));
    (1..=8).contains(&base.len())
        && ext.len() <= 3
        && !(name.contains('.') && ext.is_empty())
        && base.chars().all(ok_char)
        && ext.chars().all(ok_char)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn stick() -> (tempfile::TempDir, MsDir) {
        let d = tempfile::tempdir().unwrap();
        std::fs::create_dir_all(d.path().join("OPEN-R/MW/CONF")).unwrap();
        std::fs::write(d.path().join("OPEN-R/MW/CONF/OBJECT.CFG"), "x").unwrap();
        let ms = MsDir::new(d.path()).unwrap();
        (d, ms)
    }

    #[test]
    fn case_insensitive_lookup() {
        let (_d, ms) = stick();
        let p = ms.resolve("/MS/open-r/mw/conf/object.cfg", false).unwrap();
        assert_eq!(p, ms.root().join("OPEN-R/MW/CONF/OBJECT.CFG"));
        assert_eq!(ms.resolve("/ms/OPEN-R", false).unwrap(), ms.root().join("OPEN-R"));
    }

    #[test]
    fn new_names_are_upper_case_and_eight_dot_three() {
        let (_d, ms) = stick();
        assert_eq!(ms.resolve("/MS/OPEN-R/MW/log.txt", true).unwrap(), ms.root().join("OPEN-R/MW/LOG.TXT"));
        assert_eq!(ms.resolve("/MS/OPEN-R/longfilename.txt", true), Err(Refusal::NotEightDotThree));
    }

    #[test]
    fn escapes_and_foreign_paths_are_refused() {
        let (_d, ms) = stick();
        assert_eq!(ms.resolve("/MS/../../etc/passwd", false), Err(Refusal::Escapes));
        assert_eq!(ms.resolve("/MS/OPEN-R/../../x", false), Err(Refusal::Escapes));
        assert!(ms.resolve("/MS/OPEN-R/../OPEN-R/MW", false).is_ok());
        assert_eq!(ms.resolve("/etc/passwd", false), Err(Refusal::NotOnStick));
        assert_eq!(ms.resolve("relative.txt", false), Err(Refusal::NotOnStick));
        assert_eq!(ms.resolve("/MSX/a", false), Err(Refusal::NotOnStick));
    }

    #[test]
    fn links_out_of_the_stick_are_refused() {
        let (d, ms) = stick();
        std::os::unix::fs::symlink("/etc", d.path().join("OUT")).unwrap();
        assert_eq!(ms.resolve("/MS/OUT/passwd", false), Err(Refusal::Escapes));
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
}
