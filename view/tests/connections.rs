//! The view server over real sockets, as a browser uses it: several keep-alive
//! connections at once, some of them left open and idle. An idle connection must hold
//! up no other (a browser keeps up to six open per host for minutes).
use std::io::{Read, Write};
use std::net::{SocketAddr, TcpStream};
use std::path::PathBuf;
use std::sync::Arc;
use std::time::{Duration, Instant};

use openr_view::View;

/// Far beyond a normal answer (milliseconds), far below the minutes a stuck
/// connection waits: the test cannot hang.
const PATIENCE: Duration = Duration::from_secs(20);

/// A fresh scratch directory.
fn scratch(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("openr-view-conn-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// A view serving a simulated world of one robot that is not running: `/field` and
/// `/world` answer from the (missing) peer files.
fn world_view() -> SocketAddr {
    let dir = scratch("world");
    let live = openr_view::world::Live::new(1, dir.join("field.json"), dir.join("truth.jsonl"), dir.join("camera.png"));
    let view = View::bind("127.0.0.1:0".parse().unwrap()).unwrap();
    view.world(Arc::new(live)).unwrap();
    view.addr()
}

/// A view replaying a bare trace of a few moments.
fn replay_view() -> SocketAddr {
    let dir = scratch("replay");
    let trace = dir.join("t.jsonl");
    let lines: Vec<String> = (0..4).map(|k| format!("{{\"kind\":\"sensor\",\"t_ms\":{},\"frame\":{},\"joints\":{{}}}}", 32 * k, 4 * k)).collect();
    std::fs::write(&trace, lines.join("\n") + "\n").unwrap();
    let view = View::bind("127.0.0.1:0".parse().unwrap()).unwrap();
    view.replay(openr_view::replay::open(&trace).unwrap()).unwrap();
    view.addr()
}

fn connect(addr: SocketAddr) -> TcpStream {
    let s = TcpStream::connect(addr).unwrap();
    s.set_read_timeout(Some(PATIENCE)).unwrap();
    s.set_write_timeout(Some(PATIENCE)).unwrap();
    s
}

/// One answer read off a keep-alive connection: (status, headers, body). Its end is
/// where its Content-Length says.
fn read_answer(s: &mut TcpStream) -> std::io::Result<(u16, String, Vec<u8>)> {
    let mut got = Vec::new();
    let mut byte = [0u8; 1];
    while !got.ends_with(b"\r\n\r\n") {
        if s.read(&mut byte)? == 0 {
            return Err(std::io::Error::new(std::io::ErrorKind::UnexpectedEof, "closed before the answer's head ended"));
        }
        got.push(byte[0]);
    }
    let head = String::from_utf8_lossy(&got).into_owned();
    let status = head.split_whitespace().nth(1).and_then(|c| c.parse().ok()).unwrap_or(0);
    let length = header(&head, "content-length").and_then(|v| v.parse::<usize>().ok()).expect("an answer with a Content-Length");
    let mut body = vec![0; length];
    s.read_exact(&mut body)?;
    Ok((status, head, body))
}

/// Why an answer did not come: a read that timed out says so.
fn why(e: &std::io::Error) -> String {
    match e.kind() {
        std::io::ErrorKind::WouldBlock | std::io::ErrorKind::TimedOut => format!("no answer within {PATIENCE:?}"),
        _ => format!("no answer: {e}"),
    }
}

/// The value of header `name` in an answer's head.
fn header<'a>(head: &'a str, name: &str) -> Option<&'a str> {
    head.lines().find_map(|l| l.split_once(':').filter(|(k, _)| k.trim().eq_ignore_ascii_case(name)).map(|(_, v)| v.trim()))
}

/// One GET, in one write (`write!` would send it in pieces, each waiting for the
/// last one's acknowledgement).
fn get(s: &mut TcpStream, addr: SocketAddr, path: &str) {
    s.write_all(format!("GET {path} HTTP/1.1\r\nHost: {addr}\r\nConnection: keep-alive\r\nAccept: */*\r\n\r\n").as_bytes()).unwrap();
}

/// Opens `n` connections in a burst, asks `path` on the first `n - 1` and reads their
/// answers, leaves them open and idle, then asks on the last one: how long its answer
/// took (an error if none came within PATIENCE).
fn last_of_a_burst(addr: SocketAddr, path: &str, n: usize) -> Result<Duration, String> {
    let mut conns: Vec<TcpStream> = (0..n).map(|_| connect(addr)).collect();
    let (idle, last) = conns.split_at_mut(n - 1);
    for s in idle.iter_mut() {
        get(s, addr, path);
    }
    for (i, s) in idle.iter_mut().enumerate() {
        let (status, head, _) = read_answer(s).map_err(|e| format!("connection {i} of {n}: {}", why(&e)))?;
        assert_eq!(status, 200, "connection {i}: {head}");
    }
    let last = &mut last[0];
    let start = Instant::now();
    get(last, addr, path);
    let (status, head, _) = read_answer(last).map_err(|e| format!("the last of {n} connections: {}", why(&e)))?;
    assert_eq!(status, 200, "{head}");
    // and the idle ones still answer
    let (status, _, _) = {
        get(&mut idle[0], addr, path);
        read_answer(&mut idle[0]).map_err(|e| format!("connection 0 again: {}", why(&e)))?
    };
    assert_eq!(status, 200);
    Ok(start.elapsed())
}

/// Rounds of bursts, each on a fresh server: a pool that hands connections to threads
/// can lose one only on its first burst (tiny_http 0.12 lost one in about 3 bursts
/// out of 10 here), so one round proves little.
const ROUNDS: usize = 12;

/// `n` connections in a burst on each of ROUNDS fresh servers; the slowest last answer.
fn bursts(serve: impl Fn() -> SocketAddr, path: &str, n: usize) -> Duration {
    let mut slowest = Duration::ZERO;
    for round in 0..ROUNDS {
        let took = last_of_a_burst(serve(), path, n).unwrap_or_else(|e| panic!("round {round}: {e}"));
        slowest = slowest.max(took);
    }
    slowest
}

#[test]
fn idle_keep_alive_connections_hold_up_no_other_world() {
    for n in [6, 8] {
        let took = bursts(world_view, "/field", n);
        eprintln!("world, {n} connections: the last answered within {} ms", took.as_millis());
    }
}

#[test]
fn idle_keep_alive_connections_hold_up_no_other_replay() {
    for n in [6, 8] {
        let took = bursts(replay_view, "/chunk?n=0", n);
        eprintln!("replay, {n} connections: the last answered within {} ms", took.as_millis());
    }
}
