//! Import snapping is not too eager on curves: Origami Simulator's `CircularPleat-antiFacet.svg`
//! (MIT, tests/data/README.md) draws 14 concentric circles as short chords (100 per circle,
//! 5–12 px long), 8 px apart, crossed by facet lines. Snapping (default tolerance, 1/1000 of
//! the diagonal) must merge no vertex of one circle with a vertex of another: read with and
//! without snapping, the mountain and valley lines form the same 14 curves, each at one
//! radius, with the same length and assignment, and every one closed once snapped.

use std::collections::HashMap;
use std::path::PathBuf;

use foldcam::formats::{self, ReadOptions};
use foldcam::pattern::{Assignment, CreasePattern};

fn data(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/svg")
        .join(name)
}

/// One closed curve of mountain or valley edges: its assignment, its vertices' smallest and
/// largest distance from the sheet's centre, its length, and whether every vertex of it has
/// exactly two curve edges (a closed chain).
#[derive(Debug)]
struct Curve {
    assignment: Assignment,
    r_min: f64,
    r_max: f64,
    length: f64,
    closed: bool,
}

/// The connected components of the pattern's mountain and valley edges.
fn curves(cp: &CreasePattern) -> Vec<Curve> {
    let (lo, hi) = cp.bounds().unwrap();
    let centre = (lo + hi) / 2.0;
    let folds: Vec<usize> = (0..cp.edges.len())
        .filter(|&e| {
            matches!(
                cp.edges[e].assignment,
                Assignment::Mountain | Assignment::Valley
            )
        })
        .collect();
    let mut parent: Vec<usize> = (0..cp.vertices.len()).collect();
    fn root(p: &mut [usize], mut v: usize) -> usize {
        while p[v] != v {
            p[v] = p[p[v]];
            v = p[v];
        }
        v
    }
    let mut degree = vec![0usize; cp.vertices.len()];
    for &e in &folds {
        let [a, b] = cp.edges[e].vertices;
        degree[a.index()] += 1;
        degree[b.index()] += 1;
        let (ra, rb) = (root(&mut parent, a.index()), root(&mut parent, b.index()));
        parent[ra.max(rb)] = ra.min(rb);
    }
    let mut by_root: HashMap<usize, Curve> = HashMap::new();
    for &e in &folds {
        let edge = &cp.edges[e];
        let [a, b] = edge.vertices;
        let r = root(&mut parent, a.index());
        let curve = by_root.entry(r).or_insert(Curve {
            assignment: edge.assignment,
            r_min: f64::INFINITY,
            r_max: 0.0,
            length: 0.0,
            closed: true,
        });
        assert_eq!(curve.assignment, edge.assignment, "a curve of two kinds");
        for v in [a, b] {
            let d = cp.vertices[v.index()].distance(centre);
            curve.r_min = curve.r_min.min(d);
            curve.r_max = curve.r_max.max(d);
            curve.closed &= degree[v.index()] == 2;
        }
        curve.length += cp.vertices[a.index()].distance(cp.vertices[b.index()]);
    }
    let mut out: Vec<Curve> = by_root.into_values().collect();
    out.sort_by(|p, q| p.r_min.total_cmp(&q.r_min));
    out
}

fn fold_edges(cp: &CreasePattern) -> usize {
    cp.edges
        .iter()
        .filter(|e| matches!(e.assignment, Assignment::Mountain | Assignment::Valley))
        .count()
}

#[test]
fn snapping_keeps_every_circle_of_the_circular_pleat_apart() {
    let path = data("CircularPleat-antiFacet.svg");
    let raw = formats::load_with(
        &path,
        &ReadOptions {
            snap: Some(0.0),
            ..ReadOptions::default()
        },
    )
    .unwrap_or_else(|e| panic!("{e}"));
    let snapped = formats::load(&path).unwrap_or_else(|e| panic!("{e}"));
    assert!(
        snapped.found(formats::FindingKind::Snapped),
        "{:?}",
        snapped.findings
    );
    let (before, after) = (curves(&raw.pattern), curves(&snapped.pattern));
    // The file's 1400 red and blue chords lie on 14 circles (radii 88 to 192 px, 8 px apart:
    // counted from the file's coordinates), before and after snapping.
    assert_eq!(before.len(), 14, "{before:?}");
    assert_eq!(after.len(), 14, "{after:?}");
    // 8 px at 96 px per inch; the snapping tolerance is well under it.
    let spacing_mm = 8.0 * 25.4 / 96.0;
    let (lo, hi) = snapped.pattern.bounds().unwrap();
    let tolerance = lo.distance(hi) * formats::SNAP_RELATIVE;
    assert!(tolerance < spacing_mm / 4.0);
    for (i, (b, a)) in before.iter().zip(&after).enumerate() {
        // Snapping closes any circle the drawing left open (one is: a chord end a hair off
        // its neighbour) and opens none.
        assert!(a.closed, "circle {i} open: {b:?} {a:?}");
        assert_eq!(b.assignment, a.assignment, "circle {i}");
        // The chord points sit on the circle; a chord's middle is inside it by r(1 − cos(π/100)),
        // under 0.05 mm here, and no vertex moved farther than the tolerance.
        assert!(a.r_max - a.r_min < spacing_mm / 4.0, "circle {i}: {a:?}");
        assert!(
            (a.r_min - b.r_min).abs() <= tolerance,
            "circle {i}: {b:?} → {a:?}"
        );
        assert!(
            (a.r_max - b.r_max).abs() <= tolerance,
            "circle {i}: {b:?} → {a:?}"
        );
        // The length of the polygon: 100 chords of 2r sin(π/100), unchanged but for the
        // merged sub-tolerance pieces.
        let chords = 200.0 * a.r_max * (std::f64::consts::PI / 100.0).sin();
        assert!((a.length - b.length).abs() < 1e-3 * b.length, "circle {i}");
        assert!(
            (a.length - chords).abs() < 1e-2 * chords,
            "circle {i}: {a:?}"
        );
    }
    // Snapping removes only pieces shorter than the tolerance (where a facet line crossed a
    // chord a hair from a junction; a point inside a curve never moves, so a piece next to it
    // may stay); the 1400 drawn chords all remain.
    let (nb, na) = (fold_edges(&raw.pattern), fold_edges(&snapped.pattern));
    assert!(na <= nb && na >= 1400, "{nb} → {na}");
}
