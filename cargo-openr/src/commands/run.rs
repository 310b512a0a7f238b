//! `cargo openr run <MS dir>`: boot a Memory Stick tree on the host.
use std::path::PathBuf;
use std::time::Duration;

use anyhow::Context;
use openr_wrappers::install;
use sdk_runtime::boot::{self, Ended, RunOptions};
use sdk_runtime::runtime::Diag;

use crate::ops::config::{self, ConfigInputs};
use crate::shell::Shell;

#[derive(Debug, clap::Args)]
pub struct Args {
    /// The Memory Stick directory (the one containing OPEN-R/)
    #[arg(value_name = "MS_DIR")]
    ms_dir: PathBuf,
    /// Stop cleanly after this much virtual time (e.g. 5s, 250ms, 2m)
    #[arg(long = "for", value_name = "DURATION", value_parser = parse_duration)]
    run_for: Option<Duration>,
    /// Robot design: selects [ERS-…] sections of the CFG files and GetRobotDesign() (default ERS-7; see `cargo openr config`)
    #[arg(long)]
    design: Option<String>,
    /// Skip CONNECT.CFG lines that name unknown services (the robot's behaviour) instead of failing
    #[arg(long)]
    lenient_connect: bool,
    /// Virtual-time speed: a factor of real time (1 = real time, 4, 0.5) or `max` (as fast as the objects keep up)
    #[arg(long)]
    speed: Option<String>,
    /// Serve pause / resume / step / speed / status commands on this Unix socket
    #[arg(long, value_name = "PATH")]
    control: Option<PathBuf>,
    /// Let external robot peers (simulator, recorder, real-robot bridge) attach on this Unix socket (docs/robot-protocol.md)
    #[arg(long, value_name = "PATH")]
    robot_socket: Option<PathBuf>,
    /// Let robot peers attach on this loopback TCP address (127.0.0.1:PORT; port 0 picks one)
    #[arg(long, value_name = "ADDR", value_parser = parse_loopback)]
    robot_tcp: Option<std::net::SocketAddr>,
    /// Run no frame before a robot peer owning the clock (lockstep) has attached
    #[arg(long)]
    robot_wait: bool,
    /// Write what the speaker plays to this WAV file
    #[arg(long, value_name = "FILE")]
    speaker_wav: Option<PathBuf>,
    /// Feed the microphones from this WAV file (default: silence)
    #[arg(long, value_name = "FILE")]
    mic_wav: Option<PathBuf>,
    /// Camera images from this PPM/BMP file, or the frames of this directory (in name order), instead of the rendered scene
    #[arg(long, value_name = "FILE|DIR")]
    images: Option<PathBuf>,
    /// Write the virtual robot's trace (JSON lines: commands, sensor frames, LEDs) to FILE
    #[arg(long, value_name = "FILE")]
    trace: Option<PathBuf>,
    /// SDK root providing the system objects (default: $OPENRSDK_ROOT if it is a cargo-openr root, else the per-user one, installed on first use)
    #[arg(long, value_name = "DIR")]
    sdk: Option<PathBuf>,
    /// No runtime diagnostics on stderr (object output is unaffected)
    #[arg(short, long)]
    quiet: bool,
    /// More runtime diagnostics on stderr
    #[arg(short, long)]
    verbose: bool,
    /// Host address the robot's network endpoints bind to (default 127.0.0.1)
    #[arg(long, value_name = "ADDR")]
    net_bind: Option<std::net::Ipv4Addr>,
    /// Add N to every port the robot binds (privileged ports first move to 10000+port), so two robots can run one program
    #[arg(long, value_name = "N", default_value_t = 0)]
    port_offset: u16,
}

fn parse_loopback(s: &str) -> Result<std::net::SocketAddr, String> {
    let a: std::net::SocketAddr = s.parse().map_err(|_| format!("`{s}` is not an address (try 127.0.0.1:7700)"))?;
    if !a.ip().is_loopback() {
        return Err(format!("`{s}`: robot peers attach on loopback addresses only (127.0.0.1, ::1)"));
    }
    Ok(a)
}

/// `5s`, `250ms`, `2m`, `1h`, or plain seconds (`1.5`).
pub fn parse_duration(s: &str) -> Result<Duration, String> {
    let s = s.trim();
    let (num, mult) = if let Some(n) = s.strip_suffix("ms") {
        (n, 1e-3)
    } else if let Some(n) = s.strip_suffix('s') {
        (n, 1.0)
    } else if let Some(n) = s.strip_suffix('m') {
        (n, 60.0)
    } else if let Some(n) = s.strip_suffix('h') {
        (n, 3600.0)
    } else {
        (s, 1.0)
    };
    let v: f64 = num.trim().parse().map_err(|_| format!("`{s}` is not a duration (try 5s, 250ms, 2m)"))?;
    if !(v.is_finite() && v >= 0.0) {
        return Err(format!("`{s}` is not a duration (try 5s, 250ms, 2m)"));
    }
    Ok(Duration::from_secs_f64(v * mult))
}

/// The SDK root whose system objects this run loads, as `ops::config` resolves it
/// (`--sdk`, `$OPENRSDK_ROOT` when it is one of ours, `openr.toml`, the per-user
/// default); installed or updated if needed.
fn sdk_root(root: PathBuf) -> anyhow::Result<PathBuf> {
    let exe = std::env::current_exe().context("cannot locate the cargo-openr executable")?;
    install::install(&root, &exe).with_context(|| format!("cannot prepare the SDK root {}", root.display()))?;
    Ok(root)
}

pub fn exec(args: Args, shell: &mut Shell) -> anyhow::Result<()> {
    sdk_runtime::net::config::apply_cli(args.net_bind, args.port_offset);
    let project = args.ms_dir.parent().map(PathBuf::from);
    let cfg = config::resolve(&ConfigInputs { sdk: args.sdk.clone(), design: args.design.clone(), speed: args.speed.clone(), project })?;
    let root = sdk_root(cfg.sdk.value)?;
    let opts = RunOptions {
        system_objects: install::system_objects(&root),
        trace: args.trace.clone(),
        speed: cfg.speed.value,
        speaker_wav: args.speaker_wav.clone(),
        mic_wav: args.mic_wav.clone(),
        images: args.images.clone(),
        control: args.control.clone(),
        peers: sdk_runtime::peer::PeerOptions { socket: args.robot_socket.clone(), tcp: args.robot_tcp, wait: args.robot_wait },
        ms_dir: args.ms_dir.clone(),
        design: cfg.design.value,
        run_for: args.run_for,
        diag: Diag { quiet: args.quiet, verbose: args.verbose },
        lenient_connect: args.lenient_connect,
    };
    if !args.quiet {
        shell.status("Running", &args.ms_dir.display().to_string());
    }
    let outcome = boot::run(&opts).with_context(|| format!("cannot run {}", args.ms_dir.display()))?;
    if !args.quiet {
        let how = match outcome.ended {
            Ended::TimeUp => "time limit reached".to_string(),
            Ended::Signal(s) => format!("signal {s}"),
            Ended::Shutdown => "OPENR::Shutdown".to_string(),
        };
        shell.status(
            "Finished",
            &format!("{} ({how}; {} frames, {} late)", args.ms_dir.display(), outcome.frames, outcome.late_frames),
        );
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::parse_duration;
    use std::time::Duration;

    #[test]
    fn durations() {
        assert_eq!(parse_duration("5s"), Ok(Duration::from_secs(5)));
        assert_eq!(parse_duration("250ms"), Ok(Duration::from_millis(250)));
        assert_eq!(parse_duration("2m"), Ok(Duration::from_secs(120)));
        assert_eq!(parse_duration("1.5"), Ok(Duration::from_millis(1500)));
        assert!(parse_duration("soon").is_err());
        assert!(parse_duration("-1s").is_err());
    }
}
