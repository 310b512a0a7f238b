//! Camera and frame figures (issue 19, goals 1 and 2): the host time of one ERS-7 image
//! (the built-in scene and every layer) in this process, beside a copy of an image-sized
//! buffer measured in the same round; whole camera programs at `--speed max` (the head
//! sweeping all the time, so no image repeats), beside the same program without the
//! camera; and the host time of one kinematic frame.
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

use anyhow::{bail, Context, Result};
use sdk_runtime::robot::model::{Design, Part, POSTURE_PARTS, POSTURE_STAND};
use sdk_runtime::robot::VirtualRobot;

use super::stats::Table;

const COPY: &str = "copy of one image vector (memcpy, same size)";

/// Median host time of one image (µs) over `n` images, the head panning by `step_deg`
/// per image (0: held still), and of a plain copy of the vector.
fn image_us(n: u32, step_deg: f64) -> (f64, f64) {
    let mut r = VirtualRobot::new(Design::Ers7);
    r.body_mut().set_posture_deg(&POSTURE_PARTS, &POSTURE_STAND);
    let mut out = vec![0u8; r.image_vector_size()];
    let mut copy = vec![0u8; out.len()];
    let (mut image, mut memcpy) = (Vec::new(), Vec::new());
    for f in 0..n {
        // a sweep between ±40° that turns at the ends
        let pan = 40.0 - (f as f64 * step_deg % 160.0 - 80.0).abs();
        r.body_mut().set_posture_deg(&[Part::NeckPan], &[pan]);
        let t = Instant::now();
        r.render_image_into(f, &mut out);
        image.push(t.elapsed().as_nanos() as f64);
        let t = Instant::now();
        copy.copy_from_slice(std::hint::black_box(&out));
        memcpy.push(t.elapsed().as_nanos() as f64);
        std::hint::black_box(&copy);
    }
    (median(image) / 1000.0, median(memcpy) / 1000.0)
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// Seconds a `--speed max` run of `ms` for `secs` of robot time takes (process included),
/// and its stdout.
fn max_speed_run(exe: &Path, ms: &Path, root: &Path, secs: f64) -> Result<(f64, String)> {
    let t = Instant::now();
    let out = Command::new(exe).args(["run", "-q", "--speed", "max", "--for", &format!("{secs}s"), "--sdk"]).arg(root).arg(ms).output()?;
    if !out.status.success() {
        bail!("{} at --speed max failed: {}", ms.display(), String::from_utf8_lossy(&out.stderr));
    }
    Ok((t.elapsed().as_secs_f64(), String::from_utf8_lossy(&out.stdout).into_owned()))
}

/// Seconds a `--speed max` run of `ms` for `secs` of robot time takes, its start-up (a
/// 0.1 s run) taken off, and its stdout.
fn max_speed_run_net(exe: &Path, ms: &Path, root: &Path, secs: f64) -> Result<(f64, String)> {
    let (long, out) = max_speed_run(exe, ms, root, secs)?;
    let (short, _) = max_speed_run(exe, ms, root, 0.1)?;
    Ok(((long - short).max(1e-6), out))
}

/// `base` (a built MS tree) with camwatch's object added (it takes every image, and reads
/// its pixels unless `pixels` is false), made in `work/name`.
pub fn with_camwatch(base: &Path, camwatch: &Path, work: &Path, name: &str, pixels: bool) -> Result<PathBuf> {
    let dst = work.join(name).join("MS");
    let _ = std::fs::remove_dir_all(&dst);
    std::fs::create_dir_all(work.join(name))?;
    let st = Command::new("cp").arg("-r").arg(base).arg(&dst).status()?;
    if !st.success() {
        bail!("cannot copy {}", base.display());
    }
    let (from, to) = (camwatch.join("OPEN-R/MW"), dst.join("OPEN-R/MW"));
    std::fs::copy(from.join("OBJS/WATCH.BIN"), to.join("OBJS/WATCH.BIN"))?;
    for cfg in ["CONF/OBJECT.CFG", "CONF/CONNECT.CFG"] {
        let mut text = std::fs::read_to_string(to.join(cfg)).with_context(|| format!("{cfg} of {}", base.display()))?;
        text.push_str(&std::fs::read_to_string(from.join(cfg))?);
        std::fs::write(to.join(cfg), text)?;
    }
    if !pixels {
        std::fs::write(dst.join("NOPIXEL"), "camwatch: take each image, read none of its pixels\n")?;
    }
    Ok(dst)
}

/// The MS trees the figures run.
pub struct Programs<'a> {
    pub camwatch: &'a Path,
    /// headsweep: the head never stops, so every image is new.
    pub headsweep: &'a Path,
    /// headsweep + camwatch.
    pub camsweep: &'a Path,
    /// headsweep + camwatch reading no pixel.
    pub camsweep_nopixel: &'a Path,
    /// headsweep + camwatch compiled without the alignment trap.
    pub camsweep_notrap: &'a Path,
    /// headsweep + camwatch with gcc's own alignment check instead of the plugin's
    /// (empty when the SDK root has no plugin: the default build is that one then).
    pub camsweep_ubsan: &'a Path,
    pub movelegs: &'a Path,
}

/// Images camwatch reports having read (`BENCH watch images=N`), if it printed them.
fn images_read(out: &str) -> Option<f64> {
    super::fields(out, "BENCH watch").into_iter().find(|(k, _)| k == "images").map(|(_, v)| v)
}

pub fn camera(exe: &Path, root: &Path, p: &Programs, tab: &mut Table) -> Result<()> {
    let (moving, copy) = image_us(300, 3.0);
    let (still, _) = image_us(300, 0.0);
    tab.push("camera image, head moving: scene + all layers (in process)", moving, "µs", Some(COPY));
    tab.push("camera image, head still (in process)", still, "µs", Some(COPY));
    tab.push(COPY, copy, "µs", None);

    // Whole programs: 60 s of robot time with the head sweeping all along (every image
    // new), with and without the camera, start-up taken off.
    const SWEEP_S: f64 = 60.0;
    let (without, _) = max_speed_run_net(exe, p.headsweep, root, SWEEP_S)?;
    // A camsweep variant: its seconds, and its host time per image read beyond headsweep's (ms).
    let sweep = |ms: &Path| -> Result<(f64, f64)> {
        let (secs, out) = max_speed_run_net(exe, ms, root, SWEEP_S)?;
        let images = images_read(&out).filter(|&n| n > 0.0).unwrap_or(30.0 * SWEEP_S);
        Ok((secs, (secs - without).max(0.0) / images * 1e3))
    };
    let (with, per_image) = sweep(p.camsweep)?;
    const NO_CAMERA: &str = "headsweep alone at --speed max (60 s, start-up taken off, no camera)";
    tab.push(
        "camsweep: camera program, head sweeping (headsweep + camwatch as built by default) at --speed max, 60 s, start-up taken off",
        SWEEP_S / with,
        "×",
        Some(NO_CAMERA),
    );
    tab.push(NO_CAMERA, SWEEP_S / without, "×", None);
    tab.push("host time per camera image, head sweeping ((camsweep − headsweep alone) / images read)", per_image, "ms", None);
    // The same with camwatch reading no pixel: what is left is the runtime's share of an
    // image (scene, layers, the hand-offs that deliver it), not the program's loop.
    let (_, per_image) = sweep(p.camsweep_nopixel)?;
    tab.push("host time per camera image, the runtime's share (camsweep with camwatch reading no pixel − headsweep alone)", per_image, "ms", None);
    // camwatch built with the other alignment traps: (program, how built, per-image row).
    let variants = [
        (p.camsweep_notrap, "built without the alignment trap (OPENR_ALIGNMENT_TRAP=0)", "without the alignment trap"),
        (p.camsweep_ubsan, "on gcc's own alignment check, not the plugin's (OPENR_ALIGNMENT_TRAP=ubsan)", "on gcc's own alignment check"),
    ];
    // (One not built is left out: see run_all.)
    for (ms, built, short) in variants.into_iter().filter(|v| !v.0.as_os_str().is_empty()) {
        let (secs, per_image) = sweep(ms)?;
        tab.push(&format!("camsweep with camwatch {built} at --speed max, 60 s, start-up taken off"), SWEEP_S / secs, "×", Some(NO_CAMERA));
        tab.push(&format!("host time per camera image, camwatch {short}"), per_image, "ms", None);
    }
    let (still, _) = max_speed_run(exe, p.camwatch, root, 60.0)?;
    tab.push("camera program, head still (camwatch) at --speed max, 60 s", 60.0 / still, "×", None);
    Ok(())
}

/// Kinematic frames: movelegs at `--speed max`, per 8 ms frame of robot time (process
/// start included, measured by a 0.1 s run and taken off).
pub fn frames(exe: &Path, root: &Path, p: &Programs, tab: &mut Table, reference: &str) -> Result<()> {
    let (long, _) = max_speed_run(exe, p.movelegs, root, 60.0)?;
    let (short, _) = max_speed_run(exe, p.movelegs, root, 0.1)?;
    tab.push("movelegs: virtual-time speed-up at --speed max (60 s of robot time)", 60.0 / long, "×", None);
    tab.push("movelegs: host time per 8 ms frame at --speed max (start-up taken off)", (long - short).max(0.0) / 7500.0 * 1e6, "µs", Some(reference));
    Ok(())
}
