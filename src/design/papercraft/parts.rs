//! Parts for making: each trimmed patch's unrolled outline with glue tabs.
//!
//! A part's outline is the patch's real boundary unrolled ([`super::trim`]), turned
//! counter-clockwise (reversing the point order only: the part is not mirrored). Every cut line
//! shared by two patch sides gets tabs on exactly one side, the one using half-edge `2e`
//! (the side with the even half-edge, along the cut line's own points); free boundaries get
//! none. Both parts know which cut line each side lies on, which is the edge label printed on
//! both ([`super::labels`] writes it).
//!
//! A side is split into pieces no longer than the style's maximum whose points stay within a
//! quarter of the tab width of their chord; each piece gets a trapezoid tab: the piece itself
//! is the root (folded as a mountain, the tab goes behind the printed side), the outer edge is
//! the chord moved out by the width, and the ends slope in at the style's angle. A tab that
//! would overlap its own part (a concave side) is narrowed by halves up to three times, then
//! dropped; [`Part::dropped_tabs`] counts those.

use glam::DVec2;
use serde::Serialize;

use super::PapercraftError;
use super::network::Network;
use super::trim::RealBoundary;
use crate::geom::polygon::{contains_point, segment_crosses_ring, signed_area};

/// Share of a tab's side cut off at the part's end before the overlap test, so the side's
/// shared end point does not count as touching the part.
const TAB_END_SHRINK: f64 = 1e-7;

/// How glue tabs are shaped (millimetres after scaling, degrees).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TabStyle {
    /// Tab width, from root to outer edge (> 0).
    pub width: f64,
    /// Angle between the root and the tab's slanted ends, in degrees (0 < angle ≤ 90).
    pub angle_deg: f64,
    /// Longest root of one tab (≥ width).
    pub max_length: f64,
}

impl TabStyle {
    fn validate(&self) -> Result<(), PapercraftError> {
        let ok = self.width.is_finite()
            && self.width > 0.0
            && self.angle_deg > 0.0
            && self.angle_deg <= 90.0
            && self.max_length.is_finite()
            && self.max_length >= self.width;
        if ok {
            Ok(())
        } else {
            Err(PapercraftError::BadParameter(format!(
                "tab style {self:?}: width must be > 0, angle in (0°, 90°], max length ≥ width"
            )))
        }
    }
}

/// One side of a part: the outline points `start..=end` (indices modulo the outline length)
/// lie on cut line `half_edge / 2`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PartSide {
    /// The patch's half-edge on this side.
    pub half_edge: usize,
    /// Index of the side's first outline point.
    pub start: usize,
    /// Number of outline segments on the side.
    pub len: usize,
}

/// Largest difference between the two lengths of a glued cut line that still glues, mm.
pub const GLUE_TOLERANCE_MM: f64 = 0.1;

/// Largest difference between the two lengths of a glued cut line that still glues, as a
/// share of the longer one (the larger of this and [`GLUE_TOLERANCE_MM`] applies).
pub const GLUE_TOLERANCE_SHARE: f64 = 0.001;

/// A cut line shared by two parts, glued: its length on each part (millimetres, along the
/// unrolled outline). Unrolling is isometric, so the two lengths agree when both patches
/// follow the mesh along the line; they differ where a patch fits the mesh badly.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Seam {
    /// The cut line (the number its labels show).
    pub cut_line: usize,
    /// The two parts' patch indices, in the order of their half-edges.
    pub parts: [usize; 2],
    /// Its length on each part, mm.
    pub lengths_mm: [f64; 2],
}

impl Seam {
    /// |length on one part − length on the other|, mm.
    pub fn mismatch_mm(&self) -> f64 {
        (self.lengths_mm[0] - self.lengths_mm[1]).abs()
    }

    /// Whether the two sides glue: they differ by at most [`GLUE_TOLERANCE_MM`] or
    /// [`GLUE_TOLERANCE_SHARE`] of the longer, whichever is larger.
    pub fn glues(&self) -> bool {
        let longer = self.lengths_mm[0].max(self.lengths_mm[1]);
        self.mismatch_mm() <= GLUE_TOLERANCE_MM.max(GLUE_TOLERANCE_SHARE * longer)
    }
}

impl std::fmt::Display for Seam {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "cut line {}: {:.2} mm on patch {}'s part, {:.2} mm on patch {}'s ({:.2} mm apart)",
            self.cut_line,
            self.lengths_mm[0],
            self.parts[0],
            self.lengths_mm[1],
            self.parts[1],
            self.mismatch_mm()
        )
    }
}

/// Every cut line two parts share, in cut-line order, with its length on each part (the sum
/// of the sides on that line).
pub fn seams(parts: &[Part]) -> Vec<Seam> {
    use std::collections::BTreeMap;
    // Per cut line, per half-edge (2c or 2c + 1): the part and the summed side length.
    let mut lines: BTreeMap<usize, BTreeMap<usize, (usize, f64)>> = BTreeMap::new();
    for part in parts {
        for side in &part.sides {
            let length = part.side_length(side);
            let entry = lines
                .entry(side.half_edge / 2)
                .or_default()
                .entry(side.half_edge)
                .or_insert((part.patch, 0.0));
            entry.1 += length;
        }
    }
    lines
        .into_iter()
        .filter_map(|(cut_line, halves)| {
            let mut it = halves.into_values();
            let (a, b) = (it.next()?, it.next()?);
            Some(Seam {
                cut_line,
                parts: [a.0, b.0],
                lengths_mm: [a.1, b.1],
            })
        })
        .collect()
}

/// A glue tab: its root is the outline from point `from` over `len` segments.
#[derive(Clone, Debug, PartialEq)]
pub struct Tab {
    /// The half-edge of the side it sits on.
    pub half_edge: usize,
    /// First outline index of the root.
    pub from: usize,
    /// Root length in outline segments.
    pub len: usize,
    /// Outer corners: next to the root's start, next to its end.
    pub outer: [DVec2; 2],
}

/// A part: the unrolled patch with its tabs.
#[derive(Clone, Debug, PartialEq)]
pub struct Part {
    /// The patch it comes from.
    pub patch: usize,
    /// Counter-clockwise outline.
    pub outline: Vec<DVec2>,
    /// Sides in outline order.
    pub sides: Vec<PartSide>,
    /// Glue tabs.
    pub tabs: Vec<Tab>,
    /// Tabs left out because even narrowed they overlapped the part.
    pub dropped_tabs: usize,
    /// Edge labels ([`super::labels`]).
    pub labels: Vec<super::labels::Label>,
}

impl Part {
    /// The part of patch `patch` from its real boundary, scaled by `scale` (mesh units to
    /// millimetres), counter-clockwise, without tabs.
    pub fn from_boundary(patch: usize, boundary: &RealBoundary, scale: f64) -> Part {
        let mut outline = Vec::new();
        let mut sides = Vec::new();
        for side in &boundary.sides {
            sides.push(PartSide {
                half_edge: side.half_edge,
                start: outline.len(),
                len: side.points.len() - 1,
            });
            outline.extend(
                side.points[..side.points.len() - 1]
                    .iter()
                    .map(|p| p.flat * scale),
            );
        }
        let n = outline.len();
        if signed_area(outline.iter().copied()) < 0.0 {
            // Reverse the order: point i goes to n − 1 − i; a side from s over l segments
            // becomes one from n − 1 − (s + l) over l, and the side order reverses.
            outline.reverse();
            sides.reverse();
            for s in &mut sides {
                s.start = (2 * n - 1 - (s.start + s.len)) % n;
            }
        }
        Part {
            patch,
            outline,
            sides,
            tabs: Vec::new(),
            dropped_tabs: 0,
            labels: Vec::new(),
        }
    }

    /// Outline point `i` (modulo the length).
    pub fn point(&self, i: usize) -> DVec2 {
        self.outline[i % self.outline.len()]
    }

    /// The length of `side` along the outline, mm.
    pub fn side_length(&self, side: &PartSide) -> f64 {
        (0..side.len)
            .map(|k| {
                self.point(side.start + k)
                    .distance(self.point(side.start + k + 1))
            })
            .sum()
    }

    /// The area of the outline and its tabs, mm².
    pub fn area(&self) -> f64 {
        signed_area(self.outline.iter().copied()).abs()
            + self
                .tabs
                .iter()
                .map(|t| signed_area(self.tab_polygon(t)).abs())
                .sum::<f64>()
    }

    /// The tab's polygon: root points, then the outer corners (counter-clockwise).
    pub fn tab_polygon(&self, tab: &Tab) -> Vec<DVec2> {
        let mut poly: Vec<DVec2> = (0..=tab.len).map(|k| self.point(tab.from + k)).collect();
        poly.push(tab.outer[1]);
        poly.push(tab.outer[0]);
        poly.reverse();
        poly
    }
}

/// Adds tabs to every part on the even half-edge of each cut line with patches on both sides.
pub fn add_tabs(
    parts: &mut [Part],
    network: &Network,
    style: &TabStyle,
) -> Result<(), PapercraftError> {
    style.validate()?;
    let hs = network.half_edges();
    for part in parts.iter_mut() {
        for side in part.sides.clone() {
            let h = side.half_edge;
            if h % 2 == 1 || hs[h ^ 1].patch.is_none() {
                continue;
            }
            for (from, len) in pieces(part, &side, style) {
                match fit_tab(part, h, from, len, style) {
                    Some(tab) => part.tabs.push(tab),
                    None => part.dropped_tabs += 1,
                }
            }
        }
    }
    Ok(())
}

/// Splits a side into pieces `(from, len)` no longer than the maximum and within a quarter
/// width of their chords.
fn pieces(part: &Part, side: &PartSide, style: &TabStyle) -> Vec<(usize, usize)> {
    let mut out = Vec::new();
    let mut from = 0;
    while from < side.len {
        let mut len = 1;
        while from + len < side.len && fits(part, side.start + from, len + 1, style) {
            len += 1;
        }
        out.push((side.start + from, len));
        from += len;
    }
    out
}

fn fits(part: &Part, from: usize, len: usize, style: &TabStyle) -> bool {
    let (a, b) = (part.point(from), part.point(from + len));
    let length: f64 = (0..len)
        .map(|k| part.point(from + k).distance(part.point(from + k + 1)))
        .sum();
    length <= style.max_length
        && (1..len).all(|k| {
            crate::geom::segment::distance_to_point(a, b, part.point(from + k))
                <= 0.25 * style.width
        })
}

fn fit_tab(part: &Part, h: usize, from: usize, len: usize, style: &TabStyle) -> Option<Tab> {
    let (a, b) = (part.point(from), part.point(from + len));
    let chord = b - a;
    let t = chord.try_normalize()?;
    let n = DVec2::new(t.y, -t.x); // outward for a counter-clockwise outline
    let slope = 1.0 / style.angle_deg.to_radians().tan();
    let mut width = style.width;
    for _ in 0..4 {
        // Keep the outer edge at least a fifth of the chord long.
        let inset = (width * slope).min(0.4 * chord.length());
        let tab = Tab {
            half_edge: h,
            from,
            len,
            outer: [a + width * n + inset * t, b + width * n - inset * t],
        };
        if !tab_overlaps_part(part, &tab) {
            return Some(tab);
        }
        width *= 0.5;
    }
    None
}

/// Whether a tab's free edges cross its part's outline or its outer corners lie inside.
pub fn tab_overlaps_part(part: &Part, tab: &Tab) -> bool {
    let (a, b) = (part.point(tab.from), part.point(tab.from + tab.len));
    let [oa, ob] = tab.outer;
    let shrink = |p: DVec2, q: DVec2| (p + TAB_END_SHRINK * (q - p), q);
    let free = [shrink(a, oa), (oa, ob), shrink(b, ob)];
    if contains_point(&part.outline, oa) || contains_point(&part.outline, ob) {
        return true;
    }
    free.iter()
        .any(|&(p, q)| segment_crosses_ring(&part.outline, p, q))
}
