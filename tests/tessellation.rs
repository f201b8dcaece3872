//! Freeform origami tessellations (seed 002): initial star-tuck patterns on the regular
//! tilings of Fig. 5, the solver on the example surfaces, unfolding and fabrication.

#[path = "tessellation/support.rs"]
mod support;

use foldcam::design::tessellation::*;
use foldcam::mesh::{HalfEdgeMesh, PolyMesh};
use std::f64::consts::PI;
use support::*;

fn half_edges(m: &PolyMesh) -> HalfEdgeMesh {
    HalfEdgeMesh::new(m, 1e-12).expect("manifold")
}

#[test]
fn try_solve() {
    for surf in [
        SampleSurface::Dome,
        SampleSurface::Saddle,
        SampleSurface::Bell,
    ] {
        for layout in [TuckLayout::Checkerboard, TuckLayout::Digon] {
            let m = sample_surface(surf, 3, 20.0);
            let mut o = TessellateOptions::default();
            o.star.layout = layout;
            let t = tessellate(&m, &o, |it| {
                eprintln!(
                    "  {} {:.3e} fold {:.1} theta {:.1} act {:?} step {} cg {}",
                    it.index,
                    it.residuals.developability,
                    it.residuals.max_fold.to_degrees(),
                    it.residuals.min_vertex_angle.to_degrees(),
                    it.active,
                    it.step,
                    it.cg_iterations
                )
            })
            .unwrap();
            eprintln!(
                "{surf:?} {layout:?}\n{}\n unfold {:?}",
                t.report.summary(),
                t.unfolded.as_ref().map(|u| u.max_length_error)
            );
        }
    }
    let _ = (
        PI,
        half_edges(&square_tiling(1, 1, 1.0)),
        triangle_tiling(1, 1, 1.0),
        hexagon_tiling(1, 1, 1.0),
    );
}
