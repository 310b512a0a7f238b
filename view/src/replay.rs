//! `cargo openr view PATH`: a recording (`--record DIR`, docs/recording.md) or a bare
//! `--trace` file read back as the moments the page draws. Each moment is a snapshot
//! (the shape `/state` serves live) built from the trace: the joints of the newest
//! sensor record, the LEDs, ears, face mode and motor power as last set, the paw
//! switches and the accelerometer; one per virtual time at which the trace has records.
//! What the trace does not carry (joint targets, the other sensors, the battery) comes
//! from a recording's `view.jsonl` (the newest line at or before the moment); a bare
//! trace goes without.
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};

use sdk_runtime::robot::model::{Design, Leg, Part, PrimitiveKind};
use sdk_runtime::robot::VirtualRobot;
use serde_json::{json, Value};

use crate::chunks::CHUNK;
use crate::record::{CAMERA_INDEX, FORMAT, MANIFEST, TRACE, VERSION};

/// What `cargo openr view PATH` serves: one robot's recording, or a simulated world's
/// (every robot's, and the simulator's ground truth).
pub struct Replay {
    pub source: PathBuf,
    pub robots: Vec<Recording>,
    pub world: Option<World>,
}

/// A world recording's field (`peer.py --field`) and ground truth, one line per frame
/// (`peer.py --state`) in time order.
pub struct World {
    pub field: Value,
    pub truth: Vec<Value>,
    /// The field camera's pictures (`peer.py --field-pictures`): (time_ms, file).
    pub pictures: Vec<(u64, PathBuf)>,
}

impl World {
    /// The newest ground truth at or before `t_ms`.
    pub fn at(&self, t_ms: u64) -> Option<&Value> {
        let k = self.truth.partition_point(|l| l["time_ms"].as_u64().unwrap_or(0) <= t_ms);
        self.truth.get(k.checked_sub(1)?)
    }
}

/// One robot's recording ready to serve.
pub struct Recording {
    /// What was opened (a directory or a trace file).
    pub source: PathBuf,
    pub design: &'static str,
    /// Its moments in time order, each built when the page first asks for it.
    pub moments: Moments,
    /// Camera picture n (1-based) is `pictures[n - 1]`, taken at `picture_times[n - 1]`.
    pub pictures: Vec<PathBuf>,
    pub picture_times: Vec<u64>,
    pub speaker: Option<PathBuf>,
}

type Res<T> = std::result::Result<T, String>;

/// Opens a recording directory (one robot's or a world's) or a `--trace` file; the
/// error names the file (and line).
pub fn open(path: &Path) -> Res<Replay> {
    let manifest = path.join(MANIFEST);
    let world = path.is_dir() && manifest.is_file() && read_manifest(&manifest)?["robots"].is_array();
    if !world {
        return Ok(Replay { source: path.into(), robots: vec![open_robot(path)?], world: None });
    }
    let m = read_manifest(&manifest)?;
    let mut robots = Vec::new();
    for (k, dir) in m["robots"].as_array().into_iter().flatten().enumerate() {
        let dir = dir.as_str().ok_or_else(|| format!("{}: robot {k} is not a directory name", manifest.display()))?;
        robots.push(open_robot(&path.join(dir))?);
    }
    if robots.is_empty() {
        return Err(format!("{}: a world of no robots", manifest.display()));
    }
    let file = |key: &str, default: &str| path.join(m["world"][key].as_str().unwrap_or(default));
    let field_path = file("field", crate::record::FIELD);
    let field = match std::fs::read_to_string(&field_path) {
        Ok(t) => serde_json::from_str(&t).map_err(|e| format!("{}:{}: not JSON: {e}", field_path.display(), e.line()))?,
        Err(e) => return Err(format!("{}: {}", field_path.display(), io_reason(&e))),
    };
    let truth = read_lines(&file("truth", crate::record::TRUTH), "time_ms", "ground-truth")?;
    let index = file("field_camera", crate::record::FIELD_CAMERA_INDEX);
    let mut pictures = Vec::new();
    for (i, p) in read_lines(&index, "time_ms", "field camera")?.into_iter().enumerate() {
        let at = format!("{}:{}", index.display(), i + 1);
        let name = p["file"].as_str().ok_or_else(|| format!("{at}: not a field camera record: it needs \"file\""))?;
        let png = index.parent().unwrap_or(path).join(name);
        if !png.is_file() {
            return Err(format!("{at}: the picture {} is missing", png.display()));
        }
        pictures.push((p["time_ms"].as_u64().unwrap_or(0), png));
    }
    Ok(Replay { source: path.into(), robots, world: Some(World { field, truth, pictures }) })
}

fn read_manifest(path: &Path) -> Res<Value> {
    let text = std::fs::read_to_string(path).map_err(|e| format!("{}: {}", path.display(), io_reason(&e)))?;
    let m: Value = serde_json::from_str(&text).map_err(|e| format!("{}:{}: not JSON: {e}", path.display(), e.line()))?;
    if m["format"] != FORMAT {
        return Err(format!("{}: not a recording manifest (its \"format\" is {}, not \"{FORMAT}\")", path.display(), m["format"]));
    }
    if m["version"].as_u64() != Some(VERSION) {
        return Err(format!("{}: recording version {} (this cargo-openr reads version {VERSION})", path.display(), m["version"]));
    }
    Ok(m)
}

/// One robot's recording directory, or a `--trace` file.
fn open_robot(path: &Path) -> Res<Recording> {
    let meta = std::fs::metadata(path).map_err(|e| format!("{}: {}", path.display(), io_reason(&e)))?;
    if !meta.is_dir() {
        let (design, records) = read_trace(path, None)?;
        return Ok(Recording {
            source: path.into(),
            design: design.name(),
            moments: Moments::new(design, records, Vec::new(), Vec::new()),
            pictures: Vec::new(),
            picture_times: Vec::new(),
            speaker: None,
        });
    }
    let manifest_path = path.join(MANIFEST);
    if !manifest_path.is_file() {
        return Err(format!(
            "{}: not a recording (it has no {MANIFEST}): give a directory written by `cargo openr run MS --record DIR`, or a `--trace` file",
            path.display()
        ));
    }
    let m = read_manifest(&manifest_path)?;
    let design =
        m["design"].as_str().and_then(Design::from_name).ok_or_else(|| format!("{}: unknown robot design {}", manifest_path.display(), m["design"]))?;
    let file = |key: &str, default: &str| path.join(m[key].as_str().unwrap_or(default));
    let (_, records) = read_trace(&file("trace", TRACE), Some(design))?;
    let camera = read_camera_index(path, &file("camera", CAMERA_INDEX))?;
    let views = read_lines(&file("view", crate::record::VIEW), "t_ms", "view")?;
    let speaker = Some(file("speaker", crate::record::SPEAKER)).filter(|p| p.is_file());
    let times: Vec<u64> = camera.iter().map(|c| c.0).collect();
    Ok(Recording {
        source: path.into(),
        design: design.name(),
        moments: Moments::new(design, records, times.clone(), views),
        pictures: camera.into_iter().map(|c| c.1).collect(),
        picture_times: times,
        speaker,
    })
}

fn io_reason(e: &std::io::Error) -> String {
    match e.kind() {
        std::io::ErrorKind::NotFound => "no such file or directory".into(),
        _ => e.to_string(),
    }
}

/// The records of a trace, each checked for the common fields, and the design its
/// joints belong to (`design` when the manifest names it).
fn read_trace(path: &Path, design: Option<Design>) -> Res<(Design, Vec<Value>)> {
    let text = std::fs::read_to_string(path).map_err(|e| format!("{}: {}", path.display(), io_reason(&e)))?;
    let mut records = Vec::new();
    let mut last_t = 0;
    let lines: Vec<&str> = text.split('\n').collect();
    for (i, line) in lines.iter().enumerate() {
        if line.trim().is_empty() {
            continue;
        }
        let at = format!("{}:{}", path.display(), i + 1);
        let r: Value = serde_json::from_str(line).map_err(|e| {
            if i + 1 == lines.len() && e.is_eof() {
                format!("{at}: the trace ends in the middle of a record (was the run killed while writing it?)")
            } else {
                format!("{at}: not a trace record: {e}")
            }
        })?;
        let (Some(t), Some(_), Some(_)) = (r["t_ms"].as_u64(), r["frame"].as_u64(), r["kind"].as_str()) else {
            return Err(format!("{at}: not a trace record: it needs \"t_ms\", \"frame\" and \"kind\" (docs/recording.md)"));
        };
        if t < last_t {
            return Err(format!("{at}: time goes back ({t} ms after {last_t} ms): not one run's trace"));
        }
        last_t = t;
        records.push(r);
    }
    if records.is_empty() {
        return Err(format!("{}: no trace records: nothing to replay", path.display()));
    }
    let design = match design {
        Some(d) => d,
        None => guess_design(&records).ok_or_else(|| format!("{}: its joints belong to no robot design cargo-openr knows", path.display()))?,
    };
    Ok((design, records))
}

/// The first design whose joints include every joint of the first sensor record.
fn guess_design(records: &[Value]) -> Option<Design> {
    let Some(joints) = records.iter().find(|r| r["kind"] == "sensor").and_then(|r| r["joints"].as_object()) else {
        return Some(Design::Ers7);
    };
    Design::ALL.into_iter().find(|d| {
        let robot = VirtualRobot::new(*d);
        let known: Vec<&str> = robot.model().primitives().iter().map(|p| p.locator).collect();
        joints.keys().all(|k| known.contains(&k.as_str()))
    })
}

/// `camera.jsonl`: (t_ms, picture file) per line, pictures numbered 1, 2, … in order.
fn read_camera_index(dir: &Path, index: &Path) -> Res<Vec<(u64, PathBuf)>> {
    let text = match std::fs::read_to_string(index) {
        Ok(t) => t,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(Vec::new()),
        Err(e) => return Err(format!("{}: {}", index.display(), io_reason(&e))),
    };
    let mut out = Vec::new();
    for (i, line) in text.lines().enumerate() {
        if line.trim().is_empty() {
            continue;
        }
        let at = format!("{}:{}", index.display(), i + 1);
        let c: Value = serde_json::from_str(line).map_err(|e| format!("{at}: not a camera record: {e}"))?;
        let (Some(n), Some(t), Some(file)) = (c["n"].as_u64(), c["t_ms"].as_u64(), c["file"].as_str()) else {
            return Err(format!("{at}: not a camera record: it needs \"n\", \"t_ms\" and \"file\""));
        };
        if n != out.len() as u64 + 1 {
            return Err(format!("{at}: picture {n} where picture {} was due", out.len() + 1));
        }
        let png = dir.join(file);
        if !png.is_file() {
            return Err(format!("{at}: the picture {} is missing", png.display()));
        }
        out.push((t, png));
    }
    Ok(out)
}

/// `view.jsonl` or a world's ground truth (absent: none): each line an object with
/// `key` (its virtual time), in time order.
fn read_lines(path: &Path, key: &str, what: &str) -> Res<Vec<Value>> {
    let text = match std::fs::read_to_string(path) {
        Ok(t) => t,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(Vec::new()),
        Err(e) => return Err(format!("{}: {}", path.display(), io_reason(&e))),
    };
    let mut out: Vec<Value> = Vec::new();
    for (i, line) in text.lines().enumerate() {
        if line.trim().is_empty() {
            continue;
        }
        let at = format!("{}:{}", path.display(), i + 1);
        let v: Value = serde_json::from_str(line).map_err(|e| format!("{at}: not a {what} record: {e}"))?;
        let t = v[key].as_u64().ok_or_else(|| format!("{at}: not a {what} record: it needs \"{key}\""))?;
        if out.last().is_some_and(|l| l[key].as_u64() > Some(t)) {
            return Err(format!("{at}: time goes back ({t} ms)"));
        }
        out.push(v);
    }
    Ok(out)
}

/// What the trace says about the robot so far.
#[derive(Clone, Default)]
struct Now {
    joints: HashMap<String, f64>,
    leds: HashMap<String, (u64, u64)>,
    ears: HashMap<String, u64>,
    face_mode: u64,
    motor_power: bool,
    paws: [bool; 4],
    accel: [f64; 3],
}

/// A recording's moments: one per virtual time at which the trace has records. Opening
/// one only finds where each moment ends in the trace and keeps the state at the start
/// of every chunk of [`CHUNK`] moments; a chunk's snapshots are built from there when
/// first asked for, and the last few chunks built are kept. So a long recording opens
/// quickly and takes the memory of its trace, not of every snapshot.
pub struct Moments {
    design: Design,
    records: Vec<Value>,
    /// The camera's picture times and `view.jsonl`'s records.
    pictures: Vec<u64>,
    views: Vec<Value>,
    /// Per moment: its time, frame and the index after its last record.
    ends: Vec<(u64, u64, usize)>,
    /// The state before the first record of each chunk's first moment.
    starts: Vec<Now>,
    built: Mutex<Vec<(usize, Arc<Vec<Value>>)>>,
}

/// Chunks kept built (the page looks around one moment at a time).
const KEEP: usize = 16;

impl Moments {
    fn new(design: Design, records: Vec<Value>, pictures: Vec<u64>, views: Vec<Value>) -> Moments {
        let (mut now, mut ends, mut starts) = (Now::default(), Vec::new(), Vec::new());
        let mut begin = 0;
        for (i, r) in records.iter().enumerate() {
            let t = r["t_ms"].as_u64().unwrap_or(0);
            if records.get(i + 1).is_some_and(|n| n["t_ms"].as_u64() == Some(t)) {
                continue; // the moment's other records first
            }
            if ends.len() % CHUNK == 0 {
                starts.push(now.clone());
            }
            for r in &records[begin..=i] {
                now.apply(r);
            }
            begin = i + 1;
            ends.push((t, r["frame"].as_u64().unwrap_or(0), begin));
        }
        Moments { design, records, pictures, views, ends, starts, built: Mutex::new(Vec::new()) }
    }

    pub fn len(&self) -> usize {
        self.ends.len()
    }

    pub fn is_empty(&self) -> bool {
        self.ends.is_empty()
    }

    /// The virtual time of moment `i`.
    pub fn t_ms(&self, i: usize) -> Option<u64> {
        self.ends.get(i).map(|e| e.0)
    }

    /// The number of moments at or before `t_ms`.
    pub fn count_to(&self, t_ms: u64) -> usize {
        self.ends.partition_point(|e| e.0 <= t_ms)
    }

    /// The snapshots of chunk `c` (moments c × CHUNK …), or None past the end.
    pub fn chunk(&self, c: usize) -> Option<Arc<Vec<Value>>> {
        let mut built = self.built.lock().unwrap_or_else(|e| e.into_inner());
        if let Some(k) = built.iter().position(|(n, _)| *n == c) {
            let hit = built.remove(k);
            built.push(hit.clone());
            return Some(hit.1);
        }
        let first = c.checked_mul(CHUNK).filter(|f| *f < self.ends.len())?;
        let robot = VirtualRobot::new(self.design);
        let prims = robot.model().primitives();
        let mut now = self.starts[c].clone();
        let mut begin = first.checked_sub(1).map_or(0, |p| self.ends[p].2);
        let mut out = Vec::with_capacity(CHUNK);
        for &(t, frame, end) in &self.ends[first..(first + CHUNK).min(self.ends.len())] {
            for r in &self.records[begin..end] {
                now.apply(r);
            }
            begin = end;
            let camera_images = self.pictures.partition_point(|&p| p <= t);
            let view = self.views.partition_point(|v| v["t_ms"].as_u64().unwrap_or(0) <= t).checked_sub(1).map(|k| &self.views[k]);
            out.push(now.snapshot(self.design, prims, (t, frame, camera_images), view));
        }
        let out = Arc::new(out);
        if built.len() == KEEP {
            built.remove(0);
        }
        built.push((c, out.clone()));
        Some(out)
    }
}

impl Now {
    fn apply(&mut self, r: &Value) {
        let loc = || r["locator"].as_str().unwrap_or("").to_string();
        match r["kind"].as_str().unwrap_or("") {
            "sensor" => {
                if let Some(j) = r["joints"].as_object() {
                    for (k, v) in j {
                        self.joints.insert(k.clone(), v.as_f64().unwrap_or(0.0));
                    }
                }
                for (k, a) in self.accel.iter_mut().enumerate() {
                    *a = r["accel"][k].as_f64().unwrap_or(0.0);
                }
                for (k, p) in self.paws.iter_mut().enumerate() {
                    *p = r["paws"][k].as_bool().unwrap_or(false);
                }
            }
            "led" => {
                let v = match r["on"].as_bool() {
                    Some(on) => (if on { 255 } else { 0 }, 0),
                    None => (r["intensity"].as_u64().unwrap_or(0), r["mode"].as_u64().unwrap_or(0)),
                };
                self.leds.insert(loc(), v);
            }
            "ear" => {
                self.ears.insert(loc(), r["state"].as_u64().unwrap_or(0));
            }
            "face_mode" => self.face_mode = r["mode"].as_u64().unwrap_or(0),
            "motor_power" => self.motor_power = r["on"].as_bool().unwrap_or(false),
            _ => {}
        }
    }

    /// The page's snapshot; the trace's values win over `view`'s where both have one.
    fn snapshot(
        &self,
        design: Design,
        prims: &[sdk_runtime::robot::model::Primitive],
        (t, frame, camera_images): (u64, u64, usize),
        view: Option<&Value>,
    ) -> Value {
        let (mut joints, mut leds, mut ears, mut sensors) = (Vec::new(), Vec::new(), Vec::new(), Vec::new());
        for p in prims {
            let loc = p.locator;
            match p.kind {
                PrimitiveKind::Joint2 => joints.push(json!({ "locator": loc, "deg": self.joints.get(loc).copied().unwrap_or(0.0), "target_deg": view.map_or(Value::Null, |v| v["targets"][loc].clone()) })),
                PrimitiveKind::Led2 | PrimitiveKind::Led3 => {
                    let (value, mode) = self.leds.get(loc).copied().unwrap_or((0, 0));
                    let kind = if p.kind == PrimitiveKind::Led2 { 2 } else { 3 };
                    leds.push(json!({ "locator": loc, "kind": kind, "value": value, "mode": mode }));
                }
                PrimitiveKind::Joint3 | PrimitiveKind::Joint4 => ears.push(json!({ "locator": loc, "state": self.ears.get(loc).copied().unwrap_or(0) })),
                PrimitiveKind::Sensor(_) => match p.part {
                    Part::PawSwitch(leg) => {
                        let k = Leg::ALL.iter().position(|l| *l == leg).unwrap_or(0);
                        sensors.push(json!({ "locator": loc, "kind": "switch", "value": self.paws[k] as u8 }));
                    }
                    Part::Accel(k) => sensors.push(json!({ "locator": loc, "kind": "accel", "value": (self.accel[k as usize % 3] * 1e6).round() })),
                    _ => {}
                },
                _ => {}
            }
        }
        if let Some(listed) = view.and_then(|v| v["sensors"].as_array()) {
            let traced: HashMap<&str, &Value> = sensors.iter().filter_map(|s| Some((s["locator"].as_str()?, &s["value"]))).collect();
            let merged: Vec<Value> = listed
                .iter()
                .map(|s| {
                    let mut s = s.clone();
                    if let Some(v) = s["locator"].as_str().and_then(|l| traced.get(l)) {
                        s["value"] = (*v).clone();
                    }
                    s
                })
                .collect();
            sensors = merged;
        }
        let battery = view.map_or(Value::Null, |v| v["battery"].clone());
        // Recordings made before the view counted messages have neither.
        let (objects, connections) = view.map_or((Value::Null, Value::Null), |v| (v["objects"].clone(), v["connections"].clone()));
        json!({
            "design": design.name(), "frame": frame, "t_ms": t, "paused": false, "speed": "replay",
            "motor_power": self.motor_power, "camera_images": camera_images, "face_mode": self.face_mode,
            "joints": joints, "leds": leds, "ears": ears, "sensors": sensors, "battery": battery,
            "objects": objects, "connections": connections,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A trace of `n` sensor moments 32 ms apart; an LED set at moment 3 (with a second
    /// record of the same moment).
    fn locator(kind: PrimitiveKind) -> &'static str {
        VirtualRobot::new(Design::Ers7).model().primitives().iter().find(|p| p.kind == kind).unwrap().locator
    }

    fn trace(n: u64) -> Vec<Value> {
        let (joint, led) = (locator(PrimitiveKind::Joint2), locator(PrimitiveKind::Led2));
        let mut records = Vec::new();
        for k in 0..n {
            records.push(json!({ "kind": "sensor", "t_ms": 32 * k, "frame": 4 * k, "joints": { joint: k as f64 } }));
            if k == 3 {
                records.push(json!({ "kind": "led", "t_ms": 32 * k, "frame": 4 * k, "locator": led, "on": true }));
            }
        }
        records
    }

    fn joint(s: &Value, loc: &str) -> Value {
        s["joints"].as_array().unwrap().iter().find(|j| j["locator"] == loc).unwrap()["deg"].clone()
    }

    #[test]
    fn a_chunk_built_late_carries_the_state_of_every_earlier_record() {
        let m = Moments::new(Design::Ers7, trace(3 * CHUNK as u64 + 5), Vec::new(), Vec::new());
        assert_eq!(m.len(), 3 * CHUNK + 5, "one moment per time, the LED's record joins moment 3");
        assert_eq!((m.t_ms(CHUNK), m.count_to(32 * 10)), (Some(32 * CHUNK as u64), 11));
        // chunk 2 first: its state comes from the kept start, not from building 0 and 1
        let c2 = m.chunk(2).unwrap();
        let first = &c2[0];
        assert_eq!(first["t_ms"], 32 * 2 * CHUNK as u64);
        assert_eq!(joint(first, locator(PrimitiveKind::Joint2)), 2.0 * CHUNK as f64);
        let led = first["leds"].as_array().unwrap().iter().find(|l| l["locator"] == locator(PrimitiveKind::Led2)).unwrap().clone();
        assert_eq!(led["value"], 255, "set at moment 3, still on in chunk 2");
        assert_eq!(m.chunk(3).unwrap().len(), 5);
        assert!(m.chunk(4).is_none());
        // and moment 2 (before the LED) agrees with chunk 0 built afterwards
        let c0 = m.chunk(0).unwrap();
        let off = c0[2]["leds"].as_array().unwrap().iter().find(|l| l["locator"] == locator(PrimitiveKind::Led2)).unwrap()["value"].clone();
        assert_eq!(off, 0);
        assert!(Arc::ptr_eq(&c2, &m.chunk(2).unwrap()), "a chunk is built once while kept");
    }
}
