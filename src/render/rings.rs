//! Rings around the findings of a check, numbered as the text report numbers them.
//!
//! Finding `i` of the slice (from 0) is labelled `i + 1`, the number
//! [`crate::check::CheckReport::to_text`] prints before the same finding. Findings whose
//! positions land within one ring width of each other share a ring, labelled with all their
//! numbers (`1,2`), so two faults at one vertex are not one unexplained ring. The ring's radius
//! is a share of the picture's width ([`RING_WIDTH_SHARE`], at least [`MIN_RING_RADIUS_PX`]
//! and six line widths), so it is found at a glance at any size. At most [`MAX_NUMBERED`] rings
//! carry numbers; beyond that the rings are drawn without.

use glam::DVec2;
use tiny_skia::{PathBuilder, Pixmap, Stroke, Transform};

use super::layout::Layout;
use super::legend::{self, draw_label, paint};
use super::style::FAULT_COLOR;
use crate::check::Finding;

/// Ring radius as a share of the image width.
pub const RING_WIDTH_SHARE: f32 = 1.0 / 30.0;
/// Smallest ring radius, pixels.
pub const MIN_RING_RADIUS_PX: f32 = 10.0;
/// Most rings that carry a number.
pub const MAX_NUMBERED: usize = 200;
/// Most numbers written on one ring (the rest become `…`).
const MAX_NUMBERS_PER_RING: usize = 4;

/// Ring radius for an image `width` pixels wide with base line width `lw`.
pub fn ring_radius(width: u32, lw: f32) -> f32 {
    (6.0 * lw)
        .max(MIN_RING_RADIUS_PX)
        .max(width as f32 * RING_WIDTH_SHARE)
}

/// One ring: its centre in pixels and the numbers (from 1) of the findings it holds.
#[derive(Clone, Debug, PartialEq)]
pub struct Ring {
    /// Centre, pixels.
    pub centre: DVec2,
    /// Finding numbers, from 1, ascending.
    pub numbers: Vec<usize>,
}

/// Groups findings into rings: a finding joins the first ring whose centre is closer than
/// `merge_px`; findings at non-finite positions are left out.
pub fn group(layout: &Layout, faults: &[Finding], merge_px: f64) -> Vec<Ring> {
    let mut rings: Vec<Ring> = Vec::new();
    for (i, f) in faults.iter().enumerate() {
        let p = layout.to_px(f.position);
        if !p.is_finite() {
            continue;
        }
        match rings.iter_mut().find(|r| r.centre.distance(p) < merge_px) {
            Some(r) => r.numbers.push(i + 1),
            None => rings.push(Ring {
                centre: p,
                numbers: vec![i + 1],
            }),
        }
    }
    rings
}

/// The label of a ring: its numbers joined by commas, cut after [`MAX_NUMBERS_PER_RING`].
fn label(numbers: &[usize]) -> String {
    let mut parts: Vec<String> = numbers
        .iter()
        .take(MAX_NUMBERS_PER_RING)
        .map(usize::to_string)
        .collect();
    if numbers.len() > MAX_NUMBERS_PER_RING {
        parts.push("…".into());
    }
    parts.join(",")
}

/// Draws a ring around every finding (semi-transparent, on top of the lines) and its number
/// on a white tab at the ring's upper right.
pub fn draw(pixmap: &mut Pixmap, layout: &Layout, faults: &[Finding], lw: f32) {
    let radius = ring_radius(layout.width, lw);
    let width = (1.5 * lw).max(2.5).max(radius / 8.0);
    let rings = group(layout, faults, f64::from(width));
    let mut pb = PathBuilder::new();
    for r in &rings {
        pb.push_circle(r.centre.x as f32, r.centre.y as f32, radius);
    }
    let Some(path) = pb.finish() else {
        return;
    };
    let stroke = Stroke {
        width,
        ..Stroke::default()
    };
    let [red, green, blue, _] = FAULT_COLOR;
    let ring_paint = paint([red, green, blue, 200]);
    pixmap.stroke_path(&path, &ring_paint, &stroke, Transform::identity(), None);
    if rings.len() > MAX_NUMBERED {
        return;
    }
    let font_px = legend::font_px_for(layout.width).max(2);
    let offset = f64::from(radius) * std::f64::consts::FRAC_1_SQRT_2;
    for r in &rings {
        let text = label(&r.numbers);
        let (_, h) = legend::text_size(&text, font_px);
        let x = r.centre.x + offset;
        let y = r.centre.y - offset - f64::from(h) - 2.0 * f64::from(font_px);
        draw_label(pixmap, x, y.max(0.0), &text, font_px);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn labels_join_and_cut_numbers() {
        assert_eq!(label(&[3]), "3");
        assert_eq!(label(&[1, 2]), "1,2");
        assert_eq!(label(&[1, 2, 3, 4, 5]), "1,2,3,4,…");
    }

    #[test]
    fn radius_grows_with_the_picture() {
        assert_eq!(ring_radius(300, 2.0), 12.0);
        assert!((ring_radius(900, 2.0) - 30.0).abs() < 1e-4);
    }
}
