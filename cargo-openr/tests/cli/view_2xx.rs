//! The view's page draws an ERS-210 as an ERS-210 (`--design ERS-210`, live and
//! replayed): its legs, tail and lights from the 210's own locators, whose joint codes
//! repeat (every leg's J1 is `:j1`, as are the head tilt and the tail pan). The program
//! is testdata/programs/move210; the live run is paused before the page is looked at,
//! and the replay is of a `--speed max` recording, so nothing depends on machine speed.
//!
//! The spec gives no ERS-210 dimensions: the page draws it with the ERS-7's (ers7-model
//! 12), which the expected figures below use too.
use serde_json::Value;

use crate::replay::{moments, sensor_at, spawn_view};
use crate::support::{build, read_trace, run_ms, spawn_ms};
use crate::view::{attr, attr_of_id, chromium, control, http, pause_after, text_of_id, view_addr};

const LF: [&str; 3] = ["PRM:/r2/c1-Joint2:j1", "PRM:/r2/c1/c2-Joint2:j2", "PRM:/r2/c1/c2/c3-Joint2:j3"];
const TAIL_PAN: &str = "PRM:/r6/c1-Joint2:j1";
const TAIL_TILT: &str = "PRM:/r6/c2-Joint2:j2";
const OFF: &str = "rgb(45,45,45)";
const GREEN: &str = "rgb(40,230,60)";
const RED: &str = "rgb(255,30,30)";

/// The ERS-210's lights and their colours when on (ers7-model 13.2: eye lights 4 red,
/// the middle ones l2/l5 green; mode indicator l7 green; tail lights blue, orange).
const LIGHTS: [(&str, &str); 9] = [
    ("PRM:/r1/c1/c2/c3/l1-LED2:l1", RED),
    ("PRM:/r1/c1/c2/c3/l2-LED2:l2", GREEN),
    ("PRM:/r1/c1/c2/c3/l3-LED2:l3", RED),
    ("PRM:/r1/c1/c2/c3/l4-LED2:l4", RED),
    ("PRM:/r1/c1/c2/c3/l5-LED2:l5", GREEN),
    ("PRM:/r1/c1/c2/c3/l6-LED2:l6", RED),
    ("PRM:/r1/c1/c2/c3/l7-LED2:l7", GREEN),
    ("PRM:/r6/l1-LED2:l1", "rgb(60,110,255)"),
    ("PRM:/r6/l2-LED2:l2", "rgb(255,140,0)"),
];
const MODE_LIGHT: &str = "PRM:/r1/c1/c2/c3/l7-LED2:l7";

fn points(s: &str) -> Vec<(f64, f64)> {
    s.split_whitespace()
        .map(|p| {
            let (x, y) = p.split_once(',').unwrap();
            (x.parse().unwrap(), y.parse().unwrap())
        })
        .collect()
}

fn near(a: (f64, f64), b: (f64, f64), tol: f64) -> bool {
    (a.0 - b.0).abs() <= tol && (a.1 - b.1).abs() <= tol
}

/// The left front leg in the side view (SVG y down) drawn from J1, J2, J3 in degrees
/// with the ERS-7's figures: J1 axis at x 65, thigh 69.5, front shin 71.5.
fn lf_side(a: [f64; 3]) -> [(f64, f64); 3] {
    let [a1, a2, a3] = a.map(f64::to_radians);
    let knee = (65.0 + 69.5 * a1.sin(), -69.5 * a1.cos() * a2.cos());
    let paw = (knee.0 + 71.5 * (a1 + a3).sin(), knee.1 - 71.5 * (a1 + a3).cos() * a2.cos());
    [(65.0, 0.0), (knee.0, -knee.1), (paw.0, -paw.1)]
}

/// The tail's tip in the side and top views: 60 long from its root, `rise` degrees
/// above the horizontal less the tilt, panned to the robot's right (SVG y down).
fn tail_tip(rise: f64, pan: f64, tilt: f64) -> ((f64, f64), (f64, f64)) {
    let (ta, tp) = ((rise - tilt).to_radians(), pan.to_radians());
    let x = -95.0 - 60.0 * ta.cos() * tp.cos();
    ((x, -(20.0 + 60.0 * ta.sin())), (x, 60.0 * ta.cos() * tp.sin()))
}

/// The markup of `<svg id="id">`.
fn svg<'a>(dom: &'a str, id: &str) -> &'a str {
    let at = dom.find(&format!("<svg id=\"{id}\"")).unwrap_or_else(|| panic!("no svg {id}"));
    &dom[at..at + dom[at..].find("</svg>").unwrap()]
}

/// The light marks drawn for `loc` in `part`: their tags.
fn marks<'a>(part: &'a str, loc: &str) -> Vec<&'a str> {
    part.match_indices(&format!("data-locator=\"{loc}\""))
        .map(|(at, _)| {
            let start = part[..at].rfind('<').unwrap();
            &part[start..at + part[at..].find('>').unwrap()]
        })
        .collect()
}

/// Whether `p` is inside the polygon `poly` (even-odd rule).
fn inside(p: (f64, f64), poly: &[(f64, f64)]) -> bool {
    let mut c = false;
    for i in 0..poly.len() {
        let (a, b) = (poly[i], poly[(i + 1) % poly.len()]);
        if (a.1 > p.1) != (b.1 > p.1) && p.0 < a.0 + (p.1 - a.1) * (b.0 - a.0) / (b.1 - a.1) {
            c = !c;
        }
    }
    c
}

/// The page `dom` draws the ERS-210 whose joint angles (degrees) `angle` gives and
/// whose lights `lit` gives (locator -> on), at moment `what`.
fn assert_draws_210(dom: &str, angle: impl Fn(&str) -> f64, lit: impl Fn(&str) -> bool, what: &str) {
    assert_eq!(text_of_id(dom, "design"), "ERS-210", "{what}: the page names the design");
    // The left front leg from r2's j1/j2/j3; drawn from the ERS-7's codes (:21..:23,
    // none on a 210) it would hang straight down.
    let lf = LF.map(&angle);
    assert!(lf[0].abs() > 5.0 && lf[2].abs() > 5.0, "{what}: move210 has bent the left front leg: {lf:?}");
    let drawn = points(&attr_of_id(dom, "leg-side-LF", "points"));
    let want = lf_side(lf);
    assert_eq!(drawn.len(), 3, "{what}: {drawn:?}");
    for (d, w) in drawn.iter().zip(want) {
        assert!(near(*d, w, 0.06), "{what}: leg-side-LF is {drawn:?}, its angles {lf:?} draw {want:?}");
    }
    assert!(!near(drawn[1], lf_side([0.0; 3])[1], 5.0), "{what}: the knee is not where zero angles put it");
    // The tail: pan r6/c1, tilt r6/c2 (the ERS-7's are the other way round), at the
    // 210's 15-degree default elevation (ers7-model 13.3).
    let (pan, tilt) = (angle(TAIL_PAN), angle(TAIL_TILT));
    let (side, top) = tail_tip(15.0, pan, tilt);
    let (ds, dt) = (points(&attr_of_id(dom, "tail-side", "points"))[1], points(&attr_of_id(dom, "tail-top", "points"))[1]);
    assert!(near(ds, side, 0.06) && near(dt, top, 0.06), "{what}: tail tip drawn at {ds:?} / {dt:?}; pan {pan}°, tilt {tilt}° draw {side:?} / {top:?}");
    assert!(!near(ds, tail_tip(45.0, 0.0, 0.0).0, 5.0), "{what}: the tail is not where the ERS-7's codes (none on a 210) put it");
    // Each light as the robot has it, in its colour; head lights on the head (in the
    // top view, inside the drawn head), tail lights at the rear, never on the head.
    let (side_view, top_view) = (svg(dom, "side"), svg(dom, "top"));
    let head = points(&attr_of_id(dom, "head-top", "points"));
    for (loc, colour) in LIGHTS {
        let on = lit(loc);
        let fill = if on { colour } else { OFF };
        let (s, t) = (marks(side_view, loc), marks(top_view, loc));
        for tag in s.iter().chain(&t) {
            assert_eq!(attr(tag, "data-value"), if on { "255" } else { "0" }, "{what}: {tag}");
            assert_eq!(attr(tag, "fill"), fill, "{what}: {loc} is {}: {tag}", if on { "on" } else { "off" });
        }
        let at = |tag: &str| -> (f64, f64) { (attr(tag, "cx").parse().unwrap(), attr(tag, "cy").parse().unwrap()) };
        if loc.starts_with("PRM:/r6/") {
            assert!(s.is_empty() && t.len() == 1, "{what}: tail light {loc} drawn once, in the top view: {s:?} {t:?}");
            assert!(at(t[0]).0 < -80.0 && !inside(at(t[0]), &head), "{what}: tail light {loc} at the rear: {t:?}");
        } else {
            assert!(s.len() == 1 && t.len() == 1, "{what}: head light {loc} drawn in each view: {s:?} {t:?}");
            assert!(inside(at(t[0]), &head), "{what}: {loc} at {:?} is on the drawn head {head:?}", at(t[0]));
        }
    }
    assert!(lit(MODE_LIGHT), "{what}: move210 keeps the mode indicator on");
    assert!(svg(dom, "face").contains(" hidden"), "{what}: no ERS-7 face panel on a 210");
}

#[test]
fn page_draws_an_ers210_from_its_own_joints_and_lights() {
    let p = build("move210");
    let mut run = spawn_ms(&p.ms(), &["--view", "--design", "ERS-210", "--speed", "max"], &[]);
    let addr = view_addr(&mut run);
    // Into the swing (1 s to the base posture, then the left front J1 and tail pan swing).
    let paused = pause_after(&addr, 1300);
    let (code, body) = http(&addr, "GET", "/state", "");
    let dom = chromium(&format!("http://{addr}/"), None);
    control(&addr, "resume");
    let _ = run.stop();
    assert_eq!(code, 200, "{body}");
    let s: Value = serde_json::from_str(&body).unwrap();
    assert_eq!(s["design"], "ERS-210", "the snapshot names the design");
    assert_eq!(s["t_ms"].as_u64(), Some(paused));
    assert_eq!(text_of_id(&dom, "t_ms"), paused.to_string(), "the page shows the paused moment");
    let angle = |loc: &str| -> f64 {
        let j = s["joints"].as_array().unwrap().iter().find(|j| j["locator"] == loc).unwrap_or_else(|| panic!("no joint {loc} in {s}"));
        j["deg"].as_f64().unwrap()
    };
    let lit = |loc: &str| -> bool {
        let l = s["leds"].as_array().unwrap().iter().find(|l| l["locator"] == loc).unwrap_or_else(|| panic!("no LED {loc} in {s}"));
        l["value"] == 255
    };
    assert_draws_210(&dom, angle, lit, &format!("live at {paused} ms"));
}

#[test]
fn a_recorded_ers210_replays_as_an_ers210() {
    let p = build("move210");
    let dir = tempfile::tempdir().unwrap();
    let rec = dir.path().join("rec");
    let out = run_ms(&p.ms(), &["--design", "ERS-210", "--speed", "max", "--for", "2s", "--record", rec.to_str().unwrap()]);
    assert_eq!(out.code, Some(0), "{}", out.stderr);
    let manifest: Value = serde_json::from_str(&std::fs::read_to_string(rec.join("recording.json")).unwrap()).unwrap();
    assert_eq!(manifest["design"], "ERS-210", "{manifest}");
    let trace = read_trace(&rec.join("trace.jsonl"));
    let t = *moments(&trace).iter().find(|&&t| t >= 1500).expect("a moment after 1.5 s");
    let view = spawn_view(&rec);
    let dom = chromium(&format!("http://{}/?t={t}", view.addr), None);
    drop(view);
    assert_eq!(text_of_id(&dom, "t_ms"), t.to_string());
    let joints = &sensor_at(&trace, t)["joints"];
    let angle = |loc: &str| joints[loc].as_f64().unwrap_or_else(|| panic!("no {loc} in the trace's sensor record at {t} ms"));
    let lit = |loc: &str| {
        let last = trace.iter().filter(|r| r["kind"] == "led" && r["locator"] == loc && r["t_ms"].as_u64().unwrap() <= t).last();
        last.is_some_and(|r| r["on"] == true)
    };
    assert_draws_210(&dom, angle, lit, &format!("replayed at {t} ms"));
}
