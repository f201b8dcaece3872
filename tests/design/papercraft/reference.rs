use foldcam::design::papercraft::PapercraftError;
use foldcam::design::papercraft::{revolution, sphere};
use foldcam::mesh::PolyMesh;
use foldcam::mesh::{MeshError, ReferenceMesh, closest_on_triangle};
use glam::DVec3;

use super::support::Rng;

fn brute_force_distance(mesh: &ReferenceMesh, p: DVec3) -> f64 {
    (0..mesh.triangle_count())
        .map(|t| closest_on_triangle(p, mesh.triangle(t)).0.distance(p))
        .fold(f64::INFINITY, f64::min)
}

#[test]
fn grid_search_finds_the_same_distance_as_brute_force() {
    let mesh = ReferenceMesh::new(&sphere(10.0, 12, 20).unwrap()).unwrap();
    let mut rng = Rng::new(4);
    for k in 0..400 {
        // inside, near the surface, and far outside the grid
        let h = [3.0, 11.0, 40.0, 500.0][k % 4];
        let p = rng.cube(h);
        let found = mesh.project(p);
        let expected = brute_force_distance(&mesh, p);
        assert!(
            (found.distance - expected).abs() <= 1e-12 * (1.0 + expected),
            "{p}"
        );
        assert!((found.point.distance(p) - found.distance).abs() < 1e-12);
    }
}

#[test]
fn projection_onto_a_sphere_lands_on_the_sphere_with_radial_normals() {
    let r = 10.0;
    let (rings, segments) = (48, 96);
    let mesh = ReferenceMesh::new(&sphere(r, rings, segments).unwrap()).unwrap();
    // The facets lie at most the sagitta of the coarser direction inside the sphere.
    let sagitta = r * (1.0 - (std::f64::consts::PI / rings as f64).cos());
    let mut rng = Rng::new(7);
    for _ in 0..300 {
        let dir = rng.cube(1.0).normalize();
        let q = dir * rng.range(0.3 * r, 3.0 * r);
        let hit = mesh.project(q);
        let radius = hit.point.length();
        assert!(
            radius <= r + 1e-9 && radius >= r - sagitta,
            "radius {radius}"
        );
        assert!(hit.point.normalize().angle_between(dir) < 0.05);
        assert!(
            hit.normal.angle_between(dir) < 0.05,
            "normal {}",
            hit.normal
        );
        assert!((hit.normal.length() - 1.0).abs() < 1e-12);
        assert!((hit.distance - (q.length() - r).abs()).abs() <= sagitta + 1e-9);
    }
}

#[test]
fn projection_onto_an_open_cylinder_is_radial_and_keeps_height() {
    let r = 5.0;
    let mesh = ReferenceMesh::new(&revolution(&[(r, 0.0), (r, 20.0)], 64).unwrap()).unwrap();
    let sagitta = r * (1.0 - (std::f64::consts::PI / 64.0).cos());
    let mut rng = Rng::new(11);
    for _ in 0..200 {
        let a = rng.range(0.0, std::f64::consts::TAU);
        let rho = rng.range(0.5, 12.0);
        let z = rng.range(1.0, 19.0);
        let q = DVec3::new(rho * a.cos(), rho * a.sin(), z);
        let hit = mesh.project(q);
        assert!(
            (hit.point.z - z).abs() < 1e-9,
            "height changed: {}",
            hit.point.z
        );
        let radial = DVec3::new(a.cos(), a.sin(), 0.0);
        assert!(hit.point.truncate().length() >= r - sagitta - 1e-9);
        assert!(hit.normal.angle_between(radial) < 0.06);
        assert!(hit.normal.z.abs() < 1e-9, "cylinder normals are horizontal");
    }
}

#[test]
fn closest_point_on_a_triangle_matches_dense_sampling() {
    let tri = [
        DVec3::new(0.0, 0.0, 0.0),
        DVec3::new(4.0, 0.5, 0.0),
        DVec3::new(1.0, 3.0, 1.0),
    ];
    let mut rng = Rng::new(3);
    let n = 300;
    for _ in 0..60 {
        let p = rng.cube(6.0);
        let (q, bary) = closest_on_triangle(p, tri);
        let rebuilt = bary[0] * tri[0] + bary[1] * tri[1] + bary[2] * tri[2];
        assert!(rebuilt.distance(q) < 1e-12);
        assert!(bary.iter().all(|&b| (-1e-12..=1.0 + 1e-12).contains(&b)));
        let mut best = f64::INFINITY;
        for i in 0..=n {
            for j in 0..=n - i {
                let (u, v) = (i as f64 / n as f64, j as f64 / n as f64);
                let s = tri[0] + u * (tri[1] - tri[0]) + v * (tri[2] - tri[0]);
                best = best.min(s.distance(p));
            }
        }
        let d = q.distance(p);
        assert!(
            d <= best + 1e-12 && d > best - 0.03,
            "{d} vs sampled {best}"
        );
    }
}

#[test]
fn a_mesh_without_area_is_refused() {
    let flat = PolyMesh::new(
        vec![DVec3::ZERO, DVec3::X, 2.0 * DVec3::X],
        vec![vec![0, 1, 2]],
    )
    .unwrap();
    assert_eq!(
        ReferenceMesh::new(&flat).unwrap_err(),
        MeshError::Degenerate
    );
    assert!(matches!(
        revolution(&[(1.0, 0.0)], 8),
        Err(PapercraftError::BadParameter(_))
    ));
    assert!(matches!(
        revolution(&[(f64::NAN, 0.0), (1.0, 1.0)], 8),
        Err(PapercraftError::BadParameter(_))
    ));
}
