//! Replacement image sources: PPM and BMP decoders, and a file or folder of images that
//! stands in for the rendered scene (`--camera`).
use std::fs;
use std::path::{Path, PathBuf};

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
    pub(super) fn next_frame(&mut self, w: usize, h: usize, rgb: &mut Vec<u8>) {
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
