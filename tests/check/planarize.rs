//! Planarisation: crossings split, touches split, duplicates merged, faces traced; random
//! drawings come out as planar graphs with Euler's formula holding.

use foldcam::geom::contains_point;
use foldcam::geom::{Crossing, intersect};
use foldcam::pattern::find_faces;
use foldcam::pattern::{Assignment, CreasePattern, PlanarizeOptions, planarize};
use glam::DVec2;
use proptest::prelude::*;

fn opts(faces: bool) -> PlanarizeOptions {
    PlanarizeOptions {
        tolerance: None,
        faces,
    }
}

fn seg(cp: &mut CreasePattern, a: (f64, f64), b: (f64, f64), kind: Assignment) {
    cp.add_segment(DVec2::new(a.0, a.1), DVec2::new(b.0, b.1), kind);
}

/// Asserts no two edges cross or overlap except at shared end vertices, and no two vertices
/// coincide (brute force, for small patterns).
fn assert_planar(cp: &CreasePattern, tol: f64) {
    for i in 0..cp.vertices.len() {
        for j in i + 1..cp.vertices.len() {
            assert!(
                cp.vertices[i].distance(cp.vertices[j]) > tol,
                "vertices {i} and {j} coincide"
            );
        }
    }
    for i in 0..cp.edges.len() {
        for j in i + 1..cp.edges.len() {
            let (a, b) = (&cp.edges[i], &cp.edges[j]);
            let shared = a.vertices.iter().filter(|v| b.vertices.contains(v)).count();
            assert!(shared < 2, "edges {i} and {j} are duplicates");
            let (p0, p1) = (cp.position(a.vertices[0]), cp.position(a.vertices[1]));
            let (q0, q1) = (cp.position(b.vertices[0]), cp.position(b.vertices[1]));
            match intersect(p0, p1, q0, q1, 1e-12) {
                Crossing::None => {}
                Crossing::Overlap => panic!("edges {i} and {j} overlap"),
                Crossing::Point { t, u } => {
                    let x = p0.lerp(p1, t);
                    let at_shared = a
                        .vertices
                        .iter()
                        .filter(|v| b.vertices.contains(v))
                        .any(|&v| cp.position(v).distance(x) <= 10.0 * tol);
                    assert!(at_shared, "edges {i} and {j} cross at t={t} u={u} ({x})");
                }
            }
        }
    }
}

fn components(cp: &CreasePattern) -> usize {
    let mut parent: Vec<usize> = (0..cp.vertices.len()).collect();
    fn root(p: &mut [usize], mut x: usize) -> usize {
        while p[x] != x {
            x = p[x];
        }
        x
    }
    for e in &cp.edges {
        let (a, b) = (
            root(&mut parent, e.vertices[0].index()),
            root(&mut parent, e.vertices[1].index()),
        );
        parent[a] = b;
    }
    (0..cp.vertices.len())
        .filter(|&v| root(&mut parent, v) == v)
        .count()
}

#[test]
fn two_crossing_segments_become_four_edges_around_a_new_vertex() {
    let mut cp = CreasePattern::new();
    seg(&mut cp, (0.0, 0.0), (2.0, 2.0), Assignment::Mountain);
    seg(&mut cp, (0.0, 2.0), (2.0, 0.0), Assignment::Valley);
    let r = planarize(&mut cp, &opts(false)).expect("planar");
    assert_eq!(r.crossings, 1);
    assert_eq!(cp.vertices.len(), 5);
    assert_eq!(cp.edges.len(), 4);
    let centre = cp
        .vertices
        .iter()
        .position(|p| p.distance(DVec2::ONE) < 1e-12);
    let centre = centre.expect("a vertex at the crossing (1, 1)");
    let degree = cp
        .edges
        .iter()
        .filter(|e| e.vertices.iter().any(|v| v.index() == centre))
        .count();
    assert_eq!(degree, 4);
    let m = cp
        .edges
        .iter()
        .filter(|e| e.assignment == Assignment::Mountain)
        .count();
    assert_eq!(m, 2, "each half keeps its assignment");
    assert_planar(&cp, r.tolerance);
}

#[test]
fn vertex_on_an_edge_splits_it() {
    let mut cp = CreasePattern::new();
    seg(&mut cp, (0.0, 0.0), (4.0, 0.0), Assignment::Boundary);
    seg(&mut cp, (1.0, 0.0), (1.0, 3.0), Assignment::Valley);
    let r = planarize(&mut cp, &opts(false)).expect("planar");
    assert_eq!(r.crossings, 0);
    assert_eq!(cp.edges.len(), 3);
    assert_eq!(cp.vertices.len(), 4);
    let b: f64 = cp
        .edge_ids()
        .filter(|&e| cp.edges[e.index()].assignment == Assignment::Boundary)
        .map(|e| cp.edge_length(e))
        .sum();
    assert!((b - 4.0).abs() < 1e-12, "boundary length kept: {b}");
}

#[test]
fn overlapping_collinear_edges_keep_the_stronger_assignment() {
    let mut cp = CreasePattern::new();
    seg(&mut cp, (0.0, 0.0), (3.0, 0.0), Assignment::Flat);
    seg(&mut cp, (1.0, 0.0), (2.0, 0.0), Assignment::Cut);
    let r = planarize(&mut cp, &opts(false)).expect("planar");
    assert_eq!(cp.edges.len(), 3, "{cp:?}");
    assert_eq!(r.duplicates_removed, 1);
    for e in cp.edge_ids() {
        let (a, b) = cp.segment(e);
        let mid = 0.5 * (a.x + b.x);
        let want = if (1.0..=2.0).contains(&mid) {
            Assignment::Cut
        } else {
            Assignment::Flat
        };
        assert_eq!(cp.edges[e.index()].assignment, want, "piece at x = {mid}");
    }
}

#[test]
fn near_vertices_merge_within_tolerance_only() {
    let mut cp = CreasePattern::new();
    seg(&mut cp, (0.0, 0.0), (1.0, 0.0), Assignment::Mountain);
    seg(&mut cp, (1.0 + 1e-9, 0.0), (1.0, 1.0), Assignment::Valley);
    seg(&mut cp, (5.0, 5.0), (5.0 + 1e-3, 5.0), Assignment::Valley);
    let r = planarize(
        &mut cp,
        &PlanarizeOptions {
            tolerance: Some(1e-6),
            faces: false,
        },
    )
    .expect("planar");
    assert_eq!(r.merged_vertices, 1);
    assert_eq!(cp.vertices.len(), 5);
    assert_eq!(
        cp.edges.len(),
        3,
        "a 1e-3 edge is longer than the tolerance and stays"
    );
}

#[test]
fn clean_pattern_is_left_exactly_as_it_was() {
    let mut cp = CreasePattern::new();
    let v: Vec<_> = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]
        .iter()
        .map(|&(x, y)| cp.add_vertex(DVec2::new(x, y)))
        .collect();
    for k in 0..4 {
        cp.add_edge(v[k], v[(k + 1) % 4], Assignment::Boundary);
    }
    cp.add_edge(v[0], v[2], Assignment::Valley);
    cp.meta
        .frame_extra
        .insert("edges_custom".into(), serde_json::json!([1, 2, 3, 4, 5]));
    let before = cp.clone();
    let r = planarize(&mut cp, &opts(false)).expect("planar");
    assert!(r.unchanged());
    assert_eq!(cp, before);
}

#[test]
fn square_with_diagonals_and_an_island_has_the_right_faces() {
    let mut cp = CreasePattern::new();
    let sq = [(0.0, 0.0), (10.0, 0.0), (10.0, 10.0), (0.0, 10.0)];
    for k in 0..4 {
        seg(&mut cp, sq[k], sq[(k + 1) % 4], Assignment::Boundary);
    }
    seg(&mut cp, (0.0, 0.0), (10.0, 10.0), Assignment::Valley);
    seg(&mut cp, (0.0, 10.0), (10.0, 0.0), Assignment::Valley);
    // A small square hole (cut) inside the lower triangle.
    let hole = [(4.0, 1.0), (6.0, 1.0), (6.0, 2.0), (4.0, 2.0)];
    for k in 0..4 {
        seg(&mut cp, hole[k], hole[(k + 1) % 4], Assignment::Cut);
    }
    planarize(&mut cp, &opts(true)).expect("planar");
    let faces = cp.faces.as_ref().expect("faces computed");
    // Four triangles plus the hole's inside.
    assert_eq!(faces.len(), 5);
    let with_hole: Vec<_> = faces.iter().filter(|f| !f.holes.is_empty()).collect();
    assert_eq!(
        with_hole.len(),
        1,
        "the lower triangle holds the island as a hole"
    );
    let set = find_faces(&cp);
    assert_eq!(set.outer.len(), 1, "one unbounded outline");
    // Euler: V − E + F = 1 + C counting the unbounded face, so V − E + (bounded faces) = C.
    let (v, e, f) = (
        cp.vertices.len() as i64,
        cp.edges.len() as i64,
        faces.len() as i64,
    );
    assert_eq!(v - e + f, components(&cp) as i64);
}

/// Distance from `p` to the segment `ab`, by projection (brute force, independent of
/// `foldcam::geom`).
fn point_segment_distance(p: DVec2, a: DVec2, b: DVec2) -> f64 {
    let ab = b - a;
    let len2 = ab.length_squared();
    let t = if len2 > 0.0 {
        ((p - a).dot(ab) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    p.distance(a + t * ab)
}

fn coord() -> impl Strategy<Value = f64> {
    // A coarse lattice makes collinear overlaps, shared end points and T-junctions common.
    prop_oneof![(0i32..8).prop_map(|k| k as f64 * 12.5), 0.0f64..100.0]
}

fn assignment() -> impl Strategy<Value = Assignment> {
    proptest::sample::select(Assignment::ALL.to_vec())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 200, ..ProptestConfig::default() })]

    #[test]
    fn random_drawings_become_planar_graphs(
        segs in proptest::collection::vec(((coord(), coord()), (coord(), coord()), assignment()), 1..40)
    ) {
        let mut cp = CreasePattern::new();
        for &(a, b, k) in &segs {
            seg(&mut cp, a, b, k);
        }
        let r = planarize(&mut cp, &opts(true)).expect("planar");
        cp.validate().expect("planarised pattern is valid");
        assert_planar(&cp, r.tolerance);
        // Nothing drawn is lost and nothing is invented: every point along an input segment
        // lies on an output edge carrying the assignment of one of the input segments through
        // it, and every output edge's midpoint lies on an input segment of its assignment.
        let input: Vec<(DVec2, DVec2, Assignment)> = segs
            .iter()
            .map(|&(a, b, k)| (DVec2::new(a.0, a.1), DVec2::new(b.0, b.1), k))
            .collect();
        let near = 1e-6 + 2.0 * r.tolerance;
        let output: Vec<(DVec2, DVec2, Assignment)> = cp
            .edges
            .iter()
            .map(|e| (cp.position(e.vertices[0]), cp.position(e.vertices[1]), e.assignment))
            .collect();
        for &(a, b, _) in input.iter().filter(|(a, b, _)| a.distance(*b) > 4.0 * near) {
            for t in [0.13, 0.37, 0.61, 0.89] {
                let p = a.lerp(b, t);
                let through: Vec<Assignment> = input
                    .iter()
                    .filter(|(c, d, _)| point_segment_distance(p, *c, *d) <= near)
                    .map(|s| s.2)
                    .collect();
                let on = output
                    .iter()
                    .filter(|(c, d, _)| point_segment_distance(p, *c, *d) <= near)
                    .collect::<Vec<_>>();
                prop_assert!(!on.is_empty(), "{p} of input {a}-{b} is on no output edge");
                prop_assert!(
                    on.iter().any(|e| through.contains(&e.2)),
                    "{p}: output {:?}, input {:?}", on.iter().map(|e| e.2).collect::<Vec<_>>(), through
                );
            }
        }
        for &(c, d, k) in &output {
            let m = c.lerp(d, 0.5);
            prop_assert!(
                input.iter().any(|&(a, b, j)| j == k && point_segment_distance(m, a, b) <= near),
                "output edge {c}-{d} ({k:?}) lies on no input segment of its assignment"
            );
        }
        // Idempotent: a second pass changes nothing.
        let again = planarize(&mut cp.clone(), &opts(true)).expect("planar");
        prop_assert!(again.unchanged(), "second pass changed: {again:?}");
        // Euler: V − E + (bounded faces) = C for a planar graph with C components.
        let faces = cp.faces.as_ref().map_or(0, |f| f.len()) as i64;
        let (v, e) = (cp.vertices.len() as i64, cp.edges.len() as i64);
        prop_assert_eq!(v - e + faces, components(&cp) as i64);
        // Every face outline is counter-clockwise, and each hole lies inside its face.
        for f in cp.faces.iter().flatten() {
            let ring: Vec<DVec2> = f.outer.iter().map(|&v| cp.position(v)).collect();
            prop_assert!(foldcam::geom::signed_area(ring.iter().copied()) > 0.0);
            for hole in &f.holes {
                let p = cp.position(hole[0]);
                prop_assert!(contains_point(&ring, p), "hole at {p} outside its face");
            }
        }
        // Outlines left on the unbounded face are inside no face of another component.
        let set = find_faces(&cp);
        for cycle in &set.outer {
            let p = cp.position(cycle[0]);
            for f in cp.faces.iter().flatten() {
                if f.outer.iter().any(|v| cycle.contains(v)) {
                    continue;
                }
                let ring: Vec<DVec2> = f.outer.iter().map(|&v| cp.position(v)).collect();
                prop_assert!(!contains_point(&ring, p), "outline at {p} is inside a face");
            }
        }
    }
}

#[test]
fn regression_long_diagonal_crossed_by_short_segment() {
    let mut cp = CreasePattern::new();
    seg(
        &mut cp,
        (0.0, 87.5),
        (70.91846698065238, 0.0),
        Assignment::Boundary,
    );
    seg(
        &mut cp,
        (25.310128997681684, 37.5),
        (50.0545509065193, 45.999368735682616),
        Assignment::Boundary,
    );
    let r = planarize(&mut cp, &opts(true)).expect("planar");
    assert_eq!(r.crossings, 1);
    assert_eq!((cp.vertices.len(), cp.edges.len()), (5, 4));
}

#[test]
fn islands_nest_inside_holes_and_separate_sheets_stay_outside() {
    let mut cp = CreasePattern::new();
    let square = |cp: &mut CreasePattern, x: f64, y: f64, s: f64, k: Assignment| {
        let c = [(x, y), (x + s, y), (x + s, y + s), (x, y + s)];
        for i in 0..4 {
            seg(cp, c[i], c[(i + 1) % 4], k);
        }
    };
    square(&mut cp, 0.0, 0.0, 100.0, Assignment::Boundary); // sheet
    square(&mut cp, 20.0, 20.0, 60.0, Assignment::Cut); // hole cut in it
    square(&mut cp, 40.0, 40.0, 20.0, Assignment::Boundary); // island inside the hole
    square(&mut cp, 200.0, 0.0, 50.0, Assignment::Boundary); // a second sheet
    planarize(&mut cp, &opts(true)).expect("planar");
    let set = find_faces(&cp);
    assert_eq!(set.faces.len(), 4);
    assert_eq!(set.outer.len(), 2, "two sheets on the unbounded face");
    let area = |f: &foldcam::pattern::Face| {
        foldcam::geom::signed_area(f.outer.iter().map(|&v| cp.position(v)))
    };
    for f in &set.faces {
        let expected_holes = match area(f).round() as i64 {
            10_000 => 1, // the sheet holds the hole's outline
            3_600 => 1,  // the hole's inside holds the island
            _ => 0,
        };
        assert_eq!(f.holes.len(), expected_holes, "face of area {}", area(f));
    }
}

#[test]
fn thousands_of_overlapping_distinct_lines_are_refused_not_hung() {
    // 3,000 collinear segments with distinct ends all overlapping: splitting them all would
    // make millions of pieces; planarisation stops with an error instead.
    let mut cp = CreasePattern::new();
    for k in 0..3000 {
        let t = k as f64 * 1e-3;
        seg(&mut cp, (t, 0.0), (100.0 - t, 0.0), Assignment::Mountain);
    }
    let err = planarize(&mut cp, &opts(false)).expect_err("too complex");
    assert!(err.to_string().contains("too tangled"), "{err}");
    cp.validate().expect("left valid");
}

#[test]
fn coincident_vertex_piles_merge_in_one_group() {
    let mut cp = CreasePattern::new();
    for _ in 0..20_000 {
        cp.add_vertex(DVec2::ZERO);
    }
    let far = cp.add_vertex(DVec2::ONE);
    cp.add_edge(foldcam::pattern::VertexId(0), far, Assignment::Valley);
    let r = planarize(&mut cp, &opts(false)).expect("planar");
    assert_eq!(cp.vertices.len(), 2);
    assert_eq!(r.merged_vertices, 19_999);
}
