use foldcam::design::papercraft::BSpline;
use foldcam::design::papercraft::CylinderPatch;
use foldcam::design::papercraft::Network;
use foldcam::design::papercraft::PapercraftError;
use foldcam::design::papercraft::Walls;
use foldcam::design::papercraft::{RealBoundary, real_boundary};
use foldcam::mesh::ReferenceMesh;
use glam::{DVec2, DVec3};

use super::support::{cube_corner, cube_lines, cube_mesh, cube_patches};

const K: f64 = 0.5;

struct Cube {
    mesh: ReferenceMesh,
    network: Network,
    walls: Walls,
}

fn cube() -> Cube {
    let mesh = ReferenceMesh::new(&cube_mesh()).unwrap();
    let (lines, _) = cube_lines();
    let network = Network::build(&lines, &cube_patches(), 1e-9).unwrap();
    let walls = Walls::build(&mesh, &lines, &network, K, 8).unwrap();
    Cube {
        mesh,
        network,
        walls,
    }
}

/// A flat patch on the plane `axis = h`, directrix along `along`, rulings along `ruling`.
fn plane_patch(h: f64, normal: DVec3, along: DVec3, ruling: DVec3) -> CylinderPatch {
    let control = (0..5)
        .map(|i| h * normal + along * (-3.0 + 1.5 * i as f64))
        .collect();
    CylinderPatch::new(BSpline::directrix(control, "plane").unwrap(), ruling).unwrap()
}

fn area(poly: &[DVec2]) -> f64 {
    0.5 * (0..poly.len())
        .map(|i| poly[i].perp_dot(poly[(i + 1) % poly.len()]))
        .sum::<f64>()
}

#[test]
fn patch_directions_are_the_face_normals_and_vertices_sweep_along_diagonals() {
    let c = cube();
    let axes = [
        -DVec3::Z,
        DVec3::Z,
        -DVec3::Y,
        DVec3::Y,
        -DVec3::X,
        DVec3::X,
    ];
    for (p, n) in c.walls.patch_normals().iter().enumerate() {
        assert!(n.distance(axes[p]) < 1e-12, "patch {p}: n_p = {n}");
    }
    for (v, &vs) in c.walls.swept_vertices().iter().enumerate() {
        let corner = c.walls.vertices()[v];
        assert!(corner.distance(cube_corner_at(corner)) < 1e-12);
        // §3.4: v_s = v + k · normalize(Σ n_p) over the three faces at the corner.
        let expected = corner + K * corner.normalize();
        assert!(
            vs.distance(expected) < 1e-12,
            "vertex {v}: {vs} vs {expected}"
        );
    }
}

fn cube_corner_at(p: DVec3) -> DVec3 {
    (0..8)
        .map(cube_corner)
        .min_by(|a, b| a.distance(p).total_cmp(&b.distance(p)))
        .unwrap()
}

#[test]
fn ribs_at_a_shared_vertex_coincide() {
    let c = cube();
    let (lines, edges) = cube_lines();
    for v in 0..8 {
        let ribs: Vec<(DVec3, DVec3)> = edges
            .iter()
            .enumerate()
            .filter_map(|(e, &[a, b])| {
                let s = lines[e].segments() as f64;
                (a == v)
                    .then(|| c.walls.rib(&c.mesh, e, 0.0))
                    .or((b == v).then(|| c.walls.rib(&c.mesh, e, s)))
            })
            .collect();
        assert_eq!(ribs.len(), 3);
        for r in &ribs[1..] {
            assert!(r.0.distance(ribs[0].0) < 1e-12 && r.1.distance(ribs[0].1) < 1e-12);
        }
    }
}

fn top(c: &Cube, h: f64) -> RealBoundary {
    let patch = plane_patch(h, DVec3::Z, DVec3::X, DVec3::Y);
    real_boundary(&c.mesh, &c.network, &c.walls, 1, &patch, 1e-6).unwrap()
}

#[test]
fn a_patch_on_the_cut_lines_is_trimmed_to_the_face() {
    let c = cube();
    let boundary = top(&c, 1.0);
    assert_eq!(boundary.sides.len(), 4);
    for p in boundary.sides.iter().flat_map(|s| &s.points) {
        assert!((p.point.z - 1.0).abs() < 1e-12);
        let ring = p.point.x.abs().max(p.point.y.abs());
        assert!((ring - 1.0).abs() < 1e-9, "{}", p.point);
    }
    assert!((area(&boundary.flat_outline()).abs() - 4.0).abs() < 1e-9);
}

#[test]
fn a_patch_off_the_mesh_grows_with_the_flaring_walls() {
    // Convex neighbours (§3.4, Fig. 3.7): farther from the mesh, the patch grows. The walls
    // are scaled copies of the edges, so at height h the top's outline is the square of
    // half-side h exactly.
    let c = cube();
    for h in [0.9, 1.1, 1.2] {
        let boundary = top(&c, h);
        for p in boundary.sides.iter().flat_map(|s| &s.points) {
            let ring = p.point.x.abs().max(p.point.y.abs());
            assert!((ring - h).abs() < 1e-9, "h {h}: {}", p.point);
        }
        let outline = boundary.flat_outline();
        assert!((area(&outline).abs() - 4.0 * h * h).abs() < 1e-8, "h {h}");
        // Corners are the corners of the scaled square, shared by consecutive sides.
        for pair in boundary.sides.windows(2) {
            assert_eq!(pair[0].points.last(), pair[1].points.first());
        }
    }
}

#[test]
fn neighbouring_patches_meet_on_their_shared_wall() {
    let c = cube();
    let h = 1.1;
    let top = top(&c, h);
    let side_patch = plane_patch(h, DVec3::X, DVec3::Z, DVec3::Y);
    let side = real_boundary(&c.mesh, &c.network, &c.walls, 5, &side_patch, 1e-6).unwrap();
    // Cut line 7 joins corners 5 and 7 (x = z = 1): both patches have a side on it.
    let on = |b: &RealBoundary| {
        b.sides
            .iter()
            .find(|s| s.half_edge / 2 == 7)
            .unwrap()
            .clone()
    };
    let (a, b) = (on(&top), on(&side));
    assert_eq!(
        a.half_edge ^ 1,
        b.half_edge,
        "the two patches use opposite half-edges"
    );
    let flat_length = |s: &[foldcam::design::papercraft::BoundaryPoint]| {
        s.windows(2)
            .map(|w| w[0].flat.distance(w[1].flat))
            .sum::<f64>()
    };
    assert!((flat_length(&a.points) - flat_length(&b.points)).abs() < 1e-9);
    assert!((flat_length(&a.points) - 2.0 * h).abs() < 1e-9);
    for p in &a.points {
        let gap = b
            .points
            .windows(2)
            .map(|w| segment_distance(p.point, w[0].point, w[1].point))
            .fold(f64::INFINITY, f64::min);
        assert!(gap < 1e-9, "gap {gap} at {}", p.point);
    }
}

fn segment_distance(p: DVec3, a: DVec3, b: DVec3) -> f64 {
    let t = ((p - a).dot(b - a) / (b - a).length_squared()).clamp(0.0, 1.0);
    p.distance(a + t * (b - a))
}

#[test]
fn a_patch_too_short_for_its_wall_is_reported() {
    let c = cube();
    let control = (0..5)
        .map(|i| DVec3::new(-0.5 + 0.25 * i as f64, 0.0, 1.0))
        .collect();
    let short =
        CylinderPatch::new(BSpline::directrix(control, "short").unwrap(), DVec3::Y).unwrap();
    let err = real_boundary(&c.mesh, &c.network, &c.walls, 1, &short, 1e-6).unwrap_err();
    assert!(
        matches!(err, PapercraftError::MissesWall { patch: 1, .. }),
        "{err}"
    );
    let (lines, _) = cube_lines();
    assert!(matches!(
        Walls::build(&c.mesh, &lines, &c.network, 0.0, 8),
        Err(PapercraftError::BadParameter(_))
    ));
    let patch = plane_patch(1.0, DVec3::Z, DVec3::X, DVec3::Y);
    assert!(matches!(
        real_boundary(&c.mesh, &c.network, &c.walls, 1, &patch, f64::NAN),
        Err(PapercraftError::BadParameter(_))
    ));
}

#[test]
fn a_curved_patch_boundary_meets_the_tolerance() {
    // A bent top: the directrix sags in z, so the crossings with the walls are curves.
    let c = cube();
    let control = vec![
        DVec3::new(-3.0, 0.0, 1.3),
        DVec3::new(-1.5, 0.0, 0.9),
        DVec3::new(0.0, 0.0, 1.25),
        DVec3::new(1.5, 0.0, 0.9),
        DVec3::new(3.0, 0.0, 1.3),
    ];
    let patch = CylinderPatch::new(BSpline::directrix(control, "bent").unwrap(), DVec3::Y).unwrap();
    for tol in [1e-2, 1e-4] {
        let b = real_boundary(&c.mesh, &c.network, &c.walls, 1, &patch, tol).unwrap();
        for side in &b.sides {
            for p in &side.points {
                // Every boundary point lies on the patch where its flat position says.
                assert!(patch.point_of_flat(p.flat).distance(p.point) < 1e-9);
            }
        }
    }
    let coarse = real_boundary(&c.mesh, &c.network, &c.walls, 1, &patch, 1e-2).unwrap();
    let fine = real_boundary(&c.mesh, &c.network, &c.walls, 1, &patch, 1e-5).unwrap();
    let count = |b: &RealBoundary| b.flat_outline().len();
    assert!(
        count(&fine) > count(&coarse),
        "a finer tolerance adds points"
    );
    // The two outlines agree within the coarse tolerance: areas differ by at most
    // tolerance × perimeter.
    let perimeter: f64 = {
        let o = fine.flat_outline();
        (0..o.len())
            .map(|i| o[i].distance(o[(i + 1) % o.len()]))
            .sum()
    };
    let diff = (area(&coarse.flat_outline()).abs() - area(&fine.flat_outline()).abs()).abs();
    assert!(diff <= 1e-2 * perimeter, "area difference {diff}");
}
