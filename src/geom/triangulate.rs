//! Triangulating a polygon with holes: spade's constrained Delaunay triangulation (CDT) of the
//! rings' corners with every ring side as a constraint, keeping the triangles inside.
//!
//! **Method.** The corners of the outer ring and of every hole are bulk-loaded into a CDT with
//! the ring sides as constraint edges (`try_bulk_load_cdt`, which skips a constraint that would
//! cross another instead of panicking), so every ring side is a side of some triangle. A
//! triangle is kept when its centroid lies inside the outer ring and outside every hole
//! (even–odd rule). No Steiner points are added: every triangle corner is a ring corner, and
//! the triangles are returned counter-clockwise as indices into the rings' corners, numbered
//! outer ring first, then each hole in order.
//!
//! **Limits.** Corners that coincide are merged by spade; a ring that touches itself (a slit,
//! a corner visited twice) keeps one copy of the repeated corner, which is what a face of a
//! planar graph with a dangling edge needs. Rings whose sides cross each other are reported as
//! [`TriangulateError::CrossingSides`]: planarise the pattern first.

use std::collections::{HashMap, HashSet};

use glam::DVec2;
use spade::{ConstrainedDelaunayTriangulation, HasPosition, Point2, Triangulation};

use super::polygon::contains_point;

/// Why a polygon could not be triangulated.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum TriangulateError {
    /// A corner is not a finite number within spade's range.
    #[error("a corner at ({x}, {y}) cannot be triangulated (not finite or out of range)")]
    BadCorner {
        /// x of the corner.
        x: f64,
        /// y of the corner.
        y: f64,
    },
    /// Two sides of the rings cross each other.
    #[error("two sides of the polygon cross each other (planarise the pattern first)")]
    CrossingSides,
}

/// A ring corner carrying its index, so that triangles can name corners after spade reorders
/// them.
#[derive(Clone, Copy, Debug)]
struct Corner {
    at: Point2<f64>,
    index: usize,
}

impl HasPosition for Corner {
    type Scalar = f64;
    fn position(&self) -> Point2<f64> {
        self.at
    }
}

/// Triangulates the polygon bounded by `outer` (any orientation) with `holes`, returning
/// counter-clockwise triangles as indices into the corners numbered outer first, then each
/// hole's in order. A ring with fewer than three distinct corners yields no triangles.
pub fn triangulate_polygon(
    outer: &[DVec2],
    holes: &[Vec<DVec2>],
) -> Result<Vec<[usize; 3]>, TriangulateError> {
    let rings: Vec<&[DVec2]> = std::iter::once(outer)
        .chain(holes.iter().map(Vec::as_slice))
        .collect();
    // Repeated corners (a ring touching itself) are loaded once, under their first index.
    let mut first_at: HashMap<[u64; 2], usize> = HashMap::new();
    let mut corners = Vec::new();
    let mut constraints = HashSet::new();
    let mut start = 0;
    for ring in &rings {
        let index: Vec<usize> = ring
            .iter()
            .enumerate()
            .map(|(k, p)| {
                *first_at
                    .entry([p.x.to_bits(), p.y.to_bits()])
                    .or_insert_with(|| {
                        corners.push(Corner {
                            at: Point2::new(p.x, p.y),
                            index: start + k,
                        });
                        start + k
                    })
            })
            .collect();
        for k in 0..index.len() {
            let (a, b) = (index[k], index[(k + 1) % index.len()]);
            if a != b {
                constraints.insert([a.min(b), a.max(b)]);
            }
        }
        start += ring.len();
    }
    // spade numbers the loaded vertices in load order.
    let position: HashMap<usize, usize> = corners
        .iter()
        .enumerate()
        .map(|(i, c)| (c.index, i))
        .collect();
    let mut constraints: Vec<[usize; 2]> = constraints
        .into_iter()
        .map(|[a, b]| [position[&a], position[&b]])
        .collect();
    constraints.sort_unstable();
    if corners.len() < 3 {
        return Ok(Vec::new());
    }
    for c in &corners {
        if spade::validate_coordinate(c.at.x).is_err()
            || spade::validate_coordinate(c.at.y).is_err()
        {
            return Err(TriangulateError::BadCorner {
                x: c.at.x,
                y: c.at.y,
            });
        }
    }
    let mut crossing = false;
    let cdt: ConstrainedDelaunayTriangulation<Corner> =
        ConstrainedDelaunayTriangulation::try_bulk_load_cdt(corners, constraints, |_| {
            crossing = true
        })
        .map_err(|_| TriangulateError::CrossingSides)?;
    if crossing {
        return Err(TriangulateError::CrossingSides);
    }
    let mut triangles = Vec::new();
    for face in cdt.inner_faces() {
        let [a, b, c] = face.vertices().map(|v| *v.data());
        let [pa, pb, pc] = [a, b, c].map(|v| DVec2::new(v.at.x, v.at.y));
        let centroid = (pa + pb + pc) / 3.0;
        let inside =
            contains_point(outer, centroid) && !holes.iter().any(|h| contains_point(h, centroid));
        if !inside {
            continue;
        }
        if (pb - pa).perp_dot(pc - pa) > 0.0 {
            triangles.push([a.index, b.index, c.index]);
        } else {
            triangles.push([a.index, c.index, b.index]);
        }
    }
    Ok(triangles)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::polygon::signed_area;

    fn area(points: &[DVec2], tris: &[[usize; 3]]) -> f64 {
        tris.iter()
            .map(|t| signed_area(t.iter().map(|&i| points[i])))
            .sum()
    }

    #[test]
    fn l_shape_keeps_its_area_with_n_minus_2_triangles() {
        let outer: Vec<DVec2> = [(0., 0.), (2., 0.), (2., 1.), (1., 1.), (1., 2.), (0., 2.)]
            .map(|(x, y)| DVec2::new(x, y))
            .to_vec();
        let tris = triangulate_polygon(&outer, &[]).unwrap();
        assert_eq!(tris.len(), outer.len() - 2);
        assert!((area(&outer, &tris) - 3.0).abs() < 1e-12);
        assert!(tris.iter().all(|t| signed_area(t.map(|i| outer[i])) > 0.0));
    }

    #[test]
    fn square_with_a_hole_leaves_the_hole_out() {
        let sq = |s: f64, o: f64| {
            [(0., 0.), (1., 0.), (1., 1.), (0., 1.)]
                .map(|(x, y)| DVec2::new(o + s * x, o + s * y))
                .to_vec()
        };
        let outer = sq(3.0, 0.0);
        let mut hole = sq(1.0, 1.0);
        hole.reverse();
        let tris = triangulate_polygon(&outer, std::slice::from_ref(&hole)).unwrap();
        let all: Vec<DVec2> = outer.iter().chain(&hole).copied().collect();
        assert!((area(&all, &tris) - 8.0).abs() < 1e-12);
        // Euler: 8 corners, one hole → 8 triangles.
        assert_eq!(tris.len(), 8);
    }

    #[test]
    fn crossing_sides_are_an_error_not_a_panic() {
        let bow: Vec<DVec2> = [(0., 0.), (1., 1.), (1., 0.), (0., 1.)]
            .map(|(x, y)| DVec2::new(x, y))
            .to_vec();
        assert_eq!(
            triangulate_polygon(&bow, &[]),
            Err(TriangulateError::CrossingSides)
        );
    }
}
