//! `cargo openr run <MS dir>`: boot a Memory Stick tree on the host.
use std::ffi::OsString;
use std::path::{Path, PathBuf};
use std::time::Duration;

use anyhow::Context;
use openr_ipstack::config::{self as net_config, NetOptions};
use openr_wrappers::install;
use sdk_runtime::boot::{self, Ended, RunOptions};
use sdk_runtime::runtime::Diag;

use crate::ops::child_args::Forward;
use crate::ops::config::{self, ConfigInputs};
use crate::ops::debugger::{self, Debugger};
use crate::ops::{sdk, sim};
use crate::shell::Shell;

#[derive(Debug, clap::Args)]
pub struct Args {
    /// The Memory Stick directory (the one containing OPEN-R/); with --sim mujoco, one per robot
    #[arg(value_name = "MS_DIR", required = true, num_args = 1..)]
    ms_dirs: Vec<PathBuf>,
    /// Simulator: the built-in kinematic ERS-7, or `mujoco` (physics, cameras rendered from a 3-D scene; needs what `tools/deps.sh` installs)
    #[arg(long, value_enum, default_value_t = Sim::Builtin)]
    sim: Sim,
    /// MuJoCo scene: field, objects and `start<k>` sites for the robots (default: the SDK root's sim/mujoco/scene.xml)
    #[arg(long, value_name = "FILE")]
    scene: Option<PathBuf>,
    /// Robots in the MuJoCo world, each running its own runtime (default: one per MS_DIR; extra robots run the last MS_DIR)
    #[arg(long, value_name = "N")]
    robots: Option<usize>,
    /// Seed of the simulator's sensor noise (same seed, programs and scene: the same run, byte for byte)
    #[arg(long, value_name = "N")]
    seed: Option<u64>,
    /// Pass an option to the MuJoCo peer (see sim/mujoco/peer.py --help), e.g. --sim-arg=--ball=0.3,0
    #[arg(long = "sim-arg", value_name = "ARG", allow_hyphen_values = true)]
    sim_args: Vec<String>,
    /// Stop cleanly after this much virtual time (e.g. 5s, 250ms, 2m)
    #[arg(long = "for", value_name = "DURATION", value_parser = parse_duration)]
    run_for: Option<Duration>,
    /// Robot design: selects [ERS-…] sections of the CFG files and GetRobotDesign() (default ERS-7; see `cargo openr config`)
    #[arg(long)]
    design: Option<String>,
    /// Base tree of the SDK root laid under MS_DIR, as a robot's stick has it: BASIC, WLAN or WCONSOLE, optionally /memprot or /nomemprot, or none (default WCONSOLE/nomemprot; see `cargo openr config`)
    #[arg(long, value_name = "KIND[/PROT]")]
    base: Option<String>,
    /// Run under gdb (pending breakpoints on, the pause signal passed; see README "Debugging")
    #[arg(long, conflicts_with = "valgrind")]
    gdb: bool,
    /// Run under valgrind with the runtime's suppressions: memcheck (default), helgrind, drd, …
    #[arg(long, value_name = "TOOL", num_args = 0..=1, default_missing_value = "memcheck", require_equals = true)]
    valgrind: Option<String>,
    /// An argument for the tool of --gdb / --valgrind (repeatable), e.g. --tool-arg=-batch
    #[arg(long = "tool-arg", value_name = "ARG", allow_hyphen_values = true)]
    tool_args: Vec<String>,
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
    /// Serve a live view of the robot in the browser on ADDR (default 127.0.0.1:0: a free loopback port; printed as `Viewing http://ADDR/`)
    #[arg(long, value_name = "ADDR", num_args = 0..=1, default_missing_value = "127.0.0.1:0", value_parser = parse_view_addr)]
    view: Option<std::net::SocketAddr>,
    /// Record the run into DIR: its trace, camera pictures and speaker sound (docs/recording.md), to replay with `cargo openr view DIR`
    #[arg(long, value_name = "DIR", conflicts_with = "trace")]
    record: Option<PathBuf>,
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
    /// Shift the camera's 30 fps image timing by MS milliseconds from boot: robots started at different moments take their pictures in different frames (with --sim, robot k adds (k mod 4) x 8 ms)
    #[arg(long, value_name = "MS", default_value_t = 0, value_parser = clap::value_parser!(u64).range(0..1000))]
    camera_phase: u64,
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
    /// Do not trap on floating-point errors (invalid operation, division by zero, overflow, denormal operand) as the robot's CPU does
    #[arg(long)]
    no_fp_traps: bool,
    /// Send what the robot addresses to ROBOT_IP[:PORT] to HOST_IP[:PORT] instead, e.g. 10.0.1.2=127.0.0.1 for a program with its server's LAN address built in (repeatable)
    #[arg(long = "net-map", value_name = "ROBOT=HOST", value_parser = net_config::parse_addr_map)]
    net_map: Vec<net_config::AddrMap>,
    /// Real time an object may take to answer Init/Stop/Destroy or a connection, or to run one message at --speed max, before it is reported stuck (e.g. 5s, 500ms; 0.1 s to 1 h)
    #[arg(long, value_name = "DURATION", default_value = "5s", value_parser = parse_watchdog)]
    watchdog: Duration,
    /// Add N to every port the robot binds (privileged ports first move to 10000+port), so two robots can run one program
    #[arg(long, value_name = "N", default_value_t = 0)]
    port_offset: u16,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
enum Sim {
    /// the kinematic ERS-7 of the runtime (no install)
    Builtin,
    /// MuJoCo physics (sim/mujoco)
    Mujoco,
}

fn parse_loopback(s: &str) -> Result<std::net::SocketAddr, String> {
    let a: std::net::SocketAddr = s.parse().map_err(|_| format!("`{s}` is not an address (try 127.0.0.1:7700)"))?;
    if !a.ip().is_loopback() {
        return Err(format!("`{s}`: robot peers attach on loopback addresses only (127.0.0.1, ::1)"));
    }
    Ok(a)
}

fn parse_view_addr(s: &str) -> Result<std::net::SocketAddr, String> {
    // `--view` takes the next word when it can: `run --view MS` would read MS as ADDR.
    s.parse().map_err(|_| format!("`{s}` is not an address (try 127.0.0.1:8080); for the default address, give MS_DIR before --view"))
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
    Duration::try_from_secs_f64(v * mult).map_err(|_| format!("`{s}` is too long a duration (at most {} s)", Duration::MAX.as_secs()))
}

fn parse_watchdog(s: &str) -> Result<Duration, String> {
    let d = parse_duration(s)?;
    if !(Duration::from_millis(100)..=Duration::from_secs(3600)).contains(&d) {
        return Err(format!("`{s}` is out of range: give 0.1 s to 1 h"));
    }
    Ok(d)
}

pub fn exec(args: Args, given: &clap::ArgMatches, shell: &mut Shell) -> anyhow::Result<()> {
    shell.set_quiet(args.quiet);
    let world = check_sim_options(&args)?;
    let ms_dir = args.ms_dirs[0].clone();
    if args.sim != Sim::Mujoco && boot::is_rp_host_program(&ms_dir) {
        // Before the view's server or anything else starts a thread.
        std::env::set_var("OPENR_RP_HOST", "1");
    }
    let project = ms_dir.parent().map(PathBuf::from);
    let cfg = config::resolve(&ConfigInputs {
        sdk: args.sdk.clone(),
        design: args.design.clone(),
        speed: args.speed.clone(),
        base: args.base.clone(),
        project,
        ..Default::default()
    })?;
    // The SDK root whose system objects this run loads, as `ops::config` resolves it
    // (`--sdk`, `$OPENRSDK_ROOT` when it is one of ours, `openr.toml`, the per-user default).
    let root = cfg.sdk.value;
    sdk::prepare(&root, shell)?;
    if args.sim == Sim::Mujoco {
        return simulate(&args, given, &world, &root, shell);
    }
    let ms_base = base_tree(&root, &cfg.design.value, &cfg.base.value)?;
    let (observers, trace) = observers(&args)?;
    let opts = RunOptions {
        ms_base,
        system_objects: install::system_objects(&root),
        trace,
        speed: cfg.speed.value,
        speaker_wav: args.speaker_wav.clone(),
        mic_wav: args.mic_wav.clone(),
        images: args.images.clone(),
        camera_phase_ms: args.camera_phase,
        control: args.control.clone(),
        peers: sdk_runtime::peer::PeerOptions { socket: args.robot_socket.clone(), tcp: args.robot_tcp, wait: args.robot_wait },
        observers,
        ms_dir: ms_dir.clone(),
        design: cfg.design.value,
        run_for: args.run_for,
        diag: Diag::new(args.quiet, args.verbose).with_report(shell.reporter()),
        lenient_connect: args.lenient_connect,
        fp_traps: !args.no_fp_traps,
        watchdog: args.watchdog,
        net: NetOptions {
            bind: args.net_bind,
            port_offset: args.port_offset,
            addr_map: args.net_map.clone(),
            port_map: std::env::var(net_config::ENV_PORT_MAP).map(|s| net_config::parse_port_map(&s)).unwrap_or_default(),
            trace: std::env::var_os(net_config::ENV_TRACE).is_some_and(|v| v != "0"),
        },
    };
    if let Some(tool) = args.gdb.then_some(Debugger::Gdb).or_else(|| args.valgrind.clone().map(Debugger::Valgrind)) {
        let mut cmd = debugger::command(&tool, &root, &args.tool_args, &["--gdb", "--valgrind", "--tool-arg"])?;
        let status = cmd.status().with_context(|| format!("cannot start {:?}", cmd.get_program()))?;
        // The tool's status is the run's (memcheck's error exit, gdb's, the runtime's).
        return match status.code() {
            Some(0) => Ok(()),
            code => Err(crate::shell::ChildStatus(code.and_then(|c| u8::try_from(c).ok()).unwrap_or(1)).into()),
        };
    }
    let sanitizers = crate::ops::sanitize::needed(&ms_dir);
    if let Some(env) = crate::ops::sanitize::environment(&sanitizers, std::env::var("LD_PRELOAD").ok().as_deref())? {
        let names: Vec<&str> = sanitizers.iter().map(|s| s.name()).collect();
        shell.status("Restarting", &format!("with the {} sanitizer runtime preloaded (objects built with --sanitize)", names.join(", ")));
        return Err(crate::ops::sanitize::reexec(env));
    }
    shell.status("Running", &ms_dir.display().to_string());
    let outcome = boot::run(&opts).with_context(|| format!("cannot run {}", ms_dir.display()))?;
    let how = match outcome.ended {
        Ended::TimeUp => "time limit reached".to_string(),
        Ended::Signal(s) => format!("signal {s}"),
        Ended::Shutdown => "OPENR::Shutdown".to_string(),
        Ended::Fatal(_) => "OPENR::Fatal".to_string(),
    };
    shell.status("Finished", &format!("{} ({how}; {} frames, {} late)", ms_dir.display(), outcome.frames, outcome.late_frames));
    if !outcome.failures.is_empty() {
        anyhow::bail!("the run failed:\n  {}", outcome.failures.join("\n  "));
    }
    Ok(())
}

/// The run's observers (`--view`, `--record`) and the trace file (`--trace`, or the
/// recording's).
fn observers(args: &Args) -> anyhow::Result<(sdk_runtime::observe::Observers, Option<PathBuf>)> {
    let mut observers = sdk_runtime::observe::Observers::default();
    if let Some(addr) = args.view {
        let view = openr_view::View::bind(addr).map_err(anyhow::Error::msg)?;
        // As soon as it listens: a browser may connect while the objects load.
        eprintln!("Viewing http://{}/", view.addr());
        observers.0.push(std::sync::Arc::new(view));
    }
    let mut trace = args.trace.clone();
    if let Some(dir) = &args.record {
        let recorder = openr_view::record::Recorder::create(dir).map_err(anyhow::Error::msg)?;
        trace = Some(recorder.trace_path());
        observers.0.push(std::sync::Arc::new(recorder));
    }
    Ok((observers, trace))
}

/// The directory of the base tree `base` in the SDK root (`None` for `none`).
fn base_tree(root: &Path, design: &str, base: &str) -> anyhow::Result<Option<PathBuf>> {
    if base == "none" {
        return Ok(None);
    }
    let dir = install::base_tree(root, design, base);
    if !dir.join("OPEN-R").is_dir() {
        anyhow::bail!(
            "the SDK root {} has no base tree {base} ({} is missing): reinstall it with `cargo openr sdk install`",
            root.display(),
            dir.join("OPEN-R").display()
        );
    }
    Ok(Some(dir))
}

/// One robot of the MuJoCo world: the MS_DIR its runtime boots and the address its
/// network endpoints bind to.
struct Robot<'a> {
    ms: &'a Path,
    ip: std::net::Ipv4Addr,
}

/// Options that only make sense with the MuJoCo simulator, and those it owns itself;
/// with `--sim mujoco`, the robots of the world (none otherwise).
fn check_sim_options(args: &Args) -> anyhow::Result<Vec<Robot<'_>>> {
    if args.sim != Sim::Mujoco {
        let given = [
            (args.ms_dirs.len() > 1, "several MS_DIRs"),
            (args.scene.is_some(), "--scene"),
            (args.robots.is_some(), "--robots"),
            (args.seed.is_some(), "--seed"),
            (!args.sim_args.is_empty(), "--sim-arg"),
        ];
        if let Some((_, what)) = given.iter().find(|(g, _)| *g) {
            anyhow::bail!("{what} needs a simulated world: add `--sim mujoco`");
        }
        return Ok(Vec::new());
    }
    if args.robot_socket.is_some() || args.robot_tcp.is_some() || args.robot_wait {
        anyhow::bail!("--sim mujoco attaches the simulator itself: drop --robot-socket/--robot-tcp/--robot-wait");
    }
    let robots = args.robots.unwrap_or(args.ms_dirs.len());
    if robots < args.ms_dirs.len() || robots == 0 || robots > 30 {
        anyhow::bail!("--robots {robots}: give 1 to 30 robots, at least one per MS_DIR ({} given)", args.ms_dirs.len());
    }
    if let Some(scene) = &args.scene {
        if !scene.is_file() {
            anyhow::bail!("--scene {}: no such file", scene.display());
        }
    }
    // Robot k runs MS_DIR k (the last one for the rest), on its own address on loopback
    // (127.0.0.1, .2, …) with the same ports.
    let base_ip = args.net_bind.unwrap_or(std::net::Ipv4Addr::LOCALHOST);
    let mut world = Vec::new();
    for k in 0..robots {
        let ip = u32::from(base_ip).checked_add(k as u32).map(std::net::Ipv4Addr::from);
        let Some(ip) = ip.filter(|ip| ip.is_loopback() == base_ip.is_loopback()) else {
            anyhow::bail!("--net-bind {base_ip}: no room for {robots} consecutive robot addresses");
        };
        world.push(Robot { ms: &args.ms_dirs[k.min(args.ms_dirs.len() - 1)], ip });
    }
    Ok(world)
}

/// What `--sim mujoco` does with an option of `run` for the robots' runtimes: every
/// option not named here is passed on as given (`ops::child_args`).
fn to_child(id: &str) -> Forward {
    match id {
        // the world's own (the peer gets them), refused with --sim mujoco, or given below
        "ms_dirs" | "sim" | "scene" | "robots" | "seed" | "sim_args" | "gdb" | "valgrind" | "tool_args" | "view" | "record" | "robot_socket" | "robot_tcp"
        | "robot_wait" | "sdk" => Forward::Caller,
        // per robot
        "trace" | "camera_phase" | "net_bind" | "control" | "speaker_wav" | "mic_wav" => Forward::Caller,
        _ => Forward::Same,
    }
}

/// Robot k's runtime: `run MS --sdk ROOT`, every option given to us (`to_child`), and
/// what differs per robot (`record`: its directory of a world recording).
fn child_args(args: &Args, given: &clap::ArgMatches, k: usize, robot: &Robot, root: &Path, record: Option<&Path>) -> Vec<OsString> {
    use clap::Args as _;
    let mut a: Vec<OsString> = vec![robot.ms.into(), "--sdk".into(), root.into()];
    a.extend(crate::ops::child_args::forwarded(&Args::augment_args(clap::Command::new("run")), given, to_child));
    let mut opt = |name: &str, v: Option<OsString>| {
        if let Some(v) = v {
            a.push(name.into());
            a.push(v);
        }
    };
    opt("--trace", args.trace.as_ref().map(|t| per_robot(t, k).into()));
    // Cameras of neighbouring robots a frame apart: the simulator draws a quarter of
    // them per frame, alongside the physics step, instead of all every fourth frame.
    let phase = (args.camera_phase + (k as u64 % 4) * 8) % 1000;
    opt("--camera-phase", (phase != 0).then(|| phase.to_string().into()));
    // The world's pause button and the sound files belong to robot 0: pausing one
    // runtime holds the lockstep of all.
    if k == 0 {
        opt("--control", args.control.clone().map(Into::into));
        opt("--speaker-wav", args.speaker_wav.clone().map(Into::into));
        opt("--mic-wav", args.mic_wav.clone().map(Into::into));
    }
    opt("--net-bind", Some(robot.ip.to_string().into()));
    // Each runtime serves its robot's view on loopback; the world's page (ours) passes it on.
    opt("--view", args.view.map(|_| "127.0.0.1:0".into()));
    opt("--record", record.map(Into::into));
    a
}

/// `--sim mujoco`: each robot of `world` in its own runtime; the peer in the SDK root
/// simulates them all.
fn simulate(args: &Args, given: &clap::ArgMatches, world: &[Robot], root: &Path, shell: &mut Shell) -> anyhow::Result<()> {
    let robots = world.len();
    // The simulator's ground truth and field: the recording's, else (for the view) a
    // scratch directory's for the run.
    let scratch = tempfile::Builder::new().prefix("cargo-openr-world").tempdir().context("cannot create a scratch directory")?;
    let mut pictures = None;
    let (dirs, truth, field) = match &args.record {
        Some(dir) => {
            let (dirs, [truth, field, field_camera]) = openr_view::record::create_world(dir, robots).map_err(anyhow::Error::msg)?;
            pictures = Some(field_camera);
            (dirs.into_iter().map(Some).collect(), truth, field)
        }
        None => {
            // The user's own --sim-arg=--state=FILE stays theirs; the view follows it.
            let given = args.sim_args.iter().rev().find_map(|a| a.strip_prefix("--state=")).map(PathBuf::from);
            (vec![None; robots], given.unwrap_or_else(|| scratch.path().join("world.jsonl")), scratch.path().join("field.json"))
        }
    };
    let mut plans = Vec::new();
    for (k, robot) in world.iter().enumerate() {
        plans.push(child_args(args, given, k, robot, root, dirs[k].as_deref()));
    }
    let mut view = None;
    if let Some(addr) = args.view {
        let server = openr_view::View::bind(addr).map_err(anyhow::Error::msg)?;
        let camera = scratch.path().join("field.png");
        let live = std::sync::Arc::new(openr_view::world::Live::new(robots, field.clone(), truth.clone(), camera));
        server.world(live.clone()).map_err(anyhow::Error::msg)?;
        eprintln!("Viewing http://{}/", server.addr());
        view = Some(live); // the server's threads answer until the command ends
    }
    let mut peer_args: Vec<OsString> = Vec::new();
    if let Some(scene) = &args.scene {
        peer_args.extend(["--scene".into(), scene.into()]);
    }
    peer_args.extend(["--seed".into(), args.seed.unwrap_or(0).to_string().into()]);
    if args.images.is_some() {
        peer_args.push("--no-camera".into()); // the runtime's --images are the camera
    }
    if args.quiet {
        peer_args.push("--quiet".into());
    }
    peer_args.extend(args.sim_args.iter().map(Into::into));
    if args.view.is_some() || args.record.is_some() {
        // After the user's --sim-arg: the view and the recording need these files.
        peer_args.push(format!("--state={}", truth.display()).into());
        peer_args.push(format!("--field={}", field.display()).into());
    }
    if args.view.is_some() {
        peer_args.push(format!("--field-camera={}", scratch.path().join("field.png").display()).into());
    }
    if let Some(dir) = &pictures {
        peer_args.push(format!("--field-pictures={}", dir.display()).into());
    }
    let plan = sim::Plan { python: sim::python(), peer: root.join(install::SIM_DIR).join("peer.py"), peer_args, robots: plans, view };
    let what = if robots == 1 { "1 robot".to_string() } else { format!("{robots} robots") };
    shell.status("Simulating", &format!("{} in MuJoCo ({what})", args.ms_dirs[0].display()));
    sim::run(&plan)
}

/// `t.jsonl` for robot 0 (so for a single robot), `t.r1.jsonl` for robot 1, …
fn per_robot(path: &Path, k: usize) -> PathBuf {
    if k == 0 {
        return path.to_path_buf();
    }
    let stem = path.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default();
    let name = match path.extension() {
        Some(e) => format!("{stem}.r{k}.{}", e.to_string_lossy()),
        None => format!("{stem}.r{k}"),
    };
    path.with_file_name(name)
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
        assert!(parse_duration("1e300s").unwrap_err().contains("too long"));
    }

    #[test]
    fn sim_children_get_every_option_given_and_their_own_per_robot_values() {
        use clap::{Args as _, FromArgMatches};
        let argv = [
            "run",
            "A/MS",
            "B/MS",
            "--sim",
            "mujoco",
            "--seed",
            "7",
            "--for",
            "10s",
            "--speed",
            "max",
            "--trace",
            "t.jsonl",
            "--control",
            "c.sock",
            "--quiet",
            "--net-map",
            "10.0.1.2=127.0.0.1",
            "--net-map",
            "10.0.1.3:80=127.0.0.1:8080",
            "--no-fp-traps",
            "--base",
            "WLAN",
            "--watchdog",
            "2s",
            "--port-offset",
            "100",
            "--design",
            "ERS-7",
        ];
        let given = super::Args::augment_args(clap::Command::new("run")).try_get_matches_from(argv).unwrap();
        let args = super::Args::from_arg_matches(&given).unwrap();
        let world = super::check_sim_options(&args).unwrap();
        let child = |k: usize| -> Vec<String> {
            super::child_args(&args, &given, k, &world[k], std::path::Path::new("/sdk"), None).iter().map(|a| a.to_string_lossy().into_owned()).collect()
        };
        let (c0, c1) = (child(0), child(1));
        for c in [&c0, &c1] {
            for want in [
                "--for=10s",
                "--speed=max",
                "--quiet",
                "--net-map=10.0.1.2=127.0.0.1",
                "--net-map=10.0.1.3:80=127.0.0.1:8080",
                "--no-fp-traps",
                "--base=WLAN",
                "--watchdog=2s",
                "--port-offset=100",
                "--design=ERS-7",
                "--sdk",
                "/sdk",
            ] {
                assert!(c.iter().any(|a| a == want), "{want} missing from {c:?}");
            }
            // the world's own options stay with the parent
            assert!(!c.iter().any(|a| a.starts_with("--sim") || a.starts_with("--seed")) && !c[1..].iter().any(|a| a.ends_with("/MS")), "{c:?}");
        }
        assert_eq!(c0[0], "A/MS");
        assert_eq!(c1[0], "B/MS");
        assert!(c0.windows(2).any(|w| w == ["--trace", "t.jsonl"]) && c1.windows(2).any(|w| w == ["--trace", "t.r1.jsonl"]), "{c0:?} {c1:?}");
        assert!(c0.windows(2).any(|w| w == ["--control", "c.sock"]) && !c1.iter().any(|a| a.starts_with("--control")), "{c1:?}");
        assert!(c0.windows(2).any(|w| w == ["--net-bind", "127.0.0.1"]) && c1.windows(2).any(|w| w == ["--net-bind", "127.0.0.2"]));
        assert!(c1.windows(2).any(|w| w == ["--camera-phase", "8"]), "{c1:?}");
        // each option once: nothing forwarded twice by the rule and the per-robot code
        for flag in ["--trace", "--control", "--net-bind", "--camera-phase"] {
            assert!(c0.iter().filter(|a| a.starts_with(flag)).count() <= 1, "{flag} twice in {c0:?}");
        }
    }
}
