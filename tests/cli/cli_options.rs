//! Every command-line option that changes a result, run with and without it: each assertion
//! would fail if the option were ignored. Expected values come from the input's own geometry
//! (edge lengths, bounding boxes, the alternating sector sum), not from foldcam's code.

use crate::bin;

use std::path::Path;

use bin::{foldcam, repo_file as data};
use foldcam::pattern::{Assignment, CreasePattern};
use serde_json::Value;

/// Runs and parses the one JSON object printed on stdout, with the exit code.
fn json(args: &[&str], dir: &Path) -> (Value, Option<i32>) {
    let o = foldcam(args, dir);
    let v = serde_json::from_slice(&o.stdout).unwrap_or_else(|e| {
        panic!(
            "{args:?}: {e}\nstdout {}\nstderr {}",
            String::from_utf8_lossy(&o.stdout),
            String::from_utf8_lossy(&o.stderr)
        )
    });
    (v, o.status.code())
}

fn load(path: &str) -> CreasePattern {
    foldcam::formats::load(Path::new(path))
        .expect("pattern loads")
        .pattern
}

/// (kind, value) of every finding of a `check --json` report.
fn findings(report: &Value) -> Vec<(String, f64)> {
    report["findings"]
        .as_array()
        .expect("findings")
        .iter()
        .map(|f| {
            (
                f["kind"].as_str().expect("kind").to_string(),
                f["value"].as_f64().expect("value"),
            )
        })
        .collect()
}

fn of_kind(report: &Value, kind: &str) -> Vec<f64> {
    findings(report)
        .into_iter()
        .filter(|(k, _)| k == kind)
        .map(|(_, v)| v)
        .collect()
}

// ---------------------------------------------------------------------------------------
// check

#[test]
fn check_min_edge_reports_exactly_the_edges_below_it() {
    let dir = tempfile::tempdir().expect("temp dir");
    let file = data("examples/patterns/flat-vertex.fold");
    let cp = load(&file);
    let mut lengths: Vec<f64> = cp
        .edges
        .iter()
        .map(|e| {
            cp.position(e.vertices[0])
                .distance(cp.position(e.vertices[1]))
        })
        .collect();
    lengths.sort_by(f64::total_cmp);
    let shortest = lengths[0];
    let limit = (shortest + lengths[1]) / 2.0;
    let below = lengths.iter().filter(|&&l| l < limit).count();
    let (r, _) = json(
        &["check", &file, "--json", "--min-edge", &limit.to_string()],
        dir.path(),
    );
    let short = of_kind(&r, "short_edge");
    assert_eq!(short.len(), below, "{r}");
    assert!(
        (short[0] - shortest).abs() < 1e-9,
        "{short:?} vs {shortest}"
    );
    let (r, _) = json(
        &[
            "check",
            &file,
            "--json",
            "--min-edge",
            &(shortest * 0.99).to_string(),
        ],
        dir.path(),
    );
    assert!(of_kind(&r, "short_edge").is_empty());
}

#[test]
fn check_max_fold_angle_reports_the_folds_beyond_it() {
    let dir = tempfile::tempdir().expect("temp dir");
    let file = data("examples/patterns/flat-vertex.fold");
    let cp = load(&file);
    let angles: Vec<f64> = cp
        .edges
        .iter()
        .filter_map(|e| e.fold_angle)
        .map(f64::abs)
        .collect();
    let largest = angles.iter().copied().fold(0.0, f64::max);
    assert!(largest > 10.0, "the example stores fold angles");
    let limit = largest - 1.0;
    let beyond = angles.iter().filter(|&&a| a > limit).count();
    let (r, _) = json(
        &[
            "check",
            &file,
            "--json",
            "--max-fold-angle",
            &limit.to_string(),
        ],
        dir.path(),
    );
    let found = of_kind(&r, "fold_angle");
    assert_eq!(found.len(), beyond, "{r}");
    assert!(
        found
            .iter()
            .all(|v| (v.abs() - largest).abs() < 1e-9 || v.abs() > limit)
    );
    let (r, _) = json(
        &[
            "check",
            &file,
            "--json",
            "--max-fold-angle",
            &(largest + 1.0).to_string(),
        ],
        dir.path(),
    );
    assert!(of_kind(&r, "fold_angle").is_empty());
}

#[test]
fn check_min_vertex_angle_reports_the_sharp_corner() {
    let dir = tempfile::tempdir().expect("temp dir");
    let file = data("examples/patterns/flat-vertex.fold");
    // The example's sectors are 60°, 100°, 120° and 80° (its description), so 61° flags one.
    let (r, _) = json(
        &["check", &file, "--json", "--min-vertex-angle", "61"],
        dir.path(),
    );
    let sharp = of_kind(&r, "vertex_angle");
    assert!(!sharp.is_empty(), "{r}");
    assert!(sharp.iter().all(|a| (a - 60.0).abs() < 1e-6), "{sharp:?}");
    let (r, _) = json(
        &["check", &file, "--json", "--min-vertex-angle", "59"],
        dir.path(),
    );
    assert!(of_kind(&r, "vertex_angle").is_empty());
}

#[test]
fn check_kawasaki_tolerance_and_no_flat_foldability() {
    let dir = tempfile::tempdir().expect("temp dir");
    let file = data("examples/patterns/broken-vertex.fold");
    let (r, code) = json(&["check", &file, "--json"], dir.path());
    assert_eq!(code, Some(1));
    let errors = of_kind(&r, "kawasaki");
    assert_eq!(errors.len(), 1, "{r}");
    let e = errors[0];
    // Just above the error: no Kawasaki finding; just below: the same one.
    let (r, _) = json(
        &[
            "check",
            &file,
            "--json",
            "--kawasaki-tolerance",
            &(e + 0.01).to_string(),
        ],
        dir.path(),
    );
    assert!(of_kind(&r, "kawasaki").is_empty(), "{r}");
    let (r, _) = json(
        &[
            "check",
            &file,
            "--json",
            "--kawasaki-tolerance",
            &(e - 0.01).to_string(),
        ],
        dir.path(),
    );
    assert_eq!(of_kind(&r, "kawasaki").len(), 1, "{r}");
    // Not meant to fold flat: neither theorem runs, and the verdict is a pass.
    let (r, code) = json(
        &["check", &file, "--json", "--no-flat-foldability"],
        dir.path(),
    );
    assert_eq!(code, Some(0), "{r}");
    assert!(of_kind(&r, "kawasaki").is_empty() && of_kind(&r, "maekawa").is_empty());
}

// ---------------------------------------------------------------------------------------
// generate

/// Bounding-box width and height of a generated pattern.
fn generated_extent(args: &[&str]) -> (f64, f64) {
    let dir = tempfile::tempdir().expect("temp dir");
    let mut all = vec!["generate"];
    all.extend_from_slice(args);
    all.extend_from_slice(&["-o", "g.fold"]);
    let o = foldcam(&all, dir.path());
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let cp = load(&dir.path().join("g.fold").to_string_lossy());
    let (lo, hi) = cp.bounds().expect("vertices");
    ((hi - lo).x, (hi - lo).y)
}

#[test]
fn generate_sizes_follow_their_options() {
    let close = |a: (f64, f64), b: (f64, f64)| (a.0 - b.0).abs() < 1e-9 && (a.1 - b.1).abs() < 1e-9;
    // Miura-ori: columns × cell width plus the zigzag offset, by rows × cell height.
    for (c, r, w, h, s) in [(4, 3, 20.0, 10.0, 0.0), (5, 2, 30.0, 15.0, 4.0)] {
        let got = generated_extent(&[
            "miura",
            "--columns",
            &c.to_string(),
            "--rows",
            &r.to_string(),
            "--width",
            &w.to_string(),
            "--height",
            &h.to_string(),
            "--shear",
            &s.to_string(),
        ]);
        let want = (c as f64 * w + s, r as f64 * h);
        assert!(close(got, want), "miura {c}×{r}: {got:?} vs {want:?}");
    }
    // Waterbomb bases: square bases of the given size.
    let got = generated_extent(&[
        "waterbomb",
        "--columns",
        "3",
        "--rows",
        "2",
        "--width",
        "20",
    ]);
    assert!(close(got, (60.0, 40.0)), "waterbomb {got:?}");
    // Yoshimura: columns × width by rows × height.
    let got = generated_extent(&[
        "yoshimura",
        "--columns",
        "3",
        "--rows",
        "2",
        "--width",
        "20",
        "--height",
        "10",
    ]);
    assert!(close(got, (60.0, 20.0)), "yoshimura {got:?}");
}

// ---------------------------------------------------------------------------------------
// plan / cut: operations per assignment and contour options

/// Length per operation, pierces, travel and naive travel of `plan --json` on the four-line
/// square (boundary 400 mm, mountain and valley 100 mm, flat 100 mm, unassigned diagonal
/// √(50² + 25²) mm).
fn plan_of(extra: &[&str]) -> (std::collections::BTreeMap<String, f64>, u64, f64) {
    let dir = tempfile::tempdir().expect("temp dir");
    let file = data("tests/data/patterns/four-lines.fold");
    let mut args = vec![
        "plan",
        &file,
        "-m",
        "grbl-diode",
        "-x",
        "card-300gsm",
        "--json",
    ];
    args.extend_from_slice(extra);
    let (v, code) = json(&args, dir.path());
    assert_eq!(code, Some(0), "{v}");
    let lengths = v["length_mm"]
        .as_array()
        .expect("lengths")
        .iter()
        .map(|p| {
            (
                p[0].as_str().expect("op").to_string(),
                p[1].as_f64().expect("mm"),
            )
        })
        .collect();
    (
        lengths,
        v["pierces"].as_u64().expect("pierces"),
        v["travel_mm"].as_f64().expect("travel"),
    )
}

fn len(lengths: &std::collections::BTreeMap<String, f64>, op: &str) -> f64 {
    lengths.get(op).copied().unwrap_or(0.0)
}

#[test]
fn operation_options_move_each_line_to_its_operation() {
    let diagonal = (50f64 * 50.0 + 25.0 * 25.0).sqrt();
    let (base, _, _) = plan_of(&["--no-kerf-offset"]);
    // Card scores mountains, valleys and unassigned lines; flat lines are not burned.
    assert!(
        (len(&base, "score") - (200.0 + diagonal)).abs() < 1e-6,
        "{base:?}"
    );
    assert!((len(&base, "cut") - 400.0).abs() < 1e-6, "{base:?}");
    let (flat, _, _) = plan_of(&["--no-kerf-offset", "--flat", "score"]);
    assert!((len(&flat, "score") - len(&base, "score") - 100.0).abs() < 1e-6);
    let (valley, _, _) = plan_of(&["--no-kerf-offset", "--valley", "cut"]);
    assert!((len(&valley, "cut") - 500.0).abs() < 1e-6, "{valley:?}");
    assert!((len(&valley, "score") - (100.0 + diagonal)).abs() < 1e-6);
    let (unassigned, _, _) = plan_of(&["--no-kerf-offset", "--unassigned", "mark"]);
    assert!(
        (len(&unassigned, "mark") - diagonal).abs() < 1e-6,
        "{unassigned:?}"
    );
    let (boundary, _, _) = plan_of(&["--no-kerf-offset", "--boundary", "score"]);
    assert!(len(&boundary, "cut") == 0.0, "{boundary:?}");
    assert!((len(&boundary, "score") - (600.0 + diagonal)).abs() < 1e-6);
}

#[test]
fn kerf_tabs_lead_in_and_order_options_change_the_cut() {
    // Without the offset the cut is the outline itself.
    let (plain, pierces, travel) = plan_of(&["--no-kerf-offset"]);
    assert!((len(&plain, "cut") - 400.0).abs() < 1e-6);
    // Offset by half the kerf with round corners: the outline grows by π × kerf. Round joins
    // are drawn as chords, and chords whose neighbours meet within half the machine's
    // resolution become that corner (no bevel the machine cannot draw), so within 2%.
    for kerf in [0.4, 1.0] {
        let (k, _, _) = plan_of(&["--kerf", &kerf.to_string()]);
        let grown = len(&k, "cut") - 400.0;
        let full = std::f64::consts::PI * kerf;
        assert!(
            grown <= 1.02 * full && grown > 0.99 * full,
            "kerf {kerf}: +{grown}"
        );
    }
    // Tabs: the loop is split into as many pieces as tabs, each tab leaving 2 mm uncut.
    let (tabs, tab_pierces, _) = plan_of(&["--no-kerf-offset", "--tabs", "2"]);
    let n = tab_pierces - pierces + 1;
    assert!(n >= 2, "tabs made {n} pieces");
    assert!((len(&plain, "cut") - len(&tabs, "cut") - 2.0 * n as f64).abs() < 1e-6);
    // A 3 mm lead-in on the one closed contour adds 3 mm of cut.
    let (lead, _, _) = plan_of(&["--no-kerf-offset", "--lead-in", "3"]);
    assert!((len(&lead, "cut") - 403.0).abs() < 1e-6, "{lead:?}");
    // Without optimisation the travel is longer than the optimised one.
    let (_, _, unordered) = plan_of(&["--no-kerf-offset", "--no-optimize"]);
    assert!(unordered > travel + 1.0, "{unordered} vs {travel}");
}

#[test]
fn r12_and_dasharray_change_the_files_written() {
    let dir = tempfile::tempdir().expect("temp dir");
    let file = data("tests/data/patterns/four-lines.fold");
    let cut = |out: &str, extra: &[&str]| {
        let mut args = vec![
            "cut",
            &file,
            "-m",
            "lightburn",
            "-x",
            "card-300gsm",
            "-o",
            out,
        ];
        args.extend_from_slice(extra);
        let o = foldcam(&args, dir.path());
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        std::fs::read_to_string(dir.path().join(out)).expect("written")
    };
    assert!(cut("a.dxf", &[]).contains("AC1015"));
    let r12 = cut("b.dxf", &["--r12"]);
    assert!(r12.contains("AC1009") && !r12.contains("LWPOLYLINE"));
    assert!(!cut("a.svg", &["--valley", "perforate"]).contains("stroke-dasharray"));
    assert!(cut("b.svg", &["--valley", "perforate", "--dasharray"]).contains("stroke-dasharray"));
}

// ---------------------------------------------------------------------------------------
// simulate

#[test]
fn simulate_side_checks_the_back_job_against_the_back() {
    let dir = tempfile::tempdir().expect("temp dir");
    let run = |args: &[&str]| foldcam(args, dir.path());
    let o = run(&[
        "generate",
        "miura",
        "-o",
        "m.fold",
        "--columns",
        "4",
        "--rows",
        "3",
    ]);
    assert!(o.status.success());
    let o = run(&[
        "cut",
        "m.fold",
        "-m",
        "grbl-diode",
        "-x",
        "card-300gsm",
        "-o",
        "m.gcode",
        "--two-sided",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let sim = |side: &str| {
        run(&[
            "simulate",
            "m.back.gcode",
            "-m",
            "grbl-diode",
            "--pattern",
            "m.fold",
            "-x",
            "card-300gsm",
            "--two-sided",
            "--side",
            side,
        ])
    };
    assert_eq!(sim("back").status.code(), Some(0));
    // The back job checked as the front: its burns follow no front crease.
    let wrong = sim("front");
    assert_eq!(wrong.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&wrong.stdout).contains("stray"));
}

#[test]
fn four_lines_fixture_has_one_line_of_each_kind() {
    // The fixture the plan tests rely on.
    let cp = load(&data("tests/data/patterns/four-lines.fold"));
    let length = |a: Assignment| -> f64 {
        cp.edges
            .iter()
            .filter(|e| e.assignment == a)
            .map(|e| {
                cp.position(e.vertices[0])
                    .distance(cp.position(e.vertices[1]))
            })
            .sum()
    };
    assert_eq!(length(Assignment::Boundary), 400.0);
    assert_eq!(length(Assignment::Mountain), 100.0);
    assert_eq!(length(Assignment::Valley), 100.0);
    assert_eq!(length(Assignment::Flat), 100.0);
    assert!((length(Assignment::Unassigned) - 3125f64.sqrt()).abs() < 1e-12);
}

// ---------------------------------------------------------------------------------------
// convert

#[test]
fn convert_planarize_splits_crossings_and_tolerance_merges_close_vertices() {
    let dir = tempfile::tempdir().expect("temp dir");
    // A square with two crossing creases, one of which starts 0.05 mm above a corner, on the
    // left side; vertex 5 repeats corner 2 and is unused. No faces.
    let fold = r#"{"file_spec":1.2,"frame_unit":"mm",
      "vertices_coords":[[0,0],[100,0],[100,100],[0,100],[0,0.05],[100,100.0]],
      "edges_vertices":[[0,1],[1,2],[2,3],[3,0],[4,2],[1,3]],
      "edges_assignment":["B","B","B","B","M","V"]}"#;
    std::fs::write(dir.path().join("x.fold"), fold).expect("write");
    // (distinct end points, lines) of the written ORIPA file, read as plain text.
    let lines = |out: &str, extra: &[&str]| {
        let mut args = vec!["convert", "x.fold", out];
        args.extend_from_slice(extra);
        let o = foldcam(&args, dir.path());
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let text = std::fs::read_to_string(dir.path().join(out)).expect("written");
        let mut points = std::collections::BTreeSet::new();
        let mut count = 0;
        for line in text.lines().filter(|l| !l.trim().is_empty()) {
            let v: Vec<f64> = line
                .split_whitespace()
                .skip(1)
                .map(|t| t.parse().expect("number"))
                .collect();
            points.insert(((v[0] * 1e6).round() as i64, (v[1] * 1e6).round() as i64));
            points.insert(((v[2] * 1e6).round() as i64, (v[3] * 1e6).round() as i64));
            count += 1;
        }
        (points.len(), count)
    };
    // As drawn: the six lines and their five distinct ends.
    assert_eq!(lines("a.cp", &[]), (5, 6));
    // Cleaned: the diagonals split at their crossing (+2 lines, +1 point) and the left side
    // split where the mountain starts on it (+1 line).
    assert_eq!(lines("b.cp", &["--planarize"]), (6, 9));
    // A tolerance above 0.05 mm merges that start into the corner: the side stays whole.
    assert_eq!(
        lines("c.cp", &["--planarize", "--tolerance", "0.1"]),
        (5, 8)
    );
}

// ---------------------------------------------------------------------------------------
// tessellate

fn tessellate(extra: &[&str], mesh: &str, dir: &Path) -> (String, foldcam::formats::Imported) {
    let mesh = data(&format!("examples/tessellation/{mesh}.obj"));
    // Partial forms (a corner over 5% of the size off the mesh) are written and exit 1
    // without --allow-partial; these tests look at the options, not the fit.
    let mut args = vec![
        "tessellate",
        &mesh,
        "-o",
        "t.fold",
        "-x",
        "stainless-0.5",
        "--allow-partial",
    ];
    args.extend_from_slice(extra);
    let o = foldcam(&args, dir);
    let stdout = String::from_utf8_lossy(&o.stdout).into_owned();
    assert!(
        o.status.success(),
        "{args:?}: {stdout}{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let imported = foldcam::formats::load(&dir.join("t.fold")).expect("tessellation loads");
    (stdout, imported)
}

#[test]
fn tessellate_layout_and_shrink_reach_the_pattern() {
    let dir = tempfile::tempdir().expect("temp dir");
    let (out, checker) = tessellate(
        &["--layout", "checkerboard", "--shrink", "0.7"],
        "dome",
        dir.path(),
    );
    assert!(
        out.contains("checkerboard layout") && out.contains("shrink 0.7"),
        "{out}"
    );
    let (out, digon) = tessellate(
        &[
            "--layout",
            "digon",
            "--max-fold-angle",
            "178",
            "--min-vertex-angle",
            "15",
        ],
        "dome",
        dir.path(),
    );
    assert!(out.contains("digon layout"), "{out}");
    // A digon on every interior edge makes a different pattern from the checkerboard.
    assert_ne!(checker.pattern.edges.len(), digon.pattern.edges.len());
}

#[test]
fn tessellate_ground_puts_the_boundary_on_one_plane_and_fit_reduces_the_distance() {
    let dir = tempfile::tempdir().expect("temp dir");
    let boundary_z_spread = |imported: &foldcam::formats::Imported| {
        let folded = imported.folded.as_ref().expect("folded frame");
        let z: Vec<f64> = imported
            .pattern
            .edges
            .iter()
            .filter(|e| e.assignment == Assignment::Boundary)
            .flat_map(|e| e.vertices)
            .map(|v| folded.positions[v.index()].z)
            .collect();
        let lo = z.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = z.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        hi - lo
    };
    let (_, free) = tessellate(&["--shrink", "0.8"], "saddle", dir.path());
    assert!(
        boundary_z_spread(&free) > 1.0,
        "the saddle's rim is not flat"
    );
    let (_, grounded) = tessellate(&["--shrink", "0.8", "--ground"], "saddle", dir.path());
    assert!(
        boundary_z_spread(&grounded) < 1e-6,
        "{}",
        boundary_z_spread(&grounded)
    );
    let (out, _) = tessellate(&["--shrink", "0.8", "--fit", "0.5"], "saddle", dir.path());
    let line = out
        .lines()
        .find(|l| l.starts_with("surface fit"))
        .unwrap_or_else(|| panic!("no surface-fit line: {out}"));
    let numbers: Vec<f64> = line
        .split(|c: char| !(c.is_ascii_digit() || c == '.' || c == 'e' || c == '-'))
        .filter_map(|t| t.parse().ok())
        .collect();
    assert!(numbers.len() >= 2 && numbers[1] < numbers[0], "{line}");
}
