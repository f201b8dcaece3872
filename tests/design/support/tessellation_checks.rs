//! Checks shared by the tessellation tests: the example meshes, the stainless limits, and
//! everything the issue asks of an unfolded result.

use std::path::PathBuf;

use foldcam::design::tessellation::{steps::*, *};
use foldcam::machine::load_material;
use foldcam::mesh::{PolyMesh, read_mesh};
use foldcam::pattern::Assignment;

/// The bundled example mesh `examples/tessellation/{name}.obj`.
pub fn example(name: &str) -> PolyMesh {
    let path =
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join(format!("examples/tessellation/{name}.obj"));
    read_mesh(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// The design limits of the shipped 0.5 mm stainless material (165°, 30°).
pub fn stainless_limits() -> Limits {
    let m = load_material("stainless-0.5").expect("shipped material");
    Limits::from_degrees(m.limits.max_fold_angle_deg, m.limits.min_vertex_angle_deg)
}

/// How many edges of `mesh` have `role`.
pub fn edges_with_role(mesh: &TessMesh, role: EdgeRole) -> usize {
    mesh.edges.iter().filter(|e| e.role == role).count()
}

/// The unfolded pattern of `t`: valid, no overlaps (the union of its triangles is as large as
/// their areas added up), edge
/// lengths equal to the folded form's within 1e-9 relative, no face of the folded form through
/// another, and every fold of its assigned sign within 165°.
pub fn check_unfolded(name: &str, t: &Tessellation) {
    check_unfolded_within(name, t, 1e-6);
}

/// [`check_unfolded`] with faces of the folded form touching within `contact` mm counted as
/// touching, not crossing.
pub fn check_unfolded_within(name: &str, t: &Tessellation, contact: f64) {
    let u = t
        .unfolded
        .as_ref()
        .unwrap_or_else(|e| panic!("{name}: {e}"));
    let cp = &u.pattern;
    cp.validate().expect("valid pattern");
    assert!(u.max_length_error < 1e-9, "{name}: {}", u.max_length_error);
    let faces = cp.faces.as_ref().expect("faces");
    assert_eq!(Some(faces), u.folded.faces.as_ref());
    // The folded form has no intersecting faces (the callers' tolerance: 1 nm by default).
    let crossing = folded_intersections(&u.folded, contact).expect("triangles");
    assert!(crossing.is_empty(), "{name}: {crossing:?}");
    assert_eq!(cp.edges, u.folded.edges);
    for e in &cp.edges {
        let [a, b] = e.vertices;
        let l2 = cp.position(a).distance(cp.position(b));
        let l3 = u.folded.positions[a.index()].distance(u.folded.positions[b.index()]);
        assert!((l2 - l3).abs() <= 1e-9 * l3, "{name}: {l2} vs {l3}");
    }
    let mut triangles = Vec::with_capacity(faces.len());
    for f in faces {
        let [p, q, r] = [0, 1, 2].map(|k| cp.position(f.outer[k]));
        assert!((q - p).perp_dot(r - p) > 0.0, "{name}: a flipped face");
        triangles.push(vec![p, q, r]);
    }
    // No two triangles of the sheet overlap: their union (by i_overlay, independent of the
    // unfolder) is as large as their areas added up.
    let overlap = crate::overlap::overlap_area(&triangles);
    let area = crate::overlap::area_sum(&triangles);
    assert!(
        overlap < 1e-7 * area,
        "{name}: {overlap:.3e} mm² of the sheet is covered twice"
    );
    let folds = cp.edges.iter().filter(|e| e.assignment.is_fold()).count();
    assert!(folds > 100, "{name}: {folds} folds");
    for e in cp.edges.iter().filter(|e| e.assignment.is_fold()) {
        let angle = e.fold_angle.expect("target angle");
        let sign = if e.assignment == Assignment::Valley {
            1.0
        } else {
            -1.0
        };
        assert!(
            angle * sign > 0.0 && angle.abs() <= 165.0,
            "{name}: {angle}"
        );
    }
}
