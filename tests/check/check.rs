//! `check` against the theory of flat folding: single-vertex patterns built from angles, a
//! square twist, boundary handling, and the vertex-angle, edge and fold-angle limits.

use foldcam::check::{CheckOptions, CheckReport, FindingKind, Quantity, check};
use foldcam::pattern::{Assignment, CreasePattern, VertexId};
use glam::DVec2;

use Assignment::{Boundary as B, Mountain as M, Unassigned as U, Valley as V};

fn dir(deg: f64) -> DVec2 {
    let r = deg.to_radians();
    DVec2::new(r.cos(), r.sin())
}

/// A single vertex at the origin with creases towards `spokes` (degrees, ascending in
/// [0, 360)) reaching a circular outline of radius 1. The outline gets extra corners so no
/// chord spans more than 60°, keeping the centre strictly inside.
fn single_vertex(spokes: &[(f64, Assignment)]) -> CreasePattern {
    let mut cp = CreasePattern::new();
    let centre = cp.add_vertex(DVec2::ZERO);
    let mut ring: Vec<VertexId> = Vec::new();
    for (i, &(deg, a)) in spokes.iter().enumerate() {
        let end = cp.add_vertex(dir(deg));
        cp.add_edge(centre, end, a);
        ring.push(end);
        let next = spokes[(i + 1) % spokes.len()].0;
        let sector = if i + 1 == spokes.len() {
            next + 360.0 - deg
        } else {
            next - deg
        };
        let parts = (sector / 60.0).ceil() as usize;
        for k in 1..parts {
            ring.push(cp.add_vertex(dir(deg + sector * k as f64 / parts as f64)));
        }
    }
    for i in 0..ring.len() {
        cp.add_edge(ring[i], ring[(i + 1) % ring.len()], B);
    }
    cp
}

fn kinds(report: &CheckReport, kind: FindingKind) -> usize {
    report.of_kind(kind).count()
}

/// Miura-ori vertex: sectors θ, 180°−θ, 180°−θ, θ.
fn miura(theta: f64, perturb: f64) -> CreasePattern {
    single_vertex(&[
        (0.0, M),
        (theta + perturb, V),
        (180.0, M),
        (360.0 - theta, M),
    ])
}

#[test]
fn miura_vertex_is_flat_foldable() {
    for theta in [30.0, 60.0, 75.0, 89.0] {
        let report = check(&miura(theta, 0.0), &CheckOptions::default());
        assert!(report.passed(), "θ = {theta}: {}", report.to_text("mm"));
        assert_eq!(report.summary.interior_vertices_checked, 1);
    }
}

#[test]
fn perturbed_crease_gives_the_rotation_as_kawasaki_error() {
    // Rotating crease 1 by δ makes the even sectors sum to θ + δ + (180° − θ) = 180° + δ, so
    // the error is δ.
    for (theta, delta) in [(60.0, 1.0), (45.0, -2.5), (80.0, 0.25)] {
        let report = check(&miura(theta, delta), &CheckOptions::default());
        let f: Vec<_> = report.of_kind(FindingKind::Kawasaki).collect();
        assert_eq!(f.len(), 1, "{}", report.to_text("mm"));
        assert!(
            (f[0].value - f64::abs(delta)).abs() < 1e-9,
            "{}",
            f[0].value
        );
        assert_eq!(f[0].vertex, Some(VertexId(0)));
        assert_eq!(f[0].position, DVec2::ZERO);
        assert!(
            f[0].hint.contains(&format!("{:.4}°", f64::abs(delta))),
            "{}",
            f[0].hint
        );
        // Maekawa still holds (3 M + 1 V).
        assert_eq!(kinds(&report, FindingKind::Maekawa), 0);
    }
}

#[test]
fn kawasaki_tolerance_is_respected() {
    let opts = CheckOptions {
        kawasaki_tolerance_deg: 0.5,
        ..CheckOptions::default()
    };
    assert!(check(&miura(60.0, 0.4), &opts).passed());
    assert!(!check(&miura(60.0, 0.6), &opts).passed());
}

#[test]
fn odd_degree_interior_vertex_fails() {
    let cp = single_vertex(&[(0.0, M), (120.0, M), (240.0, V)]);
    let report = check(&cp, &CheckOptions::default());
    let f: Vec<_> = report.of_kind(FindingKind::Kawasaki).collect();
    assert_eq!(f.len(), 1);
    assert_eq!(f[0].quantity, Quantity::Creases);
    assert_eq!(f[0].value, 3.0);
}

#[test]
fn maekawa_two_and_two_fails_with_counts() {
    let cp = single_vertex(&[(0.0, M), (90.0, V), (180.0, M), (270.0, V)]);
    let report = check(&cp, &CheckOptions::default());
    assert_eq!(kinds(&report, FindingKind::Kawasaki), 0);
    let f: Vec<_> = report.of_kind(FindingKind::Maekawa).collect();
    assert_eq!(f.len(), 1);
    let counts = f[0].mv_counts.expect("counts");
    assert_eq!((counts.mountains, counts.valleys), (2, 2));
    assert_eq!(f[0].value, 0.0);
    assert!(
        f[0].hint.contains("flip one of the 2 mountains"),
        "{}",
        f[0].hint
    );
}

#[test]
fn maekawa_is_skipped_with_unassigned_creases() {
    let cp = single_vertex(&[(0.0, M), (90.0, U), (180.0, M), (270.0, V)]);
    let report = check(&cp, &CheckOptions::default());
    assert!(report.passed());
    assert_eq!(report.summary.maekawa_skipped_unassigned, 1);
    assert_eq!(report.summary.interior_vertices_checked, 1);
}

#[test]
fn flat_and_join_lines_do_not_fold() {
    // A flat facet line through the vertex changes nothing: still a Miura vertex.
    let cp = single_vertex(&[
        (0.0, M),
        (60.0, V),
        (100.0, Assignment::Flat),
        (180.0, M),
        (300.0, M),
        (330.0, Assignment::Join),
    ]);
    assert!(check(&cp, &CheckOptions::default()).passed());
}

/// A square sheet [0, 4]² with one straight valley across the middle.
fn sheet_with_middle_valley() -> CreasePattern {
    let mut cp = CreasePattern::new();
    let p = |cp: &mut CreasePattern, x: f64, y: f64| cp.add_vertex(DVec2::new(x, y));
    let c = [
        p(&mut cp, 0.0, 0.0),
        p(&mut cp, 4.0, 0.0),
        p(&mut cp, 4.0, 4.0),
        p(&mut cp, 0.0, 4.0),
    ];
    let l = p(&mut cp, 0.0, 2.0);
    let r = p(&mut cp, 4.0, 2.0);
    cp.add_edge(c[0], c[1], B);
    cp.add_edge(c[1], r, B);
    cp.add_edge(r, c[2], B);
    cp.add_edge(c[2], c[3], B);
    cp.add_edge(c[3], l, B);
    cp.add_edge(l, c[0], B);
    cp.add_edge(l, r, V);
    cp
}

#[test]
fn boundary_vertices_are_not_checked() {
    let report = check(&sheet_with_middle_valley(), &CheckOptions::default());
    assert!(report.passed(), "{}", report.to_text("mm"));
    assert_eq!(report.summary.interior_vertices_checked, 0);
}

#[test]
fn pattern_without_boundary_checks_only_enclosed_vertices() {
    // A 3 × 3 lattice of creases (no outline): only the centre is enclosed.
    let mut cp = CreasePattern::new();
    let id = |i: usize, j: usize| VertexId::new(i * 3 + j);
    for i in 0..3 {
        for j in 0..3 {
            cp.add_vertex(DVec2::new(j as f64, i as f64));
        }
    }
    for i in 0..3 {
        for j in 0..2 {
            cp.add_edge(id(i, j), id(i, j + 1), M);
            cp.add_edge(id(j, i), id(j + 1, i), if i == 1 { V } else { M });
        }
    }
    let report = check(&cp, &CheckOptions::default());
    assert_eq!(report.summary.interior_vertices_checked, 1);
    // Centre: M, V, M, V → Maekawa fails there and nowhere else.
    let f: Vec<_> = report.of_kind(FindingKind::Maekawa).collect();
    assert_eq!(f.len(), 1);
    assert_eq!(f[0].vertex, Some(id(1, 1)));
}

/// The square twist: a diamond of mountains with two pleats leaving each corner.
fn square_twist() -> CreasePattern {
    let mut cp = CreasePattern::new();
    let mut p = |x: f64, y: f64| cp.add_vertex(DVec2::new(x, y));
    let inner = [p(1.0, 0.0), p(0.0, 1.0), p(-1.0, 0.0), p(0.0, -1.0)];
    // Pleat ends on the outline of [-3, 3]², in counter-clockwise order with the corners.
    let ring_pts = [
        (3.0, -3.0),
        (3.0, 0.0),
        (3.0, 1.0),
        (3.0, 3.0),
        (0.0, 3.0),
        (-1.0, 3.0),
        (-3.0, 3.0),
        (-3.0, 0.0),
        (-3.0, -1.0),
        (-3.0, -3.0),
        (0.0, -3.0),
        (1.0, -3.0),
    ];
    let ring: Vec<VertexId> = ring_pts.iter().map(|&(x, y)| p(x, y)).collect();
    for i in 0..ring.len() {
        cp.add_edge(ring[i], ring[(i + 1) % ring.len()], B);
    }
    for i in 0..4 {
        cp.add_edge(inner[i], inner[(i + 1) % 4], M);
    }
    // (corner, ring index, assignment): each corner gets one mountain and one valley pleat.
    let pleats = [
        (0, 1, M),
        (0, 11, V),
        (1, 2, V),
        (1, 4, M),
        (2, 5, V),
        (2, 7, M),
        (3, 8, V),
        (3, 10, M),
    ];
    for (corner, r, a) in pleats {
        cp.add_edge(inner[corner], ring[r], a);
    }
    cp
}

#[test]
fn square_twist_is_flat_foldable() {
    let cp = square_twist();
    let report = check(&cp, &CheckOptions::default());
    assert!(report.passed(), "{}", report.to_text("mm"));
    assert_eq!(report.summary.interior_vertices_checked, 4);
    // Sectors at each twist corner are 90°, 45°, 90°, 135°.
    let smallest = report.summary.smallest_crease_angle.expect("angle");
    assert!(
        (smallest.degrees - 45.0).abs() < 1e-9,
        "{}",
        smallest.degrees
    );
}

#[test]
fn flipping_a_square_twist_pleat_breaks_maekawa() {
    let mut cp = square_twist();
    let last = cp.edges.len() - 1;
    cp.edges[last].assignment = V;
    let report = check(&cp, &CheckOptions::default());
    let f: Vec<_> = report.of_kind(FindingKind::Maekawa).collect();
    assert_eq!(f.len(), 1);
    assert_eq!(f[0].position, DVec2::new(0.0, -1.0));
}

#[test]
fn vertex_angle_limit_catches_a_narrow_sector() {
    // Sectors 10°, 170°, 170°, 10° (a Miura vertex with θ = 10°): flat-foldable, with two
    // 10° slivers around the 0° crease.
    let cp = miura(10.0, 0.0);
    let with = |limit: f64| {
        let opts = CheckOptions {
            min_vertex_angle_deg: Some(limit),
            ..CheckOptions::default()
        };
        check(&cp, &opts)
    };
    let strict = with(15.0);
    let f: Vec<_> = strict.of_kind(FindingKind::VertexAngle).collect();
    assert_eq!(f.len(), 1, "{}", strict.to_text("mm"));
    assert_eq!(f[0].vertex, Some(VertexId(0)));
    assert!((f[0].value - 10.0).abs() < 1e-9);
    assert_eq!(f[0].limit, 15.0);
    assert_eq!(kinds(&strict, FindingKind::Kawasaki), 0);
    assert!(with(5.0).passed(), "{}", with(5.0).to_text("mm"));
    let smallest = strict.summary.smallest_crease_angle.expect("angle");
    assert!((smallest.degrees - 10.0).abs() < 1e-9);
}

#[test]
fn exterior_sector_between_outline_edges_is_not_counted() {
    // Corners have only outline edges (90° inside, 270° outside); the crease meets the
    // outline at 90°.
    let opts = CheckOptions {
        min_vertex_angle_deg: Some(89.0),
        ..CheckOptions::default()
    };
    let report = check(&sheet_with_middle_valley(), &opts);
    assert!(report.passed(), "{}", report.to_text("mm"));
    let smallest = report.summary.smallest_crease_angle.expect("angle");
    assert!((smallest.degrees - 90.0).abs() < 1e-9);
}

#[test]
fn crease_meeting_the_outline_at_a_sliver_is_found() {
    let mut cp = sheet_with_middle_valley();
    // A valley from the bottom-left corner at 5° to the right edge.
    let end = cp.add_vertex(DVec2::new(4.0, 4.0 * 5f64.to_radians().tan()));
    cp.edges[1].vertices = [VertexId(1), end];
    cp.add_edge(end, VertexId(5), B);
    cp.add_edge(VertexId(0), end, V);
    let opts = CheckOptions {
        min_vertex_angle_deg: Some(15.0),
        ..CheckOptions::default()
    };
    let report = check(&cp, &opts);
    let at_corner: Vec<_> = report
        .of_kind(FindingKind::VertexAngle)
        .filter(|f| f.vertex == Some(VertexId(0)))
        .collect();
    assert_eq!(at_corner.len(), 1);
    assert!((at_corner[0].value - 5.0).abs() < 1e-9);
}

#[test]
fn fold_angle_and_edge_length_limits() {
    let mut cp = sheet_with_middle_valley();
    cp.edges[6].fold_angle = Some(170.0);
    let opts = CheckOptions {
        max_fold_angle_deg: Some(150.0),
        min_edge_length: Some(2.5),
        ..CheckOptions::default()
    };
    let report = check(&cp, &opts);
    let fold: Vec<_> = report.of_kind(FindingKind::FoldAngle).collect();
    assert_eq!(fold.len(), 1);
    assert_eq!(fold[0].value, 170.0);
    assert_eq!(fold[0].position, DVec2::new(2.0, 2.0));
    // The four half-sides of length 2 are short; the rest are 4 long.
    assert_eq!(kinds(&report, FindingKind::ShortEdge), 4);
    let shortest = report.summary.shortest_edge.expect("shortest");
    assert_eq!(shortest.value, 2.0);
    assert_eq!(
        report.summary.largest_fold_angle.expect("fold").value,
        170.0
    );
    cp.edges[6].fold_angle = Some(-120.0);
    assert_eq!(kinds(&check(&cp, &opts), FindingKind::FoldAngle), 0);
}

#[test]
fn findings_are_sorted_by_kind_then_severity() {
    let mut cp = sheet_with_middle_valley();
    cp.edges[6].fold_angle = Some(170.0);
    let opts = CheckOptions {
        max_fold_angle_deg: Some(150.0),
        min_edge_length: Some(3.0),
        min_vertex_angle_deg: Some(100.0),
        ..CheckOptions::default()
    };
    let report = check(&cp, &opts);
    let ks: Vec<FindingKind> = report.findings.iter().map(|f| f.kind).collect();
    let mut sorted = ks.clone();
    sorted.sort();
    assert_eq!(ks, sorted);
    assert!(ks.contains(&FindingKind::VertexAngle));
}

#[test]
fn json_report_parses_and_has_the_findings() {
    let report = check(&miura(60.0, 1.0), &CheckOptions::default());
    let json = serde_json::to_string(&report).expect("serialise");
    let value: serde_json::Value = serde_json::from_str(&json).expect("parse");
    let findings = value["findings"].as_array().expect("findings");
    assert_eq!(findings.len(), 1);
    assert_eq!(findings[0]["kind"], "kawasaki");
    assert_eq!(findings[0]["position"], serde_json::json!([0.0, 0.0]));
    assert!((findings[0]["value"].as_f64().expect("value") - 1.0).abs() < 1e-9);
    assert_eq!(value["summary"]["interior_vertices_checked"], 1);
    assert_eq!(value["summary"]["assignments"]["mountain"], 3);
}

#[test]
fn text_report_caps_each_kind_and_ends_with_the_verdict() {
    // 60 separate short creases.
    let mut cp = CreasePattern::new();
    for i in 0..60 {
        let x = i as f64 * 10.0;
        cp.add_segment(DVec2::new(x, 0.0), DVec2::new(x + 0.1, 0.0), M);
    }
    let opts = CheckOptions {
        min_edge_length: Some(1.0),
        ..CheckOptions::default()
    };
    let report = check(&cp, &opts);
    assert_eq!(report.findings.len(), 60);
    let text = report.to_text("mm");
    // Each line: its number in the report's list (`#1`, as preview --check rings it), kind, …
    let lines = text
        .lines()
        .filter(|l| l.starts_with('#') && l.split_whitespace().nth(1) == Some("short_edge"))
        .count();
    assert_eq!(lines, 50);
    assert!(text.lines().any(|l| l.starts_with("#50 ")), "{text}");
    assert!(text.contains("and 10 more short_edge"), "{text}");
    assert!(text.contains("min edge 1 mm"), "{text}");
    assert!(text.contains("0.1000 mm long"), "{text}");
    assert!(
        text.trim_end()
            .lines()
            .last()
            .expect("line")
            .starts_with("FAIL: 60")
    );
    let passing = check(&miura(60.0, 0.0), &CheckOptions::default()).to_text("mm");
    // A pass names the checks that ran and how much each covered: the degree-4 vertex.
    assert_eq!(
        passing.trim_end().lines().last(),
        Some("PASS (checked: flat_foldability (1))")
    );
}

#[test]
fn a_pass_says_what_was_checked_and_not_checked_exits_1() {
    let dir = tempfile::tempdir().unwrap();
    let bin = env!("CARGO_BIN_EXE_foldcam");
    let run = |args: &[&str]| {
        std::process::Command::new(bin)
            .args(args)
            .current_dir(dir.path())
            .output()
            .unwrap()
    };
    let last_line = |o: &std::process::Output| {
        let text = String::from_utf8_lossy(&o.stdout).to_string();
        text.trim_end().lines().last().unwrap_or("").to_string()
    };
    // A Miura-ori sheared by 4 mm with its creases at 170°: 3D targets, where Kawasaki and
    // Maekawa do not decide. They hold all the same at its 11 × 7 interior vertices (the
    // creases fold flat), but whether they reach the 170° form was not checked: not a plain
    // PASS, and exit 1 unless --allow-unchecked.
    let made = run(&[
        "generate",
        "miura",
        "--columns",
        "12",
        "--rows",
        "8",
        "--shear",
        "4",
        "-o",
        "m.fold",
    ]);
    assert!(made.status.success());
    let pattern = foldcam::formats::load(&dir.path().join("m.fold"))
        .unwrap()
        .pattern;
    let report = check(&pattern, &CheckOptions::default());
    assert_eq!(report.summary.vertices_3d, 77);
    assert_eq!(report.summary.vertices_3d_flat, 77);
    assert_eq!(report.unchecked_vertices, 77);
    assert!(report.passed() && !report.checked_folding());
    let o = run(&["check", "m.fold"]);
    assert_eq!(o.status.code(), Some(1));
    let verdict = last_line(&o);
    assert!(
        verdict.starts_with(
            "PASS, but NOT CHECKED at 77 of 77 interior vertices: they are 3D targets"
        ),
        "{verdict}"
    );
    assert!(
        verdict.contains("Kawasaki and Maekawa hold there all the same"),
        "{verdict}"
    );
    assert!(verdict.contains("--allow-unchecked"), "{verdict}");
    assert_eq!(verdict, report.verdict());
    let allowed = run(&["check", "m.fold", "--allow-unchecked"]);
    assert_eq!(allowed.status.code(), Some(0));
    assert_eq!(last_line(&allowed), verdict);
    // The JSON report says the same.
    let o = run(&["check", "m.fold", "--json"]);
    assert_eq!(o.status.code(), Some(1));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["unchecked_vertices"], 77);
    assert_eq!(v["verdict"], verdict.as_str());
    // Folded fully (180°), the same Miura-ori is checked flat and passes plainly.
    let flat = run(&[
        "generate",
        "miura",
        "--columns",
        "12",
        "--rows",
        "8",
        "--shear",
        "4",
        "--fold-angle",
        "180",
        "-o",
        "flat.fold",
    ]);
    assert!(flat.status.success());
    let o = run(&["check", "flat.fold"]);
    assert_eq!(o.status.code(), Some(0));
    assert!(
        last_line(&o).starts_with("PASS (checked: flat_foldability (77)"),
        "{}",
        last_line(&o)
    );
    // One crease of it turned by 2° no longer folds flat: at a 3D target that fails nothing,
    // but the vertex is then not checked at all.
    let mut bent = pattern.clone();
    let centre = report
        .summary
        .smallest_crease_angle
        .expect("an angle")
        .vertex;
    let e = (0..bent.edges.len())
        .find(|&e| bent.edges[e].vertices.contains(&centre) && bent.edges[e].assignment.may_fold())
        .unwrap();
    let far = bent.edges[e].other(centre);
    let c = bent.vertices[centre.index()];
    bent.vertices[far.index()] =
        c + DVec2::from_angle(2f64.to_radians()).rotate(bent.vertices[far.index()] - c);
    let report = check(&bent, &CheckOptions::default());
    assert!(report.passed(), "a 3D target fails nothing here");
    assert!(report.unchecked_vertices >= 1 && !report.checked_folding());
    std::fs::write(
        dir.path().join("bent.fold"),
        foldcam::formats::fold::write_string(&bent, None),
    )
    .unwrap();
    let o = run(&["check", "bent.fold"]);
    assert_eq!(o.status.code(), Some(1));
    assert!(
        last_line(&o).starts_with(&format!(
            "PASS, but NOT CHECKED at {} of 77 interior vertices",
            report.unchecked_vertices
        )),
        "{}",
        last_line(&o)
    );
    assert!(
        run(&["check", "bent.fold", "--allow-unchecked"])
            .status
            .success()
    );
    // Folded in 3D, the file carries a frame: developability runs and nothing is unchecked.
    let folded = run(&[
        "fold3d",
        "bent.fold",
        "--percent",
        "50",
        "-o",
        "folded.fold",
    ]);
    assert!(matches!(folded.status.code(), Some(0 | 1)));
    let o = run(&["check", "folded.fold", "--fold-frame", "1"]);
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(text.contains("developability    ran"), "{text}");
    assert!(!text.contains("NOT CHECKED"), "{text}");
}

#[test]
fn flat_foldability_can_be_switched_off() {
    let opts = CheckOptions {
        flat_foldability: false,
        ..CheckOptions::default()
    };
    let report = check(&miura(60.0, 3.0), &opts);
    assert!(report.passed());
    assert_eq!(report.summary.interior_vertices_checked, 0);
}

#[test]
fn empty_pattern_passes() {
    let report = check(&CreasePattern::new(), &CheckOptions::default());
    assert!(report.passed());
    assert!(report.summary.shortest_edge.is_none());
}

#[test]
fn degree_six_vertex_follows_kawasaki() {
    // Sectors 40°, 70°, 60°, 50°, 80°, 60°: alternate sums 40 + 60 + 80 = 70 + 50 + 60 = 180.
    let sectors = [40.0, 70.0, 60.0, 50.0, 80.0, 60.0];
    let assignments = [M, M, V, M, M, V];
    let mut at = 0.0;
    let spokes: Vec<(f64, Assignment)> = sectors
        .iter()
        .zip(assignments)
        .map(|(s, a)| {
            let spoke = (at, a);
            at += s;
            spoke
        })
        .collect();
    assert!(check(&single_vertex(&spokes), &CheckOptions::default()).passed());
    // Widening one sector by 3° and narrowing the next by 3° breaks it by 3°.
    let mut moved = spokes.clone();
    moved[2].0 += 3.0;
    let report = check(&single_vertex(&moved), &CheckOptions::default());
    let f: Vec<_> = report.of_kind(FindingKind::Kawasaki).collect();
    assert_eq!(f.len(), 1);
    assert!((f[0].value - 3.0).abs() < 1e-9);
}

/// Reads "rotate crease eN about vK by X° (counter-)clockwise" from a Kawasaki hint.
fn parse_rotation(hint: &str) -> Option<(usize, f64)> {
    let words: Vec<&str> = hint.split_whitespace().collect();
    let edge = words.get(2)?.strip_prefix('e')?.parse().ok()?;
    let degrees: f64 = words.get(6)?.strip_suffix('°')?.parse().ok()?;
    let sign = match *words.get(7)? {
        "counter-clockwise" => 1.0,
        "clockwise" => -1.0,
        _ => return None,
    };
    Some((edge, sign * degrees))
}

#[test]
fn following_the_kawasaki_hint_repairs_the_vertex() {
    for (theta, delta) in [(60.0, 1.0), (45.0, -2.5), (70.0, 4.0)] {
        let mut cp = miura(theta, delta);
        let report = check(&cp, &CheckOptions::default());
        let finding = report
            .of_kind(FindingKind::Kawasaki)
            .next()
            .expect("finding");
        let hint = &finding.hint;
        let (edge, degrees) = parse_rotation(hint).expect(hint);
        // The hint also names the option that would pass the vertex as drawn, with its value.
        let option = "--kawasaki-tolerance ";
        let at = hint.find(option).expect(hint) + option.len();
        let value: f64 = hint[at..]
            .split_whitespace()
            .next()
            .unwrap()
            .parse()
            .expect(hint);
        assert!(
            value >= finding.value && value < finding.value + 1e-4 + 1e-12,
            "{hint}"
        );
        let accepted = CheckOptions {
            kawasaki_tolerance_deg: value,
            ..CheckOptions::default()
        };
        assert_eq!(
            check(&cp, &accepted).of_kind(FindingKind::Kawasaki).count(),
            0,
            "{hint}"
        );
        // Rotate the crease's far end about the centre (vertex 0).
        let far = cp.edges[edge].other(VertexId(0));
        let p = cp.vertices[far.index()];
        cp.vertices[far.index()] = DVec2::from_angle(degrees.to_radians()).rotate(p);
        let opts = CheckOptions {
            kawasaki_tolerance_deg: 1e-3,
            ..CheckOptions::default()
        };
        let after = check(&cp, &opts);
        assert_eq!(after.of_kind(FindingKind::Kawasaki).count(), 0, "{hint}");
    }
}

/// `k` sector angles of at least 5° summing to 180°, from positive weights.
fn parts(weights: &[f64]) -> Vec<f64> {
    let free = 180.0 - 5.0 * weights.len() as f64;
    let total: f64 = weights.iter().sum();
    weights.iter().map(|w| 5.0 + free * w / total).collect()
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(64))]

    /// Any vertex whose alternate sectors each sum to 180° passes; rotating one crease by δ
    /// (within its sectors) gives a Kawasaki error of |δ|.
    #[test]
    fn random_flat_vertices_and_their_perturbations(
        even in proptest::collection::vec(1.0f64..100.0, 1..5),
        odd_seed in proptest::collection::vec(1.0f64..100.0, 4),
        pick in 0usize..8,
        frac in -0.9f64..0.9,
    ) {
        let k = even.len();
        let (even, odd) = (parts(&even), parts(&odd_seed[..k]));
        let sectors: Vec<f64> = (0..2 * k).map(|i| if i % 2 == 0 { even[i / 2] } else { odd[i / 2] }).collect();
        let mut at = 0.0;
        let mut spokes = Vec::new();
        for (i, s) in sectors.iter().enumerate() {
            spokes.push((at, if i <= k { M } else { V }));
            at += s;
        }
        let flat = check(&single_vertex(&spokes), &CheckOptions::default());
        proptest::prop_assert!(flat.passed(), "{}", flat.to_text("mm"));

        let j = pick % (2 * k);
        let room = sectors[j].min(sectors[(j + 2 * k - 1) % (2 * k)]) - 1.0;
        let delta = frac * room;
        spokes[j].0 += delta;
        let report = check(&single_vertex(&spokes), &CheckOptions::default());
        let found: Vec<_> = report.of_kind(FindingKind::Kawasaki).collect();
        if delta.abs() > 0.011 {
            proptest::prop_assert_eq!(found.len(), 1);
            proptest::prop_assert!((found[0].value - delta.abs()).abs() < 1e-7);
        } else if delta.abs() < 0.009 {
            proptest::prop_assert!(found.is_empty());
        }
        proptest::prop_assert_eq!(report.of_kind(FindingKind::Maekawa).count(), 0);
    }
}

#[test]
fn a_small_kawasaki_error_is_offered_as_the_drawings_precision() {
    let v = check(&miura(60.0, 0.05), &CheckOptions::default()).verdict();
    assert!(
        v.contains("; if the drawing is only this precise, --kawasaki-tolerance 0.05"),
        "{v}"
    );
}
