//! Shared fixtures: the binary under test and one SDK root per test run.
use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use std::sync::OnceLock;

pub fn exe() -> &'static str {
    env!("CARGO_BIN_EXE_cargo-openr")
}

pub fn repo() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).parent().unwrap().to_path_buf()
}

/// An SDK root installed by the binary under test (installed once per run; a later run
/// with the same binary finds it fresh).
pub fn sdk_root() -> &'static Path {
    static ROOT: OnceLock<PathBuf> = OnceLock::new();
    ROOT.get_or_init(|| {
        let root = Path::new(env!("CARGO_TARGET_TMPDIR")).join("sdk-root");
        let out = cargo_openr(&["sdk", "install", "--prefix", root.to_str().unwrap()]);
        assert!(out.status.success(), "sdk install failed: {}", String::from_utf8_lossy(&out.stderr));
        root
    })
}

pub fn cargo_openr(args: &[&str]) -> Output {
    Command::new(exe()).args(args).output().expect("run cargo-openr")
}

/// Runs a command and returns (success, stdout+stderr) for assertion messages.
pub fn run(cmd: &mut Command) -> (bool, String) {
    let out = cmd.output().unwrap_or_else(|e| panic!("cannot run {cmd:?}: {e}"));
    let text = format!("{}{}", String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr));
    (out.status.success(), text)
}

/// Copies a directory tree (files, directories, symlinks as files).
pub fn copy_tree(from: &Path, to: &Path) {
    std::fs::create_dir_all(to).unwrap();
    for entry in std::fs::read_dir(from).unwrap() {
        let entry = entry.unwrap();
        let dst = to.join(entry.file_name());
        if entry.file_type().unwrap().is_dir() {
            copy_tree(&entry.path(), &dst);
        } else {
            std::fs::copy(entry.path(), &dst).unwrap();
        }
    }
}

/// A program of `testdata/programs/` built (`make install`) in a scratch copy.
pub struct Built {
    pub dir: tempfile::TempDir,
    pub name: String,
}

impl Built {
    /// The program's Memory Stick tree.
    pub fn ms(&self) -> PathBuf {
        self.dir.path().join(&self.name).join("MS")
    }
}

/// Copies `testdata/programs/<name>` and runs `make OPENRSDK_ROOT=<root> install`;
/// returns the copy and whether make succeeded, with its output.
pub fn make_install(name: &str, extra: &[&str]) -> (Built, bool, String) {
    let root = sdk_root();
    let tmp = tempfile::tempdir().unwrap();
    let dir = tmp.path().join(name);
    copy_tree(&repo().join("testdata/programs").join(name), &dir);
    let (ok, log) = run(Command::new("make").arg(format!("OPENRSDK_ROOT={}", root.display())).args(extra).arg("install").current_dir(&dir));
    (Built { dir: tmp, name: name.to_string() }, ok, log)
}

/// Builds a program that must build.
pub fn build(name: &str) -> Built {
    let (built, ok, log) = make_install(name, &[]);
    assert!(ok, "building {name} failed:\n{log}");
    built
}

/// Output of one `cargo openr run`.
pub struct RunOutput {
    pub code: Option<i32>,
    pub stdout: String,
    pub stderr: String,
}

impl RunOutput {
    /// stdout lines that start with `prefix`, in order.
    pub fn lines_starting(&self, prefix: &str) -> Vec<&str> {
        self.stdout.lines().filter(|l| l.starts_with(prefix)).collect()
    }
}

/// Runs `cargo openr run <ms> <args>` to completion (a hang is killed after 60 s and
/// fails the test).
pub fn run_ms(ms: &Path, args: &[&str]) -> RunOutput {
    run_ms_signalled(ms, args, &[])
}

/// Same, sending `signal` to the runtime after each given delay (from its start).
pub fn run_ms_signalled(ms: &Path, args: &[&str], signals: &[(std::time::Duration, i32)]) -> RunOutput {
    run_ms_driven(ms, args, None, signals)
}

extern "C" {
    #[link_name = "kill"]
    fn libc_kill(pid: i32, sig: i32) -> i32;
}

/// Same as [`run_ms`], feeding the runtime's stdin: each chunk is written once `at` has
/// passed since the start, then stdin is closed (the objects read EOF from then on).
pub fn run_ms_with_stdin(ms: &Path, args: &[&str], input: &[(std::time::Duration, &[u8])]) -> RunOutput {
    run_ms_driven(ms, args, Some(input), &[])
}

/// Runs `cargo openr run <ms> <args>` to completion: stdin null, or fed `input` on its
/// timetable then closed; each signal sent at its delay; killed (and the test failed)
/// after 60 s.
fn run_ms_driven(ms: &Path, args: &[&str], input: Option<&[(std::time::Duration, &[u8])]>, signals: &[(std::time::Duration, i32)]) -> RunOutput {
    use std::io::{Read, Write};
    use std::process::Stdio;
    use std::time::{Duration, Instant};
    let mut child = Command::new(exe())
        .env("OPENRSDK_ROOT", sdk_root())
        .arg("run")
        .arg(ms)
        .args(args)
        .stdin(if input.is_some() { Stdio::piped() } else { Stdio::null() })
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let start = Instant::now();
    let in_t = input.map(|input| {
        let mut stdin = child.stdin.take().unwrap();
        let chunks: Vec<(Duration, Vec<u8>)> = input.iter().map(|(d, b)| (*d, b.to_vec())).collect();
        std::thread::spawn(move || {
            for (at, bytes) in chunks {
                let now = start.elapsed();
                if at > now {
                    std::thread::sleep(at - now);
                }
                if stdin.write_all(&bytes).and_then(|_| stdin.flush()).is_err() {
                    break;
                }
            }
        })
    });
    let drain = |mut pipe: Box<dyn Read + Send>| {
        std::thread::spawn(move || {
            let mut s = Vec::new();
            let _ = pipe.read_to_end(&mut s);
            String::from_utf8_lossy(&s).into_owned()
        })
    };
    let out_t = drain(Box::new(child.stdout.take().unwrap()));
    let err_t = drain(Box::new(child.stderr.take().unwrap()));
    let mut pending: Vec<(Duration, i32)> = signals.to_vec();
    let status = loop {
        if let Some(st) = child.try_wait().unwrap() {
            break st;
        }
        pending.retain(|(at, sig)| {
            if start.elapsed() >= *at {
                // SAFETY: kill touches no memory; try_wait found the child unreaped, so the pid is still its.
                unsafe { libc_kill(child.id() as i32, *sig) };
                false
            } else {
                true
            }
        });
        if start.elapsed() > Duration::from_secs(60) {
            let _ = child.kill();
            panic!("cargo openr run {} hung for 60 s", ms.display());
        }
        std::thread::sleep(Duration::from_millis(10));
    };
    if let Some(t) = in_t {
        let _ = t.join();
    }
    RunOutput { code: status.code(), stdout: out_t.join().unwrap(), stderr: err_t.join().unwrap() }
}

/// The records of a `--trace` file (JSON lines), in order.
pub fn read_trace(path: &Path) -> Vec<serde_json::Value> {
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("cannot read trace {}: {e}", path.display()));
    text.lines().filter(|l| !l.trim().is_empty()).map(|l| serde_json::from_str(l).unwrap_or_else(|e| panic!("bad trace line {l:?}: {e}"))).collect()
}

/// A `cargo openr run` that keeps running while the test talks to it (over the network
/// or its stdin); stdout and stderr are collected as they come.
pub struct Running {
    child: Option<std::process::Child>,
    stdin: Option<std::process::ChildStdin>,
    stdout: std::sync::Arc<std::sync::Mutex<String>>,
    stderr: std::sync::Arc<std::sync::Mutex<String>>,
    readers: Vec<std::thread::JoinHandle<()>>,
}

/// Starts `cargo openr run <ms> <args>` with extra environment variables and returns at once.
pub fn spawn_ms(ms: &Path, args: &[&str], env: &[(&str, &str)]) -> Running {
    use std::io::Read;
    use std::sync::{Arc, Mutex};
    let mut child = Command::new(exe())
        .env("OPENRSDK_ROOT", sdk_root())
        .envs(env.iter().copied())
        .arg("run")
        .arg(ms)
        .args(args)
        .stdin(std::process::Stdio::piped())
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let stdout = Arc::new(Mutex::new(String::new()));
    let stderr = Arc::new(Mutex::new(String::new()));
    let mut readers = Vec::new();
    let pipes: [(Box<dyn Read + Send>, Arc<Mutex<String>>); 2] =
        [(Box::new(child.stdout.take().unwrap()), stdout.clone()), (Box::new(child.stderr.take().unwrap()), stderr.clone())];
    for (mut pipe, sink) in pipes {
        readers.push(std::thread::spawn(move || {
            let mut buf = [0u8; 4096];
            while let Ok(n) = pipe.read(&mut buf) {
                if n == 0 {
                    break;
                }
                sink.lock().unwrap().push_str(&String::from_utf8_lossy(&buf[..n]));
            }
        }));
    }
    let stdin = child.stdin.take();
    Running { child: Some(child), stdin, stdout, stderr, readers }
}

impl Running {
    pub fn stdout(&self) -> String {
        self.stdout.lock().unwrap().clone()
    }

    pub fn stderr(&self) -> String {
        self.stderr.lock().unwrap().clone()
    }

    /// Waits until stdout contains `needle` (true) or `timeout` passes / the run ends (false).
    pub fn wait_for(&mut self, needle: &str, timeout: std::time::Duration) -> bool {
        let start = std::time::Instant::now();
        loop {
            if self.stdout().contains(needle) {
                return true;
            }
            let exited = self.child.as_mut().map_or(true, |c| c.try_wait().ok().flatten().is_some());
            if exited {
                std::thread::sleep(std::time::Duration::from_millis(50));
                return self.stdout().contains(needle);
            }
            if start.elapsed() > timeout {
                return false;
            }
            std::thread::sleep(std::time::Duration::from_millis(10));
        }
    }

    /// Writes `text` to the runtime's stdin (the objects' console input).
    pub fn write_stdin(&mut self, text: &str) {
        use std::io::Write;
        let stdin = self.stdin.as_mut().expect("stdin still open");
        stdin.write_all(text.as_bytes()).unwrap();
        stdin.flush().unwrap();
    }

    /// Waits for the run to end by itself (at most `timeout`, then SIGTERM).
    pub fn wait(mut self, timeout: std::time::Duration) -> RunOutput {
        let start = std::time::Instant::now();
        let mut child = self.child.take().unwrap();
        let status = loop {
            if let Some(st) = child.try_wait().unwrap() {
                break st;
            }
            if start.elapsed() > timeout {
                // SAFETY: kill touches no memory; try_wait found the child unreaped, so the pid is still its.
                unsafe { libc_kill(child.id() as i32, 15) };
                let t = std::time::Instant::now();
                loop {
                    if child.try_wait().unwrap().is_some() {
                        break;
                    }
                    if t.elapsed() > std::time::Duration::from_secs(20) {
                        let _ = child.kill();
                        break;
                    }
                    std::thread::sleep(std::time::Duration::from_millis(10));
                }
                break child.wait().unwrap();
            }
            std::thread::sleep(std::time::Duration::from_millis(10));
        };
        drop(self.stdin.take());
        for r in self.readers.drain(..) {
            let _ = r.join();
        }
        RunOutput { code: status.code(), stdout: self.stdout(), stderr: self.stderr() }
    }

    /// SIGTERM now (the runtime's clean shutdown) and the output.
    pub fn stop(self) -> RunOutput {
        self.wait(std::time::Duration::ZERO)
    }
}

impl Drop for Running {
    fn drop(&mut self) {
        if let Some(mut c) = self.child.take() {
            let _ = c.kill();
            let _ = c.wait();
        }
    }
}

/// Runs `cargo-openr <args>` in `dir` with extra environment variables.
pub fn cargo_openr_in(dir: &Path, args: &[&str], env: &[(&str, &str)]) -> Output {
    Command::new(exe()).args(args).current_dir(dir).envs(env.iter().copied()).output().expect("run cargo-openr")
}

/// Connects to a Unix socket the runtime is about to bind (retrying for `timeout`).
pub fn connect_unix(path: &Path, timeout: std::time::Duration) -> std::os::unix::net::UnixStream {
    let start = std::time::Instant::now();
    loop {
        match std::os::unix::net::UnixStream::connect(path) {
            Ok(s) => return s,
            Err(_) if start.elapsed() < timeout => std::thread::sleep(std::time::Duration::from_millis(10)),
            Err(e) => panic!("cannot connect to {}: {e}", path.display()),
        }
    }
}

/// Waits until `path` exists (a socket the runtime binds), at most `timeout`.
pub fn wait_for_path(path: &Path, timeout: std::time::Duration) -> bool {
    let start = std::time::Instant::now();
    while !path.exists() {
        if start.elapsed() > timeout {
            return false;
        }
        std::thread::sleep(std::time::Duration::from_millis(10));
    }
    true
}
