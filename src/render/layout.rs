//! Where the pattern goes in the image: the uniform scale, the margins, the band for the
//! key (scale bar and legend), and the pattern-to-pixel mapping (y up in the pattern, y down in the image,
//! no mirroring).
//!
//! The width is the caller's; the height follows the pattern's aspect ratio, capped at
//! [`MAX_ASPECT`] times the width and at [`MAX_SIZE`] pixels (a tall pattern is then scaled
//! down to fit and centred horizontally). Degenerate bounds are handled: a line with zero
//! width or height scales along its other extent; a single point is drawn centred at one
//! pixel per unit.

use glam::DVec2;

use crate::geom::tolerance::ROUNDOFF;

/// Smallest accepted image width, pixels.
pub const MIN_SIZE: u32 = 16;
/// Largest accepted image width and largest produced height, pixels.
pub const MAX_SIZE: u32 = 16384;
/// Largest height as a multiple of the width.
pub const MAX_ASPECT: u32 = 4;

/// The mapping from pattern coordinates to pixels, and the image size.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Layout {
    /// Image width, pixels.
    pub width: u32,
    /// Image height, pixels.
    pub height: u32,
    /// Pixels per pattern unit.
    pub scale: f64,
    /// Pixel x of the pattern's left edge (min x).
    left: f64,
    /// Pixel y of the pattern's top edge (max y).
    top: f64,
    /// The pattern's min x and max y.
    anchor: DVec2,
    /// Margin, pixels.
    pub margin: u32,
    /// Size of one font pixel, pixels.
    pub font_px: u32,
    /// Top of the key band (equal to `height` when there is none).
    pub band_top: u32,
}

impl Layout {
    /// Lays out bounds `lo..hi` in an image `width` pixels wide with `margin` pixels on each
    /// side, reserving a band of `band` pixels at the bottom for the key (scale bar and
    /// legend, [`super::legend::Key`]). The caller has checked `width` (within
    /// [`MIN_SIZE`]..=[`MAX_SIZE`]) and `margin` (≤ width / 8).
    pub fn new(lo: DVec2, hi: DVec2, width: u32, margin: u32, band: u32) -> Layout {
        let font_px = super::legend::font_px_for(width);
        let max_height = (width.saturating_mul(MAX_ASPECT)).min(MAX_SIZE);
        let band = band.min(max_height / 2);
        let avail_w = f64::from(width - 2 * margin);
        let avail_h = f64::from(max_height.saturating_sub(2 * margin + band).max(1));
        let ext = hi - lo;
        let sx = if ext.x > 0.0 {
            avail_w / ext.x
        } else {
            f64::INFINITY
        };
        let sy = if ext.y > 0.0 {
            avail_h / ext.y
        } else {
            f64::INFINITY
        };
        let scale = match sx.min(sy) {
            s if s.is_finite() && s > 0.0 => s,
            _ => 1.0,
        };
        let drawn_h = (ext.y * scale).ceil().max(1.0);
        let height = (drawn_h as u32 + 2 * margin + band).min(max_height.max(MIN_SIZE));
        let left = f64::from(margin) + 0.5 * (avail_w - ext.x * scale);
        Layout {
            width,
            height,
            scale,
            left,
            top: f64::from(margin) + 0.5 * (drawn_h - ext.y * scale),
            anchor: DVec2::new(lo.x, hi.y),
            margin,
            font_px,
            band_top: height - band,
        }
    }

    /// The pixel position of a pattern point (f64; convert to f32 only for tiny-skia).
    #[inline]
    pub fn to_px(self, p: DVec2) -> DVec2 {
        DVec2::new(
            self.left + (p.x - self.anchor.x) * self.scale,
            self.top + (self.anchor.y - p.y) * self.scale,
        )
    }
}

/// The largest "nice" length (1, 2 or 5 × 10^k) not above `max`; `None` for a non-positive
/// or non-finite `max`.
pub fn nice_length(max: f64) -> Option<f64> {
    if !(max.is_finite() && max > 0.0) {
        return None;
    }
    let k = max.log10().floor();
    let base = 10f64.powf(k);
    let m = max / base;
    // Guard against log10 rounding putting m just below 1 or at 10.
    let pick = [10.0, 5.0, 2.0, 1.0]
        .into_iter()
        .find(|&c| c <= m * (1.0 + ROUNDOFF))
        .unwrap_or(0.5);
    Some(pick * base)
}

/// The label of a scale-bar length: `"10 mm"`, `"0.5 units"`, `"1 unit"`.
pub fn length_label(length: f64, unit: &str) -> String {
    let decimals = if length >= 1.0 {
        0
    } else {
        (-length.log10()).ceil().max(0.0) as usize
    };
    let number = format!("{length:.decimals$}");
    if unit == "units" && number == "1" {
        return "1 unit".to_string();
    }
    format!("{number} {unit}")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nice_lengths_are_one_two_five() {
        assert_eq!(nice_length(7.3), Some(5.0));
        assert_eq!(nice_length(19.9), Some(10.0));
        assert_eq!(nice_length(20.0), Some(20.0));
        assert!((nice_length(0.03).expect("nice") - 0.02).abs() < 1e-15);
        assert_eq!(nice_length(1000.0), Some(1000.0));
        assert_eq!(nice_length(0.0), None);
    }

    #[test]
    fn labels() {
        assert_eq!(length_label(10.0, "mm"), "10 mm");
        assert_eq!(length_label(0.5, "units"), "0.5 units");
        assert_eq!(length_label(0.02, "mm"), "0.02 mm");
        assert_eq!(length_label(1.0, "units"), "1 unit");
    }

    #[test]
    fn y_up_maps_to_image_top() {
        let l = Layout::new(DVec2::ZERO, DVec2::new(100.0, 50.0), 220, 10, 0);
        assert_eq!(l.height, 120);
        assert_eq!(l.to_px(DVec2::new(0.0, 50.0)), DVec2::new(10.0, 10.0));
        assert_eq!(l.to_px(DVec2::new(100.0, 0.0)), DVec2::new(210.0, 110.0));
    }

    #[test]
    fn tall_patterns_are_capped_and_points_do_not_divide_by_zero() {
        let l = Layout::new(DVec2::ZERO, DVec2::new(1.0, 100.0), 100, 10, 0);
        assert_eq!(l.height, 400);
        let p = Layout::new(DVec2::ONE, DVec2::ONE, 100, 10, 20);
        assert!(p.scale.is_finite() && p.to_px(DVec2::ONE).is_finite());
    }
}
