//! Faces for every FOLD file written: Origami Simulator's importer refuses a FOLD file without
//! `faces_vertices` (it needs `vertices_coords`, `edges_vertices`, `edges_assignment` and
//! `faces_vertices`), and viewers such as Rabbit Ear draw faces from it.
//!
//! A pattern that has faces is written as it is. One without faces gets them traced from its
//! planar graph ([`crate::pattern::faces`]) when it is already planar; a drawing that is not
//! (crossing lines, vertices on edges) is planarised first, with planarisation's default
//! tolerance, and that clean copy is what is written. A pattern written with a folded state
//! is never renumbered (the state's vertices must keep matching); it gets faces only when it
//! is planar as it stands.
//!
//! Traced faces whose every side is a boundary or cut edge shared with another face are holes
//! in the sheet (a window cut out of a card, the centre of a circular pleat), not paper, and
//! are left out, as Origami Simulator's importer removes them: a boundary edge then borders
//! exactly one face.

use std::borrow::Cow;
use std::collections::HashMap;

use crate::pattern::faces::find_faces;
use crate::pattern::{Assignment, CreasePattern, Face, PlanarizeOptions, VertexId, planarize};

/// The pattern to write: `cp` itself when it has faces, else a copy with faces (planarised
/// when needed and `renumber` allows it). A pattern that fails validation is returned as it
/// is (the writer still writes what it holds).
pub fn with_faces(cp: &CreasePattern, renumber: bool) -> Cow<'_, CreasePattern> {
    if cp.faces.is_some() || cp.edges.is_empty() || cp.validate().is_err() {
        return Cow::Borrowed(cp);
    }
    let mut clean = cp.clone();
    let options = PlanarizeOptions {
        tolerance: None,
        faces: true,
    };
    let Ok(report) = planarize(&mut clean, &options) else {
        return Cow::Borrowed(cp);
    };
    let planar = report.merged_vertices
        + report.splits
        + report.zero_length_removed
        + report.duplicates_removed
        == 0;
    if planar {
        // Isolated vertices aside, the graph is planar as it stands: trace its faces without
        // renumbering anything.
        let mut same = cp.clone();
        same.faces = Some(without_holes(cp, find_faces(cp).faces));
        Cow::Owned(same)
    } else if renumber {
        let faces = clean.faces.take().unwrap_or_default();
        clean.faces = Some(without_holes(&clean, faces));
        Cow::Owned(clean)
    } else {
        Cow::Borrowed(cp)
    }
}

/// The faces less the holes: faces whose every side is a boundary or cut edge that another
/// face also has.
fn without_holes(cp: &CreasePattern, faces: Vec<Face>) -> Vec<Face> {
    let key = |a: VertexId, b: VertexId| (a.0.min(b.0), a.0.max(b.0));
    let assignment: HashMap<(u32, u32), Assignment> = cp
        .edges
        .iter()
        .map(|e| (key(e.vertices[0], e.vertices[1]), e.assignment))
        .collect();
    let sides = |f: &Face| {
        let n = f.outer.len();
        (0..n)
            .map(|i| key(f.outer[i], f.outer[(i + 1) % n]))
            .collect::<Vec<_>>()
    };
    let mut uses: HashMap<(u32, u32), usize> = HashMap::new();
    for f in &faces {
        for s in sides(f) {
            *uses.entry(s).or_default() += 1;
        }
    }
    let is_hole = |f: &Face| {
        sides(f).iter().all(|s| {
            matches!(
                assignment.get(s),
                Some(Assignment::Boundary | Assignment::Cut)
            ) && uses.get(s).copied().unwrap_or(0) > 1
        })
    };
    faces.into_iter().filter(|f| !is_hole(f)).collect()
}
