//! The camera's view of the world: a soccer-field scene (green carpet, pink ball,
//! optional white border line and walls), the head camera pose from the joint angles
//! and body posture, and a ray caster that renders the full sensor-resolution RGB image.
//!
//! Why it exists: vision programs (ball tracking, colour detection) need images in which
//! a pink ball appears where geometry puts it and moves the right way when the head
//! turns. The layer synthesis ([`super::camera`]) turns the RGB image into the
//! `OFbkImageVectorData` layers.
//!
//! World frame: x forward (the robot's heading), y to the robot's left, z up, mm; the
//! floor is z = 0 and the midpoint between the front and rear J1 axes stands above the
//! origin (the robot does not move in the world — no odometry).
//!
//! Camera chain (ers7-model 12 and 4.7; reference lines the drawing leaves open are an
//! inference): body origin at the J1-axis height of [`super::scene::posture`], rotated by
//! roll (about x, + = leaning right) and pitch (+ = nose up); neck-tilt1 axis 65 + 2.5 mm
//! ahead of and 19.5 mm above it (front J1 axis = half the 130 mm hip spacing); neck
//! link 80 mm, straight up at tilt1 = 0, tilt1 < 0 leans it forward; pan (+ = left) and
//! tilt2 (+ = nose up) act at the top of the neck; the camera sits 81.06 mm ahead of and
//! 14.6 mm below the tilt2 axis and looks along the head's forward axis. Held in the air
//! ([`super::scene::Scene::lifted`]) the J1 axes are taken as 300 mm high.
//!
//! Pinhole: image column u grows to the camera's right, row v downward, (0, 0) = top
//! left; the horizontal and vertical fields of view of ers7-model 9.1 (ERS-2xx 13.1)
//! span the full image. No lens distortion, vignetting, noise or motion blur.
//!
//! Shading: flat colours; the ball is Lambert-lit from above (70 % ambient) and casts a
//! soft contact shadow; walls are slightly darker than the line colour; whatever is
//! beyond the field (or above its walls) is a dark grey room. The scene's PSD wall
//! (`Scene::wall_mm`, a plane across the robot's heading that many mm ahead of the
//! camera) is drawn as a light grey wall, so camera and distance sensors agree.

use super::kinematics::Body;
use super::model::{Design, Part};
use super::scene::{posture, Posture, Scene};

mod runs;
mod spans;
#[cfg(test)]
mod sweep_tests;

pub use runs::{segments, FlatRuns};

/// A ball lying on the floor.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ball {
    /// Centre position on the floor, mm (world frame).
    pub x_mm: f64,
    pub y_mm: f64,
    pub radius_mm: f64,
    pub rgb: [u8; 3],
}

impl Default for Ball {
    /// The AIBO pink ball (radius 40 mm) 1 m in front of the robot (in the lower
    /// third of the image when standing with the head level).
    fn default() -> Ball {
        Ball { x_mm: 1000.0, y_mm: 0.0, radius_mm: 40.0, rgb: PINK }
    }
}

/// A rectangular field: the carpet ends at its border, a white line runs along the
/// inside of the border and white walls stand on it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FieldBox {
    pub x_min: f64,
    pub x_max: f64,
    pub y_min: f64,
    pub y_max: f64,
    /// Width of the border line, mm (0 = none).
    pub line_mm: f64,
    /// Height of the walls, mm (0 = none).
    pub wall_height_mm: f64,
}

impl Default for FieldBox {
    /// 4 m × 3 m around the robot, 25 mm border line, 100 mm walls.
    fn default() -> FieldBox {
        FieldBox { x_min: -2000.0, x_max: 2000.0, y_min: -1500.0, y_max: 1500.0, line_mm: 25.0, wall_height_mm: 100.0 }
    }
}

pub const PINK: [u8; 3] = [250, 90, 160];
pub const GREEN: [u8; 3] = [40, 150, 70];
pub const WHITE: [u8; 3] = [235, 235, 235];
pub const ROOM: [u8; 3] = [70, 70, 78];
pub const PSD_WALL: [u8; 3] = [200, 200, 195];

/// What the camera sees (part of [`Scene`]).
#[derive(Clone, Debug, PartialEq)]
pub struct CameraWorld {
    pub ball: Option<Ball>,
    /// None = an endless carpet.
    pub field: Option<FieldBox>,
    pub carpet_rgb: [u8; 3],
    pub line_rgb: [u8; 3],
    pub room_rgb: [u8; 3],
}

impl Default for CameraWorld {
    fn default() -> CameraWorld {
        CameraWorld { ball: Some(Ball::default()), field: Some(FieldBox::default()), carpet_rgb: GREEN, line_rgb: WHITE, room_rgb: ROOM }
    }
}

pub type Vec3 = [f64; 3];

fn add(a: Vec3, b: Vec3) -> Vec3 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}
fn sub(a: Vec3, b: Vec3) -> Vec3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
fn scale(a: Vec3, s: f64) -> Vec3 {
    [a[0] * s, a[1] * s, a[2] * s]
}
fn dot(a: Vec3, b: Vec3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// Rotation matrix, row-major.
type Mat3 = [[f64; 3]; 3];

fn mul(a: &Mat3, b: &Mat3) -> Mat3 {
    let mut m = [[0.0; 3]; 3];
    for (i, row) in m.iter_mut().enumerate() {
        for (j, v) in row.iter_mut().enumerate() {
            *v = (0..3).map(|k| a[i][k] * b[k][j]).sum();
        }
    }
    m
}
fn apply(m: &Mat3, v: Vec3) -> Vec3 {
    [dot(m[0], v), dot(m[1], v), dot(m[2], v)]
}
fn rot_x(a: f64) -> Mat3 {
    let (s, c) = a.sin_cos();
    [[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]]
}
fn rot_y(a: f64) -> Mat3 {
    let (s, c) = a.sin_cos();
    [[c, 0.0, s], [0.0, 1.0, 0.0], [-s, 0.0, c]]
}
fn rot_z(a: f64) -> Mat3 {
    let (s, c) = a.sin_cos();
    [[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]]
}

pub const NECK_BASE: Vec3 = [65.0 + 2.5, 0.0, 19.5];
pub const NECK_LENGTH: f64 = 80.0;
pub const CAMERA_OFFSET: Vec3 = [81.06, 0.0, -14.6];
pub const LIFTED_HEIGHT_MM: f64 = 300.0;

/// Where the camera is and where it looks (world frame).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CameraPose {
    pub position: Vec3,
    /// Unit vectors of the camera: optical axis, image-left, image-up.
    pub forward: Vec3,
    pub left: Vec3,
    pub up: Vec3,
}

/// The camera pose for joint angles (rad) and a body posture.
pub fn camera_pose_from(tilt1: f64, pan: f64, tilt2: f64, p: &Posture) -> CameraPose {
    let height = if p.height_mm.is_finite() { p.height_mm } else { LIFTED_HEIGHT_MM };
    // nose-up angles are rotations about +y by the negative angle
    let body = mul(&rot_x(p.roll), &rot_y(-p.pitch));
    let neck = mul(&body, &rot_y(-tilt1));
    let head = mul(&mul(&neck, &rot_z(pan)), &rot_y(-tilt2));
    let base = add([0.0, 0.0, height], apply(&body, NECK_BASE));
    let top = add(base, apply(&neck, [0.0, 0.0, NECK_LENGTH]));
    let position = add(top, apply(&head, CAMERA_OFFSET));
    let col = |j: usize| [head[0][j], head[1][j], head[2][j]];
    CameraPose { position, forward: col(0), left: col(1), up: col(2) }
}

/// The camera pose of `body` standing in `scene`.
pub fn camera_pose(body: &Body, scene: &Scene) -> CameraPose {
    let a = |part| body.angle(part).map_or(0.0, |u| u / 1e6);
    camera_pose_from(a(Part::NeckTilt1), a(Part::NeckPan), a(Part::NeckTilt2), &posture(body, scene))
}

/// Sensor resolution (the double resolution of layer H) and field of view (degrees).
pub fn sensor_spec(design: Design) -> (usize, usize, f64, f64) {
    match design {
        Design::Ers7 => (416, 320, 56.9, 45.2),
        _ => (352, 288, 57.6, 47.8),
    }
}

/// A pinhole camera at a pose.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PinholeCamera {
    pub pose: CameraPose,
    pub width: usize,
    pub height: usize,
    /// tan(half field of view) per half image, i.e. ray slope per pixel.
    pub su: f64,
    pub sv: f64,
}

impl PinholeCamera {
    pub fn new(design: Design, pose: CameraPose) -> PinholeCamera {
        let (w, h, hfov, vfov) = sensor_spec(design);
        let su = (hfov.to_radians() / 2.0).tan() / (w as f64 / 2.0);
        let sv = (vfov.to_radians() / 2.0).tan() / (h as f64 / 2.0);
        PinholeCamera { pose, width: w, height: h, su, sv }
    }

    /// Unnormalised ray direction through image point (u, v) (continuous pixel
    /// coordinates: pixel (i, j) covers [i, i+1) × [j, j+1)).
    pub fn ray(&self, u: f64, v: f64) -> Vec3 {
        let a = -(u - self.width as f64 / 2.0) * self.su;
        let b = -(v - self.height as f64 / 2.0) * self.sv;
        add(self.pose.forward, add(scale(self.pose.left, a), scale(self.pose.up, b)))
    }

    /// Continuous image coordinates of a world point, or None when it is behind the
    /// camera. (May be outside the image.)
    pub fn project(&self, p: Vec3) -> Option<(f64, f64)> {
        let d = sub(p, self.pose.position);
        let z = dot(d, self.pose.forward);
        if z <= 1e-9 {
            return None;
        }
        let a = dot(d, self.pose.left) / z;
        let b = dot(d, self.pose.up) / z;
        Some((self.width as f64 / 2.0 - a / self.su, self.height as f64 / 2.0 - b / self.sv))
    }

    /// Renders `world` (plus the scene's PSD wall at `wall_mm` ahead of the camera)
    /// into `rgb` (`width × height × 3`, row-major, resized if needed). Each row is cut
    /// into spans of one flat colour ([`spans`]): one pixel of a span is cast, the
    /// pixels near an edge and those that may show the ball or its shadow are cast one
    /// by one, so the image is the same as casting every pixel ([`Caster::pixel`]).
    /// `runs` (when given) gets the image's runs of at least `min_run` identical pixels.
    pub fn render(&self, world: &CameraWorld, wall_mm: Option<f64>, rgb: &mut Vec<u8>, runs: Option<(&mut FlatRuns, usize)>) {
        #[cfg(target_arch = "x86_64")]
        if std::arch::is_x86_feature_detected!("avx2") {
            // SAFETY: the CPU has AVX2 (checked just above), all `render_avx2` needs.
            return unsafe { self.render_avx2(world, wall_mm, rgb, runs) };
        }
        self.render_rows(world, wall_mm, rgb, runs)
    }

    /// [`PinholeCamera::render_rows`] compiled for AVX2: the same arithmetic (Rust never
    /// fuses a multiply and an add, square roots and divisions are IEEE's), so the same
    /// bytes, in wider vectors (the fills of flat spans above all).
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    fn render_avx2(&self, world: &CameraWorld, wall_mm: Option<f64>, rgb: &mut Vec<u8>, runs: Option<(&mut FlatRuns, usize)>) {
        self.render_rows(world, wall_mm, rgb, runs)
    }

    /// [`PinholeCamera::render`]'s work, for the code of the CPU at hand.
    #[inline(always)]
    fn render_rows(&self, world: &CameraWorld, wall_mm: Option<f64>, rgb: &mut Vec<u8>, runs: Option<(&mut FlatRuns, usize)>) {
        let (w, h) = (self.width, self.height);
        rgb.resize(w * h * 3, 0);
        let caster = Caster::new(self, world, wall_mm);
        let edges = spans::Edges::new(&caster, self);
        let mut cuts = spans::Cuts::new(&edges);
        let mut palette = spans::Palette::default();
        let mut runs = runs.map(|(r, min_run)| {
            r.clear(min_run);
            r
        });
        // the rows beyond these cannot pass the ball test (its square root and division
        // were ~2 % of an image's time)
        let ball_rows = world.ball.map_or((0, 0), |b| spans::ball_rows(self, &b));
        for (v, row) in rgb.chunks_exact_mut(w * 3).take(h).enumerate() {
            let d0 = self.ray(0.5, v as f64 + 0.5);
            let ball_row = if (ball_rows.0..ball_rows.1).contains(&v) { caster.ball_row(d0) } else { None };
            cuts.find(&caster, &edges, v, d0, ball_row.is_some(), w);
            let pixel = |u| caster.pixel(d0, &ball_row, u);
            match runs.as_deref_mut() {
                Some(r) => {
                    let mut r = runs::RowRuns::new(r);
                    cuts.paint(row, &mut palette, pixel, |a, b, c| r.piece(a, b, c));
                }
                None => cuts.paint(row, &mut palette, pixel, |_, _, _| {}),
            }
        }
    }

    /// [`PinholeCamera::render`] casting every pixel (the definition the spans follow).
    #[cfg(test)]
    pub fn render_every_pixel(&self, world: &CameraWorld, wall_mm: Option<f64>, rgb: &mut Vec<u8>) {
        let (w, h) = (self.width, self.height);
        rgb.resize(w * h * 3, 0);
        let caster = Caster::new(self, world, wall_mm);
        for (v, row) in rgb.chunks_exact_mut(w * 3).take(h).enumerate() {
            let d0 = self.ray(0.5, v as f64 + 0.5);
            let ball_row = caster.ball_row(d0);
            for (u, px) in row.chunks_exact_mut(3).enumerate() {
                px.copy_from_slice(&caster.pixel(d0, &ball_row, u));
            }
        }
    }
}

/// One image's ray casting: the camera, the scene and what every ray of it shares.
pub(crate) struct Caster<'a> {
    world: &'a CameraWorld,
    /// Camera position and the ray step from one pixel of a row to the next.
    c: Vec3,
    du: Vec3,
    psd_wall_x: Option<f64>,
    /// The ball, its centre, camera − centre and |camera − centre|² − r².
    ball: Option<(Ball, Vec3, Vec3, f64)>,
    light: Vec3,
    /// 1 / the ball's radius (worked out once: the same bytes as per pixel).
    inv_r: f64,
}

/// The ball as seen by one row ([`Caster::ball_row`]).
type BallRow = Option<(Ball, Vec3, Vec3, f64)>;

impl<'a> Caster<'a> {
    fn new(cam: &'a PinholeCamera, world: &'a CameraWorld, wall_mm: Option<f64>) -> Caster<'a> {
        let c = cam.pose.position;
        let ball = world.ball.map(|b| {
            let centre = [b.x_mm, b.y_mm, b.radius_mm];
            let oc = sub(c, centre);
            (b, centre, oc, dot(oc, oc) - b.radius_mm * b.radius_mm)
        });
        let light = {
            let l: Vec3 = [0.3, 0.2, 1.0];
            scale(l, 1.0 / dot(l, l).sqrt())
        };
        let inv_r = world.ball.map_or(1.0, |b| 1.0 / b.radius_mm);
        Caster { world, c, du: scale(cam.pose.left, -cam.su), psd_wall_x: wall_mm.map(|m| c[0] + m.max(0.0)), ball, light, inv_r }
    }

    /// The ball if the row whose first ray is `d0` may show it: the plane of the row's
    /// rays (spanned by d0 and du) passes within the radius of the centre.
    fn ball_row(&self, d0: Vec3) -> BallRow {
        self.ball.filter(|(b, centre, _, _)| {
            let n = cross(d0, self.du);
            let nn = dot(n, n).sqrt();
            nn > 0.0 && (dot(n, sub(*centre, self.c)) / nn).abs() <= b.radius_mm
        })
    }

    /// The colour of pixel `u` of the row whose first ray is `d0`.
    /// (`ball_row` by reference: a call per cast pixel copied it whole.)
    fn pixel(&self, d0: Vec3, ball_row: &BallRow, u: usize) -> [u8; 3] {
        let (c, psd_wall_x) = (self.c, self.psd_wall_x);
        let d = add(d0, scale(self.du, u as f64));
        if let Some((b, centre, oc, cc)) = *ball_row {
            let aa = dot(d, d);
            let bb = dot(oc, d);
            let disc = bb * bb - aa * cc;
            if disc >= 0.0 {
                let t = (-bb - disc.sqrt()) / aa;
                if t > 0.0 && psd_wall_x.is_none_or(|x| d[0] <= 0.0 || t < (x - c[0]) / d[0]) {
                    let p = add(c, scale(d, t));
                    let n = scale(sub(p, centre), self.inv_r);
                    return shade(b.rgb, 0.7 + 0.3 * dot(n, self.light).max(0.0));
                }
            }
        }
        self.background(self.world, c, d, psd_wall_x)
    }

    /// Colour of the floor / walls / room along ray `d` from `c` (no ball).
    fn background(&self, world: &CameraWorld, c: Vec3, d: Vec3, psd_wall_x: Option<f64>) -> [u8; 3] {
        let t_floor = if d[2] < 0.0 && c[2] > 0.0 { -c[2] / d[2] } else { f64::INFINITY };
        let t_psd = match psd_wall_x {
            Some(x) if d[0] > 0.0 => (x - c[0]) / d[0],
            _ => f64::INFINITY,
        };
        // the field's walls: the ray leaves the box through the nearest plane ahead
        let (t_box, inside) = match world.field {
            Some(f) => {
                let inside = c[0] > f.x_min && c[0] < f.x_max && c[1] > f.y_min && c[1] < f.y_max;
                let tx = if d[0] > 0.0 {
                    (f.x_max - c[0]) / d[0]
                } else if d[0] < 0.0 {
                    (f.x_min - c[0]) / d[0]
                } else {
                    f64::INFINITY
                };
                let ty = if d[1] > 0.0 {
                    (f.y_max - c[1]) / d[1]
                } else if d[1] < 0.0 {
                    (f.y_min - c[1]) / d[1]
                } else {
                    f64::INFINITY
                };
                (tx.min(ty), inside)
            }
            None => (f64::INFINITY, true),
        };
        if t_psd < t_floor && t_psd < t_box {
            let z = c[2] + d[2] * t_psd;
            return shade(PSD_WALL, if z < 150.0 { 0.9 } else { 1.0 });
        }
        if t_floor <= t_box && inside {
            let p = add(c, scale(d, t_floor));
            let mut rgb = world.carpet_rgb;
            if let Some(f) = world.field {
                let edge = (p[0] - f.x_min).min(f.x_max - p[0]).min(p[1] - f.y_min).min(f.y_max - p[1]);
                if edge < f.line_mm {
                    rgb = world.line_rgb;
                }
            }
            if let Some(b) = world.ball {
                // soft contact shadow under the ball
                let dx = p[0] - b.x_mm;
                let dy = p[1] - b.y_mm;
                let r2 = (dx * dx + dy * dy) / (b.radius_mm * b.radius_mm);
                if r2 < 1.0 {
                    rgb = shade(rgb, 0.55 + 0.45 * r2);
                }
            }
            return rgb;
        }
        if let Some(f) = world.field {
            if inside && t_box.is_finite() {
                let z = c[2] + d[2] * t_box;
                if (0.0..f.wall_height_mm).contains(&z) {
                    return shade(world.line_rgb, 0.85);
                }
            }
        }
        world.room_rgb
    }
}

fn cross(a: Vec3, b: Vec3) -> Vec3 {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

fn shade(rgb: [u8; 3], k: f64) -> [u8; 3] {
    rgb.map(|c| round_byte(c as f64 * k))
}

/// `x.round().clamp(0.0, 255.0) as u8` without libm's `round` (a call on baseline
/// x86-64, ~3 % of an image) nor a conversion there and back (~1/4 of a ball pixel's
/// time): for 0 < x < 255, x + 2⁵² is x rounded to an integer (ties to even; the
/// integer in the low bits of the sum), and x minus that integer is exact, so it is ½
/// just where `round` (half away from zero) rounds up instead.
#[inline(always)]
fn round_byte(x: f64) -> u8 {
    const SHIFT: f64 = (1u64 << 52) as f64;
    if x.is_nan() || x <= 0.0 {
        return 0; // negative, zero or NaN
    }
    if x >= 255.0 {
        return 255;
    }
    let y = x + SHIFT;
    (y.to_bits() as u32 + (x - (y - SHIFT) == 0.5) as u32) as u8
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::model::{RobotModel, POSTURE_PARTS, POSTURE_SLEEP, POSTURE_STAND};

    fn body(posture: &[f64; 18]) -> Body {
        let mut b = Body::new(RobotModel::new(Design::Ers7));
        b.set_posture_deg(&POSTURE_PARTS, posture);
        b
    }

    #[test]
    fn round_byte_is_round_then_clamp() {
        let mut xs = vec![-1.0, -0.5, 0.0, 0.49999999999999994, 0.5, 1.5, 2.5, 254.49999999999997, 254.5, 255.0, 300.0, f64::NAN];
        xs.extend((0..=2_600_000).map(|i| i as f64 * 1e-4));
        // every tie and integer, and the doubles next to them
        for k in 0..=256 {
            for x in [k as f64, k as f64 + 0.5] {
                xs.extend([x, x.next_up(), x.next_down(), x.next_up().next_up(), x.next_down().next_down()]);
            }
        }
        let mut g = Lcg(3);
        xs.extend((0..1_000_000).map(|_| g.range(-1.0, 256.0)));
        for x in xs {
            assert_eq!(round_byte(x), x.round().clamp(0.0, 255.0) as u8, "{x}");
        }
    }

    #[test]
    fn standing_camera_pose_is_plausible() {
        let p = camera_pose(&body(&POSTURE_STAND), &Scene::default());
        // about 22 cm above the floor, well ahead of the body centre, looking level-ish
        assert!((180.0..260.0).contains(&p.position[2]), "{:?}", p.position);
        assert!((120.0..200.0).contains(&p.position[0]), "{:?}", p.position);
        assert!(p.forward[2].abs() < 0.15 && p.forward[0] > 0.95, "{:?}", p.forward);
        assert!(p.left[1] > 0.99);
        let s = camera_pose(&body(&POSTURE_SLEEP), &Scene::default());
        assert!(s.position[2] < p.position[2]);
        // pan left: the optical axis turns toward +y
        let mut b = body(&POSTURE_STAND);
        b.set_posture_deg(&[Part::NeckPan], &[30.0]);
        assert!(camera_pose(&b, &Scene::default()).forward[1] > 0.4);
        // tilt2 up: the optical axis rises
        b.set_posture_deg(&[Part::NeckPan, Part::NeckTilt2], &[0.0, 40.0]);
        assert!(camera_pose(&b, &Scene::default()).forward[2] > 0.2);
    }

    #[test]
    fn project_inverts_ray() {
        let pose = camera_pose(&body(&POSTURE_STAND), &Scene::default());
        let cam = PinholeCamera::new(Design::Ers7, pose);
        for (u, v) in [(0.0, 0.0), (100.5, 37.25), (416.0, 320.0)] {
            let p = add(pose.position, scale(cam.ray(u, v), 500.0));
            let (pu, pv) = cam.project(p).unwrap();
            assert!((pu - u).abs() < 1e-9 && (pv - v).abs() < 1e-9);
        }
        // the image corners span the field of view
        let r = cam.ray(416.0, 160.0);
        let ang = (dot(r, pose.left) / dot(r, pose.forward)).atan().to_degrees();
        assert!((ang + 56.9 / 2.0).abs() < 1e-9);
    }

    /// A small deterministic generator for the scene sweep.
    pub(crate) struct Lcg(pub u64);
    impl Lcg {
        pub(crate) fn next(&mut self) -> f64 {
            self.0 = self.0.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            (self.0 >> 11) as f64 / (1u64 << 53) as f64
        }
        pub(crate) fn range(&mut self, lo: f64, hi: f64) -> f64 {
            lo + (hi - lo) * self.next()
        }
        /// Sometimes exactly `special` (level heads and bodies make rows parallel to edges).
        fn or(&mut self, special: f64, lo: f64, hi: f64) -> f64 {
            if self.next() < 0.3 {
                special
            } else {
                self.range(lo, hi)
            }
        }
    }

    pub(crate) fn random_scene(g: &mut Lcg) -> (PinholeCamera, CameraWorld, Option<f64>) {
        let height = if g.next() < 0.1 { f64::INFINITY } else { g.range(40.0, 350.0) };
        let p = Posture { pitch: g.or(0.0, -0.6, 0.6), roll: g.or(0.0, -0.4, 0.4), height_mm: height, paw_contact: [true; 4] };
        let pose = camera_pose_from(g.or(0.0, -1.4, 0.1), g.or(0.0, -1.6, 1.6), g.or(0.0, -0.3, 0.9), &p);
        let design = if g.next() < 0.8 { Design::Ers7 } else { Design::Ers210 };
        let near = g.next() < 0.3;
        let ball = (g.next() < 0.85).then(|| Ball {
            x_mm: if near { pose.position[0] + g.range(-300.0, 600.0) } else { g.range(-2500.0, 2500.0) },
            y_mm: if near { pose.position[1] + g.range(-300.0, 300.0) } else { g.range(-2000.0, 2000.0) },
            radius_mm: g.range(15.0, 300.0),
            rgb: PINK,
        });
        let field = match g.next() {
            x if x < 0.15 => None,
            x if x < 0.5 => Some(FieldBox::default()),
            _ => {
                let (x0, y0) = (g.range(-3000.0, 100.0), g.range(-3000.0, 100.0));
                let line_mm = [0.0, 25.0, 300.0][(g.next() * 3.0) as usize];
                let wall_height_mm = [0.0, 100.0, 400.0][(g.next() * 3.0) as usize];
                Some(FieldBox { x_min: x0, x_max: x0 + g.range(300.0, 5000.0), y_min: y0, y_max: y0 + g.range(300.0, 5000.0), line_mm, wall_height_mm })
            }
        };
        let world = CameraWorld { ball, field, ..CameraWorld::default() };
        let wall = (g.next() < 0.4).then(|| g.or(0.0, 0.0, 3000.0));
        (PinholeCamera::new(design, pose), world, wall)
    }

    #[test]
    fn spans_give_the_same_image_as_every_pixel() {
        let mut g = Lcg(19);
        let (mut fast, mut slow, mut runs) = (Vec::new(), Vec::new(), FlatRuns::default());
        // the default scene from the standard postures first
        let mut cases: Vec<_> = [POSTURE_STAND, POSTURE_SLEEP]
            .iter()
            .map(|p| (PinholeCamera::new(Design::Ers7, camera_pose(&body(p), &Scene::default())), CameraWorld::default(), None))
            .collect();
        cases.extend((0..400).map(|_| random_scene(&mut g)));
        for (i, (cam, world, wall)) in cases.iter().enumerate() {
            cam.render(world, *wall, &mut fast, Some((&mut runs, 2)));
            cam.render_every_pixel(world, *wall, &mut slow);
            // the runs the renderer records are the image's maximal runs
            assert!(runs == FlatRuns::scan(&fast, 3, cam.width, 2), "case {i}: runs");
            if fast != slow {
                let k = fast.iter().zip(&slow).position(|(a, b)| a != b).unwrap() / 3;
                panic!(
                    "case {i}: pixel ({}, {}) differs: {:?} vs {:?}\n{cam:?}\n{world:?} {wall:?}",
                    k % cam.width,
                    k / cam.width,
                    &fast[3 * k..3 * k + 3],
                    &slow[3 * k..3 * k + 3]
                );
            }
        }
    }
}
