//! Developability of a 3D frame: does the folded form unfold onto the crease pattern without
//! stretching?
//!
//! The folded form (a FOLD `foldedForm` frame) is developable onto the pattern exactly when
//! every face keeps its flat shape: each face, moved rigidly, lies on its face of the
//! pattern. A face is congruent to its flat shape when the distances from every vertex to
//! three non-collinear *anchor* vertices are kept: in the plane, three distances fix a point,
//! and a 3D point at those distances from three anchors lies on their plane exactly when the
//! two mirror solutions coincide, so the face is also planar. This costs O(k) per face of k
//! vertices (all pairs would cost O(k²)) and implies the usual vertex condition — the sector
//! angles around an interior vertex of a developable surface sum to 360° (the angle defect
//! vanishes).
//!
//! The error of a face is the largest |d₃ − d₂| over the anchor distances, relative to the
//! face's diameter in the pattern; a face fails above [`DEVELOPABLE_RELATIVE_TOLERANCE`].

use glam::{DVec2, DVec3};

use super::{Finding, FindingKind, Quantity};
use crate::pattern::{CreasePattern, Face, VertexId};

/// Largest relative change of a distance within a face (to its diameter) that still counts
/// as unstretched: far above f64 rounding, far below anything a sheet would notice.
pub const DEVELOPABLE_RELATIVE_TOLERANCE: f64 = 1e-6;

/// What the developability pass found.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Developability {
    /// Faces compared.
    pub faces: usize,
    /// The largest relative error over all faces.
    pub largest_error: f64,
    /// Faces beyond the tolerance.
    pub findings: Vec<Finding>,
}

/// Compares every face of `faces` (pattern vertex ids) in the pattern and in `folded`
/// (3D positions indexed like the pattern's vertices). Faces naming a vertex `folded` lacks
/// are skipped.
pub fn check_faces(cp: &CreasePattern, folded: &[DVec3], faces: &[Face]) -> Developability {
    let mut out = Developability::default();
    for face in faces {
        let ids: Vec<VertexId> = face
            .outer
            .iter()
            .chain(face.holes.iter().flatten())
            .copied()
            .collect();
        if ids.len() < 3
            || ids
                .iter()
                .any(|v| v.index() >= folded.len() || v.index() >= cp.vertices.len())
        {
            continue;
        }
        out.faces += 1;
        let flat: Vec<DVec2> = ids.iter().map(|&v| cp.position(v)).collect();
        let space: Vec<DVec3> = ids.iter().map(|&v| folded[v.index()]).collect();
        let (error, at) = face_error(&flat, &space);
        out.largest_error = out.largest_error.max(error);
        if error > DEVELOPABLE_RELATIVE_TOLERANCE {
            out.findings.push(finding(&flat, ids[at], error));
        }
    }
    out
}

/// The relative error of one face and the index of its worst vertex.
fn face_error(flat: &[DVec2], space: &[DVec3]) -> (f64, usize) {
    let anchors = anchors(flat);
    let diameter = anchors
        .iter()
        .flat_map(|&a| flat.iter().map(move |p| p.distance(flat[a])))
        .fold(0.0, f64::max);
    if diameter <= 0.0 {
        return (0.0, 0);
    }
    let mut worst = (0.0, 0);
    for (i, (p, q)) in flat.iter().zip(space).enumerate() {
        for &a in &anchors {
            let e = (p.distance(flat[a]) - q.distance(space[a])).abs() / diameter;
            if e > worst.0 {
                worst = (e, i);
            }
        }
    }
    worst
}

/// Three vertices spanning the face: the first, the one farthest from it, and the one
/// farthest from the line through those two (fewer when the face is degenerate).
fn anchors(flat: &[DVec2]) -> Vec<usize> {
    let far = |from: &dyn Fn(DVec2) -> f64| {
        (0..flat.len()).max_by(|&i, &j| from(flat[i]).total_cmp(&from(flat[j])))
    };
    let a = 0;
    let Some(b) = far(&|p| p.distance(flat[a])) else {
        return vec![a];
    };
    let dir = flat[b] - flat[a];
    let Some(c) = far(&|p| dir.perp_dot(p - flat[a]).abs()) else {
        return vec![a, b];
    };
    vec![a, b, c]
}

fn finding(flat: &[DVec2], worst: VertexId, error: f64) -> Finding {
    let centre = flat.iter().copied().sum::<DVec2>() / flat.len() as f64;
    Finding {
        kind: FindingKind::Developability,
        vertex: Some(worst),
        edge: None,
        position: centre,
        value: error,
        limit: DEVELOPABLE_RELATIVE_TOLERANCE,
        quantity: Quantity::Ratio,
        mv_counts: None,
        message: format!(
            "the face at {worst} is stretched in the 3D frame: a distance within it changes by \
             {error:.2e} of the face's size (tolerance {DEVELOPABLE_RELATIVE_TOLERANCE:.0e})"
        ),
        hint: "the folded form does not unfold onto this pattern: re-export the 3D frame with \
               the pattern, or check the face's vertices"
            .to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pattern::Assignment;

    /// Two unit squares sharing the edge x = 1.
    fn two_squares() -> (CreasePattern, Vec<Face>) {
        let mut cp = CreasePattern::new();
        let v: Vec<VertexId> = [
            (0.0, 0.0),
            (1.0, 0.0),
            (2.0, 0.0),
            (2.0, 1.0),
            (1.0, 1.0),
            (0.0, 1.0),
        ]
        .into_iter()
        .map(|(x, y)| cp.add_vertex(DVec2::new(x, y)))
        .collect();
        cp.add_edge(v[1], v[4], Assignment::Valley);
        let faces = vec![
            Face::simple(vec![v[0], v[1], v[4], v[5]]),
            Face::simple(vec![v[1], v[2], v[3], v[4]]),
        ];
        (cp, faces)
    }

    #[test]
    fn a_rigid_fold_is_developable_and_a_stretch_is_not() {
        let (cp, faces) = two_squares();
        // Fold the right square up by 90° about x = 1.
        let folded = vec![
            DVec3::new(0.0, 0.0, 0.0),
            DVec3::new(1.0, 0.0, 0.0),
            DVec3::new(1.0, 0.0, 1.0),
            DVec3::new(1.0, 1.0, 1.0),
            DVec3::new(1.0, 1.0, 0.0),
            DVec3::new(0.0, 1.0, 0.0),
        ];
        let ok = check_faces(&cp, &folded, &faces);
        assert_eq!(ok.faces, 2);
        assert!(ok.findings.is_empty(), "{:?}", ok.findings);
        // Lift one corner of the left square off its plane: the face bends, which no fold
        // of a rigid face allows.
        let mut bent = folded.clone();
        bent[0].z = 0.1;
        let bad = check_faces(&cp, &bent, &faces);
        assert_eq!(bad.findings.len(), 1);
        assert_eq!(bad.findings[0].kind, FindingKind::Developability);
        // Lifting a corner by 0.1 changes its distance to a neighbouring corner from 1 to
        // √1.01 (the largest change, more than √2 → √2.01 to the far corner), relative to
        // the face's diameter √2.
        let expected = (1.01f64.sqrt() - 1.0) / 2f64.sqrt();
        assert!(
            (bad.largest_error - expected).abs() < 1e-12,
            "{}",
            bad.largest_error
        );
    }
}
