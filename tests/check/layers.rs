//! The global layer-order solver (`check::layers`): closed-form counts on tiny patterns,
//! Flat-Folder's published counts (copied grids here; the whole shared set in the ignored
//! tests), our own generators, bundled examples and fold scripts.

use std::path::{Path, PathBuf};

use foldcam::check::layers::{
    KawasakiTolerance, LayerOptions, LayerSolver, check_layers, local_faults, solve_layers,
};
use foldcam::check::{CheckOptions, FindingKind, check};
use foldcam::design::classic::{MiuraOri, SquareTwist, Waterbomb, Yoshimura};
use foldcam::design::folding::{crease_pattern, step_states};
use foldcam::design::folding::{parse_script, run_script};
use foldcam::formats;
use foldcam::pattern::{Assignment, CreasePattern, PlanarizeOptions, planarize};
use glam::DVec2;

fn clean(mut cp: CreasePattern) -> CreasePattern {
    let options = PlanarizeOptions {
        tolerance: None,
        faces: true,
    };
    planarize(&mut cp, &options).expect("planarises");
    cp
}

fn load(path: &Path) -> CreasePattern {
    clean(
        formats::load(path)
            .unwrap_or_else(|e| panic!("{e}"))
            .pattern,
    )
}

fn states(cp: &CreasePattern) -> String {
    solve_layers(cp, &LayerOptions::default())
        .expect("layer problem")
        .states
}

/// True when at least one state exists (counting stops at one per component).
fn has_state(cp: &CreasePattern) -> bool {
    let options = LayerOptions {
        max_states: Some(1),
        ..LayerOptions::default()
    };
    solve_layers(cp, &options)
        .expect("layer problem")
        .foldable()
}

fn locally_flat(cp: &CreasePattern) -> bool {
    !check(cp, &CheckOptions::default())
        .findings
        .iter()
        .any(|f| matches!(f.kind, FindingKind::Kawasaki | FindingKind::Maekawa))
}

/// A unit square folded in half along x = 0.5 with the given assignment.
fn folded_once(a: Assignment) -> CreasePattern {
    let mut cp = CreasePattern::new();
    let p = [
        (0.0, 0.0),
        (0.5, 0.0),
        (1.0, 0.0),
        (1.0, 1.0),
        (0.5, 1.0),
        (0.0, 1.0),
    ]
    .map(|(x, y)| cp.add_vertex(DVec2::new(x, y)));
    for i in 0..6 {
        cp.add_edge(p[i], p[(i + 1) % 6], Assignment::Boundary);
    }
    cp.add_edge(p[1], p[4], a);
    clean(cp)
}

/// A strip folded at x = 1 and x = 2 (three equal panels), with the given assignments.
fn zigzag(a: Assignment, b: Assignment) -> CreasePattern {
    let mut cp = CreasePattern::new();
    for x in 0..3 {
        let x = f64::from(x);
        cp.add_segment(
            DVec2::new(x, 0.0),
            DVec2::new(x + 1.0, 0.0),
            Assignment::Boundary,
        );
        cp.add_segment(
            DVec2::new(x, 1.0),
            DVec2::new(x + 1.0, 1.0),
            Assignment::Boundary,
        );
    }
    cp.add_segment(
        DVec2::new(0.0, 0.0),
        DVec2::new(0.0, 1.0),
        Assignment::Boundary,
    );
    cp.add_segment(
        DVec2::new(3.0, 0.0),
        DVec2::new(3.0, 1.0),
        Assignment::Boundary,
    );
    cp.add_segment(DVec2::new(1.0, 0.0), DVec2::new(1.0, 1.0), a);
    cp.add_segment(DVec2::new(2.0, 0.0), DVec2::new(2.0, 1.0), b);
    clean(cp)
}

#[test]
fn one_fold_has_one_order_and_an_unassigned_fold_two() {
    // Two panels on top of each other: the valley (or mountain) says which is on top; an
    // unassigned crease allows both.
    assert_eq!(states(&folded_once(Assignment::Valley)), "1");
    assert_eq!(states(&folded_once(Assignment::Mountain)), "1");
    assert_eq!(states(&folded_once(Assignment::Unassigned)), "2");
}

#[test]
fn three_panel_strip_counts_match_the_stackings_by_hand() {
    // Panels 0|1|2 fold onto one square; the two creases land on opposite edges of it, so
    // neither fold constrains the other and no panel crosses a fold: only the stacking
    // order matters. Valley at x = 1: panel 1 above panel 0. The second crease is seen from
    // panel 1's back (it lies face down): a mountain puts panel 2 above panel 1 (the pleat,
    // 0 < 1 < 2: one stack), a valley puts it below panel 1, either under panel 0 or
    // between 0 and 1 (two stacks); unassigned leaves three places for panel 2. Both
    // unassigned: all 3! = 6 stacks.
    assert_eq!(
        states(&zigzag(Assignment::Valley, Assignment::Mountain)),
        "1"
    );
    assert_eq!(states(&zigzag(Assignment::Valley, Assignment::Valley)), "2");
    assert_eq!(
        states(&zigzag(Assignment::Valley, Assignment::Unassigned)),
        "3"
    );
    assert_eq!(
        states(&zigzag(Assignment::Unassigned, Assignment::Unassigned)),
        "6"
    );
}

#[test]
#[ignore = "needs ../shared"]
fn faces_named_when_no_order_exists() {
    // Flat-Folder's smallest unsatisfiable pattern: every face the contradiction names is
    // located inside that face on the pattern.
    let dir = shared();
    let cp = load(&dir.join("unsatisfiable/001_ku_Bad_Twist.fold"));
    assert!(locally_flat(&cp));
    let solver = LayerSolver::new(&cp, &LayerOptions::default()).expect("layer problem");
    let report = solver.report();
    assert_eq!(report.states, "0");
    let c = report.contradiction.as_ref().expect("a contradiction");
    assert!(c.faces.len() >= 2);
    let faces = cp.faces.as_ref().expect("faces");
    for (f, p) in c.faces.iter().zip(&c.positions) {
        let ring: Vec<DVec2> = faces[f.index()]
            .outer
            .iter()
            .map(|&v| cp.position(v))
            .collect();
        let (lo, hi) = ring
            .iter()
            .fold((ring[0], ring[0]), |(lo, hi), &q| (lo.min(q), hi.max(q)));
        assert!(
            p.cmpge(lo - 1e-6).all() && p.cmple(hi + 1e-6).all(),
            "{f} at {p}"
        );
    }
}

fn copied(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/flat-folder")
        .join(name)
}

#[test]
fn copied_grids_match_flat_folder_counts() {
    // Counts published in Flat-Folder's grids_data.csv (see tests/data/flat-folder/README.md).
    for (name, expected) in [
        ("000_brown_2x2_A1.fold", "1"),
        ("001_brown_2x2_C1.fold", "1"),
        ("002_brown_2x2_D1.fold", "16"),
        ("171_brown_4x4_C30.fold", "16"),
        ("372_brown_4x4_D112.fold", "4096"),
    ] {
        let cp = load(&copied(name));
        assert!(locally_flat(&cp), "{name}");
        assert_eq!(states(&cp), expected, "{name}");
    }
}

#[test]
fn a_state_and_its_face_orders_are_admitted_and_a_flipped_pair_is_not() {
    let cp = load(&copied("002_brown_2x2_D1.fold"));
    let solver = LayerSolver::new(&cp, &LayerOptions::default()).expect("layer problem");
    for k in [0u128, 5, 15] {
        let orders = solver.face_orders(k).expect("state exists");
        assert!(solver.admits(&orders), "state {k}");
    }
    assert!(solver.face_orders(16).is_none());
    // Flipping a pair forced by a crease is refused.
    let mut orders = solver.face_orders(0).expect("state 0");
    let forced = orders
        .iter()
        .position(|&(f, g, _)| {
            let (fv, gv) = (
                &cp.faces.as_ref().expect("faces")[f.index()],
                &cp.faces.as_ref().expect("faces")[g.index()],
            );
            fv.outer.iter().filter(|v| gv.outer.contains(v)).count() >= 2
        })
        .expect("two neighbouring faces overlap");
    orders[forced].2 = -orders[forced].2;
    assert!(!solver.admits(&orders));
}

#[test]
fn every_state_number_gives_a_different_order() {
    let cp = load(&copied("002_brown_2x2_D1.fold"));
    let solver = LayerSolver::new(&cp, &LayerOptions::default()).expect("layer problem");
    let mut seen = std::collections::HashSet::new();
    for k in 0..16u128 {
        let orders = solver.face_orders(k).expect("state exists");
        assert!(seen.insert(orders), "state {k} repeats an earlier one");
    }
}

#[test]
fn the_cap_makes_the_count_inexact() {
    let cp = load(&copied("372_brown_4x4_D112.fold"));
    let options = LayerOptions {
        max_states: Some(2),
        ..LayerOptions::default()
    };
    let report = solve_layers(&cp, &options).expect("layer problem");
    assert!(!report.exact);
    assert!(
        report
            .component_states
            .iter()
            .any(|c| !c.exact && c.states == "2")
    );
}

#[test]
fn square_twist_folds_flat_across_angles_and_sizes() {
    for twist_deg in [1.0, 10.0, 22.5, 30.0, 40.0, 44.0] {
        for (sheet, square) in [(120.0, 30.0), (61.0, 30.0), (200.0, 20.0)] {
            let cp = clean(
                SquareTwist {
                    sheet,
                    square,
                    twist_deg,
                }
                .build()
                .expect("valid parameters"),
            );
            assert!(locally_flat(&cp), "{twist_deg}° {sheet}/{square}");
            assert!(has_state(&cp), "{twist_deg}° {sheet}/{square}");
        }
    }
}

#[test]
fn generated_patterns_have_a_layer_order() {
    let mut patterns = vec![
        ("square twist", SquareTwist::default().build()),
        ("miura", MiuraOri::default().build()),
        ("waterbomb", Waterbomb::default().build()),
        ("yoshimura", Yoshimura::default().build()),
    ];
    for (columns, rows, shear) in [(2, 2, 0.0), (5, 3, 3.0), (4, 6, 6.0)] {
        patterns.push((
            "miura",
            MiuraOri {
                columns,
                rows,
                shear,
                ..MiuraOri::default()
            }
            .build(),
        ));
        patterns.push((
            "waterbomb",
            Waterbomb {
                columns,
                rows,
                ..Waterbomb::default()
            }
            .build(),
        ));
        patterns.push((
            "yoshimura",
            Yoshimura {
                columns,
                rows,
                ..Yoshimura::default()
            }
            .build(),
        ));
    }
    let mut checked = 0;
    for (name, cp) in patterns {
        let cp = clean(cp.expect("valid parameters"));
        if !locally_flat(&cp) {
            // not meant to fold flat at every vertex (reported by `check` already)
            continue;
        }
        assert!(has_state(&cp), "{name}");
        checked += 1;
    }
    assert!(
        checked >= 4,
        "only {checked} generated patterns fold flat locally"
    );
}

#[test]
fn bundled_patterns_that_pass_locally_have_a_layer_order() {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("examples/patterns");
    let mut checked = 0;
    for entry in std::fs::read_dir(dir).expect("examples/patterns") {
        let path = entry.expect("entry").path();
        if formats::Format::from_path(&path).is_none() {
            continue;
        }
        let cp = load(&path);
        if !locally_flat(&cp) {
            continue;
        }
        assert!(has_state(&cp), "{}", path.display());
        checked += 1;
    }
    assert!(checked >= 2);
}

#[test]
fn fold_scripts_end_in_a_state_the_solver_admits() {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("examples/folding");
    let mut checked = 0;
    for entry in std::fs::read_dir(dir).expect("examples/folding") {
        let path = entry.expect("entry").path();
        if path.extension().is_none_or(|e| e != "toml") {
            continue;
        }
        let text = std::fs::read_to_string(&path).expect("readable");
        let folding = run_script(&parse_script(&text).expect("parses")).expect("runs");
        let sheet = crease_pattern(&folding);
        let Some(last) = step_states(&folding, &sheet).pop() else {
            continue;
        };
        let flat = last
            .positions
            .iter()
            .all(|p| (p.z - last.positions[0].z).abs() < 1e-6);
        let all_flat_folds = sheet.pattern.edges.iter().all(|e| {
            e.fold_angle
                .is_none_or(|a| a.abs() < 1e-6 || (a.abs() - 180.0).abs() < 1e-6)
        });
        if !flat || !all_flat_folds {
            continue;
        }
        let cp = clean(sheet.pattern.clone());
        assert_eq!(
            cp.faces.as_ref().map(Vec::len),
            sheet.pattern.faces.as_ref().map(Vec::len)
        );
        let solver = LayerSolver::new(&cp, &LayerOptions::default()).expect("layer problem");
        assert_ne!(solver.report().states, "0", "{}", path.display());
        assert!(solver.admits(&last.face_orders), "{}", path.display());
        checked += 1;
    }
    assert!(checked >= 1, "no fold script ends flat");
}

/// Flat-Folder's published set in ../shared; the tests that read it are ignored on a clone
/// without it and fail here, naming it, when it is missing.
fn shared() -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../shared/testdata/flat-folder");
    assert!(dir.is_dir(), "{} is absent", dir.display());
    dir
}

/// Rows of a Flat-Folder CSV: (file number, faces, limited, states, seconds).
/// Flat-Folder's rows: number, faces, its cap per component (`None`: no limit), states,
/// seconds.
fn rows(dir: &Path, csv: &str) -> Vec<(String, usize, Option<u64>, String, f64)> {
    let text = std::fs::read_to_string(dir.join(csv)).expect("csv");
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().expect("header").split(',').collect();
    let col = |n: &str| {
        header
            .iter()
            .position(|h| h.eq_ignore_ascii_case(n))
            .expect(n)
    };
    let (num, faces, limited, states, setup, solve) = (
        col("number"),
        col("faces"),
        col("limited"),
        col("states"),
        col("setup_sec"),
        col("solve_sec"),
    );
    lines
        .map(|l| l.split(',').collect::<Vec<_>>())
        .filter(|c| c.len() == header.len())
        .map(|c| {
            (
                c[num].to_string(),
                c[faces].parse().unwrap_or(usize::MAX),
                c[limited].parse().ok(),
                c[states].to_string(),
                c[setup].parse::<f64>().unwrap_or(f64::MAX)
                    + c[solve].parse::<f64>().unwrap_or(0.0),
            )
        })
        .collect()
}

fn file_numbered(dir: &Path, number: &str) -> Option<PathBuf> {
    std::fs::read_dir(dir)
        .ok()?
        .flatten()
        .map(|e| e.path())
        .find(|p| {
            p.file_name()
                .is_some_and(|n| n.to_string_lossy().starts_with(&format!("{number}_")))
        })
}

/// Designs the small-pattern test must compare, which the local checks used to refuse: Lang's
/// Rings8 (545 faces, beyond the bounds) and Squaring the Circle carry Kawasaki errors of up
/// to 0.059° and 0.025° from their drawings' rounding; his 5-Fold 2-Layer Weave folds one
/// vertex 0.16 of its shortest edge away from itself.
const ROUNDED_DESIGNS: [&str; 3] = ["019_lang", "041_lang", "361_lang"];

/// The designs compared in a debug build: those Flat-Folder counted exactly within this many
/// seconds of its own (published) time … (up to 10 s takes 32 more designs and four times as
/// long: 324 s instead of 86 s here; the whole set runs in release in
/// `examples/flat_folder_set.rs`)
const MAX_FLAT_FOLDER_SECONDS: f64 = 1.5;
/// … and with at most this many faces.
const MAX_FACES: usize = 400;

/// Every pattern with `no limit`, at most 400 faces and at most 1.5 s of Flat-Folder's own time
/// (and the rounded designs of [`ROUNDED_DESIGNS`]) gives exactly Flat-Folder's count; the
/// local faults are sorted as `check --layers` sorts them, Kawasaki errors within the
/// tolerance fitted to the drawing let through, and none is refused. This subset stays within
/// a few minutes in a debug build; the whole set runs in `examples/flat_folder_set.rs`.
#[test]
#[ignore = "needs ../shared"]
fn flat_folder_counts_match_on_small_patterns() {
    let dir = shared();
    let (mut compared, mut rounded, mut named_seen) = (0, Vec::new(), Vec::new());
    for (csv, sub) in [
        ("grids_data.csv", "grids"),
        ("instagram_data.csv", "instagram"),
    ] {
        for (number, faces, cap, expected, seconds) in rows(&dir, csv) {
            let Some(path) = file_numbered(&dir.join(sub), &number) else {
                continue;
            };
            let name = path
                .file_name()
                .map_or_else(String::new, |n| n.to_string_lossy().into_owned());
            let named = sub == "instagram" && ROUNDED_DESIGNS.iter().any(|d| name.starts_with(d));
            if cap.is_some() || ((faces > MAX_FACES || seconds > MAX_FLAT_FOLDER_SECONDS) && !named)
            {
                continue;
            }
            let cp = load(&path);
            let faults = local_faults(&cp, KawasakiTolerance::Fitted);
            assert!(
                faults.refusing.is_empty(),
                "{name}: refused: {:?}",
                faults.first_refusal().map(|f| &f.message)
            );
            if !faults.rounding.is_empty() {
                rounded.push(name.clone());
            }
            assert_eq!(states(&cp), expected, "{}", path.display());
            compared += 1;
            if named {
                named_seen.push(name);
            }
        }
    }
    assert_eq!(named_seen.len(), ROUNDED_DESIGNS.len(), "{named_seen:?}");
    for d in ["019_lang", "361_lang"] {
        assert!(
            rounded.iter().any(|n| n.starts_with(d)),
            "{d} with rounding: {rounded:?}"
        );
    }
    assert!(compared >= 500, "only {compared} patterns compared");
}

/// Where Flat-Folder capped its count (at 10,000 states per component) and finished within a
/// minute, the same cap gives exactly its lower bound: the components are split as finely as
/// Flat-Folder splits them, so the same components reach the cap.
#[test]
#[ignore = "needs ../shared"]
fn flat_folder_lower_bounds_match_at_its_cap() {
    let dir = shared();
    let mut compared = Vec::new();
    for (csv, sub) in [
        ("grids_data.csv", "grids"),
        ("instagram_data.csv", "instagram"),
    ] {
        for (number, _, cap, expected, seconds) in rows(&dir, csv) {
            let (Some(cap), Some(path)) = (cap, file_numbered(&dir.join(sub), &number)) else {
                continue;
            };
            if seconds > 60.0 {
                continue;
            }
            let cp = load(&path);
            let options = LayerOptions {
                max_states: Some(cap),
                ..LayerOptions::default()
            };
            let report = solve_layers(&cp, &options).expect("layer problem");
            assert!(!report.exact, "{}: capped", path.display());
            assert_eq!(report.states, expected, "{}", path.display());
            compared.push(number);
        }
    }
    assert!(compared.len() >= 6, "only {compared:?}");
}

#[test]
#[ignore = "needs ../shared"]
fn flat_folder_unsatisfiable_patterns_are_refused() {
    let dir = shared();
    let mut refused = 0;
    for entry in std::fs::read_dir(dir.join("unsatisfiable")).expect("listing") {
        let path = entry.expect("entry").path();
        let cp = load(&path);
        assert!(locally_flat(&cp), "{}", path.display());
        let report = solve_layers(&cp, &LayerOptions::default()).expect("layer problem");
        assert_eq!(report.states, "0", "{}", path.display());
        assert!(report.contradiction.is_some(), "{}", path.display());
        refused += 1;
    }
    assert_eq!(refused, 6);
}

#[test]
fn square_twist_pleats_have_the_classic_width_and_angle() {
    // Each pleat: a mountain and a parallel valley L·sin α apart, the mountain at α from the
    // side it leaves (the smallest sector at every corner).
    for twist_deg in [10.0, 22.5, 40.0] {
        let t = SquareTwist {
            twist_deg,
            ..SquareTwist::default()
        };
        let cp = t.build().expect("twist");
        let alpha = twist_deg.to_radians();
        let lines = |a: Assignment| -> Vec<(DVec2, DVec2)> {
            cp.edges
                .iter()
                .filter(|e| e.assignment == a)
                .map(|e| (cp.position(e.vertices[0]), cp.position(e.vertices[1])))
                .collect()
        };
        let (mountains, valleys) = (lines(Assignment::Mountain), lines(Assignment::Valley));
        assert_eq!(mountains.len(), 4);
        for (a, b) in &mountains {
            let d = (*b - *a).normalize();
            let partner = valleys.iter().find(|(c, e)| {
                let u = (*e - *c).normalize();
                (u.perp_dot(d)).abs() < 1e-9 && u.dot(d) > 0.0
            });
            let (c, _) = partner.expect("a parallel valley in the same direction");
            let width = (*c - *a).perp_dot(d).abs();
            assert!(
                (width - t.square * alpha.sin()).abs() < 1e-9,
                "{twist_deg}°: {width}"
            );
        }
        let fans = foldcam::pattern::VertexFans::new(&cp);
        let smallest = cp
            .vertex_ids()
            .filter(|&v| fans.of(v).len() == 4)
            .flat_map(|v| {
                let s = fans.of(v);
                (0..4).map(move |i| {
                    let next = if i + 1 < 4 {
                        s[i + 1].angle
                    } else {
                        s[0].angle + std::f64::consts::TAU
                    };
                    next - s[i].angle
                })
            })
            .fold(f64::MAX, f64::min);
        assert!(
            (smallest - alpha).abs() < 1e-9,
            "{twist_deg}°: smallest sector {smallest}"
        );
    }
}

/// Flat-Folder's grid `name` (copied in `tests/data/flat-folder`) turned by 17°, drawn 100
/// units wide with every coordinate rounded to `step`, as a drawing program that prints a
/// fixed number of decimals writes it.
fn rounded_grid(name: &str, step: f64) -> CreasePattern {
    let mut cp = formats::load(&copied(name)).expect("copied grid").pattern;
    let turn = glam::DMat2::from_angle(17f64.to_radians());
    for p in &mut cp.vertices {
        *p = (turn * *p * 100.0 / step).round() * step;
    }
    clean(cp)
}

#[test]
fn rounding_is_reported_beside_the_count_not_refused() {
    let name = "372_brown_4x4_D112.fold";
    let expected = states(&load(&copied(name)));
    assert_eq!(expected, "4096");
    let rounded = rounded_grid(name, 0.005);
    // The local check at its default 0.01° sees the rounding …
    let mut local = check(&rounded, &CheckOptions::default());
    let kawasaki = local.of_kind(FindingKind::Kawasaki).count();
    assert!(kawasaki > 0, "rounding to 0.005 leaves no Kawasaki error");
    // … the layer check lets it through as the drawing's rounding, lists it as warnings, and
    // counts what the exact design counts.
    let outcome = check_layers(&rounded, &mut local, &LayerOptions::default()).expect("layers");
    assert_eq!(outcome.skipped, None);
    assert_eq!(
        outcome.report.as_ref().map(|r| r.states.clone()),
        Some(expected.clone())
    );
    assert_eq!(outcome.rounding, kawasaki);
    assert_eq!(local.warnings.len(), kawasaki);
    assert!(local.passed(), "{:?}", local.findings.first());
    assert!(
        local
            .to_text("mm")
            .contains(&format!("PASS with {kawasaki} warning(s)"))
    );
    for w in &local.warnings {
        assert!(w.value <= w.limit, "{} over {}", w.value, w.limit);
        assert!(
            w.hint.contains("within the drawing's precision"),
            "{}",
            w.hint
        );
    }
    // A fixed tolerance below the rounding refuses it, naming a vertex.
    let strict = LayerOptions {
        kawasaki: KawasakiTolerance::Degrees(0.001),
        ..LayerOptions::default()
    };
    let mut local = check(&rounded, &CheckOptions::default());
    let outcome = check_layers(&rounded, &mut local, &strict).expect("layers");
    assert!(outcome.report.is_none());
    let why = outcome.skipped.expect("refused");
    assert!(why.contains("kawasaki at v"), "{why}");
}

#[test]
fn a_vertex_off_by_degrees_is_refused_by_name() {
    // The bundled broken vertex: one crease turned 5°. No drawing's rounding explains that.
    let path =
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("examples/patterns/broken-vertex.fold");
    let cp = load(&path);
    let faults = local_faults(&cp, KawasakiTolerance::Fitted);
    assert!(faults.rounding.is_empty());
    let first = faults.first_refusal().expect("refused");
    assert_eq!(first.vertex.map(|v| v.0), Some(0));
    assert!(first.message.contains("5.0000°"), "{}", first.message);
    // Every error beyond 0.19° is refused at any vertex (the fitted tolerance is the shortest
    // edge / 300 over the vertex's shortest crease, at most 1/300 rad): turn a crease of the
    // square twist by 0.2°.
    let mut twist = SquareTwist::default().build().expect("twist");
    let fans = foldcam::pattern::VertexFans::new(&twist);
    let centre = twist
        .vertex_ids()
        .find(|&v| {
            fans.of(v).len() == 4
                && fans
                    .of(v)
                    .iter()
                    .all(|s| twist.edges[s.edge.index()].assignment.is_fold())
        })
        .expect("an interior vertex");
    let spoke = fans.of(centre)[0];
    let far = twist.edges[spoke.edge.index()].other(centre);
    let c = twist.position(centre);
    let turned = glam::DMat2::from_angle(0.2f64.to_radians()) * (twist.position(far) - c) + c;
    twist.vertices[far.index()] = turned;
    let twist = clean(twist);
    let faults = local_faults(&twist, KawasakiTolerance::Fitted);
    assert!(
        faults.first_refusal().is_some(),
        "a 0.2° turn passed as rounding"
    );
}

#[test]
fn a_search_writes_its_progress_and_ends_finished_with_the_same_count() {
    use foldcam::check::layers::{LayerProgress, LayerStage};
    let cp = load(&copied("372_brown_4x4_D112.fold"));
    let progress = std::sync::Arc::new(LayerProgress::default());
    assert_eq!(progress.stage(), LayerStage::Waiting);
    let watched = LayerOptions {
        progress: Some(progress.clone()),
        ..LayerOptions::default()
    };
    let report = solve_layers(&cp, &watched).expect("layer problem");
    assert_eq!(progress.stage(), LayerStage::Finished);
    assert_eq!(progress.describe(), "done");
    // Watching changes nothing: the count is Flat-Folder's, with or without a watcher.
    assert_eq!(report.states, "4096");
    assert_eq!(
        report,
        solve_layers(&cp, &LayerOptions::default()).expect("layer problem")
    );
}
