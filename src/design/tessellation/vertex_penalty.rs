//! Vertex-adjacent faces (Tachi 2014, §3.2, eq. 5–7): detecting a crease that has passed through a face
//! sharing only its vertex, and the penalty that pulls it back.
//!
//! At an interior vertex `v` with ring `u_0 … u_{n−1}` (counter-clockwise about the front
//! normals) the unit crease directions `e_k` form a closed chain on the unit sphere. For
//! crease `o` the *derived fan* drops the two sectors next to `e_o` and closes the gap with the
//! sector `(e_{o−1}, e_{o+1})`; the crease is illegal when it is a valley (ρ > 0) inside the
//! derived fan or a mountain (ρ < 0) outside it, the fronts taken towards the fan's interior
//! (the side of area < 2π). Inside/outside is the winding number `Σ α_{o,i,i+1} / 2π` of the
//! derived chain seen from `e_o`, with the signed visual angle of eq. 5
//! `α = atan2(det(e_o, e_i, e_{i+1}), (e_o × e_i)·(e_o × e_{i+1}))`.
//!
//! The chain turns by the fold angle at every crease, so by Gauss–Bonnet the region left of
//! it (where the fronts face) has area `2π − Σ ρ_k`: the fronts face the interior when
//! `Σ ρ_k > 0`; otherwise valleys and mountains swap roles (the paper's "without loss of
//! generality").
//!
//! An illegal crease gets the harmonic mean (eq. 7) of the angular distances (eq. 6)
//! `d_{o,i,i+1} = |e_o×e_i||e_o×e_{i+1}| + (e_o×e_i)·(e_o×e_{i+1})` to the sectors of its
//! derived fan, `f_o = (n − 1) / Σ 1/d`, zero when the crease touches a sector.
//!
//! Following the paper, only interior vertices with more than four faces are checked (with
//! four or fewer, the fold-angle rows of eq. 3 already keep the faces apart), an illegal
//! crease adds a row, and a crease at contact (f_o ≤ [`TOLERANCE`]) is accepted.
//! A crease with |ρ| under [`FLAT_FOLD`] is skipped (it lies on its own closing sector,
//! undecided). f_o grows with the square of the angular penetration, so the row `f_o = 0`
//! would pull a crease back only halfway per Newton step and stall near contact (measured: a
//! remeshed 2,022-face cap with truncated stars kept some 430 creases just above the
//! tolerance for 150 iterations); the solver's row is `√f_o = 0` instead (same zero set,
//! about linear in the penetration), see `constraints::rows`.

use std::collections::HashMap;
use std::f64::consts::TAU;

use glam::DVec3;

use super::geometry::fold_angle;

/// Folds smaller than this (radians) are not classified.
pub const FLAT_FOLD: f64 = 1e-6;

/// Largest penalty f_o accepted for an illegal crease (contact): about 1e-6 rad of angular
/// penetration.
pub const TOLERANCE: f64 = 1e-12;

/// Fewest faces at a vertex for the check (the paper: more than four).
pub const MIN_FACES: usize = 5;

/// An interior vertex and its neighbours in counter-clockwise order about the front normals
/// (triangle `(center, ring[k], ring[k + 1])` exists for every k).
#[derive(Clone, Debug, PartialEq)]
pub struct Fan {
    /// The vertex.
    pub center: u32,
    /// Its neighbours.
    pub ring: Vec<u32>,
}

/// The ordered fans of every interior vertex with at least [`MIN_FACES`] triangles
/// (topology only: [`TessMesh::fans`](super::model::TessMesh::fans) keeps them for the mesh's lifetime).
pub fn fans(triangles: &[[u32; 3]], interior: &[bool]) -> Vec<Fan> {
    let mut next: Vec<HashMap<u32, u32>> = vec![HashMap::new(); interior.len()];
    for t in triangles {
        for k in 0..3 {
            next[t[k] as usize].insert(t[(k + 1) % 3], t[(k + 2) % 3]);
        }
    }
    let mut out = Vec::new();
    for (v, links) in next.iter().enumerate() {
        if !interior[v] || links.len() < MIN_FACES {
            continue;
        }
        let Some(&start) = links.keys().min() else {
            continue;
        };
        let mut ring = vec![start];
        let mut u = start;
        while let Some(&w) = links.get(&u) {
            if w == start || ring.len() > links.len() {
                break;
            }
            ring.push(w);
            u = w;
        }
        if ring.len() == links.len() {
            out.push(Fan {
                center: v as u32,
                ring,
            });
        }
    }
    out
}

/// The state of one crease of a fan.
#[derive(Clone, Debug, PartialEq)]
pub struct Crease {
    /// Ring position o of the crease.
    pub index: usize,
    /// Whether it passes through its derived fan the wrong way (see the module docs).
    pub illegal: bool,
    /// f_o of eq. 7 (≥ 0; 0 when it touches a sector of the derived fan).
    pub penalty: f64,
    /// ∂f_o/∂X as (vertex, block) pairs.
    pub grad: Vec<(u32, DVec3)>,
}

/// Unit crease directions of a fan with their lengths.
fn directions(x: &[DVec3], fan: &Fan) -> Option<(Vec<DVec3>, Vec<f64>)> {
    let c = x[fan.center as usize];
    let mut e = Vec::with_capacity(fan.ring.len());
    let mut len = Vec::with_capacity(fan.ring.len());
    for &u in &fan.ring {
        let d = x[u as usize] - c;
        let l = d.length();
        if l <= 0.0 || !l.is_finite() {
            return None;
        }
        e.push(d / l);
        len.push(l);
    }
    Some((e, len))
}

/// Fold angles ρ_k of the fan's creases (valley positive).
fn folds(x: &[DVec3], fan: &Fan) -> Vec<f64> {
    let n = fan.ring.len();
    let c = x[fan.center as usize];
    (0..n)
        .map(|k| {
            let p = |i: usize| x[fan.ring[i % n] as usize];
            fold_angle(c, p(k), p(k + 1), p(k + n - 1)).value
        })
        .collect()
}

/// The creases of `fan` at `x` that can be classified, with their penalties (eq. 5–7).
#[cfg(test)]
pub fn creases(x: &[DVec3], fan: &Fan) -> Vec<Crease> {
    classified(x, fan, false)
}

/// Only the illegal creases of `fan` at `x`, with their penalties: what the solver rows and
/// [`measure`] need, without the penalty work for legal creases.
pub fn illegal_creases(x: &[DVec3], fan: &Fan) -> Vec<Crease> {
    classified(x, fan, true)
}

fn classified(x: &[DVec3], fan: &Fan, only_illegal: bool) -> Vec<Crease> {
    let n = fan.ring.len();
    let Some((e, len)) = directions(x, fan) else {
        return Vec::new();
    };
    let rho = folds(x, fan);
    let total: f64 = rho.iter().sum();
    if total.abs() < FLAT_FOLD {
        return Vec::new();
    }
    let sigma = total.signum();
    let mut out = Vec::new();
    for o in 0..n {
        if rho[o].abs() < FLAT_FOLD {
            continue;
        }
        // Derived chain: e_{o+1}, …, e_{o−1}, closed by the sector (e_{o−1}, e_{o+1}).
        let arcs = || (1..n).map(|k| ((o + k) % n, (o + k % (n - 1) + 1) % n));
        // Eq. 5: the signed view angles of the derived fan's sectors sum to 2π (inside) or 0.
        let winding: f64 = arcs()
            .map(|(i, j)| {
                let (a, b) = (e[o].cross(e[i]), e[o].cross(e[j]));
                winding_atan2(e[o].dot(e[i].cross(e[j])), a.dot(b))
            })
            .sum::<f64>()
            / TAU;
        let inside = (winding.round() - sigma).abs() < 0.5;
        let r = sigma * rho[o];
        let illegal = (r > 0.0 && inside) || (r < 0.0 && !inside);
        if only_illegal && !illegal {
            continue;
        }
        let (penalty, unit_grad) = harmonic_penalty(&e, o, arcs());
        let mut grad: Vec<(u32, DVec3)> = Vec::new();
        for (k, g) in unit_grad {
            // e = (x_u − x_c)/L: ∂e/∂x_u = (I − e eᵀ)/L, and the centre takes the negative.
            let block = (g - g.dot(e[k]) * e[k]) / len[k];
            push(&mut grad, fan.ring[k], block);
            push(&mut grad, fan.center, -block);
        }
        out.push(Crease {
            index: o,
            illegal,
            penalty,
            grad,
        });
    }
    out
}

/// `y.atan2(x)` within 1e-5 rad (a degree-11 odd polynomial for atan on [0, 1], error
/// 1.7e-6, after reducing to the first octant), several times cheaper than libm's atan2
/// (a tenth of a solve's time in perf, most of it from this test's n² calls per fan of n
/// creases, every iteration). The winding number sums some dozen such angles and is rounded to an integer,
/// so the error stays far under the half turn that could change it.
fn winding_atan2(y: f64, x: f64) -> f64 {
    let (ax, ay) = (x.abs(), y.abs());
    let (lo, hi) = if ax >= ay { (ay, ax) } else { (ax, ay) };
    if hi == 0.0 {
        return 0.0;
    }
    let t = lo / hi;
    let t2 = t * t;
    let mut a = t
        * (0.999_977_26
            + t2 * (-0.332_623_47
                + t2 * (0.193_543_46
                    + t2 * (-0.116_432_87 + t2 * (0.052_653_32 + t2 * -0.011_721_20)))));
    if ay > ax {
        a = std::f64::consts::FRAC_PI_2 - a;
    }
    if x < 0.0 {
        a = std::f64::consts::PI - a;
    }
    if y.is_sign_negative() { -a } else { a }
}

fn push(entries: &mut Vec<(u32, DVec3)>, v: u32, g: DVec3) {
    match entries.iter_mut().find(|(w, _)| *w == v) {
        Some((_, acc)) => *acc += g,
        None => entries.push((v, g)),
    }
}

/// Eq. 6 for one sector with its gradient with respect to the unit vectors `[e_o, e_i, e_j]`.
fn sector_distance(eo: DVec3, ei: DVec3, ej: DVec3) -> (f64, [DVec3; 3]) {
    let (a, b) = (eo.cross(ei), eo.cross(ej));
    let (la, lb) = (a.length(), b.length());
    let value = la * lb + a.dot(b);
    // ∂d/∂a = b + |b| â, ∂d/∂b = a + |a| b̂, then through a = e_o × e_i, b = e_o × e_j.
    let p = b + lb * a.normalize_or_zero();
    let q = a + la * b.normalize_or_zero();
    (value, [ei.cross(p) + ej.cross(q), p.cross(eo), q.cross(eo)])
}

/// Eq. 7, the harmonic mean of eq. 6 over the sectors `arcs` of the derived fan of crease
/// `o`, with its gradient with respect to the unit directions (ring position, block).
fn harmonic_penalty(
    e: &[DVec3],
    o: usize,
    arcs: impl Iterator<Item = (usize, usize)>,
) -> (f64, Vec<(usize, DVec3)>) {
    let parts: Vec<(usize, usize, f64, [DVec3; 3])> = arcs
        .map(|(i, j)| {
            let (d, g) = sector_distance(e[o], e[i], e[j]);
            (i, j, d, g)
        })
        .collect();
    let m = parts.len() as f64;
    if parts.iter().any(|p| p.2 <= 0.0) {
        // Touching a sector: f = 0, and ∂f = m ∂d of that sector, which vanishes there.
        return (0.0, Vec::new());
    }
    let inverse_sum: f64 = parts.iter().map(|p| 1.0 / p.2).sum();
    let f = m / inverse_sum;
    let mut grad = Vec::with_capacity(3 * parts.len());
    for (i, j, d, g) in parts {
        let w = f * f / (m * d * d); // ∂f/∂d
        grad.extend([(o, w * g[0]), (i, w * g[1]), (j, w * g[2])]);
    }
    (f, grad)
}

/// Illegal creases at `x` over `fans` and the largest penalty among them.
pub fn measure(x: &[DVec3], fans: &[Fan]) -> (usize, f64) {
    let mut count = 0;
    let mut worst = 0.0f64;
    for fan in fans {
        for c in illegal_creases(x, fan) {
            count += 1;
            worst = worst.max(c.penalty);
        }
    }
    (count, worst)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::design::tessellation::model::TessMesh;

    /// A six-face fan around the origin; `ring[k]` are the neighbours' positions.
    fn fan_mesh(ring: &[DVec3]) -> TessMesh {
        let mut positions = vec![DVec3::ZERO];
        positions.extend_from_slice(ring);
        let n = ring.len() as u32;
        let triangles = (0..n).map(|k| [0, 1 + k, 1 + (k + 1) % n]).collect();
        TessMesh::from_triangles(
            positions,
            triangles,
            &HashMap::new(),
            Vec::new(),
            Vec::new(),
            0,
        )
    }

    /// Directions on a cap around +z, counter-clockwise seen from above: a convex cone whose
    /// fronts face its inside, every crease a valley.
    fn cap() -> Vec<DVec3> {
        (0..6)
            .map(|k| {
                let a = k as f64 * std::f64::consts::PI / 3.0;
                DVec3::new(a.cos(), a.sin(), 0.5)
            })
            .collect()
    }

    /// The cap with crease 0 pushed across the cone and out through the far sectors.
    fn pierced() -> Vec<DVec3> {
        let mut ring = cap();
        ring[0] = DVec3::new(-1.0, 0.05, 0.18);
        ring
    }

    /// Largest error allowed of [`winding_atan2`], radians.
    const WINDING_ATAN2_ERROR: f64 = 1e-5;

    #[test]
    fn the_winding_arctangent_is_within_its_error_of_libm() {
        let mut rng = crate::test_rng::TestRng::new(7);
        let mut worst = 0.0f64;
        for k in 0..200_000 {
            let (y, x) = if k < 8 {
                // The axes and diagonals exactly.
                let a = k as f64 * std::f64::consts::FRAC_PI_4;
                (a.sin(), a.cos())
            } else {
                (rng.unit() - 0.5, rng.unit() - 0.5)
            };
            worst = worst.max((winding_atan2(y, x) - y.atan2(x)).abs());
        }
        assert!(worst < WINDING_ATAN2_ERROR, "{worst}");
        assert_eq!(winding_atan2(0.0, 0.0), 0.0);
    }

    #[test]
    fn a_convex_cone_is_legal_and_a_pierced_one_is_not() {
        let mesh = fan_mesh(&cap());
        let found = &mesh.fans;
        assert_eq!(found.len(), 1);
        let legal = creases(&mesh.positions, &found[0]);
        assert_eq!(legal.len(), 6);
        assert!(legal.iter().all(|c| !c.illegal && c.penalty > 0.0));
        // Reversing the orientation swaps fronts and backs: still legal.
        let mut flipped = cap();
        flipped.reverse();
        let m2 = fan_mesh(&flipped);
        let c2 = creases(&m2.positions, &m2.fans[0]);
        assert!(c2.iter().all(|c| !c.illegal), "{c2:?}");

        let mesh = fan_mesh(&pierced());
        let fan = &mesh.fans[0];
        let c = creases(&mesh.positions, fan);
        let bad: Vec<usize> = c.iter().filter(|c| c.illegal).map(|c| c.index).collect();
        assert_eq!(bad, vec![0], "{c:?}");
        assert_eq!(measure(&mesh.positions, &mesh.fans).0, 1);
    }

    #[test]
    fn penalty_gradient_matches_finite_differences() {
        let mesh = fan_mesh(&pierced());
        let fan = mesh.fans[0].clone();
        let x = mesh.positions.clone();
        let base = creases(&x, &fan);
        let h = 1e-6;
        for crease in &base {
            for v in 0..x.len() {
                for c in 0..3 {
                    let (mut up, mut down) = (x.clone(), x.clone());
                    up[v][c] += h;
                    down[v][c] -= h;
                    let f = |y: &[DVec3]| {
                        creases(y, &fan)
                            .into_iter()
                            .find(|k| k.index == crease.index)
                            .map_or(f64::NAN, |k| k.penalty)
                    };
                    let numeric = (f(&up) - f(&down)) / (2.0 * h);
                    let analytic = crease
                        .grad
                        .iter()
                        .find(|(w, _)| *w as usize == v)
                        .map_or(0.0, |(_, g)| g[c]);
                    assert!(
                        (numeric - analytic).abs() < 1e-6,
                        "crease {} vertex {v}.{c}: {numeric} vs {analytic}",
                        crease.index
                    );
                }
            }
        }
    }

    #[test]
    fn penalty_is_the_harmonic_mean_of_the_sector_distances() {
        let e = [DVec3::Z, DVec3::X, DVec3::Y, -DVec3::X];
        // Eq. 6's two forms agree: |a||b| + a·b = cos γ − cos(β_i + β_j).
        let (d, _) = sector_distance(e[0], e[1], e[2]);
        let want = e[1].dot(e[2]) - (e[0].angle_between(e[1]) + e[0].angle_between(e[2])).cos();
        assert!((d - want).abs() < 1e-15 && (d - 1.0).abs() < 1e-15);
        // e_o on the arc from X to −X over Z: distance 0, so the mean is 0.
        let (touch, _) = sector_distance(e[0], e[1], e[3]);
        assert!(touch.abs() < 1e-15);
        let (f, _) = harmonic_penalty(&e, 0, [(1, 2), (2, 1)].into_iter());
        assert!((f - 1.0).abs() < 1e-15);
        let (f, _) = harmonic_penalty(&e, 0, [(1, 2), (1, 3)].into_iter());
        assert_eq!(f, 0.0);
    }

    /// The penalty enters the solver as rows (FD-checked through `constraints::rows`), and
    /// the solve pulls the pierced crease back out while making the vertex developable; the
    /// exact face test agrees that the pierced fan intersects and the result does not.
    #[test]
    fn the_solver_pulls_a_pierced_crease_back() {
        use crate::design::tessellation::constraints::{Family, Limits, rows};
        use crate::design::tessellation::intersect::intersecting_triangles;
        use crate::design::tessellation::solver::{SolveOptions, solve};
        let mut mesh = fan_mesh(&pierced());
        let limits = Limits::from_degrees(180.0, 5.0);
        let x = mesh.positions.clone();
        let base = rows(&mesh, &x, &limits);
        assert_eq!(
            base.iter()
                .filter(|r| r.family == Family::VertexPenalty)
                .count(),
            1
        );
        let h = 1e-6;
        for v in 0..x.len() {
            for c in 0..3 {
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
                    assert!((numeric - analytic).abs() < 1e-6, "{:?}", row.family);
                }
            }
        }
        let before = intersecting_triangles(&mesh.positions, &mesh.triangles, 1e-9).unwrap();
        assert!(!before.is_empty(), "the pierced fan intersects");
        let opts = SolveOptions {
            limits,
            ..SolveOptions::default()
        };
        let report = solve(&mut mesh, &opts, ()).unwrap();
        assert!(report.converged, "{}", report.summary());
        assert_eq!(report.initial.illegal_creases, 1);
        // Pulled back to contact (or past it): at most 1e-6 rad of angular penetration.
        assert!(report.last.max_penalty <= TOLERANCE, "{}", report.summary());
        assert!(report.last.developability < 1e-12);
        let after = intersecting_triangles(&mesh.positions, &mesh.triangles, 1e-5).unwrap();
        assert!(after.is_empty(), "{after:?}");
        // Without the rows the same solve keeps the crease through the far face.
        let mut loose = fan_mesh(&pierced());
        let off = SolveOptions {
            limits: Limits {
                vertex_penalty: false,
                ..limits
            },
            ..opts
        };
        let report = solve(&mut loose, &off, ()).unwrap();
        assert!(
            report.converged && report.last.illegal_creases == 1,
            "{}",
            report.summary()
        );
    }
}
