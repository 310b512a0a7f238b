//! `mipsel-linux-{ld,strip,ar,ranlib}`: the host binutils, unchanged. Host objects are
//! x86-64 ELF, which the host tools handle; `strip` keeps `.dynsym`, which is all the
//! loader reads.
use std::ffi::OsString;
use std::process::Command;

use crate::Error;

pub(crate) fn run(tool: &str, args: Vec<OsString>) -> Result<i32, Error> {
    let exe = crate::compile::host_tool(tool, &[])?;
    crate::compile::exec(Command::new(exe).args(args))
}
