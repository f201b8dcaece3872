//! Curved creases are perforated along the curve: a drawn curve flattened into many short
//! edges is one crease, with vertex clearances only where other lines meet it. Checked on a
//! generated concentric-circles pleat (closed curves) and on Origami Simulator's
//! `HexSpiralTess.svg` (curves between junctions), on 0.5 mm stainless and on card; and the
//! simulated machine reports a curve whose burns are missing.

use std::f64::consts::TAU;
use std::path::{Path, PathBuf};

use foldcam::fab::{FabPlan, Operation, PlanOptions, Toolpath, plan};
use foldcam::machine::{MachineProfile, Material, load_machine, load_material};
use foldcam::pattern::{Assignment, CreasePattern, EdgeId, PlanarizeOptions, planarize};
use foldcam::{post, sim};
use glam::DVec2;

/// Chords per circle: turns of 360°/96 = 3.75° at each point, a flattened curve.
const CHORDS: usize = 96;

/// A 200 mm square sheet with `rings` concentric circles about its centre, 12 mm apart from
/// r = 12 mm, alternately mountain and valley; returns the pattern and each circle's edges.
fn concentric_pleat(rings: usize) -> (CreasePattern, Vec<Vec<EdgeId>>) {
    let mut cp = CreasePattern::new();
    let c = DVec2::splat(100.0);
    let corners = [(0.0, 0.0), (200.0, 0.0), (200.0, 200.0), (0.0, 200.0)];
    for i in 0..4 {
        let (a, b) = (corners[i], corners[(i + 1) % 4]);
        cp.add_segment(
            DVec2::new(a.0, a.1),
            DVec2::new(b.0, b.1),
            Assignment::Boundary,
        );
    }
    let mut circles = Vec::new();
    for k in 0..rings {
        let r = 12.0 * (k + 1) as f64;
        let kind = if k % 2 == 0 {
            Assignment::Mountain
        } else {
            Assignment::Valley
        };
        let v: Vec<_> = (0..CHORDS)
            .map(|i| cp.add_vertex(c + DVec2::from_angle(TAU * i as f64 / CHORDS as f64) * r))
            .collect();
        let edges = (0..CHORDS)
            .map(|i| cp.add_edge(v[i], v[(i + 1) % CHORDS], kind))
            .collect();
        circles.push(edges);
    }
    (cp, circles)
}

/// The machine, material and options: stainless as shipped on the fiber laser; card on the
/// diode laser with every crease perforated instead of scored.
fn setup(material: &str) -> (MachineProfile, Material, PlanOptions) {
    let machine_name = if material.starts_with("stainless") {
        "linuxcnc-fiber"
    } else {
        "grbl-diode"
    };
    let machine = load_machine(machine_name).unwrap();
    let material = load_material(material).unwrap();
    let overrides = foldcam::fab::PlanOverrides {
        mountain: Some(Some(Operation::Perforate)),
        valley: Some(Some(Operation::Perforate)),
        ..Default::default()
    };
    let options = PlanOptions::for_machine(&machine, &material, &overrides).unwrap();
    (machine, material, options)
}

fn stroke_length(tp: &Toolpath) -> f64 {
    tp.strokes
        .iter()
        .flat_map(|s| s.windows(2).map(|w| w[0].distance(w[1])))
        .sum()
}

/// The nominal duty cycle: cut / (cut + bridge) of the material.
/// The toolpath's cut share: the beam burns half a kerf past both ends of each toolpath dash,
/// so with kerf compensation the toolpath dash is one kerf shorter than the dash the material
/// gets (at least a tenth of it), the period unchanged.
fn duty(options: &PlanOptions) -> f64 {
    let p = &options.perforation;
    let kerf = if options.kerf_offset {
        options.kerf_mm.min(0.9 * p.cut_mm)
    } else {
        0.0
    };
    (p.cut_mm - kerf) / (p.cut_mm + p.bridge_mm)
}

fn perforated_mm(p: &FabPlan) -> f64 {
    p.jobs
        .iter()
        .flat_map(|j| &j.paths)
        .filter(|t| t.op == Operation::Perforate)
        .map(stroke_length)
        .sum()
}

#[test]
fn concentric_circles_are_perforated_all_round() {
    for material in ["stainless-0.5", "card-300gsm"] {
        let (cp, circles) = concentric_pleat(7);
        let (machine, material, options) = setup(material);
        let p = plan(&cp, &machine, &material, &options).unwrap();
        let name = &material.name;
        let job = &p.jobs[0];
        let centre = job.to_machine.transform_point2(DVec2::splat(100.0));
        for (k, edges) in circles.iter().enumerate() {
            let r = 12.0 * (k + 1) as f64;
            // One toolpath realises the whole circle.
            let paths: Vec<&Toolpath> = job
                .paths
                .iter()
                .filter(|t| t.edges.iter().any(|e| edges.contains(e)))
                .collect();
            assert_eq!(
                paths.len(),
                1,
                "{name}: circle {k} in {} toolpaths",
                paths.len()
            );
            let tp = paths[0];
            assert_eq!(tp.edges.len(), CHORDS, "{name}: circle {k}");
            // Every dash point on the circle (between the chord and the arc: the sagitta).
            let sagitta = r * (1.0 - (std::f64::consts::PI / CHORDS as f64).cos());
            for q in tp.strokes.iter().flatten() {
                let d = q.distance(centre);
                assert!(
                    d <= r + 1e-6 && d >= r - sagitta - 1e-6,
                    "{name}: {q} is {d} mm out"
                );
            }
            // The chain's length is the polygon's perimeter; a closed crease has no end
            // clearance, so it is cut at exactly the nominal duty all round.
            let perimeter = CHORDS as f64 * 2.0 * r * (std::f64::consts::PI / CHORDS as f64).sin();
            let cut = stroke_length(tp);
            assert!(
                (cut / perimeter - duty(&options)).abs() < 1e-9,
                "{name}: circle {k} cut {cut} of {perimeter} mm"
            );
        }
    }
}

/// Plans, posts and runs every job; returns the coverage reports.
fn run_jobs(cp: &CreasePattern, p: &FabPlan, machine: &MachineProfile) -> Vec<sim::CoverageReport> {
    p.jobs
        .iter()
        .map(|job| {
            let gcode = post::gcode(p, job, machine).unwrap();
            let run = sim::run(&gcode, machine).unwrap();
            assert!(run.is_clean(), "{:?}", run.violations.first());
            sim::coverage(&run, cp, job, p)
        })
        .collect()
}

#[test]
fn simulate_counts_an_uncovered_curve_as_uncovered() {
    let (cp, circles) = concentric_pleat(4);
    let (machine, material, options) = setup("stainless-0.5");
    let mut p = plan(&cp, &machine, &material, &options).unwrap();
    assert!(run_jobs(&cp, &p, &machine).iter().all(|c| c.passed()));
    // Drop the toolpath of circle 2 from the job, as a planner that skipped the curve would:
    // the G-code no longer burns it, and coverage must say so for every one of its edges.
    let gone = &circles[2];
    p.jobs[0]
        .paths
        .retain(|t| !t.edges.iter().any(|e| gone.contains(e)));
    let cov = run_jobs(&cp, &p, &machine).remove(0);
    assert!(!cov.passed());
    let mut missing: Vec<EdgeId> = cov.left_out().map(|e| e.edge).collect();
    missing.sort();
    let mut expected = gone.clone();
    expected.sort();
    assert_eq!(missing, expected);
    assert!(cov.left_out().all(|e| e.burned == 0.0 && !e.ok));
    // Every other edge is still covered as planned.
    assert_eq!(cov.failed_edges().count(), gone.len());
}

/// A two-sided plan (mountains from the front, valleys from the back): a circle of each kind
/// dropped from its job is reported once over the plan, by the job of its own side, and the
/// burned share measured there (in that job's mirrored machine frame) is zero.
#[test]
fn a_two_sided_plan_reports_each_left_out_edge_once() {
    let (cp, circles) = concentric_pleat(4);
    let (machine, material, mut options) = setup("stainless-0.5");
    options.two_sided = true;
    let mut p = plan(&cp, &machine, &material, &options).unwrap();
    assert_eq!(p.jobs.len(), 2);
    assert!(run_jobs(&cp, &p, &machine).iter().all(|c| c.passed()));
    // Circle 0 is a mountain (front), circle 1 a valley (back): drop both toolpaths.
    let (mountain, valley) = (&circles[0], &circles[1]);
    for job in &mut p.jobs {
        job.paths.retain(|t| {
            !t.edges
                .iter()
                .any(|e| mountain.contains(e) || valley.contains(e))
        });
    }
    let reports = run_jobs(&cp, &p, &machine);
    let mut listed: Vec<EdgeId> = reports
        .iter()
        .flat_map(|c| c.left_out().map(|e| e.edge))
        .collect();
    listed.sort();
    let mut expected: Vec<EdgeId> = mountain.iter().chain(valley).copied().collect();
    expected.sort();
    // Each dropped edge exactly once over the two jobs (before: once per job, twice).
    assert_eq!(listed, expected);
    let side_of = |c: &sim::CoverageReport| -> Vec<EdgeId> {
        let mut v: Vec<EdgeId> = c.left_out().map(|e| e.edge).collect();
        v.sort();
        v
    };
    let (mut m, mut v) = (mountain.clone(), valley.clone());
    m.sort();
    v.sort();
    let front = p.jobs.iter().position(|j| j.name == "front").unwrap();
    let back = p.jobs.iter().position(|j| j.name == "back").unwrap();
    assert_eq!(side_of(&reports[front]), m);
    assert_eq!(side_of(&reports[back]), v);
    assert!(
        reports
            .iter()
            .flat_map(|c| c.left_out())
            .all(|e| e.burned == 0.0 && !e.ok)
    );
    // Everything else still passes, on both sides.
    for c in &reports {
        assert_eq!(c.failed_edges().count(), c.left_out().count());
    }
}

/// The number of creases the plan's one warning about creases too short for a dash counts
/// ("12 creases (…) too short …", "1 crease (…) too short …"), 0 without that warning.
fn too_short_count(warnings: &[foldcam::fab::PlanWarning]) -> usize {
    let lines: Vec<&str> = warnings
        .iter()
        .filter(|w| w.kind == foldcam::fab::PlanWarningKind::CreasesTooShort)
        .map(|w| w.text.as_str())
        .collect();
    assert!(
        lines.len() <= 1,
        "one warning for all short creases: {lines:?}"
    );
    lines.first().map_or(0, |w| {
        w.split_whitespace()
            .next()
            .and_then(|n| n.parse().ok())
            .unwrap_or_else(|| panic!("no count in {w}"))
    })
}

/// The pleat of [`concentric_pleat`] with Origami Simulator's facet lines: every vertex of a
/// circle joined by flat (F) lines to two vertices of the next circle out, so that the rings
/// between the circles are triangulated as that tool draws its curved-crease files.
fn faceted_pleat(rings: usize) -> (CreasePattern, Vec<Vec<EdgeId>>) {
    let (mut cp, circles) = concentric_pleat(rings);
    for k in 0..rings - 1 {
        let inner: Vec<_> = circles[k]
            .iter()
            .map(|&e| cp.edges[e.index()].vertices[0])
            .collect();
        let outer: Vec<_> = circles[k + 1]
            .iter()
            .map(|&e| cp.edges[e.index()].vertices[0])
            .collect();
        for i in 0..CHORDS {
            cp.add_edge(inner[i], outer[i], Assignment::Flat);
            cp.add_edge(inner[i], outer[(i + 1) % CHORDS], Assignment::Flat);
        }
    }
    (cp, circles)
}

/// The perforation strokes of each circle's toolpath, in machine coordinates.
fn circle_strokes(p: &FabPlan, circles: &[Vec<EdgeId>]) -> Vec<Vec<Vec<DVec2>>> {
    circles
        .iter()
        .map(|edges| {
            let paths: Vec<&Toolpath> = p.jobs[0]
                .paths
                .iter()
                .filter(|t| {
                    t.op == Operation::Perforate && t.edges.iter().any(|e| edges.contains(e))
                })
                .collect();
            assert_eq!(paths.len(), 1, "one crease per circle");
            paths[0].strokes.clone()
        })
        .collect()
}

#[test]
fn facet_lines_neither_split_a_curve_nor_add_clearance() {
    // Origami Simulator draws curved creases between triangulated facets: F lines meet the
    // curve at every point. Skipped (stainless maps F to nothing) or only marked, they leave
    // the material whole, so the plan must be the one without them: every circle one closed
    // crease dashed all round at the nominal duty, dash for dash.
    let rings = 6;
    let (plain, _) = concentric_pleat(rings);
    let (faceted, circles) = faceted_pleat(rings);
    let (machine, material, options) = setup("stainless-0.5");
    let expected = circle_strokes(
        &plan(&plain, &machine, &material, &options).unwrap(),
        &circles,
    );
    let skipped = plan(&faceted, &machine, &material, &options).unwrap();
    assert_eq!(circle_strokes(&skipped, &circles), expected);
    let mut marked_options = options.clone();
    marked_options.mapping.flat = Some(Operation::Mark);
    let marked = plan(&faceted, &machine, &material, &marked_options).unwrap();
    assert_eq!(circle_strokes(&marked, &circles), expected);
    let marks = marked.jobs[0]
        .paths
        .iter()
        .filter(|t| t.op == Operation::Mark)
        .count();
    assert!(marks > 0, "the facet lines are marked");
    // The share the plan reports: the dashes over the crease length, the nominal duty.
    let share = skipped.stats.perforated_share().unwrap();
    assert!((share - duty(&options)).abs() < 1e-9, "{share}");
    for cov in run_jobs(&faceted, &skipped, &machine) {
        assert!(cov.passed(), "{:?}", cov.failed_edges().next());
    }
}

#[test]
fn a_scored_line_still_ends_a_crease() {
    // Lines that weaken the sheet are real vertices: scored in place of skipped, the facet
    // lines cut every circle into pieces with clearances at both ends.
    let (faceted, circles) = faceted_pleat(3);
    let (machine, material, mut options) = setup("stainless-0.5");
    options.mapping.flat = Some(Operation::Score);
    let p = plan(&faceted, &machine, &material, &options).unwrap();
    // Every point of the middle circle meets scored lines: each chord is a crease of its own,
    // 1.6 mm long, too short for a dash after its clearances, and the plan says so.
    let longest_piece = p.jobs[0]
        .paths
        .iter()
        .filter(|t| t.op == Operation::Perforate)
        .map(|t| t.edges.iter().filter(|e| circles[1].contains(e)).count())
        .max()
        .unwrap_or(0);
    assert!(longest_piece <= 1, "{longest_piece} chords in one crease");
    assert!(too_short_count(&p.warnings) >= CHORDS, "{:?}", p.warnings);
}

/// The pattern of `path`, read and planarised as `foldcam plan` does.
fn load(path: &Path) -> CreasePattern {
    let mut cp = foldcam::formats::load(path).unwrap().pattern;
    planarize(&mut cp, &PlanarizeOptions::default()).unwrap();
    cp
}

#[test]
fn hex_spiral_curves_are_perforated_on_stainless_and_card() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/HexSpiralTess.svg");
    let cp = load(&path);
    let crease_mm: f64 = cp
        .edge_ids()
        .filter(|&e| cp.edges[e.index()].assignment.is_fold())
        .map(|e| {
            let (a, b) = cp.segment(e);
            a.distance(b)
        })
        .sum();
    for material in ["stainless-0.5", "card-300gsm"] {
        let (machine, material, options) = setup(material);
        let p = plan(&cp, &machine, &material, &options).unwrap();
        let name = &material.name;
        // Dashes at the nominal duty over nearly the whole crease length: only the vertex
        // clearances at the junctions are left uncut (each curve runs ~10-20 mm between them).
        let perforated = perforated_mm(&p);
        let share = perforated / (duty(&options) * crease_mm);
        assert!(
            share > 0.9 && share <= 1.0,
            "{name}: {perforated} of {crease_mm} mm, {share}"
        );
        // The simulated machine agrees; what it reports as left out are only the stubs of a
        // fraction of a millimetre where two line ends of the drawing almost meet.
        for cov in run_jobs(&cp, &p, &machine) {
            assert!(cov.stray.is_empty(), "{name}: {:?}", cov.stray.first());
            let wrong: Vec<_> = cov.failed_edges().filter(|e| e.in_plan).collect();
            assert!(wrong.is_empty(), "{name}: {:?}", wrong.first());
            let left: f64 = cov.left_out().map(|e| e.length_mm).sum();
            assert!(left < 1e-3 * crease_mm, "{name}: {left} mm left out");
            // Each edge left out is a crease too short for one dash between its vertex
            // clearances, and the planner said so, with their number.
            let too_short = too_short_count(&p.warnings);
            assert!(
                cov.left_out().count() <= too_short,
                "{name}: {:?}",
                p.warnings
            );
            let limit = 2.0 * options.toolpath_perforation().vertex_clearance_mm.max(0.5)
                + options.perforation.min_dash_mm;
            let long: Vec<f64> = cov
                .left_out()
                .map(|e| e.length_mm)
                .filter(|l| *l >= limit)
                .collect();
            assert!(
                long.is_empty(),
                "{name}: left out although longer than {limit} mm: {long:?}"
            );
        }
    }
}

/// The crease patterns of `../shared/testdata/svg` (Origami Simulator's files), each sized to
/// 200 mm as `foldcam plan --size 200` does.
fn shared_svgs() -> Vec<(String, CreasePattern)> {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../shared/testdata/svg");
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "svg"))
        .collect();
    files.sort();
    assert!(files.len() >= 20, "{} files", files.len());
    files
        .into_iter()
        .map(|path| {
            let mut cp = load(&path);
            cp.scale_to(foldcam::pattern::Scale::Size(200.0)).unwrap();
            (path.file_name().unwrap().to_string_lossy().into_owned(), cp)
        })
        .collect()
}

/// Files of `../shared/testdata/svg` whose creases are too short at 200 mm for 0.5 mm
/// stainless's rules: the auxetic kirigami's hinges are about 4 mm long, the pop-up house's
/// roof steps 1 to 10 mm, and every crease end keeps 1.5 mm of metal (plus half the kerf)
/// and a bridge, so no layout can cut 55% of them there. Drawn at 400 mm they pass.
const SHORT_HINGES: [&str; 2] = ["auxetic_triangle.svg", "housePopup.svg"];

#[test]
#[ignore = "needs ../shared"]
fn every_shared_svg_is_perforated_along_most_of_its_creases_on_stainless() {
    // Origami Simulator's files, facet lines and curves included: on the fiber laser and 0.5 mm
    // stainless at 200 mm, at least 55% of every file's crease length is cut by dashes (the
    // nominal duty is 75%; vertex clearances take the rest), the simulated machine burns what
    // was planned, and any crease left uncut is counted in the plan's warning.
    let (machine, material, options) = setup("stainless-0.5");
    let mut checked = 0;
    for (name, mut cp) in shared_svgs() {
        let short = SHORT_HINGES.contains(&name.as_str());
        if short {
            cp.scale_to(foldcam::pattern::Scale::Size(400.0)).unwrap();
        }
        let p = match plan(&cp, &machine, &material, &options) {
            Ok(p) => p,
            Err(e) => panic!("{name}: {e}"),
        };
        let Some(share) = p.stats.perforated_share() else {
            // No crease at all (nothing to perforate): only a cut outline.
            continue;
        };
        assert!(share >= 0.55, "{name}: {:.1}% perforated", 100.0 * share);
        for cov in run_jobs(&cp, &p, &machine) {
            assert!(cov.stray.is_empty(), "{name}: {:?}", cov.stray.first());
            assert!(
                cov.left_out().count() <= too_short_count(&p.warnings),
                "{name}: {:?}",
                p.warnings
            );
        }
        checked += 1;
    }
    assert!(checked >= 20, "only {checked} files with creases");
}
