//! Where a solved (or half-solved) tessellation stands against the fabrication limits of
//! Tachi (2014) §5, per crease and per vertex, for drawing them on the folded form: every
//! crease's fold angle ρ (eq. 3's dihedral, valley positive) against the fold-angle limit and
//! its mountain/valley sign, and every vertex's smallest angle between neighbouring creases
//! (the §5 vertex-angle limit, corners joined across flat diagonals) and its developability
//! defect (eq. 1).

use glam::DVec3;

use crate::design::tessellation::geometry::fold_angle;
use crate::design::tessellation::measure::angle_defects;
use crate::design::tessellation::{Limits, TessMesh};
use crate::pattern::Assignment;

/// One edge of the tessellated surface and its fold.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CreaseState {
    /// End vertices (indices into the surface's positions).
    pub vertices: [u32; 2],
    /// Mountain, valley, flat (a diagonal kept flat) or boundary.
    pub assignment: Assignment,
    /// Fold angle ρ, radians, valley positive (0 on the boundary).
    pub fold: f64,
    /// |ρ| beyond the fold-angle limit.
    pub beyond_limit: bool,
    /// Folded against its assignment (a mountain folding as a valley or the reverse).
    pub wrong_sign: bool,
}

/// One vertex of the tessellated surface.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct VertexState {
    /// Smallest angle between neighbouring creases there, radians.
    pub min_angle: f64,
    /// |2π − Σθ| for an interior vertex, 0 on the boundary, radians.
    pub defect: f64,
    /// `min_angle` under the vertex-angle limit.
    pub under_limit: bool,
    /// `defect` over the developability tolerance.
    pub not_developable: bool,
}

/// The limits at every crease and vertex of a surface.
#[derive(Clone, Debug, PartialEq)]
pub struct LimitMap {
    /// Every edge, in the surface's edge order.
    pub creases: Vec<CreaseState>,
    /// Every vertex, in the surface's vertex order.
    pub vertices: Vec<VertexState>,
}

impl LimitMap {
    /// Creases beyond the fold-angle limit or folded the wrong way.
    pub fn creases_violating(&self) -> usize {
        self.creases
            .iter()
            .filter(|c| c.beyond_limit || c.wrong_sign)
            .count()
    }

    /// Vertices under the vertex-angle limit or not developable.
    pub fn vertices_violating(&self) -> usize {
        self.vertices
            .iter()
            .filter(|v| v.under_limit || v.not_developable)
            .count()
    }
}

/// Measures `mesh` at `x` against `limits`; a vertex counts as developable within `tolerance`
/// radians (the solver's [`SolveOptions::tolerance`](crate::design::tessellation::SolveOptions)).
/// The limits are compared as they are, without the solver's inner margin.
pub fn limit_map(mesh: &TessMesh, x: &[DVec3], limits: &Limits, tolerance: f64) -> LimitMap {
    let creases = mesh
        .edges
        .iter()
        .map(|e| {
            let fold = if e.interior {
                let [i, j, a, b] = mesh.hinge(e).map(|v| x[v as usize]);
                fold_angle(i, j, a, b).value
            } else {
                0.0
            };
            let sign = match e.assignment {
                Assignment::Valley => 1.0,
                Assignment::Mountain => -1.0,
                _ => 0.0,
            };
            CreaseState {
                vertices: e.vertices,
                assignment: e.assignment,
                fold,
                beyond_limit: fold.abs() > limits.max_fold,
                wrong_sign: sign * fold < 0.0,
            }
        })
        .collect();
    let mut min_angle = vec![f64::INFINITY; x.len()];
    let angles = mesh.sectors.angles(mesh, x);
    for (t, tri) in mesh.triangles.iter().enumerate() {
        for (k, &v) in tri.iter().enumerate() {
            let sector = mesh.sectors.of_corner[3 * t + k] as usize;
            min_angle[v as usize] = min_angle[v as usize].min(angles[sector]);
        }
    }
    let vertices = angle_defects(mesh, x)
        .iter()
        .zip(min_angle)
        .map(|(&d, min_angle)| VertexState {
            min_angle,
            defect: d.abs(),
            under_limit: min_angle < limits.min_vertex_angle,
            not_developable: d.abs() > tolerance,
        })
        .collect();
    LimitMap { creases, vertices }
}
