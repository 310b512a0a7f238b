//! A recording's moments, built when the page asks for them: one per virtual time at
//! which the trace has records. Opening a trace reads it once, checks each record,
//! finds where each moment ends and keeps the state at the start of every chunk of
//! [`CHUNK`] moments; a chunk's snapshots are built from there (its records parsed again
//! from the trace's text) when first asked for, and the last few chunks built are kept.
//! So a long recording opens in one pass and takes the memory of its trace's text, not
//! of every snapshot or every parsed record.
use std::collections::HashMap;
use std::ops::Range;
use std::sync::{Arc, Mutex};

use sdk_runtime::robot::model::{Design, Leg, Part, PrimitiveKind, RobotModel};
use serde_json::{json, Value};

use crate::chunks::CHUNK;

/// Chunks kept built (the page looks around one moment at a time).
const KEEP: usize = 16;

pub struct Moments {
    design: Design,
    /// The design's primitives, which every snapshot lists.
    model: RobotModel,
    /// The trace's text and the byte range of each record in it.
    text: String,
    records: Vec<Range<usize>>,
    /// The camera's picture times and `view.jsonl`'s records.
    pictures: Vec<u64>,
    views: Lines,
    /// Per moment: its time, frame and the index after its last record.
    ends: Vec<(u64, u64, usize)>,
    /// The state before the first record of each chunk's first moment.
    starts: Vec<Now>,
    built: Mutex<Vec<(usize, Arc<Vec<Value>>)>>,
}

/// Reads a trace's records in order ([`Builder::add`]), then makes its [`Moments`].
#[derive(Default)]
pub(crate) struct Builder {
    records: Vec<Range<usize>>,
    ends: Vec<(u64, u64, usize)>,
    starts: Vec<Now>,
    now: Now,
    /// The moment being read: its time and frame.
    open: Option<(u64, u64)>,
}

impl Builder {
    /// Record `r`, the text at `range` of the trace, checked by the caller (times never
    /// go back).
    pub(crate) fn add(&mut self, r: &Value, range: Range<usize>) {
        let t = r["t_ms"].as_u64().unwrap_or(0);
        match self.open {
            Some((open_t, _)) if open_t == t => {}
            _ => {
                self.close();
                if self.ends.len().is_multiple_of(CHUNK) {
                    self.starts.push(self.now.clone());
                }
            }
        }
        self.open = Some((t, r["frame"].as_u64().unwrap_or(0)));
        self.now.apply(r);
        self.records.push(range);
    }

    fn close(&mut self) {
        if let Some((t, frame)) = self.open.take() {
            self.ends.push((t, frame, self.records.len()));
        }
    }

    pub(crate) fn is_empty(&self) -> bool {
        self.records.is_empty()
    }

    pub(crate) fn finish(mut self, design: Design, text: String, pictures: Vec<u64>, views: Lines) -> Moments {
        self.close();
        Moments {
            design,
            model: RobotModel::new(design),
            text,
            records: self.records,
            pictures,
            views,
            ends: self.ends,
            starts: self.starts,
            built: Mutex::new(Vec::new()),
        }
    }
}

/// A JSON-lines file kept as its text: each line's time and place in it, parsed when
/// asked for.
#[derive(Default)]
pub(crate) struct Lines {
    text: String,
    at: Vec<(u64, Range<usize>)>,
}

impl Lines {
    pub(crate) fn new(text: String, at: Vec<(u64, Range<usize>)>) -> Lines {
        Lines { text, at }
    }

    /// Line `i` (checked when the file was read).
    pub(crate) fn get(&self, i: usize) -> Option<Value> {
        serde_json::from_str(&self.text[self.at.get(i)?.1.clone()]).ok()
    }

    /// The newest line at or before `t_ms`.
    pub(crate) fn newest_at(&self, t_ms: u64) -> Option<usize> {
        self.at.partition_point(|l| l.0 <= t_ms).checked_sub(1)
    }
}

impl Moments {
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
        let prims = self.model.primitives();
        let mut now = self.starts[c].clone();
        let mut begin = first.checked_sub(1).map_or(0, |p| self.ends[p].2);
        let mut out = Vec::with_capacity(CHUNK);
        let mut view: Option<(usize, Value)> = None; // consecutive moments share a line
        for &(t, frame, end) in &self.ends[first..(first + CHUNK).min(self.ends.len())] {
            for range in &self.records[begin..end] {
                // Checked when the trace was opened.
                if let Ok(r) = serde_json::from_str::<Value>(&self.text[range.clone()]) {
                    now.apply(&r);
                }
            }
            begin = end;
            let camera_images = self.pictures.partition_point(|&p| p <= t);
            let k = self.views.newest_at(t);
            if k != view.as_ref().map(|v| v.0) {
                view = k.and_then(|k| Some((k, self.views.get(k)?)));
            }
            out.push(now.snapshot(self.design, prims, (t, frame, camera_images), view.as_ref().map(|v| &v.1)));
        }
        let out = Arc::new(out);
        if built.len() == KEEP {
            built.remove(0);
        }
        built.push((c, out.clone()));
        Some(out)
    }
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
        RobotModel::new(Design::Ers7).primitives().iter().find(|p| p.kind == kind).unwrap().locator
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

    /// The records as one trace text, read as `replay` reads a file.
    fn moments(records: &[Value]) -> Moments {
        let mut text = String::new();
        let mut b = Builder::default();
        for r in records {
            let line = r.to_string();
            b.add(r, text.len()..text.len() + line.len());
            text.push_str(&line);
            text.push('\n');
        }
        b.finish(Design::Ers7, text, Vec::new(), Lines::default())
    }

    fn joint(s: &Value, loc: &str) -> Value {
        s["joints"].as_array().unwrap().iter().find(|j| j["locator"] == loc).unwrap()["deg"].clone()
    }

    #[test]
    fn a_chunk_built_late_carries_the_state_of_every_earlier_record() {
        let m = moments(&trace(3 * CHUNK as u64 + 5));
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
