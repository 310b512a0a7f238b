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
//! stub.cfg or its `.ocf` changed; `compile_commands.json` is written at the project root.
use std::fs;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::{Instant, SystemTime};

use anyhow::{bail, Context};
use serde_json::json;

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
        } else if let Ok(toml) = fs::read_to_string(d.join("Cargo.toml")) {
            if toml.contains("cdylib") {
                let name = toml_value(&toml, "name").unwrap_or_else(|| "object".into());
                let bin = toml_value(&toml, "bin").unwrap_or_else(|| derived_bin(&name));
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

/// `key = "value"` anywhere in a Cargo.toml (first occurrence).
fn toml_value(toml: &str, key: &str) -> Option<String> {
    toml.lines().find_map(|l| {
        let (k, v) = l.split_once('=')?;
        (k.trim() == key).then(|| v.trim().trim_matches('"').to_string())
    })
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
    let mut compiled = 0;
    for o in &objects {
        let did = match o.kind {
            Kind::Cxx => build_cxx(opts, &dir, o, &objs_dir, &mut commands, emit)?,
            Kind::Rust => build_rust(opts, &dir, o, &objs_dir, emit)?,
        };
        compiled += did as usize;
    }
    write_clangd_config(&dir)?;
    let cc = serde_json::to_string_pretty(&commands)?;
    let cc_path = dir.join("compile_commands.json");
    if fs::read_to_string(&cc_path).ok().as_deref() != Some(cc.as_str()) {
        fs::write(&cc_path, cc).with_context(|| format!("cannot write {}", cc_path.display()))?;
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

fn is_network(sources: &[PathBuf], dir: &Path) -> bool {
    let mut files = sources.to_vec();
    if let Ok(rd) = fs::read_dir(dir) {
        files.extend(rd.filter_map(|e| e.ok()).map(|e| e.path()).filter(|p| p.extension().is_some_and(|e| e == "h")));
    }
    files.iter().any(|f| fs::read_to_string(f).is_ok_and(|t| t.contains("<ant.h>") || t.contains("EndpointTypes.h") || t.contains("<MCOOP")))
}

fn build_cxx(
    opts: &BuildOptions,
    project: &Path,
    o: &Object,
    objs_dir: &Path,
    commands: &mut Vec<serde_json::Value>,
    emit: &mut dyn FnMut(Event),
) -> anyhow::Result<bool> {
    let out = project.join("target/openr").join(&o.name);
    fs::create_dir_all(&out).with_context(|| format!("cannot create {}", out.display()))?;
    let root = &opts.sdk;
    let cxx = root.join("bin/mipsel-linux-g++");
    let stub_cfg = o.dir.join("stub.cfg");
    let stub_cc = out.join(format!("{}Stub.cc", o.name));
    let mut sources: Vec<PathBuf> = fs::read_dir(&o.dir)?
        .filter_map(|e| e.ok())
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|e| e == "cc" || e == "cpp" || e == "c"))
        .filter(|p| !is_generated(p))
        .collect();
    sources.sort();
    let ocf = [o.dir.clone(), o.dir.join("robot")]
        .iter()
        .filter_map(|d| fs::read_dir(d).ok())
        .flat_map(|rd| rd.filter_map(|e| e.ok()).map(|e| e.path()))
        .find(|p| p.extension().is_some_and(|e| e == "ocf"))
        .with_context(|| format!("object `{}`: no .ocf in {} or its robot/ directory", o.name, o.dir.display()))?;

    let mut flags: Vec<String> = profile_flags(opts);
    flags.extend(["-I.".into(), format!("-I{}", o.dir.display())]);
    flags.push(format!("-I{}", root.join("OPEN_R/include/R4000").display()));
    flags.push(format!("-I{}", root.join("OPEN_R/include").display()));
    if is_network(&sources, &o.dir) {
        flags.push(format!("-I{}", root.join("OPEN_R/include/MCOOP").display()));
    }

    let mut announced = false;
    let mut announce = |emit: &mut dyn FnMut(Event)| {
        if !announced {
            announced = true;
            emit(Event::Compiling { object: o.name.clone(), kind: Kind::Cxx });
        }
    };

    if stale(&stub_cc, std::slice::from_ref(&stub_cfg)) {
        announce(emit);
        let cfg = stubgen::parse_files(std::slice::from_ref(&stub_cfg)).map_err(|e| anyhow::anyhow!("{e}"))?;
        stubgen::write_outputs(&cfg, &out).map_err(|e| anyhow::anyhow!("{e}"))?;
    }

    let mut all = vec![stub_cc.clone()];
    all.extend(sources.iter().cloned());
    let mut objs = Vec::new();
    for src in &all {
        let stem = src.file_stem().unwrap().to_string_lossy().into_owned();
        let obj = out.join(format!("{stem}.o"));
        let dep = out.join(format!("{stem}.d"));
        let cmd_file = out.join(format!("{stem}.cmd"));
        let mut args: Vec<String> = vec![cxx.display().to_string()];
        args.extend(flags.iter().cloned());
        args.extend(["-o".into(), obj.display().to_string(), "-c".into(), src.display().to_string()]);
        commands.push(json!({ "directory": out, "arguments": host_command(&args, src)?, "file": src, "output": obj }));
        let line = args.join("\u{1f}");
        let inputs: Vec<PathBuf> = dep_files(&dep).unwrap_or_else(|| vec![src.clone()]).iter().map(|p| out.join(p)).collect();
        let up_to_date = !stale(&obj, &inputs) && fs::read_to_string(&cmd_file).ok().as_deref() == Some(line.as_str());
        objs.push(obj.clone());
        if up_to_date {
            continue;
        }
        announce(emit);
        let result = Command::new(&args[0])
            .args(&args[1..])
            .args(opts.color.then_some("-fdiagnostics-color=always"))
            .args(["-MMD", "-MF"])
            .arg(&dep)
            .current_dir(&out)
            .output()
            .with_context(|| format!("cannot run {}", cxx.display()))?;
        let text = String::from_utf8_lossy(&result.stderr).into_owned();
        if !result.status.success() {
            let _ = fs::remove_file(&obj);
            emit(Event::Message { object: o.name.clone(), level: "error", rendered: text });
            bail!("could not compile `{}` (C++): {} failed", o.name, src.display());
        }
        if !text.trim().is_empty() {
            emit(Event::Message { object: o.name.clone(), level: "warning", rendered: text });
        }
        fs::write(&cmd_file, &line)?;
    }

    let target = ocf.file_stem().unwrap().to_string_lossy().into_owned();
    let bin = out.join(format!("{target}.bin"));
    let mut link_inputs = objs.clone();
    link_inputs.push(ocf.clone());
    let installed = objs_dir.join(&o.bin);
    let mut fresh = true;
    // The extra link arguments are an input too: changing them alone relinks.
    let link_stamp = out.join("link.cmd");
    let link_line = opts.ldflags.join("\u{1f}");
    if stale(&bin, &link_inputs) || fs::read_to_string(&link_stamp).ok().as_deref() != Some(link_line.as_str()) {
        announce(emit);
        fresh = false;
        // mkbin adds `-L<root>/OPEN_R/lib` and the OPEN-R archives (default_libs) itself.
        let mk = openr_wrappers::mkbin::Options {
            verbose: false,
            output: Some(bin.clone()),
            prefix: None,
            ocf: Some(ocf.clone()),
            default_libs: true,
            link_args: objs.iter().map(|p| p.clone().into_os_string()).chain(opts.ldflags.iter().map(Into::into)).collect(),
        };
        if let Err(e) = openr_wrappers::mkbin::link(&mk, root) {
            emit(Event::Message { object: o.name.clone(), level: "error", rendered: e.to_string() });
            bail!("could not link `{}` (C++)", o.name);
        }
        fs::write(&link_stamp, &link_line)?;
    }
    if stale(&installed, std::slice::from_ref(&bin)) {
        fresh = false;
        gzip(&bin, &installed)?;
    }
    emit(Event::Artifact { object: o.name.clone(), kind: Kind::Cxx, bin: installed, fresh });
    Ok(announced)
}

const CLANGD_MARKER: &str = "# Written by `cargo openr build`; delete this line to keep your own edits.";

/// Errors that clang makes of what g++ `-fpermissive` (the wrapper's flag) accepts with a
/// warning: without this `.clangd`, clangd marks LP64 `(int)pointer` casts of 2002-era
/// ANT code as errors that the real build never has.
const CLANGD_CONFIG: &str = "Diagnostics:\n  Suppress: [bad_reinterpret_cast_small_int, bad_cxx_cast_generic]\n";

/// Writes the project's `.clangd` unless the user has one of their own.
fn write_clangd_config(project: &Path) -> anyhow::Result<()> {
    let path = project.join(".clangd");
    let text = format!("{CLANGD_MARKER}\n{CLANGD_CONFIG}");
    match fs::read_to_string(&path) {
        Ok(old) if old == text || !old.starts_with(CLANGD_MARKER) => Ok(()),
        Err(e) if e.kind() != std::io::ErrorKind::NotFound => Ok(()),
        _ => fs::write(&path, text).with_context(|| format!("cannot write {}", path.display())),
    }
}

/// Files that `stubgen2` and `mkbin` write into an object's directory when the project is
/// also built with its Makefile: compiling them again would define the stub and the ocf
/// data twice ("multiple definition of `openr_ocf_name`").
fn is_generated(src: &Path) -> bool {
    let name = src.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
    name.ends_with("Stub.cc") || name.ends_with(".snap.cc")
}

/// The profile's flags in front of the include paths: `dev` is cargo's dev (`-O0 -g`: every
/// local visible in gdb), `--release` optimises and keeps debug info; then the user's extra
/// `cxxflags` (from the command line, `OPENR_CXXFLAGS` or `openr.toml`).
fn profile_flags(opts: &BuildOptions) -> Vec<String> {
    let mut flags: Vec<String> = vec![if opts.release { "-O2" } else { "-O0" }.into(), "-g".into()];
    flags.extend(opts.cxxflags.iter().cloned());
    flags
}

/// The compile command as a tool that does not know our wrapper needs it (clangd, IDEs):
/// the host compiler the wrapper runs, with every flag the wrapper adds in front, so that
/// it parses for the host (x86-64) in gcc 3.3's dialect, not for a MIPS target.
fn host_command(args: &[String], src: &Path) -> anyhow::Result<Vec<String>> {
    let c = src.extension().is_some_and(|e| e == "c");
    let (name, env, wrapper_flags) = if c {
        ("gcc", "OPENR_HOST_CC", openr_wrappers::cc_flags())
    } else {
        ("g++", "OPENR_HOST_CXX", openr_wrappers::cxx_flags())
    };
    let host = openr_wrappers::host_tool(name, &[env]).map_err(|e| anyhow::anyhow!("{e}"))?;
    let mut out = vec![host.display().to_string()];
    out.extend(wrapper_flags.iter().map(|f| f.to_string()));
    out.extend(args[1..].iter().cloned());
    Ok(out)
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
}
