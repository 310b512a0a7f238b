//! In-process observers of a run (`cargo openr run --view`, `--record`): handed the
//! running runtime once, before the first frame, they read the robot, the clock and the
//! power state whenever they like and may send control commands (`control::command`).
//! A recorder also sees each frame as it ends ([`Observer::frame`], on the frame
//! thread, so at `--speed max` it sees the same frames every run) and is told when the
//! run is over ([`Observer::finish`]).
//!
//! Why not a robot peer (docs/robot-protocol.md): a FRAME carries the effector's output
//! only, while a viewer also shows what the robot measures (switches, distances, the
//! accelerometer, the battery) and the camera picture; and an observer must never hold
//! up a frame, which a peer's socket can.
use std::sync::Arc;

use crate::error::Result;
use crate::runtime::Runtime;

pub trait Observer: Send + Sync {
    /// Called once when the runtime is up, before the first frame. An error ends the run.
    fn attach(&self, rt: &'static Runtime) -> Result<()>;

    /// A frame ended (the robot is unlocked). Must not block: it holds up the robot.
    fn frame(&self, _rt: &Runtime, _frame: &Frame<'_>) {}

    /// The run is over (after Stop/Destroy, no frame follows): write out what is left.
    fn finish(&self) {}
}

/// What one frame produced, for [`Observer::frame`].
pub struct Frame<'a> {
    /// The frame number and the virtual time at its end, as the trace stamps them.
    pub frame: u32,
    pub t_ms: u64,
    /// The camera took a picture in this frame (`VirtualRobot::camera_rgb` is it).
    pub picture: bool,
    /// A sensor vector was produced in this frame (the trace has a `sensor` record).
    pub sensor: bool,
    /// The sounds that started playing in this frame (their PCM as the vector has it:
    /// 8-bit signed or 16-bit little-endian; zeros while the amplifier is off).
    pub sounds: &'a [(crate::audio::Format, Vec<u8>)],
}

/// The observers of a run.
#[derive(Clone, Default)]
pub struct Observers(pub Vec<Arc<dyn Observer>>);

impl std::fmt::Debug for Observers {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Observers({})", self.0.len())
    }
}
