//! `cargo openr run --record DIR` and `cargo openr view DIR|TRACE`: a recording (or a
//! bare `--trace` file) replayed in the view's page, as headless Chromium renders it,
//! shows what the trace says at the same virtual time; its timeline steps and plays;
//! a recording at `--speed max` is the same bytes every run; bad input is a clear error.
use std::io::Read;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use crate::audio::wav_data;
use crate::support::{build, copy_tree, exe, read_trace, run_ms, sdk_root, Built};
use crate::view::{attr_of_id, cell, chromium, chromium_with, http, text_of_id};

pub(crate) const LEGS: [&str; 4] = ["PRM:/r2/c1-Joint2:21", "PRM:/r2/c1/c2/c3-Joint2:23", "PRM:/r3/c1-Joint2:31", "PRM:/r5/c1/c2/c3-Joint2:53"];

/// movelegs with imagesave's camera object added: legs that move and a camera.
fn legs_with_camera() -> Built {
    let legs = build("movelegs");
    let camera = build("imagesave");
    let (ms, cam) = (legs.ms(), camera.ms());
    std::fs::copy(cam.join("OPEN-R/MW/OBJS/IMGSAVE.BIN"), ms.join("OPEN-R/MW/OBJS/IMGSAVE.BIN")).unwrap();
    for cfg in ["OBJECT.CFG", "CONNECT.CFG"] {
        let mut text = std::fs::read_to_string(ms.join("OPEN-R/MW/CONF").join(cfg)).unwrap();
        text.push_str(&std::fs::read_to_string(cam.join("OPEN-R/MW/CONF").join(cfg)).unwrap());
        std::fs::write(ms.join("OPEN-R/MW/CONF").join(cfg), text).unwrap();
    }
    legs
}

/// `cargo openr view PATH` serving until dropped.
pub(crate) struct Viewer {
    child: Child,
    pub(crate) stderr: Arc<Mutex<String>>,
    pub(crate) addr: String,
}

impl Drop for Viewer {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

pub(crate) fn spawn_view(path: &Path) -> Viewer {
    let mut child = Command::new(exe()).arg("view").arg(path).stdout(Stdio::null()).stderr(Stdio::piped()).spawn().unwrap();
    let stderr = Arc::new(Mutex::new(String::new()));
    let (mut pipe, sink) = (child.stderr.take().unwrap(), stderr.clone());
    std::thread::spawn(move || {
        let mut buf = [0u8; 4096];
        while let Ok(n) = pipe.read(&mut buf) {
            if n == 0 {
                break;
            }
            sink.lock().unwrap().push_str(&String::from_utf8_lossy(&buf[..n]));
        }
    });
    let start = Instant::now();
    loop {
        let err = stderr.lock().unwrap().clone();
        if let Some((addr, _)) = err.split("Viewing http://").nth(1).and_then(|rest| rest.split_once("/\n")) {
            let addr = addr.to_string();
            return Viewer { child, stderr, addr };
        }
        let exited = child.try_wait().unwrap().is_some();
        assert!(!exited && start.elapsed() < Duration::from_secs(60), "no `Viewing` line:\n{err}");
        std::thread::sleep(Duration::from_millis(20));
    }
}

/// The body of `GET path` (binary).
pub(crate) fn get_bytes(addr: &str, path: &str) -> Vec<u8> {
    use std::io::Write;
    let mut s = std::net::TcpStream::connect(addr).unwrap();
    write!(s, "GET {path} HTTP/1.0\r\n\r\n").unwrap();
    let mut b = Vec::new();
    s.read_to_end(&mut b).unwrap();
    assert!(b.starts_with(b"HTTP/1.1 200") || b.starts_with(b"HTTP/1.0 200"), "GET {path}: {}", String::from_utf8_lossy(&b[..b.len().min(40)]));
    b[b.windows(4).position(|x| x == b"\r\n\r\n").unwrap() + 4..].to_vec()
}

/// The virtual times of the trace's records, each once, in order.
pub(crate) fn moments(trace: &[serde_json::Value]) -> Vec<u64> {
    let mut t: Vec<u64> = trace.iter().map(|r| r["t_ms"].as_u64().unwrap()).collect();
    t.dedup();
    t
}

/// The trace's newest sensor record at or before `t_ms`.
pub(crate) fn sensor_at(trace: &[serde_json::Value], t_ms: u64) -> &serde_json::Value {
    trace.iter().filter(|r| r["kind"] == "sensor" && r["t_ms"].as_u64().unwrap() <= t_ms).last().expect("a sensor record before t")
}

/// The page at `query` shows moment `t` with the legs' angles of the trace at `t`.
pub(crate) fn assert_shows(dom: &str, trace: &[serde_json::Value], t: u64, what: &str) {
    assert_eq!(text_of_id(dom, "t_ms"), t.to_string(), "{what}: the page's virtual time");
    let rec = sensor_at(trace, t);
    for loc in LEGS {
        let want = format!("{:.3}", rec["joints"][loc].as_f64().unwrap());
        assert_eq!(cell(dom, loc, "joint-deg"), want, "{what}: {loc} at {t} ms");
    }
}

#[test]
fn a_recording_replays_what_the_trace_says_at_the_same_virtual_time() {
    let p = legs_with_camera();
    let dir = tempfile::tempdir().unwrap();
    let rec = dir.path().join("rec");
    let out = run_ms(&p.ms(), &["--speed", "max", "--for", "3s", "--record", rec.to_str().unwrap()]);
    assert_eq!(out.code, Some(0), "{}", out.stderr);
    let trace = read_trace(&rec.join("trace.jsonl"));
    let index: Vec<serde_json::Value> = read_trace(&rec.join("camera.jsonl"));
    assert!(index.len() >= 80, "about 30 pictures a second for 3 s: {}", index.len());
    let first = std::fs::read(rec.join(index[0]["file"].as_str().unwrap())).unwrap();
    assert!(first.starts_with(b"\x89PNG"), "camera pictures are PNG");

    let view = spawn_view(&rec);
    let url = format!("http://{}/", view.addr);
    let times = moments(&trace);
    // A moment in the middle where the leg moves to the next one.
    let k = (times.len() / 2..times.len() - 1)
        .find(|&k| {
            let (a, b) = (sensor_at(&trace, times[k]), sensor_at(&trace, times[k + 1]));
            a["joints"][LEGS[0]] != b["joints"][LEGS[0]]
        })
        .expect("the leg moves in the second half");
    let t = times[k];
    let dom = chromium(&format!("{url}?t={t}"), None);
    assert_shows(&dom, &trace, t, "seek");
    // What the trace lacks comes from view.jsonl: the target, a distance, the battery.
    let view_rec = read_trace(&rec.join("view.jsonl")).into_iter().filter(|v| v["t_ms"].as_u64().unwrap() <= t).last().expect("a view record by then");
    let target = view_rec["targets"][LEGS[0]].as_f64().unwrap();
    assert_eq!(cell(&dom, LEGS[0], "joint-target"), format!("{target:.3}"), "the target at {t} ms");
    let psd = view_rec["sensors"].as_array().unwrap().iter().find(|s| s["kind"] == "psd").unwrap();
    let mm = psd["value"].as_f64().unwrap() / 1000.0;
    assert_eq!(cell(&dom, psd["locator"].as_str().unwrap(), "sensor-value"), format!("{mm:.1} mm"));
    assert_eq!(text_of_id(&dom, "battery-remaining"), format!("{} %", view_rec["battery"]["remaining_pct"]));
    // The camera picture of the moment: the newest one taken by then, as recorded.
    let n = index.iter().filter(|c| c["t_ms"].as_u64().unwrap() <= t).count();
    assert!(n > 0, "pictures by {t} ms");
    assert_eq!(attr_of_id(&dom, "camera", "src"), format!("/camera.png?n={n}"));
    let png = get_bytes(&view.addr, &format!("/camera.png?n={n}"));
    assert_eq!(png, std::fs::read(rec.join(index[n - 1]["file"].as_str().unwrap())).unwrap(), "picture {n} is served as recorded");

    // Step: the next moment of the trace; the leg drawing moved with it.
    let stepped = chromium(&format!("{url}?t={t}&step=1"), None);
    assert_shows(&stepped, &trace, times[k + 1], "step");
    assert_ne!(attr_of_id(&dom, "leg-side-LF", "points"), attr_of_id(&stepped, "leg-side-LF", "points"), "the drawn leg moved");
    let back = chromium(&format!("{url}?t={}&back=1", times[k + 1]), None);
    assert_shows(&back, &trace, t, "back");

    // Play from the start: virtual time runs on, and each moment shown is the trace's.
    let played = chromium_with(&format!("{url}?t=0&play=1"), None, &["--virtual-time-budget=1500"]);
    let shown: u64 = text_of_id(&played, "t_ms").parse().unwrap();
    assert!(shown > times[0] + 200, "playing moved on from {} ms: {shown} ms", times[0]);
    assert_shows(&played, &trace, shown, "play");
    let err = view.stderr.lock().unwrap().clone();
    assert!(err.contains(&format!("{} camera pictures", index.len())), "{err}");
}

#[test]
fn recording_at_speed_max_is_the_same_every_run() {
    let p = legs_with_camera();
    let dir = tempfile::tempdir().unwrap();
    let mut recs = Vec::new();
    for k in 0..2 {
        let rec = dir.path().join(format!("rec{k}"));
        let out = run_ms(&p.ms(), &["--speed", "max", "--for", "1s", "--record", rec.to_str().unwrap()]);
        assert_eq!(out.code, Some(0), "{}", out.stderr);
        recs.push(rec);
    }
    let files = |rec: &PathBuf| -> Vec<(String, Vec<u8>)> {
        let mut names = vec!["recording.json".to_string(), "trace.jsonl".into(), "view.jsonl".into(), "camera.jsonl".into()];
        for c in read_trace(&rec.join("camera.jsonl")) {
            names.push(c["file"].as_str().unwrap().to_string());
        }
        names.into_iter().map(|n| (n.clone(), std::fs::read(rec.join(&n)).unwrap())).collect()
    };
    let (a, b) = (files(&recs[0]), files(&recs[1]));
    assert!(a.len() > 20, "pictures recorded: {}", a.len() - 4);
    assert_eq!(a.len(), b.len(), "as many pictures");
    for ((name, x), (_, y)) in a.iter().zip(&b) {
        assert!(x == y, "{name} differs between two runs at --speed max");
    }
}

#[test]
fn a_recording_keeps_the_speaker_sound_on_the_virtual_timeline() {
    let p = build("soundplay");
    let dir = tempfile::tempdir().unwrap();
    let rec = dir.path().join("rec");
    let out = run_ms(&p.ms(), &["--speed", "max", "--for", "2s", "--record", rec.to_str().unwrap()]);
    assert_eq!(out.code, Some(0), "{}", out.stderr);
    let first: u64 =
        out.lines_starting("SoundPlay : buffer 0 played from frame").first().and_then(|l| l.rsplit(' ').next()?.parse().ok()).expect("buffer 0 played");
    let wav = std::fs::read(rec.join("speaker.wav")).unwrap();
    let tone = std::fs::read(p.ms().join("OPEN-R/MW/DATA/P/TONE.WAV")).unwrap();
    let (played, tone) = (wav_data(&wav), wav_data(&tone));
    // 16 kHz 16-bit mono: frame F (F x 8 ms) starts at (F - 1) x 8 ms, 256 bytes a frame.
    let at = (first as usize - 1) * 256;
    assert!(played[..at].iter().all(|b| *b == 0), "silence before the first sound");
    assert_eq!(&played[at..at + tone.len()], tone, "the tone from frame {first}'s start, sample for sample");
    let view = spawn_view(&rec);
    let dom = chromium(&format!("http://{}/", view.addr), None);
    assert_eq!(attr_of_id(&dom, "speaker", "src"), "/speaker.wav", "the page plays the recorded sound");
    assert_eq!(get_bytes(&view.addr, "/speaker.wav"), wav, "the sound is served as recorded");
    assert!(view.stderr.lock().unwrap().contains(", sound)"));
}

#[test]
fn a_trace_alone_replays_without_camera() {
    let p = build("movelegs");
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("t.jsonl");
    let out = run_ms(&p.ms(), &["--speed", "max", "--for", "2s", "--trace", path.to_str().unwrap()]);
    assert_eq!(out.code, Some(0), "{}", out.stderr);
    let trace = read_trace(&path);
    let view = spawn_view(&path);
    let times = moments(&trace);
    let t = times[times.len() * 2 / 3];
    let dom = chromium(&format!("http://{}/?t={t}", view.addr), None);
    assert_shows(&dom, &trace, t, "trace replay");
    assert!(dom.contains("id=\"camera-box\" hidden"), "no camera panel without pictures");
    assert_eq!(cell(&dom, LEGS[0], "joint-target"), "–", "no targets in a trace");
    assert!(!dom.contains("id=\"timeline-bar\" hidden"), "the timeline is shown");
}

/// `cargo openr view PATH` fails with a message containing every one of `want`.
pub(crate) fn fails_with(path: &Path, want: &[&str]) {
    // A recording wrongly accepted would be served until killed: bound the wait, so the
    // test fails instead of hanging (a refusal comes at once).
    let mut child = Command::new(exe()).arg("view").arg(path).stdout(std::process::Stdio::piped()).stderr(std::process::Stdio::piped()).spawn().unwrap();
    let start = std::time::Instant::now();
    while child.try_wait().unwrap().is_none() {
        if start.elapsed() > std::time::Duration::from_secs(60) {
            let _ = child.kill();
            let out = child.wait_with_output().unwrap();
            panic!("{}: still serving after 60 s (accepted?): {}", path.display(), String::from_utf8_lossy(&out.stderr));
        }
        std::thread::sleep(std::time::Duration::from_millis(10));
    }
    let out = child.wait_with_output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{}: {err}", path.display());
    for w in want {
        assert!(err.contains(w), "{}: wanted {w:?} in:\n{err}", path.display());
    }
    assert!(!err.contains("panicked") && !err.contains("Viewing"), "{err}");
}

#[test]
fn bad_recordings_are_clear_errors() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let missing = d.join("nothing-here");
    fails_with(&missing, &[&format!("{}: no such file or directory", missing.display())]);
    fails_with(d, &[&format!("{}: not a recording (it has no recording.json)", d.display())]);

    // A good recording of two moments, then each part spoiled in turn.
    let good = d.join("good");
    std::fs::create_dir_all(good.join("camera")).unwrap();
    let manifest = r#"{"format":"cargo-openr recording","version":1,"design":"ERS-7","trace":"trace.jsonl","camera":"camera.jsonl","speaker":"speaker.wav"}"#;
    std::fs::write(good.join("recording.json"), manifest).unwrap();
    let sensor = |t: u64| {
        format!(
            r#"{{"t_ms":{t},"frame":{},"kind":"sensor","first_frame":1,"joints":{{"PRM:/r2/c1-Joint2:21":1.5}},"accel":[0,0,9.8],"paws":[true,true,true,true]}}"#,
            t / 8
        )
    };
    std::fs::write(good.join("trace.jsonl"), format!("{}\n{}\n", sensor(32), sensor(64))).unwrap();
    std::fs::write(good.join("camera.jsonl"), "{\"n\":1,\"t_ms\":40,\"frame\":5,\"file\":\"camera/000001.png\"}\n").unwrap();
    std::fs::write(good.join("camera/000001.png"), b"\x89PNG").unwrap();
    {
        let v = spawn_view(&good);
        let (code, _) = http(&v.addr, "GET", "/", "");
        assert_eq!(code, 200, "the good recording is served");
    }
    let spoilt = |name: &str, file: &str, text: &str| {
        let dir = d.join(name);
        copy_tree(&good, &dir);
        std::fs::write(dir.join(file), text).unwrap();
        dir
    };
    let r = spoilt("manifest", "recording.json", "{\"format\": \"cargo-openr recording\",\n  \"version\": 1,,\n}");
    fails_with(&r, &[&format!("{}:2: not JSON", r.join("recording.json").display())]);
    let r = spoilt("version", "recording.json", &manifest.replace("\"version\":1", "\"version\":7"));
    fails_with(&r, &["recording.json: recording version 7"]);
    let r = spoilt("cut", "trace.jsonl", &format!("{}\n{}", sensor(32), &sensor(64)[..50]));
    fails_with(&r, &[&format!("{}:2: the trace ends in the middle of a record", r.join("trace.jsonl").display())]);
    let r = spoilt("corrupt", "trace.jsonl", &format!("{}\nnot json\n{}\n", sensor(32), sensor(64)));
    fails_with(&r, &[&format!("{}:2: not a trace record", r.join("trace.jsonl").display())]);
    let r = spoilt("fields", "trace.jsonl", &format!("{}\n{{\"kind\":\"led\"}}\n", sensor(32)));
    fails_with(&r, &["trace.jsonl:2: not a trace record: it needs \"t_ms\", \"frame\" and \"kind\""]);
    let r = spoilt("backwards", "trace.jsonl", &format!("{}\n{}\n", sensor(64), sensor(32)));
    fails_with(&r, &["trace.jsonl:2: time goes back (32 ms after 64 ms)"]);
    let r = spoilt("empty", "trace.jsonl", "");
    fails_with(&r, &["trace.jsonl: no trace records"]);
    let r = spoilt("picture", "camera.jsonl", "{\"n\":1,\"t_ms\":40,\"frame\":5,\"file\":\"camera/000009.png\"}\n");
    fails_with(&r, &[&format!("{}:1: the picture", r.join("camera.jsonl").display()), "000009.png is missing"]);
    let r = spoilt("view", "view.jsonl", "{\"t_ms\":32,\"targets\":{}}\n{\"targets\":{}}\n");
    fails_with(&r, &[&format!("{}:2: not a view record: it needs \"t_ms\"", r.join("view.jsonl").display())]);
    let r = spoilt("viewback", "view.jsonl", "{\"t_ms\":64,\"targets\":{}}\n{\"t_ms\":32,\"targets\":{}}\n");
    fails_with(&r, &[&format!("{}:2: time goes back (32 ms)", r.join("view.jsonl").display())]);
    let r = spoilt("viewjson", "view.jsonl", "[1,\n");
    fails_with(&r, &[&format!("{}:1: not a view record", r.join("view.jsonl").display())]);
    let r = spoilt("notrace", "trace.jsonl", "");
    std::fs::remove_file(r.join("trace.jsonl")).unwrap();
    fails_with(&r, &[&format!("{}: no such file or directory", r.join("trace.jsonl").display())]);
    // A bare trace file is checked the same way.
    let bare = d.join("bare.jsonl");
    std::fs::write(&bare, format!("{}\n{{oops\n", sensor(32))).unwrap();
    fails_with(&bare, &[&format!("{}:2: not a trace record", bare.display())]);
}

#[test]
fn record_refuses_what_it_cannot_record() {
    let dir = tempfile::tempdir().unwrap();
    let out = Command::new(exe()).env("OPENRSDK_ROOT", sdk_root()).arg("run").arg(dir.path()).args(["--record", "r", "--trace", "t"]).output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_ne!(out.status.code(), Some(0), "{err}");
    assert!(err.contains("--record") && err.contains("--trace") && err.contains("cannot be used with"), "{err}");
}

/// The recording's index as the page inlines it (`const REPLAY = …;`).
fn inlined_index(page: &str) -> serde_json::Value {
    let json = page.split("const REPLAY = ").nth(1).and_then(|r| r.split(";\n").next()).expect("the inlined index");
    serde_json::from_str(json).unwrap()
}

#[test]
fn a_long_recording_is_served_in_chunks() {
    let p = build("movelegs");
    let dir = tempfile::tempdir().unwrap();
    let rec = dir.path().join("rec");
    let out = run_ms(&p.ms(), &["--speed", "max", "--for", "12s", "--record", rec.to_str().unwrap()]);
    assert_eq!(out.code, Some(0), "{}", out.stderr);
    let trace = read_trace(&rec.join("trace.jsonl"));
    let times = moments(&trace);
    let view = spawn_view(&rec);
    let (code, page) = http(&view.addr, "GET", "/", "");
    assert_eq!(code, 200);
    let index = inlined_index(&page);
    let chunk = index["chunk"].as_u64().unwrap() as usize;
    let r = &index["robots"][0];
    assert_eq!(r["count"].as_u64().unwrap() as usize, times.len());
    let chunks = times.len().div_ceil(chunk);
    assert!(chunks >= 4, "12 s make several chunks of {chunk} moments: {chunks}");
    let starts: Vec<u64> = r["starts"].as_array().unwrap().iter().map(|v| v.as_u64().unwrap()).collect();
    assert_eq!(starts, times.iter().step_by(chunk).copied().collect::<Vec<_>>(), "each chunk's first moment");
    let keys: Vec<&String> = index["loaded"].as_object().unwrap().keys().collect();
    assert_eq!(keys, ["0"], "only the first chunk comes with the page");
    // A chunk: its moments, in order.
    let (code, body) = http(&view.addr, "GET", "/chunk?n=2", "");
    assert_eq!(code, 200, "{body}");
    let part: Vec<serde_json::Value> = serde_json::from_str(&body).unwrap();
    let shown: Vec<u64> = part.iter().map(|s| s["t_ms"].as_u64().unwrap()).collect();
    assert_eq!(shown, times[2 * chunk..3 * chunk]);
    let (code, _) = http(&view.addr, "GET", &format!("/chunk?n={chunks}"), "");
    assert_eq!(code, 404, "no chunk past the end");
    // Seeking late in the run inlines that moment's chunk, not the first.
    let t = times[3 * chunk + chunk / 2];
    let (_, page) = http(&view.addr, "GET", &format!("/?t={t}"), "");
    let keys: Vec<String> = inlined_index(&page)["loaded"].as_object().unwrap().keys().cloned().collect();
    assert_eq!(keys, ["3"], "the chunk of {t} ms");
    assert_shows(&chromium(&format!("http://{}/?t={t}", view.addr), None), &trace, t, "seek");
    // Playing from the start fetches the chunks it reaches.
    let played = chromium_with(&format!("http://{}/?t=0&play=1", view.addr), None, &["--virtual-time-budget=6000"]);
    let shown: u64 = text_of_id(&played, "t_ms").parse().unwrap();
    assert!(shown > times[2 * chunk], "playing went past the first two chunks: {shown} ms");
    assert_shows(&played, &trace, shown, "play");
}

#[test]
fn a_recording_replays_the_message_counts_of_each_connection() {
    let p = build("pingpong");
    let dir = tempfile::tempdir().unwrap();
    let rec = dir.path().join("rec");
    let out = run_ms(&p.ms(), &["--speed", "max", "--for", "2s", "--record", rec.to_str().unwrap()]);
    assert_eq!(out.code, Some(0), "{}", out.stderr);
    let views = read_trace(&rec.join("view.jsonl"));
    let link = "Ping.Ball.longword.S Pong.Ball.longword.O";
    let notify = |v: &serde_json::Value| v["connections"][0]["notify"].as_u64().unwrap();
    let first = views.iter().find(|v| notify(v) > 0).expect("a view record after the first notification");
    let last = views.last().unwrap();
    let view = spawn_view(&rec);
    let url = format!("http://{}/", view.addr);
    let mut shown = Vec::new();
    for v in [first, last] {
        let dom = chromium(&format!("{url}?t={}", v["t_ms"]), None);
        let t: u64 = text_of_id(&dom, "t_ms").parse().unwrap();
        let recorded = views.iter().filter(|v| v["t_ms"].as_u64().unwrap() <= t).last().unwrap();
        let n: u64 = cell(&dom, link, "link-notify").parse().unwrap();
        assert_eq!(n, notify(recorded), "at {t} ms the page shows the recorded count");
        assert_eq!(text_of_id(&dom, "objects"), "ping, pong");
        shown.push(n);
    }
    assert!(shown[1] > shown[0], "more messages later: {shown:?}");
    drop(view);

    // A recording made before the view counted messages still replays, without them.
    let old: String = views
        .iter()
        .map(|v| {
            let mut v = v.clone();
            v.as_object_mut().unwrap().retain(|k, _| k != "objects" && k != "connections");
            format!("{v}\n")
        })
        .collect();
    std::fs::write(rec.join("view.jsonl"), old).unwrap();
    let view = spawn_view(&rec);
    let dom = chromium(&format!("http://{}/?t={}", view.addr, last["t_ms"]), None);
    assert_eq!(text_of_id(&dom, "objects"), "–");
    assert!(!dom.contains(&format!("data-locator=\"{link}\"")), "no connection rows");
    assert!(text_of_id(&dom, "t_ms").parse::<u64>().unwrap() > 0, "the moment is shown");
}
