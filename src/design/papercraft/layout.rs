//! Laying parts out on sheets and turning each sheet into a [`CreasePattern`].
//!
//! [`pack`] packs the parts on their shapes, outlines and tabs ([`super::packing`]): parts
//! interlock where their outlines allow, and are never closer than the gap. The greedy
//! packing on shapes is not always the better one, so [`pack`] keeps the packing on boxes
//! when that one uses less sheet.
//!
//! [`pack_boxes`], the first packer, is kept for comparison: each part (with its tabs) is
//! turned to the angle, in 5° steps over a half turn, that gives the smallest bounding box,
//! then packed by a skyline bottom-left packer on bounding boxes enlarged by the gap: the
//! lowest position along the skyline where the box fits, leftmost on ties; a part that fits
//! nowhere opens a new sheet. Parts go in order of decreasing box height.
//!
//! [`usage`] measures how much sheet a packing uses.
//!
//! The sheet's pattern: outlines and tab edges are cuts (`B`), tab roots mountain folds
//! (`M`, −90°: the tab turns behind the printed side), edge labels flat lines (`F`, marked
//! or skipped as the material says).

use glam::DVec2;

use super::PapercraftError;
use super::parts::Part;
use crate::geom::tolerance::{RELATIVE, ROUNDOFF};
use crate::pattern::{Assignment, CreasePattern, Edge};

/// Sheet size and spacing, millimetres.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SheetSpec {
    /// Sheet width (x).
    pub width: f64,
    /// Sheet height (y).
    pub height: f64,
    /// Empty border along every sheet edge.
    pub margin: f64,
    /// Smallest distance between two parts (their outlines and tabs; between their boxes
    /// for [`pack_boxes`]).
    pub gap: f64,
}

/// A part placed on a sheet: rotated by `angle` (radians) about the origin, then moved by
/// `offset`.
#[derive(Clone, Debug, PartialEq)]
pub struct Placement {
    /// Index into the parts list.
    pub part: usize,
    /// Sheet index.
    pub sheet: usize,
    /// Rotation, radians counter-clockwise.
    pub angle: f64,
    /// Translation after the rotation.
    pub offset: DVec2,
}

impl Placement {
    /// Maps a point of the part to the sheet.
    pub fn apply(&self, p: DVec2) -> DVec2 {
        DVec2::from_angle(self.angle).rotate(p) + self.offset
    }
}

/// Refuses a part with fewer than three outline corners or a coordinate that is not finite.
pub(super) fn check_parts(parts: &[Part]) -> Result<(), PapercraftError> {
    for (i, part) in parts.iter().enumerate() {
        if part.outline.len() < 3 {
            return Err(PapercraftError::BadParameter(format!(
                "part {i}: an outline needs at least 3 corners, it has {}",
                part.outline.len()
            )));
        }
        if !part_points(part).iter().all(|p| p.is_finite()) {
            return Err(PapercraftError::BadParameter(format!(
                "part {i}: a coordinate of its outline or tabs is not finite"
            )));
        }
    }
    Ok(())
}

/// Every point of a part with its tabs (outline and outer tab corners).
pub fn part_points(part: &Part) -> Vec<DVec2> {
    let mut pts = part.outline.clone();
    pts.extend(part.tabs.iter().flat_map(|t| t.outer));
    pts
}

/// The lower and upper corners of the box round `points` (±∞ corners for none), mm.
pub(super) fn bounds(points: impl Iterator<Item = DVec2>) -> (DVec2, DVec2) {
    crate::geom::Rect::covering(points).corners()
}

/// The largest sheet side accepted, millimetres (the shape packer scans heights in steps of
/// at most 1 mm).
pub const MAX_SHEET_MM: f64 = 10_000.0;

/// The usable area of a sheet (inside the margins), millimetres; refuses a spec whose sizes
/// are not finite and non-negative, whose sides exceed [`MAX_SHEET_MM`], whose margins leave
/// no room or whose gap is wider than the sheet.
pub(super) fn usable_size(spec: &SheetSpec) -> Result<DVec2, PapercraftError> {
    let ok = [spec.width, spec.height, spec.margin, spec.gap]
        .iter()
        .all(|v| v.is_finite() && *v >= 0.0)
        && spec.width <= MAX_SHEET_MM
        && spec.height <= MAX_SHEET_MM
        && spec.width > 2.0 * spec.margin
        && spec.height > 2.0 * spec.margin
        && spec.gap < spec.width.max(spec.height);
    if !ok {
        return Err(PapercraftError::BadParameter(format!(
            "sheet {spec:?}: sizes must be finite, at most {MAX_SHEET_MM} mm, with margins \
             that leave room and a gap narrower than the sheet"
        )));
    }
    Ok(DVec2::new(
        spec.width - 2.0 * spec.margin,
        spec.height - 2.0 * spec.margin,
    ))
}

/// The angle (radians, in 5° steps over a half turn) at which the part with its tabs has
/// the smallest bounding box that fits in `usable`, with that box's lower corner and size;
/// `None` when it fits at no angle tried.
fn smallest_box(part: &Part, usable: DVec2) -> Option<(f64, DVec2, DVec2)> {
    let pts = part_points(part);
    (0..36)
        .map(|k| {
            let angle = k as f64 * std::f64::consts::PI / 36.0;
            let rot = DVec2::from_angle(angle);
            let (lo, hi) = bounds(pts.iter().map(|&p| rot.rotate(p)));
            (angle, lo, hi - lo)
        })
        .filter(|(_, _, size)| size.x <= usable.x && size.y <= usable.y)
        .min_by(|a, b| (a.2.x * a.2.y).total_cmp(&(b.2.x * b.2.y)))
}

/// The angle of [`smallest_box`] alone.
pub(super) fn best_angle(part: &Part, usable: DVec2) -> Option<f64> {
    smallest_box(part, usable).map(|b| b.0)
}

/// Packs `parts` onto as many sheets as needed, on their shapes
/// ([`super::packing::pack_shapes`]); when the packing on boxes ([`pack_boxes`]) happens to
/// use fewer sheets, or as many and less sheet area ([`usage`]), that one is returned (both
/// keep the parts at least the gap apart). Refuses a bad spec or a part larger than the
/// usable sheet at every angle tried.
pub fn pack(parts: &[Part], spec: &SheetSpec) -> Result<Vec<Placement>, PapercraftError> {
    let shapes = super::packing::pack_shapes(parts, spec)?;
    let boxes = pack_boxes(parts, spec)?;
    let (s, b) = (usage(parts, &shapes, spec), usage(parts, &boxes, spec));
    let boxes_better = b.sheets < s.sheets || (b.sheets == s.sheets && b.used_area < s.used_area);
    Ok(if boxes_better { boxes } else { shapes })
}

/// Packs `parts` on their bounding boxes (the skyline packer described in the module docs),
/// kept to compare with the packing on shapes. Same refusals as [`pack`].
pub fn pack_boxes(parts: &[Part], spec: &SheetSpec) -> Result<Vec<Placement>, PapercraftError> {
    let usable = usable_size(spec)?;
    check_parts(parts)?;
    let mut boxed: Vec<(usize, f64, DVec2, DVec2)> = Vec::new();
    for (i, part) in parts.iter().enumerate() {
        let best = smallest_box(part, usable).ok_or(PapercraftError::PartTooLarge { part: i })?;
        boxed.push((i, best.0, best.1, best.2));
    }
    boxed.sort_by(|a, b| b.3.y.total_cmp(&a.3.y));
    let mut sheets: Vec<Skyline> = Vec::new();
    let mut out = Vec::new();
    for (i, angle, lo, size) in boxed {
        let need = size + DVec2::splat(spec.gap);
        let placed = sheets
            .iter_mut()
            .enumerate()
            .find_map(|(s, sky)| sky.place(need).map(|at| (s, at)));
        let (sheet, at) = match placed {
            Some(found) => found,
            None => {
                let mut sky = Skyline::new(usable + DVec2::splat(spec.gap));
                let at = sky
                    .place(need)
                    .ok_or(PapercraftError::PartTooLarge { part: i })?;
                sheets.push(sky);
                (sheets.len() - 1, at)
            }
        };
        out.push(Placement {
            part: i,
            sheet,
            angle,
            offset: DVec2::splat(spec.margin) + at - lo,
        });
    }
    out.sort_by_key(|p| p.part);
    Ok(out)
}

/// How much sheet a packing uses.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Usage {
    /// Sheets used.
    pub sheets: usize,
    /// Area of the parts with their tabs, mm².
    pub parts_area: f64,
    /// Sheet area used, mm²: on every sheet the full width times the height up to the top of
    /// its highest part plus the margin (what is left above can be cut off and used).
    pub used_area: f64,
}

impl Usage {
    /// Parts' area over used sheet area (1 would be no waste at all; 0 for no sheets).
    pub fn ratio(&self) -> f64 {
        if self.used_area > 0.0 {
            self.parts_area / self.used_area
        } else {
            0.0
        }
    }
}

/// Measures a packing of `parts` on sheets of `spec` (see [`Usage`]).
pub fn usage(parts: &[Part], placements: &[Placement], spec: &SheetSpec) -> Usage {
    let sheets = placements.iter().map(|p| p.sheet + 1).max().unwrap_or(0);
    let mut top = vec![0.0f64; sheets];
    let mut parts_area = 0.0;
    for pl in placements {
        let part = &parts[pl.part];
        let y = part_points(part)
            .iter()
            .map(|&p| pl.apply(p).y)
            .fold(f64::NEG_INFINITY, f64::max);
        top[pl.sheet] = top[pl.sheet].max(y);
        parts_area += part.area();
    }
    let used_area = top
        .iter()
        .map(|&y| spec.width * (y + spec.margin).min(spec.height))
        .sum();
    Usage {
        sheets,
        parts_area,
        used_area,
    }
}

/// A skyline: segments `(x, width, y)` covering `[0, size.x]`.
struct Skyline {
    size: DVec2,
    segments: Vec<(f64, f64, f64)>,
}

impl Skyline {
    fn new(size: DVec2) -> Self {
        Skyline {
            size,
            segments: vec![(0.0, size.x, 0.0)],
        }
    }

    /// The bottom-left position for a box of `need`, which is then added to the skyline.
    fn place(&mut self, need: DVec2) -> Option<DVec2> {
        let mut best: Option<(f64, f64)> = None;
        for i in 0..self.segments.len() {
            let x = self.segments[i].0;
            if x + need.x > self.size.x + RELATIVE {
                break;
            }
            let y = self.segments[i..]
                .iter()
                .take_while(|s| s.0 < x + need.x - ROUNDOFF)
                .map(|s| s.2)
                .fold(0.0, f64::max);
            if y + need.y <= self.size.y + RELATIVE
                && best.is_none_or(|(by, bx)| y < by || (y == by && x < bx))
            {
                best = Some((y, x));
            }
        }
        let (y, x) = best?;
        self.raise(x, need.x, y + need.y);
        Some(DVec2::new(x, y))
    }

    fn raise(&mut self, x: f64, w: f64, top: f64) {
        let mut next = Vec::new();
        for &(sx, sw, sy) in &self.segments {
            let (s0, s1) = (sx, sx + sw);
            if s1 <= x || s0 >= x + w {
                next.push((sx, sw, sy));
                continue;
            }
            if s0 < x {
                next.push((s0, x - s0, sy));
            }
            if s1 > x + w {
                next.push((x + w, s1 - x - w, sy));
            }
        }
        next.push((x, w, top));
        next.sort_by(|a, b| a.0.total_cmp(&b.0));
        self.segments = next;
    }
}

/// The crease pattern of sheet `sheet`: every part placed on it, outlines and tab edges as
/// cuts, tab roots as mountain folds.
pub fn sheet_pattern(parts: &[Part], placements: &[Placement], sheet: usize) -> CreasePattern {
    let mut cp = CreasePattern::new();
    for pl in placements.iter().filter(|p| p.sheet == sheet) {
        let part = &parts[pl.part];
        let n = part.outline.len();
        let ids: Vec<_> = part
            .outline
            .iter()
            .map(|&p| cp.add_vertex(pl.apply(p)))
            .collect();
        let mut fold = vec![false; n];
        for tab in &part.tabs {
            (0..tab.len).for_each(|k| fold[(tab.from + k) % n] = true);
        }
        for i in 0..n {
            let edge = if fold[i] {
                Edge::new(ids[i], ids[(i + 1) % n], Assignment::Mountain).with_angle(-90.0)
            } else {
                Edge::new(ids[i], ids[(i + 1) % n], Assignment::Boundary)
            };
            cp.edges.push(edge);
        }
        for tab in &part.tabs {
            let (a, b) = (ids[tab.from % n], ids[(tab.from + tab.len) % n]);
            let oa = cp.add_vertex(pl.apply(tab.outer[0]));
            let ob = cp.add_vertex(pl.apply(tab.outer[1]));
            cp.add_edge(a, oa, Assignment::Boundary);
            cp.add_edge(oa, ob, Assignment::Boundary);
            cp.add_edge(ob, b, Assignment::Boundary);
        }
        for label in &part.labels {
            let mut at: Vec<(DVec2, crate::pattern::VertexId)> = Vec::new();
            let mut vertex = |cp: &mut CreasePattern, p: DVec2| match at.iter().find(|v| v.0 == p) {
                Some(&(_, id)) => id,
                None => {
                    let id = cp.add_vertex(pl.apply(p));
                    at.push((p, id));
                    id
                }
            };
            for &[a, b] in &label.strokes {
                let (va, vb) = (vertex(&mut cp, a), vertex(&mut cp, b));
                cp.add_edge(va, vb, Assignment::Flat);
            }
        }
    }
    cp
}
