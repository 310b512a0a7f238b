//! The SDK's gcc plugin (`sdk-payload/plugin/openr-align.cc`): built into the SDK root
//! with the host compiler, passed to that compiler by `mipsel-linux-g++` / `gcc`. It
//! checks each access against the robot's alignment with a handler that never returns,
//! so the optimisers work as without the trap (gcc's own recoverable check counts as a
//! store to all memory: a loop adding to a member reloads it every pass), and it leaves
//! out the program's MIPS inline assembly (`asm volatile`, `__asm__`), which the
//! wrapper's `-Dasm(...)=` cannot reach.
//!
//! A plugin only loads into the very gcc it was built for. Each build is kept for the
//! compiler binary it was made and tried with, by that binary's identity (path, size,
//! mtime): `libexec/openr-align/<key>.so`. A compile by a compiler without one goes on
//! gcc's own check (same faults, slower loops). Without gcc's plugin headers
//! (`gcc-N-plugin-dev`), or when the plugin does not build or load, `<key>.missing` says
//! why; `cargo openr doctor` reports it, and the root builds it once the headers are
//! there.
use std::fs;
use std::hash::{Hash, Hasher};
use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

use crate::compile::host_tool;
use crate::error::Error;

/// Where the plugins of an SDK root are, one per compiler.
pub const DIR: &str = "libexec/openr-align";
/// Where its source (`sdk-payload/plugin/`) is installed, for readers and debuggers.
pub const SOURCE_DIR: &str = "OPEN_R/src/gcc-plugin";
const SOURCE: &str = "OPEN_R/src/gcc-plugin/openr-align.cc";

/// `OPENR_ALIGNMENT_TRAP`: `0` leaves the trap out, `ubsan` uses gcc's own recoverable
/// check (the plugin reads it too); anything else (or unset) the plugin's.
pub const VAR: &str = "OPENR_ALIGNMENT_TRAP";

const NO_HEADERS: &str = "has no plugin headers";

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

/// `<root>/libexec/openr-align/<key of the compiler>.<ext>`.
fn file_for(root: &Path, compiler: &Path, ext: &str) -> Option<PathBuf> {
    let mut h = std::collections::hash_map::DefaultHasher::new();
    identity(compiler)?.hash(&mut h);
    Some(root.join(DIR).join(format!("{:016x}.{ext}", h.finish())))
}

/// The plugin of `root` built for `compiler`, if there is one.
fn plugin_for(root: &Path, compiler: &Path) -> Option<PathBuf> {
    file_for(root, compiler, "so").filter(|p| p.is_file())
}

/// The `-fplugin=` flag for a compile by `compiler` against the SDK root `root`, if the
/// root has a plugin built for that compiler.
pub fn flag(root: &Path, compiler: &Path) -> Option<String> {
    plugin_for(root, compiler).map(|so| format!("-fplugin={}", so.display()))
}

/// What a root's plugin is for the host C++ compiler: `Ok(path of the plugin)` when it
/// loads into it, else why not (for `cargo openr doctor`).
pub fn status(root: &Path) -> Result<PathBuf, String> {
    let cxx = host_tool("g++", &["OPENR_HOST_CXX"]).map_err(|e| e.to_string())?;
    if let Some(so) = plugin_for(root, &cxx) {
        return Ok(so);
    }
    match file_for(root, &cxx, "missing").and_then(|n| fs::read_to_string(n).ok()) {
        Some(why) => Err(why.trim_end().to_string()),
        None => Err(format!("not built yet for {} (the next `cargo openr sdk install` builds it)", cxx.display())),
    }
}

/// The package with gcc's plugin headers for the host C++ compiler, when they are not
/// installed (`gcc-12-plugin-dev`): what `cargo openr doctor` tells to install.
pub fn missing_headers_package() -> Option<String> {
    let cxx = host_tool("g++", &["OPENR_HOST_CXX"]).ok()?;
    match headers(&cxx) {
        Some(_) => None,
        None => Some(headers_package(&ask(&cxx, "-dumpfullversion")?)),
    }
}

/// `gcc-<major>-plugin-dev` for gcc `version`.
fn headers_package(version: &str) -> String {
    format!("gcc-{}-plugin-dev", version.split('.').next().unwrap_or("N"))
}

/// gcc's plugin headers for `cxx`, if installed.
fn headers(cxx: &Path) -> Option<PathBuf> {
    ask(cxx, "-print-file-name=plugin").map(|d| PathBuf::from(d).join("include")).filter(|d| d.join("gcc-plugin.h").is_file())
}

/// `compiler -flag` (one line of output), if it runs.
fn ask(compiler: &Path, flag: &str) -> Option<String> {
    let out = Command::new(compiler).arg(flag).stdin(Stdio::null()).output().ok()?;
    out.status.success().then(|| String::from_utf8_lossy(&out.stdout).trim().to_string())
}

/// Whether an installed, otherwise up-to-date root should have the plugin built for the
/// host compiler ([`build`], under the root's install lock): there is none for it (gcc
/// upgraded, another `OPENR_HOST_CXX`), or its plugin headers were missing and are there
/// now. A build that failed for other reasons with this very compiler is not tried again.
pub fn needs_rebuild(root: &Path) -> bool {
    let Ok(cxx) = host_tool("g++", &["OPENR_HOST_CXX"]) else { return false };
    if plugin_for(root, &cxx).is_some() || !root.join(SOURCE).is_file() {
        return false;
    }
    match file_for(root, &cxx, "missing").and_then(|n| fs::read_to_string(n).ok()) {
        Some(why) => why.contains(NO_HEADERS) && headers(&cxx).is_some(),
        None => true,
    }
}

/// Builds the plugin into `root` (its source already written) for the host C++
/// compiler, and for the C compiler when it is the same gcc, each tried before it is
/// kept. A root without it works (gcc's own check), so a missing header package or a
/// plugin that does not build or load is written to the compiler's `.missing` note,
/// not returned; only I/O on the root is an error.
pub fn build(root: &Path) -> Result<(), Error> {
    let cxx = host_tool("g++", &["OPENR_HOST_CXX"])?;
    let dir = root.join(DIR);
    fs::create_dir_all(&dir).map_err(|e| Error::io(&dir, e))?;
    let (Some(so), Some(note)) = (file_for(root, &cxx, "so"), file_for(root, &cxx, "missing")) else {
        return Err(Error::usage(format!("cannot read the compiler {}", cxx.display())));
    };
    // Built beside and renamed once it loads: a compile running meanwhile finds the
    // plugin whole or not at all.
    let tmp = dir.join(format!(".build-{}.so", std::process::id()));
    let result = compile(root, &cxx, &tmp).and_then(|version| loads(&cxx, &tmp, "c++").map(|()| version));
    let version = match result {
        Ok(version) => version,
        Err(why) => {
            let _ = fs::remove_file(&tmp);
            return crate::install::write_atomic(&note, format!("{why}\n").as_bytes());
        }
    };
    let _ = fs::remove_file(&note);
    fs::rename(&tmp, &so).map_err(|e| Error::io(&so, e))?;
    // The C compiler loads the same plugin when it is the same gcc (cc1 exports what
    // cc1plus does); tried too, and kept under its own key.
    if let Ok(cc) = host_tool("gcc", &["OPENR_HOST_CC"]) {
        if let Some(cc_so) = file_for(root, &cc, "so").filter(|p| *p != so) {
            if ask(&cc, "-dumpfullversion").as_deref() == Some(version.as_str()) && loads(&cc, &so, "c").is_ok() {
                let tmp = dir.join(format!(".copy-{}.so", std::process::id()));
                fs::copy(&so, &tmp).and_then(|_| fs::rename(&tmp, &cc_so)).map_err(|e| Error::io(&cc_so, e))?;
            }
        }
    }
    Ok(())
}

/// Compiles the plugin with `cxx` into `out`; its gcc version, or why not.
fn compile(root: &Path, cxx: &Path, out: &Path) -> Result<String, String> {
    let version = ask(cxx, "-dumpfullversion").ok_or_else(|| format!("{} -dumpfullversion failed", cxx.display()))?;
    let package = headers_package(&version);
    let headers = headers(cxx).ok_or_else(|| {
        format!("{} {version} {NO_HEADERS} (apt-get install {package}): the alignment trap uses gcc's own check, which slows tight loops", cxx.display())
    })?;
    let built = Command::new(cxx)
        .args(["-shared", "-fPIC", "-fno-rtti", "-O2", "-o"])
        .arg(out)
        .arg(format!("-I{}", headers.display()))
        .arg(root.join(SOURCE))
        .output()
        .map_err(|e| format!("{}: {e}", cxx.display()))?;
    if !built.status.success() {
        let err = String::from_utf8_lossy(&built.stderr);
        let first: Vec<&str> = err.lines().filter(|l| l.contains("error")).take(3).collect();
        return Err(format!("the alignment plugin does not build with {} {version}: {}", cxx.display(), first.join(" / ")));
    }
    Ok(version)
}

/// Whether `compiler` loads `plugin` and compiles an aligned access with it (`lang`: c
/// or c++).
fn loads(compiler: &Path, plugin: &Path, lang: &str) -> Result<(), String> {
    let mut child = Command::new(compiler)
        .args(["-x", lang, "-O2", "-fsanitize=alignment", "-c", "-o", "/dev/null", "-"])
        .arg(format!("-fplugin={}", plugin.display()))
        .stdin(Stdio::piped())
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .map_err(|e| format!("{}: {e}", compiler.display()))?;
    if let Some(mut stdin) = child.stdin.take() {
        let _ = stdin.write_all(b"int get(int* p) { return *p; }\n");
    }
    let out = child.wait_with_output().map_err(|e| format!("{}: {e}", compiler.display()))?;
    if out.status.success() {
        return Ok(());
    }
    let err = String::from_utf8_lossy(&out.stderr);
    Err(format!("{} does not load the alignment plugin: {}", compiler.display(), err.lines().next().unwrap_or("").trim()))
}
