//! Sound vectors (robot-api 6.5): the speaker vectors objects fill, and the microphone
//! vectors the runtime builds.
use super::*;

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
