//! Networking (network-api): programs of `testdata/programs/` that use the IPStack, run
//! by `cargo openr run` and talked to with real clients and small local servers, all on
//! 127.0.0.1. Each test uses its own `--port-offset` (or free ports), so tests can run
//! in parallel.
use std::io::{Read, Write};
use std::net::{Shutdown, TcpListener, TcpStream, UdpSocket};
use std::os::fd::AsRawFd;
use std::time::Duration;

use crate::support::{build, run_ms, spawn_ms, Running};

const T: Duration = Duration::from_secs(30);

fn connect(port: u16) -> TcpStream {
    let s = TcpStream::connect(("127.0.0.1", port)).unwrap_or_else(|e| panic!("connect to {port}: {e}"));
    s.set_read_timeout(Some(Duration::from_secs(10))).unwrap();
    s
}

fn read_exact_n(s: &mut TcpStream, n: usize) -> Vec<u8> {
    let mut v = vec![0u8; n];
    s.read_exact(&mut v).unwrap_or_else(|e| panic!("reading {n} bytes: {e}"));
    v
}

/// Closes with a reset (SO_LINGER {1, 0}).
fn reset(s: TcpStream) {
    let l = libc::linger { l_onoff: 1, l_linger: 0 };
    // SAFETY: `s` is an open socket and `l` a live linger of the size given.
    unsafe {
        libc::setsockopt(s.as_raw_fd(), libc::SOL_SOCKET, libc::SO_LINGER, (&l as *const libc::linger).cast(), std::mem::size_of::<libc::linger>() as u32);
    }
    drop(s);
}

fn started(r: &mut Running, line: &str) {
    assert!(r.wait_for(line, T), "`{line}` never printed\nstdout:\n{}\nstderr:\n{}", r.stdout(), r.stderr());
}

fn count(text: &str, needle: &str) -> usize {
    text.matches(needle).count()
}

/// Waits until the echo server is listening again after its Close (the robot refuses in
/// that gap only if the host closes its listener, which ours keeps open).
fn echo(port: u16, data: &[u8]) -> Vec<u8> {
    let mut s = connect(port);
    s.write_all(data).unwrap();
    read_exact_n(&mut s, data.len())
}

#[test]
fn tcp_echo_server_two_robots_and_bad_peers() {
    let built = build("tcp-echo");
    let ms = built.ms();
    // two robots running the same program: each adds its offset to the port
    let mut a = spawn_ms(&ms, &["--port-offset", "101"], &[]);
    let mut b = spawn_ms(&ms, &["--port-offset", "102"], &[]);
    started(&mut a, "EchoServer : listening on port 54321");
    started(&mut b, "EchoServer : listening on port 54321");
    let (pa, pb) = (54321 + 101, 54321 + 102);

    // both answer; the echo tool's records end with their NUL
    assert_eq!(echo(pa, b"hello robot a\0"), b"hello robot a\0");
    assert_eq!(echo(pb, b"hello robot b\0"), b"hello robot b\0");

    // several rounds on one connection, then more than one buffer (512) at once
    let mut s = connect(pa);
    for i in 0..5 {
        let msg = format!("round {i}\0");
        s.write_all(msg.as_bytes()).unwrap();
        assert_eq!(read_exact_n(&mut s, msg.len()), msg.as_bytes());
    }
    let big: Vec<u8> = (0..3000u32).map(|i| (i % 251) as u8).collect();
    s.write_all(&big).unwrap();
    assert_eq!(read_exact_n(&mut s, big.len()), big);
    drop(s);

    // a half-open connection: the client stops sending but still reads the echo
    let mut s = connect(pa);
    s.write_all(b"half open\0").unwrap();
    s.shutdown(Shutdown::Write).unwrap();
    let mut rest = Vec::new();
    s.read_to_end(&mut rest).unwrap();
    assert_eq!(rest, b"half open\0", "the echo arrives, then the server closes");

    // a peer that resets
    let s = connect(pa);
    std::thread::sleep(Duration::from_millis(200));
    reset(s);
    // ... and new clients are served afterwards (3 more times)
    for i in 0..3 {
        let msg = format!("after reset {i}");
        assert_eq!(echo(pa, msg.as_bytes()), msg.as_bytes());
    }
    // robot b was never disturbed
    assert_eq!(echo(pb, b"still here"), b"still here");

    let out_a = a.stop();
    let out_b = b.stop();
    assert_eq!(out_a.code, Some(0), "stderr:\n{}", out_a.stderr);
    assert_eq!(out_b.code, Some(0), "stderr:\n{}", out_b.stderr);
    assert!(out_a.stdout.contains("EchoServer : received 14 bytes : hello robot a"), "{}", out_a.stdout);
    assert!(out_a.stdout.contains("EchoServer : receive error 3"), "reset = TCP_CONNECTION_RESET:\n{}", out_a.stdout);
    assert!(count(&out_a.stdout, "EchoServer : peer closed the connection") >= 4, "{}", out_a.stdout);
    assert!(out_b.stdout.contains("hello robot b") && !out_b.stdout.contains("hello robot a"));
    assert!(!out_a.stderr.contains("panicked") && !out_a.stderr.contains("crash"), "{}", out_a.stderr);
}

#[test]
fn udp_echo_server() {
    let built = build("udp-echo");
    let mut r = spawn_ms(&built.ms(), &["--port-offset", "103"], &[]);
    started(&mut r, "UDPEcho : bound to UDP port");
    let port = 54330 + 103;
    let client = UdpSocket::bind("127.0.0.1:0").unwrap();
    client.set_read_timeout(Some(Duration::from_secs(10))).unwrap();
    let mut buf = [0u8; 2048];
    for msg in [&b"first datagram\0"[..], b"x", &[7u8; 300]] {
        client.send_to(msg, ("127.0.0.1", port)).unwrap();
        let (n, from) = client.recv_from(&mut buf).unwrap();
        assert_eq!(&buf[..n], msg);
        assert_eq!(from.port(), port, "answered from the bound port");
    }
    // longer than the 512-byte buffer: truncated
    client.send_to(&[9u8; 700], ("127.0.0.1", port)).unwrap();
    let (n, _) = client.recv_from(&mut buf).unwrap();
    assert_eq!(n, 512);
    // another client gets its own answer
    let other = UdpSocket::bind("127.0.0.1:0").unwrap();
    other.set_read_timeout(Some(Duration::from_secs(10))).unwrap();
    other.send_to(b"other\0", ("127.0.0.1", port)).unwrap();
    let (n, _) = other.recv_from(&mut buf).unwrap();
    assert_eq!(&buf[..n], b"other\0");
    let out = r.stop();
    assert_eq!(out.code, Some(0), "{}", out.stderr);
    assert!(out.stdout.contains("UDPEcho : 15 bytes from 127.0.0.1:"), "{}", out.stdout);
}

#[test]
fn bad_input_gets_the_error_codes_of_the_spec() {
    let built = build("net-errors");
    let ms = built.ms();
    // a server that reads 5 bytes and resets, a port nobody listens on, a UDP sink
    let resetter = TcpListener::bind("127.0.0.1:0").unwrap();
    let closed_port = TcpListener::bind("127.0.0.1:0").unwrap().local_addr().unwrap().port();
    let sink = UdpSocket::bind("127.0.0.1:0").unwrap();
    sink.set_read_timeout(Some(Duration::from_secs(10))).unwrap();
    std::fs::write(
        ms.join("OPEN-R/MW/CONF/NETERR.CFG"),
        format!("{} {} {}\n", resetter.local_addr().unwrap().port(), closed_port, sink.local_addr().unwrap().port()),
    )
    .unwrap();
    let server = std::thread::spawn(move || {
        let (mut s, _) = resetter.accept().unwrap();
        let mut five = [0u8; 5];
        s.read_exact(&mut five).unwrap();
        reset(s);
        // keep the port taken while the robot tries to listen on it
        std::thread::sleep(Duration::from_secs(4));
        drop(resetter);
        five
    });
    let out = run_ms(&ms, &["--for", "8s"]);
    assert_eq!(&server.join().unwrap(), b"hello");
    let mut buf = [0u8; 64];
    let (n, _) = sink.recv_from(&mut buf).unwrap();
    assert_eq!(&buf[..n], b"datagram");
    let expected: &[(&str, i32)] = &[
        ("create-pop3", 27),      // ANT_ENDPOINT_NOFACTORY
        ("send-unconnected", 17), // TCP_OPERATION_INVALID
        ("connect", 0),
        ("listen-connected", 17), // TCP_OPERATION_INVALID
        ("send-oversized", 16),   // TCP_BUFFER_INVALID: beyond the shared buffer
        ("send-empty", 16),
        ("send-outside", 16),
        ("tcp-unknown-op", 18), // TCP_OPERATION_UNKNOWN
        ("send", 0),
        ("receive-reset", 3), // TCP_CONNECTION_RESET
        ("close", 0),
        ("send-closed", 2), // TCP_CONNECTION_CLOSED: a closed endpoint reused
        ("receive-closed", 2),
        ("close-closed", 2),
        ("connect-refused", 8), // TCP_PORT_UNREACHABLE
        ("listen-inuse", 6),    // TCP_ADDRESSINUSE
        ("abort", 0),
        ("udp-send-unbound", 14), // UDP_OPERATION_INVALID
        ("udp-bind", 0),
        ("udp-addressinuse", 4),  // UDP_ADDRESSINUSE (TCP's is 6)
        ("udp-oversized", 10),    // UDP_MESSAGE_TOO_LONG
        ("udp-send-outside", 13), // UDP_BUFFER_INVALID (TCP's is 16)
        ("udp-unknown-op", 15),   // UDP_OPERATION_UNKNOWN
        ("udp-send", 0),
        ("destroy-pending-buffer", 1), // ANT_FAIL: a Receive still writes into it
        ("udp-close", 0),
        ("destroy-buffer-after-close", 0),
        ("udp-send-closed", 2),            // UDP_CONNECTION_CLOSED
        ("dns-address-before-lookup", 10), // DNS_OPERATION_INVALID
        ("dns-lookup", 0),
        ("dns-alias-99", 8), // DNS_INDEX_INVALID
        ("dns-close", 0),
        ("dns-lookup-closed", 6), // DNS_CONNECTION_CLOSED
    ];
    for (check, code) in expected {
        let line = format!("NetErrors : {check} = {code}\n");
        assert!(out.stdout.contains(&line), "expected `{}`\nstdout:\n{}\nstderr:\n{}", line.trim(), out.stdout, out.stderr);
    }
    assert!(out.stdout.contains("NetErrors : dns-missing n_address = 0, name = no-such-host.invalid.\n"), "{}", out.stdout);
    assert!(out.stdout.contains("NetErrors : done"));
    assert!(out.stderr.contains("destroyed while a Send or Receive on it is pending: refused (antFAIL), it stays allocated"), "{}", out.stderr);
    assert_eq!(out.code, Some(0), "{}", out.stderr);
}

/// An orderly close after the last echo: FIN first, then whatever the client still sends (its
/// next round) is read and dropped until it closes too. Closing with the client's next record
/// unread would make the kernel answer with a reset, racing the FIN the client is reading.
fn hang_up(mut s: TcpStream) {
    s.shutdown(Shutdown::Write).unwrap();
    let mut rest = Vec::new();
    let _ = s.read_to_end(&mut rest);
}

#[test]
fn tcp_client_talks_to_a_host_echo_server() {
    let built = build("tcp-client");
    let ms = built.ms();
    let server = TcpListener::bind("127.0.0.1:0").unwrap();
    std::fs::write(ms.join("OPEN-R/MW/CONF/ECHOCLNT.CFG"), format!("127.0.0.1 {}\n", server.local_addr().unwrap().port())).unwrap();
    let echo = std::thread::spawn(move || {
        let (mut s, _) = server.accept().unwrap();
        s.set_read_timeout(Some(Duration::from_secs(20))).unwrap();
        let mut records = Vec::new();
        for _ in 0..3 {
            let rec = read_exact_n(&mut s, 25);
            s.write_all(&rec).unwrap();
            records.push(rec);
        }
        hang_up(s);
        records
    });
    let out = run_ms(&ms, &["--for", "4s"]);
    for rec in echo.join().unwrap() {
        assert_eq!(rec, b"This is a test message.\n\0");
    }
    assert!(out.stdout.contains("EchoClient : round 3 : 25 bytes : This is a test message."), "{}\n{}", out.stdout, out.stderr);
    assert!(out.stdout.contains("EchoClient : receive error 2\nEchoClient : closed\n"), "{}", out.stdout);
    assert_eq!(out.code, Some(0));

    // nobody listening: reported once, no retry
    let closed = TcpListener::bind("127.0.0.1:0").unwrap().local_addr().unwrap().port();
    std::fs::write(ms.join("OPEN-R/MW/CONF/ECHOCLNT.CFG"), format!("127.0.0.1 {closed}\n")).unwrap();
    let out = run_ms(&ms, &["--for", "1s"]);
    assert_eq!(count(&out.stdout, "EchoClient : connect error 8"), 1, "TCP_PORT_UNREACHABLE:\n{}", out.stdout);
}

#[test]
fn net_map_sends_a_built_in_lan_address_to_a_host_server() {
    let built = build("lan-client");
    let ms = built.ms();
    let server = TcpListener::bind("127.0.0.1:0").unwrap();
    let port = server.local_addr().unwrap().port();
    let echo = std::thread::spawn(move || {
        let (mut s, _) = server.accept().unwrap();
        s.set_read_timeout(Some(Duration::from_secs(20))).unwrap();
        let mut records = Vec::new();
        for _ in 0..3 {
            let rec = read_exact_n(&mut s, 25);
            s.write_all(&rec).unwrap();
            records.push(rec);
        }
        hang_up(s);
        records
    });
    let map = format!("10.0.1.2:54321=127.0.0.1:{port}");
    let out = run_ms(&ms, &["--for", "4s", "--net-map", &map]);
    for rec in echo.join().unwrap() {
        assert_eq!(rec, b"This is a test message.\n\0");
    }
    assert_eq!(out.code, Some(0), "{}\n{}", out.stdout, out.stderr);
    // the robot still sees the address it asked for
    assert!(out.stdout.contains("EchoClient : connecting to 10.0.1.2:54321"), "{}", out.stdout);
    assert!(out.stdout.contains(" to 10.0.1.2:54321"), "{}", out.stdout);
    assert!(out.stdout.contains("EchoClient : round 3 : 25 bytes : This is a test message."), "{}\n{}", out.stdout, out.stderr);
    // a malformed map is refused before the run
    let out = run_ms(&ms, &["--for", "1s", "--net-map", "10.0.1.2"]);
    assert_eq!(out.code, Some(2), "{}", out.stderr);
    assert!(out.stderr.contains("`10.0.1.2`: expected ROBOT_IP=HOST_IP or ROBOT_IP:PORT=HOST_IP:PORT"), "{}", out.stderr);
}

/// A tiny DNS server for the robot: A records, one CNAME, the PTR of 127.0.0.1.
fn dns_server() -> (u16, std::thread::JoinHandle<usize>) {
    let sock = UdpSocket::bind("127.0.0.1:0").unwrap();
    sock.set_read_timeout(Some(Duration::from_secs(30))).unwrap();
    let port = sock.local_addr().unwrap().port();
    let handle = std::thread::spawn(move || {
        let mut queries = 0;
        let mut buf = [0u8; 512];
        while let Ok((n, from)) = sock.recv_from(&mut buf) {
            queries += 1;
            let q = &buf[..n];
            // question name
            let (mut labels, mut pos) = (Vec::new(), 12);
            while q[pos] != 0 {
                let l = q[pos] as usize;
                labels.push(String::from_utf8_lossy(&q[pos + 1..pos + 1 + l]).into_owned());
                pos += 1 + l;
            }
            let qname = labels.join(".");
            let qtype = u16::from_be_bytes([q[pos + 1], q[pos + 2]]);
            let question = &q[12..pos + 5];
            let encode = |name: &str| {
                let mut v = Vec::new();
                for l in name.split('.') {
                    v.push(l.len() as u8);
                    v.extend_from_slice(l.as_bytes());
                }
                v.push(0);
                v
            };
            let rr = |name: &str, rtype: u16, rdata: &[u8]| {
                let mut v = encode(name);
                v.extend_from_slice(&rtype.to_be_bytes());
                v.extend_from_slice(&[0, 1, 0, 0, 0, 60]);
                v.extend_from_slice(&(rdata.len() as u16).to_be_bytes());
                v.extend_from_slice(rdata);
                v
            };
            let answers: Vec<Vec<u8>> = match (qtype, qname.as_str()) {
                (1, "robot.aibo.test") => vec![rr(&qname, 1, &[10, 0, 1, 7])],
                (1, "www.aibo.test") => vec![rr(&qname, 5, &encode("robot.aibo.test")), rr("robot.aibo.test", 1, &[10, 0, 1, 7])],
                (1, "localhost") => vec![rr(&qname, 1, &[127, 0, 0, 1])],
                (12, "1.0.0.127.in-addr.arpa") => vec![rr(&qname, 12, &encode("localhost"))],
                _ => vec![],
            };
            let mut r = vec![q[0], q[1], 0x81, if answers.is_empty() { 0x83 } else { 0x80 }, 0, 1, 0, answers.len() as u8, 0, 0, 0, 0];
            r.extend_from_slice(question);
            for a in answers {
                r.extend_from_slice(&a);
            }
            sock.send_to(&r, from).unwrap();
        }
        queries
    });
    (port, handle)
}

#[test]
fn interactive_dns_resolver() {
    let built = build("dns-lookup");
    let ms = built.ms();
    std::fs::create_dir_all(ms.join("OPEN-R/SYSTEM/CONF")).unwrap();
    std::fs::write(ms.join("OPEN-R/SYSTEM/CONF/WLANCONF.TXT"), "ETHER_IP=10.0.1.100\nDNS_SERVER_1=127.0.0.1\nDNS_DEFDNAME=aibo.test\n").unwrap();
    let (port, server) = dns_server();
    let map = format!("53={port}");
    let mut r = spawn_ms(&ms, &[], &[("OPENR_NET_PORT_MAP", &map)]);
    started(&mut r, "DNSLookUp> ");
    r.write_stdin("robot\n");
    started(&mut r, "Address : 10.0.1.7");
    r.write_stdin("www.aibo.test\n");
    assert!(r.wait_for("Name    : robot.aibo.test\nAddress : 10.0.1.7\nDNSLookUp> Name    : robot.aibo.test", T), "{}", r.stdout());
    r.write_stdin("no-such-host.invalid\n");
    started(&mut r, "no-such-host.invalid. Non-existent host/domain");
    r.write_stdin("localhost\n");
    started(&mut r, "Name    : localhost\nAddress : 127.0.0.1");
    r.write_stdin("shutdown\n");
    let out = r.wait(T);
    assert_eq!(out.code, Some(0), "{}", out.stderr);
    assert!(out.stdout.contains("Default Server : localhost\nAddress        : 127.0.0.1\nDefault domain : aibo.test\n"), "{}", out.stdout);
    assert!(out.stdout.contains("SHUTDOWN ..."));
    assert!(out.stderr.contains(&format!("net: robot port 53 (DNS server) is host port {port}")), "{}", out.stderr);
    drop(server); // ends at its read timeout
}

#[test]
fn sntp_client_sets_the_clock() {
    let built = build("sntp");
    let ms = built.ms();
    let server = UdpSocket::bind("127.0.0.1:0").unwrap();
    server.set_read_timeout(Some(Duration::from_secs(30))).unwrap();
    let port = server.local_addr().unwrap().port();
    // 2000-01-01 + 800 000 000 s = 2025-05-09 14:13:20 UTC
    let t: u32 = 3_155_673_600u32.wrapping_add(800_000_000);
    let sntp = std::thread::spawn(move || {
        let mut buf = [0u8; 512];
        let (n, from) = server.recv_from(&mut buf).unwrap();
        let request = buf[..n].to_vec();
        let mut reply = [0u8; 48];
        reply[0] = 0x0c; // server, version 1
        reply[40..44].copy_from_slice(&t.to_be_bytes());
        server.send_to(&reply, from).unwrap();
        request
    });
    let map = format!("123={port}");
    let mut r = spawn_ms(&ms, &[], &[("OPENR_NET_PORT_MAP", &map)]);
    started(&mut r, "NTP : clock set to");
    let out = r.stop();
    let request = sntp.join().unwrap();
    assert_eq!(request.len(), 48);
    assert_eq!(request[0], 0x0b);
    assert!(request[1..].iter().all(|&b| b == 0));
    assert!(out.stdout.contains("NTP : looking up localhost.\n"), "{}", out.stdout);
    let line = out.lines_starting("NTP : clock set to").join("");
    assert!(line.contains("May 2025"), "{line}");
    assert!(out.stderr.contains(&format!("net: robot port 123 (UDP send) is host port {port}")), "{}", out.stderr);
}

#[test]
fn wireless_lan_information() {
    let built = build("wlan-info");
    let out = run_ms(&built.ms(), &["--for", "1s", "--port-offset", "7"]);
    assert_eq!(out.code, Some(0), "{}", out.stderr);
    let expected = "[MAC Address] 02:00:00:00:00:07\n[Ether Statistics]\n  carrierSenseErrorCount  : 0\n";
    assert!(out.stdout.contains(expected), "{}", out.stdout);
    for line in [
        "  mode          : ADHOC\n",
        "  essid         : AIBONET\n",
        "  stationName   : AIBO7\n",
        "  channel       : 11\n",
        "  encryption    : OFF\n",
        "  rate          : 11MB\n",
        "[WLAN Statistics]\n  link             : 100\n",
        "[ETHER_IP] 10.0.1.100\n",
    ] {
        assert!(out.stdout.contains(line), "missing {line:?}:\n{}", out.stdout);
    }
}

/// Python's ftplib against the FTP server: passive (the 227 text carries the robot's
/// port, the client adds the offset) and active (the server connects from port 20).
const FTP_CLIENT: &str = r#"
import ftplib, io, sys
OFF = int(sys.argv[1])
class F(ftplib.FTP):
    def makepasv(self):
        h, p = super().makepasv()
        return h, p + OFF
f = F()
f.connect('127.0.0.1', 10021 + OFF, timeout=20)
print(f.getwelcome())
print(f.login('anonymous', 'anonymous'))
print(f.pwd())
print(f.sendcmd('SYST'))
buf = io.BytesIO()
print(f.retrbinary('RETR readme.txt', buf.write))
print('RETR', buf.getvalue())
lines = []
print(f.retrlines('LIST', lines.append))
print('LIST', ' | '.join(sorted(lines)))
f.set_pasv(False)
data = bytes(range(256)) * 100
print(f.storbinary('STOR test.bin', io.BytesIO(data)))
buf = io.BytesIO()
print(f.retrbinary('RETR TEST.BIN', buf.write))
print('same', buf.getvalue() == data)
try:
    f.retrbinary('RETR nothing.txt', buf.write)
except ftplib.error_perm as e:
    print('missing', e)
print(f.quit())
g = F()
g.connect('127.0.0.1', 10021 + OFF, timeout=20)
print(g.login('guest', 'whatever'))
print(g.pwd())
try:
    g.cwd('/MS')
except ftplib.error_perm as e:
    print('above home', e)
try:
    g.login('anonymous', 'wrong')
except ftplib.error_perm as e:
    print('bad password', e)
print(g.quit())
"#;

#[test]
fn ftp_server_serves_the_memory_stick() {
    let built = build("ftpd");
    let ms = built.ms();
    let mut r = spawn_ms(&ms, &["--port-offset", "150"], &[]);
    started(&mut r, "FtpServer : listening on port 21");
    let out = std::process::Command::new("python3").arg("-c").arg(FTP_CLIENT).arg("150").output().expect("python3");
    let client = String::from_utf8_lossy(&out.stdout).into_owned();
    let run = r.stop();
    assert!(out.status.success(), "ftplib failed:\n{client}\n{}\nserver:\n{}\n{}", String::from_utf8_lossy(&out.stderr), run.stdout, run.stderr);
    for line in [
        "220 AIBO FTP Server ready\n",
        "230 User anonymous logged in.\n",
        "/MS/\n",
        "215 Aperios system type.\n",
        "RETR b'Hello from the Memory Stick.\\n'\n",
        "-rw-rw-rw- 0 AIBO AIBO 29 May 11 1999 README.TXT",
        "drwxrwxrwx 0 AIBO AIBO",
        "same True\n",
        "missing 550 No such file.\n",
        "221 Goodbye. Thanks for using the AIBO FTP Server.\n",
        "230 User guest logged in.\n/MS/OPEN-R/MW/\n",
        "above home 550 No such directory.\n",
        "bad password 530 Login incorrect.\n",
    ] {
        assert!(client.contains(line), "missing {line:?} in:\n{client}");
    }
    assert_eq!(count(&client, "226 Transfer complete."), 4, "{client}");
    let stored = std::fs::read(ms.join("TEST.BIN")).expect("STOR test.bin made /MS/TEST.BIN");
    assert_eq!(stored.len(), 25600);
    assert_eq!(run.code, Some(0), "{}", run.stderr);
    assert!(run.stderr.contains("net: robot port 21 (TCP listen) is host port 10171"), "{}", run.stderr);
    assert!(run.stderr.contains("net: robot port 20 (TCP connect source) is host port 10170"), "{}", run.stderr);
}
