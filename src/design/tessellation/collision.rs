//! Collision rows: faces of the folded form that pass through each other, or approach each
//! other, are pushed apart by active inequality rows in the solve. Tachi (2014) §3.2 handles
//! only vertex-adjacent faces in the solve (eq. 5–7, [`vertex_penalty`](super::vertex_penalty))
//! and leaves global collisions (type 3) to the user; on strongly curved surfaces the tucks
//! then grow into their neighbours near the boundary (his Fig. 14), which these rows try to
//! prevent.
//!
//! For a pair of triangles that do not share an edge (faces sharing an edge are kept apart by
//! the fold-angle rows of eq. 3):
//! - **crossing**: the triangle whose part beyond the other's plane is the shallower (the
//!   smaller "straddle") has its deepest vertex `p` on that side pushed back to the gap
//!   `c` ([`Limits::collision_gap`](super::Limits::collision_gap)) in front of the plane:
//!   `g = σ n·(p − q) − c`, with `n` the other
//!   triangle's unit normal, `q` the foot of `p` on its plane and σ the side the rest of the
//!   triangle lies on. Once every vertex of one triangle lies on one side of the other's
//!   plane the two cannot cross, so the row is a sufficient condition.
//! - **approaching**: a vertex whose foot falls inside the other triangle and that lies
//!   within `hold · c` of its plane gets the same row on its current side (the
//!   hysteresis of the other inequality rows, see [`Limits::hold`](super::Limits::hold)).
//!
//! The gradient is exact: moving `p` changes `n·(p − q)` by `n`, moving a vertex `b_i` of the
//! other triangle moves its plane at `q` by `w_i` (the barycentric coordinates of `q`), and the
//! normal's rotation does not change the distance to first order (`p − q` is parallel to
//! `n`, its change perpendicular).
//!
//! Pairs sharing a vertex are left to the vertex-adjacent penalty (eq. 5–7), which decides
//! legality from the fold direction; here the side would be a guess.
//!
//! Measured (examples/tessellation_collisions.rs, remeshed caps, truncated stars, stainless
//! limits): the rows keep the folded form free of crossings for longer (the 2,022-face cap at
//! shrink 0.45 and a 0.5 mm gap: 15 crossing pairs sharing no vertex instead of 511) but the
//! solve then stalls with developability defects of 0.05–0.16 rad (also on the 432-face cap
//! at shrinks 0.8–0.6, gaps 0.1–0.5 mm): near the rim the tucks must hide a larger share of
//! the sheet than near the pole (a flat sheet mapped onto a sphere cannot keep one scale;
//! over a 60° cap the stereographic scale changes by 1/cos²(30°) = 4/3), more than the room
//! between neighbouring tucks allows, so pushing them apart fights eq. 1. The rows are
//! therefore off by default.

use std::ops::ControlFlow;

use glam::DVec3;

use super::intersect::triangles_cross;
use crate::geom::{Box3, overlapping_boxes, triangle_box};

/// One collision row: its value and its Jacobian blocks.
pub type Contact = (f64, Vec<(u32, DVec3)>);

/// Candidate pairs `(a, b)`, `a < b`, of triangles whose bounding boxes come within `gap`
/// and that share no vertex, by a sweep along x.
fn candidates(x: &[DVec3], triangles: &[[u32; 3]], gap: f64) -> Vec<(usize, usize)> {
    let boxes: Vec<Box3> = triangles
        .iter()
        .map(|t| triangle_box(&t.map(|v| x[v as usize]), gap))
        .collect();
    let mut out = Vec::new();
    overlapping_boxes(&boxes, |a, b| {
        if !triangles[a].iter().any(|v| triangles[b].contains(v)) {
            out.push((a.min(b), a.max(b)));
        }
        ControlFlow::Continue(())
    });
    out
}

/// The collision rows at `x` (module docs) for the gap `gap` (mm); `hold` as in
/// [`Limits::hold`](super::Limits::hold).
pub fn rows(x: &[DVec3], triangles: &[[u32; 3]], gap: f64, hold: f64) -> Vec<Contact> {
    let mut out = Vec::new();
    for (a, b) in candidates(x, triangles, hold * gap) {
        let (ia, ib) = (triangles[a], triangles[b]);
        let ta = ia.map(|v| x[v as usize]);
        let tb = ib.map(|v| x[v as usize]);
        if triangles_cross(&ta, &tb, 0.0) {
            let pa = push_back(&ia, &ta, &ib, &tb, gap);
            let pb = push_back(&ib, &tb, &ia, &ta, gap);
            match (pa, pb) {
                (Some(pa), Some(pb)) => out.push(if pa.1 <= pb.1 { pa.0 } else { pb.0 }),
                (Some(p), None) | (None, Some(p)) => out.push(p.0),
                (None, None) => {}
            }
            continue;
        }
        for (iv, tv, iw, tw) in [(&ia, &ta, &ib, &tb), (&ib, &tb, &ia, &ta)] {
            for k in 0..3 {
                if let Some(row) = near(iv[k], tv[k], iw, tw, gap, hold) {
                    out.push(row);
                }
            }
        }
    }
    out
}

/// The unit normal of `t`, `None` when degenerate.
fn normal(t: &[DVec3; 3]) -> Option<DVec3> {
    let n = (t[1] - t[0]).cross(t[2] - t[0]);
    (n.length() > 0.0).then(|| n.normalize())
}

/// Barycentric coordinates of the foot of `p` on the plane of `t` (normal `n`).
fn barycentric(p: DVec3, t: &[DVec3; 3], n: DVec3) -> [f64; 3] {
    let area = (t[1] - t[0]).cross(t[2] - t[0]).dot(n);
    let w0 = (t[1] - p).cross(t[2] - p).dot(n) / area;
    let w1 = (t[2] - p).cross(t[0] - p).dot(n) / area;
    [w0, w1, 1.0 - w0 - w1]
}

/// The row keeping vertex `p` (index `v`) at `gap` on side `sigma` of the plane of `t`
/// (indices `it`, normal `n`).
fn row(v: u32, p: DVec3, it: &[u32; 3], t: &[DVec3; 3], n: DVec3, sigma: f64, gap: f64) -> Contact {
    let w = barycentric(p, t, n);
    let value = sigma * n.dot(p - t[0]) - gap;
    let mut entries = vec![(v, sigma * n)];
    for k in 0..3 {
        entries.push((it[k], -sigma * w[k] * n));
    }
    (value, entries)
}

/// For crossing triangles: the row pushing the deepest vertex of `s` on its minority side of
/// the plane of `t` back, with that depth (the straddle); `None` when `t` is degenerate.
fn push_back(
    is: &[u32; 3],
    s: &[DVec3; 3],
    it: &[u32; 3],
    t: &[DVec3; 3],
    gap: f64,
) -> Option<(Contact, f64)> {
    let n = normal(t)?;
    let d = s.map(|p| n.dot(p - t[0]));
    let (hi, lo) = (
        d.iter().copied().fold(f64::MIN, f64::max),
        d.iter().copied().fold(f64::MAX, f64::min),
    );
    // The minority side is the shallower one; its deepest vertex goes back.
    let (sigma, k) = if hi <= -lo {
        (-1.0, (0..3).max_by(|&i, &j| d[i].total_cmp(&d[j]))?)
    } else {
        (1.0, (0..3).min_by(|&i, &j| d[i].total_cmp(&d[j]))?)
    };
    Some((row(is[k], s[k], it, t, n, sigma, gap), hi.min(-lo)))
}

/// The row for vertex `p` (index `v`) approaching triangle `t` from its current side: its foot
/// inside `t` and closer than `hold · gap` to its plane.
fn near(v: u32, p: DVec3, it: &[u32; 3], t: &[DVec3; 3], gap: f64, hold: f64) -> Option<Contact> {
    let n = normal(t)?;
    let d = n.dot(p - t[0]);
    if d.abs() >= hold * gap || barycentric(p, t, n).iter().any(|&w| w < 0.0) {
        return None;
    }
    Some(row(v, p, it, t, n, if d >= 0.0 { 1.0 } else { -1.0 }, gap))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two separate triangles: `[0, 1, 2]` in the plane z = 0 and `[3, 4, 5]` poking its
    /// vertex 3 down through it.
    fn poke(depth: f64) -> Vec<DVec3> {
        vec![
            DVec3::new(0.0, 0.0, 0.0),
            DVec3::new(10.0, 0.0, 0.0),
            DVec3::new(0.0, 10.0, 0.0),
            DVec3::new(2.0, 3.0, -depth),
            DVec3::new(3.0, 2.0, 4.0),
            DVec3::new(2.5, 2.5, 5.0),
        ]
    }

    const TRIS: [[u32; 3]; 2] = [[0, 1, 2], [3, 4, 5]];

    /// The gap of the tests, mm.
    const GAP: f64 = 0.02;

    #[test]
    fn a_crossing_vertex_is_pushed_back_to_the_side_of_its_triangle() {
        let x = poke(0.3);
        let rows = rows(&x, &TRIS, GAP, 0.5);
        assert_eq!(rows.len(), 1);
        let (value, entries) = &rows[0];
        // Vertex 3 is 0.3 below the plane and must come GAP above it.
        assert!((value - (-0.3 - GAP)).abs() < 1e-12, "{value}");
        let moved = entries.iter().find(|(v, _)| *v == 3).expect("vertex 3");
        assert!((moved.1 - DVec3::Z).length() < 1e-12);
        // Apart, far: no row; within hold · GAP above: a row on the upper side.
        assert!(super::rows(&poke(-1.0), &TRIS, GAP, 0.5).is_empty());
        let close = super::rows(&poke(-0.004), &TRIS, GAP, 0.5);
        assert_eq!(close.len(), 1);
        assert!((close[0].0 - (0.004 - GAP)).abs() < 1e-12);
        // The independent intersection check agrees on which state crosses.
        let crossing = |x: &[DVec3]| {
            crate::design::tessellation::intersect::intersecting_triangles(x, &TRIS, 1e-6)
                .unwrap()
                .len()
        };
        assert_eq!((crossing(&poke(0.3)), crossing(&poke(-0.004))), (1, 0));
    }

    #[test]
    fn rows_match_finite_differences() {
        for x in [poke(0.3), poke(-0.004)] {
            let base = rows(&x, &TRIS, GAP, 0.5);
            let h = 1e-7;
            for v in 0..x.len() {
                for c in 0..3 {
                    let (mut up, mut down) = (x.clone(), x.clone());
                    up[v][c] += h;
                    down[v][c] -= h;
                    let (ru, rd) = (rows(&up, &TRIS, GAP, 0.5), rows(&down, &TRIS, GAP, 0.5));
                    let numeric = (ru[0].0 - rd[0].0) / (2.0 * h);
                    let analytic = base[0]
                        .1
                        .iter()
                        .filter(|(w, _)| *w as usize == v)
                        .map(|(_, g)| g[c])
                        .sum::<f64>();
                    assert!(
                        (numeric - analytic).abs() < 1e-6,
                        "vertex {v} axis {c}: {numeric} vs {analytic}"
                    );
                }
            }
        }
    }
}
