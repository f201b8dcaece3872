//! Edge labels: the number of the cut line written inside both parts next to every side
//! they are glued along, so the builder knows which sides go together (the issue asks for
//! matching labels on both parts; the thesis's figures show none).
//!
//! Each label is the cut-line index in seven-segment stroke digits (drawn for this crate:
//! a digit is 0.5 h wide and h tall, digits advance by 0.8 h), centred at the side's middle
//! (half its length), offset inward by 0.5 h from it, its top towards the side. The strokes
//! go into the crease pattern as flat (`F`) lines: the material's `flat` operation decides
//! whether the machine marks them (a pen or a low-power laser pass) or skips them, and the
//! SVG and PNG previews draw them.
//!
//! A label must lie inside its part: every stroke end inside the outline, no stroke
//! crossing it, and its box clear of the part's other labels. The height is tried at h,
//! 0.7 h and 0.5 h, and a cut line is labelled only at a height that fits on both of its
//! parts; [`add_labels`] returns the cut lines left unlabelled.

use glam::DVec2;

use super::network::Network;
use super::parts::{Part, PartSide};
use crate::geom::polygon::{contains_point, segment_crosses_ring};

/// A label on a part.
#[derive(Clone, Debug, PartialEq)]
pub struct Label {
    /// The cut line it names.
    pub line: usize,
    /// The digits written.
    pub text: String,
    /// Stroke segments in part coordinates (millimetres).
    pub strokes: Vec<[DVec2; 2]>,
    /// The corners of its box (for overlap checks).
    pub frame: [DVec2; 4],
}

/// Seven-segment corners: (0,0) bottom left … (1,2) top right, in half-widths and halves.
const SEGMENTS: [[(u8, u8); 2]; 7] = [
    [(0, 2), (1, 2)], // a: top
    [(1, 2), (1, 1)], // b: top right
    [(1, 1), (1, 0)], // c: bottom right
    [(0, 0), (1, 0)], // d: bottom
    [(0, 1), (0, 0)], // e: bottom left
    [(0, 2), (0, 1)], // f: top left
    [(0, 1), (1, 1)], // g: middle
];

/// Which segments (a…g as bits 0…6) each digit lights.
const DIGITS: [u8; 10] = [
    0b011_1111, 0b000_0110, 0b101_1011, 0b100_1111, 0b110_0110, 0b110_1101, 0b111_1101, 0b000_0111,
    0b111_1111, 0b110_1111,
];

/// Labels every cut line shared by two parts with its index, height `height` mm (> 0;
/// non-positive or non-finite heights label nothing). Returns the cut lines that got no
/// label because none fits on both parts.
pub fn add_labels(parts: &mut [Part], network: &Network, height: f64) -> Vec<usize> {
    let mut missing = Vec::new();
    if !(height.is_finite() && height > 0.0) {
        return missing;
    }
    let hs = network.half_edges();
    let lines = hs.len() / 2;
    for e in 0..lines {
        let (Some(p), Some(q)) = (hs[2 * e].patch, hs[2 * e + 1].patch) else {
            continue;
        };
        let find = |parts: &[Part], patch: usize, h: usize| {
            let i = parts.iter().position(|part| part.patch == patch)?;
            let side = *parts[i].sides.iter().find(|s| s.half_edge == h)?;
            Some((i, side))
        };
        let (Some((i, si)), Some((j, sj))) = (find(parts, p, 2 * e), find(parts, q, 2 * e + 1))
        else {
            continue;
        };
        let text = e.to_string();
        let fitted = [1.0, 0.7, 0.5].iter().find_map(|&f| {
            let a = place(&parts[i], &si, e, &text, f * height)?;
            let b = place(&parts[j], &sj, e, &text, f * height)?;
            Some((a, b))
        });
        match fitted {
            Some((a, b)) => {
                parts[i].labels.push(a);
                parts[j].labels.push(b);
            }
            None => missing.push(e),
        }
    }
    missing
}

/// The label `text` of cut line `e` on `side` of `part` at height `h`, if it fits.
fn place(part: &Part, side: &PartSide, e: usize, text: &str, h: f64) -> Option<Label> {
    let pts: Vec<DVec2> = (0..=side.len).map(|k| part.point(side.start + k)).collect();
    let total: f64 = pts.windows(2).map(|w| w[0].distance(w[1])).sum();
    let at = |s: f64| {
        let mut left = s;
        for w in pts.windows(2) {
            let l = w[0].distance(w[1]);
            if left <= l && l > 0.0 {
                return w[0].lerp(w[1], left / l);
            }
            left -= l;
        }
        pts[pts.len() - 1]
    };
    let t = (at(0.6 * total) - at(0.4 * total)).try_normalize()?;
    let up = DVec2::new(t.y, -t.x); // outward: the outline is counter-clockwise
    let right = DVec2::new(up.y, -up.x);
    let width = 0.8 * h * text.len() as f64 - 0.3 * h;
    let centre = at(0.5 * total) - up * h;
    let origin = centre - right * (0.5 * width) - up * (0.5 * h);
    let map = |x: f64, y: f64| origin + right * x + up * y;
    let mut strokes = Vec::new();
    for (k, c) in text.chars().enumerate() {
        let bits = DIGITS[c.to_digit(10)? as usize];
        let x0 = 0.8 * h * k as f64;
        for (s, seg) in SEGMENTS.iter().enumerate() {
            if bits & (1 << s) != 0 {
                let [(ax, ay), (bx, by)] = *seg;
                let p = |x: u8, y: u8| map(x0 + 0.5 * h * f64::from(x), 0.5 * h * f64::from(y));
                strokes.push([p(ax, ay), p(bx, by)]);
            }
        }
    }
    let pad = 0.25 * h;
    let frame = [
        map(-pad, -pad),
        map(width + pad, -pad),
        map(width + pad, h + pad),
        map(-pad, h + pad),
    ];
    let outline = &part.outline;
    let inside = frame.iter().all(|&c| contains_point(outline, c))
        && (0..4).all(|k| !segment_crosses_ring(outline, frame[k], frame[(k + 1) % 4]));
    let clear = part
        .labels
        .iter()
        .all(|l| !frames_overlap(&l.frame, &frame));
    (inside && clear).then(|| Label {
        line: e,
        text: text.to_string(),
        strokes,
        frame,
    })
}

/// Whether two convex quadrilaterals overlap (a corner inside the other, or edges cross).
pub fn frames_overlap(a: &[DVec2; 4], b: &[DVec2; 4]) -> bool {
    a.iter().any(|&p| contains_point(b, p))
        || b.iter().any(|&p| contains_point(a, p))
        || (0..4).any(|i| segment_crosses_ring(b, a[i], a[(i + 1) % 4]))
}
