//! `cargo openr run --sim mujoco`: one runtime process per robot (each its own address
//! space, symbol namespace and /MS), all attached to one MuJoCo peer that owns their
//! clocks in lockstep and simulates them in one shared world.
use std::ffi::OsString;
use std::io::{BufRead, BufReader, Read, Write};
use std::os::unix::process::CommandExt;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, ExitStatus, Stdio};
use std::sync::{Arc, Mutex};
use std::time::Duration;

use anyhow::{bail, Context};

/// The MuJoCo release the simulator is written and measured against (`tools/deps.sh` installs it).
pub const MUJOCO_VERSION: &str = "4.0.0";

/// The Python that runs the simulator: `$OPENR_PYTHON`, else the venv `tools/deps.sh`
/// makes (`~/.cache/cargo-openr/mujoco-venv`), else `python3` from PATH.
pub fn python() -> PathBuf {
    if let Some(p) = std::env::var_os("OPENR_PYTHON").filter(|p| !p.is_empty()) {
        return PathBuf::from(p);
    }
    let venv = std::env::var_os("XDG_CACHE_HOME")
        .filter(|v| !v.is_empty())
        .map(PathBuf::from)
        .or_else(|| std::env::var_os("HOME").map(|h| PathBuf::from(h).join(".cache")))
        .map(|c| c.join("cargo-openr/mujoco-venv/bin/python"));
    match venv {
        Some(v) if v.is_file() => v,
        _ => PathBuf::from("python3"),
    }
}

/// The GL backend MuJoCo renders with: `$MUJOCO_GL`, else EGL (headless Mesa).
pub fn gl_backend() -> String {
    std::env::var("MUJOCO_GL").ok().filter(|v| !v.is_empty()).unwrap_or_else(|| "egl".into())
}

/// Imports mujoco and renders one tiny image offscreen: `mujoco X.Y.Z` when both work,
/// else what failed (the last line Python printed).
pub fn probe(python: &Path) -> Result<String, String> {
    const SCRIPT: &str = "import mujoco\n\
        m = mujoco.MjModel.from_xml_string('<mujoco><worldbody><geom size=\"1\"/></worldbody></mujoco>')\n\
        r = mujoco.Renderer(m, 8, 8); r.update_scene(mujoco.MjData(m)); r.render(); r.close()\n\
        print(mujoco.__version__)\n";
    let out = Command::new(python).args(["-c", SCRIPT]).env("MUJOCO_GL", gl_backend()).output();
    match out {
        Err(e) => Err(format!("cannot run {}: {e}", python.display())),
        Ok(o) if o.status.success() => Ok(format!("mujoco {}", String::from_utf8_lossy(&o.stdout).trim())),
        Ok(o) => {
            let err = String::from_utf8_lossy(&o.stderr);
            let last = err.lines().rev().find(|l| !l.trim().is_empty()).unwrap_or("failed").trim().to_string();
            Err(last)
        }
    }
}

/// What to start: the peer (script and options) and, per robot, the `run` arguments of
/// its runtime (without the robot socket, which is added here).
pub struct Plan {
    pub python: PathBuf,
    pub peer: PathBuf,
    pub peer_args: Vec<OsString>,
    pub robots: Vec<Vec<OsString>>,
    /// `--view`: the world's page, told where each robot's runtime serves its own view
    /// (the runtime's `Viewing http://ADDR/` line, kept off the console).
    pub view: Option<Arc<openr_view::world::Live>>,
}

/// Exit status of the peer when MuJoCo or offscreen GL is not usable (`UNAVAILABLE` in peer.py).
const PEER_UNAVAILABLE: i32 = 3;

fn unavailable(python: &Path, why: &str) -> anyhow::Error {
    anyhow::anyhow!(
        "the MuJoCo simulator cannot start: {} (MUJOCO_GL={}): {why}\n\
         help: install it with `tools/deps.sh` (pip mujoco=={MUJOCO_VERSION} in a venv, apt libegl1 libgl1-mesa-dri), \
         or point OPENR_PYTHON at a Python that has it; `cargo openr doctor` checks",
        python.display(),
        gl_backend()
    )
}

/// Runs the world until every runtime has ended. The peer checks MuJoCo and GL itself
/// before any robot attaches (no separate probe: importing MuJoCo costs ~1 s); when
/// anything fails, the rest is stopped rather than left waiting for its clock.
pub fn run(plan: &Plan) -> anyhow::Result<()> {
    let dir = tempfile::Builder::new().prefix("cargo-openr-sim").tempdir().context("cannot create a socket directory")?;
    let exe = crate::ops::sdk::exe()?;
    let labelled = plan.robots.len() > 1;
    let console = Arc::new(Mutex::new(()));
    let sockets: Vec<PathBuf> = (0..plan.robots.len()).map(|k| dir.path().join(format!("robot{k}.sock"))).collect();
    let mut cmd = Command::new(&plan.python);
    cmd.arg(&plan.peer).args(&plan.peer_args).args(&sockets).env("MUJOCO_GL", gl_backend());
    let mut peer = spawn(&mut cmd, false, false).map_err(|e| unavailable(&plan.python, &e.to_string()))?;
    let mut runtimes = Vec::new();
    let mut copiers = Vec::new();
    for (k, (args, sock)) in plan.robots.iter().zip(&sockets).enumerate() {
        let mut cmd = Command::new(&exe);
        cmd.arg("run").args(args).arg("--robot-socket").arg(sock).arg("--robot-wait");
        let mut child = match spawn(&mut cmd, labelled, labelled || plan.view.is_some()) {
            Ok(c) => c,
            Err(e) => {
                stop_all(std::iter::once(&mut peer).chain(&mut runtimes));
                return Err(e).with_context(|| format!("cannot start the runtime of robot {k}"));
            }
        };
        let tag = if labelled { format!("[robot {k}] ") } else { String::new() };
        if let Some(out) = child.stdout.take() {
            copiers.push(copy_lines(out, tag.clone(), Stream::Stdout, console.clone()));
        }
        if let Some(err) = child.stderr.take() {
            copiers.push(copy_lines(err, tag, Stream::Stderr(plan.view.clone().map(|v| (k, v))), console.clone()));
        }
        runtimes.push(child);
    }
    let failed = wait_all(std::iter::once(&mut peer).chain(&mut runtimes).collect());
    for c in copiers {
        let _ = c.join();
    }
    // Report the child that failed first: the others were stopped because of it.
    match failed {
        None => Ok(()),
        Some((0, s)) if s.code() == Some(PEER_UNAVAILABLE) => Err(unavailable(&plan.python, "see the peer's message above")),
        Some((0, s)) => bail!("the MuJoCo simulator failed ({s}); its messages are above"),
        Some((k, s)) => bail!("robot {}: the runtime failed ({s})", k - 1),
    }
}

/// Children end with us (PR_SET_PDEATHSIG), and leave Ctrl-C to the runtimes: they stop
/// on it, the peer then sees their connections close and ends by itself.
fn spawn(cmd: &mut Command, stdout: bool, stderr: bool) -> std::io::Result<Child> {
    if stdout {
        cmd.stdout(Stdio::piped());
    }
    if stderr {
        cmd.stderr(Stdio::piped());
    }
    // SAFETY: prctl is async-signal-safe; nothing else runs between fork and exec.
    unsafe {
        cmd.pre_exec(|| {
            libc::prctl(libc::PR_SET_PDEATHSIG, libc::SIGTERM);
            Ok(())
        });
    }
    cmd.spawn()
}

/// Waits for every child (the peer first, then the runtimes); the first one that fails
/// stops the others — a runtime without its peer, or a peer without a runtime to
/// attach to, would otherwise wait forever. Returns that first failure (index, status).
fn wait_all(mut children: Vec<&mut Child>) -> Option<(usize, ExitStatus)> {
    // SAFETY: ignoring SIGINT in this process only; children set their own handlers.
    unsafe { libc::signal(libc::SIGINT, libc::SIG_IGN) };
    let mut done: Vec<bool> = vec![false; children.len()];
    let mut first_failure = None;
    while done.iter().any(|d| !d) {
        for (k, (c, d)) in children.iter_mut().zip(&mut done).enumerate() {
            if let Some(status) = (!*d).then(|| c.try_wait().ok().flatten()).flatten() {
                *d = true;
                if !status.success() && first_failure.is_none() {
                    first_failure = Some((k, status));
                    stop_all(children.iter_mut().map(|c| &mut **c));
                    break;
                }
            }
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    first_failure
}

fn stop_all<'a>(children: impl IntoIterator<Item = &'a mut Child>) {
    for c in children {
        if c.try_wait().ok().flatten().is_none() {
            // SAFETY: plain kill(2) of our own child.
            unsafe { libc::kill(c.id() as i32, libc::SIGTERM) };
        }
    }
}

/// Which of a robot's outputs a copier carries.
enum Stream {
    Stdout,
    /// Robot k's stderr, with the world view to tell where the robot's own view listens.
    Stderr(Option<(usize, Arc<openr_view::world::Live>)>),
}

/// Copies a robot's output line by line with its tag, so lines of robots never mix;
/// its `Viewing` line goes to the world's view instead.
fn copy_lines(from: impl Read + Send + 'static, tag: String, stream: Stream, console: Arc<Mutex<()>>) -> std::thread::JoinHandle<()> {
    std::thread::spawn(move || {
        for line in BufReader::new(from).split(b'\n').map_while(Result::ok) {
            if let Stream::Stderr(Some((k, view))) = &stream {
                let addr = std::str::from_utf8(&line).ok().and_then(|l| l.strip_prefix("Viewing http://")?.strip_suffix('/')?.parse().ok());
                if let Some(addr) = addr {
                    view.robot_listening(*k, addr);
                    continue;
                }
            }
            let stderr = matches!(stream, Stream::Stderr(_));
            let _guard = console.lock().unwrap();
            let mut text = tag.clone().into_bytes();
            text.extend_from_slice(&line);
            text.push(b'\n');
            let _ = if stderr { std::io::stderr().write_all(&text) } else { std::io::stdout().write_all(&text) };
        }
    })
}
