use foldcam::design::papercraft::CutLine;
use foldcam::design::papercraft::PapercraftError;
use foldcam::design::papercraft::sphere;
use foldcam::mesh::ReferenceMesh;
use glam::DVec3;

use super::support::Rng;

fn wiggly(rng: &mut Rng, n: usize) -> CutLine {
    CutLine::new(0, (0..n).map(|_| rng.cube(10.0)).collect()).unwrap()
}

#[test]
fn the_spline_passes_through_every_point_and_ends_at_the_ends() {
    let mut rng = Rng::new(1);
    for n in 2..9 {
        let line = wiggly(&mut rng, n);
        for (i, p) in line.points().iter().enumerate() {
            assert!(line.at(i as f64).distance(*p) < 1e-12, "point {i} of {n}");
        }
        assert_eq!(line.at(-1.0), line.start());
        assert!(line.at(1e9).distance(line.end()) < 1e-12);
    }
}

#[test]
fn reversing_the_points_traces_the_same_curve_backwards() {
    let mut rng = Rng::new(2);
    for n in 2..8 {
        let line = wiggly(&mut rng, n);
        let back = line.reversed();
        let m = line.segments() as f64;
        for k in 0..=50 {
            let s = m * k as f64 / 50.0;
            assert!(line.at(s).distance(back.at(m - s)) < 1e-10, "n {n}, s {s}");
        }
    }
}

#[test]
fn equally_spaced_collinear_points_give_a_uniform_straight_line() {
    // With reflected end points every segment's four points are equally spaced on a line,
    // and the uniform Catmull–Rom cubic reduces to linear interpolation.
    let (a, step) = (DVec3::new(1.0, -2.0, 3.0), DVec3::new(0.5, 0.25, -1.0));
    let line = CutLine::new(0, (0..5).map(|i| a + step * i as f64).collect()).unwrap();
    for k in 0..=80 {
        let s = 4.0 * k as f64 / 80.0;
        assert!(line.at(s).distance(a + step * s) < 1e-12, "s {s}");
    }
}

#[test]
fn samples_lie_on_the_mesh_and_shared_ends_stay_shared() {
    let r = 10.0;
    let mesh = ReferenceMesh::new(&sphere(r, 32, 64).unwrap()).unwrap();
    let on = |v: DVec3| mesh.project(v.normalize() * r).point;
    let (a, b, c) = (on(DVec3::X), on(DVec3::new(0.0, 1.0, 0.4)), on(DVec3::Z));
    let ab = CutLine::new(0, vec![a, on(DVec3::new(1.0, 1.0, 0.1)), b]).unwrap();
    let bc = CutLine::new(1, vec![b, on(DVec3::new(0.2, 0.6, 1.0)), c]).unwrap();
    let s1 = ab.sample(&mesh, 12);
    let s2 = bc.sample(&mesh, 12);
    assert_eq!(s1.len(), 2 * 12 + 1);
    assert_eq!(s1[s1.len() - 1], s2[0], "the shared end point is one point");
    assert!(s1[0].distance(a) < 1e-12);
    for p in s1.iter().chain(&s2) {
        assert!(
            mesh.project(*p).distance < 1e-9,
            "sample {p} is off the mesh"
        );
    }
    // The spline between points bulges off the sphere; the samples do not.
    let raw_off = (0..=24)
        .map(|k| (ab.at(k as f64 / 12.0).length() - r).abs())
        .fold(0.0, f64::max);
    assert!(
        raw_off > 0.1,
        "the test curve should leave the sphere ({raw_off})"
    );
}

#[test]
fn short_or_non_finite_cut_lines_are_refused() {
    assert_eq!(
        CutLine::new(3, vec![DVec3::ZERO]).unwrap_err(),
        PapercraftError::ShortCutLine { line: 3, points: 1 }
    );
    assert!(matches!(
        CutLine::new(4, vec![DVec3::ZERO, DVec3::new(f64::NAN, 0.0, 0.0)]),
        Err(PapercraftError::NonFinite { what }) if what == "cut line 4"
    ));
}
