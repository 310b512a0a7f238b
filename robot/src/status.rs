//! `OStatus` values returned by the robot API (robot-api 2), as plain `u32` so the
//! wiring can hand them to C++ unchanged.

pub type OStatus = u32;

pub const O_SUCCESS: OStatus = 0;
pub const O_FAIL: OStatus = 2;
pub const O_NOT_SUPPORTED: OStatus = 3;
pub const O_INVALID_ARG: OStatus = 4;
pub const O_NOT_FOUND: OStatus = 6;
pub const O_INVALID_PRIMITIVE_ID: OStatus = 4096;
pub const O_INVALID_DATA_TYPE: OStatus = 4098;
pub const O_NO_SYNC_KEY: OStatus = 4106;
pub const O_INVALID_SYNC_KEY: OStatus = 4107;
pub const O_GAIN_DISABLED: OStatus = 4108;
