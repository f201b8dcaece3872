//! The classic generators produce valid, planar, locally flat-foldable patterns whose geometry
//! matches their defining formulas.

use foldcam::check::{CheckOptions, check};
use foldcam::design::classic::{MiuraOri, SquareTwist, Waterbomb, Yoshimura, grid, waterbomb_base};
use foldcam::pattern::VertexFans;
use foldcam::pattern::{Assignment, CreasePattern, VertexId};
use glam::DVec2;

fn interior_vertices(cp: &CreasePattern) -> Vec<VertexId> {
    let mut on_boundary = vec![false; cp.vertices.len()];
    for e in &cp.edges {
        if e.assignment.is_boundary_like() {
            on_boundary[e.vertices[0].index()] = true;
            on_boundary[e.vertices[1].index()] = true;
        }
    }
    cp.vertex_ids()
        .filter(|v| !on_boundary[v.index()])
        .collect()
}

/// Kawasaki's alternating sum (degrees) and M/V counts at `v`, computed here from the spokes.
fn kawasaki_maekawa(cp: &CreasePattern, fans: &VertexFans, v: VertexId) -> (f64, usize, usize) {
    let spokes = fans.of(v);
    let n = spokes.len();
    let mut alt = 0.0;
    for i in 0..n {
        let a = spokes[i].angle;
        let b = if i + 1 < n {
            spokes[i + 1].angle
        } else {
            spokes[0].angle + std::f64::consts::TAU
        };
        alt += if i % 2 == 0 { b - a } else { a - b };
    }
    let count = |k| {
        spokes
            .iter()
            .filter(|s| cp.edges[s.edge.index()].assignment == k)
            .count()
    };
    (
        alt.to_degrees(),
        count(Assignment::Mountain),
        count(Assignment::Valley),
    )
}

fn assert_flat_foldable(cp: &CreasePattern, name: &str) {
    cp.validate().expect("valid");
    let inner = interior_vertices(cp);
    assert!(!inner.is_empty(), "{name} has interior vertices");
    let fans = VertexFans::new(cp);
    for &v in &inner {
        let (alt, m, vv) = kawasaki_maekawa(cp, &fans, v);
        assert!(alt.abs() < 1e-9, "{name}: Kawasaki at {v}: {alt}°");
        assert_eq!(m.abs_diff(vv), 2, "{name}: Maekawa at {v}");
    }
    let report = check(cp, &CheckOptions::default());
    assert!(report.passed(), "{name}: {:?}", report.findings.first());
    // Faces were traced: Euler for one connected sheet, V − E + F = 1.
    let faces = cp.faces.as_ref().expect("faces").len() as i64;
    assert_eq!(
        cp.vertices.len() as i64 - cp.edges.len() as i64 + faces,
        1,
        "{name}: Euler"
    );
}

#[test]
fn every_generator_is_locally_flat_foldable() {
    assert_flat_foldable(&MiuraOri::default().build().expect("miura"), "miura");
    assert_flat_foldable(&SquareTwist::default().build().expect("twist"), "twist");
    assert_flat_foldable(
        &Waterbomb::default().build().expect("waterbomb"),
        "waterbomb",
    );
    assert_flat_foldable(&waterbomb_base(50.0).expect("base"), "waterbomb base");
    assert_flat_foldable(
        &Yoshimura::default().build().expect("yoshimura"),
        "yoshimura",
    );
    assert_flat_foldable(&grid(6, 10.0).expect("grid"), "grid");
    for twist in [5.0, 15.0, 30.0, 40.0] {
        let t = SquareTwist {
            twist_deg: twist,
            ..SquareTwist::default()
        };
        assert_flat_foldable(&t.build().expect("twist"), &format!("twist {twist}°"));
    }
}

#[test]
fn miura_sector_angles_follow_from_the_shear() {
    let m = MiuraOri {
        columns: 4,
        rows: 4,
        width: 20.0,
        height: 10.0,
        shear: 5.0,
    };
    let cp = m.build().expect("miura");
    // Zigzag segments leave an even-row vertex at φ = atan(h/d) above and below the pleat.
    let phi = (m.height / m.shear).atan().to_degrees();
    let v = cp
        .vertex_ids()
        .find(|&v| cp.position(v).distance(DVec2::new(40.0, 20.0)) < 1e-9)
        .expect("vertex (2, 2)");
    let fans = VertexFans::new(&cp);
    let mut sectors: Vec<f64> = Vec::new();
    let s = fans.of(v);
    for i in 0..s.len() {
        let next = if i + 1 < s.len() {
            s[i + 1].angle
        } else {
            s[0].angle + std::f64::consts::TAU
        };
        sectors.push((next - s[i].angle).to_degrees());
    }
    let mut expected = vec![phi, 180.0 - phi, 180.0 - phi, phi];
    sectors.sort_by(f64::total_cmp);
    expected.sort_by(f64::total_cmp);
    for (a, b) in sectors.iter().zip(&expected) {
        assert!((a - b).abs() < 1e-9, "sectors {sectors:?} vs {expected:?}");
    }
    // Counts: (c+1)(r+1) vertices; c(r+1) + r(c+1) edges.
    assert_eq!(cp.vertices.len(), 25);
    assert_eq!(cp.edges.len(), 40);
}

#[test]
fn square_twist_has_no_unintended_crossings() {
    let cp = SquareTwist::default().build().expect("twist");
    // 4 square corners, 8 pleat ends on the outline, 4 sheet corners; 4 sides, 8 pleats and the
    // outline cut into 12 pieces by the pleat ends.
    assert_eq!(cp.vertices.len(), 16);
    assert_eq!(cp.edges.len(), 24);
    let b = cp
        .edges
        .iter()
        .filter(|e| e.assignment == Assignment::Boundary)
        .count();
    assert_eq!(b, 12);
}

#[test]
fn grids_have_2n_n_plus_1_unit_edges_up_to_the_benchmarks_million() {
    // n = 707 is the benchmark's grid: 2 · 707 · 708 = 1,001,112 edges.
    for n in [1usize, 7, 100, 707] {
        let cp = grid(n, 1.0).expect("grid");
        assert_eq!(cp.edges.len(), 2 * n * (n + 1), "n = {n}");
        assert_eq!(cp.vertices.len(), (n + 1) * (n + 1), "n = {n}");
        let bad = cp.edges.iter().find(|e| {
            let [a, b] = e.vertices.map(|v| cp.position(v));
            (a.distance(b) - 1.0).abs() > 1e-12
        });
        assert!(bad.is_none(), "n = {n}: an edge is not one cell long");
    }
}

#[test]
fn bad_parameters_are_refused_with_their_name() {
    let e = MiuraOri {
        shear: 25.0,
        ..MiuraOri::default()
    }
    .build()
    .expect_err("shear too large");
    assert_eq!(e.parameter, "shear");
    let e = SquareTwist {
        twist_deg: 50.0,
        ..SquareTwist::default()
    }
    .build()
    .expect_err("twist");
    assert_eq!(e.parameter, "twist_deg");
    let e = Yoshimura {
        width: f64::NAN,
        ..Yoshimura::default()
    }
    .build()
    .expect_err("NaN");
    assert_eq!(e.parameter, "width");
    let e = Waterbomb {
        columns: 0,
        ..Waterbomb::default()
    }
    .build()
    .expect_err("zero");
    assert_eq!(e.parameter, "columns");
}
