//! `/cdt.png`: the camera's colour-detection layer (robot-api 6.6, layer C) as an
//! overlay for the camera picture: a pixel any CDT channel detected takes the colour of
//! its lowest set channel, the rest is transparent. The layer is synthesized again from
//! the last picture and the loaded tables, only when a browser asks, outside the
//! robot's lock (the same function the camera uses, so the same bits).
use sdk_runtime::robot::camera::{synthesize, CdtLut, CDT_CHANNELS};
use sdk_runtime::robot::image::{band, ImageLayout, TAG_SIZE};
use sdk_runtime::runtime::Runtime;

/// Channel k's colour (ocdtCHANNEL0 first), opaque.
pub(crate) const COLOURS: [[u8; 4]; CDT_CHANNELS] = [
    [255, 0, 255, 255],
    [0, 255, 255, 255],
    [255, 255, 0, 255],
    [0, 255, 0, 255],
    [255, 128, 0, 255],
    [0, 96, 255, 255],
    [255, 255, 255, 255],
    [255, 0, 0, 255],
];

/// What `/cdt.png` answers.
pub(crate) enum Overlay {
    Png(Vec<u8>),
    /// The camera took no picture (the program never opened it, or not yet).
    NoPicture,
    /// The program loaded no table (`SetCdtVectorData`): layer C is empty.
    NoTable,
}

/// The overlay of the last picture as PNG (layer C's size, RGBA).
pub(crate) fn overlay_png(rt: &Runtime) -> std::result::Result<Overlay, png::EncodingError> {
    let (layout, lut, rgb) = {
        let robot = rt.vr.robot();
        let cam = robot.camera();
        if cam.rgb.data.is_empty() {
            return Ok(Overlay::NoPicture);
        }
        if cam.lut.key().iter().all(Option::is_none) {
            return Ok(Overlay::NoTable);
        }
        (cam.layout.clone(), cam.lut.clone(), cam.rgb.data.clone())
    };
    let (w, h, rgba) = overlay_rgba(&layout, &lut, &rgb);
    let mut out = Vec::new();
    let mut enc = png::Encoder::new(&mut out, w as u32, h as u32);
    enc.set_color(png::ColorType::Rgba);
    enc.set_depth(png::BitDepth::Eight);
    enc.set_compression(png::Compression::Fast);
    let mut writer = enc.write_header()?;
    writer.write_image_data(&rgba)?;
    writer.finish()?;
    Ok(Overlay::Png(out))
}

/// Layer C of the sensor-resolution picture `rgb` classified with `lut`, one RGBA
/// pixel per CDT pixel: (width, height, pixels).
fn overlay_rgba(layout: &ImageLayout, lut: &CdtLut, rgb: &[u8]) -> (usize, usize, Vec<u8>) {
    let mut vector = vec![0u8; layout.size()];
    synthesize(layout, rgb, lut, 0, &mut vector);
    let k = layout.layers.iter().position(|l| l.bands == 1).expect("a CDT layer");
    let c = layout.layers[k];
    let mut rgba = Vec::with_capacity(c.width * c.height * 4);
    for y in 0..c.height {
        for x in 0..c.width {
            // The last row begins with the image's tag, not pixels.
            let tag = y + 1 == c.height && x < TAG_SIZE;
            let bits = if tag { 0 } else { vector[layout.pixel_offset(k, band::CDT, x, y).expect("inside the layer")] };
            rgba.extend_from_slice(if bits == 0 { &[0; 4] } else { &COLOURS[bits.trailing_zeros() as usize] });
        }
    }
    (c.width, c.height, rgba)
}

#[cfg(test)]
mod tests {
    use super::*;
    use sdk_runtime::robot::camera::{cdt_entry, parse_cdt, Camera};
    use sdk_runtime::robot::model::Design;

    #[test]
    fn each_channel_takes_its_colour_and_the_tag_stays_clear() {
        let cam = Camera::new(Design::Ers7);
        let (w, h) = (cam.rgb.width, cam.rgb.height);
        // Left half pink (channel 0), right half green (channel 1), a blue top row band
        // that neither table detects.
        let mut rgb = Vec::with_capacity(w * h * 3);
        for y in 0..h {
            for x in 0..w {
                rgb.extend_from_slice(match (y < 8, x < w / 2) {
                    (true, _) => &[30, 30, 220],
                    (false, true) => &[255, 80, 180],
                    (false, false) => &[20, 200, 40],
                });
            }
        }
        let pink = [cdt_entry(255, 150, 255, 129); 32];
        let green = [cdt_entry(110, 0, 127, 0); 32];
        let bytes = sdk_runtime::robot::camera::build_cdt_vector(7, &[(0x01, pink), (0x02, green)]);
        let mut lut = CdtLut::default();
        for t in parse_cdt(&bytes, 7, Design::Ers7).unwrap() {
            lut.load(&t);
        }
        let (cw, ch, rgba) = overlay_rgba(&cam.layout, &lut, &rgb);
        assert_eq!((cw, ch), (104, 80), "layer C of the ERS-7");
        let px = |x: usize, y: usize| &rgba[(y * cw + x) * 4..(y * cw + x) * 4 + 4];
        assert_eq!(px(0, 0), &[0; 4], "blue: no channel");
        assert_eq!(px(10, 40), &COLOURS[0], "pink: channel 0");
        assert_eq!(px(90, 40), &COLOURS[1], "green: channel 1");
        assert_eq!(px(TAG_SIZE - 1, ch - 1), &[0; 4], "the tag is no pixel");
        assert_eq!(px(TAG_SIZE, ch - 1), &COLOURS[0]);
    }
}
