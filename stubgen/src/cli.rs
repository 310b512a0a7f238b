//! The `stubgen2` command.

use std::ffi::OsString;
use std::io::Write;
use std::path::{Path, PathBuf};

const USAGE: &str = "usage: stubgen2 <stub.cfg> [<more.cfg> ...]\n\
    Reads the stub.cfg file(s) (concatenated) and writes def.h, entry.h,\n\
    <ObjectName>Stub.h and <ObjectName>Stub.cc into the current directory.\n";

/// Run `stubgen2` with `args` (file arguments only, no program name) in directory `cwd`.
///
/// Relative file arguments are taken relative to `cwd`, and the outputs are written into
/// `cwd`. On success the summary goes to `out`, warnings (if any) to `err`, and the
/// result is 0. On error
/// `stubgen2: <error>` goes to `err`, nothing is written, and the result is 1. Without
/// arguments the usage goes to `err` and the result is 2; `-h`/`--help` as the only
/// argument prints it on `out` and returns 0.
pub fn run_stubgen2(args: &[OsString], cwd: &Path, out: &mut dyn Write, err: &mut dyn Write) -> i32 {
    if args.is_empty() {
        let _ = write!(err, "stubgen2: no stub.cfg given\n{USAGE}");
        return 2;
    }
    if args.len() == 1 && (args[0] == "-h" || args[0] == "--help") {
        let _ = out.write_all(USAGE.as_bytes());
        return 0;
    }
    let files: Vec<(PathBuf, PathBuf)> = args
        .iter()
        .map(|a| {
            let shown = PathBuf::from(a);
            let real = cwd.join(&shown);
            (shown, real)
        })
        .collect();
    let result = crate::parse::parse_named_files(&files).and_then(|cfg| crate::generate::write_outputs(&cfg, cwd).map(|_| cfg));
    match result {
        Ok(cfg) => {
            for w in crate::warn::warnings(&cfg) {
                let _ = writeln!(err, "stubgen2: {w}");
            }
            let _ = out.write_all(crate::generate::summary(&cfg).as_bytes());
            let _ = out.flush();
            0
        }
        Err(e) => {
            let _ = writeln!(err, "stubgen2: {e}");
            1
        }
    }
}
