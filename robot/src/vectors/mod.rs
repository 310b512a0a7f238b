//! Readers and writers of the OPEN-R data vectors on raw byte slices, with the robot's
//! exact ILP32 layouts (robot-api 6.2-6.5; `include/OPENR/ODataFormats.h`).
//!
//! Why it exists: command, sensor and sound vectors live in shared memory written by
//! C++ objects; the runtime must read and write them by byte offset without trusting
//! their contents. Every reader bounds-checks and returns [`VectorError`] for malformed
//! input; nothing here panics on input data. All integers are little-endian.
//!
//! Layout summary (offsets from the vector start):
//! * header `ODataVectorInfo`, 192 bytes; `info[]` at 192;
//! * command: 32-byte `OCommandInfo`, 128-byte `OCommandData` (16 × 8-byte values);
//! * sensor: 32-byte `OSensorFrameInfo`, 256-byte `OSensorFrameData` (16 × 16 bytes);
//! * sound: 64-byte `OSoundInfo`, slot = data size rounded up to 32.
//!
//! Image vectors are in [`super::image`]. Here: the sizes, errors, byte helpers and the
//! common header; the modules `command`, `sensor` and `sound` hold one vector kind each.

use std::fmt;

use super::model::PrimitiveId;

mod command;
mod sensor;
mod sound;
#[cfg(test)]
mod tests;

pub use command::*;
pub use sensor::*;
pub use sound::*;

pub const HEADER_SIZE: usize = 192;
pub const COMMAND_INFO_SIZE: usize = 32;
pub const COMMAND_DATA_SIZE: usize = 128;
pub const COMMAND_FRAME_SIZE: usize = 8;
pub const SENSOR_INFO_SIZE: usize = 32;
pub const SENSOR_DATA_SIZE: usize = 256;
pub const SENSOR_VALUE_SIZE: usize = 16;
pub const SOUND_INFO_SIZE: usize = 64;
/// `ocommandMAX_FRAMES`.
pub const COMMAND_MAX_FRAMES: u32 = 16;
/// Frames per sensor entry on ERS-7/210/220.
pub const SENSOR_FRAMES: usize = 4;
/// `odataOPTIONAL_MAX`.
pub const OPTIONAL_MAX: usize = 128;
pub const PAGE: usize = 4096;

pub const SYNC_KEY_UNDEF: u32 = 0xFFFF_FFFF;
pub const FRAME_INVALID: u32 = 0xFFFF_FFFF;

/// `ODataType` values used here (robot-api 6.1).
pub mod odata {
    pub const SOUND: u32 = 16;
    pub const FBK_YCRCB: u32 = 19;
    pub const FBK_CDT: u32 = 20;
    pub const FBK_YCRCB_HPF: u32 = 24;
    pub const JOINT_COMMAND: u32 = 256;
    pub const CAMERA_COMMAND: u32 = 257;
    pub const LED_COMMAND: u32 = 258;
    pub const JOINT_COMMAND2: u32 = 259;
    pub const LED_COMMAND2: u32 = 260;
    pub const JOINT_COMMAND3: u32 = 261;
    pub const JOINT_COMMAND4: u32 = 262;
    pub const LED_COMMAND3: u32 = 263;
    pub const COMMAND_VECTOR: u32 = 1024;
    pub const SENSOR_FRAME_VECTOR: u32 = 1025;
    pub const SOUND_VECTOR: u32 = 1026;
    pub const FBKIMAGE_VECTOR: u32 = 1027;
    pub const CDT_VECTOR: u32 = 1028;
}

/// Why a vector was rejected.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum VectorError {
    /// The buffer ends before `need` bytes.
    TooShort { need: usize, have: usize },
    /// `vectorInfo.type` is not the expected vector type.
    WrongType { expected: u32, found: u32 },
    /// `numData > maxNumData`.
    TooManyData { num_data: u32, max_num_data: u32 },
    /// A slot's data lies outside the buffer.
    SlotOutOfBounds { slot: usize, offset: u64, len: u64 },
    /// A command slot claims more than 16 frames.
    TooManyFrames { slot: usize, num_frames: u32 },
    /// `optOffset + optSize > 128`.
    BadOptional { offset: u32, size: u32 },
    /// A caller-supplied argument does not fit (e.g. buffer too small for `n` entries).
    BadArgument(&'static str),
}

impl fmt::Display for VectorError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            VectorError::TooShort { need, have } => write!(f, "vector too short: need {need} bytes, have {have}"),
            VectorError::WrongType { expected, found } => write!(f, "vector type {found}, expected {expected}"),
            VectorError::TooManyData { num_data, max_num_data } => write!(f, "numData {num_data} > maxNumData {max_num_data}"),
            VectorError::SlotOutOfBounds { slot, offset, len } => {
                write!(f, "slot {slot}: data at {offset}+{len} lies outside the vector")
            }
            VectorError::TooManyFrames { slot, num_frames } => write!(f, "slot {slot}: numFrames {num_frames} > 16"),
            VectorError::BadOptional { offset, size } => write!(f, "optional bytes {offset}+{size} exceed 128"),
            VectorError::BadArgument(m) => write!(f, "{m}"),
        }
    }
}

impl std::error::Error for VectorError {}

pub type Result<T> = std::result::Result<T, VectorError>;

// ---------------------------------------------------------------------------------
// byte helpers

fn need(buf: &[u8], end: usize) -> Result<()> {
    if end > buf.len() {
        Err(VectorError::TooShort { need: end, have: buf.len() })
    } else {
        Ok(())
    }
}

pub(crate) fn rd_u32(buf: &[u8], off: usize) -> Result<u32> {
    need(buf, off.saturating_add(4))?;
    Ok(u32::from_le_bytes([buf[off], buf[off + 1], buf[off + 2], buf[off + 3]]))
}

pub(crate) fn rd_u16(buf: &[u8], off: usize) -> Result<u16> {
    need(buf, off.saturating_add(2))?;
    Ok(u16::from_le_bytes([buf[off], buf[off + 1]]))
}

pub(crate) fn wr_u32(buf: &mut [u8], off: usize, v: u32) -> Result<()> {
    need(buf, off.saturating_add(4))?;
    buf[off..off + 4].copy_from_slice(&v.to_le_bytes());
    Ok(())
}

pub(crate) fn wr_u16(buf: &mut [u8], off: usize, v: u16) -> Result<()> {
    need(buf, off.saturating_add(2))?;
    buf[off..off + 2].copy_from_slice(&v.to_le_bytes());
    Ok(())
}

/// Rounds a byte count up to whole 4096-byte pages (Sony's region sizes).
pub fn region_size(bytes: usize) -> usize {
    bytes.div_ceil(PAGE) * PAGE
}

fn round32(n: usize) -> usize {
    n.div_ceil(32) * 32
}

// ---------------------------------------------------------------------------------
// header

/// `ODataVectorInfo` fields (robot-api 6.2).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct VectorHeader {
    pub mem_region_id: u32,
    pub phys_addr: u32,
    pub offset: u32,
    pub total_size: u32,
    pub vector_type: u32,
    pub info_offset: u32,
    pub info_size: u32,
    pub max_num_data: u32,
    pub num_data: u32,
    pub sync_key: u32,
    pub wait: u32,
    pub opt_offset: u32,
    pub opt_size: u32,
}

impl VectorHeader {
    pub fn read(buf: &[u8]) -> Result<VectorHeader> {
        need(buf, HEADER_SIZE)?;
        let f = |i: usize| rd_u32(buf, 4 * i);
        Ok(VectorHeader {
            mem_region_id: f(0)?,
            phys_addr: f(1)?,
            offset: f(2)?,
            total_size: f(3)?,
            vector_type: f(4)?,
            info_offset: f(5)?,
            info_size: f(6)?,
            max_num_data: f(7)?,
            num_data: f(8)?,
            sync_key: f(9)?,
            wait: f(10)?,
            opt_offset: f(11)?,
            opt_size: f(12)?,
        })
    }

    /// Writes the 13 named fields; padding and `optional` are left untouched.
    pub fn write(&self, buf: &mut [u8]) -> Result<()> {
        need(buf, HEADER_SIZE)?;
        let v = [
            self.mem_region_id,
            self.phys_addr,
            self.offset,
            self.total_size,
            self.vector_type,
            self.info_offset,
            self.info_size,
            self.max_num_data,
            self.num_data,
            self.sync_key,
            self.wait,
            self.opt_offset,
            self.opt_size,
        ];
        for (i, x) in v.iter().enumerate() {
            wr_u32(buf, 4 * i, *x)?;
        }
        Ok(())
    }

    /// The valid `optional` bytes (robot-api 8.2.6), or None when `optSize` is 0.
    pub fn optional<'a>(&self, buf: &'a [u8]) -> Result<Option<&'a [u8]>> {
        if self.opt_size == 0 {
            return Ok(None);
        }
        let end = self.opt_offset as u64 + self.opt_size as u64;
        if end > OPTIONAL_MAX as u64 {
            return Err(VectorError::BadOptional { offset: self.opt_offset, size: self.opt_size });
        }
        need(buf, HEADER_SIZE)?;
        Ok(Some(&buf[64 + self.opt_offset as usize..64 + end as usize]))
    }
}

/// Writes the region fields the allocator owns (`memRegionID`, `offset`, `totalSize`).
pub fn set_region_fields(buf: &mut [u8], mem_region_id: u32, offset: u32, total_size: u32) -> Result<()> {
    wr_u32(buf, 0, mem_region_id)?;
    wr_u32(buf, 8, offset)?;
    wr_u32(buf, 12, total_size)
}

/// Common allocator header: zeroes the 192 bytes, then fills the fields.
fn init_header(buf: &mut [u8], vector_type: u32, info_size: usize, n: usize) -> Result<()> {
    need(buf, HEADER_SIZE)?;
    buf[..HEADER_SIZE].fill(0);
    VectorHeader {
        total_size: u32::try_from(buf.len()).map_err(|_| VectorError::BadArgument("vector larger than 4 GiB"))?,
        vector_type,
        info_offset: HEADER_SIZE as u32,
        info_size: info_size as u32,
        max_num_data: n as u32,
        sync_key: SYNC_KEY_UNDEF,
        ..VectorHeader::default()
    }
    .write(buf)
}
