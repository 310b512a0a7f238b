//! The command line: a clap definition per subcommand in `commands/`, nothing else.
use std::ffi::OsString;

use clap::{CommandFactory, FromArgMatches, Parser, Subcommand};

use crate::commands;
use crate::shell::Shell;

#[derive(Debug, Parser)]
#[command(name = "cargo openr", bin_name = "cargo openr", version, about = "Build and run Sony AIBO (OPEN-R) programs on a PC")]
pub struct Cli {
    /// Coloured output: auto (stderr is a terminal), always, never (also CARGO_TERM_COLOR)
    #[arg(long, global = true, value_enum, value_name = "WHEN", env = "CARGO_TERM_COLOR", default_value = "auto")]
    pub color: crate::shell::ColorChoice,
    #[command(subcommand)]
    pub command: Command,
}

#[derive(Debug, Subcommand)]
pub enum Command {
    /// Materialise the OPEN-R SDK root (headers, mipsel-linux-* wrappers, mkbin, stubgen2)
    Sdk(commands::sdk::Args),
    /// Build a project's C++ and Rust objects into its MS/ tree (incremental, no make)
    Build(commands::build::Args),
    /// Run a Memory Stick tree (MS/) on the host: load its objects and boot them
    Run(commands::run::Args),
    /// Replay a recording (`run --record DIR`) or a `--trace` file in the browser, on a timeline
    View(commands::view::Args),
    /// Measure the runtime (message round trip, throughput, cold start) against the machine's limit
    Bench(commands::bench::Args),
    /// Create a new OPEN-R project (objects, Makefiles, MS/ tree) from a template
    New(commands::new::Args),
    /// Lint a project: 8.3 names, OBJECT.CFG objects, CONNECT.CFG wiring, stub.cfg, .ocf
    Check(commands::check::Args),
    /// Memory Stick tree tools (`ms verify`)
    Ms(commands::ms::Args),
    /// Check the host: compilers, make, binutils, gdb, Python/MuJoCo, GL, the SDK root
    Doctor(commands::doctor::Args),
    /// Print the build environment (SDK root, wrappers, flags, include dirs, libraries)
    Env(commands::env::Args),
    /// Print the resolved configuration and where each value came from
    Config(commands::config::Args),
}

pub fn run(args: Vec<OsString>, shell: &mut Shell) -> anyhow::Result<()> {
    let matches = Cli::command().try_get_matches_from(args).unwrap_or_else(|e| e.exit());
    let cli = Cli::from_arg_matches(&matches).unwrap_or_else(|e| e.exit());
    // `run` rebuilds its children's command lines from what was given (ops::child_args).
    let given = matches.subcommand().map(|(_, m)| m.clone()).unwrap_or_default();
    shell.set_color(cli.color);
    match cli.command {
        Command::Sdk(a) => commands::sdk::exec(a, shell),
        Command::Build(a) => commands::build::exec(a, shell),
        Command::Run(a) => commands::run::exec(a, &given, shell),
        Command::View(a) => commands::view::exec(a, shell),
        Command::Bench(a) => commands::bench::exec(a, shell),
        Command::New(a) => commands::new::exec(a, shell),
        Command::Check(a) => commands::check::exec(a, shell),
        Command::Ms(a) => commands::ms::exec(a, shell),
        Command::Doctor(a) => commands::doctor::exec(a, shell),
        Command::Env(a) => commands::env::exec(a, shell),
        Command::Config(a) => commands::config::exec(a, shell),
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn verify_cli() {
        use clap::CommandFactory;
        super::Cli::command().debug_assert();
    }
}
