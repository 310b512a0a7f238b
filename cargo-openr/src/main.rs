//! `cargo-openr`: the `cargo openr` subcommand, and — started under another name — every
//! tool of the SDK root (`mipsel-linux-g++`, `mkbin`, `stubgen2`, …), as cargo-zigbuild
//! does: `argv[0]` decides before clap runs.
mod cli;
mod commands;
mod ops;
mod shell;

use std::ffi::OsString;
use std::path::Path;
use std::process::ExitCode;

fn main() -> ExitCode {
    let mut args: Vec<OsString> = std::env::args_os().collect();
    let argv0 = args.first().cloned().unwrap_or_default();
    let name = Path::new(&argv0).file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
    if openr_wrappers::tool_for(&name) == Some(openr_wrappers::Tool::RpStart) {
        return start_rp_openr(args.split_off(1));
    }
    if let Some(tool) = openr_wrappers::tool_for(&name) {
        return ExitCode::from(run_as_tool(tool, &name, args.split_off(1)));
    }
    // `cargo openr …` runs us as `cargo-openr openr …`.
    if args.get(1).is_some_and(|a| a == "openr") {
        args.remove(1);
    }
    let mut shell = shell::Shell::new();
    match cli::run(args, &mut shell) {
        Ok(()) => ExitCode::SUCCESS,
        // A child tool (gdb, valgrind) already said what went wrong: pass its status on.
        Err(e) if e.downcast_ref::<shell::ChildStatus>().is_some() => ExitCode::from(e.downcast_ref::<shell::ChildStatus>().map_or(1, |c| c.0)),
        Err(e) => {
            shell.error(&format!("{e:#}"));
            ExitCode::FAILURE
        }
    }
}

fn run_as_tool(tool: openr_wrappers::Tool, name: &str, args: Vec<OsString>) -> u8 {
    let root = std::env::current_exe().ok().and_then(|exe| openr_wrappers::root_from_exe(&exe));
    let Some(root) = root else {
        eprintln!("{name}: cannot find the SDK root: this tool must be run from an SDK root made by `cargo openr sdk install`");
        return 1;
    };
    let code = openr_wrappers::run_tool(tool, name, args, &root);
    u8::try_from(code).unwrap_or(1)
}

/// `start-rp-openr [run options]`: `cargo openr run MS` for the RP host program in the cwd.
fn start_rp_openr(extra: Vec<OsString>) -> ExitCode {
    // libOPENR refuses the calls Sony's RP OPEN-R does not offer host objects (IG4.3).
    // Set before any thread exists.
    std::env::set_var("OPENR_RP_HOST", "1");
    let mut shell = shell::Shell::new();
    let cwd = std::env::current_dir().unwrap_or_else(|_| ".".into());
    let root = ops::rp::own_root();
    let result = ops::rp::start_args(&cwd, extra, root.as_deref(), &mut shell).and_then(|args| cli::run(args, &mut shell));
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            shell.error(&format!("start-rp-openr: {e:#}"));
            ExitCode::FAILURE
        }
    }
}
