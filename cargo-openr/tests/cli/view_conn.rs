//! `cargo openr run --view` over keep-alive connections, as a browser uses them:
//! several at once, most of them left open and idle; none holds up another
//! (view/tests/connections.rs tries the same on many fresh replay and world servers).
use std::io::{Read, Write};
use std::net::TcpStream;
use std::time::{Duration, Instant};

use crate::support::{build, spawn_ms};
use crate::view::{pause_after, view_addr};

/// Far beyond a normal answer, far below the minutes a stuck connection waits.
const PATIENCE: Duration = Duration::from_secs(20);

/// `method path` with `body` on a kept connection, in one write; (status, body) of
/// the answer, which ends where its Content-Length says.
fn ask(s: &mut TcpStream, method: &str, path: &str, body: &str) -> (u16, String) {
    let req = format!("{method} {path} HTTP/1.1\r\nHost: view\r\nContent-Length: {}\r\n\r\n{body}", body.len());
    s.write_all(req.as_bytes()).unwrap();
    let mut head = Vec::new();
    let mut byte = [0u8; 1];
    while !head.ends_with(b"\r\n\r\n") {
        let n = s.read(&mut byte).unwrap_or_else(|e| panic!("{method} {path}: no answer within {PATIENCE:?} ({e})"));
        assert_eq!(n, 1, "{method} {path}: closed before the answer: {}", String::from_utf8_lossy(&head));
        head.push(byte[0]);
    }
    let head = String::from_utf8(head).unwrap();
    assert!(head.contains("Cache-Control: no-store\r\n"), "{head}");
    let length: usize = head.lines().find_map(|l| l.strip_prefix("Content-Length: ")).expect("a Content-Length").parse().unwrap();
    let mut body = vec![0; length];
    s.read_exact(&mut body).unwrap();
    (head.split_whitespace().nth(1).unwrap().parse().unwrap(), String::from_utf8(body).unwrap())
}

#[test]
fn idle_keep_alive_connections_hold_up_no_other() {
    let p = build("hello");
    let mut run = spawn_ms(&p.ms(), &["--view", "--speed", "max"], &[]);
    let addr = view_addr(&mut run);
    let t = pause_after(&addr, 200);
    // Six at once (a browser's most per host), five asked and left idle, then the sixth.
    let mut conns: Vec<TcpStream> = (0..6).map(|_| TcpStream::connect(&addr).unwrap()).collect();
    for s in &conns {
        s.set_read_timeout(Some(PATIENCE)).unwrap();
    }
    for s in &mut conns[..5] {
        let (code, state) = ask(s, "GET", "/state", "");
        assert_eq!(code, 200, "{state}");
    }
    let start = Instant::now();
    let (code, state) = ask(&mut conns[5], "GET", "/state", "");
    let took = start.elapsed();
    assert_eq!(code, 200, "{state}");
    let state: serde_json::Value = serde_json::from_str(&state).unwrap();
    assert_eq!(state["t_ms"], t, "the paused time");
    // The idle ones still serve, a control command too.
    let (code, answer) = ask(&mut conns[0], "POST", "/control", "step 1");
    assert_eq!(code, 200, "{answer}");
    assert!(answer.starts_with("ok"), "{answer}");
    let (code, page) = ask(&mut conns[1], "GET", "/", "");
    assert!(code == 200 && page.contains("</html>"), "{code}");
    let _ = run.stop();
    eprintln!("the sixth connection answered in {:.1} ms", took.as_secs_f64() * 1000.0);
}
