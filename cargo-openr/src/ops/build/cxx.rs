//! C++ objects: plan each object (stub, the units whose inputs or command changed), run
//! every object's stale units on one pool of `-j` workers, then link the objects on the
//! same pool. Events are emitted in object order whatever order the work finished in, so
//! the output is stable from run to run.
use std::fs;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::Mutex;

use anyhow::{bail, Context};
use serde_json::json;

use super::compile_db::host_command;
use super::{dep_files, gzip, stale, BuildOptions, Event, Kind, Object};

/// One translation unit to compile.
struct Unit {
    src: PathBuf,
    obj: PathBuf,
    dep: PathBuf,
    cmd_file: PathBuf,
    args: Vec<String>,
    /// The command line as recorded in `cmd_file` (a change recompiles).
    line: String,
}

/// What one object needs.
pub(super) struct Plan<'a> {
    object: &'a Object,
    out: PathBuf,
    ocf: PathBuf,
    /// Every unit's `.o`, in link order (the stub first).
    objs: Vec<PathBuf>,
    /// The units that must be compiled.
    stale_units: Vec<Unit>,
    /// Any compiler or linker work at all (the stub, a unit, the link).
    pub work: bool,
    /// What stubgen2 warned about when it regenerated the stub (a SubName used twice …).
    stub_warnings: Vec<String>,
}

fn is_network(sources: &[PathBuf], dir: &Path) -> bool {
    let mut files = sources.to_vec();
    if let Ok(rd) = fs::read_dir(dir) {
        files.extend(rd.filter_map(|e| e.ok()).map(|e| e.path()).filter(|p| p.extension().is_some_and(|e| e == "h")));
    }
    files.iter().any(|f| fs::read_to_string(f).is_ok_and(|t| t.contains("<ant.h>") || t.contains("EndpointTypes.h") || t.contains("<MCOOP")))
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

fn link_stamp(out: &Path) -> PathBuf {
    out.join("link.cmd")
}

fn link_line(opts: &BuildOptions) -> String {
    opts.ldflags.join("\u{1f}")
}

/// Generates the stub when `stub.cfg` changed and finds the units to compile; every unit's
/// command goes into `commands` (the compile database).
pub(super) fn plan<'a>(opts: &BuildOptions, project: &Path, o: &'a Object, commands: &mut Vec<serde_json::Value>) -> anyhow::Result<Plan<'a>> {
    let out = project.join("target/openr").join(&o.name);
    fs::create_dir_all(&out).with_context(|| format!("cannot create {}", out.display()))?;
    let root = &opts.sdk;
    // C units go through the C compiler, as a Makefile's `%.o: %.c` rule with $(CC) does:
    // compiled as C++ their functions would get C++ linkage and not link with C callers.
    let (cxx, cc) = (root.join("bin/mipsel-linux-g++"), root.join("bin/mipsel-linux-gcc"));
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

    let mut work = false;
    let mut stub_warnings = Vec::new();
    if stale(&stub_cc, std::slice::from_ref(&stub_cfg)) {
        work = true;
        let cfg = stubgen::parse_files(std::slice::from_ref(&stub_cfg)).map_err(|e| anyhow::anyhow!("{e}"))?;
        stubgen::write_outputs(&cfg, &out).map_err(|e| anyhow::anyhow!("{e}"))?;
        stub_warnings = stubgen::warnings(&cfg).iter().map(|w| format!("stubgen2: {w}\n")).collect();
    }

    let mut all = vec![stub_cc];
    all.extend(sources);
    let (mut objs, mut stale_units) = (Vec::new(), Vec::new());
    for src in all {
        let stem = src.file_stem().unwrap().to_string_lossy().into_owned();
        let obj = out.join(format!("{stem}.o"));
        let dep = out.join(format!("{stem}.d"));
        let cmd_file = out.join(format!("{stem}.cmd"));
        let compiler = if src.extension().is_some_and(|e| e == "c") { &cc } else { &cxx };
        let mut args: Vec<String> = vec![compiler.display().to_string()];
        args.extend(flags.iter().cloned());
        args.extend(["-o".into(), obj.display().to_string(), "-c".into(), src.display().to_string()]);
        commands.push(json!({ "directory": out, "arguments": host_command(&args, &src)?, "file": src, "output": obj }));
        let line = args.join("\u{1f}");
        let inputs: Vec<PathBuf> = dep_files(&dep).unwrap_or_else(|| vec![src.clone()]).iter().map(|p| out.join(p)).collect();
        let up_to_date = !stale(&obj, &inputs) && fs::read_to_string(&cmd_file).ok().as_deref() == Some(line.as_str());
        objs.push(obj.clone());
        if !up_to_date {
            stale_units.push(Unit { src, obj, dep, cmd_file, args, line });
        }
    }
    let bin = out.join(format!("{}.bin", ocf.file_stem().unwrap().to_string_lossy()));
    let mut link_inputs = objs.clone();
    link_inputs.push(ocf.clone());
    work |= !stale_units.is_empty() || stale(&bin, &link_inputs) || fs::read_to_string(link_stamp(&out)).ok().as_deref() != Some(link_line(opts).as_str());
    Ok(Plan { object: o, out, ocf, objs, stale_units, work, stub_warnings })
}

/// Runs `task(i)` for i in 0..n on up to `jobs` threads; returns the results in index order.
/// After a task reports failure (`Err`), tasks not yet started are skipped (`None`).
fn pool<T: Send, E: Send>(n: usize, jobs: usize, task: &(dyn Fn(usize) -> Result<T, E> + Sync)) -> Vec<Option<Result<T, E>>> {
    let next = AtomicUsize::new(0);
    let failed = AtomicBool::new(false);
    let results: Mutex<Vec<Option<Result<T, E>>>> = Mutex::new((0..n).map(|_| None).collect());
    std::thread::scope(|s| {
        for _ in 0..jobs.clamp(1, n.max(1)) {
            s.spawn(|| loop {
                let i = next.fetch_add(1, Ordering::SeqCst);
                if i >= n || failed.load(Ordering::SeqCst) {
                    break;
                }
                let r = task(i);
                if r.is_err() {
                    failed.store(true, Ordering::SeqCst);
                }
                results.lock().unwrap()[i] = Some(r);
            });
        }
    });
    results.into_inner().unwrap()
}

/// A unit's compiler output (stderr): `Ok` when it compiled.
fn compile(opts: &BuildOptions, out: &Path, u: &Unit) -> Result<String, String> {
    let result = Command::new(&u.args[0])
        .args(&u.args[1..])
        .args(opts.color.then_some("-fdiagnostics-color=always"))
        .args(["-MMD", "-MF"])
        .arg(&u.dep)
        .current_dir(out)
        .output();
    let result = match result {
        Ok(r) => r,
        Err(e) => return Err(format!("cannot run {}: {e}\n", u.args[0])),
    };
    let text = String::from_utf8_lossy(&result.stderr).into_owned();
    if !result.status.success() {
        let _ = fs::remove_file(&u.obj);
        return Err(text);
    }
    fs::write(&u.cmd_file, &u.line).map_err(|e| format!("cannot write {}: {e}\n", u.cmd_file.display()))?;
    Ok(text)
}

/// Links one object into its `.bin` when needed and installs it gzipped; `Err` is the
/// linker's message.
fn link(opts: &BuildOptions, p: &Plan, objs_dir: &Path) -> Result<(bool, PathBuf), String> {
    let bin = p.out.join(format!("{}.bin", p.ocf.file_stem().unwrap().to_string_lossy()));
    let mut link_inputs = p.objs.clone();
    link_inputs.push(p.ocf.clone());
    let installed = objs_dir.join(&p.object.bin);
    let mut fresh = true;
    // The extra link arguments are an input too: changing them alone relinks.
    let (stamp, line) = (link_stamp(&p.out), link_line(opts));
    if stale(&bin, &link_inputs) || fs::read_to_string(&stamp).ok().as_deref() != Some(line.as_str()) {
        fresh = false;
        // mkbin adds `-L<root>/OPEN_R/lib` and the OPEN-R archives (default_libs) itself.
        let mk = openr_wrappers::mkbin::Options {
            verbose: opts.verbose,
            output: Some(bin.clone()),
            prefix: None,
            ocf: Some(p.ocf.clone()),
            default_libs: true,
            link_args: p.objs.iter().map(|o| o.clone().into_os_string()).chain(opts.ldflags.iter().map(Into::into)).collect(),
        };
        openr_wrappers::mkbin::link(&mk, &opts.sdk).map_err(|e| e.to_string())?;
        fs::write(&stamp, &line).map_err(|e| format!("cannot write {}: {e}", stamp.display()))?;
    }
    if stale(&installed, std::slice::from_ref(&bin)) {
        fresh = false;
        gzip(&bin, &installed).map_err(|e| format!("{e:#}"))?;
    }
    Ok((fresh, installed))
}

/// Compiles and links every planned object with up to `opts.jobs` processes at once.
/// Returns how many objects did compiler work.
pub(super) fn build_all(opts: &BuildOptions, plans: &[Plan], objs_dir: &Path, emit: &mut dyn FnMut(Event)) -> anyhow::Result<usize> {
    for p in plans.iter().filter(|p| p.work) {
        emit(Event::Compiling { object: p.object.name.clone(), kind: Kind::Cxx });
        for w in &p.stub_warnings {
            emit(Event::Message { object: p.object.name.clone(), level: "warning", rendered: w.clone() });
        }
    }
    let units: Vec<(&Plan, &Unit)> = plans.iter().flat_map(|p| p.stale_units.iter().map(move |u| (p, u))).collect();
    if opts.verbose {
        for (p, u) in &units {
            emit(Event::Running { object: p.object.name.clone(), command: u.args.join(" ") });
        }
    }
    let results = pool(units.len(), opts.jobs, &|i| compile(opts, &units[i].0.out, units[i].1));
    let mut first_failure = None;
    for ((p, u), r) in units.iter().zip(results) {
        let name = p.object.name.clone();
        match r {
            Some(Ok(text)) if !text.trim().is_empty() => emit(Event::Message { object: name, level: "warning", rendered: text }),
            Some(Err(text)) => {
                emit(Event::Message { object: name, level: "error", rendered: text });
                first_failure.get_or_insert_with(|| format!("could not compile `{}` (C++): {} failed", p.object.name, u.src.display()));
            }
            _ => {}
        }
    }
    if let Some(msg) = first_failure {
        bail!(msg);
    }
    let linked = pool(plans.len(), opts.jobs, &|i| link(opts, &plans[i], objs_dir));
    let mut first_failure = None;
    for (p, r) in plans.iter().zip(linked) {
        match r {
            Some(Ok((fresh, bin))) => emit(Event::Artifact { object: p.object.name.clone(), kind: Kind::Cxx, bin, fresh }),
            Some(Err(text)) => {
                emit(Event::Message { object: p.object.name.clone(), level: "error", rendered: text });
                first_failure.get_or_insert_with(|| format!("could not link `{}` (C++)", p.object.name));
            }
            None => {}
        }
    }
    if let Some(msg) = first_failure {
        bail!(msg);
    }
    Ok(plans.iter().filter(|p| p.work).count())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_pool_keeps_index_order_and_stops_scheduling_after_a_failure() {
        // One worker: exactly the tasks up to the failure ran.
        let r = pool(50, 1, &|i| if i % 7 == 3 { Err(i) } else { Ok(i * 2) });
        assert_eq!(&r[..4], &[Some(Ok(0)), Some(Ok(2)), Some(Ok(4)), Some(Err(3))]);
        assert!(r[4..].iter().all(Option::is_none));
        // Several workers: every result lands at its own index.
        let r = pool(40, 4, &|i| Ok::<usize, usize>(i * 3));
        assert_eq!(r, (0..40).map(|i| Some(Ok(i * 3))).collect::<Vec<_>>());
        assert!(pool(0, 4, &|i| Ok::<usize, usize>(i)).is_empty());
    }
}
