//! The whole design in one call: mesh → star tucks → solve → unfold → face-intersection check.

use super::constraints::{Limits, assign_folds};
use super::fit::{FitOptions, FitReport, Target, fit_surface};
use super::intersect::intersecting_triangles;
use super::solver::{Iteration, SolveOptions, SolveReport, solve};
use super::star::{InitialPattern, StarOptions, star_tucks};
use super::unfold::{Unfolded, unfold};
use super::{TessError, TessMesh};
use crate::mesh::{HalfEdgeMesh, PolyMesh};

/// Everything [`tessellate`] needs besides the mesh.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TessellateOptions {
    /// Initial pattern (§2.1).
    pub star: StarOptions,
    /// Solver settings and fabrication limits (§3.3, §5).
    pub solve: SolveOptions,
    /// Ground contact (§6): put every boundary vertex on the horizontal plane through the
    /// lowest boundary vertex of the initial pattern (overrides `solve.limits.ground_z`).
    pub ground: bool,
    /// Surface fit (§3.4) after a converged solve, towards the initial face corners.
    pub fit: Option<FitOptions>,
    /// Faces of the folded form crossing each other by less than this (mm) only touch.
    pub intersection_tolerance: f64,
}

impl Default for TessellateOptions {
    fn default() -> Self {
        TessellateOptions {
            star: StarOptions::default(),
            solve: SolveOptions::default(),
            ground: false,
            fit: None,
            intersection_tolerance: 1e-3,
        }
    }
}

impl TessellateOptions {
    /// Default options with the given fabrication limits.
    pub fn with_limits(limits: Limits) -> Self {
        let mut o = TessellateOptions::default();
        o.solve.limits = limits;
        o
    }
}

/// A finished tessellation.
#[derive(Clone, Debug)]
pub struct Tessellation {
    /// The initial pattern before solving (its mesh holds the initial positions).
    pub initial: InitialPattern,
    /// The solved surface.
    pub mesh: TessMesh,
    /// How the solve went.
    pub report: SolveReport,
    /// How the surface fit went, when requested and the solve converged.
    pub fit: Option<FitReport>,
    /// The unfolded pattern and its folded state; `Err` when the flat pattern overlaps.
    pub unfolded: Result<Unfolded, TessError>,
    /// Pairs of triangles of the solved surface (the folded state's faces, same indices)
    /// that pass through each other, see [`intersect`](super::intersect).
    pub intersections: Vec<(usize, usize)>,
    /// The tolerance they were found with, mm.
    pub intersection_tolerance: f64,
}

impl Tessellation {
    /// The solver's summary with the face-intersection count of the folded form.
    pub fn summary(&self) -> String {
        let found = match self.intersections.first() {
            None => "none".to_string(),
            Some((a, b)) => format!(
                "{} pairs (first: triangles {a} and {b})",
                self.intersections.len()
            ),
        };
        format!(
            "{}\n  face intersections (folded form, tolerance {:.0e} mm): {found}",
            self.report.summary(),
            self.intersection_tolerance
        )
    }
}

/// Checks that `mesh` is an oriented manifold disk: connected, one boundary, Euler
/// characteristic 1.
pub fn disk(mesh: &PolyMesh) -> Result<HalfEdgeMesh, TessError> {
    let (lo, hi) = mesh.bounds();
    let scale = (hi - lo).max_element().max(f64::MIN_POSITIVE);
    let he = HalfEdgeMesh::new(mesh, 1e-12 * scale * scale)?;
    let used = (0..mesh.positions().len())
        .filter(|&v| !he.fan(v).is_empty())
        .count();
    let hes = he.half_edges();
    let edges = hes
        .iter()
        .filter(|h| h.twin.is_none() || h.from < h.to)
        .count();
    let euler = used as i64 - edges as i64 + mesh.faces().len() as i64;
    let mut seen = vec![false; mesh.faces().len()];
    let mut stack = vec![0usize];
    seen[0] = true;
    while let Some(f) = stack.pop() {
        for h in he.face_half_edges(f) {
            if let Some(t) = hes[h as usize].twin {
                let g = hes[t as usize].face as usize;
                if !seen[g] {
                    seen[g] = true;
                    stack.push(g);
                }
            }
        }
    }
    if seen.iter().any(|s| !s) {
        return Err(TessError::NotADisk(
            "the faces form more than one piece".into(),
        ));
    }
    if euler != 1 {
        return Err(TessError::NotADisk(format!(
            "Euler characteristic {euler} (a closed surface is 2, an annulus 0): cut it open"
        )));
    }
    Ok(he)
}

/// Tessellates `mesh`: star tucks (§2.1), mountain/valley by role, the solve (§3.3) with
/// `progress` called per iteration, the unfolding and the face-intersection check.
pub fn tessellate(
    mesh: &PolyMesh,
    opts: &TessellateOptions,
    progress: impl FnMut(&Iteration),
) -> Result<Tessellation, TessError> {
    let he = disk(mesh)?;
    let mut initial = star_tucks(&he, &opts.star)?;
    assign_folds(&mut initial.mesh);
    let mut solved = initial.mesh.clone();
    let mut solve_opts = opts.solve;
    if opts.ground {
        solve_opts.limits.ground_z = solved
            .positions
            .iter()
            .zip(&solved.interior)
            .filter(|(_, inside)| !**inside)
            .map(|(p, _)| p.z)
            .reduce(f64::min);
    }
    let report = solve(&mut solved, &solve_opts, progress)?;
    let fit = match opts.fit {
        Some(fit) if report.converged => {
            let targets = corner_targets(&initial.mesh, &he);
            Some(fit_surface(&mut solved, &targets, &fit, &solve_opts)?)
        }
        _ => None,
    };
    let unfolded = unfold(&solved);
    let intersections = intersecting_triangles(
        &solved.positions,
        &solved.triangles,
        opts.intersection_tolerance,
    )?;
    Ok(Tessellation {
        initial,
        mesh: solved,
        report,
        fit,
        unfolded,
        intersections,
        intersection_tolerance: opts.intersection_tolerance,
    })
}

/// Every face corner of the initial pattern, at its initial place, with its input vertex's
/// normal (key vertices get no target).
fn corner_targets(initial: &TessMesh, he: &HalfEdgeMesh) -> Vec<Target> {
    (0..initial.positions.len())
        .filter_map(|v| {
            let input = initial.input_vertex[v] as usize;
            (initial.key_of_input[input] != Some(v as u32)).then(|| Target {
                vertex: v as u32,
                point: initial.positions[v],
                normal: he.vertex_normal(input),
            })
        })
        .collect()
}
