//! Files written by other origami tools (`tests/data`, see its README): every one
//! imports, and `check` gives the right verdict on the known flat-foldable ones. The MIT files
//! are copied into `tests/data/` (see its README), so these run on a fresh clone.

use std::path::{Path, PathBuf};

use foldcam::check::{CheckOptions, FindingKind, check};
use foldcam::formats;
use foldcam::pattern::VertexFans;
use foldcam::pattern::{Assignment, CreasePattern, PlanarizeOptions, planarize};

fn testdata() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/data")
}

fn load(dir: &Path, name: &str) -> CreasePattern {
    let mut cp = formats::load(&dir.join(name))
        .unwrap_or_else(|e| panic!("{name}: {e}"))
        .pattern;
    planarize(&mut cp, &PlanarizeOptions::default()).expect("planarises");
    cp
}

#[test]
fn every_file_imports_and_validates() {
    let dir = testdata();
    let mut count = 0;
    for sub in ["fold", "svg"] {
        for entry in std::fs::read_dir(dir.join(sub)).expect("listing") {
            let path = entry.expect("entry").path();
            let imported = formats::load(&path).unwrap_or_else(|e| panic!("{e}"));
            imported.pattern.validate().expect("valid pattern");
            assert!(
                !imported.pattern.edges.is_empty(),
                "{}: no edges",
                path.display()
            );
            count += 1;
        }
    }
    assert!(count >= 20, "expected the 22 test files, found {count}");
}

/// Patterns known to fold flat: every interior vertex passes Kawasaki and Maekawa.
#[test]
fn known_flat_foldable_patterns_pass() {
    let dir = testdata();
    let flat = [
        "fold/os-BoxPleatPyramid.fold",
        "fold/os-BoxPleatTessellation.fold",
        "fold/squaretwist.fold",
        "fold/diagonal-cp.fold",
        "svg/squareBase.svg",
        "svg/simpleVertex.svg",
        "svg/mapfold.svg",
        "svg/brochurefold.svg",
        "svg/russianTriangle.svg",
        "svg/miura-ori.svg",
        "svg/waterbomb.svg",
    ];
    for name in flat {
        let cp = load(&dir, name);
        let report = check(&cp, &CheckOptions::default());
        assert!(report.passed(), "{name}: {:?}", report.findings.first());
        let vertexless = name.ends_with("diagonal-cp.fold");
        assert!(
            vertexless || report.summary.interior_vertices_checked > 0,
            "{name}: no interior vertex was checked"
        );
    }
}

/// Origami Simulator's waterbomb base drives both midlines as valleys and both diagonals as
/// mountains: 4 and 4 at a degree-8 vertex, which Maekawa forbids (counted here directly).
#[test]
fn waterbomb_base_as_assigned_fails_maekawa_at_its_centre() {
    let dir = testdata();
    let cp = load(&dir, "svg/waterbombBase.svg");
    let fans = VertexFans::new(&cp);
    let centre = cp
        .vertex_ids()
        .find(|&v| fans.of(v).len() == 8)
        .expect("a degree-8 centre");
    let count = |k| {
        fans.of(centre)
            .iter()
            .filter(|s| cp.edges[s.edge.index()].assignment == k)
            .count()
    };
    assert_eq!(
        (count(Assignment::Mountain), count(Assignment::Valley)),
        (4, 4)
    );
    // The file folds its valleys to 90° (stroke opacity 0.5): a 3D target, to which
    // Maekawa (folding flat) does not apply; the centre is counted as such.
    let report = check(&cp, &CheckOptions::default());
    assert_eq!(report.of_kind(FindingKind::Maekawa).count(), 0);
    assert!(report.summary.vertices_3d >= 1);
    // Meant to fold flat (no stored angles), the same assignment fails Maekawa there.
    let mut flat = cp.clone();
    for e in &mut flat.edges {
        e.fold_angle = None;
    }
    let report = check(&flat, &CheckOptions::default());
    let maekawa: Vec<_> = report.of_kind(FindingKind::Maekawa).collect();
    assert_eq!(maekawa.len(), 1);
    assert_eq!(maekawa[0].vertex, Some(centre));
}

/// The frog base drawing approximates 22.5° by atan(2/5) = 21.80°, so Kawasaki fails by the
/// difference at the flap vertices: the reported error is that geometry's, not noise.
#[test]
fn frog_base_drawing_is_off_by_its_approximated_angle() {
    let dir = testdata();
    let cp = load(&dir, "svg/frogBase.svg");
    let report = check(&cp, &CheckOptions::default());
    assert!(!report.passed());
    let smallest = report
        .summary
        .smallest_crease_angle
        .as_ref()
        .expect("an angle");
    assert!((smallest.degrees - 0.4f64.atan().to_degrees()).abs() < 1e-3);
    // At every vertex reported, the error equals |Σ odd sectors − 180°| computed here from the
    // drawing itself: crease directions sorted by atan2, sectors between neighbours.
    let mut checked = 0;
    for f in report.of_kind(FindingKind::Kawasaki) {
        let v = f.vertex.expect("a vertex");
        let at = cp.position(v);
        let mut dirs: Vec<f64> = cp
            .edges
            .iter()
            .filter(|e| e.assignment.may_fold() && e.vertices.contains(&v))
            .map(|e| {
                let other = if e.vertices[0] == v {
                    e.vertices[1]
                } else {
                    e.vertices[0]
                };
                let d = cp.position(other) - at;
                d.y.atan2(d.x)
            })
            .collect();
        dirs.sort_by(f64::total_cmp);
        let n = dirs.len();
        assert!(n.is_multiple_of(2) && n >= 4, "degree {n}");
        let odd: f64 = (0..n)
            .step_by(2)
            .map(|i| {
                let next = if i + 1 < n {
                    dirs[i + 1]
                } else {
                    dirs[0] + std::f64::consts::TAU
                };
                next - dirs[i]
            })
            .sum();
        let expected = (odd.to_degrees() - 180.0).abs();
        assert!(
            (f.value - expected).abs() < 1e-6,
            "vertex {at}: reported {}°, drawing gives {expected}°",
            f.value
        );
        checked += 1;
    }
    assert!(checked > 0, "the frog base fails Kawasaki somewhere");
}
