//! `mkbin`: Sony's argument grammar (object-model 5.4), a host link.
//!
//! Sony linked a MIPS executable with a snapshot header; we link a position-independent
//! shared object that the runtime `dlopen`s:
//! * `-Bsymbolic` so that each object binds its own `Self`, `ObjectEntryTable`, `_Init`…
//!   (every object defines the same names, 5.6);
//! * `--wrap` for the libc calls the runtime must see ([`WRAPPED`]);
//! * the OPEN-R archives of the SDK root (the runtime's C++ surface) as default libraries.
use std::ffi::{OsStr, OsString};
use std::fs;
use std::path::{Path, PathBuf};
use std::process::Command;

use crate::compile::host_tool;
use crate::error::{Error, ErrorKind};
use crate::ocf::{self, Ocf};

/// libc functions redirected to `__wrap_<name>` in `OPEN_R/lib/libmcoopstub.a`: path-taking
/// calls (the `/MS` file system), `strtok` (per-object state), `exit` (stops one object)
/// and the sleeps (virtual time).
pub const WRAPPED: &[&str] = &[
    "open",
    "open64",
    "creat",
    "fopen",
    "fopen64",
    "freopen",
    "stat",
    "lstat",
    "stat64",
    "lstat64",
    "access",
    "opendir",
    "readdir",
    "mkdir",
    "rmdir",
    "unlink",
    "remove",
    "rename",
    "truncate",
    "strtok",
    "exit",
    "usleep",
    "sleep",
    "nanosleep",
];

/// Archives every object links, in this order, after the user's arguments. They play the
/// part of Sony's default libraries plus `-lOPENR -lObjectComm`, which real Makefiles
/// sometimes forget when they use only the API of one of them.
pub const DEFAULT_LIBS: &[&str] = &["OPENR", "ObjectComm", "Internet", "antMCOOP", "ERA201D1", "mcoopstub"];

/// Symbols the runtime looks up in every object's dynamic symbol table.
pub const ENTRY_SYMBOLS: &[&str] = &["ObjectEntryTable", "PrologueEntry"];

/// The parsed command line.
#[derive(Debug, Default, PartialEq, Eq)]
pub struct Options {
    pub verbose: bool,
    pub output: Option<PathBuf>,
    pub prefix: Option<PathBuf>,
    pub ocf: Option<PathBuf>,
    pub default_libs: bool,
    /// Everything else, in order: objects, archives, `-L`, `-l`, linker flags.
    pub link_args: Vec<OsString>,
}

/// Parses mkbin's arguments left to right, exactly as Sony's script did (prefix matching
/// included: `-pthread` is a prefix, not a flag).
pub fn parse_args(args: Vec<OsString>) -> Result<Options, Error> {
    let mut o = Options { default_libs: true, ..Options::default() };
    let mut it = args.into_iter();
    let set_ocf = |o: &mut Options, p: PathBuf| -> Result<(), Error> {
        if o.ocf.replace(p).is_some() {
            return Err(Error::usage(".ocf multiply specified"));
        }
        Ok(())
    };
    while let Some(arg) = it.next() {
        let s = arg.to_string_lossy().into_owned();
        let mut value = |flag: &str| -> Result<PathBuf, Error> {
            match &s[flag.len()..] {
                "" => it.next().map(PathBuf::from).ok_or_else(|| Error::usage(format!("option {flag} needs a value"))),
                rest => Ok(PathBuf::from(rest)),
            }
        };
        match s.as_str() {
            "-v" => o.verbose = true,
            "--nodefaultlib" => o.default_libs = false,
            "--nocrt" | "--vm" | "--novm" => {}
            "--help" => return Err(Error::usage(USAGE)),
            _ if s.starts_with("-m") => {
                let p = value("-m")?;
                set_ocf(&mut o, p)?;
            }
            _ if s.starts_with("-o") => o.output = Some(value("-o")?),
            _ if s.starts_with("-p") => o.prefix = Some(value("-p")?),
            _ if s.ends_with(".ocf") => set_ocf(&mut o, PathBuf::from(&arg))?,
            _ => o.link_args.push(arg),
        }
    }
    Ok(o)
}

const USAGE: &str = "usage: mkbin [-v] [-p SDKROOT] [-o OUTPUT.bin] [-m FILE.ocf] OBJECTS... [FILE.ocf] [-L DIR] [-l LIB]...\n\
  Links OPEN-R object files into a host .bin (a position-independent shared object).\n\
  The ocf defaults to OUTPUT.ocf; --vm, --novm and --nocrt are accepted and ignored.";

pub(crate) fn run(args: Vec<OsString>, own_root: &Path) -> Result<i32, Error> {
    if args.iter().any(|a| a == "--help") {
        eprintln!("{USAGE}");
        return Ok(0);
    }
    let opts = parse_args(args)?;
    link(&opts, own_root)?;
    Ok(0)
}

/// The SDK root whose libraries are linked: `-p` when it is a cargo-openr root, else the
/// root this tool lives in (a Makefile's `-p /usr/local/OPEN_R_SDK` default must not
/// break a build that runs our tools from elsewhere).
fn lib_root(opts: &Options, own_root: &Path) -> PathBuf {
    match &opts.prefix {
        Some(p) if crate::install::is_sdk_root(p) => p.clone(),
        _ => own_root.to_path_buf(),
    }
}

/// Runs the whole link; on success the output exists and has the entry symbols, on
/// failure nothing is left at the output path, nor the `.snap.*` intermediates (on
/// success they stay, as Sony's did).
pub fn link(opts: &Options, own_root: &Path) -> Result<PathBuf, Error> {
    let output = opts.output.clone().unwrap_or_else(|| PathBuf::from("a.bin"));
    let base = output.to_string_lossy().strip_suffix(".bin").map(PathBuf::from).unwrap_or_else(|| output.clone());
    let ocf_path = opts.ocf.clone().unwrap_or_else(|| with_ext(&base, ".ocf"));
    if !ocf_path.exists() {
        return Err(Error::usage(format!("no object configuration: {} does not exist (give FILE.ocf or -m FILE)", ocf_path.display())));
    }
    let ocf = ocf::read(&ocf_path)?;
    let root = lib_root(opts, own_root);
    if opts.verbose {
        eprintln!("mkbin version 1.3 (cargo-openr {})", env!("CARGO_PKG_VERSION"));
        eprintln!("prefix: {}", root.display());
        eprintln!("target: {}", output.display());
        eprintln!("ocf: {}", ocf_path.display());
    }
    let snap_cc = with_ext(&base, ".snap.cc");
    let snap_o = with_ext(&base, ".snap.o");
    let tmp = with_ext(&output, ".partial");
    let linked = fs::write(&snap_cc, snapshot_source(&ocf))
        .map_err(|e| Error::io(&snap_cc, e))
        .and_then(|()| compile_snapshot(&snap_cc, &snap_o, &root, opts.verbose))
        .and_then(|()| link_shared(opts, &root, &snap_o, &tmp, &output))
        .and_then(|()| check_entry_symbols(&tmp));
    if let Err(e) = linked {
        for f in [&tmp, &snap_o, &snap_cc] {
            let _ = fs::remove_file(f);
        }
        return Err(e);
    }
    fs::rename(&tmp, &output).map_err(|e| Error::io(&output, e))?;
    Ok(output)
}

fn compile_snapshot(snap_cc: &Path, snap_o: &Path, root: &Path, verbose: bool) -> Result<(), Error> {
    let cxx = host_tool("g++", &["OPENR_HOST_CXX"])?;
    let mut cc = Command::new(&cxx);
    cc.args(["-fPIC", "-c", "-o"]).arg(snap_o).arg(snap_cc);
    run_cmd(&mut cc, root, verbose)
}

/// The host link of one object into `tmp`.
///
/// Undefined symbols are link errors (`-z defs`), as they were for Sony's mkbin, instead
/// of surfacing only when the runtime `dlopen`s the object. That is exact for this host:
/// an object needs nothing from the runtime executable by name. The OPEN-R archives and
/// Rust objects find the runtime's tables with `dlsym(RTLD_DEFAULT, "openr_runtime_api_v1")`
/// (and `openr_runtime_net_v1`), and the runtime's other export, `fopen64`, interposes a
/// libc function the object links anyway. So every symbol must come from the object, its
/// archives, the OPEN-R archives or the shared C/C++ runtime g++ adds (libstdc++, libm,
/// libc, libgcc_s) and `-ldl`; a user's `-lpthread`, `-lrt`… are on the line too.
fn link_shared(opts: &Options, root: &Path, snap_o: &Path, tmp: &Path, output: &Path) -> Result<(), Error> {
    let cxx = host_tool("g++", &["OPENR_HOST_CXX"])?;
    let mut ld = Command::new(&cxx);
    ld.args(["-shared", "-fPIC", "-Wl,-Bsymbolic", "-Wl,-z,defs", "-Wl,--demangle"]);
    ld.arg(format!("-Wl,--wrap={}", WRAPPED.join(",--wrap=")));
    ld.arg(format!("-L{}", root.join("OPEN_R/lib").display()));
    ld.arg("-o").arg(tmp).arg(snap_o).args(&opts.link_args).args(crate::sanitize::link_flags()?);
    if opts.default_libs {
        ld.arg("-Wl,--start-group");
        ld.args(DEFAULT_LIBS.iter().map(|l| format!("-l{l}")));
        ld.arg("-Wl,--end-group");
    }
    ld.arg("-ldl");
    let (line, out) = run_captured(&mut ld, root, opts.verbose)?;
    let log = String::from_utf8_lossy(&out.stderr).into_owned() + &String::from_utf8_lossy(&out.stdout);
    if out.status.success() {
        // Warnings reach the user as they would have with an inherited stderr.
        use std::io::Write;
        let _ = std::io::stderr().write_all(log.as_bytes());
        return Ok(());
    }
    let undefined = crate::ldlog::undefined_references(&log);
    if undefined.is_empty() {
        return Err(ErrorKind::LinkFailed { command: line, status: out.status.to_string(), log }.into());
    }
    Err(ErrorKind::Undefined { output: output.to_path_buf(), references: undefined, log }.into())
}

/// `<base><ext>` (`foo` + `.ocf`), keeping any directory.
fn with_ext(base: &Path, ext: &str) -> PathBuf {
    let mut s = base.as_os_str().to_owned();
    s.push(ext);
    PathBuf::from(s)
}

/// The host counterpart of gensnap's `*.snap.cc`: the ocf values, readable by the runtime.
fn snapshot_source(ocf: &Ocf) -> String {
    let name: String = ocf.name.chars().filter(|c| c.is_ascii_graphic() && *c != '"' && *c != '\\').collect();
    format!(
        "// Generated by mkbin from the object's ocf (object-model 1.3).\n\
         extern \"C\" {{\n\
         __attribute__((visibility(\"default\"))) extern const char openr_ocf_name[] = \"{name}\";\n\
         __attribute__((visibility(\"default\"))) extern const unsigned long openr_ocf_values[3] = {{ {}UL, {}UL, {}UL }};\n\
         }}\n",
        ocf.stack, ocf.heap, ocf.priority
    )
}

/// Runs a child with mkbin's environment (`LC_ALL=C`, `<root>/bin` first in PATH).
fn run_cmd(cmd: &mut Command, root: &Path, verbose: bool) -> Result<(), Error> {
    let line = prepare(cmd, root, verbose);
    let status = cmd.status().map_err(|e| Error::io(PathBuf::from(cmd.get_program()), e))?;
    if status.success() {
        Ok(())
    } else {
        Err(ErrorKind::CommandFailed { command: line, status: status.to_string() }.into())
    }
}

/// Sets mkbin's environment on `cmd`, shows it when verbose; returns its command line.
fn prepare(cmd: &mut Command, root: &Path, verbose: bool) -> String {
    let path = std::env::var_os("PATH").unwrap_or_default();
    let mut dirs = vec![root.join("bin")];
    dirs.extend(std::env::split_paths(&path));
    cmd.env("LC_ALL", "C").env("PATH", std::env::join_paths(dirs).unwrap_or(path));
    let line = render(cmd);
    if verbose {
        eprintln!("{line}");
    }
    line
}

/// Same as [`run_cmd`], returning the child's output instead of passing it through.
fn run_captured(cmd: &mut Command, root: &Path, verbose: bool) -> Result<(String, std::process::Output), Error> {
    let line = prepare(cmd, root, verbose);
    let out = cmd.output().map_err(|e| Error::io(PathBuf::from(cmd.get_program()), e))?;
    Ok((line, out))
}

fn render(cmd: &Command) -> String {
    std::iter::once(cmd.get_program()).chain(cmd.get_args()).map(OsStr::to_string_lossy).collect::<Vec<_>>().join(" ")
}

/// The runtime dispatches through `ObjectEntryTable` and checks `PrologueEntry` exists;
/// both must survive `strip`, i.e. be in `.dynsym`.
pub fn check_entry_symbols(path: &Path) -> Result<(), Error> {
    let missing = missing_dynamic_symbols(path, ENTRY_SYMBOLS)?;
    match missing.first() {
        None => Ok(()),
        Some(sym) => Err(ErrorKind::BadObject {
            path: path.to_path_buf(),
            message: format!(
                "symbol {sym} not found in the dynamic symbol table: every object needs a stub \
                 (stubgen2 output, or a hand-written stub with GEN_ENTRY(PrologueEntry, Prologue) \
                 and an ObjectEntryTable[])"
            ),
        }
        .into()),
    }
}

/// The names of `wanted` that `path` does not define in its dynamic symbol table.
pub fn missing_dynamic_symbols(path: &Path, wanted: &[&str]) -> Result<Vec<String>, Error> {
    let data = fs::read(path).map_err(|e| Error::io(path, e))?;
    missing_dynamic_symbols_in(path, &data, wanted)
}

/// Same as [`missing_dynamic_symbols`] for an ELF image already in memory (a `.BIN`
/// unzipped); `path` names it in errors.
pub fn missing_dynamic_symbols_in(path: &Path, data: &[u8], wanted: &[&str]) -> Result<Vec<String>, Error> {
    use object::{Object, ObjectSymbol};
    let file = object::File::parse(data).map_err(|e| ErrorKind::BadObject { path: path.to_path_buf(), message: format!("not an ELF shared object: {e}") })?;
    let defined: Vec<String> = file.dynamic_symbols().filter(|s| s.is_definition()).filter_map(|s| s.name().ok().map(str::to_string)).collect();
    Ok(wanted.iter().filter(|w| !defined.iter().any(|d| d == *w)).map(|w| w.to_string()).collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn args(a: &[&str]) -> Vec<OsString> {
        a.iter().map(OsString::from).collect()
    }

    #[test]
    fn sony_grammar() {
        let o = parse_args(args(&["-p", "/sdk", "-o", "x.bin", "XStub.o", "X.o", "libA.a", "x.ocf", "-L/l", "-lObjectComm", "-lOPENR"])).unwrap();
        assert_eq!(o.prefix, Some("/sdk".into()));
        assert_eq!(o.output, Some("x.bin".into()));
        assert_eq!(o.ocf, Some("x.ocf".into()));
        assert_eq!(o.link_args, args(&["XStub.o", "X.o", "libA.a", "-L/l", "-lObjectComm", "-lOPENR"]));
    }

    #[test]
    fn attached_values_and_prefix_matching() {
        let o = parse_args(args(&["-v", "-pthread", "-oout.bin", "-mobj.cfg", "--novm", "--nocrt", "a.o"])).unwrap();
        assert!(o.verbose);
        assert_eq!(o.prefix, Some("thread".into()), "Sony matched -p by prefix");
        assert_eq!(o.output, Some("out.bin".into()));
        assert_eq!(o.ocf, Some("obj.cfg".into()));
        assert_eq!(o.link_args, args(&["a.o"]));
        assert!(!parse_args(args(&["--nodefaultlib"])).unwrap().default_libs);
    }

    #[test]
    fn bad_command_lines() {
        let e = parse_args(args(&["a.ocf", "b.ocf"])).unwrap_err().to_string();
        assert_eq!(e, ".ocf multiply specified");
        let e = parse_args(args(&["-m", "a.ocf", "b.ocf"])).unwrap_err().to_string();
        assert_eq!(e, ".ocf multiply specified");
        let e = parse_args(args(&["a.o", "-o"])).unwrap_err().to_string();
        assert_eq!(e, "option -o needs a value");
    }

    #[test]
    fn every_wrapped_call_has_a_wrapper() {
        let src: String =
            openr_sdk_payload::CXX.iter().filter(|(p, _)| p.starts_with("mcoopstub/")).map(|(_, b)| String::from_utf8_lossy(b).into_owned()).collect();
        for sym in WRAPPED {
            assert!(src.contains(&format!("__wrap_{sym}(")), "no __wrap_{sym} in cxx/mcoopstub");
        }
    }
}
