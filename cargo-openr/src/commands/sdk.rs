//! `cargo openr sdk [install] [--prefix DIR]`
use std::path::PathBuf;

use anyhow::Context;
use openr_wrappers::install::{self, Outcome};

use crate::ops::sdk;
use crate::shell::Shell;

#[derive(Debug, clap::Args)]
pub struct Args {
    #[command(subcommand)]
    action: Option<Action>,
}

#[derive(Debug, clap::Subcommand)]
enum Action {
    /// Install (or update) the SDK root and print its path
    Install {
        /// Where to put it (default: ~/.local/share/cargo-openr/OPEN_R_SDK)
        #[arg(long, value_name = "DIR")]
        prefix: Option<PathBuf>,
    },
}

pub fn exec(args: Args, shell: &mut Shell) -> anyhow::Result<()> {
    let prefix = match args.action {
        Some(Action::Install { prefix: Some(p) }) => p,
        _ => install::default_prefix().context("cannot find a home directory; pass --prefix DIR")?,
    };
    let prefix = std::path::absolute(&prefix).unwrap_or(prefix);
    match sdk::prepare(&prefix, shell)? {
        Outcome::Installed => shell.status("Installed", &format!("OPEN-R SDK root at {}", prefix.display())),
        Outcome::UpToDate => shell.status("Fresh", &format!("OPEN-R SDK root at {}", prefix.display())),
    }
    shell.out(&prefix.display().to_string());
    Ok(())
}
