//! Helpers shared by the fabrication-geometry tests: options, pattern builders, distances.
#![allow(dead_code)]

use foldcam::fab::{ContourRole, Operation, PlanOptions, Toolpath};
use foldcam::machine::{OperationMapping, Perforation};
use foldcam::pattern::{Assignment, CreasePattern, VertexId};
use glam::DVec2;

/// Cut 3 mm, bridge 1 mm, min dash 0.5 mm, web 0.4 mm, vertex clearance 0.5 mm, kerf 0.2 mm;
/// mountains and valleys perforated, flat skipped, outline cut; no offset, tabs or lead-ins.
pub fn options() -> PlanOptions {
    PlanOptions {
        mapping: OperationMapping {
            mountain: Some(Operation::Perforate),
            valley: Some(Operation::Perforate),
            unassigned: Some(Operation::Perforate),
            flat: None,
            boundary: Some(Operation::Cut),
        },
        perforation: Perforation {
            cut_mm: 3.0,
            bridge_mm: 1.0,
            min_dash_mm: 0.5,
            min_web_mm: 0.4,
            vertex_clearance_mm: 0.5,
        },
        kerf_mm: 0.2,
        kerf_offset: false,
        resolution_mm: 0.001,
        two_sided: false,
        tabs: None,
        lead_in_mm: None,
        margin_mm: 5.0,
        optimize: true,
        notes: Vec::new(),
        placement: Default::default(),
    }
}

/// Adds a closed polygon of `kind` edges through `points`; returns its vertices.
pub fn polygon(cp: &mut CreasePattern, points: &[DVec2], kind: Assignment) -> Vec<VertexId> {
    let v: Vec<VertexId> = points.iter().map(|&p| cp.add_vertex(p)).collect();
    for i in 0..v.len() {
        cp.add_edge(v[i], v[(i + 1) % v.len()], kind);
    }
    v
}

/// An axis-aligned square's corners, counter-clockwise.
pub fn square(lo: f64, hi: f64) -> Vec<DVec2> {
    vec![
        DVec2::new(lo, lo),
        DVec2::new(hi, lo),
        DVec2::new(hi, hi),
        DVec2::new(lo, hi),
    ]
}

/// Distance from `p` to segment `a–b`.
pub fn point_segment(p: DVec2, a: DVec2, b: DVec2) -> f64 {
    let d = b - a;
    let t = if d.length_squared() > 0.0 {
        ((p - a).dot(d) / d.length_squared()).clamp(0.0, 1.0)
    } else {
        0.0
    };
    p.distance(a + d * t)
}

/// Distance between segments `a0–a1` and `b0–b1` (zero when they cross).
pub fn segment_segment(a0: DVec2, a1: DVec2, b0: DVec2, b1: DVec2) -> f64 {
    let (r, s) = (a1 - a0, b1 - b0);
    let denom = r.perp_dot(s);
    // Nearly parallel segments (collinear ones included) are measured by their end points:
    // the crossing parameters of two almost collinear segments are rounding noise.
    if denom.abs() > 1e-9 * r.length() * s.length() {
        let t = (b0 - a0).perp_dot(s) / denom;
        let u = (b0 - a0).perp_dot(r) / denom;
        if (0.0..=1.0).contains(&t) && (0.0..=1.0).contains(&u) {
            return 0.0;
        }
    }
    point_segment(a0, b0, b1)
        .min(point_segment(a1, b0, b1))
        .min(point_segment(b0, a0, a1))
        .min(point_segment(b1, a0, a1))
}

/// Signed area of a polyline ring (a repeated last point is harmless).
pub fn area(ring: &[DVec2]) -> f64 {
    let n = ring.len();
    0.5 * (0..n)
        .map(|i| ring[i].perp_dot(ring[(i + 1) % n]))
        .sum::<f64>()
}

/// The toolpaths of `role`, with their indices.
pub fn with_role(paths: &[Toolpath], role: ContourRole) -> Vec<(usize, &Toolpath)> {
    paths
        .iter()
        .enumerate()
        .filter(|(_, p)| p.role == role)
        .collect()
}

/// Axis-aligned bounds of the points.
pub fn bounds(points: impl IntoIterator<Item = DVec2>) -> (DVec2, DVec2) {
    points.into_iter().fold(
        (DVec2::splat(f64::INFINITY), DVec2::splat(f64::NEG_INFINITY)),
        |(lo, hi), p| (lo.min(p), hi.max(p)),
    )
}

/// A closed polyline: at least a triangle, last point equal to the first.
pub fn is_closed(stroke: &[DVec2]) -> bool {
    stroke.len() >= 4 && stroke.first() == stroke.last()
}

/// Every cut edge's points at the parameters `ts` lie within `tolerance` of some cut stroke.
pub fn assert_cut_edges_covered(
    cp: &CreasePattern,
    paths: &[Toolpath],
    ts: &[f64],
    tolerance: f64,
) {
    let segments: Vec<(DVec2, DVec2)> = paths
        .iter()
        .filter(|p| p.op == Operation::Cut)
        .flat_map(|p| p.strokes.iter())
        .flat_map(|s| s.windows(2).map(|w| (w[0], w[1])))
        .collect();
    for e in cp.edge_ids() {
        if !cp.edges[e.index()].assignment.is_boundary_like() {
            continue;
        }
        let (a, b) = cp.segment(e);
        for &t in ts {
            let p = a.lerp(b, t);
            let d = segments
                .iter()
                .map(|&(s, q)| point_segment(p, s, q))
                .fold(f64::INFINITY, f64::min);
            assert!(
                d <= tolerance,
                "cut edge {e} at {p} is {d} mm from every cut stroke"
            );
        }
    }
}
