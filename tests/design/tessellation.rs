//! Freeform origami tessellations (Tachi 2014): initial star-tuck patterns on the regular
//! tilings of Fig. 5, the solver on the example surfaces (dome, saddle, bell), the unfolded
//! crease pattern, and its fabrication on 0.5 mm stainless steel.

use crate::cuts_clean;
use crate::support::tessellation as support;
use crate::support::tessellation_checks as checks;

use std::f64::consts::PI;
use std::path::PathBuf;

use checks::*;
use cuts_clean::assert_cuts_clean_on;
use foldcam::design::tessellation::{measure::*, steps::*, *};
use foldcam::mesh::{HalfEdgeMesh, PolyMesh};
use foldcam::pattern::{Assignment, CreasePattern};
use support::*;

fn half_edges(m: &PolyMesh) -> HalfEdgeMesh {
    HalfEdgeMesh::new(m, 1e-12).expect("manifold")
}

/// Fig. 5: at s = 1 the star tucks of the regular triangle (checkerboard and digon), square and
/// hexagon tilings are exactly developable, with d = l·cot(π/n).
#[test]
fn regular_tilings_give_exactly_developable_initial_patterns() {
    let l = 10.0;
    let cases = [
        (
            "triangles, checkerboard",
            triangle_tiling(5, 5, l),
            TuckLayout::Checkerboard,
            3,
        ),
        (
            "triangles, digons",
            triangle_tiling(5, 5, l),
            TuckLayout::Digon,
            6,
        ),
        (
            "squares, digons",
            square_tiling(5, 5, l),
            TuckLayout::Auto,
            4,
        ),
        (
            "hexagons, digons",
            hexagon_tiling(4, 4, l),
            TuckLayout::Auto,
            3,
        ),
    ];
    for (name, mesh, layout, n) in cases {
        let he = half_edges(&mesh);
        let init = star_tucks(
            &he,
            &StarOptions {
                shrink: 1.0,
                layout,
                ..StarOptions::default()
            },
        )
        .expect(name);
        let defects = angle_defects(&init.mesh, &init.mesh.positions);
        let interior = init.mesh.interior_count();
        assert!(interior > 20, "{name}: only {interior} interior vertices");
        for (v, d) in defects.iter().enumerate() {
            assert!(d.abs() < 1e-12, "{name}: vertex {v} has angle defect {d:e}");
        }
        let want = l / (PI / n as f64).tan();
        let mut checked = 0;
        for v in (0..mesh.positions().len()).filter(|&v| !he.is_boundary(v)) {
            assert_eq!(init.points[v], n, "{name}: star points at {v}");
            let d = init.depth[v].expect("interior vertices get a tuck");
            assert!(
                (d - want).abs() < 1e-12 * want,
                "{name}: depth {d} vs {want}"
            );
            let k = init.mesh.key_of_input[v].expect("key") as usize;
            let offset = mesh.positions()[v] - init.mesh.positions[k];
            assert!(
                (offset - glam::DVec3::new(0.0, 0.0, want)).length() < 1e-12,
                "{name}"
            );
            checked += 1;
        }
        assert!(checked >= 4, "{name}");
    }
}

/// The role-based mountain/valley assignment is the fold sign of the half-open pattern: on
/// the flat tilings for any shrink and layout, on the curved examples in their checkerboard
/// layout. (With digons on the dome, neighbouring tucks converge behind the surface and some
/// digon creases start over-closed, past 180°: the solver has to open them.)
#[test]
fn assignments_are_the_folds_of_the_half_open_tucks() {
    let meshes = [
        (triangle_tiling(4, 4, 10.0), true),
        (square_tiling(4, 4, 10.0), true),
        (hexagon_tiling(3, 3, 10.0), true),
        (example("dome"), false),
        (example("saddle"), false),
        (example("bell"), false),
    ];
    let shrinks = [0.6, 0.8, 0.95];
    for (mesh, flat) in meshes {
        let mesh = &mesh;
        let layouts: &[TuckLayout] = if flat {
            &[TuckLayout::Auto, TuckLayout::Digon]
        } else {
            &[TuckLayout::Auto]
        };
        for &layout in layouts {
            for shrink in shrinks {
                let mut init = star_tucks(
                    &half_edges(mesh),
                    &StarOptions {
                        shrink,
                        layout,
                        ..StarOptions::default()
                    },
                )
                .unwrap();
                assign_folds(&mut init.mesh);
                let mut creases = 0;
                for e in init.mesh.edges.iter().filter(|e| e.interior) {
                    let [i, j, a, b] = init.mesh.hinge(e).map(|v| init.mesh.positions[v as usize]);
                    let rho = fold_angle(i, j, a, b).value;
                    let want = match e.assignment {
                        Assignment::Valley => 1.0,
                        Assignment::Mountain => -1.0,
                        _ => continue,
                    };
                    assert_eq!(rho.signum(), want, "{:?} at s = {shrink}: {rho}", e.role);
                    creases += 1;
                }
                assert!(creases > 50);
            }
        }
    }
}

/// Solves an example with the 0.5 mm stainless limits and checks every done-when criterion.
fn solved(name: &str) -> Tessellation {
    let limits = stainless_limits();
    let t = tessellate(
        &example(name),
        &TessellateOptions::with_limits(limits),
        &mut (),
    )
    .unwrap();
    let r = &t.report;
    eprintln!("{name}: {}", r.summary());
    assert!(r.converged, "{name}: {}", r.summary());
    assert!(r.last.developability < 1e-9, "{name}");
    assert!(r.last.max_fold <= limits.max_fold, "{name}");
    assert!(r.last.wrong_sign >= 0.0, "{name}");
    assert!(r.last.min_vertex_angle >= limits.min_vertex_angle, "{name}");
    // Independent re-measurement on the solved mesh.
    for (v, d) in angle_defects(&t.mesh, &t.mesh.positions).iter().enumerate() {
        assert!(d.abs() < 1e-9, "{name}: vertex {v} defect {d:e}");
    }
    // Eq. 5–7 are active by default and leave no crease through a vertex-adjacent face.
    assert!(r.limits.vertex_penalty, "{name}");
    assert_eq!(r.last.illegal_creases, 0, "{name}");
    assert!(t.intersections.is_empty(), "{name}: {:?}", t.intersections);
    t
}

#[test]
fn dome_converges_and_unfolds_isometrically() {
    let t = solved("dome");
    check_unfolded("dome", &t);
}

#[test]
fn saddle_converges_and_unfolds_isometrically() {
    let t = solved("saddle");
    check_unfolded("saddle", &t);
}

#[test]
fn bell_converges_and_unfolds_isometrically() {
    let t = solved("bell");
    check_unfolded("bell", &t);
}

/// The unfolded dome goes through the fabrication pipeline on the fiber laser with 0.5 mm
/// stainless steel: planned, written as G-code, run on the simulated machine without
/// violations and with every crease and cut covered.
#[test]
fn unfolded_dome_cuts_clean_on_stainless() {
    let t = solved("dome");
    let cp: &CreasePattern = &t.unfolded.as_ref().expect("unfolds").pattern;
    assert_cuts_clean_on("dome", cp, "linuxcnc-fiber", "stainless-0.5");
}

#[test]
fn bad_input_is_refused_with_a_reason() {
    let tetra = PolyMesh::new(
        vec![
            glam::DVec3::ZERO,
            glam::DVec3::X,
            glam::DVec3::Y,
            glam::DVec3::Z,
        ],
        vec![vec![0, 2, 1], vec![0, 1, 3], vec![1, 2, 3], vec![0, 3, 2]],
    )
    .unwrap();
    let opts = TessellateOptions::default();
    assert!(matches!(
        tessellate(&tetra, &opts, &mut ()),
        Err(TessError::NotADisk(_))
    ));
    let mut shrink = opts.clone();
    shrink.star.shrink = 0.0;
    assert!(matches!(
        tessellate(&example("dome"), &shrink, &mut ()),
        Err(TessError::BadParameter(_))
    ));
    shrink.star.shrink = f64::NAN;
    assert!(matches!(
        tessellate(&example("dome"), &shrink, &mut ()),
        Err(TessError::BadParameter(_))
    ));
    let mut checker = opts.clone();
    checker.star.layout = TuckLayout::Checkerboard;
    let squares = square_tiling(3, 3, 10.0);
    assert!(matches!(
        tessellate(&squares, &checker, &mut ()),
        Err(TessError::BadParameter(_))
    ));
    let mut limits = opts;
    limits.solve.limits = Limits::from_degrees(200.0, 30.0);
    assert!(matches!(
        tessellate(&example("dome"), &limits, &mut ()),
        Err(TessError::BadParameter(_))
    ));
}

fn foldcam(args: &[&str]) -> std::process::Output {
    std::process::Command::new(env!("CARGO_BIN_EXE_foldcam"))
        .args(args)
        .output()
        .expect("runs")
}

/// The command writes a FOLD with the pattern (frame 0) and the folded form (frame 1) and the two
/// previews, and refuses out-of-range variation parameters with exit 2, writing nothing.
#[test]
fn cli_writes_pattern_folded_form_and_previews() {
    let dir = tempfile::tempdir().expect("temp dir");
    let out = dir.path().join("dome.fold");
    let (png, cp_png) = (dir.path().join("f.png"), dir.path().join("cp.png"));
    let mesh = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("examples/tessellation/dome.obj");
    let run = foldcam(&[
        "tessellate",
        mesh.to_str().expect("utf-8"),
        "-x",
        "stainless-0.5",
        "-o",
        out.to_str().expect("utf-8"),
        "--png",
        png.to_str().expect("utf-8"),
        "--cp-png",
        cp_png.to_str().expect("utf-8"),
    ]);
    let stdout = String::from_utf8_lossy(&run.stdout);
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert!(run.status.success(), "{stdout}\n{stderr}");
    assert!(
        stdout.contains("converged") && stderr.contains("iteration"),
        "{stdout}{stderr}"
    );
    assert!(
        stdout.contains("illegal creases 0")
            && stdout.contains("face intersections")
            && stdout.contains("): none"),
        "{stdout}"
    );
    let imported = foldcam::formats::load(&out).expect("readable FOLD");
    let folded = imported.folded.expect("folded frame");
    assert_eq!(folded.positions.len(), imported.pattern.vertices.len());
    assert_eq!(folded.edges.len(), imported.pattern.edges.len());
    assert!(folded.positions.iter().any(|p| p.z.abs() > 1.0));
    for p in [png, cp_png] {
        assert!(std::fs::read(&p).expect("written").starts_with(b"\x89PNG"));
    }
    for (tuck, flag, value, complaint) in [
        (
            "truncated",
            "--truncation",
            "1.5",
            "truncation must be in (0, 1)",
        ),
        ("twisted", "--twist", "0", "twist must be non-zero"),
        ("twist", "--twist", "95", "within (-90, 90) degrees"),
    ] {
        let out = dir.path().join(format!("{tuck}.fold"));
        let run = foldcam(&[
            "tessellate",
            mesh.to_str().expect("utf-8"),
            "--tuck",
            tuck,
            flag,
            value,
            "-o",
            out.to_str().expect("utf-8"),
        ]);
        assert_eq!(run.status.code(), Some(2), "{tuck}");
        let stderr = String::from_utf8_lossy(&run.stderr);
        assert!(stderr.contains(complaint), "{tuck}: {stderr}");
        assert!(!out.exists(), "{tuck}: nothing written");
    }
}

/// Ground contact (§6): the bell stands on a table, every boundary vertex on one plane.
#[test]
fn bell_stands_on_the_ground() {
    let mut opts = TessellateOptions::with_limits(stainless_limits());
    opts.ground = true;
    let t = tessellate(&example("bell"), &opts, &mut ()).unwrap();
    assert!(t.report.converged, "{}", t.report.summary());
    let z0 = t.report.limits.ground_z.expect("plane chosen");
    let on_ground = t
        .mesh
        .positions
        .iter()
        .zip(&t.mesh.interior)
        .filter(|(_, inside)| !**inside)
        .inspect(|(p, _)| assert!((p.z - z0).abs() < 1e-9, "{} vs {z0}", p.z))
        .count();
    assert!(on_ground > 30);
    check_unfolded("bell on the ground", &t);
}

/// Surface fit (§3.4): moves projected by eq. 9 bring the solved saddle closer to its input
/// face corners while every condition still holds.
#[test]
fn surface_fit_reduces_the_distance_and_keeps_the_constraints() {
    let limits = stainless_limits();
    let mut opts = TessellateOptions::with_limits(limits);
    opts.fit = Some(FitOptions {
        weight: 0.1,
        rounds: 10,
    });
    let t = tessellate(&example("saddle"), &opts, &mut ()).unwrap();
    let fit = t.fit.expect("fit ran after a converged solve");
    assert!(fit.accepted > 0 && fit.last < 0.9 * fit.initial, "{fit:?}");
    let r = residuals(&t.mesh, &t.mesh.positions, None);
    assert!(r.developability < 1e-9, "{r:?}");
    assert!(
        r.max_fold <= limits.max_fold && r.wrong_sign >= 0.0,
        "{r:?}"
    );
    assert!(r.min_vertex_angle >= limits.min_vertex_angle, "{r:?}");
    check_unfolded("fitted saddle", &t);
}

/// The digon layout (every face black, a six-pointed star at each valence-6 vertex) solves the
/// dome once the limits allow its 12 thin tuck triangles per key vertex (their angles at the
/// key average 30°, so δ_corner = 30° leaves no room): fold ≤ 178°, vertex angle ≥ 15°.
#[test]
fn digon_layout_solves_the_dome_with_relaxed_limits() {
    let limits = Limits::from_degrees(178.0, 15.0);
    let mut opts = TessellateOptions::with_limits(limits);
    opts.star.layout = TuckLayout::Digon;
    let t = tessellate(&example("dome"), &opts, &mut ()).unwrap();
    assert_eq!(t.initial.layout, TuckLayout::Digon);
    assert!(t.report.converged, "{}", t.report.summary());
    let r = residuals(&t.mesh, &t.mesh.positions, None);
    assert!(r.developability < 1e-9 && r.wrong_sign >= 0.0, "{r:?}");
    assert!(r.max_fold <= limits.max_fold && r.min_vertex_angle >= limits.min_vertex_angle);
    let u = t.unfolded.as_ref().expect("no overlaps");
    assert!(u.max_length_error < 1e-9);
    let digons = edges_with_role(&t.mesh, EdgeRole::Digon);
    let he = half_edges(&example("dome"));
    let interior_edges = he.half_edges().iter().filter(|h| h.twin.is_some()).count() / 2;
    assert_eq!(
        digons, interior_edges,
        "one digon crease per interior input edge"
    );
}

/// The face-intersection check finds a constructed pair of folded faces passing through each
/// other (one sharing a vertex with it, one apart), and refuses non-triangular faces.
#[test]
fn folded_intersections_find_faces_through_each_other() {
    use foldcam::pattern::{Face, FoldedState, VertexId};
    use glam::DVec3;
    let face = |v: [usize; 3]| Face::simple(v.map(VertexId::new).to_vec());
    let positions = vec![
        DVec3::new(0.0, 0.0, 0.0),
        DVec3::new(10.0, 0.0, 0.0),
        DVec3::new(0.0, 10.0, 0.0),
        // Shares vertex 0; its far edge pierces face 0.
        DVec3::new(5.0, 1.0, -2.0),
        DVec3::new(1.0, 5.0, 2.0),
        // Apart from everything, well above the plane.
        DVec3::new(2.0, 2.0, 5.0),
        DVec3::new(4.0, 2.0, 6.0),
        DVec3::new(2.0, 4.0, 7.0),
        // Shares nothing; pierces faces 0 and 1 along (2, 2, 0)–(2.5, 2.5, 0).
        DVec3::new(2.0, 2.0, -1.0),
        DVec3::new(2.0, 2.0, 1.0),
        DVec3::new(3.0, 3.0, 1.0),
    ];
    let mut folded = FoldedState {
        positions,
        edges: Vec::new(),
        faces: Some(vec![
            face([0, 1, 2]),
            face([0, 3, 4]),
            face([5, 6, 7]),
            face([8, 9, 10]),
        ]),
        face_orders: Vec::new(),
    };
    let found = folded_intersections(&folded, 1e-3).unwrap();
    assert_eq!(found, vec![(0, 1), (0, 3), (1, 3)]);
    folded.faces = Some(vec![Face::simple([0, 1, 2, 3].map(VertexId::new).to_vec())]);
    assert!(matches!(
        folded_intersections(&folded, 1e-3),
        Err(TessError::BadParameter(_))
    ));
}

/// A straight strip of squares (2 × 40, 10 mm) wrapped onto a cone with sin(half-angle) =
/// 1/4: the strip is a geodesic band that winds 1.6 times around the cone and crosses itself,
/// a global (type 3) collision that no local condition of §3 sees.
fn strip_on_a_cone() -> PolyMesh {
    let (sa, ca) = (0.25f64, (1.0f64 - 0.0625).sqrt());
    let ys = [60.0, 70.0, 80.0];
    let mut positions = Vec::new();
    for i in 0..41 {
        let x = -200.0 + 10.0 * i as f64;
        for y in ys {
            let (r, phi) = (f64::hypot(x, y), f64::atan2(y, x));
            let (rho, psi) = (r * sa, phi / sa);
            positions.push(glam::DVec3::new(rho * psi.cos(), rho * psi.sin(), -r * ca));
        }
    }
    let faces = (0..40u32)
        .flat_map(|i| (0..2u32).map(move |j| (i * 3 + j, (i + 1) * 3 + j)))
        .map(|(p, q)| vec![p, p + 1, q + 1, q])
        .collect();
    PolyMesh::new(positions, faces).expect("valid strip")
}

/// The solve converges on the self-crossing strip, the check reports the crossing faces, and
/// the command refuses to write it (exit 1, with the reason).
#[test]
fn a_self_crossing_result_is_found_and_not_written() {
    let mesh = strip_on_a_cone();
    let t = tessellate(
        &mesh,
        &TessellateOptions::with_limits(stainless_limits()),
        &mut (),
    )
    .unwrap();
    assert!(t.report.converged, "{}", t.report.summary());
    assert!(t.intersections.len() > 10, "{}", t.summary());
    let folded = &t.unfolded.as_ref().expect("unfolds flat").folded;
    assert_eq!(
        folded_intersections(folded, t.intersection_tolerance).unwrap(),
        t.intersections
    );
    let dir = tempfile::tempdir().expect("temp dir");
    let obj = dir.path().join("cone.obj");
    std::fs::write(&obj, mesh.to_obj()).expect("written");
    let out = dir.path().join("cone.fold");
    // One shrink, the library's default above: the whole ladder, on the strip's own triangles
    // and re-triangulated, takes minutes in a debug build and ends in the same refusal.
    let run = foldcam(&[
        "tessellate",
        obj.to_str().expect("utf-8"),
        "-x",
        "stainless-0.5",
        "--shrink",
        "0.8",
        "-o",
        out.to_str().expect("utf-8"),
    ]);
    let stdout = String::from_utf8_lossy(&run.stdout);
    assert_eq!(run.status.code(), Some(1), "{stdout}");
    assert!(stdout.contains("intersects itself"), "{stdout}");
    assert!(!out.exists());
}

/// Counts what a ladder reports: iterations and refused results.
#[derive(Default)]
struct Counts {
    iterations: usize,
    refused: Vec<f64>,
}

impl Watch for Counts {
    fn iteration(&mut self, _: &Iteration) -> std::ops::ControlFlow<()> {
        self.iterations += 1;
        std::ops::ControlFlow::Continue(())
    }

    fn refused(&mut self, shrink: f64, _: &Tessellation) -> std::ops::ControlFlow<()> {
        self.refused.push(shrink);
        std::ops::ControlFlow::Continue(())
    }
}

/// A ladder whose time limit has run out stops: the solve under way keeps what it reached (here
/// nothing: the limit is zero), no other shrink or triangulation is tried, and the result is
/// refused with the time limit named; the same ladder without a limit goes on to the next shrink.
#[test]
fn a_time_limit_ends_the_ladder_with_its_reason() {
    let mesh = foldcam::design::tessellation::samples::spherical_cap(12, 6, 60.0, 100.0);
    let mut opts = TessellateOptions::with_limits(stainless_limits());
    opts.schedule = Schedule::ladder();
    opts.time_limit = Some(std::time::Duration::ZERO);
    let mut heard = Counts::default();
    let t = tessellate(&mesh, &opts, &mut heard).unwrap();
    assert_eq!(heard.iterations, 0);
    assert_eq!(heard.refused, [SHRINK_LADDER[0]], "one attempt only");
    assert!(t.report.out_of_time && !t.report.converged);
    assert_eq!(t.report.iterations, 0);
    assert_eq!(t.out_of_time, Some(std::time::Duration::ZERO));
    let problem = t.problem().expect("refused");
    assert!(problem.contains("time limit of 0ns ran out"), "{problem}");
    assert!(
        t.report.summary().contains("time limit"),
        "{}",
        t.report.summary()
    );
}

/// `--time-limit` on the command line: the cap's ladder cut short after 50 ms exits 1 with the
/// reason and writes nothing; 0 and negative limits are refused or mean no limit as the help says.
#[test]
fn cli_time_limit_refuses_with_the_reason_and_writes_nothing() {
    let dir = tempfile::tempdir().expect("temp dir");
    let out = dir.path().join("cap.fold");
    let mesh = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("examples/tessellation/cap.obj");
    let with_limit = |limit: &str| {
        foldcam(&[
            "tessellate",
            mesh.to_str().expect("utf-8"),
            &format!("--time-limit={limit}"),
            "-o",
            out.to_str().expect("utf-8"),
        ])
    };
    let run = with_limit("0.05");
    let stdout = String::from_utf8_lossy(&run.stdout);
    assert_eq!(run.status.code(), Some(1), "{stdout}");
    assert!(
        stdout.contains("nothing written") && stdout.contains("time limit of 50ms ran out"),
        "{stdout}"
    );
    assert!(!out.exists());
    let run = with_limit("-3");
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert_eq!(run.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains("--time-limit"), "{stderr}");
    assert!(!out.exists());
}
