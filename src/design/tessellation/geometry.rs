//! Triangle angles, fold angles and relative heights with their analytic gradients: the
//! building blocks of the constraint Jacobian (eq. 8 of Tachi 2014 applies the chain rule through these).
//!
//! Conventions. A corner angle θ of triangle `(o, a, b)` at `o`. A fold angle ρ of the edge
//! `i → j` between triangle `p = (i, j, a)` and `q = (j, i, b)` (both counter-clockwise about
//! their front normals): zero when flat, positive for a valley (the front sides turn towards
//! each other, FOLD's sign), in (−π, π]. The relative height `h_p` of `p` over the edge is
//! `2·area(p) / |e|²`, the height divided by the edge length (Fig. 7).

use glam::DVec3;

/// A value with its gradient with respect to a few vertices (vertex index, ∂/∂x).
#[derive(Clone, Debug, PartialEq)]
pub struct Graded<const N: usize> {
    /// The value.
    pub value: f64,
    /// Gradient blocks, one per vertex in the order the function documents.
    pub grad: [DVec3; N],
}

/// Corner angle at `o` of the triangle `(o, a, b)`, in radians, with gradients `[o, a, b]`.
/// Gradients are zero for a degenerate corner (θ = 0 or π), where the angle is not smooth.
pub fn corner_angle(o: DVec3, a: DVec3, b: DVec3) -> Graded<3> {
    let (u, w) = (a - o, b - o);
    let cross = u.cross(w);
    let value = cross.length().atan2(u.dot(w));
    let n = cross.normalize_or_zero();
    let (uu, ww) = (u.length_squared(), w.length_squared());
    if n == DVec3::ZERO || uu == 0.0 || ww == 0.0 {
        return Graded {
            value,
            grad: [DVec3::ZERO; 3],
        };
    }
    let ga = -n.cross(u) / uu;
    let gb = n.cross(w) / ww;
    Graded {
        value,
        grad: [-(ga + gb), ga, gb],
    }
}

/// Twice the area of the triangle `(x0, x1, x2)`, with gradients `[x0, x1, x2]`.
pub fn double_area(x0: DVec3, x1: DVec3, x2: DVec3) -> Graded<3> {
    let cross = (x1 - x0).cross(x2 - x0);
    let n = cross.normalize_or_zero();
    Graded {
        value: cross.length(),
        grad: [n.cross(x2 - x1), n.cross(x0 - x2), n.cross(x1 - x0)],
    }
}

/// Fold angle ρ of the edge `i → j` between `p = (i, j, a)` and `q = (j, i, b)`, with
/// gradients `[i, j, a, b]` (zero when either triangle is degenerate).
pub fn fold_angle(i: DVec3, j: DVec3, a: DVec3, b: DVec3) -> Graded<4> {
    let e = j - i;
    let np = e.cross(a - i);
    let nq = (i - j).cross(b - j);
    let el = e.length();
    let value = if el == 0.0 {
        0.0
    } else {
        nq.cross(np).dot(e / el).atan2(np.dot(nq))
    };
    let (ap, aq) = (np.length_squared(), nq.length_squared());
    if el == 0.0 || ap == 0.0 || aq == 0.0 {
        return Graded {
            value,
            grad: [DVec3::ZERO; 4],
        };
    }
    // ∂ρ/∂a = |e| N_p / |N_p|², ∂ρ/∂b = |e| N_q / |N_q|² (unnormalised normals); the edge
    // ends take the rest by the feet of a and b on the edge (rigid motions leave ρ unchanged).
    let ga = el * np / ap;
    let gb = el * nq / aq;
    let ta = (a - i).dot(e) / (el * el);
    let tb = (b - i).dot(e) / (el * el);
    let gi = -((1.0 - ta) * ga + (1.0 - tb) * gb);
    let gj = -(ta * ga + tb * gb);
    Graded {
        value,
        grad: [gi, gj, ga, gb],
    }
}

/// Relative height `h = 2·area / |e|²` of the triangle `(i, j, a)` over its edge `i j`, with
/// gradients `[i, j, a]`.
pub fn relative_height(i: DVec3, j: DVec3, a: DVec3) -> Graded<3> {
    let area2 = double_area(i, j, a);
    let e = j - i;
    let ee = e.length_squared();
    let value = area2.value / ee;
    let d_ee_j = 2.0 * e;
    let grad = [
        area2.grad[0] / ee + area2.value * d_ee_j / (ee * ee),
        area2.grad[1] / ee - area2.value * d_ee_j / (ee * ee),
        area2.grad[2] / ee,
    ];
    Graded { value, grad }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn numeric<const N: usize>(f: impl Fn(&[DVec3; N]) -> f64, x: [DVec3; N]) -> [DVec3; N] {
        let h = 1e-6;
        let mut g = [DVec3::ZERO; N];
        for k in 0..N {
            for c in 0..3 {
                let (mut up, mut down) = (x, x);
                up[k][c] += h;
                down[k][c] -= h;
                g[k][c] = (f(&up) - f(&down)) / (2.0 * h);
            }
        }
        g
    }

    fn close<const N: usize>(a: [DVec3; N], b: [DVec3; N]) {
        for k in 0..N {
            assert!((a[k] - b[k]).length() < 1e-6, "{a:?} vs {b:?}");
        }
    }

    const P: [DVec3; 4] = [
        DVec3::new(0.1, -0.2, 0.3),
        DVec3::new(1.3, 0.1, -0.2),
        DVec3::new(0.4, 1.1, 0.5),
        DVec3::new(0.7, -0.9, 0.8),
    ];

    #[test]
    fn gradients_match_finite_differences() {
        let x3 = [P[0], P[1], P[2]];
        close(
            corner_angle(P[0], P[1], P[2]).grad,
            numeric(|x| corner_angle(x[0], x[1], x[2]).value, x3),
        );
        close(
            relative_height(P[0], P[1], P[2]).grad,
            numeric(|x| relative_height(x[0], x[1], x[2]).value, x3),
        );
        close(
            fold_angle(P[0], P[1], P[2], P[3]).grad,
            numeric(|x| fold_angle(x[0], x[1], x[2], x[3]).value, P),
        );
    }

    #[test]
    fn valley_is_positive() {
        let (i, j) = (DVec3::ZERO, DVec3::X);
        let a = DVec3::new(0.5, 1.0, 0.0);
        let up = fold_angle(i, j, a, DVec3::new(0.5, -1.0, 1.0)).value;
        let flat = fold_angle(i, j, a, DVec3::new(0.5, -1.0, 0.0)).value;
        assert!((up - std::f64::consts::FRAC_PI_4).abs() < 1e-12, "{up}");
        assert!(flat.abs() < 1e-15);
        let right = corner_angle(i, j, a).value;
        assert!((right - 1.0f64.atan2(0.5)).abs() < 1e-15);
    }
}
