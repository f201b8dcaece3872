//! The sheet outline: validation, and the cut of a non-convex outline into convex pieces.
//!
//! The simulator's geometry (Miyazaki et al. 1992, §4.2–4.3 face splitting, the §4.1 overlap tests) works on convex
//! faces, where a line splits a face into at most two. A non-convex sheet (any simple polygon)
//! therefore starts as several convex faces of the face tree, children of the sheet made at
//! step 0: a fold line crossing the sheet several times then gives one face per piece on
//! either side. The pieces come from ear clipping (a triangulation) followed by merging
//! neighbouring pieces whose union stays convex (Hertel and Mehlhorn's greedy rule).

use glam::DVec2;

use super::FoldError;
use super::geometry::{Line2, double_area};
use crate::geom::segment::segment_distance;

/// Errors unless the counter-clockwise `ring` is a simple polygon with a positive area and
/// distinct corners.
pub(super) fn check_simple(ring: &[DVec2], tol: f64) -> Result<(), FoldError> {
    let n = ring.len();
    if double_area(ring) <= tol * tol {
        return Err(FoldError::Sheet("has no area".into()));
    }
    for i in 0..n {
        if Line2::through(ring[i], ring[(i + 1) % n], tol).is_none() {
            return Err(FoldError::Sheet(format!("has two equal corners ({i})")));
        }
    }
    for i in 0..n {
        for j in i + 1..n {
            let adjacent = j == i + 1 || (i == 0 && j == n - 1);
            let (a, b) = (ring[i], ring[(i + 1) % n]);
            let (c, d) = (ring[j], ring[(j + 1) % n]);
            if !adjacent && segment_distance(a, b, c, d) <= tol {
                return Err(FoldError::Sheet(format!(
                    "outline crosses or touches itself (sides {i} and {j})"
                )));
            }
        }
    }
    Ok(())
}

/// Whether the counter-clockwise ring turns left (or goes straight) at every corner.
pub(super) fn is_convex(ring: &[DVec2], tol: f64) -> bool {
    let n = ring.len();
    (0..n).all(|i| {
        Line2::through(ring[i], ring[(i + 1) % n], 0.0)
            .is_none_or(|edge| edge.side(ring[(i + 2) % n]) >= -tol)
    })
}

/// Convex pieces covering the simple counter-clockwise `ring` (as lists of its corner
/// indices, counter-clockwise), meeting along diagonals between its corners.
pub(super) fn convex_pieces(ring: &[DVec2], tol: f64) -> Result<Vec<Vec<usize>>, FoldError> {
    let mut pieces = ear_clip(ring, tol)?;
    // Merge two pieces sharing a diagonal while their union is convex.
    let mut merged = true;
    while merged {
        merged = false;
        'pairs: for a in 0..pieces.len() {
            for b in a + 1..pieces.len() {
                if let Some(union) = union(&pieces[a], &pieces[b]) {
                    let poly: Vec<DVec2> = union.iter().map(|&i| ring[i]).collect();
                    if is_convex(&poly, tol) {
                        pieces[a] = union;
                        pieces.swap_remove(b);
                        merged = true;
                        break 'pairs;
                    }
                }
            }
        }
    }
    Ok(pieces)
}

/// Triangles of the ring by ear clipping, as corner indices.
fn ear_clip(ring: &[DVec2], tol: f64) -> Result<Vec<Vec<usize>>, FoldError> {
    let mut left: Vec<usize> = (0..ring.len()).collect();
    let mut out = Vec::new();
    while left.len() > 3 {
        let m = left.len();
        let ear = (0..m).find(|&k| {
            let (i, j, l) = (left[(k + m - 1) % m], left[k], left[(k + 1) % m]);
            let (a, b, c) = (ring[i], ring[j], ring[l]);
            let turn = (b - a).perp_dot(c - b);
            turn > tol * ((b - a).length() + (c - b).length())
                && left
                    .iter()
                    .filter(|&&v| v != i && v != j && v != l)
                    .all(|&v| !in_triangle(ring[v], a, b, c))
        });
        let Some(k) = ear else {
            return Err(FoldError::Sheet(
                "outline cannot be cut into convex faces".into(),
            ));
        };
        out.push(vec![left[(k + m - 1) % m], left[k], left[(k + 1) % m]]);
        left.remove(k);
    }
    out.push(left);
    Ok(out)
}

/// Whether `p` lies in the closed counter-clockwise triangle `a b c`.
fn in_triangle(p: DVec2, a: DVec2, b: DVec2, c: DVec2) -> bool {
    (b - a).perp_dot(p - a) >= 0.0
        && (c - b).perp_dot(p - b) >= 0.0
        && (a - c).perp_dot(p - c) >= 0.0
}

/// The union of two counter-clockwise pieces sharing a side (`u → v` in `a`, `v → u` in
/// `b`), or `None` if they share none.
fn union(a: &[usize], b: &[usize]) -> Option<Vec<usize>> {
    let (na, nb) = (a.len(), b.len());
    for i in 0..na {
        let (u, v) = (a[i], a[(i + 1) % na]);
        if let Some(j) = (0..nb).find(|&j| b[j] == v && b[(j + 1) % nb] == u) {
            // a from v round to u, then b from u (exclusive) round to v (exclusive).
            let mut out: Vec<usize> = (1..=na).map(|k| a[(i + k) % na]).collect();
            out.extend((2..nb).map(|k| b[(j + k) % nb]));
            return Some(out);
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ring(points: &[[f64; 2]]) -> Vec<DVec2> {
        points.iter().map(|p| DVec2::from(*p)).collect()
    }

    #[test]
    fn an_l_shape_is_cut_into_two_convex_pieces_of_its_area() {
        let l = ring(&[
            [0., 0.],
            [100., 0.],
            [100., 40.],
            [40., 40.],
            [40., 100.],
            [0., 100.],
        ]);
        check_simple(&l, 1e-9).expect("simple");
        assert!(!is_convex(&l, 1e-9));
        let pieces = convex_pieces(&l, 1e-9).expect("pieces");
        assert_eq!(pieces.len(), 2);
        let mut area = 0.0;
        for p in &pieces {
            let poly: Vec<DVec2> = p.iter().map(|&i| l[i]).collect();
            assert!(is_convex(&poly, 1e-9));
            area += double_area(&poly) / 2.0;
        }
        assert!((area - 6400.0).abs() < 1e-9, "{area}");
    }

    #[test]
    fn a_bow_tie_is_refused() {
        let bow = ring(&[[0., 0.], [10., 10.], [10., 0.], [0., 10.]]);
        assert!(check_simple(&bow, 1e-9).is_err());
    }
}
