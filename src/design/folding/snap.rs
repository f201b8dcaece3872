//! The snapping rules of Miyazaki et al. (1992) §2.3 4) in the plane of the picked face (see [`super::drag`]).

use glam::DVec2;

use super::geometry::Line2;
use crate::geom::Segment;
use crate::geom::tolerance::ROUNDOFF;

/// Rule 2: a bisector laying a moving edge of the picked face onto another edge's line.
pub(super) fn edge_onto_edge(
    line: &Line2,
    p: &DVec2,
    own: &[Segment],
    edges: &[Segment],
    tol: f64,
    eps: f64,
) -> Option<Line2> {
    let moving = line.side(*p).signum();
    let mut best: Option<(f64, Line2)> = None;
    for &Segment { a, b } in own {
        // The part of the edge on the moving side.
        let (sa, sb) = (moving * line.side(a), moving * line.side(b));
        if sa <= eps && sb <= eps {
            continue;
        }
        let cut = |s: f64, t: f64, p: DVec2, q: DVec2| {
            if s >= -eps {
                p
            } else {
                p + (q - p) * (s / (s - t))
            }
        };
        let (a, b) = (cut(sa, sb, a, b), cut(sb, sa, b, a));
        if a.distance(b) <= tol {
            continue;
        }
        let (ra, rb) = (line.reflect(a), line.reflect(b));
        for &Segment { a: c, b: e } in edges {
            let Some(target) = Line2::through(c, e, eps) else {
                continue;
            };
            let (da, db) = (target.side(ra).abs(), target.side(rb).abs());
            if da > tol || db > tol {
                continue;
            }
            let Some(source) = Line2::through(a, b, eps) else {
                continue;
            };
            if let Some(l) = bisector_of(&source, &target, line, eps)
                && best.as_ref().is_none_or(|(d, _)| da + db < *d)
            {
                best = Some((da + db, l));
            }
        }
    }
    best.map(|(_, l)| l)
}

/// The bisector of two lines closest in direction to `near` (the midline when parallel).
///
/// Parallel lines give their midline only when it runs within 45° of `near`: an edge that
/// crosses the fold line at about a right angle lands on its own line (or a parallel one
/// close by) whatever the fold line's position, and the midline would turn the fold line by
/// about 90° — that is no snap.
fn bisector_of(a: &Line2, b: &Line2, near: &Line2, eps: f64) -> Option<Line2> {
    let cross = a.dir.perp_dot(b.dir);
    if cross.abs() < ROUNDOFF {
        if a.dir.dot(near.dir).abs() < std::f64::consts::FRAC_1_SQRT_2 {
            return None;
        }
        let foot = b.point + b.dir * b.dir.dot(a.point - b.point);
        let point = (a.point + foot) * 0.5;
        return Some(Line2 { point, dir: a.dir });
    }
    let t = (b.point - a.point).perp_dot(b.dir) / cross;
    let x = a.point + a.dir * t;
    [a.dir + b.dir, a.dir - b.dir]
        .into_iter()
        .filter_map(|d| Line2::through(x, x + d, eps))
        .max_by(|l, m| {
            l.dir
                .dot(near.dir)
                .abs()
                .total_cmp(&m.dir.dot(near.dir).abs())
        })
}

/// Rule 3: the line through the two vertices nearest the fold line (within `tol`).
pub(super) fn through_two(line: &Line2, vertices: &[DVec2], tol: f64, eps: f64) -> Option<Line2> {
    if tol <= 0.0 {
        return None;
    }
    let mut near: Vec<(f64, DVec2)> = vertices
        .iter()
        .map(|&v| (line.side(v).abs(), v))
        .filter(|(d, _)| *d <= tol)
        .collect();
    near.sort_by(|a, b| a.0.total_cmp(&b.0));
    let (_, first) = *near.first()?;
    let (_, second) = *near.iter().find(|(_, v)| v.distance(first) > 2.0 * tol)?;
    let l = Line2::through(first, second, eps)?;
    // Keep the original orientation so the moving side stays put.
    Some(if l.dir.dot(line.dir) < 0.0 {
        Line2 {
            point: l.point,
            dir: -l.dir,
        }
    } else {
        l
    })
}

/// Rule 4: the angle snapped to the nearest multiple of 30° or 45° within `tol` degrees.
pub(super) fn snap_angle(angle: f64, tol: f64) -> Option<f64> {
    if tol <= 0.0 || angle.abs() == 180.0 {
        return None;
    }
    let candidates = (1..=6)
        .map(|k| 30.0 * k as f64)
        .chain((1..=4).map(|k| 45.0 * k as f64));
    candidates
        .map(|c| c * angle.signum())
        .filter(|c| (c - angle).abs() <= tol && (c - angle).abs() > 0.0)
        .min_by(|a, b| (a - angle).abs().total_cmp(&(b - angle).abs()))
}
