//! The alignment trap's gcc plugin (`sdk-payload/plugin/openr-align.cc`): built into
//! the SDK root with the host compiler, passed to that compiler by `mipsel-linux-g++` /
//! `gcc`. It checks each access against the robot's alignment with a handler that never
//! returns, so the optimisers work as without the trap (gcc's own recoverable check
//! counts as a store to all memory: a loop adding to a member reloads it every pass).
//!
//! A plugin only loads into the very gcc it was built for: the root records which
//! compiler binaries that is (path, size, mtime), and a compile by any other one goes
//! without the plugin, on gcc's own check (same faults, slower loops). Without gcc's
//! plugin headers (`gcc-N-plugin-dev`) the root has no plugin and says why in
//! [`NOTE`]; `cargo openr doctor` reports it.
use std::fs;
use std::path::{Path, PathBuf};
use std::process::Command;

use crate::compile::host_tool;
use crate::error::Error;

/// The plugin in an SDK root.
pub const PLUGIN: &str = "libexec/openr-align.so";
/// The compilers it loads into, one identity per line.
pub const COMPILERS: &str = "libexec/openr-align.compilers";
/// Why the root has no plugin (only when it has none).
pub const NOTE: &str = "libexec/openr-align.missing";
/// Where its source (`sdk-payload/plugin/`) is installed, for readers and debuggers.
pub const SOURCE_DIR: &str = "OPEN_R/src/gcc-plugin";
const SOURCE: &str = "OPEN_R/src/gcc-plugin/openr-align.cc";

/// `OPENR_ALIGNMENT_TRAP`: `0` leaves the trap out, `ubsan` uses gcc's own recoverable
/// check without the plugin; anything else (or unset) the plugin where there is one.
pub const VAR: &str = "OPENR_ALIGNMENT_TRAP";

/// Whether the build wants the alignment trap at all.
pub fn trap_wanted() -> bool {
    std::env::var_os(VAR).map_or(true, |v| v != "0")
}

/// `canonical path \t size \t mtime (ns)` of a compiler binary: what a plugin build is
/// tied to without running the compiler.
fn identity(compiler: &Path) -> Option<String> {
    let real = compiler.canonicalize().ok()?;
    let m = fs::metadata(&real).ok()?;
    let t = m.modified().ok()?.duration_since(std::time::UNIX_EPOCH).ok()?;
    Some(format!("{}\t{}\t{}", real.display(), m.len(), t.as_nanos()))
}

/// The `-fplugin=` flag for a compile by `compiler` against the SDK root `root`, if the
/// root has a plugin built for that compiler and the build wants it.
pub fn flag(root: &Path, compiler: &Path) -> Option<String> {
    if std::env::var_os(VAR).is_some_and(|v| v == "0" || v == "ubsan") {
        return None;
    }
    let so = root.join(PLUGIN);
    let compilers = fs::read_to_string(root.join(COMPILERS)).ok()?;
    let me = identity(compiler)?;
    (compilers.lines().any(|l| l == me) && so.is_file()).then(|| format!("-fplugin={}", so.display()))
}

/// `compiler -flag` (one line of output), if it runs.
fn ask(compiler: &Path, flag: &str) -> Option<String> {
    let out = Command::new(compiler).arg(flag).output().ok()?;
    out.status.success().then(|| String::from_utf8_lossy(&out.stdout).trim().to_string())
}

/// What a root's plugin is for the host C++ compiler: `Ok(path of the plugin)` when it
/// loads into it, else why not (for `cargo openr doctor`).
pub fn status(root: &Path) -> Result<PathBuf, String> {
    let cxx = host_tool("g++", &["OPENR_HOST_CXX"]).map_err(|e| e.to_string())?;
    if built_for(root, &cxx) {
        return Ok(root.join(PLUGIN));
    }
    if let Ok(note) = fs::read_to_string(root.join(NOTE)) {
        return Err(note.lines().nth(1).unwrap_or_default().to_string());
    }
    Err(format!("built for another compiler than {}", cxx.display()))
}

fn built_for(root: &Path, compiler: &Path) -> bool {
    let me = identity(compiler).unwrap_or_default();
    root.join(PLUGIN).is_file() && fs::read_to_string(root.join(COMPILERS)).is_ok_and(|c| c.lines().any(|l| l == me))
}

/// Builds the plugin into `root` (the source at [`SOURCE`] already written) for the host
/// C++ compiler, and for the C compiler when it is the same gcc. A root without it
/// works (gcc's own check), so a missing header package or a failed build is written
/// to [`NOTE`] (the compiler's identity, then why), not returned; only I/O on the root
/// is an error.
pub fn build(root: &Path) -> Result<(), Error> {
    let cxx = match host_tool("g++", &["OPENR_HOST_CXX"]) {
        Ok(cxx) => cxx,
        Err(e) => return crate::install::write_atomic(&root.join(NOTE), format!("\n{e}\n").as_bytes()),
    };
    let why = match try_build(root, &cxx) {
        Ok(compilers) => {
            let _ = fs::remove_file(root.join(NOTE));
            return crate::install::write_atomic(&root.join(COMPILERS), compilers.as_bytes());
        }
        Err(why) => why,
    };
    let _ = fs::remove_file(root.join(PLUGIN));
    let _ = fs::remove_file(root.join(COMPILERS));
    crate::install::write_atomic(&root.join(NOTE), format!("{}\n{why}\n", identity(&cxx).unwrap_or_default()).as_bytes())
}

/// Whether an installed, otherwise up-to-date root should have its plugin built again
/// ([`build`], under the root's install lock): the host compiler changed since (gcc
/// upgraded, another `OPENR_HOST_CXX`), or its plugin headers were missing and are
/// there now. A build that failed for this very compiler is not tried again.
pub fn needs_rebuild(root: &Path) -> bool {
    let Ok(cxx) = host_tool("g++", &["OPENR_HOST_CXX"]) else { return false };
    if built_for(root, &cxx) || !root.join(SOURCE).is_file() {
        return false;
    }
    let Ok(note) = fs::read_to_string(root.join(NOTE)) else { return true };
    let mut lines = note.lines();
    let same = lines.next() == identity(&cxx).as_deref();
    let why = lines.next().unwrap_or_default();
    !same || (why.contains(NO_HEADERS) && headers(&cxx).is_some())
}

const NO_HEADERS: &str = "has no plugin headers";

/// gcc's plugin headers for `cxx`, if installed.
fn headers(cxx: &Path) -> Option<PathBuf> {
    ask(cxx, "-print-file-name=plugin").map(|d| PathBuf::from(d).join("include")).filter(|d| d.join("gcc-plugin.h").is_file())
}

fn try_build(root: &Path, cxx: &Path) -> Result<String, String> {
    let cxx = cxx.to_path_buf();
    let version = ask(&cxx, "-dumpfullversion").ok_or_else(|| format!("{} -dumpfullversion failed", cxx.display()))?;
    let major = version.split('.').next().unwrap_or("N").to_string();
    let headers = headers(&cxx).ok_or_else(|| {
        format!(
            "{} {version} {NO_HEADERS} (apt-get install gcc-{major}-plugin-dev): the alignment trap uses gcc's own check, which slows tight loops",
            cxx.display()
        )
    })?;
    // Built beside and renamed: a compile running meanwhile loads the old one or none.
    let tmp = root.join(format!("{PLUGIN}.tmp-{}", std::process::id()));
    let out = Command::new(&cxx)
        .args(["-shared", "-fPIC", "-fno-rtti", "-O2", "-o"])
        .arg(&tmp)
        .arg(format!("-I{}", headers.display()))
        .arg(root.join(SOURCE))
        .output()
        .map_err(|e| format!("{}: {e}", cxx.display()))?;
    let out = match out.status.success() {
        true => fs::rename(&tmp, root.join(PLUGIN)).map(|()| out).map_err(|e| format!("{}: {e}", root.join(PLUGIN).display()))?,
        false => out,
    };
    let _ = fs::remove_file(&tmp);
    if !out.status.success() {
        let err = String::from_utf8_lossy(&out.stderr);
        let first: Vec<&str> = err.lines().filter(|l| l.contains("error")).take(3).collect();
        return Err(format!("the alignment plugin does not build with {} {version}: {}", cxx.display(), first.join(" / ")));
    }
    let mut compilers = identity(&cxx).ok_or_else(|| format!("cannot stat {}", cxx.display()))? + "\n";
    // The C compiler loads it too when it is the same gcc (cc1 exports what cc1plus does).
    if let Ok(cc) = host_tool("gcc", &["OPENR_HOST_CC"]) {
        if ask(&cc, "-dumpfullversion").as_deref() == Some(version.as_str()) {
            if let Some(id) = identity(&cc) {
                compilers.push_str(&id);
                compilers.push('\n');
            }
        }
    }
    Ok(compilers)
}
