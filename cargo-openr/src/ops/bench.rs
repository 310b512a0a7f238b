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

/// The value of `key` among `fields`, or an error quoting the program's output.
fn field(fields: &[(String, f64)], key: &str, out: &str) -> Result<f64> {
    fields.iter().find(|(n, _)| n == key).map(|(_, v)| *v).with_context(|| format!("no {key} in:\n{out}"))
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
    let get = |k: &str| field(&f, k, &out);
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
    let get = |k: &str| field(&f, k, &out);
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
    network(exe, repo, root, work, &mut figs)?;
    Ok(figs)
}

// ---------------------------------------------------------------- network (IPStack)

/// A runtime on `ms` with `--port-offset`, killed (SIGTERM) when dropped.
struct Robot(std::process::Child);

impl Robot {
    fn start(exe: &Path, root: &Path, ms: &Path, offset: u16) -> Result<Robot> {
        let child = Command::new(exe)
            .args(["run", "-q", "--port-offset", &offset.to_string(), "--sdk"])
            .arg(root)
            .arg(ms)
            .stdout(std::process::Stdio::null())
            .stdin(std::process::Stdio::null())
            .spawn()?;
        Ok(Robot(child))
    }
}

impl Drop for Robot {
    fn drop(&mut self) {
        unsafe { libc::kill(self.0.id() as i32, libc::SIGTERM) };
        let _ = self.0.wait();
    }
}

/// Connects, retrying while the robot boots.
fn connect_retry(port: u16) -> Result<std::net::TcpStream> {
    let start = Instant::now();
    loop {
        match std::net::TcpStream::connect(("127.0.0.1", port)) {
            Ok(s) => {
                s.set_nodelay(true)?;
                s.set_read_timeout(Some(std::time::Duration::from_secs(20)))?;
                return Ok(s);
            }
            Err(e) if start.elapsed().as_secs() > 30 => bail!("cannot connect to port {port}: {e}"),
            Err(_) => std::thread::sleep(std::time::Duration::from_millis(50)),
        }
    }
}

/// Round trips of a 64-byte record: (p50, p99) in µs.
fn echo_rtt(port: u16, rounds: usize) -> Result<(f64, f64)> {
    use std::io::{Read, Write};
    let mut s = connect_retry(port)?;
    let msg = [0x5au8; 64];
    let mut back = [0u8; 64];
    let mut rtt = Vec::with_capacity(rounds);
    for i in 0..rounds + 100 {
        let t = Instant::now();
        s.write_all(&msg)?;
        s.read_exact(&mut back)?;
        if i >= 100 {
            rtt.push(t.elapsed().as_nanos() as f64 / 1000.0);
        }
    }
    rtt.sort_by(|a, b| a.total_cmp(b));
    Ok((rtt[rounds / 2], rtt[rounds * 99 / 100]))
}

/// `RETR name` in passive mode (the 227 port plus `pasv_offset`): bytes per second.
fn ftp_retr(port: u16, pasv_offset: u16, name: &str) -> Result<f64> {
    use std::io::{BufRead, BufReader, Read, Write};
    let ctrl = connect_retry(port)?;
    let mut w = ctrl.try_clone()?;
    let mut r = BufReader::new(ctrl);
    let mut reply = |expect: &str| -> Result<String> {
        let mut line = String::new();
        r.read_line(&mut line)?;
        if !line.starts_with(expect) {
            bail!("FTP: expected {expect}, got {line:?}");
        }
        Ok(line)
    };
    reply("220")?;
    for (cmd, code) in [("USER anonymous", "331"), ("PASS anonymous", "230"), ("TYPE I", "200")] {
        w.write_all(format!("{cmd}\r\n").as_bytes())?;
        reply(code)?;
    }
    w.write_all(b"PASV\r\n")?;
    let pasv = reply("227")?;
    let nums: Vec<u16> = pasv.rsplit(' ').next().unwrap_or("").trim().trim_matches(|c| c == '(' || c == ')' || c == '.').split(',').filter_map(|n| n.parse().ok()).collect();
    if nums.len() != 6 {
        bail!("bad 227 line {pasv:?}");
    }
    let data_port = (nums[4] << 8 | nums[5]) + pasv_offset;
    let t = Instant::now();
    let mut data = connect_retry(data_port)?;
    w.write_all(format!("RETR {name}\r\n").as_bytes())?;
    reply("150")?;
    let mut buf = vec![0u8; 1 << 16];
    let mut total = 0usize;
    loop {
        let n = data.read(&mut buf)?;
        if n == 0 {
            break;
        }
        total += n;
    }
    let secs = t.elapsed().as_secs_f64();
    reply("226")?;
    let _ = w.write_all(b"QUIT\r\n");
    Ok(total as f64 / secs)
}

/// A plain host FTP server (USER, PASS, TYPE, PASV, RETR of one file, QUIT) for the
/// same client; returns its control port.
fn host_ftp_server(file: PathBuf) -> Result<u16> {
    use std::io::{BufRead, BufReader, Write};
    let listener = std::net::TcpListener::bind("127.0.0.1:0")?;
    let port = listener.local_addr()?.port();
    std::thread::spawn(move || {
        for conn in listener.incoming().flatten() {
            let file = file.clone();
            std::thread::spawn(move || -> std::io::Result<()> {
                let mut w = conn.try_clone()?;
                let mut r = BufReader::new(conn);
                w.write_all(b"220 host ready\r\n")?;
                let mut pasv: Option<std::net::TcpListener> = None;
                let mut line = String::new();
                while r.read_line(&mut line)? > 0 {
                    let cmd = line.split_whitespace().next().unwrap_or("").to_ascii_uppercase();
                    match cmd.as_str() {
                        "USER" => w.write_all(b"331 ok\r\n")?,
                        "PASS" => w.write_all(b"230 ok\r\n")?,
                        "TYPE" => w.write_all(b"200 ok\r\n")?,
                        "PASV" => {
                            let l = std::net::TcpListener::bind("127.0.0.1:0")?;
                            let p = l.local_addr()?.port();
                            pasv = Some(l);
                            w.write_all(format!("227 Entering Passive Mode. 127,0,0,1,{},{}\r\n", p >> 8, p & 0xff).as_bytes())?;
                        }
                        "RETR" => {
                            let (mut d, _) = pasv.take().expect("PASV first").accept()?;
                            w.write_all(b"150 data\r\n")?;
                            std::io::copy(&mut std::fs::File::open(&file)?, &mut d)?;
                            drop(d);
                            w.write_all(b"226 done\r\n")?;
                        }
                        _ => {
                            w.write_all(b"221 bye\r\n")?;
                            break;
                        }
                    }
                    line.clear();
                }
                Ok(())
            });
        }
    });
    Ok(port)
}

/// Echo round trips through the tcp-echo robot and bytes per second through the ftpd
/// robot, each next to the same client and a plain host server in the same run.
fn network(exe: &Path, repo: &Path, root: &Path, work: &Path, figs: &mut Vec<Figure>) -> Result<()> {
    let mut fig = |name: &str, value: f64, unit: &'static str| figs.push(Figure { name: name.into(), value, unit });
    const OFFSET: u16 = 900;

    let ms = build(&repo.join("testdata/programs/tcp-echo"), work, root)?;
    let robot = Robot::start(exe, root, &ms, OFFSET)?;
    let (p50, p99) = echo_rtt(54321 + OFFSET, 5000)?;
    drop(robot);
    fig("TCP echo round trip through the EchoServer robot p50 (64 B)", p50, "µs");
    fig("TCP echo round trip through the EchoServer robot p99", p99, "µs");
    let plain = std::net::TcpListener::bind("127.0.0.1:0")?;
    let plain_port = plain.local_addr()?.port();
    std::thread::spawn(move || {
        use std::io::{Read, Write};
        for mut c in plain.incoming().flatten() {
            let _ = c.set_nodelay(true);
            let mut buf = [0u8; 4096];
            while let Ok(n) = c.read(&mut buf) {
                if n == 0 || c.write_all(&buf[..n]).is_err() {
                    break;
                }
            }
        }
    });
    let (p50, p99) = echo_rtt(plain_port, 5000)?;
    fig("TCP echo round trip through a plain host echo server p50", p50, "µs");
    fig("TCP echo round trip through a plain host echo server p99", p99, "µs");

    let ms = build(&repo.join("testdata/programs/ftpd"), work, root)?;
    let big = ms.join("BIG.BIN");
    let block: Vec<u8> = (0..1 << 20).map(|i: u32| (i % 253) as u8).collect();
    let mut f = std::fs::File::create(&big)?;
    for _ in 0..64 {
        std::io::Write::write_all(&mut f, &block)?;
    }
    drop(f);
    let robot = Robot::start(exe, root, &ms, OFFSET + 1)?;
    let rate = ftp_retr(10021 + OFFSET + 1, OFFSET + 1, "BIG.BIN")?;
    drop(robot);
    fig("FTP RETR of 64 MiB from the ftpd robot (8 KiB sends)", rate / 1e6, "MB/s");
    let port = host_ftp_server(big)?;
    let rate = ftp_retr(port, 0, "BIG.BIN")?;
    fig("FTP RETR of 64 MiB from a plain host FTP server", rate / 1e6, "MB/s");
    Ok(())
}
