//! `cargo openr check [DIR]`: lint a project — its MS/ tree, stub.cfg files and .ocf files.
use std::path::PathBuf;

use crate::ops::check;
use crate::ops::config::{self, ConfigInputs};
use crate::ops::diag::{MessageFormat, Report};
use crate::shell::Shell;

#[derive(Debug, clap::Args)]
pub struct Args {
    /// The project directory (holds MS/ and the objects' stub.cfg)
    #[arg(value_name = "DIR", default_value = ".")]
    dir: PathBuf,
    /// Robot design whose [ERS-…] sections of the CFG files are checked (default: see `cargo openr config`)
    #[arg(long)]
    design: Option<String>,
    /// `human` (rustc style, stderr) or `json` (one object per line, stdout)
    #[arg(long, value_enum, default_value_t)]
    message_format: MessageFormat,
}

pub fn exec(args: Args, shell: &mut Shell) -> anyhow::Result<()> {
    let cfg = config::resolve(&ConfigInputs { design: args.design, project: Some(args.dir.clone()), ..Default::default() })?;
    let mut report = Report::default();
    let mut sticks = Vec::new();
    for opts in check::project_inputs(&args.dir, &cfg.design.value)? {
        report.diagnostics.extend(check::check(&opts)?.diagnostics);
        sticks.push(opts.ms.strip_prefix(&args.dir).unwrap_or(&opts.ms).display().to_string());
    }
    // A Remote Processing project's sides are named: which sticks were checked.
    let what = if sticks == ["MS"] { args.dir.display().to_string() } else { format!("{} ({})", args.dir.display(), sticks.join(", ")) };
    finish(&report, args.message_format, &what, shell)
}

/// Prints the findings and a summary; an error when any finding is an error.
pub(crate) fn finish(report: &Report, format: MessageFormat, what: &str, shell: &mut Shell) -> anyhow::Result<()> {
    for d in &report.diagnostics {
        shell.diagnostic(d, format);
    }
    let (errors, warnings) = (report.errors(), report.warnings());
    let plural = |n: usize, w: &str| format!("{n} {w}{}", if n == 1 { "" } else { "s" });
    if errors > 0 {
        anyhow::bail!("could not verify `{what}` due to {} ({} emitted)", plural(errors, "error"), plural(warnings, "warning"));
    }
    shell.status("Checked", &format!("{what}: {}, {}", plural(errors, "error"), plural(warnings, "warning")));
    Ok(())
}
