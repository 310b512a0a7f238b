//! `mipsel-linux-{ld,strip,ar,ranlib}`: the host binutils, unchanged. Host objects are
//! x86-64 ELF, which the host tools handle; `strip` keeps `.dynsym`, which is all the
//! loader reads. Under `OPENR_SANITIZE` (or `OPENR_KEEP_DEBUG=1`) `strip` keeps the
//! debug information, so that the Makefile's `$(STRIP) $@` does not take the source lines
//! out of sanitizer reports and gdb sessions.
use std::ffi::OsString;
use std::process::Command;

use crate::Error;

pub(crate) fn run(tool: &str, args: Vec<OsString>) -> Result<i32, Error> {
    let exe = crate::compile::host_tool(tool, &[])?;
    let keep_debug = tool == "strip" && (crate::sanitize::from_env()?.is_some() || std::env::var_os("OPENR_KEEP_DEBUG").is_some_and(|v| v == "1"));
    let mut cmd = Command::new(exe);
    if keep_debug {
        // Symbols that are not needed for relocation go, the DWARF stays.
        cmd.arg("--strip-unneeded").arg("--keep-section=.debug_*");
        cmd.args(args.into_iter().filter(|a| a != "-s" && a != "--strip-all" && a != "-g" && a != "--strip-debug"));
        return crate::compile::exec(&mut cmd);
    }
    crate::compile::exec(cmd.args(args))
}
