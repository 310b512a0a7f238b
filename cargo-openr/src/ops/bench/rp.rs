//! Remote Processing (`--only rp`): bench/programs/pingpong's notify→ready round trip with
//! Pong on the host — two processes, the robot's TCPGW.BIN and the host's gateway joined
//! by a loopback TCP channel, ready/notify forwarded end to end — beside the same two
//! objects on one robot and a raw TCP ping-pong of the gateway's own frames between two
//! threads (the machine's limit), all three in the same round.
use std::net::{TcpListener, TcpStream};
use std::path::Path;
use std::process::{Command, Stdio};
use std::time::Instant;

use anyhow::{bail, Context, Result};
use sdk_runtime::gateway::wire;

use super::network::Robot;
use super::stats::Table;
use super::{field, fields, run_ms};

const RP_P50: &str = "RP notify→ready round trip p50 (Ping on the robot, Pong on the host: gateways, loopback TCP)";
const RP_P99: &str = "RP notify→ready round trip p99 (Pong on the host)";
const RP_RATE: &str = "RP object messages per second (Pong on the host)";
const LOCAL_P50: &str = "RP's round trip p50 with both objects on the robot (same round)";
const LOCAL_P99: &str = "RP's round trip p99 with both objects on the robot (same round)";
const LOCAL_RATE: &str = "RP's object messages per second with both objects on the robot (same round)";
const TCP_P50: &str = "raw TCP ping-pong p50 (2 threads, loopback, the gateway's 9 B DATA / 5 B READY frames)";
const TCP_P99: &str = "raw TCP ping-pong p99";
const TCP_RATE: &str = "raw TCP messages per second";

/// One pingpong run's figures: p50 and p99 in µs, messages per second.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RoundTrip {
    pub p50_us: f64,
    pub p99_us: f64,
    pub rate: f64,
}

/// The `BENCH pingpong …` line Ping prints when it is done.
pub fn round_trip(out: &str) -> Result<RoundTrip> {
    let f = fields(out, "BENCH pingpong");
    let get = |k: &str| field(&f, k, out);
    Ok(RoundTrip { p50_us: get("p50_ns")? / 1000.0, p99_us: get("p99_ns")? / 1000.0, rate: get("msgs_per_sec")? })
}

/// The round's three measurements; `pingpong` is the built program's `MS/` (its `RP/`
/// sides are beside it).
pub fn rp(exe: &Path, root: &Path, pingpong: &Path, work: &Path, tab: &mut Table) -> Result<()> {
    let local = round_trip(&run_ms(exe, pingpong, root)?)?;
    let remote = split_run(exe, root, pingpong.parent().context("pingpong dir")?, work)?;
    let raw = raw_tcp_ping_pong(20_000)?;
    tab.push(RP_P50, remote.p50_us, "µs", Some(TCP_P50));
    tab.push(RP_P99, remote.p99_us, "µs", Some(TCP_P99));
    tab.push(RP_RATE, remote.rate, "msg/s", Some(TCP_RATE));
    tab.push(LOCAL_P50, local.p50_us, "µs", Some(TCP_P50));
    tab.push(LOCAL_P99, local.p99_us, "µs", Some(TCP_P99));
    tab.push(LOCAL_RATE, local.rate, "msg/s", Some(TCP_RATE));
    tab.push(TCP_P50, raw.p50_us, "µs", None);
    tab.push(TCP_P99, raw.p99_us, "µs", None);
    tab.push(TCP_RATE, raw.rate, "msg/s", None);
    Ok(())
}

/// A gateway CFG line with its port (second field) set to `port`; comments and lines
/// without a port stay as they are.
fn with_port(line: &str, port: u16) -> String {
    let mut f: Vec<String> = line.split_whitespace().map(str::to_string).collect();
    if line.starts_with('#') || f.len() < 2 {
        return line.to_string();
    }
    f[1] = port.to_string();
    f.join(" ")
}

/// Ping on the robot (`RP/robot/MS`, it shuts the robot down when done), Pong on the host
/// (`RP/host/MS`, stopped then); their gateways' port moved to a free one.
fn split_run(exe: &Path, root: &Path, dir: &Path, work: &Path) -> Result<RoundTrip> {
    let (robot_ms, host_ms) = (dir.join("RP/robot/MS"), dir.join("RP/host/MS"));
    let port = TcpListener::bind("127.0.0.1:0")?.local_addr()?.port();
    for f in [robot_ms.join("OPEN-R/MW/CONF/ROBOTGW.CFG"), host_ms.join("OPEN-R/MW/CONF/HOSTGW.CFG")] {
        let text = std::fs::read_to_string(&f).with_context(|| format!("cannot read {}", f.display()))?;
        // The port is a line's second field, whatever an earlier round set it to.
        let moved: String = text.lines().map(|l| format!("{}\n", with_port(l, port))).collect();
        std::fs::write(&f, moved)?;
    }
    let robot = Command::new(exe)
        .args(["run", "-q", "--for", "120s", "--sdk"])
        .arg(root)
        .arg(&robot_ms)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()?;
    let log = work.join("rp-host.log");
    let host = Command::new(exe)
        .args(["run", "-q", "--base", "none", "--sdk"])
        .arg(root)
        .arg(&host_ms)
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(std::fs::File::create(&log)?)
        .spawn()?;
    let host = Robot(host);
    let out = robot.wait_with_output()?;
    drop(host);
    let stdout = String::from_utf8_lossy(&out.stdout);
    if !out.status.success() || !stdout.contains("BENCH pingpong") {
        let host_log = std::fs::read_to_string(&log).unwrap_or_default();
        bail!("the RP pingpong did not finish:\nrobot: {stdout}{}\nhost: {host_log}", String::from_utf8_lossy(&out.stderr));
    }
    round_trip(&stdout)
}

/// The machine's limit for the gateway's round trip: one thread sends the DATA frame of
/// Ping's 4-byte ball, the other answers with a READY frame, over loopback TCP with
/// TCP_NODELAY as the gateway's channels, framed by the gateway's own code.
pub fn raw_tcp_ping_pong(rounds: usize) -> Result<RoundTrip> {
    const WARMUP: usize = 1000;
    let listener = TcpListener::bind("127.0.0.1:0")?;
    let addr = listener.local_addr()?;
    let echo = std::thread::spawn(move || -> std::io::Result<()> {
        let (mut s, _) = listener.accept()?;
        s.set_nodelay(true)?;
        while let Ok((wire::DATA, _)) = wire::read_frame(&mut s) {
            wire::write_frame(&mut s, wire::READY_ASSERT, &[])?;
        }
        Ok(())
    });
    let mut c = TcpStream::connect(addr)?;
    c.set_nodelay(true)?;
    let mut rtt = Vec::with_capacity(rounds);
    let mut start = Instant::now();
    for i in 0..WARMUP + rounds {
        if i == WARMUP {
            start = Instant::now();
        }
        let t = Instant::now();
        wire::write_frame(&mut c, wire::DATA, &(i as u32).to_le_bytes())?;
        let (kind, _) = wire::read_frame(&mut c)?;
        if kind != wire::READY_ASSERT {
            bail!("raw TCP ping-pong: frame type {kind} back");
        }
        if i >= WARMUP {
            rtt.push(t.elapsed().as_nanos() as f64 / 1000.0);
        }
    }
    let secs = start.elapsed().as_secs_f64();
    drop(c);
    let _ = echo.join();
    let (p50_us, p99_us) = super::stats::p50_p99(&mut rtt);
    Ok(RoundTrip { p50_us, p99_us, rate: 2.0 * rounds as f64 / secs })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_round_moves_the_gateway_port_again() {
        let first = with_port("TCPGateway.Ball.int.S 59002 127.0.0.1", 40001);
        assert_eq!(first, "TCPGateway.Ball.int.S 40001 127.0.0.1");
        assert_eq!(with_port(&first, 40002), "TCPGateway.Ball.int.S 40002 127.0.0.1", "a moved port moves again");
        assert_eq!(with_port("# port 59002", 40003), "# port 59002");
    }

    #[test]
    fn pingpong_line_gives_microseconds_and_rate() {
        let out = "SampleLine : other output\nBENCH pingpong round_trips=20000 p50_ns=91262 p99_ns=329544 msgs_per_sec=14497\n";
        assert_eq!(round_trip(out).unwrap(), RoundTrip { p50_us: 91.262, p99_us: 329.544, rate: 14497.0 });
        let e = round_trip("BENCH pingpong round_trips=20000 p50_ns=91262\n").unwrap_err().to_string();
        assert!(e.starts_with("no p99_ns in:"), "{e}");
        assert!(round_trip("nothing here\n").is_err());
    }

    #[test]
    fn raw_tcp_ping_pong_measures_every_round() {
        let r = raw_tcp_ping_pong(200).unwrap();
        assert!(r.p50_us > 0.0 && r.p50_us <= r.p99_us && r.rate > 0.0, "{r:?}");
    }
}
