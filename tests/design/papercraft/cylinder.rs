use foldcam::design::papercraft::BSpline;
use foldcam::design::papercraft::CylinderPatch;
use foldcam::design::papercraft::PapercraftError;
use glam::{DVec2, DVec3};

use super::support::{Rng, curve_length};

fn random_patch(seed: u64, n: usize) -> CylinderPatch {
    let mut rng = Rng::new(seed);
    // A wandering directrix and an oblique ruling, neither orthogonal to the other.
    let control = (0..n)
        .map(|i| DVec3::new(10.0 * i as f64, 0.0, 0.0) + rng.cube(6.0))
        .collect();
    let ruling = DVec3::new(0.3, 0.4, 1.0) + rng.cube(0.2);
    CylinderPatch::new(BSpline::directrix(control, "test").unwrap(), ruling).unwrap()
}

#[test]
fn the_directrix_interpolates_its_ends_and_its_derivative_is_exact() {
    let patch = random_patch(5, 8);
    let c = patch.directrix();
    assert_eq!(c.spans(), 4);
    assert!(c.at(0.0).distance(c.control()[0]) < 1e-12);
    assert!(c.at(4.0).distance(c.control()[7]) < 1e-12);
    let d = c.derivative();
    for k in 1..40 {
        let u = 4.0 * k as f64 / 40.0;
        let h = 1e-5;
        let fd = (c.at(u + h) - c.at(u - h)) / (2.0 * h);
        assert!(d.at(u).distance(fd) < 1e-6 * (1.0 + fd.length()), "u {u}");
    }
    // Affine invariance (the basis sums to one): moving every control point moves the curve.
    let shift = DVec3::new(1.0, -2.0, 0.5);
    let moved = BSpline::directrix(c.control().iter().map(|&p| p + shift).collect(), "m").unwrap();
    for k in 0..=20 {
        let u = 4.0 * k as f64 / 20.0;
        assert!(moved.at(u).distance(c.at(u) + shift) < 1e-12);
    }
}

#[test]
fn a_straight_directrix_unrolls_to_its_chord() {
    let (a, b) = (DVec3::new(1.0, 2.0, 0.0), DVec3::new(9.0, -4.0, 0.0));
    let control = (0..6).map(|i| a.lerp(b, i as f64 / 5.0)).collect();
    let patch = CylinderPatch::new(BSpline::directrix(control, "line").unwrap(), DVec3::Z).unwrap();
    assert!((patch.section_length() - a.distance(b)).abs() < 1e-12 * a.distance(b));
}

#[test]
fn unrolling_preserves_rulings_and_section_arcs() {
    for seed in 0..4 {
        let patch = random_patch(seed, 7);
        let d = patch.ruling();
        let mut rng = Rng::new(100 + seed);
        for _ in 0..10 {
            let u = rng.range(0.0, patch.u_max());
            let (v1, v2) = (rng.range(-20.0, 20.0), rng.range(-20.0, 20.0));
            let flat = patch.unroll(u, v1).distance(patch.unroll(u, v2));
            assert!((flat - (v1 - v2).abs()).abs() < 1e-12 * (1.0 + flat));
            // Section arcs: the directrix projected on the plane normal to the ruling.
            let u2 = rng.range(0.0, patch.u_max());
            let section = |t: f64| {
                let c = patch.directrix().at(t);
                c - c.dot(d) * d
            };
            let arc = curve_length(section, u.min(u2), u.max(u2), 4000);
            let unrolled = (patch.section_arc_length(u) - patch.section_arc_length(u2)).abs();
            assert!(
                (arc - unrolled).abs() <= 1e-9 * arc,
                "seed {seed}: arc {arc} vs unrolled {unrolled}"
            );
        }
    }
}

#[test]
fn straight_lines_of_the_unrolled_part_have_the_same_length_on_the_surface() {
    // Straight segments in the plane are geodesics of the developable surface; the surface
    // length of their image must equal their flat length (isometry, 1e-9 relative).
    for seed in 10..13 {
        let patch = random_patch(seed, 9);
        let mut rng = Rng::new(seed);
        let w = patch.section_length();
        for _ in 0..4 {
            let p = DVec2::new(rng.range(0.02 * w, 0.98 * w), rng.range(-10.0, 10.0));
            let q = DVec2::new(rng.range(0.02 * w, 0.98 * w), rng.range(-10.0, 10.0));
            let on_surface = curve_length(|t| patch.point_of_flat(p.lerp(q, t)), 0.0, 1.0, 1500);
            let flat = p.distance(q);
            assert!(
                (on_surface - flat).abs() <= 1e-9 * flat,
                "seed {seed}: surface {on_surface} vs flat {flat}"
            );
        }
    }
}

#[test]
fn roll_inverts_unroll_and_the_normal_is_orthogonal() {
    let patch = random_patch(21, 6);
    let mut rng = Rng::new(9);
    for _ in 0..100 {
        let (u, v) = (rng.range(0.0, patch.u_max()), rng.range(-5.0, 5.0));
        let (u2, v2) = patch.roll(patch.unroll(u, v));
        assert!(
            (u - u2).abs() < 1e-10 && (v - v2).abs() < 1e-9,
            "({u}, {v}) → ({u2}, {v2})"
        );
        let n = patch.normal(u);
        let tangent = patch.directrix().derivative().at(u);
        assert!(n.dot(patch.ruling()).abs() < 1e-12 && n.dot(tangent).abs() < 1e-9);
    }
}

#[test]
fn bad_patches_are_refused() {
    let four = vec![DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::Z];
    assert!(matches!(
        BSpline::directrix(four, "p"),
        Err(PapercraftError::BadParameter(_))
    ));
    let nan = vec![DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::Z, DVec3::NAN];
    assert!(matches!(
        BSpline::directrix(nan, "p"),
        Err(PapercraftError::NonFinite { .. })
    ));
    let ok = || {
        BSpline::directrix(
            (0..5).map(|i| DVec3::new(0.0, 0.0, i as f64)).collect(),
            "p",
        )
        .unwrap()
    };
    assert!(matches!(
        CylinderPatch::new(ok(), DVec3::ZERO),
        Err(PapercraftError::BadParameter(_))
    ));
    // A directrix along the ruling sweeps no area.
    assert!(matches!(
        CylinderPatch::new(ok(), DVec3::Z),
        Err(PapercraftError::BadParameter(_))
    ));
    assert!(CylinderPatch::new(ok(), DVec3::X).is_ok());
}
