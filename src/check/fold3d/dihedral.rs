//! The fold angle of a hinge and its gradient with respect to the four corners.
//!
//! For a hinge with edge `j → k` (counter-clockwise along its first triangle `j k i`) and
//! wings `i` (first triangle) and `l` (second triangle `k j l`), let `nA = (k − j) × (i − j)`
//! and `nB = (j − k) × (l − k)` be the triangles' normals (both +z in the flat sheet) and
//! `ê = (k − j)/|k − j|`. The fold angle is
//! `φ = atan2((n̂B × n̂A) · ê, n̂A · n̂B)`: 0 flat, positive when the wings rise towards the
//! sheet's front (a valley, FOLD's sign), ±π folded flat.
//!
//! The gradient is the classical one of the dihedral angle (Bridson et al. 2003; Liu & Paulino
//! 2017, eq. 27–30, with our sign): `∂φ/∂i = |e| nA/|nA|²`, `∂φ/∂l = |e| nB/|nB|²`, and with
//! `tᵢ = (i − j)·e/|e|²`, `tₗ = (l − j)·e/|e|²`,
//! `∂φ/∂j = −(1 − tᵢ) ∂φ/∂i − (1 − tₗ) ∂φ/∂l`, `∂φ/∂k = −tᵢ ∂φ/∂i − tₗ ∂φ/∂l`
//! (they sum to zero: a translation does not fold).

use glam::DVec3;

/// The fold angle (radians, in (−π, π]) and its gradient with respect to
/// `[j, k, i, l]` (see the module docs). A degenerate triangle (zero area or zero-length edge)
/// gives a zero gradient.
#[inline]
pub fn fold_angle_gradient(j: DVec3, k: DVec3, i: DVec3, l: DVec3) -> (f64, [DVec3; 4]) {
    match fold_turn_gradient(j, k, i, l) {
        Some((sin, cos, g)) => (sin.atan2(cos), g),
        None => (0.0, [DVec3::ZERO; 4]),
    }
}

/// `sin φ`, `cos φ` of the fold angle and its gradient with respect to `[j, k, i, l]`; `None`
/// for a degenerate triangle (zero area or zero-length edge). The angle itself is left to the
/// caller ([`turn_from`] follows it from step to step without an `atan2`).
#[inline]
pub fn fold_turn_gradient(
    j: DVec3,
    k: DVec3,
    i: DVec3,
    l: DVec3,
) -> Option<(f64, f64, [DVec3; 4])> {
    let e = k - j;
    let na = e.cross(i - j);
    let nb = (j - k).cross(l - k);
    let (na2, nb2, e2) = (na.length_squared(), nb.length_squared(), e.length_squared());
    if na2 <= 0.0 || nb2 <= 0.0 || e2 <= 0.0 {
        return None;
    }
    // Two square roots and two divisions (this runs for every hinge at every step):
    // `inv = 1/(|nA| |nB|)`, `1/|nA|² = |nB|² inv²`, `1/|e| = |e|/|e|²`.
    let el = e2.sqrt();
    let inv_e2 = 1.0 / e2;
    let inv = 1.0 / (na2 * nb2).sqrt();
    let cos = na.dot(nb) * inv;
    let sin = nb.cross(na).dot(e) * (inv * el * inv_e2);
    let inv2 = inv * inv;
    let gi = na * (el * nb2 * inv2);
    let gl = nb * (el * na2 * inv2);
    let ti = (i - j).dot(e) * inv_e2;
    let tl = (l - j).dot(e) * inv_e2;
    let gj = -(1.0 - ti) * gi - (1.0 - tl) * gl;
    let gk = -ti * gi - tl * gl;
    Some((sin, cos, [gj, gk, gi, gl]))
}

/// Below this `|sin Δ|` a turn `Δ` is summed from its series (error under 10⁻²³ rad).
const SERIES_TURN: f64 = 0.01;

/// The turn `Δ` in (−π, π] from an angle with sine and cosine `from` to one with `to` (both
/// unit pairs): `sin Δ = s₁c₀ − c₁s₀`, `cos Δ = c₁c₀ + s₁s₀`. A small turn (every step of a
/// settling fold) is `asin(sin Δ)` from its Taylor series, `x + x³/6 + 3x⁵/40 + 5x⁷/112 +
/// 35x⁹/1152`, which is several times cheaper than `atan2`; a large one is `atan2`.
#[inline]
pub fn turn_from(from: (f64, f64), to: (f64, f64)) -> f64 {
    let (s0, c0) = from;
    let (s1, c1) = to;
    let sin = s1 * c0 - c1 * s0;
    let cos = c1 * c0 + s1 * s0;
    if cos > 0.0 && sin.abs() < SERIES_TURN {
        let x2 = sin * sin;
        sin * (1.0
            + x2 * (1.0 / 6.0 + x2 * (3.0 / 40.0 + x2 * (5.0 / 112.0 + x2 * (35.0 / 1152.0)))))
    } else {
        sin.atan2(cos)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DQuat;

    /// The unit square split along x = y... here along the x axis: first triangle above.
    fn hinge(fold: f64) -> [DVec3; 4] {
        let j = DVec3::new(0.0, 0.0, 0.0);
        let k = DVec3::new(1.0, 0.0, 0.0);
        let i = DVec3::new(0.3, 1.0, 0.0);
        // The second wing lies at −y and is turned about the edge.
        let l0 = DVec3::new(0.6, -0.8, 0.0);
        let l = DQuat::from_axis_angle(DVec3::X, -fold) * l0;
        [j, k, i, l]
    }

    #[test]
    fn valley_is_positive_and_the_angle_is_the_turn() {
        for fold in [0.0, 0.4, -0.4, 1.5, -2.5, 3.0] {
            let [j, k, i, l] = hinge(fold);
            let (phi, _) = fold_angle_gradient(j, k, i, l);
            assert!((phi - fold).abs() < 1e-12, "{phi} vs {fold}");
        }
        // Valley: the wing rose to +z, the front side.
        assert!(hinge(0.4)[3].z > 0.0);
    }

    #[test]
    fn a_turn_followed_from_step_to_step_is_the_turn() {
        // Small steps (the series) and large ones (atan2), across ±π and round twice.
        let mut angle: f64 = 0.3;
        let mut at = (angle.sin(), angle.cos());
        for step in [1e-7, -3e-4, 0.009, -0.0099, 0.02, 1.0, 2.9, -3.1, 0.5] {
            for _ in 0..7 {
                let next = angle + step;
                let to = (next.sin(), next.cos());
                let turn = turn_from(at, to);
                assert!((turn - step).abs() < 1e-14, "{turn} vs {step}");
                angle = next;
                at = to;
            }
        }
        assert!(turn_from((0.0, 1.0), (0.0, -1.0)) == std::f64::consts::PI);
    }

    #[test]
    fn gradient_matches_finite_differences() {
        let mut p = hinge(0.7);
        p[2] += DVec3::new(0.05, 0.02, 0.3);
        let (_, g) = fold_angle_gradient(p[0], p[1], p[2], p[3]);
        let h = 1e-6;
        for c in 0..4 {
            for axis in 0..3 {
                let mut plus = p;
                let mut minus = p;
                plus[c][axis] += h;
                minus[c][axis] -= h;
                let fp = fold_angle_gradient(plus[0], plus[1], plus[2], plus[3]).0;
                let fm = fold_angle_gradient(minus[0], minus[1], minus[2], minus[3]).0;
                let numeric = (fp - fm) / (2.0 * h);
                assert!(
                    (numeric - g[c][axis]).abs() < 1e-6,
                    "corner {c} axis {axis}: {numeric} vs {}",
                    g[c][axis]
                );
            }
        }
    }
}
