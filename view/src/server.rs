//! The HTTP side of the view: `GET /` (the page, with the current snapshot inlined so
//! it draws before any script request), `GET /state` (a snapshot as JSON), `POST
//! /control` (one `--control` command line; the answer line back). A simulated world
//! ([`crate::world`]) serves `/field`, `/world` and each robot's view under `/robot/K/`.
//! Replaying a recording ([`crate::chunks`]), `GET /` inlines the recording's index and
//! the moments the URL asks for; the rest come in pieces.
use std::net::{SocketAddr, TcpListener};
use std::sync::{Arc, OnceLock};

use crate::cdt::Overlay;
use crate::http::{Reply, Request};
use sdk_runtime::error::{ErrorKind, Result};
use sdk_runtime::runtime::Runtime;

const PAGE: &str = include_str!("page.html");
/// Where the page takes its first snapshot from, and a recording's moments.
const INITIAL: &str = "/*INITIAL*/null";
const REPLAY: &str = "/*REPLAY*/null";
const WORLD: &str = "/*WORLD*/null";

/// What the server shows: the running robot or a recording.
enum Source {
    Live(&'static Runtime),
    World(Arc<crate::world::Live>),
    Replay(Arc<crate::replay::Replay>),
}

/// A bound view server; serves once attached to a runtime.
pub struct View {
    listener: TcpListener,
    addr: SocketAddr,
    rt: Arc<OnceLock<&'static Runtime>>,
}

impl View {
    /// Listens on `addr` (port 0 picks one). A port in use is an error.
    pub fn bind(addr: SocketAddr) -> std::result::Result<View, String> {
        let listener = TcpListener::bind(addr).map_err(|e| format!("--view {addr}: cannot listen: {e}"))?;
        let addr = listener.local_addr().map_err(|e| format!("--view {addr}: cannot listen: {e}"))?;
        Ok(View { listener, addr, rt: Arc::new(OnceLock::new()) })
    }

    /// The address it listens on.
    pub fn addr(&self) -> SocketAddr {
        self.addr
    }
}

impl sdk_runtime::observe::Observer for View {
    fn attach(&self, rt: &'static Runtime) -> Result<()> {
        let _ = self.rt.set(rt);
        self.serve(Source::Live(rt)).map_err(ErrorKind::Runtime)?;
        Ok(())
    }
}

impl View {
    /// Serves `rec` (from threads of its own) instead of a running robot.
    pub fn replay(&self, rec: crate::replay::Replay) -> std::result::Result<(), String> {
        self.serve(Source::Replay(Arc::new(rec)))
    }

    /// Serves a simulated world: the robots' own views through this one.
    pub fn world(&self, world: Arc<crate::world::Live>) -> std::result::Result<(), String> {
        self.serve(Source::World(world))
    }

    /// Each connection is answered by a thread of its own ([`crate::http`]): a slow
    /// client (a big camera picture), a world's answer that waits for a robot's, or an
    /// idle keep-alive connection holds up no other.
    fn serve(&self, source: Source) -> std::result::Result<(), String> {
        let fail = |e: std::io::Error| format!("cannot start the view server: {e}");
        let listener = self.listener.try_clone().map_err(fail)?;
        crate::http::serve(listener, crate::http::LIMITS, Arc::new(move |req: &Request| answer(&source, req))).map_err(fail)
    }
}

/// JSON for inside a `<script>`: no `</` that could end it.
pub(crate) fn script_json(v: &serde_json::Value) -> String {
    v.to_string().replace("</", "<\\/")
}

fn answer(source: &Source, req: &Request) -> Reply {
    match source {
        Source::Live(rt) => answer_live(rt, req),
        Source::World(w) => answer_world(w, req),
        Source::Replay(rec) => crate::chunks::answer(rec, req),
    }
}

/// The page with a snapshot, a recording's index or a world inlined.
pub(crate) fn page(initial: &str, replay: &str, world: &str) -> Reply {
    let page = PAGE.replacen(INITIAL, initial, 1).replacen(REPLAY, replay, 1).replacen(WORLD, world, 1);
    Reply::text(page).kind("text/html; charset=utf-8")
}

pub(crate) fn json(v: &serde_json::Value) -> Reply {
    Reply::text(v.to_string()).kind("application/json")
}

pub(crate) fn not_found(path: &str) -> Reply {
    Reply::text(format!("no such page: {path}\n")).status(404)
}

/// The path of a request target, without its query.
fn path_of(url: &str) -> &str {
    url.split('?').next().unwrap_or("")
}

fn answer_live(rt: &'static Runtime, req: &Request) -> Reply {
    let path = path_of(&req.url);
    match (req.method.as_str(), path) {
        ("GET", "/") => page(&script_json(&crate::snapshot::take(rt)), "null", "null"),
        ("GET", "/state") => json(&crate::snapshot::take(rt)),
        ("GET", "/camera.png") => match camera_png(rt) {
            Ok(Some(png)) => Reply::data(png).kind("image/png"),
            Ok(None) => Reply::text("the camera has taken no picture yet\n").status(404),
            Err(e) => Reply::text(format!("cannot encode the camera picture: {e}\n")).status(500),
        },
        ("GET", "/cdt.png") => match crate::cdt::overlay_png(rt) {
            Ok(Overlay::Png(png)) => Reply::data(png).kind("image/png"),
            Ok(Overlay::NoPicture) => Reply::text("no CDT layer: the camera has taken no picture yet\n").status(404),
            Ok(Overlay::NoTable) => Reply::text("no CDT layer: the program set no colour detection table (SetCdtVectorData)\n").status(404),
            Err(e) => Reply::text(format!("cannot encode the CDT layer: {e}\n")).status(500),
        },
        ("POST", "/control") => {
            // The first 256 bytes: one command line.
            let line = String::from_utf8_lossy(&req.body[..req.body.len().min(256)]);
            let answer = sdk_runtime::control::command(rt, line.trim());
            let code = if answer.starts_with("ok") { 200 } else { 400 };
            Reply::text(answer).status(code).kind("text/plain")
        }
        _ => not_found(path),
    }
}

/// A world's page: robot K's view passed through (`/robot/K/...`; the world's pause
/// button is robot 0's, as its lockstep holds every robot), the field and its truth.
fn answer_world(w: &crate::world::Live, req: &Request) -> Reply {
    let (path, query) = req.url.split_once('?').unwrap_or((&req.url, ""));
    match (req.method.as_str(), path) {
        ("GET", "/") => {
            let k = crate::chunks::param::<usize>(query, "robot").unwrap_or(0);
            let initial = w.ask(k, "GET", "/state", b"").ok().and_then(|(_, _, b)| serde_json::from_slice::<serde_json::Value>(&b).ok());
            let world = serde_json::json!({ "robots": w.robots(), "robot": k, "field": w.field(), "truth": w.truth() });
            page(&script_json(&initial.unwrap_or(serde_json::Value::Null)), "null", &script_json(&world))
        }
        ("GET", "/field") => json(&w.field()),
        ("GET", "/world") => json(&w.truth()),
        ("GET", "/field.png") => match w.camera() {
            Some(png) => Reply::data(png).kind("image/png"),
            None => Reply::text("the field camera has taken no picture yet\n").status(503),
        },
        (method, _) => {
            let (k, rest) = if path == "/control" { (0, path.to_string()) } else { crate::world::robot_path(path) };
            let body = &req.body[..req.body.len().min(256)];
            let target = if query.is_empty() { rest } else { format!("{rest}?{query}") };
            match w.ask(k, method, &target, body) {
                Ok((code, kind, bytes)) => Reply::data(bytes).status(code).kind(&kind),
                Err(e) => Reply::text(format!("{e}\n")).status(503),
            }
        }
    }
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
