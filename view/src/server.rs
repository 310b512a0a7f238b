//! The HTTP side of the view: `GET /` (the page, with the current snapshot inlined so
//! it draws before any script request), `GET /state` (a snapshot as JSON), `POST
//! /control` (one `--control` command line; the answer line back). Replaying a
//! recording, `GET /` inlines all its moments instead, `/camera.png?n=N` is picture N
//! and `/speaker.wav` the sound.
use std::io::Read;
use std::net::SocketAddr;
use std::sync::{Arc, OnceLock};

use sdk_runtime::error::{ErrorKind, Result};
use sdk_runtime::runtime::Runtime;
use tiny_http::{Header, Method, Request, Response, Server};

const PAGE: &str = include_str!("page.html");
/// Where the page takes its first snapshot from, and a recording's moments.
const INITIAL: &str = "/*INITIAL*/null";
const REPLAY: &str = "/*REPLAY*/null";

/// What the server shows: the running robot or a recording.
#[derive(Clone)]
enum Source {
    Live(&'static Runtime),
    Replay(Arc<crate::replay::Recording>),
}

/// A bound view server; serves once attached to a runtime.
pub struct View {
    server: Arc<Server>,
    addr: SocketAddr,
    rt: Arc<OnceLock<&'static Runtime>>,
}

impl View {
    /// Listens on `addr` (port 0 picks one). A port in use is an error.
    pub fn bind(addr: SocketAddr) -> std::result::Result<View, String> {
        let server = Server::http(addr).map_err(|e| format!("--view {addr}: cannot listen: {e}"))?;
        let addr = server.server_addr().to_ip().ok_or_else(|| format!("--view {addr}: not an IP listener"))?;
        Ok(View { server: Arc::new(server), addr, rt: Arc::new(OnceLock::new()) })
    }

    /// The address it listens on.
    pub fn addr(&self) -> SocketAddr {
        self.addr
    }
}

impl sdk_runtime::observe::Observer for View {
    fn attach(&self, rt: &'static Runtime) -> Result<()> {
        let _ = self.rt.set(rt);
        serve(&self.server, Source::Live(rt)).map_err(ErrorKind::Runtime)?;
        Ok(())
    }
}

impl View {
    /// Serves `rec` (from threads of its own) instead of a running robot.
    pub fn replay(&self, rec: crate::replay::Recording) -> std::result::Result<(), String> {
        serve(&self.server, Source::Replay(Arc::new(rec)))
    }
}

fn serve(server: &Arc<Server>, source: Source) -> std::result::Result<(), String> {
    // Two threads answer: a slow client (a big camera picture) holds up no other.
    for _ in 0..2 {
        let (server, source) = (server.clone(), source.clone());
        std::thread::Builder::new()
            .name("openr-view".into())
            .spawn(move || {
                while let Ok(req) = server.recv() {
                    answer(&source, req);
                }
            })
            .map_err(|e| format!("cannot start the view server: {e}"))?;
    }
    Ok(())
}

fn header(name: &str, value: &str) -> Header {
    Header::from_bytes(name.as_bytes(), value.as_bytes()).expect("valid header")
}

/// JSON for inside a `<script>`: no `</` that could end it.
fn script_json(v: &serde_json::Value) -> String {
    v.to_string().replace("</", "<\\/")
}

fn answer(source: &Source, req: Request) {
    let res = match source {
        Source::Live(rt) => answer_live(rt, req),
        Source::Replay(rec) => answer_replay(rec, req),
    };
    let (req, res) = match res {
        Ok(x) => x,
        Err(_) => return,
    };
    let _ = req.respond(res.with_header(header("Cache-Control", "no-store")));
}

type Answer = std::result::Result<(Request, Response<std::io::Cursor<Vec<u8>>>), ()>;

fn page(initial: &str, replay: &str) -> Response<std::io::Cursor<Vec<u8>>> {
    let page = PAGE.replacen(INITIAL, initial, 1).replacen(REPLAY, replay, 1);
    Response::from_string(page).with_header(header("Content-Type", "text/html; charset=utf-8"))
}

fn not_found(path: &str) -> Response<std::io::Cursor<Vec<u8>>> {
    Response::from_string(format!("no such page: {path}\n")).with_status_code(404)
}

fn answer_live(rt: &'static Runtime, mut req: Request) -> Answer {
    let path = req.url().split('?').next().unwrap_or("").to_string();
    let res = match (req.method(), path.as_str()) {
        (Method::Get, "/") => page(&script_json(&crate::snapshot::take(rt)), "null"),
        (Method::Get, "/state") => Response::from_string(crate::snapshot::take(rt).to_string()).with_header(header("Content-Type", "application/json")),
        (Method::Get, "/camera.png") => match camera_png(rt) {
            Ok(png) => Response::from_data(png).with_header(header("Content-Type", "image/png")),
            Err(e) => Response::from_string(format!("cannot encode the camera picture: {e}\n")).with_status_code(500),
        },
        (Method::Post, "/control") => {
            let mut line = String::new();
            let _ = req.as_reader().take(256).read_to_string(&mut line);
            let answer = sdk_runtime::control::command(rt, line.trim());
            let code = if answer.starts_with("ok") { 200 } else { 400 };
            Response::from_string(answer).with_status_code(code).with_header(header("Content-Type", "text/plain"))
        }
        _ => not_found(&path),
    };
    Ok((req, res))
}

fn answer_replay(rec: &crate::replay::Recording, req: Request) -> Answer {
    let url = req.url().to_string();
    let (path, query) = url.split_once('?').unwrap_or((&url, ""));
    let file = |p: &std::path::Path, kind: &str| match std::fs::read(p) {
        Ok(bytes) => Response::from_data(bytes).with_header(header("Content-Type", kind)),
        Err(e) => Response::from_string(format!("{}: {e}\n", p.display())).with_status_code(500),
    };
    let res = match (req.method(), path) {
        (Method::Get, "/") => {
            let replay = serde_json::json!({
                "source": rec.source.display().to_string(), "design": rec.design,
                "states": rec.states, "pictures": rec.pictures.len(), "speaker": rec.speaker.is_some(),
            });
            page("null", &script_json(&replay))
        }
        (Method::Get, "/camera.png") => {
            let n = query.split('&').find_map(|kv| kv.strip_prefix("n=")).and_then(|v| v.parse::<usize>().ok()).unwrap_or(0);
            match n.checked_sub(1).and_then(|i| rec.pictures.get(i)) {
                Some(p) => file(p, "image/png"),
                None => not_found(&url),
            }
        }
        (Method::Get, "/speaker.wav") => match &rec.speaker {
            Some(p) => file(p, "audio/wav"),
            None => not_found(path),
        },
        _ => not_found(path),
    };
    Ok((req, res))
}

/// The camera's last picture (sensor resolution, RGB) as PNG: encoded only when a
/// browser asks for it, outside the robot's lock.
fn camera_png(rt: &Runtime) -> std::result::Result<Vec<u8>, png::EncodingError> {
    let (w, h, data) = {
        let robot = rt.vr.robot();
        let img = robot.camera_rgb();
        (img.width as u32, img.height as u32, img.data.clone())
    };
    crate::record::encode_png(w, h, &data)
}
