//! Round trips across formats on random planar patterns: SVG → FOLD → SVG and .cp → FOLD → .cp
//! preserve geometry and assignments (in each format's vocabulary).

use foldcam::formats::{Format, parse, render};
use foldcam::pattern::{Assignment, CreasePattern};
use glam::DVec2;
use proptest::prelude::*;

/// A random planar pattern: lattice edges with random assignments (or none) and at most one
/// diagonal per cell, so nothing crosses; `origin` and `pitch` vary the coordinates.
#[derive(Debug, Clone)]
struct Lattice {
    cols: usize,
    rows: usize,
    pitch: f64,
    origin: (f64, f64),
    edges: Vec<Option<Assignment>>,
    diagonals: Vec<u8>,
}

fn kinds() -> impl Strategy<Value = Option<Assignment>> {
    prop_oneof![
        Just(None),
        proptest::sample::select(vec![
            Assignment::Mountain,
            Assignment::Valley,
            Assignment::Boundary,
            Assignment::Flat,
            Assignment::Cut,
            Assignment::Unassigned,
        ])
        .prop_map(Some)
    ]
}

fn lattice() -> impl Strategy<Value = Lattice> {
    (
        1usize..6,
        1usize..6,
        0.5f64..80.0,
        -500.0f64..500.0,
        -500.0f64..500.0,
    )
        .prop_flat_map(|(cols, rows, pitch, ox, oy)| {
            let lattice_edges = cols * (rows + 1) + rows * (cols + 1);
            (
                proptest::collection::vec(kinds(), lattice_edges),
                proptest::collection::vec(0u8..3, cols * rows),
            )
                .prop_map(move |(edges, diagonals)| Lattice {
                    cols,
                    rows,
                    pitch,
                    origin: (ox, oy),
                    edges,
                    diagonals,
                })
        })
}

fn build(l: &Lattice) -> CreasePattern {
    let mut cp = CreasePattern::new();
    let p = |i: usize, j: usize| {
        DVec2::new(
            l.origin.0 + i as f64 * l.pitch,
            l.origin.1 + j as f64 * l.pitch,
        )
    };
    let mut k = 0;
    let mut add = |cp: &mut CreasePattern, a: DVec2, b: DVec2| {
        if let Some(kind) = l.edges[k] {
            cp.add_segment(a, b, kind);
        }
        k += 1;
    };
    for j in 0..=l.rows {
        for i in 0..l.cols {
            add(&mut cp, p(i, j), p(i + 1, j));
        }
    }
    for j in 0..l.rows {
        for i in 0..=l.cols {
            add(&mut cp, p(i, j), p(i, j + 1));
        }
    }
    for j in 0..l.rows {
        for i in 0..l.cols {
            match l.diagonals[j * l.cols + i] {
                1 => cp.add_segment(p(i, j), p(i + 1, j + 1), Assignment::Valley),
                2 => cp.add_segment(p(i + 1, j), p(i, j + 1), Assignment::Mountain),
                _ => continue,
            };
        }
    }
    cp
}

/// Whether two patterns have the same edges up to numbering and direction: every edge of `a`
/// has one in `b` with the same assignment (after `class`) and ends within `tol`, and the counts
/// agree.
fn same_edges(
    a: &CreasePattern,
    b: &CreasePattern,
    tol: f64,
    class: impl Fn(Assignment) -> Assignment,
) -> Result<(), String> {
    if a.edges.len() != b.edges.len() {
        return Err(format!("{} edges vs {}", a.edges.len(), b.edges.len()));
    }
    let mut used = vec![false; b.edges.len()];
    for e in a.edge_ids() {
        let (p, q) = a.segment(e);
        let kind = class(a.edges[e.index()].assignment);
        let found = b.edge_ids().position(|f| {
            let (r, s) = b.segment(f);
            let close = (p.distance(r) <= tol && q.distance(s) <= tol)
                || (p.distance(s) <= tol && q.distance(r) <= tol);
            !used[f.index()] && close && class(b.edges[f.index()].assignment) == kind
        });
        match found {
            Some(i) => used[i] = true,
            None => return Err(format!("no match for {kind:?} edge {p} – {q}")),
        }
    }
    Ok(())
}

fn through(format: Format, cp: &CreasePattern) -> CreasePattern {
    let text = render(format, cp, None);
    let imported = parse(format, &text).unwrap_or_else(|e| panic!("{format:?}: {e}"));
    imported.pattern
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, ..ProptestConfig::default() })]

    #[test]
    fn svg_fold_svg_keeps_geometry_and_assignments(l in lattice()) {
        let cp = build(&l);
        prop_assume!(!cp.edges.is_empty());
        let first = through(Format::Svg, &cp);
        let again = through(Format::Svg, &through(Format::Fold, &first));
        // usvg holds coordinates as f32: about 1e-7 of their magnitude (≤ 1000 mm here).
        let tol = 1e-3 * l.pitch.min(1.0);
        let same = |k| k;
        prop_assert_eq!(same_edges(&first, &again, tol, same), Ok(()));
        prop_assert_eq!(same_edges(&cp, &first, tol, same), Ok(()));
    }

    #[test]
    fn cp_fold_cp_keeps_geometry_and_assignments(l in lattice()) {
        let cp = build(&l);
        prop_assume!(!cp.edges.is_empty());
        let first = through(Format::Cp, &cp);
        let again = through(Format::Cp, &through(Format::Fold, &first));
        prop_assert_eq!(same_edges(&first, &again, 1e-9, |k| k), Ok(()));
        // .cp knows boundary, mountain, valley and auxiliary only.
        let in_cp_terms = |k| match k {
            Assignment::Cut => Assignment::Boundary,
            Assignment::Unassigned | Assignment::Join => Assignment::Flat,
            k => k,
        };
        prop_assert_eq!(same_edges(&cp, &first, 1e-9, in_cp_terms), Ok(()));
    }
}
