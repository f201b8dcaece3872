//! Isometric unfolding of a folded state into a crease pattern.
//!
//! Faces are placed breadth-first across shared edges ([`crate::geom::unfold`], shared with
//! tessellation). Each face is a planar polygon in 3D with its (Newell) normal `n`; it is laid
//! into the plane by the rigid map that sends the shared edge `a b` onto its already placed
//! image `A B` ([`anchor_map`]): `P = A + E·((p − a)·e) + W·((p − a)·w)`, with `e` the unit
//! vector from `a` to `b`, `w = n × e`, `E` the unit vector from `A` to `B` and `W` = `E`
//! turned by +90°. Lengths and
//! angles inside each face are kept exactly (to rounding), and a face whose vertex order is
//! counter-clockwise about its normal comes out counter-clockwise in the plane. A face whose
//! orientation disagrees with its neighbour would land on top of it: it is mirrored instead.
//!
//! The first face of each connected piece keeps its x, y position when its normal is +z
//! (so flat-folded 2D forms and gently folded ones unfold in place). Pieces after the first
//! are shifted right of the previous ones.
//!
//! Small length errors left by rounded input (below 1e-4 relative) are then removed by
//! [`super::relax`], which moves vertices by the least amount that restores every face edge's
//! 3D length.
//!
//! Limits: a vertex is placed by the first face that reaches it; when a later face would put
//! it elsewhere (the folded state is not developable there, e.g. a cube corner, or faces
//! meet only at a vertex) the first position is kept and a warning reports the largest gap,
//! so the lengths of that later face are not all kept. Faces of zero area are not placed;
//! vertices on no placed face keep their x and y.

use std::collections::HashMap;

use glam::{DVec2, DVec3};

use super::relax::{Rod, fit_lengths, worst_error};
use crate::formats::{Finding, FindingKind};
use crate::geom::tolerance::{RELATIVE, RELATIVE_SQUARED};
use crate::geom::unfold::{anchor_map, breadth_first};
use crate::pattern::{Face, VertexId};

/// Relative length errors up to this are rounding: no adjustment.
const RELAX_BELOW: f64 = 1e-12;

/// Relative length errors beyond this are real (non-developable) geometry: not adjusted.
const RELAX_ABOVE: f64 = 1e-4;

/// Relative length error below which the unfolding counts as isometric.
const LENGTHS_KEPT: f64 = 1e-9;

/// The result of [`unfold`]: 2D positions for every vertex, and what could not be kept.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Unfolding {
    /// Unfolded position of each vertex, in the folded state's unit.
    pub vertices: Vec<DVec2>,
    /// Remarks: non-developable vertices, mirrored or degenerate faces, separate pieces.
    pub warnings: Vec<Finding>,
}

/// Unfolds the faces of a folded state (vertex positions `points`, faces indexing them) into
/// the plane, preserving every face's edge lengths and angles. Faces' vertex ids must be
/// below `points.len()` (as in a validated pattern); other ids are skipped.
pub fn unfold(points: &[DVec3], faces: &[Face]) -> Unfolding {
    let mut u = Unfolder::new(points, faces);
    for root in 0..faces.len() {
        if !u.visited[root] && u.normals[root].is_some() {
            u.unfold_piece(root);
        }
    }
    u.finish()
}

/// Counts of what went wrong, for the warnings.
#[derive(Default)]
struct Stats {
    conflicts: usize,
    max_gap: f64,
    mirrored: usize,
    degenerate: usize,
    pieces: usize,
}

struct Unfolder<'a> {
    points: &'a [DVec3],
    faces: &'a [Face],
    normals: Vec<Option<DVec3>>,
    edge_faces: HashMap<(u32, u32), Vec<usize>>,
    placed: Vec<Option<DVec2>>,
    visited: Vec<bool>,
    /// Tolerance for position disagreements: 1e-9 of the points' extent.
    tol: f64,
    /// Gap between pieces.
    gap: f64,
    /// Right edge of the pieces laid out so far, and the bottom of the first.
    layout: Option<(f64, f64)>,
    stats: Stats,
}

impl<'a> Unfolder<'a> {
    fn new(points: &'a [DVec3], faces: &'a [Face]) -> Self {
        let (lo, hi) = points
            .iter()
            .fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(l, h), &p| {
                (l.min(p), h.max(p))
            });
        let extent = if points.is_empty() {
            0.0
        } else {
            lo.distance(hi)
        };
        let mut edge_faces: HashMap<(u32, u32), Vec<usize>> = HashMap::new();
        for (f, face) in faces.iter().enumerate() {
            for (a, b) in cycle_edges(face) {
                edge_faces.entry(pair(a, b)).or_default().push(f);
            }
        }
        let normals = faces
            .iter()
            .map(|f| face_normal(points, &f.outer, extent))
            .collect::<Vec<_>>();
        let degenerate = normals.iter().filter(|n| n.is_none()).count();
        Unfolder {
            points,
            faces,
            normals,
            edge_faces,
            placed: vec![None; points.len()],
            visited: vec![false; faces.len()],
            tol: RELATIVE * extent,
            gap: 0.05 * extent.max(f64::MIN_POSITIVE),
            layout: None,
            stats: Stats {
                degenerate,
                ..Stats::default()
            },
        }
    }

    fn point(&self, v: VertexId) -> Option<DVec3> {
        self.points.get(v.index()).copied()
    }

    /// Unfolds the piece of faces connected to `root` across edges: faces of zero area are
    /// not reached, and each face is placed across the first edge that reaches it.
    fn unfold_piece(&mut self, root: usize) {
        let before: Vec<bool> = self.placed.iter().map(Option::is_some).collect();
        let (faces, edge_faces, normals) = (self.faces, &self.edge_faces, &self.normals);
        let order = breadth_first(root, &mut self.visited, |f, out| {
            for (a, b) in cycle_edges(&faces[f]) {
                let across = edge_faces.get(&pair(a, b)).into_iter().flatten();
                out.extend(
                    across
                        .filter(|&&g| normals[g].is_some())
                        .map(|&g| (g, (a, b))),
                );
            }
        });
        for step in order {
            match step.across {
                None => self.place_root(step.face),
                Some((parent, (a, b))) => self.place_across(step.face, parent, a, b),
            }
        }
        let new: Vec<usize> = (0..self.placed.len())
            .filter(|&v| self.placed[v].is_some() && !before[v])
            .collect();
        self.lay_out_piece(&new);
    }

    /// Places the first face of a piece: its first edge keeps its x–y direction.
    fn place_root(&mut self, f: usize) {
        let outer = &self.faces[f].outer;
        let Some(a) = outer.first().copied() else {
            return;
        };
        let Some(pa) = self.point(a) else { return };
        let b = outer
            .iter()
            .copied()
            .find(|&v| self.point(v).is_some_and(|p| p.distance(pa) > self.tol))
            .unwrap_or(a);
        let pb = self.point(b).unwrap_or(pa);
        let start = pa.truncate();
        let dir = (pb - pa).truncate().try_normalize().unwrap_or(DVec2::X);
        self.visited[f] = true;
        self.place_face(f, (pa, pb), (start, start + dir * pa.distance(pb)), false);
    }

    /// Places face `g` across the edge `a b` it shares with the placed face `parent`.
    fn place_across(&mut self, g: usize, parent: usize, a: VertexId, b: VertexId) {
        self.visited[g] = true;
        let (Some(pa), Some(pb)) = (self.point(a), self.point(b)) else {
            return;
        };
        let (Some(qa), Some(qb)) = (self.placed[a.index()], self.placed[b.index()]) else {
            return;
        };
        let side = |c: DVec2| (qb - qa).perp_dot(c - qa);
        let parent_side = side(self.centroid(parent));
        let image_side = side(self.face_image_centroid(g, (pa, pb), (qa, qb)));
        let mirror = parent_side * image_side > 0.0;
        self.stats.mirrored += usize::from(mirror);
        self.place_face(g, (pa, pb), (qa, qb), mirror);
    }

    /// The centroid of the placed vertices of face `f`'s outer cycle.
    fn centroid(&self, f: usize) -> DVec2 {
        let pts: Vec<DVec2> = self.faces[f]
            .outer
            .iter()
            .filter_map(|v| self.placed.get(v.index()).copied().flatten())
            .collect();
        pts.iter().copied().sum::<DVec2>() / pts.len().max(1) as f64
    }

    /// The centroid face `g` would have under the (unmirrored) anchor map.
    fn face_image_centroid(&self, g: usize, from: (DVec3, DVec3), to: (DVec2, DVec2)) -> DVec2 {
        let map = self.anchor_map(g, from, to, false);
        let outer = &self.faces[g].outer;
        let sum: DVec2 = outer.iter().filter_map(|&v| self.point(v)).map(&map).sum();
        sum / outer.len().max(1) as f64
    }

    /// The rigid map of face `g` sending the 3D segment `from` onto the 2D segment `to`.
    fn anchor_map(
        &self,
        g: usize,
        from: (DVec3, DVec3),
        to: (DVec2, DVec2),
        mirror: bool,
    ) -> impl Fn(DVec3) -> DVec2 + use<> {
        anchor_map(self.normals[g].unwrap_or(DVec3::Z), from, to, mirror)
    }

    /// Places every vertex of face `g` (outer cycle and holes) with the anchor map; vertices
    /// already placed keep their position and any disagreement is recorded.
    fn place_face(&mut self, g: usize, from: (DVec3, DVec3), to: (DVec2, DVec2), mirror: bool) {
        let map = self.anchor_map(g, from, to, mirror);
        let face = &self.faces[g];
        for &v in std::iter::once(&face.outer).chain(&face.holes).flatten() {
            let Some(p) = self.point(v) else { continue };
            let q = map(p);
            match self.placed[v.index()] {
                None => self.placed[v.index()] = Some(q),
                Some(old) => {
                    let gap = old.distance(q);
                    if gap > self.tol {
                        self.stats.conflicts += 1;
                        self.stats.max_gap = self.stats.max_gap.max(gap);
                    }
                }
            }
        }
    }

    /// Shifts a piece after the first to the right of those already laid out.
    fn lay_out_piece(&mut self, vertices: &[usize]) {
        self.stats.pieces += 1;
        let pts: Vec<DVec2> = vertices.iter().filter_map(|&v| self.placed[v]).collect();
        let Some(&first) = pts.first() else { return };
        let (lo, hi) = pts
            .iter()
            .fold((first, first), |(l, h), &p| (l.min(p), h.max(p)));
        let shift = match self.layout {
            None => DVec2::ZERO,
            Some((right, bottom)) => DVec2::new(right + self.gap - lo.x, bottom - lo.y),
        };
        for &v in vertices {
            if let Some(p) = self.placed[v].as_mut() {
                *p += shift;
            }
        }
        let bottom = self.layout.map_or(lo.y, |(_, b)| b);
        self.layout = Some((hi.x + shift.x, bottom));
    }

    /// The face edges between placed vertices, with their 3D lengths.
    fn rods(&self) -> Vec<Rod> {
        let mut seen = std::collections::HashSet::new();
        let mut rods = Vec::new();
        for (f, face) in self.faces.iter().enumerate() {
            if !self.visited[f] || self.normals[f].is_none() {
                continue;
            }
            for (a, b) in cycle_edges(face) {
                let (Some(pa), Some(pb)) = (self.point(a), self.point(b)) else {
                    continue;
                };
                let placed = |v: VertexId| self.placed.get(v.index()).is_some_and(Option::is_some);
                let length = pa.distance(pb);
                if placed(a) && placed(b) && length > self.tol && seen.insert(pair(a, b)) {
                    rods.push(Rod {
                        a: a.index(),
                        b: b.index(),
                        length,
                    });
                }
            }
        }
        rods
    }

    /// Removes small length errors (rounded input) from the placed vertices; returns the
    /// largest relative error before and after.
    fn relax(&mut self) -> (f64, f64) {
        let rods = self.rods();
        let mut pts: Vec<DVec2> = self.placed.iter().map(|p| p.unwrap_or_default()).collect();
        let before = worst_error(&pts, &rods);
        if before <= RELAX_BELOW || before > RELAX_ABOVE {
            return (before, before);
        }
        let after = fit_lengths(&mut pts, &rods);
        for (slot, p) in self.placed.iter_mut().zip(pts) {
            if slot.is_some() {
                *slot = Some(p);
            }
        }
        (before, after)
    }

    fn finish(mut self) -> Unfolding {
        let (before, after) = self.relax();
        let mut warnings = Vec::new();
        let s = &self.stats;
        if before > RELAX_BELOW && after < before {
            let rest = if after > LENGTHS_KEPT {
                "; what remains is geometry that does not unfold flat"
            } else {
                ""
            };
            warnings.push(FindingKind::NotDevelopable.warning(format!(
                "the folded state is not exactly developable (faces not quite flat, e.g. rounded \
                 coordinates): adjusted the unfolding to bring edge length errors from {before:.1e} \
                 down to {after:.1e} (relative){rest}"
            )));
        } else if s.conflicts > 0 && after > LENGTHS_KEPT {
            warnings.push(FindingKind::NotDevelopable.warning(format!(
                "the folded state is not developable: {} vertex placements disagree (by up to {:.3e}); \
                 the first was kept, so edge lengths differ from the folded state by up to {after:.1e} \
                 (relative)",
                s.conflicts, s.max_gap
            )));
        }
        if s.mirrored > 0 {
            warnings.push(FindingKind::MirroredFaces.warning(format!(
                "{} faces are oriented against their neighbours and were unfolded mirrored",
                s.mirrored
            )));
        }
        if s.degenerate > 0 {
            warnings.push(FindingKind::DegenerateFaces.warning(format!(
                "{} faces have no area and were not unfolded",
                s.degenerate
            )));
        }
        if s.pieces > 1 {
            warnings.push(FindingKind::Pieces.warning(format!(
                "{} separate pieces were laid out side by side",
                s.pieces
            )));
        }
        let unplaced = self.placed.iter().filter(|p| p.is_none()).count();
        if unplaced > 0 {
            warnings.push(FindingKind::LooseVertices.warning(format!(
                "{unplaced} vertices lie on no face and keep their x and y"
            )));
        }
        let vertices = self
            .placed
            .iter()
            .zip(self.points)
            .map(|(q, p)| q.unwrap_or(p.truncate()))
            .collect();
        Unfolding { vertices, warnings }
    }
}

/// The unordered key of an edge.
fn pair(a: VertexId, b: VertexId) -> (u32, u32) {
    (a.0.min(b.0), a.0.max(b.0))
}

/// Consecutive vertex pairs of a face's outer cycle and holes (repeated vertices skipped).
fn cycle_edges(face: &Face) -> impl Iterator<Item = (VertexId, VertexId)> + '_ {
    std::iter::once(&face.outer)
        .chain(&face.holes)
        .flat_map(|c| (0..c.len()).map(move |i| (c[i], c[(i + 1) % c.len()])))
        .filter(|(a, b)| a != b)
}

/// The unit normal of a polygon by Newell's method; `None` for a polygon without area (or
/// with vertex ids out of range).
fn face_normal(points: &[DVec3], cycle: &[VertexId], extent: f64) -> Option<DVec3> {
    let pts: Vec<DVec3> = cycle
        .iter()
        .map(|v| points.get(v.index()).copied())
        .collect::<Option<_>>()?;
    let origin = *pts.first()?;
    let twice_area: DVec3 = (0..pts.len())
        .map(|i| (pts[i] - origin).cross(pts[(i + 1) % pts.len()] - origin))
        .sum();
    (twice_area.length() > RELATIVE_SQUARED * extent * extent).then(|| twice_area.normalize())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn face(v: &[u32]) -> Face {
        Face::simple(v.iter().map(|&i| VertexId(i)).collect())
    }

    #[test]
    fn right_angle_fold_unfolds_flat() {
        // Two unit squares folded 90° along x = 1.
        let pts = [
            DVec3::new(0.0, 0.0, 0.0),
            DVec3::new(1.0, 0.0, 0.0),
            DVec3::new(1.0, 1.0, 0.0),
            DVec3::new(0.0, 1.0, 0.0),
            DVec3::new(1.0, 0.0, 1.0),
            DVec3::new(1.0, 1.0, 1.0),
        ];
        let faces = [face(&[0, 1, 2, 3]), face(&[1, 4, 5, 2])];
        let u = unfold(&pts, &faces);
        assert!(u.warnings.is_empty(), "{:?}", u.warnings);
        assert!(
            u.vertices[4].distance(DVec2::new(2.0, 0.0)) < 1e-12,
            "{:?}",
            u.vertices
        );
        assert!(u.vertices[5].distance(DVec2::new(2.0, 1.0)) < 1e-12);
    }

    #[test]
    fn cone_vertex_is_reported() {
        // Three faces of a cube corner: 270° around the vertex, not developable.
        let pts = [
            DVec3::ZERO,
            DVec3::X,
            DVec3::new(1.0, 1.0, 0.0),
            DVec3::Y,
            DVec3::new(0.0, 1.0, 1.0),
            DVec3::Z,
            DVec3::new(1.0, 0.0, 1.0),
        ];
        let faces = [
            face(&[0, 1, 2, 3]),
            face(&[0, 3, 4, 5]),
            face(&[0, 5, 6, 1]),
        ];
        let u = unfold(&pts, &faces);
        assert!(
            u.warnings
                .iter()
                .any(|w| w.kind == FindingKind::NotDevelopable),
            "{:?}",
            u.warnings
        );
    }
}
