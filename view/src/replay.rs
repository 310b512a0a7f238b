//! `cargo openr view PATH`: a recording (`--record DIR`, docs/recording.md) or a bare
//! `--trace` file read back as the moments the page draws. Each moment is a snapshot
//! (the shape `/state` serves live) built from the trace: the joints of the newest
//! sensor record, the LEDs, ears, face mode and motor power as last set, the paw
//! switches and the accelerometer; one per virtual time at which the trace has records.
//! What the trace does not carry (joint targets, the other sensors, the battery) comes
//! from a recording's `view.jsonl` (the newest line at or before the moment); a bare
//! trace goes without.
use std::path::{Path, PathBuf};

use sdk_runtime::robot::model::Design;
use sdk_runtime::robot::VirtualRobot;
use serde_json::Value;

use crate::moments::{Builder, Lines, Moments};
use crate::record::{CAMERA_INDEX, FORMAT, MANIFEST, TRACE, VERSION};

/// What `cargo openr view PATH` serves: one robot's recording, or a simulated world's
/// (every robot's, and the simulator's ground truth).
pub struct Replay {
    pub source: PathBuf,
    pub robots: Vec<Recording>,
    pub world: Option<World>,
}

/// A world recording's field (`peer.py --field`) and ground truth, one line per frame
/// (`peer.py --state`) in time order.
pub struct World {
    pub field: Value,
    pub truth: Vec<Value>,
    /// The field camera's pictures (`peer.py --field-pictures`): (time_ms, file).
    pub pictures: Vec<(u64, PathBuf)>,
}

impl World {
    /// The newest ground truth at or before `t_ms`.
    pub fn at(&self, t_ms: u64) -> Option<&Value> {
        let k = self.truth.partition_point(|l| l["time_ms"].as_u64().unwrap_or(0) <= t_ms);
        self.truth.get(k.checked_sub(1)?)
    }
}

/// One robot's recording ready to serve.
pub struct Recording {
    /// What was opened (a directory or a trace file).
    pub source: PathBuf,
    pub design: &'static str,
    /// Its moments in time order, each built when the page first asks for it.
    pub moments: Moments,
    /// Camera picture n (1-based) is `pictures[n - 1]`, taken at `picture_times[n - 1]`.
    pub pictures: Vec<PathBuf>,
    pub picture_times: Vec<u64>,
    pub speaker: Option<PathBuf>,
}

type Res<T> = std::result::Result<T, String>;

/// Opens a recording directory (one robot's or a world's) or a `--trace` file; the
/// error names the file (and line).
pub fn open(path: &Path) -> Res<Replay> {
    let manifest = path.join(MANIFEST);
    let world = path.is_dir() && manifest.is_file() && read_manifest(&manifest)?["robots"].is_array();
    if !world {
        return Ok(Replay { source: path.into(), robots: vec![open_robot(path)?], world: None });
    }
    let m = read_manifest(&manifest)?;
    let mut robots = Vec::new();
    for (k, dir) in m["robots"].as_array().into_iter().flatten().enumerate() {
        let dir = dir.as_str().ok_or_else(|| format!("{}: robot {k} is not a directory name", manifest.display()))?;
        robots.push(open_robot(&path.join(dir))?);
    }
    if robots.is_empty() {
        return Err(format!("{}: a world of no robots", manifest.display()));
    }
    let file = |key: &str, default: &str| path.join(m["world"][key].as_str().unwrap_or(default));
    let field_path = file("field", crate::record::FIELD);
    let field = match std::fs::read_to_string(&field_path) {
        Ok(t) => serde_json::from_str(&t).map_err(|e| format!("{}:{}: not JSON: {e}", field_path.display(), e.line()))?,
        Err(e) => return Err(format!("{}: {}", field_path.display(), io_reason(&e))),
    };
    let truth = read_lines(&file("truth", crate::record::TRUTH), "time_ms", "ground-truth")?;
    let index = file("field_camera", crate::record::FIELD_CAMERA_INDEX);
    let mut pictures = Vec::new();
    for (i, p) in read_lines(&index, "time_ms", "field camera")?.into_iter().enumerate() {
        let at = format!("{}:{}", index.display(), i + 1);
        let name = p["file"].as_str().ok_or_else(|| format!("{at}: not a field camera record: it needs \"file\""))?;
        let png = index.parent().unwrap_or(path).join(name);
        if !png.is_file() {
            return Err(format!("{at}: the picture {} is missing", png.display()));
        }
        pictures.push((p["time_ms"].as_u64().unwrap_or(0), png));
    }
    Ok(Replay { source: path.into(), robots, world: Some(World { field, truth, pictures }) })
}

fn read_manifest(path: &Path) -> Res<Value> {
    let text = std::fs::read_to_string(path).map_err(|e| format!("{}: {}", path.display(), io_reason(&e)))?;
    let m: Value = serde_json::from_str(&text).map_err(|e| format!("{}:{}: not JSON: {e}", path.display(), e.line()))?;
    if m["format"] != FORMAT {
        return Err(format!("{}: not a recording manifest (its \"format\" is {}, not \"{FORMAT}\")", path.display(), m["format"]));
    }
    if m["version"].as_u64() != Some(VERSION) {
        return Err(format!("{}: recording version {} (this cargo-openr reads version {VERSION})", path.display(), m["version"]));
    }
    Ok(m)
}

/// One robot's recording directory, or a `--trace` file.
fn open_robot(path: &Path) -> Res<Recording> {
    let meta = std::fs::metadata(path).map_err(|e| format!("{}: {}", path.display(), io_reason(&e)))?;
    if !meta.is_dir() {
        let (design, moments) = read_trace(path, None, Vec::new(), Lines::default())?;
        return Ok(Recording { source: path.into(), design: design.name(), moments, pictures: Vec::new(), picture_times: Vec::new(), speaker: None });
    }
    let manifest_path = path.join(MANIFEST);
    if !manifest_path.is_file() {
        return Err(format!(
            "{}: not a recording (it has no {MANIFEST}): give a directory written by `cargo openr run MS --record DIR`, or a `--trace` file",
            path.display()
        ));
    }
    let m = read_manifest(&manifest_path)?;
    let design =
        m["design"].as_str().and_then(Design::from_name).ok_or_else(|| format!("{}: unknown robot design {}", manifest_path.display(), m["design"]))?;
    let file = |key: &str, default: &str| path.join(m[key].as_str().unwrap_or(default));
    let camera = read_camera_index(path, &file("camera", CAMERA_INDEX))?;
    let views = index_lines(&file("view", crate::record::VIEW), "t_ms", "view")?;
    let speaker = Some(file("speaker", crate::record::SPEAKER)).filter(|p| p.is_file());
    let times: Vec<u64> = camera.iter().map(|c| c.0).collect();
    let (_, moments) = read_trace(&file("trace", TRACE), Some(design), times.clone(), views)?;
    Ok(Recording { source: path.into(), design: design.name(), moments, pictures: camera.into_iter().map(|c| c.1).collect(), picture_times: times, speaker })
}

fn io_reason(e: &std::io::Error) -> String {
    match e.kind() {
        std::io::ErrorKind::NotFound => "no such file or directory".into(),
        _ => e.to_string(),
    }
}

/// A trace's moments, each record checked for the common fields (one pass), and the
/// design its joints belong to (`design` when the manifest names it).
fn read_trace(path: &Path, design: Option<Design>, pictures: Vec<u64>, views: Lines) -> Res<(Design, Moments)> {
    let text = std::fs::read_to_string(path).map_err(|e| format!("{}: {}", path.display(), io_reason(&e)))?;
    let mut moments = Builder::default();
    let mut first_sensor = None;
    let mut last_t = 0;
    let (mut at_byte, mut lines) = (0, text.split('\n').peekable());
    let mut i = 0;
    while let Some(line) = lines.next() {
        let range = at_byte..at_byte + line.len();
        at_byte = range.end + 1;
        i += 1;
        if line.trim().is_empty() {
            continue;
        }
        let at = format!("{}:{i}", path.display());
        let r: Value = serde_json::from_str(line).map_err(|e| {
            if lines.peek().is_none() && e.is_eof() {
                format!("{at}: the trace ends in the middle of a record (was the run killed while writing it?)")
            } else {
                format!("{at}: not a trace record: {e}")
            }
        })?;
        let (Some(t), Some(_), Some(kind)) = (r["t_ms"].as_u64(), r["frame"].as_u64(), r["kind"].as_str()) else {
            return Err(format!("{at}: not a trace record: it needs \"t_ms\", \"frame\" and \"kind\" (docs/recording.md)"));
        };
        if t < last_t {
            return Err(format!("{at}: time goes back ({t} ms after {last_t} ms): not one run's trace"));
        }
        last_t = t;
        if kind == "sensor" && first_sensor.is_none() {
            first_sensor = Some(r.clone());
        }
        moments.add(&r, range);
    }
    if moments.is_empty() {
        return Err(format!("{}: no trace records: nothing to replay", path.display()));
    }
    let design = match design {
        Some(d) => d,
        None => guess_design(first_sensor.as_ref()).ok_or_else(|| format!("{}: its joints belong to no robot design cargo-openr knows", path.display()))?,
    };
    Ok((design, moments.finish(design, text, pictures, views)))
}

/// The first design whose joints include every joint of the first sensor record.
fn guess_design(first_sensor: Option<&Value>) -> Option<Design> {
    let Some(joints) = first_sensor.and_then(|r| r["joints"].as_object()) else {
        return Some(Design::Ers7);
    };
    Design::ALL.into_iter().find(|d| {
        let robot = VirtualRobot::new(*d);
        let known: Vec<&str> = robot.model().primitives().iter().map(|p| p.locator).collect();
        joints.keys().all(|k| known.contains(&k.as_str()))
    })
}

/// `camera.jsonl`: (t_ms, picture file) per line, pictures numbered 1, 2, … in order.
fn read_camera_index(dir: &Path, index: &Path) -> Res<Vec<(u64, PathBuf)>> {
    let text = match std::fs::read_to_string(index) {
        Ok(t) => t,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(Vec::new()),
        Err(e) => return Err(format!("{}: {}", index.display(), io_reason(&e))),
    };
    let mut out = Vec::new();
    for (i, line) in text.lines().enumerate() {
        if line.trim().is_empty() {
            continue;
        }
        let at = format!("{}:{}", index.display(), i + 1);
        let c: Value = serde_json::from_str(line).map_err(|e| format!("{at}: not a camera record: {e}"))?;
        let (Some(n), Some(t), Some(file)) = (c["n"].as_u64(), c["t_ms"].as_u64(), c["file"].as_str()) else {
            return Err(format!("{at}: not a camera record: it needs \"n\", \"t_ms\" and \"file\""));
        };
        if n != out.len() as u64 + 1 {
            return Err(format!("{at}: picture {n} where picture {} was due", out.len() + 1));
        }
        let png = dir.join(file);
        if !png.is_file() {
            return Err(format!("{at}: the picture {} is missing", png.display()));
        }
        out.push((t, png));
    }
    Ok(out)
}

/// `view.jsonl` or a world's ground truth (absent: none): each line an object with
/// `key` (its virtual time), in time order.
fn read_lines(path: &Path, key: &str, what: &str) -> Res<Vec<Value>> {
    let mut out = Vec::new();
    each_line(path, key, what, |v, _, _| out.push(v))?;
    Ok(out)
}

/// The same, kept as text with each line's time and place (each line checked once).
fn index_lines(path: &Path, key: &str, what: &str) -> Res<Lines> {
    let mut at = Vec::new();
    let text = each_line(path, key, what, |_, t, range| at.push((t, range)))?;
    Ok(Lines::new(text, at))
}

/// Checks each line of `path` and hands it on, parsed, with its time and place; the
/// file's text (empty when the file is absent).
fn each_line(path: &Path, key: &str, what: &str, mut line_read: impl FnMut(Value, u64, std::ops::Range<usize>)) -> Res<String> {
    let text = match std::fs::read_to_string(path) {
        Ok(t) => t,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(String::new()),
        Err(e) => return Err(format!("{}: {}", path.display(), io_reason(&e))),
    };
    let (mut offset, mut last) = (0, None);
    for (i, line) in text.split('\n').enumerate() {
        let range = offset..offset + line.len();
        offset = range.end + 1;
        if line.trim().is_empty() {
            continue;
        }
        let here = format!("{}:{}", path.display(), i + 1);
        let v: Value = serde_json::from_str(line).map_err(|e| format!("{here}: not a {what} record: {e}"))?;
        let t = v[key].as_u64().ok_or_else(|| format!("{here}: not a {what} record: it needs \"{key}\""))?;
        if last.is_some_and(|l| l > t) {
            return Err(format!("{here}: time goes back ({t} ms)"));
        }
        last = Some(t);
        line_read(v, t, range);
    }
    Ok(text)
}
