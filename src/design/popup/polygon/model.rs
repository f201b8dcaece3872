//! The polygon card of Mitani & Suzuki (2004): faces (Fig. 5), the 3D ↔ 2D maps (eq. 1–3), adding faces by
//! regularised difference (§3.2, eq. 5) and openings by the equivalent face (§3.3, eq. 6).
//!
//! Axes follow the paper and the voxel card: `x` along the central fold, `y` the depth in front
//! of the back sheet (the plane y = 0), `z` the height above the base sheet (z = 0). The pattern
//! point of a card point is `(x, z − y)` (eq. 1): the back sheet is the upper half of the sheet
//! (`0 ≤ v ≤ height`), the base the lower half (`−depth ≤ v ≤ 0`), the central fold is v = 0.
//!
//! # Snapping
//! Polygons are stored on an integer grid of [`UNIT_MM`] (0.1 µm) so that every boolean
//! operation of i_overlay sees the same grid. Points where a slanted edge crosses another edge
//! are rounded to the grid (at most 0.07 µm off), which alone would leave slivers between the
//! new face and the faces it trims. So the new face is stored as exactly what the trimmed faces
//! gave up (their old polygons minus their new ones): the faces tile the sheet exactly on the
//! grid (eq. 4 holds with integer areas), every vertex lying on another face's edge lies on it
//! exactly, and the new face differs from the polygon drawn only by that rounding.

use glam::{DVec2, DVec3};
use i_overlay::core::fill_rule::FillRule;
use i_overlay::core::overlay_rule::OverlayRule;
use i_overlay::core::single::SingleIntOverlay;
use thiserror::Error;

pub use super::grid::{Point, Shapes, UNIT_MM, to_mm};
use super::grid::{area_units2, bounds, overlap, rect, shape_contains, to_units, units};

/// Largest card dimension (width, depth, height), in millimetres.
pub const MAX_SIDE_MM: f64 = 10_000.0;

/// Most points in one input polygon.
pub const MAX_POLYGON_POINTS: usize = 100_000;

/// Why an edit or a card is refused.
#[derive(Clone, Debug, PartialEq, Error)]
pub enum PolygonError {
    /// A card dimension is not finite or outside (0, [`MAX_SIDE_MM`]].
    #[error("card {what} {value} mm must be finite, positive and at most {MAX_SIDE_MM} mm")]
    BadSize {
        /// Which dimension.
        what: &'static str,
        /// The value given.
        value: f64,
    },
    /// The reference plane lies outside the card: `t` must be in `0..=depth` for a vertical
    /// plane and `0..=height` for a horizontal one.
    #[error("{kind} reference plane at {t} mm lies outside the card (allowed 0..={max} mm)")]
    BadPlane {
        /// Vertical or horizontal.
        kind: FaceKind,
        /// The position given.
        t: f64,
        /// The largest allowed position.
        max: f64,
    },
    /// A polygon point is not finite or too far out.
    #[error("polygon point {index} ({x}, {y}) is not a finite coordinate within ±{MAX_SIDE_MM} mm")]
    BadPoint {
        /// Index in the polygon.
        index: usize,
        /// First coordinate.
        x: f64,
        /// Second coordinate.
        y: f64,
    },
    /// Fewer than 3 or more than [`MAX_POLYGON_POINTS`] points.
    #[error("a polygon needs 3 to {MAX_POLYGON_POINTS} points, got {0}")]
    PointCount(usize),
    /// The polygon encloses no area inside the sheet.
    #[error("the polygon encloses no area inside the sheet")]
    Empty,
}

/// The two kinds of faces (§2.1, Fig. 3).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum FaceKind {
    /// VFace: vertical, in the plane y = t.
    Vertical,
    /// HFace: horizontal, in the plane z = t.
    Horizontal,
}

impl std::fmt::Display for FaceKind {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            FaceKind::Vertical => "vertical",
            FaceKind::Horizontal => "horizontal",
        })
    }
}

/// The plane a face lies on at 90°: its kind and `t` in grid units ([`UNIT_MM`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Plane {
    /// Vertical (y = t) or horizontal (z = t).
    pub kind: FaceKind,
    /// The position in grid units.
    pub t: i32,
}

impl Plane {
    /// The back sheet (y = 0).
    pub const BACK: Plane = Plane {
        kind: FaceKind::Vertical,
        t: 0,
    };
    /// The base sheet (z = 0).
    pub const BASE: Plane = Plane {
        kind: FaceKind::Horizontal,
        t: 0,
    };

    /// `t` in millimetres.
    pub fn t_mm(self) -> f64 {
        f64::from(self.t) * UNIT_MM
    }

    /// Eq. 2 (VFace) and eq. 3 (HFace): the card point (mm) of pattern point `p` (mm).
    pub fn to_card(self, p: DVec2) -> DVec3 {
        let t = self.t_mm();
        match self.kind {
            FaceKind::Vertical => DVec3::new(p.x, t, p.y + t),
            FaceKind::Horizontal => DVec3::new(p.x, -p.y + t, t),
        }
    }

    /// The card line `(y, z)` that the pattern line v = `v` (grid units) of this plane lands
    /// on, in grid units (eq. 2, 3 with x dropped).
    pub fn line_at(self, v: i32) -> (i64, i64) {
        let (t, v) = (i64::from(self.t), i64::from(v));
        match self.kind {
            FaceKind::Vertical => (t, v + t),
            FaceKind::Horizontal => (t - v, t),
        }
    }
}

/// Eq. 1: the pattern point (mm) of a card point (mm).
pub fn pattern_point(p: DVec3) -> DVec2 {
    DVec2::new(p.x, p.z - p.y)
}

/// One face (Fig. 5, `OAFace`): its plane and its polygon on the pattern.
#[derive(Clone, Debug, PartialEq)]
pub struct OaFace {
    /// Kind and `t`.
    pub plane: Plane,
    /// The polygon with holes on the pattern, possibly several pieces or empty once later
    /// faces have covered it.
    pub polygon: Shapes,
    /// Bounding box of `polygon` (min, max), unspecified when empty.
    bounds: (Point, Point),
}

impl OaFace {
    fn new(plane: Plane, polygon: Shapes) -> Self {
        let bounds = bounds(&polygon);
        OaFace {
            plane,
            polygon,
            bounds,
        }
    }

    /// The polygon in millimetres: shapes of rings (outer counter-clockwise, holes clockwise).
    pub fn polygon_mm(&self) -> Vec<Vec<Vec<DVec2>>> {
        self.polygon
            .iter()
            .map(|shape| {
                shape
                    .iter()
                    .map(|c| c.iter().map(|&p| to_mm(p)).collect())
                    .collect()
            })
            .collect()
    }

    /// Area in square millimetres.
    pub fn area_mm2(&self) -> f64 {
        area_units2(&self.polygon) as f64 * 0.5 * UNIT_MM * UNIT_MM
    }
}

/// A polygon pop-up card (Fig. 5, `OrigamicArchitecture`): the sheet and its faces. Face 0 is
/// the back sheet, face 1 the base sheet, then one face per edit in order; faces covered by
/// later ones stay (empty) so their indices never change.
#[derive(Clone, Debug, PartialEq)]
pub struct PolygonCard {
    width: i32,
    depth: i32,
    height: i32,
    faces: Vec<OaFace>,
}

impl PolygonCard {
    /// The initial card (§3.1 (1), Fig. 8 a): a sheet `width` mm along the fold, a base
    /// `depth` mm deep and a back sheet `height` mm high, flat at 90°.
    pub fn new(width: f64, depth: f64, height: f64) -> Result<Self, PolygonError> {
        let side = |what, value: f64| {
            if value.is_finite() && value > 0.0 && value <= MAX_SIDE_MM {
                Ok(units(value))
            } else {
                Err(PolygonError::BadSize { what, value })
            }
        };
        let (w, d, h) = (
            side("width", width)?,
            side("depth", depth)?,
            side("height", height)?,
        );
        let back = OaFace::new(Plane::BACK, vec![vec![rect(0, 0, w, h)]]);
        let base = OaFace::new(Plane::BASE, vec![vec![rect(0, -d, w, 0)]]);
        Ok(PolygonCard {
            width: w,
            depth: d,
            height: h,
            faces: vec![back, base],
        })
    }

    /// Width along the fold, base depth and back-sheet height, in millimetres.
    pub fn size_mm(&self) -> (f64, f64, f64) {
        let mm = |u: i32| f64::from(u) * UNIT_MM;
        (mm(self.width), mm(self.depth), mm(self.height))
    }

    /// The sheet on the pattern: x in `0..width`, v in `−depth..height` (grid units).
    pub fn sheet(&self) -> [Point; 4] {
        let (w, d, h) = (self.width, self.depth, self.height);
        [
            Point::new(0, -d),
            Point::new(w, -d),
            Point::new(w, h),
            Point::new(0, h),
        ]
    }

    /// Every face, index 0 the back sheet and 1 the base.
    pub fn faces(&self) -> &[OaFace] {
        &self.faces
    }

    /// Adds a face on a reference plane (§3.1 (2)–(4)): `kind` at `t_mm`, outlined by `points`
    /// on that plane — `(x, z)` on a vertical plane, `(x, y)` on a horizontal one, mm. Returns
    /// the new face's index.
    pub fn add_face(
        &mut self,
        kind: FaceKind,
        t_mm: f64,
        points: &[DVec2],
    ) -> Result<usize, PolygonError> {
        let plane = self.plane(kind, t_mm)?;
        check_points(points)?;
        let t = plane.t_mm();
        // Eq. 1 on the points of the plane.
        let ring: Vec<Point> = points
            .iter()
            .map(|q| match kind {
                FaceKind::Vertical => pattern_point(DVec3::new(q.x, t, q.y)),
                FaceKind::Horizontal => pattern_point(DVec3::new(q.x, q.y, t)),
            })
            .map(to_units)
            .collect();
        self.add_pattern_polygon(plane, ring)
    }

    /// Cuts an opening `points` into the plane `kind` at `t_mm` (§3.3) by adding the equivalent
    /// face of eq. 6: `CreateVHole(P) = CreateHFace(P')`, `CreateHHole(P) = CreateVFace(P')`.
    /// Points as in [`PolygonCard::add_face`]. Returns the index of the equivalent face.
    pub fn add_opening(
        &mut self,
        kind: FaceKind,
        t_mm: f64,
        points: &[DVec2],
    ) -> Result<usize, PolygonError> {
        let plane = self.plane(kind, t_mm)?;
        check_points(points)?;
        let t = plane.t_mm();
        let low = points.iter().map(|q| q.y).fold(f64::INFINITY, f64::min);
        // On the grid, so the equivalent face's pattern polygon is the opening's exactly.
        let low = f64::from(units(low)) * UNIT_MM;
        // P'_v[i] = (x, y − z + minZ, minZ): a horizontal face at z = minZ, given by (x, y);
        // P'_h[i] = (x, minY, z − y + minY): a vertical face at y = minY, given by (x, z).
        // On the plane's own coordinates (x, w) both read (x, t − w + min w).
        let kind = match kind {
            FaceKind::Vertical => FaceKind::Horizontal,
            FaceKind::Horizontal => FaceKind::Vertical,
        };
        let p2: Vec<DVec2> = points
            .iter()
            .map(|q| DVec2::new(q.x, t - q.y + low))
            .collect();
        self.add_face(kind, low, &p2)
    }

    /// Adds a face given directly on the pattern as one ring (grid units, any orientation,
    /// non-zero winding), clipped to the sheet, and subtracts it from every earlier face
    /// (eq. 5). Returns its index.
    pub fn add_pattern_polygon(
        &mut self,
        plane: Plane,
        ring: Vec<Point>,
    ) -> Result<usize, PolygonError> {
        self.add_pattern_shapes(plane, vec![vec![ring]])
    }

    /// [`PolygonCard::add_pattern_polygon`] for shapes with holes (outer rings
    /// counter-clockwise, holes clockwise).
    pub fn add_pattern_shapes(
        &mut self,
        plane: Plane,
        shapes: Shapes,
    ) -> Result<usize, PolygonError> {
        // Keep i_overlay's i32 engine within its coordinate budget (±2^29).
        let limit = units(2.0 * MAX_SIDE_MM);
        let far = shapes
            .iter()
            .flatten()
            .flatten()
            .enumerate()
            .find(|(_, p)| {
                p.x.unsigned_abs() > limit.unsigned_abs()
                    || p.y.unsigned_abs() > limit.unsigned_abs()
            });
        if let Some((index, p)) = far {
            let q = to_mm(*p);
            return Err(PolygonError::BadPoint {
                index,
                x: q.x,
                y: q.y,
            });
        }
        let sheet = self.sheet();
        let clipped = shapes.overlay(&sheet[..], OverlayRule::Intersect, FillRule::NonZero);
        if area_units2(&clipped) == 0 {
            return Err(PolygonError::Empty);
        }
        let new_bounds = bounds(&clipped);
        let (mut before, mut after) = (Shapes::new(), Shapes::new());
        let mut trimmed = Vec::new();
        for (i, face) in self.faces.iter().enumerate() {
            if face.polygon.is_empty() || !overlap(face.bounds, new_bounds) {
                continue;
            }
            // Eq. 5: OAFace'(i).Polygon2D = OAFace'(i).Polygon2D −* OAFace.Polygon2D.
            let rest = face
                .polygon
                .overlay(&clipped, OverlayRule::Difference, FillRule::NonZero);
            before.extend(face.polygon.iter().cloned());
            after.extend(rest.iter().cloned());
            trimmed.push((i, rest));
        }
        // The new face is what the trimmed faces gave up: the same region up to the rounding
        // of crossings, but bounded by exactly the rounded vertices the differences made, so
        // the faces tile the sheet exactly (eq. 4) on the grid.
        let taken = before.overlay(&after, OverlayRule::Difference, FillRule::NonZero);
        if area_units2(&taken) == 0 {
            return Err(PolygonError::Empty);
        }
        for (i, rest) in trimmed {
            self.faces[i] = OaFace::new(self.faces[i].plane, rest);
        }
        self.faces.push(OaFace::new(plane, taken));
        Ok(self.faces.len() - 1)
    }

    /// The face containing pattern point `p` (mm) strictly inside, if any.
    pub fn face_at(&self, p: DVec2) -> Option<usize> {
        let q = DVec2::new(p.x / UNIT_MM, p.y / UNIT_MM);
        self.faces
            .iter()
            .position(|f| f.polygon.iter().any(|shape| shape_contains(shape, q)))
    }

    /// The card point (mm) at 90° of pattern point `p` (mm), through the face containing it.
    pub fn card_point(&self, p: DVec2) -> Option<DVec3> {
        self.face_at(p).map(|i| self.faces[i].plane.to_card(p))
    }

    /// Validates a reference plane and snaps `t` to the grid.
    fn plane(&self, kind: FaceKind, t_mm: f64) -> Result<Plane, PolygonError> {
        let max = match kind {
            FaceKind::Vertical => self.depth,
            FaceKind::Horizontal => self.height,
        };
        let max_mm = f64::from(max) * UNIT_MM;
        if !(t_mm.is_finite() && (0.0..=max_mm).contains(&t_mm)) {
            return Err(PolygonError::BadPlane {
                kind,
                t: t_mm,
                max: max_mm,
            });
        }
        Ok(Plane {
            kind,
            t: units(t_mm),
        })
    }
}

fn check_points(points: &[DVec2]) -> Result<(), PolygonError> {
    if !(3..=MAX_POLYGON_POINTS).contains(&points.len()) {
        return Err(PolygonError::PointCount(points.len()));
    }
    for (index, p) in points.iter().enumerate() {
        if !(p.is_finite() && p.abs().max_element() <= MAX_SIDE_MM) {
            return Err(PolygonError::BadPoint {
                index,
                x: p.x,
                y: p.y,
            });
        }
    }
    Ok(())
}
