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
    crate::runtime::spawn("openr-control", move || {
        for conn in listener.incoming().flatten() {
            let _ = crate::runtime::spawn("openr-control-client", move || client(rt, conn));
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
        let answer = match read_line(&mut input) {
            Input::End => return,
            Input::TooLong => {
                let _ = writeln!(out, "error: command line longer than {MAX_LINE} bytes (connection closed)");
                return;
            }
            Input::NotUtf8(at) => format!("error: the command line is not UTF-8 text (invalid byte at {at})"),
            Input::Line(text) => command(rt, text.trim()),
        };
        if writeln!(out, "{answer}").is_err() {
            return;
        }
    }
}

/// What [`read_line`] found.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Input {
    /// End of input (or a read error): the connection is over.
    End,
    /// A line longer than the limit: answered with an error, then the connection closes.
    TooLong,
    /// A line that is not UTF-8: the offset of the first invalid byte.
    NotUtf8(usize),
    /// One line of text (with its line end, if it had one).
    Line(String),
}

/// Reads one command line of at most 1024 bytes (plus its `\n`).
pub fn read_line(input: &mut impl BufRead) -> Input {
    let mut line = Vec::new();
    match input.take(MAX_LINE as u64 + 1).read_until(b'\n', &mut line) {
        Ok(0) | Err(_) => return Input::End,
        Ok(_) => {}
    }
    if line.last() != Some(&b'\n') && line.len() > MAX_LINE {
        return Input::TooLong;
    }
    match String::from_utf8(line) {
        Ok(text) => Input::Line(text),
        Err(e) => Input::NotUtf8(e.utf8_error().valid_up_to()),
    }
}

/// A command of the control channel.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Command {
    Status,
    Pause,
    Resume,
    Step(u64),
    Speed(Speed),
    Shutdown,
}

impl std::str::FromStr for Command {
    type Err = String;
    /// Parses a command line (blanks around words ignored); the error is the answer
    /// without its `error: ` prefix.
    fn from_str(line: &str) -> std::result::Result<Command, String> {
        let mut words = line.split_whitespace();
        Ok(match (words.next(), words.next(), words.next()) {
            (Some("status"), None, _) => Command::Status,
            (Some("pause"), None, _) => Command::Pause,
            (Some("resume"), None, _) => Command::Resume,
            (Some("step"), n, None) => match n.map(str::parse::<u64>) {
                None => Command::Step(1),
                Some(Ok(n)) if (1..=1_000_000).contains(&n) => Command::Step(n),
                Some(_) => return Err("step takes a number of frames (1..1000000)".into()),
            },
            (Some("speed"), Some(v), None) => Command::Speed(v.parse::<Speed>()?),
            (Some("shutdown"), None, _) => Command::Shutdown,
            _ => return Err(format!("unknown command `{}` (status, pause, resume, step [N], speed <factor|max>, shutdown)", line.trim())),
        })
    }
}

impl std::fmt::Display for Command {
    /// The command line that parses back to this command.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Command::Status => f.write_str("status"),
            Command::Pause => f.write_str("pause"),
            Command::Resume => f.write_str("resume"),
            Command::Step(n) => write!(f, "step {n}"),
            Command::Speed(Speed::Max) => f.write_str("speed max"),
            Command::Speed(Speed::Factor(x)) => write!(f, "speed {x}"),
            Command::Shutdown => f.write_str("shutdown"),
        }
    }
}

fn t_ms(rt: &Runtime) -> u128 {
    rt.clock.since_boot().as_millis()
}

/// Executes one command line and returns the answer line.
pub fn command(rt: &Runtime, line: &str) -> String {
    let cmd = match line.parse::<Command>() {
        Ok(c) => c,
        Err(e) => return format!("error: {e}"),
    };
    match cmd {
        Command::Status => {
            let speed = match rt.clock.speed() {
                Speed::Max => "max".to_string(),
                Speed::Factor(f) => format!("{f}"),
            };
            format!("ok t_ms={} speed={speed} paused={}", t_ms(rt), rt.clock.paused())
        }
        Command::Pause => {
            let at = rt.clock.pause_settled(Duration::from_secs(5));
            format!("ok t_ms={}", at.as_millis())
        }
        Command::Resume => {
            rt.clock.set_paused(false);
            format!("ok t_ms={}", t_ms(rt))
        }
        Command::Step(frames) => {
            if !rt.clock.paused() {
                return "error: step needs a paused clock (send `pause` first)".into();
            }
            let target = rt.clock.since_boot() + crate::clock::FRAME * frames as u32;
            rt.clock.step(frames);
            rt.clock.wait_until(target);
            let at = rt.clock.pause_settled(Duration::from_secs(5));
            format!("ok t_ms={}", at.as_millis())
        }
        Command::Speed(s) => {
            rt.sched.set_serial(s == Speed::Max);
            rt.clock.set_speed(s);
            "ok".into()
        }
        Command::Shutdown => {
            rt.request_shutdown();
            "ok".into()
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lines_are_bounded_and_decoded() {
        let mut input = &b"status\n\xffx\nlast"[..];
        assert_eq!(read_line(&mut input), Input::Line("status\n".into()));
        assert_eq!(read_line(&mut input), Input::NotUtf8(0));
        assert_eq!(read_line(&mut input), Input::Line("last".into()));
        assert_eq!(read_line(&mut input), Input::End);
        let long = vec![b'a'; MAX_LINE + 1];
        assert_eq!(read_line(&mut &long[..]), Input::TooLong);
        let fits = [&[b'a'; MAX_LINE][..], b"\n"].concat();
        assert!(matches!(read_line(&mut &fits[..]), Input::Line(l) if l.len() == MAX_LINE + 1));
    }

    #[test]
    fn commands_parse_and_print_back() {
        for (line, cmd) in [
            (" status ", Command::Status),
            ("step", Command::Step(1)),
            ("step 7", Command::Step(7)),
            ("speed MAX", Command::Speed(Speed::Max)),
            ("speed 2.5", Command::Speed(Speed::Factor(2.5))),
        ] {
            assert_eq!(line.parse::<Command>(), Ok(cmd));
            assert_eq!(cmd.to_string().parse::<Command>(), Ok(cmd));
        }
        assert_eq!("step 0".parse::<Command>(), Err("step takes a number of frames (1..1000000)".into()));
        assert!("speed 1e-300".parse::<Command>().unwrap_err().contains("out of range"));
        assert!("status now".parse::<Command>().unwrap_err().starts_with("unknown command `status now`"));
    }
}
