//! End-to-end tests of the camera: rendering, layers, CDT, replacement images.

use std::time::Instant;

use crate::camera::*;
use crate::image::{band, color_frequency, field_counter, ImageLayout};
use crate::model::{POSTURE_PARTS, POSTURE_STAND};
use crate::render::{Ball, PinholeCamera};
use crate::vectors::rd_u32;
use crate::*;

fn standing() -> VirtualRobot {
    let mut r = VirtualRobot::new(Design::Ers7);
    r.body_mut().set_posture_deg(&POSTURE_PARTS, &POSTURE_STAND);
    r
}

/// (Y, Cr, Cb) of layer `layer` at band pixel (x, y).
fn ycc(l: &ImageLayout, b: &[u8], layer: usize, x: usize, y: usize) -> [u8; 3] {
    [band::Y, band::CR, band::CB].map(|k| b[l.pixel_offset(layer, k, x, y).unwrap()])
}

fn ball_centre_px(cam: &PinholeCamera, ball: &Ball) -> (f64, f64) {
    cam.project([ball.x_mm, ball.y_mm, ball.radius_mm]).expect("ball ahead")
}

fn is_pink(c: [u8; 3]) -> bool {
    c[1] > 150 && c[2] > 128
}
fn is_green(c: [u8; 3]) -> bool {
    c[1] < 115 && c[2] < 128
}

#[test]
fn image_vector_header_and_layers() {
    let mut r = standing();
    let mut out = Vec::new();
    r.render_image(1234, &mut out);
    let l = r.image_layout();
    assert_eq!(out.len(), l.size());
    assert_eq!(out.len(), 320 + 199_680 + 49_920 + 12_480 + 8_320);
    assert_eq!(rd_u32(&out, 16).unwrap(), 1027);
    assert_eq!(rd_u32(&out, 32).unwrap(), 4);
    let cam = r.primitive_of(Part::Camera).unwrap();
    let expect = [(24, 208, 160, 320, 199_680), (24, 104, 80, 320 + 199_680, 49_920), (24, 52, 40, 320 + 249_600, 12_480), (20, 104, 80, 320 + 262_080, 8_320)];
    for (i, (ty, w, h, off, size)) in expect.into_iter().enumerate() {
        let o = 192 + 32 * i;
        let f = |k: usize| rd_u32(&out, o + 4 * k).unwrap();
        assert_eq!([f(0), f(1), f(2), f(3), f(4), f(5), f(6)], [ty, cam, 1234, off, size, w, h], "layer {i}");
    }
}

#[test]
fn ball_appears_where_geometry_says() {
    let mut r = standing();
    let mut out = Vec::new();
    r.render_image(1, &mut out);
    let l = r.image_layout();
    let ball = r.scene().camera.ball.unwrap();
    let cam = r.camera_model();
    let (u, v) = ball_centre_px(&cam, &ball);
    assert!((0.0..416.0).contains(&u) && (0.0..320.0).contains(&v), "default ball visible standing: {u} {v}");
    // the rendered RGB and every colour layer agree
    let rgb = r.camera_rgb();
    let px = rgb.pixel(u as usize, v as usize);
    assert!(is_pink(rgb_to_ycrcb(px)), "{px:?}");
    for (layer, f) in [(0, 2.0), (1, 4.0), (2, 8.0)] {
        let c = ycc(&l, &out, layer, (u / f) as usize, (v / f) as usize);
        assert!(is_pink(c), "layer {layer}: {c:?}");
    }
    // floor: below the ball (nearer, between ball and robot) and to its sides
    let radius_px = ball.radius_mm / ((ball.x_mm - cam.pose.position[0]) * cam.su);
    for (du, dv) in [(0.0, 2.0), (-3.0, 0.0), (3.0, 0.0)] {
        let (x, y) = (u + du * radius_px, v + dv * radius_px);
        let c = ycc(&l, &out, 0, (x / 2.0) as usize, (y / 2.0) as usize);
        assert!(is_green(c), "floor at ({x}, {y}): {c:?}");
    }
    // the pink region's centroid is at the projected centre (within 2 H pixels)
    let (mut sx, mut sy, mut n) = (0.0, 0.0, 0.0);
    for y in 0..159 {
        for x in 0..208 {
            if is_pink(ycc(&l, &out, 0, x, y)) {
                sx += x as f64 + 0.5;
                sy += y as f64 + 0.5;
                n += 1.0;
            }
        }
    }
    assert!(n > 20.0);
    assert!((sx / n - u / 2.0).abs() < 2.0 && (sy / n - v / 2.0).abs() < 2.0, "{} {} vs {} {}", sx / n, sy / n, u / 2.0, v / 2.0);
    // the radius in pixels matches the apparent size
    let expected_area = std::f64::consts::PI * (radius_px / 2.0).powi(2);
    assert!((n / expected_area - 1.0).abs() < 0.35, "{n} vs {expected_area}");
}

#[test]
fn pan_left_moves_ball_right() {
    let centroid = |pan: f64| {
        let mut r = standing();
        r.body_mut().set_posture_deg(&[Part::NeckPan], &[pan]);
        r.render_image(1, &mut Vec::new());
        let rgb = r.camera_rgb().clone();
        let (mut sx, mut n) = (0.0, 0.0);
        for y in 0..rgb.height {
            for x in 0..rgb.width {
                if is_pink(rgb_to_ycrcb(rgb.pixel(x, y))) {
                    sx += x as f64;
                    n += 1.0;
                }
            }
        }
        assert!(n > 0.0, "ball visible at pan {pan}");
        let u = r.camera_model().project([1000.0, 0.0, 40.0]).unwrap().0;
        assert!((sx / n - u).abs() < 3.0);
        sx / n
    };
    let (c0, c10, cm10) = (centroid(0.0), centroid(10.0), centroid(-10.0));
    assert!(c10 > c0 + 30.0, "{c0} {c10}");
    assert!(cm10 < c0 - 30.0, "{c0} {cm10}");
}

#[test]
fn hpf_bands_reconstruct_full_resolution_luminance() {
    let mut r = standing();
    // make the image busy: ball near, head slightly down
    r.scene_mut().camera.ball = Some(Ball { x_mm: 600.0, y_mm: 30.0, ..Ball::default() });
    r.body_mut().set_posture_deg(&[Part::NeckTilt2], &[0.0]);
    let mut out = Vec::new();
    r.render_image(1, &mut out);
    let l = r.image_layout();
    let rgb = r.camera_rgb().clone();
    let mut max_err = 0;
    let mut edges = 0;
    for y in 0..159 {
        for x in 0..208 {
            let g = |k| out[l.pixel_offset(0, k, x, y).unwrap()];
            let block = reconstruct(g(band::Y), g(band::Y_LH), g(band::Y_HL), g(band::Y_HH));
            for (i, &yv) in block.iter().enumerate() {
                let want = rgb_to_ycrcb(rgb.pixel(2 * x + i % 2, 2 * y + i / 2))[0] as i32;
                max_err = max_err.max((yv as i32 - want).abs());
            }
            if g(band::Y_LH) != 128 || g(band::Y_HL) != 128 {
                edges += 1;
            }
        }
    }
    assert!(max_err <= 2, "max error {max_err}");
    assert!(edges > 50, "high-pass bands carry detail ({edges})");
    // M reconstructs H's Y band, L reconstructs M's
    for (lo, hi) in [(1, 0), (2, 1)] {
        let ll = l.layers[lo];
        for y in 0..ll.height - 1 {
            for x in 0..ll.width {
                let g = |k| out[l.pixel_offset(lo, k, x, y).unwrap()];
                let block = reconstruct(g(band::Y), g(band::Y_LH), g(band::Y_HL), g(band::Y_HH));
                for (i, &yv) in block.iter().enumerate() {
                    let (hx, hy) = (2 * x + i % 2, 2 * y + i / 2);
                    if hy == l.layers[hi].height - 1 && hx < 16 {
                        continue; // tag bytes
                    }
                    let want = out[l.pixel_offset(hi, band::Y, hx, hy).unwrap()] as i32;
                    assert!((yv as i32 - want).abs() <= 2, "layer {lo} ({x},{y})");
                }
            }
        }
    }
    // the RGB helper returns an image of the double resolution resembling the render
    let back = layer_to_rgb(&l, &out, 0).unwrap();
    assert_eq!((back.width, back.height), (416, 320));
    let (u, v) = r.camera_model().project([600.0, 30.0, 40.0]).unwrap();
    let p = back.pixel(u as usize, v as usize);
    let q = rgb.pixel(u as usize, v as usize);
    for k in 0..3 {
        assert!((p[k] as i32 - q[k] as i32).abs() <= 12, "{p:?} vs {q:?}");
    }
    assert!(layer_to_rgb(&l, &out, 3).is_none());
}

fn pink_table() -> [u32; 32] {
    [cdt_entry(255, 150, 255, 129); 32]
}

#[test]
fn cdt_bits_and_color_frequency_agree() {
    let mut r = standing();
    r.scene_mut().camera.ball = Some(Ball { x_mm: 600.0, ..Ball::default() });
    r.body_mut().set_posture_deg(&[Part::NeckTilt2], &[0.0]);
    let cam = r.primitive_of(Part::Camera).unwrap();
    let green = [cdt_entry(110, 0, 127, 0); 32];
    let v = build_cdt_vector(cam, &[(0x01, pink_table()), (0x20, green)]);
    assert_eq!(r.set_cdt(&v), O_SUCCESS);
    let mut out = Vec::new();
    r.render_image(7, &mut out);
    let l = r.image_layout();
    let c = l.layers[3];
    let mut counts = [0u32; 8];
    for y in 0..c.height {
        for x in 0..c.width {
            if y == c.height - 1 && x < 16 {
                continue;
            }
            let bits = out[l.pixel_offset(3, band::CDT, x, y).unwrap()];
            for (k, n) in counts.iter_mut().enumerate() {
                *n += (bits >> k) as u32 & 1;
            }
            // bits follow the rule on the M layer's pixel
            let m = ycc(&l, &out, 1, x, y);
            if !(y == c.height - 1 && x < 16) {
                assert_eq!(bits, r.camera().lut.classify(m[0], m[1], m[2]));
            }
        }
    }
    assert!(counts[0] >= 160, "ball detected: {counts:?}");
    assert!(counts[5] > 1000, "carpet detected: {counts:?}");
    assert_eq!(counts[1] + counts[2] + counts[3] + counts[4] + counts[6] + counts[7], 0);
    assert_eq!(counts, r.camera().last_counts);
    // the ball's pixel carries bit 0
    let (u, v) = r.camera_model().project([600.0, 0.0, 40.0]).unwrap();
    assert_eq!(out[l.pixel_offset(3, band::CDT, (u / 4.0) as usize, (v / 4.0) as usize).unwrap()] & 1, 1);
    // every band of every layer carries the same tag
    for layer in l.layers.iter() {
        for b in 0..layer.bands {
            let at = layer.data_offset + (layer.height - 1) * layer.row_stride() + b * layer.width;
            let tag = &out[at..at + 16];
            assert_eq!(color_frequency(tag, 0x01) as u32, (counts[0] / 16).min(255));
            assert_eq!(color_frequency(tag, 0x20) as u32, (counts[5] / 16).min(255));
            assert_eq!(color_frequency(tag, 0x02), 0);
            assert_eq!(field_counter(tag), Some(1));
        }
    }
}

#[test]
fn field_counter_increments() {
    let mut r = standing();
    let mut out = Vec::new();
    let l = r.image_layout();
    let tag_at = |layer: usize| {
        let x = l.layers[layer];
        x.data_offset + (x.height - 1) * x.row_stride()
    };
    let mut prev = None;
    for f in [4u32, 8, 12, 17] {
        r.render_image(f, &mut out);
        assert_eq!(rd_u32(&out, 192 + 8).unwrap(), f);
        let fc = field_counter(&out[tag_at(0)..]).unwrap();
        assert_eq!(field_counter(&out[tag_at(3)..]), Some(fc));
        if let Some(p) = prev {
            assert_eq!(fc, p + 1);
        }
        prev = Some(fc);
    }
}

#[test]
fn malformed_cdt_vectors_return_codes() {
    let mut r = standing();
    let cam = r.primitive_of(Part::Camera).unwrap();
    let good = build_cdt_vector(cam, &[(0x01, pink_table())]);
    assert_eq!(r.set_cdt(&good), O_SUCCESS);
    assert_eq!(r.camera().lut.table(0), Some(&pink_table()));
    // vector type
    let mut b = good.clone();
    b[16..20].copy_from_slice(&1027u32.to_le_bytes());
    assert_eq!(r.set_cdt(&b), O_INVALID_DATA_TYPE);
    // info type
    let mut b = good.clone();
    b[192..196].copy_from_slice(&20u32.to_le_bytes());
    assert_eq!(r.set_cdt(&b), O_INVALID_DATA_TYPE);
    // primitive
    assert_eq!(r.set_cdt(&build_cdt_vector(cam + 1, &[(0x01, pink_table())])), O_INVALID_PRIMITIVE_ID);
    assert_eq!(r.set_cdt(&build_cdt_vector(0xFFFF_FFFF, &[(0x01, pink_table())])), O_INVALID_PRIMITIVE_ID);
    // channels: 0, two bits, channel 7 on ERS-7
    for ch in [0, 0x03, 0x80, 0x100] {
        assert_eq!(r.set_cdt(&build_cdt_vector(cam, &[(ch, pink_table())])), O_INVALID_ARG, "channel {ch:#x}");
    }
    // a bad info after a good one loads nothing
    let mut r2 = standing();
    assert_eq!(r2.set_cdt(&build_cdt_vector(cam, &[(0x02, pink_table()), (0x80, pink_table())])), O_INVALID_ARG);
    assert!(r2.camera().lut.table(1).is_none());
    // truncated, too many
    assert_eq!(r.set_cdt(&good[..100]), O_FAIL);
    assert_eq!(r.set_cdt(&good[..192 + 100]), O_FAIL);
    let mut b = good.clone();
    b[32..36].copy_from_slice(&9u32.to_le_bytes());
    assert_eq!(r.set_cdt(&b), O_FAIL);
    // numData 0 is fine; garbage never panics
    assert_eq!(r.set_cdt(&build_cdt_vector(cam, &[])), O_SUCCESS);
    let mut seed = 12345u32;
    for len in [0, 1, 191, 192, 300, 1344, 4096] {
        let mut b: Vec<u8> = (0..len)
            .map(|_| {
                seed = seed.wrapping_mul(1_103_515_245).wrapping_add(12345);
                (seed >> 16) as u8
            })
            .collect();
        let _ = r.set_cdt(&b);
        if len >= 192 {
            b[16..20].copy_from_slice(&1028u32.to_le_bytes());
            let _ = r.set_cdt(&b);
        }
    }
    // ERS-210 accepts channel 7
    let mut r210 = VirtualRobot::new(Design::Ers210);
    let cam210 = r210.primitive_of(Part::Camera).unwrap();
    assert_eq!(r210.set_cdt(&build_cdt_vector(cam210, &[(0x80, pink_table())])), O_SUCCESS);
}

fn ppm(w: usize, h: usize, f: impl Fn(usize, usize) -> [u8; 3]) -> Vec<u8> {
    let mut b = format!("P6\n# test image\n{w} {h}\n255\n").into_bytes();
    for y in 0..h {
        for x in 0..w {
            b.extend_from_slice(&f(x, y));
        }
    }
    b
}

fn bmp24(w: usize, h: usize, f: impl Fn(usize, usize) -> [u8; 3]) -> Vec<u8> {
    let stride = (w * 3).div_ceil(4) * 4;
    let size = 54 + stride * h;
    let mut b = vec![0u8; size];
    b[0..2].copy_from_slice(b"BM");
    b[2..6].copy_from_slice(&(size as u32).to_le_bytes());
    b[10..14].copy_from_slice(&54u32.to_le_bytes());
    b[14..18].copy_from_slice(&40u32.to_le_bytes());
    b[18..22].copy_from_slice(&(w as i32).to_le_bytes());
    b[22..26].copy_from_slice(&(h as i32).to_le_bytes());
    b[26..28].copy_from_slice(&1u16.to_le_bytes());
    b[28..30].copy_from_slice(&24u16.to_le_bytes());
    for y in 0..h {
        let row = 54 + (h - 1 - y) * stride; // bottom-up
        for x in 0..w {
            let [r, g, bl] = f(x, y);
            b[row + 3 * x..row + 3 * x + 3].copy_from_slice(&[bl, g, r]);
        }
    }
    b
}

const QUAD: [[u8; 3]; 4] = [[255, 0, 0], [0, 255, 0], [0, 0, 255], [250, 250, 250]];

fn quad(x: usize, y: usize, w: usize, h: usize) -> [u8; 3] {
    QUAD[(x * 2 / w) + 2 * (y * 2 / h)]
}

#[test]
fn ppm_and_bmp_sources_load_and_convert() {
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join("a.ppm");
    std::fs::write(&p, ppm(10, 6, |x, y| quad(x, y, 10, 6))).unwrap();
    let mut r = standing();
    assert_eq!(r.set_image_source(Some(&p)).unwrap(), 1);
    let mut out = Vec::new();
    let l = r.image_layout();
    for _ in 0..2 {
        r.render_image(1, &mut out);
        // quadrant centres in layer H (208 × 160)
        for (i, (x, y)) in [(52, 40), (156, 40), (52, 120), (156, 120)].into_iter().enumerate() {
            assert_eq!(ycc(&l, &out, 0, x, y), rgb_to_ycrcb(QUAD[i]), "quadrant {i}");
            assert_eq!(ycc(&l, &out, 2, x / 4, y / 4), rgb_to_ycrcb(QUAD[i]), "L quadrant {i}");
        }
        assert_eq!(r.camera_rgb().pixel(0, 0), QUAD[0]);
    }
    // a directory: frames in name order (a BMP and a PPM), cycled
    let frames = dir.path().join("frames");
    std::fs::create_dir(&frames).unwrap();
    std::fs::write(frames.join("002.bmp"), bmp24(7, 5, |x, y| quad(x, y, 7, 5))).unwrap();
    std::fs::write(frames.join("001.ppm"), ppm(3, 3, |_, _| [10, 200, 30])).unwrap();
    std::fs::write(frames.join("notes.txt"), b"ignored").unwrap();
    assert_eq!(r.set_image_source(Some(&frames)).unwrap(), 2);
    let mut firsts = Vec::new();
    for _ in 0..4 {
        r.render_image(1, &mut out);
        firsts.push(r.camera_rgb().pixel(0, 0));
        if r.camera_rgb().pixel(0, 0) == QUAD[0] {
            // BMP orientation: bottom-up rows, BGR order
            assert_eq!(r.camera_rgb().pixel(415, 0), QUAD[1]);
            assert_eq!(r.camera_rgb().pixel(0, 319), QUAD[2]);
            assert_eq!(r.camera_rgb().pixel(415, 319), QUAD[3]);
        }
    }
    assert_eq!(firsts, vec![[10, 200, 30], QUAD[0], [10, 200, 30], QUAD[0]]);
    // errors
    let bad = dir.path().join("bad.ppm");
    std::fs::write(&bad, b"P6\n10 10\n255\nshort").unwrap();
    assert!(r.set_image_source(Some(&bad)).is_err());
    assert!(r.set_image_source(Some(&dir.path().join("missing.bmp"))).is_err());
    let empty = dir.path().join("empty");
    std::fs::create_dir(&empty).unwrap();
    assert!(r.set_image_source(Some(&empty)).is_err());
    // back to the rendered scene
    assert_eq!(r.set_image_source(None).unwrap(), 0);
    r.render_image(1, &mut out);
    assert_ne!(r.camera_rgb().pixel(0, 319), QUAD[2]);
    // decoder details: 16-bit PPM, top-down 32-bit BMP
    let mut p16 = b"P6 1 1 65535 ".to_vec();
    p16.extend_from_slice(&[0xFF, 0xFF, 0x80, 0x00, 0x00, 0x00]);
    assert_eq!(decode_ppm(&p16).unwrap().data, vec![255, 128, 0]);
    let mut b32 = bmp24(1, 1, |_, _| [0, 0, 0]);
    b32[22..26].copy_from_slice(&(-1i32).to_le_bytes());
    b32[28..30].copy_from_slice(&32u16.to_le_bytes());
    b32.truncate(54);
    b32.extend_from_slice(&[1, 2, 3, 4]);
    assert_eq!(decode_bmp(&b32).unwrap().data, vec![3, 2, 1]);
    assert!(decode_bmp(b"BM").is_err());
}

#[test]
fn ers210_renders_its_own_layout() {
    let mut r = VirtualRobot::new(Design::Ers210);
    let mut out = Vec::new();
    r.render_image(3, &mut out);
    assert_eq!(out.len(), r.image_layout().size());
    assert_eq!((r.camera_rgb().width, r.camera_rgb().height), (352, 288));
}

/// Prints the time of a full image (render + all layers); asserts only correctness.
#[test]
fn render_time() {
    let mut r = standing();
    let mut out = Vec::new();
    r.render_image(0, &mut out);
    let n = 30;
    let t = Instant::now();
    for f in 0..n {
        r.body_mut().set_posture_deg(&[Part::NeckPan], &[f as f64]);
        r.render_image(f, &mut out);
    }
    let per = t.elapsed() / n;
    let rgb = r.camera_rgb().clone();
    let t = Instant::now();
    let mut lut = CdtLut::default();
    lut.load(&CdtTable { channel: 0, entries: pink_table() });
    for f in 0..n {
        synthesize(&r.image_layout(), &rgb.data, &lut, f, &mut out);
    }
    let synth = t.elapsed() / n;
    println!("camera: full image {per:?} per frame (layer synthesis alone {synth:?})");
    assert_eq!(out.len(), r.image_layout().size());
}

#[test]
fn camera_parameters_change_the_image() {
    let mean_y = |r: &mut VirtualRobot| {
        let mut out = Vec::new();
        r.render_image(1, &mut out);
        let l = r.image_layout();
        let mut s = 0u64;
        for y in 0..159 {
            for x in 0..208 {
                s += out[l.pixel_offset(0, band::Y, x, y).unwrap()] as u64;
            }
        }
        (s / (208 * 159)) as i64
    };
    let mut r = standing();
    let cam = r.primitive_of(Part::Camera).unwrap();
    let base = mean_y(&mut r);
    assert_eq!(r.camera_control(cam, CAM_SET_GAIN, 1), O_SUCCESS);
    let dark = mean_y(&mut r);
    assert!((dark - base / 2).abs() <= 2, "{base} {dark}");
    assert_eq!(r.camera_control(cam, CAM_SET_GAIN, 2), O_SUCCESS);
    assert_eq!(r.camera_control(cam, CAM_SET_SHUTTER_SPEED, 1), O_SUCCESS);
    assert!(mean_y(&mut r) > base + 20);
    assert_eq!(r.camera_control(cam, CAM_SET_SHUTTER_SPEED, 2), O_SUCCESS);
    assert_eq!(mean_y(&mut r), base);
    assert_eq!(r.camera_control(cam, CAM_SET_WHITE_BALANCE, 0), O_INVALID_ARG);
    assert_eq!(r.camera_control(cam, CAM_SET_GAIN, 4), O_INVALID_ARG);
    assert_eq!(r.camera_control(cam, 387, 1), O_NOT_SUPPORTED);
    let pan = r.primitive_of(Part::NeckPan).unwrap();
    assert_eq!(r.camera_control(pan, CAM_SET_GAIN, 1), O_INVALID_ARG);
    assert_eq!(r.camera_control(0xDEAD, CAM_SET_GAIN, 1), O_INVALID_PRIMITIVE_ID);
}

// ---------------------------------------------------------------------------------
// layer synthesis pinned against a straightforward reference

/// The per-pixel synthesis as first written (before it was optimised), kept as the
/// reference `synthesize` must match byte for byte. CDT bits follow the robot-api 6.7
/// rule directly from the loaded tables (not through `CdtLut`'s lookup tables).
mod reference {
    use crate::camera::{CdtLut, CDT_CHANNELS};
    use crate::image::{ImageLayout, LayerLayout, TAG_SIZE};

    const KY: [i32; 3] = [19_661, 38_550, 7_325];

    fn luma(r: i32, g: i32, b: i32) -> i32 {
        (KY[0] * r + KY[1] * g + KY[2] * b + 32_768) >> 16
    }

    fn div_round(n: i32, d: i32) -> i32 {
        (2 * n + d).div_euclid(2 * d)
    }

    fn clip(v: i32) -> u8 {
        v.clamp(0, 255) as u8
    }

    fn from_rgb(l: &LayerLayout, rgb: &[u8], dst: &mut [u8]) {
        let (w, h) = (l.width, l.height);
        let sw = 2 * w;
        let stride = l.row_stride();
        for y in 0..h {
            let row = &mut dst[y * stride..(y + 1) * stride];
            let px = |sx: usize, sy: usize| {
                let o = (sy * sw + sx) * 3;
                (rgb[o] as i32, rgb[o + 1] as i32, rgb[o + 2] as i32)
            };
            for x in 0..w {
                let (r0, g0, b0) = px(2 * x, 2 * y);
                let (r1, g1, b1) = px(2 * x + 1, 2 * y);
                let (r2, g2, b2) = px(2 * x, 2 * y + 1);
                let (r3, g3, b3) = px(2 * x + 1, 2 * y + 1);
                let (a, b, c, d) = (luma(r0, g0, b0), luma(r1, g1, b1), luma(r2, g2, b2), luma(r3, g3, b3));
                let sy = a + b + c + d;
                row[x] = clip(div_round(sy, 4));
                row[w + x] = clip(128 + div_round(128 * (r0 + r1 + r2 + r3 - sy), 1020));
                row[2 * w + x] = clip(128 + div_round(128 * (b0 + b1 + b2 + b3 - sy), 1020));
                row[3 * w + x] = clip(128 + div_round(c + d - a - b, 4));
                row[4 * w + x] = clip(128 + div_round(b + d - a - c, 4));
                row[5 * w + x] = clip(128 + div_round(a + d - b - c, 4));
            }
        }
    }

    fn from_layer(src: &LayerLayout, s: &[u8], l: &LayerLayout, dst: &mut [u8]) {
        let (w, ss, sw, stride) = (l.width, src.row_stride(), src.width, l.row_stride());
        for y in 0..l.height {
            for x in 0..w {
                let q = |band: usize| {
                    let i = band * sw + 2 * x;
                    let (t, b) = (2 * y * ss + i, (2 * y + 1) * ss + i);
                    (s[t] as i32, s[t + 1] as i32, s[b] as i32, s[b + 1] as i32)
                };
                let (a, b, c, d) = q(0);
                let (cr0, cr1, cr2, cr3) = q(1);
                let (cb0, cb1, cb2, cb3) = q(2);
                let row = &mut dst[y * stride..(y + 1) * stride];
                row[x] = clip(div_round(a + b + c + d, 4));
                row[w + x] = clip(div_round(cr0 + cr1 + cr2 + cr3, 4));
                row[2 * w + x] = clip(div_round(cb0 + cb1 + cb2 + cb3, 4));
                row[3 * w + x] = clip(128 + div_round(c + d - a - b, 4));
                row[4 * w + x] = clip(128 + div_round(b + d - a - c, 4));
                row[5 * w + x] = clip(128 + div_round(a + d - b - c, 4));
            }
        }
    }

    fn classify(lut: &CdtLut, y: u8, cr: u8, cb: u8) -> u8 {
        let mut bits = 0;
        for k in 0..CDT_CHANNELS {
            if let Some(t) = lut.table(k) {
                let [cr_min, cr_max, cb_min, cb_max] = t[y as usize >> 3].to_le_bytes();
                if (cr_min..=cr_max).contains(&cr) && (cb_min..=cb_max).contains(&cb) {
                    bits |= 1 << k;
                }
            }
        }
        bits
    }

    pub fn synthesize(layout: &ImageLayout, rgb: &[u8], lut: &CdtLut, field_counter: u32, buf: &mut [u8]) -> [u32; CDT_CHANNELS] {
        let [lh, lm, ll, lc] = layout.layers;
        let (_, rest) = buf.split_at_mut(lh.data_offset);
        let (h, rest) = rest.split_at_mut(lm.data_offset - lh.data_offset);
        let (m, rest) = rest.split_at_mut(ll.data_offset - lm.data_offset);
        let (l, c) = rest.split_at_mut(lc.data_offset - ll.data_offset);
        from_rgb(&lh, rgb, h);
        from_layer(&lh, h, &lm, m);
        from_layer(&lm, m, &ll, l);
        let mut counts = [0u32; CDT_CHANNELS];
        for y in 0..lc.height {
            for x in 0..lc.width {
                let at = y * lm.row_stride() + x;
                let bits = classify(lut, m[at], m[at + lm.width], m[at + 2 * lm.width]);
                c[y * lc.row_stride() + x] = bits;
                if !(y + 1 == lc.height && x < TAG_SIZE) {
                    for (k, n) in counts.iter_mut().enumerate() {
                        *n += (bits >> k) as u32 & 1;
                    }
                }
            }
        }
        layout.write_tags(buf, field_counter, counts).expect("sized");
        counts
    }
}

/// A deterministic pseudo-random byte stream.
fn lcg_bytes(seed: u32, n: usize) -> Vec<u8> {
    let mut s = seed;
    (0..n)
        .map(|_| {
            s = s.wrapping_mul(1_103_515_245).wrapping_add(12_345);
            (s >> 16) as u8
        })
        .collect()
}

/// Tables exercising several channels and per-segment ranges.
pub(super) fn test_lut() -> CdtLut {
    let mut lut = CdtLut::default();
    let green = [cdt_entry(110, 0, 127, 0); 32];
    let mut stairs = [0u32; 32];
    for (s, e) in stairs.iter_mut().enumerate() {
        let v = (s * 8) as u8;
        *e = cdt_entry(v.saturating_add(60), v / 2, 255 - v / 3, v / 4);
    }
    let everything = [cdt_entry(255, 0, 255, 0); 32];
    let empty = [cdt_entry(0, 255, 0, 255); 32]; // min > max: matches nothing
    for (channel, entries) in [(0, pink_table()), (5, green), (2, stairs), (6, everything), (3, empty)] {
        lut.load(&CdtTable { channel, entries });
    }
    lut
}

/// Sensor-size test images: random, extremes, gradients, saturated checkerboards.
fn test_images(w: usize, h: usize) -> Vec<(&'static str, Vec<u8>)> {
    let img = |f: &dyn Fn(usize, usize, usize) -> u8| {
        let mut v = Vec::with_capacity(w * h * 3);
        for y in 0..h {
            for x in 0..w {
                v.extend((0..3).map(|c| f(x, y, c)));
            }
        }
        v
    };
    let noise = lcg_bytes(99, w * h * 3);
    let sat = [[255, 0, 0], [0, 255, 0], [0, 0, 255], [255, 255, 0], [255, 0, 255], [0, 255, 255], [0, 0, 0], [255, 255, 255]];
    vec![
        ("random", lcg_bytes(7, w * h * 3)),
        ("random 0/255", noise.iter().map(|&v| if v & 1 == 0 { 0 } else { 255 }).collect()),
        ("black", vec![0; w * h * 3]),
        ("white", vec![255; w * h * 3]),
        ("grey 128", vec![128; w * h * 3]),
        ("horizontal gradient", img(&|x, _, c| ((x * 255 / (w - 1)) as u8).wrapping_add(c as u8 * 85))),
        ("vertical gradient", img(&|_, y, c| ((y * 255 / (h - 1)) as u8) ^ (c as u8 * 0x55))),
        ("diagonal gradient", img(&|x, y, c| ((x + y + 40 * c) % 256) as u8)),
        ("saturated pixels", img(&|x, y, c| sat[(x * 3 + y * 5) % 8][c])),
        ("saturated blocks", img(&|x, y, c| sat[(x / 9 + y / 7) % 8][c])),
        // extreme high-pass values, both signs (the upper clip of LH, HL, HH)
        ("pixel checkerboard", img(&|x, y, _| if (x + y) % 2 == 0 { 0 } else { 255 })),
        ("pixel checkerboard'", img(&|x, y, _| if (x + y) % 2 == 0 { 255 } else { 0 })),
        ("row stripes", img(&|_, y, c| if y % 2 == 0 { 255 } else { [0, 30, 0][c] })),
        ("row stripes'", img(&|_, y, _| if y % 2 == 0 { 0 } else { 255 })),
        ("column stripes", img(&|x, _, c| if x % 2 == 0 { [255, 0, 255][c] } else { 0 })),
        ("column stripes'", img(&|x, _, _| if x % 2 == 0 { 0 } else { 255 })),
    ]
}

#[test]
fn synthesize_matches_reference_byte_for_byte() {
    let lut = test_lut();
    for design in [Design::Ers7, Design::Ers210] {
        let layout = ImageLayout::new(design);
        let (w, h) = (2 * layout.layers[0].width, 2 * layout.layers[0].height);
        let mut any_counts = [0u32; CDT_CHANNELS];
        let mut clipped = [false; 3]; // LH, HL, HH of layer H reached 255
        for (i, (name, rgb)) in test_images(w, h).into_iter().enumerate() {
            // both start from the same garbage, so bytes either leaves alone compare too
            let garbage = lcg_bytes(1000 + i as u32, layout.size());
            let (mut want, mut got) = (garbage.clone(), garbage);
            let fc = 3 + i as u32;
            let want_counts = reference::synthesize(&layout, &rgb, &lut, fc, &mut want);
            let got_counts = synthesize(&layout, &rgb, &lut, fc, &mut got);
            assert_eq!(got_counts, want_counts, "{design:?} {name}: counts");
            if let Some(at) = got.iter().zip(&want).position(|(g, w)| g != w) {
                let layer = layout.layers.iter().rposition(|l| l.data_offset <= at);
                panic!("{design:?} {name}: byte {at} (layer {layer:?}) is {} instead of {}", got[at], want[at]);
            }
            for (a, n) in any_counts.iter_mut().zip(want_counts) {
                *a += n;
            }
            let h = layout.layers[0];
            for (k, c) in [band::Y_LH, band::Y_HL, band::Y_HH].into_iter().zip(&mut clipped) {
                *c |= (0..h.height - 1).any(|y| (0..h.width).any(|x| want[layout.pixel_offset(0, k, x, y).unwrap()] == 255));
            }
        }
        assert_eq!(clipped, [true; 3], "{design:?}: the images reach the upper clip of every high-pass band");
        // the images reach every loaded channel except the empty one
        for k in [0, 2, 5, 6] {
            assert!(any_counts[k] > 0, "{design:?} channel {k}: {any_counts:?}");
        }
        assert_eq!(any_counts[3], 0);
    }
}

/// Layer synthesis time per image (run in release:
/// `cargo test --release -p sdk-runtime -- --ignored --nocapture synth_speed`).
#[test]
#[ignore = "benchmark"]
fn synth_speed() {
    let mut r = standing();
    let mut out = Vec::new();
    r.render_image(0, &mut out);
    let rendered = r.camera_rgb().data.clone();
    let layout = r.image_layout();
    let lut = test_lut();
    for (name, rgb) in [("rendered", rendered), ("random", lcg_bytes(7, 416 * 320 * 3))] {
        let n = 300;
        let mut runs: Vec<f64> = (0..9)
            .map(|_| {
                let t = Instant::now();
                for f in 0..n {
                    std::hint::black_box(synthesize(&layout, std::hint::black_box(&rgb), &lut, f, &mut out));
                }
                t.elapsed().as_nanos() as f64 / n as f64
            })
            .collect();
        runs.sort_by(f64::total_cmp);
        println!("synthesize ({name}): median {:.0} ns per image (min {:.0}, max {:.0})", runs[4], runs[0], runs[8]);
    }
}
