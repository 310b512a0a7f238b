//! The compiler command line of a repair: which argument is the unit, and the command
//! lines of the preprocessing run, the diagnostic rounds and the final compile.
use std::ffi::OsString;
use std::path::{Path, PathBuf};

/// Options whose value is the next argument.
const TAKES_VALUE: &[&str] = &[
    "-o",
    "-x",
    "-MF",
    "-MT",
    "-MQ",
    "-I",
    "-iquote",
    "-isystem",
    "-idirafter",
    "-include",
    "-imacros",
    "-D",
    "-U",
    "-L",
    "-l",
    "-Xlinker",
    "-Xpreprocessor",
    "-Xassembler",
    "-aux-info",
    "--param",
    "-iprefix",
    "-iwithprefix",
    "-iwithprefixbefore",
    "-isysroot",
    "-imultilib",
    "-T",
    "-u",
    "-z",
    "-e",
    "-A",
    "-MJ",
    "-dumpbase",
    "-dumpdir",
];

const SOURCE_EXT: &[&str] = &["cc", "cpp", "cxx", "c++", "C", "cp", "CPP", "c"];

/// Dependency-output options (dropped from the runs whose output is thrown away).
fn is_dep_option(a: &str) -> bool {
    matches!(a, "-MD" | "-MMD" | "-MP" | "-MG" | "-M" | "-MM") || a.starts_with("-Wp,-M")
}

/// The one compiled unit of `args`: its index, when the command compiles (`-c`/`-S`)
/// exactly one source file.
pub(crate) fn unit(args: &[OsString]) -> Option<usize> {
    let mut found = None;
    let mut compiles = false;
    let mut i = 0;
    while i < args.len() {
        let a = args[i].to_string_lossy();
        if a == "-c" || a == "-S" {
            compiles = true;
        } else if a == "-E" || a == "-" || a == "-save-temps" || a.starts_with("-fdump-") {
            return None;
        } else if TAKES_VALUE.contains(&&*a) {
            i += 1;
        } else if !a.starts_with('-') && Path::new(&*a).extension().is_some_and(|e| SOURCE_EXT.iter().any(|s| e == *s)) {
            if found.is_some() {
                return None;
            }
            found = Some(i);
        }
        i += 1;
    }
    found.filter(|_| compiles)
}

/// `args` without output and dependency options, the unit replaced by `unit`.
fn without_outputs(args: &[OsString], unit_index: usize, unit: &Path) -> Vec<OsString> {
    let mut out = Vec::new();
    let mut i = 0;
    while i < args.len() {
        let a = args[i].to_string_lossy();
        if matches!(&*a, "-o" | "-MF" | "-MT" | "-MQ") {
            i += 2;
            continue;
        }
        let joined = ["-o", "-MF", "-MT", "-MQ"].iter().any(|p| a.len() > p.len() && a.starts_with(p));
        if joined || is_dep_option(&a) {
            i += 1;
            continue;
        }
        if TAKES_VALUE.contains(&&*a) && i + 1 < args.len() {
            out.extend([args[i].clone(), args[i + 1].clone()]);
            i += 2;
            continue;
        }
        out.push(if i == unit_index { unit.as_os_str().to_owned() } else { args[i].clone() });
        i += 1;
    }
    out
}

/// The preprocessing run that gives the include tree: the user's unit, output to `out`.
pub(crate) fn preprocess(args: &[OsString], unit_index: usize, out: &Path) -> Vec<OsString> {
    let unit = PathBuf::from(&args[unit_index]);
    let mut v = without_outputs(args, unit_index, &unit);
    v.extend(["-E".into(), "-o".into(), out.as_os_str().to_owned()]);
    v
}

/// A diagnostic round on the shadow unit: syntax only, machine-readable diagnostics.
pub(crate) fn round(args: &[OsString], unit_index: usize, shadow_unit: &Path) -> Vec<OsString> {
    let mut v = quote_dir(args, unit_index);
    // `-w` (or the warning's own -Wno-) would hide where `template` is missing (rules.rs).
    v.extend(without_outputs(args, unit_index, shadow_unit).into_iter().filter(|a| a != "-w" && a != "-Wno-missing-template-keyword"));
    v.extend(
        [
            "-fsyntax-only",
            "-fdiagnostics-format=text",
            "-fdiagnostics-parseable-fixits",
            "-fdiagnostics-column-unit=byte",
            "-fdiagnostics-column-origin=1",
            "-fno-diagnostics-show-caret",
            "-fdiagnostics-color=never",
            "-fmax-errors=0",
        ]
        .map(OsString::from),
    );
    v
}

/// The real compile of the shadow unit: the user's command line, with the unit's own
/// directory first for its quoted includes (as for the original) and the shadow
/// directory mapped to the unit's in debug info.
pub(crate) fn final_compile(args: &[OsString], unit_index: usize, shadow_unit: &Path) -> Vec<OsString> {
    let orig_dir = unit_dir(args, unit_index);
    let shadow_dir = shadow_unit.parent().expect("the shadow unit is in a directory");
    let map = if orig_dir.as_os_str().is_empty() {
        format!("-ffile-prefix-map={}/=", shadow_dir.display())
    } else {
        format!("-ffile-prefix-map={}={}", shadow_dir.display(), orig_dir.display())
    };
    let mut v = quote_dir(args, unit_index);
    v.push(map.into());
    v.extend(args.iter().enumerate().map(|(i, a)| if i == unit_index { shadow_unit.as_os_str().to_owned() } else { a.clone() }));
    v
}

fn unit_dir(args: &[OsString], unit_index: usize) -> PathBuf {
    Path::new(&args[unit_index]).parent().map(Path::to_path_buf).unwrap_or_default()
}

/// `-iquote <the unit's directory>`: the shadow unit's quoted includes that do not name
/// a shadow are looked up where the original's were.
fn quote_dir(args: &[OsString], unit_index: usize) -> Vec<OsString> {
    let dir = unit_dir(args, unit_index);
    let dir = if dir.as_os_str().is_empty() { PathBuf::from(".") } else { dir };
    vec!["-iquote".into(), dir.into()]
}

/// The dependency file the compile writes (`-MD`/`-MMD`), if any.
pub(crate) fn depfile(args: &[OsString], unit_index: usize) -> Option<PathBuf> {
    let s: Vec<String> = args.iter().map(|a| a.to_string_lossy().into_owned()).collect();
    if !s.iter().any(|a| a == "-MD" || a == "-MMD") {
        return None;
    }
    if let Some(i) = s.iter().position(|a| a == "-MF") {
        return s.get(i + 1).map(PathBuf::from);
    }
    if let Some(f) = s.iter().find_map(|a| a.strip_prefix("-MF").filter(|f| !f.is_empty())) {
        return Some(PathBuf::from(f));
    }
    let base = match s.iter().position(|a| a == "-o") {
        Some(i) => PathBuf::from(s.get(i + 1)?),
        None => PathBuf::from(Path::new(&s[unit_index]).file_name()?),
    };
    Some(base.with_extension("d"))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn v(s: &str) -> Vec<OsString> {
        s.split_whitespace().map(OsString::from).collect()
    }

    #[test]
    fn finds_the_one_unit_of_a_compile() {
        assert_eq!(unit(&v("-O2 -I. -o Legacy.o -c Legacy.cc")), Some(5));
        assert_eq!(unit(&v("-x c++ -c -o a.o a.cc -MF a.cc.d")), Some(5));
        assert_eq!(unit(&v("-o a.bin a.cc b.cc -c")), None, "two units");
        assert_eq!(unit(&v("-o a a.cc")), None, "a link");
        assert_eq!(unit(&v("-E a.cc")), None);
    }

    #[test]
    fn rounds_drop_outputs_and_dependencies() {
        let args = v("-O2 -MMD -MF x.d -Wp,-MD,y.d -o sub/a.o -c sub/a.cc -I inc");
        let r = round(&args, 8, Path::new("/S/u/a.cc"));
        let r: Vec<String> = r.iter().map(|a| a.to_string_lossy().into_owned()).collect();
        assert_eq!(&r[..7], ["-iquote", "sub", "-O2", "-c", "/S/u/a.cc", "-I", "inc"]);
        assert!(r.contains(&"-fsyntax-only".to_string()));
        let f = final_compile(&args, 8, Path::new("/S/u/a.cc"));
        let f: Vec<String> = f.iter().map(|a| a.to_string_lossy().into_owned()).collect();
        assert_eq!(&f[..3], ["-iquote", "sub", "-ffile-prefix-map=/S/u=sub"]);
        assert_eq!(f[11], "/S/u/a.cc");
        assert_eq!(depfile(&args, 8), Some(PathBuf::from("x.d")));
        assert_eq!(depfile(&v("-MMD -o b/a.o -c a.cc"), 4), Some(PathBuf::from("b/a.d")));
        assert_eq!(depfile(&v("-MD -c a.cc"), 2), Some(PathBuf::from("a.d")));
    }
}
