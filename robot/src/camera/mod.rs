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
//!
//! Here: the camera parameters and the per-robot [`Camera`]; the parts are in `colour`,
//! `cdt`, `source` and `layers`.

mod cdt;
mod colour;
#[cfg(test)]
mod end_to_end;
mod layers;
#[cfg(test)]
mod reuse_tests;
#[cfg(test)]
mod runs_tests;
mod source;

pub use cdt::*;
pub use colour::*;
pub use layers::*;
pub use source::*;

use super::image::ImageLayout;
use super::model::{Design, PrimitiveId};
use super::render::{CameraWorld, FlatRuns, PinholeCamera};
use super::status::*;

// Camera parameters (robot-api 5.3, 5.4, 10).

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

/// Camera state of one robot: tables, field counter, image source, render buffers.
#[derive(Clone, Debug)]
pub struct Camera {
    pub design: Design,
    pub layout: ImageLayout,
    pub lut: CdtLut,
    /// Counter written into the next image's tag (starts at 1).
    pub field_counter: u32,
    pub source: Option<FileSource>,
    /// The sensor-resolution RGB of the last image (camera settings applied).
    pub rgb: RgbImage,
    /// CDT pixel counts of the last image.
    pub last_counts: [u32; CDT_CHANNELS],
    pub settings: CameraSettings,
    reuse: Reuse,
    /// Runs of identical pixels of `rgb` when it is a render (the settings map equal
    /// pixels to equal pixels, so they hold after them too), and their layers' runs.
    runs: FlatRuns,
    /// `runs` describe `rgb` (false once `rgb` is replaced by anything but a render).
    runs_hold: bool,
    layer_runs: LayerRuns,
}

/// What `rgb` and the last layers were made from: a robot whose camera and scene did not
/// move since the last image gets the same picture again without rendering or
/// synthesising it (a camera program that holds its head still pays one copy).
#[derive(Clone, Debug, Default)]
struct Reuse {
    /// `rgb` is the render of this scene, these settings applied.
    scene: Option<(PinholeCamera, CameraWorld, Option<f64>, CameraSettings)>,
    /// `rgb` is the same as for the previous image.
    rgb_unchanged: bool,
    /// The layer bytes (from layer H's data on) synthesized from `rgb` with these tables,
    /// and their CDT counts.
    layers: Option<(CdtKey, Vec<u8>, [u32; CDT_CHANNELS])>,
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
            reuse: Reuse::default(),
            runs: FlatRuns::default(),
            runs_hold: false,
            layer_runs: LayerRuns::default(),
        }
    }

    /// Fills `self.rgb` from the file source, or returns false (render the scene).
    pub fn fill_from_source(&mut self) -> bool {
        match &mut self.source {
            Some(s) => {
                s.next_frame(self.rgb.width, self.rgb.height, &mut self.rgb.data);
                self.rgb_replaced();
                true
            }
            None => false,
        }
    }

    /// Fills `self.rgb` with `data` (sensor-resolution RGB, cut or zero-padded to size).
    pub fn fill_from(&mut self, data: &[u8]) {
        let n = self.rgb.width * self.rgb.height * 3;
        self.rgb.data.clear();
        self.rgb.data.extend_from_slice(&data[..n.min(data.len())]);
        self.rgb.data.resize(n, 0);
        self.rgb_replaced();
    }

    /// Renders `world` seen by `cam` (and the PSD wall) into `self.rgb`, unless `rgb`
    /// already holds that picture with the current settings.
    pub fn render_scene(&mut self, cam: &PinholeCamera, world: &CameraWorld, wall_mm: Option<f64>) {
        let same = matches!(&self.reuse.scene, Some((c, w, m, s)) if c == cam && w == world && *m == wall_mm && *s == self.settings);
        if same {
            self.reuse.rgb_unchanged = true;
            return;
        }
        cam.render(world, wall_mm, &mut self.rgb.data, Some((&mut self.runs, 2 * MIN_RUN)));
        self.rgb_replaced();
        self.runs_hold = true;
        self.reuse.scene = Some((*cam, world.clone(), wall_mm, self.settings));
    }

    /// `rgb` holds a new raw picture: applies the camera settings to it.
    fn rgb_replaced(&mut self) {
        self.settings.apply(&mut self.rgb.data);
        self.reuse = Reuse::default();
        self.runs_hold = false; // (a render records its runs again)
    }

    /// Bytes of one image vector ([`Camera::build_vector`]'s `out`).
    pub fn vector_size(&self) -> usize {
        self.layout.size()
    }

    /// Builds the complete image vector from `self.rgb` (filled by one of the `fill_*`
    /// or [`Camera::render_scene`] calls) into `out` (at least [`Camera::vector_size`]
    /// bytes: the shared region itself, so the vector is written once) and advances the
    /// field counter. Layers of an unchanged picture and tables are copied from the last
    /// image instead of synthesized again (the same bytes).
    pub fn build_vector(&mut self, primitive: PrimitiveId, frame: u32, out: &mut [u8]) {
        self.layout.write_header(out, primitive, frame).expect("sized");
        let start = self.layout.layers[0].data_offset;
        let end = self.layout.size();
        let key = self.lut.key();
        let unchanged = std::mem::take(&mut self.reuse.rgb_unchanged);
        match &self.reuse.layers {
            Some((k, bytes, counts)) if unchanged && *k == key => {
                out[start..end].copy_from_slice(bytes);
                self.last_counts = *counts;
                self.layout.write_tags(out, self.field_counter, *counts).expect("sized");
            }
            _ => {
                let runs = self.runs_hold.then_some((&self.runs, &mut self.layer_runs));
                self.last_counts = synthesize_runs(&self.layout, &self.rgb.data, runs, &self.lut, self.field_counter, out);
                // Kept only once a picture repeats: a moving camera pays no copy.
                self.reuse.layers = unchanged.then(|| (key, out[start..end].to_vec(), self.last_counts));
            }
        }
        self.field_counter = self.field_counter.wrapping_add(1);
    }
}
