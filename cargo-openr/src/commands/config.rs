//! `cargo openr config`: the resolved configuration and where each value came from
//! (command line > environment > openr.toml > defaults).
use std::path::PathBuf;

use crate::ops::config::{self, speed_text, ConfigInputs};
use crate::shell::Shell;

#[derive(Debug, clap::Args)]
pub struct Args {
    /// The project directory whose openr.toml is read (then its parents)
    #[arg(long, value_name = "DIR", default_value = ".")]
    project: PathBuf,
    /// SDK root
    #[arg(long, value_name = "DIR")]
    sdk: Option<PathBuf>,
    /// Robot design
    #[arg(long)]
    design: Option<String>,
    /// Virtual-time speed (a factor or `max`)
    #[arg(long)]
    speed: Option<String>,
    /// `human` or `json` (one object: each setting with value and source)
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
    let inputs = ConfigInputs { sdk: args.sdk, design: args.design, speed: args.speed, project: Some(args.project), ..Default::default() };
    let cfg = config::resolve(&inputs)?;
    let rows = [
        ("sdk", cfg.sdk.value.display().to_string(), cfg.sdk.source.to_string()),
        ("design", cfg.design.value.clone(), cfg.design.source.to_string()),
        ("speed", speed_text(cfg.speed.value), cfg.speed.source.to_string()),
        ("cxxflags", cfg.cxxflags.value.join(" "), cfg.cxxflags.source.to_string()),
        ("ldflags", cfg.ldflags.value.join(" "), cfg.ldflags.source.to_string()),
        ("base", cfg.base.value.clone(), cfg.base.source.to_string()),
    ];
    match args.format {
        Format::Json => {
            let mut m = serde_json::Map::new();
            for (k, v, s) in &rows {
                m.insert(k.to_string(), serde_json::json!({ "value": v, "source": s }));
            }
            m.insert("project_file".into(), serde_json::json!(cfg.project_file));
            shell.out(&serde_json::Value::Object(m).to_string());
        }
        Format::Human => {
            for (k, v, s) in &rows {
                shell.out(&format!("{k:<8} = {v:<50} # {s}"));
            }
        }
    }
    Ok(())
}
