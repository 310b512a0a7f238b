//! The SDK root a command works against is made from this very executable (its tools are
//! links to it), so it is installed, or updated after a rebuild, before every use.
use std::path::{Path, PathBuf};

use anyhow::Context;
use openr_wrappers::install::{self, Outcome};

/// This executable, the multi-call binary the SDK root's tools run.
pub fn exe() -> anyhow::Result<PathBuf> {
    std::env::current_exe().context("cannot locate the cargo-openr executable")
}

/// Installs or updates the SDK root at `root` from this executable.
pub fn prepare(root: &Path) -> anyhow::Result<Outcome> {
    let exe = exe()?;
    install::install(root, &exe).with_context(|| format!("cannot prepare the SDK root {}", root.display()))
}
