//! SVG writer: well-formed XML, one Inkscape layer per operation, millimetre page, y flipped
//! back, perforation dashes as separate paths or one dashed path.

use crate::post_common;

use foldcam::fab::{FabPlan, Operation};
use foldcam::machine::Bed;
use foldcam::post::{PostError, layer_style, svg};
use glam::{DVec2, dvec2};
use post_common::{dashes, job, machine, plan, toolpath};
use usvg::roxmltree::{Document, Node};

const INKSCAPE: &str = "http://www.inkscape.org/namespaces/inkscape";

fn bed() -> Bed {
    machine(foldcam::machine::Dialect::Grbl).bed
}

fn write(plan: &FabPlan, dasharray: bool) -> String {
    svg(plan, &plan.jobs[0], &bed(), dasharray).unwrap()
}

/// The layer groups: (label, paths).
fn layers<'a>(doc: &'a Document<'a>) -> Vec<(String, Vec<Node<'a, 'a>>)> {
    doc.root_element()
        .children()
        .filter(|n| n.attribute((INKSCAPE, "groupmode")) == Some("layer"))
        .map(|g| {
            let label = g.attribute((INKSCAPE, "label")).unwrap().to_string();
            let paths = g.children().filter(|n| n.has_tag_name("path")).collect();
            (label, paths)
        })
        .collect()
}

/// The points of a path's `d` (M/L/Z only).
fn points(d: &str) -> Vec<DVec2> {
    let numbers: Vec<f64> = d
        .replace(['M', 'L', 'Z'], " ")
        .split_whitespace()
        .map(|n| n.parse().unwrap())
        .collect();
    numbers.chunks(2).map(|c| dvec2(c[0], c[1])).collect()
}

#[test]
fn parses_with_one_layer_per_operation_in_colour() {
    let text = write(&plan(job()), false);
    let doc = Document::parse(&text).expect("well-formed XML");
    let found: Vec<_> = layers(&doc)
        .into_iter()
        .map(|(l, p)| (l, p.len()))
        .collect();
    let want = [("mark", 1), ("score", 1), ("perforate", 3), ("cut", 1)];
    assert_eq!(found, want.map(|(l, n)| (l.to_string(), n)));
    for g in doc
        .descendants()
        .filter(|n| n.attribute((INKSCAPE, "label")).is_some())
    {
        let op = Operation::from_name(g.attribute((INKSCAPE, "label")).unwrap()).unwrap();
        assert_eq!(g.attribute("stroke"), Some(layer_style(op).hex));
        assert_eq!(g.attribute("fill"), Some("none"));
        let width: f64 = g.attribute("stroke-width").unwrap().parse().unwrap();
        assert!(width > 0.0 && width <= 0.1, "hairline");
    }
    assert!(
        text.contains("<desc>cut: 300 mm/min, power 80 %, 2 passes</desc>"),
        "{text}"
    );
}

#[test]
fn page_is_the_bed_in_millimetres() {
    let text = write(&plan(job()), false);
    let doc = Document::parse(&text).unwrap();
    let root = doc.root_element();
    assert_eq!(root.attribute("width"), Some("300mm"));
    assert_eq!(root.attribute("height"), Some("200mm"));
    assert_eq!(root.attribute("viewBox"), Some("0 0 300 200"));
    let tree = usvg::Tree::from_str(&text, &usvg::Options::default()).expect("usvg reads it");
    let mm_per_px = 25.4 / 96.0;
    assert!((tree.size().width() as f64 * mm_per_px - 300.0).abs() < 0.01);
}

#[test]
fn machine_y_is_flipped_back_to_the_page() {
    let text = write(&plan(job()), false);
    let doc = Document::parse(&text).unwrap();
    let (_, marks) = &layers(&doc)[0];
    let drawn = points(marks[0].attribute("d").unwrap());
    assert_eq!(drawn, vec![dvec2(1.0, 199.0), dvec2(3.0, 199.0)]);
    let mut flipped_bed = bed();
    flipped_bed.y_flipped = true;
    let plan = plan(job());
    let text = svg(&plan, &plan.jobs[0], &flipped_bed, false).unwrap();
    assert!(text.contains("M1 1L3 1"), "{text}");
}

#[test]
fn perforations_are_separate_dashes_by_default() {
    let text = write(&plan(job()), false);
    let doc = Document::parse(&text).unwrap();
    let (_, dashes_drawn) = &layers(&doc)[2];
    assert_eq!(dashes_drawn.len(), dashes().len());
    for (path, dash) in dashes_drawn.iter().zip(dashes()) {
        assert!(path.attribute("stroke-dasharray").is_none());
        let drawn = points(path.attribute("d").unwrap());
        let want: Vec<DVec2> = dash.iter().map(|p| dvec2(p.x, 200.0 - p.y)).collect();
        assert_eq!(drawn, want);
    }
    assert!(!text.contains("stroke-dasharray"));
}

#[test]
fn dasharray_mode_draws_each_perforation_as_one_dashed_path() {
    let text = write(&plan(job()), true);
    let doc = Document::parse(&text).unwrap();
    let (label, paths) = &layers(&doc)[2];
    assert_eq!((label.as_str(), paths.len()), ("perforate", 1));
    let pattern: Vec<f64> = paths[0]
        .attribute("stroke-dasharray")
        .unwrap()
        .split(' ')
        .map(|n| n.parse().unwrap())
        .collect();
    // Dashes of 10 mm with 5 mm gaps, then a closing gap as long as the path (40 mm).
    assert_eq!(pattern, vec![10.0, 5.0, 10.0, 5.0, 10.0, 40.0]);
    let drawn = points(paths[0].attribute("d").unwrap());
    assert_eq!(drawn.first(), Some(&dvec2(10.0, 170.0)));
    assert_eq!(drawn.last(), Some(&dvec2(50.0, 170.0)));
    let (_, cuts) = &layers(&doc)[3];
    assert!(
        cuts[0].attribute("stroke-dasharray").is_none(),
        "only perforations dash"
    );
}

#[test]
fn closed_contours_close_and_numbers_are_clean() {
    let text = write(&plan(job()), false);
    assert!(text.contains("56.744") && !text.contains("56.7440"));
    assert!(!text.contains("NaN") && !text.contains("inf") && !text.contains("-0 "));
    let doc = Document::parse(&text).unwrap();
    let (_, cuts) = &layers(&doc)[3];
    let d = cuts[0].attribute("d").unwrap();
    assert!(d.ends_with('Z') && points(d).len() == 4, "{d}");
}

#[test]
fn names_are_escaped() {
    let mut p = plan(job());
    p.jobs[0].name = "a<b & \"c\"".into();
    Document::parse(&write(&p, false)).expect("escaped job name");
}

#[test]
fn bad_input_is_an_error() {
    let mut p = plan(job());
    p.jobs[0].paths[2].strokes[1][0].x = f64::INFINITY;
    let err = svg(&p, &p.jobs[0], &bed(), false).unwrap_err();
    assert!(matches!(
        err,
        PostError::BadCoordinate {
            path: 2,
            stroke: 1,
            ..
        }
    ));
    let p = plan(job());
    let mut no_bed = bed();
    no_bed.width_mm = f64::NAN;
    let err = svg(&p, &p.jobs[0], &no_bed, false).unwrap_err();
    assert!(matches!(err, PostError::BadBed { .. }));
    let mut empty = plan(job());
    empty.jobs[0].paths = vec![toolpath(Operation::Plot, Vec::new())];
    let err = svg(&empty, &empty.jobs[0], &bed(), true).unwrap_err();
    assert!(matches!(err, PostError::EmptyJob { .. }));
}
