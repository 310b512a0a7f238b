//! RGB ↔ Y Cr Cb in the fixed point of robot-api 6.6 (rounded, clipped to 0..255).

/// Fixed-point (×65536) luminance weights 0.51/1.7, 1/1.7, 0.19/1.7 (sum 65536).
const KY: [i32; 3] = [19_661, 38_550, 7_325];

#[inline(always)]
pub(super) fn luma(r: i32, g: i32, b: i32) -> i32 {
    (KY[0] * r + KY[1] * g + KY[2] * b + 32_768) >> 16
}

/// Rounded `n / d` for d > 0.
#[inline]
pub(super) fn div_round(n: i32, d: i32) -> i32 {
    (2 * n + d).div_euclid(2 * d)
}

#[inline]
pub(super) fn clip(v: i32) -> u8 {
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
}
