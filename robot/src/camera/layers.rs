//! Synthesis of the four `OFbkImageVectorData` layers (H, M, L and the CDT layer C) from a
//! sensor-resolution RGB image, and their reconstruction to RGB (robot-api 6.6).
use super::cdt::{CdtLut, CDT_CHANNELS};
use super::colour::{clip, luma, ycrcb_to_rgb};
use super::source::RgbImage;
use crate::image::{ImageLayout, LayerLayout, TAG_SIZE};
use crate::render::{segments, FlatRuns};

// The loops below are shaped for the auto-vectoriser (~0.1 ms per ERS-7 image in
// release on x86-64, against ~0.6 ms for a per-pixel loop over the formulas): rows
// are walked with `chunks_exact`/`zip` (no bounds checks), bytes are read as
// little-endian words, the arithmetic after the luminance is done in 16 bits, and
// `div_round`/`clip` become the equivalent expressions of [`mean4`], [`high_pass`] and
// [`chroma`] (checked exhaustively by `tests::band_formulas_match_div_round_and_clip`).
// `synthesize_matches_reference_byte_for_byte` (end_to_end.rs) pins the output to
// a straightforward per-pixel implementation.

/// Rounded mean of four bytes summed in `sum`: `div_round(sum, 4)` = ⌊(sum + 2) / 4⌋,
/// which never needs clipping.
#[inline(always)]
fn mean4(sum: u16) -> u8 {
    ((sum + 2) >> 2) as u8
}

/// A high-pass band, `clip(128 + div_round(n, 4))` for n ∈ −510..=510: that is
/// ⌊(n + 514) / 4⌋ ∈ 1..=256, so only the upper clip remains.
#[inline(always)]
fn high_pass(n: i16) -> u8 {
    ((n + 514) >> 2).min(255) as u8
}

/// A colour band of layer H, `clip(128 + div_round(128·s, 1020))` for
/// s = ΣR − ΣY (or ΣB − ΣY) ∈ −1020..=1020 over a 2×2 block. With u = s + 1020 it is
/// ⌊(256u + 1020) / 2040⌋ = ⌊(32u + 127.5) / 255⌋ = ⌊(32u + 127) / 255⌋ (no multiple
/// of 255 lies in between), at most 256, and 32u + 127 fits in 16 bits.
#[inline(always)]
fn chroma(s: i16) -> u8 {
    ((32 * (s + 1020) as u16 + 127) / 255).min(255) as u8
}

/// The six bands (or any six `w`-long parts) of a layer row (split off one by one:
/// `chunks_exact_mut` divides by `w`, two divisions a row).
#[inline(always)]
fn six<T>(row: &mut [T], w: usize) -> [&mut [T]; 6] {
    let (p0, rest) = row.split_at_mut(w);
    let (p1, rest) = rest.split_at_mut(w);
    let (p2, rest) = rest.split_at_mut(w);
    let (p3, rest) = rest.split_at_mut(w);
    let (p4, rest) = rest.split_at_mut(w);
    [p0, p1, p2, p3, p4, &mut rest[..w]]
}

/// Columns `a..e` of six bands (written out: `each_mut().map` is not inlined).
#[inline(always)]
fn sub6<'a, T>(parts: &'a mut [&mut [T]; 6], a: usize, e: usize) -> [&'a mut [T]; 6] {
    let [p0, p1, p2, p3, p4, p5] = parts;
    [&mut p0[a..e], &mut p1[a..e], &mut p2[a..e], &mut p3[a..e], &mut p4[a..e], &mut p5[a..e]]
}

/// The two RGB pixels of `q` (6 bytes), read as two little-endian words.
#[inline(always)]
fn pixel_pair(q: &[u8]) -> [[i32; 3]; 2] {
    let lo = u32::from_le_bytes(q[..4].try_into().expect("6 bytes"));
    let hi = u16::from_le_bytes(q[4..6].try_into().expect("6 bytes")) as i32;
    let byte = |k: u32| (lo >> (8 * k)) as i32 & 0xff;
    [[byte(0), byte(1), byte(2)], [byte(3), hi & 0xff, hi >> 8]]
}

/// The pieces of a layer row: the row's runs (all of it per pixel without runs).
#[inline(always)]
fn row_runs(runs: Option<&FlatRuns>, y: usize) -> &[(u32, u32)] {
    runs.map_or(&[], |r| r.row(y))
}

/// Writes `band[a..b]` from its first pixel `band[a]` (a flat run).
#[inline(always)]
fn copy_first(band: &mut [u8], a: usize, b: usize) {
    let v = band[a];
    band[a + 1..b].fill(v);
}

/// Writes layer H of `layout` from the sensor-resolution RGB image (`2w × 2h`); the
/// pixels of a run of `runs` are copies of the run's first one.
#[inline(always)]
fn synth_from_rgb(l: &LayerLayout, rgb: &[u8], dst: &mut [u8], runs: Option<&FlatRuns>) {
    let w = l.width;
    let sensor_row = 2 * w * 3;
    // Per block of a row: the luminances a b / c d, ΣR − ΣY and ΣB − ΣY, computed in a
    // first loop; the bands follow from them in a second one (two simple loops
    // vectorise much better than one).
    let mut block = vec![0i16; 6 * w];
    let rows = dst.chunks_exact_mut(l.row_stride()).zip(rgb.chunks_exact(2 * sensor_row)).take(l.height);
    for (y, (row, pair)) in rows.enumerate() {
        let (top, bot) = pair.split_at(sensor_row);
        let mut sums = six(&mut block, w);
        let mut bands = six(row, w);
        segments(row_runs(runs, y), w, |a, b, flat| {
            if flat {
                bands_fill(&mut bands, a, b, h_block(&top[6 * a..6 * a + 6], &bot[6 * a..6 * a + 6]));
            } else {
                h_blocks(&top[6 * a..6 * b], &bot[6 * a..6 * b], sub6(&mut sums, a, b), sub6(&mut bands, a, b));
            }
        });
    }
}

/// Layer H pixels from the two sensor rows `top` and `bot` of their blocks (`sums`: scratch).
#[inline(always)]
fn h_blocks(top: &[u8], bot: &[u8], sums: [&mut [i16]; 6], bands: [&mut [u8]; 6]) {
    let [ya, yb, yc, yd, dr, db] = sums;
    let pixels = top.chunks_exact(6).zip(bot.chunks_exact(6));
    let s = ya.iter_mut().zip(yb.iter_mut()).zip(yc.iter_mut()).zip(yd.iter_mut()).zip(dr.iter_mut()).zip(db.iter_mut());
    for ((t, u), (((((ya, yb), yc), yd), dr), db)) in pixels.zip(s) {
        let [[r0, g0, b0], [r1, g1, b1]] = pixel_pair(t);
        let [[r2, g2, b2], [r3, g3, b3]] = pixel_pair(u);
        let (a, b, c, d) = (luma(r0, g0, b0), luma(r1, g1, b1), luma(r2, g2, b2), luma(r3, g3, b3));
        let sy = a + b + c + d;
        [*ya, *yb, *yc, *yd] = [a, b, c, d].map(|v| v as i16);
        *dr = (r0 + r1 + r2 + r3 - sy) as i16;
        *db = (b0 + b1 + b2 + b3 - sy) as i16;
    }
    let [yll, cr, cb, lh, hl, hh] = bands;
    let bands = yll.iter_mut().zip(cr).zip(cb).zip(lh).zip(hl).zip(hh);
    let s = ya.iter().zip(yb.iter()).zip(yc.iter()).zip(yd.iter()).zip(dr.iter()).zip(db.iter());
    for ((((((&a, &b), &c), &d), &dr), &db), (((((yll, cr), cb), lh), hl), hh)) in s.zip(bands) {
        *yll = mean4((a + b + c + d) as u16);
        *cr = chroma(dr);
        *cb = chroma(db);
        *lh = high_pass(c + d - a - b);
        *hl = high_pass(b + d - a - c);
        *hh = high_pass(a + d - b - c);
    }
}

/// The six band values of one layer H block ([`h_blocks`] on one block, without the
/// set-up of its loops: the pixel of a flat run).
#[inline(always)]
fn h_block(top: &[u8], bot: &[u8]) -> [u8; 6] {
    let [[r0, g0, b0], [r1, g1, b1]] = pixel_pair(top);
    let [[r2, g2, b2], [r3, g3, b3]] = pixel_pair(bot);
    let [a, b, c, d] = [luma(r0, g0, b0), luma(r1, g1, b1), luma(r2, g2, b2), luma(r3, g3, b3)].map(|v| v as i16);
    let sy = (a + b + c + d) as i32;
    let (dr, db) = ((r0 + r1 + r2 + r3 - sy) as i16, (b0 + b1 + b2 + b3 - sy) as i16);
    [mean4((a + b + c + d) as u16), chroma(dr), chroma(db), high_pass(c + d - a - b), high_pass(b + d - a - c), high_pass(a + d - b - c)]
}

/// Writes `bands[k][a..b]` = `v[k]` (a flat run).
#[inline(always)]
fn bands_fill(bands: &mut [&mut [u8]; 6], a: usize, b: usize, v: [u8; 6]) {
    bands.iter_mut().zip(v).for_each(|(band, v)| band[a..b].fill(v));
}

/// The two bytes of `q` (2 bytes), read as one little-endian word.
#[inline(always)]
fn byte_pair(q: &[u8]) -> (u16, u16) {
    let v = u16::from_le_bytes(q.try_into().expect("2 bytes"));
    (v & 0xff, v >> 8)
}

/// Writes an HPF layer `l` from the Y/Cr/Cb bands of the previous (double-size) HPF
/// layer `src` (whose data is `s`); the pixels of a run of `runs` are copies of the
/// run's first one.
#[inline(always)]
fn synth_from_layer(src: &LayerLayout, s: &[u8], l: &LayerLayout, dst: &mut [u8], runs: Option<&FlatRuns>) {
    let (w, sw) = (l.width, src.width);
    let rows = dst.chunks_exact_mut(l.row_stride()).zip(s.chunks_exact(2 * src.row_stride())).take(l.height);
    debug_assert_eq!(sw, 2 * w);
    for (y, (row, pair)) in rows.enumerate() {
        let (top, bot) = pair.split_at(src.row_stride());
        let mut bands = six(row, w);
        segments(row_runs(runs, y), w, |a, b, flat| {
            if flat {
                // one block, its pixel along the run
                let px = |k: usize, t: &[u8]| byte_pair(&t[k * sw + 2 * a..k * sw + 2 * a + 2]);
                let mean = |k| {
                    let ((p, q), (r, t)) = (px(k, top), px(k, bot));
                    mean4(p + q + r + t)
                };
                let ((ya, yb), (yc, yd)) = (px(0, top), px(0, bot));
                let (ya, yb, yc, yd) = (ya as i16, yb as i16, yc as i16, yd as i16);
                let hp = [high_pass(yc + yd - ya - yb), high_pass(yb + yd - ya - yc), high_pass(ya + yd - yb - yc)];
                bands_fill(&mut bands, a, b, [mean(0), mean(1), mean(2), hp[0], hp[1], hp[2]]);
                return;
            }
            let [yll, cr, cb, lh, hl, hh] = sub6(&mut bands, a, b);
            // Y LL, Cr and Cb: means of the source's Y, Cr and Cb over 2×2 blocks
            for (k, out) in [yll, cr, cb].into_iter().enumerate() {
                let (t, u) = (&top[k * sw + 2 * a..k * sw + 2 * b], &bot[k * sw + 2 * a..k * sw + 2 * b]);
                for (o, (t, u)) in out.iter_mut().zip(t.chunks_exact(2).zip(u.chunks_exact(2))) {
                    let ((a, b), (c, d)) = (byte_pair(t), byte_pair(u));
                    *o = mean4(a + b + c + d);
                }
            }
            let hp = lh.iter_mut().zip(hl).zip(hh);
            for ((t, u), ((lh, hl), hh)) in top[2 * a..2 * b].chunks_exact(2).zip(bot[2 * a..2 * b].chunks_exact(2)).zip(hp) {
                let ((a, b), (c, d)) = (byte_pair(t), byte_pair(u));
                let (a, b, c, d) = (a as i16, b as i16, c as i16, d as i16);
                *lh = high_pass(c + d - a - b);
                *hl = high_pass(b + d - a - c);
                *hh = high_pass(a + d - b - c);
            }
        });
    }
}

/// Adds the number of bytes of `pixels` with bit k set to `counts[k]`.
#[inline(always)]
fn count_bits(pixels: &[u8], counts: &mut [u32; CDT_CHANNELS]) {
    // 32 byte-wide sums per channel vectorise well (a fold per channel ran 8 bytes at
    // a time); 255 chunks cannot overflow them (wrapping_add only spares debug builds
    // the overflow check).
    for block in pixels.chunks(32 * 255) {
        let mut acc = [[0u8; 32]; CDT_CHANNELS];
        let mut chunks = block.chunks_exact(32);
        for ch in &mut chunks {
            for (k, acc) in acc.iter_mut().enumerate() {
                acc.iter_mut().zip(ch).for_each(|(n, &b)| *n = n.wrapping_add(b >> k & 1));
            }
        }
        let rest = chunks.remainder();
        for (k, (c, acc)) in counts.iter_mut().zip(&acc).enumerate() {
            *c += acc.iter().map(|&n| n as u32).sum::<u32>() + rest.iter().map(|&b| (b >> k & 1) as u32).sum::<u32>();
        }
    }
}

/// Writes the CDT layer `l` from an HPF layer of the same size (the pixels of a run of
/// `runs` are copies of the run's first one); returns per-channel counts of matched
/// pixels (excluding the tag bytes).
#[inline(always)]
fn synth_cdt(src: &LayerLayout, s: &[u8], l: &LayerLayout, dst: &mut [u8], lut: &CdtLut, runs: Option<&FlatRuns>) -> [u32; CDT_CHANNELS] {
    let mut counts = [0u32; CDT_CHANNELS];
    let (w, h, sw) = (l.width.min(src.width), l.height.min(src.height), src.width);
    let rows = dst.chunks_exact_mut(l.row_stride()).zip(s.chunks_exact(src.row_stride())).take(h);
    for (y, (drow, srow)) in rows.enumerate() {
        let drow = &mut drow[..w];
        let (ys, crs, cbs) = (&srow[..w], &srow[sw..sw + w], &srow[2 * sw..2 * sw + w]);
        segments(row_runs(runs, y), w, |a, b, flat| {
            let e = if flat { a + 1 } else { b };
            for (((d, &y), &cr), &cb) in drow[a..e].iter_mut().zip(&ys[a..e]).zip(&crs[a..e]).zip(&cbs[a..e]) {
                *d = lut.classify(y, cr, cb);
            }
            if flat {
                copy_first(drow, a, b);
            }
        });
        if w != l.row_stride() {
            count_bits(pixels_of_row(drow, y, l.height), &mut counts);
        }
    }
    if w == l.row_stride() {
        // rows without gaps: counted in one go
        let (most, last) = dst[..h * w].split_at(h.saturating_sub(1) * w);
        count_bits(most, &mut counts);
        count_bits(pixels_of_row(last, h.saturating_sub(1), l.height), &mut counts);
    }
    counts
}

/// The pixels of row `y` of a CDT layer of `height` rows: the tag bytes of the last row
/// hold none.
#[inline(always)]
fn pixels_of_row(row: &[u8], y: usize, height: usize) -> &[u8] {
    if y + 1 == height {
        row.get(TAG_SIZE..).unwrap_or(&[])
    } else {
        row
    }
}

/// Fills the four layers of `buf` (an image vector of `layout`) from a sensor-size
/// RGB image and writes the tags. Returns the per-channel CDT pixel counts.
pub fn synthesize(layout: &ImageLayout, rgb: &[u8], lut: &CdtLut, field_counter: u32, buf: &mut [u8]) -> [u32; CDT_CHANNELS] {
    synthesize_runs(layout, rgb, None, lut, field_counter, buf)
}

/// Shortest runs, in pixels of the layer, that are copied rather than computed pixel by
/// pixel (shorter ones cost more in split loops than they save).
pub const MIN_RUN: usize = 8;

/// The runs of the layers below the sensor image (kept between images to spare the
/// allocations).
#[derive(Clone, Debug)]
pub struct LayerRuns {
    h: FlatRuns,
    m: FlatRuns,
    l: FlatRuns,
    /// Shortest run copied ([`MIN_RUN`]; tests try shorter ones).
    min: usize,
}

impl Default for LayerRuns {
    fn default() -> LayerRuns {
        LayerRuns::with_min(MIN_RUN)
    }
}

impl LayerRuns {
    pub fn with_min(min: usize) -> LayerRuns {
        LayerRuns { h: FlatRuns::default(), m: FlatRuns::default(), l: FlatRuns::default(), min }
    }
}

/// [`synthesize`] given the runs of identical pixels of `rgb` (`runs`, e.g. the
/// renderer's, with the scratch their layers' runs are made in): the same bytes, long
/// runs copied instead of computed pixel by pixel ([`crate::render::FlatRuns`]).
pub fn synthesize_runs(
    layout: &ImageLayout,
    rgb: &[u8],
    runs: Option<(&FlatRuns, &mut LayerRuns)>,
    lut: &CdtLut,
    field_counter: u32,
    buf: &mut [u8],
) -> [u32; CDT_CHANNELS] {
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("avx2") {
        // SAFETY: the CPU has AVX2 (checked just above), all `synthesize_avx2` needs.
        return unsafe { synthesize_avx2(layout, rgb, runs, lut, field_counter, buf) };
    }
    synthesize_layers(layout, rgb, runs, lut, field_counter, buf)
}

/// [`synthesize_layers`] compiled for AVX2: the same integer arithmetic (the same bytes)
/// in wider vectors, ~2× faster than baseline x86-64's SSE2.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn synthesize_avx2(
    layout: &ImageLayout,
    rgb: &[u8],
    runs: Option<(&FlatRuns, &mut LayerRuns)>,
    lut: &CdtLut,
    field_counter: u32,
    buf: &mut [u8],
) -> [u32; CDT_CHANNELS] {
    synthesize_layers(layout, rgb, runs, lut, field_counter, buf)
}

#[inline(always)]
fn synthesize_layers(
    layout: &ImageLayout,
    rgb: &[u8],
    runs: Option<(&FlatRuns, &mut LayerRuns)>,
    lut: &CdtLut,
    field_counter: u32,
    buf: &mut [u8],
) -> [u32; CDT_CHANNELS] {
    let [lh, lm, ll, lc] = layout.layers;
    debug_assert!(lh.data_offset + lh.data_size() <= lm.data_offset && lm.data_offset + lm.data_size() <= ll.data_offset);
    debug_assert!(ll.data_offset + ll.data_size() <= lc.data_offset);
    assert!(rgb.len() >= 4 * lh.width * lh.height * 3, "RGB image smaller than the sensor");
    let (_, rest) = buf.split_at_mut(lh.data_offset);
    let (h, rest) = rest.split_at_mut(lm.data_offset - lh.data_offset);
    let (m, rest) = rest.split_at_mut(ll.data_offset - lm.data_offset);
    let (l, rest) = rest.split_at_mut(lc.data_offset - ll.data_offset);
    let counts = match runs {
        None => {
            synth_from_rgb(&lh, rgb, h, None);
            synth_from_layer(&lh, h, &lm, m, None);
            synth_from_layer(&lm, m, &ll, l, None);
            synth_cdt(&lm, m, &lc, rest, lut, None)
        }
        Some((sensor, r)) => {
            sensor.halve(lh.height, r.min, &mut r.h);
            synth_from_rgb(&lh, rgb, h, Some(&r.h));
            r.h.halve(lm.height, r.min, &mut r.m);
            synth_from_layer(&lh, h, &lm, m, Some(&r.m));
            r.m.halve(ll.height, r.min, &mut r.l);
            synth_from_layer(&lm, m, &ll, l, Some(&r.l));
            synth_cdt(&lm, m, &lc, rest, lut, Some(&r.m))
        }
    };
    layout.write_tags(buf, field_counter, counts).expect("buffer sized to layout");
    counts
}

/// Converts a layer of an image vector back to RGB (robot-api 6.6 inverse formulas).
/// HPF layers are reconstructed at double resolution (each 2×2 block shares its
/// Cr/Cb); a plain YCrCb layer at its own size; None for the CDT layer or a bad buffer.
/// The tag bytes are converted like pixels.
pub fn layer_to_rgb(layout: &ImageLayout, buf: &[u8], layer: usize) -> Option<RgbImage> {
    let l = *layout.layers.get(layer)?;
    if l.bands < 3 || buf.len() < l.data_offset + l.data_size() {
        return None;
    }
    let d = &buf[l.data_offset..l.data_offset + l.data_size()];
    let f = if l.bands == 6 { 2 } else { 1 };
    let (w2, h2) = (l.width * f, l.height * f);
    let mut data = vec![0u8; w2 * h2 * 3];
    for y in 0..l.height {
        let row = &d[y * l.row_stride()..(y + 1) * l.row_stride()];
        for x in 0..l.width {
            let band = |b: usize| row[b * l.width + x];
            let (cr, cb) = (band(1), band(2));
            let ys = if f == 2 { reconstruct(band(0), band(3), band(4), band(5)) } else { [band(0); 4] };
            for (i, yv) in ys.iter().enumerate().take(f * f) {
                let (px, py) = (x * f + i % 2, y * f + i / 2);
                let o = (py * w2 + px) * 3;
                data[o..o + 3].copy_from_slice(&ycrcb_to_rgb([*yv, cr, cb]));
            }
        }
    }
    Some(RgbImage { width: w2, height: h2, data })
}

/// The 2×2 double-resolution block (top-left, top-right, bottom-left, bottom-right)
/// of one HPF pixel (robot-api 6.6).
pub fn reconstruct(ll: u8, lh: u8, hl: u8, hh: u8) -> [u8; 4] {
    let (ll, lh, hl, hh) = (ll as i32, lh as i32 - 128, hl as i32 - 128, hh as i32 - 128);
    [ll - lh - hl + hh, ll - lh + hl - hh, ll + lh - hl - hh, ll + lh + hl + hh].map(clip)
}

#[cfg(test)]
mod tests {
    use super::super::colour::{div_round, rgb_to_ycrcb};
    use super::*;

    /// `mean4`, `high_pass` and `chroma` equal the `div_round`/`clip` formulas they
    /// replace on every value synthesis can give them.
    #[test]
    fn band_formulas_match_div_round_and_clip() {
        for sum in 0..=1020 {
            assert_eq!(mean4(sum as u16), clip(div_round(sum, 4)), "sum {sum}");
        }
        for n in -510..=510 {
            assert_eq!(high_pass(n as i16), clip(128 + div_round(n, 4)), "n {n}");
        }
        for s in -1020..=1020 {
            assert_eq!(chroma(s as i16), clip(128 + div_round(128 * s, 1020)), "s {s}");
        }
        // the Cr/Cb of layer H agree with the single-pixel conversion
        for rgb in [[0, 0, 0], [255, 255, 255], [255, 0, 0], [0, 0, 255], [0, 255, 255], [250, 90, 160]] {
            let [r, g, b] = rgb.map(i32::from);
            let y = luma(r, g, b);
            let ycc = rgb_to_ycrcb(rgb);
            assert_eq!([chroma((4 * (r - y)) as i16), chroma((4 * (b - y)) as i16)], [ycc[1], ycc[2]], "{rgb:?}");
        }
    }

    #[test]
    fn count_bits_counts_every_bit_of_every_byte() {
        let mut x = 0x2545_f491_4f6c_dd1du64;
        for n in [0, 1, 31, 32, 33, 104, 8160, 8161, 8320, 20000] {
            let bytes: Vec<u8> = (0..n)
                .map(|_| {
                    x ^= x << 13;
                    x ^= x >> 7;
                    x ^= x << 17;
                    x as u8
                })
                .collect();
            let mut counts = [5u32; CDT_CHANNELS];
            count_bits(&bytes, &mut counts);
            let want: [u32; CDT_CHANNELS] = std::array::from_fn(|k| 5 + bytes.iter().map(|&b| (b >> k & 1) as u32).sum::<u32>());
            assert_eq!(counts, want, "{n} bytes");
        }
        let mut counts = [0; CDT_CHANNELS];
        count_bits(&[0xff; 40000], &mut counts);
        assert_eq!(counts, [40000; CDT_CHANNELS]);
    }

    #[test]
    fn hpf_round_trip() {
        for (a, b, c, d) in [(0, 255, 255, 0), (10, 20, 30, 40), (200, 201, 199, 198), (255, 255, 255, 255)] {
            let ll = div_round(a + b + c + d, 4);
            let lh = clip(128 + div_round(c + d - a - b, 4));
            let hl = clip(128 + div_round(b + d - a - c, 4));
            let hh = clip(128 + div_round(a + d - b - c, 4));
            let r = reconstruct(clip(ll), lh, hl, hh);
            for (got, want) in r.iter().zip([a, b, c, d]) {
                assert!((*got as i32 - want).abs() <= 2, "{r:?} vs {:?}", (a, b, c, d));
            }
        }
    }
}
