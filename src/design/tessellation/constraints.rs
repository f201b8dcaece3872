//! The constraint rows g(X) = 0 of Tachi (2014) §3 with their sparse analytic Jacobian rows (eq. 8).
//!
//! - developability of every interior vertex, eq. 1: `g_v = 2π − Σ θ_{v,i}`;
//! - fold-angle range and limit, eq. 3 with §5's `ρ_limit = 180° − δ_fold`: with σ = +1 for a
//!   valley and −1 for a mountain and ρ' = σρ, a fold beyond the limit gets
//!   `f = 2 (sin(ρ'/2) − sin(ρ_target/2)) h_p h_q` and a fold of the wrong sign gets
//!   `f = 2 (sin(ρ'/2) − sin(m/2)) h_p h_q` (eq. 4: h are relative heights, Fig. 7); a crease
//!   left free to fold either way (the twist folds, see [`assign_folds`]) gets the limit row
//!   only;
//! - vertex angles, §5: every angle θ between neighbouring creases ≥ δ_corner (a triangle
//!   corner, or corners summed across flat diagonals: [`Sectors`](super::sectors::Sectors)), `θ − (δ_corner + m)` when
//!   violated;
//! - flat diagonals (polygon faces, the n-gon of a truncated star) stay flat: eq. 3 with
//!   ρ_limit = 0 as an equality;
//! - vertex-adjacent faces, eq. 5–7: a crease passing through a face that shares only its
//!   vertex gets the penalty row `√f_o = 0` (see [`vertex_penalty`]; the root is a deviation
//!   that keeps Newton's convergence quadratic near contact).
//!
//! Inequalities are handled as the paper handles eq. 2: a violated one becomes an equality for
//! that step (an active set). Deviation: each inequality targets a small margin m inside its
//! limit ([`Limits::margin`]) and stays active within half the margin of it
//! ([`Limits::hold`]), so the solver does not chatter on the limit and the result satisfies
//! the limit strictly. That makes the merit jump where a row enters the set; the solver steps
//! with `hold = 1` (continuous entry) when no step descends otherwise.

use std::f64::consts::PI;

use glam::DVec3;

use super::boundary;
use super::collision;
use super::geometry::{corner_angle, fold_angle, relative_height};
use super::model::{EdgeRole, TessEdge, TessMesh};
use super::vertex_penalty;
use crate::pattern::Assignment;

/// The fabrication limits of §5, in radians.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Limits {
    /// ρ_limit = 180° − δ_fold: the largest fold angle magnitude.
    pub max_fold: f64,
    /// δ_corner: the smallest corner angle of any triangle.
    pub min_vertex_angle: f64,
    /// Margin m kept inside each limit by the active rows.
    pub margin: f64,
    /// An inequality enters the active set within `hold · m` of its limit and is then pushed
    /// to `m` inside it; in (0, 1], 1 makes the row values continuous (default 0.5).
    pub hold: f64,
    /// Ground contact (§6's design example): when set, every boundary vertex lies on the
    /// horizontal plane at this z (mesh units), one equality row per vertex.
    pub ground_z: Option<f64>,
    /// Whether the vertex-adjacent penalty rows (eq. 5–7) are active (the paper: always).
    pub vertex_penalty: bool,
    /// Collision rows ([`collision`]; beyond the paper, which leaves these to the user's
    /// eye): a face vertex crossing a face it shares no vertex with, or coming closer to it
    /// than `hold ·` this distance (mesh units, mm), is pushed to this distance in front of
    /// it; 0 (the default) turns the rows off. Experimental: the rows do not enter the
    /// convergence test, and on the spherical caps measured they stall the solve (see
    /// [`collision`]).
    pub collision_gap: f64,
    /// Which violated boundary runs of eq. 2 become rows (see [`super::boundary`]).
    pub boundary_runs: BoundaryRuns,
}

/// Which violated runs of the boundary condition (Tachi 2014, eq. 2) become equality rows.
/// The two forms reach the same condition by different paths, and so different folded forms:
/// measured with truncated stars at the 0.5 mm stainless limits, shrink 0.45, on the spherical
/// cap `spherical_cap(12, R, 60°, 100 mm)` re-triangulated:
///
/// | cap | rows | iterations | time | intersecting face pairs |
/// |---|---|---|---|---|
/// | 2,022 faces | dominant | 31–33 | 2.0–2.3 s | 231 |
/// | 2,022 faces | every start | 59 | 5.8–6.4 s | 585 |
/// | 10,086 faces | dominant | 68–71 | 56–80 s | 13,115–13,229 |
/// | 10,086 faces | every start | 95–109 | 116–150 s | 4,407–5,766 |
/// | 450 faces (shrink 0.5) | dominant | 16 | 0.5 s | 90 |
/// | 450 faces (shrink 0.5) | every start | 16 | 0.2 s | 0 |
///
/// So neither dominates; a [`Schedule::Ladder`](super::Schedule::Ladder) tries the
/// dominant rows first and every start's row when the folded form intersects itself.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum BoundaryRuns {
    /// Of the runs ending at the same vertex only the most violated one (it implies the
    /// others at the current point): few rows, fast steps (the default).
    #[default]
    Dominant,
    /// Every start vertex's worst run: the others too, which as equalities also hold the
    /// turning between their starts at zero (a stiffer outline; many long rows, slow on large
    /// meshes).
    EveryStart,
}

impl Limits {
    /// Limits from degrees (a material's `max_fold_angle_deg`, `min_vertex_angle_deg`).
    pub fn from_degrees(max_fold_deg: f64, min_vertex_angle_deg: f64) -> Self {
        Limits {
            max_fold: max_fold_deg.to_radians(),
            min_vertex_angle: min_vertex_angle_deg.to_radians(),
            margin: 0.25f64.to_radians(),
            hold: 0.5,
            ground_z: None,
            vertex_penalty: true,
            collision_gap: 0.0,
            boundary_runs: BoundaryRuns::Dominant,
        }
    }
}

impl Default for Limits {
    /// The paper's example: δ_fold = 15° (ρ_limit = 165°), δ_corner = 30°.
    fn default() -> Self {
        Limits::from_degrees(165.0, 30.0)
    }
}

/// Which condition a row expresses.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Family {
    /// Eq. 1 at an interior vertex.
    Developability,
    /// Eq. 3: a fold beyond ρ_limit.
    FoldLimit,
    /// Eq. 3 with limit 0: a fold of the wrong sign for its assignment.
    FoldSign,
    /// §5: a corner angle under δ_corner.
    VertexAngle,
    /// §6: a boundary vertex off the ground plane.
    Ground,
    /// Eq. 2: a run of the boundary turning back by more than half a turn.
    Boundary,
    /// Eq. 5–7: a crease through a face that shares only its vertex.
    VertexPenalty,
    /// A flat diagonal (of a polygon face or a truncated star's n-gon) kept flat: eq. 3's
    /// form with ρ_limit = 0 as an equality.
    Flat,
    /// A vertex crossing or approaching a face it shares no vertex with ([`collision`]).
    Collision,
}

/// One constraint: its value and its Jacobian row as (vertex, ∂/∂x) blocks.
#[derive(Clone, Debug)]
pub struct Row {
    /// What it expresses.
    pub family: Family,
    /// g_r(X).
    pub value: f64,
    /// Non-zero blocks of ∂g_r/∂X.
    pub entries: Vec<(u32, DVec3)>,
}

fn add(entries: &mut Vec<(u32, DVec3)>, v: u32, g: DVec3) {
    match entries.iter_mut().find(|(w, _)| *w == v) {
        Some((_, acc)) => *acc += g,
        None => entries.push((v, g)),
    }
}

/// Mountain/valley of every interior crease by its role in the star tuck, seen from the front
/// (the side the input faces' normals point to, with the key vertices behind): face rims,
/// digons and key-to-corner creases are mountains, key-to-tip creases valleys, diagonals of
/// polygon faces flat. These are the signs of the half-open initial pattern (s < 1), where the
/// closed tucks of s = 1 leave them undecided (±180°). The n-gon rims of the §2.2 variations
/// take the sign of their fold in the initial pattern (`mesh.positions`), a valley when it is
/// exactly flat. Twist folds stay [`Assignment::Unassigned`]: the twist is a free parameter
/// that changes during the solve (Tachi 2014, §2.2), so the solver bounds only their fold
/// magnitude and [`assign_free_folds`] reads their direction off the solved form.
pub fn assign_folds(mesh: &mut TessMesh) {
    for k in 0..mesh.edges.len() {
        let e = &mesh.edges[k];
        if !e.interior {
            continue;
        }
        let assignment = match e.role {
            EdgeRole::Diagonal => Assignment::Flat,
            EdgeRole::KeyTip => Assignment::Valley,
            EdgeRole::FaceRim | EdgeRole::Digon | EdgeRole::KeyCorner => Assignment::Mountain,
            EdgeRole::TwistFold => Assignment::Unassigned,
            EdgeRole::TruncationRim => folds_now(mesh, e),
            EdgeRole::Boundary => Assignment::Boundary,
        };
        mesh.edges[k].assignment = assignment;
    }
}

/// Mountain or valley, by the sign of its fold at `mesh.positions` (a valley when exactly
/// flat), for every interior crease the solve left free ([`Assignment::Unassigned`]: the twist
/// folds, see [`assign_folds`]). Call after solving, before unfolding.
pub fn assign_free_folds(mesh: &mut TessMesh) {
    for k in 0..mesh.edges.len() {
        let e = &mesh.edges[k];
        if !e.interior || e.assignment != Assignment::Unassigned {
            continue;
        }
        mesh.edges[k].assignment = folds_now(mesh, e);
    }
}

/// Valley or mountain by the sign of the crease's fold at `mesh.positions` (a valley when
/// exactly flat).
fn folds_now(mesh: &TessMesh, e: &TessEdge) -> Assignment {
    let [i, j, a, b] = mesh.hinge(e).map(|v| mesh.positions[v as usize]);
    if fold_angle(i, j, a, b).value >= 0.0 {
        Assignment::Valley
    } else {
        Assignment::Mountain
    }
}

/// Angle sums' defects g_v (eq. 1) of every interior vertex, radians (0 elsewhere).
pub fn angle_defects(mesh: &TessMesh, x: &[DVec3]) -> Vec<f64> {
    angle_sums(mesh, x)
        .iter()
        .zip(&mesh.interior)
        .map(|(s, &inside)| if inside { 2.0 * PI - s } else { 0.0 })
        .collect()
}

/// Sum of the triangle corner angles at every vertex, radians.
pub fn angle_sums(mesh: &TessMesh, x: &[DVec3]) -> Vec<f64> {
    let mut sums = vec![0.0; x.len()];
    for t in &mesh.triangles {
        for k in 0..3 {
            let (o, a, b) = (t[k], t[(k + 1) % 3], t[(k + 2) % 3]);
            sums[o as usize] += corner_angle(x[o as usize], x[a as usize], x[b as usize]).value;
        }
    }
    sums
}

/// All rows at `x`: every developability row and the active inequality rows.
pub fn rows(mesh: &TessMesh, x: &[DVec3], limits: &Limits) -> Vec<Row> {
    let mut dev: Vec<Option<Row>> = mesh
        .interior
        .iter()
        .map(|&inside| {
            inside.then(|| Row {
                family: Family::Developability,
                value: 2.0 * PI,
                entries: Vec::new(),
            })
        })
        .collect();
    let mut out = Vec::new();
    let mut boundary_angles = boundary::AngleSums::new();
    let floor = limits.min_vertex_angle + limits.margin;
    let sectors = &mesh.sectors;
    let mut sector_angle = vec![0.0; sectors.count];
    for (t, tri) in mesh.triangles.iter().enumerate() {
        for k in 0..3 {
            let idx = [tri[k], tri[(k + 1) % 3], tri[(k + 2) % 3]];
            let [o, a, b] = idx.map(|v| x[v as usize]);
            let th = corner_angle(o, a, b);
            sector_angle[sectors.of_corner[3 * t + k] as usize] += th.value;
            if let Some(row) = dev[idx[0] as usize].as_mut() {
                row.value -= th.value;
                for (v, g) in idx.iter().zip(th.grad) {
                    add(&mut row.entries, *v, -g);
                }
            } else {
                let sum = boundary_angles.entry(idx[0]).or_default();
                sum.0 += th.value;
                for (v, g) in idx.iter().zip(th.grad) {
                    add(&mut sum.1, *v, g);
                }
            }
        }
    }
    out.extend(vertex_angle_rows(mesh, x, &sector_angle, limits, floor));
    for e in mesh.edges.iter().filter(|e| e.interior) {
        let sigma = match e.assignment {
            Assignment::Valley => 1.0,
            Assignment::Mountain => -1.0,
            Assignment::Flat => {
                out.push(hinge_row(x, mesh.hinge(e), 1.0, 0.0, Family::Flat));
                continue;
            }
            Assignment::Unassigned => {
                out.extend(free_fold_row(x, mesh.hinge(e), limits));
                continue;
            }
            _ => continue,
        };
        if let Some(row) = fold_row(x, mesh.hinge(e), sigma, limits) {
            out.push(row);
        }
    }
    let outline = boundary::boundary_loop(mesh);
    for (value, entries) in boundary::rows(
        &outline,
        &boundary_angles,
        limits.margin,
        limits.hold,
        limits.boundary_runs,
    ) {
        out.push(Row {
            family: Family::Boundary,
            value,
            entries,
        });
    }
    if let Some(z) = limits.ground_z {
        for (v, _) in mesh
            .interior
            .iter()
            .enumerate()
            .filter(|(_, inside)| !**inside)
        {
            out.push(Row {
                family: Family::Ground,
                value: x[v].z - z,
                entries: vec![(v as u32, DVec3::Z)],
            });
        }
    }
    if limits.vertex_penalty {
        for fan in &mesh.fans {
            for c in vertex_penalty::illegal_creases(x, fan) {
                out.extend(penalty_row(c));
            }
        }
    }
    if limits.collision_gap > 0.0 {
        let gap = limits.collision_gap;
        for (value, entries) in collision::rows(x, &mesh.triangles, gap, limits.hold) {
            out.push(Row {
                family: Family::Collision,
                value,
                entries,
            });
        }
    }
    let mut all: Vec<Row> = dev.into_iter().flatten().collect();
    all.extend(out);
    all
}

/// The eq. 5–7 row of an illegal crease as `√f_o = 0` (Tachi's f_o grows with the square of
/// the angular penetration, so its root is about linear in it and Newton's method pulls the
/// crease back to contact quadratically; the row `f_o = 0` only halves the penetration per
/// step and stalls near contact, where its gradient falls under the Tikhonov term of the
/// minimum-norm step). Same zero set; `None` at contact (f_o = 0, no gradient).
fn penalty_row(c: vertex_penalty::Crease) -> Option<Row> {
    if c.penalty <= 0.0 {
        return None;
    }
    let root = c.penalty.sqrt();
    let scale = 0.5 / root;
    Some(Row {
        family: Family::VertexPenalty,
        value: root,
        entries: c.grad.into_iter().map(|(v, g)| (v, scale * g)).collect(),
    })
}

/// §5 vertex-angle rows: `θ − (δ_corner + m)` for every sector (the angle between two
/// neighbouring creases, see [`Sectors`](super::sectors::Sectors)) under `δ_corner + m/2`.
fn vertex_angle_rows(
    mesh: &TessMesh,
    x: &[DVec3],
    sector_angle: &[f64],
    limits: &Limits,
    floor: f64,
) -> Vec<Row> {
    let sectors = &mesh.sectors;
    let threshold = limits.min_vertex_angle + limits.hold * limits.margin;
    let mut row_of: Vec<u32> = vec![u32::MAX; sectors.count];
    let mut out: Vec<Row> = Vec::new();
    for (s, &angle) in sector_angle.iter().enumerate() {
        if angle < threshold {
            row_of[s] = out.len() as u32;
            out.push(Row {
                family: Family::VertexAngle,
                value: angle - floor,
                entries: Vec::new(),
            });
        }
    }
    if out.is_empty() {
        return out;
    }
    for (t, tri) in mesh.triangles.iter().enumerate() {
        for k in 0..3 {
            let r = row_of[sectors.of_corner[3 * t + k] as usize];
            if r == u32::MAX {
                continue;
            }
            let idx = [tri[k], tri[(k + 1) % 3], tri[(k + 2) % 3]];
            let [o, a, b] = idx.map(|v| x[v as usize]);
            let th = corner_angle(o, a, b);
            for (v, g) in idx.iter().zip(th.grad) {
                add(&mut out[r as usize].entries, *v, g);
            }
        }
    }
    out
}

/// Eq. 3 for one crease when its fold ρ' = σρ is past the limit or of the wrong sign.
fn fold_row(x: &[DVec3], hinge: [u32; 4], sigma: f64, limits: &Limits) -> Option<Row> {
    let [i, j, a, b] = hinge.map(|v| x[v as usize]);
    let r = sigma * fold_angle(i, j, a, b).value;
    let (family, target) = if r > limits.max_fold - limits.hold * limits.margin {
        (Family::FoldLimit, limits.max_fold - limits.margin)
    } else if r < limits.hold * limits.margin {
        (Family::FoldSign, limits.margin)
    } else {
        return None;
    };
    Some(hinge_row(x, hinge, sigma, target, family))
}

/// Eq. 3 for a crease free to fold either way ([`Assignment::Unassigned`], the twist folds):
/// only the fold-angle limit, on the side it folds to now.
fn free_fold_row(x: &[DVec3], hinge: [u32; 4], limits: &Limits) -> Option<Row> {
    let [i, j, a, b] = hinge.map(|v| x[v as usize]);
    let rho = fold_angle(i, j, a, b).value;
    let sigma = if rho >= 0.0 { 1.0 } else { -1.0 };
    (sigma * rho > limits.max_fold - limits.hold * limits.margin).then(|| {
        hinge_row(
            x,
            hinge,
            sigma,
            limits.max_fold - limits.margin,
            Family::FoldLimit,
        )
    })
}

/// Eq. 3–4: `f = 2 (sin(σρ/2) − sin(target/2)) h_p h_q` over `hinge = [i, j, a, b]`, with its
/// gradient (eq. 8's chain rule through ρ and the relative heights).
fn hinge_row(x: &[DVec3], hinge: [u32; 4], sigma: f64, target: f64, family: Family) -> Row {
    let [i, j, a, b] = hinge.map(|v| x[v as usize]);
    let rho = fold_angle(i, j, a, b);
    let r = sigma * rho.value;
    let hp = relative_height(i, j, a);
    let hq = relative_height(j, i, b);
    let (s, st) = ((r / 2.0).sin(), (target / 2.0).sin());
    let hh = hp.value * hq.value;
    let value = 2.0 * (s - st) * hh;
    let dr = (r / 2.0).cos() * sigma * hh;
    let dh = 2.0 * (s - st);
    let mut entries = Vec::with_capacity(4);
    for (k, v) in hinge.iter().enumerate() {
        add(&mut entries, *v, dr * rho.grad[k]);
    }
    // h_p over (i, j, a), h_q over (j, i, b).
    for (k, v) in [hinge[0], hinge[1], hinge[2]].iter().enumerate() {
        add(&mut entries, *v, dh * hq.value * hp.grad[k]);
    }
    for (k, v) in [hinge[1], hinge[0], hinge[3]].iter().enumerate() {
        add(&mut entries, *v, dh * hp.value * hq.grad[k]);
    }
    Row {
        family,
        value,
        entries,
    }
}

/// The worst state of each condition at `x`.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Residuals {
    /// Largest |g_v| over interior vertices (eq. 1), radians.
    pub developability: f64,
    /// Largest fold magnitude over creases, radians.
    pub max_fold: f64,
    /// Most negative σρ over creases (0 when every crease folds its assigned way), radians.
    pub wrong_sign: f64,
    /// Smallest angle between neighbouring creases (a triangle corner, or corners joined
    /// across flat diagonals: see [`Sectors`](super::sectors::Sectors)), radians.
    pub min_vertex_angle: f64,
    /// Largest |ρ| over the flat diagonals (0 without any), radians.
    pub max_flat: f64,
    /// Largest distance of a boundary vertex from the ground plane (0 without one), mesh units.
    pub ground: f64,
    /// Smallest `Σ τ + π` over runs of the boundary (eq. 2 holds when ≥ 0), radians.
    pub boundary_turn: f64,
    /// Creases through a vertex-adjacent face (eq. 5–7), whether or not the rows are active.
    pub illegal_creases: usize,
    /// Largest penalty f_o (eq. 7, dimensionless) among the illegal creases, 0 without any.
    pub max_penalty: f64,
}

/// Measures [`Residuals`] at `x` (the ground distance against `ground_z`).
pub fn residuals(mesh: &TessMesh, x: &[DVec3], ground_z: Option<f64>) -> Residuals {
    let sums = angle_sums(mesh, x);
    let developability = sums
        .iter()
        .zip(&mesh.interior)
        .filter(|(_, inside)| **inside)
        .fold(0.0f64, |m, (s, _)| m.max((2.0 * PI - s).abs()));
    let (illegal_creases, max_penalty) = vertex_penalty::measure(x, &mesh.fans);
    let mut r = Residuals {
        illegal_creases,
        max_penalty,
        developability,
        boundary_turn: boundary::worst_turn(&boundary::boundary_loop(mesh), &sums),
        min_vertex_angle: f64::INFINITY,
        ..Residuals::default()
    };
    if let Some(z) = ground_z {
        for (v, _) in mesh
            .interior
            .iter()
            .enumerate()
            .filter(|(_, inside)| !**inside)
        {
            r.ground = r.ground.max((x[v].z - z).abs());
        }
    }
    for angle in mesh.sectors.angles(mesh, x) {
        r.min_vertex_angle = r.min_vertex_angle.min(angle);
    }
    for e in mesh.edges.iter().filter(|e| e.interior) {
        let sigma = match e.assignment {
            Assignment::Valley => 1.0,
            Assignment::Mountain => -1.0,
            _ => 0.0,
        };
        let [i, j, a, b] = mesh.hinge(e).map(|v| x[v as usize]);
        let rho = fold_angle(i, j, a, b).value;
        if e.assignment == Assignment::Flat {
            r.max_flat = r.max_flat.max(rho.abs());
        }
        r.max_fold = r.max_fold.max(rho.abs());
        if sigma != 0.0 {
            r.wrong_sign = r.wrong_sign.min(sigma * rho);
        }
    }
    r
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::design::tessellation::star::{StarOptions, star_tucks};
    use crate::mesh::{HalfEdgeMesh, PolyMesh};

    /// A bumped hexagonal patch: seven vertices, six triangles.
    fn bump() -> HalfEdgeMesh {
        let mut p = vec![DVec3::new(0.0, 0.0, 0.4)];
        for k in 0..6 {
            let a = k as f64 * PI / 3.0;
            p.push(DVec3::new(a.cos(), a.sin(), 0.0));
        }
        let faces = (0..6).map(|k| vec![0, 1 + k, 1 + (k + 1) % 6]).collect();
        HalfEdgeMesh::new(&PolyMesh::new(p, faces).unwrap(), 1e-12).unwrap()
    }

    #[test]
    fn rows_match_finite_differences() {
        let init = star_tucks(&bump(), &StarOptions::default()).unwrap();
        let mut mesh = init.mesh;
        assign_folds(&mut mesh);
        // Tight limits activate fold and angle rows; a huge margin activates eq. 2 rows too.
        let mut limits = Limits::from_degrees(20.0, 50.0);
        let x = mesh.positions.clone();
        let base = rows(&mesh, &x, &limits);
        assert!(base.iter().any(|r| r.family == Family::FoldLimit));
        assert!(base.iter().any(|r| r.family == Family::VertexAngle));
        limits.margin = 20.0;
        limits.ground_z = Some(-0.5);
        let base = rows(&mesh, &x, &limits);
        assert!(base.iter().any(|r| r.family == Family::Boundary));
        assert!(base.iter().any(|r| r.family == Family::Ground));
        let h = 1e-6;
        for (v, c) in [(0usize, 0usize), (3, 2), (mesh.positions.len() - 1, 1)] {
            let (mut up, mut down) = (x.clone(), x.clone());
            up[v][c] += h;
            down[v][c] -= h;
            let (ru, rd) = (rows(&mesh, &up, &limits), rows(&mesh, &down, &limits));
            for (k, row) in base.iter().enumerate() {
                let numeric = (ru[k].value - rd[k].value) / (2.0 * h);
                let analytic = row
                    .entries
                    .iter()
                    .find(|(w, _)| *w as usize == v)
                    .map_or(0.0, |(_, g)| g[c]);
                assert!(
                    (numeric - analytic).abs() < 1e-5,
                    "row {k} {:?} vertex {v}: {numeric} vs {analytic}",
                    row.family
                );
            }
        }
    }

    #[test]
    fn the_penalty_row_is_the_root_of_eq_7_with_its_gradient() {
        // A six-face fan with crease 0 pushed out through the far sectors (illegal).
        let mut positions = vec![DVec3::ZERO];
        positions.extend((0..6).map(|k| {
            let a = k as f64 * PI / 3.0;
            DVec3::new(a.cos(), a.sin(), 0.5)
        }));
        positions[1] = DVec3::new(-1.0, 0.05, 0.18);
        let triangles = (0..6u32).map(|k| [0, 1 + k, 1 + (k + 1) % 6]).collect();
        let mesh = TessMesh::from_triangles(
            positions,
            triangles,
            &std::collections::HashMap::new(),
            Vec::new(),
            Vec::new(),
            0,
        );
        let limits = Limits::from_degrees(180.0, 0.0);
        let penalty_of = |x: &[DVec3]| -> Vec<f64> {
            rows(&mesh, x, &limits)
                .into_iter()
                .filter(|r| r.family == Family::VertexPenalty)
                .map(|r| r.value)
                .collect()
        };
        let x = mesh.positions.clone();
        let (count, worst) = vertex_penalty::measure(&x, &mesh.fans);
        let base: Vec<Row> = rows(&mesh, &x, &limits)
            .into_iter()
            .filter(|r| r.family == Family::VertexPenalty)
            .collect();
        assert_eq!((count, base.len()), (1, 1));
        assert!((base[0].value * base[0].value - worst).abs() < 1e-12 * worst.max(1.0));
        let h = 1e-7;
        for v in 0..x.len() {
            for c in 0..3 {
                let (mut up, mut down) = (x.clone(), x.clone());
                up[v][c] += h;
                down[v][c] -= h;
                let numeric = (penalty_of(&up)[0] - penalty_of(&down)[0]) / (2.0 * h);
                let analytic = base[0]
                    .entries
                    .iter()
                    .find(|(w, _)| *w as usize == v)
                    .map_or(0.0, |(_, g)| g[c]);
                assert!(
                    (numeric - analytic).abs() < 1e-5,
                    "vertex {v}: {numeric} vs {analytic}"
                );
            }
        }
    }
}
