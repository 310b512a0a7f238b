//! JSON-lines trace of what the virtual robot did, stamped with virtual time.
//!
//! Why it exists: a headless emulator needs a record a human or a test can read to see
//! that a program moved the head, blinked the LEDs or was clamped — and to compare runs.
//! [`TraceRecord::to_json`] renders one record as one line of JSON (no trailing
//! newline); the wiring appends it to a file.
//!
//! # Schema
//!
//! Every line is an object with the common fields
//!
//! | field | type | meaning |
//! |---|---|---|
//! | `t_ms` | integer | virtual time at the end of the frame, ms since boot (frame count × 8) |
//! | `frame` | integer | frame number (8 ms counter, 1..0x0FFFFFF0, wraps to 1) |
//! | `kind` | string | record kind, below |
//!
//! and, per `kind`:
//!
//! * `"vector_start"` — a command vector started: `conn` (connection), `token`,
//!   `duration_frames`, `slots`: array of `{ "index", "locator" (or `null` when the ID
//!   is unknown), "primitive" (ID), "type" ("JOINT_COMMAND2", "LED_COMMAND2",
//!   "LED_COMMAND3", "JOINT_COMMAND4", "JOINT_COMMAND3", "LED_COMMAND",
//!   "UNSUPPORTED"), "ignored" (bool), "values" }`. `values` is, for JOINT_COMMAND2,
//!   the per-frame targets in degrees (as requested, before clamping); for held
//!   types, `[value, period]` pairs (LED_COMMAND3: `[intensity, mode, period]`).
//! * `"vector_done"` — `conn`, `token`: the vector finished (region released, Ready).
//! * `"led"` — `locator`, and `on` (LED2) or `intensity` + `mode` (LED3): an LED's state
//!   changed.
//! * `"face_mode"` — `mode` (0 = A, 1 = B): the face panel switched.
//! * `"ear"` — `locator`, `state` (0/1): an ear plunger changed.
//! * `"ear_held"` — `locator`: an ear has been in STATE1 for 1 s (hardware warning).
//! * `"clamp"` — `locator`, `requested_deg`, `clamped_deg`, `rule` ("range" or
//!   "combined"): a joint target was clamped (reported when clamping starts or the
//!   requested value changes).
//! * `"sensor"` — a sensor vector was produced: `first_frame`, `joints`: object
//!   locator → measured angle in degrees (newest frame), `accel`: `[a1, a2, a3]` in
//!   m/s², `paws`: `[LF, LR, RF, RR]` booleans (ERS-7 / 2xx legs).
//! * `"motor_power"` — `on`.
//! * `"gain"` — `locator`, `enabled`, `p`, `i`, `d` (after Enable/Disable/SetJointGain).
//! * `"sync"` — `key`, `timed_out`: a sync key released its vectors.
//!
//! Degrees and m/s² are rounded to 3 decimals.

use serde::{Serialize, Serializer};

/// Summary of one command slot for the trace.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct SlotSummary {
    pub index: usize,
    pub locator: Option<&'static str>,
    pub primitive: u32,
    #[serde(rename = "type")]
    pub type_name: &'static str,
    pub ignored: bool,
    /// JOINT_COMMAND2: one element per frame, degrees. Held types: [value, period] or
    /// [intensity, mode, period].
    #[serde(serialize_with = "as_values")]
    pub values: Vec<Vec<f64>>,
}

/// What happened. Serialised as the fields that follow `kind` (untagged: the record
/// writes `kind` itself, and both LED variants are `"led"`).
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(untagged)]
pub enum TraceEvent {
    VectorStart {
        conn: u32,
        token: u64,
        duration_frames: u32,
        slots: Vec<SlotSummary>,
    },
    VectorDone {
        conn: u32,
        token: u64,
    },
    Led2 {
        locator: &'static str,
        on: bool,
    },
    Led3 {
        locator: &'static str,
        intensity: u8,
        mode: u16,
    },
    FaceMode {
        mode: u16,
    },
    Ear {
        locator: &'static str,
        state: u32,
    },
    EarHeld {
        locator: &'static str,
    },
    Clamp {
        locator: &'static str,
        #[serde(serialize_with = "as_num")]
        requested_deg: f64,
        #[serde(serialize_with = "as_num")]
        clamped_deg: f64,
        #[serde(rename = "rule", serialize_with = "as_rule")]
        combined: bool,
    },
    Sensor {
        first_frame: u32,
        #[serde(serialize_with = "as_joint_map")]
        joints: Vec<(&'static str, f64)>,
        #[serde(serialize_with = "as_nums")]
        accel: [f64; 3],
        paws: [bool; 4],
    },
    MotorPower {
        on: bool,
    },
    Gain {
        locator: &'static str,
        enabled: bool,
        p: u16,
        i: u16,
        d: u16,
    },
    Sync {
        key: u32,
        timed_out: bool,
    },
}

/// One trace line.
#[derive(Clone, Debug, PartialEq)]
pub struct TraceRecord {
    pub t_ms: u64,
    pub frame: u32,
    pub event: TraceEvent,
}

/// A measured value: rounded to 3 decimals, written as an integer when it is one (`-10`,
/// not `-10.0`; `-0` is `0`), `null` when not finite.
#[derive(Clone, Copy)]
struct Rounded(f64);

impl Serialize for Rounded {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        if !self.0.is_finite() {
            return s.serialize_none();
        }
        let r = (self.0 * 1000.0).round() / 1000.0;
        if r.fract() == 0.0 && r.abs() < (1u64 << 53) as f64 {
            s.serialize_i64(r as i64)
        } else {
            s.serialize_f64(r)
        }
    }
}

fn as_num<S: Serializer>(v: &f64, s: S) -> Result<S::Ok, S::Error> {
    Rounded(*v).serialize(s)
}

fn as_nums<S: Serializer>(v: &[f64; 3], s: S) -> Result<S::Ok, S::Error> {
    s.collect_seq(v.iter().map(|x| Rounded(*x)))
}

fn as_joint_map<S: Serializer>(v: &[(&'static str, f64)], s: S) -> Result<S::Ok, S::Error> {
    s.collect_map(v.iter().map(|(l, d)| (*l, Rounded(*d))))
}

fn as_rule<S: Serializer>(combined: &bool, s: S) -> Result<S::Ok, S::Error> {
    s.serialize_str(if *combined { "combined" } else { "range" })
}

/// One element per frame: a bare number when the element is one value, else an array.
fn as_values<S: Serializer>(v: &[Vec<f64>], s: S) -> Result<S::Ok, S::Error> {
    #[derive(Serialize)]
    #[serde(untagged)]
    enum Element {
        One(Rounded),
        Many(Vec<Rounded>),
    }
    s.collect_seq(v.iter().map(|e| match e.as_slice() {
        [x] => Element::One(Rounded(*x)),
        xs => Element::Many(xs.iter().map(|x| Rounded(*x)).collect()),
    }))
}

impl TraceRecord {
    pub fn kind(&self) -> &'static str {
        match self.event {
            TraceEvent::VectorStart { .. } => "vector_start",
            TraceEvent::VectorDone { .. } => "vector_done",
            TraceEvent::Led2 { .. } | TraceEvent::Led3 { .. } => "led",
            TraceEvent::FaceMode { .. } => "face_mode",
            TraceEvent::Ear { .. } => "ear",
            TraceEvent::EarHeld { .. } => "ear_held",
            TraceEvent::Clamp { .. } => "clamp",
            TraceEvent::Sensor { .. } => "sensor",
            TraceEvent::MotorPower { .. } => "motor_power",
            TraceEvent::Gain { .. } => "gain",
            TraceEvent::Sync { .. } => "sync",
        }
    }

    /// One JSON object, no newline.
    pub fn to_json(&self) -> String {
        #[derive(Serialize)]
        struct Line<'a> {
            t_ms: u64,
            frame: u32,
            kind: &'static str,
            #[serde(flatten)]
            event: &'a TraceEvent,
        }
        serde_json::to_string(&Line { t_ms: self.t_ms, frame: self.frame, kind: self.kind(), event: &self.event }).expect("a trace record is plain data")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn renders_schema() {
        let r = TraceRecord {
            t_ms: 8,
            frame: 1,
            event: TraceEvent::VectorStart {
                conn: 3,
                token: 9,
                duration_frames: 2,
                slots: vec![
                    SlotSummary {
                        index: 0,
                        locator: Some("PRM:/r1/c1-Joint2:11"),
                        primitive: 256,
                        type_name: "JOINT_COMMAND2",
                        ignored: false,
                        values: vec![vec![-10.0], vec![-10.5]],
                    },
                    SlotSummary { index: 1, locator: None, primitive: 7, type_name: "LED_COMMAND2", ignored: true, values: vec![vec![1.0, 64.0]] },
                ],
            },
        };
        assert_eq!(
            r.to_json(),
            "{\"t_ms\":8,\"frame\":1,\"kind\":\"vector_start\",\"conn\":3,\"token\":9,\"duration_frames\":2,\"slots\":[\
{\"index\":0,\"locator\":\"PRM:/r1/c1-Joint2:11\",\"primitive\":256,\"type\":\"JOINT_COMMAND2\",\"ignored\":false,\"values\":[-10,-10.5]},\
{\"index\":1,\"locator\":null,\"primitive\":7,\"type\":\"LED_COMMAND2\",\"ignored\":true,\"values\":[[1,64]]}]}"
        );
        let s = TraceRecord {
            t_ms: 32,
            frame: 4,
            event: TraceEvent::Sensor { first_frame: 1, joints: vec![("a\"b", 1.23456)], accel: [0.0, -0.0, 9.80665], paws: [true, false, true, true] },
        };
        assert_eq!(
            s.to_json(),
            "{\"t_ms\":32,\"frame\":4,\"kind\":\"sensor\",\"first_frame\":1,\"joints\":{\"a\\\"b\":1.235},\"accel\":[0,0,9.807],\"paws\":[true,false,true,true]}"
        );
        let c = TraceRecord { t_ms: 0, frame: 0, event: TraceEvent::Clamp { locator: "x", requested_deg: 0.0, clamped_deg: 5.0, combined: false } };
        assert!(c.to_json().ends_with("\"kind\":\"clamp\",\"locator\":\"x\",\"requested_deg\":0,\"clamped_deg\":5,\"rule\":\"range\"}"));
        let odd =
            TraceRecord { t_ms: 0, frame: 0, event: TraceEvent::Clamp { locator: "y", requested_deg: f64::NAN, clamped_deg: 1e17 + 0.5, combined: true } };
        assert!(odd.to_json().ends_with("\"requested_deg\":null,\"clamped_deg\":1e+17,\"rule\":\"combined\"}"), "{}", odd.to_json());
        let led = TraceRecord { t_ms: 16, frame: 2, event: TraceEvent::Led3 { locator: "l", intensity: 255, mode: 1 } };
        assert_eq!(led.to_json(), "{\"t_ms\":16,\"frame\":2,\"kind\":\"led\",\"locator\":\"l\",\"intensity\":255,\"mode\":1}");
    }
}
