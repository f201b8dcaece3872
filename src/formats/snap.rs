//! Snapping line ends that were meant to meet: the import tolerance of drawings.
//!
//! Drawing programs leave the end of a line a fraction of a pixel short of (or past) the line
//! or corner it was drawn to; planarisation's own tolerance (a few micrometres) does not join
//! them, so the pattern gets dangling creases and vertices that fail Kawasaki's and Maekawa's
//! theorems. Origami Simulator's importer merges vertices within a tolerance of 3 px for the
//! same reason.
//!
//! The readers ([`super::finish_drawing`]) first move line ends ([`snap_ends`]), then merge
//! junctions closer than the tolerance ([`snap_junctions`]: several lines meant to meet at
//! one point that cross a little apart), then planarise again at the fine tolerance. Points
//! inside a chain (a vertex with two edges of one assignment, such as the chords of a
//! flattened curve, which may lie closer together than the snapping tolerance) never move,
//! so curves keep their shape.
//!
//! [`snap_ends`] works on a planarised pattern and moves only *line ends*: vertices with a
//! single edge. Each end within `tolerance` of another vertex is merged into the nearest such
//! vertex; otherwise an end within `tolerance` of an edge (not its own) moves onto the nearest
//! point of that edge, which a following planarisation splits there. Vertices where two or
//! more edges meet never move, so a fine pattern keeps its small features even with a coarse
//! tolerance; only a genuinely loose end nearer than the tolerance to something else changes.
//!
//! Cost: O(E log E) to sort the edges' boxes plus O(k) distance tests per end, k the edges
//! whose box (grown by the tolerance) spans the end's x.

use glam::DVec2;

use crate::geom::segment::project;
use crate::geom::{DisjointSets, HashGrid};
use crate::pattern::{CreasePattern, EdgeId, VertexId};

/// Default snapping tolerance relative to the drawing's bounding-box diagonal (1e-3: 0.28 mm
/// on a 200 mm square sheet). Origami Simulator's 3 px is 0.8 mm at 96 dpi.
pub const SNAP_RELATIVE: f64 = 1e-3;

/// The default snapping tolerance of a drawing: [`SNAP_RELATIVE`] of its diagonal, in the
/// pattern's unit (0 for an empty pattern).
pub fn default_snap(cp: &CreasePattern) -> f64 {
    cp.bounds()
        .map_or(0.0, |(lo, hi)| lo.distance(hi) * SNAP_RELATIVE)
}

/// Moves every line end (a vertex with exactly one edge) that lies within `tolerance` of
/// another vertex or of an edge not its own onto it (see the module docs), and trims stubs
/// shorter than `tolerance` that overshoot a junction (moving the end onto the junction);
/// returns how many ends moved. The caller planarises afterwards to merge and split at the moved ends.
pub fn snap_ends(cp: &mut CreasePattern, tolerance: f64) -> usize {
    if tolerance.is_nan() || tolerance <= 0.0 {
        return 0;
    }
    let incident = cp.vertex_edges();
    let ends: Vec<VertexId> = cp
        .vertex_ids()
        .filter(|v| incident[v.index()].len() == 1)
        .collect();
    if ends.is_empty() {
        return 0;
    }
    let index = EdgeIndex::new(cp, tolerance);
    let mut moved = 0;
    for v in ends {
        let own = incident[v.index()][0];
        let other = cp.edges[own.index()].other(v);
        // An overshoot: a stub shorter than the tolerance past a junction is trimmed.
        let overshoot = (incident[other.index()].len() >= 3 && cp.edge_length(own) <= tolerance)
            .then(|| cp.position(other));
        if let Some(target) = overshoot.or_else(|| index.nearest(cp, &incident, v, own, tolerance))
        {
            cp.vertices[v.index()] = target;
            moved += 1;
        }
    }
    moved
}

/// Largest turn between the two edges of a chain point, in degrees: a vertex with two edges
/// of one assignment that turn more sharply is a corner, which snapping may move. The chords
/// of a curve flattened within 0.01 mm turn far less.
pub const CHAIN_MAX_TURN_DEG: f64 = 30.0;

/// Merges junctions (vertices that are not inside a chain: one, three or more edges, two of
/// different assignments, or two turning by more than [`CHAIN_MAX_TURN_DEG`]) lying within
/// `tolerance` of each other: every vertex of a cluster moves to the point where the lines
/// leaving the cluster come closest to meeting, in least squares. Returns how many
/// vertices moved; the caller planarises afterwards to merge them.
pub fn snap_junctions(cp: &mut CreasePattern, tolerance: f64) -> usize {
    if tolerance.is_nan() || tolerance <= 0.0 {
        return 0;
    }
    let incident = cp.vertex_edges();
    let junction = |v: usize| match incident[v].as_slice() {
        [a, b] => {
            let (ea, eb) = (&cp.edges[a.index()], &cp.edges[b.index()]);
            let p = cp.vertices[v];
            let da = cp.vertices[ea.other(VertexId(v as u32)).index()] - p;
            let db = cp.vertices[eb.other(VertexId(v as u32)).index()] - p;
            let turn = 180.0 - da.angle_to(db).abs().to_degrees();
            ea.assignment != eb.assignment || turn > CHAIN_MAX_TURN_DEG
        }
        list => !list.is_empty(),
    };
    let mut grid = HashGrid::new(tolerance);
    let candidates: Vec<usize> = (0..cp.vertices.len()).filter(|&v| junction(v)).collect();
    for &v in &candidates {
        grid.insert(cp.vertices[v], v);
    }
    let mut groups = DisjointSets::new(cp.vertices.len());
    for &v in &candidates {
        let p = cp.vertices[v];
        for w in grid.near(p) {
            if w > v && p.distance(cp.vertices[w]) <= tolerance {
                groups.union(v, w);
            }
        }
    }
    // The clusters, each listed by its root.
    let mut clusters: std::collections::BTreeMap<usize, Vec<usize>> = Default::default();
    for &v in &candidates {
        clusters.entry(groups.find(v)).or_default().push(v);
    }
    // Every point from the positions as read, then every move: clusters do not see each
    // other's moves, whatever the order.
    let targets: Vec<(&Vec<usize>, DVec2)> = clusters
        .values()
        .filter(|m| m.len() > 1)
        .map(|m| (m, meeting_point(cp, &incident, m, tolerance)))
        .collect();
    let mut moved = 0;
    for (members, to) in targets {
        for &v in members {
            if cp.vertices[v] != to {
                cp.vertices[v] = to;
                moved += 1;
            }
        }
    }
    moved
}

/// Shortest edge, over the tolerance, whose line [`snap_junctions`] trusts for placing a
/// junction; a cluster with a shorter edge leaving it (the chords of flattened curves) stays at
/// its member with the most edges.
const LINE_MIN_OVER_TOLERANCE: f64 = 10.0;

/// Largest `|sin|` of the angle between two edges leaving a cluster for them to count as the
/// two halves of one drawn line (about 0.6°).
const SAME_LINE_SIN: f64 = 0.01;

/// Smallest `sin²` of the angle between the lines of a cluster for them to fix a point: lines
/// within 1° of parallel (`sin² 1° ≈ 3.0e-4`) meet too far along themselves to say where.
pub const MEETING_MIN_SIN2: f64 = 3.0e-4;

/// Where the lines through a cluster of junctions meet: the point nearest, in least squares,
/// to the line of every edge leaving the cluster. Each such edge joins a member to a vertex
/// outside; both lie on the line as drawn (crossings are computed on it, snapped ends are
/// moved onto it), so the point is where the drawing's lines come closest to one meeting.
/// Falls back to the member with the most edges (the first on ties) when an edge leaving the
/// cluster is short, when the lines are nearly parallel, or when their meeting point lies
/// farther than `tolerance` from that member.
fn meeting_point(
    cp: &CreasePattern,
    incident: &[Vec<EdgeId>],
    members: &[usize],
    tolerance: f64,
) -> DVec2 {
    let mut busiest = members[0];
    for &v in &members[1..] {
        if incident[v].len() > incident[busiest].len() {
            busiest = v;
        }
    }
    let fallback = cp.vertices[busiest];
    // The lines (a point, a unit direction) of the edges leaving the cluster.
    let mut lines = Vec::new();
    for &v in members {
        for &e in &incident[v] {
            let far = cp.edges[e.index()].other(VertexId(v as u32)).index();
            if members.contains(&far) {
                continue;
            }
            let along = cp.vertices[far] - cp.vertices[v];
            if along.length() < LINE_MIN_OVER_TOLERANCE * tolerance {
                // A chord of a curve or a short stub: its direction says little about where
                // lines meet.
                return fallback;
            }
            lines.push((cp.vertices[v], along / along.length()));
        }
    }
    // Normal equations of Σ w |(I − d dᵀ)(x − p)|², each drawn line weighted once: a line
    // passing through the junction leaves it twice, and its two halves share the weight (one
    // weight per edge pulled the point towards passing lines, and on Origami Simulator's
    // crane left junctions at 0.37° where the lines as drawn miss by 0.18°).
    let (mut xx, mut xy, mut yy, mut b) = (0.0, 0.0, 0.0, DVec2::ZERO);
    for &(p, d) in &lines {
        let halves = lines
            .iter()
            .filter(|(_, e)| d.perp_dot(*e).abs() < SAME_LINE_SIN)
            .count();
        let w = 1.0 / halves as f64;
        let (a11, a12, a22) = (1.0 - d.x * d.x, -d.x * d.y, 1.0 - d.y * d.y);
        xx += w * a11;
        xy += w * a12;
        yy += w * a22;
        b += w * DVec2::new(a11 * p.x + a12 * p.y, a12 * p.x + a22 * p.y);
    }
    let det = xx * yy - xy * xy;
    let trace = xx + yy;
    if det.is_nan() || det <= MEETING_MIN_SIN2 * trace * trace / 4.0 {
        return fallback;
    }
    let x = DVec2::new(yy * b.x - xy * b.y, xx * b.y - xy * b.x) / det;
    if x.distance(fallback) <= tolerance {
        x
    } else {
        fallback
    }
}

/// Edges sorted by the low x of their box grown by the tolerance, with the running maximum
/// of the high x, so the edges whose box spans an x are found by a binary search.
struct EdgeIndex {
    /// (low x, high x, edge), sorted by low x.
    boxes: Vec<(f64, f64, EdgeId)>,
}

impl EdgeIndex {
    fn new(cp: &CreasePattern, tolerance: f64) -> Self {
        let mut boxes: Vec<(f64, f64, EdgeId)> = cp
            .edge_ids()
            .map(|e| {
                let (a, b) = cp.segment(e);
                (a.x.min(b.x) - tolerance, a.x.max(b.x) + tolerance, e)
            })
            .collect();
        boxes.sort_by(|p, q| p.0.total_cmp(&q.0));
        EdgeIndex { boxes }
    }

    /// The point the end `v` (whose edge is `own`) snaps to: the nearest vertex within
    /// `tolerance` where lines meet (not another end, which may itself move), else the
    /// nearest point of another edge, else the nearest other end. `incident` lists each
    /// vertex's edges.
    fn nearest(
        &self,
        cp: &CreasePattern,
        incident: &[Vec<EdgeId>],
        v: VertexId,
        own: EdgeId,
        tol: f64,
    ) -> Option<DVec2> {
        let p = cp.position(v);
        let mut best_vertex: Option<(f64, DVec2)> = None;
        let mut best_end: Option<(f64, DVec2)> = None;
        let mut best_edge: Option<(f64, DVec2)> = None;
        let upto = self.boxes.partition_point(|b| b.0 <= p.x);
        for &(_, hi, e) in &self.boxes[..upto] {
            if hi < p.x || e == own {
                continue;
            }
            let edge = &cp.edges[e.index()];
            if edge.vertices.contains(&v) {
                continue;
            }
            let (a, b) = cp.segment(e);
            for w in edge.vertices {
                let (q, d) = (cp.position(w), p.distance(cp.position(w)));
                let best = if incident[w.index()].len() == 1 {
                    &mut best_end
                } else {
                    &mut best_vertex
                };
                if d <= tol && best.is_none_or(|(bd, _)| d < bd) {
                    *best = Some((d, q));
                }
            }
            let q = a.lerp(b, project(a, b, p));
            let d = p.distance(q);
            if d <= tol && best_edge.is_none_or(|(bd, _)| d < bd) {
                best_edge = Some((d, q));
            }
        }
        best_vertex.or(best_edge).or(best_end).map(|(_, q)| q)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pattern::{Assignment, PlanarizeOptions, planarize};

    fn clean(cp: &mut CreasePattern) {
        planarize(cp, &PlanarizeOptions::default()).expect("small pattern");
    }

    #[test]
    fn a_short_end_joins_the_line_it_was_drawn_to() {
        // A T whose stem stops 0.05 short of the bar.
        let mut cp = CreasePattern::new();
        cp.add_segment(
            DVec2::new(0.0, 0.0),
            DVec2::new(10.0, 0.0),
            Assignment::Valley,
        );
        cp.add_segment(
            DVec2::new(5.0, 0.05),
            DVec2::new(5.0, 5.0),
            Assignment::Mountain,
        );
        clean(&mut cp);
        assert_eq!(cp.vertices.len(), 4);
        assert_eq!(snap_ends(&mut cp, 0.1), 1);
        clean(&mut cp);
        assert_eq!((cp.vertices.len(), cp.edges.len()), (4, 3));
    }

    #[test]
    fn ends_prefer_a_vertex_and_leave_joined_corners_alone() {
        // Two lines meeting at a corner, and a third ending 0.03 from that corner.
        let mut cp = CreasePattern::new();
        cp.add_segment(DVec2::ZERO, DVec2::new(10.0, 0.0), Assignment::Boundary);
        cp.add_segment(DVec2::ZERO, DVec2::new(0.0, 10.0), Assignment::Boundary);
        cp.add_segment(
            DVec2::new(0.03, 0.02),
            DVec2::new(5.0, 5.0),
            Assignment::Valley,
        );
        clean(&mut cp);
        assert_eq!(snap_ends(&mut cp, 0.1), 1);
        clean(&mut cp);
        assert_eq!((cp.vertices.len(), cp.edges.len()), (4, 3));
        assert!(cp.vertices.contains(&DVec2::ZERO));
    }

    #[test]
    fn junctions_merge_but_chain_points_stay() {
        // Three lines meant to meet at the origin cross pairwise a little apart, and an arc
        // of chords 0.05 apart passes nearby.
        let mut cp = CreasePattern::new();
        cp.add_segment(
            DVec2::new(-5.0, 0.0),
            DVec2::new(5.0, 0.0),
            Assignment::Valley,
        );
        cp.add_segment(
            DVec2::new(0.02, -5.0),
            DVec2::new(0.02, 5.0),
            Assignment::Mountain,
        );
        cp.add_segment(
            DVec2::new(-5.0, -5.03),
            DVec2::new(5.0, 4.97),
            Assignment::Mountain,
        );
        let chain: Vec<DVec2> = (0..=20)
            .map(|i| DVec2::new(3.0 + 0.05 * f64::from(i), -3.0))
            .collect();
        for w in chain.windows(2) {
            cp.add_segment(w[0], w[1], Assignment::Flat);
        }
        clean(&mut cp);
        let before = cp.vertices.len();
        assert!(snap_junctions(&mut cp, 0.1) >= 2);
        clean(&mut cp);
        // The three crossings became one vertex; the 21 chain points are all still there.
        assert_eq!(cp.vertices.len(), before - 2);
        assert!(chain.iter().all(|p| cp.vertices.contains(p)));
    }

    #[test]
    fn ends_farther_than_the_tolerance_stay() {
        let mut cp = CreasePattern::new();
        cp.add_segment(DVec2::ZERO, DVec2::new(10.0, 0.0), Assignment::Valley);
        cp.add_segment(
            DVec2::new(5.0, 0.5),
            DVec2::new(5.0, 5.0),
            Assignment::Valley,
        );
        clean(&mut cp);
        assert_eq!(snap_ends(&mut cp, 0.1), 0);
        assert_eq!(snap_ends(&mut cp, 0.0), 0);
    }
}
