//! `cargo openr new <name> [--template hello|subject-observer|walk|rust-object] [--path DIR]`
use std::path::PathBuf;

use clap::builder::{PossibleValue, PossibleValuesParser};
use openr_templates::new::TEMPLATES;

use crate::ops::new::{self, NewOptions};
use crate::shell::Shell;

#[derive(Debug, clap::Args)]
pub struct Args {
    /// Project name: letters, digits, `-`, `_`; gives the object classes (`my-dog` → MyDog) and .BIN names (MYDOG.BIN)
    name: String,
    /// Project template
    #[arg(long, default_value = "hello", value_parser = templates())]
    template: String,
    /// Directory to create (default: ./<name>); must not exist or be empty
    #[arg(long, value_name = "DIR")]
    path: Option<PathBuf>,
}

/// The `--template` values: every template of `openr_templates`, its `about` as help.
fn templates() -> PossibleValuesParser {
    PossibleValuesParser::new(TEMPLATES.iter().map(|t| PossibleValue::new(t.name).help(t.about)))
}

pub fn exec(args: Args, shell: &mut Shell) -> anyhow::Result<()> {
    let path = args.path.unwrap_or_else(|| PathBuf::from(&args.name));
    let opts = NewOptions { name: args.name, template: args.template, path };
    let created = new::new(&opts)?;
    let objs: Vec<String> = created.objects.iter().map(|o| format!("{} ({})", o.class, o.bin)).collect();
    shell.status("Created", &format!("`{}` OPEN-R project at {} ({} files): {}", opts.template, created.dir.display(), created.files.len(), objs.join(", ")));
    shell.out(&created.dir.display().to_string());
    Ok(())
}
