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
//! A flat span's colour follows from the signs of the forms at it ([`Cuts::key`]), so
//! it is cast once per image and key ([`Palette`]), and spans of one colour are filled
//! at once. Rows are walked top down: each form is looked at only on the rows where it
//! may change sign along a row ([`Form::rows`]).
//! `tests::spans_give_the_same_image_as_every_pixel` and `sweep_tests` check the result
//! against casting every pixel over many poses and scenes.
use super::{dot, sub, Caster, Vec3};

/// Relative margin of a sign: |n·d| ≤ MARGIN·|n|·|d| counts as "maybe zero".
const MARGIN: f64 = 1e-9;

const EX: Vec3 = [1.0, 0.0, 0.0];
const EY: Vec3 = [0.0, 1.0, 0.0];
const EZ: Vec3 = [0.0, 0.0, 1.0];

/// A linear form whose sign is a choice of the per-pixel code, and where it counts: where
/// each `when` axis (0 = x, 1 = y, 2 = z of the ray) may have the sign s.
struct Form {
    /// MARGIN·|n|·size: the margin of the sign.
    margin: f64,
    when: [Option<(usize, f64)>; 2],
    /// This form's bit of a span's key ([`Cuts::key`]).
    bit: u64,
    /// n·d for the first ray of row 0, its change per row and per pixel.
    a0: f64,
    a1: f64,
    b: f64,
    inv_b: f64,
    /// The `when` conditions as bits (2·axis + 1 for positive), and the pixel where the
    /// form is zero along row v, p + v·q, with the margin in pixels (`walk`: when that
    /// is exact enough, |p| and |q|·height well below 1/ε; else [`near_zero`]).
    need: u8,
    p: f64,
    q: f64,
    mw: f64,
    walk: bool,
    /// The rows outside `rows.0..rows.1` keep one sign all along ([`Form::row_sign`]).
    rows: (usize, usize),
}

impl Form {
    /// n·d at the first pixel of row `v`, and the margin of its sign.
    #[inline(always)]
    fn start(&self, v: f64) -> (f64, f64) {
        (self.a0 + v * self.a1, self.margin)
    }

    /// n·d at the first pixel of row `v`, and the sign (true: positive) when the form
    /// keeps one beyond the margin over the whole row (`w` pixels), as on most rows.
    #[inline(always)]
    fn row_sign(&self, v: f64, w: f64) -> (f64, Option<bool>) {
        let (a, m) = self.start(v);
        let z = a + w * self.b;
        (
            a,
            if a > m && z > m {
                Some(true)
            } else if a < -m && z < -m {
                Some(false)
            } else {
                None
            },
        )
    }

    /// The rows of 0..height on which [`Form::row_sign`] may be None. Along v the
    /// form at both ends of a row moves by the same a1, and the rounded sums are
    /// monotonic in v, so "positive at both ends" holds on a run of rows reaching one
    /// end of the image and "negative at both ends" on one reaching the other: the
    /// rows between are found from where the sums cross ±m (checked by the test itself,
    /// instead of a test on every row).
    fn rows(&self, height: usize, w: f64) -> (usize, usize) {
        if !self.a1.is_finite() || self.a1 == 0.0 {
            return (0, height);
        }
        let both = |v: usize, sign: f64| {
            let (a, m) = self.start(v as f64);
            let z = a + w * self.b;
            sign * a > m && sign * z > m
        };
        // the rows where the form at either end of a row is s·m
        let at = |s: f64| [(s * self.margin - self.a0) / self.a1, (s * self.margin - self.a0 - w * self.b) / self.a1];
        // the sign held at the top rows, then the one at the bottom rows
        let (top, bottom) = if self.a1 > 0.0 { (-1.0, 1.0) } else { (1.0, -1.0) };
        // first row not in the top run, first row of the bottom run
        let [t0, t1] = at(top);
        let lo = first_from(height, t0.min(t1), |v| !both(v, top));
        let [b0, b1] = at(bottom);
        let hi = first_from(height, b0.max(b1), |v| both(v, bottom));
        (lo, hi.max(lo))
    }
}

/// [`first`] from a guess of where `p` turns true: a step or two from it when the guess
/// is good, a bisection otherwise (the branches of a bisection per form were ~3 % of an
/// image's time).
fn first_from(n: usize, guess: f64, p: impl Fn(usize) -> bool) -> usize {
    let mut v = if guess > 0.0 { (guess.min(n as f64) as usize).min(n) } else { 0 };
    for _ in 0..4 {
        if v > 0 && p(v - 1) {
            v -= 1;
        } else if v < n && !p(v) {
            v += 1;
        } else {
            return v;
        }
    }
    first(n, p)
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
    /// The rows that may show the shadow.
    shadow_rows: (usize, usize),
    /// A bound of |d| over the image: |d0| + width·|du|.
    size: f64,
    /// 1 / each axis of the ray's step along a row.
    inv_du: Vec3,
    /// The forms by the row from which they may change sign along a row, and by the row
    /// from which they no longer do ([`Form::rows`]).
    enter: Vec<(usize, usize)>,
    leave: Vec<(usize, usize)>,
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
            let bit = 1 << forms.len();
            let margin = MARGIN * dot(n, n).sqrt() * size;
            let (a0, a1, b) = (dot(n, first), dot(n, dv), dot(n, k.du));
            let need = when.iter().flatten().fold(0, |m, &(axis, sign)| m | 1 << (2 * axis + (sign > 0.0) as usize));
            let (inv_b, h) = (1.0 / b, height as f64);
            let (p, q) = (-a0 * inv_b, -a1 * inv_b);
            let walk = b != 0.0 && p.abs() < 1e7 && (q * h).abs() < 1e7;
            let mut f = Form { margin, when, bit, a0, a1, b, inv_b, need, p, q, mw: margin * inv_b.abs(), walk, rows: (0, height) };
            f.rows = f.rows(height, w);
            forms.push(f)
        };
        // Floor or not, and the x/y direction (wall faces, the PSD wall); first, for
        // [`Cuts::find`].
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
        let shadow_rows = k.world.ball.map_or((0, 0), |b| shadow_rows(cam, &b));
        debug_assert!(forms.len() <= MAX_FORMS);
        let mut enter: Vec<_> = forms.iter().enumerate().map(|(i, f)| (f.rows.0, i)).collect();
        let mut leave: Vec<_> = forms.iter().enumerate().map(|(i, f)| (f.rows.1, i)).collect();
        enter.sort_unstable();
        leave.sort_unstable();
        Edges { forms, shadow, shadow_rows, size, inv_du: k.du.map(|x| 1.0 / x), enter, leave }
    }
}

/// The rows that may show the contact shadow of `b` (a disc of its radius on the floor
/// under its centre): those its bounding square projects on ([`rows_of`]). A camera not
/// above the floor sees no floor.
fn shadow_rows(cam: &super::PinholeCamera, b: &super::Ball) -> (usize, usize) {
    if cam.pose.position[2] <= 0.0 {
        return (0, 0);
    }
    rows_of(cam, [(-1.0, -1.0), (-1.0, 1.0), (1.0, -1.0), (1.0, 1.0)].map(|(dx, dy)| [b.x_mm + dx * b.radius_mm, b.y_mm + dy * b.radius_mm, 0.0]))
}

/// The rows that may show the ball: those its bounding cube projects on ([`rows_of`]).
pub(super) fn ball_rows(cam: &super::PinholeCamera, b: &super::Ball) -> (usize, usize) {
    let (centre, r) = ([b.x_mm, b.y_mm, b.radius_mm], b.radius_mm);
    let corners: [Vec3; 8] = std::array::from_fn(|i| std::array::from_fn(|k| centre[k] + if i >> k & 1 == 1 { r } else { -r }));
    rows_of(cam, corners)
}

/// The rows of the image a convex solid with these corners may show on: those the
/// corners project on, two more each side (far more than the rounding of any test on
/// a row moves it). A solid not wholly in front of the camera may be anywhere: all rows.
fn rows_of<const N: usize>(cam: &super::PinholeCamera, corners: [Vec3; N]) -> (usize, usize) {
    let p = cam.pose;
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for corner in corners {
        let d = sub(corner, p.position);
        let z = dot(d, p.forward);
        if z <= 1.0 || z.is_nan() {
            return (0, cam.height);
        }
        // the continuous image row (ray through row j: j + 0.5)
        let v = cam.height as f64 / 2.0 - dot(d, p.up) / z / cam.sv - 0.5;
        (lo, hi) = (lo.min(v), hi.max(v));
    }
    if !(lo.is_finite() && hi.is_finite()) {
        return (0, cam.height);
    }
    let h = cam.height as f64;
    ((lo - 2.0).clamp(0.0, h) as usize, (hi + 3.0).clamp(0.0, h) as usize)
}

/// An interval of the row's pixel index (real numbers; may be empty or unbounded; never
/// NaN, so plain comparisons order its bounds).
#[derive(Clone, Copy, Debug)]
struct Span(f64, f64);

impl Span {
    const ALL: Span = Span(f64::NEG_INFINITY, f64::INFINITY);
    const NONE: Span = Span(1.0, 0.0);

    /// lo..=hi, or every pixel when a bound is NaN (a degenerate form: cast them all).
    #[inline(always)]
    fn new(lo: f64, hi: f64) -> Span {
        if lo.is_nan() || hi.is_nan() {
            Span::ALL
        } else {
            Span(lo, hi)
        }
    }

    #[inline(always)]
    fn and(self, o: Span) -> Span {
        Span(if o.0 > self.0 { o.0 } else { self.0 }, if o.1 < self.1 { o.1 } else { self.1 })
    }

    #[inline(always)]
    fn is_empty(self) -> bool {
        self.0 > self.1
    }
}

/// Where |a + b·u| ≤ m (`inv_b` = 1/b).
#[inline(always)]
fn near_zero(a: f64, b: f64, inv_b: f64, m: f64) -> Span {
    if b == 0.0 {
        return if a.abs() <= m { Span::ALL } else { Span::NONE };
    }
    let (u1, u2) = ((-a - m) * inv_b, (-a + m) * inv_b);
    if b > 0.0 {
        Span::new(u1, u2)
    } else {
        Span::new(u2, u1)
    }
}

/// Where a + b·u may be negative and where it may be positive ([`may_have_sign`] with
/// s = −1 and 1), by 1/b (`inv_b`) worked out once per image.
#[inline(always)]
fn axis_spans(a: f64, b: f64, inv_b: f64, m: f64) -> [Span; 2] {
    if b == 0.0 {
        return [may_have_sign(a, b, -1.0, m), may_have_sign(a, b, 1.0, m)];
    }
    // a + b·u ≤ m, a + b·u ≥ −m
    let (neg, pos) = ((m - a) * inv_b, (-m - a) * inv_b);
    if b > 0.0 {
        [Span::new(f64::NEG_INFINITY, neg), Span::new(pos, f64::INFINITY)]
    } else {
        [Span::new(neg, f64::INFINITY), Span::new(f64::NEG_INFINITY, pos)]
    }
}

/// Where s·(a + b·u) ≥ −m.
fn may_have_sign(a: f64, b: f64, s: f64, m: f64) -> Span {
    let (a, b) = (s * a, s * b);
    if b == 0.0 {
        return if a >= -m { Span::ALL } else { Span::NONE };
    }
    let u0 = (-m - a) / b;
    if b > 0.0 {
        Span::new(u0, f64::INFINITY)
    } else {
        Span::new(f64::NEG_INFINITY, u0)
    }
}

/// Where p2·u² + p1·u + p0 ≥ 0: up to two spans.
fn quadratic_ge0(p2: f64, p1: f64, p0: f64) -> [Span; 2] {
    const NONE: Span = Span::NONE;
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
        [Span::new(f64::NEG_INFINITY, r1), Span::new(r2, f64::INFINITY)]
    } else {
        [Span::new(r1, r2), NONE]
    }
}

/// The pixels of one row to cast one by one: half-open index ranges, sorted (an empty
/// range ends a flat span without casting a pixel). Rows are found in order, top down.
pub(super) struct Cuts {
    ranges: Vec<(usize, usize)>,
    width: usize,
    /// The key bits of the forms positive along the whole row, and the forms that may
    /// change sign in it: (n·d at pixel 0, its change per pixel, bit).
    key0: u64,
    crossing: Vec<(f64, f64, u64)>,
    /// The next row, the forms that may change sign along it ([`Edges::enter`]), the key
    /// bits of the other forms positive, and the next entries of `enter` and `leave`.
    row: usize,
    active: Vec<usize>,
    key_rest: u64,
    entered: usize,
    left: usize,
}

impl Cuts {
    pub(super) fn new(e: &Edges) -> Cuts {
        let key_rest = e.forms.iter().filter(|f| f.start(0.0).0 > 0.0).fold(0, |k, f| k | f.bit);
        Cuts { ranges: Vec::new(), width: 0, key0: 0, crossing: Vec::new(), row: 0, active: Vec::new(), key_rest, entered: 0, left: 0 }
    }

    /// Finds the pixels of row `v` (whose first ray is `d0`; `ball`: the ball may show
    /// in it) that cannot share a span's colour.
    #[inline(always)]
    pub(super) fn find(&mut self, k: &Caster, e: &Edges, v: usize, d0: Vec3, ball: bool, width: usize) {
        assert_eq!(v, self.row, "rows in order");
        self.row += 1;
        self.ranges.clear();
        self.crossing.clear();
        self.width = width;
        let (du, size) = (k.du, e.size);
        let (row, v, w) = (v, v as f64, width as f64);
        // forms starting or ceasing to change sign along rows here; those that do not
        // keep one sign until the next change (the sign they have now)
        while let Some(&(_, i)) = e.enter.get(self.entered).filter(|x| x.0 <= row) {
            self.active.push(i);
            self.key_rest &= !e.forms[i].bit;
            self.entered += 1;
        }
        while let Some(&(_, i)) = e.leave.get(self.left).filter(|x| x.0 <= row) {
            self.active.retain(|&j| j != i);
            let f = &e.forms[i];
            self.key_rest |= if f.start(v).0 > 0.0 { f.bit } else { 0 };
            self.left += 1;
        }
        let form = |n: Vec3| (dot(n, d0), dot(n, du));
        // where the ray's x, y, z may be negative / positive (worked out when wanted)
        let mut signs: [Option<[Span; 2]>; 3] = [None; 3];
        // the conditions (`need` bits) that fail on the whole row and those that hold on
        // it, from the axes that keep one sign over it (the first three forms): a form
        // whose condition fails counts nowhere in the row (its key bit stays clear)
        let (mut fail, mut hold) = (0u8, 0u8);
        for (axis, i) in [1, 2, 0].into_iter().enumerate() {
            if let Some(positive) = e.forms[i].row_sign(v, w).1 {
                fail |= 1 << (2 * axis + !positive as usize);
                hold |= 1 << (2 * axis + positive as usize);
            }
        }
        let mut key0 = self.key_rest;
        for &i in &self.active {
            let f = &e.forms[i];
            if f.need & fail != 0 {
                continue;
            }
            // most forms keep one sign over the whole row
            let a = match f.row_sign(v, w) {
                (_, Some(positive)) => {
                    key0 |= if positive { f.bit } else { 0 };
                    continue;
                }
                (a, None) => a,
            };
            self.crossing.push((a, f.b, f.bit));
            let mut s = if f.walk {
                let u = f.p + v * f.q;
                Span(u - f.mw, u + f.mw)
            } else {
                near_zero(a, f.b, f.inv_b, f.margin)
            };
            // conditions that hold on the whole row cut nothing off
            if f.need & !hold != 0 {
                for &(axis, sign) in f.when.iter().flatten() {
                    let (a, b, inv_b) = (d0[axis], du[axis], e.inv_du[axis]);
                    let sg = signs[axis].get_or_insert_with(|| axis_spans(a, b, inv_b, MARGIN * size));
                    s = s.and(sg[(sign > 0.0) as usize]);
                }
            }
            add(&mut self.ranges, width, s, 0.0);
        }
        self.key0 = key0;
        if let (true, Some((_, _, oc, cc))) = (ball, k.ball) {
            if cc <= 0.0 {
                add(&mut self.ranges, width, Span::ALL, 0.0);
            } else {
                // disc(u) = (oc·d)² − |d|²·cc ≥ 0 where the ball is in front (oc·d < 0)
                let (b0, b1) = form(oc);
                let (a0, a1, a2) = (dot(d0, d0), dot(d0, du), dot(du, du));
                let m = MARGIN * ((b0.abs() + width as f64 * b1.abs()).powi(2) + cc * size * size);
                let front = may_have_sign(b0, b1, -1.0, MARGIN * dot(oc, oc).sqrt() * size);
                for s in quadratic_ge0(b1 * b1 - cc * a2, 2.0 * (b0 * b1 - cc * a1), b0 * b0 - cc * a0 + m) {
                    add(&mut self.ranges, width, s.and(front), 1.0);
                }
            }
        }
        if let Some((nx, ny, r)) = e.shadow.filter(|_| (e.shadow_rows.0..e.shadow_rows.1).contains(&row)) {
            // the floor point within the radius of the ball's centre: qx² + qy² < r²·dz²
            let ((x0, x1), (y0, y1), (z0, z1)) = (form(nx), form(ny), (d0[2], du[2]));
            let m = MARGIN * (dot(nx, nx) + dot(ny, ny) + r * r) * size * size;
            let (r2, p2, p1, p0) = (r * r, x1 * x1 + y1 * y1, 2.0 * (x0 * x1 + y0 * y1), x0 * x0 + y0 * y0);
            let down = may_have_sign(d0[2], du[2], -1.0, MARGIN * size);
            for s in quadratic_ge0(r2 * z1 * z1 - p2, 2.0 * r2 * z0 * z1 - p1, r2 * z0 * z0 - p0 + m) {
                add(&mut self.ranges, width, s.and(down), 1.0);
            }
        }
        // a few ranges: an insertion sort in place
        let r = &mut self.ranges;
        for i in 1..r.len() {
            let mut j = i;
            while j > 0 && r[j - 1] > r[j] {
                r.swap(j - 1, j);
                j -= 1;
            }
        }
    }

    /// The key of the flat span starting at pixel `u`: a bit per form, set where the
    /// form is positive. Every choice of [`Caster::pixel`] on a flat span is the sign
    /// of a form whose choices are reachable there, and those forms are beyond their
    /// margin at the span's pixels (else the pixel would be cut), so their bits are
    /// their true signs; which forms count follows from the bits of the axes (always
    /// cut). So two flat spans of one image with one key have one colour ([`Palette`]),
    /// whatever the bits of the forms that do not count.
    #[inline]
    fn key(&self, u: usize) -> u64 {
        let u = u as f64;
        self.crossing.iter().fold(self.key0, |k, &(a, b, bit)| if a + b * u > 0.0 { k | bit } else { k })
    }

    /// Writes the row: the cut pixels cast one by one, each span between them filled
    /// with the colour of its first pixel (from `palette` when a span of its key was
    /// cast before). `piece(a, b, colour)` is told of every span and pixel in order.
    #[inline(always)]
    pub(super) fn paint(&self, row: &mut [u8], palette: &mut Palette, pixel: impl Fn(usize) -> [u8; 3], mut piece: impl FnMut(usize, usize, [u8; 3])) {
        let mut span = |a: usize| palette.colour(self.key(a), || pixel(a));
        // Flat spans not yet written: start..next, one colour. Most cuts change no
        // choice that counts there (the next span has the same colour): one fill.
        let (mut start, mut colour) = (0, [0; 3]);
        #[inline(always)]
        fn flush(row: &mut [u8], piece: &mut impl FnMut(usize, usize, [u8; 3]), start: usize, end: usize, c: [u8; 3]) {
            if start < end {
                fill(&mut row[3 * start..3 * end], c);
                piece(start, end, c);
            }
        }
        let mut next = 0;
        // An empty range at the row's end flushes the last span like any other.
        for &(lo, hi) in self.ranges.iter().chain(&[(self.width, self.width)]) {
            if lo > next {
                let c = span(next);
                if c != colour || start == next {
                    flush(row, &mut piece, start, next, colour);
                    (start, colour) = (next, c);
                }
                next = lo;
            }
            if hi > next {
                flush(row, &mut piece, start, next, colour);
                for u in next..hi {
                    let c = pixel(u);
                    row[3 * u..3 * u + 3].copy_from_slice(&c);
                    piece(u, u + 1, c);
                }
                (start, next) = (hi, hi);
            }
        }
        flush(row, &mut piece, start, next, colour);
    }
}

/// Adds the pixels of `s` (widened by `pad` pixels) that lie in a row of `width`, as
/// a half-open range; a span between two pixels still ends the flat span there.
#[inline]
fn add(ranges: &mut Vec<(usize, usize)>, width: usize, s: Span, pad: f64) {
    if s.is_empty() {
        return;
    }
    let w = width as f64;
    let clamp = |x: f64| {
        if x > 0.0 {
            if x < w {
                x
            } else {
                w
            }
        } else {
            0.0
        }
    };
    // ⌈lo⌉ and ⌊hi⌋ + 1 of values clamped to 0..=w (no libm call on baseline x86-64)
    let lo = clamp(s.0 - pad - 1e-6);
    let lo = lo as i64 as usize + ((lo as i64 as f64) < lo) as usize;
    let hi = (clamp(s.1 + pad + 1e-6) as i64 as usize + 1).clamp(lo, width);
    // an empty range at either end of the row ends nothing
    if lo < hi || (lo > 0 && lo < width) {
        ranges.push((lo, hi));
    }
}

/// The colours of the flat spans of one image by key ([`Cuts::key`]): a span whose key
/// was seen gets its colour without a cast (most spans of an image repeat a few keys).
pub(super) struct Palette {
    /// Open addressing: key | FULL, or 0 for a free slot.
    keys: [u64; PALETTE],
    colours: [[u8; 3]; PALETTE],
    len: usize,
}

const PALETTE: usize = 64;
/// Marks a used slot (keys have at most [`MAX_FORMS`] bits).
const FULL: u64 = 1 << 63;
const MAX_FORMS: usize = 63;

impl Default for Palette {
    fn default() -> Palette {
        Palette { keys: [0; PALETTE], colours: [[0; 3]; PALETTE], len: 0 }
    }
}

impl Palette {
    /// The colour of key `key`, from `cast` the first time.
    #[inline]
    fn colour(&mut self, key: u64, cast: impl FnOnce() -> [u8; 3]) -> [u8; 3] {
        let key = key | FULL;
        let mut i = (key.wrapping_mul(0x9e37_79b9_7f4a_7c15) >> 58) as usize % PALETTE;
        loop {
            match self.keys[i] {
                k if k == key => return self.colours[i],
                0 => break,
                _ => i = (i + 1) % PALETTE,
            }
        }
        let c = cast();
        // a full table keeps what it has (the probe above always finds a free slot)
        if self.len + 1 < PALETTE {
            (self.keys[i], self.colours[i]) = (key, c);
            self.len += 1;
        }
        c
    }
}

/// Fills `px` (whole RGB pixels) with one colour, 16 pixels per copy.
#[inline(always)]
fn fill(px: &mut [u8], c: [u8; 3]) {
    let n = px.len();
    if n < 48 {
        px.chunks_exact_mut(3).for_each(|p| p.copy_from_slice(&c));
        return;
    }
    // the 24-byte period of the colour as three words (16 three-byte copies cost more)
    let x = u64::from(c[0]) | u64::from(c[1]) << 8 | u64::from(c[2]) << 16;
    let words = [x | x << 24 | x << 48, x >> 16 | x << 8 | x << 32 | x << 56, x >> 8 | x << 16 | x << 40];
    let mut block = [0u8; 48];
    for (b, w) in block.chunks_exact_mut(8).zip(words.iter().cycle()) {
        b.copy_from_slice(&w.to_le_bytes());
    }
    px.chunks_exact_mut(48).for_each(|ch| ch.copy_from_slice(&block));
    // the rest: a block ending at the end, over the last one (whole pixels, so in phase;
    // a copy of variable length would be a call)
    if !n.is_multiple_of(48) {
        px[n - 48..].copy_from_slice(&block);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `Form::rows` finds the rows a scan of every row finds, near-level forms too.
    #[test]
    fn rows_match_a_scan_of_every_row() {
        let mut g = crate::render::tests::Lcg(5);
        for i in 0..20_000 {
            let a1 = if i % 7 == 0 { g.range(-1e-7, 1e-7) } else { g.range(-3.0, 3.0) };
            let f = Form {
                margin: [0.0, 1e-9, 1e-3][i % 3],
                when: [None; 2],
                bit: 1,
                a0: g.range(-500.0, 500.0),
                a1,
                b: g.range(-2.0, 2.0),
                inv_b: 0.0,
                need: 0,
                p: 0.0,
                q: 0.0,
                mw: 0.0,
                walk: false,
                rows: (0, 0),
            };
            let (h, w) = (320, 416.0);
            let both = |v: usize, sign: f64| {
                let (a, m) = f.start(v as f64);
                let z = a + w * f.b;
                sign * a > m && sign * z > m
            };
            let (top, bottom) = if f.a1 > 0.0 { (-1.0, 1.0) } else { (1.0, -1.0) };
            let lo = (0..h).find(|&v| !both(v, top)).unwrap_or(h);
            let hi = (0..h).find(|&v| both(v, bottom)).unwrap_or(h).max(lo);
            assert_eq!(f.rows(h, w), (lo, hi), "form {i}");
        }
    }
}
