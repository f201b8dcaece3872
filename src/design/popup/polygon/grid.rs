//! The integer grid of the pattern: polygons are stored in units of [`UNIT_MM`] (0.1 µm) so
//! that every boolean operation of i_overlay sees one grid, shared edges coincide exactly and
//! areas add up exactly (see the `model` module docs).

use glam::DVec2;
use i_overlay::i_float::int::point::IntPoint;

/// Closed contours on the integer grid: a list of shapes, each an outer contour
/// (counter-clockwise) followed by its holes (clockwise); no point is repeated.
pub type Shapes = Vec<Vec<Vec<Point>>>;

/// A point of the integer pattern grid.
pub type Point = IntPoint<i32>;

/// The grid step of stored coordinates, in millimetres.
pub const UNIT_MM: f64 = 1e-4;

/// Whether `q` (grid units, fractional) lies inside a shape (outer contour minus holes).
pub(crate) fn shape_contains(shape: &[Vec<Point>], q: DVec2) -> bool {
    let inside = |c: &Vec<Point>| {
        let ring: Vec<DVec2> = c
            .iter()
            .map(|p| DVec2::new(p.x.into(), p.y.into()))
            .collect();
        crate::geom::polygon::contains_point(&ring, q)
    };
    shape.first().is_some_and(inside) && !shape[1..].iter().any(inside)
}

/// Millimetres to grid units (callers keep |mm| within 2 × `MAX_SIDE_MM`).
pub(crate) fn units(mm: f64) -> i32 {
    (mm / UNIT_MM).round() as i32
}

/// A pattern point in millimetres to the grid.
pub(crate) fn to_units(p: DVec2) -> Point {
    Point::new(units(p.x), units(p.y))
}

/// A grid point in millimetres.
pub fn to_mm(p: Point) -> DVec2 {
    DVec2::new(f64::from(p.x) * UNIT_MM, f64::from(p.y) * UNIT_MM)
}

/// The counter-clockwise rectangle `[x0, x1] × [y0, y1]`.
pub(crate) fn rect(x0: i32, y0: i32, x1: i32, y1: i32) -> Vec<Point> {
    vec![
        Point::new(x0, y0),
        Point::new(x1, y0),
        Point::new(x1, y1),
        Point::new(x0, y1),
    ]
}

/// Twice the signed area of all contours (holes count negative), exactly.
pub(crate) fn area_units2(shapes: &Shapes) -> i128 {
    shapes
        .iter()
        .flatten()
        .map(|c| {
            (0..c.len())
                .map(|i| {
                    let (a, b) = (c[i], c[(i + 1) % c.len()]);
                    i128::from(a.x) * i128::from(b.y) - i128::from(b.x) * i128::from(a.y)
                })
                .sum::<i128>()
        })
        .sum()
}

pub(crate) fn bounds(shapes: &Shapes) -> (Point, Point) {
    let mut lo = Point::new(i32::MAX, i32::MAX);
    let mut hi = Point::new(i32::MIN, i32::MIN);
    for p in shapes.iter().flatten().flatten() {
        lo = Point::new(lo.x.min(p.x), lo.y.min(p.y));
        hi = Point::new(hi.x.max(p.x), hi.y.max(p.y));
    }
    (lo, hi)
}

pub(crate) fn overlap(a: (Point, Point), b: (Point, Point)) -> bool {
    a.0.x < b.1.x && b.0.x < a.1.x && a.0.y < b.1.y && b.0.y < a.1.y
}
