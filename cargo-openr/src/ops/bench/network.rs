//! Networking through a robot (IPStack): TCP echo round trips through the EchoServer
//! robot and FTP RETR throughput from the ftpd robot, each beside the same client talking
//! to a plain host server in the same run.
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

use anyhow::{bail, Result};

use super::build;
use super::stats::Table;
/// A runtime on `ms` (with `--port-offset` when started here), killed (SIGTERM) when dropped.
pub(super) struct Robot(pub(super) std::process::Child);

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
        // SAFETY: kill touches no memory; the child is not reaped yet (waited just below), so the pid is still its.
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
    Ok(super::stats::p50_p99(&mut rtt))
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
    let nums: Vec<u16> =
        pasv.rsplit(' ').next().unwrap_or("").trim().trim_matches(|c| c == '(' || c == ')' || c == '.').split(',').filter_map(|n| n.parse().ok()).collect();
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

/// How the host FTP server sends a file.
#[derive(Clone, Copy)]
enum Retr {
    /// `std::io::copy`, which Linux makes a `sendfile`: what a host server does.
    Sendfile,
    /// What the ftpd program does: an 8 KiB read, then an 8 KiB send, on a socket with
    /// TCP_NODELAY (as the robot's IP stack sets): the same work without the runtime.
    Chunks,
}

/// The ftpd program's `FTP_BUFFER_SIZE`.
const FTPD_CHUNK: usize = 8192;

/// A plain host FTP server (USER, PASS, TYPE, PASV, RETR of one file, QUIT) for the
/// same client; returns its control port.
fn host_ftp_server(file: PathBuf, how: Retr) -> Result<u16> {
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
                            let mut f = std::fs::File::open(&file)?;
                            match how {
                                Retr::Sendfile => drop(std::io::copy(&mut f, &mut d)?),
                                Retr::Chunks => {
                                    use std::io::Read;
                                    d.set_nodelay(true)?;
                                    let mut buf = [0u8; FTPD_CHUNK];
                                    loop {
                                        let n = f.read(&mut buf)?;
                                        if n == 0 {
                                            break;
                                        }
                                        d.write_all(&buf[..n])?;
                                    }
                                }
                            }
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

const ECHO_ROBOT_P50: &str = "TCP echo round trip through the EchoServer robot p50 (64 B)";
const ECHO_ROBOT_P99: &str = "TCP echo round trip through the EchoServer robot p99";
const ECHO_HOST_P50: &str = "TCP echo round trip through a plain host echo server p50";
const ECHO_HOST_P99: &str = "TCP echo round trip through a plain host echo server p99";
const FTP_ROBOT: &str = "FTP RETR of 64 MiB from the ftpd robot (8 KiB sends)";
const FTP_HOST: &str = "FTP RETR of 64 MiB from a plain host FTP server";
const FTP_ROBOT_LIKE: &str = "FTP RETR from the ftpd robot, beside a host server doing ftpd's 8 KiB reads and sends";
const FTP_HOST_CHUNKS: &str = "FTP RETR of 64 MiB from a host server doing ftpd's 8 KiB reads and sends (TCP_NODELAY)";

/// Echo round trips through the tcp-echo robot and bytes per second through the ftpd
/// robot, each next to the same client and a plain host server in the same run.
pub fn network(exe: &Path, repo: &Path, root: &Path, work: &Path, tab: &mut Table) -> Result<()> {
    const OFFSET: u16 = 900;

    let ms = build(&repo.join("testdata/programs/tcp-echo"), work, root)?;
    let robot = Robot::start(exe, root, &ms, OFFSET)?;
    let (p50, p99) = echo_rtt(54321 + OFFSET, 5000)?;
    drop(robot);
    tab.push(ECHO_ROBOT_P50, p50, "µs", Some(ECHO_HOST_P50));
    tab.push(ECHO_ROBOT_P99, p99, "µs", Some(ECHO_HOST_P99));
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
    tab.push(ECHO_HOST_P50, p50, "µs", None);
    tab.push(ECHO_HOST_P99, p99, "µs", None);

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
    tab.push(FTP_ROBOT, rate / 1e6, "MB/s", Some(FTP_HOST));
    tab.push(FTP_ROBOT_LIKE, rate / 1e6, "MB/s", Some(FTP_HOST_CHUNKS));
    let port = host_ftp_server(big.clone(), Retr::Sendfile)?;
    let rate = ftp_retr(port, 0, "BIG.BIN")?;
    tab.push(FTP_HOST, rate / 1e6, "MB/s", None);
    let port = host_ftp_server(big, Retr::Chunks)?;
    let rate = ftp_retr(port, 0, "BIG.BIN")?;
    tab.push(FTP_HOST_CHUNKS, rate / 1e6, "MB/s", None);
    Ok(())
}
