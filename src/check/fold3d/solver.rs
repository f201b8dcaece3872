//! Explicit damped dynamics of the bar-and-hinge model, as in Origami Simulator (Ghassaei,
//! Demaine & Gershenfeld 2018, section 3).
//!
//! **Forces.** A bar of rest length `L` and axial stiffness `k = EA/L` pulls its ends with
//! `k (|d| − L) d̂` and damps their relative velocity with `c (v_b − v_a)`,
//! `c = 2ζ √k` (unit mass, as in Origami Simulator). A hinge of stiffness `κ = k_h · |edge|` (`k_h` the crease or the facet
//! stiffness, a force) with fold angle `φ` and target `φ₀` applies `−κ (φ − φ₀) ∂φ/∂x` to its
//! four corners ([`super::dihedral`]).
//!
//! **Integration.** Semi-implicit (symplectic) Euler, `v ← v + Δt F/m`, `x ← x + Δt v`, run
//! as dynamic relaxation (Barnes 1999): the time step is 1 and each vertex gets the
//! fictitious mass that makes it stable, `m = (λ_K + 2 s λ_C)/(4 s²)`, from Gershgorin bounds
//! `λ_K`, `λ_C` of its rows of the stiffness and damping matrices (every bar's and hinge's
//! blocks summed per vertex, in the flat sheet; `s` = [`STEP_SAFETY`]); this is the stability
//! limit of explicit integration with damping, `Δt ≤ 2/(√(ω² + γ²/4) + γ/2)`, solved for the
//! mass. Stiff and soft regions then advance at the same pace, and a stiff sheet settles in a
//! few thousand steps. Kinetic damping stops every vertex whenever the total kinetic energy
//! passes a peak. Fold angles are unwrapped from step to step, so a hinge driven towards
//! ±180° does not jump to the other side.
//!
//! **Schedule.** The target percentage rises linearly from 0 over the first
//! [`super::FoldOptions::ramp_steps`] steps (a quasi-static fold, which keeps the bars near
//! their rest lengths; with [`super::FoldOptions::adaptive_ramp`] it rises up to
//! [`super::RAMP_SPEEDUP`] times faster while [`Solver::step_force`] stays small, a
//! continuation with an adaptive load step), then holds until the largest residual force on a vertex (without the
//! damping), over the axial stiffness `EA`, falls below the tolerance, or a step or time cap
//! stops it.
//!
//! **Angles.** A hinge's fold angle is followed from step to step by the turn between its
//! last and its new `(sin φ, cos φ)` ([`super::dihedral::turn_from`]: a series for the small
//! turns of every step instead of an `atan2`), which also unwraps it.
//!
//! **Parallelism.** Each step is three passes: bars and hinges side by side (each writing
//! only its own forces), then vertices (each gathering the forces of the elements it belongs
//! to through a compressed incidence list, then integrating). Large models run the passes on
//! rayon.

use glam::DVec3;
use rayon::prelude::*;

use super::FoldOptions;
use super::dihedral::{fold_angle_gradient, fold_turn_gradient, turn_from};
use super::model::{BarHingeModel, HingeKind};

/// Fraction of the stability limit used as the time step.
pub const STEP_SAFETY: f64 = 0.9;

/// Elements (bars + hinges) from which the passes run in parallel.
const PARALLEL_MIN: usize = 12_000;

/// Hinge output of one step: forces on `[j, k, i, l]`, the unwrapped fold angle and its
/// sine and cosine.
#[derive(Clone, Copy, Debug)]
struct HingeOut {
    force: [DVec3; 4],
    angle: f64,
    turn: (f64, f64),
}

impl Default for HingeOut {
    /// Flat: no force, angle 0.
    fn default() -> Self {
        HingeOut {
            force: [DVec3::ZERO; 4],
            angle: 0.0,
            turn: (0.0, 1.0),
        }
    }
}

/// The state of a running simulation.
pub struct Solver<'m> {
    pub(super) model: &'m BarHingeModel,
    /// Positions.
    pub positions: Vec<DVec3>,
    velocities: Vec<DVec3>,
    pub(super) bar_k: Vec<f64>,
    bar_c: Vec<f64>,
    pub(super) hinge_k: Vec<f64>,
    /// Every hinge's angle at 100 % (0 for facet and free hinges), radians.
    pub(super) hinge_full: Vec<f64>,
    /// The fraction of [`Self::hinge_full`] the hinges are driven to.
    pub(super) fraction: f64,
    bar_out: Vec<DVec3>,
    hinge_out: Vec<HingeOut>,
    /// Per vertex, the range of its slots in `slots`.
    slot_start: Vec<u32>,
    slots: Vec<u32>,
    /// Fictitious mass of every vertex (dynamic relaxation: the time step is 1).
    mass: Vec<f64>,
    /// Kinetic energy after the last step.
    kinetic: f64,
    /// Largest force on a vertex in the last step (damping included), over `EA`.
    step_force: f64,
    pub(super) axial: f64,
    parallel: bool,
}

impl<'m> Solver<'m> {
    /// A solver at the flat sheet with the options' stiffnesses (targets at 0 %).
    pub fn new(model: &'m BarHingeModel, opts: &FoldOptions) -> Self {
        let bar_k: Vec<f64> = model
            .bars
            .iter()
            .map(|b| opts.axial_stiffness / b.rest.max(f64::MIN_POSITIVE))
            .collect();
        let bar_c = bar_k
            .iter()
            .map(|k| 2.0 * opts.damping_ratio * k.sqrt())
            .collect();
        let hinge_k = model
            .hinges
            .iter()
            .map(|h| {
                let len = model.rest[h.edge[0] as usize].distance(model.rest[h.edge[1] as usize]);
                len * match h.kind {
                    HingeKind::Crease(_) => opts.crease_stiffness,
                    HingeKind::Free => 0.0,
                    HingeKind::Facet => opts.facet_stiffness,
                }
            })
            .collect();
        let (slot_start, slots) = incidence(model);
        let mut s = Solver {
            model,
            positions: model.rest.clone(),
            velocities: vec![DVec3::ZERO; model.rest.len()],
            bar_k,
            bar_c,
            hinge_k,
            hinge_full: model
                .hinges
                .iter()
                .map(|h| match h.kind {
                    HingeKind::Crease(a) => a,
                    _ => 0.0,
                })
                .collect(),
            fraction: 0.0,
            bar_out: vec![DVec3::ZERO; model.bars.len()],
            hinge_out: vec![HingeOut::default(); model.hinges.len()],
            slot_start,
            slots,
            mass: Vec::new(),
            kinetic: 0.0,
            step_force: 0.0,
            axial: opts.axial_stiffness,
            parallel: model.bars.len() + model.hinges.len() >= PARALLEL_MIN,
        };
        s.mass = s.stable_masses();
        s
    }

    /// Sets every crease hinge's target to `fraction ×` its 100 % angle.
    pub fn set_fraction(&mut self, fraction: f64) {
        self.fraction = fraction;
    }

    /// The largest force on a vertex in the last step, damping included, over the axial
    /// stiffness `EA`: a residual measured on the fly at no extra cost, which the adaptive
    /// ramp of [`super::fold_with`] reads. It is not [`Self::residual`] (which leaves the
    /// damping out and is taken at the new positions). 0 before the first step.
    pub fn step_force(&self) -> f64 {
        self.step_force
    }

    /// Every hinge's unwrapped angle and its `(sin, cos)`, as the last step left them.
    pub(super) fn hinge_state(&self) -> (Vec<f64>, Vec<(f64, f64)>) {
        self.hinge_out.iter().map(|h| (h.angle, h.turn)).unzip()
    }

    /// Sets every hinge's unwrapped angle and `(sin, cos)` (a static solve's result), with
    /// no force and no velocity: the state a settled run leaves.
    pub(super) fn set_hinge_state(&mut self, angles: &[f64], turns: &[(f64, f64)]) {
        for ((h, &angle), &turn) in self.hinge_out.iter_mut().zip(angles).zip(turns) {
            *h = HingeOut {
                force: [DVec3::ZERO; 4],
                angle,
                turn,
            };
        }
        self.velocities.fill(DVec3::ZERO);
        self.kinetic = 0.0;
    }

    /// The unwrapped fold angle of every hinge after the last step, radians.
    pub fn angles(&self) -> Vec<f64> {
        self.hinge_out.iter().map(|h| h.angle).collect()
    }

    /// Whether every position is finite and within [`crate::limits::MAX_COORDINATE`] (a
    /// state beyond it has blown up, and no reader would accept it).
    pub fn finite(&self) -> bool {
        self.positions
            .iter()
            .all(|p| p.is_finite() && p.abs().max_element() <= crate::limits::MAX_COORDINATE)
    }

    /// Per-vertex masses that make a unit time step stable (see the module docs).
    fn stable_masses(&self) -> Vec<f64> {
        let n = self.positions.len();
        let mut lk = vec![0.0; n];
        let mut lc = vec![0.0; n];
        for (b, bar) in self.model.bars.iter().enumerate() {
            for v in bar.ends {
                lk[v as usize] += 2.0 * self.bar_k[b];
                lc[v as usize] += 2.0 * self.bar_c[b];
            }
        }
        for (h, hinge) in self.model.hinges.iter().enumerate() {
            let [j, k] = hinge.edge.map(|v| self.model.rest[v as usize]);
            let [i, l] = hinge.wings.map(|v| self.model.rest[v as usize]);
            let (_, g) = fold_angle_gradient(j, k, i, l);
            let sum: f64 = g.iter().map(|v| v.length()).sum();
            let corners = [hinge.edge[0], hinge.edge[1], hinge.wings[0], hinge.wings[1]];
            for (c, v) in corners.iter().enumerate() {
                lk[*v as usize] += self.hinge_k[h] * g[c].length() * sum;
            }
        }
        let s = STEP_SAFETY;
        lk.iter()
            .zip(&lc)
            .map(|(&a, &c)| ((a + 2.0 * s * c) / (4.0 * s * s)).max(f64::MIN_POSITIVE))
            .collect()
    }

    /// Advances one time step.
    pub fn step(&mut self) {
        let model = self.model;
        let (x, v) = (&self.positions, &self.velocities);
        let (bar_k, bar_c) = (&self.bar_k, &self.bar_c);
        let bar = |b: usize, out: &mut DVec3| {
            let [p, q] = model.bars[b].ends.map(|e| e as usize);
            let d = x[q] - x[p];
            let len = d.length();
            let spring = if len > 0.0 {
                d * (bar_k[b] * (len - model.bars[b].rest) / len)
            } else {
                DVec3::ZERO
            };
            *out = spring + (v[q] - v[p]) * bar_c[b];
        };
        let (hinge_k, full, fraction) = (&self.hinge_k, &self.hinge_full, self.fraction);
        let hinge = |h: usize, out: &mut HingeOut| {
            let hg = &model.hinges[h];
            let [j, k] = hg.edge.map(|e| x[e as usize]);
            let [i, l] = hg.wings.map(|e| x[e as usize]);
            // A degenerate triangle keeps its last angle and pulls nothing.
            out.force = [DVec3::ZERO; 4];
            if let Some((sin, cos, g)) = fold_turn_gradient(j, k, i, l) {
                out.angle += turn_from(out.turn, (sin, cos));
                out.turn = (sin, cos);
                let torque = -hinge_k[h] * (out.angle - fraction * full[h]);
                out.force = g.map(|gc| gc * torque);
            }
        };
        if self.parallel {
            let (bar_out, hinge_out) = (&mut self.bar_out, &mut self.hinge_out);
            rayon::join(
                || {
                    bar_out
                        .par_iter_mut()
                        .enumerate()
                        .with_min_len(1024)
                        .for_each(|(b, o)| bar(b, o))
                },
                || {
                    hinge_out
                        .par_iter_mut()
                        .enumerate()
                        .with_min_len(512)
                        .for_each(|(h, o)| hinge(h, o))
                },
            );
        } else {
            self.bar_out
                .iter_mut()
                .enumerate()
                .for_each(|(b, o)| bar(b, o));
            self.hinge_out
                .iter_mut()
                .enumerate()
                .for_each(|(h, o)| hinge(h, o));
        }
        self.integrate();
    }

    /// Gathers every vertex's force and integrates it with a unit step; kinetic damping
    /// (Barnes 1999) stops every vertex when the kinetic energy passes a peak.
    fn integrate(&mut self) {
        let (starts, slots) = (&self.slot_start, &self.slots);
        let (bars, hinges, mass) = (&self.bar_out, &self.hinge_out, &self.mass);
        let nb = 2 * bars.len() as u32;
        let gather = |vtx: usize| -> DVec3 {
            let mut f = DVec3::ZERO;
            for &s in &slots[starts[vtx] as usize..starts[vtx + 1] as usize] {
                f += if s < nb {
                    let b = bars[(s / 2) as usize];
                    if s & 1 == 0 { b } else { -b }
                } else {
                    let t = s - nb;
                    hinges[(t / 4) as usize].force[(t % 4) as usize]
                };
            }
            f
        };
        // Per vertex: its kinetic energy and the squared force on it.
        let update = |(vtx, (x, v)): (usize, (&mut DVec3, &mut DVec3))| -> (f64, f64) {
            let f = gather(vtx);
            *v += f / mass[vtx];
            *x += *v;
            (mass[vtx] * v.length_squared(), f.length_squared())
        };
        let add = |a: (f64, f64), b: (f64, f64)| (a.0 + b.0, a.1.max(b.1));
        let (kinetic, force2) = if self.parallel {
            self.positions
                .par_iter_mut()
                .zip(self.velocities.par_iter_mut())
                .enumerate()
                .with_min_len(1024)
                .map(update)
                .reduce(|| (0.0, 0.0), add)
        } else {
            self.positions
                .iter_mut()
                .zip(self.velocities.iter_mut())
                .enumerate()
                .map(update)
                .fold((0.0, 0.0), add)
        };
        self.step_force = force2.sqrt() / self.axial;
        if kinetic < self.kinetic {
            self.velocities.fill(DVec3::ZERO);
            self.kinetic = 0.0;
        } else {
            self.kinetic = kinetic;
        }
    }

    /// Largest force on a vertex without the damping, over the axial stiffness `EA`, at the
    /// current positions (a dimensionless residual: 1e-4 is the pull of a bar stretched by
    /// 0.01 %).
    pub fn residual(&self) -> f64 {
        let (x, model) = (&self.positions, self.model);
        let mut f = vec![DVec3::ZERO; x.len()];
        for (b, bar) in model.bars.iter().enumerate() {
            let [p, q] = bar.ends.map(|e| e as usize);
            let d = x[q] - x[p];
            let len = d.length();
            if len > 0.0 {
                let spring = d * (self.bar_k[b] * (len - bar.rest) / len);
                f[p] += spring;
                f[q] -= spring;
            }
        }
        for (h, hinge) in model.hinges.iter().enumerate() {
            let [j, k] = hinge.edge.map(|e| x[e as usize]);
            let [i, l] = hinge.wings.map(|e| x[e as usize]);
            // The angle followed from the last step as the step follows it.
            let Some((sin, cos, g)) = fold_turn_gradient(j, k, i, l) else {
                continue;
            };
            let last = &self.hinge_out[h];
            let angle = last.angle + turn_from(last.turn, (sin, cos));
            let torque = -self.hinge_k[h] * (angle - self.fraction * self.hinge_full[h]);
            let corners = [hinge.edge[0], hinge.edge[1], hinge.wings[0], hinge.wings[1]];
            for (c, v) in corners.iter().enumerate() {
                f[*v as usize] += g[c] * torque;
            }
        }
        f.iter().map(|v| v.length()).fold(0.0, f64::max) / self.axial
    }
}

/// Per vertex, the slots of the element forces acting on it: `2b`/`2b + 1` for the ends of bar
/// `b`, `2B + 4h + c` for corner `c` of hinge `h` (`B` bars).
fn incidence(model: &BarHingeModel) -> (Vec<u32>, Vec<u32>) {
    let n = model.rest.len();
    let mut lists: Vec<Vec<u32>> = vec![Vec::new(); n];
    for (b, bar) in model.bars.iter().enumerate() {
        lists[bar.ends[0] as usize].push(2 * b as u32);
        lists[bar.ends[1] as usize].push(2 * b as u32 + 1);
    }
    let nb = 2 * model.bars.len() as u32;
    for (h, hinge) in model.hinges.iter().enumerate() {
        let corners = [hinge.edge[0], hinge.edge[1], hinge.wings[0], hinge.wings[1]];
        for (c, v) in corners.iter().enumerate() {
            lists[*v as usize].push(nb + 4 * h as u32 + c as u32);
        }
    }
    let mut starts = Vec::with_capacity(n + 1);
    let mut slots = Vec::new();
    starts.push(0);
    for l in lists {
        slots.extend(l);
        starts.push(slots.len() as u32);
    }
    (starts, slots)
}
