//! Snapping a pointer position to what a crease-pattern editor offers: existing vertices,
//! crossings of the reference lines, a square grid over the sheet, lines at multiples of an
//! angle (22.5° in box-pleated and 22.5° designs) through anchor points, and existing edges.
//!
//! Candidates within [`SnapOptions::radius`] of the pointer are ranked by kind
//! ([`SnapKind`], first wins), then by distance.

use glam::DVec2;
use serde::{Deserialize, Serialize};

use super::{CreasePattern, VertexId};
use crate::geom::Segment;
use crate::geom::segment::{Crossing, intersect};

/// The angle step of origami's 22.5° designs, degrees.
pub const DEFAULT_ANGLE_STEP_DEG: f64 = 22.5;

/// Parallel lines (|sin| of the angle between them below this) have no crossing to snap to.
const PARALLEL_SINE: f64 = 1e-9;

/// What to snap to.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SnapOptions {
    /// Largest distance from the pointer to a snapped point, in the pattern's unit.
    pub radius: f64,
    /// Divisions of the grid across the longer side of the pattern's bounding box (the grid
    /// starts at the box's lower-left corner); `0` turns the grid off.
    #[serde(default)]
    pub grid: u32,
    /// Angle step of the lines through each anchor, degrees; `None` turns them off.
    #[serde(default)]
    pub angle_step_deg: Option<f64>,
    /// Points the angle lines go through (a crease's start; a dragged vertex's neighbours).
    #[serde(default)]
    pub anchors: Vec<[f64; 2]>,
    /// A vertex that is not a target (the one being dragged): neither it nor its edges.
    #[serde(default)]
    pub exclude_vertex: Option<usize>,
}

/// What a point snapped to, in order of preference.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum SnapKind {
    /// An existing vertex.
    Vertex,
    /// A crossing of two reference lines (angle lines, grid lines, edges).
    Crossing,
    /// A grid point.
    Grid,
    /// A point on an angle line through an anchor.
    Angle,
    /// A point on an existing edge.
    Edge,
    /// Nothing near: the pointer itself.
    Free,
}

/// A snapped point.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Snapped {
    /// The point, pattern unit.
    pub point: [f64; 2],
    /// What it snapped to.
    pub kind: SnapKind,
    /// The vertex, when `kind` is [`SnapKind::Vertex`].
    pub vertex: Option<usize>,
}

/// A reference line: a point and a unit direction (infinite), or a segment.
#[derive(Clone, Copy)]
enum Line {
    Infinite(DVec2, DVec2),
    Segment(Segment),
}

impl Line {
    fn distance(&self, p: DVec2) -> f64 {
        match *self {
            Line::Infinite(o, d) => (p - o).perp_dot(d).abs(),
            Line::Segment(s) => s.distance_to_point(p),
        }
    }

    fn nearest(&self, p: DVec2) -> DVec2 {
        match *self {
            Line::Infinite(o, d) => o + d * (p - o).dot(d),
            Line::Segment(s) => s.closest_point(p),
        }
    }

    /// The crossing with `other` (`reach` long pieces of infinite lines around `p`).
    fn cross(&self, other: &Line, p: DVec2, reach: f64) -> Option<DVec2> {
        let piece = |l: &Line| match *l {
            Line::Infinite(o, d) => {
                let c = o + d * (p - o).dot(d);
                (c - d * reach, c + d * reach)
            }
            Line::Segment(s) => (s.a, s.b),
        };
        let (a0, a1) = piece(self);
        let (b0, b1) = piece(other);
        let (da, db) = (a1 - a0, b1 - b0);
        if da.perp_dot(db).abs() <= PARALLEL_SINE * da.length() * db.length() {
            return None;
        }
        match intersect(a0, a1, b0, b1, 0.0) {
            Crossing::Point { t, .. } => Some(a0.lerp(a1, t)),
            _ => None,
        }
    }
}

/// Snaps `p` (pattern unit) to the best candidate of `cp` within `options.radius`.
///
/// Contract: `cp` is validated; the work is linear in the number of vertices and edges plus
/// the square of the number of reference lines near `p`.
pub fn snap(cp: &CreasePattern, p: DVec2, options: &SnapOptions) -> Snapped {
    let r = options.radius.max(0.0);
    let free = Snapped {
        point: [p.x, p.y],
        kind: SnapKind::Free,
        vertex: None,
    };
    if !(r > 0.0 && r.is_finite() && p.is_finite()) {
        return free;
    }
    let excluded = options.exclude_vertex.map(VertexId::new);
    let mut best: Option<(SnapKind, f64, DVec2, Option<usize>)> = None;
    let mut offer = |kind: SnapKind, q: DVec2, vertex: Option<usize>| {
        let d = q.distance(p);
        if d <= r && q.is_finite() && best.is_none_or(|(k, bd, _, _)| (kind, d) < (k, bd)) {
            best = Some((kind, d, q, vertex));
        }
    };
    for (i, &v) in cp.vertices.iter().enumerate() {
        if Some(VertexId::new(i)) != excluded {
            offer(SnapKind::Vertex, v, Some(i));
        }
    }
    let mut lines: Vec<(Line, SnapKind)> = Vec::new();
    // Grid lines and points.
    if options.grid > 0
        && let Some((lo, hi)) = cp.bounds()
    {
        let cell = (hi - lo).max_element() / f64::from(options.grid);
        if cell > 0.0 {
            let g = lo + ((p - lo) / cell).round() * cell;
            offer(SnapKind::Grid, g, None);
            if (p.x - g.x).abs() <= r {
                lines.push((
                    Line::Infinite(DVec2::new(g.x, 0.0), DVec2::Y),
                    SnapKind::Grid,
                ));
            }
            if (p.y - g.y).abs() <= r {
                lines.push((
                    Line::Infinite(DVec2::new(0.0, g.y), DVec2::X),
                    SnapKind::Grid,
                ));
            }
        }
    }
    // Angle lines through the anchors.
    if let Some(step) = options.angle_step_deg.filter(|s| *s > 0.0 && s.is_finite()) {
        let count = (180.0 / step).round().clamp(1.0, 360.0) as usize;
        for a in options.anchors.iter().map(|a| DVec2::new(a[0], a[1])) {
            if !a.is_finite() {
                continue;
            }
            for k in 0..count {
                let d = DVec2::from_angle((k as f64 * step).to_radians());
                let line = Line::Infinite(a, d);
                if line.distance(p) <= r {
                    offer(SnapKind::Angle, line.nearest(p), None);
                    lines.push((line, SnapKind::Angle));
                }
            }
        }
    }
    // Edges near the pointer (not those of the excluded vertex).
    for e in &cp.edges {
        if excluded.is_some_and(|v| e.vertices.contains(&v)) {
            continue;
        }
        let line = Line::Segment(Segment::new(
            cp.position(e.vertices[0]),
            cp.position(e.vertices[1]),
        ));
        if line.distance(p) <= r {
            offer(SnapKind::Edge, line.nearest(p), None);
            lines.push((line, SnapKind::Edge));
        }
    }
    // Crossings of two reference lines of different kinds or of two angle lines (two edges
    // cross only at vertices, two grid lines at grid points: both offered already).
    for (i, (a, ka)) in lines.iter().enumerate() {
        for (b, kb) in &lines[i + 1..] {
            if ka == kb && *ka != SnapKind::Angle {
                continue;
            }
            if let Some(q) = a.cross(b, p, 2.0 * r) {
                offer(SnapKind::Crossing, q, None);
            }
        }
    }
    match best {
        Some((kind, _, q, vertex)) => Snapped {
            point: [q.x, q.y],
            kind,
            vertex,
        },
        None => free,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pattern::Assignment;

    fn square() -> CreasePattern {
        let mut cp = CreasePattern::new();
        let c = [(0.0, 0.0), (16.0, 0.0), (16.0, 16.0), (0.0, 16.0)].map(|(x, y)| DVec2::new(x, y));
        for k in 0..4 {
            cp.add_segment(c[k], c[(k + 1) % 4], Assignment::Boundary);
        }
        crate::pattern::planarize(&mut cp, &Default::default()).unwrap();
        cp
    }

    fn options(radius: f64) -> SnapOptions {
        SnapOptions {
            radius,
            grid: 0,
            angle_step_deg: None,
            anchors: Vec::new(),
            exclude_vertex: None,
        }
    }

    #[test]
    fn vertices_come_first_then_grid_then_free() {
        let cp = square();
        let s = snap(&cp, DVec2::new(15.6, 15.7), &options(1.0));
        assert_eq!((s.kind, s.point), (SnapKind::Vertex, [16.0, 16.0]));
        let mut o = options(1.0);
        o.grid = 4; // 4 mm cells
        let s = snap(&cp, DVec2::new(7.7, 4.3), &o);
        assert_eq!((s.kind, s.point), (SnapKind::Grid, [8.0, 4.0]));
        let s = snap(&cp, DVec2::new(6.0, 6.0), &options(1.0));
        assert_eq!((s.kind, s.point), (SnapKind::Free, [6.0, 6.0]));
    }

    #[test]
    fn a_22_5_degree_line_from_the_corner_meets_the_right_side_at_tan_22_5() {
        let cp = square();
        let mut o = options(0.5);
        o.angle_step_deg = Some(DEFAULT_ANGLE_STEP_DEG);
        o.anchors = vec![[0.0, 0.0]];
        // Near the right side where the 22.5° line from (0, 0) meets it: y = 16 tan 22.5°.
        let y = 16.0 * 22.5_f64.to_radians().tan();
        let s = snap(&cp, DVec2::new(15.8, y + 0.2), &o);
        assert_eq!(s.kind, SnapKind::Crossing);
        assert!((s.point[0] - 16.0).abs() < 1e-9 && (s.point[1] - y).abs() < 1e-9);
        // Away from the side: on the line itself, at the foot of the perpendicular.
        let s = snap(
            &cp,
            DVec2::new(8.0, 8.0 * 22.5_f64.to_radians().tan() + 0.1),
            &o,
        );
        assert_eq!(s.kind, SnapKind::Angle);
        let angle = s.point[1].atan2(s.point[0]).to_degrees();
        assert!((angle - 22.5).abs() < 1e-9, "{angle}");
    }

    #[test]
    fn the_dragged_vertex_is_no_target() {
        let cp = square();
        let mut o = options(1.0);
        let v = cp
            .vertices
            .iter()
            .position(|p| *p == DVec2::new(16.0, 16.0))
            .unwrap();
        o.exclude_vertex = Some(v);
        let s = snap(&cp, DVec2::new(15.6, 15.7), &o);
        assert_eq!(s.kind, SnapKind::Free);
    }
}
