//! `cargo openr doctor`: what the host has of what building and running AIBO programs
//! needs, each with the line that fixes it.
use std::path::Path;
use std::process::Command;

use serde::Serialize;

use crate::ops::sim;

/// One checked item.
#[derive(Debug, Clone, Serialize)]
pub struct Finding {
    pub name: String,
    /// Needed to build or run programs (doctor fails when one of these is missing).
    pub required: bool,
    pub ok: bool,
    /// What was found (path, version) or what is wrong.
    pub detail: String,
    /// The command that fixes it, when not ok.
    pub fix: Option<String>,
}

/// Runs every check. `sdk` is the resolved SDK root, `exe` the running cargo-openr.
pub fn diagnose(sdk: &Path, exe: &Path) -> Vec<Finding> {
    let mut out = Vec::new();
    for (tool, pkg, required) in [
        ("g++", "g++", true),
        ("gcc", "gcc", true),
        ("make", "make", true),
        ("ar", "binutils", true),
        ("strip", "binutils", true),
        ("gzip", "gzip", true),
        ("gdb", "gdb", false),
        ("valgrind", "valgrind", false),
        ("python3", "python3", false),
    ] {
        out.push(match which::which(tool) {
            Ok(path) => Finding { name: tool.into(), required, ok: true, detail: with_version(&path), fix: None },
            Err(_) => Finding { name: tool.into(), required, ok: false, detail: "not found in PATH".into(), fix: Some(format!("apt-get install {pkg}")) },
        });
    }
    out.push(mujoco());
    out.push(sdk_root(sdk, exe));
    if openr_wrappers::install::is_sdk_root(sdk) {
        out.push(align_plugin(sdk));
    }
    out
}

/// The alignment trap's gcc plugin in the root: without it, gcc's own check (same
/// faults, tight loops about twice as slow).
fn align_plugin(sdk: &Path) -> Finding {
    let name = "alignment trap plugin".to_string();
    match openr_wrappers::align_plugin::status(sdk) {
        Ok(path) => Finding { name, required: false, ok: true, detail: path.display().to_string(), fix: None },
        Err(why) => {
            // Installing the headers is the usual fix; the next `sdk install` (or any
            // `cargo openr run`/`build`) then builds the plugin into the root.
            let install = format!("cargo openr sdk install --prefix {}", sdk.display());
            let fix = match openr_wrappers::align_plugin::missing_headers_package() {
                Some(pkg) => format!("apt-get install {pkg} && {install}"),
                None => install,
            };
            Finding { name, required: false, ok: false, detail: why, fix: Some(fix) }
        }
    }
}

/// `path (version)` from `tool --version`'s first line.
fn with_version(path: &Path) -> String {
    let version = Command::new(path)
        .arg("--version")
        .output()
        .ok()
        .and_then(|o| String::from_utf8_lossy(if o.stdout.is_empty() { &o.stderr } else { &o.stdout }).lines().next().map(str::to_string))
        .filter(|l| !l.trim().is_empty());
    match version {
        Some(v) => format!("{} ({})", path.display(), v.trim()),
        None => path.display().to_string(),
    }
}

/// MuJoCo for `run --sim mujoco`: the simulator's Python imports it and renders offscreen
/// with the GL backend (`MUJOCO_GL`, default egl) -- the same probe `run` makes.
fn mujoco() -> Finding {
    let python = sim::python();
    let name = "MuJoCo + GL".to_string();
    match sim::probe(&python) {
        Ok(version) => Finding {
            name,
            required: false,
            ok: version.ends_with(sim::MUJOCO_VERSION),
            detail: format!("{version} rendering with MUJOCO_GL={} via {}", sim::gl_backend(), python.display()),
            fix: (!version.ends_with(sim::MUJOCO_VERSION)).then(|| format!("tools/deps.sh (installs mujoco=={} into the venv)", sim::MUJOCO_VERSION)),
        },
        Err(why) => Finding {
            name,
            required: false,
            ok: false,
            detail: format!("{} (MUJOCO_GL={}): {why}", python.display(), sim::gl_backend()),
            fix: Some("tools/deps.sh (apt libegl1 libegl-mesa0 libgl1-mesa-dri libosmesa6; pip mujoco in ~/.cache/cargo-openr/mujoco-venv)".into()),
        },
    }
}

fn sdk_root(sdk: &Path, exe: &Path) -> Finding {
    use openr_wrappers::install::{is_sdk_root, is_up_to_date};
    let name = "SDK root".to_string();
    let fix = Some(format!("cargo openr sdk install --prefix {}", sdk.display()));
    if !is_sdk_root(sdk) {
        let detail = if sdk.exists() { format!("{} is not a cargo-openr SDK root", sdk.display()) } else { format!("{} is not installed", sdk.display()) };
        // `cargo openr run` installs it on first use, so it is not required here.
        return Finding { name, required: false, ok: false, detail, fix };
    }
    if !is_up_to_date(sdk, exe) {
        return Finding { name, required: false, ok: false, detail: format!("{} is out of date (installed by another cargo-openr)", sdk.display()), fix };
    }
    Finding { name, required: false, ok: true, detail: format!("{} (up to date)", sdk.display()), fix: None }
}
