//! A recording served in pieces, so that a long one opens as fast as a short one: `GET
//! /` inlines the index (per robot: its moments' count, the virtual time each chunk of
//! [`CHUNK`] moments starts at, pictures, sound; a world's field) and only the chunks
//! holding the moments the URL asks for (`?robot=K&t=MS&back=N&step=N`); the page
//! fetches the others as it goes (`/robot/K/chunk?n=C`: the moments C × CHUNK … of robot
//! K, each with the world's ground truth at its time). `/robot/K/camera.png?n=N` is
//! picture N, `?t=MS` the newest one taken by then; `/robot/K/speaker.wav` the sound;
//! `/field.png?t=MS` a world's field camera's newest picture by then.
//! A one-robot recording answers the same without `/robot/K` (robot 0).
use crate::http::{Reply, Request};
use crate::replay::Replay;
use crate::server::{json as json_reply, not_found, page, script_json};
use serde_json::{json, Value};

/// Moments per chunk: about 2 s of a run (a moment every 32 ms sensor frame), ~0.3 MB.
pub const CHUNK: usize = 64;

pub(crate) fn param<T: std::str::FromStr>(query: &str, name: &str) -> Option<T> {
    query.split('&').find_map(|kv| kv.strip_prefix(name)?.strip_prefix('=')).and_then(|v| v.parse().ok())
}

/// Chunk `c` of robot `k`'s moments; in a world, each with `truth`.
fn chunk(rec: &Replay, k: usize, c: usize) -> Option<Value> {
    let part = rec.robots.get(k)?.moments.chunk(c)?;
    Some(Value::Array(
        part.iter()
            .map(|s| {
                let mut s = s.clone();
                if let Some(w) = &rec.world {
                    s["truth"] = w.at(s["t_ms"].as_u64().unwrap_or(0)).cloned().unwrap_or(Value::Null);
                }
                s
            })
            .collect(),
    ))
}

/// The page's inlined index, with the chunks of robot `k` around the moment `query` asks for.
fn index(rec: &Replay, k: usize, query: &str) -> Value {
    let robots: Vec<Value> = rec
        .robots
        .iter()
        .map(|r| {
            json!({
                "design": r.design, "count": r.moments.len(),
                "starts": (0..r.moments.len()).step_by(CHUNK).filter_map(|i| r.moments.t_ms(i)).collect::<Vec<_>>(),
                "end": r.moments.len().checked_sub(1).and_then(|i| r.moments.t_ms(i)),
                "pictures": r.pictures.len(), "speaker": r.speaker.is_some(),
            })
        })
        .collect();
    let moments = &rec.robots[k].moments;
    let at = param::<u64>(query, "t").map_or(0, |t| moments.count_to(t).saturating_sub(1));
    let (back, step) = (param::<usize>(query, "back").unwrap_or(0), param::<usize>(query, "step").unwrap_or(0));
    let (lo, hi) = (at.saturating_sub(back + 1) / CHUNK, (at + step + 1).min(moments.len().saturating_sub(1)) / CHUNK);
    let loaded: serde_json::Map<String, Value> = (lo..=hi).filter_map(|c| Some((c.to_string(), chunk(rec, k, c)?))).collect();
    json!({
        "source": rec.source.display().to_string(), "chunk": CHUNK, "robot": k, "robots": robots,
        "world": rec.world.as_ref().map(|w| w.field.clone()), "loaded": loaded,
        "field_pictures": rec.world.as_ref().map_or(0, |w| w.pictures.len()),
    })
}

pub(crate) fn answer(rec: &Replay, req: &Request) -> Reply {
    let url = req.url.as_str();
    let (path, query) = url.split_once('?').unwrap_or((url, ""));
    let (k, rest) = crate::world::robot_path(path);
    let file = |p: &std::path::Path, kind: &str| match std::fs::read(p) {
        Ok(bytes) => Reply::data(bytes).kind(kind),
        Err(e) => Reply::text(format!("{}: {e}\n", p.display())).status(500),
    };
    if path == "/field.png" {
        // The field camera's newest picture by `?t=MS`.
        let t = param::<u64>(query, "t").unwrap_or(0);
        let pictures = rec.world.as_ref().map_or(&[][..], |w| &w.pictures[..]);
        return match pictures.partition_point(|(pt, _)| *pt <= t).checked_sub(1) {
            Some(i) => file(&pictures[i].1, "image/png"),
            None => not_found(url),
        };
    }
    let Some(robot) = rec.robots.get(k) else {
        return not_found(path);
    };
    match (req.method.as_str(), rest.as_str()) {
        ("GET", "/") => page("null", &script_json(&index(rec, param(query, "robot").filter(|k| *k < rec.robots.len()).unwrap_or(0), query)), "null"),
        ("GET", "/chunk") => match param(query, "n").and_then(|c| chunk(rec, k, c)) {
            Some(v) => json_reply(&v),
            None => not_found(url),
        },
        ("GET", "/camera.png") => {
            let n = match param::<u64>(query, "t") {
                Some(t) => robot.picture_times.partition_point(|p| *p <= t),
                None => param(query, "n").unwrap_or(0),
            };
            match n.checked_sub(1).and_then(|i| robot.pictures.get(i)) {
                Some(p) => file(p, "image/png"),
                None => not_found(url),
            }
        }
        ("GET", "/speaker.wav") => match &robot.speaker {
            Some(p) => file(p, "audio/wav"),
            None => not_found(path),
        },
        _ => not_found(path),
    }
}
