//! `cargo openr doctor`: what the host has of what building and running AIBO programs
//! needs, each with the line that fixes it.
use std::path::Path;
use std::process::Command;

use serde::Serialize;

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
            Err(_) => Finding {
                name: tool.into(),
                required,
                ok: false,
                detail: "not found in PATH".into(),
                fix: Some(format!("apt-get install {pkg}")),
            },
        });
    }
    out.push(mujoco());
    out.push(gl_backend());
    out.push(sdk_root(sdk, exe));
    out
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

fn mujoco() -> Finding {
    let out = Command::new("python3").args(["-c", "import mujoco; print(mujoco.__version__)"]).output();
    match out {
        Ok(o) if o.status.success() => Finding {
            name: "python3 mujoco".into(),
            required: false,
            ok: true,
            detail: format!("mujoco {}", String::from_utf8_lossy(&o.stdout).trim()),
            fix: None,
        },
        _ => Finding {
            name: "python3 mujoco".into(),
            required: false,
            ok: false,
            detail: "`python3 -c \"import mujoco\"` failed".into(),
            fix: Some("pip install mujoco".into()),
        },
    }
}

/// MuJoCo renders off-screen through EGL or OSMesa (`MUJOCO_GL=egl|osmesa`).
fn gl_backend() -> Finding {
    let dirs = ["/usr/lib/x86_64-linux-gnu", "/usr/lib64", "/usr/lib", "/usr/local/lib", "/lib/x86_64-linux-gnu"];
    let has = |prefix: &str| {
        dirs.iter().any(|d| {
            std::fs::read_dir(d).is_ok_and(|rd| rd.flatten().any(|e| e.file_name().to_string_lossy().starts_with(prefix)))
        })
    };
    let mut found = Vec::new();
    if has("libEGL.so") {
        found.push("egl");
    }
    if has("libOSMesa.so") {
        found.push("osmesa");
    }
    let chosen = std::env::var("MUJOCO_GL").ok().filter(|v| !v.is_empty());
    let ok = match &chosen {
        Some(c) => found.contains(&c.as_str()) || c == "glfw",
        None => !found.is_empty(),
    };
    let mut detail = if found.is_empty() { "no libEGL.so or libOSMesa.so found".to_string() } else { format!("available: {}", found.join(", ")) };
    if let Some(c) = chosen {
        detail.push_str(&format!("; MUJOCO_GL={c}"));
    }
    Finding {
        name: "GL backend (MUJOCO_GL)".into(),
        required: false,
        ok,
        detail,
        fix: (!ok).then(|| "apt-get install libegl1 libosmesa6".into()),
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
