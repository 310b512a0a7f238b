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
//! Image vectors are in [`super::image`].

use std::fmt;

use super::model::PrimitiveId;

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

// ---------------------------------------------------------------------------------
// command vectors (6.3)

/// Bytes `NewCommandVectorData(n)` needs before page rounding: 192 + 160·n.
pub fn command_vector_size(n: usize) -> usize {
    HEADER_SIZE + (COMMAND_INFO_SIZE + COMMAND_DATA_SIZE) * n
}

/// Writes the exact initial contents of `NewCommandVectorData(n)` (robot-api 6.3) into
/// `buf` (which must hold at least [`command_vector_size`]`(n)` bytes; `totalSize` =
/// `buf.len()`, `memRegionID` = 0 — see [`set_region_fields`]). Data blocks are zeroed.
pub fn command_vector_init(buf: &mut [u8], n: usize) -> Result<()> {
    let size = command_vector_size(n);
    if buf.len() < size {
        return Err(VectorError::TooShort { need: size, have: buf.len() });
    }
    init_header(buf, odata::COMMAND_VECTOR, COMMAND_INFO_SIZE, n)?;
    for i in 0..n {
        let o = HEADER_SIZE + COMMAND_INFO_SIZE * i;
        let data = HEADER_SIZE + COMMAND_INFO_SIZE * n + COMMAND_DATA_SIZE * i;
        for (k, v) in [0, 0xFFFF_FFFF, FRAME_INVALID, 0, COMMAND_FRAME_SIZE as u32, data as u32, COMMAND_DATA_SIZE as u32, 0]
            .into_iter()
            .enumerate()
        {
            wr_u32(buf, o + 4 * k, v)?;
        }
    }
    buf[HEADER_SIZE + COMMAND_INFO_SIZE * n..size].fill(0);
    Ok(())
}

/// A value held for `period` frames (`period` 0 is treated as 1, robot-api 8.2.2).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Held<T> {
    pub value: T,
    pub period: u16,
}

/// `OLEDCommandValue3` contents.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Led3Value {
    pub intensity: i16,
    pub mode: u16,
}

/// The typed frames of one command slot.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum CommandValues {
    /// JOINT_COMMAND2: one target (µrad) per 8 ms frame.
    Joint2(Vec<i32>),
    /// JOINT_COMMAND3: one ojoint3 state per frame.
    Joint3(Vec<u32>),
    /// JOINT_COMMAND4: ojoint4 state held for `period` frames.
    Joint4(Vec<Held<u32>>),
    /// LED_COMMAND2: oledON/OFF held for `period` frames.
    Led2(Vec<Held<u32>>),
    /// LED_COMMAND3: intensity + mode held for `period` frames.
    Led3(Vec<Held<Led3Value>>),
    /// Legacy LED_COMMAND: oledON/OFF held for `period` × 16 frames.
    LegacyLed(Vec<Held<u32>>),
    /// A command type this emulator does not execute (legacy joint/camera, raw types).
    Unsupported(u32),
}

/// What one slot asks of its primitive in one frame.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FrameCommand {
    /// Joint2 target, µrad.
    Joint(i32),
    /// Joint3 / Joint4 binary state.
    State(u32),
    /// LED2 on/off.
    Led2(bool),
    /// LED3 intensity/mode.
    Led3(Led3Value),
}

fn held_at<T: Copy>(v: &[Held<T>], k: u32, unit: u32) -> Option<T> {
    let mut end = 0u32;
    for h in v {
        end = end.saturating_add(u32::from(h.period.max(1)).saturating_mul(unit));
        if k < end {
            return Some(h.value);
        }
    }
    None
}

fn held_len<T>(v: &[Held<T>], unit: u32) -> u32 {
    v.iter().fold(0u32, |a, h| a.saturating_add(u32::from(h.period.max(1)).saturating_mul(unit)))
}

impl CommandValues {
    /// Frames (8 ms) this slot lasts (robot-api 8.2.2); 0 for unsupported types.
    pub fn duration_frames(&self) -> u32 {
        match self {
            CommandValues::Joint2(v) => v.len() as u32,
            CommandValues::Joint3(v) => v.len() as u32,
            CommandValues::Joint4(v) | CommandValues::Led2(v) => held_len(v, 1),
            CommandValues::Led3(v) => held_len(v, 1),
            CommandValues::LegacyLed(v) => held_len(v, 16),
            CommandValues::Unsupported(_) => 0,
        }
    }

    /// The command for frame `k` (0 = first frame of the slot), None once it has ended.
    pub fn at(&self, k: u32) -> Option<FrameCommand> {
        match self {
            CommandValues::Joint2(v) => v.get(k as usize).map(|&x| FrameCommand::Joint(x)),
            CommandValues::Joint3(v) => v.get(k as usize).map(|&x| FrameCommand::State(x)),
            CommandValues::Joint4(v) => held_at(v, k, 1).map(FrameCommand::State),
            CommandValues::Led2(v) => held_at(v, k, 1).map(|x| FrameCommand::Led2(x != 0)),
            CommandValues::Led3(v) => held_at(v, k, 1).map(FrameCommand::Led3),
            CommandValues::LegacyLed(v) => held_at(v, k, 16).map(|x| FrameCommand::Led2(x != 0)),
            CommandValues::Unsupported(_) => None,
        }
    }

    /// Short name of the command type (trace).
    pub fn type_name(&self) -> &'static str {
        match self {
            CommandValues::Joint2(_) => "JOINT_COMMAND2",
            CommandValues::Joint3(_) => "JOINT_COMMAND3",
            CommandValues::Joint4(_) => "JOINT_COMMAND4",
            CommandValues::Led2(_) => "LED_COMMAND2",
            CommandValues::Led3(_) => "LED_COMMAND3",
            CommandValues::LegacyLed(_) => "LED_COMMAND",
            CommandValues::Unsupported(_) => "UNSUPPORTED",
        }
    }
}

/// One valid slot (`i < numData`, `numFrames > 0`) of a command vector.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CommandSlot {
    /// Index in `info[]` (for writing `frameNumber` back).
    pub index: usize,
    pub data_type: u32,
    pub primitive: PrimitiveId,
    pub values: CommandValues,
}

/// A parsed `OCommandVectorData`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CommandVector {
    pub header: VectorHeader,
    /// Slots with `numFrames > 0`; slots with `numFrames == 0` do nothing (robot-api 8.2.2).
    pub slots: Vec<CommandSlot>,
    /// `optional[optOffset..optOffset+optSize]`, if any.
    pub optional: Option<Vec<u8>>,
}

impl CommandVector {
    /// The vector's duration: its longest slot (robot-api 8.2.2).
    pub fn duration_frames(&self) -> u32 {
        self.slots.iter().map(|s| s.values.duration_frames()).max().unwrap_or(0)
    }
}

/// Parses an `OCommandVectorData` (header, `numData` infos, their data blocks).
/// Structural problems (short buffer, wrong vector type, numData > maxNumData,
/// data outside the buffer, numFrames > 16, bad optional range) are errors; unknown
/// command types become [`CommandValues::Unsupported`] so the rest of the vector
/// still plays (robot-api 8.2.3).
pub fn parse_command_vector(buf: &[u8]) -> Result<CommandVector> {
    let header = VectorHeader::read(buf)?;
    if header.vector_type != odata::COMMAND_VECTOR {
        return Err(VectorError::WrongType { expected: odata::COMMAND_VECTOR, found: header.vector_type });
    }
    if header.num_data > header.max_num_data {
        return Err(VectorError::TooManyData { num_data: header.num_data, max_num_data: header.max_num_data });
    }
    let n = header.num_data as usize;
    need(buf, HEADER_SIZE + COMMAND_INFO_SIZE * n)?;
    let optional = header.optional(buf)?.map(<[u8]>::to_vec);
    let mut slots = Vec::new();
    for i in 0..n {
        let o = HEADER_SIZE + COMMAND_INFO_SIZE * i;
        let data_type = rd_u32(buf, o)?;
        let primitive = rd_u32(buf, o + 4)?;
        let num_frames = rd_u32(buf, o + 12)?;
        let data_offset = rd_u32(buf, o + 20)?;
        if num_frames == 0 {
            continue;
        }
        if num_frames > COMMAND_MAX_FRAMES {
            return Err(VectorError::TooManyFrames { slot: i, num_frames });
        }
        let len = num_frames as u64 * COMMAND_FRAME_SIZE as u64;
        if data_offset as u64 + len > buf.len() as u64 {
            return Err(VectorError::SlotOutOfBounds { slot: i, offset: data_offset as u64, len });
        }
        let base = data_offset as usize;
        let frames = (0..num_frames as usize).map(|k| base + COMMAND_FRAME_SIZE * k);
        let held32 = |buf: &[u8]| -> Result<Vec<Held<u32>>> {
            frames.clone().map(|f| Ok(Held { value: rd_u32(buf, f)?, period: rd_u16(buf, f + 4)? })).collect()
        };
        let values = match data_type {
            odata::JOINT_COMMAND2 => CommandValues::Joint2(frames.clone().map(|f| rd_u32(buf, f).map(|v| v as i32)).collect::<Result<_>>()?),
            odata::JOINT_COMMAND3 => CommandValues::Joint3(frames.clone().map(|f| rd_u32(buf, f)).collect::<Result<_>>()?),
            odata::JOINT_COMMAND4 => CommandValues::Joint4(held32(buf)?),
            odata::LED_COMMAND2 => CommandValues::Led2(held32(buf)?),
            odata::LED_COMMAND => CommandValues::LegacyLed(held32(buf)?),
            odata::LED_COMMAND3 => CommandValues::Led3(
                frames
                    .clone()
                    .map(|f| {
                        Ok(Held {
                            value: Led3Value { intensity: rd_u16(buf, f)? as i16, mode: rd_u16(buf, f + 2)? },
                            period: rd_u16(buf, f + 4)?,
                        })
                    })
                    .collect::<Result<_>>()?,
            ),
            other => CommandValues::Unsupported(other),
        };
        slots.push(CommandSlot { index: i, data_type, primitive, values });
    }
    Ok(CommandVector { header, slots, optional })
}

/// Writes `OCommandInfo[slot].frameNumber` (the effector does this when a vector starts).
pub fn write_command_frame_number(buf: &mut [u8], slot: usize, frame: u32) -> Result<()> {
    let off = HEADER_SIZE + COMMAND_INFO_SIZE * slot + 8;
    wr_u32(buf, off, frame)
}

/// Test/tool helper: appends one slot to a vector made by [`command_vector_init`]
/// (sets type/ID/numFrames like `OCommandInfo::Set`, writes the 8-byte frames,
/// increments `numData`).
pub fn command_vector_push(buf: &mut [u8], data_type: u32, primitive: PrimitiveId, frames: &[[u8; 8]]) -> Result<usize> {
    let h = VectorHeader::read(buf)?;
    if h.num_data >= h.max_num_data {
        return Err(VectorError::BadArgument("command vector full"));
    }
    if frames.is_empty() || frames.len() > COMMAND_MAX_FRAMES as usize {
        return Err(VectorError::BadArgument("1..16 frames per slot"));
    }
    let i = h.num_data as usize;
    let o = HEADER_SIZE + COMMAND_INFO_SIZE * i;
    wr_u32(buf, o, data_type)?;
    wr_u32(buf, o + 4, primitive)?;
    wr_u32(buf, o + 12, frames.len() as u32)?;
    let data = rd_u32(buf, o + 20)? as usize;
    for (k, f) in frames.iter().enumerate() {
        let at = data + COMMAND_FRAME_SIZE * k;
        need(buf, at + 8)?;
        buf[at..at + 8].copy_from_slice(f);
    }
    wr_u32(buf, 32, h.num_data + 1)?;
    Ok(i)
}

/// Encodes an 8-byte `OJointCommandValue2`.
pub fn joint2_frame(urad: i32) -> [u8; 8] {
    let mut f = [0u8; 8];
    f[..4].copy_from_slice(&urad.to_le_bytes());
    f
}

/// Encodes an 8-byte `OLEDCommandValue2` / `OJointCommandValue4` / legacy LED value.
pub fn held_frame(value: u32, period: u16) -> [u8; 8] {
    let mut f = [0u8; 8];
    f[..4].copy_from_slice(&value.to_le_bytes());
    f[4..6].copy_from_slice(&period.to_le_bytes());
    f
}

/// Encodes an 8-byte `OLEDCommandValue3`.
pub fn led3_frame(intensity: i16, mode: u16, period: u16) -> [u8; 8] {
    let mut f = [0u8; 8];
    f[..2].copy_from_slice(&intensity.to_le_bytes());
    f[2..4].copy_from_slice(&mode.to_le_bytes());
    f[4..6].copy_from_slice(&period.to_le_bytes());
    f
}

// ---------------------------------------------------------------------------------
// sensor frame vectors (6.4)

/// `OJointValue` (16 bytes).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct JointValue {
    pub value: i32,
    pub signal: u16,
    pub pwm_duty: i16,
    pub ref_value: i32,
    pub ref_signal: u16,
}

/// `OSensorValue` / `OSwitchStatus` (16 bytes).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct SensorValue {
    pub value: i32,
    pub signal: u16,
}

impl JointValue {
    pub fn to_bytes(&self) -> [u8; 16] {
        let mut b = [0u8; 16];
        b[0..4].copy_from_slice(&self.value.to_le_bytes());
        b[4..6].copy_from_slice(&self.signal.to_le_bytes());
        b[6..8].copy_from_slice(&self.pwm_duty.to_le_bytes());
        b[8..12].copy_from_slice(&self.ref_value.to_le_bytes());
        b[12..14].copy_from_slice(&self.ref_signal.to_le_bytes());
        b
    }
    pub fn from_bytes(b: &[u8; 16]) -> JointValue {
        JointValue {
            value: i32::from_le_bytes([b[0], b[1], b[2], b[3]]),
            signal: u16::from_le_bytes([b[4], b[5]]),
            pwm_duty: i16::from_le_bytes([b[6], b[7]]),
            ref_value: i32::from_le_bytes([b[8], b[9], b[10], b[11]]),
            ref_signal: u16::from_le_bytes([b[12], b[13]]),
        }
    }
}

impl SensorValue {
    pub fn to_bytes(&self) -> [u8; 16] {
        let mut b = [0u8; 16];
        b[0..4].copy_from_slice(&self.value.to_le_bytes());
        b[4..6].copy_from_slice(&self.signal.to_le_bytes());
        b
    }
    pub fn from_bytes(b: &[u8; 16]) -> SensorValue {
        SensorValue { value: i32::from_le_bytes([b[0], b[1], b[2], b[3]]), signal: u16::from_le_bytes([b[4], b[5]]) }
    }
}

/// One 16-byte frame of a sensor entry.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FrameValue {
    Joint(JointValue),
    Sensor(SensorValue),
}

impl FrameValue {
    pub fn to_bytes(&self) -> [u8; 16] {
        match self {
            FrameValue::Joint(j) => j.to_bytes(),
            FrameValue::Sensor(s) => s.to_bytes(),
        }
    }
}

/// One entry (primitive) of a sensor vector with its 4 frames, oldest first.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SensorEntry {
    /// `OSensorFrameInfo.type` (e.g. odataJOINT_VALUE 18).
    pub data_type: u32,
    pub primitive: PrimitiveId,
    pub frames: [FrameValue; SENSOR_FRAMES],
}

/// Bytes of an `n`-entry sensor vector before page rounding: 192 + 288·n.
pub fn sensor_vector_size(n: usize) -> usize {
    HEADER_SIZE + (SENSOR_INFO_SIZE + SENSOR_DATA_SIZE) * n
}

/// Offset of entry `i`'s data block in an `n`-entry vector.
pub fn sensor_data_offset(n: usize, i: usize) -> usize {
    HEADER_SIZE + SENSOR_INFO_SIZE * n + SENSOR_DATA_SIZE * i
}

/// Writes the contents `NewSensorFrameVectorData(n)` produces (robot-api 6.4): header
/// type 1025, numData 0, infos type 0 / IDs and frame numbers 0xFFFFFFFF / numFrames 0 /
/// frameSize 16 / dataSize 256; data zeroed.
pub fn sensor_vector_init(buf: &mut [u8], n: usize) -> Result<()> {
    let size = sensor_vector_size(n);
    if buf.len() < size {
        return Err(VectorError::TooShort { need: size, have: buf.len() });
    }
    init_header(buf, odata::SENSOR_FRAME_VECTOR, SENSOR_INFO_SIZE, n)?;
    for i in 0..n {
        let o = HEADER_SIZE + SENSOR_INFO_SIZE * i;
        let vals = [0, 0xFFFF_FFFF, FRAME_INVALID, 0, SENSOR_VALUE_SIZE as u32, sensor_data_offset(n, i) as u32, SENSOR_DATA_SIZE as u32, 0];
        for (k, v) in vals.into_iter().enumerate() {
            wr_u32(buf, o + 4 * k, v)?;
        }
    }
    buf[HEADER_SIZE + SENSOR_INFO_SIZE * n..size].fill(0);
    Ok(())
}

/// Fills a sensor vector: allocator layout for `entries.len()` entries, `numData` =
/// entry count, each info's type/ID/`frameNumber = first_frame`/`numFrames = 4`, the 4
/// frames, and optionally the command vector's `optional` bytes at `(optOffset, bytes)`.
pub fn write_sensor_vector(buf: &mut [u8], first_frame: u32, entries: &[SensorEntry], optional: Option<(u32, &[u8])>) -> Result<()> {
    let n = entries.len();
    sensor_vector_init(buf, n)?;
    wr_u32(buf, 32, n as u32)?;
    if let Some((off, bytes)) = optional {
        if off as usize + bytes.len() > OPTIONAL_MAX {
            return Err(VectorError::BadOptional { offset: off, size: bytes.len() as u32 });
        }
        wr_u32(buf, 44, off)?;
        wr_u32(buf, 48, bytes.len() as u32)?;
        let at = 64 + off as usize;
        buf[at..at + bytes.len()].copy_from_slice(bytes);
    }
    for (i, e) in entries.iter().enumerate() {
        let o = HEADER_SIZE + SENSOR_INFO_SIZE * i;
        wr_u32(buf, o, e.data_type)?;
        wr_u32(buf, o + 4, e.primitive)?;
        wr_u32(buf, o + 8, first_frame)?;
        wr_u32(buf, o + 12, SENSOR_FRAMES as u32)?;
        let d = sensor_data_offset(n, i);
        for (k, f) in e.frames.iter().enumerate() {
            let at = d + SENSOR_VALUE_SIZE * k;
            buf[at..at + SENSOR_VALUE_SIZE].copy_from_slice(&f.to_bytes());
        }
    }
    Ok(())
}

/// [`write_sensor_vector`] into a new buffer of exactly [`sensor_vector_size`] bytes.
pub fn build_sensor_vector(first_frame: u32, entries: &[SensorEntry], optional: Option<(u32, &[u8])>) -> Result<Vec<u8>> {
    let mut v = vec![0u8; sensor_vector_size(entries.len())];
    write_sensor_vector(&mut v, first_frame, entries, optional)?;
    Ok(v)
}

/// A sensor entry read back from a vector.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SensorEntryView {
    pub data_type: u32,
    pub primitive: PrimitiveId,
    pub frame_number: u32,
    pub frames: Vec<[u8; 16]>,
}

/// Reads entry `i` of a sensor vector (validating bounds).
pub fn read_sensor_entry(buf: &[u8], i: usize) -> Result<SensorEntryView> {
    let h = VectorHeader::read(buf)?;
    if h.vector_type != odata::SENSOR_FRAME_VECTOR {
        return Err(VectorError::WrongType { expected: odata::SENSOR_FRAME_VECTOR, found: h.vector_type });
    }
    if i >= h.num_data as usize {
        return Err(VectorError::BadArgument("entry index >= numData"));
    }
    let o = HEADER_SIZE + SENSOR_INFO_SIZE * i;
    let num_frames = rd_u32(buf, o + 12)?.min(16) as usize;
    let data = rd_u32(buf, o + 20)? as usize;
    need(buf, data.saturating_add(SENSOR_VALUE_SIZE * num_frames))?;
    let frames = (0..num_frames)
        .map(|k| {
            let mut f = [0u8; 16];
            f.copy_from_slice(&buf[data + 16 * k..data + 16 * k + 16]);
            f
        })
        .collect();
    Ok(SensorEntryView { data_type: rd_u32(buf, o)?, primitive: rd_u32(buf, o + 4)?, frame_number: rd_u32(buf, o + 8)?, frames })
}

// ---------------------------------------------------------------------------------
// sound vectors (6.5)

/// Bytes `NewSoundVectorData(n, data_size)` needs before page rounding.
pub fn sound_vector_size(n: usize, data_size: usize) -> usize {
    HEADER_SIZE + (round32(data_size) + SOUND_INFO_SIZE) * n
}

/// Writes the exact initial contents of `NewSoundVectorData(n, data_size)` (robot-api
/// 6.5) for robot design `design` ("ERS-2…" → 8000 Hz/8 bit, otherwise 16000/16).
pub fn sound_vector_init(buf: &mut [u8], n: usize, data_size: usize, design: &str) -> Result<()> {
    let size = sound_vector_size(n, data_size);
    if buf.len() < size {
        return Err(VectorError::TooShort { need: size, have: buf.len() });
    }
    let ds = u32::try_from(data_size).map_err(|_| VectorError::BadArgument("sound data size too large"))?;
    init_header(buf, odata::SOUND_VECTOR, SOUND_INFO_SIZE, n)?;
    let slot = round32(data_size);
    let (rate, bits) = if design.starts_with("ERS-2") { (8000u16, 8u16) } else { (16000, 16) };
    for i in 0..n {
        let o = HEADER_SIZE + SOUND_INFO_SIZE * i;
        buf[o..o + SOUND_INFO_SIZE].fill(0);
        wr_u32(buf, o, odata::SOUND)?;
        wr_u32(buf, o + 4, 0xFFFF_FFFF)?;
        wr_u32(buf, o + 8, FRAME_INVALID)?;
        wr_u32(buf, o + 12, slot as u32)?;
        wr_u32(buf, o + 16, (HEADER_SIZE + SOUND_INFO_SIZE * n + slot * i) as u32)?;
        wr_u32(buf, o + 20, ds)?;
        wr_u32(buf, o + 24, ds)?;
        wr_u16(buf, o + 28, 1)?; // osoundformatPCM
        wr_u16(buf, o + 30, 1)?; // osoundchannelMONO
        wr_u16(buf, o + 32, rate)?;
        wr_u16(buf, o + 34, bits)?;
    }
    buf[HEADER_SIZE + SOUND_INFO_SIZE * n..size].fill(0);
    Ok(())
}

/// One valid slot of a sound vector.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SoundSlot {
    pub index: usize,
    pub data_type: u32,
    pub primitive: PrimitiveId,
    pub data_offset: u32,
    pub data_size: u32,
    pub format: u16,
    pub channel: u16,
    pub sampling_rate: u16,
    pub bits_per_sample: u16,
}

/// A parsed `OSoundVectorData` (PCM bytes stay in the buffer: `data_offset..+data_size`).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SoundVector {
    pub header: VectorHeader,
    pub slots: Vec<SoundSlot>,
}

/// Parses a sound vector, checking that every slot's PCM data lies inside `buf`.
pub fn parse_sound_vector(buf: &[u8]) -> Result<SoundVector> {
    let header = VectorHeader::read(buf)?;
    if header.vector_type != odata::SOUND_VECTOR {
        return Err(VectorError::WrongType { expected: odata::SOUND_VECTOR, found: header.vector_type });
    }
    if header.num_data > header.max_num_data {
        return Err(VectorError::TooManyData { num_data: header.num_data, max_num_data: header.max_num_data });
    }
    header.optional(buf)?;
    let n = header.num_data as usize;
    need(buf, HEADER_SIZE + SOUND_INFO_SIZE * n)?;
    let mut slots = Vec::with_capacity(n);
    for i in 0..n {
        let o = HEADER_SIZE + SOUND_INFO_SIZE * i;
        let data_offset = rd_u32(buf, o + 16)?;
        let data_size = rd_u32(buf, o + 24)?;
        if data_offset as u64 + data_size as u64 > buf.len() as u64 {
            return Err(VectorError::SlotOutOfBounds { slot: i, offset: data_offset as u64, len: data_size as u64 });
        }
        slots.push(SoundSlot {
            index: i,
            data_type: rd_u32(buf, o)?,
            primitive: rd_u32(buf, o + 4)?,
            data_offset,
            data_size,
            format: rd_u16(buf, o + 28)?,
            channel: rd_u16(buf, o + 30)?,
            sampling_rate: rd_u16(buf, o + 32)?,
            bits_per_sample: rd_u16(buf, o + 34)?,
        });
    }
    Ok(SoundVector { header, slots })
}

/// Writes `OSoundInfo[slot].frameNumber` (the speaker does this when it starts a slot).
pub fn write_sound_frame_number(buf: &mut [u8], slot: usize, frame: u32) -> Result<()> {
    wr_u32(buf, HEADER_SIZE + SOUND_INFO_SIZE * slot + 8, frame)
}

/// Builds one microphone vector (robot-api 8.6): 1 slot, PCM, 2 channels, 16 kHz,
/// 16 bits; `dataSize` = `actualDataSize` = `pcm.len()`, `frameNumber` = capture frame.
pub fn build_mic_vector(mic: PrimitiveId, frame: u32, pcm: &[u8]) -> Result<Vec<u8>> {
    let mut buf = vec![0u8; sound_vector_size(1, pcm.len())];
    sound_vector_init(&mut buf, 1, pcm.len(), "ERS-7")?;
    let o = HEADER_SIZE;
    wr_u32(&mut buf, 32, 1)?;
    wr_u32(&mut buf, o + 4, mic)?;
    wr_u32(&mut buf, o + 8, frame)?;
    wr_u16(&mut buf, o + 30, 2)?;
    wr_u32(&mut buf, o + 36, pcm.len() as u32)?;
    let d = HEADER_SIZE + SOUND_INFO_SIZE;
    buf[d..d + pcm.len()].copy_from_slice(pcm);
    Ok(buf)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn u32at(b: &[u8], o: usize) -> u32 {
        rd_u32(b, o).unwrap()
    }

    #[test]
    fn command_vector_init_n3_exact() {
        let n = 3;
        assert_eq!(command_vector_size(n), 672);
        assert_eq!(region_size(command_vector_size(n)), 4096);
        let mut b = vec![0xAAu8; 4096];
        command_vector_init(&mut b, n).unwrap();
        let hdr = [0, 0, 0, 4096, 1024, 192, 32, 3, 0, 0xFFFF_FFFF, 0, 0, 0];
        for (i, v) in hdr.iter().enumerate() {
            assert_eq!(u32at(&b, 4 * i), *v, "header field {i}");
        }
        assert!(b[52..192].iter().all(|&x| x == 0));
        for i in 0..3 {
            let o = 192 + 32 * i;
            assert_eq!(
                [u32at(&b, o), u32at(&b, o + 4), u32at(&b, o + 8), u32at(&b, o + 12), u32at(&b, o + 16), u32at(&b, o + 20), u32at(&b, o + 24)],
                [0, 0xFFFF_FFFF, 0xFFFF_FFFF, 0, 8, (288 + 128 * i) as u32, 128]
            );
        }
        // data blocks: 288, 416, 544; end 672
        assert_eq!(u32at(&b, 192 + 20), 192 + 32 * 3);
        assert!(b[288..672].iter().all(|&x| x == 0));
        assert!(command_vector_init(&mut b[..671], 3).is_err());
    }

    #[test]
    fn parse_joint_led_ear_slots() {
        let mut b = vec![0u8; command_vector_size(4)];
        command_vector_init(&mut b, 4).unwrap();
        let j: Vec<[u8; 8]> = (0..16).map(|k| joint2_frame(k * 1000)).collect();
        command_vector_push(&mut b, odata::JOINT_COMMAND2, 0x101, &j).unwrap();
        command_vector_push(&mut b, odata::LED_COMMAND2, 0x10a, &[held_frame(1, 64), held_frame(0, 64)]).unwrap();
        command_vector_push(&mut b, odata::LED_COMMAND3, 0x110, &[led3_frame(255, 1, 0)]).unwrap();
        command_vector_push(&mut b, odata::JOINT_COMMAND4, 0x104, &[held_frame(1, 16), held_frame(0, 240)]).unwrap();
        let v = parse_command_vector(&b).unwrap();
        assert_eq!(v.slots.len(), 4);
        assert_eq!(v.slots[0].values.duration_frames(), 16);
        assert_eq!(v.slots[0].values.at(15), Some(FrameCommand::Joint(15000)));
        assert_eq!(v.slots[0].values.at(16), None);
        assert_eq!(v.slots[1].values.duration_frames(), 128);
        assert_eq!(v.slots[1].values.at(63), Some(FrameCommand::Led2(true)));
        assert_eq!(v.slots[1].values.at(64), Some(FrameCommand::Led2(false)));
        // period 0 counts as 1
        assert_eq!(v.slots[2].values.duration_frames(), 1);
        assert_eq!(v.slots[2].values.at(0), Some(FrameCommand::Led3(Led3Value { intensity: 255, mode: 1 })));
        assert_eq!(v.slots[3].values.duration_frames(), 256);
        assert_eq!(v.duration_frames(), 256);
        write_command_frame_number(&mut b, 2, 77).unwrap();
        assert_eq!(u32at(&b, 192 + 64 + 8), 77);
    }

    #[test]
    fn led_8_values_period_64_is_512_frames() {
        let vals = CommandValues::Led2((0..8).map(|k| Held { value: k % 2, period: 64 }).collect());
        assert_eq!(vals.duration_frames(), 512);
        assert_eq!(vals.duration_frames() as u64 * 8, 4096);
        let legacy = CommandValues::LegacyLed(vec![Held { value: 1, period: 4 }]);
        assert_eq!(legacy.duration_frames(), 64);
    }

    #[test]
    fn malformed_command_vectors_are_errors() {
        let mut b = vec![0u8; command_vector_size(2)];
        command_vector_init(&mut b, 2).unwrap();
        command_vector_push(&mut b, odata::JOINT_COMMAND2, 0x101, &[joint2_frame(1)]).unwrap();
        assert!(parse_command_vector(&b[..100]).is_err());
        let mut c = b.clone();
        wr_u32(&mut c, 16, 1025).unwrap();
        assert!(matches!(parse_command_vector(&c), Err(VectorError::WrongType { .. })));
        let mut c = b.clone();
        wr_u32(&mut c, 32, 3).unwrap();
        assert!(matches!(parse_command_vector(&c), Err(VectorError::TooManyData { .. })));
        let mut c = b.clone();
        wr_u32(&mut c, 192 + 12, 17).unwrap();
        assert!(matches!(parse_command_vector(&c), Err(VectorError::TooManyFrames { .. })));
        let mut c = b.clone();
        wr_u32(&mut c, 192 + 20, 0xFFFF_FFF0).unwrap();
        assert!(matches!(parse_command_vector(&c), Err(VectorError::SlotOutOfBounds { .. })));
        let mut c = b.clone();
        wr_u32(&mut c, 44, 100).unwrap();
        wr_u32(&mut c, 48, 29).unwrap();
        assert!(matches!(parse_command_vector(&c), Err(VectorError::BadOptional { .. })));
        // max_num_data huge but buffer short
        let mut c = b.clone();
        wr_u32(&mut c, 28, 0xFFFF_FFFF).unwrap();
        wr_u32(&mut c, 32, 0xFFFF_FFFF).unwrap();
        assert!(parse_command_vector(&c).is_err());
        // unknown type and numFrames 0 do not reject the vector
        let mut c = b.clone();
        wr_u32(&mut c, 192, 257).unwrap();
        let v = parse_command_vector(&c).unwrap();
        assert_eq!(v.slots[0].values, CommandValues::Unsupported(257));
        let mut c = b.clone();
        wr_u32(&mut c, 192 + 12, 0).unwrap();
        assert!(parse_command_vector(&c).unwrap().slots.is_empty());
        // fuzz-ish: every truncation is an error or ok, never a panic
        for len in 0..b.len() {
            let _ = parse_command_vector(&b[..len]);
        }
    }

    #[test]
    fn sensor_vector_layout() {
        assert_eq!(sensor_vector_size(34), 192 + 288 * 34);
        assert_eq!(sensor_data_offset(34, 0), 192 + 32 * 34);
        assert_eq!(sensor_data_offset(34, 33), 192 + 32 * 34 + 256 * 33);
        let jv = JointValue { value: -1, signal: 512, pwm_duty: -20, ref_value: 123456, ref_signal: 600 };
        let sv = SensorValue { value: 9_806_650, signal: 7 };
        let entries = vec![
            SensorEntry { data_type: 18, primitive: 0x100, frames: [FrameValue::Joint(jv); 4] },
            SensorEntry { data_type: 9, primitive: 0x101, frames: [FrameValue::Sensor(sv); 4] },
        ];
        let b = build_sensor_vector(5, &entries, Some((2, &[9, 8, 7]))).unwrap();
        assert_eq!(b.len(), 192 + 288 * 2);
        assert_eq!(u32at(&b, 16), 1025);
        assert_eq!(u32at(&b, 20), 192);
        assert_eq!(u32at(&b, 24), 32);
        assert_eq!(u32at(&b, 28), 2);
        assert_eq!(u32at(&b, 32), 2);
        assert_eq!(u32at(&b, 36), 0xFFFF_FFFF);
        assert_eq!((u32at(&b, 44), u32at(&b, 48)), (2, 3));
        assert_eq!(&b[66..69], &[9, 8, 7]);
        let i1 = 192 + 32;
        assert_eq!(
            [u32at(&b, i1), u32at(&b, i1 + 4), u32at(&b, i1 + 8), u32at(&b, i1 + 12), u32at(&b, i1 + 16), u32at(&b, i1 + 20), u32at(&b, i1 + 24)],
            [9, 0x101, 5, 4, 16, (192 + 64 + 256) as u32, 256]
        );
        let e0 = read_sensor_entry(&b, 0).unwrap();
        assert_eq!(e0.frames.len(), 4);
        assert_eq!(JointValue::from_bytes(&e0.frames[3]), jv);
        // OJointValue byte offsets: value 0, signal 4, pwmDuty 6, refValue 8, refSignal 12
        let d0 = 192 + 64;
        assert_eq!(&b[d0 + 4..d0 + 6], &512u16.to_le_bytes());
        assert_eq!(&b[d0 + 6..d0 + 8], &(-20i16).to_le_bytes());
        assert_eq!(&b[d0 + 8..d0 + 12], &123456i32.to_le_bytes());
        assert_eq!(SensorValue::from_bytes(&read_sensor_entry(&b, 1).unwrap().frames[0]), sv);
        assert!(read_sensor_entry(&b, 2).is_err());
        let mut fresh = vec![1u8; sensor_vector_size(34)];
        sensor_vector_init(&mut fresh, 34).unwrap();
        assert_eq!(u32at(&fresh, 32), 0);
        assert_eq!(u32at(&fresh, 192 + 4), 0xFFFF_FFFF);
        assert_eq!(u32at(&fresh, 192 + 16), 16);
    }

    #[test]
    fn sound_vector_init_exact() {
        // 2 slots of 1000 bytes: slot 1024
        let size = sound_vector_size(2, 1000);
        assert_eq!(size, 192 + (1024 + 64) * 2);
        let mut b = vec![0xFFu8; region_size(size)];
        sound_vector_init(&mut b, 2, 1000, "ERS-7").unwrap();
        assert_eq!(u32at(&b, 16), 1026);
        assert_eq!(u32at(&b, 24), 64);
        assert_eq!(u32at(&b, 28), 2);
        assert_eq!(u32at(&b, 32), 0);
        let o = 192 + 64;
        assert_eq!(u32at(&b, o), 16);
        assert_eq!(u32at(&b, o + 4), 0xFFFF_FFFF);
        assert_eq!(u32at(&b, o + 12), 1024);
        assert_eq!(u32at(&b, o + 16), 192 + 128 + 1024);
        assert_eq!(u32at(&b, o + 20), 1000);
        assert_eq!(u32at(&b, o + 24), 1000);
        assert_eq!(rd_u16(&b, o + 28).unwrap(), 1);
        assert_eq!(rd_u16(&b, o + 30).unwrap(), 1);
        assert_eq!(rd_u16(&b, o + 32).unwrap(), 16000);
        assert_eq!(rd_u16(&b, o + 34).unwrap(), 16);
        assert_eq!(u32at(&b, o + 36), 0);
        sound_vector_init(&mut b, 2, 1000, "ERS-210").unwrap();
        assert_eq!(rd_u16(&b, o + 32).unwrap(), 8000);
        wr_u32(&mut b, 32, 1).unwrap();
        let v = parse_sound_vector(&b).unwrap();
        assert_eq!(v.slots.len(), 1);
        assert_eq!(v.slots[0].data_offset, 320);
        write_sound_frame_number(&mut b, 0, 9).unwrap();
        assert_eq!(u32at(&b, 192 + 8), 9);
        let mic = build_mic_vector(0x123, 42, &[1u8; 1024]).unwrap();
        let m = parse_sound_vector(&mic).unwrap();
        assert_eq!((m.slots[0].channel, m.slots[0].sampling_rate, m.slots[0].data_size), (2, 16000, 1024));
        assert_eq!(u32at(&mic, 192 + 8), 42);
        assert_eq!(u32at(&mic, 192 + 36), 1024);
    }
}
