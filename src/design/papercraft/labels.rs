//! Edge labels: the number of the cut line written inside both parts next to every side
//! they are glued along, so the builder knows which sides go together (the issue asks for
//! matching labels on both parts; the thesis's figures show none).
//!
//! Each label is the cut-line index in the crate's single-stroke digits
//! ([`crate::geom::stroke_digits`]: a digit is 0.5 h wide and h tall, digits advance by
//! 0.8 h), written **level on its sheet** (its baseline along the sheet's +x, read left to
//! right, never turned or mirrored: the parts are labelled after they are packed, knowing
//! each part's turn) next to the side's middle (half its length), inside the part, its box
//! (the text with a 0.25 h border) 0.25 h from the side. Only when no level label fits on
//! both parts at any size or position is the label written along the side instead, its top
//! towards the side, turned to read left to right as [`make_upright`] does. The strokes
//! go into the crease pattern as flat (`F`) lines: the material's `flat` operation decides
//! whether the machine marks them (a pen or a low-power laser pass) or skips them, and the
//! SVG and PNG previews draw them.
//!
//! A label must lie inside its part: every stroke end inside the outline, no stroke
//! crossing it, and its box clear of the part's other labels. The height is tried at h,
//! 0.7 h, 0.5 h and 0.35 h, and at each height the label next to the side's middle, then
//! at 0.35, 0.65, 0.2 and 0.8 of its length; a cut line is labelled only at a height that
//! fits on both of its parts; [`add_labels`] returns the cut lines left unlabelled.
//!
//! [`make_upright`] turns every label whose text would read upside down on its sheet by a
//! half turn about its centre (the same box, so it still fits), so that every baseline's
//! direction on the sheet lies in (−90°, 90°].

use glam::DVec2;

use super::network::Network;
use super::parts::{Part, PartSide};
use crate::geom::polygon::{contains_point, segment_crosses_ring};
use crate::geom::stroke_digits::{text_strokes, text_width};

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

/// Labels every cut line shared by two parts with its index, height `height` mm (> 0;
/// non-positive or non-finite heights label nothing), level on the sheet of a part placed
/// turned by `angles[k]` (radians counter-clockwise, as [`super::layout::Placement`]; parts
/// beyond the slice's end at 0). Returns the cut lines that got no label because none fits
/// on both parts.
///
/// Lines are labelled in index order at the largest size that fits on both parts; when
/// some line finds no room, the parts it joins are limited to the next smaller size and
/// every label is placed again (their larger labels may have taken its room), until every
/// line fits or nothing is left to shrink.
pub fn add_labels(
    parts: &mut [Part],
    network: &Network,
    height: f64,
    angles: &[f64],
) -> Vec<usize> {
    if !(height.is_finite() && height > 0.0) {
        return Vec::new();
    }
    // Per part, the index in SIZES of the largest size its labels may take.
    let mut largest = vec![0usize; parts.len()];
    loop {
        parts.iter_mut().for_each(|p| p.labels.clear());
        let missing = label_pass(parts, network, height, &largest, angles);
        let mut shrunk = false;
        for &(_, i, j) in &missing {
            for k in [i, j] {
                if largest[k] + 1 < SIZES.len() {
                    largest[k] += 1;
                    shrunk = true;
                }
            }
        }
        if !shrunk {
            return missing.iter().map(|&(e, _, _)| e).collect();
        }
    }
}

/// One labelling pass, part k's labels no larger than `SIZES[largest[k]]`; returns the
/// lines left unlabelled with the indices of their two parts.
fn label_pass(
    parts: &mut [Part],
    network: &Network,
    height: f64,
    largest: &[usize],
    angles: &[f64],
) -> Vec<(usize, usize, usize)> {
    let mut missing = Vec::new();
    let hs = network.half_edges();
    for e in 0..hs.len() / 2 {
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
        let from = largest[i].max(largest[j]);
        let (path_i, path_j) = (SidePath::new(&parts[i], &si), SidePath::new(&parts[j], &sj));
        let level = |k: usize| Facing::Level(angles.get(k).copied().unwrap_or(0.0));
        let fitted = [(level(i), level(j)), (Facing::AlongSide, Facing::AlongSide)]
            .into_iter()
            .find_map(|(facing_i, facing_j)| {
                SIZES[from..].iter().find_map(|&f| {
                    let fit = |part: &Part, path: &SidePath, facing: Facing| {
                        POSITIONS
                            .iter()
                            .find_map(|&s| place(part, path, e, &text, f * height, s, facing))
                    };
                    Some((
                        fit(&parts[i], &path_i, facing_i)?,
                        fit(&parts[j], &path_j, facing_j)?,
                    ))
                })
            });
        match fitted {
            Some((a, b)) => {
                parts[i].labels.push(a);
                parts[j].labels.push(b);
            }
            None => missing.push((e, i, j)),
        }
    }
    missing
}

/// Heights tried, as fractions of the design's label height.
const SIZES: [f64; 4] = [1.0, 0.7, 0.5, 0.35];
/// Positions tried along a side, as fractions of its length from its start.
const POSITIONS: [f64; 5] = [0.5, 0.35, 0.65, 0.2, 0.8];

/// A side of a part as a polyline, with its length (mm), built once for all the label sizes
/// and positions tried on it.
struct SidePath {
    pts: Vec<DVec2>,
    total: f64,
}

impl SidePath {
    fn new(part: &Part, side: &PartSide) -> Self {
        let pts: Vec<DVec2> = (0..=side.len).map(|k| part.point(side.start + k)).collect();
        let total = pts.windows(2).map(|w| w[0].distance(w[1])).sum();
        SidePath { pts, total }
    }

    /// The point at arc length `s` from the side's start.
    fn at(&self, s: f64) -> DVec2 {
        let mut left = s;
        for w in self.pts.windows(2) {
            let l = w[0].distance(w[1]);
            if left <= l && l > 0.0 {
                return w[0].lerp(w[1], left / l);
            }
            left -= l;
        }
        self.pts[self.pts.len() - 1]
    }
}

/// Which way a label's text runs.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Facing {
    /// Level on the sheet of a part placed turned by this angle (radians counter-clockwise).
    Level(f64),
    /// Along its side, its top towards the side.
    AlongSide,
}

/// The label `text` of cut line `e` on the side `path` of `part` at height `h`, next to the
/// point at fraction `along` of the side's length, facing `facing`, if it fits.
fn place(
    part: &Part,
    path: &SidePath,
    e: usize,
    text: &str,
    h: f64,
    along: f64,
    facing: Facing,
) -> Option<Label> {
    let (at, total) = (|s: f64| path.at(s), path.total);
    let (from, to) = ((along - 0.1).max(0.0), (along + 0.1).min(1.0));
    let t = (at(to * total) - at(from * total)).try_normalize()?;
    let outward = DVec2::new(t.y, -t.x); // the outline is counter-clockwise
    // The text's reading direction and its up, in part coordinates.
    let right = match facing {
        Facing::Level(angle) => DVec2::from_angle(-angle),
        Facing::AlongSide => DVec2::new(outward.y, -outward.x),
    };
    let up = right.perp();
    let width = text_width(text, h);
    // The box (text and a 0.25 h border) reaches `reach` from its centre towards the side;
    // the centre sits so that the box stays 0.25 h from it.
    let (box_w, box_h) = (width + 0.5 * h, 1.5 * h);
    let reach = 0.5 * (box_w * right.dot(outward).abs() + box_h * up.dot(outward).abs());
    let centre = at(along * total) - outward * (0.25 * h + reach);
    let origin = centre - right * (0.5 * width) - up * (0.5 * h);
    let map = |p: DVec2| origin + right * p.x + up * p.y;
    let strokes: Vec<[DVec2; 2]> = text_strokes(text, DVec2::ZERO, h)
        .ok()?
        .iter()
        .flat_map(|line| line.windows(2).map(|w| [map(w[0]), map(w[1])]))
        .collect();
    let pad = 0.25 * h;
    let frame = [
        map(DVec2::new(-pad, -pad)),
        map(DVec2::new(width + pad, -pad)),
        map(DVec2::new(width + pad, h + pad)),
        map(DVec2::new(-pad, h + pad)),
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

/// The direction the text of `label` reads in, in part coordinates (unit length): from the
/// first corner of its frame to the second.
pub fn baseline(label: &Label) -> DVec2 {
    (label.frame[1] - label.frame[0]).normalize_or_zero()
}

/// Whether a baseline direction on the sheet reads upright: its angle lies in (−90°, 90°].
pub fn reads_upright(direction: DVec2) -> bool {
    direction.x > 0.0 || (direction.x == 0.0 && direction.y > 0.0)
}

/// Turns every label of a part that is placed turned by `angle` (radians counter-clockwise,
/// as in [`super::layout::Placement`]) so that it reads upright on the sheet
/// ([`reads_upright`]): a label that would not is turned by a half turn about the centre of
/// its frame, strokes and frame alike.
pub fn make_upright(part: &mut Part, angle: f64) {
    let rot = DVec2::from_angle(angle);
    for label in &mut part.labels {
        if reads_upright(rot.rotate(baseline(label))) {
            continue;
        }
        let centre = 0.25 * label.frame.iter().sum::<DVec2>();
        let turn = |p: DVec2| 2.0 * centre - p;
        for s in &mut label.strokes {
            *s = [turn(s[0]), turn(s[1])];
        }
        label.frame = label.frame.map(turn);
    }
}

/// Whether two convex quadrilaterals overlap (a corner inside the other, or edges cross).
pub fn frames_overlap(a: &[DVec2; 4], b: &[DVec2; 4]) -> bool {
    a.iter().any(|&p| contains_point(b, p))
        || b.iter().any(|&p| contains_point(a, p))
        || (0..4).any(|i| segment_crosses_ring(b, a[i], a[(i + 1) % 4]))
}
