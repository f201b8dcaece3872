//! Rigid-foldability simulation (Tachi 2014, §5, after Tachi's rigid origami simulation): loop
//! closure and its analytic Jacobian, a degree-4 vertex against the closed-form kinematics of
//! flat-foldable vertices, a Miura-ori sheet, an inconsistent target, and the tessellations
//! of the example surfaces.

use std::path::PathBuf;

use foldcam::design::classic::MiuraOri;
use foldcam::design::tessellation::measure::fold_angle;
use foldcam::design::tessellation::rigid::*;
use foldcam::design::tessellation::{Limits, TessellateOptions, tessellate};
use foldcam::machine::load_material;
use foldcam::mesh::read_mesh;
use foldcam::pattern::{Assignment, CreasePattern, Face, VertexId};
use glam::{DVec2, DVec3};

/// A single vertex with creases at the given directions (degrees) and triangular sectors.
fn vertex(deg: &[f64]) -> CreasePattern {
    let mut cp = CreasePattern::new();
    let c = cp.add_vertex(DVec2::ZERO);
    let tips: Vec<VertexId> = deg
        .iter()
        .map(|d| cp.add_vertex(DVec2::from_angle(d.to_radians()) * 10.0))
        .collect();
    for &t in &tips {
        cp.add_edge(c, t, Assignment::Valley);
    }
    let n = tips.len();
    for k in 0..n {
        cp.add_edge(tips[k], tips[(k + 1) % n], Assignment::Boundary);
    }
    let faces = (0..n).map(|k| Face::simple(vec![c, tips[k], tips[(k + 1) % n]]));
    cp.faces = Some(faces.collect());
    cp
}

/// Sector angles α = 70°, β = 60°, π − α, π − β: flat-foldable.
const ALPHA: f64 = 70.0;
const BETA: f64 = 60.0;

fn flat_foldable_vertex() -> CreasePattern {
    vertex(&[0.0, ALPHA, ALPHA + BETA, 180.0 + BETA])
}

/// Closed form of a flat-foldable degree-4 vertex: the opposite creases 0 and 2 fold by ρ,
/// creases 1 and 3 by ∓2·atan(k·tan(ρ/2)), k = cos((α+β)/2) / cos((α−β)/2).
fn degree4_targets(rho: f64) -> Vec<f64> {
    let (a, b) = (ALPHA.to_radians(), BETA.to_radians());
    let k = ((a + b) / 2.0).cos() / ((a - b) / 2.0).cos();
    let minor = 2.0 * (k * (rho / 2.0).tan()).atan();
    vec![rho, -minor, rho, minor]
}

fn assert_jacobian_matches_differences(m: &RigidModel, rho: &[f64]) {
    let jac = m.jacobian(rho);
    let h = 1e-6;
    for c in 0..rho.len() {
        let mut plus = rho.to_vec();
        let mut minus = rho.to_vec();
        plus[c] += h;
        minus[c] -= h;
        let (rp, rm) = (m.residuals(&plus), m.residuals(&minus));
        for (v, row) in jac.iter().enumerate() {
            let analytic: DVec3 = row.iter().filter(|e| e.0 == c).map(|e| e.1).sum();
            let numeric = (rp[v] - rm[v]) / (2.0 * h);
            assert!(
                (analytic - numeric).length() < 1e-7,
                "vertex {v}, crease {c}: analytic {analytic}, numeric {numeric}"
            );
        }
    }
}

#[test]
fn loop_closure_jacobian_matches_finite_differences() {
    let m = RigidModel::new(&flat_foldable_vertex()).unwrap();
    assert_eq!(m.loop_count(), 1);
    assert_jacobian_matches_differences(&m, &[0.4, -1.1, 0.7, 2.0]);
    let miura = MiuraOri {
        columns: 3,
        rows: 3,
        ..MiuraOri::default()
    }
    .build()
    .unwrap();
    let m = RigidModel::new(&miura).unwrap();
    assert_eq!(m.loop_count(), 4);
    let rho: Vec<f64> = (0..m.crease_edges().len())
        .map(|c| (c as f64 * 1.7).sin())
        .collect();
    assert_jacobian_matches_differences(&m, &rho);
}

#[test]
fn degree4_vertex_folds_rigidly_to_its_one_dof_kinematics() {
    let cp = flat_foldable_vertex();
    let m = RigidModel::new(&cp).unwrap();
    let target = degree4_targets(1.2);
    let r = simulate(&m, &target, &RigidOptions::default(), |_, _| {}).unwrap();
    assert!(r.reached, "{}", r.summary());
    assert!(r.angle_error < 1e-9, "{}", r.summary());
    assert!(
        r.final_residual < 1e-9 && r.max_residual < 1e-9,
        "{}",
        r.summary()
    );
    // The 3D sectors have the simulated dihedral angles (FOLD sign: valley positive).
    let p = &r.positions;
    for k in 0..4 {
        let (tip, next, prev) = (1 + k, 1 + (k + 1) % 4, 1 + (k + 3) % 4);
        let rho = fold_angle(p[0], p[tip], p[next], p[prev]).value;
        assert!(
            (rho - r.angles[k]).abs() < 1e-9,
            "crease {k}: {rho} vs {}",
            r.angles[k]
        );
    }
    // Edge lengths are kept (rigid faces).
    for e in &cp.edges {
        let [a, b] = e.vertices.map(|v| v.index());
        let flat = cp.vertices[a].distance(cp.vertices[b]);
        assert!((p[a].distance(p[b]) - flat).abs() < 1e-9);
    }
}

#[test]
fn inconsistent_degree4_target_is_not_reached() {
    let m = RigidModel::new(&flat_foldable_vertex()).unwrap();
    let r = simulate(
        &m,
        &[1.0, 0.5, 1.0, -0.5],
        &RigidOptions::default(),
        |_, _| {},
    )
    .unwrap();
    assert!(!r.reached, "{}", r.summary());
    assert!(r.angle_error > 0.1, "{}", r.summary());
    // It still stays on the constraint manifold.
    assert!(r.final_residual < 1e-9, "{}", r.summary());
}

#[test]
fn miura_sheet_folds_rigidly() {
    let miura = MiuraOri {
        columns: 4,
        rows: 4,
        width: 20.0,
        height: 16.0,
        shear: 6.0,
    };
    let cp = miura.build().unwrap();
    let m = RigidModel::new(&cp).unwrap();
    // Zigzag creases fold by ρ, straight ones by 2·atan(cos φ · tan(ρ/2)) (φ: angle between
    // the straight and the zigzag creases), signs from the assignments.
    let rho = 1.3f64;
    let phi = miura.height.atan2(miura.shear);
    let minor = 2.0 * (phi.cos().abs() * (rho / 2.0).tan()).atan();
    let target: Vec<f64> = m
        .crease_edges()
        .iter()
        .map(|&e| {
            let edge = &cp.edges[e];
            let [a, b] = edge.vertices.map(|v| cp.vertices[v.index()]);
            let size = if (a.y - b.y).abs() < 1e-9 { minor } else { rho };
            match edge.assignment {
                Assignment::Mountain => -size,
                _ => size,
            }
        })
        .collect();
    let r = simulate(&m, &target, &RigidOptions::default(), |_, _| {}).unwrap();
    assert!(r.reached, "{}", r.summary());
    assert!(
        r.final_residual < 1e-9 && r.angle_error < 1e-9,
        "{}",
        r.summary()
    );
    // The folded sheet is shorter than the flat one along the pleats.
    let span = |xs: Vec<f64>| {
        xs.iter().cloned().fold(f64::NEG_INFINITY, f64::max)
            - xs.iter().cloned().fold(f64::INFINITY, f64::min)
    };
    let flat = span(cp.vertices.iter().map(|p| p.x).collect());
    let folded = span(r.positions.iter().map(|p| p.x).collect());
    assert!(folded < 0.9 * flat, "{folded} vs {flat}");
}

#[test]
fn folding_a_sheet_onto_itself_collides() {
    // Two parallel valleys 4 mm apart with 10 mm flaps: folded by 1.4 rad each the flaps stay
    // apart; folded by 3 rad each (more than 180° in total) the flaps pass through each other.
    let mut cp = CreasePattern::new();
    let xs = [0.0, 10.0, 14.0, 24.0];
    let lo: Vec<VertexId> = xs
        .iter()
        .map(|&x| cp.add_vertex(DVec2::new(x, 0.0)))
        .collect();
    let hi: Vec<VertexId> = xs
        .iter()
        .map(|&x| cp.add_vertex(DVec2::new(x, 10.0)))
        .collect();
    for k in 0..3 {
        cp.add_edge(lo[k], lo[k + 1], Assignment::Boundary);
        cp.add_edge(hi[k], hi[k + 1], Assignment::Boundary);
    }
    cp.add_edge(lo[0], hi[0], Assignment::Boundary);
    cp.add_edge(lo[3], hi[3], Assignment::Boundary);
    cp.add_edge(lo[1], hi[1], Assignment::Valley);
    cp.add_edge(lo[2], hi[2], Assignment::Valley);
    cp.faces = Some(
        (0..3)
            .map(|k| Face::simple(vec![lo[k], lo[k + 1], hi[k + 1], hi[k]]))
            .collect(),
    );
    let m = RigidModel::new(&cp).unwrap();
    let ok = simulate(&m, &[1.4, 1.4], &RigidOptions::default(), |_, _| {}).unwrap();
    assert!(ok.reached, "{}", ok.summary());
    let r = simulate(&m, &[3.0, 3.0], &RigidOptions::default(), |_, _| {}).unwrap();
    assert!(!r.reached, "{}", r.summary());
    assert!(
        matches!(r.stuck, Some(Stuck::Collision { faces: [0, 2], .. })),
        "{:?}",
        r.stuck
    );
    assert_eq!(r.target_collision, Some([0, 2]));
    assert_eq!(ok.target_collision, None);
}

#[test]
fn bad_input_is_refused() {
    let m = RigidModel::new(&flat_foldable_vertex()).unwrap();
    let opts = RigidOptions::default();
    assert!(matches!(
        simulate(&m, &[1.0], &opts, |_, _| {}),
        Err(RigidError::BadInput(_))
    ));
    assert!(matches!(
        simulate(&m, &[f64::NAN, 0.0, 0.0, 0.0], &opts, |_, _| {}),
        Err(RigidError::BadInput(_))
    ));
    let zero = RigidOptions { steps: 0, ..opts };
    assert!(simulate(&m, &[0.0; 4], &zero, |_, _| {}).is_err());
    assert!(matches!(
        RigidModel::new(&CreasePattern::new()),
        Err(RigidError::NoFaces)
    ));
    let mut nan = flat_foldable_vertex();
    nan.vertices[2].x = f64::NAN;
    assert!(matches!(
        RigidModel::new(&nan),
        Err(RigidError::BadInput(_))
    ));
}

fn stainless() -> TessellateOptions {
    let m = load_material("stainless-0.5").expect("shipped material");
    TessellateOptions::with_limits(Limits::from_degrees(
        m.limits.max_fold_angle_deg,
        m.limits.min_vertex_angle_deg,
    ))
}

/// The solved dome, saddle and bell fold rigidly from flat (with triangulated faces, as §5
/// simulates them) to their target shape; the simulated shape is the solver's, up to a rigid
/// motion (all pairwise distances agree).
#[test]
fn example_tessellations_fold_rigidly_from_flat() {
    for name in ["dome", "saddle", "bell"] {
        let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
            .join(format!("examples/tessellation/{name}.obj"));
        let mesh = read_mesh(&path).unwrap();
        let t = tessellate(&mesh, &stainless(), &mut ()).unwrap();
        assert!(t.report.converged, "{name}");
        let u = t.unfolded.unwrap();
        let m = RigidModel::new(&u.pattern).unwrap();
        let opts = RigidOptions {
            steps: 50,
            ..RigidOptions::default()
        };
        let r = simulate(&m, &m.targets_from(&u.pattern), &opts, |_, _| {}).unwrap();
        assert!(r.reached, "{name}: {}", r.summary());
        assert!(r.final_residual < 1e-9, "{name}: {}", r.summary());
        assert_eq!(r.target_collision, None, "{name}");
        let x = &u.folded.positions;
        let p = &r.positions;
        for i in (0..x.len()).step_by(7) {
            for j in 0..x.len() {
                let (a, b) = (x[i].distance(x[j]), p[i].distance(p[j]));
                assert!((a - b).abs() < 1e-6, "{name}: {i}-{j}: {a} vs {b}");
            }
        }
    }
}

#[test]
fn cli_reports_the_rigid_simulation() {
    let dir = tempfile::tempdir().unwrap();
    let mesh = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("examples/tessellation/dome.obj");
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_foldcam"))
        .arg("tessellate")
        .arg(&mesh)
        .arg("-o")
        .arg(dir.path().join("dome.fold"))
        .args(["--material", "stainless-0.5", "--rigid", "20"])
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "{stdout}");
    assert!(
        stdout.contains("rigid folding: reached the target after 20 steps"),
        "{stdout}"
    );
    // Progress names each of the 20 steps and no step beyond them.
    let stderr = String::from_utf8_lossy(&out.stderr);
    let steps: Vec<&str> = stderr
        .lines()
        .filter(|l| l.contains("rigid step"))
        .collect();
    assert_eq!(steps.len(), 20, "{stderr}");
    assert!(steps[19].contains("rigid step   20:"), "{stderr}");
    let bad = std::process::Command::new(env!("CARGO_BIN_EXE_foldcam"))
        .arg("tessellate")
        .arg(&mesh)
        .arg("-o")
        .arg(dir.path().join("bad.fold"))
        .args(["--rigid", "0"])
        .output()
        .unwrap();
    assert_eq!(
        bad.status.code(),
        Some(2),
        "{}",
        String::from_utf8_lossy(&bad.stderr)
    );
}

#[test]
fn progress_counts_the_steps_asked_for_and_no_more() {
    let m = RigidModel::new(&flat_foldable_vertex()).unwrap();
    let opts = RigidOptions {
        steps: 7,
        ..RigidOptions::default()
    };
    let mut heard = Vec::new();
    let r = simulate(&m, &degree4_targets(1.2), &opts, |s, _| heard.push(s)).unwrap();
    assert!(r.reached, "{}", r.summary());
    assert_eq!(heard, (1..=7).collect::<Vec<_>>());
    assert_eq!(r.steps, 7);
    assert!(r.summary().contains("after 7 steps"), "{}", r.summary());
}
