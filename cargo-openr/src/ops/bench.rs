//! `cargo openr bench`: measures the runtime's hot paths with real objects built from
//! `bench/programs/`, next to what the machine can do without OPEN-R (a raw two-thread
//! ping-pong over the same kind of queue) in the same run.
use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::mpsc;
use std::time::Instant;

use anyhow::{bail, Context, Result};

/// One measured figure.
#[derive(Debug, Clone)]
pub struct Figure {
    pub name: String,
    pub value: f64,
    pub unit: &'static str,
}

/// Builds `program` (a directory with an aggregate Makefile) in `work` with the SDK root.
fn build(program: &Path, work: &Path, root: &Path) -> Result<PathBuf> {
    let dst = work.join(program.file_name().context("program dir")?);
    let _ = std::fs::remove_dir_all(&dst);
    let st = Command::new("cp").arg("-r").arg(program).arg(&dst).status()?;
    if !st.success() {
        bail!("cannot copy {}", program.display());
    }
    // bench/programs include ../../common.mk relative to their object directories.
    let common = program.parent().context("parent")?.join("common.mk");
    if common.exists() {
        std::fs::copy(common, work.join("common.mk"))?;
    }
    let out = Command::new("make").arg(format!("OPENRSDK_ROOT={}", root.display())).arg("install").current_dir(&dst).output()?;
    if !out.status.success() {
        bail!("building {} failed:\n{}{}", program.display(), String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr));
    }
    Ok(dst.join("MS"))
}

fn run_ms(exe: &Path, ms: &Path, root: &Path) -> Result<String> {
    let out = Command::new(exe).args(["run", "-q", "--for", "120s", "--sdk"]).arg(root).arg(ms).output()?;
    if !out.status.success() {
        bail!("running {} failed:\n{}", ms.display(), String::from_utf8_lossy(&out.stderr));
    }
    Ok(String::from_utf8_lossy(&out.stdout).into_owned())
}

/// `key=value` fields of the first stdout line starting with `prefix`.
fn fields(out: &str, prefix: &str) -> Vec<(String, f64)> {
    out.lines()
        .filter(|l| l.starts_with(prefix))
        .flat_map(|l| l.split_whitespace())
        .filter_map(|kv| kv.split_once('='))
        .filter_map(|(k, v)| Some((k.to_string(), v.parse().ok()?)))
        .collect()
}

fn monotonic_ns() -> i64 {
    let mut ts = libc::timespec { tv_sec: 0, tv_nsec: 0 };
    unsafe { libc::clock_gettime(libc::CLOCK_MONOTONIC, &mut ts) };
    ts.tv_sec * 1_000_000_000 + ts.tv_nsec
}

/// The machine's limit for a message round trip between two threads over std's
/// channel (the queue every object has): p50 and p99 in ns, and messages per second.
pub fn raw_ping_pong(rounds: usize) -> (f64, f64, f64) {
    let (to_b, from_a) = mpsc::channel::<u32>();
    let (to_a, from_b) = mpsc::channel::<u32>();
    let echo = std::thread::spawn(move || {
        while let Ok(v) = from_a.recv() {
            if to_a.send(v).is_err() {
                break;
            }
        }
    });
    let mut rtt = Vec::with_capacity(rounds);
    let start = Instant::now();
    for i in 0..rounds as u32 {
        let t = Instant::now();
        to_b.send(i).expect("echo thread alive");
        from_b.recv().expect("echo thread alive");
        rtt.push(t.elapsed().as_nanos() as f64);
    }
    let secs = start.elapsed().as_secs_f64();
    drop(to_b);
    let _ = echo.join();
    rtt.sort_by(|a, b| a.total_cmp(b));
    (rtt[rounds / 2], rtt[rounds * 99 / 100], 2.0 * rounds as f64 / secs)
}

/// Runs `n` runtimes on `ms` at once for 10 s; returns (frames, late frames) summed.
fn robots_in_real_time(exe: &Path, ms: &Path, root: &Path, n: usize) -> Result<(u64, u64)> {
    let children: Vec<_> = (0..n)
        .map(|_| Command::new(exe).args(["run", "--for", "10s", "--sdk"]).arg(root).arg(ms).stdout(std::process::Stdio::null()).stderr(std::process::Stdio::piped()).spawn())
        .collect::<std::io::Result<_>>()?;
    let (mut frames, mut late) = (0, 0);
    for c in children {
        let out = c.wait_with_output()?;
        let err = String::from_utf8_lossy(&out.stderr);
        let line = err.lines().find(|l| l.contains("Finished")).with_context(|| format!("no summary in:\n{err}"))?;
        let num = |suffix: &str| -> Option<u64> {
            let before = line.split(suffix).next()?;
            before.rsplit(|c: char| !c.is_ascii_digit()).find(|w| !w.is_empty())?.parse().ok()
        };
        frames += num(" frames").context("frame count")?;
        late += num(" late").context("late count")?;
    }
    Ok((frames, late))
}

/// Runs every benchmark; `repo` holds `bench/programs`, `root` is an installed SDK root.
pub fn run_all(exe: &Path, repo: &Path, root: &Path, work: &Path) -> Result<Vec<Figure>> {
    let programs = repo.join("bench/programs");
    let mut figs = Vec::new();
    let mut fig = |name: &str, value: f64, unit: &'static str| figs.push(Figure { name: name.into(), value, unit });

    let ms = build(&programs.join("pingpong"), work, root)?;
    let out = run_ms(exe, &ms, root)?;
    let f = fields(&out, "BENCH pingpong");
    let get = |k: &str| f.iter().find(|(n, _)| n == k).map(|(_, v)| *v).with_context(|| format!("no {k} in:\n{out}"));
    fig("notify→ready round trip p50 (2 objects)", get("p50_ns")? / 1000.0, "µs");
    fig("notify→ready round trip p99 (2 objects)", get("p99_ns")? / 1000.0, "µs");
    fig("object messages per second", get("msgs_per_sec")?, "msg/s");
    let (p50, p99, rate) = raw_ping_pong(20_000);
    fig("raw two-thread channel ping-pong p50", p50 / 1000.0, "µs");
    fig("raw two-thread channel ping-pong p99", p99 / 1000.0, "µs");
    fig("raw channel messages per second", rate, "msg/s");

    let ms = build(&programs.join("coldstart"), work, root)?;
    let t0 = monotonic_ns();
    let out = Command::new(exe).args(["run", "-q", "--for", "0.2s", "--sdk"]).arg(root).arg(&ms).output()?;
    if !out.status.success() {
        bail!("coldstart run failed: {}", String::from_utf8_lossy(&out.stderr));
    }
    let stdout = String::from_utf8_lossy(&out.stdout);
    let starts: Vec<f64> = fields(&stdout, "BENCH coldstart").into_iter().map(|(_, v)| v).collect();
    if starts.len() != 10 {
        bail!("expected 10 DoStart lines, got {}:\n{stdout}", starts.len());
    }
    let last = starts.iter().copied().fold(f64::MIN, f64::max);
    fig("cold start to the 10th DoStart (10 objects, process spawn included)", (last - t0 as f64) / 1e6, "ms");

    // Virtual time: the leg program of the corpus, 60 s of robot time at --speed max.
    let ms = build(&repo.join("testdata/programs/movelegs"), work, root)?;
    let t = std::time::Instant::now();
    let out = Command::new(exe).args(["run", "-q", "--speed", "max", "--for", "60s", "--sdk"]).arg(root).arg(&ms).output()?;
    if !out.status.success() {
        bail!("movelegs at --speed max failed: {}", String::from_utf8_lossy(&out.stderr));
    }
    fig("movelegs: virtual-time speed-up at --speed max (60 s of robot time)", 60.0 / t.elapsed().as_secs_f64(), "×");

    // Real time: how regular the 32 ms sensor vectors arrive at an object.
    let ms = build(&programs.join("sensorjitter"), work, root)?;
    let out = run_ms(exe, &ms, root)?;
    let f = fields(&out, "BENCH jitter");
    let get = |k: &str| f.iter().find(|(n, _)| n == k).map(|(_, v)| *v).with_context(|| format!("no {k} in:\n{out}"));
    fig("sensor period jitter |Δt − 32 ms| p50 (real time, 1000 vectors)", get("p50_ns")? / 1000.0, "µs");
    fig("sensor period jitter |Δt − 32 ms| p99", get("p99_ns")? / 1000.0, "µs");

    // Many robots: N runtimes at once, each with the camera at 30 fps and an object that
    // reads every image and sensor vector, 10 s of real time.
    let ms = build(&programs.join("camwatch"), work, root)?;
    let mut best = 0;
    for n in [1usize, 2, 3, 4, 6, 8] {
        let (frames, late) = robots_in_real_time(exe, &ms, root, n)?;
        let pct = 100.0 * late as f64 / frames.max(1) as f64;
        fig(&format!("{n} ERS-7(s) with camera in real time: late frames"), pct, "%");
        if pct < 0.1 {
            best = n;
        }
    }
    fig("ERS-7s with camera running in real time with < 0.1% late frames", best as f64, "robots");
    Ok(figs)
}
