//! `cargo openr run --view`: the live page, as a real browser (headless Chromium, from
//! `tools/deps.sh`) renders it, agrees with the trace of the same run. The runs are
//! paused through the page's own control endpoint before each look, so nothing here
//! depends on the machine's speed.
use std::io::{Read, Write};
use std::net::TcpStream;
use std::path::Path;
use std::process::Command;
use std::time::{Duration, Instant};

use crate::support::{build, exe, read_trace, sdk_root, spawn_ms, Running};

/// Waits for `Viewing http://ADDR/` on stderr; returns ADDR.
pub(crate) fn view_addr(run: &mut Running) -> String {
    let start = Instant::now();
    loop {
        let err = run.stderr();
        // The whole line: stderr arrives in pieces.
        if let Some((addr, _)) = err.split("Viewing http://").nth(1).and_then(|rest| rest.split_once("/\n")) {
            return addr.to_string();
        }
        assert!(start.elapsed() < Duration::from_secs(60), "no `Viewing` line:\n{err}");
        std::thread::sleep(Duration::from_millis(20));
    }
}

/// One HTTP/1.0 request; (status, body).
pub(crate) fn http(addr: &str, method: &str, path: &str, body: &str) -> (u16, String) {
    let mut s = TcpStream::connect(addr).unwrap();
    write!(s, "{method} {path} HTTP/1.0\r\nHost: {addr}\r\nContent-Length: {}\r\n\r\n{body}", body.len()).unwrap();
    let mut out = String::new();
    s.read_to_string(&mut out).unwrap();
    let status = out.split_whitespace().nth(1).and_then(|c| c.parse().ok()).unwrap_or(0);
    (status, out.split_once("\r\n\r\n").map_or(String::new(), |(_, b)| b.to_string()))
}

/// Pauses the run once its virtual time reached `at_ms`; returns the paused time.
pub(crate) fn pause_after(addr: &str, at_ms: u64) -> u64 {
    let start = Instant::now();
    loop {
        // A world's robot answers 503 until its runtime serves.
        let (code, body) = http(addr, "GET", "/state", "");
        let s: serde_json::Value = if code == 200 { serde_json::from_str(&body).unwrap() } else { serde_json::Value::Null };
        if s["t_ms"].as_u64().is_some_and(|t| t >= at_ms) {
            break;
        }
        assert!(start.elapsed() < Duration::from_secs(120), "the run never reached {at_ms} ms");
        std::thread::sleep(Duration::from_millis(20));
    }
    control(addr, "pause")
}

/// A `--control` command through the page's endpoint; the answer's t_ms.
pub(crate) fn control(addr: &str, line: &str) -> u64 {
    let (code, answer) = http(addr, "POST", "/control", line);
    assert_eq!(code, 200, "{line}: {answer}");
    answer.split_whitespace().find_map(|w| w.strip_prefix("t_ms=")).and_then(|v| v.parse().ok()).unwrap_or(0)
}

/// Headless Chromium on the page: `--dump-dom` (the DOM after load), or a screenshot.
pub(crate) fn chromium(url: &str, screenshot: Option<&Path>) -> String {
    chromium_with(url, screenshot, &[])
}

pub(crate) fn chromium_with(url: &str, screenshot: Option<&Path>, extra: &[&str]) -> String {
    // A load that has not ended after CHROMIUM_GUARD fails the test: it never hangs the
    // suite, and a stall is not retried away (one that lasted ~6 minutes was the view
    // server's: tiny_http's pool had left a connection of the page's burst unserved).
    chromium_once(url, screenshot, extra).unwrap_or_else(|| panic!("chromium did not end within {CHROMIUM_GUARD:?} on {url}"))
}

/// A failure guard, far beyond a normal load (1–3 s).
const CHROMIUM_GUARD: Duration = Duration::from_secs(120);

/// Its standard output (the DOM with `--dump-dom`), or None once CHROMIUM_GUARD
/// passed (it is killed).
fn chromium_once(url: &str, screenshot: Option<&Path>, extra: &[&str]) -> Option<String> {
    let profile = tempfile::tempdir().unwrap();
    let mut cmd = Command::new("chromium");
    cmd.args(["--headless", "--disable-gpu", "--no-sandbox", "--no-first-run", "--hide-scrollbars"])
        .arg(format!("--user-data-dir={}", profile.path().display()));
    match screenshot {
        Some(p) => cmd.arg("--window-size=1100,820").arg(format!("--screenshot={}", p.display())),
        None => cmd.arg("--dump-dom"),
    };
    // Files, not pipes: nothing to drain while waiting.
    let (out, err) = (profile.path().join("stdout"), profile.path().join("stderr"));
    cmd.stdout(std::fs::File::create(&out).unwrap()).stderr(std::fs::File::create(&err).unwrap());
    let mut child = cmd.args(extra).arg(url).spawn().expect("chromium (install it with tools/deps.sh)");
    let start = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().unwrap() {
            break status;
        }
        if start.elapsed() > CHROMIUM_GUARD {
            let _ = child.kill();
            let _ = child.wait();
            return None;
        }
        std::thread::sleep(Duration::from_millis(50));
    };
    assert!(status.success(), "chromium failed: {}", std::fs::read_to_string(&err).unwrap_or_default());
    Some(String::from_utf8_lossy(&std::fs::read(&out).unwrap()).into_owned())
}

/// The text of the element of class `class` after `data-locator="loc"` in a DOM dump.
pub(crate) fn cell(dom: &str, loc: &str, class: &str) -> String {
    let at = dom.find(&format!("<tr data-locator=\"{loc}\"")).unwrap_or_else(|| panic!("no row for {loc}"));
    let rest = &dom[at..];
    let from = rest.find(&format!("{class}\">")).unwrap_or_else(|| panic!("no {class} for {loc}")) + class.len() + 2;
    rest[from..].split('<').next().unwrap().to_string()
}

/// The value of attribute `attr` of the element with `id`.
pub(crate) fn attr_of_id(dom: &str, id: &str, name: &str) -> String {
    let at = dom.find(&format!("id=\"{id}\"")).unwrap_or_else(|| panic!("no element {id}"));
    let tag_start = dom[..at].rfind('<').unwrap();
    attr(&dom[tag_start..tag_start + dom[tag_start..].find('>').unwrap()], name).to_string()
}

/// The value of attribute `name` in the markup of one tag.
pub(crate) fn attr<'a>(tag: &'a str, name: &str) -> &'a str {
    let from = tag.find(&format!(" {name}=\"")).unwrap_or_else(|| panic!("no {name} in {tag}")) + name.len() + 3;
    tag[from..].split('"').next().unwrap()
}

pub(crate) fn text_of_id(dom: &str, id: &str) -> String {
    let at = dom.find(&format!("id=\"{id}\"")).unwrap_or_else(|| panic!("no element {id}"));
    let from = at + dom[at..].find('>').unwrap() + 1;
    dom[from..].split('<').next().unwrap().to_string()
}

/// The trace's sensor records just before and after `t_ms`.
fn sensor_around(trace: &[serde_json::Value], t_ms: u64) -> (&serde_json::Value, &serde_json::Value) {
    let sensors: Vec<_> = trace.iter().filter(|r| r["kind"] == "sensor").collect();
    let after = sensors.iter().position(|r| r["t_ms"].as_u64().unwrap() >= t_ms).expect("a sensor record after the pause");
    (sensors[after.saturating_sub(1)], sensors[after])
}

#[test]
fn page_shows_the_joint_angles_of_the_trace_and_the_legs_move() {
    let p = build("movelegs");
    let dir = tempfile::tempdir().unwrap();
    let trace = dir.path().join("t.jsonl");
    let mut run = spawn_ms(&p.ms(), &["--view", "--speed", "1", "--for", "4s", "--trace", trace.to_str().unwrap()], &[]);
    let addr = view_addr(&mut run);
    assert!(addr.starts_with("127.0.0.1:"), "loopback by default: {addr}");
    let url = format!("http://{addr}/");
    let t1 = pause_after(&addr, 1000);
    let dom1 = chromium(&url, None);
    assert_eq!(text_of_id(&dom1, "t_ms"), t1.to_string(), "the page shows the paused virtual time");
    let t2 = control(&addr, "step 30");
    assert_eq!(t2, t1 + 240);
    let dom2 = chromium(&url, None);
    let shot = dir.path().join("view.png");
    chromium(&url, Some(&shot));
    let png = std::fs::read(&shot).unwrap();
    assert!(png.starts_with(b"\x89PNG") && png.len() > 10_000, "a screenshot of the page");
    if let Ok(to) = std::env::var("OPENR_VIEW_SCREENSHOT") {
        std::fs::copy(&shot, to).unwrap();
    }
    control(&addr, "resume");
    let out = run.wait(Duration::from_secs(120));
    assert_eq!(out.code, Some(0), "{}", out.stderr);

    let trace = read_trace(&trace);
    let legs = ["PRM:/r2/c1-Joint2:21", "PRM:/r2/c1/c2/c3-Joint2:23", "PRM:/r3/c1-Joint2:31", "PRM:/r5/c1/c2/c3-Joint2:53"];
    let mut moved = 0.0f64;
    for (dom, t) in [(&dom1, t1), (&dom2, t2)] {
        let (before, after) = sensor_around(&trace, t);
        for loc in legs {
            let shown: f64 = cell(dom, loc, "joint-deg").parse().unwrap();
            let (a, b) = (before["joints"][loc].as_f64().unwrap(), after["joints"][loc].as_f64().unwrap());
            let (lo, hi) = (a.min(b) - 0.01, a.max(b) + 0.01);
            assert!((lo..=hi).contains(&shown), "{loc} at {t} ms: the page shows {shown}°, the trace {a}°..{b}°");
        }
        moved = moved.max((cell(&dom1, legs[0], "joint-deg").parse::<f64>().unwrap() - cell(dom, legs[0], "joint-deg").parse::<f64>().unwrap()).abs());
    }
    assert!(moved > 1.0, "movelegs moves the left front leg between {t1} and {t2} ms");
    let (a, b) = (attr_of_id(&dom1, "leg-side-LF", "points"), attr_of_id(&dom2, "leg-side-LF", "points"));
    assert_ne!(a, b, "the drawn leg moved");
}

#[test]
fn page_lights_the_leds_blinkleds_lights() {
    let p = build("blinkleds");
    let dir = tempfile::tempdir().unwrap();
    let trace = dir.path().join("t.jsonl");
    let mut run = spawn_ms(&p.ms(), &["--view", "127.0.0.1:0", "--for", "3s", "--trace", trace.to_str().unwrap()], &[]);
    let addr = view_addr(&mut run);
    let t = pause_after(&addr, 700);
    let dom = chromium(&format!("http://{addr}/"), None);
    control(&addr, "resume");
    let out = run.wait(Duration::from_secs(120));
    assert_eq!(out.code, Some(0), "{}", out.stderr);
    let trace = read_trace(&trace);
    // Each head LED2 as the trace last set it at the paused time, and its colour on the page.
    let mut checked = 0;
    for (code, on_colour) in [("l1", "rgb(255,140,0)"), ("l2", "rgb(255,255,255)"), ("l4", "rgb(40,230,60)"), ("l5", "rgb(60,110,255)")] {
        let loc = format!("PRM:/r1/c1/c2/c3/{code}-LED2:{code}");
        let on = trace
            .iter()
            .filter(|r| r["kind"] == "led" && r["locator"] == loc.as_str() && r["t_ms"].as_u64().unwrap() <= t)
            .last()
            .map_or(false, |r| r["on"] == true);
        let at = dom.find(&format!("data-locator=\"{loc}\"")).unwrap_or_else(|| panic!("no LED {loc} on the page"));
        let tag = &dom[dom[..at].rfind('<').unwrap()..at + dom[at..].find('>').unwrap()];
        let expect = if on { on_colour } else { "rgb(45,45,45)" };
        assert!(tag.contains(&format!("fill=\"{expect}\"")), "{loc} is {} at {t} ms: {tag}", if on { "on" } else { "off" });
        checked += on as usize;
    }
    assert!(checked > 0, "some head light is on at {t} ms");
}

#[test]
fn a_view_port_in_use_is_a_clear_error() {
    let taken = std::net::TcpListener::bind("127.0.0.1:0").unwrap();
    let addr = taken.local_addr().unwrap().to_string();
    let p = build("hello");
    let out = Command::new(exe()).env("OPENRSDK_ROOT", sdk_root()).args(["run", "--for", "1s", "--view", &addr]).arg(p.ms()).output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_ne!(out.status.code(), Some(0), "{err}");
    assert!(err.contains(&format!("--view {addr}: cannot listen")) && err.contains("in use"), "{err}");
    assert!(!err.contains("Viewing"), "{err}");
}

#[test]
fn view_before_ms_dir_is_taken_for_the_address() {
    let dir = tempfile::tempdir().unwrap();
    // `--view` before MS_DIR takes it for the address: the error says so.
    let out = Command::new(exe()).args(["run", "--view"]).arg(dir.path()).output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_ne!(out.status.code(), Some(0), "{err}");
    assert!(err.contains("is not an address") && err.contains("give MS_DIR before --view"), "{err}");
}

#[test]
fn page_shows_the_camera_picture() {
    let p = build("imagesave");
    let dir = tempfile::tempdir().unwrap();
    // The camera sees a picture: left half red, right half blue.
    let (w, h) = (416usize, 320usize);
    let mut ppm = format!("P6 {w} {h} 255\n").into_bytes();
    for _ in 0..h {
        for x in 0..w {
            ppm.extend_from_slice(if x < w / 2 { &[220, 30, 30] } else { &[30, 30, 220] });
        }
    }
    let pic = dir.path().join("pic.ppm");
    std::fs::write(&pic, ppm).unwrap();
    let mut run = spawn_ms(&p.ms(), &["--view", "--for", "3s", "--images", pic.to_str().unwrap()], &[]);
    let addr = view_addr(&mut run);
    let t = pause_after(&addr, 500);
    let (code, png) = {
        let mut s = TcpStream::connect(&addr).unwrap();
        write!(s, "GET /camera.png HTTP/1.0\r\n\r\n").unwrap();
        let mut out = Vec::new();
        s.read_to_end(&mut out).unwrap();
        let at = out.windows(4).position(|x| x == b"\r\n\r\n").unwrap() + 4;
        (String::from_utf8_lossy(&out[..12]).into_owned(), out[at..].to_vec())
    };
    assert!(code.contains("200"), "{code}");
    let dom = chromium_with(&format!("http://{addr}/"), None, &["--virtual-time-budget=2000"]);
    control(&addr, "resume");
    let out = run.wait(Duration::from_secs(120));
    assert_eq!(out.code, Some(0), "{}", out.stderr);

    let mut reader = png::Decoder::new(&png[..]).read_info().unwrap();
    let mut buf = vec![0; reader.output_buffer_size()];
    let info = reader.next_frame(&mut buf).unwrap();
    assert_eq!((info.width, info.height), (w as u32, h as u32));
    let px = |x: usize, y: usize| &buf[(y * w + x) * 3..(y * w + x) * 3 + 3];
    assert_eq!(px(20, 160), &[220, 30, 30], "left: red");
    assert_eq!(px(400, 160), &[30, 30, 220], "right: blue");
    let shown: u64 = text_of_id(&dom, "camera-images").parse().unwrap();
    assert!(shown >= t / 34, "about 30 pictures a second by {t} ms: the page counts {shown}");
    assert!(!attr_of_id(&dom, "camera-box", "id").is_empty() && !dom.contains("id=\"camera-box\" hidden"), "the camera panel is shown");
    assert!(attr_of_id(&dom, "camera", "src").starts_with("/camera.png"), "the page loads the picture");
}

/// A loopback proxy in front of the view server that steps the paused run by
/// `frames` just before it forwards the page's first `/state` poll: the poll then
/// must see a later moment than the page was served with, whatever the machine's speed.
fn step_before_first_poll(upstream: String, frames: u32) -> String {
    use std::net::{Shutdown, TcpListener};
    use std::sync::atomic::{AtomicBool, Ordering};
    use std::sync::Arc;
    let listener = TcpListener::bind("127.0.0.1:0").unwrap();
    let addr = listener.local_addr().unwrap().to_string();
    let stepped = Arc::new(AtomicBool::new(false));
    std::thread::spawn(move || {
        for client in listener.incoming().flatten() {
            let (upstream, stepped) = (upstream.clone(), stepped.clone());
            std::thread::spawn(move || {
                let Ok(server) = TcpStream::connect(&upstream) else { return };
                let (mut from_client, mut to_server) = (client.try_clone().unwrap(), server.try_clone().unwrap());
                let (mut from_server, mut to_client) = (server, client);
                std::thread::spawn(move || {
                    let _ = std::io::copy(&mut from_server, &mut to_client);
                    let _ = to_client.shutdown(Shutdown::Both);
                });
                let mut buf = [0; 16384];
                while let Ok(n @ 1..) = from_client.read(&mut buf) {
                    if buf[..n].starts_with(b"GET /state") && !stepped.swap(true, Ordering::SeqCst) {
                        control(&upstream, &format!("step {frames}"));
                    }
                    if to_server.write_all(&buf[..n]).is_err() {
                        break;
                    }
                }
                let _ = to_server.shutdown(Shutdown::Write);
            });
        }
    });
    addr
}

#[test]
fn page_follows_the_run() {
    let p = build("movelegs");
    let mut run = spawn_ms(&p.ms(), &["--view", "--speed", "max"], &[]);
    let addr = view_addr(&mut run);
    let paused = pause_after(&addr, 200);
    // The page as served carries the paused moment; its polling draws the newer one.
    let proxy = step_before_first_poll(addr, 30);
    let dom = chromium_with(&format!("http://{proxy}/"), None, &["--virtual-time-budget=3000"]);
    let _ = run.stop();
    let inlined = dom.split("const INITIAL = ").nth(1).and_then(|r| r.split("\"t_ms\":").nth(1)).expect("the inlined snapshot");
    let initial: u64 = inlined.split(|c: char| !c.is_ascii_digit()).next().unwrap().parse().unwrap();
    assert_eq!(initial, paused, "the page was served with the paused moment");
    let shown: u64 = text_of_id(&dom, "t_ms").parse().unwrap();
    assert!(shown > initial, "the page drew a later state than the one it was served with ({shown} ms vs {initial} ms)");
}

#[test]
fn camera_png_is_not_found_while_the_camera_took_no_picture() {
    // hello never opens the camera: the run has no picture to show, nor a CDT layer
    // (view_cdt.rs), which is no server error.
    let p = build("hello");
    let mut run = spawn_ms(&p.ms(), &["--view", "--speed", "max"], &[]);
    let addr = view_addr(&mut run);
    pause_after(&addr, 200);
    let (code, body) = http(&addr, "GET", "/camera.png", "");
    let (cdt_code, cdt_body) = http(&addr, "GET", "/cdt.png", "");
    let (_, state) = http(&addr, "GET", "/state", "");
    let _ = run.stop();
    assert_eq!(code, 404, "{body}");
    assert!(body.contains("no picture"), "{body}");
    assert_eq!(cdt_code, 404, "{cdt_body}");
    assert!(cdt_body.contains("no CDT layer") && cdt_body.contains("no picture"), "{cdt_body}");
    let state: serde_json::Value = serde_json::from_str(&state).unwrap();
    assert_eq!(state["camera_images"], 0, "{state}");
}

#[test]
fn page_lists_the_objects_and_counts_the_messages_of_each_connection() {
    let p = build("pingpong");
    let mut run = spawn_ms(&p.ms(), &["--view", "--speed", "max"], &[]);
    let addr = view_addr(&mut run);
    let url = format!("http://{addr}/");
    let link = "Ping.Ball.longword.S Pong.Ball.longword.O";
    let count = |dom: &str, class: &str| -> u64 { cell(dom, link, class).parse().unwrap() };
    pause_after(&addr, 200);
    let dom1 = chromium(&url, None);
    control(&addr, "resume");
    pause_after(&addr, 600);
    let dom2 = chromium(&url, None);
    let _ = run.stop();
    assert_eq!(text_of_id(&dom1, "objects"), "ping, pong", "the program's objects, by their ocf NAME");
    let (n1, n2) = (count(&dom1, "link-notify"), count(&dom2, "link-notify"));
    assert!(n1 > 0 && n2 > n1, "the ball's notifications: {n1} at the first look, {n2} at the second");
    // Each notification Pong answers with one ready.
    let (r1, r2) = (count(&dom1, "link-ready"), count(&dom2, "link-ready"));
    assert!(r1 > 0 && r2 > r1, "the ready messages: {r1}, then {r2}");
}
