//! The compliant fold simulation (`check::fold3d`) against closed forms and other solvers:
//! Miura-ori kinematics derived here from the cell geometry, the rigid-foldable forms that
//! `tessellate` solves, a pop-up card's own folded state, and isometry along the way.

use foldcam::check::fold3d::{
    FoldError, FoldOptions, ModelError, PAST_FLAT_TOLERANCE_DEG, Stop, fold, fold_with,
};
use foldcam::design::classic::MiuraOri;
use foldcam::pattern::{Assignment, CreasePattern, PlanarizeOptions, planarize};
use glam::{DVec2, DVec3};
use std::path::PathBuf;

/// A Miura-ori sheet with faces.
fn miura(columns: usize, rows: usize) -> (MiuraOri, CreasePattern) {
    let m = MiuraOri {
        columns,
        rows,
        ..MiuraOri::default()
    };
    let mut cp = m.build().unwrap();
    planarize(&mut cp, &PlanarizeOptions::default()).unwrap();
    (m, cp)
}

/// Closed-form Miura-ori kinematics of one degree-4 vertex, derived from the cell geometry
/// (independently of the simulator). The vertex has collinear pleat creases `c1`, `c3` and
/// zigzag creases `c2`, `c4` at angle γ to `c1` (sectors γ, π − γ, π − γ, γ). Folded, the
/// mirror symmetry swapping `c2` and `c4` puts `c1 = (s, 0, k)` and `c3 = (−s, 0, k)` in one
/// plane, with η the angle between them, `s = sin(η/2)`, `k = cos(η/2)`; the rigid sectors
/// give `c2 = (p, ±q, 0)` with `p = cos γ / s`, `q = √(1 − p²)`. The normals of the four
/// faces then give the zigzag fold ρ_z and the pleat fold ρ_x:
/// `cos ρ_z = −(cos η + cos² γ)/sin² γ`, `cos ρ_x = (q² − k² p²)/sin² γ`.
/// Returns (ρ_x, η, q) for a zigzag fold ρ_z (radians).
fn miura_closed_form(gamma: f64, rho_z: f64) -> (f64, f64, f64) {
    let (cg, sg) = (gamma.cos(), gamma.sin());
    let cos_eta = -cg * cg - sg * sg * rho_z.cos();
    let eta = cos_eta.clamp(-1.0, 1.0).acos();
    let (s, k) = ((eta / 2.0).sin(), (eta / 2.0).cos());
    let p = cg / s;
    let q2 = 1.0 - p * p;
    let cos_rx = (q2 - k * k * p * p) / (sg * sg);
    (cos_rx.clamp(-1.0, 1.0).acos(), eta, q2.max(0.0).sqrt())
}

#[test]
fn closed_form_is_flat_at_zero_and_flat_folded_at_pi() {
    let g = 1.2f64;
    let (rx, eta, q) = miura_closed_form(g, 0.0);
    assert!(rx.abs() < 1e-6 && (eta - std::f64::consts::PI).abs() < 1e-6);
    assert!((q - g.sin()).abs() < 1e-6);
    let (rx, eta, _) = miura_closed_form(g, std::f64::consts::PI);
    assert!((rx - std::f64::consts::PI).abs() < 1e-6);
    assert!((eta - (std::f64::consts::PI - 2.0 * g)).abs() < 1e-6);
}

/// Mean |fold angle| (degrees) of the interior creases among `edges`.
fn mean_abs(angles: &[Option<f64>], edges: impl Iterator<Item = usize>) -> f64 {
    let v: Vec<f64> = edges.filter_map(|e| angles[e]).map(f64::abs).collect();
    v.iter().sum::<f64>() / v.len() as f64
}

/// The mean |fold angle| of the zigzag creases and of the pleats of a Miura-ori of
/// `cols` × `rows` cells, radians. Generator numbering: (rows + 1) · cols row segments
/// (pleats), then the zigzag columns.
fn zigzag_and_pleat(
    cp: &CreasePattern,
    angles: &[Option<f64>],
    cols: usize,
    rows: usize,
) -> (f64, f64) {
    let horizontal = (rows + 1) * cols;
    let crease = |e: &usize| cp.edges[*e].assignment != Assignment::Boundary;
    let zig = (horizontal..cp.edges.len()).filter(crease);
    let pleat = (0..horizontal).filter(crease);
    (
        mean_abs(angles, zig).to_radians(),
        mean_abs(angles, pleat).to_radians(),
    )
}

#[test]
fn miura_at_half_follows_closed_form_kinematics() {
    let (cols, rows) = (6, 6);
    let (m, cp) = miura(cols, rows);
    let opts = FoldOptions {
        percent: 50.0,
        ..FoldOptions::default()
    };
    let f = fold(&cp, &opts).unwrap();
    let r = &f.report;
    assert_eq!(r.stop, Stop::Settled);
    assert!(r.wrong_sign.is_empty());
    // Every crease folds with the sign of its assignment.
    for (e, edge) in cp.edges.iter().enumerate() {
        let want = match edge.assignment {
            Assignment::Mountain => -1.0,
            Assignment::Valley => 1.0,
            _ => continue,
        };
        let got = r.fold_angles[e].unwrap();
        assert!(
            got * want > 1.0,
            "edge {e} {:?} folded {got}",
            edge.assignment
        );
    }
    let (rho_z, rho_x) = zigzag_and_pleat(&cp, &r.fold_angles, cols, rows);
    let c = (m.shear * m.shear + m.height * m.height).sqrt();
    let (want_x, eta, q) = miura_closed_form((m.shear / c).acos(), rho_z);
    // Halfway between flat and flat-folded on average, but not equally: the two families
    // cannot both reach 90° (the closed form ties them).
    assert!(rho_z > 1.2 * rho_x, "{rho_z} {rho_x}");
    assert!(
        (rho_x - want_x).abs() < 0.01 * want_x,
        "{rho_x} vs {want_x}"
    );
    // Overall dimensions: along the pleats cols · a · sin(η/2), across rows · c · q.
    let x = &f.folded.positions;
    let vid = |i: usize, j: usize| j * (cols + 1) + i;
    let lx = x[vid(0, rows / 2)].distance(x[vid(cols, rows / 2)]);
    let ly = x[vid(cols / 2, 0)].distance(x[vid(cols / 2, rows)]);
    let (want_lx, want_ly) = (
        cols as f64 * m.width * (eta / 2.0).sin(),
        rows as f64 * c * q,
    );
    assert!((lx - want_lx).abs() < 0.01 * want_lx, "{lx} vs {want_lx}");
    assert!((ly - want_ly).abs() < 0.01 * want_ly, "{ly} vs {want_ly}");
}

/// The pleat angle of a Miura-ori folded to `angles` is within 1% of the closed form's for
/// its zigzag angle ([`miura_closed_form`]).
fn assert_pleat_on_closed_form(
    m: &MiuraOri,
    cp: &CreasePattern,
    angles: &[Option<f64>],
    cols: usize,
    rows: usize,
) {
    let (rho_z, rho_x) = zigzag_and_pleat(cp, angles, cols, rows);
    let c = (m.shear * m.shear + m.height * m.height).sqrt();
    let (want_x, _, _) = miura_closed_form((m.shear / c).acos(), rho_z);
    assert!(
        (rho_x - want_x).abs() < 0.01 * want_x,
        "{rho_x} vs {want_x}"
    );
}

/// The opt-in adaptive ramp reaches the same folded form as the linear ramp, by the closed
/// form of the Miura-ori's rigid kinematics ([`miura_closed_form`]), in fewer steps.
#[test]
fn the_adaptive_ramp_follows_the_closed_form_in_fewer_steps() {
    let (cols, rows) = (6, 6);
    let (m, cp) = miura(cols, rows);
    let run = |adaptive_ramp| {
        let opts = FoldOptions {
            percent: 90.0,
            adaptive_ramp,
            implicit: false,
            ..FoldOptions::default()
        };
        fold(&cp, &opts).unwrap()
    };
    let (linear, adaptive) = (run(false), run(true));
    let r = &adaptive.report;
    assert_eq!(r.stop, Stop::Settled);
    assert!(r.wrong_sign.is_empty() && r.past_flat.is_empty());
    assert!(r.crossing_faces.is_empty());
    assert!(r.max_strain < 0.01, "{}", r.max_strain);
    assert!(
        r.steps < linear.report.steps,
        "adaptive {} steps, linear {}",
        r.steps,
        linear.report.steps
    );
    assert_pleat_on_closed_form(&m, &cp, &r.fold_angles, cols, rows);
}

/// Largest |bar strain| of positions `x`.
fn max_bar_strain(model: &foldcam::check::fold3d::BarHingeModel, x: &[DVec3]) -> f64 {
    model
        .bars
        .iter()
        .map(|b| {
            let len = x[b.ends[0] as usize].distance(x[b.ends[1] as usize]);
            ((len - b.rest) / b.rest).abs()
        })
        .fold(0.0, f64::max)
}

#[test]
fn miura_bars_stay_within_one_percent_at_every_step() {
    let (_, cp) = miura(4, 4);
    let mut worst = 0.0f64;
    let mut steps = 0;
    // Every explicit step is seen (the static solve shows only its load steps).
    let opts = FoldOptions {
        implicit: false,
        ..FoldOptions::default()
    };
    let f = fold_with(&cp, &opts, |model, x| {
        worst = worst.max(max_bar_strain(model, x));
        steps += 1;
    })
    .unwrap();
    assert_eq!(steps, f.report.steps);
    assert!(worst < 0.01, "largest strain on the way: {worst}");
    // It did fold: every crease within a few degrees of flat-folded.
    assert!(
        f.report
            .fold_angles
            .iter()
            .flatten()
            .all(|a| a.abs() > 150.0)
    );
    assert!(f.report.wrong_sign.is_empty());
}

/// Rotation (as a matrix) and translation that best map `a` onto `b` in the least-squares
/// sense (Kabsch's problem, solved with Horn's quaternion: the eigenvector of the largest
/// eigenvalue of a symmetric 4 × 4 matrix, by Jacobi rotations).
fn align(a: &[DVec3], b: &[DVec3]) -> Vec<DVec3> {
    let n = a.len() as f64;
    let ca = a.iter().sum::<DVec3>() / n;
    let cb = b.iter().sum::<DVec3>() / n;
    let mut s = [[0.0f64; 3]; 3];
    for (p, q) in a.iter().zip(b) {
        let (p, q) = ((*p - ca).to_array(), (*q - cb).to_array());
        for i in 0..3 {
            for j in 0..3 {
                s[i][j] += p[i] * q[j];
            }
        }
    }
    let [[sxx, sxy, sxz], [syx, syy, syz], [szx, szy, szz]] = s;
    let mut m = [
        [sxx + syy + szz, syz - szy, szx - sxz, sxy - syx],
        [syz - szy, sxx - syy - szz, sxy + syx, szx + sxz],
        [szx - sxz, sxy + syx, -sxx + syy - szz, syz + szy],
        [sxy - syx, szx + sxz, syz + szy, -sxx - syy + szz],
    ];
    let mut v = [[0.0f64; 4]; 4];
    for (i, row) in v.iter_mut().enumerate() {
        row[i] = 1.0;
    }
    for _ in 0..100 {
        for p in 0..4 {
            for q in p + 1..4 {
                if m[p][q].abs() < 1e-300 {
                    continue;
                }
                let theta = (m[q][q] - m[p][p]) / (2.0 * m[p][q]);
                let t = theta.signum() / (theta.abs() + (theta * theta + 1.0).sqrt());
                let t = if theta == 0.0 { 1.0 } else { t };
                let c = 1.0 / (t * t + 1.0).sqrt();
                let sn = t * c;
                for row in m.iter_mut() {
                    let (mkp, mkq) = (row[p], row[q]);
                    row[p] = c * mkp - sn * mkq;
                    row[q] = sn * mkp + c * mkq;
                }
                let (rp, rq) = (m[p], m[q]);
                m[p] = std::array::from_fn(|k| c * rp[k] - sn * rq[k]);
                m[q] = std::array::from_fn(|k| sn * rp[k] + c * rq[k]);
                for row in v.iter_mut() {
                    let (vp, vq) = (row[p], row[q]);
                    row[p] = c * vp - sn * vq;
                    row[q] = sn * vp + c * vq;
                }
            }
        }
    }
    let best = (0..4).max_by(|&i, &j| m[i][i].total_cmp(&m[j][j])).unwrap();
    let q = glam::DQuat::from_xyzw(v[1][best], v[2][best], v[3][best], v[0][best]).normalize();
    a.iter().map(|p| q * (*p - ca) + cb).collect()
}

#[test]
fn alignment_recovers_a_rigid_motion() {
    let a: Vec<DVec3> = (0..20)
        .map(|i| DVec3::new(i as f64, (i * i % 7) as f64, (i % 3) as f64))
        .collect();
    let q = glam::DQuat::from_euler(glam::EulerRot::XYZ, 0.3, -1.1, 2.0);
    let b: Vec<DVec3> = a
        .iter()
        .map(|p| q * *p + DVec3::new(5.0, -2.0, 1.0))
        .collect();
    let moved = align(&a, &b);
    assert!(moved.iter().zip(&b).all(|(p, q)| p.distance(*q) < 1e-9));
}

fn diagonal(x: &[DVec3]) -> f64 {
    let lo = x.iter().fold(DVec3::splat(f64::MAX), |m, p| m.min(*p));
    let hi = x.iter().fold(DVec3::splat(f64::MIN), |m, p| m.max(*p));
    lo.distance(hi)
}

fn foldcam() -> std::process::Command {
    std::process::Command::new(env!("CARGO_BIN_EXE_foldcam"))
}

fn manifest(rel: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join(rel)
}

/// The bundled dome, saddle, bell and 60° cap, tessellated at the stainless limits and folded
/// from flat by `fold3d`, against the form the tessellation solver computed (after rigid
/// alignment, as a share of its bounding-box diagonal).
///
/// The static solve (the default) lands on every solved form within 0.02% (0.002% seen),
/// isometric within 1% at every load step (the cap within 3%). The explicit run lands within 2%, but for the cap: it needs the
/// slower ramps (at the default ramp 86 of its creases settle against their assignment, 27%
/// off the form; with them none do) and lands 5.6% off.
#[test]
fn tessellation_from_flat_reaches_the_solved_form() {
    for mesh in ["dome", "saddle", "bell", "cap"] {
        let dir = tempfile::tempdir().unwrap();
        let out = dir.path().join(format!("{mesh}.fold"));
        let status = foldcam()
            .arg("tessellate")
            .arg(manifest(&format!("examples/tessellation/{mesh}.obj")))
            // The saddle's star tucks leave a corner 6.6% of its size off the mesh: partial,
            // but its solved form is what is compared here.
            .args(["-x", "stainless-0.5", "--allow-partial", "-o"])
            .arg(&out)
            .output()
            .unwrap();
        assert!(
            status.status.success(),
            "{mesh}: {}",
            String::from_utf8_lossy(&status.stderr)
        );
        let imported = foldcam::formats::load(&out).unwrap();
        let solved = imported.folded.expect("the tessellation's folded form");
        let cp = imported.pattern;
        let n = cp.vertices.len();
        let diag = diagonal(&solved.positions);
        // The largest distance of a pattern vertex from the solved form, over the diagonal.
        let off = |f: &foldcam::check::fold3d::Fold| {
            let moved = align(&f.folded.positions[..n], &solved.positions);
            let far = (moved.iter().zip(&solved.positions))
                .map(|(p, q)| p.distance(*q))
                .fold(0.0, f64::max);
            far / diag
        };
        for implicit in [true, false] {
            let method = if implicit { "static solve" } else { "explicit" };
            let mut strain = Vec::new();
            // Time enough for the slower ramps in an unoptimised build too.
            let opts = FoldOptions {
                max_time: std::time::Duration::from_secs(900),
                implicit,
                ..FoldOptions::default()
            };
            let f =
                fold_with(&cp, &opts, |model, x| strain.push(max_bar_strain(model, x))).unwrap();
            let r = &f.report;
            assert_eq!(r.stop, Stop::Settled, "{mesh}, {method}");
            assert!(r.wrong_sign.is_empty(), "{mesh}, {method}");
            let off = off(&f);
            eprintln!(
                "{mesh}, {method}: {:.3}% of the diagonal off the solved form, {:.2} s",
                100.0 * off,
                r.seconds
            );
            if implicit {
                assert!(r.static_solve.is_some_and(|s| s.used), "{mesh}");
                assert!(r.slower_ramps.is_empty(), "{mesh}");
                // Seen: at every load step, then at the end. The cap, not rigid-foldable from
                // flat, stretches by 2.3% at a load step on its way.
                let worst = strain.iter().fold(0.0f64, |w, s| w.max(*s));
                let limit = if mesh == "cap" { 0.03 } else { 0.01 };
                assert!(worst < limit, "{mesh}: largest strain on the way: {worst}");
                assert!(off < 2e-4, "{mesh}: {:.4}% off", 100.0 * off);
                continue;
            }
            assert_eq!(r.slower_ramps.is_empty(), mesh != "cap", "{mesh}");
            // Isometric all the way (the last run's way, after any given up).
            let given_up: usize = r.slower_ramps.iter().map(|r| r.steps).sum();
            assert_eq!(strain.len(), r.steps);
            let worst = strain[given_up..].iter().fold(0.0f64, |w, s| w.max(*s));
            eprintln!("{mesh}: largest strain on the way {:.3}%", 100.0 * worst);
            // Rigid-foldable within 1%, but for the cap, whose faces stretch up to 1.06% on
            // the way (and 0.02% at the end).
            let limit = if mesh == "cap" { 0.015 } else { 0.01 };
            assert!(worst < limit, "{mesh}: largest strain on the way: {worst}");
            // The cap reaches its form's branch but settles 5.6% off, short of the 2% the
            // others meet: a fold-angle error of 7° is left on one crease.
            let bound = if mesh == "cap" { 0.06 } else { 0.02 };
            assert!(off < bound, "{mesh}: {:.3}% off", 100.0 * off);
        }
    }
}

#[test]
fn pop_up_card_at_half_matches_its_own_folded_state() {
    use foldcam::design::popup::voxel::{crease_pattern, fold_card, parse_voxel_card};
    let text = std::fs::read_to_string(manifest("examples/popup/house.voxel.txt")).unwrap();
    let card = parse_voxel_card(&text).unwrap();
    let cp = crease_pattern(&card).unwrap();
    let f = fold(
        &cp,
        &FoldOptions {
            percent: 50.0,
            ..FoldOptions::default()
        },
    )
    .unwrap();
    assert_eq!(f.report.stop, Stop::Settled);
    assert!(f.report.wrong_sign.is_empty());
    // The card's creases all fold by the same angle; half of it gives the opening.
    let target = cp
        .edges
        .iter()
        .filter_map(foldcam::check::fold3d::crease_target_deg)
        .map(f64::abs)
        .fold(0.0, f64::max);
    let opening = 180.0 - 0.5 * target;
    // The card's 3D frame has Y = −v (its flat state is the pattern mirrored): mirror it
    // back, and check that at 180° (flat) it is then the pattern itself.
    let corners = |opening: f64| {
        let own = fold_card(&card, &cp, opening);
        let faces = own.state.faces.clone().unwrap();
        let corners: Vec<DVec3> = faces
            .iter()
            .flat_map(|o| o.outer.iter().map(|v| own.state.positions[v.index()]))
            .map(|p| DVec3::new(p.x, -p.y, p.z))
            .collect();
        corners
    };
    let flat_pattern: Vec<DVec3> = cp
        .faces
        .as_ref()
        .unwrap()
        .iter()
        .flat_map(|o| o.outer.iter().map(|v| cp.vertices[v.index()].extend(0.0)))
        .collect();
    let flat = corners(180.0);
    assert_eq!(flat.len(), flat_pattern.len());
    let d0 = align(&flat, &flat_pattern)
        .iter()
        .zip(&flat_pattern)
        .map(|(p, q)| p.distance(*q))
        .fold(0.0, f64::max);
    assert!(d0 < 1e-6 * diagonal(&flat_pattern), "{d0}");
    let b = corners(opening);
    let sim_faces = f.folded.faces.as_ref().unwrap();
    let a: Vec<DVec3> = sim_faces
        .iter()
        .flat_map(|s| s.outer.iter().map(|v| f.folded.positions[v.index()]))
        .collect();
    assert_eq!(a.len(), b.len());
    let moved = align(&a, &b);
    let diag = diagonal(&b);
    let off = moved
        .iter()
        .zip(&b)
        .map(|(p, q)| p.distance(*q))
        .fold(0.0, f64::max);
    assert!(off < 0.02 * diag, "{off} vs diagonal {diag}");
}

/// A degree-4 vertex whose sectors break Kawasaki's theorem (100°, 80°, 100°, 80° would pass;
/// here 120°, 60°, 80°, 100°).
fn kawasaki_violation() -> CreasePattern {
    let mut cp = CreasePattern::new();
    let c = cp.add_vertex(DVec2::ZERO);
    let dirs = [0.0f64, 120.0, 180.0, 260.0];
    let tips: Vec<_> = dirs
        .iter()
        .map(|d| cp.add_vertex(DVec2::from_angle(d.to_radians()) * 50.0))
        .collect();
    // Corners of the sheet between the spokes, so every face is a convex quadrilateral.
    let mut ring = Vec::new();
    for k in 0..4 {
        ring.push(tips[k]);
        let mid = (dirs[k] + dirs[(k + 1) % 4] + if k == 3 { 360.0 } else { 0.0 }) / 2.0;
        ring.push(cp.add_vertex(DVec2::from_angle(mid.to_radians()) * 60.0));
    }
    let kinds = [
        Assignment::Mountain,
        Assignment::Valley,
        Assignment::Valley,
        Assignment::Valley,
    ];
    for (t, kind) in tips.iter().zip(kinds) {
        cp.add_edge(c, *t, kind);
    }
    for k in 0..ring.len() {
        cp.add_edge(ring[k], ring[(k + 1) % ring.len()], Assignment::Boundary);
    }
    planarize(
        &mut cp,
        &PlanarizeOptions {
            faces: true,
            ..PlanarizeOptions::default()
        },
    )
    .unwrap();
    cp
}

#[test]
fn unfoldable_vertex_reports_where_strain_concentrates() {
    let cp = kawasaki_violation();
    let f = fold(
        &cp,
        &FoldOptions {
            percent: 80.0,
            ..FoldOptions::default()
        },
    )
    .unwrap();
    let r = &f.report;
    assert!(f.folded.positions.iter().all(|p| p.is_finite()));
    assert!(r.max_strain.is_finite() && r.residual.is_finite());
    // Four faces meet at the vertex, all strained; the report names one of them and a place
    // within the sheet.
    assert!(r.max_strain_face.is_some());
    let at = r.max_strain_at.unwrap();
    assert!(at.length() < 60.0, "{at}");
    // Far from its targets: the angle error says so.
    assert!(r.max_angle_error_deg > 5.0, "{}", r.max_angle_error_deg);
}

#[test]
fn step_cap_and_bad_input_end_cleanly() {
    let (_, cp) = miura(4, 4);
    let capped = fold(
        &cp,
        &FoldOptions {
            max_steps: 10,
            implicit: false,
            ..FoldOptions::default()
        },
    )
    .unwrap();
    assert_eq!(capped.report.stop, Stop::StepCap);
    assert_eq!(capped.report.steps, 10);
    let mut no_faces = cp.clone();
    no_faces.faces = None;
    assert_eq!(
        fold(&no_faces, &FoldOptions::default()).unwrap_err(),
        FoldError::Model(ModelError::NoFaces)
    );
    let bad = FoldOptions {
        percent: 120.0,
        ..FoldOptions::default()
    };
    assert!(matches!(
        fold(&cp, &bad),
        Err(FoldError::Option {
            name: "percent",
            ..
        })
    ));
}

#[test]
fn cuts_split_the_sheet() {
    // A square with a cut from one side to the centre: the vertices on the cut get a copy each.
    let mut cp = CreasePattern::new();
    let sq = [(0., 0.), (100., 0.), (100., 100.), (0., 100.)]
        .map(|(x, y)| cp.add_vertex(DVec2::new(x, y)));
    for k in 0..4 {
        cp.add_edge(sq[k], sq[(k + 1) % 4], Assignment::Boundary);
    }
    let mid = cp.add_vertex(DVec2::new(50.0, 0.0));
    let centre = cp.add_vertex(DVec2::new(50.0, 50.0));
    cp.add_edge(mid, centre, Assignment::Cut);
    cp.add_edge(centre, sq[2], Assignment::Valley);
    cp.add_edge(centre, sq[3], Assignment::Valley);
    planarize(
        &mut cp,
        &PlanarizeOptions {
            faces: true,
            ..PlanarizeOptions::default()
        },
    )
    .unwrap();
    let model = foldcam::check::fold3d::BarHingeModel::build(&cp).unwrap();
    // The cut's bottom end (on the outline) is split; the centre is joined around the top.
    assert_eq!(model.vertex_count(), cp.vertices.len() + 1);
    let mid_id = cp
        .vertices
        .iter()
        .position(|p| *p == DVec2::new(50.0, 0.0))
        .unwrap();
    assert_eq!(
        model.source.iter().filter(|v| v.index() == mid_id).count(),
        2
    );
}

#[test]
fn cli_folds_an_oripa_file_and_writes_every_output() {
    let dir = tempfile::tempdir().unwrap();
    let fold_path = dir.path().join("base.fold");
    let (png, gif) = (dir.path().join("base.png"), dir.path().join("base.gif"));
    let out = foldcam()
        .arg("fold3d")
        .arg(manifest("examples/patterns/preliminary-base.cp"))
        .arg("-o")
        .arg(&fold_path)
        .args(["--percent", "40", "--strain", "--width", "200", "--png"])
        .arg(&png)
        .arg("--gif")
        .arg(&gif)
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout);
    // A good pattern at 40 % folds without a finding: exit 0, not 1.
    assert!(
        out.status.success(),
        "{stdout}{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(stdout.contains("largest bar strain"), "{stdout}");
    assert!(stdout.contains("largest fold-angle error"), "{stdout}");
    assert!(png.exists() && gif.exists());
    // Frame 0 is the flat pattern, frame 1 the folded form in 3D with reached angles.
    let text = std::fs::read_to_string(&fold_path).unwrap();
    let key = foldcam::formats::fold::read_str(&text).unwrap();
    let folded = key.folded.expect("foldedForm frame");
    assert!(folded.positions.iter().any(|p| p.z.abs() > 1e-3));
    assert!(
        folded
            .edges
            .iter()
            .any(|e| e.fold_angle.is_some_and(|a| a.abs() > 1.0))
    );
    // Folded, no edge is stretched or shrunk beyond 1 % of its flat length, and every fold
    // that moved turned the way its assignment says (valley positive, mountain negative).
    let flat = &key.pattern;
    crate::isometry::assert_isometric(flat, &folded, 0.01, "preliminary base");
    for (e, f) in flat.edges.iter().zip(&folded.edges) {
        let reached = f.fold_angle.unwrap_or(0.0);
        match e.assignment {
            foldcam::pattern::Assignment::Valley => assert!(reached >= -1e-6, "{reached}"),
            foldcam::pattern::Assignment::Mountain => assert!(reached <= 1e-6, "{reached}"),
            _ => {}
        }
    }
}

#[test]
fn cli_bad_input_writes_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let fold_path = dir.path().join("x.fold");
    let out = foldcam()
        .arg("fold3d")
        .arg(manifest("examples/patterns/preliminary-base.cp"))
        .arg("-o")
        .arg(&fold_path)
        .args(["--percent", "140"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let bad_png = dir.path().join("x.jpg");
    let out = foldcam()
        .arg("fold3d")
        .arg(manifest("examples/patterns/preliminary-base.cp"))
        .arg("-o")
        .arg(&fold_path)
        .arg("--png")
        .arg(&bad_png)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("x.jpg"));
    assert!(!fold_path.exists() && !bad_png.exists());
}

/// Every format foldcam reads, and every bundled crease pattern: `fold3d` folds it into a
/// `foldedForm` frame with the pattern's vertices lifted off the plane, every fold reached
/// with its assignment's sign, and no bar stretched beyond 1 %.
#[test]
fn cli_folds_every_format_and_every_bundled_pattern() {
    let dir = tempfile::tempdir().unwrap();
    // An .opx made from a bundled pattern (ORIPA's XML), beside the files that ship.
    let opx = dir.path().join("flat-vertex.opx");
    let o = foldcam()
        .arg("convert")
        .arg(manifest("examples/patterns/flat-vertex.fold"))
        .arg(&opx)
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let inputs = [
        manifest("examples/patterns/flat-vertex.fold"),
        manifest("examples/patterns/broken-vertex.fold"),
        manifest("examples/patterns/preliminary-base.cp"),
        manifest("tests/data/svg/miura-ori.svg"),
        manifest("tests/data/oripa-style.dxf"),
        opx,
    ];
    for input in &inputs {
        let out = dir.path().join("out.fold");
        let o = foldcam()
            .arg("fold3d")
            .arg(input)
            .arg("-o")
            .arg(&out)
            .args(["--percent", "50"])
            .output()
            .unwrap();
        let what = input.display();
        let stdout = String::from_utf8_lossy(&o.stdout);
        // 0 settled, 1 a cap stopped it (the broken vertex cannot fold): never bad input.
        assert!(
            o.status.code().is_some_and(|c| c <= 1),
            "{what}: {stdout}{}",
            String::from_utf8_lossy(&o.stderr)
        );
        let key = foldcam::formats::load(&out).unwrap();
        let folded = key
            .folded
            .unwrap_or_else(|| panic!("{what}: no foldedForm frame"));
        assert_eq!(folded.positions.len(), key.pattern.vertices.len(), "{what}");
        assert!(folded.positions.iter().any(|p| p.z.abs() > 1e-3), "{what}");
        // The broken vertex (Kawasaki and Maekawa fail there) cannot fold as assigned: the
        // report must say so rather than claim the targets.
        if input.ends_with("broken-vertex.fold") {
            assert!(
                stdout.contains("folded against their assignment"),
                "{what}: {stdout}"
            );
            continue;
        }
        if o.status.code() == Some(0) {
            for (e, f) in key.pattern.edges.iter().zip(&folded.edges) {
                let sign = match e.assignment {
                    Assignment::Valley => 1.0,
                    Assignment::Mountain => -1.0,
                    _ => continue,
                };
                let reached = f.fold_angle.unwrap_or(0.0);
                assert!(reached * sign > 0.0, "{what}: a crease folded {reached}°");
            }
            for e in &key.pattern.edges {
                let [a, b] = e.vertices;
                let flat = key.pattern.position(a).distance(key.pattern.position(b));
                let bent = folded.positions[a.index()].distance(folded.positions[b.index()]);
                assert!(
                    (bent - flat).abs() <= 0.01 * flat,
                    "{what}: {flat} -> {bent}"
                );
            }
        }
    }
}

/// A Miura-ori (20 × 15 mm cells, 6 mm zigzag offset) whose straight creases are one kind per
/// row and whose zigzag creases alternate along their length: folded all the way, its
/// straight creases are driven past flat (the held-out sheet of issue 40).
fn miura_one_kind_per_row() -> CreasePattern {
    let m = MiuraOri {
        columns: 8,
        rows: 6,
        width: 20.0,
        height: 15.0,
        shear: 6.0,
    };
    let mut cp = m.build().unwrap();
    let v = cp.vertices.clone();
    for e in &mut cp.edges {
        if !matches!(e.assignment, Assignment::Mountain | Assignment::Valley) {
            continue;
        }
        let (a, b) = (v[e.vertices[0].index()], v[e.vertices[1].index()]);
        let row = (a.y.min(b.y) / m.height).round() as i64;
        let column = (a.x.min(b.x) / m.width).round() as i64;
        let straight = (a.y - b.y).abs() < 1e-9;
        let mountain = if straight {
            row % 2 == 0
        } else {
            (row + column) % 2 == 0
        };
        e.assignment = if mountain {
            Assignment::Mountain
        } else {
            Assignment::Valley
        };
        e.fold_angle = None;
    }
    planarize(&mut cp, &PlanarizeOptions::default()).unwrap();
    cp
}

/// The fold angle of crease `e` measured from the folded positions alone (FOLD's sign, degrees
/// in (−180, 180]): the faces' normals on either side, oriented by the flat pattern.
fn measured_fold_angle(cp: &CreasePattern, x: &[DVec3], e: usize) -> Option<f64> {
    let faces = cp.faces.as_deref()?;
    let [j, k] = cp.edges[e].vertices;
    // The face with j → k along its boundary (counter-clockwise in the flat sheet) and the
    // face with k → j.
    let side = |from: usize, to: usize| {
        faces.iter().find(|f| {
            let n = f.outer.len();
            (0..n).any(|i| f.outer[i].index() == from && f.outer[(i + 1) % n].index() == to)
        })
    };
    let (fa, fb) = (side(j.index(), k.index())?, side(k.index(), j.index())?);
    let normal = |f: &foldcam::pattern::Face| {
        let p: Vec<DVec3> = f.outer.iter().map(|v| x[v.index()]).collect();
        (1..p.len() - 1)
            .map(|i| (p[i] - p[0]).cross(p[i + 1] - p[0]))
            .sum::<DVec3>()
            .normalize()
    };
    let (na, nb) = (normal(fa), normal(fb));
    let axis = (x[k.index()] - x[j.index()]).normalize();
    Some(nb.cross(na).dot(axis).atan2(na.dot(nb)).to_degrees())
}

/// Pairs of faces (lower first) where a side of one pierces the inside of the other by more
/// than `depth` (mm), sides that start at a shared corner excepted: an edge-through-polygon
/// test written here, independent of the simulator's triangle check.
fn faces_pierced(cp: &CreasePattern, x: &[DVec3], depth: f64) -> Vec<(usize, usize)> {
    let faces = cp.faces.as_deref().unwrap();
    let mut found = Vec::new();
    for (a, fa) in faces.iter().enumerate() {
        for (b, fb) in faces.iter().enumerate() {
            if a == b {
                continue;
            }
            let pb: Vec<DVec3> = fb.outer.iter().map(|v| x[v.index()]).collect();
            let n = (1..pb.len() - 1)
                .map(|i| (pb[i] - pb[0]).cross(pb[i + 1] - pb[0]))
                .sum::<DVec3>()
                .normalize();
            let m = fa.outer.len();
            let pierced = (0..m).any(|i| {
                let (s, t) = (fa.outer[i], fa.outer[(i + 1) % m]);
                if fb.outer.contains(&s) || fb.outer.contains(&t) {
                    return false;
                }
                let (p, q) = (x[s.index()], x[t.index()]);
                let (dp, dq) = ((p - pb[0]).dot(n), (q - pb[0]).dot(n));
                if !(dp.abs() > depth && dq.abs() > depth && dp.signum() != dq.signum()) {
                    return false;
                }
                let hit = p + (q - p) * (dp / (dp - dq));
                let k = pb.len();
                (0..k).all(|e| {
                    let inward = n.cross(pb[(e + 1) % k] - pb[e]).normalize();
                    (hit - pb[e]).dot(inward) > depth
                })
            });
            if pierced {
                found.push((a.min(b), a.max(b)));
            }
        }
    }
    found.sort_unstable();
    found.dedup();
    found
}

#[test]
fn a_fold_past_flat_is_reported_and_written_within_folds_range() {
    let cp = miura_one_kind_per_row();
    // The explicit dynamics overshoot this sheet's creases past flat, which is what is
    // reported here.
    let opts = FoldOptions {
        percent: 100.0,
        implicit: false,
        ..FoldOptions::default()
    };
    let f = fold(&cp, &opts).unwrap();
    let x = &f.folded.positions;
    let r = &f.report;
    // Creases whose faces turned through flat, measured from the positions: the turn has the
    // wrong sign for the assignment although it is near ±180.
    let through: Vec<usize> = (0..cp.edges.len())
        .filter(|&e| {
            let target = match cp.edges[e].assignment {
                Assignment::Valley => 1.0,
                Assignment::Mountain => -1.0,
                _ => return false,
            };
            // Past flat by more than the stated tolerance: the wrong sign, within 10° of ±180.
            measured_fold_angle(&cp, x, e).is_some_and(|a| {
                a * target < 0.0 && a.abs() > 170.0 && 180.0 - a.abs() > PAST_FLAT_TOLERANCE_DEG
            })
        })
        .collect();
    assert!(
        !through.is_empty(),
        "this sheet folds some crease past flat"
    );
    for e in &through {
        assert!(
            r.past_flat.iter().any(|p| p.index() == *e),
            "edge {e} turned past flat ({:?} deg measured) but is not reported: {:?}",
            measured_fold_angle(&cp, x, *e),
            r.past_flat
        );
    }
    // Every pair of faces an independent edge-through-face test finds is reported.
    let pierced = faces_pierced(&cp, x, 1e-3);
    for (a, b) in &pierced {
        assert!(
            r.crossing_faces
                .iter()
                .any(|(p, q)| (p.index(), q.index()) == (*a, *b)),
            "faces {a} and {b} pass through each other but are not reported"
        );
    }
    // What is written stays within FOLD's range, and the error is a turn, at most 180°.
    for a in r.fold_angles.iter().flatten() {
        assert!((-180.0..=180.0).contains(a), "{a}");
    }
    assert!(r.max_angle_error_deg <= 180.0, "{}", r.max_angle_error_deg);
}

#[test]
fn cli_fold3d_output_of_a_fold_past_flat_is_read_back_by_check() {
    let dir = tempfile::tempdir().unwrap();
    let input = dir.path().join("miura-rows.fold");
    std::fs::write(
        &input,
        foldcam::formats::fold::write_string(&miura_one_kind_per_row(), None),
    )
    .unwrap();
    let output = dir.path().join("folded.fold");
    let out = foldcam()
        .arg("fold3d")
        .arg(&input)
        .args(["--method", "explicit", "--percent", "100", "-o"])
        .arg(&output)
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(stdout.contains("folded past flat"), "{stdout}");
    assert!(!stdout.contains("no faces pass through"), "{stdout}");
    for frame in ["0", "1"] {
        let check = foldcam()
            .arg("check")
            .arg(&output)
            .args(["--fold-frame", frame])
            .output()
            .unwrap();
        let text = String::from_utf8_lossy(&check.stderr);
        // check exits 0 (pass) or 1 (findings); 2 is a file it refuses.
        assert!(
            matches!(check.status.code(), Some(0 | 1)),
            "frame {frame}: {text}{}",
            String::from_utf8_lossy(&check.stdout)
        );
    }
}

/// The static solve (load steps of Levenberg–Marquardt iterations, `FoldOptions::implicit`)
/// settles a Miura-ori on the closed form of its rigid kinematics, on the same fold angles as
/// the explicit dynamics settled as far, and is the result the report gives.
#[test]
fn the_static_solve_settles_a_miura_on_the_closed_form_and_the_explicit_form() {
    let (cols, rows) = (6, 6);
    let (m, cp) = miura(cols, rows);
    let run = |implicit| {
        let opts = FoldOptions {
            percent: 90.0,
            implicit,
            tolerance: 1e-7,
            ..FoldOptions::default()
        };
        fold(&cp, &opts).unwrap()
    };
    let (explicit, implicit) = (run(false), run(true));
    let r = &implicit.report;
    let solve = r.static_solve.expect("the static solve ran");
    assert!(solve.used, "{solve:?}");
    assert!(solve.factorizations >= 4 && solve.linear_solves >= solve.factorizations);
    assert_eq!(r.stop, Stop::Settled);
    assert!(r.residual < 1e-7, "{}", r.residual);
    assert!(r.wrong_sign.is_empty() && r.past_flat.is_empty());
    assert!(r.crossing_faces.is_empty());
    assert!(r.max_strain < 0.01, "{}", r.max_strain);
    assert!(explicit.report.static_solve.is_none());
    assert_pleat_on_closed_form(&m, &cp, &r.fold_angles, cols, rows);
    let apart = r
        .fold_angles
        .iter()
        .zip(&explicit.report.fold_angles)
        .filter_map(|(a, b)| Some((a.as_ref()? - b.as_ref()?).abs()))
        .fold(0.0, f64::max);
    assert!(apart < 0.1, "fold angles {apart} degrees apart");
    // The same shape up to a rigid motion (the static solve does not pin the sheet).
    let n = cp.vertices.len();
    let (a, b) = (
        &implicit.folded.positions[..n],
        &explicit.folded.positions[..n],
    );
    let off = align(a, b)
        .iter()
        .zip(b)
        .map(|(p, q)| p.distance(*q))
        .fold(0.0, f64::max);
    assert!(
        off < 1e-3 * diagonal(b),
        "{off} vs diagonal {}",
        diagonal(b)
    );
}

/// A pattern the static solve cannot settle on its assignment's side is folded by the
/// explicit dynamics after it: the report says so and still meets the explicit run's checks.
#[test]
fn a_static_solve_that_does_not_settle_hands_over_to_the_explicit_run() {
    let cp = kawasaki_violation();
    let opts = FoldOptions {
        percent: 100.0,
        implicit: true,
        ..FoldOptions::default()
    };
    let f = fold(&cp, &opts).unwrap();
    let solve = f.report.static_solve.expect("the static solve ran");
    let plain = fold(
        &cp,
        &FoldOptions {
            implicit: false,
            ..opts.clone()
        },
    )
    .unwrap();
    // The vertex cannot fold to its targets: the static solve stops short of the tolerance
    // and the explicit run's steps follow its start, ending as the explicit run alone ends.
    assert!(!solve.used, "{solve:?}");
    let start = foldcam::check::fold3d::STATIC_START_STEPS;
    assert_eq!(f.report.steps, start + plain.report.steps);
    assert_eq!(f.report.stop, plain.report.stop);
    assert_eq!(f.report.max_strain_face, plain.report.max_strain_face);
}

/// A static solve stopped by the time cap keeps its state (lifted out of flat on the
/// assignment's side, short of its target) and says so, instead of handing over to an
/// explicit run that would start from flat with no time left.
#[test]
fn a_static_solve_stopped_by_the_time_cap_keeps_its_state() {
    let (_, cp) = miura(6, 6);
    let opts = FoldOptions {
        percent: 90.0,
        max_time: std::time::Duration::ZERO,
        ..FoldOptions::default()
    };
    let f = fold(&cp, &opts).unwrap();
    let r = &f.report;
    assert_eq!(r.stop, Stop::TimeCap);
    assert!(
        r.static_solve.is_some_and(|s| s.used),
        "{:?}",
        r.static_solve
    );
    // Only the explicit lift out of flat ran.
    assert_eq!(r.steps, foldcam::check::fold3d::STATIC_START_STEPS);
    assert!(r.slower_ramps.is_empty());
    assert!(r.wrong_sign.is_empty(), "{:?}", r.wrong_sign);
    let height = (f.folded.positions.iter())
        .map(|p| p.z.abs())
        .fold(0.0, f64::max);
    assert!(height > 0.0, "still flat");
    assert!(r.max_angle_error_deg > 10.0, "{}", r.max_angle_error_deg);
}
