//! Perforation layout: vertex clearances keep dashes of neighbouring lines at least
//! `min_web + kerf` apart (degree-8 22.5° centres, Resch-like degree-6 vertices with 60° and
//! 30° sectors, random vertices), dashes are symmetric, start and end with a bridge, fit the
//! crease exactly at the nominal duty cycle, and too-short creases are reported.

use crate::fab_common;

use fab_common::{options, point_segment, polygon, segment_segment};
use foldcam::fab::{Operation, PlanOptions, Toolpath};
use foldcam::fab::{PlanWarningKind, toolpaths_with_warnings};
use foldcam::pattern::{Assignment, CreasePattern};
use glam::DVec2;
use proptest::prelude::*;
use proptest::test_runner::{Config, RngSeed};

/// A vertex at the origin with spokes at the given directions (degrees) to a convex rim of
/// boundary edges at radius `r` through the spoke ends (and through extra rim points so that
/// no rim edge passes near the centre).
fn star(directions_deg: &[f64], r: f64, kind: Assignment) -> CreasePattern {
    let mut rim: Vec<(f64, bool)> = directions_deg.iter().map(|&d| (d, true)).collect();
    for k in 0..12 {
        let fill = 30.0 * k as f64;
        if directions_deg.iter().all(|d| (d - fill).abs() > 1.0) {
            rim.push((fill, false));
        }
    }
    rim.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut cp = CreasePattern::new();
    let ends: Vec<DVec2> = rim
        .iter()
        .map(|(d, _)| DVec2::from_angle(d.to_radians()) * r)
        .collect();
    let rim_vertices = polygon(&mut cp, &ends, Assignment::Boundary);
    let centre = cp.add_vertex(DVec2::ZERO);
    for (v, (_, spoke)) in rim_vertices.into_iter().zip(rim) {
        if spoke {
            cp.add_edge(centre, v, kind);
        }
    }
    cp
}

fn perforations(paths: &[Toolpath]) -> Vec<&Toolpath> {
    paths
        .iter()
        .filter(|p| p.op == Operation::Perforate)
        .collect()
}

/// No two dashes of different creases, and no dash and cut line of the pattern, closer than
/// `min_web + kerf`.
fn assert_webs(cp: &CreasePattern, paths: &[Toolpath], opts: &PlanOptions) {
    let web = opts.perforation.min_web_mm + opts.kerf_mm - 1e-9;
    let perf = perforations(paths);
    for (i, a) in perf.iter().enumerate() {
        for b in &perf[i + 1..] {
            for da in &a.strokes {
                for db in &b.strokes {
                    let d = segment_segment(da[0], da[1], db[0], db[1]);
                    assert!(d >= web, "dashes {da:?} and {db:?} are {d} mm apart");
                }
            }
        }
        for e in cp.edge_ids() {
            if cp.edges[e.index()].assignment.is_boundary_like() {
                let (p, q) = cp.segment(e);
                for d in &a.strokes {
                    let gap = segment_segment(d[0], d[1], p, q);
                    assert!(gap >= web, "dash {d:?} is {gap} mm from cut {e}");
                }
            }
        }
    }
}

/// The crease's two end points: the farthest pair among its edges' vertices.
fn crease_ends(cp: &CreasePattern, path: &Toolpath) -> (DVec2, DVec2) {
    let pts: Vec<DVec2> = path
        .edges
        .iter()
        .flat_map(|&e| {
            let (a, b) = cp.segment(e);
            [a, b]
        })
        .collect();
    let mut best = (pts[0], pts[0]);
    for &p in &pts {
        for &q in &pts {
            if p.distance(q) > best.0.distance(best.1) {
                best = (p, q);
            }
        }
    }
    best
}

/// Layout invariants of one crease: straight 2-point dashes on the crease, in order, equal
/// dashes and bridges at the nominal duty cycle, bridges at both ends, symmetric, exact fit.
fn assert_layout(cp: &CreasePattern, path: &Toolpath, opts: &PlanOptions) {
    let (a, b) = crease_ends(cp, path);
    let length = a.distance(b);
    let dir = (b - a) / length;
    // Parameters along the crease, oriented from `a`.
    let mut spans: Vec<(f64, f64)> = path
        .strokes
        .iter()
        .map(|s| {
            assert_eq!(s.len(), 2);
            assert!(s.iter().all(|p| p.is_finite()));
            for p in s {
                assert!(point_segment(*p, a, b) < 1e-9, "dash point off the crease");
            }
            let (s0, s1) = ((s[0] - a).dot(dir), (s[1] - a).dot(dir));
            (s0.min(s1), s0.max(s1))
        })
        .collect();
    spans.sort_by(|x, y| x.0.total_cmp(&y.0));
    let n = spans.len();
    assert!(n >= 1);
    let start_bridge = spans[0].0;
    let end_bridge = length - spans[n - 1].1;
    let p = &opts.perforation;
    assert!(start_bridge >= p.vertex_clearance_mm.max(p.bridge_mm) - 1e-9);
    assert!(
        (start_bridge - end_bridge).abs() < 1e-9,
        "not symmetric about the middle"
    );
    let mirrored: Vec<(f64, f64)> = spans
        .iter()
        .rev()
        .map(|&(s, t)| (length - t, length - s))
        .collect();
    for (x, y) in spans.iter().zip(&mirrored) {
        assert!((x.0 - y.0).abs() < 1e-9 && (x.1 - y.1).abs() < 1e-9);
    }
    let dash = spans[0].1 - spans[0].0;
    assert!(dash >= opts.perforation.min_dash_mm - 1e-9);
    for s in &spans {
        assert!((s.1 - s.0 - dash).abs() < 1e-9, "unequal dashes");
    }
    if n >= 2 {
        let bridge = spans[1].0 - spans[0].1;
        for w in spans.windows(2) {
            assert!((w[1].0 - w[0].1 - bridge).abs() < 1e-9, "unequal bridges");
        }
        let available = length - start_bridge - end_bridge;
        let total = n as f64 * dash + (n - 1) as f64 * bridge;
        assert!(
            (total - available).abs() < 1e-9,
            "dashes do not fit exactly"
        );
        let nominal = p.cut_mm / (p.cut_mm + p.bridge_mm);
        assert!(
            (dash / (dash + bridge) - nominal).abs() < 1e-9,
            "duty cycle"
        );
    }
}

fn check_vertex(directions_deg: &[f64]) {
    let cp = star(directions_deg, 40.0, Assignment::Mountain);
    let opts = options();
    let (paths, warnings) = toolpaths_with_warnings(&cp, &opts).unwrap();
    assert!(warnings.is_empty(), "{warnings:?}");
    let perf = perforations(&paths);
    assert_eq!(perf.len(), directions_deg.len(), "one toolpath per crease");
    for p in &perf {
        assert_layout(&cp, p, &opts);
    }
    assert_webs(&cp, &paths, &opts);
}

#[test]
fn degree_eight_vertex_with_22_5_degree_sectors() {
    // Eight creases in half a turn, the other half open: the 22.5° sectors are the tight ones.
    let dirs: Vec<f64> = (0..8).map(|k| 22.5 * k as f64).collect();
    check_vertex(&dirs);
    let full: Vec<f64> = (0..8).map(|k| 45.0 * k as f64 + 10.0).collect();
    check_vertex(&full);
}

#[test]
fn waterbomb_centre_sixteen_creases() {
    // A degree-16 centre of 22.5° sectors (a square base folded once more).
    let dirs: Vec<f64> = (0..16).map(|k| 22.5 * k as f64).collect();
    check_vertex(&dirs);
}

#[test]
fn resch_degree_six_vertices() {
    check_vertex(&[0.0, 60.0, 120.0, 180.0, 240.0, 300.0]);
    // The narrow 30° sectors of a Resch triangle tessellation vertex.
    check_vertex(&[0.0, 30.0, 60.0, 150.0, 180.0, 270.0]);
    check_vertex(&[0.0, 30.0, 120.0, 150.0, 240.0, 270.0]);
}

#[test]
fn clearance_grows_as_the_sector_shrinks() {
    let first_dash = |sector: f64| {
        let cp = star(&[0.0, sector, 180.0], 40.0, Assignment::Valley);
        let (paths, _) = toolpaths_with_warnings(&cp, &options()).unwrap();
        perforations(&paths)
            .iter()
            .flat_map(|p| p.strokes.iter().flatten())
            .filter(|p| p.y.abs() < 1e-9 && p.x > 0.0) // the crease along +x
            .map(|p| p.length())
            .fold(f64::INFINITY, f64::min)
    };
    let (wide, narrow) = (first_dash(60.0), first_dash(15.0));
    assert!(narrow > wide + 1.0, "{narrow} vs {wide}");
}

#[test]
fn a_crease_too_short_gets_no_dash_and_a_warning() {
    let mut cp = CreasePattern::new();
    let rim = polygon(
        &mut cp,
        &fab_common::square(0.0, 100.0),
        Assignment::Boundary,
    );
    let _ = rim;
    let a = cp.add_vertex(DVec2::new(50.0, 0.0));
    let b = cp.add_vertex(DVec2::new(50.0, 0.8));
    // Split the bottom side at a so the crease meets the outline.
    cp.edges[0].vertices[1] = a;
    cp.add_edge(a, foldcam::pattern::VertexId(1), Assignment::Boundary);
    let short = cp.add_edge(a, b, Assignment::Valley);
    let (paths, warnings) = toolpaths_with_warnings(&cp, &options()).unwrap();
    assert!(perforations(&paths).is_empty());
    assert_eq!(warnings.len(), 1, "{warnings:?}");
    assert_eq!(warnings[0].kind, PlanWarningKind::CreasesTooShort);
    assert_eq!(warnings[0].edges, [short], "{warnings:?}");
    assert!(
        warnings[0].text.contains(&short.to_string()),
        "{}",
        warnings[0]
    );
}

#[test]
fn drawn_segments_of_one_crease_share_one_layout() {
    // One straight valley drawn as three segments across a square: one crease, one layout.
    let mut cp = CreasePattern::new();
    polygon(
        &mut cp,
        &fab_common::square(0.0, 100.0),
        Assignment::Boundary,
    );
    let xs = [0.0, 20.0, 45.0, 100.0];
    let v: Vec<_> = xs
        .iter()
        .map(|&x| cp.add_vertex(DVec2::new(x, 50.0)))
        .collect();
    for w in v.windows(2) {
        cp.add_edge(w[0], w[1], Assignment::Valley);
    }
    // Put the ends on the outline.
    let mut cp2 = cp.clone();
    foldcam::pattern::planarize(&mut cp2, &Default::default()).expect("planarises");
    let (paths, warnings) = toolpaths_with_warnings(&cp2, &options()).unwrap();
    assert!(warnings.is_empty());
    let perf = perforations(&paths);
    assert_eq!(perf.len(), 1);
    assert_eq!(perf[0].edges.len(), 3);
    assert_layout(&cp2, perf[0], &options());
}

/// A straight crease from `a` to `b` with extra lines (perforated or cut) at both ends.
/// Whether a warning names edge `e` (as a whole word: `e0` but not `e01`).
fn names_edge(warning: &str, e: &str) -> bool {
    warning
        .split(|c: char| !c.is_ascii_alphanumeric())
        .any(|word| word == e)
}

fn random_vertex_pattern(length: f64, ends: [&[(f64, f64, bool)]; 2]) -> CreasePattern {
    let mut cp = CreasePattern::new();
    let a = cp.add_vertex(DVec2::ZERO);
    let b = cp.add_vertex(DVec2::new(length, 0.0));
    cp.add_edge(a, b, Assignment::Mountain);
    for (end, lines) in [(a, ends[0]), (b, ends[1])] {
        let base = if end == a { 0.0 } else { 180.0 };
        for &(angle, frac, cut) in lines {
            let p = cp.position(end)
                + DVec2::from_angle((base + angle).to_radians()) * frac * length / 3.0;
            let q = cp.add_vertex(p);
            let kind = if cut {
                Assignment::Cut
            } else {
                Assignment::Valley
            };
            cp.add_edge(end, q, kind);
        }
    }
    cp
}

/// Up to four extra lines at distinct angles at least 2° apart and from the crease.
fn end_lines() -> impl Strategy<Value = Vec<(f64, f64, bool)>> {
    prop::collection::vec((2.0f64..358.0, 0.2f64..1.0, any::<bool>()), 0..4).prop_map(|mut v| {
        v.sort_by(|x, y| x.0.total_cmp(&y.0));
        v.dedup_by(|x, y| (x.0 - y.0).abs() < 2.0);
        v
    })
}

proptest! {
    #![proptest_config(Config { cases: 200, rng_seed: RngSeed::Fixed(0x05ee_dfab), ..Config::default() })]

    #[test]
    fn random_creases_keep_their_invariants(
        length in 0.1f64..200.0,
        start in end_lines(),
        end in end_lines(),
    ) {
        let cp = random_vertex_pattern(length, [&start, &end]);
        let opts = options();
        let (paths, warnings) = toolpaths_with_warnings(&cp, &opts).unwrap();
        for p in &paths {
            prop_assert!(p.strokes.iter().flatten().all(|q| q.is_finite()));
        }
        let main = perforations(&paths)
            .into_iter()
            .find(|p| p.edges == vec![foldcam::pattern::EdgeId(0)]);
        match main {
            Some(p) => assert_layout(&cp, p, &opts),
            None => prop_assert!(warnings
                .iter()
                .any(|w| w.edges.contains(&foldcam::pattern::EdgeId(0)) && names_edge(&w.text, "e0"))),
        }
        for p in perforations(&paths) {
            assert_layout(&cp, p, &opts);
        }
        assert_webs(&cp, &paths, &opts);
    }
}

/// The operation each burn of a simulated run belongs to: the last operation comment before
/// its line.
fn burn_operations(run: &foldcam::sim::SimReport) -> Vec<Option<Operation>> {
    run.burns
        .iter()
        .map(|b| {
            run.operations
                .iter()
                .take_while(|o| o.line <= b.line)
                .last()
                .map(|o| o.operation)
        })
        .collect()
}

#[test]
fn the_metal_left_at_every_vertex_is_the_clearance_asked() {
    // Read back from the G-code: on 0.5 mm stainless (kerf 0.08 mm) every perforation burn,
    // widened by half the kerf on every side, stays the vertex clearance away from every
    // vertex of the pattern (each vertex of these patterns is a real vertex: a crease end).
    use foldcam::job::{Job, JobFormat};
    use foldcam::machine::{load_machine, load_material};
    let machine = load_machine("linuxcnc-fiber").unwrap();
    let material = load_material("stainless-0.5").unwrap();
    let examples = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/patterns");
    let mut bird = foldcam::formats::load(&examples.join("bird-base.cp"))
        .unwrap()
        .pattern;
    foldcam::pattern::planarize(&mut bird, &Default::default()).unwrap();
    bird.scale_to(foldcam::pattern::Scale::Size(150.0)).unwrap();
    let patterns = [
        (
            "miura",
            foldcam::design::classic::MiuraOri::default()
                .build()
                .unwrap(),
        ),
        (
            "waterbomb",
            foldcam::design::classic::Waterbomb::default()
                .build()
                .unwrap(),
        ),
        ("bird base", bird),
    ];
    for clearance in [None, Some(0.4), Some(3.0)] {
        let overrides = foldcam::fab::PlanOverrides {
            vertex_clearance_mm: clearance,
            ..Default::default()
        };
        for (name, cp) in &patterns {
            let job = Job::plan(cp, &machine, &material, &overrides)
                .and_then(|j| j.post(JobFormat::Gcode))
                .and_then(|j| j.verify())
                .unwrap_or_else(|e| panic!("{name}: {e}"));
            let asked = clearance.unwrap_or(material.perforation.vertex_clearance_mm);
            let half_kerf = material.kerf_mm / 2.0;
            let mut nearest = f64::INFINITY;
            for (plan_job, read) in job.plan.jobs.iter().zip(&job.readback) {
                let ops = burn_operations(&read.sim);
                let dashes: Vec<_> = read
                    .sim
                    .burns
                    .iter()
                    .zip(&ops)
                    .filter(|(_, op)| **op == Some(Operation::Perforate))
                    .map(|(b, _)| (b.from, b.to))
                    .collect();
                assert!(!dashes.is_empty(), "{name}: no perforation read back");
                for v in cp.vertex_ids() {
                    let at = plan_job.to_machine.transform_point2(cp.position(v));
                    for &(a, b) in &dashes {
                        let metal = point_segment(at, a, b) - half_kerf;
                        nearest = nearest.min(metal);
                        // Within the G-code's 0.001 mm coordinates.
                        assert!(
                            metal >= asked - 1e-3,
                            "{name}: {metal:.4} mm of metal at {v} (asked {asked} mm)"
                        );
                    }
                }
            }
            assert!(nearest.is_finite(), "{name}: no dash near any vertex");
        }
    }
}

#[test]
fn facet_lines_alone_are_said_to_be_skipped() {
    use foldcam::machine::{load_machine, load_material};
    let machine = load_machine("linuxcnc-fiber").unwrap();
    let material = load_material("stainless-0.5").unwrap();
    let options =
        PlanOptions::for_machine(&machine, &material, &foldcam::fab::PlanOverrides::default())
            .unwrap();
    // An outline triangulated by facet lines only: the outline is cut, and the plan says that
    // nothing else is machined.
    let mut cp = CreasePattern::new();
    let rim = polygon(
        &mut cp,
        &fab_common::square(0.0, 50.0),
        Assignment::Boundary,
    );
    cp.add_edge(rim[0], rim[2], Assignment::Flat);
    let p = foldcam::fab::plan(&cp, &machine, &material, &options).unwrap();
    assert_eq!(p.stats.perforated_share(), None);
    assert!(
        p.warnings
            .iter()
            .any(|w| w.kind == PlanWarningKind::FacetsOnly
                && w.text.contains("no creases, only 1 facet")),
        "{:?}",
        p.warnings
    );
    // Facet lines without an outline: nothing to do, and the error says which options help.
    let mut bare = CreasePattern::new();
    let a = bare.add_vertex(DVec2::ZERO);
    let b = bare.add_vertex(DVec2::new(10.0, 10.0));
    bare.add_edge(a, b, Assignment::Flat);
    let e = foldcam::fab::plan(&bare, &machine, &material, &options).unwrap_err();
    assert!(e.to_string().contains("--flat"), "{e}");
}

#[test]
fn a_polyline_crease_that_doubles_back_ends_at_its_hairpin() {
    // A valley drawn as a hairpin (out along x, back at 10° below it): the turn at the tip is
    // far beyond a curve's, so the tip is a real vertex, both legs keep their clearances there,
    // and their dashes stay a web apart.
    let mut cp = CreasePattern::new();
    polygon(
        &mut cp,
        &fab_common::square(-10.0, 110.0),
        Assignment::Boundary,
    );
    let a = cp.add_vertex(DVec2::new(0.0, 50.0));
    let tip = cp.add_vertex(DVec2::new(100.0, 50.0));
    let back = DVec2::new(100.0, 50.0) - DVec2::from_angle(10f64.to_radians()) * 100.0;
    let c = cp.add_vertex(back);
    cp.add_edge(a, tip, Assignment::Valley);
    cp.add_edge(tip, c, Assignment::Valley);
    let opts = options();
    let (paths, _) = toolpaths_with_warnings(&cp, &opts).unwrap();
    let perf = perforations(&paths);
    assert_eq!(perf.len(), 2, "one crease per leg");
    assert_webs(&cp, &paths, &opts);
    for p in &perf {
        for q in p.strokes.iter().flatten() {
            assert!(q.distance(DVec2::new(100.0, 50.0)) >= opts.perforation.vertex_clearance_mm);
        }
    }
}
