//! Sanitizers: `cargo openr build --sanitize KIND` instruments the objects, and `cargo
//! openr run` starts a stick with such objects correctly by itself. AddressSanitizer and
//! ThreadSanitizer must be the first library of the process, before the runtime's own
//! allocations: when an object of the stick needs `libasan`/`libtsan`, `run` re-executes
//! itself with that library in `LD_PRELOAD` and options that work with the runtime.
use std::ffi::OsString;
use std::io::Read;
use std::path::{Path, PathBuf};
use std::process::Command;

use anyhow::Context;

/// `--sanitize`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Sanitizer {
    Address,
    Undefined,
    Thread,
}

impl Sanitizer {
    pub fn name(self) -> &'static str {
        match self {
            Sanitizer::Address => "address",
            Sanitizer::Undefined => "undefined",
            Sanitizer::Thread => "thread",
        }
    }

    /// Compiler flags: the instrumentation, frames for readable stacks.
    pub fn cxxflags(self) -> Vec<String> {
        vec![format!("-fsanitize={}", self.name()), "-fno-omit-frame-pointer".into()]
    }

    /// Link arguments: g++ adds the sanitizer's shared runtime as a NEEDED library.
    pub fn ldflags(self) -> Vec<String> {
        vec![format!("-fsanitize={}", self.name())]
    }

    /// The runtime library an instrumented object needs, and the options variable.
    fn runtime(self) -> (&'static str, &'static str) {
        match self {
            Sanitizer::Address => ("libasan.so", "ASAN_OPTIONS"),
            Sanitizer::Undefined => ("libubsan.so", "UBSAN_OPTIONS"),
            Sanitizer::Thread => ("libtsan.so", "TSAN_OPTIONS"),
        }
    }

    /// Options the runtime needs, used where the user set none:
    /// * the runtime's own crash reporter stays in charge of SIGSEGV/SIGBUS
    ///   (`allow_user_segv_handler`), ASan's report still comes first for what it detects;
    /// * leaks are off by default: the runtime keeps process-lifetime tables on purpose,
    ///   set `ASAN_OPTIONS=detect_leaks=1` to look at an object's leaks;
    /// * UBSan prints the stack of its report and stops the run there (a non-zero exit,
    ///   as a fault on the robot); `UBSAN_OPTIONS=halt_on_error=0` reports and goes on.
    fn default_options(self) -> &'static str {
        match self {
            Sanitizer::Address => "allow_user_segv_handler=1:detect_leaks=0:abort_on_error=0",
            Sanitizer::Undefined => "print_stacktrace=1:halt_on_error=1",
            Sanitizer::Thread => "report_signal_unsafe=0",
        }
    }

    const ALL: [Sanitizer; 3] = [Sanitizer::Address, Sanitizer::Undefined, Sanitizer::Thread];
}

/// The `.BIN` files under `ms` (any case), sorted.
fn bins(ms: &Path, out: &mut Vec<PathBuf>) {
    let Ok(rd) = std::fs::read_dir(ms) else { return };
    let mut entries: Vec<PathBuf> = rd.flatten().map(|e| e.path()).collect();
    entries.sort();
    for p in entries {
        if p.is_dir() {
            bins(&p, out);
        } else if p.extension().is_some_and(|e| e.eq_ignore_ascii_case("bin")) {
            out.push(p);
        }
    }
}

/// The sanitizers whose runtime library an object of `bin` (gzipped ELF) needs, from the
/// names in its `.dynstr` (where DT_NEEDED names live).
fn needed_by(bin: &Path) -> Vec<Sanitizer> {
    use object::{Object, ObjectSection};
    let Ok(f) = std::fs::File::open(bin) else { return vec![] };
    let mut data = Vec::new();
    if flate2::read::GzDecoder::new(f).read_to_end(&mut data).is_err() {
        return vec![];
    }
    let Ok(elf) = object::File::parse(&*data) else { return vec![] };
    let Some(dynstr) = elf.section_by_name(".dynstr").and_then(|s| s.data().ok()) else { return vec![] };
    let names: Vec<&[u8]> = dynstr.split(|b| *b == 0).collect();
    Sanitizer::ALL.into_iter().filter(|s| names.iter().any(|n| n.starts_with(s.runtime().0.as_bytes()))).collect()
}

/// What a stick's objects need.
pub fn needed(ms: &Path) -> Vec<Sanitizer> {
    let mut files = Vec::new();
    bins(&ms.join("OPEN-R"), &mut files);
    let mut out: Vec<Sanitizer> = Vec::new();
    for f in files {
        for s in needed_by(&f) {
            if !out.contains(&s) {
                out.push(s);
            }
        }
    }
    out
}

/// The host compiler's copy of `lib` (`g++ -print-file-name=libasan.so`).
fn library_path(lib: &str) -> anyhow::Result<PathBuf> {
    let gxx = openr_wrappers::host_tool("g++", &["OPENR_HOST_CXX"]).map_err(|e| anyhow::anyhow!("{e}"))?;
    let out = Command::new(&gxx).arg(format!("-print-file-name={lib}")).output().with_context(|| format!("cannot run {}", gxx.display()))?;
    let path = PathBuf::from(String::from_utf8_lossy(&out.stdout).trim());
    if !path.is_absolute() || !path.exists() {
        anyhow::bail!(
            "the objects were built with a sanitizer but {} has no {lib}: install the compiler's sanitizer runtime (e.g. `apt-get install {}`)",
            gxx.display(),
            package(lib)
        );
    }
    Ok(std::fs::canonicalize(&path).unwrap_or(path))
}

fn package(lib: &str) -> &'static str {
    match lib {
        "libasan.so" => "libasan8",
        "libtsan.so" => "libtsan2",
        _ => "libubsan1",
    }
}

/// The environment to run a stick needing `sanitizers` with, or `None` when this process
/// already has it. `preload` is the current `LD_PRELOAD`.
pub fn environment(sanitizers: &[Sanitizer], preload: Option<&str>) -> anyhow::Result<Option<Vec<(String, OsString)>>> {
    if sanitizers.contains(&Sanitizer::Address) && sanitizers.contains(&Sanitizer::Thread) {
        anyhow::bail!("the stick mixes objects built with --sanitize address and --sanitize thread: one process cannot load both; rebuild them with one");
    }
    let mut env = Vec::new();
    let mut libs: Vec<String> = preload.unwrap_or("").split([':', ' ']).filter(|s| !s.is_empty()).map(str::to_string).collect();
    let mut changed = false;
    for s in sanitizers {
        let (lib, var) = s.runtime();
        if std::env::var_os(var).is_none() {
            env.push((var.to_string(), s.default_options().into()));
        }
        // ASan's and TSan's runtimes must come first; UBSan's is preloaded too, so that it
        // reads its options from the initial environment and is known to the runtime as a
        // tool (its file accesses are not an object's) before any object loads.
        if !libs.iter().any(|l| Path::new(l).file_name().is_some_and(|n| n.to_string_lossy().starts_with(lib))) {
            libs.insert(0, library_path(lib)?.display().to_string());
            changed = true;
        }
    }
    if !changed {
        return Ok(None);
    }
    env.push(("LD_PRELOAD".into(), libs.join(":").into()));
    Ok(Some(env))
}

/// Re-executes this process (same arguments) with `env` added. Returns only on failure.
pub fn reexec(env: Vec<(String, OsString)>) -> anyhow::Error {
    use std::os::unix::process::CommandExt;
    let exe = match std::env::current_exe() {
        Ok(e) => e,
        Err(e) => return anyhow::anyhow!("cannot find this executable to restart it with a sanitizer: {e}"),
    };
    let mut args = std::env::args_os();
    let argv0 = args.next().unwrap_or_else(|| exe.clone().into());
    let err = Command::new(&exe).arg0(argv0).args(args).envs(env).exec();
    anyhow::anyhow!("cannot restart {} with the sanitizer preloaded: {err}", exe.display())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nothing_to_do_when_the_library_is_preloaded_already() {
        assert!(environment(&[], None).unwrap().is_none());
        let preloaded = "/usr/lib/x86_64-linux-gnu/libasan.so.8";
        assert!(environment(&[Sanitizer::Address], Some(preloaded)).unwrap().is_none());
        let env = environment(&[Sanitizer::Undefined], None).unwrap().unwrap();
        assert!(env.iter().any(|(k, v)| k == "LD_PRELOAD" && v.to_string_lossy().contains("libubsan.so")), "{env:?}");
    }

    #[test]
    fn address_and_thread_cannot_share_a_process() {
        let e = environment(&[Sanitizer::Address, Sanitizer::Thread], None).unwrap_err().to_string();
        assert!(e.contains("one process cannot load both"), "{e}");
    }

    #[test]
    fn flags_name_the_sanitizer() {
        assert_eq!(Sanitizer::Address.cxxflags(), ["-fsanitize=address", "-fno-omit-frame-pointer"]);
        assert_eq!(Sanitizer::Undefined.ldflags(), ["-fsanitize=undefined"]);
    }
}
