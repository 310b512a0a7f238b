//! `cargo openr env [--format sh|json]`: the build environment (SDK root, compiler
//! wrappers, added flags, include dirs, default libraries) for IDEs and build systems.
use std::path::PathBuf;

use crate::ops::config::{self, ConfigInputs};
use crate::ops::env;
use crate::shell::Shell;

#[derive(Debug, clap::Args)]
pub struct Args {
    /// SDK root (default: see `cargo openr config`)
    #[arg(long, value_name = "DIR")]
    sdk: Option<PathBuf>,
    /// `sh` (export lines, for eval) or `json`
    #[arg(long, value_enum, default_value_t)]
    format: Format,
}

#[derive(Debug, Clone, Copy, Default, clap::ValueEnum)]
pub enum Format {
    #[default]
    Sh,
    Json,
}

pub fn exec(args: Args, shell: &mut Shell) -> anyhow::Result<()> {
    let cfg = config::resolve(&ConfigInputs { sdk: args.sdk, project: Some(PathBuf::from(".")), ..Default::default() })?;
    if !openr_wrappers::install::is_sdk_root(&cfg.sdk.value) {
        shell.warn(&format!("{} is not installed yet: run `cargo openr sdk install --prefix {0}`", cfg.sdk.value.display()));
    }
    let vars = env::build_env(&cfg.sdk.value);
    let text = match args.format {
        Format::Sh => env::to_sh(&vars),
        Format::Json => env::to_json(&vars),
    };
    shell.out(text.trim_end());
    Ok(())
}
