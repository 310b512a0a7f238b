//! The virtual robot's speaker and microphones: what a program plays is what the
//! speaker WAV holds; a bad mic file is a clear error.
use std::fs;

use crate::support::{build, run_ms};

/// The data chunk of a WAV file.
pub(crate) fn wav_data(bytes: &[u8]) -> &[u8] {
    let mut o = 12;
    while o + 8 <= bytes.len() {
        let len = u32::from_le_bytes(bytes[o + 4..o + 8].try_into().unwrap()) as usize;
        if &bytes[o..o + 4] == b"data" {
            return &bytes[o + 8..(o + 8 + len).min(bytes.len())];
        }
        o += 8 + len + (len & 1);
    }
    panic!("no data chunk");
}

#[test]
fn the_speaker_wav_holds_exactly_the_pcm_the_program_played() {
    let p = build("soundplay");
    let dir = tempfile::tempdir().unwrap();
    let wav = dir.path().join("speaker.wav");
    let out = run_ms(&p.ms(), &["--speed", "max", "--for", "2s", "--speaker-wav", wav.to_str().unwrap()]);
    assert_eq!(out.code, Some(0), "{}", out.stderr);
    assert!(out.stdout.contains("SoundPlay : done, 16 buffers"), "{}", out.stdout);
    let played = fs::read(&wav).unwrap();
    let tone = fs::read(p.ms().join("OPEN-R/MW/DATA/P/TONE.WAV")).unwrap();
    let (played, tone) = (wav_data(&played), wav_data(&tone));
    assert_eq!(played.len(), 16 * 1024, "16 buffers of 32 ms at 16 kHz 16-bit");
    assert_eq!(&played[..tone.len()], tone, "the tone, sample for sample");
    assert!(played[tone.len()..].iter().all(|b| *b == 0), "the zero padding of the last buffer");
    // 32 ms per buffer: consecutive buffers start 4 frames apart.
    let frames: Vec<u32> = out.lines_starting("SoundPlay : buffer").iter().filter_map(|l| l.rsplit(' ').next()?.parse().ok()).collect();
    assert!(frames.len() >= 15 && frames.windows(2).all(|w| w[1] - w[0] == 4), "gapless 32 ms buffers: {frames:?}");
}

#[test]
fn a_missing_or_bad_mic_wav_is_a_clear_error() {
    let p = build("hello");
    let out = run_ms(&p.ms(), &["--for", "1s", "--mic-wav", "/nonexistent/mic.wav"]);
    assert_ne!(out.code, Some(0));
    assert!(!out.stderr.contains("panicked"), "{}", out.stderr);
    let want = format!("error: cannot run {}: /nonexistent/mic.wav: No such file or directory", p.ms().display());
    assert!(out.stderr.contains(&want), "the run fails naming the file and the OS reason:\n{}", out.stderr);
    assert!(!out.stdout.contains("Hello World"), "no object ran:\n{}", out.stdout);
    let dir = tempfile::tempdir().unwrap();
    let bad = dir.path().join("bad.wav");
    fs::write(&bad, b"RIFF\x04\x00\x00\x00WAVE").unwrap();
    let out = run_ms(&p.ms(), &["--for", "1s", "--mic-wav", bad.to_str().unwrap()]);
    assert_ne!(out.code, Some(0));
    assert!(out.stderr.contains("bad.wav: not a usable WAV file"), "{}", out.stderr);
}

/// The PCM of speaker-start: 8 buffers of 512 samples of a 500 Hz square wave (±8000).
fn square_wave() -> Vec<u8> {
    (0..8 * 512).flat_map(|i| (if (i / 16) % 2 == 0 { 8000i16 } else { -8000 }).to_le_bytes()).collect()
}

#[test]
fn the_speaker_is_ready_before_every_start_in_20_of_20_runs() {
    // speaker-start sends both buffers in DoStart: only a speaker that asserted ready at
    // its connection (robot-api 8.5) lets it play (object-model 2.8.1).
    let p = build("speaker-start");
    let dir = tempfile::tempdir().unwrap();
    let want = square_wave();
    let mut played = 0;
    let mut failures = Vec::new();
    for i in 0..20 {
        let wav = dir.path().join(format!("speaker{i}.wav"));
        let out = run_ms(&p.ms(), &["--speed", "max", "--for", "1s", "--speaker-wav", wav.to_str().unwrap()]);
        let data = fs::read(&wav).map(|b| wav_data(&b).to_vec()).unwrap_or_default();
        if out.code == Some(0)
            && out.stdout.contains("SpeakerStart : primed 2 buffers")
            && out.stdout.contains("SpeakerStart : done, 8 buffers")
            && data == want
        {
            played += 1;
        } else {
            failures.push(format!("run {i}: exit {:?}, {} bytes played\n{}{}", out.code, data.len(), out.stdout, out.stderr));
        }
    }
    assert_eq!(played, 20, "runs that played the whole tone; first failure:\n{}", failures.first().map_or("", |s| s));
}
