//! Static equilibrium of the bar-and-hinge model by load steps and Levenberg–Marquardt
//! iterations: the implicit alternative to [`super::solver`]'s explicit dynamics.
//!
//! **Energy.** The explicit forces are the negative gradient of
//! `E(x) = Σ_bars ½ k (|d| − L)² + Σ_hinges ½ κ (φ − f φ₀)²` (Ghassaei, Demaine & Gershenfeld
//! 2018, section 3, without the damping), so the state the dynamics settle in is a minimum of
//! `E`: a nonlinear least-squares problem with residuals `√k (|d| − L)` and `√κ (φ − f φ₀)`.
//!
//! **Step.** Gauss–Newton with Levenberg–Marquardt damping (Nocedal & Wright 2006, section
//! 10.3): `(JᵀJ + μ D) Δx = −Jᵀr` with `J`'s bar rows `√k d̂` and hinge rows `√κ ∂φ/∂x`
//! ([`super::dihedral`]), `D` the diagonal of `JᵀJ` plus a floor (the six rigid motions leave
//! `JᵀJ` singular). `JᵀJ` is sparse (two vertices meet where a bar or a hinge joins them); its
//! pattern is fixed, so the sparse Cholesky factorization's symbolic part (faer) is computed
//! once. A step that does not lower `E` is refused and `μ` grows; an accepted one shrinks it.
//!
//! **Factor reuse and line search.** A factor made at one iterate keeps serving the next
//! ones (chord iterations) while their steps lower `E`, each tried at 1, ½ and ¼ of its
//! length, across load steps too (`JᵀJ` depends on the positions, not on the target); where
//! none does, the factor is made anew at the current positions (and `μ` grows when even a
//! fresh factor fails). Measured on a 71 × 71 Miura-ori folded to 90 % (10,082 triangles,
//! `examples/fold3d_methods.rs`): 26 factorizations for 53 solves in 4 load steps, 39 for 83
//! in 10.
//!
//! **Start and load steps.** At the flat sheet a bar's stretch is of second order in the
//! lift, which the Gauss–Newton model does not see, so [`START_STEPS`] explicit steps lift
//! the sheet to the first load step's target; then the target rises in [`LOAD_STEPS`] (or as
//! many as the frames asked for) equal steps, each solved until its largest vertex force
//! falls to [`STEP_REDUCTION`] of its start, the last to the run's tolerance: a continuation
//! along the quasi-static path the explicit ramp follows. On a 20 × 20 Miura-ori both methods settled to a residual of 1e-7 agree
//! on every fold angle within 0.03°.

use faer::Side;
use faer::linalg::solvers::Solve;
use faer::sparse::linalg::solvers::{Llt, SymbolicLlt};
use faer::sparse::{SparseColMat, SymbolicSparseColMat};
use glam::DVec3;

use super::dihedral::{fold_turn_gradient, turn_from};
use super::model::BarHingeModel;
use super::solver::Solver;

/// Equal load steps from flat to the target.
pub const LOAD_STEPS: usize = 4;

/// Each load step but the last is solved until its largest vertex force falls to this
/// fraction of what it was when the step began (the last, to the run's tolerance).
pub const STEP_REDUCTION: f64 = 0.1;

/// Explicit steps that lift the sheet out of flat to the first load step.
pub const START_STEPS: usize = 400;

/// Iterations per load step, at most (the last gets [`LAST_ITERATIONS`]).
const STEP_ITERATIONS: usize = 60;

/// Iterations of the last load step, at most.
const LAST_ITERATIONS: usize = 400;

/// Starting damping, relative to each diagonal entry of `JᵀJ`.
const MU_START: f64 = 1e-6;

/// Damping floor relative to the largest diagonal entry (keeps the rigid motions solvable).
const MU_FLOOR: f64 = 1e-12;

/// The sparsity of `JᵀJ` and where every row's blocks go in its values.
struct Pattern {
    /// Upper triangle, 3 × 3 blocks by vertex pair expanded to scalars (column-major).
    symbolic: SymbolicSparseColMat<usize>,
    /// The factorization's symbolic part, computed once.
    llt: SymbolicLlt<usize>,
    /// Per bar: the value index of entry `(a, b)` of the blocks `(p,p)`, `(q,q)`, `(p,q)`.
    bar_slots: Vec<[[usize; 9]; 3]>,
    /// Per hinge: the same for its ten vertex pairs (corners `[j, k, i, l]`, `c ≤ c'`).
    hinge_slots: Vec<[[usize; 9]; 10]>,
    /// The value index of every diagonal entry.
    diagonal: Vec<usize>,
}

/// The pairs `(c, c')`, `c ≤ c'`, of a hinge's four corners, in the order of `hinge_slots`.
const HINGE_PAIRS: [(usize, usize); 10] = [
    (0, 0),
    (1, 1),
    (2, 2),
    (3, 3),
    (0, 1),
    (0, 2),
    (0, 3),
    (1, 2),
    (1, 3),
    (2, 3),
];

impl Pattern {
    fn new(model: &BarHingeModel) -> Option<Pattern> {
        let n = model.rest.len();
        // Neighbours (lower or equal index) of every vertex.
        let mut lower: Vec<Vec<u32>> = (0..n as u32).map(|v| vec![v]).collect();
        let mut link = |a: u32, b: u32| {
            let (lo, hi) = (a.min(b), a.max(b));
            lower[hi as usize].push(lo);
        };
        for bar in &model.bars {
            link(bar.ends[0], bar.ends[1]);
        }
        for h in &model.hinges {
            let c = [h.edge[0], h.edge[1], h.wings[0], h.wings[1]];
            for &(a, b) in &HINGE_PAIRS[4..] {
                link(c[a], c[b]);
            }
        }
        for l in &mut lower {
            l.sort_unstable();
            l.dedup();
        }
        // Column 3j + b: rows 3i + a of every lower neighbour i < j, then 3j + a for a ≤ b.
        let mut col_ptr = vec![0usize];
        let mut row_idx = Vec::new();
        for (j, neighbours) in lower.iter().enumerate() {
            for b in 0..3 {
                for &i in neighbours {
                    let i = i as usize;
                    let rows = if i == j { b + 1 } else { 3 };
                    row_idx.extend((0..rows).map(|a| 3 * i + a));
                }
                col_ptr.push(row_idx.len());
            }
        }
        let slot = |i: u32, j: u32, a: usize, b: usize| -> usize {
            // Entry (3i + a, 3j + b) of the upper triangle, i ≤ j (and a ≤ b when i == j).
            let (i, j) = (i as usize, j as usize);
            let col = 3 * j + b;
            let (start, end) = (col_ptr[col], col_ptr[col + 1]);
            let row = 3 * i + a;
            // Every pair looked up was linked above, so the search finds it.
            start + row_idx[start..end].binary_search(&row).unwrap_or(0)
        };
        // The entries of block (u, v) in row-major (a, b) order; for u == v the lower half
        // maps onto the upper one (the block is symmetric).
        let block = |u: u32, v: u32| -> [usize; 9] {
            let mut s = [0usize; 9];
            for a in 0..3 {
                for b in 0..3 {
                    s[3 * a + b] = if u < v {
                        slot(u, v, a, b)
                    } else if v < u {
                        slot(v, u, b, a)
                    } else if a <= b {
                        slot(u, u, a, b)
                    } else {
                        // The lower half of a diagonal block is its upper half: added once.
                        SKIP
                    };
                }
            }
            s
        };
        let bar_slots = model
            .bars
            .iter()
            .map(|bar| {
                let [p, q] = bar.ends;
                [block(p, p), block(q, q), block(p, q)]
            })
            .collect();
        let hinge_slots = model
            .hinges
            .iter()
            .map(|h| {
                let c = [h.edge[0], h.edge[1], h.wings[0], h.wings[1]];
                HINGE_PAIRS.map(|(a, b)| block(c[a], c[b]))
            })
            .collect();
        let diagonal = (0..3 * n)
            .map(|d| slot((d / 3) as u32, (d / 3) as u32, d % 3, d % 3))
            .collect();
        let symbolic = SymbolicSparseColMat::new_checked(3 * n, 3 * n, col_ptr, None, row_idx);
        let llt = SymbolicLlt::try_new(symbolic.as_ref(), Side::Upper).ok()?;
        Some(Pattern {
            symbolic,
            llt,
            bar_slots,
            hinge_slots,
            diagonal,
        })
    }
}

/// A block entry not stored (the lower half of a diagonal block).
const SKIP: usize = usize::MAX;

/// Adds `w · g_u g_vᵀ` to a block given by its slots (row-major).
#[inline]
fn add_outer(values: &mut [f64], slots: &[usize; 9], w: f64, gu: DVec3, gv: DVec3) {
    let (u, v) = (gu.to_array(), gv.to_array());
    for a in 0..3 {
        for b in 0..3 {
            let slot = slots[3 * a + b];
            if slot != SKIP {
                values[slot] += w * u[a] * v[b];
            }
        }
    }
}

/// What one evaluation at the positions gives: the energy, its gradient `Jᵀr` per vertex,
/// the largest vertex force over `EA`, and each hinge's unwrapped angle and `(sin, cos)`.
struct Evaluation {
    energy: f64,
    gradient: Vec<DVec3>,
    force: f64,
    angles: Vec<f64>,
    turns: Vec<(f64, f64)>,
}

/// Energy and gradient at `x`, the hinge angles followed from `(angles, turns)`.
fn evaluate(s: &Solver<'_>, x: &[DVec3], angles: &[f64], turns: &[(f64, f64)]) -> Evaluation {
    let model = s.model;
    let mut gradient = vec![DVec3::ZERO; x.len()];
    let mut energy = 0.0;
    for (b, bar) in model.bars.iter().enumerate() {
        let [p, q] = bar.ends.map(|e| e as usize);
        let d = x[q] - x[p];
        let len = d.length();
        if len > 0.0 {
            let stretch = len - bar.rest;
            energy += 0.5 * s.bar_k[b] * stretch * stretch;
            let g = d * (s.bar_k[b] * stretch / len);
            gradient[q] += g;
            gradient[p] -= g;
        }
    }
    let mut new_angles = angles.to_vec();
    let mut new_turns = turns.to_vec();
    for (h, hinge) in model.hinges.iter().enumerate() {
        let [j, k] = hinge.edge.map(|e| x[e as usize]);
        let [i, l] = hinge.wings.map(|e| x[e as usize]);
        let Some((sin, cos, g)) = fold_turn_gradient(j, k, i, l) else {
            continue;
        };
        let angle = angles[h] + turn_from(turns[h], (sin, cos));
        new_angles[h] = angle;
        new_turns[h] = (sin, cos);
        let off = angle - s.fraction * s.hinge_full[h];
        energy += 0.5 * s.hinge_k[h] * off * off;
        let corners = [hinge.edge[0], hinge.edge[1], hinge.wings[0], hinge.wings[1]];
        for (c, v) in corners.iter().enumerate() {
            gradient[*v as usize] += g[c] * (s.hinge_k[h] * off);
        }
    }
    let force = gradient.iter().map(|g| g.length()).fold(0.0, f64::max) / s.axial;
    Evaluation {
        energy,
        gradient,
        force,
        angles: new_angles,
        turns: new_turns,
    }
}

/// The factor of `JᵀJ` (in `values`) damped by `mu` (see the module docs).
fn factor_with(pattern: &Pattern, values: &[f64], mu: f64) -> Option<Llt<usize, f64>> {
    let top = pattern
        .diagonal
        .iter()
        .map(|&d| values[d])
        .fold(0.0, f64::max)
        .max(f64::MIN_POSITIVE);
    let mut damped = values.to_vec();
    for &d in &pattern.diagonal {
        let v = values[d];
        damped[d] = v + mu * v.max(MU_FLOOR * top) + MU_FLOOR * top;
    }
    let matrix = SparseColMat::new(pattern.symbolic.clone(), damped);
    Llt::try_new_with_symbolic(pattern.llt.clone(), matrix.as_ref(), Side::Upper).ok()
}

/// `JᵀJ` at `x` in the pattern's values.
fn assemble(s: &Solver<'_>, pattern: &Pattern, x: &[DVec3], values: &mut [f64]) {
    values.fill(0.0);
    let model = s.model;
    for (b, bar) in model.bars.iter().enumerate() {
        let [p, q] = bar.ends.map(|e| e as usize);
        let d = x[q] - x[p];
        let len = d.length();
        if len <= 0.0 {
            continue;
        }
        let u = d / len;
        let k = s.bar_k[b];
        let [pp, qq, pq] = &pattern.bar_slots[b];
        add_outer(values, pp, k, u, u);
        add_outer(values, qq, k, u, u);
        add_outer(values, pq, -k, u, u);
    }
    for (h, hinge) in model.hinges.iter().enumerate() {
        let kappa = s.hinge_k[h];
        if kappa == 0.0 {
            continue;
        }
        let [j, k] = hinge.edge.map(|e| x[e as usize]);
        let [i, l] = hinge.wings.map(|e| x[e as usize]);
        let Some((_, _, g)) = fold_turn_gradient(j, k, i, l) else {
            continue;
        };
        for (slots, &(a, b)) in pattern.hinge_slots[h].iter().zip(&HINGE_PAIRS) {
            add_outer(values, slots, kappa, g[a], g[b]);
        }
    }
}

/// How a static solve ended.
#[derive(Clone, Copy)]
pub(super) struct Settled {
    /// Linear solves made.
    pub iterations: usize,
    /// Factorizations made (a factor serves several solves while they lower the energy).
    pub factorizations: usize,
    /// Whether the last load step reached the tolerance.
    pub converged: bool,
}

/// Folds the solver's model to `fraction` of its targets by `loads` load steps (at least
/// [`LOAD_STEPS`]; see the module docs), leaving the solver at the result; `at_load` sees the
/// fraction and the positions at the end of every load step but the last. `None` when the
/// factorization cannot be set up.
pub(super) fn settle(
    s: &mut Solver<'_>,
    fraction: f64,
    loads: usize,
    tolerance: f64,
    out_of_time: &dyn Fn() -> bool,
    at_load: &mut dyn FnMut(f64, &[DVec3]),
) -> Option<Settled> {
    let loads = loads.max(LOAD_STEPS);
    let pattern = Pattern::new(s.model)?;
    let n3 = 3 * s.positions.len();
    let mut values = vec![0.0; pattern.symbolic.row_idx().len()];
    let (mut iterations, mut factorizations) = (0, 0);
    // Out of the flat sheet with the explicit dynamics: at flat every bar's stretch is of
    // second order in the lift, which the Gauss–Newton model does not see.
    let start = fraction / loads as f64;
    for k in 1..=START_STEPS {
        s.set_fraction(start * k as f64 / START_STEPS as f64);
        s.step();
    }
    let (angles, turns) = s.hinge_state();
    let mut now = evaluate(s, &s.positions, &angles, &turns);
    let mut mu = MU_START;
    // The factor in use and whether it was made at the current positions: a stale one keeps
    // serving while its steps lower the energy (chord iterations), across load steps too
    // (`JᵀJ` depends on the positions, not on the target), and is made anew where they stop.
    let mut factor: Option<Llt<usize, f64>> = None;
    let mut fresh = false;
    for load in 1..=loads {
        let reached = fraction * load as f64 / loads as f64;
        s.set_fraction(reached);
        let last = load == loads;
        // The same positions and angles, energy and forces at the new target.
        now = evaluate(s, &s.positions, &now.angles, &now.turns);
        let (goal, cap) = if last {
            (tolerance, LAST_ITERATIONS)
        } else {
            ((STEP_REDUCTION * now.force).max(tolerance), STEP_ITERATIONS)
        };
        for _ in 0..cap {
            if now.force < goal || out_of_time() {
                break;
            }
            if factor.is_none() {
                assemble(s, &pattern, &s.positions, &mut values);
                factorizations += 1;
                factor = factor_with(&pattern, &values, mu);
                fresh = true;
                if factor.is_none() {
                    mu *= 10.0;
                    continue;
                }
            }
            let Some(llt) = &factor else { continue };
            let mut step: Vec<f64> = now.gradient.iter().flat_map(|g| (-*g).to_array()).collect();
            llt.solve_in_place(faer::MatMut::from_column_major_slice_mut(&mut step, n3, 1));
            iterations += 1;
            // Backtracking along the step before giving up on the factor.
            let mut found = None;
            for t in [1.0, 0.5, 0.25] {
                let trial: Vec<DVec3> = s
                    .positions
                    .iter()
                    .zip(step.chunks_exact(3))
                    .map(|(p, d)| *p + t * DVec3::new(d[0], d[1], d[2]))
                    .collect();
                let next = evaluate(s, &trial, &now.angles, &now.turns);
                if next.energy.is_finite() && next.energy < now.energy {
                    found = Some((trial, next));
                    break;
                }
            }
            if let Some((trial, next)) = found {
                s.positions = trial;
                now = next;
                if fresh {
                    mu = (mu / 3.0).max(MU_FLOOR);
                }
                fresh = false;
            } else {
                if fresh {
                    mu *= 4.0;
                }
                factor = None;
            }
        }
        if !last {
            at_load(reached, &s.positions);
        }
    }
    s.set_hinge_state(&now.angles, &now.turns);
    Some(Settled {
        iterations,
        factorizations,
        // The last load step's goal is the run's tolerance.
        converged: now.force < tolerance,
    })
}
