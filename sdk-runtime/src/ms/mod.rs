//! The Memory Stick as objects see it (object-model 1.5): absolute `/MS/...` paths,
//! case-insensitive FAT 8.3 names stored upper case, nothing outside the stick.
//!
//! A robot's stick is a base tree of the SDK (`OPEN_R/MS_ERS7/WCONSOLE/nomemprot/OPEN-R`,
//! …) with the program's `MS/OPEN-R` copied over it. The runtime does not copy: it
//! overlays the two. A path is looked up in the program's MS directory first, then in the
//! base tree; what an object writes always lands in the program's directory (a base-only
//! directory it writes into is created there on demand, a base-only file it opens for
//! writing is copied there first), so the SDK root is never written.
//!
//! Confinement: the path is normalised (`.`, `..`, repeated `/`) before anything else;
//! `..` above `/MS` is refused. The host path handed back has no symbolic link left in its
//! directories (the deepest existing ancestor is canonicalised and must lie in the
//! layer), and an existing last component that is a link must resolve inside the layer
//! too — a link of the stick leading out, or dangling, is refused (EACCES) for reading
//! and writing alike. Objects cannot make links themselves (`symlink`/`link` are refused,
//! see `interpose`), so the only links are those the user put in the directory.
use std::ffi::OsString;
use std::io;
use std::path::{Path, PathBuf};

mod names;
#[cfg(test)]
mod tests;

pub use names::is_eight_dot_three;
use names::{find_entry, normalise};

/// A host directory standing for `/MS`, optionally over a base tree.
#[derive(Debug, Clone)]
pub struct MsDir {
    root: PathBuf,
    base: Option<PathBuf>,
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
    /// Removing or renaming what only the base tree has (the SDK root): EROFS.
    InBaseTree,
}

impl Refusal {
    pub fn errno(self) -> i32 {
        match self {
            Refusal::NotOnStick => libc::ENOENT,
            Refusal::Escapes => libc::EACCES,
            Refusal::NotEightDotThree => libc::ENAMETOOLONG,
            Refusal::InBaseTree => libc::EROFS,
        }
    }
}

/// What the caller will do with the path.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Access {
    /// Read or inspect (open read-only, stat, opendir, access).
    Read,
    /// Create or modify (open for writing, mkdir, the target of rename, chmod, utime).
    Write,
    /// Remove the entry itself (unlink, rmdir, the source of rename).
    Remove,
}

/// Where one layer has the components of a path: the host names of the first `found`.
struct Walk {
    names: Vec<OsString>,
    found: usize,
}

fn walk(root: &Path, comps: &[&str]) -> Walk {
    let mut cur = root.to_path_buf();
    let mut names = Vec::new();
    for comp in comps {
        match find_entry(&cur, comp) {
            Some(name) => {
                cur.push(&name);
                names.push(name);
            }
            None => break,
        }
    }
    Walk { found: names.len(), names }
}

impl MsDir {
    pub fn new(root: impl Into<PathBuf>) -> io::Result<MsDir> {
        let root = root.into().canonicalize()?;
        Ok(MsDir { root, base: None })
    }

    /// Lays `base` (a directory holding `OPEN-R`, e.g. a base tree of the SDK root) under
    /// the program's directory.
    pub fn with_base(mut self, base: impl Into<PathBuf>) -> io::Result<MsDir> {
        self.base = Some(base.into().canonicalize()?);
        Ok(self)
    }

    /// The program's directory (where writes land).
    pub fn root(&self) -> &Path {
        &self.root
    }

    pub fn base(&self) -> Option<&Path> {
        self.base.as_deref()
    }

    /// Maps an object path to a host path. Each existing component is matched
    /// case-insensitively; missing components are named in upper case, so the call then
    /// fails or creates as on FAT. A new name created by `Write` must be 8.3.
    pub fn resolve(&self, path: &str, access: Access) -> Result<PathBuf, Refusal> {
        let comps = normalise(path)?;
        if comps.is_empty() && access == Access::Remove {
            return Err(Refusal::Escapes); // rmdir("/MS"), rename("/MS", …)
        }
        let n = comps.len();
        let own = walk(&self.root, &comps);
        let base = self.base.as_deref().map(|b| (b, walk(b, &comps)));
        if own.found == n {
            return self.confine(&self.root, &own.names, &[]);
        }
        let upper: Vec<OsString> = comps.iter().map(|c| c.to_ascii_uppercase().into()).collect();
        match (&base, access) {
            (Some((b, w)), Access::Read) if w.found == n => self.confine(b, &w.names, &[]),
            (Some((_, w)), Access::Remove) if w.found == n => Err(Refusal::InBaseTree),
            (Some((b, w)), Access::Write) if w.found == n => self.copy_up(b, &own, w, &comps),
            (Some((_, w)), Access::Write) if w.found == n - 1 && own.found < n - 1 => {
                // The parent exists in the base tree only: make it in the program's tree.
                check_new_name(comps[n - 1])?;
                let names = merged(&own, w, &upper[..n - 1]);
                let dir = self.confine(&self.root, &own.names, &names[own.found..])?;
                std::fs::create_dir_all(&dir).map_err(|_| Refusal::Escapes)?;
                self.confine(&self.root, &names, &upper[n - 1..])
            }
            _ => {
                if access == Access::Write && own.found == n - 1 {
                    check_new_name(comps[n - 1])?;
                }
                self.confine(&self.root, &own.names, &upper[own.found..])
            }
        }
    }

    /// Resolves a path that must exist (configuration files, objects, design data),
    /// looking through to the base tree.
    pub fn existing(&self, path: &str) -> Option<PathBuf> {
        self.resolve(path, Access::Read).ok().filter(|p| p.exists())
    }

    /// Like [`existing`](Self::existing) in the program's own directory only.
    pub fn existing_in_program(&self, path: &str) -> Option<PathBuf> {
        let comps = normalise(path).ok()?;
        let own = walk(&self.root, &comps);
        (own.found == comps.len()).then(|| self.confine(&self.root, &own.names, &[]).ok()).flatten().filter(|p| p.exists())
    }

    /// The base tree's directory at `path` when the program's directory has it too: a
    /// listing of it then shows both.
    pub fn lower_dir(&self, path: &str) -> Option<PathBuf> {
        let base = self.base.as_deref()?;
        let comps = normalise(path).ok()?;
        let (own, w) = (walk(&self.root, &comps), walk(base, &comps));
        if own.found != comps.len() || w.found != comps.len() {
            return None;
        }
        self.confine(base, &w.names, &[]).ok().filter(|d| d.is_dir())
    }

    /// A file the base tree has, opened for writing: copied into the program's tree
    /// first (a directory is handed back as it is: mkdir then fails with EEXIST, open
    /// with EISDIR, and nothing is written).
    fn copy_up(&self, base: &Path, own: &Walk, w: &Walk, comps: &[&str]) -> Result<PathBuf, Refusal> {
        let src = self.confine(base, &w.names, &[])?;
        if src.is_dir() {
            return Ok(src);
        }
        let upper: Vec<OsString> = comps.iter().map(|c| c.to_ascii_uppercase().into()).collect();
        let names = merged(own, w, &upper);
        let dst = self.confine(&self.root, &own.names, &names[own.found..])?;
        if let Some(dir) = dst.parent() {
            std::fs::create_dir_all(dir).map_err(|_| Refusal::Escapes)?;
        }
        std::fs::copy(&src, &dst).map_err(|_| Refusal::Escapes)?;
        Ok(dst)
    }

    /// `layer/names…/rest…` (`names` exist, `rest` do not) as a host path whose
    /// directories hold no symbolic link, or `Escapes` when any of it leads out of
    /// `layer` (or dangles).
    fn confine(&self, layer: &Path, names: &[OsString], rest: &[OsString]) -> Result<PathBuf, Refusal> {
        let mut path = layer.to_path_buf();
        path.extend(names);
        let Some(last) = names.last() else {
            let mut p = layer.to_path_buf();
            p.extend(rest);
            return Ok(p);
        };
        path.pop();
        let dir = path.canonicalize().map_err(|_| Refusal::Escapes)?;
        if !dir.starts_with(layer) {
            return Err(Refusal::Escapes);
        }
        let entry = dir.join(last);
        let is_link = entry.symlink_metadata().is_ok_and(|m| m.file_type().is_symlink());
        if is_link && !entry.canonicalize().is_ok_and(|real| real.starts_with(layer)) {
            return Err(Refusal::Escapes);
        }
        if !rest.is_empty() {
            // Below an existing entry: it must be a real directory of the layer.
            let real = entry.canonicalize().map_err(|_| Refusal::Escapes)?;
            if !real.starts_with(layer) {
                return Err(Refusal::Escapes);
            }
            let mut p = real;
            p.extend(rest);
            return Ok(p);
        }
        Ok(entry)
    }
}

/// The program's names where it has the component, else the base tree's, else `upper`.
fn merged(own: &Walk, base: &Walk, upper: &[OsString]) -> Vec<OsString> {
    (0..upper.len()).map(|i| own.names.get(i).or_else(|| base.names.get(i)).unwrap_or(&upper[i]).clone()).collect()
}

fn check_new_name(name: &str) -> Result<(), Refusal> {
    if is_eight_dot_three(name) {
        Ok(())
    } else {
        Err(Refusal::NotEightDotThree)
    }
}
