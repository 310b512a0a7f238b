//! `cargo openr run --sim mujoco --view / --record` and the replay of a world: one page
//! shows every robot of the simulated world (a card each, the selected one in full), the
//! field from above with robots and ball where the simulator's ground truth puts them,
//! and each robot's camera picture; as headless Chromium renders it (its DOM and the
//! pixels of its screenshots). Runs at `--speed max`, paused through the page's own
//! control endpoint before each look.
use std::path::Path;
use std::time::Duration;

use serde_json::Value;

use crate::mujoco::head_camera_ms;
use crate::replay::{assert_shows, fails_with, get_bytes, moments, sensor_at, spawn_view, LEGS};
use crate::support::{build, read_trace, run_ms, spawn_ms};
use crate::view::{attr_of_id, cell, chromium, chromium_with, control, http, pause_after, text_of_id, view_addr};

/// (width, height, RGB) of a PNG (RGB or RGBA).
fn pixels(png: &[u8]) -> (usize, usize, Vec<[u8; 3]>) {
    let mut reader = png::Decoder::new(png).read_info().unwrap();
    let mut buf = vec![0; reader.output_buffer_size()];
    let info = reader.next_frame(&mut buf).unwrap();
    let step = info.color_type.samples();
    assert!(step >= 3, "a colour picture: {:?}", info.color_type);
    let px = buf[..info.buffer_size()].chunks(step).map(|c| [c[0], c[1], c[2]]).collect();
    (info.width as usize, info.height as usize, px)
}

fn orange(p: [u8; 3]) -> bool {
    let (r, g, b) = (p[0] as i32, p[1] as i32, p[2] as i32);
    r > 150 && g * 100 < r * 65 && g * 100 > r * 25 && b < 60
}

fn near(p: [u8; 3], want: [u8; 3], by: i32) -> bool {
    (0..3).all(|i| (p[i] as i32 - want[i] as i32).abs() <= by)
}

fn f(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

/// Robot 0 runs movehead with imagesave's camera object, robot 1 movelegs; the ball
/// lies 0.8 m ahead of robot 0.
fn world_args<'a>(legs: &'a Path, extra: &[&'a str]) -> Vec<&'a str> {
    let mut a = vec![legs.to_str().unwrap(), "--sim", "mujoco", "--speed", "max", "--sim-arg=--ball=0.8,0.1"];
    a.extend_from_slice(extra);
    a
}

#[test]
fn the_live_page_shows_every_robot_the_field_and_the_cameras() {
    let (head, _cam) = head_camera_ms();
    let legs = build("movelegs");
    let mut run = spawn_ms(&head.ms(), &world_args(&legs.ms(), &["--for", "4s", "--view"]), &[]);
    let addr = view_addr(&mut run);
    assert!(addr.starts_with("127.0.0.1:"), "{addr}");
    // The world's pause button is robot 0's: its lockstep holds every robot.
    let t = pause_after(&addr, 1000);
    let get = |path: &str| -> Value {
        let (code, body) = http(&addr, "GET", path, "");
        assert_eq!(code, 200, "GET {path}: {body}");
        serde_json::from_str(&body).unwrap()
    };
    let (s0, s1, truth) = (get("/robot/0/state"), get("/robot/1/state"), get("/world"));
    assert_eq!(s0["t_ms"], t, "robot 0 paused at {t} ms");
    assert!(s1["t_ms"].as_u64().unwrap().abs_diff(t) <= 8, "robot 1 runs in lockstep: {} ms vs {t} ms", s1["t_ms"]);
    let (code, body) = http(&addr, "GET", "/robot/5/state", "");
    assert!(code == 503 && body.contains("robot 5 is not running"), "{code} {body}");

    // Robot 1 selected: its joints as its runtime reports them, its card marked.
    let dom = chromium(&format!("http://{addr}/?robot=1"), None);
    assert_eq!(text_of_id(&dom, "t_ms"), s1["t_ms"].to_string());
    for loc in LEGS {
        let j = s1["joints"].as_array().unwrap().iter().find(|j| j["locator"] == loc).unwrap();
        assert_eq!(cell(&dom, loc, "joint-deg"), format!("{:.3}", f(&j["deg"])), "{loc}");
    }
    assert_eq!(text_of_id(&dom, "world-robots"), "2");
    assert_eq!(attr_of_id(&dom, "pick-1", "class"), "selected");
    // The field: every robot and the ball where the ground truth has them.
    for k in 0..2 {
        let pos = &truth["robots"][k]["pos"];
        assert_eq!(attr_of_id(&dom, &format!("field-robot-{k}"), "data-x").parse::<f64>().unwrap(), f(&pos[0]), "robot {k}");
        assert_eq!(attr_of_id(&dom, &format!("field-robot-{k}"), "data-y").parse::<f64>().unwrap(), f(&pos[1]), "robot {k}");
    }
    assert_eq!(attr_of_id(&dom, "field-ball", "cx").parse::<f64>().unwrap(), f(&truth["ball"][0]));
    assert_eq!(attr_of_id(&dom, "field-ball", "cy").parse::<f64>().unwrap(), f(&truth["ball"][1]));

    // Robot 0's camera: the simulator's picture, on its card and in full when selected.
    let dom0 = chromium_with(&format!("http://{addr}/?robot=0"), None, &["--virtual-time-budget=2000"]);
    assert!(attr_of_id(&dom0, "camera", "src").starts_with("/robot/0/camera.png"), "the page shows robot 0's picture");
    assert!(attr_of_id(&dom0, "thumb-0", "src").starts_with("/robot/0/camera.png"));
    let (w, h, px) = pixels(&get_bytes(&addr, "/robot/0/camera.png"));
    assert_eq!((w, h), (416, 320), "the ERS-7 camera's resolution");
    let ball = px.iter().filter(|p| orange(**p)).count();
    assert!(ball > 100, "robot 0 faces the ball 0.8 m ahead: {ball} orange pixels");
    // The field camera: the whole field rendered by MuJoCo, the ball on it.
    assert!(attr_of_id(&dom0, "field-camera", "src").starts_with("/field.png"));
    let (w, h, px) = pixels(&get_bytes(&addr, "/field.png"));
    assert_eq!((w, h), (480, 320));
    let green = px.iter().filter(|p| p[1] as u32 > 2 * p[0] as u32 && p[1] as u32 > 2 * p[2] as u32).count();
    assert!(green > w * h / 3, "mostly carpet: {green} green pixels of {}", w * h);
    let ball = px.iter().filter(|p| orange(**p)).count();
    assert!(ball >= 3, "the ball on the field: {ball} orange pixels");
    control(&addr, "resume");
    let out = run.wait(Duration::from_secs(300));
    assert_eq!(out.code, Some(0), "{}", out.stderr);
    assert_eq!(out.stderr.matches("Viewing http://").count(), 1, "one page for the world: {}", out.stderr);
}

#[test]
fn a_world_recording_replays_every_robot_and_the_field() {
    let (head, _cam) = head_camera_ms();
    let legs = build("movelegs");
    let dir = tempfile::tempdir().unwrap();
    let rec = dir.path().join("rec");
    let out = run_ms(&head.ms(), &world_args(&legs.ms(), &["--for", "2.5s", "--record", rec.to_str().unwrap()]));
    assert_eq!(out.code, Some(0), "{}", out.stderr);
    let manifest: Value = serde_json::from_str(&std::fs::read_to_string(rec.join("recording.json")).unwrap()).unwrap();
    assert_eq!(manifest["robots"], serde_json::json!(["robot0", "robot1"]));
    let truth = read_trace(&rec.join("world.jsonl"));
    assert!(truth.len() >= 300, "a ground-truth line per frame: {}", truth.len());
    let pictures = read_trace(&rec.join("robot0/camera.jsonl"));
    assert!(pictures.len() >= 60, "robot 0's camera, 30 a second: {}", pictures.len());
    let trace1 = read_trace(&rec.join("robot1/trace.jsonl"));

    let view = spawn_view(&rec);
    assert!(view.stderr.lock().unwrap().contains("a world of 2 robots"), "{}", view.stderr.lock().unwrap());
    let times = moments(&trace1);
    let k = (times.len() / 2..times.len() - 1)
        .find(|&k| sensor_at(&trace1, times[k])["joints"][LEGS[0]] != sensor_at(&trace1, times[k + 1])["joints"][LEGS[0]])
        .expect("robot 1's leg moves in the second half");
    let t = times[k];
    let at = |t: u64| truth.iter().filter(|l| l["time_ms"].as_u64().unwrap() <= t).last().unwrap().clone();
    let dom = chromium(&format!("http://{}/?robot=1&t={t}", view.addr), None);
    assert_shows(&dom, &trace1, t, "robot 1");
    let now = at(t);
    assert_eq!(attr_of_id(&dom, "field-ball", "cx").parse::<f64>().unwrap(), f(&now["ball"][0]), "the ball at {t} ms");
    assert_eq!(attr_of_id(&dom, "field-robot-1", "data-x").parse::<f64>().unwrap(), f(&now["robots"][1]["pos"][0]));
    // Robot 0's card: the newest picture it took by then, as recorded.
    assert_eq!(attr_of_id(&dom, "thumb-0", "src"), format!("/robot/0/camera.png?t={t}"));
    let newest = pictures.iter().filter(|c| c["t_ms"].as_u64().unwrap() <= t).last().unwrap();
    assert_eq!(get_bytes(&view.addr, &format!("/robot/0/camera.png?t={t}")), std::fs::read(rec.join("robot0").join(newest["file"].as_str().unwrap())).unwrap());
    // The field camera's newest picture by then.
    let field = read_trace(&rec.join("field/index.jsonl"));
    assert!(field.len() >= 10, "the field camera, 5 pictures a second: {}", field.len());
    assert_eq!(attr_of_id(&dom, "field-camera", "src"), format!("/field.png?t={t}"));
    let newest = field.iter().filter(|c| c["time_ms"].as_u64().unwrap() <= t).last().unwrap();
    assert_eq!(get_bytes(&view.addr, &format!("/field.png?t={t}")), std::fs::read(rec.join("field").join(newest["file"].as_str().unwrap())).unwrap());
    // Step on robot 1's timeline: its next moment.
    let stepped = chromium(&format!("http://{}/?robot=1&t={t}&step=1", view.addr), None);
    assert_shows(&stepped, &trace1, times[k + 1], "robot 1, step");

    // The screenshot: the ball and robot 0 drawn where the ground truth has them, on
    // the carpet (6 x 4 m, drawn to scale).
    let shot = dir.path().join("replay.png");
    chromium(&format!("http://{}/?robot=0&t={t}", view.addr), Some(&shot));
    if let Ok(to) = std::env::var("OPENR_WORLD_SCREENSHOT") {
        std::fs::copy(&shot, to).unwrap(); // docs/world-view.png
    }
    let (w, h, px) = pixels(&std::fs::read(&shot).unwrap());
    // The field is the page's first panel, top left; the camera pictures are elsewhere.
    let region = |x: usize, y: usize| x < 620 && y < 500;
    let carpet = [26, 140, 38]; // scene.xml: rgba 0.1 0.55 0.15
    let (mut x0, mut x1, mut y0, mut y1) = (w, 0, h, 0);
    for y in 0..h {
        for x in 0..w {
            if region(x, y) && near(px[y * w + x], carpet, 3) {
                (x0, x1, y0, y1) = (x0.min(x), x1.max(x + 1), y0.min(y), y1.max(y + 1));
            }
        }
    }
    assert!(x1 > x0 + 300 && y1 > y0 + 200, "the carpet is drawn: {x0}..{x1} x {y0}..{y1}");
    let ratio = (x1 - x0) as f64 / (y1 - y0) as f64;
    assert!((ratio - 1.5).abs() < 0.02, "6 x 4 m to scale: {ratio:.3}");
    let to_px = |x: f64, y: f64| (x0 as f64 + (x + 3.0) / 6.0 * (x1 - x0) as f64, y0 as f64 + (2.0 - y) / 4.0 * (y1 - y0) as f64);
    let centroid = |pick: &dyn Fn([u8; 3]) -> bool| {
        let (mut sx, mut sy, mut n) = (0.0, 0.0, 0usize);
        for y in y0..y1 {
            for x in x0..x1 {
                if pick(px[y * w + x]) {
                    (sx, sy, n) = (sx + x as f64 + 0.5, sy + y as f64 + 0.5, n + 1);
                }
            }
        }
        (sx / n.max(1) as f64, sy / n.max(1) as f64, n)
    };
    let (bx, by, n) = centroid(&|p| near(p, [255, 115, 0], 12));
    let (ex, ey) = to_px(f(&now["ball"][0]), f(&now["ball"][1]));
    assert!(n > 20 && (bx - ex).abs() < 1.5 && (by - ey).abs() < 1.5, "the ball drawn at ({bx:.1}, {by:.1}) ({n} px), the truth says ({ex:.1}, {ey:.1})");
    let (rx, ry, n) = centroid(&|p| near(p, [42, 92, 255], 12));
    let (ex, ey) = to_px(f(&now["robots"][0]["pos"][0]), f(&now["robots"][0]["pos"][1]));
    assert!(n > 100 && (rx - ex).abs() < 3.0 && (ry - ey).abs() < 3.0, "robot 0 drawn at ({rx:.1}, {ry:.1}) ({n} px), the truth says ({ex:.1}, {ey:.1})");
}

#[test]
fn bad_world_recordings_are_clear_errors() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path().join("world");
    std::fs::create_dir_all(&d).unwrap();
    let sensor = r#"{"t_ms":32,"frame":4,"kind":"sensor","joints":{"PRM:/r2/c1-Joint2:21":1.5},"accel":[0,0,9.8],"paws":[true,true,true,true]}"#;
    std::fs::write(d.join("t.jsonl"), format!("{sensor}\n")).unwrap();
    let manifest = r#"{"format":"cargo-openr recording","version":1,"robots":["t.jsonl"],"world":{"truth":"world.jsonl","field":"field.json"}}"#;
    std::fs::write(d.join("recording.json"), manifest).unwrap();
    fails_with(&d, &[&format!("{}: no such file or directory", d.join("field.json").display())]);
    std::fs::write(d.join("field.json"), "{\"shapes\": [}").unwrap();
    fails_with(&d, &[&format!("{}:1: not JSON", d.join("field.json").display())]);
    std::fs::write(d.join("field.json"), "{\"shapes\": []}").unwrap();
    std::fs::write(d.join("world.jsonl"), "{\"time_ms\":8,\"robots\":[]}\n{\"robots\":[]}\n").unwrap();
    fails_with(&d, &[&format!("{}:2: not a ground-truth record: it needs \"time_ms\"", d.join("world.jsonl").display())]);
    std::fs::write(d.join("world.jsonl"), "{\"time_ms\":8,\"robots\":[]}\n").unwrap();
    std::fs::create_dir_all(d.join("field")).unwrap();
    std::fs::write(d.join("field/index.jsonl"), "{\"n\":1,\"time_ms\":200,\"frame\":25,\"file\":\"000001.png\"}\n").unwrap();
    fails_with(&d, &[&format!("{}:1: the picture", d.join("field/index.jsonl").display()), "000001.png is missing"]);
    std::fs::write(d.join("field/000001.png"), b"\x89PNG").unwrap();
    {
        let v = spawn_view(&d);
        assert!(v.stderr.lock().unwrap().contains("a world of 1 robots, 1 ground-truth frames"), "{}", v.stderr.lock().unwrap());
    }
    std::fs::write(d.join("recording.json"), manifest.replace("t.jsonl", "robot7")).unwrap();
    fails_with(&d, &[&format!("{}: no such file or directory", d.join("robot7").display())]);
    std::fs::write(d.join("recording.json"), manifest.replace("[\"t.jsonl\"]", "[]")).unwrap();
    fails_with(&d, &["recording.json: a world of no robots"]);
}
