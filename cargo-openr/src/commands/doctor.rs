//! `cargo openr doctor`: host tools, Python/MuJoCo, GL, the SDK root — ok or how to fix.
use std::path::PathBuf;

use crate::ops::config::{self, ConfigInputs};
use crate::ops::{doctor, sdk};
use crate::shell::Shell;

#[derive(Debug, clap::Args)]
pub struct Args {
    /// SDK root to check (default: see `cargo openr config`)
    #[arg(long, value_name = "DIR")]
    sdk: Option<PathBuf>,
    /// `human` or `json` (one object: sdk, findings)
    #[arg(long, value_enum, default_value_t)]
    format: Format,
}

#[derive(Debug, Clone, Copy, Default, clap::ValueEnum)]
pub enum Format {
    #[default]
    Human,
    Json,
}

pub fn exec(args: Args, shell: &mut Shell) -> anyhow::Result<()> {
    let cfg = config::resolve(&ConfigInputs { sdk: args.sdk, project: Some(PathBuf::from(".")), ..Default::default() })?;
    let exe = sdk::exe()?;
    let findings = doctor::diagnose(&cfg.sdk.value, &exe);
    match args.format {
        Format::Json => {
            let v = serde_json::json!({ "sdk": cfg.sdk.value, "findings": findings });
            shell.out(&v.to_string());
        }
        Format::Human => {
            for f in &findings {
                let state = if f.ok {
                    "ok"
                } else if f.required {
                    "MISSING"
                } else {
                    "missing"
                };
                shell.out(&format!("{state:>8}  {:<24} {}", f.name, f.detail));
                if let Some(fix) = &f.fix {
                    shell.out(&format!("{:>8}  {:<24} fix: {fix}", "", ""));
                }
            }
        }
    }
    let missing: Vec<&str> = findings.iter().filter(|f| f.required && !f.ok).map(|f| f.name.as_str()).collect();
    if !missing.is_empty() {
        anyhow::bail!("missing what building and running programs needs: {}", missing.join(", "));
    }
    Ok(())
}
