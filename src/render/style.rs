//! Line styles of the preview: the usual origami conventions, in colour.
//!
//! | assignment | look |
//! | --- | --- |
//! | valley (V) | dashed blue |
//! | mountain (M) | dash-dot red |
//! | boundary (B) | solid black |
//! | cut (C) | solid green, thicker |
//! | flat (F) | thin solid light grey |
//! | unassigned (U) | solid magenta |
//! | join (J) | dotted orange |
//!
//! Widths and dash lengths are multiples of the base line width in pixels, so the patterns
//! stay legible at any resolution.

use crate::pattern::Assignment;

/// How one class of line is drawn.
#[derive(Clone, Debug, PartialEq)]
pub struct LineStyle {
    /// Colour, RGBA, not premultiplied.
    pub color: [u8; 4],
    /// Stroke width, pixels.
    pub width: f32,
    /// Dash pattern, pixels (on, off, on, off …); `None` for a solid line.
    pub dash: Option<Vec<f32>>,
}

/// The drawing order: faint lines first, outlines and cuts on top.
pub const DRAW_ORDER: [Assignment; 7] = [
    Assignment::Flat,
    Assignment::Join,
    Assignment::Unassigned,
    Assignment::Valley,
    Assignment::Mountain,
    Assignment::Boundary,
    Assignment::Cut,
];

/// Colour of fault highlights (rings and edge halos), RGBA.
pub const FAULT_COLOR: [u8; 4] = [255, 128, 0, 255];

/// The style of an assignment for a base line width `lw` (pixels).
pub fn line_style(a: Assignment, lw: f32) -> LineStyle {
    let (color, width, dash): ([u8; 4], f32, Option<Vec<f32>>) = match a {
        Assignment::Valley => ([20, 80, 230, 255], lw, Some(vec![4.0 * lw, 2.5 * lw])),
        Assignment::Mountain => (
            [220, 30, 30, 255],
            lw,
            Some(vec![6.0 * lw, 2.0 * lw, 1.0 * lw, 2.0 * lw]),
        ),
        Assignment::Boundary => ([0, 0, 0, 255], 1.2 * lw, None),
        Assignment::Cut => ([0, 160, 40, 255], 2.0 * lw, None),
        Assignment::Flat => ([190, 190, 190, 255], 0.5 * lw, None),
        Assignment::Unassigned => ([220, 0, 220, 255], lw, None),
        Assignment::Join => ([240, 140, 0, 255], lw, Some(vec![1.0 * lw, 1.5 * lw])),
    };
    LineStyle { color, width, dash }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_assignment_has_a_distinct_colour() {
        let colours: Vec<[u8; 4]> = Assignment::ALL
            .iter()
            .map(|&a| line_style(a, 2.0).color)
            .collect();
        for (i, a) in colours.iter().enumerate() {
            assert!(colours[i + 1..].iter().all(|b| b != a));
        }
        assert_eq!(DRAW_ORDER.len(), Assignment::ALL.len());
    }
}
