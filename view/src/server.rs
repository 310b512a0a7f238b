//! The HTTP side of the view: `GET /` (the page, with the current snapshot inlined so
//! it draws before any script request), `GET /state` (a snapshot as JSON), `POST
//! /control` (one `--control` command line; the answer line back). A simulated world
//! ([`crate::world`]) serves `/field`, `/world` and each robot's view under `/robot/K/`.
//! Replaying a recording ([`crate::chunks`]), `GET /` inlines the recording's index and
//! the moments the URL asks for; the rest come in pieces.
use std::io::Read;
use std::net::SocketAddr;
use std::sync::{Arc, OnceLock};

use crate::cdt::Overlay;
use sdk_runtime::error::{ErrorKind, Result};
use sdk_runtime::runtime::Runtime;
use tiny_http::{Header, Method, Request, Response, Server};

const PAGE: &str = include_str!("page.html");
/// Where the page takes its first snapshot from, and a recording's moments.
const INITIAL: &str = "/*INITIAL*/null";
const REPLAY: &str = "/*REPLAY*/null";
const WORLD: &str = "/*WORLD*/null";

/// What the server shows: the running robot or a recording.
#[derive(Clone)]
enum Source {
    Live(&'static Runtime),
    World(Arc<crate::world::Live>),
    Replay(Arc<crate::replay::Replay>),
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
    pub fn replay(&self, rec: crate::replay::Replay) -> std::result::Result<(), String> {
        serve(&self.server, Source::Replay(Arc::new(rec)))
    }

    /// Serves a simulated world: the robots' own views through this one.
    pub fn world(&self, world: Arc<crate::world::Live>) -> std::result::Result<(), String> {
        serve(&self.server, Source::World(world))
    }
}

fn serve(server: &Arc<Server>, source: Source) -> std::result::Result<(), String> {
    // Two threads answer (four for a world, whose answers wait for a robot's): a slow
    // client (a big camera picture) holds up no other.
    let threads = if matches!(source, Source::World(_)) { 4 } else { 2 };
    for _ in 0..threads {
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

pub(crate) fn header(name: &str, value: &str) -> Header {
    Header::from_bytes(name.as_bytes(), value.as_bytes()).expect("valid header")
}

/// JSON for inside a `<script>`: no `</` that could end it.
pub(crate) fn script_json(v: &serde_json::Value) -> String {
    v.to_string().replace("</", "<\\/")
}

fn answer(source: &Source, req: Request) {
    let res = match source {
        Source::Live(rt) => answer_live(rt, req),
        Source::World(w) => answer_world(w, req),
        Source::Replay(rec) => crate::chunks::answer(rec, req),
    };
    let (req, res) = match res {
        Ok(x) => x,
        Err(_) => return,
    };
    let _ = req.respond(res.with_header(header("Cache-Control", "no-store")));
}

pub(crate) type Answer = std::result::Result<(Request, Reply), ()>;
pub(crate) type Reply = Response<std::io::Cursor<Vec<u8>>>;

/// The page with a snapshot, a recording's index or a world inlined.
pub(crate) fn page(initial: &str, replay: &str, world: &str) -> Reply {
    let page = PAGE.replacen(INITIAL, initial, 1).replacen(REPLAY, replay, 1).replacen(WORLD, world, 1);
    Response::from_string(page).with_header(header("Content-Type", "text/html; charset=utf-8"))
}

pub(crate) fn json(v: &serde_json::Value) -> Reply {
    Response::from_string(v.to_string()).with_header(header("Content-Type", "application/json"))
}

pub(crate) fn not_found(path: &str) -> Reply {
    Response::from_string(format!("no such page: {path}\n")).with_status_code(404)
}

fn answer_live(rt: &'static Runtime, mut req: Request) -> Answer {
    let path = req.url().split('?').next().unwrap_or("").to_string();
    let res = match (req.method(), path.as_str()) {
        (Method::Get, "/") => page(&script_json(&crate::snapshot::take(rt)), "null", "null"),
        (Method::Get, "/state") => Response::from_string(crate::snapshot::take(rt).to_string()).with_header(header("Content-Type", "application/json")),
        (Method::Get, "/camera.png") => match camera_png(rt) {
            Ok(Some(png)) => Response::from_data(png).with_header(header("Content-Type", "image/png")),
            Ok(None) => Response::from_string("the camera has taken no picture yet\n").with_status_code(404),
            Err(e) => Response::from_string(format!("cannot encode the camera picture: {e}\n")).with_status_code(500),
        },
        (Method::Get, "/cdt.png") => match crate::cdt::overlay_png(rt) {
            Ok(Overlay::Png(png)) => Response::from_data(png).with_header(header("Content-Type", "image/png")),
            Ok(Overlay::NoPicture) => Response::from_string("no CDT layer: the camera has taken no picture yet\n").with_status_code(404),
            Ok(Overlay::NoTable) => Response::from_string("no CDT layer: the program set no colour detection table (SetCdtVectorData)\n").with_status_code(404),
            Err(e) => Response::from_string(format!("cannot encode the CDT layer: {e}\n")).with_status_code(500),
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

/// A world's page: robot K's view passed through (`/robot/K/...`; the world's pause
/// button is robot 0's, as its lockstep holds every robot), the field and its truth.
fn answer_world(w: &crate::world::Live, mut req: Request) -> Answer {
    let url = req.url().to_string();
    let (path, query) = url.split_once('?').unwrap_or((&url, ""));
    let res = match (req.method(), path) {
        (Method::Get, "/") => {
            let k = query.split('&').find_map(|kv| kv.strip_prefix("robot=")).and_then(|v| v.parse::<usize>().ok()).unwrap_or(0);
            let initial = w.ask(k, "GET", "/state", b"").ok().and_then(|(_, _, b)| serde_json::from_slice::<serde_json::Value>(&b).ok());
            let world = serde_json::json!({ "robots": w.robots(), "robot": k, "field": w.field(), "truth": w.truth() });
            page(&script_json(&initial.unwrap_or(serde_json::Value::Null)), "null", &script_json(&world))
        }
        (Method::Get, "/field") => json(&w.field()),
        (Method::Get, "/world") => json(&w.truth()),
        (Method::Get, "/field.png") => match w.camera() {
            Some(png) => Response::from_data(png).with_header(header("Content-Type", "image/png")),
            None => Response::from_string("the field camera has taken no picture yet\n").with_status_code(503),
        },
        (method, _) => {
            let method = method.to_string();
            let (k, rest) = if path == "/control" { (0, path.to_string()) } else { crate::world::robot_path(path) };
            let mut body = Vec::new();
            let _ = req.as_reader().take(256).read_to_end(&mut body);
            let target = if query.is_empty() { rest } else { format!("{rest}?{query}") };
            match w.ask(k, &method, &target, &body) {
                Ok((code, kind, bytes)) => Response::from_data(bytes).with_status_code(code).with_header(header("Content-Type", &kind)),
                Err(e) => Response::from_string(format!("{e}\n")).with_status_code(503),
            }
        }
    };
    Ok((req, res))
}

/// The camera's last picture (sensor resolution, RGB) as PNG: encoded only when a
/// browser asks for it, outside the robot's lock. None before the first picture (a
/// program that never opens the camera has none at all).
fn camera_png(rt: &Runtime) -> std::result::Result<Option<Vec<u8>>, png::EncodingError> {
    let (w, h, data) = {
        let robot = rt.vr.robot();
        let img = robot.camera_rgb();
        if img.data.is_empty() {
            return Ok(None);
        }
        (img.width as u32, img.height as u32, img.data.clone())
    };
    crate::record::encode_png(w, h, &data).map(Some)
}
