//! The camera: an image given with `--images` is what an object saves from layer H.
use std::fs;

use crate::support::{build, run_ms};

/// A P6 PPM: left half red, right half blue, a green bottom quarter.
fn test_image(w: usize, h: usize) -> Vec<u8> {
    let mut v = format!("P6\n{w} {h}\n255\n").into_bytes();
    for y in 0..h {
        for x in 0..w {
            v.extend_from_slice(match (x < w / 2, y >= h * 3 / 4) {
                (_, true) => &[20, 200, 40],
                (true, false) => &[220, 30, 30],
                (false, false) => &[30, 40, 220],
            });
        }
    }
    v
}

#[test]
fn saved_bmps_show_the_frame_the_camera_took() {
    let p = build("imagesave");
    let dir = tempfile::tempdir().unwrap();
    let img = dir.path().join("scene.ppm");
    fs::write(&img, test_image(416, 320)).unwrap();
    let out = run_ms(&p.ms(), &["--for", "3s", "--images", img.to_str().unwrap()]);
    assert_eq!(out.code, Some(0), "{}", out.stderr);
    let bmp = fs::read(p.ms().join("IMG1.BMP")).unwrap();
    let (w, h) = (208usize, 160usize);
    // Bottom-up BGR rows of 208 × 3 bytes (a multiple of 4: no padding).
    let px = |x: usize, y: usize| {
        let o = 54 + ((h - 1 - y) * w + x) * 3;
        (bmp[o + 2] as i32, bmp[o + 1] as i32, bmp[o] as i32)
    };
    let close = |got: (i32, i32, i32), want: (i32, i32, i32)| (got.0 - want.0).abs() <= 24 && (got.1 - want.1).abs() <= 24 && (got.2 - want.2).abs() <= 24;
    for (x, y, want) in [(20, 20, (220, 30, 30)), (180, 30, (30, 40, 220)), (100, 150, (20, 200, 40)), (60, 100, (220, 30, 30))] {
        assert!(close(px(x, y), want), "pixel ({x},{y}) = {:?}, the image had {want:?}", px(x, y));
    }
}

#[test]
fn an_unreadable_image_source_is_a_clear_error() {
    let p = build("hello");
    let dir = tempfile::tempdir().unwrap();
    let bad = dir.path().join("x.ppm");
    fs::write(&bad, b"P3\n1 1\n255\n0 0 0\n").unwrap();
    let out = run_ms(&p.ms(), &["--for", "1s", "--images", bad.to_str().unwrap()]);
    assert_ne!(out.code, Some(0));
    assert!(out.stderr.contains("x.ppm: cannot use as camera images"), "{}", out.stderr);
}

/// Frame numbers of the images imagesave saved (its "saved /MS/IMGn.BMP frame N" lines).
fn saved_frames(p: &crate::support::Built, args: &[&str]) -> Vec<u64> {
    let out = run_ms(&p.ms(), args);
    assert_eq!(out.code, Some(0), "{}", out.stderr);
    let frames: Vec<u64> = out.lines_starting("ImageSave : saved ").iter().map(|l| l.rsplit(' ').next().unwrap().parse().unwrap()).collect();
    assert!(frames.len() >= 2, "{}", out.stdout);
    frames
}

#[test]
fn a_camera_phase_moves_the_pictures_to_other_frames() {
    let p = build("imagesave");
    let base = saved_frames(&p, &["--for", "3s", "--speed", "max"]);
    // 8 ms later in the camera's period: each picture one frame earlier.
    let shifted = saved_frames(&p, &["--for", "3s", "--speed", "max", "--camera-phase", "8"]);
    assert_eq!(shifted, base.iter().map(|f| f - 1).collect::<Vec<_>>(), "phase 0: {base:?}");
}

#[test]
fn a_camera_phase_of_a_second_or_more_is_refused() {
    let p = build("hello");
    let out = run_ms(&p.ms(), &["--for", "1s", "--camera-phase", "1000"]);
    assert_eq!(out.code, Some(2), "{}", out.stderr);
    assert!(out.stderr.contains("--camera-phase") && out.stderr.contains("0..1000"), "{}", out.stderr);
}
