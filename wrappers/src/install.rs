//! `cargo openr sdk install`: materialises an SDK root that unmodified Makefiles accept
//! as `OPENRSDK_ROOT`.
//!
//! ```text
//! <root>/bin/mipsel-linux-{g++,c++,gcc,ld,strip,ar,ranlib} -> ../libexec/cargo-openr
//! <root>/OPEN_R/bin/{stubgen2,mkbin,gzcp}                    -> ../../libexec/cargo-openr
//! <root>/RP_OPEN_R/bin/{rp-openr-stubgen2,rp-openr-config,start-rp-openr,rp-openr-ipcrm,setup-rp-openr}
//!                                                           -> ../../libexec/cargo-openr
//! <root>/RP_OPEN_R/{include,lib}  -> ../OPEN_R/{include,lib}   (remote processing, host objects)
//! <root>/OPEN_R/include/**       our OPEN-R headers
//! <root>/OPEN_R/lib/lib*.a       the runtime's C++ surface, compiled here with host g++
//! <root>/OPEN_R/src/**           its sources, for debuggers
//! <root>/libexec/openr-align/    the alignment trap's gcc plugin, per compiler (align_plugin.rs)
//! <root>/OPEN_R/MS_ERS7/...      Memory Stick base trees
//! <root>/sim/mujoco/*.py,*.xml   the MuJoCo simulator peer (`cargo openr run --sim mujoco`)
//! ```
//!
//! The tree is built beside the destination and swapped in with renames, so an
//! interrupted install never leaves a half-written root; a root whose stamp matches is
//! left untouched (idempotent, and fast).
use std::collections::hash_map::DefaultHasher;
use std::fs;
use std::hash::{Hash, Hasher};
use std::path::{Path, PathBuf};
use std::process::Command;

use openr_sdk_payload as sdk_files;

use crate::compile::host_tool;
use crate::error::{Error, ErrorKind};
use crate::TOOLS;

/// File whose presence marks a directory as a cargo-openr SDK root; holds the payload hash.
pub const STAMP: &str = ".cargo-openr-sdk";

/// Where the MuJoCo simulator (peer.py, ers7.xml, scene.xml, …) lives in an SDK root.
pub const SIM_DIR: &str = "sim/mujoco";

/// Valgrind suppressions for the runtime itself (`cargo openr run --valgrind` passes them).
pub const VALGRIND_SUPP: &str = "share/valgrind/cargo-openr.supp";
const VALGRIND_SUPP_TEXT: &str = include_str!("../share/cargo-openr.supp");

/// gdb commands for a run under `cargo openr run --gdb`.
pub const GDB_INIT: &str = "share/gdb/cargo-openr.gdb";
const GDB_INIT_TEXT: &str = "\
# Written by cargo openr sdk install; `cargo openr run --gdb` loads it.
# Objects are loaded after the process starts: breakpoints on them wait for the load.
set breakpoint pending on
# SIGUSR1 is the robot's pause button (robot-api 9.3), not a fault.
handle SIGUSR1 nostop noprint pass
set print pretty on
";

/// What `install` did.
#[derive(Debug, PartialEq, Eq)]
pub enum Outcome {
    Installed,
    UpToDate,
}

/// Whether `dir` is an SDK root made by this tool.
pub fn is_sdk_root(dir: &Path) -> bool {
    dir.join(STAMP).is_file()
}

/// The per-user default location: `$XDG_DATA_HOME/cargo-openr/OPEN_R_SDK`
/// (`~/.local/share/...`).
pub fn default_prefix() -> Option<PathBuf> {
    let data = std::env::var_os("XDG_DATA_HOME")
        .filter(|v| !v.is_empty())
        .map(PathBuf::from)
        .or_else(|| std::env::var_os("HOME").map(|h| PathBuf::from(h).join(".local/share")))?;
    Some(data.join("cargo-openr").join("OPEN_R_SDK"))
}

/// Why `install` builds the tree (it takes a minute or two: the runtime's C++ surface
/// is compiled), told before it starts so that a caller can say so.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Building {
    /// No SDK root there yet.
    New,
    /// A root made by another build of cargo-openr (another payload).
    OtherBuild,
}

/// Installs the SDK root at `prefix` using `exe` (the multi-call binary) for the tools.
pub fn install(prefix: &Path, exe: &Path) -> Result<Outcome, Error> {
    install_telling(prefix, exe, |_| {})
}

/// [`install`], calling `building` once before a tree is built.
pub fn install_telling(prefix: &Path, exe: &Path, building: impl FnOnce(Building)) -> Result<Outcome, Error> {
    // Fast path: the very executable that wrote the stamp (same size and mtime) carries
    // the same payload, so there is nothing to hash.
    let meta = exe_fingerprint(exe);
    let old = fs::read_to_string(prefix.join(STAMP)).unwrap_or_default();
    if meta.is_some() && old.lines().nth(1) == meta.as_deref() {
        return refreshed(prefix, false);
    }
    let parent = prefix.parent().filter(|p| !p.as_os_str().is_empty()).unwrap_or(Path::new("."));
    fs::create_dir_all(parent).map_err(|e| Error::io(parent, e))?;
    let _lock = lock(parent, prefix)?;
    let exe_bytes = fs::read(exe).map_err(|e| Error::io(exe, e))?;
    let hash = payload_hash(&exe_bytes);
    let stamp = format!("{hash}\n{}\n", meta.unwrap_or_default());
    let old = fs::read_to_string(prefix.join(STAMP)).unwrap_or_default();
    if old.lines().next() == Some(hash.as_str()) {
        // Same payload from another build of the binary: refresh the fingerprint only.
        write_atomic(&prefix.join(STAMP), stamp.as_bytes())?;
        return refreshed(prefix, true);
    }
    if prefix.exists() && !is_sdk_root(prefix) && !is_empty_dir(prefix) {
        return Err(Error::usage(format!("{} exists and is not a cargo-openr SDK root; choose a new or empty directory", prefix.display())));
    }
    let name = prefix.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_else(|| "sdk".into());
    remove_leftovers(parent, &name);
    building(if is_sdk_root(prefix) { Building::OtherBuild } else { Building::New });
    let staging = parent.join(format!(".{name}.partial-{}", std::process::id()));
    let result = build_tree(&staging, prefix, &exe_bytes, &stamp).and_then(|()| swap_in(&staging, prefix));
    if result.is_err() {
        let _ = fs::remove_dir_all(&staging);
    }
    result.map(|()| Outcome::Installed)
}

/// An up-to-date root, its alignment plugin built for the host compiler if it has none
/// yet (under the install lock, which the caller may hold already). A root that cannot
/// be written to (installed by root, say) is used as it is: the trap then uses gcc's
/// own check, and a warning says why.
fn refreshed(prefix: &Path, locked: bool) -> Result<Outcome, Error> {
    if crate::align_plugin::needs_rebuild(prefix) {
        let parent = prefix.parent().filter(|p| !p.as_os_str().is_empty()).unwrap_or(Path::new("."));
        let built = (if locked { Ok(None) } else { lock(parent, prefix).map(Some) }).and_then(|_lock| {
            if crate::align_plugin::needs_rebuild(prefix) {
                crate::align_plugin::build(prefix)?;
            }
            Ok(())
        });
        if let Err(e) = built {
            eprintln!("warning: cannot build the alignment trap's gcc plugin into {}: {e} (the trap uses gcc's own, slower check)", prefix.display());
        }
    }
    Ok(Outcome::UpToDate)
}

/// Whether `prefix` holds an SDK root that `install(prefix, exe)` would leave untouched
/// (checked without writing anything; `cargo openr doctor`).
pub fn is_up_to_date(prefix: &Path, exe: &Path) -> bool {
    let old = fs::read_to_string(prefix.join(STAMP)).unwrap_or_default();
    let meta = exe_fingerprint(exe);
    if meta.is_some() && old.lines().nth(1) == meta.as_deref() {
        return true;
    }
    fs::read(exe).is_ok_and(|bytes| old.lines().next() == Some(payload_hash(&bytes).as_str()))
}

/// `len:mtime` of the executable.
fn exe_fingerprint(exe: &Path) -> Option<String> {
    let m = fs::metadata(exe).ok()?;
    let t = m.modified().ok()?.duration_since(std::time::UNIX_EPOCH).ok()?;
    Some(format!("{}:{}", m.len(), t.as_nanos()))
}

/// Serialises concurrent installs into one prefix (several `cargo openr run` at once).
fn lock(parent: &Path, prefix: &Path) -> Result<fs::File, Error> {
    use std::os::unix::io::AsRawFd;
    let name = prefix.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
    let path = parent.join(format!(".{name}.lock"));
    let f = fs::OpenOptions::new().create(true).truncate(false).write(true).open(&path).map_err(|e| Error::io(&path, e))?;
    // SAFETY: `f` is an open file; flock touches no memory.
    if unsafe { libc::flock(f.as_raw_fd(), libc::LOCK_EX) } != 0 {
        return Err(Error::io(&path, std::io::Error::last_os_error()));
    }
    Ok(f)
}

fn is_empty_dir(p: &Path) -> bool {
    fs::read_dir(p).is_ok_and(|mut d| d.next().is_none())
}

/// The executable's bytes carry the whole payload (headers, C++ sources, simulator are
/// embedded in it), so they alone say whether an installed root is this one.
fn payload_hash(exe: &[u8]) -> String {
    let mut h = DefaultHasher::new();
    exe.hash(&mut h);
    format!("{}-{:016x}", env!("CARGO_PKG_VERSION"), h.finish())
}

/// Removes what an install into `parent/name` that was killed half-way left behind
/// (its staging tree, the previous root it was swapping out). Installs into one prefix
/// are serialised by its lock, which the caller holds: none of these is in use.
fn remove_leftovers(parent: &Path, name: &str) {
    let partial = format!(".{name}.partial-");
    let Ok(entries) = fs::read_dir(parent) else { return };
    for e in entries.flatten() {
        let file = e.file_name();
        let file = file.to_string_lossy();
        if file.starts_with(&partial) || file == format!(".{name}.old") {
            let _ = fs::remove_dir_all(e.path());
        }
    }
}

fn swap_in(staging: &Path, prefix: &Path) -> Result<(), Error> {
    let old = staging.with_extension("old");
    let had_old = prefix.exists();
    if had_old {
        fs::rename(prefix, &old).map_err(|e| Error::io(prefix, e))?;
    }
    if let Err(e) = fs::rename(staging, prefix) {
        if had_old {
            let _ = fs::rename(&old, prefix);
        }
        return Err(Error::io(prefix, e));
    }
    if had_old {
        let _ = fs::remove_dir_all(&old);
    }
    Ok(())
}

/// `-fdebug-prefix-map` from the staging directory the root is built in to the root's
/// final place, so that the libraries' and system objects' debug info names sources that
/// exist after the install (gdb, sanitizer reports: `<root>/OPEN_R/src/OPENR/OObject.cc`).
fn debug_prefix_map(staging: &Path, root: &Path) -> String {
    let root = std::path::absolute(root).unwrap_or_else(|_| root.to_path_buf());
    format!("-fdebug-prefix-map={}={}", staging.display(), root.display())
}

fn build_tree(root: &Path, final_root: &Path, exe: &[u8], stamp: &str) -> Result<(), Error> {
    let map = debug_prefix_map(root, final_root);
    let _ = fs::remove_dir_all(root);
    let include = root.join("OPEN_R/include");
    let src = root.join("OPEN_R/src");
    write_files(&include, sdk_files::INCLUDE)?;
    write_files(&src, sdk_files::CXX)?;
    write_files(&root.join(SIM_DIR), sdk_files::SIM)?;
    write_files(root, &[(VALGRIND_SUPP, VALGRIND_SUPP_TEXT.as_bytes()), (GDB_INIT, GDB_INIT_TEXT.as_bytes())])?;
    install_tools(root, exe)?;
    write_files(&root.join(crate::align_plugin::SOURCE_DIR), sdk_files::PLUGIN)?;
    crate::align_plugin::build(root)?;
    build_archives(root, &include, &src, &map)?;
    build_system_objects(root, &include, &src, &map)?;
    write_base_trees(&root.join("OPEN_R"))?;
    write(&root.join(STAMP), stamp.as_bytes())
}

fn write_files(dir: &Path, files: &[(&str, &[u8])]) -> Result<(), Error> {
    for (rel, bytes) in files {
        write(&dir.join(rel), bytes)?;
    }
    Ok(())
}

fn write(path: &Path, bytes: &[u8]) -> Result<(), Error> {
    if let Some(p) = path.parent() {
        fs::create_dir_all(p).map_err(|e| Error::io(p, e))?;
    }
    fs::write(path, bytes).map_err(|e| Error::io(path, e))
}

/// Writes `bytes` to `path` through a temporary sibling and a rename.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> Result<(), Error> {
    let mut tmp = path.as_os_str().to_owned();
    tmp.push(format!(".tmp-{}", std::process::id()));
    let tmp = PathBuf::from(tmp);
    // A failed write (disk full) or rename leaves no temp file behind.
    fs::write(&tmp, bytes).and_then(|()| fs::rename(&tmp, path)).map_err(|e| {
        let _ = fs::remove_file(&tmp);
        Error::io(path, e)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_install_killed_half_way_does_not_block_the_next() {
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path();
        for left in [".sdk.old", ".sdk.partial-4242", ".other.old"] {
            fs::create_dir_all(p.join(left).join("OPEN_R")).unwrap();
        }
        fs::create_dir_all(p.join("sdk")).unwrap();
        fs::write(p.join("sdk/STAMP"), b"old root").unwrap();
        remove_leftovers(p, "sdk");
        let staging = p.join(format!(".sdk.partial-{}", std::process::id()));
        fs::create_dir_all(&staging).unwrap();
        fs::write(staging.join("STAMP"), b"new root").unwrap();
        swap_in(&staging, &p.join("sdk")).unwrap();
        assert_eq!(fs::read(p.join("sdk/STAMP")).unwrap(), b"new root");
        let mut left: Vec<_> = fs::read_dir(p).unwrap().map(|e| e.unwrap().file_name().into_string().unwrap()).collect();
        left.sort();
        assert_eq!(left, [".other.old", "sdk"], "another prefix's files are not touched");
    }

    #[test]
    fn a_failed_atomic_write_names_the_file_and_leaves_nothing_behind() {
        let dir = tempfile::tempdir().unwrap();
        // The target is a directory: the rename fails after the temp file was written.
        let target = dir.path().join("STAMP");
        fs::create_dir(&target).unwrap();
        fs::write(target.join("x"), b"keep").unwrap();
        let err = write_atomic(&target, b"new").unwrap_err().to_string();
        assert!(err.contains("STAMP"), "{err}");
        let left: Vec<_> = fs::read_dir(dir.path()).unwrap().map(|e| e.unwrap().file_name()).collect();
        assert_eq!(left, vec![std::ffi::OsString::from("STAMP")]);
        assert_eq!(fs::read(target.join("x")).unwrap(), b"keep");
    }
}

fn install_tools(root: &Path, exe: &[u8]) -> Result<(), Error> {
    use std::os::unix::fs::{symlink, PermissionsExt};
    let target = root.join("libexec/cargo-openr");
    write(&target, exe)?;
    fs::set_permissions(&target, fs::Permissions::from_mode(0o755)).map_err(|e| Error::io(&target, e))?;
    for (name, _, dir) in TOOLS {
        let d = root.join(dir);
        fs::create_dir_all(&d).map_err(|e| Error::io(&d, e))?;
        let up = "../".repeat(dir.split('/').count());
        symlink(format!("{up}libexec/cargo-openr"), d.join(name)).map_err(|e| Error::io(d.join(name), e))?;
    }
    // RP OPEN-R host objects use the very headers and archives of the robot build
    // (`rp-openr-config` names OPEN_R/...); these links let Makefiles that name
    // RP_OPEN_R/include or RP_OPEN_R/lib directly find them too.
    for d in ["include", "lib"] {
        let link = root.join("RP_OPEN_R").join(d);
        symlink(format!("../OPEN_R/{d}"), &link).map_err(|e| Error::io(&link, e))?;
    }
    Ok(())
}

/// Compiles `OPEN_R/src/<lib>/*.cc` into `OPEN_R/lib/lib<lib>.a`, one archive per
/// directory. Archives of families with no sources yet are still created (empty) so
/// that `-l<lib>` always resolves.
fn build_archives(root: &Path, include: &Path, src: &Path, map: &str) -> Result<(), Error> {
    let lib = root.join("OPEN_R/lib");
    let obj = root.join("OPEN_R/lib/.obj");
    fs::create_dir_all(&obj).map_err(|e| Error::io(&obj, e))?;
    let cxx = host_tool("g++", &["OPENR_HOST_CXX"])?;
    let ar = host_tool("ar", &[])?;
    let mut jobs: Vec<(String, PathBuf, PathBuf)> = Vec::new();
    for (rel, _) in sdk_files::CXX.iter().filter(|(p, _)| p.ends_with(".cc")) {
        let Some((libname, file)) = rel.split_once('/') else { continue };
        if libname == "system" {
            continue; // system objects, built by build_system_objects
        }
        let o = obj.join(libname).join(file.replace('/', "_")).with_extension("o");
        jobs.push((libname.to_string(), src.join(rel), o));
    }
    // Two compilers at a time: the machines this runs on have few cores.
    let workers = std::thread::available_parallelism().map_or(2, |n| n.get()).min(4);
    let chunks: Vec<Vec<&(String, PathBuf, PathBuf)>> = (0..workers).map(|w| jobs.iter().skip(w).step_by(workers).collect()).collect();
    std::thread::scope(|s| {
        let handles: Vec<_> = chunks
            .iter()
            .map(|chunk| {
                let (cxx, src, include, map) = (&cxx, src, include, map);
                s.spawn(move || -> Result<(), Error> {
                    for (_, cc, o) in chunk {
                        fs::create_dir_all(o.parent().unwrap()).map_err(|e| Error::io(o, e))?;
                        let mut cmd = Command::new(cxx);
                        cmd.args(["-std=gnu++98", "-fPIC", "-O2", "-g", "-c", "-Wall", "-Wno-unused", map])
                            .arg(format!("-I{}", src.display()))
                            .arg(format!("-I{}", include.join("R4000").display()))
                            .arg(format!("-I{}", include.join("MCOOP").display()))
                            .arg(format!("-I{}", include.display()))
                            .arg("-o")
                            .arg(o)
                            .arg(cc);
                        run_quiet(&mut cmd)?;
                    }
                    Ok(())
                })
            })
            .collect();
        handles.into_iter().try_for_each(|h| h.join().expect("compiler thread panicked"))
    })?;
    for libname in crate::mkbin::DEFAULT_LIBS {
        let archive = lib.join(format!("lib{libname}.a"));
        let members: Vec<&PathBuf> = jobs.iter().filter(|(l, _, _)| l == libname).map(|(_, _, o)| o).collect();
        let mut cmd = Command::new(&ar);
        cmd.arg("rcs").arg(&archive).args(members);
        run_quiet(&mut cmd)?;
    }
    fs::remove_dir_all(&obj).map_err(|e| Error::io(&obj, e))
}

/// System objects the runtime loads before a stick's own objects (robot-api 8.1):
/// `(directory under cxx/system, file under OPEN_R/SYSTEM/OBJS)`.
pub const SYSTEM_OBJECTS: &[(&str, &str)] = &[("VirtualRobotComm", "VRCOMM.BIN"), ("VirtualRobotAudioComm", "VRAUCOMM.BIN")];

/// Builds each system object like a user object: stubgen2, the compiler, mkbin.
fn build_system_objects(root: &Path, include: &Path, src: &Path, map: &str) -> Result<(), Error> {
    let cxx = host_tool("g++", &["OPENR_HOST_CXX"])?;
    let objs_dir = root.join("OPEN_R/SYSTEM/OBJS");
    fs::create_dir_all(&objs_dir).map_err(|e| Error::io(&objs_dir, e))?;
    for (dir, bin) in SYSTEM_OBJECTS {
        let source = src.join("system").join(dir);
        let build = root.join("OPEN_R/SYSTEM/.build").join(dir);
        fs::create_dir_all(&build).map_err(|e| Error::io(&build, e))?;
        let cfg = stubgen::parse_files(&[source.join("stub.cfg")]).map_err(|e| Error::usage(e.to_string()))?;
        stubgen::write_outputs(&cfg, &build).map_err(|e| Error::usage(e.to_string()))?;
        let mut units: Vec<PathBuf> = vec![build.join(format!("{}Stub.cc", cfg.object_name))];
        let mut entries: Vec<PathBuf> = fs::read_dir(&source).map_err(|e| Error::io(&source, e))?.flatten().map(|e| e.path()).collect();
        entries.sort();
        units.extend(entries.iter().filter(|p| p.extension().is_some_and(|x| x == "cc")).cloned());
        let mut objects = Vec::new();
        for unit in &units {
            let o = build.join(unit.file_stem().unwrap_or_default()).with_extension("o");
            let mut cmd = Command::new(&cxx);
            cmd.args(crate::compile::host_flags(crate::compile::Lang::Cxx, &[]))
                .args(crate::align_plugin::flag(root, &cxx))
                .args(["-O2", "-g", "-c", map])
                .arg(format!("-I{}", build.display()))
                .arg(format!("-I{}", source.display()))
                .arg(format!("-I{}", src.display()))
                .arg(format!("-I{}", include.join("R4000").display()))
                .arg(format!("-I{}", include.display()))
                .arg("-o")
                .arg(&o)
                .arg(unit);
            run_quiet(&mut cmd)?;
            objects.push(o.into_os_string());
        }
        let ocf = fs::read_dir(&source)
            .map_err(|e| Error::io(&source, e))?
            .flatten()
            .map(|e| e.path())
            .find(|p| p.extension().is_some_and(|x| x == "ocf"))
            .ok_or_else(|| Error::usage(format!("{}: no .ocf", source.display())))?;
        let opts =
            crate::mkbin::Options { output: Some(build.join("object.bin")), ocf: Some(ocf), default_libs: true, link_args: objects, ..Default::default() };
        let linked = crate::mkbin::link(&opts, root)?;
        fs::rename(&linked, objs_dir.join(bin)).map_err(|e| Error::io(objs_dir.join(bin), e))?;
    }
    let tmp = root.join("OPEN_R/SYSTEM/.build");
    fs::remove_dir_all(&tmp).map_err(|e| Error::io(&tmp, e))
}

/// The system objects of an installed SDK root, in load order.
pub fn system_objects(root: &Path) -> Vec<PathBuf> {
    SYSTEM_OBJECTS.iter().map(|(_, bin)| root.join("OPEN_R/SYSTEM/OBJS").join(bin)).collect()
}

/// Runs a child and folds its output into the error when it fails.
fn run_quiet(cmd: &mut Command) -> Result<(), Error> {
    let out = cmd.output().map_err(|e| Error::io(PathBuf::from(cmd.get_program()), e))?;
    if out.status.success() {
        return Ok(());
    }
    let line = std::iter::once(cmd.get_program()).chain(cmd.get_args()).map(|a| a.to_string_lossy()).collect::<Vec<_>>().join(" ");
    Err(ErrorKind::CommandFailed { command: format!("{line}\n{}", String::from_utf8_lossy(&out.stderr)), status: out.status.to_string() }.into())
}

/// The base tree `base` (`WCONSOLE/nomemprot`, …; see `cargo openr config`) of `root`
/// for robot design `design`: the directory holding its `OPEN-R`.
pub fn base_tree(root: &Path, design: &str, base: &str) -> PathBuf {
    let model = if matches!(design, "ERS-210" | "ERS-220") { "MS_ERS200" } else { "MS_ERS7" };
    root.join("OPEN_R").join(model).join(base)
}

/// Memory Stick base trees (object-model 1.5): the directories and the comment-only
/// OBJECT.CFG that a sample overlays; `cargo openr run` lays one under the program's MS.
fn write_base_trees(open_r: &Path) -> Result<(), Error> {
    const OBJECT_CFG: &str = "#\r\n# OBJECT.CFG of the base tree: list user objects here, one\r\n\
                              # /MS/OPEN-R/MW/OBJS/XXXXXXXX.BIN per line.\r\n#\r\n[ERS-210]\r\n";
    // The robot's defaults, the very ones the runtime assumes without the file: a run
    // over the base tree reports the same settings as one without it.
    let mut wlan = String::from("# Wireless LAN settings (KEY=VALUE), read by the runtime's network layer.\r\n");
    for (k, v) in openr_sdk_payload::WLAN_DEFAULTS {
        wlan.push_str(&format!("{k}={v}\r\n"));
    }
    for model in ["MS_ERS7", "MS_ERS200"] {
        for kind in ["BASIC", "WLAN", "WCONSOLE"] {
            for prot in ["memprot", "nomemprot"] {
                let tree = open_r.join(model).join(kind).join(prot).join("OPEN-R");
                write(&tree.join("MW/CONF/OBJECT.CFG"), OBJECT_CFG.as_bytes())?;
                for d in ["MW/OBJS", "MW/DATA/P", "MW/DATA/E", "SYSTEM/OBJS", "SYSTEM/DATA/E"] {
                    fs::create_dir_all(tree.join(d)).map_err(|e| Error::io(tree.join(d), e))?;
                }
                write(&tree.join("SYSTEM/CONF/OBJECT.CFG"), b"# System objects are built into the cargo-openr runtime.\r\n")?;
                if prot == "nomemprot" {
                    // Distributed execution runs over nomemprot only (remote-processing 5).
                    write(&tree.join("SYSTEM/OBJS/TCPGW.BIN"), crate::rp::TCPGW_BIN)?;
                }
                write(&tree.join("SYSTEM/CONF/EXTOBJ.CFG"), b"# Extra system objects: none, the runtime provides them.\r\n")?;
                write(&tree.join("SYSTEM/CONF/EMON.CFG"), b"# Exception monitor script: the runtime reports crashes itself.\r\n")?;
                if kind != "BASIC" {
                    write(&tree.join("SYSTEM/CONF/WLANDFLT.TXT"), wlan.as_bytes())?;
                    write(&tree.join("SYSTEM/CONF/CARDDRV.CFG"), b"# Network card drivers: the runtime's network layer stands for them.\r\n")?;
                }
            }
        }
    }
    Ok(())
}
