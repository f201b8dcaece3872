//! The bundled face mask (`examples/tessellation/mask.obj`, foldcam's own procedural model, a
//! realistic open surface like the mask of Tachi 2014): the file is the model, and star tucks
//! solve it within the 0.5 mm stainless limits, with a pattern that unfolds isometrically, a folded form clear of itself near the input
//! surface, and a clean cut on the fiber laser through the simulated machine.

use crate::cuts_clean;
use crate::support::tessellation_checks as checks;

use checks::*;
use cuts_clean::assert_cuts_clean_with;
use foldcam::design::tessellation::{measure::*, samples::*, steps::*, *};
use foldcam::mesh::HalfEdgeMesh;

/// The shipped file is `face_mask(8)` (384 faces, every interior vertex of valence 6), says
/// whose work it is, and is a disk with one boundary.
#[test]
fn mask_obj_is_the_procedural_model() {
    let text = std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/tessellation/mask.obj"),
    )
    .expect("mask.obj");
    assert!(text.lines().next().unwrap().contains("foldcam's own"));
    let file = example("mask");
    let model = face_mask(8);
    assert_eq!(file.faces().len(), 6 * 8 * 8);
    assert_eq!(file.faces().len(), model.faces().len());
    assert_eq!(file.positions().len(), model.positions().len());
    // The reader numbers vertices by first use and keeps single precision (about 1e-5 mm
    // here): compare the faces corner by corner, by position.
    for (f, g) in file.faces().iter().zip(model.faces()) {
        assert_eq!(f.len(), g.len());
        for (&a, &b) in f.iter().zip(g) {
            let (p, q) = (file.positions()[a as usize], model.positions()[b as usize]);
            assert!(p.distance(q) < 1e-4, "{p} vs {q}");
        }
    }
    let he = HalfEdgeMesh::new(&file, 1e-9).expect("manifold");
    disk(&file).expect("a disk");
    // An elliptic outline of 150 × 190 mm; the nose tip is the highest point, in front.
    let (lo, hi) = file.bounds();
    assert!(((hi.x - lo.x) - 2.0 * MASK_SIZE_MM[0]).abs() < 1e-4);
    assert!(((hi.y - lo.y) - 2.0 * MASK_SIZE_MM[1]).abs() < 1e-4);
    let top = file
        .positions()
        .iter()
        .max_by(|a, b| a.z.total_cmp(&b.z))
        .unwrap();
    assert!(top.x.abs() < 1e-4 && top.y < 0.0, "{top}");
    for v in 0..file.positions().len() {
        if !he.is_boundary(v) {
            assert_eq!(he.fan(v).len(), 6, "vertex {v}");
        }
    }
}

/// Star tucks at shrink 0.6, where `foldcam tessellate`'s default schedule arrives (0.8 and
/// 0.7 leave limits unmet; the two failing solves are left out to keep this test short), at
/// the stainless limits: every condition re-measured on the result, the unfolded pattern
/// checked, the folded form's face corners near the input surface, and the pattern cut clean
/// on the fiber laser.
#[test]
fn mask_solves_within_stainless_limits_and_cuts_clean() {
    let mesh = example("mask");
    let limits = stainless_limits();
    let mut opts = TessellateOptions::with_limits(limits);
    opts.star.shrink = 0.6;
    let t = tessellate(&mesh, &opts, &mut ()).unwrap();
    let r = &t.report;
    eprintln!("mask: shrink {}, {}", t.initial.shrink, t.summary());
    assert!(t.problem().is_none(), "{:?}", t.problem());
    assert!(r.converged);
    assert!(r.last.max_fold <= limits.max_fold);
    assert!(r.last.min_vertex_angle >= limits.min_vertex_angle);
    // A crease may touch its neighbour (contact within the solver's penalty tolerance, about
    // 1e-6 rad) but not pass through it: re-measured on the result.
    let again = residuals(&t.mesh, &t.mesh.positions, None);
    eprintln!(
        "mask: {} creases in contact, largest penalty {:e}",
        again.illegal_creases, again.max_penalty
    );
    assert!(again.max_penalty <= PENALTY_TOLERANCE);
    for (v, d) in angle_defects(&t.mesh, &t.mesh.positions).iter().enumerate() {
        assert!(d.abs() < 1e-9, "vertex {v} defect {d:e}");
    }
    for e in t.mesh.edges.iter().filter(|e| e.interior) {
        let [i, j, a, b] = t.mesh.hinge(e).map(|v| t.mesh.positions[v as usize]);
        let rho = fold_angle(i, j, a, b).value;
        assert!(rho.abs() <= limits.max_fold + 1e-9, "{}", rho.to_degrees());
    }
    check_unfolded("mask", &t);
    // The tucks sit behind the surface; the face corners stay within a few edge lengths'
    // tuck depth of it (edges are about 10 mm here).
    let d = corner_distance(&mesh, &t.mesh).expect("a surface");
    eprintln!(
        "mask: face corners {:.2} mm max, {:.2} mm mean from the input",
        d.max, d.mean
    );
    assert!(d.mean < 5.0 && d.max < 20.0, "{d:?}");
    let cp = &t.unfolded.as_ref().expect("unfolds").pattern;
    // Some creases between the tucks are under 3.5 mm: a 0.5 mm dash fits between vertex
    // clearances of 0.8 mm, not the material's 1.5 mm (the planner would leave them uncut
    // with a warning, which this test counts as a failure).
    let overrides = foldcam::fab::PlanOverrides {
        vertex_clearance_mm: Some(0.8),
        ..Default::default()
    };
    assert_cuts_clean_with("mask", cp, "linuxcnc-fiber", "stainless-0.5", &overrides);
}
