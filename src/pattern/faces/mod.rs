//! Faces of a planar graph: trace every half-edge cycle, keep the counter-clockwise ones as
//! faces, and attach each clockwise cycle (the outline of a connected component) as a hole of
//! the face around it, found by casting a ray down from the component's lowest vertex
//! ([`nesting`]).
//!
//! Cost: O(E log d) to sort the fans and O(E) to trace; with several components, the ray casts
//! use a column index of the edges (O(E + H·k) for H components and k edges per column).
//!
//! Contract: the pattern must be planar (no crossing or overlapping edges, as after
//! [`super::planarize()`]); otherwise the cycles are still traced but need not be simple.
//! Dangling edges and isolated slits appear twice in the cycle that surrounds them.

mod nesting;
mod trace;

use super::vertex_fan::VertexFans;
use super::{CreasePattern, Face, VertexId};

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
    find_faces_with(cp, &VertexFans::new(cp))
}

/// [`find_faces`] with the vertex fans already built (they must be `cp`'s).
pub fn find_faces_with(cp: &CreasePattern, fans: &VertexFans) -> FaceSet {
    let traced = trace::trace(cp, fans);
    let mut face_of_cycle = vec![None; traced.cycles.len()];
    let mut faces = Vec::new();
    let mut outlines = Vec::new();
    for (c, cycle) in traced.cycles.iter().enumerate() {
        if trace::cycle_area(cp, cycle) > 0.0 {
            face_of_cycle[c] = Some(faces.len());
            faces.push(Face::simple(cycle.clone()));
        } else {
            outlines.push(c);
        }
    }
    let containers = nesting::containing_faces(cp, fans, &traced, &face_of_cycle, &outlines);
    let mut outer = Vec::new();
    for (&c, container) in outlines.iter().zip(containers) {
        let cycle = traced.cycles[c].clone();
        match container {
            Some(f) => faces[f].holes.push(cycle),
            None => outer.push(cycle),
        }
    }
    FaceSet { faces, outer }
}
