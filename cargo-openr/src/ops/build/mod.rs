//! `cargo openr build`: builds every object of an OPEN-R project into its Memory Stick
//! tree (`MS/OPEN-R/MW/OBJS/<NAME>.BIN`) without `make`.
//!
//! The project needs no manifest of its own; its objects are found in the project tree
//! (`MS/`, `target/` and hidden directories are skipped):
//! * a **C++ object** is a directory with a `stub.cfg`: its `*.cc`/`*.cpp`/`*.c` sources are
//!   compiled with the SDK root's `bin/mipsel-linux-g++` (flags as Sony's Makefiles give
//!   them), the stub by the `stubgen` crate, the link by `mkbin`; the `.ocf` is the one in
//!   the directory or its `robot/` subdirectory. The `.BIN` name is the `OBJS/NAME.BIN`
//!   its Makefile installs, else the OBJECT.CFG entry named after the object, else the
//!   object name's first 8 characters in upper case;
//! * a **Rust object** is a cargo package with `crate-type = ["cdylib"]`; `cargo build`
//!   builds it and its `.so` is gzipped. The `.BIN` name is `bin = "NAME.BIN"` under
//!   `[package.metadata.openr]` of its Cargo.toml, else derived from the package name.
//!
//! Work products go to `target/openr/<object>/` of the project. A C++ object is rebuilt
//! only when a source, one of the headers its `-MMD` `.d` file lists, its flags, its
//! stub.cfg or its `.ocf` changed; `compile_commands.json` is written at the project root
//! ([`compile_db`]). The C++ units of all objects compile on one pool of `-j` processes,
//! then the objects link on it ([`cxx`]); events come out in object order regardless.
use std::fs;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::{Instant, SystemTime};

use anyhow::{bail, Context};

mod compile_db;
mod cxx;

/// What to build.
#[derive(Debug, Clone)]
pub struct BuildOptions {
    /// The project directory.
    pub dir: PathBuf,
    /// The SDK root (installed).
    pub sdk: PathBuf,
    pub release: bool,
    /// Extra C/C++ compiler flags (after the profile's, before the include paths).
    pub cxxflags: Vec<String>,
    /// Extra link arguments given to `mkbin` after the objects.
    pub ldflags: Vec<String>,
    /// Ask the compiler for coloured diagnostics (`-fdiagnostics-color=always`; not part
    /// of the recorded command line, so switching it rebuilds nothing).
    pub color: bool,
    /// Show each compiler command (`-v`; mkbin shows its link commands itself).
    pub verbose: bool,
    /// At most this many compiler or linker processes at once (`-j`).
    pub jobs: usize,
    /// Only these objects (by name), all when empty.
    pub packages: Vec<String>,
}

/// One object of the project.
#[derive(Debug, Clone)]
pub struct Object {
    pub name: String,
    pub dir: PathBuf,
    pub bin: String,
    pub kind: Kind,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    Cxx,
    Rust,
}

impl Kind {
    pub fn label(self) -> &'static str {
        match self {
            Kind::Cxx => "C++",
            Kind::Rust => "Rust",
        }
    }
}

/// A progress event; the command renders it as a status line or a JSON record.
#[derive(Debug)]
pub enum Event {
    /// Compiler work starts for an object.
    Compiling { object: String, kind: Kind },
    /// A command about to run (`-v`), as the shell would show it.
    Running { object: String, command: String },
    /// An object's `.BIN` is in place; `fresh` when nothing had to be done.
    Artifact { object: String, kind: Kind, bin: PathBuf, fresh: bool },
    /// A compiler's output for an object (`level` is `error` or `warning`).
    Message { object: String, level: &'static str, rendered: String },
}

/// What a build did.
#[derive(Debug)]
pub struct BuildReport {
    pub objects: usize,
    pub compiled: usize,
    pub elapsed: std::time::Duration,
}

/// Finds the project's objects.
pub fn discover(dir: &Path) -> anyhow::Result<Vec<Object>> {
    let object_cfg = fs::read_to_string(dir.join("MS/OPEN-R/MW/CONF/OBJECT.CFG")).unwrap_or_default();
    let mut out = Vec::new();
    walk(dir, 0, &mut |d| {
        if d.join("stub.cfg").is_file() {
            let cfg = stubgen::parse_files(&[d.join("stub.cfg")]).map_err(|e| anyhow::anyhow!("{e}"))?;
            let name = cfg.object_name.clone();
            let bin = makefile_bin(d).or_else(|| object_cfg_bin(&object_cfg, &name)).unwrap_or_else(|| derived_bin(&name));
            out.push(Object { name, dir: d.to_path_buf(), bin, kind: Kind::Cxx });
        } else if let Ok(text) = fs::read_to_string(d.join("Cargo.toml")) {
            if let Some((name, bin)) = rust_object(&d.join("Cargo.toml"), &text)? {
                let bin = bin.unwrap_or_else(|| derived_bin(&name));
                out.push(Object { name, dir: d.to_path_buf(), bin, kind: Kind::Rust });
            }
        }
        Ok(())
    })?;
    out.sort_by(|a, b| a.name.cmp(&b.name));
    Ok(out)
}

fn walk(dir: &Path, depth: usize, f: &mut dyn FnMut(&Path) -> anyhow::Result<()>) -> anyhow::Result<()> {
    f(dir)?;
    if depth >= 3 {
        return Ok(());
    }
    let mut entries: Vec<PathBuf> = fs::read_dir(dir)
        .with_context(|| format!("cannot read {}", dir.display()))?
        .filter_map(|e| e.ok())
        .filter(|e| e.file_type().map(|t| t.is_dir()).unwrap_or(false))
        .map(|e| e.path())
        .collect();
    entries.sort();
    for e in entries {
        let n = e.file_name().unwrap().to_string_lossy().into_owned();
        if n == "MS" || n == "target" || n.starts_with('.') {
            continue;
        }
        walk(&e, depth + 1, f)?;
    }
    Ok(())
}

/// `OBJS/NAME.BIN` in the object's Makefile (or its `robot/Makefile`).
fn makefile_bin(dir: &Path) -> Option<String> {
    for mk in [dir.join("Makefile"), dir.join("robot/Makefile")] {
        let Ok(text) = fs::read_to_string(mk) else { continue };
        if let Some(i) = text.find("OBJS/") {
            let rest = &text[i + 5..];
            let end = rest.find(|c: char| !(c.is_ascii_alphanumeric() || c == '_' || c == '.')).unwrap_or(rest.len());
            let name = &rest[..end];
            if name.to_ascii_uppercase().ends_with(".BIN") && !name.contains('$') {
                return Some(name.to_string());
            }
        }
    }
    None
}

fn object_cfg_bin(object_cfg: &str, name: &str) -> Option<String> {
    let want = derived_bin(name);
    object_cfg.lines().map(str::trim).filter_map(|l| l.rsplit('/').next()).find(|b| b.eq_ignore_ascii_case(&want)).map(str::to_string)
}

fn derived_bin(name: &str) -> String {
    let stem: String = name.chars().filter(|c| c.is_ascii_alphanumeric()).take(8).collect::<String>().to_ascii_uppercase();
    format!("{stem}.BIN")
}

/// A Cargo.toml that builds a `cdylib` package is a Rust object: its package name and
/// `[package.metadata.openr] bin`, if given. A workspace manifest or an rlib is not.
fn rust_object(path: &Path, text: &str) -> anyhow::Result<Option<(String, Option<String>)>> {
    let doc: toml::Table = crate::ops::config::parse_toml(path, text)?;
    let cdylib =
        doc.get("lib").and_then(|l| l.get("crate-type")).and_then(|t| t.as_array()).is_some_and(|types| types.iter().any(|t| t.as_str() == Some("cdylib")));
    let Some(package) = doc.get("package").filter(|_| cdylib) else { return Ok(None) };
    let name = package.get("name").and_then(|n| n.as_str()).unwrap_or("object").to_string();
    let bin = package.get("metadata").and_then(|m| m.get("openr")).and_then(|o| o.get("bin")).and_then(|b| b.as_str()).map(str::to_string);
    Ok(Some((name, bin)))
}

/// Builds the project; `emit` sees every event as it happens.
pub fn build(opts: &BuildOptions, emit: &mut dyn FnMut(Event)) -> anyhow::Result<BuildReport> {
    let start = Instant::now();
    let dir = std::path::absolute(&opts.dir)?;
    let mut objects = discover(&dir)?;
    if !opts.packages.is_empty() {
        for p in &opts.packages {
            if !objects.iter().any(|o| &o.name == p) {
                let names: Vec<&str> = objects.iter().map(|o| o.name.as_str()).collect();
                bail!("no object `{p}` in {} (objects: {})", dir.display(), names.join(", "));
            }
        }
        objects.retain(|o| opts.packages.contains(&o.name));
    }
    if objects.is_empty() {
        bail!("no objects found in {} (a directory with a stub.cfg, or a cargo cdylib package)", dir.display());
    }
    let objs_dir = dir.join("MS/OPEN-R/MW/OBJS");
    fs::create_dir_all(&objs_dir).with_context(|| format!("cannot create {}", objs_dir.display()))?;
    let mut commands = Vec::new();
    let plans = objects.iter().filter(|o| o.kind == Kind::Cxx).map(|o| cxx::plan(opts, &dir, o, &mut commands)).collect::<anyhow::Result<Vec<_>>>()?;
    compile_db::write(&dir, &commands)?;
    let mut compiled = cxx::build_all(opts, &plans, &objs_dir, emit)?;
    // cargo schedules a Rust object's crates in parallel itself.
    for o in objects.iter().filter(|o| o.kind == Kind::Rust) {
        compiled += build_rust(opts, &dir, o, &objs_dir, emit)? as usize;
    }
    Ok(BuildReport { objects: objects.len(), compiled, elapsed: start.elapsed() })
}

fn mtime(p: &Path) -> Option<SystemTime> {
    fs::metadata(p).and_then(|m| m.modified()).ok()
}

/// True when `out` is missing or older than any of `inputs`.
fn stale(out: &Path, inputs: &[PathBuf]) -> bool {
    let Some(t) = mtime(out) else { return true };
    inputs.iter().any(|i| mtime(i).is_none_or(|m| m > t))
}

/// The files a `-MMD` `.d` file lists.
fn dep_files(d: &Path) -> Option<Vec<PathBuf>> {
    let text = fs::read_to_string(d).ok()?;
    let (_, rest) = text.split_once(':')?;
    let joined = rest.replace("\\\n", " ");
    let first = joined.lines().next().unwrap_or("");
    Some(first.split_whitespace().map(PathBuf::from).collect())
}

/// Installs `from` gzipped as `to`, atomically (as the SDK root's `gzcp` does).
fn gzip(from: &Path, to: &Path) -> anyhow::Result<()> {
    openr_wrappers::gzip_file(from, to).with_context(|| format!("cannot install {}", to.display()))
}

fn build_rust(opts: &BuildOptions, project: &Path, o: &Object, objs_dir: &Path, emit: &mut dyn FnMut(Event)) -> anyhow::Result<bool> {
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let mut cmd = Command::new(cargo);
    cmd.args(["build", "--quiet", "--message-format=json-render-diagnostics", "--manifest-path"]).arg(o.dir.join("Cargo.toml"));
    if opts.release {
        cmd.arg("--release");
    }
    let result = cmd.output().context("cannot run cargo")?;
    let mut so = None;
    let mut compiled = false;
    for line in String::from_utf8_lossy(&result.stdout).lines() {
        let Ok(v) = serde_json::from_str::<serde_json::Value>(line) else { continue };
        if v["reason"] == "compiler-artifact" {
            if v["fresh"] == false {
                compiled = true;
            }
            if let Some(files) = v["filenames"].as_array() {
                if let Some(f) = files.iter().filter_map(|f| f.as_str()).find(|f| f.ends_with(".so")) {
                    so = Some(PathBuf::from(f));
                }
            }
        }
    }
    if compiled {
        emit(Event::Compiling { object: o.name.clone(), kind: Kind::Rust });
    }
    if !result.status.success() {
        emit(Event::Message { object: o.name.clone(), level: "error", rendered: String::from_utf8_lossy(&result.stderr).into_owned() });
        bail!("could not compile `{}` (Rust)", o.name);
    }
    let so = so.with_context(|| format!("cargo built no cdylib for `{}`", o.name))?;
    let installed = objs_dir.join(&o.bin);
    // Which .so the installed .BIN came from: a profile switch (--release) installs the
    // other profile's .so even when it is older than the .BIN.
    let stamp_dir = project.join("target/openr").join(&o.name);
    fs::create_dir_all(&stamp_dir)?;
    let stamp_path = stamp_dir.join("installed-from");
    let stamp = format!("{}\n{:?}\n", so.display(), mtime(&so));
    let fresh = !stale(&installed, std::slice::from_ref(&so)) && fs::read_to_string(&stamp_path).ok().as_deref() == Some(stamp.as_str());
    if !fresh {
        check_rust_symbols(o, &so, emit)?;
        gzip(&so, &installed)?;
        fs::write(&stamp_path, &stamp)?;
    }
    emit(Event::Artifact { object: o.name.clone(), kind: Kind::Rust, bin: installed, fresh: fresh && !compiled });
    Ok(compiled)
}

/// rustc links a cdylib even when an `extern "C"` function is defined nowhere (no
/// `-z defs`, which mkbin gives C++ objects); the system's dynamic loader, asked as
/// `check` asks it, finds such symbols before the `.BIN` is installed.
fn check_rust_symbols(o: &Object, so: &Path, emit: &mut dyn FnMut(Event)) -> anyhow::Result<()> {
    let problems = sdk_runtime::link_check::load_problems(so, so).map_err(|e| anyhow::anyhow!("{e}"))?;
    if problems.is_empty() {
        return Ok(());
    }
    let mut rendered = format!("{}: the cdylib would not load:", so.display());
    for p in &problems {
        rendered.push_str(&format!("\n  {p}"));
    }
    rendered.push_str("\n  hint: an `extern \"C\"` function must be defined by the crate, a library it links (`#[link(name = …)]`, a build script) or the C runtime; check its name");
    emit(Event::Message { object: o.name.clone(), level: "error", rendered });
    bail!("could not link `{}` (Rust)", o.name);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn derived_bin_names_are_8_3_upper_case() {
        assert_eq!(derived_bin("mixed-rust-peer"), "MIXEDRUS.BIN");
        assert_eq!(derived_bin("MyDog"), "MYDOG.BIN");
    }

    #[test]
    fn dep_files_reads_continued_lines() {
        let d = std::env::temp_dir().join(format!("openr-dep-{}.d", std::process::id()));
        fs::write(&d, "a.o: a.cc \\\n  b.h c.h\n").unwrap();
        assert_eq!(dep_files(&d).unwrap(), [PathBuf::from("a.cc"), "b.h".into(), "c.h".into()]);
        let _ = fs::remove_file(d);
    }

    #[test]
    fn a_rust_object_is_a_cdylib_package_read_as_toml() {
        let p = Path::new("Cargo.toml");
        let walk = "[package]\nname = \"rust-walk\" # the object\n[lib]\ncrate-type = [\"cdylib\"]\n[package.metadata.openr]\nbin = \"RWALK.BIN\"\n";
        assert_eq!(rust_object(p, walk).unwrap(), Some(("rust-walk".into(), Some("RWALK.BIN".into()))));
        // "cdylib" in a comment or a dependency's name does not make an object
        let lib = "[package]\nname = \"cdylib-helper\" # not a cdylib\n[lib]\ncrate-type = [\"rlib\"]\n";
        assert_eq!(rust_object(p, lib).unwrap(), None);
        assert_eq!(rust_object(p, "[workspace]\nmembers = [\"a\"]\n").unwrap(), None);
        let e = rust_object(p, "[package]\nname = \"x\"\n[lib\n").unwrap_err().to_string();
        assert!(e.starts_with("Cargo.toml:3: "), "{e}");
    }
}
