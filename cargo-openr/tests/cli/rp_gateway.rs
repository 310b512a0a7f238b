//! Remote Processing OPEN-R split over two processes (remote-processing 1.3, 6, 7.5):
//! an emulated robot running `TCPGW.BIN` and a host program with a HOSTGW.CFG, joined by
//! real TCP channels on loopback. Ports are picked free per test and written into copies
//! of the CFG files, so tests run side by side.
use std::fs;
use std::path::{Path, PathBuf};
use std::sync::OnceLock;
use std::time::{Duration, Instant};

use crate::rp::free_port;
use crate::support::{build, copy_tree, run_ms, spawn_ms, Built, Running};

/// Generous: the machine may be busy; each wait ends as soon as the output is there.
const PATIENCE: Duration = Duration::from_secs(90);

/// rp-objcomm-multi built once for every test of this file.
fn multi() -> &'static Path {
    static BUILT: OnceLock<Built> = OnceLock::new();
    let b = BUILT.get_or_init(|| build("rp-objcomm-multi"));
    Box::leak(b.dir.path().join("rp-objcomm-multi").into_boxed_path())
}

/// A copy of `from` (a side's directory holding MS/) in `to`, Sony's ports 59001.. moved
/// to `ports` in its gateway CFG file.
fn side(from: &Path, to: &Path, ports: &[u16]) -> PathBuf {
    copy_tree(from, to);
    let conf = to.join("MS/OPEN-R/MW/CONF");
    for f in ["ROBOTGW.CFG", "HOSTGW.CFG"] {
        let p = conf.join(f);
        let Ok(text) = fs::read_to_string(&p) else { continue };
        let moved = |f: &str| match f.parse::<usize>() {
            Ok(n) if (59001..59001 + ports.len()).contains(&n) => ports[n - 59001].to_string(),
            _ => f.to_string(),
        };
        let lines: Vec<String> =
            text.lines().map(|l| if l.starts_with('#') { l.to_string() } else { l.split_whitespace().map(moved).collect::<Vec<_>>().join(" ") }).collect();
        fs::write(&p, lines.join("\n") + "\n").unwrap();
    }
    to.join("MS")
}

fn ports(n: usize) -> Vec<u16> {
    // Held together while picking, so the n ports differ.
    let held: Vec<std::net::TcpListener> = (0..n).map(|_| std::net::TcpListener::bind("127.0.0.1:0").unwrap()).collect();
    held.iter().map(|l| l.local_addr().unwrap().port()).collect()
}

/// Waits until the run's stderr contains `needle`.
fn wait_stderr(r: &Running, needle: &str) -> bool {
    let start = Instant::now();
    while start.elapsed() < PATIENCE {
        if r.stderr().contains(needle) {
            return true;
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    false
}

fn robot(ms: &Path) -> Running {
    spawn_ms(ms, &["--for", "600s"], &[])
}

fn host(ms: &Path, extra: &[&str]) -> Running {
    let mut args = vec!["--base", "none", "--for", "600s"];
    args.extend_from_slice(extra);
    spawn_ms(ms, &args, &[])
}

fn sorted(lines: impl Iterator<Item = String>) -> Vec<String> {
    let mut v: Vec<String> = lines.collect();
    v.sort();
    v
}

/// What the observers of ObjectComm-multi print, whichever side they run on.
fn observer_lines() -> Vec<String> {
    let mut want = Vec::new();
    for (obs, from) in [(1, 1), (2, 1), (3, 1), (3, 2)] {
        for k in 1..=2 {
            want.push(format!("SampleObserver{obs}::Notify() !!! Hello from SampleSubject{from} (#{k}) !!!"));
        }
    }
    want.sort();
    want
}

fn wait_lines(r: &mut Running, prefix: &str, n: usize) -> Vec<String> {
    let start = Instant::now();
    loop {
        let got: Vec<String> = r.stdout().lines().filter(|l| l.starts_with(prefix)).map(str::to_string).collect();
        if got.len() >= n || start.elapsed() > PATIENCE {
            return sorted(got.into_iter());
        }
        std::thread::sleep(Duration::from_millis(20));
    }
}

/// RP2: subjects on the robot, observers on the host; every observer prints what it
/// prints when all five objects run in one process.
#[test]
fn rp2_subjects_on_the_robot_feed_observers_on_the_host() {
    let tmp = tempfile::tempdir().unwrap();
    let p = ports(5);
    let r_ms = side(&multi().join("RP2/robot"), &tmp.path().join("robot"), &p);
    let h_ms = side(&multi().join("RP2/host"), &tmp.path().join("host"), &p);
    let rob = robot(&r_ms);
    assert!(wait_stderr(&rob, "Running"), "{}", rob.stderr());
    let mut h = host(&h_ms, &[]);
    let got = wait_lines(&mut h, "SampleObserver", 8);
    let h_out = h.stop();
    assert_eq!(got, observer_lines(), "host:\n{}\n{}", h_out.stdout, h_out.stderr);
    assert!(h_out.stderr.contains(&format!("HOSTGW.CFG:5: channel {}: connected to robot 127.0.0.1:{}", p[1], p[1])), "{}", h_out.stderr);
    let r_out = rob.stop();
    assert_eq!(r_out.code, Some(0), "{}", r_out.stderr);
    let sent = sorted(r_out.stdout.lines().filter(|l| l.contains(": send #")).map(str::to_string));
    let want: Vec<String> = sorted(
        [
            "SampleSubject1 : send #1 to 3 observer(s)",
            "SampleSubject1 : send #2 to 3 observer(s)",
            "SampleSubject2 : send #1 to 1 observer(s)",
            "SampleSubject2 : send #2 to 1 observer(s)",
        ]
        .iter()
        .map(|s| s.to_string()),
    );
    assert_eq!(sent, want, "{}", r_out.stdout);
    assert!(r_out.stderr.contains("ROBOTGW.CFG:5: channel") && r_out.stderr.contains("connected (TCPGateway.ReceiveString11.char.S"), "{}", r_out.stderr);
}

/// `dskip=1` on a gateway observer line is that observer's `SetBufCtrlParam(1, 1, 1)`:
/// the subject on the robot passes it every second notification, so the host's
/// SampleObserver1 sees SampleSubject1's #2 only; the other connections are unchanged.
#[test]
fn dskip_on_a_gateway_observer_line_passes_every_second_notification() {
    let tmp = tempfile::tempdir().unwrap();
    let p = ports(5);
    let r_ms = side(&multi().join("RP2/robot"), &tmp.path().join("robot"), &p);
    let gw = r_ms.join("OPEN-R/MW/CONF/ROBOTGW.CFG");
    let text = fs::read_to_string(&gw)
        .unwrap()
        .replace(&format!("TCPGateway.SendString11.char.O {}", p[1]), &format!("TCPGateway.SendString11.char.O {} dskip=1", p[1]));
    assert!(text.contains("dskip=1"), "{text}");
    fs::write(&gw, text).unwrap();
    let h_ms = side(&multi().join("RP2/host"), &tmp.path().join("host"), &p);
    let rob = robot(&r_ms);
    assert!(wait_stderr(&rob, "Running"), "{}", rob.stderr());
    let mut h = host(&h_ms, &[]);
    let got = wait_lines(&mut h, "SampleObserver", 7);
    // Past the 7 lines: nothing else may come.
    std::thread::sleep(Duration::from_millis(500));
    let h_out = h.stop();
    let got_all = sorted(h_out.stdout.lines().filter(|l| l.starts_with("SampleObserver")).map(str::to_string));
    let want: Vec<String> = observer_lines().into_iter().filter(|l| l != "SampleObserver1::Notify() !!! Hello from SampleSubject1 (#1) !!!").collect();
    assert_eq!(got, want, "host:\n{}\n{}", h_out.stdout, h_out.stderr);
    assert_eq!(got_all, want, "host:\n{}", h_out.stdout);
    let r_out = rob.stop();
    assert!(!r_out.stderr.contains("dskip"), "a valid option is not warned about:\n{}", r_out.stderr);
}

/// RP3, the mirror: subjects on the host, observers on the robot.
#[test]
fn rp3_subjects_on_the_host_feed_observers_on_the_robot() {
    let tmp = tempfile::tempdir().unwrap();
    let p = ports(5);
    let r_ms = side(&multi().join("RP3/robot"), &tmp.path().join("robot"), &p);
    let h_ms = side(&multi().join("RP3/host"), &tmp.path().join("host"), &p);
    let mut rob = robot(&r_ms);
    let h = host(&h_ms, &[]);
    let got = wait_lines(&mut rob, "SampleObserver", 8);
    let h_out = h.stop();
    let r_out = rob.stop();
    assert_eq!(got, observer_lines(), "robot:\n{}\n{}\nhost:\n{}", r_out.stdout, r_out.stderr, h_out.stderr);
    assert!(h_out.stdout.contains("SampleSubject1 : send #2 to 3 observer(s)"), "{}", h_out.stdout);
    assert_eq!(h_out.code, Some(0), "{}", h_out.stderr);
}

/// RP2-BAD: both subjects share one robot port and one host gateway subject feeds all
/// observers: both sides warn at start-up, and data reaches every host observer.
#[test]
fn one_gateway_port_for_several_connections_is_warned_about() {
    let tmp = tempfile::tempdir().unwrap();
    let p = ports(2);
    let r_ms = side(&multi().join("RP2-BAD/robot"), &tmp.path().join("robot"), &p);
    let h_ms = side(&multi().join("RP2-BAD/host"), &tmp.path().join("host"), &p);
    for (from, to) in [("RP2/robot", &r_ms), ("RP2/host", &h_ms)] {
        copy_tree(&multi().join(from).join("MS/OPEN-R/MW/OBJS"), &to.join("OPEN-R/MW/OBJS"));
    }
    let rob = robot(&r_ms);
    let mut h = host(&h_ms, &[]);
    // Which subject's channel the shared port carries depends on which connects first
    // (the -BAD shape): data must still reach the observer, from either subject.
    let fan_out = h.wait_for("SampleObserver1::Notify() !!! Hello from SampleSubject", PATIENCE);
    let h_out = h.stop();
    let r_out = rob.stop();
    assert!(fan_out, "host:\n{}\n{}", h_out.stdout, h_out.stderr);
    assert!(
        r_out.stderr.contains("CONNECT.CFG:4: gateway service TCPGateway.SendString11.char.O")
            && r_out.stderr.contains("is in 2 connections (lines 4, 7): one channel carries one subject-observer connection"),
        "{}",
        r_out.stderr
    );
    assert!(h_out.stderr.contains("CONNECT.CFG:4: gateway service TCPGateway.ReceiveString11.char.S"), "{}", h_out.stderr);
    assert!(h_out.stderr.contains("is in 3 connections (lines 4, 5, 6)"), "{}", h_out.stderr);
}

/// A robot MS whose only object is the gateway, with this ROBOTGW.CFG.
fn gateway_only_robot(dir: &Path, robotgw: &str) -> PathBuf {
    let conf = dir.join("MS/OPEN-R/MW/CONF");
    fs::create_dir_all(&conf).unwrap();
    fs::write(conf.join("OBJECT.CFG"), "/MS/OPEN-R/SYSTEM/OBJS/TCPGW.BIN\n").unwrap();
    fs::write(conf.join("ROBOTGW.CFG"), robotgw).unwrap();
    dir.join("MS")
}

/// A host object's GetRobotDesign answers the robot's design through the API proxy
/// (remote-processing 7.4): rp-hostapi's host object against an ERS-210 robot.
#[test]
fn get_robot_design_on_the_host_answers_the_robots_design() {
    let built = build("rp-hostapi");
    let tmp = tempfile::tempdir().unwrap();
    let port = ports(1)[0];
    let r_ms = gateway_only_robot(&tmp.path().join("robot"), &format!("TCPGateway.Proxy.AperiosMessage.P {port}\n"));
    let h_ms = tmp.path().join("host/MS");
    copy_tree(&built.dir.path().join("rp-hostapi/RP/host/MS"), &h_ms);
    fs::write(h_ms.join("OPEN-R/MW/CONF/HOSTGW.CFG"), format!("!ROBOT_PROXY {port} 127.0.0.1\n")).unwrap();
    let rob = spawn_ms(&r_ms, &["--for", "600s", "--design", "ERS-210"], &[]);
    assert!(wait_stderr(&rob, "Running"), "{}", rob.stderr());
    let mut h = host(&h_ms, &[]);
    let asked = h.wait_for("HostApi: GetRobotDesign", PATIENCE);
    let h_out = h.stop();
    rob.stop();
    assert!(asked, "{}\n{}", h_out.stdout, h_out.stderr);
    assert!(h_out.stdout.contains("HostApi: GetRobotDesign ok (ERS-210)"), "the host runs as an ERS-7:\n{}\n{}", h_out.stdout, h_out.stderr);
}

/// With no robot behind the proxy line, GetRobotDesign is oFAIL (after the proxy's
/// connect wait), said once on stderr — not the host's own design.
#[test]
fn get_robot_design_on_the_host_fails_while_the_robot_is_unreachable() {
    let built = build("rp-hostapi");
    let tmp = tempfile::tempdir().unwrap();
    let port = ports(1)[0]; // free: nothing listens there
    let h_ms = tmp.path().join("host/MS");
    copy_tree(&built.dir.path().join("rp-hostapi/RP/host/MS"), &h_ms);
    fs::write(h_ms.join("OPEN-R/MW/CONF/HOSTGW.CFG"), format!("!ROBOT_PROXY {port} 127.0.0.1\n")).unwrap();
    let mut h = host(&h_ms, &[]);
    let asked = h.wait_for("HostApi: GetRobotDesign", PATIENCE);
    let h_out = h.stop();
    assert!(asked, "{}\n{}", h_out.stdout, h_out.stderr);
    assert!(h_out.stdout.contains("HostApi: GetRobotDesign failed"), "{}\n{}", h_out.stdout, h_out.stderr);
    assert_eq!(h_out.stderr.matches("the robot's OPEN-R API proxy is not reachable").count(), 1, "{}", h_out.stderr);
}

/// A host MS with no objects of its own, with this HOSTGW.CFG.
fn gateway_only_host(dir: &Path, hostgw: &str) -> PathBuf {
    let conf = dir.join("MS/OPEN-R/MW/CONF");
    fs::create_dir_all(&conf).unwrap();
    fs::write(conf.join("OBJECT.CFG"), "").unwrap();
    fs::write(conf.join("HOSTGW.CFG"), hostgw).unwrap();
    dir.join("MS")
}

#[test]
fn bad_robotgw_lines_fail_the_robot_with_file_and_line() {
    let tmp = tempfile::tempdir().unwrap();
    let ms = gateway_only_robot(tmp.path(), "# robot\nTCPGateway.Proxy.AperiosMessage.P 59001\nTCPGateway.Cam.Frame.Q 59002\n");
    let out = run_ms(&ms, &["--for", "1s", "--speed", "max"]);
    assert_ne!(out.code, Some(0));
    assert!(out.stderr.contains("ROBOTGW.CFG:3: `TCPGateway.Cam.Frame.Q` is not a gateway service `<Object>.<Service>.<DataType>.S|O`"), "{}", out.stderr);
    // A port that is taken: the line that wanted it.
    let taken = std::net::TcpListener::bind("127.0.0.1:0").unwrap();
    let port = taken.local_addr().unwrap().port();
    fs::write(ms.join("OPEN-R/MW/CONF/ROBOTGW.CFG"), format!("\nTCPGateway.Cam.Frame.O {port}\n")).unwrap();
    let out = run_ms(&ms, &["--for", "1s", "--speed", "max"]);
    assert_ne!(out.code, Some(0));
    assert!(out.stderr.contains(&format!("ROBOTGW.CFG:2: cannot listen on 127.0.0.1:{port} for channel {port}")), "{}", out.stderr);
    // Two lines on one port.
    fs::write(ms.join("OPEN-R/MW/CONF/ROBOTGW.CFG"), "TCPGateway.A.char.O 59002\nTCPGateway.B.char.S 59002\n").unwrap();
    let out = run_ms(&ms, &["--for", "1s", "--speed", "max"]);
    assert!(out.stderr.contains("ROBOTGW.CFG:2: port 59002 is already line 1: one channel per port"), "{}", out.stderr);
}

#[test]
fn a_host_line_without_an_address_needs_the_proxy_line() {
    let tmp = tempfile::tempdir().unwrap();
    let ms = gateway_only_host(tmp.path(), "TCPGateway.Cam.Frame.S 59002\n");
    let out = run_ms(&ms, &["--base", "none", "--for", "1s", "--speed", "max"]);
    assert_ne!(out.code, Some(0));
    assert!(out.stderr.contains("HOSTGW.CFG:1: no robot address, and no `!ROBOT_PROXY` line to take it from"), "{}", out.stderr);
}

/// Nobody listens: the host says so (and keeps trying) and its run fails at the end.
#[test]
fn an_unreachable_robot_is_reported_and_fails_the_host_run() {
    let tmp = tempfile::tempdir().unwrap();
    let port = free_port();
    let ms = gateway_only_host(tmp.path(), &format!("# no robot here\nTCPGateway.Cam.Frame.S {port} 127.0.0.1\n"));
    // Real time: the tries are on the gateway's thread, virtual time does not wait for them.
    let out = run_ms(&ms, &["--base", "none", "--for", "3s"]);
    assert_ne!(out.code, Some(0), "{}", out.stderr);
    assert!(out.stderr.contains(&format!("HOSTGW.CFG:2: robot 127.0.0.1:{port} not reachable")), "{}", out.stderr);
    assert!(out.stderr.contains(&format!("HOSTGW.CFG:2: channel {port} never reached the robot")), "{}", out.stderr);
}

/// A subject line meets a subject line: refused on both sides, naming both lines; the
/// host run fails, the robot keeps listening.
#[test]
fn a_subject_paired_with_a_subject_is_refused_on_both_sides() {
    let tmp = tempfile::tempdir().unwrap();
    let port = free_port();
    let r_ms = gateway_only_robot(&tmp.path().join("robot"), &format!("TCPGateway.Cmd.Order.S {port}\n"));
    let h_ms = gateway_only_host(&tmp.path().join("host"), &format!("\nTCPGateway.Cmd.Order.S {port} 127.0.0.1\n"));
    let rob = robot(&r_ms);
    let h = host(&h_ms, &[]);
    let refused = "TCPGateway.Cmd.Order.S is a subject (.S) and the far side's TCPGateway.Cmd.Order.S";
    assert!(wait_stderr(&h, refused), "{}", h.stderr());
    assert!(wait_stderr(&rob, refused), "{}", rob.stderr());
    let h_out = h.stop();
    let r_out = rob.stop();
    assert_ne!(h_out.code, Some(0));
    assert!(h_out.stderr.contains(&format!("HOSTGW.CFG:2: channel {port}: {refused} (")), "{}", h_out.stderr);
    assert!(h_out.stderr.contains("ROBOTGW.CFG:1) is a subject (.S) too"), "{}", h_out.stderr);
    assert!(r_out.stderr.contains(&format!("ROBOTGW.CFG:1: channel {port}: {refused} (")), "{}", r_out.stderr);
    assert_eq!(r_out.code, Some(0), "{}", r_out.stderr);
}

/// `(robot frame, J1 degrees)` of each report LegSwing printed.
fn leg_reports(stdout: &str) -> Vec<(u32, i32)> {
    stdout
        .lines()
        .filter_map(|l| {
            let rest = l.strip_prefix("LegSwing : robot frame ")?;
            let (frame, rest) = rest.split_once(", right front J1 ")?;
            Some((frame.parse().ok()?, rest.strip_suffix(" deg")?.parse().ok()?))
        })
        .collect()
}

/// Waits until LegSwing reported a swing both ways (J1 up to 25° or more and back to 15°
/// or less) after robot frame `after`; the reports.
fn wait_swing(h: &Running, after: u32) -> Vec<(u32, i32)> {
    let start = Instant::now();
    loop {
        let got: Vec<(u32, i32)> = leg_reports(&h.stdout()).into_iter().filter(|r| r.0 > after).collect();
        let up = got.iter().position(|r| r.1 >= 25);
        if up.is_some_and(|k| got[k..].iter().any(|r| r.1 <= 15)) || start.elapsed() > PATIENCE {
            return got;
        }
        std::thread::sleep(Duration::from_millis(20));
    }
}

/// LMasterRSlave's shape: the control loop runs on the host, the robot only relays.
/// Proxy calls (OpenPrimitive, gains, SetMotorPower, GetJointValue) run on the robot,
/// command vectors reach its effector, sensor frames come back; Sony's 10.0.1.100 lines
/// reach the emulator through --net-map. The host is killed (SIGKILL) and started again:
/// the robot runs on, takes the new host, and the leg swings again.
#[test]
fn a_host_control_loop_drives_the_robot_leg_and_survives_a_host_restart() {
    let built = build("rp-legs");
    let dir = built.dir.path().join("rp-legs/RP");
    let tmp = tempfile::tempdir().unwrap();
    let p = ports(3);
    let r_ms = side(&dir.join("robot"), &tmp.path().join("robot"), &p);
    let h_ms = side(&dir.join("host"), &tmp.path().join("host"), &p);
    let net_map = ["--net-map", "10.0.1.100=127.0.0.1"];
    let rob = robot(&r_ms);
    let h1 = host(&h_ms, &net_map);
    let first = wait_swing(&h1, 0);
    let out1 = h1.stdout();
    assert!(out1.contains("LegSwing : motor power on, OStatus 0"), "{out1}\n{}", h1.stderr());
    assert!(out1.contains("LegSwing : opened PRM:/r4/c1-Joint2:41 as primitive"), "{out1}");
    assert!(first.iter().any(|r| r.1 >= 25) && first.iter().any(|r| r.1 <= 15), "no swing: {first:?}\n{out1}\n{}", h1.stderr());
    let last = first.last().unwrap().0;
    drop(h1); // SIGKILL: the host side dies without a word
    assert!(wait_stderr(&rob, &format!("channel {}: host 127.0.0.1:", p[1])), "{}", rob.stderr());
    assert!(wait_stderr(&rob, "gone; listening for it again"), "{}", rob.stderr());
    let h2 = host(&h_ms, &net_map);
    let second = wait_swing(&h2, last);
    let out2 = h2.stop();
    assert!(second.iter().any(|r| r.1 >= 25) && second.iter().any(|r| r.1 <= 15), "no swing after the restart: {second:?}\n{}\n{}", out2.stdout, out2.stderr);
    assert!(second[0].0 > last, "the robot's frames go on from {last}: {second:?}");
    let r_out = rob.stop();
    assert_eq!(r_out.code, Some(0), "the robot kept running to the end: {}", r_out.stderr);
    assert_eq!(
        r_out.stderr.matches(&format!("channel {}: host 127.0.0.1:", p[2])).count(),
        4,
        "two hosts came and went on the effector channel: {}",
        r_out.stderr
    );
}
