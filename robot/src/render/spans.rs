//! Which pixels of a row must be cast one by one, and which share one flat colour.
//!
//! Every choice [`Caster::pixel`] makes for a ray d (floor or not, which wall face, inside
//! the line, below the wall's top, behind the PSD wall, …) is the sign of a linear form
//! n·d, except the ball and its shadow (quadratic in d). Along a row d = d0 + u·du is
//! linear in the pixel index u, so each form changes sign at most once, at a point found
//! by one division. Pixels where some form is within a tiny relative margin of zero
//! (1e-9 of its size: far beyond the rounding of the per-pixel arithmetic, so the
//! per-pixel code decides every other pixel exactly as the true sign does) and pixels
//! that may show the ball or the shadow are cast one by one; between them every choice
//! is the same for all pixels, so the colour is one flat colour, cast once and copied.
//! A form counts only where the choices it feeds are reachable (a line on the floor
//! only where the ray goes down, a wall face only where the ray goes towards it):
//! otherwise the far side of the camera would cut rows for nothing.
//! `tests::spans_give_the_same_image_as_every_pixel` checks the result against casting
//! every pixel over many poses and scenes.
use super::{dot, sub, Caster, Vec3};

/// Relative margin of a sign: |n·d| ≤ MARGIN·|n|·|d| counts as "maybe zero".
const MARGIN: f64 = 1e-9;

const EX: Vec3 = [1.0, 0.0, 0.0];
const EY: Vec3 = [0.0, 1.0, 0.0];
const EZ: Vec3 = [0.0, 0.0, 1.0];

/// A linear form whose sign is a choice of the per-pixel code, and where it counts: where
/// each `when` axis (0 = x, 1 = y, 2 = z of the ray) may have the sign s.
struct Form {
    norm: f64,
    when: [Option<(usize, f64)>; 2],
    /// n·d for the first ray of row 0, its change per row and per pixel.
    a0: f64,
    a1: f64,
    b: f64,
    /// The rows outside `rows.0..rows.1` keep one sign all along ([`Form::keeps_sign`]).
    rows: (usize, usize),
}

impl Form {
    /// n·d at the first pixel of row `v`, and the margin of its sign.
    #[inline(always)]
    fn start(&self, v: f64, size: f64) -> (f64, f64) {
        (self.a0 + v * self.a1, MARGIN * self.norm * size)
    }

    /// Whether the form keeps one sign beyond the margin over the whole of row `v`
    /// (`w` pixels), as it does on most rows.
    #[inline(always)]
    fn keeps_sign(&self, v: f64, w: f64, size: f64) -> bool {
        let (a, m) = self.start(v, size);
        let z = a + w * self.b;
        (a > m && z > m) || (a < -m && z < -m)
    }

    /// The rows of 0..height on which [`Form::keeps_sign`] may be false. Along v the
    /// form at both ends of a row moves by the same a1, and the rounded sums are
    /// monotonic in v, so "positive at both ends" holds on a run of rows reaching one
    /// end of the image and "negative at both ends" on one reaching the other: the
    /// rows between are found by two bisections (instead of a test on every row).
    fn rows(&self, height: usize, w: f64, size: f64) -> (usize, usize) {
        if !self.a1.is_finite() || self.a1 == 0.0 {
            return (0, height);
        }
        let both = |v: usize, sign: f64| {
            let (a, m) = self.start(v as f64, size);
            let z = a + w * self.b;
            sign * a > m && sign * z > m
        };
        // the sign held at the top rows, then the one at the bottom rows
        let (top, bottom) = if self.a1 > 0.0 { (-1.0, 1.0) } else { (1.0, -1.0) };
        // first row not in the top run, first row of the bottom run
        let lo = first(height, |v| !both(v, top));
        let hi = first(height, |v| both(v, bottom));
        (lo, hi.max(lo))
    }
}

/// The first v of 0..n for which `p` holds (n if none), `p` false up to some v and true
/// from there on.
fn first(n: usize, p: impl Fn(usize) -> bool) -> usize {
    let (mut lo, mut hi) = (0, n);
    while lo < hi {
        let mid = lo + (hi - lo) / 2;
        if p(mid) {
            hi = mid;
        } else {
            lo = mid + 1;
        }
    }
    lo
}

/// The forms of one image (camera position and scene fixed).
pub(super) struct Edges {
    forms: Vec<Form>,
    /// Forms whose squares make the shadow: x and y on the floor relative to the ball
    /// (times the ray's downward component).
    shadow: Option<(Vec3, Vec3, f64)>,
    /// A bound of |d| over the image: |d0| + width·|du|.
    size: f64,
}

impl Edges {
    pub(super) fn new(k: &Caster, cam: &super::PinholeCamera) -> Edges {
        let c = k.c;
        let first = cam.ray(0.5, 0.5);
        let dv = sub(cam.ray(0.5, 1.5), first);
        let last = cam.ray(0.5, cam.height as f64 - 0.5);
        let size = dot(first, first).sqrt().max(dot(last, last).sqrt()) + cam.width as f64 * dot(k.du, k.du).sqrt();
        let mut forms = Vec::new();
        let (height, w) = (cam.height, cam.width as f64);
        let mut push = |n: Vec3, when: [Option<(usize, f64)>; 2]| {
            let mut f = Form { norm: dot(n, n).sqrt(), when, a0: dot(n, first), a1: dot(n, dv), b: dot(n, k.du), rows: (0, height) };
            f.rows = f.rows(height, w, size);
            forms.push(f)
        };
        // Floor or not, and the x/y direction (wall faces, the PSD wall).
        push(EZ, [None, None]);
        push(EX, [None, None]);
        push(EY, [None, None]);
        let down = Some((2, -1.0));
        if let Some(f) = k.world.field {
            let h = f.wall_height_mm;
            for (a, inner, s) in [(f.x_min, f.x_min + f.line_mm, -1.0), (f.x_max, f.x_max - f.line_mm, 1.0)] {
                let face = Some((0, s));
                // the field's edge on the floor, also the foot of the wall
                push([-c[2], 0.0, c[0] - a], [down, None]);
                push([-c[2], 0.0, c[0] - a], [face, None]);
                push([c[2] - h, 0.0, a - c[0]], [face, None]);
                push([-c[2], 0.0, c[0] - inner], [down, None]);
            }
            for (a, inner, s) in [(f.y_min, f.y_min + f.line_mm, -1.0), (f.y_max, f.y_max - f.line_mm, 1.0)] {
                let face = Some((1, s));
                push([0.0, -c[2], c[1] - a], [down, None]);
                push([0.0, -c[2], c[1] - a], [face, None]);
                push([0.0, c[2] - h, a - c[1]], [face, None]);
                push([0.0, -c[2], c[1] - inner], [down, None]);
            }
            // which face a ray leaves the field through
            for (xf, sx) in [(f.x_min, -1.0), (f.x_max, 1.0)] {
                for (yf, sy) in [(f.y_min, -1.0), (f.y_max, 1.0)] {
                    push([-(yf - c[1]), xf - c[0], 0.0], [Some((0, sx)), Some((1, sy))]);
                }
            }
        }
        if let Some(x) = k.psd_wall_x {
            let ahead = Some((0, 1.0));
            push([c[2], 0.0, x - c[0]], [ahead, down]);
            push([c[2] - 150.0, 0.0, x - c[0]], [ahead, None]);
            if let Some(f) = k.world.field {
                for (yf, sy) in [(f.y_min, -1.0), (f.y_max, 1.0)] {
                    push([-(yf - c[1]), x - c[0], 0.0], [ahead, Some((1, sy))]);
                }
            }
        }
        let shadow = k.world.ball.map(|b| ([-c[2], 0.0, c[0] - b.x_mm], [0.0, -c[2], c[1] - b.y_mm], b.radius_mm));
        Edges { forms, shadow, size }
    }
}

/// An interval of the row's pixel index (real numbers; may be empty or unbounded).
#[derive(Clone, Copy, Debug)]
struct Span(f64, f64);

impl Span {
    const ALL: Span = Span(f64::NEG_INFINITY, f64::INFINITY);

    fn and(self, o: Span) -> Span {
        Span(self.0.max(o.0), self.1.min(o.1))
    }

    fn is_empty(self) -> bool {
        !matches!(self.0.partial_cmp(&self.1), Some(std::cmp::Ordering::Less | std::cmp::Ordering::Equal))
    }
}

/// Where |a + b·u| ≤ m.
fn near_zero(a: f64, b: f64, m: f64) -> Span {
    if b == 0.0 {
        return if a.abs() <= m { Span::ALL } else { Span(1.0, 0.0) };
    }
    let (u1, u2) = ((-a - m) / b, (-a + m) / b);
    Span(u1.min(u2), u1.max(u2))
}

/// Where s·(a + b·u) ≥ −m.
fn may_have_sign(a: f64, b: f64, s: f64, m: f64) -> Span {
    let (a, b) = (s * a, s * b);
    if b == 0.0 {
        return if a >= -m { Span::ALL } else { Span(1.0, 0.0) };
    }
    let u0 = (-m - a) / b;
    if b > 0.0 {
        Span(u0, f64::INFINITY)
    } else {
        Span(f64::NEG_INFINITY, u0)
    }
}

/// Where p2·u² + p1·u + p0 ≥ 0: up to two spans.
fn quadratic_ge0(p2: f64, p1: f64, p0: f64) -> [Span; 2] {
    const NONE: Span = Span(1.0, 0.0);
    if p2 == 0.0 {
        return [may_have_sign(p0, p1, 1.0, 0.0), NONE];
    }
    let disc = p1 * p1 - 4.0 * p2 * p0;
    if disc < 0.0 {
        return [if p2 > 0.0 { Span::ALL } else { NONE }, NONE];
    }
    // the stable pair of roots
    let q = -0.5 * (p1 + p1.signum() * disc.sqrt());
    let (mut r1, mut r2) = (q / p2, if q != 0.0 { p0 / q } else { 0.0 });
    if r1 > r2 {
        std::mem::swap(&mut r1, &mut r2);
    }
    if p2 > 0.0 {
        [Span(f64::NEG_INFINITY, r1), Span(r2, f64::INFINITY)]
    } else {
        [Span(r1, r2), NONE]
    }
}

/// The pixels of one row to cast one by one: half-open index ranges, sorted (an empty
/// range ends a flat span without casting a pixel).
#[derive(Default)]
pub(super) struct Cuts {
    ranges: Vec<(usize, usize)>,
    width: usize,
}

impl Cuts {
    /// Finds the pixels of row `v` (whose first ray is `d0`; `ball`: the ball may show
    /// in it) that cannot share a span's colour.
    pub(super) fn find(&mut self, k: &Caster, e: &Edges, v: usize, d0: Vec3, ball: bool, width: usize) {
        self.ranges.clear();
        self.width = width;
        let (du, size) = (k.du, e.size);
        let form = |n: Vec3| (dot(n, d0), dot(n, du));
        // where the ray's x, y, z may be negative / positive
        let signs: [[Span; 2]; 3] = std::array::from_fn(|axis| {
            let (a, b) = (d0[axis], du[axis]);
            [may_have_sign(a, b, -1.0, MARGIN * size), may_have_sign(a, b, 1.0, MARGIN * size)]
        });
        let v = v as f64;
        let w = width as f64;
        let row = v as usize;
        for f in &e.forms {
            // most forms keep one sign over the whole row
            if !(f.rows.0..f.rows.1).contains(&row) || f.keeps_sign(v, w, size) {
                continue;
            }
            let (a, m) = f.start(v, size);
            let mut s = near_zero(a, f.b, m);
            for &(axis, sign) in f.when.iter().flatten() {
                s = s.and(signs[axis][(sign > 0.0) as usize]);
            }
            self.add(s, 0.0);
        }
        if let (true, Some((_, _, oc, cc))) = (ball, k.ball) {
            if cc <= 0.0 {
                self.add(Span::ALL, 0.0);
            } else {
                // disc(u) = (oc·d)² − |d|²·cc ≥ 0 where the ball is in front (oc·d < 0)
                let (b0, b1) = form(oc);
                let (a0, a1, a2) = (dot(d0, d0), dot(d0, du), dot(du, du));
                let m = MARGIN * ((b0.abs() + width as f64 * b1.abs()).powi(2) + cc * size * size);
                let front = may_have_sign(b0, b1, -1.0, MARGIN * dot(oc, oc).sqrt() * size);
                for s in quadratic_ge0(b1 * b1 - cc * a2, 2.0 * (b0 * b1 - cc * a1), b0 * b0 - cc * a0 + m) {
                    self.add(s.and(front), 1.0);
                }
            }
        }
        if let Some((nx, ny, r)) = e.shadow {
            // the floor point within the radius of the ball's centre: qx² + qy² < r²·dz²
            let ((x0, x1), (y0, y1), (z0, z1)) = (form(nx), form(ny), (d0[2], du[2]));
            let m = MARGIN * (dot(nx, nx) + dot(ny, ny) + r * r) * size * size;
            let (r2, p2, p1, p0) = (r * r, x1 * x1 + y1 * y1, 2.0 * (x0 * x1 + y0 * y1), x0 * x0 + y0 * y0);
            for s in quadratic_ge0(r2 * z1 * z1 - p2, 2.0 * r2 * z0 * z1 - p1, r2 * z0 * z0 - p0 + m) {
                self.add(s.and(signs[2][0]), 1.0);
            }
        }
        self.ranges.sort_unstable();
    }

    /// Adds the pixels of `s` (widened by `pad` pixels) that lie in the row, as a
    /// half-open range; a span between two pixels still ends the flat span there.
    #[inline]
    fn add(&mut self, s: Span, pad: f64) {
        // a NaN bound (a degenerate form) cuts the whole row
        let s = if s.0.is_nan() || s.1.is_nan() { Span::ALL } else { s };
        if s.is_empty() {
            return;
        }
        let w = self.width as f64;
        // ⌈lo⌉ and ⌊hi⌋ + 1 of values clamped to 0..=w (no libm call on baseline x86-64)
        let lo = (s.0 - pad - 1e-6).clamp(0.0, w);
        let lo = lo as usize + ((lo as usize as f64) < lo) as usize;
        let hi = ((s.1 + pad + 1e-6).clamp(0.0, w) as usize + 1).clamp(lo, self.width);
        // an empty range at either end of the row ends nothing
        if lo < hi || (lo > 0 && lo < self.width) {
            self.ranges.push((lo, hi));
        }
    }

    /// Writes the row: the cut pixels cast one by one, each span between them filled
    /// with the colour of its first pixel. `piece(a, b, colour)` is told of every span
    /// and pixel in order.
    pub(super) fn paint(&self, row: &mut [u8], pixel: impl Fn(usize) -> [u8; 3], mut piece: impl FnMut(usize, usize, [u8; 3])) {
        let mut next = 0;
        for &(lo, hi) in &self.ranges {
            if lo > next {
                let c = pixel(next);
                fill(&mut row[3 * next..3 * lo], c);
                piece(next, lo, c);
                next = lo;
            }
            for u in next..hi {
                let c = pixel(u);
                row[3 * u..3 * u + 3].copy_from_slice(&c);
                piece(u, u + 1, c);
            }
            next = next.max(hi);
        }
        if next < self.width {
            let c = pixel(next);
            fill(&mut row[3 * next..3 * self.width], c);
            piece(next, self.width, c);
        }
    }
}

/// Fills `px` (whole RGB pixels) with one colour, 16 pixels per copy.
fn fill(px: &mut [u8], c: [u8; 3]) {
    // the 24-byte period of the colour as three words (16 three-byte copies cost more)
    let x = u64::from(c[0]) | u64::from(c[1]) << 8 | u64::from(c[2]) << 16;
    let words = [x | x << 24 | x << 48, x >> 16 | x << 8 | x << 32 | x << 56, x >> 8 | x << 16 | x << 40];
    let mut block = [0u8; 48];
    for (b, w) in block.chunks_exact_mut(8).zip(words.iter().cycle()) {
        b.copy_from_slice(&w.to_le_bytes());
    }
    let mut chunks = px.chunks_exact_mut(48);
    for ch in &mut chunks {
        ch.copy_from_slice(&block);
    }
    let rest = chunks.into_remainder();
    let n = rest.len();
    rest.copy_from_slice(&block[..n]);
}
