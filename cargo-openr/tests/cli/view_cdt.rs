//! The live view's CDT overlay (`/cdt.png`, the page's checkbox or `?cdt=1`):
//! `testdata/programs/cdtdetect` loads a pink table (channel 0) and a green one
//! (channel 1) and the camera sees a known picture, so the camera's layer C has a
//! known shape. The run is paused before each look (nothing depends on the machine's
//! speed).
use std::io::{Read, Write};
use std::net::TcpStream;
use std::path::Path;

use crate::support::{build, spawn_ms, Running};
use crate::view::{chromium_with, http, pause_after, view_addr};

const PINK: [u8; 3] = [255, 80, 180];
const GREEN: [u8; 3] = [20, 200, 40];
const RED: [u8; 3] = [220, 30, 30];
/// The overlay's colours of channels 0 and 1 (view/src/cdt.rs).
const CHANNEL0: [u8; 4] = [255, 0, 255, 255];
const CHANNEL1: [u8; 4] = [0, 255, 255, 255];

/// The camera's picture (ERS-7 sensor, 416 × 320) at (x, y): red, with a pink
/// rectangle (x 104..208, y 80..240) and a green band at the bottom (y 288..).
/// Red is near pink but outside its table (Cb 99 < 129); every edge falls on a
/// 4 × 4 block, one pixel of layer C.
fn scene(x: usize, y: usize) -> [u8; 3] {
    if y >= 288 {
        GREEN
    } else if (104..208).contains(&x) && (80..240).contains(&y) {
        PINK
    } else {
        RED
    }
}

fn scene_ppm(path: &Path) {
    let (w, h) = (416, 320);
    let mut ppm = format!("P6 {w} {h} 255\n").into_bytes();
    for y in 0..h {
        for x in 0..w {
            ppm.extend_from_slice(&scene(x, y));
        }
    }
    std::fs::write(path, ppm).unwrap();
}

/// cdtdetect viewing the scene, paused after 500 ms of virtual time; (run, address).
fn cdtdetect_paused(dir: &Path) -> (Running, String) {
    let p = build("cdtdetect");
    let pic = dir.join("scene.ppm");
    scene_ppm(&pic);
    let mut run = spawn_ms(&p.ms(), &["--view", "--speed", "max", "--images", pic.to_str().unwrap()], &[]);
    let addr = view_addr(&mut run);
    pause_after(&addr, 500);
    (run, addr)
}

/// GET `path`: (status, body bytes).
fn get(addr: &str, path: &str) -> (u16, Vec<u8>) {
    let mut s = TcpStream::connect(addr).unwrap();
    write!(s, "GET {path} HTTP/1.0\r\n\r\n").unwrap();
    let mut out = Vec::new();
    s.read_to_end(&mut out).unwrap();
    let at = out.windows(4).position(|x| x == b"\r\n\r\n").unwrap() + 4;
    let status = String::from_utf8_lossy(&out[..at]).split_whitespace().nth(1).and_then(|c| c.parse().ok()).unwrap_or(0);
    (status, out[at..].to_vec())
}

/// A PNG as (width, height, channels, pixels).
fn decode(png: &[u8]) -> (usize, usize, usize, Vec<u8>) {
    let mut reader = png::Decoder::new(png).read_info().unwrap();
    let mut buf = vec![0; reader.output_buffer_size()];
    let info = reader.next_frame(&mut buf).unwrap();
    buf.truncate(info.buffer_size());
    (info.width as usize, info.height as usize, info.color_type.samples(), buf)
}

/// The number after `word` in `line`.
fn after(line: &str, word: &str) -> u64 {
    line.split_whitespace().skip_while(|w| *w != word).nth(1).and_then(|v| v.parse().ok()).unwrap_or_else(|| panic!("no {word} in {line}"))
}

#[test]
fn cdt_png_is_layer_c_with_each_channel_in_its_colour() {
    let dir = tempfile::tempdir().unwrap();
    let (run, addr) = cdtdetect_paused(dir.path());
    let (code, png) = get(&addr, "/cdt.png");
    let stdout = run.stdout();
    let _ = run.stop();
    assert_eq!(code, 200, "{}", String::from_utf8_lossy(&png));
    let (w, h, channels, px) = decode(&png);
    assert_eq!((w, h, channels), (104, 80, 4), "layer C's size (ERS-7), RGBA");
    // Each layer-C pixel stands for a 4 × 4 block of the sensor; the last row's first
    // 16 bytes are the image's tag, no pixels.
    let mut counts = [0u64; 2];
    for y in 0..h {
        for x in 0..w {
            let want = match scene(4 * x, 4 * y) {
                _ if y == h - 1 && x < 16 => [0; 4],
                PINK => CHANNEL0,
                GREEN => CHANNEL1,
                _ => [0; 4],
            };
            let got = &px[(y * w + x) * 4..(y * w + x) * 4 + 4];
            assert_eq!(got, want, "CDT pixel ({x},{y})");
            counts[0] += (want == CHANNEL0) as u64;
            counts[1] += (want == CHANNEL1) as u64;
        }
    }
    assert_eq!(counts, [26 * 40, 104 * 8 - 16]);
    // The program found the same pixels in the image vector, and its tag agrees.
    assert!(stdout.contains("CdtDetect : SetCdtVectorData oSUCCESS"), "{stdout}");
    for (name, n) in [("pink", counts[0]), ("green", counts[1])] {
        let line = stdout.lines().find(|l| l.starts_with(&format!("CdtDetect : image 0 {name} "))).unwrap_or_else(|| panic!("no {name} line:\n{stdout}"));
        assert_eq!(after(line, "pixels"), n, "{line}");
        assert_eq!(after(line, "ColorFrequency"), n / 16, "{line}");
    }
}

/// The RGB pixels of a screenshot: (width, pixels).
fn screenshot(url: &str, dir: &Path, name: &str) -> (usize, Vec<[u8; 3]>) {
    let shot = dir.join(name);
    chromium_with(url, Some(&shot), &["--virtual-time-budget=3000", "--window-size=1100,1400"]);
    let (w, _, channels, px) = decode(&std::fs::read(&shot).unwrap());
    (w, px.chunks_exact(channels).map(|p| [p[0], p[1], p[2]]).collect())
}

/// The bounding box (x0, y0, x1, y1), exclusive, of the screenshot's pixels close to
/// `colour`, or None.
fn bbox(shot: &(usize, Vec<[u8; 3]>), colour: [u8; 3]) -> Option<(usize, usize, usize, usize)> {
    let (w, px) = shot;
    let close = |p: &[u8; 3]| p.iter().zip(colour).all(|(a, b)| a.abs_diff(b) <= 8);
    px.iter().enumerate().filter(|(_, p)| close(p)).fold(None, |b, (i, _)| {
        let (x, y) = (i % w, i / w);
        Some(b.map_or((x, y, x + 1, y + 1), |(x0, y0, x1, y1): (usize, usize, usize, usize)| (x0.min(x), y0.min(y), x1.max(x + 1), y1.max(y + 1))))
    })
}

#[test]
fn page_overlays_the_cdt_layer_on_the_camera_picture() {
    let dir = tempfile::tempdir().unwrap();
    let (run, addr) = cdtdetect_paused(dir.path());
    let plain = screenshot(&format!("http://{addr}/"), dir.path(), "plain.png");
    let overlaid = screenshot(&format!("http://{addr}/?cdt=1"), dir.path(), "cdt.png");
    if let Ok(to) = std::env::var("OPENR_VIEW_CDT_SCREENSHOT") {
        std::fs::copy(dir.path().join("cdt.png"), to).unwrap();
    }
    let _ = run.stop();

    // Without the overlay the camera picture is drawn as it is (416 × 320, its top-left
    // corner red): the pink rectangle where the scene has it, no channel colour.
    let (x0, y0, x1, y1) = bbox(&plain, RED).expect("the camera picture on the page");
    assert_eq!((x1 - x0, y1 - y0), (416, 288), "the picture's red part, at its size");
    assert_eq!(bbox(&plain, PINK), Some((x0 + 104, y0 + 80, x0 + 208, y0 + 240)), "the pink rectangle");
    assert_eq!(bbox(&plain, CHANNEL0[..3].try_into().unwrap()), None, "no overlay unless asked");
    assert_eq!(bbox(&plain, CHANNEL1[..3].try_into().unwrap()), None, "no overlay unless asked");

    // With ?cdt=1 channel 0's colour covers the pink rectangle and nothing else, channel
    // 1's the green band; the red part (detected by neither) shows the picture.
    assert_eq!(bbox(&overlaid, RED), Some((x0, y0, x1, y1)), "the picture at the same place");
    assert_eq!(bbox(&overlaid, CHANNEL0[..3].try_into().unwrap()), Some((x0 + 104, y0 + 80, x0 + 208, y0 + 240)), "channel 0 over the pink");
    assert_eq!(bbox(&overlaid, PINK), None, "the pink is all covered");
    assert_eq!(bbox(&overlaid, CHANNEL1[..3].try_into().unwrap()), Some((x0, y0 + 288, x0 + 416, y0 + 320)), "channel 1 over the green band");
    // The tag (the last CDT row's first 16 pixels) is no detection: the picture shows.
    assert_eq!(bbox(&overlaid, GREEN), Some((x0, y0 + 316, x0 + 64, y0 + 320)), "the tag leaves the green visible");
}

#[test]
fn cdt_png_is_not_found_without_a_table() {
    // imagesave opens the camera but loads no table: pictures, no CDT layer.
    let p = build("imagesave");
    let mut run = spawn_ms(&p.ms(), &["--view", "--speed", "max"], &[]);
    let addr = view_addr(&mut run);
    pause_after(&addr, 500);
    let (camera, _) = get(&addr, "/camera.png");
    let (code, body) = http(&addr, "GET", "/cdt.png", "");
    let _ = run.stop();
    assert_eq!(camera, 200, "imagesave's camera took pictures");
    assert_eq!(code, 404, "{body}");
    assert!(body.contains("no CDT layer") && body.contains("no colour detection table (SetCdtVectorData)"), "{body}");
}
