//! Isometric unfolding: faces of a folded surface laid flat one at a time, breadth-first from
//! a root face, each by the rigid map that sends an edge it shares with an already placed face
//! onto that edge's flat image. Lengths and angles inside every face are kept (to rounding);
//! what happens where placements disagree (a non-developable vertex) is the caller's choice.
//!
//! Two callers: FOLD import (`formats::fold::unfold`: polygon faces, mirrored faces, several
//! pieces, length relaxation) and tessellation (`design::tessellation::unfold`: triangles of
//! one disk). They share the visiting order ([`breadth_first`]) and the placement maps
//! ([`anchor_map`] for a face given its normal, [`apex`] for a triangle's third corner).

use std::collections::VecDeque;

use glam::{DVec2, DVec3};

/// One face reached by [`breadth_first`]: the face, and the face and edge it was reached
/// across (`None` for the root).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Reached<E> {
    /// The face reached.
    pub face: usize,
    /// The placed face it shares `edge` with, and that edge; `None` for the root.
    pub across: Option<(usize, E)>,
}

/// The faces reachable from `root` across shared edges, in breadth-first order, `root` first.
///
/// `neighbours(f, out)` appends to `out` every `(g, edge)` with `g` a face sharing `edge`
/// with `f`, in the order they are to be tried; a face is reached once, across the first such
/// edge met, and is marked in `visited` (indexed by face) when reached. A face already marked
/// on entry is never reached (nor is `root`, if it is marked). The caller places the faces in
/// the returned order: each face's parent comes before it.
pub fn breadth_first<E: Copy>(
    root: usize,
    visited: &mut [bool],
    mut neighbours: impl FnMut(usize, &mut Vec<(usize, E)>),
) -> Vec<Reached<E>> {
    let mut order = Vec::new();
    if visited.get(root).is_none_or(|&v| v) {
        return order;
    }
    visited[root] = true;
    order.push(Reached {
        face: root,
        across: None,
    });
    let mut queue = VecDeque::from([root]);
    let mut next = Vec::new();
    while let Some(f) = queue.pop_front() {
        next.clear();
        neighbours(f, &mut next);
        for &(g, edge) in &next {
            if visited.get(g).is_none_or(|&v| v) {
                continue;
            }
            visited[g] = true;
            order.push(Reached {
                face: g,
                across: Some((f, edge)),
            });
            queue.push_back(g);
        }
    }
    order
}

/// The rigid map of the plane through `from.0` with unit normal `normal` onto the flat plane
/// that sends the 3D segment `from` onto the 2D segment `to` (of the same length):
/// `P = A + E·((p − a)·e) + W·((p − a)·w)`, with `e` the unit vector from `a` to `b`,
/// `w = n × e`, `E` the unit vector from `A` to `B` and `W` = `E` turned by +90° (−90° when
/// `mirror`). A polygon counter-clockwise about `normal` comes out counter-clockwise (unless
/// mirrored). A zero-length `from` takes any direction perpendicular to `normal`, a zero-length
/// `to` the +x axis.
pub fn anchor_map(
    normal: DVec3,
    (pa, pb): (DVec3, DVec3),
    (qa, qb): (DVec2, DVec2),
    mirror: bool,
) -> impl Fn(DVec3) -> DVec2 + use<> {
    let e = (pb - pa)
        .try_normalize()
        .unwrap_or_else(|| normal.any_orthonormal_vector());
    let w = normal.cross(e);
    let big_e = (qb - qa).try_normalize().unwrap_or(DVec2::X);
    let big_w = if mirror { -big_e.perp() } else { big_e.perp() };
    move |p: DVec3| qa + big_e * (p - pa).dot(e) + big_w * (p - pa).dot(w)
}

/// The flat position of corner `b` of the 3D triangle `(s, e, b)` once the edge `s e` lies on
/// the flat edge `fs → fe`: on the left of `fs → fe`, at the same distance along the edge and
/// from it as in 3D. `s ≠ e` and `fs ≠ fe` (else the result is NaN).
pub fn apex(s: DVec3, e: DVec3, b: DVec3, fs: DVec2, fe: DVec2) -> DVec2 {
    let axis = (e - s).normalize();
    let along = (b - s).dot(axis);
    let height = ((b - s) - along * axis).length();
    let u = (fe - fs).normalize();
    fs + along * u + height * u.perp()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn breadth_first_reaches_a_chain_in_order_and_skips_visited_faces() {
        // Faces 0–1–2–3 in a row, 4 joined to 1; face 3 already placed.
        let links = [vec![1], vec![0, 2, 4], vec![1, 3], vec![2], vec![1]];
        let mut visited = vec![false, false, false, true, false];
        let order = breadth_first(0, &mut visited, |f, out| {
            out.extend(links[f].iter().map(|&g| (g, (f, g))));
        });
        let faces: Vec<usize> = order.iter().map(|r| r.face).collect();
        assert_eq!(faces, [0, 1, 2, 4]);
        assert_eq!(order[0].across, None);
        assert_eq!(order[3].across, Some((1, (1, 4))));
        assert!(visited.iter().all(|&v| v));
        assert!(breadth_first(0, &mut visited, |_, _: &mut Vec<(usize, ())>| {}).is_empty());
    }

    #[test]
    fn maps_keep_lengths_and_place_the_apex_on_the_left() {
        // A right triangle standing upright over the x axis: (0,0,0), (3,0,0), (0,0,4).
        let (s, e, b) = (
            DVec3::ZERO,
            DVec3::new(3.0, 0.0, 0.0),
            DVec3::new(0.0, 0.0, 4.0),
        );
        let (fs, fe) = (DVec2::new(1.0, 1.0), DVec2::new(1.0, 4.0));
        let flat = apex(s, e, b, fs, fe);
        // Laid along +y from (1, 1), the corner over s goes 4 to the left: to (−3, 1).
        assert!((flat - DVec2::new(-3.0, 1.0)).length() < 1e-12, "{flat}");
        // The normal (e − s) × (b − s) points along −y; the anchor map agrees with the apex.
        let n = (e - s).cross(b - s).normalize();
        let map = anchor_map(n, (s, e), (fs, fe), false);
        assert!((map(b) - flat).length() < 1e-12);
        assert!((map(e) - fe).length() < 1e-12);
        let mirrored = anchor_map(n, (s, e), (fs, fe), true);
        assert!((mirrored(b) - DVec2::new(5.0, 1.0)).length() < 1e-12);
    }
}
