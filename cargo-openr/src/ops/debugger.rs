//! `cargo openr run --gdb` / `--valgrind[=TOOL]`: the run re-executes itself under the
//! tool, set up for the runtime — gdb with pending breakpoints and the pause signal
//! passed through (the SDK root's `share/gdb/cargo-openr.gdb`), valgrind with the
//! runtime's suppressions (`share/valgrind/cargo-openr.supp`) so that what it reports
//! is the objects', and memcheck's full leak check with a failing exit status on errors.
use std::ffi::OsString;
use std::path::Path;
use std::process::Command;

use anyhow::Context;
use openr_wrappers::install;

/// Which tool, with what extra arguments of the user's.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Debugger {
    Gdb,
    Valgrind(String),
}

/// The command that runs this process's command line (minus `strip`-ed own flags) under
/// the tool.
pub fn command(tool: &Debugger, root: &Path, extra: &[String], own_flags: &[&str]) -> anyhow::Result<Command> {
    let exe = std::env::current_exe().context("cannot find this executable to run it under the debugger")?;
    let args: Vec<OsString> = strip(std::env::args_os().skip(1), own_flags);
    let mut cmd = match tool {
        Debugger::Gdb => {
            let gdb = which::which("gdb").map_err(|_| anyhow::anyhow!("gdb is not installed: `apt-get install gdb`"))?;
            let mut c = Command::new(gdb);
            c.arg("-q").arg("-x").arg(root.join(install::GDB_INIT)).args(extra).arg("--args");
            c
        }
        Debugger::Valgrind(t) => {
            let vg = which::which("valgrind").map_err(|_| anyhow::anyhow!("valgrind is not installed: `apt-get install valgrind`"))?;
            let mut c = Command::new(vg);
            c.arg(format!("--tool={t}")).arg(format!("--suppressions={}", root.join(install::VALGRIND_SUPP).display()));
            if t == "memcheck" {
                c.args(["--leak-check=full", "--error-exitcode=1"]);
            } else if t == "helgrind" || t == "drd" {
                c.arg("--error-exitcode=1");
            }
            c.args(extra);
            // Valgrind reads an object's symbols from the file it was mapped from, which a
            // memory file (the loader's default) is not to it: load from private files.
            if std::env::var_os("OPENR_SCRATCH_FILES").is_none() {
                c.env("OPENR_SCRATCH_FILES", "1");
            }
            c
        }
    };
    cmd.arg(exe).args(args);
    Ok(cmd)
}

/// `args` without the flags that asked for the tool (`--gdb`, `--valgrind=memcheck`,
/// `--tool-arg X` / `--tool-arg=X`), so the run under the tool does not start it again.
fn strip(args: impl Iterator<Item = OsString>, own: &[&str]) -> Vec<OsString> {
    let mut out = Vec::new();
    let mut skip_value = false;
    for a in args {
        if skip_value {
            skip_value = false;
            continue;
        }
        let s = a.to_string_lossy();
        let name = s.split('=').next().unwrap_or("");
        if own.contains(&name) {
            // Flags with a separate value: only --tool-arg takes one.
            skip_value = name == "--tool-arg" && !s.contains('=');
            continue;
        }
        out.push(a);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_tools_own_flags_are_taken_out() {
        let args = ["run", "MS", "--gdb", "--tool-arg", "-batch", "--tool-arg=-ex=run", "--valgrind=helgrind", "--for", "1s"].map(OsString::from);
        let out = strip(args.into_iter(), &["--gdb", "--valgrind", "--tool-arg"]);
        assert_eq!(out, ["run", "MS", "--for", "1s"].map(OsString::from));
    }
}
