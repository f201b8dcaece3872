//! Files written by other origami tools (`tests/data`, see its README): every one
//! imports, and `check` gives the right verdict on the known flat-foldable ones. The MIT files
//! are copied into `tests/data/` (see its README), so these run on a fresh clone.

use std::path::{Path, PathBuf};

use foldcam::check::{CheckOptions, FindingKind, check};
use foldcam::formats;
use foldcam::pattern::vertex_fan::VertexFans;
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
    let report = check(&cp, &CheckOptions::default());
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
    for f in report.of_kind(FindingKind::Kawasaki) {
        assert!(f.value > 0.5 && f.value < 3.0, "error {}°", f.value);
    }
}
