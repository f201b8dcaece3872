//! The painter's order of faces: which face to draw first so nearer faces cover farther ones.
//!
//! Sorting by the depth of face centroids alone fails for a pop-up card: the base page is one
//! large face whose centroid lies nearer the eye than a small piece standing on it near the
//! back, so the base would be painted over the piece. The order here therefore starts from
//! the centroid order (far first) and refines it with plane tests for every pair of faces
//! whose projected bounding boxes overlap:
//!
//! 1. if every corner of `b` lies on the far side of `a`'s plane (or on it), `b` is drawn
//!    before `a`; if every corner lies on the near side, after it;
//! 2. otherwise (`b` straddles `a`'s plane) the same test with the roles swapped;
//! 3. otherwise (the faces intersect, or lie in one plane) the state's `face_orders` decides
//!    if it names the pair (FOLD: `[f, g, +1]` puts `f` on the side of `g` that `g`'s normal
//!    points to, −1 on the other side); else no constraint is added.
//!
//! The constraints are resolved by a topological sort that always draws the farthest ready
//! face (by centroid) next; a cycle (faces overlapping cyclically, A over B over C over A) is
//! broken at its farthest face, which is then drawn in centroid order. Limits: intersecting
//! faces and cycles can still be drawn wrong (a z-buffer would be needed); coplanar faces
//! that `face_orders` does not name keep the centroid order; the pair tests cost
//! O(n²) and are skipped above [`MAX_REFINED_FACES`] faces, which then use the centroid order.

use std::cmp::Reverse;
use std::collections::{BinaryHeap, HashMap};

use glam::{DVec2, DVec3};

use super::view3d::Camera;
use crate::geom::tolerance::RELATIVE;
use crate::pattern::FaceId;

/// Largest face count for which pairwise plane tests refine the centroid order.
pub const MAX_REFINED_FACES: usize = 3000;

/// Relative tolerance of the plane tests, as a share of the two faces' extent.
const PLANE_TOLERANCE: f64 = 1e-7;

/// One face as the sorter sees it: its corners in 3D.
pub(crate) struct FaceGeometry {
    id: FaceId,
    corners: Vec<DVec3>,
    centroid_depth: f64,
    lo: DVec2,
    hi: DVec2,
    normal: DVec3,
}

impl FaceGeometry {
    /// The geometry of a face with the given outer corners (at least one) and normal.
    pub(crate) fn new(
        id: FaceId,
        corners: Vec<DVec3>,
        normal: DVec3,
        camera: &Camera,
    ) -> FaceGeometry {
        let centroid = corners.iter().sum::<DVec3>() / corners.len().max(1) as f64;
        let first = corners.first().map_or(DVec2::ZERO, |&p| camera.screen(p));
        let (lo, hi) = corners.iter().fold((first, first), |(lo, hi), &p| {
            let s = camera.screen(p);
            (lo.min(s), hi.max(s))
        });
        FaceGeometry {
            id,
            centroid_depth: camera.depth(centroid),
            corners,
            lo,
            hi,
            normal: normal.normalize_or_zero(),
        }
    }
}

/// Stacking of face pairs, from FOLD's `faceOrders`: `(f, g)` → +1 when `f` lies on the side
/// of `g` that `g`'s normal points to, −1 on the other side.
type Stacking = HashMap<(FaceId, FaceId), i8>;

/// The order to draw `faces` in (indices into `faces`), far first; `orders` is the state's
/// `face_orders`.
pub(crate) fn paint_order(
    faces: &[FaceGeometry],
    camera: &Camera,
    orders: &[(FaceId, FaceId, i8)],
) -> Vec<usize> {
    let n = faces.len();
    let mut by_depth: Vec<usize> = (0..n).collect();
    by_depth.sort_by(|&a, &b| faces[a].centroid_depth.total_cmp(&faces[b].centroid_depth));
    if n > MAX_REFINED_FACES {
        return by_depth;
    }
    let mut rank = vec![0; n];
    for (r, &f) in by_depth.iter().enumerate() {
        rank[f] = r;
    }
    let stacking: Stacking = orders
        .iter()
        .filter(|o| o.2 != 0)
        .map(|&(f, g, s)| ((f, g), s))
        .collect();
    let mut after: Vec<Vec<usize>> = vec![Vec::new(); n];
    let mut pending = vec![0usize; n];
    for a in 0..n {
        for b in a + 1..n {
            if let Some((first, then)) = pair_order(&faces[a], &faces[b], camera, &stacking)
                .map(|a_first| if a_first { (a, b) } else { (b, a) })
            {
                after[first].push(then);
                pending[then] += 1;
            }
        }
    }
    topological(&by_depth, &rank, &after, pending)
}

/// Kahn's algorithm, drawing the farthest ready face next and breaking cycles at the farthest
/// remaining face.
fn topological(
    by_depth: &[usize],
    rank: &[usize],
    after: &[Vec<usize>],
    mut pending: Vec<usize>,
) -> Vec<usize> {
    let n = by_depth.len();
    let mut done = vec![false; n];
    let mut ready: BinaryHeap<Reverse<usize>> = (0..n)
        .filter(|&f| pending[f] == 0)
        .map(|f| Reverse(rank[f]))
        .collect();
    let mut order = Vec::with_capacity(n);
    let mut next_forced = 0;
    while order.len() < n {
        let Some(Reverse(r)) = ready.pop() else {
            while done[by_depth[next_forced]] {
                next_forced += 1;
            }
            ready.push(Reverse(next_forced));
            continue;
        };
        let f = by_depth[r];
        if done[f] {
            continue;
        }
        done[f] = true;
        order.push(f);
        for &g in &after[f] {
            pending[g] = pending[g].saturating_sub(1);
            if pending[g] == 0 && !done[g] {
                ready.push(Reverse(rank[g]));
            }
        }
    }
    order
}

/// `Some(true)` if `a` must be drawn before `b`, `Some(false)` if after, `None` if the faces
/// do not overlap on screen or cannot be ordered by their planes or the stacking.
fn pair_order(
    a: &FaceGeometry,
    b: &FaceGeometry,
    camera: &Camera,
    stacking: &Stacking,
) -> Option<bool> {
    let overlap = a.lo.x < b.hi.x && b.lo.x < a.hi.x && a.lo.y < b.hi.y && b.lo.y < a.hi.y;
    if !overlap {
        return None;
    }
    let extent = (a.hi - a.lo).max(b.hi - b.lo).max_element();
    let tol = PLANE_TOLERANCE * extent.max(f64::MIN_POSITIVE);
    match side_of(a, b, camera, tol) {
        Some(Side::Far) => Some(false),
        Some(Side::Near) => Some(true),
        None => match side_of(b, a, camera, tol) {
            Some(Side::Far) => Some(true),
            Some(Side::Near) => Some(false),
            None => stacked(a, b, camera, stacking),
        },
    }
}

/// The order of `a` and `b` from the stacking, if it names them: the face on the eye's side
/// of the other is drawn last.
fn stacked(
    a: &FaceGeometry,
    b: &FaceGeometry,
    camera: &Camera,
    stacking: &Stacking,
) -> Option<bool> {
    let eye_side = |f: &FaceGeometry| f.normal.dot(camera.toward_eye).signum();
    if let Some(&s) = stacking.get(&(a.id, b.id)) {
        // `a` lies on the side of `b` that `b`'s normal points to (s > 0) or the other side;
        // it is drawn first when that side faces away from the eye.
        return Some(f64::from(s) * eye_side(b) < 0.0);
    }
    let &s = stacking.get(&(b.id, a.id))?;
    Some(f64::from(s) * eye_side(a) > 0.0)
}

enum Side {
    Far,
    Near,
}

/// Where `other` lies relative to the plane of `face`, seen from the eye; `None` when it
/// straddles the plane, lies in it, or the plane is seen edge-on.
fn side_of(face: &FaceGeometry, other: &FaceGeometry, camera: &Camera, tol: f64) -> Option<Side> {
    let facing = face.normal.dot(camera.toward_eye);
    if facing.abs() < RELATIVE {
        return None;
    }
    let origin = *face.corners.first()?;
    let toward_eye = face.normal * facing.signum();
    let (mut near, mut far) = (false, false);
    for &p in &other.corners {
        let s = (p - origin).dot(toward_eye);
        near |= s > tol;
        far |= s < -tol;
    }
    match (near, far) {
        (true, false) => Some(Side::Near),
        (false, true) => Some(Side::Far),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn quad(corners: [[f64; 3]; 4], camera: &Camera) -> FaceGeometry {
        let c: Vec<DVec3> = corners.iter().map(|&p| DVec3::from_array(p)).collect();
        let normal = (c[1] - c[0]).cross(c[3] - c[0]);
        FaceGeometry::new(FaceId(0), c, normal, camera)
    }

    #[test]
    fn a_piece_standing_near_the_back_of_a_large_base_is_drawn_after_it() {
        let camera = Camera::new(30.0, 25.0);
        let base = quad(
            [
                [0.0, 0.0, 0.0],
                [100.0, 0.0, 0.0],
                [100.0, 100.0, 0.0],
                [0.0, 100.0, 0.0],
            ],
            &camera,
        );
        let piece = quad(
            [
                [40.0, 80.0, 0.0],
                [60.0, 80.0, 0.0],
                [60.0, 80.0, 5.0],
                [40.0, 80.0, 5.0],
            ],
            &camera,
        );
        assert!(
            piece.centroid_depth < base.centroid_depth,
            "centroids alone fail"
        );
        assert_eq!(paint_order(&[piece, base], &camera, &[]), vec![1, 0]);
    }

    #[test]
    fn cycles_and_empty_input_terminate() {
        let camera = Camera::new(0.0, 90.0);
        assert!(paint_order(&[], &camera, &[]).is_empty());
        // Three slanted strips, each over the next: a cycle of constraints.
        let strip = |angle: f64| {
            let (s, c) = angle.to_radians().sin_cos();
            let d = DVec3::new(c, s, 0.0);
            let across = DVec3::new(-s, c, 0.0);
            let p = |t: f64, w: f64, z: f64| (t * d + w * across + DVec3::Z * z).to_array();
            quad(
                [
                    p(-10.0, -1.0, 0.0),
                    p(10.0, -1.0, 2.0),
                    p(10.0, 1.0, 2.0),
                    p(-10.0, 1.0, 0.0),
                ],
                &camera,
            )
        };
        let faces = [strip(0.0), strip(120.0), strip(240.0)];
        let mut order = paint_order(&faces, &camera, &[]);
        order.sort_unstable();
        assert_eq!(order, vec![0, 1, 2]);
    }
}
