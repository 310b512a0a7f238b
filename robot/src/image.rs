//! Layout of `OFbkImageVectorData` (robot-api 6.6, ers7-model 9.2).
//!
//! Why it exists: the camera system object must produce image vectors whose infos,
//! band-interleaved rows and tag rows match what `OFbkImage` and the samples expect.
//! This module computes the layout and writes header, infos and tags; pixel synthesis
//! is left to the camera wiring ([`ImageLayout::pixel_offset`] tells where each pixel
//! goes).
//!
//! Per layer of width `w`: rows are band-interleaved (H/M/L: Y_LL, Cr, Cb, Y_LH, Y_HL,
//! Y_HH, each `w` bytes, stride 6w; C: one CDT band, stride w). The first 16 bytes of
//! the last row of every band carry the tag: bytes 0..4 the field counter (32-bit LE;
//! `FieldCounter()` reads the low 16 bits), bytes 4..8 CDT channels 4..7 and 8..12
//! channels 0..3 `ColorFrequency` (pixel count / 16, saturated to 255), 12..16 zero.

use super::model::{Design, PrimitiveId};
use super::vectors::{odata, wr_u32, Result, VectorError, HEADER_SIZE};

pub const IMAGE_INFO_SIZE: usize = 32;
pub const LAYERS: usize = 4;
pub const TAG_SIZE: usize = 16;

/// `OFbkImageBand` codes.
pub mod band {
    pub const Y: u32 = 0;
    pub const CR: u32 = 1;
    pub const CB: u32 = 2;
    pub const CDT: u32 = 3;
    pub const Y_LH: u32 = 4;
    pub const Y_HL: u32 = 5;
    pub const Y_HH: u32 = 6;
}

/// One layer of the image vector.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LayerLayout {
    /// odataFBK_YCrCb_HPF (24) for H/M/L, odataFBK_CDT (20) for C.
    pub data_type: u32,
    pub width: usize,
    pub height: usize,
    /// Bands per row (6 or 1).
    pub bands: usize,
    /// From the vector start.
    pub data_offset: usize,
}

impl LayerLayout {
    pub fn row_stride(&self) -> usize {
        self.width * self.bands
    }
    pub fn data_size(&self) -> usize {
        self.row_stride() * self.height
    }
    /// `OFbkImage::Skip()`.
    pub fn skip(&self) -> usize {
        self.row_stride() - self.width
    }
    /// Position of `band` inside a row, or None when the layer has no such band
    /// (the combinations `OFbkImage` treats as invalid).
    pub fn band_position(&self, b: u32) -> Option<usize> {
        match (self.data_type, b) {
            (odata::FBK_CDT, band::CDT) => Some(0),
            (odata::FBK_CDT, _) => None,
            (_, band::Y | band::CR | band::CB) => Some(b as usize),
            (odata::FBK_YCRCB_HPF, band::Y_LH | band::Y_HL | band::Y_HH) => Some(b as usize - 1),
            _ => None,
        }
    }
}

/// The 4-layer layout (H, M, L, C) of one design's image vector.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ImageLayout {
    pub layers: [LayerLayout; LAYERS],
}

impl ImageLayout {
    /// ERS-7: H 208×160, M 104×80, L 52×40 (6 bands), C 104×80; ERS-2xx: H 176×144,
    /// M 88×72, L 44×36, C 88×72. Data blocks follow the 4 infos contiguously.
    pub fn new(design: Design) -> ImageLayout {
        let (w, h) = match design {
            Design::Ers7 => (208, 160),
            _ => (176, 144),
        };
        let dims = [(w, h, 6), (w / 2, h / 2, 6), (w / 4, h / 4, 6), (w / 2, h / 2, 1)];
        let mut off = HEADER_SIZE + IMAGE_INFO_SIZE * LAYERS;
        let layers = dims.map(|(width, height, bands)| {
            let l = LayerLayout { data_type: if bands == 6 { odata::FBK_YCRCB_HPF } else { odata::FBK_CDT }, width, height, bands, data_offset: off };
            off += l.data_size();
            l
        });
        ImageLayout { layers }
    }

    /// Total bytes of the vector.
    pub fn size(&self) -> usize {
        let last = &self.layers[LAYERS - 1];
        last.data_offset + last.data_size()
    }

    /// Byte offset (from the vector start) of pixel (x, y) of `band` in `layer`.
    pub fn pixel_offset(&self, layer: usize, b: u32, x: usize, y: usize) -> Option<usize> {
        let l = self.layers.get(layer)?;
        if x >= l.width || y >= l.height {
            return None;
        }
        Some(l.data_offset + y * l.row_stride() + l.band_position(b)? * l.width + x)
    }

    /// Writes header (type 1027, 4 infos, numData 4, syncKey UNDEF) and infos with
    /// `primitive` and `frame_number`; leaves the pixel data untouched.
    pub fn write_header(&self, buf: &mut [u8], primitive: PrimitiveId, frame_number: u32) -> Result<()> {
        if buf.len() < self.size() {
            return Err(VectorError::TooShort { need: self.size(), have: buf.len() });
        }
        buf[..HEADER_SIZE + IMAGE_INFO_SIZE * LAYERS].fill(0);
        let total = u32::try_from(buf.len()).map_err(|_| VectorError::BadArgument("image vector too large"))?;
        for (i, v) in [0, 0, 0, total, odata::FBKIMAGE_VECTOR, HEADER_SIZE as u32, IMAGE_INFO_SIZE as u32, 4, 4, 0xFFFF_FFFF].into_iter().enumerate() {
            wr_u32(buf, 4 * i, v)?;
        }
        for (i, l) in self.layers.iter().enumerate() {
            let o = HEADER_SIZE + IMAGE_INFO_SIZE * i;
            for (k, v) in
                [l.data_type, primitive, frame_number, l.data_offset as u32, l.data_size() as u32, l.width as u32, l.height as u32].into_iter().enumerate()
            {
                wr_u32(buf, o + 4 * k, v)?;
            }
        }
        Ok(())
    }

    /// Writes the 16-byte tag into the last row of every band of every layer.
    /// `color_pixels[k]` = number of pixels matched by CDT channel k.
    pub fn write_tags(&self, buf: &mut [u8], field_counter: u32, color_pixels: [u32; 8]) -> Result<()> {
        if buf.len() < self.size() {
            return Err(VectorError::TooShort { need: self.size(), have: buf.len() });
        }
        let mut tag = [0u8; TAG_SIZE];
        tag[0..4].copy_from_slice(&field_counter.to_le_bytes());
        for (ch, &n) in color_pixels.iter().enumerate() {
            let f = (n / 16).min(255) as u8;
            let at = if ch < 4 { 8 + ch } else { 4 + (ch - 4) };
            tag[at] = f;
        }
        for l in &self.layers {
            if l.height == 0 || l.width < TAG_SIZE {
                continue;
            }
            for b in 0..l.bands {
                let at = l.data_offset + (l.height - 1) * l.row_stride() + b * l.width;
                buf[at..at + TAG_SIZE].copy_from_slice(&tag);
            }
        }
        Ok(())
    }
}

/// `OFbkImage::FieldCounter()` of a band's tag bytes.
pub fn field_counter(tag: &[u8]) -> Option<u16> {
    Some(u16::from_le_bytes([*tag.first()?, *tag.get(1)?]))
}

/// `OFbkImage::ColorFrequency(chan)` of a band's tag bytes (`chan` = ocdtCHANNELk bit).
pub fn color_frequency(tag: &[u8], chan: u32) -> u8 {
    let at = match chan {
        0x01 => 8,
        0x02 => 9,
        0x04 => 10,
        0x08 => 11,
        0x10 => 4,
        0x20 => 5,
        0x40 => 6,
        0x80 => 7,
        _ => return 0,
    };
    tag.get(at).copied().unwrap_or(0)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::vectors::rd_u32;

    #[test]
    fn ers7_layer_sizes() {
        let l = ImageLayout::new(Design::Ers7);
        let sizes: Vec<usize> = l.layers.iter().map(|x| x.data_size()).collect();
        assert_eq!(sizes, vec![199_680, 49_920, 12_480, 8_320]);
        assert_eq!(l.layers[0].data_offset, 320);
        assert_eq!(l.layers[1].data_offset, 320 + 199_680);
        assert_eq!(l.layers[0].skip(), 5 * 208);
        assert_eq!(l.layers[3].skip(), 0);
        assert_eq!(l.size(), 320 + 199_680 + 49_920 + 12_480 + 8_320);
        // Cr of H at (1, 2)
        assert_eq!(l.pixel_offset(0, band::CR, 1, 2), Some(320 + 2 * 6 * 208 + 208 + 1));
        assert_eq!(l.pixel_offset(0, band::Y_HH, 0, 0), Some(320 + 5 * 208));
        assert_eq!(l.pixel_offset(3, band::CR, 0, 0), None);
        assert_eq!(l.pixel_offset(3, band::CDT, 3, 0), Some(l.layers[3].data_offset + 3));
        assert_eq!(l.pixel_offset(0, band::CDT, 0, 0), None);
        assert_eq!(l.pixel_offset(0, band::Y, 208, 0), None);
        let l2 = ImageLayout::new(Design::Ers210);
        assert_eq!((l2.layers[2].width, l2.layers[2].height), (44, 36));
    }

    #[test]
    fn header_and_tags() {
        let l = ImageLayout::new(Design::Ers7);
        let mut b = vec![0u8; l.size()];
        l.write_header(&mut b, 0x120, 77).unwrap();
        assert_eq!(rd_u32(&b, 16).unwrap(), 1027);
        assert_eq!(rd_u32(&b, 32).unwrap(), 4);
        let c = 192 + 32 * 3;
        assert_eq!(rd_u32(&b, c).unwrap(), 20);
        assert_eq!(rd_u32(&b, c + 4).unwrap(), 0x120);
        assert_eq!(rd_u32(&b, c + 8).unwrap(), 77);
        assert_eq!(rd_u32(&b, c + 20).unwrap(), 104);
        assert_eq!(rd_u32(&b, 192 + 16).unwrap(), 199_680);
        l.write_tags(&mut b, 0x1_0005, [160, 0, 0, 0, 32, 0, 0, 99999]).unwrap();
        for layer in 0..4 {
            let lay = l.layers[layer];
            for band_i in 0..lay.bands {
                let at = lay.data_offset + (lay.height - 1) * lay.row_stride() + band_i * lay.width;
                let tag = &b[at..at + 16];
                assert_eq!(field_counter(tag), Some(5));
                assert_eq!(color_frequency(tag, 0x01), 10);
                assert_eq!(color_frequency(tag, 0x10), 2);
                assert_eq!(color_frequency(tag, 0x80), 255);
                assert_eq!(color_frequency(tag, 0x03), 0);
            }
        }
        assert!(l.write_tags(&mut b[..1000], 0, [0; 8]).is_err());
    }
}
