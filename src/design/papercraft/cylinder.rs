//! Cylindrical developable patches (Ōgaki 2016, §3.2 Step 2) and their isometric unrolling.
//!
//! A patch is the ruled surface `S(u, v) = c(u) + v·d` swept by lines of unit direction `d`
//! (the ruling, "直線エレメント") along the degree-4 B-spline directrix `c` ("測地線" in the
//! thesis). All rulings are parallel, so the surface is a (generalised) cylinder and
//! developable.
//!
//! Unrolling: let `c⊥(u) = c(u) − (c(u)·d) d` be the orthogonal section (the directrix
//! projected onto the plane normal to `d`) and `s(u) = ∫₀ᵘ |c⊥'(t)| dt` its arc length. The
//! map `(u, v) ↦ (s(u), v + c(u)·d)` is an isometry: its first fundamental form is
//! `E = s'² + (c'·d)² = |c'|²`, `F = c'·d`, `G = 1`, the same as the surface's. Sections
//! unroll onto horizontal lines `y = const` only up to the shift `c(u)·d`, which is how a
//! directrix oblique to `d` is handled. Arc length is integrated by 8-point Gauss–Legendre
//! on 16 sub-intervals per knot span (exact to rounding for a smooth section; accuracy drops
//! near a point where the directrix runs parallel to the ruling, where the section has a cusp).

use glam::{DVec2, DVec3};

use super::PapercraftError;
use super::bspline::BSpline;
use crate::geom::tolerance::TINY;

/// Arc-length inversion stops when the bracket is this share of the section's length: a few
/// ulps of f64.
const ARC_LENGTH_RELATIVE: f64 = 1e-14;

/// Newton's method on a Legendre polynomial stops at a step this small: the nodes lie in
/// [−1, 1], so this is the round-off of f64 near 1.
const ROOT_STEP: f64 = 1e-16;

const SUBDIVISIONS: usize = 16;
const GAUSS_POINTS: usize = 8;

/// A cylindrical patch: directrix and ruling direction, with the section's arc-length table.
#[derive(Clone, Debug)]
pub struct CylinderPatch {
    directrix: BSpline,
    derivative: BSpline,
    ruling: DVec3,
    gauss: Vec<(f64, f64)>,
    /// Arc length of the section at `u = k / SUBDIVISIONS`.
    table: Vec<f64>,
}

impl CylinderPatch {
    /// A patch from its directrix and ruling direction (any finite non-zero vector; it is
    /// normalised). Refuses a directrix whose section has zero length (the directrix runs
    /// along the ruling, so the surface is a line).
    pub fn new(directrix: BSpline, ruling: DVec3) -> Result<Self, PapercraftError> {
        let ruling = ruling.try_normalize().ok_or_else(|| {
            PapercraftError::BadParameter("ruling direction must be non-zero".into())
        })?;
        let derivative = directrix.derivative();
        let mut patch = CylinderPatch {
            directrix,
            derivative,
            ruling,
            gauss: gauss_legendre(GAUSS_POINTS),
            table: Vec::new(),
        };
        let steps = patch.directrix.spans() * SUBDIVISIONS;
        let h = 1.0 / SUBDIVISIONS as f64;
        let mut acc = 0.0;
        patch.table.push(0.0);
        for k in 0..steps {
            acc += patch.section_length_between(k as f64 * h, (k + 1) as f64 * h);
            patch.table.push(acc);
        }
        if acc.is_nan() || acc <= 0.0 {
            return Err(PapercraftError::BadParameter(
                "the directrix runs along the ruling (its section has no length)".into(),
            ));
        }
        Ok(patch)
    }

    /// The directrix.
    pub fn directrix(&self) -> &BSpline {
        &self.directrix
    }

    /// The unit ruling direction.
    pub fn ruling(&self) -> DVec3 {
        self.ruling
    }

    /// Parameter domain of the directrix, `[0, u_max]`.
    pub fn u_max(&self) -> f64 {
        self.directrix.spans() as f64
    }

    /// The surface point `S(u, v) = c(u) + v·d`.
    pub fn point(&self, u: f64, v: f64) -> DVec3 {
        self.directrix.at(u) + v * self.ruling
    }

    /// Unit surface normal `c'(u) × d` normalised (zero where the directrix is parallel to
    /// the ruling).
    pub fn normal(&self, u: f64) -> DVec3 {
        self.derivative.at(u).cross(self.ruling).normalize_or_zero()
    }

    /// Speed of the orthogonal section, `|c⊥'(u)|`.
    fn section_speed(&self, u: f64) -> f64 {
        let t = self.derivative.at(u);
        (t - t.dot(self.ruling) * self.ruling).length()
    }

    fn section_length_between(&self, a: f64, b: f64) -> f64 {
        let (mid, half) = (0.5 * (a + b), 0.5 * (b - a));
        self.gauss
            .iter()
            .map(|&(x, w)| w * self.section_speed(mid + half * x))
            .sum::<f64>()
            * half
    }

    /// Arc length `s(u)` of the orthogonal section from `u = 0` (u clamped to the domain).
    pub fn section_arc_length(&self, u: f64) -> f64 {
        let u = u.clamp(0.0, self.u_max());
        let k = ((u * SUBDIVISIONS as f64).floor() as usize).min(self.table.len() - 2);
        let u0 = k as f64 / SUBDIVISIONS as f64;
        self.table[k] + self.section_length_between(u0, u)
    }

    /// Total section length (the unrolled width).
    pub fn section_length(&self) -> f64 {
        self.table[self.table.len() - 1]
    }

    /// The unrolled position of `S(u, v)`: `(s(u), v + c(u)·d)`.
    pub fn unroll(&self, u: f64, v: f64) -> DVec2 {
        DVec2::new(
            self.section_arc_length(u),
            v + self.directrix.at(u).dot(self.ruling),
        )
    }

    /// The inverse of [`Self::unroll`]: `(u, v)` of a flat point whose x lies in
    /// `[0, section_length]` (clamped). Newton steps on `s(u) = x`, kept inside a bisection
    /// bracket, to `1e-14` of the section length.
    pub fn roll(&self, flat: DVec2) -> (f64, f64) {
        let x = flat.x.clamp(0.0, self.section_length());
        let (mut lo, mut hi) = (0.0, self.u_max());
        let mut u = self.u_max() * x / self.section_length();
        let tol = ARC_LENGTH_RELATIVE * self.section_length().max(TINY);
        for _ in 0..100 {
            let f = self.section_arc_length(u) - x;
            if f.abs() <= tol {
                break;
            }
            if f > 0.0 {
                hi = u
            } else {
                lo = u
            }
            let speed = self.section_speed(u);
            let newton = u - f / speed;
            u = if speed > 0.0 && newton > lo && newton < hi {
                newton
            } else {
                0.5 * (lo + hi)
            };
        }
        (u, flat.y - self.directrix.at(u).dot(self.ruling))
    }

    /// The 3D point whose unrolled position is `flat`.
    pub fn point_of_flat(&self, flat: DVec2) -> DVec3 {
        let (u, v) = self.roll(flat);
        self.point(u, v)
    }
}

/// Nodes and weights of n-point Gauss–Legendre quadrature on [−1, 1] (Newton on the Legendre
/// polynomial from the usual cosine guesses).
pub(crate) fn gauss_legendre(n: usize) -> Vec<(f64, f64)> {
    (0..n)
        .map(|i| {
            let mut x = (std::f64::consts::PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
            let mut dp = 1.0;
            for _ in 0..100 {
                let (mut p0, mut p1) = (1.0, x);
                for k in 2..=n {
                    let p2 = ((2 * k - 1) as f64 * x * p1 - (k - 1) as f64 * p0) / k as f64;
                    p0 = p1;
                    p1 = p2;
                }
                dp = n as f64 * (x * p1 - p0) / (x * x - 1.0);
                let step = p1 / dp;
                x -= step;
                if step.abs() < ROOT_STEP {
                    break;
                }
            }
            (x, 2.0 / ((1.0 - x * x) * dp * dp))
        })
        .collect()
}
