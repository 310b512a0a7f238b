//! In-process observers of a run (`cargo openr run --view`): handed the running
//! runtime once, before the first frame, they read the robot, the clock and the power
//! state whenever they like and may send control commands (`control::command`).
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
}

/// The observers of a run.
#[derive(Clone, Default)]
pub struct Observers(pub Vec<Arc<dyn Observer>>);

impl std::fmt::Debug for Observers {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Observers({})", self.0.len())
    }
}
