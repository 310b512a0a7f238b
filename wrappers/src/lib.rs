//! The tools of an OPEN-R SDK root, re-created for the host.
//!
//! An unmodified AIBO Makefile calls `$(OPENRSDK_ROOT)/bin/mipsel-linux-g++`,
//! `$(OPENRSDK_ROOT)/OPEN_R/bin/stubgen2`, `mkbin`, `gzcp` and friends. All of them are
//! one multi-call binary (`cargo-openr`): [`tool_for`] maps the name it was started
//! under to a [`Tool`], and [`run_tool`] runs it. [`install`] materialises an SDK root.
//!
//! ```
//! use openr_wrappers::{tool_for, Tool};
//! assert_eq!(tool_for("mipsel-linux-g++"), Some(Tool::Cxx));
//! assert_eq!(tool_for("cargo-openr"), None);
//! ```

pub mod align_plugin;
mod binutils;
mod compile;
mod error;
mod gzcp;
pub mod install;
pub mod ldlog;
mod legacy_notes;
pub mod mkbin;
pub mod ocf;
mod repair;
mod root;
pub mod rp;
pub mod sanitize;

use std::ffi::OsString;
use std::path::Path;

pub use compile::{cc_flags, cxx_flags, host_tool};
pub use error::{Error, ErrorKind};
pub use gzcp::gzip_file;
pub use root::root_from_exe;

/// One tool of the SDK root.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Tool {
    Cxx,
    Cc,
    Ld,
    Strip,
    Ar,
    Ranlib,
    Stubgen2,
    Mkbin,
    Gzcp,
    /// `RP_OPEN_R/bin/rp-openr-stubgen2`
    RpStubgen2,
    /// `RP_OPEN_R/bin/rp-openr-config`
    RpConfig,
    /// `RP_OPEN_R/bin/start-rp-openr`: runs the runtime, so `cargo-openr` dispatches it itself
    RpStart,
    RpIpcrm,
    RpSetup,
}

/// `(name, tool, directory under the SDK root)` for every tool the root provides.
pub const TOOLS: &[(&str, Tool, &str)] = &[
    ("mipsel-linux-g++", Tool::Cxx, "bin"),
    ("mipsel-linux-c++", Tool::Cxx, "bin"),
    ("mipsel-linux-gcc", Tool::Cc, "bin"),
    ("mipsel-linux-ld", Tool::Ld, "bin"),
    ("mipsel-linux-strip", Tool::Strip, "bin"),
    ("mipsel-linux-ar", Tool::Ar, "bin"),
    ("mipsel-linux-ranlib", Tool::Ranlib, "bin"),
    ("stubgen2", Tool::Stubgen2, "OPEN_R/bin"),
    ("mkbin", Tool::Mkbin, "OPEN_R/bin"),
    ("gzcp", Tool::Gzcp, "OPEN_R/bin"),
    ("rp-openr-stubgen2", Tool::RpStubgen2, rp::BIN_DIR),
    ("rp-openr-config", Tool::RpConfig, rp::BIN_DIR),
    ("start-rp-openr", Tool::RpStart, rp::BIN_DIR),
    ("rp-openr-ipcrm", Tool::RpIpcrm, rp::BIN_DIR),
    ("setup-rp-openr", Tool::RpSetup, rp::BIN_DIR),
];

/// The tool an executable named `name` (its file name, no directory) stands for.
pub fn tool_for(name: &str) -> Option<Tool> {
    TOOLS.iter().find(|(n, _, _)| *n == name).map(|(_, t, _)| *t)
}

/// Runs `tool` with `args` (without argv\[0\]) for the SDK root `root`; returns the exit
/// code. Diagnostics go to stderr prefixed with the tool's name, as Sony's tools did.
pub fn run_tool(tool: Tool, name: &str, args: Vec<OsString>, root: &Path) -> i32 {
    let result = match tool {
        Tool::Cxx => compile::run(compile::Lang::Cxx, args),
        Tool::Cc => compile::run(compile::Lang::C, args),
        Tool::Ld => binutils::run("ld", args),
        Tool::Strip => binutils::run("strip", args),
        Tool::Ar => binutils::run("ar", args),
        Tool::Ranlib => binutils::run("ranlib", args),
        Tool::Gzcp => gzcp::run(&args),
        Tool::Mkbin => mkbin::run(args, root),
        Tool::RpStubgen2 => return rp::stubgen(&args),
        Tool::RpConfig => rp::config::run(&args, root),
        Tool::RpIpcrm => rp::ipcrm(&args),
        Tool::RpSetup => rp::setup(root),
        Tool::RpStart => Err(Error::usage("start-rp-openr is run by the cargo-openr binary itself")),
        Tool::Stubgen2 => {
            let cwd = std::env::current_dir().unwrap_or_else(|_| ".".into());
            let (mut out, mut err) = (std::io::stdout(), std::io::stderr());
            return stubgen::run_stubgen2(&args, &cwd, &mut out, &mut err);
        }
    };
    match result {
        Ok(code) => code,
        Err(e) => {
            eprintln!("{name}: {e}");
            1
        }
    }
}
