//! The speaker and the microphones of the virtual robot (robot-api 8.5, 8.6).
//!
//! Speaker: sound vectors queue up and play back to back, each for as long as its PCM
//! lasts (`dataSize / (rate × bytes × channels)`, rounded up to 8 ms frames); a vector
//! that has played is released and its subject made ready, as the effector does. What
//! plays is appended to a WAV file (`--speaker-wav`), silence while motor power (the
//! amplifier) is off. Mic: a block of 16 kHz stereo 16-bit samples every 16 ms
//! (ERS-7, 1024 bytes) or 32 ms (ERS-2xx, 2048 bytes), read from a WAV file (`--mic-wav`, converted to that format) or silence.
use std::collections::VecDeque;
use std::fs::File;
use std::io::{Seek, SeekFrom, Write};
use std::path::{Path, PathBuf};

use crate::error::{Error, Result};
use crate::robot::vectors;

/// The microphones' PCM: rate, channels, bits.
pub const MIC_FORMAT: (u32, u16, u16) = (16000, 2, 16);
/// Speaker tokens live apart from effector tokens.
const FIRST_SPEAKER_TOKEN: u64 = 1 << 40;

/// The PCM format of a WAV file.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Format {
    pub rate: u32,
    pub bits: u16,
    pub channels: u16,
}

/// A WAV file being written; the header's sizes are kept current after every block, so
/// an interrupted run still leaves a readable file.
pub struct WavWriter {
    file: File,
    path: PathBuf,
    format: Format,
    data_len: u32,
}

impl WavWriter {
    pub fn create(path: &Path, format: Format) -> Result<WavWriter> {
        let file = File::create(path).map_err(|e| Error::io(path, e))?;
        let mut w = WavWriter { file, path: path.to_path_buf(), format, data_len: 0 };
        w.write_header()?;
        Ok(w)
    }

    fn write_header(&mut self) -> Result<()> {
        let f = self.format;
        let block = f.channels as u32 * (f.bits as u32 / 8);
        let mut h = Vec::with_capacity(44);
        h.extend_from_slice(b"RIFF");
        h.extend_from_slice(&(36 + self.data_len).to_le_bytes());
        h.extend_from_slice(b"WAVEfmt ");
        h.extend_from_slice(&16u32.to_le_bytes());
        h.extend_from_slice(&1u16.to_le_bytes());
        h.extend_from_slice(&f.channels.to_le_bytes());
        h.extend_from_slice(&f.rate.to_le_bytes());
        h.extend_from_slice(&(f.rate * block).to_le_bytes());
        h.extend_from_slice(&(block as u16).to_le_bytes());
        h.extend_from_slice(&f.bits.to_le_bytes());
        h.extend_from_slice(b"data");
        h.extend_from_slice(&self.data_len.to_le_bytes());
        self.file.seek(SeekFrom::Start(0)).and_then(|_| self.file.write_all(&h)).map_err(|e| Error::io(&self.path, e))
    }

    /// The PCM format the file was created with.
    pub fn format(&self) -> Format {
        self.format
    }

    /// Appends PCM already in the file's format.
    pub fn append(&mut self, pcm: &[u8]) -> Result<()> {
        self.file.seek(SeekFrom::End(0)).and_then(|_| self.file.write_all(pcm)).map_err(|e| Error::io(&self.path, e))?;
        self.data_len += pcm.len() as u32;
        self.write_header()
    }
}

/// Reads a PCM WAV file and converts it to 16 kHz stereo 16-bit little-endian.
pub fn read_wav_as_mic(path: &Path) -> Result<Vec<u8>> {
    let bytes = std::fs::read(path).map_err(|e| Error::io(path, e))?;
    let bad = |m: &str| Error::config(path, None, format!("not a usable WAV file: {m}"));
    if bytes.len() < 12 || &bytes[0..4] != b"RIFF" || &bytes[8..12] != b"WAVE" {
        return Err(bad("no RIFF/WAVE header"));
    }
    let (mut fmt, mut data) = (None, None);
    let mut o = 12;
    while o + 8 <= bytes.len() {
        let id = &bytes[o..o + 4];
        let len = u32::from_le_bytes([bytes[o + 4], bytes[o + 5], bytes[o + 6], bytes[o + 7]]) as usize;
        let body = &bytes[o + 8..(o + 8 + len).min(bytes.len())];
        match id {
            b"fmt " if body.len() >= 16 => fmt = Some(body),
            b"data" => data = Some(body),
            _ => {}
        }
        o += 8 + len + (len & 1);
    }
    let (fmt, data) = (fmt.ok_or_else(|| bad("no fmt chunk"))?, data.ok_or_else(|| bad("no data chunk"))?);
    let u16at = |o: usize| u16::from_le_bytes([fmt[o], fmt[o + 1]]);
    let (tag, channels, bits) = (u16at(0), u16at(2), u16at(14));
    let rate = u32::from_le_bytes([fmt[4], fmt[5], fmt[6], fmt[7]]);
    if tag != 1 || !(1..=2).contains(&channels) || !(bits == 8 || bits == 16) || rate == 0 {
        return Err(bad(&format!("need PCM, 1-2 channels, 8 or 16 bits (found format {tag}, {channels} ch, {bits} bits, {rate} Hz)")));
    }
    let frame_bytes = channels as usize * bits as usize / 8;
    let frames = data.len() / frame_bytes;
    let sample = |f: usize, ch: usize| -> i16 {
        let o = f * frame_bytes + ch.min(channels as usize - 1) * (bits as usize / 8);
        if bits == 8 {
            ((data[o] as i16) - 128) << 8
        } else {
            i16::from_le_bytes([data[o], data[o + 1]])
        }
    };
    let out_frames = (frames as u64 * 16_000 / rate as u64) as usize;
    let mut out = Vec::with_capacity(out_frames * 4);
    for i in 0..out_frames {
        let f = ((i as u64 * rate as u64) / 16_000) as usize;
        for ch in 0..2 {
            out.extend_from_slice(&sample(f.min(frames.saturating_sub(1)), ch).to_le_bytes());
        }
    }
    Ok(out)
}

struct Playing {
    token: u64,
    base: usize,
    size: usize,
    frames_left: u32,
    started: bool,
    slots: Vec<vectors::SoundSlot>,
}

/// What the speaker finished in one frame.
pub struct SpeakerStep {
    pub done: Vec<u64>,
    /// The PCM of each sound slot that started in this frame (as in the vector: 8-bit
    /// signed or 16-bit little-endian), for external robot peers.
    pub started: Vec<(Format, Vec<u8>)>,
}

pub struct Speaker {
    queue: VecDeque<Playing>,
    wav: Option<WavWriter>,
    wav_path: Option<PathBuf>,
    next_token: u64,
    warned_format: bool,
}

impl Speaker {
    pub fn new(wav_path: Option<PathBuf>) -> Speaker {
        Speaker { queue: VecDeque::new(), wav: None, wav_path, next_token: FIRST_SPEAKER_TOKEN, warned_format: false }
    }

    /// Queues a sound vector; the region stays valid until its token is reported done.
    pub fn submit(&mut self, base: usize, size: usize) -> std::result::Result<u64, String> {
        // SAFETY: the system object keeps the region until we report it done.
        let bytes = unsafe { std::slice::from_raw_parts(base as *const u8, size) };
        let v = vectors::parse_sound_vector(bytes).map_err(|e| e.to_string())?;
        let mut ms = 0u64;
        for s in &v.slots {
            let bps = s.sampling_rate as u64 * (s.bits_per_sample as u64 / 8) * s.channel.max(1) as u64;
            if bps == 0 || s.format != 1 {
                return Err(format!("sound slot {}: unsupported format {} ({} Hz, {} bits)", s.index, s.format, s.sampling_rate, s.bits_per_sample));
            }
            ms += (s.data_size as u64 * 1000).div_ceil(bps);
        }
        let token = self.next_token;
        self.next_token += 1;
        let frames = (ms.div_ceil(8) as u32).max(1);
        self.queue.push_back(Playing { token, base, size, frames_left: frames, started: false, slots: v.slots });
        Ok(token)
    }

    /// Runs one 8 ms frame: starts the next vector if none plays (writing its
    /// `frameNumber` and its PCM), counts down the one playing.
    pub fn step(&mut self, frame: u32, amplifier_on: bool, warn: impl Fn(&str)) -> SpeakerStep {
        let mut done = Vec::new();
        let mut started = Vec::new();
        if let Some(p) = self.queue.front_mut() {
            if !p.started {
                p.started = true;
                // SAFETY: region alive until done.
                let bytes = unsafe { std::slice::from_raw_parts_mut(p.base as *mut u8, p.size) };
                let slots = p.slots.clone();
                for s in &slots {
                    let _ = vectors::write_sound_frame_number(bytes, s.index, frame);
                    let pcm = &bytes[s.data_offset as usize..(s.data_offset + s.data_size) as usize];
                    let format = Format { rate: s.sampling_rate as u32, bits: s.bits_per_sample, channels: s.channel.max(1) };
                    self.record(pcm, format, amplifier_on, &warn);
                    started.push((format, if amplifier_on { pcm.to_vec() } else { vec![0; pcm.len()] }));
                }
            }
            let p = self.queue.front_mut().expect("front exists");
            p.frames_left -= 1;
            if p.frames_left == 0 {
                done.push(p.token);
                self.queue.pop_front();
            }
        }
        SpeakerStep { done, started }
    }

    fn record(&mut self, pcm: &[u8], format: Format, amplifier_on: bool, warn: &impl Fn(&str)) {
        let Some(path) = &self.wav_path else { return };
        if self.wav.is_none() {
            match WavWriter::create(path, format) {
                Ok(w) => self.wav = Some(w),
                Err(e) => {
                    warn(&format!("speaker: {e}"));
                    self.wav_path = None;
                    return;
                }
            }
        }
        let w = self.wav.as_mut().expect("created above");
        if w.format != format && !self.warned_format {
            warn(&format!("speaker: format changed to {format:?}; the WAV keeps {:?}", w.format));
            self.warned_format = true;
        }
        // OPEN-R 8-bit PCM is signed, WAV's is offset binary.
        let converted: Vec<u8> = match (amplifier_on, format.bits) {
            (false, 8) => vec![0x80; pcm.len()],
            (false, _) => vec![0; pcm.len()],
            (true, 8) => pcm.iter().map(|b| b ^ 0x80).collect(),
            (true, _) => pcm.to_vec(),
        };
        if let Err(e) = w.append(&converted) {
            warn(&format!("speaker: {e}"));
        }
    }
}

/// The microphones: a stream of 16 kHz stereo 16-bit PCM, then silence.
pub struct Mic {
    pcm: Vec<u8>,
    pos: usize,
}

impl Mic {
    pub fn new(pcm: Vec<u8>) -> Mic {
        Mic { pcm, pos: 0 }
    }

    /// The next block of `len` bytes (the design's block, `Design::mic_block_bytes`).
    pub fn next_block(&mut self, len: usize) -> Vec<u8> {
        let mut block = vec![0u8; len];
        let n = self.pcm.len().saturating_sub(self.pos).min(len);
        block[..n].copy_from_slice(&self.pcm[self.pos..self.pos + n]);
        self.pos += n;
        block
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wav_round_trip_and_conversion_to_mic_format() {
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("a.wav");
        let mut w = WavWriter::create(&p, Format { rate: 8000, bits: 8, channels: 1 }).unwrap();
        w.append(&[128, 255, 0, 128]).unwrap();
        drop(w);
        let pcm = read_wav_as_mic(&p).unwrap();
        // 4 frames at 8 kHz = 8 frames at 16 kHz, stereo 16-bit.
        assert_eq!(pcm.len(), 8 * 4);
        let s = |i: usize| i16::from_le_bytes([pcm[i * 2], pcm[i * 2 + 1]]);
        assert_eq!((s(0), s(1), s(4), s(5), s(8)), (0, 0, 127 << 8, 127 << 8, -128 << 8));
        let mut mic = Mic::new(pcm);
        let b = mic.next_block(1024);
        assert_eq!(b.len(), 1024);
        assert!(b[32..].iter().all(|x| *x == 0), "then silence");
    }

    #[test]
    fn unusable_wav_files_are_refused_with_their_name() {
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("x.wav");
        std::fs::write(&p, b"not a wav").unwrap();
        let e = read_wav_as_mic(&p).unwrap_err().to_string();
        assert!(e.contains("x.wav: not a usable WAV file"), "{e}");
        let e = read_wav_as_mic(&dir.path().join("missing.wav")).unwrap_err().to_string();
        assert!(e.contains("missing.wav"), "{e}");
    }
}
