//! `cargo openr run --record DIR`: writes what the view shows into DIR, in the format
//! of docs/recording.md. The runtime writes the trace (`trace.jsonl`, the `--trace`
//! format); this observer writes the manifest, what the view shows beyond the trace
//! (joint targets, every sensor, the battery: `view.jsonl`, one line per sensor frame),
//! the camera pictures and the speaker's sound on the virtual timeline. Pictures and sound are handed to a writer thread, so
//! the frame thread only copies them; their content and order come from the frames, so
//! a run at `--speed max` writes the same bytes every time.
use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::mpsc::{channel, Sender};
use std::sync::Mutex;
use std::thread::JoinHandle;

use sdk_runtime::audio::{Format, WavWriter};
use sdk_runtime::error::{ErrorKind, Result};
use sdk_runtime::observe::{Frame, Observer};
use sdk_runtime::runtime::Runtime;

/// The manifest's name and the `format` it carries.
pub const MANIFEST: &str = "recording.json";
pub const FORMAT: &str = "cargo-openr recording";
pub const VERSION: u64 = 1;
pub const TRACE: &str = "trace.jsonl";
pub const CAMERA_INDEX: &str = "camera.jsonl";
pub const SPEAKER: &str = "speaker.wav";
pub const VIEW: &str = "view.jsonl";
/// A world recording's (`--sim mujoco --record DIR`) ground truth and field.
pub const TRUTH: &str = "world.jsonl";
pub const FIELD: &str = "field.json";
/// The field camera's pictures (`peer.py --field-pictures`) and their index.
pub const FIELD_CAMERA: &str = "field";
pub const FIELD_CAMERA_INDEX: &str = "field/index.jsonl";

/// `--sim mujoco --record DIR`: DIR's manifest naming robot k's recording `robotK/`
/// (each written by its own runtime) and the simulator's files; returns the robots'
/// directories and the paths of the ground truth, the field and the field camera's
/// pictures for the simulator.
pub fn create_world(dir: &Path, robots: usize) -> std::result::Result<(Vec<PathBuf>, [PathBuf; 3]), String> {
    std::fs::create_dir_all(dir).map_err(|e| format!("--record {}: cannot create the directory: {e}", dir.display()))?;
    let names: Vec<String> = (0..robots).map(|k| format!("robot{k}")).collect();
    let manifest = serde_json::json!({
        "format": FORMAT, "version": VERSION, "frame_ms": 8, "robots": names, "world": { "truth": TRUTH, "field": FIELD, "field_camera": FIELD_CAMERA_INDEX },
    });
    let path = dir.join(MANIFEST);
    std::fs::write(&path, format!("{}\n", serde_json::to_string_pretty(&manifest).expect("json"))).map_err(|e| format!("--record: {}: {e}", path.display()))?;
    Ok((names.iter().map(|n| dir.join(n)).collect(), [dir.join(TRUTH), dir.join(FIELD), dir.join(FIELD_CAMERA)]))
}

enum Item {
    Picture { t_ms: u64, frame: u32, width: u32, height: u32, rgb: Vec<u8> },
    Sound { t_ms: u64, format: Format, pcm: Vec<u8> },
    View(serde_json::Value),
}

/// The recorder of one run.
pub struct Recorder {
    dir: PathBuf,
    tx: Mutex<Option<Sender<Item>>>,
    writer: Mutex<Option<JoinHandle<()>>>,
}

impl Recorder {
    /// Makes DIR (it may exist; the recording's files in it are replaced). The trace
    /// goes to [`Recorder::trace_path`].
    pub fn create(dir: &Path) -> std::result::Result<Recorder, String> {
        std::fs::create_dir_all(dir.join("camera")).map_err(|e| format!("--record {}: cannot create the directory: {e}", dir.display()))?;
        for stale in [CAMERA_INDEX, SPEAKER, MANIFEST, VIEW] {
            let _ = std::fs::remove_file(dir.join(stale));
        }
        Ok(Recorder { dir: dir.to_path_buf(), tx: Mutex::new(None), writer: Mutex::new(None) })
    }

    pub fn trace_path(&self) -> PathBuf {
        self.dir.join(TRACE)
    }
}

fn io_err(path: &Path, e: std::io::Error) -> sdk_runtime::Error {
    ErrorKind::Runtime(format!("--record: {}: {e}", path.display())).into()
}

impl Observer for Recorder {
    fn attach(&self, rt: &'static Runtime) -> Result<()> {
        let design = rt.vr.robot().model().design().name();
        let manifest = serde_json::json!({
            "format": FORMAT, "version": VERSION, "design": design, "frame_ms": 8,
            "trace": TRACE, "view": VIEW, "camera": CAMERA_INDEX, "speaker": SPEAKER,
        });
        let path = self.dir.join(MANIFEST);
        std::fs::write(&path, format!("{}\n", serde_json::to_string_pretty(&manifest).expect("json"))).map_err(|e| io_err(&path, e))?;
        let index_path = self.dir.join(CAMERA_INDEX);
        let index = std::fs::File::create(&index_path).map_err(|e| io_err(&index_path, e))?;
        let view_path = self.dir.join(VIEW);
        let view = std::fs::File::create(&view_path).map_err(|e| io_err(&view_path, e))?;
        let (tx, rx) = channel::<Item>();
        let dir = self.dir.clone();
        let writer = std::thread::Builder::new()
            .name("openr-record".into())
            .spawn(move || {
                let mut w =
                    Writer { dir, index: std::io::BufWriter::new(index), view: Some(std::io::BufWriter::new(view)), pictures: 0, wav: None, samples: 0 };
                for item in rx {
                    if let Err(e) = w.write(item) {
                        eprintln!("warning: --record: {e}");
                    }
                }
                let _ = w.index.flush();
                if let Some(v) = w.view.as_mut() {
                    let _ = v.flush();
                }
            })
            .map_err(|e| ErrorKind::Runtime(format!("cannot start the recorder: {e}")))?;
        *self.tx.lock().unwrap_or_else(|p| p.into_inner()) = Some(tx);
        *self.writer.lock().unwrap_or_else(|p| p.into_inner()) = Some(writer);
        Ok(())
    }

    fn frame(&self, rt: &Runtime, f: &Frame<'_>) {
        let tx = self.tx.lock().unwrap_or_else(|p| p.into_inner());
        let Some(tx) = tx.as_ref() else { return };
        for (format, pcm) in f.sounds {
            let _ = tx.send(Item::Sound { t_ms: f.t_ms, format: *format, pcm: pcm.clone() });
        }
        if f.sensor {
            let _ = tx.send(Item::View(view_record(rt, f)));
        }
        if f.picture {
            let robot = rt.vr.robot();
            let img = robot.camera_rgb();
            let _ = tx.send(Item::Picture { t_ms: f.t_ms, frame: f.frame, width: img.width as u32, height: img.height as u32, rgb: img.data.clone() });
        }
    }

    fn finish(&self) {
        drop(self.tx.lock().unwrap_or_else(|p| p.into_inner()).take());
        if let Some(w) = self.writer.lock().unwrap_or_else(|p| p.into_inner()).take() {
            let _ = w.join();
        }
    }
}

/// What the page shows that the trace lacks, at a sensor frame: the joints' targets,
/// every sensor, the battery, the objects and their connections' message counts (the
/// live snapshot's values).
fn view_record(rt: &Runtime, f: &Frame<'_>) -> serde_json::Value {
    let s = crate::snapshot::take(rt);
    let targets: serde_json::Map<String, serde_json::Value> =
        s["joints"].as_array().into_iter().flatten().map(|j| (j["locator"].as_str().unwrap_or("").to_string(), j["target_deg"].clone())).collect();
    serde_json::json!({ "t_ms": f.t_ms, "frame": f.frame, "targets": targets, "sensors": s["sensors"], "battery": s["battery"], "objects": s["objects"], "connections": s["connections"] })
}

struct Writer {
    dir: PathBuf,
    index: std::io::BufWriter<std::fs::File>,
    view: Option<std::io::BufWriter<std::fs::File>>,
    pictures: u64,
    wav: Option<WavWriter>,
    /// Sample frames written to the WAV so far.
    samples: u64,
}

impl Writer {
    fn write(&mut self, item: Item) -> std::result::Result<(), String> {
        match item {
            Item::Picture { t_ms, frame, width, height, rgb } => {
                self.pictures += 1;
                let file = format!("camera/{:06}.png", self.pictures);
                let png = encode_png(width, height, &rgb).map_err(|e| format!("cannot encode {file}: {e}"))?;
                let path = self.dir.join(&file);
                std::fs::write(&path, png).map_err(|e| format!("{}: {e}", path.display()))?;
                let line = serde_json::json!({ "n": self.pictures, "t_ms": t_ms, "frame": frame, "file": file, "width": width, "height": height });
                writeln!(self.index, "{line}").map_err(|e| format!("{CAMERA_INDEX}: {e}"))?;
                // Line by line: a run that is killed still leaves an index of whole lines.
                self.index.flush().map_err(|e| format!("{CAMERA_INDEX}: {e}"))
            }
            Item::Sound { t_ms, format, pcm } => self.sound(t_ms, format, &pcm),
            Item::View(v) => match self.view.as_mut() {
                Some(w) => writeln!(w, "{v}").map_err(|e| format!("{VIEW}: {e}")),
                None => Ok(()),
            },
        }
    }

    /// The sound that started in the frame ending at `t_ms` goes at `t_ms - 8` ms of
    /// the WAV (silence before it), so the file's time is virtual time.
    fn sound(&mut self, t_ms: u64, format: Format, pcm: &[u8]) -> std::result::Result<(), String> {
        if self.wav.is_none() {
            let path = self.dir.join(SPEAKER);
            self.wav = Some(WavWriter::create(&path, format).map_err(|e| e.to_string())?);
        }
        let wav = self.wav.as_mut().expect("created above");
        let kept = wav.format();
        let block = (kept.channels as u64 * (kept.bits as u64 / 8)).max(1);
        let silence = if kept.bits == 8 { 0x80u8 } else { 0 };
        let at = t_ms.saturating_sub(8) * kept.rate as u64 / 1000;
        if at > self.samples {
            wav.append(&vec![silence; ((at - self.samples) * block) as usize]).map_err(|e| e.to_string())?;
            self.samples = at;
        }
        // OPEN-R 8-bit PCM is signed, WAV's is offset binary.
        let converted: Vec<u8> = if format.bits == 8 { pcm.iter().map(|b| b ^ 0x80).collect() } else { pcm.to_vec() };
        wav.append(&converted).map_err(|e| e.to_string())?;
        self.samples += converted.len() as u64 / block;
        Ok(())
    }
}

/// RGB pixels as PNG (fast compression: the camera runs at 30 pictures a second).
pub(crate) fn encode_png(width: u32, height: u32, rgb: &[u8]) -> std::result::Result<Vec<u8>, png::EncodingError> {
    let mut out = Vec::new();
    let mut enc = png::Encoder::new(&mut out, width, height);
    enc.set_color(png::ColorType::Rgb);
    enc.set_depth(png::BitDepth::Eight);
    enc.set_compression(png::Compression::Fast);
    let mut writer = enc.write_header()?;
    writer.write_image_data(rgb)?;
    writer.finish()?;
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A fresh scratch directory (no tempfile dependency for two tests).
    fn scratch(name: &str) -> PathBuf {
        let d = std::env::temp_dir().join(format!("openr-view-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        std::fs::create_dir_all(&d).unwrap();
        d
    }

    fn writer(dir: &Path) -> Writer {
        let index = std::fs::File::create(dir.join(CAMERA_INDEX)).unwrap();
        Writer { dir: dir.to_path_buf(), index: std::io::BufWriter::new(index), view: None, pictures: 0, wav: None, samples: 0 }
    }

    /// Sounds land at their frame's start on the virtual timeline, silence between.
    #[test]
    fn sound_is_written_at_its_virtual_time() {
        let dir = scratch("sound16");
        let mut w = writer(&dir);
        let f16 = Format { rate: 16000, bits: 16, channels: 1 };
        // Frame 3 (t_ms 24) starts at 16 ms: 256 samples of silence, then 4 bytes.
        w.write(Item::Sound { t_ms: 24, format: f16, pcm: vec![1, 2, 3, 4] }).unwrap();
        // Frame 5 (t_ms 40) starts at 32 ms = sample 512; 2 samples were written after 256.
        w.write(Item::Sound { t_ms: 40, format: f16, pcm: vec![5, 6] }).unwrap();
        let wav = std::fs::read(dir.join(SPEAKER)).unwrap();
        let data = &wav[44..];
        assert_eq!(u32::from_le_bytes(wav[40..44].try_into().unwrap()) as usize, data.len(), "the header's data size");
        let mut want = vec![0u8; 512];
        want.extend([1, 2, 3, 4]);
        want.resize(1024, 0);
        want.extend([5, 6]);
        assert_eq!(data, &want[..]);
    }

    #[test]
    fn eight_bit_sound_is_offset_binary_with_offset_binary_silence() {
        let dir = scratch("sound8");
        let mut w = writer(&dir);
        w.write(Item::Sound { t_ms: 16, format: Format { rate: 8000, bits: 8, channels: 1 }, pcm: vec![0x00, 0x7f] }).unwrap();
        let wav = std::fs::read(dir.join(SPEAKER)).unwrap();
        let mut want = vec![0x80u8; 64];
        want.extend([0x80, 0xff]);
        assert_eq!(&wav[44..], &want[..]);
    }
}
