//! `cargo openr run --sim mujoco --view`: one page for the whole simulated world. Each
//! robot's runtime (its own process) serves its own view on a loopback port; this
//! server, in the `cargo openr run` process, passes `/robot/K/...` on to robot K's and
//! serves the field: `/field` (the scene's fixed shapes, written once by the MuJoCo
//! peer, `peer.py --field`) and `/world` (the newest line of the peer's ground truth,
//! `peer.py --state`, followed as the peer writes it) and `/field.png` (the field
//! camera's newest picture, `peer.py --field-camera`).
use std::io::{Read, Write};
use std::net::{SocketAddr, TcpStream};
use std::path::PathBuf;
use std::sync::Mutex;
use std::time::Duration;

use serde_json::Value;

/// What the world's page needs from the run: the robots' view addresses (known once
/// each runtime listens) and the peer's two files.
pub struct Live {
    robots: Mutex<Vec<Option<SocketAddr>>>,
    field: PathBuf,
    truth: Mutex<Tail>,
    camera: PathBuf,
}

/// The newest whole line of a file that grows.
struct Tail {
    path: PathBuf,
    file: Option<std::fs::File>,
    partial: Vec<u8>,
    last: Option<String>,
}

impl Live {
    /// `camera`: the field camera's newest picture (PNG, replaced whole by the peer).
    pub fn new(robots: usize, field: PathBuf, truth: PathBuf, camera: PathBuf) -> Live {
        let truth = Mutex::new(Tail { path: truth, file: None, partial: Vec::new(), last: None });
        Live { robots: Mutex::new(vec![None; robots]), field, truth, camera }
    }

    /// The field camera's newest picture, if it took one yet.
    pub fn camera(&self) -> Option<Vec<u8>> {
        std::fs::read(&self.camera).ok()
    }

    pub fn robots(&self) -> usize {
        self.robots.lock().unwrap_or_else(|p| p.into_inner()).len()
    }

    /// Robot `k`'s runtime serves its view on `addr`.
    pub fn robot_listening(&self, k: usize, addr: SocketAddr) {
        if let Some(slot) = self.robots.lock().unwrap_or_else(|p| p.into_inner()).get_mut(k) {
            *slot = Some(addr);
        }
    }

    fn robot(&self, k: usize) -> Option<SocketAddr> {
        self.robots.lock().unwrap_or_else(|p| p.into_inner()).get(k).copied().flatten()
    }

    /// The scene's shapes (null until the peer wrote them).
    pub fn field(&self) -> Value {
        std::fs::read_to_string(&self.field).ok().and_then(|t| serde_json::from_str(&t).ok()).unwrap_or(Value::Null)
    }

    /// The newest ground-truth line (null before the first frame).
    pub fn truth(&self) -> Value {
        let mut tail = self.truth.lock().unwrap_or_else(|p| p.into_inner());
        tail.read();
        tail.last.as_deref().and_then(|l| serde_json::from_str(l).ok()).unwrap_or(Value::Null)
    }

    /// `method path` with `body` to robot `k`'s view: (status, content type, body).
    pub fn ask(&self, k: usize, method: &str, path: &str, body: &[u8]) -> Result<(u16, String, Vec<u8>), String> {
        let addr = self.robot(k).ok_or_else(|| format!("robot {k} is not running (yet)"))?;
        request(addr, method, path, body).map_err(|e| format!("robot {k} ({addr}): {e}"))
    }
}

impl Tail {
    fn read(&mut self) {
        if self.file.is_none() {
            self.file = std::fs::File::open(&self.path).ok();
        }
        let Some(f) = self.file.as_mut() else { return };
        let mut new = Vec::new();
        if f.read_to_end(&mut new).is_err() {
            return;
        }
        self.partial.extend_from_slice(&new);
        if let Some(end) = self.partial.iter().rposition(|b| *b == b'\n') {
            let whole: Vec<u8> = self.partial.drain(..=end).collect();
            if let Some(line) = whole[..end].rsplit(|b| *b == b'\n').next() {
                self.last = Some(String::from_utf8_lossy(line).into_owned());
            }
        }
    }
}

/// One HTTP/1.0 request to a robot's view server (our own, on loopback), read to its end.
fn request(addr: SocketAddr, method: &str, path: &str, body: &[u8]) -> std::io::Result<(u16, String, Vec<u8>)> {
    let mut s = TcpStream::connect_timeout(&addr, Duration::from_secs(2))?;
    s.set_read_timeout(Some(Duration::from_secs(10)))?;
    write!(s, "{method} {path} HTTP/1.0\r\nHost: {addr}\r\nContent-Length: {}\r\n\r\n", body.len())?;
    s.write_all(body)?;
    let mut out = Vec::new();
    s.read_to_end(&mut out)?;
    let bad = || std::io::Error::new(std::io::ErrorKind::InvalidData, "not an HTTP answer");
    let head_end = out.windows(4).position(|w| w == b"\r\n\r\n").ok_or_else(bad)?;
    let head = String::from_utf8_lossy(&out[..head_end]).into_owned();
    let status = head.split_whitespace().nth(1).and_then(|c| c.parse().ok()).ok_or_else(bad)?;
    let kind = head
        .lines()
        .find_map(|l| l.split_once(':').filter(|(k, _)| k.eq_ignore_ascii_case("content-type")).map(|(_, v)| v.trim().to_string()))
        .unwrap_or_else(|| "application/octet-stream".into());
    Ok((status, kind, out[head_end + 4..].to_vec()))
}

/// `/robot/K/rest` -> (K, `/rest`); other paths are robot 0's.
pub(crate) fn robot_path(path: &str) -> (usize, String) {
    if let Some(rest) = path.strip_prefix("/robot/") {
        let (k, tail) = rest.split_once('/').unwrap_or((rest, ""));
        if let Ok(k) = k.parse() {
            return (k, format!("/{tail}"));
        }
    }
    (0, path.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn robot_paths() {
        assert_eq!(robot_path("/robot/3/state"), (3, "/state".into()));
        assert_eq!(robot_path("/robot/12/camera.png"), (12, "/camera.png".into()));
        assert_eq!(robot_path("/robot/1"), (1, "/".into()));
        assert_eq!(robot_path("/state"), (0, "/state".into()));
        assert_eq!(robot_path("/robot/x/state"), (0, "/robot/x/state".into()));
    }

    #[test]
    fn the_tail_is_the_newest_whole_line() {
        let dir = std::env::temp_dir().join(format!("openr-view-tail-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("truth.jsonl");
        let live = Live::new(1, dir.join("none.json"), path.clone(), dir.join("none.png"));
        assert_eq!(live.truth(), Value::Null, "no file yet");
        let mut f = std::fs::File::create(&path).unwrap();
        f.write_all(b"{\"frame\":1}\n{\"frame\":2}\n{\"fra").unwrap();
        assert_eq!(live.truth()["frame"], 2);
        f.write_all(b"me\":3}\n").unwrap();
        assert_eq!(live.truth()["frame"], 3);
        assert_eq!(live.truth()["frame"], 3, "nothing new: the same line");
        assert_eq!(live.field(), Value::Null);
        assert_eq!(live.camera(), None);
    }
}
