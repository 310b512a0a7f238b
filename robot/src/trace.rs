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

use std::fmt::Write;

/// Summary of one command slot for the trace.
#[derive(Clone, Debug, PartialEq)]
pub struct SlotSummary {
    pub index: usize,
    pub locator: Option<&'static str>,
    pub primitive: u32,
    pub type_name: &'static str,
    pub ignored: bool,
    /// JOINT_COMMAND2: one element per frame, degrees. Held types: [value, period] or
    /// [intensity, mode, period].
    pub values: Vec<Vec<f64>>,
}

/// What happened.
#[derive(Clone, Debug, PartialEq)]
pub enum TraceEvent {
    VectorStart { conn: u32, token: u64, duration_frames: u32, slots: Vec<SlotSummary> },
    VectorDone { conn: u32, token: u64 },
    Led2 { locator: &'static str, on: bool },
    Led3 { locator: &'static str, intensity: u8, mode: u16 },
    FaceMode { mode: u16 },
    Ear { locator: &'static str, state: u32 },
    EarHeld { locator: &'static str },
    Clamp { locator: &'static str, requested_deg: f64, clamped_deg: f64, combined: bool },
    Sensor { first_frame: u32, joints: Vec<(&'static str, f64)>, accel: [f64; 3], paws: [bool; 4] },
    MotorPower { on: bool },
    Gain { locator: &'static str, enabled: bool, p: u16, i: u16, d: u16 },
    Sync { key: u32, timed_out: bool },
}

/// One trace line.
#[derive(Clone, Debug, PartialEq)]
pub struct TraceRecord {
    pub t_ms: u64,
    pub frame: u32,
    pub event: TraceEvent,
}

fn num(out: &mut String, v: f64) {
    if v.is_finite() {
        let r = (v * 1000.0).round() / 1000.0;
        let _ = write!(out, "{}", if r == 0.0 { 0.0 } else { r });
    } else {
        out.push_str("null");
    }
}

fn string(out: &mut String, s: &str) {
    out.push('"');
    for c in s.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            c if (c as u32) < 0x20 => {
                let _ = write!(out, "\\u{:04x}", c as u32);
            }
            c => out.push(c),
        }
    }
    out.push('"');
}

fn key(out: &mut String, k: &str) {
    out.push(',');
    string(out, k);
    out.push(':');
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
        let mut o = String::with_capacity(128);
        let _ = write!(o, "{{\"t_ms\":{},\"frame\":{}", self.t_ms, self.frame);
        key(&mut o, "kind");
        string(&mut o, self.kind());
        match &self.event {
            TraceEvent::VectorStart { conn, token, duration_frames, slots } => {
                let _ = write!(o, ",\"conn\":{conn},\"token\":{token},\"duration_frames\":{duration_frames},\"slots\":[");
                for (i, s) in slots.iter().enumerate() {
                    if i > 0 {
                        o.push(',');
                    }
                    let _ = write!(o, "{{\"index\":{}", s.index);
                    key(&mut o, "locator");
                    match s.locator {
                        Some(l) => string(&mut o, l),
                        None => o.push_str("null"),
                    }
                    let _ = write!(o, ",\"primitive\":{}", s.primitive);
                    key(&mut o, "type");
                    string(&mut o, s.type_name);
                    let _ = write!(o, ",\"ignored\":{},\"values\":[", s.ignored);
                    for (k, v) in s.values.iter().enumerate() {
                        if k > 0 {
                            o.push(',');
                        }
                        if v.len() == 1 {
                            num(&mut o, v[0]);
                        } else {
                            o.push('[');
                            for (n, x) in v.iter().enumerate() {
                                if n > 0 {
                                    o.push(',');
                                }
                                num(&mut o, *x);
                            }
                            o.push(']');
                        }
                    }
                    o.push_str("]}");
                }
                o.push(']');
            }
            TraceEvent::VectorDone { conn, token } => {
                let _ = write!(o, ",\"conn\":{conn},\"token\":{token}");
            }
            TraceEvent::Led2 { locator, on } => {
                key(&mut o, "locator");
                string(&mut o, locator);
                let _ = write!(o, ",\"on\":{on}");
            }
            TraceEvent::Led3 { locator, intensity, mode } => {
                key(&mut o, "locator");
                string(&mut o, locator);
                let _ = write!(o, ",\"intensity\":{intensity},\"mode\":{mode}");
            }
            TraceEvent::FaceMode { mode } => {
                let _ = write!(o, ",\"mode\":{mode}");
            }
            TraceEvent::Ear { locator, state } => {
                key(&mut o, "locator");
                string(&mut o, locator);
                let _ = write!(o, ",\"state\":{state}");
            }
            TraceEvent::EarHeld { locator } => {
                key(&mut o, "locator");
                string(&mut o, locator);
            }
            TraceEvent::Clamp { locator, requested_deg, clamped_deg, combined } => {
                key(&mut o, "locator");
                string(&mut o, locator);
                key(&mut o, "requested_deg");
                num(&mut o, *requested_deg);
                key(&mut o, "clamped_deg");
                num(&mut o, *clamped_deg);
                key(&mut o, "rule");
                string(&mut o, if *combined { "combined" } else { "range" });
            }
            TraceEvent::Sensor { first_frame, joints, accel, paws } => {
                let _ = write!(o, ",\"first_frame\":{first_frame},\"joints\":{{");
                for (i, (l, d)) in joints.iter().enumerate() {
                    if i > 0 {
                        o.push(',');
                    }
                    string(&mut o, l);
                    o.push(':');
                    num(&mut o, *d);
                }
                o.push_str("},\"accel\":[");
                for (i, a) in accel.iter().enumerate() {
                    if i > 0 {
                        o.push(',');
                    }
                    num(&mut o, *a);
                }
                let _ = write!(o, "],\"paws\":[{},{},{},{}]", paws[0], paws[1], paws[2], paws[3]);
            }
            TraceEvent::MotorPower { on } => {
                let _ = write!(o, ",\"on\":{on}");
            }
            TraceEvent::Gain { locator, enabled, p, i, d } => {
                key(&mut o, "locator");
                string(&mut o, locator);
                let _ = write!(o, ",\"enabled\":{enabled},\"p\":{p},\"i\":{i},\"d\":{d}");
            }
            TraceEvent::Sync { key: k, timed_out } => {
                let _ = write!(o, ",\"key\":{k},\"timed_out\":{timed_out}");
            }
        }
        o.push('}');
        o
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
    }
}
