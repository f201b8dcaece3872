//! A cylindrical patch fitted to a loop of cut lines, for the studio's cut-line editor: the
//! maker only draws cut lines, so each region they close needs a directrix and a ruling
//! without the thesis's hand-placed control points (Ōgaki 2016, §3.2 Step 2 places them by
//! hand; this fit is our addition).
//!
//! The loop's cut lines are sampled on the reference mesh. With `n_p` their mean normal (the
//! patch direction of §3.4) and a candidate ruling `r ⊥ n_p`, every sample `p` gets the
//! section coordinates `u = (p − c)·t`, `w = (p − c)·n_p` (c the samples' centroid,
//! `t = n_p × r`); the cross-section is fitted as `w(u)` by a least-squares polynomial of
//! degree [`SCORE_DEGREE`]. The ruling kept is the candidate (every [`COARSE_STEP_DEG`]° over
//! a half turn, then refined in 1° steps) with the smallest largest residual: for a
//! developable the surface is straight along the ruling, so the samples seen along it fall
//! on one curve. The directrix is then the degree-4 B-spline least-squares fit of
//! [`super::fit::fit_directrix`] to the samples projected along `r` onto the plane through
//! `c`, extended at both ends along its end tangents by `extend` (mesh units) so that the
//! patch reaches past the walls of the cut lines at the ends of the section.
//!
//! Limits: the section must be a graph over `u` (a patch whose normals turn by more than a
//! right angle from `n_p` is not fitted well); only the cut lines are sampled, not the mesh
//! inside the loop.

use glam::DVec3;

use super::PapercraftError;
use super::bspline::BSpline;
use super::cut_line::CutLine;
use super::fit::fit_directrix;
use crate::mesh::ReferenceMesh;

/// Samples per cut-line segment taken for the fit.
pub const SAMPLES_PER_SEGMENT: usize = 8;

/// Degree of the polynomial section used to score a ruling.
pub const SCORE_DEGREE: usize = 4;

/// Spacing of the first ruling candidates, degrees.
pub const COARSE_STEP_DEG: f64 = 5.0;

/// Control points of the fitted directrix (before the two added for the extensions).
pub const CONTROL_POINTS: usize = 9;

/// The normals cancel when their sum is shorter than this share of their count.
pub const CANCELLED: f64 = 1e-6;

/// Points added along each end tangent when extending the directrix.
const EXTENSION_POINTS: usize = 6;

/// A fitted cylindrical patch.
#[derive(Clone, Debug)]
pub struct FittedPatch {
    /// Directrix control points (degree-4 B-spline), mesh units.
    pub directrix: Vec<DVec3>,
    /// Unit ruling direction.
    pub ruling: DVec3,
    /// Largest distance of a cut-line sample from the fitted section, mesh units.
    pub residual: f64,
}

/// Fits a cylinder to the region bounded by `lines` (the loop's cut lines, any order or
/// direction), extending its directrix by `extend` mesh units at both ends.
///
/// # Errors
/// [`PapercraftError::NoPatchDirection`] (as patch `patch`) when the normals cancel out;
/// [`PapercraftError::BadParameter`] when the samples give no section (all on one ruling).
pub fn fit_cylinder(
    mesh: &ReferenceMesh,
    lines: &[&CutLine],
    extend: f64,
    patch: usize,
) -> Result<FittedPatch, PapercraftError> {
    let samples: Vec<DVec3> = lines
        .iter()
        .flat_map(|l| l.sample(mesh, SAMPLES_PER_SEGMENT))
        .collect();
    let normal_sum: DVec3 = samples.iter().map(|&p| mesh.project(p).normal).sum();
    if normal_sum.length() <= CANCELLED * samples.len() as f64 {
        return Err(PapercraftError::NoPatchDirection { patch });
    }
    let n_p = normal_sum.normalize();
    let centre = samples.iter().copied().sum::<DVec3>() / samples.len() as f64;
    let a = n_p.any_orthonormal_vector();
    let b = n_p.cross(a);
    let ruling_at = |deg: f64| {
        let th = deg.to_radians();
        a * th.cos() + b * th.sin()
    };
    let score = |deg: f64| section_residual(&samples, centre, n_p, ruling_at(deg));
    let coarse = (0..(180.0 / COARSE_STEP_DEG) as usize)
        .map(|k| k as f64 * COARSE_STEP_DEG)
        .min_by(|x, y| score(*x).total_cmp(&score(*y)))
        .unwrap_or(0.0);
    let best = (-(COARSE_STEP_DEG as i32)..=COARSE_STEP_DEG as i32)
        .map(|d| coarse + d as f64)
        .min_by(|x, y| score(*x).total_cmp(&score(*y)))
        .unwrap_or(coarse);
    let ruling = ruling_at(best);
    let t = n_p.cross(ruling);
    let u: Vec<f64> = samples.iter().map(|&p| (p - centre).dot(t)).collect();
    let section: Vec<DVec3> = samples
        .iter()
        .map(|&p| p - (p - centre).dot(ruling) * ruling)
        .collect();
    let count = CONTROL_POINTS.min(section.len());
    let first = fit_directrix(&section, &u, &vec![1.0; section.len()], count, 2)?;
    let residual = first.distances.iter().copied().fold(0.0, f64::max);
    let directrix = extended(&first.curve, extend, count + 2)?;
    Ok(FittedPatch {
        directrix,
        ruling,
        residual,
    })
}

/// Largest residual of the least-squares polynomial `w(u)` of the samples seen along `r`.
fn section_residual(samples: &[DVec3], centre: DVec3, n_p: DVec3, r: DVec3) -> f64 {
    let t = n_p.cross(r);
    let uw: Vec<(f64, f64)> = samples
        .iter()
        .map(|&p| ((p - centre).dot(t), (p - centre).dot(n_p)))
        .collect();
    let half = uw.iter().map(|(u, _)| u.abs()).fold(0.0, f64::max);
    if half <= 0.0 {
        return f64::INFINITY;
    }
    let m = SCORE_DEGREE + 1;
    let mut ata = vec![vec![0.0; m]; m];
    let mut atb = vec![0.0; m];
    for &(u, w) in &uw {
        let x = u / half;
        let powers: Vec<f64> = (0..m).map(|k| x.powi(k as i32)).collect();
        for i in 0..m {
            atb[i] += powers[i] * w;
            for j in 0..m {
                ata[i][j] += powers[i] * powers[j];
            }
        }
    }
    let Some(coef) = solve(ata, atb) else {
        return f64::INFINITY;
    };
    uw.iter()
        .map(|&(u, w)| {
            let x = u / half;
            let fit: f64 = coef.iter().rev().fold(0.0, |acc, c| acc * x + c);
            (w - fit).abs()
        })
        .fold(0.0, f64::max)
}

/// Gaussian elimination with partial pivoting; `None` for a singular system.
fn solve(mut a: Vec<Vec<f64>>, mut b: Vec<f64>) -> Option<Vec<f64>> {
    let n = b.len();
    for col in 0..n {
        let pivot = (col..n).max_by(|&i, &j| a[i][col].abs().total_cmp(&a[j][col].abs()))?;
        if a[pivot][col].abs() < f64::EPSILON * n as f64 {
            return None;
        }
        a.swap(col, pivot);
        b.swap(col, pivot);
        let pivot_row = a[col].clone();
        for row in col + 1..n {
            let f = a[row][col] / pivot_row[col];
            for (x, p) in a[row][col..].iter_mut().zip(&pivot_row[col..]) {
                *x -= f * p;
            }
            b[row] -= f * b[col];
        }
    }
    let mut x = vec![0.0; n];
    for row in (0..n).rev() {
        let s: f64 = (row + 1..n).map(|k| a[row][k] * x[k]).sum();
        x[row] = (b[row] - s) / a[row][row];
    }
    Some(x)
}

/// The control points of `curve` extended by `length` along its end tangents, refitted with
/// `count` control points.
fn extended(curve: &BSpline, length: f64, count: usize) -> Result<Vec<DVec3>, PapercraftError> {
    let spans = curve.spans() as f64;
    let inner = 16 * curve.spans();
    let mut points: Vec<DVec3> = (0..=inner)
        .map(|k| curve.at(spans * k as f64 / inner as f64))
        .collect();
    let d = curve.derivative();
    let start_dir = (-d.at(0.0)).normalize_or_zero();
    let end_dir = d.at(spans).normalize_or_zero();
    let (start, end) = (points[0], points[inner]);
    let before: Vec<DVec3> = (1..=EXTENSION_POINTS)
        .rev()
        .map(|k| start + start_dir * length * k as f64 / EXTENSION_POINTS as f64)
        .collect();
    points.splice(0..0, before);
    points.extend(
        (1..=EXTENSION_POINTS).map(|k| end + end_dir * length * k as f64 / EXTENSION_POINTS as f64),
    );
    let mut params = vec![0.0];
    for w in points.windows(2) {
        params.push(params[params.len() - 1] + (w[1] - w[0]).length());
    }
    let fit = fit_directrix(&points, &params, &vec![1.0; points.len()], count, 2)?;
    Ok(fit.curve.control().to_vec())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::design::papercraft::cylinder::CylinderPatch;
    use crate::design::papercraft::shapes::revolution;

    /// A circular cylinder of radius 30 round the z axis, 0 ≤ z ≤ 60.
    fn tube() -> ReferenceMesh {
        let profile: Vec<(f64, f64)> = (0..=6).map(|k| (30.0, 10.0 * k as f64)).collect();
        ReferenceMesh::new(&revolution(&profile, 96).unwrap()).unwrap()
    }

    fn arc(r: f64, z: f64, from: f64, to: f64) -> Vec<DVec3> {
        (0..=4)
            .map(|k| {
                let a = (from + (to - from) * k as f64 / 4.0).to_radians();
                DVec3::new(r * a.cos(), r * a.sin(), z)
            })
            .collect()
    }

    #[test]
    fn a_patch_of_a_cylinder_gets_its_axis_as_ruling() {
        // A 90° window on the tube: two arcs (z = 10, 50) and two vertical lines. The surface
        // is a cylinder with rulings along z, so the fit must find z (up to sign) and a
        // section that is the circle of radius 30.
        let mesh = tube();
        let lines = [
            CutLine::new(0, arc(30.0, 10.0, 0.0, 90.0)).unwrap(),
            CutLine::new(
                1,
                vec![DVec3::new(0.0, 30.0, 10.0), DVec3::new(0.0, 30.0, 50.0)],
            )
            .unwrap(),
            CutLine::new(2, arc(30.0, 50.0, 90.0, 0.0)).unwrap(),
            CutLine::new(
                3,
                vec![DVec3::new(30.0, 0.0, 50.0), DVec3::new(30.0, 0.0, 10.0)],
            )
            .unwrap(),
        ];
        let refs: Vec<&CutLine> = lines.iter().collect();
        let fit = fit_cylinder(&mesh, &refs, 10.0, 0).unwrap();
        assert!(
            fit.ruling.z.abs() > (2.0f64).to_radians().cos(),
            "{:?}",
            fit.ruling
        );
        // Chord error of the 96-gon mesh: 30·(1 − cos(π/96)) ≈ 0.016.
        assert!(fit.residual < 0.05, "residual {}", fit.residual);
        let patch = CylinderPatch::new(
            BSpline::directrix(fit.directrix, "fit").unwrap(),
            fit.ruling,
        )
        .unwrap();
        // The middle of the section (away from the straight extensions) lies on the circle,
        // to the mesh's chord error and the fit.
        for k in 7..=13 {
            let p = patch.point(patch.u_max() * k as f64 / 20.0, 0.0);
            let radius = (p.x * p.x + p.y * p.y).sqrt();
            assert!((radius - 30.0).abs() < 0.1, "k {k}: {radius}");
        }
        // The section is longer than the 90° arc (47.1) by about the two extensions.
        let length = patch.section_length();
        assert!(length > 47.1 + 15.0, "section {length}");
    }

    #[test]
    fn cancelling_normals_are_refused() {
        // Two half rings round the tube, one the other turned by 180°: the normals along
        // them sum to nothing.
        let mesh = tube();
        let a = CutLine::new(0, arc(30.0, 30.0, 0.0, 180.0)).unwrap();
        let b = CutLine::new(1, arc(30.0, 30.0, 180.0, 360.0)).unwrap();
        let err = fit_cylinder(&mesh, &[&a, &b], 10.0, 3).unwrap_err();
        assert_eq!(err, PapercraftError::NoPatchDirection { patch: 3 });
    }
}
