//! `mipsel-linux-g++` / `mipsel-linux-gcc`: the host compilers with the flags that let
//! gcc-3.3-era AIBO code build unmodified (object-model 5.5, legacy-code 1).
use std::ffi::OsString;
use std::path::PathBuf;
use std::process::{Command, Stdio};

use crate::error::{Error, ErrorKind};

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Lang {
    Cxx,
    C,
}

/// Flags added in front of the user's. Why each one:
/// * `-std=gnu++98` / `-std=gnu89`: gcc 3.3's dialects. gnu++17 makes `std::byte` clash
///   with OPEN-R's `byte` under `using namespace std`, gnu++11 rejects in-class
///   `static const double` initialisers, C++14 drops `gets`. Only added when the
///   Makefile chose no `-std=` itself.
/// * `-fpermissive`: LP64 `(int)voidptr` casts and other gcc-3.3 leniencies are warnings.
/// * `-fsanitize=unreachable` (C++): a function that flows off its end without a return
///   returns whatever the register holds, as with gcc 3.3 (and as real AIBO code relies
///   on); g++ 8 and later otherwise take the end for unreachable and run into the code
///   that follows. A `__builtin_unreachable()` the program reaches calls libmcoopstub's
///   handler, which faults the object saying where. (With gcc 12 the code stays as
///   fast; from gcc 13 on such a call in a header no longer tells the optimiser what
///   it promises.)
/// * `-fPIC`: every object, archive member included, ends up in a shared object.
/// * `-Dasm(...)=`: MIPS inline assembly (e.g. `asm("mfc0 $2, $12")`) cannot run on the
///   host; glibc and libstdc++ spell theirs `__asm__`, which stays intact.
/// * `-fcommon` (C): gcc 10 made tentative definitions in headers a link error.
/// * `-fsanitize=alignment`: the robot's MIPS CPU faults on a misaligned load or store,
///   x86 does not; the check calls libmcoopstub's handler, which faults the object when
///   the robot would have (`OPENR_ALIGNMENT_TRAP=0`, or `-fno-sanitize=alignment` in the
///   user's flags, turns it off). The compile itself also loads the SDK root's gcc
///   plugin ([`crate::align_plugin`]), which makes the check the robot's and cheap, and
///   leaves out MIPS inline assembly that `-Dasm(...)=` cannot reach (`asm volatile`).
pub(crate) fn host_flags(lang: Lang, user: &[OsString]) -> Vec<&'static str> {
    let has_std = user.iter().any(|a| a.to_string_lossy().starts_with("-std="));
    let mut flags = Vec::new();
    if !has_std {
        flags.push(match lang {
            Lang::Cxx => "-std=gnu++98",
            Lang::C => "-std=gnu89",
        });
    }
    if lang == Lang::Cxx {
        flags.extend(["-fpermissive", "-fsanitize=unreachable"]);
    } else {
        flags.push("-fcommon");
    }
    flags.extend(["-fPIC", "-Dasm(...)="]);
    if crate::align_plugin::trap_wanted() {
        flags.push("-fsanitize=alignment");
    }
    flags
}

/// The flags `mipsel-linux-g++` adds in front of the user's (when the user gives no
/// `-std=`), for IDEs and other build systems (`cargo openr env`).
pub fn cxx_flags() -> Vec<&'static str> {
    host_flags(Lang::Cxx, &[])
}

/// The flags `mipsel-linux-gcc` adds in front of the user's (when the user gives no `-std=`).
pub fn cc_flags() -> Vec<&'static str> {
    host_flags(Lang::C, &[])
}

pub(crate) fn run(lang: Lang, args: Vec<OsString>) -> Result<i32, Error> {
    let (env, default) = match lang {
        Lang::Cxx => ("OPENR_HOST_CXX", "g++"),
        Lang::C => ("OPENR_HOST_CC", "gcc"),
    };
    let exe = host_tool(default, &[env])?;
    // stderr is read so that errors gcc 3.3 did not make get repaired or explained;
    // everything else (stdout, exit status) is the host compiler's own.
    let mut host = host_flags(lang, &args);
    host.extend(crate::sanitize::compile_flags()?);
    if let Some(plugin) = plugin_flag(&exe) {
        // One flag for the life of this short process: leaked so that it joins the
        // static flags the legacy repair reruns the compile with.
        host.push(Box::leak(plugin.into_boxed_str()));
    }
    let mut cmd = Command::new(&exe);
    cmd.args(&host).args(&args).stderr(Stdio::piped());
    let out = cmd.spawn().and_then(|c| c.wait_with_output()).map_err(|e| Error::io(PathBuf::from(cmd.get_program()), e))?;
    let stderr = String::from_utf8_lossy(&out.stderr);
    if !out.status.success() {
        // Only a failed compile pays for the legacy repair (repair/mod.rs).
        if let Some(repaired) = crate::repair::attempt(&exe, &host, &args, &stderr) {
            eprint!("{}", repaired.stderr);
            return Ok(repaired.code);
        }
    }
    eprint!("{stderr}");
    if !out.status.success() {
        let cwd = std::env::current_dir().unwrap_or_default();
        for note in crate::legacy_notes::notes(&stderr, &cwd) {
            eprintln!("{note}");
        }
    }
    Ok(out.status.code().unwrap_or(1))
}

/// `-fplugin=` for the SDK's gcc plugin when this tool's SDK root has one built for
/// `compiler`.
fn plugin_flag(compiler: &std::path::Path) -> Option<String> {
    let root = crate::root::root_from_exe(&std::env::current_exe().ok()?)?;
    crate::align_plugin::flag(&root, compiler)
}

/// Finds a host tool: the first set variable of `env_overrides`, else `name` in PATH.
pub fn host_tool(name: &str, env_overrides: &[&str]) -> Result<PathBuf, Error> {
    for var in env_overrides {
        if let Some(v) = std::env::var_os(var).filter(|v| !v.is_empty()) {
            return which::which(&v).map_err(|_| missing(name, &v.to_string_lossy(), &format!("named by {var}")));
        }
    }
    which::which(name).map_err(|_| missing(name, name, "in PATH"))
}

/// `tool` (what was looked for, `where_`) is missing; the package is the one that
/// provides `name` (the role, e.g. g++, whatever an override called it).
fn missing(name: &str, tool: &str, where_: &str) -> Error {
    let pkg = match name {
        "g++" => "g++",
        "gcc" => "gcc",
        _ => "binutils",
    };
    ErrorKind::MissingHostTool { tool: format!("`{tool}` ({where_})"), hint: format!("install it with `apt-get install {pkg}` (or run `cargo openr doctor`)") }
        .into()
}

/// Replaces this process with `cmd` (a pass-through tool must behave exactly like the
/// host one: same exit status, signals, stdio). Returns only if exec fails.
pub(crate) fn exec(cmd: &mut Command) -> Result<i32, Error> {
    use std::os::unix::process::CommandExt;
    let err = cmd.exec();
    Err(Error::io(PathBuf::from(cmd.get_program()), err))
}
