//! Faces of a planar graph: trace every half-edge cycle, keep the counter-clockwise ones as
//! faces and attach each clockwise cycle (the outline of a connected component) as a hole of
//! the smallest face around it.
//!
//! Contract: the pattern must be planar (no crossing or overlapping edges, as after
//! [`super::planarize()`]); otherwise the cycles are still traced but need not be simple.
//! Dangling edges and isolated slits appear twice in the cycle that surrounds them.

use glam::DVec2;

use super::vertex_fan::VertexFans;
use super::{CreasePattern, Face, VertexId};
use crate::geom::polygon::contains_point;

/// The faces of a planar pattern and the outlines of its components.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct FaceSet {
    /// Bounded faces: outer cycle counter-clockwise, holes clockwise.
    pub faces: Vec<Face>,
    /// Outline of each connected component that no face contains (clockwise cycles of the
    /// unbounded face): their vertices are on the sheet's outside.
    pub outer: Vec<Vec<VertexId>>,
}

impl FaceSet {
    /// Marks the vertices that lie on the unbounded face.
    pub fn outer_vertex_mask(&self, vertex_count: usize) -> Vec<bool> {
        let mut mask = vec![false; vertex_count];
        for cycle in &self.outer {
            for v in cycle {
                mask[v.index()] = true;
            }
        }
        mask
    }
}

/// Traces the faces of `cp` (see the module docs for the contract).
pub fn find_faces(cp: &CreasePattern) -> FaceSet {
    let fans = VertexFans::new(cp);
    let cycles = trace_cycles(cp, &fans);
    let mut faces = Vec::new();
    let mut negative = Vec::new();
    for cycle in cycles {
        let area = cycle_area(cp, &cycle);
        if area > 0.0 {
            faces.push((Face::simple(cycle), area));
        } else {
            negative.push(cycle);
        }
    }
    let mut outer = Vec::new();
    let rings: Vec<Vec<DVec2>> = faces
        .iter()
        .map(|(f, _)| f.outer.iter().map(|&v| cp.position(v)).collect())
        .collect();
    let bboxes: Vec<(DVec2, DVec2)> = rings.iter().map(|r| ring_bounds(r)).collect();
    for cycle in negative {
        match containing_face(cp, &cycle, &rings, &bboxes, &faces) {
            Some(f) => faces[f].0.holes.push(cycle),
            None => outer.push(cycle),
        }
    }
    FaceSet {
        faces: faces.into_iter().map(|(f, _)| f).collect(),
        outer,
    }
}

/// Follows every half-edge once: from `u→v`, the next half-edge leaves `v` along the spoke
/// just clockwise of `v→u`, which keeps the face on the left.
fn trace_cycles(cp: &CreasePattern, fans: &VertexFans) -> Vec<Vec<VertexId>> {
    // Half-edge h = index of a spoke in fans.spokes (it leaves the vertex owning the row).
    let owner = spoke_owners(fans);
    let twin = spoke_twins(cp, fans, &owner);
    let mut used = vec![false; fans.spokes.len()];
    let mut cycles = Vec::new();
    for start in 0..fans.spokes.len() {
        if used[start] {
            continue;
        }
        let mut cycle = Vec::new();
        let mut h = start;
        while !used[h] {
            used[h] = true;
            cycle.push(owner[h]);
            // Arrive at the far end through the twin, then turn to its clockwise neighbour.
            let t = twin[h] as usize;
            let v = owner[t];
            let lo = fans.offsets[v.index()] as usize;
            let hi = fans.offsets[v.index() + 1] as usize;
            h = if t == lo { hi - 1 } else { t - 1 };
        }
        cycles.push(cycle);
    }
    cycles
}

/// Signed area of a cycle, or 0 when it is zero up to rounding (a tree traced around both
/// sides, whose terms cancel): the shoelace terms are taken about the first vertex and the
/// sum is compared with the sum of their magnitudes.
fn cycle_area(cp: &CreasePattern, cycle: &[VertexId]) -> f64 {
    let o = cp.position(cycle[0]);
    let (mut sum, mut mag) = (0.0, 0.0);
    for w in cycle.windows(2).skip(1) {
        let t = (cp.position(w[0]) - o).perp_dot(cp.position(w[1]) - o);
        sum += t;
        mag += t.abs();
    }
    if sum.abs() <= 1e-10 * mag {
        0.0
    } else {
        0.5 * sum
    }
}

fn spoke_owners(fans: &VertexFans) -> Vec<VertexId> {
    let mut owner = Vec::with_capacity(fans.spokes.len());
    for v in 0..fans.len() {
        let n = (fans.offsets[v + 1] - fans.offsets[v]) as usize;
        owner.extend(std::iter::repeat_n(VertexId::new(v), n));
    }
    owner
}

/// For each spoke, the index of the spoke of the same edge at its other end.
fn spoke_twins(cp: &CreasePattern, fans: &VertexFans, owner: &[VertexId]) -> Vec<u32> {
    let mut first = vec![u32::MAX; cp.edges.len()];
    let mut twin = vec![0u32; fans.spokes.len()];
    for (i, s) in fans.spokes.iter().enumerate() {
        let e = s.edge.index();
        if first[e] == u32::MAX {
            first[e] = i as u32;
        } else {
            let j = first[e] as usize;
            twin[i] = j as u32;
            twin[j] = i as u32;
        }
    }
    debug_assert_eq!(owner.len(), twin.len());
    twin
}

fn ring_bounds(ring: &[DVec2]) -> (DVec2, DVec2) {
    ring.iter().fold(
        (DVec2::splat(f64::INFINITY), DVec2::splat(f64::NEG_INFINITY)),
        |(lo, hi), &p| (lo.min(p), hi.max(p)),
    )
}

/// The smallest face whose outer ring contains the cycle's first vertex, excluding faces
/// that share a vertex with the cycle (its own component).
fn containing_face(
    cp: &CreasePattern,
    cycle: &[VertexId],
    rings: &[Vec<DVec2>],
    bboxes: &[(DVec2, DVec2)],
    faces: &[(Face, f64)],
) -> Option<usize> {
    let p = cp.position(*cycle.first()?);
    let mut best: Option<(usize, f64)> = None;
    for (i, ((lo, hi), (face, area))) in bboxes.iter().zip(faces).enumerate() {
        if p.cmplt(*lo).any() || p.cmpgt(*hi).any() {
            continue;
        }
        if best.is_some_and(|(_, a)| *area >= a) {
            continue;
        }
        if face.outer.iter().any(|v| cycle.contains(v)) {
            continue;
        }
        if contains_point(&rings[i], p) {
            best = Some((i, *area));
        }
    }
    best.map(|(i, _)| i)
}
