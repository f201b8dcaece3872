//! The ORIPA `.cp` reader and writer: parsing, per-line errors, planarisation, exact round
//! trips, and malformed input that must never panic.

use foldcam::formats::cp;
use foldcam::pattern::{Assignment, CreasePattern, Units};
use glam::DVec2;
use proptest::prelude::*;

/// A preliminary base on ORIPA's usual −200..200 sheet: outline, valley diagonals, mountain
/// midlines, as ORIPA writes it (y down).
const PRELIMINARY: &str = "\
1 -200 -200 200 -200
1 200 -200 200 200
1 200 200 -200 200
1 -200 200 -200 -200
3 -200 -200 200 200
3 200 -200 -200 200
2 -200 0 200 0
2 0 -200 0 200
";

fn read(text: &str) -> CreasePattern {
    cp::read_str(text)
        .unwrap_or_else(|e| panic!("{e}\n{text}"))
        .pattern
}

fn count(pattern: &CreasePattern, a: Assignment) -> usize {
    pattern.edges.iter().filter(|e| e.assignment == a).count()
}

fn has_edge(pattern: &CreasePattern, a: DVec2, b: DVec2) -> bool {
    pattern.edge_ids().any(|e| {
        let (p, q) = pattern.segment(e);
        (p == a && q == b) || (p == b && q == a)
    })
}

/// Edges as sorted, orientation-free coordinate pairs with their assignment, for comparing
/// patterns up to vertex and edge order.
fn canonical(pattern: &CreasePattern) -> Vec<([f64; 4], Assignment)> {
    let mut out: Vec<_> = pattern
        .edges
        .iter()
        .map(|e| {
            let [a, b] = e.vertices.map(|v| pattern.position(v));
            let (p, q) = if (a.x, a.y) <= (b.x, b.y) {
                (a, b)
            } else {
                (b, a)
            };
            ([p.x, p.y, q.x, q.y], e.assignment)
        })
        .collect();
    out.sort_by(|x, y| x.partial_cmp(y).unwrap_or(std::cmp::Ordering::Equal));
    out
}

#[test]
fn a_preliminary_base_is_planarised() {
    let imported = cp::read_str(PRELIMINARY).expect("reads");
    let p = &imported.pattern;
    assert_eq!(p.units, Units::Unitless);
    // Diagonals and midlines cross at the centre; the midlines split the outline.
    assert_eq!(count(p, Assignment::Boundary), 8);
    assert_eq!(count(p, Assignment::Valley), 4);
    assert_eq!(count(p, Assignment::Mountain), 4);
    assert_eq!(p.vertices.len(), 9);
    assert!(p.edges.iter().all(|e| e.fold_angle.is_none()));
    assert!(
        imported.warnings().next().is_none(),
        "{:?}",
        imported.findings
    );
    assert_eq!(
        p.bounds(),
        Some((DVec2::splat(-200.0), DVec2::splat(200.0)))
    );
}

#[test]
fn y_is_negated_so_the_pattern_is_not_mirrored() {
    // ORIPA's y points down: a valley from the screen's top-left corner (−200, −200) to the
    // centre runs, in the y-up pattern, from (−200, 200) to the centre.
    let p = read("1 -200 -200 200 -200\n3 -200 -200 0 0\n");
    assert!(has_edge(&p, DVec2::new(-200.0, 200.0), DVec2::ZERO));
    assert!(has_edge(
        &p,
        DVec2::new(-200.0, 200.0),
        DVec2::new(200.0, 200.0)
    ));
}

#[test]
fn line_types_map_to_assignments() {
    let p = read("1 0 0 1 0\n2 0 1 1 1\n3 0 2 1 2\n4 0 3 1 3\n0 0 4 1 4\n7 0 5 1 5\n-1 0 6 1 6\n");
    assert_eq!(count(&p, Assignment::Boundary), 1);
    assert_eq!(count(&p, Assignment::Mountain), 1);
    assert_eq!(count(&p, Assignment::Valley), 1);
    assert_eq!(count(&p, Assignment::Flat), 4);
}

#[test]
fn whitespace_blank_lines_and_crlf_are_accepted() {
    let p = read("\u{feff}\r\n  2\t0 0   10 0 \r\n\r\n3 0 0 0 10\r\n   \n");
    assert_eq!(p.edges.len(), 2);
    assert_eq!(p.vertices.len(), 3);
}

#[test]
fn errors_name_the_line_and_the_problem() {
    let cases = [
        ("2 0 0 1 1\n\n3 0 0 1\n", "line 3", "expected 5 fields"),
        ("2 0 0 1 1 9\n", "line 1", "found 6"),
        ("M 0 0 1 1\n", "line 1", "not an integer"),
        ("2.5 0 0 1 1\n", "line 1", "not an integer"),
        (
            "2 0 0 1 1\n2 0 zero 1 1\n",
            "line 2",
            "y0 \"zero\" is not a number",
        ),
        ("2 0 0 NaN 1\n", "line 1", "finite"),
        ("2 0 0 inf 1\n", "line 1", "finite"),
        ("2 0 0 1 -2e9\n", "line 1", "beyond"),
        ("", "file", "no lines"),
        ("\n  \n\t\n", "file", "no lines"),
        ("2 1 1 1 1\n", "file", "non-zero length"),
    ];
    for (text, place, message) in cases {
        let e = cp::read_str(text).expect_err(text);
        assert_eq!(e.place, place, "{text:?}: {e}");
        assert!(e.message.contains(message), "{text:?}: {e}");
    }
}

#[test]
fn zero_length_lines_are_dropped_with_a_warning() {
    let imported = cp::read_str("2 0 0 1 0\n3 5 5 5 5\n2 1 0 2 0\n").expect("reads");
    assert_eq!(imported.pattern.edges.len(), 2);
    let w: Vec<_> = imported.warnings().collect();
    assert_eq!(w.len(), 1, "{w:?}");
    assert_eq!(w[0].kind, foldcam::formats::FindingKind::ZeroLengthLines);
    assert!(w[0].text.contains("line 2"), "{w:?}");
}

#[test]
fn the_writer_uses_oripa_types_and_negates_y() {
    let mut p = CreasePattern {
        units: Units::Unitless,
        ..CreasePattern::default()
    };
    let kinds = Assignment::ALL;
    for (i, &a) in kinds.iter().enumerate() {
        let y = i as f64 + 0.1;
        p.add_segment(DVec2::new(0.0, y), DVec2::new(1.0 / 3.0, y), a);
    }
    let text = cp::write_string(&p);
    let lines: Vec<Vec<&str>> = text.lines().map(|l| l.split(' ').collect()).collect();
    assert_eq!(lines.len(), kinds.len());
    let types: Vec<&str> = lines.iter().map(|l| l[0]).collect();
    // B M V F U C J
    assert_eq!(types, vec!["1", "2", "3", "4", "0", "1", "0"]);
    for (i, l) in lines.iter().enumerate() {
        assert_eq!(l.len(), 5);
        let y: f64 = l[2].parse().expect("a number");
        assert_eq!(y, -(i as f64 + 0.1));
        let x1: f64 = l[3].parse().expect("a number");
        assert_eq!(x1, 1.0 / 3.0);
        assert_eq!(l[1], "0", "zero written without a sign");
    }
}

#[test]
fn cp_model_cp_model_is_exact() {
    let first = read(PRELIMINARY);
    let text = cp::write_string(&first);
    let second = read(&text);
    assert_eq!(canonical(&first), canonical(&second));
    assert_eq!(cp::write_string(&second).lines().count(), first.edges.len());
}

#[test]
fn cuts_unassigned_and_joins_lose_their_kind() {
    let mut p = CreasePattern::new();
    p.add_segment(DVec2::ZERO, DVec2::X, Assignment::Cut);
    p.add_segment(DVec2::Y, DVec2::ONE, Assignment::Unassigned);
    p.add_segment(DVec2::new(0.0, 2.0), DVec2::new(1.0, 2.0), Assignment::Join);
    let back = read(&cp::write_string(&p));
    assert_eq!(count(&back, Assignment::Boundary), 1);
    assert_eq!(count(&back, Assignment::Flat), 2);
}

fn line_type() -> impl Strategy<Value = i64> {
    prop_oneof![Just(0i64), Just(1), Just(2), Just(3), Just(4), -5i64..20]
}

/// A random, possibly crossing, line list with coordinates on ORIPA's scale.
fn line_list() -> impl Strategy<Value = Vec<(i64, [f64; 4])>> {
    let coord = prop_oneof![(-200i32..=200).prop_map(f64::from), -250.0f64..250.0,];
    proptest::collection::vec(
        (
            line_type(),
            [coord.clone(), coord.clone(), coord.clone(), coord],
        ),
        1..25,
    )
}

fn to_text(lines: &[(i64, [f64; 4])]) -> String {
    lines
        .iter()
        .map(|(t, c)| format!("{t} {} {} {} {}\n", c[0], c[1], c[2], c[3]))
        .collect()
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 128, ..ProptestConfig::default() })]

    #[test]
    fn random_line_lists_round_trip(lines in line_list()) {
        let text = to_text(&lines);
        let nonzero = lines.iter().any(|(_, c)| c[0] != c[2] || c[1] != c[3]);
        let first = match cp::read_str(&text) {
            Ok(imported) => imported.pattern,
            Err(e) => {
                prop_assert!(!nonzero, "{}", e);
                return Ok(());
            }
        };
        first.validate().map_err(|e| TestCaseError::fail(e.to_string()))?;
        // Every input endpoint is a vertex of the result (y negated), up to the merge
        // tolerance, and every assignment read comes from a line type of the input.
        let tol = 1e-6 * 500.0;
        for (_, c) in lines.iter().filter(|(_, c)| c[0] != c[2] || c[1] != c[3]) {
            for p in [DVec2::new(c[0], -c[1]), DVec2::new(c[2], -c[3])] {
                prop_assert!(first.vertices.iter().any(|v| v.distance(p) <= tol), "{} lost", p);
            }
        }
        // Every edge read lies along an input line of its own assignment (its midpoint is on
        // one), so assignments are neither swapped nor mixed up between lines.
        for e in &first.edges {
            let m = first.position(e.vertices[0]).lerp(first.position(e.vertices[1]), 0.5);
            let on_line_of_kind = lines.iter().any(|(t, c)| {
                let (a, b) = (DVec2::new(c[0], -c[1]), DVec2::new(c[2], -c[3]));
                let ab = b - a;
                let u = if ab.length_squared() > 0.0 {
                    ((m - a).dot(ab) / ab.length_squared()).clamp(0.0, 1.0)
                } else {
                    0.0
                };
                cp::assignment_of(*t) == e.assignment && m.distance(a + u * ab) <= tol
            });
            prop_assert!(on_line_of_kind, "edge at {} ({:?}) is on no input line of its type", m, e.assignment);
        }
        let second = cp::read_str(&cp::write_string(&first))
            .map_err(|e| TestCaseError::fail(e.to_string()))?
            .pattern;
        prop_assert_eq!(canonical(&first), canonical(&second));
    }

    #[test]
    fn malformed_text_never_panics(text in "[0-9a-zA-Z .eE+\\-\n\t\r]{0,200}") {
        // Whatever is accepted is a valid pattern.
        if let Ok(imported) = cp::read_str(&text) {
            prop_assert!(imported.pattern.validate().is_ok());
        }
    }

    #[test]
    fn malformed_fields_never_panic(
        rows in proptest::collection::vec(
            proptest::collection::vec(
                prop_oneof![
                    Just("2".to_string()),
                    Just("nan".to_string()),
                    Just("-inf".to_string()),
                    Just("1e308".to_string()),
                    Just("1e-320".to_string()),
                    Just("99999999999999999999".to_string()),
                    (-1e10f64..1e10).prop_map(|v| v.to_string()),
                    "[a-z.+-]{1,4}",
                ],
                0..7,
            ),
            0..12,
        )
    ) {
        let text: String = rows.iter().map(|r| r.join(" ") + "\n").collect();
        match cp::read_str(&text) {
            Ok(imported) => prop_assert!(imported.pattern.validate().is_ok()),
            Err(e) => prop_assert!(!e.message.is_empty() && !e.place.is_empty()),
        }
    }
}
