//! Helpers of the polygon pop-up tests: samples, small builders and the geometric assertions.

use crate::cuts_clean;

use std::collections::HashMap;

use foldcam::design::popup::polygon::{
    FaceKind, PATTERN_TOLERANCE_MM, PolygonCard, Shapes, UNIT_MM, face_planes, fold_card,
    parse_design,
};
use foldcam::design::popup::voxel::{self, VoxelCard};
use foldcam::geom::signed_area;
use foldcam::pattern::{Assignment, CreasePattern, Face, FoldedState, VertexId};
use glam::{DVec2, DVec3};
use i_overlay::core::fill_rule::FillRule;
use i_overlay::core::overlay_rule::OverlayRule;
use i_overlay::core::single::SingleIntOverlay;
use i_overlay::i_float::int::point::IntPoint;

pub fn example_path(name: &str) -> String {
    format!("{}/examples/popup/{name}", env!("CARGO_MANIFEST_DIR"))
}

pub fn example(name: &str) -> PolygonCard {
    let text = std::fs::read_to_string(example_path(name)).expect("example exists");
    parse_design(&text)
        .expect("parses")
        .build()
        .expect("builds")
}

/// The counter-clockwise rectangle `[x0, x1] × [y0, y1]` on a reference plane.
pub fn quad(x0: f64, y0: f64, x1: f64, y1: f64) -> Vec<DVec2> {
    vec![
        DVec2::new(x0, y0),
        DVec2::new(x1, y0),
        DVec2::new(x1, y1),
        DVec2::new(x0, y1),
    ]
}

/// A box from x0 to x1 standing `depth` mm out of the back sheet, `height` mm high: its front
/// wall and its roof.
pub fn add_box(card: &mut PolygonCard, x0: f64, x1: f64, depth: f64, height: f64) {
    card.add_face(FaceKind::Vertical, depth, &quad(x0, 0.0, x1, height))
        .unwrap();
    card.add_face(FaceKind::Horizontal, height, &quad(x0, 0.0, x1, depth))
        .unwrap();
}

/// A 120 × (60 + 80) mm card with a 50 × 30 × 30 mm box on x 35..85.
pub fn house() -> PolygonCard {
    let mut card = PolygonCard::new(120.0, 60.0, 80.0).unwrap();
    add_box(&mut card, 35.0, 85.0, 30.0, 30.0);
    card
}

pub fn ring_bounds(ring: &[DVec2]) -> (DVec2, DVec2) {
    let lo = ring.iter().copied().fold(DVec2::MAX, DVec2::min);
    let hi = ring.iter().copied().fold(DVec2::MIN, DVec2::max);
    (lo, hi)
}

/// Lengths of the edges of one assignment, sorted.
pub fn fold_lengths(cp: &CreasePattern, kind: Assignment) -> Vec<f64> {
    let mut out: Vec<f64> = cp
        .edge_ids()
        .filter(|&e| cp.edges[e.index()].assignment == kind)
        .map(|e| cp.edge_length(e))
        .collect();
    out.sort_by(f64::total_cmp);
    out
}

/// Area of integer shapes in grid units squared.
pub fn shapes_area(shapes: &Shapes) -> f64 {
    shapes
        .iter()
        .flatten()
        .map(|c| signed_area(c.iter().map(|p| DVec2::new(p.x.into(), p.y.into()))))
        .sum()
}

fn face_ring(cp: &CreasePattern, ring: &[VertexId]) -> Vec<DVec2> {
    ring.iter().map(|&v| cp.position(v)).collect()
}

pub fn face_area(cp: &CreasePattern, f: &Face) -> f64 {
    let ring = |c: &Vec<VertexId>| signed_area(face_ring(cp, c));
    ring(&f.outer) + f.holes.iter().map(ring).sum::<f64>()
}

/// The pattern's faces tile the sheet and folds carry ±90°.
pub fn assert_tiles_sheet(card: &PolygonCard, cp: &CreasePattern) {
    cp.validate().unwrap();
    let (w, d, h) = card.size_mm();
    let total: f64 = cp
        .faces
        .as_ref()
        .unwrap()
        .iter()
        .map(|f| face_area(cp, f))
        .sum();
    let sheet = w * (d + h);
    assert!(
        (total - sheet).abs() < 1e-6 * sheet,
        "faces cover {total}, sheet {sheet}"
    );
    for e in &cp.edges {
        let want = match e.assignment {
            Assignment::Valley => Some(90.0),
            Assignment::Mountain => Some(-90.0),
            _ => None,
        };
        assert_eq!(e.fold_angle, want, "{:?}", e.assignment);
    }
}

/// §3.4: only lines parallel to x fold.
pub fn assert_creases_parallel_to_x(cp: &CreasePattern) {
    for e in cp.edge_ids() {
        if cp.edges[e.index()].assignment.is_fold() {
            let (a, b) = cp.segment(e);
            assert_eq!(a.y, b.y, "crease {a} – {b} is not parallel to x");
        }
    }
}

/// At 90° every folded face lies in the plane y = t (VFace) or z = t (HFace) of the card
/// faces that cover its pattern region (checked by area: the pattern face lies inside the
/// union of the card faces on that plane).
pub fn assert_faces_on_planes(card: &PolygonCard, cp: &CreasePattern) {
    let folded = fold_card(card, cp, 90.0).state;
    let planes = face_planes(card, cp);
    let faces = cp.faces.as_ref().unwrap();
    for ((f, g), plane) in faces.iter().zip(folded.faces.as_ref().unwrap()).zip(planes) {
        let t = plane.t_mm();
        for v in g.outer.iter().chain(g.holes.iter().flatten()) {
            let p = folded.positions[v.index()];
            let off = match plane.kind {
                FaceKind::Vertical => p.y - t,
                FaceKind::Horizontal => p.z - t,
            };
            assert!(off.abs() < 1e-9, "{p} off the plane {plane:?}");
        }
        let on_plane: Shapes = card
            .faces()
            .iter()
            .filter(|c| c.plane == plane)
            .flat_map(|c| c.polygon.clone())
            .collect();
        let units = |c: &Vec<VertexId>| -> Vec<IntPoint<i32>> {
            face_ring(cp, c)
                .iter()
                .map(|p| {
                    IntPoint::new(
                        (p.x / UNIT_MM).round() as i32,
                        (p.y / UNIT_MM).round() as i32,
                    )
                })
                .collect()
        };
        let region: Vec<Vec<IntPoint<i32>>> = std::iter::once(units(&f.outer))
            .chain(f.holes.iter().map(units))
            .collect();
        let inside = vec![region].overlay(&on_plane, OverlayRule::Intersect, FillRule::NonZero);
        // Planarising merges vertices closer than its tolerance: the pattern face may differ
        // from the card faces by a band that thin along its boundary.
        let want = face_area(cp, f);
        let got = shapes_area(&inside) * UNIT_MM * UNIT_MM;
        let band = perimeter(cp, f) * PATTERN_TOLERANCE_MM;
        assert!(
            (got - want).abs() <= band,
            "face on {plane:?}: {got} of {want} mm²"
        );
    }
}

fn perimeter(cp: &CreasePattern, f: &Face) -> f64 {
    std::iter::once(&f.outer)
        .chain(&f.holes)
        .map(|c| {
            let r = face_ring(cp, c);
            (0..r.len())
                .map(|i| (r[(i + 1) % r.len()] - r[i]).length())
                .sum::<f64>()
        })
        .sum()
}

/// Eq. 7 keeps every edge length.
pub fn assert_isometric(cp: &CreasePattern, state: &FoldedState, source: &[VertexId]) {
    for e in &state.edges {
        let [a, b] = e.vertices;
        let folded = (state.positions[a.index()] - state.positions[b.index()]).length();
        let flat = (cp.position(source[a.index()]) - cp.position(source[b.index()])).length();
        assert!((folded - flat).abs() < 1e-9, "{folded} vs {flat}");
    }
}

fn normal(positions: &[DVec3], f: &Face) -> DVec3 {
    let ring: Vec<DVec3> = f.outer.iter().map(|v| positions[v.index()]).collect();
    let n = (0..ring.len()).fold(DVec3::ZERO, |n, i| {
        n + ring[i].cross(ring[(i + 1) % ring.len()])
    });
    n.normalize()
}

/// Every fold joins two faces turned by its fold angle; returns the number of folds checked.
pub fn assert_fold_angles(state: &FoldedState) -> usize {
    let faces = state.faces.as_ref().unwrap();
    let mut by_edge = HashMap::<_, Vec<usize>>::new();
    for (i, f) in faces.iter().enumerate() {
        for ring in std::iter::once(&f.outer).chain(&f.holes) {
            for k in 0..ring.len() {
                let (a, b) = (ring[k], ring[(k + 1) % ring.len()]);
                by_edge.entry((a.min(b), a.max(b))).or_default().push(i);
            }
        }
    }
    let mut checked = 0;
    for e in state.edges.iter().filter(|e| e.assignment.is_fold()) {
        let [a, b] = e.vertices;
        let pair = &by_edge[&(a.min(b), a.max(b))];
        assert_eq!(pair.len(), 2, "a fold joins two faces: {e:?}");
        let (n1, n2) = (
            normal(&state.positions, &faces[pair[0]]),
            normal(&state.positions, &faces[pair[1]]),
        );
        let turn = n1.dot(n2).clamp(-1.0, 1.0).acos().to_degrees();
        let want = e.fold_angle.unwrap();
        assert!((turn - want.abs()).abs() < 1e-6, "{turn} vs {want}");
        let sign = if e.assignment == Assignment::Valley {
            1.0
        } else {
            -1.0
        };
        assert!(want == 0.0 || want.signum() == sign);
        checked += 1;
    }
    checked
}

/// Plans `cp` for a diode laser on 300 g/m² card, writes G-code and runs it on the simulated
/// machine: no violations, every crease and cut covered as planned.
pub fn assert_cuts_clean(name: &str, cp: &CreasePattern) {
    cuts_clean::assert_cuts_clean_on(name, cp, "grbl-diode", "card-300gsm");
}

/// Eq. 4 exactly on the integer grid: pairwise intersections are empty and the areas add up
/// to the sheet; the regularised union computed separately matches within 1e-9.
pub fn assert_pattern_condition(card: &PolygonCard) {
    let faces = card.faces();
    for i in 0..faces.len() {
        for j in i + 1..faces.len() {
            let common = faces[i].polygon.overlay(
                &faces[j].polygon,
                OverlayRule::Intersect,
                FillRule::NonZero,
            );
            assert_eq!(shapes_area(&common), 0.0, "faces {i} and {j} overlap");
        }
    }
    let (w, d, h) = card.size_mm();
    let sheet = w * (d + h);
    let sum: f64 = faces.iter().map(|f| f.area_mm2()).sum();
    assert!(
        (sum - sheet).abs() <= 1e-9 * sheet,
        "faces {sum}, sheet {sheet}"
    );
    let mut union = faces[0].polygon.clone();
    for f in &faces[1..] {
        union = union.overlay(&f.polygon, OverlayRule::Union, FillRule::NonZero);
    }
    let area = shapes_area(&union) * UNIT_MM * UNIT_MM;
    assert!(
        (area - sheet).abs() <= 1e-9 * sheet,
        "union {area}, sheet {sheet}"
    );
}

/// The same card surface: sample points of the pattern land on the same card point at 90°.
pub fn assert_same_surface(vcard: &VoxelCard, pcard: &PolygonCard) {
    let s = vcard.cell_mm();
    let m = vcard.margin_mm();
    let surface = voxel::Surface::new(vcard);
    let mut n = 0;
    for x in 0..surface.nx {
        for r in 0..surface.rows {
            // A point inside the cell, off every grid line.
            let (u, v) = (x as f64 + 0.37, r as f64 - vcard.ny() as f64 + 0.61);
            let want = DVec3::from(surface.plane(x as i64, r as i64).to_card(u, v)) * s
                + DVec3::new(m, 0.0, 0.0);
            let got = pcard.card_point(DVec2::new(u * s + m, v * s)).unwrap();
            assert!(
                (got - want).length() < 1e-9,
                "cell ({x}, {r}): {got} vs {want}"
            );
            n += 1;
        }
    }
    assert!(n >= 9, "sampled {n} cells");
}

pub fn total_length(cp: &CreasePattern, kind: Assignment) -> f64 {
    cp.edge_ids()
        .filter(|&e| cp.edges[e.index()].assignment == kind)
        .map(|e| cp.edge_length(e))
        .sum()
}
