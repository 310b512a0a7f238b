//! The HTTP side of the view: `GET /` (the page, with the current snapshot inlined so
//! it draws before any script request), `GET /state` (a snapshot as JSON), `POST
//! /control` (one `--control` command line; the answer line back).
use std::io::Read;
use std::net::SocketAddr;
use std::sync::{Arc, OnceLock};

use sdk_runtime::error::{ErrorKind, Result};
use sdk_runtime::runtime::Runtime;
use tiny_http::{Header, Method, Request, Response, Server};

const PAGE: &str = include_str!("page.html");
/// Where the page takes its first snapshot from.
const INITIAL: &str = "/*INITIAL*/null";

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
        let (server, rt) = (self.server.clone(), *self.rt.get().expect("set"));
        // Two threads answer: a slow client (a big camera picture) holds up no other.
        for _ in 0..2 {
            let server = server.clone();
            std::thread::Builder::new()
                .name("openr-view".into())
                .spawn(move || {
                    while let Ok(req) = server.recv() {
                        answer(rt, req);
                    }
                })
                .map_err(|e| ErrorKind::Runtime(format!("cannot start the view server: {e}")))?;
        }
        Ok(())
    }
}

fn header(name: &str, value: &str) -> Header {
    Header::from_bytes(name.as_bytes(), value.as_bytes()).expect("valid header")
}

fn answer(rt: &'static Runtime, mut req: Request) {
    let path = req.url().split('?').next().unwrap_or("").to_string();
    let res = match (req.method(), path.as_str()) {
        (Method::Get, "/") => {
            let page = PAGE.replacen(INITIAL, &crate::snapshot::take(rt).to_string(), 1);
            Response::from_string(page).with_header(header("Content-Type", "text/html; charset=utf-8"))
        }
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
        _ => Response::from_string(format!("no such page: {path}\n")).with_status_code(404),
    };
    let res = res.with_header(header("Cache-Control", "no-store"));
    let _ = req.respond(res);
}

/// The camera's last picture (sensor resolution, RGB) as PNG: encoded only when a
/// browser asks for it, outside the robot's lock.
fn camera_png(rt: &Runtime) -> std::result::Result<Vec<u8>, png::EncodingError> {
    let (w, h, data) = {
        let robot = rt.vr.robot();
        let img = robot.camera_rgb();
        (img.width as u32, img.height as u32, img.data.clone())
    };
    let mut out = Vec::new();
    let mut enc = png::Encoder::new(&mut out, w, h);
    enc.set_color(png::ColorType::Rgb);
    enc.set_depth(png::BitDepth::Eight);
    enc.set_compression(png::Compression::Fast);
    let mut writer = enc.write_header()?;
    writer.write_image_data(&data)?;
    writer.finish()?;
    Ok(out)
}
