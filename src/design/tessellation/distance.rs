//! How far the folded form lies from the surface it was made for: the distance of every face
//! corner of the solved tessellation to the input mesh (Tachi 2014 judges the fit of §3.4 by
//! this distance; the issue asks for it per mode and mesh).

use super::model::TessMesh;
use crate::design::papercraft::ReferenceMesh;
use crate::mesh::PolyMesh;

/// Distance of the face corners of a tessellation to its input surface, mesh units (mm).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SurfaceDistance {
    /// Largest distance of a face corner.
    pub max: f64,
    /// Mean distance over the face corners.
    pub mean: f64,
    /// Face corners measured.
    pub corners: usize,
}

/// The distance of every face corner of `solved` (its first `corner_count` vertices) to
/// `input`, each found through the closest-point grid of
/// [`crate::design::papercraft::ReferenceMesh`]; `None` when `input` has no
/// triangle of positive area.
pub fn corner_distance(input: &PolyMesh, solved: &TessMesh) -> Option<SurfaceDistance> {
    let surface = ReferenceMesh::new(input).ok()?;
    let corners = &solved.positions[..solved.corner_count];
    let d: Vec<f64> = corners
        .iter()
        .map(|&p| surface.project(p).distance)
        .collect();
    Some(SurfaceDistance {
        max: d.iter().fold(0.0f64, |m, &v| m.max(v)),
        mean: d.iter().sum::<f64>() / d.len().max(1) as f64,
        corners: d.len(),
    })
}

#[cfg(test)]
mod tests {
    use glam::DVec3;

    use super::*;

    /// A unit square in z = 0 as two triangles: the distance of points above, beside and
    /// diagonally off it by the closed forms.
    #[test]
    fn distance_to_a_square_by_closed_forms() {
        let square = PolyMesh::new(
            vec![DVec3::ZERO, DVec3::X, DVec3::new(1.0, 1.0, 0.0), DVec3::Y],
            vec![vec![0, 1, 2, 3]],
        )
        .expect("valid");
        let surface = ReferenceMesh::new(&square).expect("a square");
        let d = |x: f64, y: f64, z: f64| surface.project(DVec3::new(x, y, z)).distance;
        assert!((d(0.3, 0.7, 2.0) - 2.0).abs() < 1e-12);
        assert!((d(0.9, 0.2, -0.5) - 0.5).abs() < 1e-12);
        assert!((d(2.0, 0.5, 0.0) - 1.0).abs() < 1e-12);
        assert!((d(2.0, 2.0, 1.0) - 3f64.sqrt()).abs() < 1e-12);
    }
}
