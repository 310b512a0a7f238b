//! The command line of a child runtime, rebuilt from what the user gave the parent:
//! every option given (command line or environment) is passed on as `--name=value`
//! unless a rule says otherwise, so a new option of `run` reaches the children of
//! `--sim mujoco` without anyone remembering to forward it.
use std::ffi::OsString;

use clap::parser::ValueSource;
use clap::{ArgAction, ArgMatches, Command};

/// What happens to one option (by its clap id).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Forward {
    /// Passed on as given.
    Same,
    /// The caller decides (per-child values, options of the parent only).
    Caller,
}

/// `--name=value` (or `--name` for a flag) for every option of `cmd` that `m` holds from
/// the command line or the environment and `rule` leaves to us, in `cmd`'s order.
pub fn forwarded(cmd: &Command, m: &ArgMatches, rule: impl Fn(&str) -> Forward) -> Vec<OsString> {
    let mut out = Vec::new();
    for arg in cmd.get_arguments() {
        let id = arg.get_id().as_str();
        let (Some(long), Forward::Same) = (arg.get_long(), rule(id)) else { continue };
        if !matches!(m.value_source(id), Some(ValueSource::CommandLine | ValueSource::EnvVariable)) {
            continue;
        }
        match arg.get_action() {
            ArgAction::SetTrue => out.push(format!("--{long}").into()),
            ArgAction::Count => (0..m.get_count(id)).for_each(|_| out.push(format!("--{long}").into())),
            _ => {
                for v in m.get_raw(id).into_iter().flatten() {
                    let mut o = OsString::from(format!("--{long}="));
                    o.push(v);
                    out.push(o);
                }
            }
        }
    }
    out
}
