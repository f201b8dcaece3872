//! Detecting 3D points that all lie in one plane, and rotating that plane onto xy.
//!
//! The plane is found from three well-spread points: the centroid `c`, the point `p1`
//! farthest from it, and the point `p2` farthest from the line `c p1`; its normal is
//! `(p1 − c) × (p2 − c)`. The points are coplanar when none is farther from that plane than
//! `rel_tol` times the largest distance from the centroid.
//!
//! Orientation: the normal is flipped to point along the positive direction of its largest
//! component, and the in-plane basis is `u` = the world x axis projected into the plane (the
//! y axis when x is nearly normal to the plane), `v = n × u`, a right-handed frame. A plane
//! with normal +z thus maps (x, y, z) to (x, y); Origami Simulator's x–z patterns (normal
//! ±y, read as +y) map to (x, −z), which is the SVG they were drawn from with y turned up,
//! not mirrored.

use glam::{DVec2, DVec3};

use crate::geom::tolerance::ROUNDOFF;

/// An orthonormal frame of a plane through the origin's parallel: projects points onto it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct PlaneFrame {
    /// First in-plane axis.
    pub u: DVec3,
    /// Second in-plane axis, `normal × u`.
    pub v: DVec3,
    /// Unit normal.
    pub normal: DVec3,
}

impl PlaneFrame {
    /// The frame for a unit normal, oriented as described in the module docs.
    pub fn from_normal(normal: DVec3) -> Self {
        // Snap rounding noise so that axis-aligned planes project exactly (x, −z stays exact).
        let snap = |c: f64| if c.abs() < ROUNDOFF { 0.0 } else { c };
        let normal = DVec3::new(snap(normal.x), snap(normal.y), snap(normal.z)).normalize();
        let dominant = normal.abs().max_element();
        let sign = [normal.x, normal.y, normal.z]
            .into_iter()
            .find(|c| c.abs() == dominant)
            .map_or(1.0, f64::signum);
        let normal = normal * sign;
        let axis = if normal.x.abs() < 0.9 {
            DVec3::X
        } else {
            DVec3::Y
        };
        let u = (axis - normal * axis.dot(normal)).normalize();
        PlaneFrame {
            u,
            v: normal.cross(u),
            normal,
        }
    }

    /// In-plane coordinates of a point.
    pub fn project(&self, p: DVec3) -> DVec2 {
        DVec2::new(p.dot(self.u), p.dot(self.v))
    }
}

/// The plane holding every point within `rel_tol` of their extent, `None` when the points
/// span 3D space. Collinear or coincident points (any plane holds them) get a plane
/// containing their line, as close to xy as possible.
pub(super) fn fit_plane(points: &[DVec3], rel_tol: f64) -> Option<PlaneFrame> {
    let first = *points.first()?;
    let c = points.iter().fold(DVec3::ZERO, |s, &p| s + (p - first)) / points.len() as f64 + first;
    let p1 = farthest(points, |p| p.distance_squared(c))?;
    let extent = p1.distance(c);
    let tol = rel_tol * extent;
    let d1 = p1 - c;
    let p2 = farthest(points, |p| (p - c).cross(d1).length_squared())?;
    let cross = d1.cross(p2 - c);
    let normal = if cross.length() <= tol * extent {
        line_plane_normal(d1)
    } else {
        cross.normalize()
    };
    let off_plane = points
        .iter()
        .map(|&p| (p - c).dot(normal).abs())
        .fold(0.0, f64::max);
    (off_plane <= tol).then(|| PlaneFrame::from_normal(normal))
}

/// A normal of the plane through a line of direction `d` closest to the xy plane.
fn line_plane_normal(d: DVec3) -> DVec3 {
    let d = d.normalize_or_zero();
    [DVec3::Z, DVec3::Y, DVec3::X]
        .into_iter()
        .map(|a| a - d * a.dot(d))
        .find(|n| n.length() > 0.5)
        .map_or(DVec3::Z, DVec3::normalize)
}

/// The point maximising `score`.
fn farthest(points: &[DVec3], score: impl Fn(DVec3) -> f64) -> Option<DVec3> {
    points
        .iter()
        .copied()
        .max_by(|a, b| score(*a).total_cmp(&score(*b)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn xz_plane_maps_to_x_minus_z() {
        let pts = [
            DVec3::new(0.0, 0.0, 0.0),
            DVec3::new(1.0, 0.0, 0.0),
            DVec3::new(0.0, 1e-22, 1.0),
        ];
        let frame = fit_plane(&pts, 1e-9).unwrap();
        assert_eq!(
            frame.project(DVec3::new(2.0, 0.0, 3.0)),
            DVec2::new(2.0, -3.0)
        );
        assert!(frame.u.cross(frame.v).dot(frame.normal) > 0.999);
    }

    #[test]
    fn offset_xy_plane_keeps_xy() {
        let pts = [
            DVec3::new(0.0, 0.0, 5.0),
            DVec3::new(1.0, 0.0, 5.0),
            DVec3::new(0.0, 1.0, 5.0),
        ];
        let frame = fit_plane(&pts, 1e-9).unwrap();
        assert_eq!(
            frame.project(DVec3::new(2.0, 3.0, 5.0)),
            DVec2::new(2.0, 3.0)
        );
    }

    #[test]
    fn tilted_plane_preserves_distances_and_3d_points_are_not_planar() {
        let n = DVec3::new(1.0, 2.0, 3.0).normalize();
        let a = n.any_orthonormal_vector();
        let b = n.cross(a);
        let pts: Vec<DVec3> = [(0.0, 0.0), (3.0, 1.0), (-2.0, 5.0), (4.0, -1.0)]
            .iter()
            .map(|&(s, t)| a * s + b * t + n * 7.0)
            .collect();
        let frame = fit_plane(&pts, 1e-9).unwrap();
        let d3 = pts[1].distance(pts[2]);
        let d2 = frame.project(pts[1]).distance(frame.project(pts[2]));
        assert!((d3 - d2).abs() < 1e-12);
        let mut bent = pts.clone();
        bent.push(n * 8.0);
        assert!(fit_plane(&bent, 1e-9).is_none());
    }
}
