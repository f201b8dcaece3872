//! Random planar patterns for the SVG round-trip property test.

use foldcam::pattern::{Assignment, CreasePattern, VertexId};
use glam::DVec2;
use proptest::prelude::*;

/// A random planar pattern: a grid of `nx × ny` cells of random size, offset from the origin,
/// with a random assignment and fold angle per grid edge and an optional diagonal per cell.
#[derive(Debug, Clone)]
pub struct GridSpec {
    nx: usize,
    ny: usize,
    cell: DVec2,
    origin: DVec2,
    edges: Vec<(u8, Option<f64>)>,
    diagonals: Vec<u8>,
}

/// The assignments the SVG palette keeps (join has no colour of its own).
const ROUND_TRIP_ASSIGNMENTS: [Assignment; 6] = [
    Assignment::Boundary,
    Assignment::Mountain,
    Assignment::Valley,
    Assignment::Flat,
    Assignment::Unassigned,
    Assignment::Cut,
];

/// Grids of 1–4 × 1–4 cells, 0.5–200 mm wide, anywhere within ±1000 mm.
pub fn grid_spec() -> impl Strategy<Value = GridSpec> {
    (
        1usize..5,
        1usize..5,
        0.5f64..200.0,
        0.3f64..3.0,
        -1000.0f64..1000.0,
        -1000.0f64..1000.0,
    )
        .prop_flat_map(|(nx, ny, w, aspect, ox, oy)| {
            let grid_edges = nx * (ny + 1) + ny * (nx + 1) + nx * ny;
            let angle = prop_oneof![Just(None), (0.0f64..=180.0).prop_map(Some)];
            (
                proptest::collection::vec((0u8..6, angle), grid_edges),
                proptest::collection::vec(0u8..3, nx * ny),
            )
                .prop_map(move |(edges, diagonals)| GridSpec {
                    nx,
                    ny,
                    cell: DVec2::new(w, w * aspect),
                    origin: DVec2::new(ox, oy),
                    edges,
                    diagonals,
                })
        })
}

/// The pattern a spec describes, vertices shared between neighbouring edges.
pub fn build(spec: &GridSpec) -> CreasePattern {
    let mut cp = CreasePattern::new();
    let id = |i: usize, j: usize| VertexId::new(j * (spec.nx + 1) + i);
    for j in 0..=spec.ny {
        for i in 0..=spec.nx {
            cp.add_vertex(spec.origin + spec.cell * DVec2::new(i as f64, j as f64));
        }
    }
    let mut pairs = Vec::new();
    for j in 0..=spec.ny {
        for i in 0..spec.nx {
            pairs.push((id(i, j), id(i + 1, j)));
        }
    }
    for i in 0..=spec.nx {
        for j in 0..spec.ny {
            pairs.push((id(i, j), id(i, j + 1)));
        }
    }
    for (k, &d) in spec.diagonals.iter().enumerate() {
        let (i, j) = (k % spec.nx, k / spec.nx);
        match d {
            1 => pairs.push((id(i, j), id(i + 1, j + 1))),
            2 => pairs.push((id(i + 1, j), id(i, j + 1))),
            _ => {}
        }
    }
    for (&(a, b), &(kind, magnitude)) in pairs.iter().zip(&spec.edges) {
        let assignment = ROUND_TRIP_ASSIGNMENTS[kind as usize];
        let e = cp.add_edge(a, b, assignment);
        cp.edges[e.index()].fold_angle = match assignment {
            Assignment::Mountain => magnitude.map(|m| -m),
            Assignment::Valley => magnitude,
            Assignment::Flat => Some(0.0),
            _ => None,
        };
    }
    cp
}
