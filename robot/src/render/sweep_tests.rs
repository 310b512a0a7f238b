//! The renderer against casting every pixel over head sweeps of the built-in scene: many
//! images of one world from poses close to each other, where flat spans of one image
//! share colours by key ([`super::spans::Palette`]) across rows and edges move a little
//! from one image to the next.
use super::tests::Lcg;
use super::*;

fn check(i: usize, cam: &PinholeCamera, world: &CameraWorld, wall: Option<f64>, fast: &mut Vec<u8>, slow: &mut Vec<u8>, runs: &mut FlatRuns) {
    cam.render(world, wall, fast, Some((runs, 2)));
    cam.render_every_pixel(world, wall, slow);
    assert!(*runs == FlatRuns::scan(fast, 3, cam.width, 2), "image {i}: runs");
    // the baseline x86-64 code too (`render` takes the AVX2 one where the CPU has it)
    let (mut base, mut base_runs) = (Vec::new(), FlatRuns::default());
    cam.render_rows(world, wall, &mut base, Some((&mut base_runs, 2)));
    assert!(base == *fast && base_runs == *runs, "image {i}: baseline code");
    if fast != slow {
        let k = fast.iter().zip(slow.iter()).position(|(a, b)| a != b).unwrap() / 3;
        panic!("image {i}: pixel ({}, {}) differs\n{cam:?}\n{world:?} {wall:?}", k % cam.width, k / cam.width);
    }
}

#[test]
fn head_sweeps_give_the_same_image_as_every_pixel() {
    let (mut fast, mut slow, mut runs) = (Vec::new(), Vec::new(), FlatRuns::default());
    let mut g = Lcg(23);
    let mut i = 0;
    for sweep in 0..8 {
        // a posture, a ball (sometimes on the line or under the camera) and a PSD wall
        let p = Posture { pitch: g.range(-0.2, 0.2), roll: g.range(-0.1, 0.1), height_mm: g.range(90.0, 300.0), paw_contact: [true; 4] };
        let mut world = CameraWorld::default();
        if let Some(b) = world.ball.as_mut() {
            (b.x_mm, b.y_mm) = match sweep % 4 {
                0 => (1000.0, 0.0),
                1 => (1990.0, g.range(-800.0, 800.0)),
                2 => (g.range(200.0, 500.0), g.range(-200.0, 200.0)),
                _ => (g.range(-1900.0, 1900.0), 1480.0),
            };
        }
        let wall = (sweep % 3 == 2).then(|| g.range(100.0, 1500.0));
        let (tilt1, tilt2) = (g.range(-0.8, 0.0), g.range(-0.3, 0.8));
        for step in 0..24 {
            let pan = -1.6 + 3.2 * step as f64 / 23.0;
            let cam = PinholeCamera::new(Design::Ers7, camera_pose_from(tilt1, pan, tilt2 + 0.01 * step as f64, &p));
            check(i, &cam, &world, wall, &mut fast, &mut slow, &mut runs);
            i += 1;
        }
    }
}

/// No row outside [`super::spans::ball_rows`] passes the per-row ball test (the renderer
/// skips the test there; casting every pixel does not).
#[test]
fn ball_rows_hold_every_row_the_ball_test_passes() {
    let mut g = Lcg(31);
    let mut seen = 0;
    for i in 0..3000 {
        let (cam, world, wall) = super::tests::random_scene(&mut g);
        let Some(b) = world.ball else { continue };
        let caster = Caster::new(&cam, &world, wall);
        let (lo, hi) = super::spans::ball_rows(&cam, &b);
        for v in (0..cam.height).filter(|v| !(lo..hi).contains(v)) {
            assert!(caster.ball_row(cam.ray(0.5, v as f64 + 0.5)).is_none(), "scene {i}, row {v} outside {lo}..{hi}");
        }
        seen += (hi - lo < cam.height) as usize;
    }
    assert!(seen > 100, "{seen} scenes with a narrower range");
}
