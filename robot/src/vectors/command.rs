//! Command vectors (robot-api 6.3): the allocator's initial contents, and the typed frames a
//! C++ object wrote, read back slot by slot for the effectors.
use super::*;

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
        for (k, v) in [0, 0xFFFF_FFFF, FRAME_INVALID, 0, COMMAND_FRAME_SIZE as u32, data as u32, COMMAND_DATA_SIZE as u32, 0].into_iter().enumerate() {
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
        let held32 =
            |buf: &[u8]| -> Result<Vec<Held<u32>>> { frames.clone().map(|f| Ok(Held { value: rd_u32(buf, f)?, period: rd_u16(buf, f + 4)? })).collect() };
        let values = match data_type {
            odata::JOINT_COMMAND2 => CommandValues::Joint2(frames.clone().map(|f| rd_u32(buf, f).map(|v| v as i32)).collect::<Result<_>>()?),
            odata::JOINT_COMMAND3 => CommandValues::Joint3(frames.clone().map(|f| rd_u32(buf, f)).collect::<Result<_>>()?),
            odata::JOINT_COMMAND4 => CommandValues::Joint4(held32(buf)?),
            odata::LED_COMMAND2 => CommandValues::Led2(held32(buf)?),
            odata::LED_COMMAND => CommandValues::LegacyLed(held32(buf)?),
            odata::LED_COMMAND3 => CommandValues::Led3(
                frames
                    .clone()
                    .map(|f| Ok(Held { value: Led3Value { intensity: rd_u16(buf, f)? as i16, mode: rd_u16(buf, f + 2)? }, period: rd_u16(buf, f + 4)? }))
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
