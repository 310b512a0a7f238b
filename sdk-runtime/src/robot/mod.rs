//! Virtual ERS-7 (placeholder facade; filled in below).
pub mod effector;
pub mod frame_clock;
pub mod image;
pub mod model;
mod model_ers2xx;
pub mod status;
pub mod sync;
pub mod vectors;
