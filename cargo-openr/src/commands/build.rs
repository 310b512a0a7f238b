//! `cargo openr build [--release] [--message-format json] [-p OBJECT]... [--path DIR]`
use std::path::PathBuf;

use serde_json::json;

use crate::ops::build::{self, BuildOptions, Event};
use crate::ops::config::{self, ConfigInputs};
use crate::ops::diag::MessageFormat;
use crate::ops::gcc_diag;
use crate::ops::sdk;
use crate::shell::Shell;

#[derive(Debug, clap::Args)]
pub struct Args {
    /// The project directory (default: the current directory)
    #[arg(long, value_name = "DIR", default_value = ".")]
    path: PathBuf,
    /// The release profile: C++ objects `-O2 -g`, Rust objects `cargo build --release`
    /// (default: the dev profile, C++ `-O0 -g`)
    #[arg(long)]
    release: bool,
    /// Show each compiler and linker command
    #[arg(short, long)]
    verbose: bool,
    /// Compiler and linker processes at once (default: the number of cores)
    #[arg(short = 'j', long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..=1024))]
    jobs: Option<u32>,
    /// Instrument the C++ objects with a sanitizer; `cargo openr run` then starts the stick with its runtime
    #[arg(long, value_enum, value_name = "KIND")]
    sanitize: Option<crate::ops::sanitize::Sanitizer>,
    /// Extra C/C++ compiler flags, e.g. "-DDEBUG -Wall" (also OPENR_CXXFLAGS, openr.toml `cxxflags`)
    #[arg(long, value_name = "FLAGS", allow_hyphen_values = true)]
    cxxflags: Option<String>,
    /// Extra link arguments for mkbin, e.g. "-lm" (also OPENR_LDFLAGS, openr.toml `ldflags`)
    #[arg(long, value_name = "FLAGS", allow_hyphen_values = true)]
    ldflags: Option<String>,
    /// Build only this object (its stub.cfg ObjectName or cargo package name); repeatable
    #[arg(short = 'p', long = "package", value_name = "OBJECT")]
    packages: Vec<String>,
    /// SDK root (default: see `cargo openr config`; installed on first use)
    #[arg(long, value_name = "DIR")]
    sdk: Option<PathBuf>,
    /// `human` (status lines on stderr) or `json` (one object per line on stdout)
    #[arg(long, value_enum, default_value_t)]
    message_format: MessageFormat,
}

pub fn exec(args: Args, shell: &mut Shell) -> anyhow::Result<()> {
    let inputs = ConfigInputs { sdk: args.sdk, cxxflags: args.cxxflags, ldflags: args.ldflags, project: Some(args.path.clone()), ..Default::default() };
    let cfg = config::resolve(&inputs)?;
    let root = cfg.sdk.value;
    sdk::prepare(&root, shell)?;
    let (mut cxxflags, mut ldflags) = (cfg.cxxflags.value, cfg.ldflags.value);
    if let Some(s) = args.sanitize {
        cxxflags.extend(s.cxxflags());
        ldflags.extend(s.ldflags());
    }
    let opts = BuildOptions {
        dir: args.path.clone(),
        sdk: root,
        release: args.release,
        cxxflags,
        ldflags,
        packages: args.packages,
        verbose: args.verbose,
        jobs: args.jobs.map_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get()), |j| j as usize),
        color: shell.color() && args.message_format != MessageFormat::Json,
    };
    let json = args.message_format == MessageFormat::Json;
    let mut emit = |e: Event| match (&e, json) {
        (Event::Compiling { object, kind }, false) => shell.status("Compiling", &format!("{object} ({})", kind.label())),
        (Event::Compiling { object, kind }, true) => shell.out(&json!({ "reason": "compiling", "package_id": object, "kind": kind.label() }).to_string()),
        (Event::Running { command, .. }, false) => shell.status("Running", &format!("`{command}`")),
        (Event::Running { object, command }, true) => shell.out(&json!({ "reason": "running", "package_id": object, "command": command }).to_string()),
        (Event::Artifact { .. }, false) => {}
        (Event::Artifact { object, kind, bin, fresh }, true) => {
            shell.out(&json!({ "reason": "compiler-artifact", "package_id": object, "kind": kind.label(), "filenames": [bin], "fresh": fresh }).to_string())
        }
        (Event::Message { rendered, .. }, false) => {
            eprint!("{rendered}");
            if !rendered.ends_with('\n') {
                eprintln!();
            }
        }
        (Event::Message { object, level, rendered }, true) => {
            // One record per diagnostic, in cargo's shape (spans, code, children).
            for m in gcc_diag::parse(rendered, level) {
                shell.out(&json!({ "reason": "compiler-message", "package_id": object, "message": m }).to_string());
            }
        }
    };
    let result = build::build(&opts, &mut emit);
    let ok = result.is_ok();
    if json {
        shell.out(&json!({ "reason": "build-finished", "success": ok }).to_string());
    }
    let report = result?;
    let profile = if args.release { "release" } else { "dev" };
    shell.status(
        "Finished",
        &format!("`{profile}` profile: {} object(s), {} compiled, in {:.2}s", report.objects, report.compiled, report.elapsed.as_secs_f64()),
    );
    Ok(())
}
