//! Edge labels: matching on both parts of every shared cut line, inside their parts, and
//! marked by the machine when the material marks flat lines.

use foldcam::design::papercraft::Made;
use foldcam::design::papercraft::{baseline, frames_overlap, make_upright, reads_upright};
use foldcam::fab::{Operation, PlanOptions, plan};
use foldcam::geom::contains_point;
use foldcam::geom::{Crossing, intersect};
use foldcam::machine::{load_machine, load_material};
use foldcam::pattern::Assignment;
use foldcam::{post, sim};
use glam::DVec2;

use super::support::build_example;

fn check_labels(name: &str, made: &Made, shared: usize) {
    let mut labelled = 0;
    for e in 0..shared {
        let on: Vec<(usize, &str)> = made
            .parts
            .iter()
            .flat_map(|p| {
                p.labels
                    .iter()
                    .filter(move |l| l.line == e)
                    .map(move |l| (p.patch, l.text.as_str()))
            })
            .collect();
        if made.unlabelled.contains(&e) {
            assert!(on.is_empty(), "{name}: cut line {e} half labelled");
            continue;
        }
        labelled += 1;
        assert_eq!(on.len(), 2, "{name}: cut line {e}: {on:?}");
        assert_ne!(
            on[0].0, on[1].0,
            "{name}: cut line {e} labelled twice on one part"
        );
        assert!(
            on.iter().all(|&(_, t)| t == e.to_string()),
            "{name}: {on:?}"
        );
    }
    assert!(
        labelled * 2 > shared,
        "{name}: only {labelled} of {shared} labelled"
    );
    for part in &made.parts {
        let n = part.outline.len();
        for (k, l) in part.labels.iter().enumerate() {
            assert!(!l.strokes.is_empty());
            for &[a, b] in &l.strokes {
                assert!(contains_point(&part.outline, a) && contains_point(&part.outline, b));
                for i in 0..n {
                    let (p, q) = (part.outline[i], part.outline[(i + 1) % n]);
                    assert_eq!(intersect(a, b, p, q, 1e-12), Crossing::None, "{name}");
                }
            }
            for other in &part.labels[k + 1..] {
                assert!(
                    !frames_overlap(&l.frame, &other.frame),
                    "{name}: labels overlap"
                );
            }
        }
    }
}

#[test]
fn every_shared_cut_line_is_labelled_alike_on_both_parts_inside_them() {
    // Vase: 8 meridians shared (foot and rim arcs are free). Fish: 18 cut lines, all shared.
    let vase = build_example("vase_auto");
    check_labels("vase", &vase, 8);
    assert!(vase.unlabelled.is_empty(), "{:?}", vase.unlabelled);
    let fish = build_example("fish");
    check_labels("fish", &fish, 18);
    assert!(fish.unlabelled.is_empty(), "{:?}", fish.unlabelled);
}

#[test]
fn labels_are_flat_lines_the_machine_marks_when_asked() {
    let made = build_example("vase_auto");
    let strokes: usize = made
        .parts
        .iter()
        .flat_map(|p| &p.labels)
        .map(|l| l.strokes.len())
        .sum();
    let flats: usize = made
        .sheets
        .iter()
        .map(|cp| {
            cp.edges
                .iter()
                .filter(|e| e.assignment == Assignment::Flat)
                .count()
        })
        .sum();
    assert_eq!(flats, strokes);
    let machine = load_machine("grbl-diode").unwrap();
    let material = load_material("paper-160gsm").unwrap();
    let overrides = foldcam::fab::PlanOverrides {
        flat: Some(Some(Operation::Mark)),
        ..Default::default()
    };
    let options = PlanOptions::for_machine(&machine, &material, &overrides).unwrap();
    let cp = &made.sheets[0];
    let p = plan(cp, &machine, &material, &options).unwrap();
    for job in &p.jobs {
        let run = sim::run(&post::gcode(&p, job, &machine).unwrap(), &machine).unwrap();
        assert!(run.is_clean(), "{:?}", run.violations.first());
        let cov = sim::coverage(&run, cp, job, &p);
        assert!(cov.passed(), "{:?}", cov.failed_edges().next());
    }
}

#[test]
fn every_label_reads_upright_on_its_sheet() {
    for name in ["vase", "vase_auto", "fish"] {
        let made = build_example(name);
        let mut multi = 0;
        for pl in &made.placements {
            for l in &made.parts[pl.part].labels {
                let on_sheet = |p: DVec2| pl.apply(p);
                let base = (on_sheet(l.frame[1]) - on_sheet(l.frame[0])).normalize();
                // The baseline's angle on the sheet lies in (−90°, 90°].
                assert!(
                    reads_upright(base) && base.x > -1e-12,
                    "{name}: label {} on part {} reads along {base}",
                    l.text,
                    pl.part
                );
                // Not mirrored: the frame's second side goes up, to the baseline's left.
                let side = on_sheet(l.frame[3]) - on_sheet(l.frame[0]);
                assert!(
                    base.perp_dot(side) > 0.0,
                    "{name}: label {} mirrored",
                    l.text
                );
                // Digits in reading order: the first stroke (first digit) lies before the
                // last stroke (last digit) along the baseline.
                if l.text.len() > 1 {
                    multi += 1;
                    let mid = |s: &[DVec2; 2]| on_sheet(0.5 * (s[0] + s[1])).dot(base);
                    let (first, last) = (&l.strokes[0], &l.strokes[l.strokes.len() - 1]);
                    assert!(mid(first) < mid(last), "{name}: label {} reversed", l.text);
                }
            }
        }
        assert!(multi > 0 || name.starts_with("vase"), "{name}");
    }
}

#[test]
fn a_label_turned_upside_down_is_turned_back_in_place() {
    let made = build_example("vase");
    let mut part = made.parts[0].clone();
    let before = part.labels.clone();
    assert!(!before.is_empty());
    // Placed as built, then at a half turn more: the labels turn about their centres.
    let angle = made.placements[0].angle + std::f64::consts::PI;
    make_upright(&mut part, angle);
    let rot = DVec2::from_angle(angle);
    for (a, b) in before.iter().zip(&part.labels) {
        assert!(reads_upright(rot.rotate(baseline(b))));
        let centre = |l: &foldcam::design::papercraft::Label| 0.25 * l.frame.iter().sum::<DVec2>();
        assert!(centre(a).distance(centre(b)) < 1e-9);
        assert!(
            (baseline(a) + baseline(b)).length() < 1e-9,
            "turned by a half turn"
        );
        assert_eq!(a.strokes.len(), b.strokes.len());
    }
}

#[test]
fn every_shared_cut_line_of_the_examples_is_labelled() {
    // The fish's tail chords are about 5 mm long: their labels shrink (down to 0.35 of the
    // label height) and move along the side until they fit on both parts.
    for name in ["vase", "vase_auto", "fish"] {
        let made = build_example(name);
        assert!(made.unlabelled.is_empty(), "{name}: {:?}", made.unlabelled);
    }
}
