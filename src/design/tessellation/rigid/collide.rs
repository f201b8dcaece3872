//! Face collisions along the rigid folding path: every pair of triangles (faces fanned into
//! triangles) that share no vertex, swept in x order, tested edge against triangle.

use glam::{DMat3, DVec3};

use super::RigidModel;
use crate::geom::tolerance::RELATIVE;

impl RigidModel {
    /// First pair of triangles sharing no vertex that intersect, as face indices.
    pub(super) fn collision(&self, frames: &[(DMat3, DVec3)]) -> Option<[usize; 2]> {
        let tris: Vec<[DVec3; 3]> = self
            .triangles
            .iter()
            .zip(&self.triangle_face)
            .map(|(t, &f)| t.map(|v| frames[f].0 * self.flat[v] + frames[f].1))
            .collect();
        let tol = RELATIVE * self.scale;
        let lo = |t: &[DVec3; 3]| t.iter().map(|p| p.x).fold(f64::INFINITY, f64::min);
        let hi = |t: &[DVec3; 3]| t.iter().map(|p| p.x).fold(f64::NEG_INFINITY, f64::max);
        let mut order: Vec<usize> = (0..tris.len()).collect();
        order.sort_by(|&a, &b| lo(&tris[a]).total_cmp(&lo(&tris[b])));
        for (n, &a) in order.iter().enumerate() {
            for &b in &order[n + 1..] {
                if lo(&tris[b]) > hi(&tris[a]) + tol {
                    break;
                }
                let shared = self.triangles[a]
                    .iter()
                    .any(|v| self.triangles[b].contains(v));
                if !shared && triangles_intersect(&tris[a], &tris[b], tol) {
                    let (fa, fb) = (self.triangle_face[a], self.triangle_face[b]);
                    return Some([fa.min(fb), fa.max(fb)]);
                }
            }
        }
        None
    }
}

/// Whether two triangles intersect by more than `tol`: an edge of one crosses the interior
/// of the other (coplanar contact is not counted).
fn triangles_intersect(a: &[DVec3; 3], b: &[DVec3; 3], tol: f64) -> bool {
    (0..3).any(|k| segment_hits(a[k], a[(k + 1) % 3], b, tol))
        || (0..3).any(|k| segment_hits(b[k], b[(k + 1) % 3], a, tol))
}

fn segment_hits(p: DVec3, q: DVec3, t: &[DVec3; 3], tol: f64) -> bool {
    let n = (t[1] - t[0]).cross(t[2] - t[0]);
    let len = n.length();
    if len == 0.0 {
        return false;
    }
    let n = n / len;
    let (dp, dq) = ((p - t[0]).dot(n), (q - t[0]).dot(n));
    if dp.abs() <= tol || dq.abs() <= tol || (dp > 0.0) == (dq > 0.0) {
        return false;
    }
    let x = p + (q - p) * (dp / (dp - dq));
    (0..3).all(|k| {
        let (a, b) = (t[k], t[(k + 1) % 3]);
        let out = (b - a).cross(x - a).dot(n) / (b - a).length().max(f64::MIN_POSITIVE);
        out > tol
    })
}
