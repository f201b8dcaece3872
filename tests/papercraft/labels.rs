//! Edge labels: matching on both parts of every shared cut line, inside their parts, and
//! marked by the machine when the material marks flat lines.

use foldcam::design::papercraft::design::Made;
use foldcam::design::papercraft::labels::frames_overlap;
use foldcam::fab::{Operation, PlanOptions, plan};
use foldcam::geom::polygon::contains_point;
use foldcam::geom::segment::{Crossing, intersect};
use foldcam::machine::{load_machine, load_material};
use foldcam::pattern::Assignment;
use foldcam::{post, sim};

use crate::support::build_example;

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
    check_labels("fish", &build_example("fish"), 18);
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
    let mut options = PlanOptions::from_material(&material);
    options.mapping.flat = Some(Operation::Mark);
    options.adapt_to_machine(&machine).unwrap();
    let cp = &made.sheets[0];
    let p = plan(cp, &machine, &material, &options).unwrap();
    for job in &p.jobs {
        let run = sim::run(&post::gcode(&p, job, &machine).unwrap(), &machine).unwrap();
        assert!(run.is_clean(), "{:?}", run.violations.first());
        let cov = sim::coverage(&run, cp, job, &p);
        assert!(cov.passed(), "{:?}", cov.failed_edges().next());
    }
}
