//! `rp-openr-config --cflags | --libs` (remote-processing 2.3, 7.1.2).
use std::path::Path;

use crate::error::Error;

const USAGE: &str = "usage: rp-openr-config [--cflags] [--libs] [--prefix] [--version]";

/// The compiler flags: the dialect flags `mipsel-linux-g++` adds (the host Makefile calls
/// plain `g++`), and the OPEN-R include directories.
pub fn cflags(root: &Path) -> Vec<String> {
    let inc = root.join("OPEN_R/include");
    let mut v: Vec<String> = crate::compile::cxx_flags().iter().map(|s| s.to_string()).collect();
    v.push("-DOPENR_RP_HOST".into());
    for d in [inc.join("R4000"), inc.join("MCOOP"), inc.clone()] {
        v.push(format!("-I{}", d.display()));
    }
    v
}

/// The link flags: what turns `g++ -o x.bin XStub.o X.o` into mkbin's link (a shared
/// object with `-Bsymbolic`, the libc wrappers and the OPEN-R archives).
pub fn libs(root: &Path) -> Vec<String> {
    let mut v: Vec<String> = ["-shared", "-fPIC", "-Wl,-Bsymbolic", "-Wl,-z,defs"].iter().map(|s| s.to_string()).collect();
    v.push(format!("-Wl,--wrap={}", crate::mkbin::WRAPPED.join(",--wrap=")));
    v.push(format!("-L{}", root.join("OPEN_R/lib").display()));
    v.push("-Wl,--start-group".into());
    v.extend(crate::mkbin::DEFAULT_LIBS.iter().map(|l| format!("-l{l}")));
    v.push("-Wl,--end-group".into());
    v.extend(["-ldl".to_string(), "-lpthread".to_string()]);
    v
}

/// Prints the requested flags on one line, in the order asked, like pkg-config.
pub(crate) fn run(args: &[std::ffi::OsString], root: &Path) -> Result<i32, Error> {
    if args.is_empty() {
        return Err(Error::usage(format!("no option given\n{USAGE}")));
    }
    let mut out: Vec<String> = Vec::new();
    for a in args {
        match a.to_str().unwrap_or("") {
            "--cflags" => out.extend(cflags(root)),
            "--libs" => out.extend(libs(root)),
            "--prefix" => out.push(root.join("RP_OPEN_R").display().to_string()),
            "--version" => out.push(format!("1.1.5 (cargo-openr {})", env!("CARGO_PKG_VERSION"))),
            "-h" | "--help" => {
                println!("{USAGE}");
                return Ok(0);
            }
            other => return Err(Error::usage(format!("unknown option {other}\n{USAGE}"))),
        }
    }
    println!("{}", out.join(" "));
    Ok(0)
}
