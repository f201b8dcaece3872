//! Fold-sequence simulator (Miyazaki et al. 1992): isometry after every step, consistent layer orders,
//! flat-foldable crease patterns, exact undo, the paper's drag rule and snapping, refused
//! steps, FOLD frames, the bird base and its path through the fabrication pipeline.

use std::path::{Path, PathBuf};
use std::process::Command;

use foldcam::check::{CheckOptions, check};
use foldcam::design::folding::layer_problems;
use foldcam::design::folding::{Drag, Snap, Snapped};
use foldcam::design::folding::{Fold, FoldError, Folding, Layers, Turn};
use foldcam::design::folding::{ScriptError, parse_script, run_script};
use foldcam::design::folding::{crease_pattern, step_states};
use foldcam::fab::{PlanOptions, plan};
use foldcam::formats::fold::{frame_count, parse_root, resolve_frame, write_string_frames};
use foldcam::machine::{load_machine, load_material};
use foldcam::pattern::Assignment;
use foldcam::{post, sim};
use glam::{DVec2, DVec3};

#[path = "folding/carry.rs"]
mod carry;
#[path = "folding/non_convex.rs"]
mod non_convex;
#[path = "folding/tuck_blocked.rs"]
mod tuck_blocked;

const EXAMPLES: [&str; 4] = [
    "paper-airplane.toml",
    "waterbomb-base.toml",
    "preliminary-base.toml",
    "bird-base.toml",
];

fn example_path(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("examples/folding")
        .join(name)
}

fn example(name: &str) -> Folding {
    let text = std::fs::read_to_string(example_path(name)).expect("example readable");
    let script = parse_script(&text).unwrap_or_else(|e| panic!("{name}: {e}"));
    run_script(&script).unwrap_or_else(|e| panic!("{name}: {e}"))
}

fn square(side: f64) -> Folding {
    Folding::new(&[
        DVec2::ZERO,
        DVec2::new(side, 0.0),
        DVec2::new(side, side),
        DVec2::new(0.0, side),
    ])
    .expect("square sheet")
}

fn flat(f: &Folding, step: usize) -> bool {
    let s = &f.steps()[step].state;
    s.groups.len() == 1 && (0..s.faces.len()).all(|i| s.face_normal(i).z.abs() > 1.0 - 1e-12)
}

/// Every face's corners keep their sheet distances, its transform is a proper rotation, and
/// the faces of every step tile the sheet (areas add up).
#[test]
fn every_face_keeps_its_shape_after_every_step() {
    for name in EXAMPLES {
        assert_every_step_isometric(&example(name), name);
    }
}

/// Isometry (within 1e-9), proper rotations, the sheet tiled and the neighbour lists right,
/// after every step of `f`.
fn assert_every_step_isometric(f: &Folding, name: &str) {
    let sheet_area = area(f.sheet());
    for (k, step) in f.steps().iter().enumerate() {
        let mut total = 0.0;
        for face in &step.state.faces {
            let flat = f.cells()[face.cell.index()].polygon.clone();
            let corners: Vec<DVec3> = flat
                .iter()
                .map(|p| face.transform.transform_point3(p.extend(0.0)))
                .collect();
            for i in 0..flat.len() {
                for j in i + 1..flat.len() {
                    let d2 = flat[i].distance(flat[j]);
                    let d3 = corners[i].distance(corners[j]);
                    assert!((d2 - d3).abs() < 1e-9, "{name} step {k}: {d2} vs {d3}");
                }
            }
            assert!((face.transform.matrix3.determinant() - 1.0).abs() < 1e-9);
            total += area(&flat);
        }
        assert!(
            (total - sheet_area).abs() < 1e-6 * sheet_area,
            "{name} step {k}"
        );
        assert_neighbours_match_the_sheet(f, k);
    }
}

/// The kept edge-neighbour lists equal the pairs of faces that share an edge on the sheet.
fn assert_neighbours_match_the_sheet(f: &Folding, step: usize) {
    let faces = &f.steps()[step].state.faces;
    for (i, a) in faces.iter().enumerate() {
        for (j, b) in faces.iter().enumerate().filter(|(j, _)| *j != i) {
            let (pa, pb) = (f.polygon(a), f.polygon(b));
            let touching = (0..pa.len()).any(|x| {
                (0..pb.len()).any(|y| {
                    shares_edge(pa[x], pa[(x + 1) % pa.len()], pb[y], pb[(y + 1) % pb.len()])
                })
            });
            assert_eq!(
                a.neighbours.iter().any(|n| n.face == j),
                touching,
                "step {step}: faces {i}, {j}"
            );
        }
    }
}

/// Whether two segments lie on one line and overlap over more than a micrometre.
fn shares_edge(a0: DVec2, a1: DVec2, b0: DVec2, b1: DVec2) -> bool {
    let d = (a1 - a0).normalize();
    let off = |p: DVec2| d.perp_dot(p - a0).abs();
    if off(b0) > 1e-6 || off(b1) > 1e-6 {
        return false;
    }
    let t = |p: DVec2| d.dot(p - a0);
    let (lo, hi) = (t(b0).min(t(b1)), t(b0).max(t(b1)));
    hi.min(t(a1)) - lo.max(0.0) > 1e-3
}

fn area(poly: &[DVec2]) -> f64 {
    let n = poly.len();
    (0..n)
        .map(|i| poly[i].perp_dot(poly[(i + 1) % n]))
        .sum::<f64>()
        / 2.0
}

#[test]
fn flat_layer_orders_are_consistent_and_the_check_can_fail() {
    let mut flat_states = 0;
    for name in EXAMPLES {
        let f = example(name);
        for k in 0..f.steps().len() {
            if flat(&f, k) {
                let problems = layer_problems(&f, &f.steps()[k].state);
                assert!(problems.is_empty(), "{name} step {k}: {problems:?}");
                flat_states += 1;
            }
        }
    }
    assert!(flat_states >= 25, "{flat_states} flat states checked");
    // Swapping the two tucked layers of the waterbomb base makes them pass through each other.
    let f = example("waterbomb-base.toml");
    let mut state = f.current().clone();
    let stack = &mut state.groups[0].stack;
    let n = stack.len();
    stack.swap(0, n - 1);
    assert!(!layer_problems(&f, &state).is_empty());
}

#[test]
fn flat_examples_cut_flat_foldable_crease_patterns() {
    for name in [
        "waterbomb-base.toml",
        "preliminary-base.toml",
        "bird-base.toml",
    ] {
        let f = example(name);
        let cp = crease_pattern(&f).pattern;
        cp.validate().expect("valid pattern");
        let report = check(&cp, &CheckOptions::default());
        // Every interior vertex where a fold meets is checked (Kawasaki and Maekawa).
        let interior = interior_fold_vertices(&cp);
        assert!(interior >= 1, "{name}");
        assert!(
            report.summary.interior_vertices_checked >= interior,
            "{name}: {} of {interior} checked",
            report.summary.interior_vertices_checked
        );
        assert_eq!(report.summary.maekawa_skipped_unassigned, 0, "{name}");
        assert!(report.passed(), "{name}: {:?}", report.findings);
    }
    // The airplane before its wings open is flat too.
    let mut f = example("paper-airplane.toml");
    let last = f.steps().len() - 1;
    f.undo_to(last - 2).expect("step exists");
    let report = check(&crease_pattern(&f).pattern, &CheckOptions::default());
    assert!(report.passed(), "airplane: {:?}", report.findings);
}

/// The vertices off the sheet outline with a mountain or valley fold at them.
fn interior_fold_vertices(cp: &foldcam::pattern::CreasePattern) -> usize {
    let mut on_boundary = vec![false; cp.vertices.len()];
    let mut folded = vec![false; cp.vertices.len()];
    for e in &cp.edges {
        for v in e.vertices {
            on_boundary[v.index()] |= e.assignment == Assignment::Boundary;
            folded[v.index()] |= e.assignment.is_fold();
        }
    }
    (0..cp.vertices.len())
        .filter(|&v| folded[v] && !on_boundary[v])
        .count()
}

#[test]
fn waterbomb_base_has_one_midline_and_both_diagonals() {
    let cp = crease_pattern(&example("waterbomb-base.toml")).pattern;
    let count = |a| cp.edges.iter().filter(|e| e.assignment == a).count();
    // Diagonals: four valley halves; the midline: two mountain halves (reversed by the tucks).
    assert_eq!(count(Assignment::Valley), 4);
    assert_eq!(count(Assignment::Mountain), 2);
    for e in &cp.edges {
        let (a, b) = (
            cp.vertices[e.vertices[0].index()],
            cp.vertices[e.vertices[1].index()],
        );
        let d = b - a;
        match e.assignment {
            Assignment::Valley => assert!((d.x.abs() - d.y.abs()).abs() < 1e-9),
            Assignment::Mountain => assert!(d.y.abs() < 1e-9 && (a.y - 75.0).abs() < 1e-9),
            _ => {}
        }
    }
}

#[test]
fn undo_restores_the_exact_earlier_state() {
    let mut f = example("bird-base.toml");
    let saved: Vec<_> = f.steps().iter().map(|s| s.state.clone()).collect();
    let cells: Vec<usize> = f.steps().iter().map(|s| s.cells).collect();
    for k in (0..saved.len() - 1).rev() {
        f.undo().expect("undo");
        assert_eq!(f.current(), &saved[k], "step {k}");
        assert_eq!(f.cells().len(), cells[k]);
    }
    assert_eq!(f.undo(), Err(FoldError::NothingToUndo));
    // Undo to a middle step, then refold the same steps: the same states again.
    let mut g = example("waterbomb-base.toml");
    let end = g.current().clone();
    g.undo_to(1).expect("undo to step 1");
    assert_eq!(g.steps().len(), 2);
    let tuck = |line: [DVec3; 2], moving: DVec3| Fold {
        line,
        moving,
        turn: Turn::Tuck,
        layers: Layers::All,
    };
    let p = |x: f64, y: f64| DVec3::new(x, y, 0.0);
    g.fold(&tuck([p(75.0, 75.0), p(0.0, 0.0)], p(10.0, 70.0)), None)
        .expect("tuck");
    g.fold(&tuck([p(75.0, 75.0), p(150.0, 0.0)], p(140.0, 70.0)), None)
        .expect("tuck");
    assert_eq!(g.current(), &end);
    assert_eq!(
        g.undo_to(9),
        Err(FoldError::NoSuchStep { step: 9, last: 3 })
    );
}

#[test]
fn impossible_steps_are_refused_and_change_nothing() {
    let mut f = square(100.0);
    let p = |x: f64, y: f64| DVec3::new(x, y, 0.0);
    let bend = |line: [DVec3; 2], moving: DVec3, turn: Turn| Fold {
        line,
        moving,
        turn,
        layers: Layers::All,
    };
    f.fold(
        &bend(
            [p(0.0, 50.0), p(100.0, 50.0)],
            p(50.0, 90.0),
            Turn::Angle(180.0),
        ),
        None,
    )
    .expect("fold in half");
    let before = f.clone();
    let cases = [
        (
            bend(
                [p(200.0, 0.0), p(200.0, 100.0)],
                p(250.0, 0.0),
                Turn::Angle(90.0),
            ),
            "misses",
        ),
        (
            bend(
                [p(200.0, 0.0), p(200.0, 100.0)],
                p(50.0, 0.0),
                Turn::Angle(90.0),
            ),
            "misses",
        ),
        (
            bend(
                [p(0.0, 0.0), p(100.0, 0.0)],
                p(50.0, 20.0),
                Turn::Angle(0.0),
            ),
            "angle",
        ),
        (
            bend([p(0.0, 0.0), p(0.0, 0.0)], p(50.0, 20.0), Turn::Angle(90.0)),
            "coincide",
        ),
        (
            bend(
                [DVec3::new(0.0, 0.0, 5.0), DVec3::new(9.0, 0.0, 5.0)],
                DVec3::new(5.0, 5.0, 5.0),
                Turn::Angle(90.0),
            ),
            "plane",
        ),
        (
            bend(
                [p(f64::NAN, 0.0), p(1.0, 0.0)],
                p(5.0, 5.0),
                Turn::Angle(90.0),
            ),
            "finite",
        ),
    ];
    for (fold, word) in &cases {
        let err = f.fold(fold, None).expect_err(word);
        assert!(err.to_string().contains(word), "{err}");
        assert_eq!(f, before);
    }
    // A tuck-in of a single layer (a corner of the top layer only) is refused.
    let mut g = square(100.0);
    let err = g
        .fold(
            &bend([p(0.0, 80.0), p(20.0, 100.0)], p(0.0, 100.0), Turn::Tuck),
            None,
        )
        .expect_err("odd tuck");
    assert!(matches!(err, FoldError::TuckAsymmetric(_)), "{err}");
    assert_eq!(g.steps().len(), 1);
}

#[test]
fn a_drag_folds_about_the_bisector_by_twice_the_plane_angle() {
    let mut f = square(100.0);
    let p = DVec3::new(100.0, 30.0, 0.0);
    let q = DVec3::new(70.0, 30.0, 30.0);
    let drag = Drag {
        from: p + DVec3::new(0.3, 0.2, 0.0),
        to: q,
        pick_radius: 1.0,
        mountain: false,
        snap: Snap {
            vertex: 0.0,
            edge: 0.0,
            line: 0.0,
            angle_deg: 0.0,
        },
        edge_points: false,
    };
    // P is no vertex: nothing to pick.
    assert!(matches!(
        f.plan_drag(&drag),
        Err(FoldError::NoVertexNear { .. })
    ));
    let p = DVec3::new(100.0, 100.0, 0.0);
    let q = DVec3::new(60.0, 60.0, 40.0 * 2f64.sqrt() * 0.8);
    let drag = Drag {
        from: p + DVec3::new(-0.3, 0.2, 0.0),
        to: q,
        ..drag
    };
    let (plan, report) = f.drag(&drag, None).expect("drag");
    assert!(plan.snapped.is_empty());
    assert!(plan.vertex.1.distance(q) < 1e-9, "{:?}", plan.vertex);
    // Fig. 3: twice the angle between the sheet plane and the bisector plane of P, Q.
    let w = (q - p).normalize();
    let expected = 2.0 * w.dot(DVec3::Z).abs().acos();
    assert!(
        (report.angle_deg.to_radians().abs() - expected).abs() < 1e-9,
        "{} vs {}",
        report.angle_deg,
        expected.to_degrees()
    );
    // The fold line lies in both planes: equidistant from P and Q, and on the sheet.
    let Turn::Angle(_) = plan.fold.turn else {
        panic!("a drag folds up")
    };
    for a in plan.fold.line {
        assert!((a.distance(p) - a.distance(q)).abs() < 1e-9 && a.z.abs() < 1e-12);
    }
}

#[test]
fn drags_snap_to_vertices_edges_lines_and_angles() {
    let none = Snap {
        vertex: 0.0,
        edge: 0.0,
        line: 0.0,
        angle_deg: 0.0,
    };
    let corner = DVec3::new(100.0, 100.0, 0.0);
    let near_origin = DVec3::new(1.5, 0.8, 0.0);
    let cases = [
        (
            Snap {
                vertex: 2.0,
                ..none
            },
            Snapped::Vertex,
        ),
        (Snap { edge: 3.0, ..none }, Snapped::EdgeOntoEdge),
        (Snap { line: 3.0, ..none }, Snapped::LineThroughVertices),
    ];
    for (snap, rule) in cases {
        let f = square(100.0);
        let drag = Drag {
            from: corner,
            to: near_origin,
            pick_radius: 1.0,
            mountain: false,
            snap,
            edge_points: false,
        };
        let plan = f.plan_drag(&drag).expect("plan");
        assert_eq!(plan.snapped.first(), Some(&rule));
        assert!(
            plan.vertex.1.distance(DVec3::ZERO) < 1e-9,
            "{rule:?}: {:?}",
            plan.vertex
        );
        // Without snapping the corner lands where it was dragged.
        let raw = f.plan_drag(&Drag { snap: none, ..drag }).expect("plan");
        assert!(raw.vertex.1.distance(near_origin) < 1e-9);
    }
    // Angle: a fold up by about 89° snaps to 90°.
    let f = square(100.0);
    let drag = Drag {
        from: DVec3::new(100.0, 0.0, 0.0),
        to: DVec3::new(50.9, 0.0, 50.0),
        pick_radius: 1.0,
        mountain: false,
        snap: Snap {
            angle_deg: 3.0,
            ..none
        },
        edge_points: false,
    };
    let plan = f.plan_drag(&drag).expect("plan");
    assert_eq!(plan.fold.turn, Turn::Angle(90.0));
    assert!(matches!(plan.snapped.as_slice(), [Snapped::Angle(a)] if *a == 90.0));
}

#[test]
fn fold_up_angle_and_sign_reach_the_crease_pattern() {
    for (angle, assignment) in [(90.0, Assignment::Valley), (-60.0, Assignment::Mountain)] {
        let mut f = square(100.0);
        let p = |x: f64, y: f64| DVec3::new(x, y, 0.0);
        f.fold(
            &Fold {
                line: [p(40.0, 0.0), p(40.0, 100.0)],
                moving: p(90.0, 50.0),
                turn: Turn::Angle(angle),
                layers: Layers::All,
            },
            None,
        )
        .expect("fold up");
        assert_eq!(f.current().groups.len(), 2);
        let cp = crease_pattern(&f).pattern;
        let crease: Vec<_> = cp.edges.iter().filter(|e| e.assignment.is_fold()).collect();
        assert_eq!(crease.len(), 1);
        assert_eq!(crease[0].assignment, assignment);
        assert!((crease[0].fold_angle.expect("angle") - angle).abs() < 1e-9);
        // The moved corner turned about x = 40 by the angle (towards +z for a valley).
        let a = f64::to_radians(angle);
        let expected = DVec3::new(40.0 + 60.0 * a.cos(), 100.0, 60.0 * a.sin());
        let states = step_states(&f, &crease_pattern(&f));
        assert!(
            states[1]
                .positions
                .iter()
                .any(|q| q.distance(expected) < 1e-9)
        );
        assert!(
            !states[0]
                .positions
                .iter()
                .any(|q| q.distance(expected) < 1e-3)
        );
    }
}

#[test]
fn fold_file_holds_the_pattern_and_one_frame_per_step() {
    let f = example("waterbomb-base.toml");
    let sheet = crease_pattern(&f);
    let states = step_states(&f, &sheet);
    let text = write_string_frames(&sheet.pattern, &states);
    let root = parse_root(&text).expect("FOLD JSON");
    assert_eq!(frame_count(&root).expect("frames"), 1 + f.steps().len());
    for (k, state) in states.iter().enumerate() {
        let frame = resolve_frame(&root, k + 1).expect("frame");
        let coords = frame["vertices_coords"].as_array().expect("coords");
        assert_eq!(coords.len(), state.positions.len());
        for (c, p) in coords.iter().zip(&state.positions) {
            let c: Vec<f64> = c
                .as_array()
                .expect("point")
                .iter()
                .map(|x| x.as_f64().expect("number"))
                .collect();
            assert!(DVec3::new(c[0], c[1], c[2]).distance(*p) < 1e-9);
        }
        let orders = frame
            .get("faceOrders")
            .and_then(|v| v.as_array())
            .map_or(0, Vec::len);
        assert_eq!(orders, state.face_orders.len());
    }
    // The final waterbomb base: 6 faces, all overlapping pairs ordered, each pair once.
    let last = states.last().expect("states");
    assert!(last.face_orders.len() >= 6);
    // The flat sheet has no crease folded yet.
    assert!(
        states[0]
            .edges
            .iter()
            .all(|e| e.fold_angle.unwrap_or(0.0) == 0.0)
    );
}

#[test]
fn the_bird_base_cuts_clean_on_card_stock() {
    let cp = crease_pattern(&example("bird-base.toml")).pattern;
    let machine = load_machine("grbl-diode").expect("machine");
    let material = load_material("card-300gsm").expect("material");
    let opts = PlanOptions::for_machine(&machine, &material, &Default::default())
        .expect("machine fits material");
    let p = plan(&cp, &machine, &material, &opts).expect("plan");
    assert!(!p.jobs.is_empty());
    for job in &p.jobs {
        let gcode = post::gcode(&p, job, &machine).expect("G-code");
        let run = sim::run(&gcode, &machine).expect("readable");
        assert!(run.is_clean(), "{:?}", run.violations.first());
        let cov = sim::coverage(&run, &cp, job, &p);
        assert!(cov.passed(), "{:?}", cov.failed_edges().next());
    }
}

#[test]
fn script_errors_name_the_step_and_the_problem() {
    let bad_step = "[sheet]\nsquare = 100\n\n[[step]]\nname = \"miss\"\nbend = { line = [[200, 0], [200, 100]], moving = [300, 0] }\n";
    let script = parse_script(bad_step).expect("parses");
    let err = run_script(&script).expect_err("misses");
    assert!(matches!(err, ScriptError::Step { number: 1, .. }), "{err}");
    assert!(err.to_string().contains("\"miss\"") && err.to_string().contains("misses"));
    for (text, word) in [
        ("[sheet]\n", "one of square"),
        ("[sheet]\nsquare = -4\n", "positive"),
        ("[sheet]\nsquare = 10\nrectangle = [1, 2]\n", "only one"),
        (
            "[sheet]\npolygon = [[0, 0], [10, 0], [0, 10], [10, 10], [5, -5]]\n",
            "crosses",
        ),
        (
            "[sheet]\nsquare = 10\n[[step]]\nfold = { line = [[0, 5], [10, 5]], moving = [5, 9] }\n",
            "angle",
        ),
        (
            "[sheet]\nsquare = 10\n[[step]]\nbend = { line = [[0, 5]], moving = [5, 9] }\n",
            "line",
        ),
        (
            "[sheet]\nsquare = 10\n[[step]]\nname = \"x\"\n",
            "one of bend",
        ),
        (
            "[sheet]\nsquare = 10\n[[step]]\nbend = { line = [[0, 5], [10, 5]], moving = [5, 9], layers = \"some\" }\n",
            "layers",
        ),
    ] {
        let err = parse_script(text).and_then(|s| run_script(&s).map(|_| ()));
        let msg = err.expect_err(text).to_string();
        assert!(msg.contains(word), "{text}: {msg}");
    }
}

fn foldcam(args: &[&str], dir: &Path) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_foldcam"))
        .args(args)
        .current_dir(dir)
        .output()
        .expect("the foldcam binary runs")
}

#[test]
fn cli_writes_frames_and_pictures_and_refuses_bad_scripts() {
    let dir = tempfile::tempdir().expect("temp dir");
    let script = example_path("preliminary-base.toml");
    let script = script.to_string_lossy();
    let o = foldcam(
        &[
            "fold",
            &script,
            "-o",
            "pre.fold",
            "--png",
            "steps.png",
            "--gif",
            "steps.gif",
            "--width",
            "64",
        ],
        dir.path(),
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let text = std::fs::read_to_string(dir.path().join("pre.fold")).expect("written");
    assert_eq!(
        frame_count(&parse_root(&text).expect("FOLD")).expect("frames"),
        5
    );
    let png = image::open(dir.path().join("steps.png")).expect("PNG");
    // Four panels of 64 px in a row, each with its caption under it.
    assert_eq!(png.width(), 4 * 64);
    assert!(png.height() > 64, "caption band under the panels");
    assert!(dir.path().join("steps.gif").is_file());
    std::fs::write(
        dir.path().join("bad.toml"),
        "[sheet]\nsquare = 10\n[[step]]\ntuck = { line = [[0, 5], [10, 5]], moving = [5, 9] }\n",
    )
    .expect("write");
    let o = foldcam(&["fold", "bad.toml", "-o", "bad.fold"], dir.path());
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("bad.toml") && err.contains("step 1"), "{err}");
    assert!(!dir.path().join("bad.fold").exists());
}

#[test]
fn bird_base_has_two_petals_and_the_petal_creases() {
    let f = example("bird-base.toml");
    let sheet = crease_pattern(&f);
    let cp = &sheet.pattern;
    let count = |a| cp.edges.iter().filter(|e| e.assignment == a).count();
    // Eight kite lines and the four midline halves inside the kite points are valleys, the two
    // petal lines and the two halves of the first diagonal mountains; the midline halves beyond
    // the kite points unfold (flat).
    assert_eq!(
        (
            count(Assignment::Valley),
            count(Assignment::Mountain),
            count(Assignment::Flat)
        ),
        (12, 4, 4)
    );
    // Folded: a long diamond from the corner stack at the origin to the two petal tips, which
    // are the sheet corners (0, 0) and (150, 150), 75·√2 mm along the diagonal.
    let last = step_states(&f, &sheet).pop().expect("states");
    let tip = DVec3::splat(75.0 * std::f64::consts::FRAC_1_SQRT_2 * 2.0).with_z(0.0);
    for corner in [DVec2::ZERO, DVec2::splat(150.0)] {
        let v = cp
            .vertices
            .iter()
            .position(|p| p.distance(corner) < 1e-6)
            .expect("corner vertex");
        assert!(
            last.positions[v].distance(tip) < 1e-9,
            "{:?}",
            last.positions[v]
        );
    }
    assert!(last.positions.iter().all(|p| p.z.abs() < 1e-9));
}

/// Random sequences of bends (all layers or the outer few, fixed seed): after every step that folds, the
/// layer order is consistent and the crease pattern flat-foldable; a refused step changes
/// nothing.
#[test]
fn random_bend_sequences_stay_consistent_and_flat_foldable() {
    let mut seed = 0x2545_f491_4f6c_dd1du64;
    let mut next = move || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut folded = 0;
    for _ in 0..60 {
        let mut f = square(100.0);
        for _ in 0..5 {
            // A line through two points of the current flat outline's bounding box.
            let (lo, hi) = bounds(&f);
            let pick = |t: f64, u: f64| {
                DVec3::new(lo.x + (hi.x - lo.x) * t, lo.y + (hi.y - lo.y) * u, 0.0)
            };
            let (a, b) = (pick(next(), next()), pick(next(), next()));
            let side = pick(next(), next());
            let fold = Fold {
                line: [a, b],
                moving: side,
                turn: Turn::Angle(if next() < 0.5 { 180.0 } else { -180.0 }),
                layers: if next() < 0.5 {
                    Layers::All
                } else {
                    Layers::Outer(1 + (next() * 3.0) as usize)
                },
            };
            let before = f.clone();
            match f.fold(&fold, None) {
                Ok(_) => {
                    folded += 1;
                    let problems = layer_problems(&f, f.current());
                    assert!(problems.is_empty(), "{fold:?}: {problems:?}");
                    let report = check(&crease_pattern(&f).pattern, &CheckOptions::default());
                    assert!(report.passed(), "{fold:?}: {:?}", report.findings.first());
                }
                Err(_) => assert_eq!(f, before),
            }
        }
    }
    assert!(folded >= 60, "{folded} folds made");
}

/// Every corner of every current face, in 3D.
fn all_corners(f: &Folding) -> Vec<DVec3> {
    f.current()
        .faces
        .iter()
        .flat_map(|face| f.corners(face))
        .collect()
}

fn bounds(f: &Folding) -> (DVec3, DVec3) {
    all_corners(f).into_iter().fold(
        (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY)),
        |(lo, hi), p| (lo.min(p), hi.max(p)),
    )
}
