//! Sensor frame vectors (robot-api 6.4): the frames the virtual robot writes for objects,
//! and a reader of one entry (for tests and the trace).
use super::*;

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
