//! `start-rp-openr` (remote-processing 2.4, 7.1.3): runs the RP host program of the current
//! directory (`./MS`) under the cargo-openr runtime.
//!
//! Decision (docs/rp-protocol.md): Sony started one UNIX process per host object joined by
//! System V queues; we run every host object as a thread of one runtime process, with the
//! runtime's message loop, ready/notify and shared memory, exactly as on the emulated robot.
//! The start-up log keeps Sony's shape: one line per object, in OBJECT.CFG order.
use std::ffi::OsString;
use std::path::{Path, PathBuf};

use anyhow::{bail, Context};
use openr_wrappers::rp::gwcfg;

use crate::shell::Shell;

/// What `start-rp-openr [run options…]` hands to `cargo openr run`, after the checks.
pub fn start_args(cwd: &Path, extra: Vec<OsString>, root: Option<&Path>, shell: &mut Shell) -> anyhow::Result<Vec<OsString>> {
    let conf = cwd.join("MS/OPEN-R/MW/CONF");
    let object_cfg = conf.join("OBJECT.CFG");
    if !object_cfg.is_file() {
        bail!("no {} : run start-rp-openr from the directory that holds MS/ (after `make install` there)", object_cfg.display());
    }
    check_hostgw(&conf.join("HOSTGW.CFG"))?;
    for name in ["OBJECT.CFG", "CONNECT.CFG"] {
        warn_design_sections(&conf.join(name), shell);
    }
    let text = std::fs::read_to_string(&object_cfg).with_context(|| format!("cannot read {}", object_cfg.display()))?;
    let pid = std::process::id();
    shell.status("Starting", &format!("RP OPEN-R host program {} (pid {pid}, one thread per object)", cwd.join("MS").display()));
    for (k, path) in object_lines(&text).enumerate() {
        shell.status("Object", &format!("{k}: {} (pid {pid})", path.trim_start_matches('/')));
    }
    let mut args: Vec<OsString> = ["cargo-openr", "run", "MS", "--base", "none"].iter().map(OsString::from).collect();
    if let (Some(root), None) = (root, std::env::var_os("OPENRSDK_ROOT")) {
        args.extend([OsString::from("--sdk"), root.as_os_str().to_owned()]);
    }
    args.extend(extra);
    Ok(args)
}

fn object_lines(text: &str) -> impl Iterator<Item = &str> {
    text.lines().map(|l| l.trim()).filter(|l| !l.is_empty() && !l.starts_with('#') && !l.starts_with('[')).filter_map(|l| l.split_whitespace().next())
}

/// HOSTGW.CFG is read before anything starts, so a bad line fails at once (the runtime's
/// host gateway reads it again and opens the channels).
fn check_hostgw(path: &Path) -> anyhow::Result<()> {
    gwcfg::read(path).map(drop).map_err(|e| anyhow::anyhow!("{e}"))
}

/// Robot-design sections are not supported in host CFG files (IG4.3); say how ours treats them.
fn warn_design_sections(path: &Path, shell: &mut Shell) {
    let Ok(text) = std::fs::read_to_string(path) else { return };
    for (i, l) in text.lines().enumerate() {
        let l = l.trim();
        if l.starts_with('[') {
            shell.warn(&format!(
                "{}:{}: robot-design section {l} in a host CFG file (Sony's RP OPEN-R does not support them): \
                 it applies as on the robot, to the design of this run (--design, default ERS-7)",
                path.display(),
                i + 1
            ));
        }
    }
}

/// The SDK root a tool symlink belongs to.
pub fn own_root() -> Option<PathBuf> {
    std::env::current_exe().ok().and_then(|exe| openr_wrappers::root_from_exe(&exe))
}
