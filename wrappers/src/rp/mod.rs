//! Remote Processing OPEN-R (remote-processing.md): the tools of `R/RP_OPEN_R/bin`.
//!
//! Host objects are compiled natively by the program's own `g++` with the flags of
//! `rp-openr-config`, and linked by `g++ -o x.bin … $(rp-openr-config --libs)`. We make
//! that link produce the same kind of object `mkbin` produces (a position-independent
//! shared object with the OPEN-R archives), so the cargo-openr runtime loads host objects
//! exactly like robot ones: `start-rp-openr` runs every host object as a thread of one
//! runtime process (no System V queues; see docs/rp-protocol.md).
pub mod config;
pub mod gwcfg;

/// First bytes of the `.BIN` of an object built into the cargo-openr runtime; the rest
/// of the line names it (the runtime's `gateway` module).
pub const BUILTIN_MAGIC: &[u8] = b"#!cargo-openr built-in object ";

/// `OPEN_R/MS_*/*/*/OPEN-R/SYSTEM/OBJS/TCPGW.BIN`: the robot's TCP gateway of Remote
/// Processing OPEN-R, which the runtime provides (as it does the virtual robot).
pub const TCPGW_BIN: &[u8] = b"#!cargo-openr built-in object robot-gateway\n";

use std::ffi::OsString;
use std::path::Path;

use crate::error::Error;

/// Where the RP tools live under the SDK root.
pub const BIN_DIR: &str = "RP_OPEN_R/bin";

/// `rp-openr-stubgen2 <stub.cfg>`: the robot generator, one argument as in Sony's tool.
/// The generated stub is the robot's: the runtime drives host objects through the same
/// `ObjectEntryTable`, so no `main` or message pump is needed in the object.
pub(crate) fn stubgen(args: &[OsString]) -> i32 {
    let (mut out, mut err) = (std::io::stdout(), std::io::stderr());
    if args.len() != 1 || args[0].to_string_lossy().starts_with('-') {
        if args.len() == 1 && (args[0] == "-h" || args[0] == "--help") {
            println!("usage: rp-openr-stubgen2 <stub.cfg>");
            return 0;
        }
        eprintln!("rp-openr-stubgen2: expected exactly one argument, the stub.cfg\nusage: rp-openr-stubgen2 <stub.cfg>");
        return 2;
    }
    let cwd = std::env::current_dir().unwrap_or_else(|_| ".".into());
    stubgen::run_stubgen2(args, &cwd, &mut out, &mut err)
}

/// `setup-rp-openr`: nothing to set up (the root is complete when installed); checks
/// that the pieces `rp-openr-config` names exist.
pub(crate) fn setup(root: &Path) -> Result<i32, Error> {
    for rel in ["OPEN_R/include/MCOOP.h", "OPEN_R/include/OPENR/OObject.h", "OPEN_R/lib/libOPENR.a", "OPEN_R/lib/libmcoopstub.a"] {
        let p = root.join(rel);
        if !p.is_file() {
            return Err(Error::usage(format!("incomplete SDK root: {} is missing; run `cargo openr sdk install` again", p.display())));
        }
    }
    println!("setup-rp-openr: RP OPEN-R is ready in {}", root.join("RP_OPEN_R").display());
    Ok(0)
}

/// `rp-openr-ipcrm`: Sony's host objects left System V queues behind after a crash. Ours
/// are threads of one process and create no IPC objects, so there is never anything to
/// remove; the tool says so and succeeds (a "reset" step of a start script keeps working).
pub(crate) fn ipcrm(args: &[OsString]) -> Result<i32, Error> {
    if let Some(a) = args.first() {
        return Err(Error::usage(format!("unexpected argument {}: rp-openr-ipcrm takes none", a.to_string_lossy())));
    }
    println!("rp-openr-ipcrm: no IPC objects to remove (cargo-openr runs host objects as threads of one process)");
    Ok(0)
}
