//! One ERS-7 camera image after another with the head panning (as `cargo openr bench`'s
//! in-process camera figure), for a profiler: `perf record target/release/examples/image_prof 3000`.
//! Prints the median host time of one image.
use openr_robot::model::{Design, Part, POSTURE_PARTS, POSTURE_STAND};
use openr_robot::VirtualRobot;
fn main() {
    let n: u32 = std::env::args().nth(1).and_then(|a| a.parse().ok()).unwrap_or(3000);
    let mut r = VirtualRobot::new(Design::Ers7);
    r.body_mut().set_posture_deg(&POSTURE_PARTS, &POSTURE_STAND);
    let mut out = vec![0u8; r.image_vector_size()];
    let mut times = Vec::new();
    for f in 0..n {
        let pan = 40.0 - (f as f64 * 3.0 % 160.0 - 80.0).abs();
        r.body_mut().set_posture_deg(&[Part::NeckPan], &[pan]);
        let t = std::time::Instant::now();
        r.render_image_into(f, &mut out);
        times.push(t.elapsed().as_nanos() as f64 / 1000.0);
    }
    times.sort_by(f64::total_cmp);
    println!("median {:.1} µs  min {:.1}", times[times.len() / 2], times[0]);
}
