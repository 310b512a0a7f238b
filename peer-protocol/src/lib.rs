//! The external robot protocol (ORP1, docs/robot-protocol.md) as data: what a peer — a
//! physics simulator, a recorder, a bridge to a real robot — and the runtime say to each
//! other, with no runtime state. The runtime (`sdk-runtime`'s `peer` module) owns the
//! sockets, the threads and the lockstep; everything it puts on or takes off the wire
//! goes through this crate:
//!
//! - [`wire`]: the 16-byte header, message types, roles, flags and error codes, and the
//!   payload reader / writer;
//! - [`payload`]: the checks of what a peer sends that need only the robot model (the
//!   fuzz checks drive them without a runtime);
//! - [`encode`]: the FRAME and WELCOME payloads, built from the virtual robot;
//! - [`outbox`]: the bounded queue and writer loop that keep a slow peer from blocking
//!   the frame thread.
//!
//! The Python peers (`tools/robot_peer.py`, `sim/mujoco/bridge.py`) copy some of these
//! numbers and hand-code the layouts; the crate's tests read their numbers and fail on any
//! difference, and have robot_peer.py decode every design's WELCOME and a FRAME
//! (tests/python_decodes.rs).
//!
//! ```
//! use openr_peer_protocol::wire::{message, read_message, HELLO, hello, parse_hello, ROLE_JOINTS};
//! let m = message(HELLO, 0, &hello(ROLE_JOINTS, 0, "sim"));
//! let (header, payload) = read_message(&mut &m[..]).unwrap().unwrap().unwrap();
//! assert_eq!((header.kind, parse_hello(&payload).unwrap().name.as_str()), (HELLO, "sim"));
//! ```

pub mod encode;
pub mod outbox;
pub mod payload;
#[cfg(test)]
mod python_agrees;
pub mod wire;

use openr_robot::model::{PrimitiveKind, SensorKind};
use wire::*;

/// The role a primitive's readings belong to (None: a peer cannot supply it).
pub fn role_of(kind: PrimitiveKind) -> Option<u32> {
    match kind {
        PrimitiveKind::Joint2 => Some(ROLE_JOINTS),
        PrimitiveKind::Sensor(SensorKind::Accelerometer) => Some(ROLE_ACCEL),
        PrimitiveKind::Sensor(SensorKind::Psd) => Some(ROLE_PSD),
        PrimitiveKind::Sensor(_) => Some(ROLE_SWITCHES),
        _ => None,
    }
}

/// A primitive's class in the WELCOME table.
pub fn class_of(kind: PrimitiveKind) -> u16 {
    match kind {
        PrimitiveKind::Joint2 => CLASS_JOINT,
        PrimitiveKind::Joint3 | PrimitiveKind::Joint4 => CLASS_EAR,
        PrimitiveKind::Led2 => CLASS_LED2,
        PrimitiveKind::Led3 => CLASS_LED3,
        PrimitiveKind::Sensor(SensorKind::Accelerometer) => CLASS_ACCEL,
        PrimitiveKind::Sensor(SensorKind::Psd) => CLASS_PSD,
        PrimitiveKind::Sensor(SensorKind::Thermometer) => CLASS_OTHER,
        PrimitiveKind::Sensor(_) => CLASS_SWITCH,
        PrimitiveKind::FbkImageSensor => CLASS_CAMERA,
        PrimitiveKind::Mic => CLASS_MIC,
        PrimitiveKind::Speaker => CLASS_SPEAKER,
    }
}
