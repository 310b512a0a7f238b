//! The control channel: a Unix socket (`--control PATH`) taking one text command per
//! line, answering one line each:
//!
//! | command | effect | answer |
//! |---|---|---|
//! | `status` | – | `ok t_ms=<virtual ms> speed=<factor\|max> paused=<true\|false>` |
//! | `pause` / `resume` | stop / restart virtual time | `ok t_ms=…` |
//! | `step [N]` | while paused, run N frames (default 1) of 8 ms | `ok t_ms=…` once they ran |
//! | `speed <factor\|max>` | change the speed | `ok` |
//! | `shutdown` | the Stop/Destroy sequence, as OPENR::Shutdown | `ok` |
//!
//! Anything else gets `error: …`, a line that is not UTF-8 too; a line longer than
//! 1024 bytes gets an error and the connection is closed. Several clients may be
//! connected at once.
use std::io::{BufRead, BufReader, Read, Write};
use std::os::unix::net::{UnixListener, UnixStream};
use std::path::Path;
use std::time::Duration;

use crate::clock::Speed;
use crate::error::{Error, Result};
use crate::runtime::Runtime;

/// Binds `path` and serves it on a thread of its own.
pub fn serve(rt: &'static Runtime, path: &Path) -> Result<()> {
    let _ = std::fs::remove_file(path);
    let listener = UnixListener::bind(path).map_err(|e| Error::io(path, e))?;
    std::thread::Builder::new()
        .name("openr-control".into())
        .spawn(move || {
            for conn in listener.incoming().flatten() {
                let _ = std::thread::Builder::new().name("openr-control-client".into()).spawn(move || client(rt, conn));
            }
        })
        .map_err(|e| Error::io(path, e))?;
    Ok(())
}

/// Longest command line taken; a longer one is answered with an error and the
/// connection closed (a client cannot make the runtime buffer without bound).
const MAX_LINE: usize = 1024;

fn client(rt: &'static Runtime, conn: UnixStream) {
    let Ok(mut out) = conn.try_clone() else { return };
    // A client that does not read its answers cannot hold this thread for ever.
    let _ = out.set_write_timeout(Some(Duration::from_secs(5)));
    let mut input = BufReader::new(conn);
    loop {
        let mut line = Vec::new();
        match (&mut input).take(MAX_LINE as u64 + 1).read_until(b'\n', &mut line) {
            Ok(0) | Err(_) => return,
            Ok(_) => {}
        }
        let complete = line.last() == Some(&b'\n');
        if !complete && line.len() > MAX_LINE {
            let _ = writeln!(out, "error: command line longer than {MAX_LINE} bytes (connection closed)");
            return;
        }
        let answer = match std::str::from_utf8(&line) {
            Ok(text) => command(rt, text.trim()),
            Err(e) => format!("error: the command line is not UTF-8 text (invalid byte at {})", e.valid_up_to()),
        };
        if writeln!(out, "{answer}").is_err() {
            return;
        }
    }
}

fn t_ms(rt: &Runtime) -> u128 {
    rt.clock.since_boot().as_millis()
}

/// Executes one command line and returns the answer line.
pub fn command(rt: &Runtime, line: &str) -> String {
    let mut words = line.split_whitespace();
    match (words.next(), words.next(), words.next()) {
        (Some("status"), None, _) => {
            let speed = match rt.clock.speed() {
                Speed::Max => "max".to_string(),
                Speed::Factor(f) => format!("{f}"),
            };
            format!("ok t_ms={} speed={speed} paused={}", t_ms(rt), rt.clock.paused())
        }
        (Some("pause"), None, _) => {
            let at = rt.clock.pause_settled(Duration::from_secs(5));
            format!("ok t_ms={}", at.as_millis())
        }
        (Some("resume"), None, _) => {
            rt.clock.set_paused(false);
            format!("ok t_ms={}", t_ms(rt))
        }
        (Some("step"), n, None) => {
            let frames = match n.map(str::parse::<u64>) {
                None => 1,
                Some(Ok(n)) if (1..=1_000_000).contains(&n) => n,
                Some(_) => return "error: step takes a number of frames (1..1000000)".into(),
            };
            if !rt.clock.paused() {
                return "error: step needs a paused clock (send `pause` first)".into();
            }
            let target = rt.clock.since_boot() + crate::clock::FRAME * frames as u32;
            rt.clock.step(frames);
            rt.clock.wait_until(target);
            let at = rt.clock.pause_settled(Duration::from_secs(5));
            format!("ok t_ms={}", at.as_millis())
        }
        (Some("speed"), Some(v), None) => match v.parse::<Speed>() {
            Ok(s) => {
                rt.sched.set_serial(s == Speed::Max);
                rt.clock.set_speed(s);
                "ok".into()
            }
            Err(e) => format!("error: {e}"),
        },
        (Some("shutdown"), None, _) => {
            rt.request_shutdown();
            "ok".into()
        }
        _ => format!("error: unknown command `{line}` (status, pause, resume, step [N], speed <factor|max>, shutdown)"),
    }
}
