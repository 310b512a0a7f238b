//! The layers synthesized from runs of identical pixels are byte for byte those of the
//! per-pixel path: rendered scenes over many head poses, a camera with settings and
//! tables, and made-up images whose runs end at odd columns, last one pixel or fill
//! whole rows.
use super::end_to_end::test_lut;
use super::*;
use crate::render::tests::{random_scene, Lcg};
use crate::render::{camera_pose_from, FlatRuns};
use crate::scene::Posture;

/// Synthesizes `rgb` both ways (from the same garbage) and panics where they differ.
fn compare(what: &str, layout: &ImageLayout, rgb: &[u8], runs: &FlatRuns, min: usize, lut: &CdtLut) {
    let garbage: Vec<u8> = (0..layout.size()).map(|i| (i * 7 + 3) as u8).collect();
    let (mut want, mut got) = (garbage.clone(), garbage);
    let want_counts = synthesize(layout, rgb, lut, 5, &mut want);
    let got_counts = synthesize_runs(layout, rgb, Some((runs, &mut LayerRuns::with_min(min))), lut, 5, &mut got);
    assert_eq!(got_counts, want_counts, "{what}: counts");
    if let Some(at) = got.iter().zip(&want).position(|(g, w)| g != w) {
        let layer = layout.layers.iter().rposition(|l| l.data_offset <= at);
        panic!("{what}: byte {at} (layer {layer:?}) is {} instead of {}", got[at], want[at]);
    }
}

#[test]
fn runs_give_the_layers_of_every_pixel_on_rendered_scenes() {
    let lut = test_lut();
    let mut g = Lcg(7);
    let mut runs = FlatRuns::default();
    let mut rgb = Vec::new();
    let mut copied = 0;
    // a head sweep of the default scene, then random scenes and poses
    let mut cases: Vec<_> = (0..12)
        .map(|i| {
            let p = Posture { pitch: 0.0, roll: 0.0, height_mm: 220.0, paw_contact: [true; 4] };
            let (pan, tilt) = (-1.2 + 0.2 * i as f64, -0.3 + 0.1 * (i % 5) as f64);
            (PinholeCamera::new(Design::Ers7, camera_pose_from(0.0, pan, tilt, &p)), CameraWorld::default(), None)
        })
        .collect();
    cases.extend((0..60).map(|_| random_scene(&mut g)));
    for (i, (cam, world, wall)) in cases.iter().enumerate() {
        let design = if cam.width == 416 { Design::Ers7 } else { Design::Ers210 };
        let layout = ImageLayout::new(design);
        for min in [1, 3, MIN_RUN] {
            cam.render(world, *wall, &mut rgb, Some((&mut runs, 2 * min)));
            compare(&format!("case {i}, runs of {min}"), &layout, &rgb, &runs, min, &lut);
        }
        copied += runs.height();
    }
    assert!(copied > 0);
}

/// An image of `w × h` pixels made of runs: per row, run lengths drawn from `lens` and
/// colours from a small palette, many rows repeating or shifting the row above.
fn made_up(g: &mut Lcg, w: usize, h: usize, lens: &[usize]) -> Vec<u8> {
    let palette = [[40, 150, 70], [235, 235, 235], [250, 90, 160], [70, 70, 78], [41, 150, 70]];
    let mut rgb = Vec::with_capacity(w * h * 3);
    let mut pick = |n: usize| (g.range(0.0, n as f64) as usize).min(n - 1);
    for y in 0..h {
        let row_start = rgb.len();
        match pick(4) {
            // the row above again, or shifted one pixel (runs ending at odd columns)
            0 | 1 if y > 0 => rgb.extend_from_within(row_start - 3 * w..row_start),
            2 if y > 0 => {
                rgb.extend_from_within(row_start - 3 * w + 3..row_start);
                rgb.extend_from_within(row_start - 3..row_start);
            }
            _ => {
                while rgb.len() < row_start + 3 * w {
                    let (n, c) = (lens[pick(lens.len())], palette[pick(palette.len())]);
                    for _ in 0..n.min((row_start + 3 * w - rgb.len()) / 3) {
                        rgb.extend_from_slice(&c);
                    }
                }
            }
        }
    }
    rgb
}

#[test]
fn runs_give_the_layers_of_every_pixel_on_made_up_images() {
    let lut = test_lut();
    let mut g = Lcg(11);
    for design in [Design::Ers7, Design::Ers210] {
        let layout = ImageLayout::new(design);
        let (w, h) = (2 * layout.layers[0].width, 2 * layout.layers[0].height);
        let whole = [w];
        let short = [1, 2, 3, 5];
        let mixed = [1, 2, 7, 16, 17, 33, 64, 129, 200];
        for (name, lens) in [("whole rows", &whole[..]), ("short runs", &short[..]), ("mixed runs", &mixed[..])] {
            for k in 0..4 {
                let rgb = made_up(&mut g, w, h, lens);
                for min in [1, 2, MIN_RUN] {
                    let runs = FlatRuns::scan(&rgb, 3, w, 2 * min);
                    compare(&format!("{design:?} {name} {k}, runs of {min}"), &layout, &rgb, &runs, min, &lut);
                    // runs need not be maximal: every run cut in two
                    let mut cut = FlatRuns::default();
                    cut.clear(1);
                    for y in 0..h {
                        for &(s, e) in runs.row(y) {
                            let mid = ((s + e) / 2) | 1;
                            cut.push(s as usize, mid.min(e) as usize);
                            cut.push(mid.min(e) as usize, e as usize);
                        }
                        cut.end_row();
                    }
                    compare(&format!("{design:?} {name} {k}, cut runs of {min}"), &layout, &rgb, &cut, min, &lut);
                }
            }
        }
    }
}

#[test]
fn a_camera_with_settings_and_tables_gets_the_bytes_of_every_pixel() {
    let mut k = Camera::new(Design::Ers7);
    k.lut = test_lut();
    assert_eq!(k.settings.control(CAM_SET_WHITE_BALANCE, 1), O_SUCCESS);
    let p = Posture { pitch: 0.1, roll: 0.0, height_mm: 200.0, paw_contact: [true; 4] };
    for pan in [-0.5, 0.0, 0.7] {
        let cam = PinholeCamera::new(Design::Ers7, camera_pose_from(-0.2, pan, 0.1, &p));
        k.render_scene(&cam, &CameraWorld::default(), Some(900.0));
        assert!(k.runs_hold, "a render keeps its runs");
        let mut want = vec![0; k.vector_size()];
        k.layout.write_header(&mut want, 7, 1).unwrap();
        let fc = k.field_counter;
        let counts = synthesize(&k.layout, &k.rgb.data, &k.lut, fc, &mut want);
        let mut got = vec![0; k.vector_size()];
        k.build_vector(7, 1, &mut got);
        assert_eq!(k.last_counts, counts);
        assert!(got == want, "pan {pan}");
    }
    k.fill_from(&vec![9; 416 * 320 * 3]);
    assert!(!k.runs_hold, "an outside picture has no runs");
}
