//! The SDK root a command works against is made from this very executable (its tools are
//! links to it), so it is installed, or updated after a rebuild, before every use.
use std::path::{Path, PathBuf};

use anyhow::Context;
use openr_wrappers::install::{self, Building, Outcome};

/// This executable, the multi-call binary the SDK root's tools run.
pub fn exe() -> anyhow::Result<PathBuf> {
    std::env::current_exe().context("cannot locate the cargo-openr executable")
}

/// Installs or updates the SDK root at `root` from this executable, saying so on
/// `shell` first when it has to build the tree (a minute or two: without the line, the
/// first run after a rebuild just looks slow).
pub fn prepare(root: &Path, shell: &mut crate::shell::Shell) -> anyhow::Result<Outcome> {
    let exe = exe()?;
    let building = |why| {
        let why = match why {
            Building::New => "first use",
            Building::OtherBuild => "it was made by another build of cargo-openr",
        };
        shell.status("Installing", &format!("OPEN-R SDK root at {} ({why}; this takes a minute or two)", root.display()));
    };
    install::install_telling(root, &exe, building).with_context(|| format!("cannot prepare the SDK root {}", root.display()))
}
