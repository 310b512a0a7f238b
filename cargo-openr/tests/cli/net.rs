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
        ("create-pop3", 27),            // ANT_ENDPOINT_NOFACTORY
        ("send-unconnected", 17),       // TCP_OPERATION_INVALID
        ("connect", 0),
        ("listen-connected", 17),       // TCP_OPERATION_INVALID
        ("send-oversized", 16),         // TCP_BUFFER_INVALID: beyond the shared buffer
        ("send-empty", 16),
        ("send-outside", 16),
        ("tcp-unknown-op", 18),         // TCP_OPERATION_UNKNOWN
        ("send", 0),
        ("receive-reset", 3),           // TCP_CONNECTION_RESET
        ("close", 0),
        ("send-closed", 2),             // TCP_CONNECTION_CLOSED: a closed endpoint reused
        ("receive-closed", 2),
        ("close-closed", 2),
        ("connect-refused", 8),         // TCP_PORT_UNREACHABLE
        ("listen-inuse", 6),            // TCP_ADDRESSINUSE
        ("abort", 0),
        ("udp-send-unbound", 14),       // UDP_OPERATION_INVALID
        ("udp-bind", 0),
        ("udp-addressinuse", 4),        // UDP_ADDRESSINUSE (TCP's is 6)
        ("udp-oversized", 10),          // UDP_MESSAGE_TOO_LONG
        ("udp-send-outside", 13),       // UDP_BUFFER_INVALID (TCP's is 16)
        ("udp-unknown-op", 15),         // UDP_OPERATION_UNKNOWN
        ("udp-send", 0),
        ("udp-close", 0),
        ("udp-send-closed", 2),         // UDP_CONNECTION_CLOSED
        ("dns-address-before-lookup", 10), // DNS_OPERATION_INVALID
        ("dns-lookup", 0),
        ("dns-alias-99", 8),            // DNS_INDEX_INVALID
        ("dns-close", 0),
        ("dns-lookup-closed", 6),       // DNS_CONNECTION_CLOSED
    ];
    for (check, code) in expected {
        let line = format!("NetErrors : {check} = {code}\n");
        assert!(out.stdout.contains(&line), "expected `{}`\nstdout:\n{}\nstderr:\n{}", line.trim(), out.stdout, out.stderr);
    }
    assert!(out.stdout.contains("NetErrors : dns-missing n_address = 0, name = no-such-host.invalid.\n"), "{}", out.stdout);
    assert!(out.stdout.contains("NetErrors : done"));
    assert_eq!(out.code, Some(0), "{}", out.stderr);
}
