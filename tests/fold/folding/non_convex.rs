//! Non-convex sheets: an L-shaped sheet starts as convex faces of the face tree; a fold line
//! crossing it once or twice folds every piece on the moving side, and the result keeps its
//! shape, its layer order and a flat-foldable crease pattern.

use foldcam::check::{CheckOptions, check};
use foldcam::design::folding::crease_pattern;
use foldcam::design::folding::layer_problems;
use foldcam::design::folding::{CellId, Fold, FoldError, Folding, Layers, Turn};
use foldcam::design::folding::{parse_script, run_script};
use foldcam::pattern::Assignment;
use glam::{DVec2, DVec3};

use super::assert_every_step_isometric;

/// An L: a 100 mm square without its top-right 60 mm square.
fn l_sheet() -> Folding {
    let corners = [
        [0., 0.],
        [100., 0.],
        [100., 40.],
        [40., 40.],
        [40., 100.],
        [0., 100.],
    ];
    Folding::new(&corners.map(DVec2::from)).expect("an L is a sheet")
}

fn bend(a: [f64; 2], b: [f64; 2], moving: [f64; 2]) -> Fold {
    let p = |q: [f64; 2]| DVec3::new(q[0], q[1], 0.0);
    Fold {
        line: [p(a), p(b)],
        moving: p(moving),
        turn: Turn::Angle(180.0),
        layers: Layers::All,
    }
}

fn assert_sound(f: &Folding, name: &str) {
    assert_every_step_isometric(f, name);
    assert!(layer_problems(f, f.current()).is_empty(), "{name}");
    let report = check(&crease_pattern(f).pattern, &CheckOptions::default());
    assert!(report.passed(), "{name}: {:?}", report.findings);
}

#[test]
fn an_l_sheet_starts_as_convex_faces_of_the_sheet() {
    let f = l_sheet();
    let faces = &f.current().faces;
    assert!(faces.len() >= 2);
    for face in faces {
        assert_eq!(f.cells()[face.cell.index()].parent, Some(CellId(0)));
    }
    assert_sound(&f, "flat L");
    // The crease pattern's outline is the L's: 400 mm round.
    let cp = crease_pattern(&f).pattern;
    let boundary: f64 = cp
        .edges
        .iter()
        .filter(|e| e.assignment == Assignment::Boundary)
        .map(|e| cp.vertices[e.vertices[0].index()].distance(cp.vertices[e.vertices[1].index()]))
        .sum();
    assert!((boundary - 400.0).abs() < 1e-9, "{boundary}");
}

#[test]
fn a_line_crossing_the_l_once_folds_its_arm() {
    let mut f = l_sheet();
    // Across the vertical arm at y = 70: the arm's top folds down over it.
    let report = f
        .fold(&bend([0.0, 70.0], [40.0, 70.0], [20.0, 90.0]), None)
        .expect("folds the arm");
    assert!(report.split >= 1);
    let top = super::bounds(&f).1.y;
    assert!((top - 70.0).abs() < 1e-9, "{top}");
    assert_sound(&f, "L, arm folded");
}

#[test]
fn a_line_crossing_the_l_twice_folds_both_tips() {
    let mut f = l_sheet();
    // x + y = 120 cuts off both arms' tips: two separate regions move.
    let report = f
        .fold(&bend([20.0, 100.0], [100.0, 20.0], [90.0, 90.0]), None)
        .expect("folds both tips");
    assert!(report.moved >= 2, "{report:?}");
    // The tips' corners land mirrored across the line: (100, 40) on (80, 20), (40, 100) on
    // (20, 80); nothing is left beyond it.
    let corners = super::all_corners(&f);
    for p in [DVec3::new(80.0, 20.0, 0.0), DVec3::new(20.0, 80.0, 0.0)] {
        assert!(corners.iter().any(|c| c.distance(p) < 1e-9), "{p}");
    }
    assert!(corners.iter().all(|c| c.x + c.y <= 120.0 + 1e-9));
    assert_sound(&f, "L, both tips folded");
    let mut g = f.clone();
    g.undo().expect("undo");
    assert_eq!(g.current(), l_sheet().current());
}

#[test]
fn a_self_crossing_outline_is_refused_with_its_reason() {
    let bow = [[0., 0.], [10., 0.], [0., 10.], [10., 10.], [5., -5.]];
    let err = Folding::new(&bow.map(DVec2::from)).expect_err("crosses itself");
    assert!(
        matches!(err, FoldError::Sheet(_)) && err.to_string().contains("crosses"),
        "{err}"
    );
    let text = "[sheet]\npolygon = [[0, 0], [100, 0], [100, 40], [40, 40], [40, 100], [0, 100]]\n\
                [[step]]\nbend = { line = [[0, 70], [40, 70]], moving = [20, 90] }\n";
    let f = run_script(&parse_script(text).expect("parses")).expect("an L script folds");
    assert_eq!(f.steps().len(), 2);
}
