//! `cargo openr ms verify <MS dir>`: lint a bare Memory Stick tree (services taken from
//! the objects' read-only data, see `ops::check`).
use std::path::PathBuf;

use crate::ops::check::{self, CheckOptions};
use crate::ops::config::{self, ConfigInputs};
use crate::ops::diag::MessageFormat;
use crate::shell::Shell;

#[derive(Debug, clap::Args)]
pub struct Args {
    #[command(subcommand)]
    action: Action,
}

#[derive(Debug, clap::Subcommand)]
enum Action {
    /// Check names, OBJECT.CFG objects and CONNECT.CFG wiring of a Memory Stick tree
    Verify {
        /// The Memory Stick directory (the one containing OPEN-R/)
        #[arg(value_name = "MS_DIR")]
        ms_dir: PathBuf,
        /// Robot design whose [ERS-…] sections of the CFG files are checked
        #[arg(long)]
        design: Option<String>,
        /// `human` (rustc style, stderr) or `json` (one object per line, stdout)
        #[arg(long, value_enum, default_value_t)]
        message_format: MessageFormat,
    },
}

pub fn exec(args: Args, shell: &mut Shell) -> anyhow::Result<()> {
    let Action::Verify { ms_dir, design, message_format } = args.action;
    let project = ms_dir.parent().map(PathBuf::from);
    let cfg = config::resolve(&ConfigInputs { design, project, ..Default::default() })?;
    let opts = CheckOptions { ms: ms_dir.clone(), stubs: Vec::new(), ocfs: Vec::new(), design: cfg.design.value, loaded_stubs_only: false };
    let report = check::check(&opts)?;
    super::check::finish(&report, message_format, &ms_dir.display().to_string(), shell)
}
