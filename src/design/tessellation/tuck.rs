//! The tuck inserted behind one vertex: the star of Tachi (2014) §2.1 and the variations of §2.2 (Fig. 6).
//!
//! A tuck is built from the vertex's **arms**, one per gap that opens between two faces at
//! the vertex: arm `i` runs from the face corner `c_i` (`own`) over the star tip `t_i` to the
//! next face corner `c_{i+1}` (`other`, the `own` of arm `i + 1`). Around an interior vertex
//! the arms close into a ring; at a boundary vertex they form an open chain. With `k` the key
//! vertex behind the surface, the four structures are:
//!
//! - **star** (§2.1): triangles `(k, t_i, c_i)` and `(k, c_{i+1}, t_i)`; `k–c_i` mountains,
//!   `k–t_i` valleys.
//! - **truncated star** (§2.2 切頂星): the key vertex is pulled out radially into a flat
//!   n-gon `q_0 … q_{n−1}`, `q_i` lying from `k` towards `c_i` in the tangent plane at the
//!   fraction [`TuckShape::truncation`] of the way. The valley `k–t_i` becomes a thin triangle
//!   `(q_{i+1}, t_i, q_i)` between two valleys `q_i–t_i`, `q_{i+1}–t_i` (each taking about
//!   half the fold); the n-gon is fanned into triangles with flat diagonals.
//! - **twisted star** (§2.2 ひねり星): a fold is added to each of the 2n star triangles: a new
//!   vertex `m_i` on every valley, half way from `k` to `t_i` and turned about the vertex
//!   normal by [`TuckShape::twist`], with creases `m_i–c_i` and `m_i–c_{i+1}`; the valley
//!   becomes the bent line `k–m_i–t_i`.
//! - **twist fold** (§2.2 ねじり折り): the twisted star with its apex pressed flat, i.e. both
//!   at once: the flat n-gon with the triangular pleats `(q_{i+1}, m_i, q_i)`, `m_i` half way
//!   from the n-gon edge's midpoint to `t_i`, turned by the twist.
//!
//! The solver moves every new vertex freely, so the truncation size and the twist are the
//! free parameters the paper describes: they change during the solve to fit the curvature.
//! The n-gon rims take their mountain/valley from the initial geometry
//! ([`EdgeRole::TruncationRim`]); the twist folds ([`EdgeRole::TwistFold`]) are left free
//! during the solve (only their fold magnitude is bounded) and take the direction they fold
//! in the solved form, since the twist may turn either way and differently in each arm.
//!
//! Deviations, where the paper says nothing: a boundary vertex (an open chain of arms) is
//! never truncated (its key vertex stays; a flat polygon would need an edge on the sheet
//! boundary); a twisted tuck needs a non-zero initial twist, since its added creases are
//! otherwise flat.
//!
//! Measured (0.5 mm stainless limits, release build, checkerboard layout, shrink 0.8): with
//! each twist fold's direction fixed from the initial pattern, twisted stars stalled on
//! `spherical_cap(6, 5, 20, 100)` (not converged after 300 iterations, 113 of its 420 twist
//! folds then folded more than 0.5° against their sign, mostly both folds of one twist vertex
//! together: the arm had turned the other way). With the direction free they converge there in 164 iterations
//! and on `spherical_cap(6, 6, 20, 100)` in 177, but the solve unwinds most twists: the
//! twist folds end at a median of 0.8° (90 % under 14°, largest 48°) on the five-ring cap.
//! The 432-face cap (`spherical_cap(12, 6, 60, 100)`) stalled with twisted stars
//! (re-triangulated to 450 faces, shrink 0.8: line search without descent after 188
//! iterations at developability 1.2e-2 rad, largest fold 166.8°, smallest crease angle
//! 29.6°, about 1,700 fold-limit and crease-angle rows active beside the 1,450
//! developability rows; most accepted steps before it were under 1e-3 of the Newton step). With the
//! Levenberg–Marquardt fallback ([`SolveOptions::damped_fallback`](super::SolveOptions::damped_fallback))
//! and four times the iteration cap ([`TWISTED_ITERATIONS`](super::pipeline::TWISTED_ITERATIONS)), which
//! [`tessellate`](super::tessellate) gives twisted stars, it converges in 424 iterations
//! (release, 20 s) within the 0.5 mm stainless limits. `spherical_cap(6, 6, 1, 100)` stalled
//! too without them (after 132 iterations at 3.8e-2 rad of developability).

use std::collections::HashMap;

use glam::{DQuat, DVec3};

use super::model::EdgeRole;

/// Which tuck structure to insert (§2.1, §2.2).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum TuckKind {
    /// Star tuck (§2.1).
    #[default]
    Star,
    /// Truncated star: the key vertex becomes a flat n-gon (§2.2).
    Truncated,
    /// Twisted star: a fold in each star triangle (§2.2).
    Twisted,
    /// Twist fold: a twisted star with a flat n-gon (§2.2).
    TwistFold,
}

impl std::fmt::Display for TuckKind {
    /// The names used in help text and reports ("twist-fold tucks").
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Self::Star => "star",
            Self::Truncated => "truncated-star",
            Self::Twisted => "twisted-star",
            Self::TwistFold => "twist-fold",
        })
    }
}

impl TuckKind {
    /// Whether the key vertex becomes a flat n-gon.
    pub fn truncated(self) -> bool {
        matches!(self, TuckKind::Truncated | TuckKind::TwistFold)
    }

    /// Whether each star triangle gets a twist fold.
    pub fn twisted(self) -> bool {
        matches!(self, TuckKind::Twisted | TuckKind::TwistFold)
    }
}

/// The tuck structure and its initial parameters.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TuckShape {
    /// The structure.
    pub kind: TuckKind,
    /// Size of the flat n-gon: how far each of its corners lies from the key vertex towards
    /// its face corner (in the tangent plane), as a fraction in (0, 1).
    pub truncation: f64,
    /// Initial twist of the added vertices about the vertex normal, radians, |twist| < π/2.
    pub twist: f64,
}

impl Default for TuckShape {
    fn default() -> Self {
        TuckShape {
            kind: TuckKind::Star,
            truncation: 0.3,
            twist: 15f64.to_radians(),
        }
    }
}

impl TuckShape {
    /// Checks the parameters the kind uses; the message names the bad one.
    pub fn validate(&self) -> Result<(), String> {
        if self.kind.truncated() && !(self.truncation > 0.0 && self.truncation < 1.0) {
            return Err(format!(
                "truncation must be in (0, 1), got {}",
                self.truncation
            ));
        }
        if self.kind.twisted()
            && !(self.twist.is_finite()
                && self.twist != 0.0
                && self.twist.abs() < std::f64::consts::FRAC_PI_2)
        {
            return Err(format!(
                "twist must be non-zero and within (-90, 90) degrees, got {}",
                self.twist.to_degrees()
            ));
        }
        Ok(())
    }
}

/// One arm of a tuck: the gap between the face corners `own` and `other`, closed at `tip`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) struct Arm {
    pub own: u32,
    pub tip: u32,
    pub other: u32,
}

/// The growing tessellation the tucks are added to.
pub(super) struct Builder {
    pub positions: Vec<DVec3>,
    pub triangles: Vec<[u32; 3]>,
    pub roles: HashMap<(u32, u32), EdgeRole>,
    pub input_vertex: Vec<u32>,
}

impl Builder {
    fn vertex(&mut self, p: DVec3, input: u32) -> u32 {
        self.positions.push(p);
        self.input_vertex.push(input);
        (self.positions.len() - 1) as u32
    }

    fn role(&mut self, a: u32, b: u32, role: EdgeRole) {
        self.roles.insert((a, b), role);
    }
}

/// Puts `arms` in chain order (each arm's `other` is the next arm's `own`) and says whether
/// they close into a ring. `None` when they do not form one chain.
pub(super) fn chain(arms: &[Arm]) -> Option<(Vec<Arm>, bool)> {
    let by_own: HashMap<u32, usize> = arms.iter().enumerate().map(|(i, a)| (a.own, i)).collect();
    let others: std::collections::HashSet<u32> = arms.iter().map(|a| a.other).collect();
    let start = arms.iter().position(|a| !others.contains(&a.own));
    let cyclic = start.is_none();
    let mut at = start.unwrap_or(0);
    let mut out = Vec::with_capacity(arms.len());
    for _ in 0..arms.len() {
        out.push(arms[at]);
        match by_own.get(&arms[at].other) {
            Some(&next) => at = next,
            None => break,
        }
    }
    (out.len() == arms.len() && (!cyclic || out[0].own == out[out.len() - 1].other))
        .then_some((out, cyclic))
}

/// Inserts the tuck of input vertex `input` with key position `key` and unit normal `normal`
/// (front side) over `arms` in chain order. Returns the key vertex (none when truncated).
pub(super) fn insert(
    b: &mut Builder,
    input: u32,
    key: DVec3,
    normal: DVec3,
    arms: &[Arm],
    cyclic: bool,
    shape: &TuckShape,
) -> Option<u32> {
    let truncate = shape.kind.truncated() && cyclic && arms.len() >= 3;
    let twist = shape.kind.twisted();
    // Apex per face corner: the key vertex, or the n-gon corner q_i towards c_i.
    let apex: Vec<u32> = if truncate {
        arms.iter()
            .map(|a| {
                let to = b.positions[a.own as usize] - key;
                let tangent = to - to.dot(normal) * normal;
                b.vertex(key + shape.truncation * tangent, input)
            })
            .collect()
    } else {
        vec![b.vertex(key, input)]
    };
    let n = arms.len();
    let apex_of = |i: usize| apex[if truncate { i % n } else { 0 }];
    let turn = DQuat::from_axis_angle(normal, shape.twist);
    for (i, arm) in arms.iter().enumerate() {
        let (a, z) = (apex_of(i), apex_of(i + 1));
        let (pa, pz) = (b.positions[a as usize], b.positions[z as usize]);
        let tip = b.positions[arm.tip as usize];
        b.role(a, arm.own, EdgeRole::KeyCorner);
        b.role(z, arm.other, EdgeRole::KeyCorner);
        // The valley end: the tip itself, or the twist vertex m_i on the way to it.
        let end = if twist {
            let base = 0.5 * (pa + pz);
            let m = key + turn * (base + 0.5 * (tip - base) - key);
            let m = b.vertex(m, input);
            b.triangles.push([a, m, arm.own]);
            b.triangles.push([m, arm.tip, arm.own]);
            b.triangles.push([z, arm.other, m]);
            b.triangles.push([m, arm.other, arm.tip]);
            b.role(m, arm.tip, EdgeRole::KeyTip);
            b.role(m, arm.own, EdgeRole::TwistFold);
            b.role(m, arm.other, EdgeRole::TwistFold);
            m
        } else {
            b.triangles.push([a, arm.tip, arm.own]);
            b.triangles.push([z, arm.other, arm.tip]);
            arm.tip
        };
        b.role(a, end, EdgeRole::KeyTip);
        b.role(z, end, EdgeRole::KeyTip);
        if truncate {
            b.triangles.push([z, end, a]);
            b.role(a, z, EdgeRole::TruncationRim);
        }
    }
    if truncate {
        // The n-gon, counter-clockwise about the front normal: q_{n−1}, …, q_0 (each thin
        // triangle holds q_i → q_{i+1}). Fanned from its first corner with flat diagonals.
        let ring: Vec<u32> = apex.iter().rev().copied().collect();
        for k in 1..n - 1 {
            b.triangles.push([ring[0], ring[k], ring[k + 1]]);
            if k > 1 {
                b.role(ring[0], ring[k], EdgeRole::Diagonal);
            }
        }
        None
    } else {
        Some(apex[0])
    }
}
