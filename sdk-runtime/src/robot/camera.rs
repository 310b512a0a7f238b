//! The virtual camera: colour detection tables (`SetCdtVectorData`), replacement image
//! sources (PPM/BMP files), and synthesis of the four `OFbkImageVectorData` layers from a
//! sensor-resolution RGB image (robot-api 6.6, 6.7, 8.4; ers7-model 9).
//!
//! Why it exists: [`super::VirtualRobot::render_image`] must hand the camera system
//! object a complete image vector each camera frame, cheaply enough for several robots
//! at 30 fps.
//!
//! Synthesis (robot-api 6.6):
//! * RGB → Y, Cr, Cb: Y = (0.51·R + G + 0.19·B)/1.70, Cr = 128 + 128·(R−Y)/255,
//!   Cb = 128 + 128·(B−Y)/255 (fixed point, rounded, clipped to 0..255).
//! * Layer H (sensor size / 2): for each 2×2 block (a b / c d) of sensor-resolution
//!   luminance: Y_LL = (a+b+c+d)/4, Y_LH = (c+d−a−b)/4 + 128, Y_HL = (b+d−a−c)/4 + 128,
//!   Y_HH = (a+d−b−c)/4 + 128; Cr/Cb from the block's mean colour.
//! * Layers M and L: the same, taking the previous layer's Y_LL band as the
//!   double-resolution luminance and averaging its Cr/Cb over 2×2 blocks.
//! * Layer C (the M resolution): bit k set when the M pixel's (Cr, Cb) lies inside
//!   channel k's table row for its Y segment (Y >> 3). Unloaded channels never match.
//! * Tag: the first 16 bytes of the last row of every band of every layer
//!   ([`ImageLayout::write_tags`]): field counter (+1 per image, starting at 1) and
//!   `ColorFrequency` = matched CDT pixels / 16. The count covers every CDT pixel except
//!   the 16 tag bytes (they hold no pixels), so it equals the number of set bits a
//!   program finds when it skips the tag.

use std::fs;
use std::path::{Path, PathBuf};

use super::image::{ImageLayout, LayerLayout, TAG_SIZE};
use super::model::{Design, PrimitiveId};
use super::status::*;
use super::vectors::{odata, rd_u32, VectorHeader, HEADER_SIZE};

// ---------------------------------------------------------------------------------
// colour conversion

/// Fixed-point (×65536) luminance weights 0.51/1.7, 1/1.7, 0.19/1.7 (sum 65536).
const KY: [i32; 3] = [19_661, 38_550, 7_325];

#[inline]
fn luma(r: i32, g: i32, b: i32) -> i32 {
    (KY[0] * r + KY[1] * g + KY[2] * b + 32_768) >> 16
}

/// Rounded `n / d` for d > 0.
#[inline]
fn div_round(n: i32, d: i32) -> i32 {
    (2 * n + d).div_euclid(2 * d)
}

#[inline]
fn clip(v: i32) -> u8 {
    v.clamp(0, 255) as u8
}

/// RGB → (Y, Cr, Cb) (robot-api 6.6).
pub fn rgb_to_ycrcb(rgb: [u8; 3]) -> [u8; 3] {
    let [r, g, b] = rgb.map(i32::from);
    let y = luma(r, g, b);
    [clip(y), clip(128 + div_round(128 * (r - y), 255)), clip(128 + div_round(128 * (b - y), 255))]
}

/// (Y, Cr, Cb) → RGB (robot-api 6.6: R = Y + 2·(Cr−128)·255/256, B likewise,
/// G = Y − 0.51·(R−Y) − 0.19·(B−Y)).
pub fn ycrcb_to_rgb(ycc: [u8; 3]) -> [u8; 3] {
    let y = ycc[0] as f64;
    let r = y + 2.0 * (ycc[1] as f64 - 128.0) * 255.0 / 256.0;
    let b = y + 2.0 * (ycc[2] as f64 - 128.0) * 255.0 / 256.0;
    let g = y - 0.51 * (r - y) - 0.19 * (b - y);
    [r, g, b].map(|v| v.round().clamp(0.0, 255.0) as u8)
}

// ---------------------------------------------------------------------------------
// CDT

pub const CDT_CHANNELS: usize = 8;
pub const CDT_SEGMENTS: usize = 32;
pub const CDT_INFO_SIZE: usize = 144;
const ODATA_CDT: u32 = 21;

/// One parsed `OCdtInfo`: channel index (0..7) and its 32 packed entries.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CdtTable {
    pub channel: usize,
    pub entries: [u32; CDT_SEGMENTS],
}

/// Parses the first `numData` infos of an `OCdtVectorData` (robot-api 6.7). Every info
/// must be type odataCDT, name `camera` and have a single-bit channel (not 0x80 on
/// ERS-7); nothing is loaded unless all are valid. Errors: `oINVALID_DATA_TYPE`
/// (vector type ≠ 1028 or info type ≠ 21), `oINVALID_PRIMITIVE_ID`, `oINVALID_ARG`
/// (bad channel), `oFAIL` (truncated vector, numData > 8 or > maxNumData).
pub fn parse_cdt(bytes: &[u8], camera: PrimitiveId, design: Design) -> Result<Vec<CdtTable>, OStatus> {
    let h = VectorHeader::read(bytes).map_err(|_| O_FAIL)?;
    if h.vector_type != odata::CDT_VECTOR {
        return Err(O_INVALID_DATA_TYPE);
    }
    let n = h.num_data as usize;
    if n > CDT_CHANNELS || h.num_data > h.max_num_data {
        return Err(O_FAIL);
    }
    if bytes.len() < HEADER_SIZE + n * CDT_INFO_SIZE {
        return Err(O_FAIL);
    }
    let mut out = Vec::with_capacity(n);
    for i in 0..n {
        let o = HEADER_SIZE + i * CDT_INFO_SIZE;
        let rd = |k: usize| rd_u32(bytes, o + k).map_err(|_| O_FAIL);
        if rd(0)? != ODATA_CDT {
            return Err(O_INVALID_DATA_TYPE);
        }
        if rd(4)? != camera {
            return Err(O_INVALID_PRIMITIVE_ID);
        }
        let chan = rd(8)?;
        let max_chan = if design == Design::Ers7 { 0x40 } else { 0x80 };
        if chan == 0 || !chan.is_power_of_two() || chan > max_chan {
            return Err(O_INVALID_ARG);
        }
        let mut entries = [0u32; CDT_SEGMENTS];
        for (s, e) in entries.iter_mut().enumerate() {
            *e = rd(12 + 4 * s)?;
        }
        out.push(CdtTable { channel: chan.trailing_zeros() as usize, entries });
    }
    Ok(out)
}

/// Builds an `OCdtVectorData` (as `NewCdtVectorData` + `Init`/`Set` would) — for tests
/// and tools. `tables`: (channel bit, entries).
pub fn build_cdt_vector(camera: PrimitiveId, tables: &[(u32, [u32; CDT_SEGMENTS])]) -> Vec<u8> {
    let mut b = vec![0u8; 4096];
    let h = VectorHeader {
        total_size: 4096,
        vector_type: odata::CDT_VECTOR,
        info_offset: HEADER_SIZE as u32,
        info_size: CDT_INFO_SIZE as u32,
        max_num_data: CDT_CHANNELS as u32,
        num_data: tables.len() as u32,
        sync_key: 0xFFFF_FFFF,
        ..VectorHeader::default()
    };
    h.write(&mut b).expect("fits");
    for i in 0..CDT_CHANNELS {
        let o = HEADER_SIZE + i * CDT_INFO_SIZE;
        let (chan, entries) = tables.get(i).copied().unwrap_or((0, [0x8080_8080; CDT_SEGMENTS]));
        let id = if i < tables.len() { camera } else { 0xFFFF_FFFF };
        let mut put = |k: usize, v: u32| b[o + k..o + k + 4].copy_from_slice(&v.to_le_bytes());
        put(0, ODATA_CDT);
        put(4, id);
        put(8, chan);
        for (s, e) in entries.iter().enumerate() {
            put(12 + 4 * s, *e);
        }
    }
    b
}

/// Packs one table entry like `OCdtInfo::Set(seg, crMax, crMin, cbMax, cbMin)`.
pub fn cdt_entry(cr_max: u8, cr_min: u8, cb_max: u8, cb_min: u8) -> u32 {
    cr_min as u32 | (cr_max as u32) << 8 | (cb_min as u32) << 16 | (cb_max as u32) << 24
}

/// The loaded tables as two lookup tables: bit k of `cr[seg][cr]` is set when Cr lies
/// in channel k's Cr range for that Y segment (likewise `cb`).
#[derive(Clone, Debug)]
pub struct CdtLut {
    tables: [Option<[u32; CDT_SEGMENTS]>; CDT_CHANNELS],
    cr: Box<[[u8; 256]; CDT_SEGMENTS]>,
    cb: Box<[[u8; 256]; CDT_SEGMENTS]>,
}

impl Default for CdtLut {
    fn default() -> CdtLut {
        CdtLut { tables: [None; CDT_CHANNELS], cr: Box::new([[0; 256]; CDT_SEGMENTS]), cb: Box::new([[0; 256]; CDT_SEGMENTS]) }
    }
}

impl CdtLut {
    pub fn load(&mut self, t: &CdtTable) {
        self.tables[t.channel] = Some(t.entries);
        self.rebuild();
    }

    pub fn table(&self, channel: usize) -> Option<&[u32; CDT_SEGMENTS]> {
        self.tables.get(channel)?.as_ref()
    }

    fn rebuild(&mut self) {
        *self.cr = [[0; 256]; CDT_SEGMENTS];
        *self.cb = [[0; 256]; CDT_SEGMENTS];
        for (k, t) in self.tables.iter().enumerate() {
            let Some(t) = t else { continue };
            for (seg, &e) in t.iter().enumerate() {
                let [cr_min, cr_max, cb_min, cb_max] = e.to_le_bytes();
                for v in cr_min..=cr_max {
                    self.cr[seg][v as usize] |= 1 << k;
                }
                for v in cb_min..=cb_max {
                    self.cb[seg][v as usize] |= 1 << k;
                }
            }
        }
    }

    /// CDT bits of one pixel (the rule of robot-api 6.7).
    #[inline]
    pub fn classify(&self, y: u8, cr: u8, cb: u8) -> u8 {
        let seg = y as usize >> 3;
        self.cr[seg][cr as usize] & self.cb[seg][cb as usize]
    }
}

// ---------------------------------------------------------------------------------
// images

/// An RGB image, row-major, 3 bytes per pixel.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct RgbImage {
    pub width: usize,
    pub height: usize,
    pub data: Vec<u8>,
}

impl RgbImage {
    pub fn pixel(&self, x: usize, y: usize) -> [u8; 3] {
        let o = (y * self.width + x) * 3;
        [self.data[o], self.data[o + 1], self.data[o + 2]]
    }

    /// Nearest-neighbour scaling into `out` (resized to `w × h`).
    pub fn scale_into(&self, w: usize, h: usize, out: &mut Vec<u8>) {
        out.resize(w * h * 3, 0);
        if self.width == 0 || self.height == 0 {
            out.fill(128);
            return;
        }
        for y in 0..h {
            let sy = y * self.height / h;
            for x in 0..w {
                let sx = x * self.width / w;
                let s = (sy * self.width + sx) * 3;
                let d = (y * w + x) * 3;
                out[d..d + 3].copy_from_slice(&self.data[s..s + 3]);
            }
        }
    }
}

/// Why an image file could not be used.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ImageError(pub String);

impl std::fmt::Display for ImageError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for ImageError {}

fn err<T>(msg: impl Into<String>) -> Result<T, ImageError> {
    Err(ImageError(msg.into()))
}

/// Decodes a binary PPM (P6, maxval 1..65535, comments allowed).
pub fn decode_ppm(bytes: &[u8]) -> Result<RgbImage, ImageError> {
    if !bytes.starts_with(b"P6") {
        return err("not a binary PPM (P6)");
    }
    let mut pos = 2;
    let mut fields = [0usize; 3];
    for f in fields.iter_mut() {
        loop {
            match bytes.get(pos) {
                Some(c) if c.is_ascii_whitespace() => pos += 1,
                Some(b'#') => {
                    while bytes.get(pos).is_some_and(|&c| c != b'\n') {
                        pos += 1;
                    }
                }
                _ => break,
            }
        }
        let start = pos;
        while bytes.get(pos).is_some_and(u8::is_ascii_digit) {
            pos += 1;
        }
        let s = std::str::from_utf8(&bytes[start..pos]).unwrap_or("");
        *f = s.parse().map_err(|_| ImageError("bad PPM header".into()))?;
    }
    if !bytes.get(pos).is_some_and(u8::is_ascii_whitespace) {
        return err("bad PPM header");
    }
    pos += 1;
    let [w, h, maxval] = fields;
    if w == 0 || h == 0 || maxval == 0 || maxval > 65535 || w.saturating_mul(h) > 1 << 26 {
        return err("unsupported PPM size or maxval");
    }
    let bps = if maxval > 255 { 2 } else { 1 };
    let need = w * h * 3 * bps;
    let Some(raw) = bytes.get(pos..pos + need) else { return err("truncated PPM") };
    let data = if bps == 1 {
        if maxval == 255 {
            raw.to_vec()
        } else {
            raw.iter().map(|&v| ((v as usize * 255 + maxval / 2) / maxval).min(255) as u8).collect()
        }
    } else {
        raw.chunks_exact(2).map(|c| ((u16::from_be_bytes([c[0], c[1]]) as usize * 255 + maxval / 2) / maxval).min(255) as u8).collect()
    };
    Ok(RgbImage { width: w, height: h, data })
}

/// Decodes an uncompressed 24-bit (or 32-bit) BMP (BITMAPINFOHEADER or later, or
/// BITMAPCOREHEADER; bottom-up or top-down).
pub fn decode_bmp(bytes: &[u8]) -> Result<RgbImage, ImageError> {
    let u16at = |o: usize| bytes.get(o..o + 2).map(|b| u16::from_le_bytes([b[0], b[1]]));
    let u32at = |o: usize| bytes.get(o..o + 4).map(|b| u32::from_le_bytes([b[0], b[1], b[2], b[3]]));
    if !bytes.starts_with(b"BM") {
        return err("not a BMP");
    }
    let (Some(data_off), Some(dib)) = (u32at(10), u32at(14)) else { return err("truncated BMP") };
    let (w, h, bpp, compression) = if dib == 12 {
        let (Some(w), Some(h), Some(bpp)) = (u16at(18), u16at(20), u16at(24)) else { return err("truncated BMP") };
        (w as i64, h as i64, bpp, 0)
    } else if dib >= 40 {
        let (Some(w), Some(h), Some(bpp), Some(c)) = (u32at(18), u32at(22), u16at(28), u32at(30)) else { return err("truncated BMP") };
        (w as i32 as i64, h as i32 as i64, bpp, c)
    } else {
        return err("unsupported BMP header");
    };
    if compression != 0 || !(bpp == 24 || bpp == 32) {
        return err("only uncompressed 24/32-bit BMP files are supported");
    }
    let top_down = h < 0;
    let (w, h) = (w.unsigned_abs() as usize, h.unsigned_abs() as usize);
    if w == 0 || h == 0 || w.saturating_mul(h) > 1 << 26 {
        return err("unsupported BMP size");
    }
    let bpp = bpp as usize / 8;
    let stride = (w * bpp).div_ceil(4) * 4;
    let off = data_off as usize;
    let Some(pixels) = bytes.get(off..off.saturating_add(stride * h)) else { return err("truncated BMP") };
    let mut data = vec![0u8; w * h * 3];
    for y in 0..h {
        let src_row = if top_down { y } else { h - 1 - y };
        let src = &pixels[src_row * stride..src_row * stride + w * bpp];
        for (x, p) in src.chunks_exact(bpp).enumerate() {
            data[(y * w + x) * 3..(y * w + x) * 3 + 3].copy_from_slice(&[p[2], p[1], p[0]]);
        }
    }
    Ok(RgbImage { width: w, height: h, data })
}

/// Decodes a PPM or BMP file (by content).
pub fn load_image(path: &Path) -> Result<RgbImage, ImageError> {
    let bytes = fs::read(path).map_err(|e| ImageError(format!("{}: {e}", path.display())))?;
    let r = if bytes.starts_with(b"BM") { decode_bmp(&bytes) } else { decode_ppm(&bytes) };
    r.map_err(|e| ImageError(format!("{}: {}", path.display(), e.0)))
}

fn is_image_name(p: &Path) -> bool {
    p.extension().and_then(|e| e.to_str()).is_some_and(|e| matches!(e.to_ascii_lowercase().as_str(), "ppm" | "bmp"))
}

/// Replacement frames instead of the rendered scene.
#[derive(Clone, Debug, Default)]
pub struct FileSource {
    /// Frames in file-name order.
    pub paths: Vec<PathBuf>,
    next: usize,
    /// (index, the frame scaled to sensor resolution).
    cache: Option<(usize, Vec<u8>)>,
}

impl FileSource {
    /// A single image file or a directory of `*.ppm` / `*.bmp` frames. The first frame
    /// is decoded now to catch errors early; the others when they are due (a frame that
    /// fails later is shown mid-grey).
    pub fn open(path: &Path) -> Result<FileSource, ImageError> {
        let paths = if path.is_dir() {
            let mut v: Vec<PathBuf> = fs::read_dir(path)
                .map_err(|e| ImageError(format!("{}: {e}", path.display())))?
                .filter_map(|e| e.ok().map(|e| e.path()))
                .filter(|p| p.is_file() && is_image_name(p))
                .collect();
            v.sort_by(|a, b| a.file_name().cmp(&b.file_name()));
            if v.is_empty() {
                return err(format!("{}: no .ppm or .bmp frames", path.display()));
            }
            v
        } else {
            vec![path.to_path_buf()]
        };
        load_image(&paths[0])?;
        Ok(FileSource { paths, next: 0, cache: None })
    }

    /// Writes the next frame (scaled to `w × h`) into `rgb` and advances.
    fn next_frame(&mut self, w: usize, h: usize, rgb: &mut Vec<u8>) {
        let i = self.next % self.paths.len();
        self.next = (i + 1) % self.paths.len();
        match &self.cache {
            Some((ci, data)) if *ci == i && data.len() == w * h * 3 => {
                rgb.clear();
                rgb.extend_from_slice(data);
            }
            _ => {
                match load_image(&self.paths[i]) {
                    Ok(img) => img.scale_into(w, h, rgb),
                    Err(_) => {
                        rgb.clear();
                        rgb.resize(w * h * 3, 128);
                    }
                }
                if self.paths.len() == 1 {
                    self.cache = Some((i, rgb.clone()));
                }
            }
        }
    }
}

// ---------------------------------------------------------------------------------
// layer synthesis

// The loops below are shaped for the auto-vectoriser (~0.1 ms per ERS-7 image in
// release on x86-64, against ~0.6 ms for a per-pixel loop over the formulas): rows
// are walked with `chunks_exact`/`zip` (no bounds checks), bytes are read as
// little-endian words, the arithmetic after the luminance is done in 16 bits, and
// `div_round`/`clip` become the equivalent expressions of [`mean4`], [`high_pass`] and
// [`chroma`] (checked exhaustively by `tests::band_formulas_match_div_round_and_clip`).
// `synthesize_matches_reference_byte_for_byte` (camera_tests.rs) pins the output to
// a straightforward per-pixel implementation.

/// Rounded mean of four bytes summed in `sum`: `div_round(sum, 4)` = ⌊(sum + 2) / 4⌋,
/// which never needs clipping.
#[inline]
fn mean4(sum: u16) -> u8 {
    ((sum + 2) >> 2) as u8
}

/// A high-pass band, `clip(128 + div_round(n, 4))` for n ∈ −510..=510: that is
/// ⌊(n + 514) / 4⌋ ∈ 1..=256, so only the upper clip remains.
#[inline]
fn high_pass(n: i16) -> u8 {
    ((n + 514) >> 2).min(255) as u8
}

/// A colour band of layer H, `clip(128 + div_round(128·s, 1020))` for
/// s = ΣR − ΣY (or ΣB − ΣY) ∈ −1020..=1020 over a 2×2 block. With u = s + 1020 it is
/// ⌊(256u + 1020) / 2040⌋ = ⌊(32u + 127.5) / 255⌋ = ⌊(32u + 127) / 255⌋ (no multiple
/// of 255 lies in between), at most 256, and 32u + 127 fits in 16 bits.
#[inline]
fn chroma(s: i16) -> u8 {
    ((32 * (s + 1020) as u16 + 127) / 255).min(255) as u8
}

/// The six bands (or any six `w`-long parts) of a layer row.
fn six<T>(row: &mut [T], w: usize) -> [&mut [T]; 6] {
    let mut parts = row.chunks_exact_mut(w);
    std::array::from_fn(|_| parts.next().expect("a row of six bands"))
}

/// The two RGB pixels of `q` (6 bytes), read as two little-endian words.
#[inline]
fn pixel_pair(q: &[u8]) -> [[i32; 3]; 2] {
    let lo = u32::from_le_bytes(q[..4].try_into().expect("6 bytes"));
    let hi = u16::from_le_bytes(q[4..6].try_into().expect("6 bytes")) as i32;
    let byte = |k: u32| (lo >> (8 * k)) as i32 & 0xff;
    [[byte(0), byte(1), byte(2)], [byte(3), hi & 0xff, hi >> 8]]
}

/// Writes layer H of `layout` from the sensor-resolution RGB image (`2w × 2h`).
fn synth_from_rgb(l: &LayerLayout, rgb: &[u8], dst: &mut [u8]) {
    let w = l.width;
    let sensor_row = 2 * w * 3;
    // Per block of a row: the luminances a b / c d, ΣR − ΣY and ΣB − ΣY, computed in a
    // first loop; the bands follow from them in a second one (two simple loops
    // vectorise much better than one).
    let mut block = vec![0i16; 6 * w];
    let rows = dst.chunks_exact_mut(l.row_stride()).zip(rgb.chunks_exact(2 * sensor_row)).take(l.height);
    for (row, pair) in rows {
        let (top, bot) = pair.split_at(sensor_row);
        let [ya, yb, yc, yd, dr, db] = six(&mut block, w);
        let pixels = top.chunks_exact(6).zip(bot.chunks_exact(6));
        let sums = ya.iter_mut().zip(yb.iter_mut()).zip(yc.iter_mut()).zip(yd.iter_mut()).zip(dr.iter_mut()).zip(db.iter_mut());
        for ((t, u), (((((ya, yb), yc), yd), dr), db)) in pixels.zip(sums) {
            let [[r0, g0, b0], [r1, g1, b1]] = pixel_pair(t);
            let [[r2, g2, b2], [r3, g3, b3]] = pixel_pair(u);
            let (a, b, c, d) = (luma(r0, g0, b0), luma(r1, g1, b1), luma(r2, g2, b2), luma(r3, g3, b3));
            let sy = a + b + c + d;
            [*ya, *yb, *yc, *yd] = [a, b, c, d].map(|v| v as i16);
            *dr = (r0 + r1 + r2 + r3 - sy) as i16;
            *db = (b0 + b1 + b2 + b3 - sy) as i16;
        }
        let [yll, cr, cb, lh, hl, hh] = six(row, w);
        let bands = yll.iter_mut().zip(cr).zip(cb).zip(lh).zip(hl).zip(hh);
        let sums = ya.iter().zip(yb.iter()).zip(yc.iter()).zip(yd.iter()).zip(dr.iter()).zip(db.iter());
        for ((((((&a, &b), &c), &d), &dr), &db), (((((yll, cr), cb), lh), hl), hh)) in sums.zip(bands) {
            *yll = mean4((a + b + c + d) as u16);
            *cr = chroma(dr);
            *cb = chroma(db);
            *lh = high_pass(c + d - a - b);
            *hl = high_pass(b + d - a - c);
            *hh = high_pass(a + d - b - c);
        }
    }
}

/// The two bytes of `q` (2 bytes), read as one little-endian word.
#[inline]
fn byte_pair(q: &[u8]) -> (u16, u16) {
    let v = u16::from_le_bytes(q.try_into().expect("2 bytes"));
    (v & 0xff, v >> 8)
}

/// Writes an HPF layer `l` from the Y/Cr/Cb bands of the previous (double-size) HPF
/// layer `src` (whose data is `s`).
fn synth_from_layer(src: &LayerLayout, s: &[u8], l: &LayerLayout, dst: &mut [u8]) {
    let (w, sw) = (l.width, src.width);
    let rows = dst.chunks_exact_mut(l.row_stride()).zip(s.chunks_exact(2 * src.row_stride())).take(l.height);
    debug_assert_eq!(sw, 2 * w);
    for (row, pair) in rows {
        let (top, bot) = pair.split_at(src.row_stride());
        let (ycc, rest) = row.split_at_mut(3 * w);
        // Y LL, Cr and Cb (the first three bands of both layers, so one loop): means
        // of the source's Y, Cr and Cb over 2×2 blocks
        let blocks = top[..3 * sw].chunks_exact(2).zip(bot[..3 * sw].chunks_exact(2));
        for (o, (t, u)) in ycc.iter_mut().zip(blocks) {
            let ((a, b), (c, d)) = (byte_pair(t), byte_pair(u));
            *o = mean4(a + b + c + d);
        }
        let (lh, rest) = rest.split_at_mut(w);
        let (hl, hh) = rest.split_at_mut(w);
        let bands = lh.iter_mut().zip(hl).zip(hh);
        for ((t, u), ((lh, hl), hh)) in top[..sw].chunks_exact(2).zip(bot[..sw].chunks_exact(2)).zip(bands) {
            let ((a, b), (c, d)) = (byte_pair(t), byte_pair(u));
            let (a, b, c, d) = (a as i16, b as i16, c as i16, d as i16);
            *lh = high_pass(c + d - a - b);
            *hl = high_pass(b + d - a - c);
            *hh = high_pass(a + d - b - c);
        }
    }
}

/// Adds the number of bytes of `pixels` with bit k set to `counts[k]`.
fn count_bits(pixels: &[u8], counts: &mut [u32; CDT_CHANNELS]) {
    // Byte-wide sums vectorise well; 255 bytes cannot overflow them (wrapping_add
    // only spares debug builds the overflow check).
    for chunk in pixels.chunks(255) {
        for (k, c) in counts.iter_mut().enumerate() {
            *c += chunk.iter().fold(0u8, |n, &b| n.wrapping_add(b >> k & 1)) as u32;
        }
    }
}

/// Writes the CDT layer `l` from an HPF layer of the same size; returns per-channel
/// counts of matched pixels (excluding the tag bytes).
fn synth_cdt(src: &LayerLayout, s: &[u8], l: &LayerLayout, dst: &mut [u8], lut: &CdtLut) -> [u32; CDT_CHANNELS] {
    let mut counts = [0u32; CDT_CHANNELS];
    let (w, h, sw) = (l.width.min(src.width), l.height.min(src.height), src.width);
    let rows = dst.chunks_exact_mut(l.row_stride()).zip(s.chunks_exact(src.row_stride())).take(h);
    for (y, (drow, srow)) in rows.enumerate() {
        let drow = &mut drow[..w];
        let (ys, crs, cbs) = (&srow[..w], &srow[sw..sw + w], &srow[2 * sw..2 * sw + w]);
        for (((d, &y), &cr), &cb) in drow.iter_mut().zip(ys).zip(crs).zip(cbs) {
            *d = lut.classify(y, cr, cb);
        }
        // the tag bytes of the last row hold no pixels
        count_bits(if y + 1 == l.height { drow.get(TAG_SIZE..).unwrap_or(&[]) } else { drow }, &mut counts);
    }
    counts
}

/// Fills the four layers of `buf` (an image vector of `layout`) from a sensor-size
/// RGB image and writes the tags. Returns the per-channel CDT pixel counts.
pub fn synthesize(layout: &ImageLayout, rgb: &[u8], lut: &CdtLut, field_counter: u32, buf: &mut [u8]) -> [u32; CDT_CHANNELS] {
    let [lh, lm, ll, lc] = layout.layers;
    debug_assert!(lh.data_offset + lh.data_size() <= lm.data_offset && lm.data_offset + lm.data_size() <= ll.data_offset);
    debug_assert!(ll.data_offset + ll.data_size() <= lc.data_offset);
    assert!(rgb.len() >= 4 * lh.width * lh.height * 3, "RGB image smaller than the sensor");
    let (_, rest) = buf.split_at_mut(lh.data_offset);
    let (h, rest) = rest.split_at_mut(lm.data_offset - lh.data_offset);
    let (m, rest) = rest.split_at_mut(ll.data_offset - lm.data_offset);
    let (l, rest) = rest.split_at_mut(lc.data_offset - ll.data_offset);
    synth_from_rgb(&lh, rgb, h);
    synth_from_layer(&lh, h, &lm, m);
    synth_from_layer(&lm, m, &ll, l);
    let counts = synth_cdt(&lm, m, &lc, rest, lut);
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

// ---------------------------------------------------------------------------------
// camera parameters (robot-api 5.3, 5.4, 10)

pub const CAM_SET_WHITE_BALANCE: u32 = 384;
pub const CAM_SET_GAIN: u32 = 385;
pub const CAM_SET_SHUTTER_SPEED: u32 = 386;

/// `ocamparam*` settings (1 = INDOOR/LOW/SLOW, 2 = OUTDOOR/MID/MID, 3 = FL/HIGH/FAST).
/// Effects on the sensed image (robot-api 5.4, an inference): gain LOW/HIGH ×0.5/×2,
/// shutter SLOW/FAST ×2/×0.5 on every channel; the scene is lit like the default
/// white balance (FL, 5000 K), so INDOOR (2856 K) tints it blue (R ×0.8, B ×1.25)
/// and OUTDOOR (6500 K) warm (R ×1.1, B ×0.9).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CameraSettings {
    pub white_balance: u32,
    pub gain: u32,
    pub shutter: u32,
}

impl Default for CameraSettings {
    fn default() -> CameraSettings {
        CameraSettings { white_balance: 3, gain: 2, shutter: 2 }
    }
}

impl CameraSettings {
    /// Applies `request` (`oprmreqCAM_SET_*`) with `camparam`: oSUCCESS, oINVALID_ARG
    /// for a value outside 1..3, oNOT_SUPPORTED for other requests.
    pub fn control(&mut self, request: u32, camparam: u32) -> OStatus {
        let slot = match request {
            CAM_SET_WHITE_BALANCE => &mut self.white_balance,
            CAM_SET_GAIN => &mut self.gain,
            CAM_SET_SHUTTER_SPEED => &mut self.shutter,
            _ => return O_NOT_SUPPORTED,
        };
        if !(1..=3).contains(&camparam) {
            return O_INVALID_ARG;
        }
        *slot = camparam;
        O_SUCCESS
    }

    /// Per-channel multipliers (R, G, B).
    pub fn factors(&self) -> [f64; 3] {
        let k = [0.5, 1.0, 2.0][self.gain.clamp(1, 3) as usize - 1] * [2.0, 1.0, 0.5][self.shutter.clamp(1, 3) as usize - 1];
        let tint = match self.white_balance {
            1 => [0.8, 1.0, 1.25],
            2 => [1.1, 1.0, 0.9],
            _ => [1.0, 1.0, 1.0],
        };
        tint.map(|t| t * k)
    }

    /// Applies the multipliers to an RGB buffer in place (nothing to do by default).
    pub fn apply(&self, rgb: &mut [u8]) {
        let f = self.factors();
        if f == [1.0; 3] {
            return;
        }
        let luts = f.map(|k| {
            let mut t = [0u8; 256];
            for (i, v) in t.iter_mut().enumerate() {
                *v = (i as f64 * k).round().clamp(0.0, 255.0) as u8;
            }
            t
        });
        for px in rgb.chunks_exact_mut(3) {
            for (c, lut) in px.iter_mut().zip(&luts) {
                *c = lut[*c as usize];
            }
        }
    }
}

// ---------------------------------------------------------------------------------
// the camera

/// Camera state of one robot: tables, field counter, image source, render buffers.
#[derive(Clone, Debug)]
pub struct Camera {
    pub design: Design,
    pub layout: ImageLayout,
    pub lut: CdtLut,
    /// Counter written into the next image's tag (starts at 1).
    pub field_counter: u32,
    pub source: Option<FileSource>,
    /// The sensor-resolution RGB of the last image.
    pub rgb: RgbImage,
    /// CDT pixel counts of the last image.
    pub last_counts: [u32; CDT_CHANNELS],
    pub settings: CameraSettings,
}

impl Camera {
    pub fn new(design: Design) -> Camera {
        let (w, h, _, _) = super::render::sensor_spec(design);
        Camera {
            design,
            layout: ImageLayout::new(design),
            lut: CdtLut::default(),
            field_counter: 1,
            source: None,
            rgb: RgbImage { width: w, height: h, data: Vec::new() },
            last_counts: [0; CDT_CHANNELS],
            settings: CameraSettings::default(),
        }
    }

    /// Fills `self.rgb` from the file source, or returns false (render the scene).
    pub fn fill_from_source(&mut self) -> bool {
        match &mut self.source {
            Some(s) => {
                s.next_frame(self.rgb.width, self.rgb.height, &mut self.rgb.data);
                true
            }
            None => false,
        }
    }

    /// Bytes of one image vector ([`Camera::build_vector`]'s `out`).
    pub fn vector_size(&self) -> usize {
        self.layout.size()
    }

    /// Builds the complete image vector from `self.rgb` into `out` (at least
    /// [`Camera::vector_size`] bytes: the shared region itself, so the vector is written
    /// once) and advances the field counter.
    /// The camera settings are applied to `self.rgb` first.
    pub fn build_vector(&mut self, primitive: PrimitiveId, frame: u32, out: &mut [u8]) {
        self.settings.apply(&mut self.rgb.data);
        self.layout.write_header(out, primitive, frame).expect("sized");
        self.last_counts = synthesize(&self.layout, &self.rgb.data, &self.lut, self.field_counter, out);
        self.field_counter = self.field_counter.wrapping_add(1);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn colour_conversion_round_trips() {
        for rgb in [[0, 0, 0], [255, 255, 255], [250, 90, 160], [40, 150, 70], [128, 128, 128], [10, 200, 30]] {
            let back = ycrcb_to_rgb(rgb_to_ycrcb(rgb));
            for k in 0..3 {
                assert!((back[k] as i32 - rgb[k] as i32).abs() <= 3, "{rgb:?} -> {back:?}");
            }
        }
        assert_eq!(rgb_to_ycrcb([128, 128, 128]), [128, 128, 128]);
        let pink = rgb_to_ycrcb([250, 90, 160]);
        assert!(pink[1] > 150, "{pink:?}");
        let green = rgb_to_ycrcb([40, 150, 70]);
        assert!(green[1] < 110 && green[2] < 128, "{green:?}");
    }

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

#[cfg(test)]
#[path = "camera_tests.rs"]
mod end_to_end;
