//! Plane geometry shared by every stage: segments, polygons, angles, bounding boxes, a sparse
//! uniform grid for neighbour queries, disjoint sets for grouping, triangulation, isometric
//! unfolding.
//!
//! Vectors are glam's `DVec2`/`DVec3` (f64). Tolerances are explicit arguments; the shared
//! defaults are named in [`tolerance`].

pub(crate) mod angle;
pub(crate) mod disjoint;
pub(crate) mod grid;
pub(crate) mod polygon;
pub(crate) mod polyline;
pub(crate) mod rect;
pub(crate) mod segment;
pub(crate) mod space;
pub(crate) mod stroke_digits;
pub mod tolerance;
pub(crate) mod triangulate;
pub(crate) mod unfold;

pub use disjoint::DisjointSets;
pub use glam::{DVec2, DVec3};
pub use grid::HashGrid;
pub use polygon::{contains_point, segment_crosses_ring, signed_area};
pub use rect::Rect;
pub use segment::Segment;
pub use segment::{Crossing, distance_to_point, intersect, segment_distance, slide_interval};
pub use space::{Box3, overlapping_boxes, segment_through_triangle, triangle_box};
pub use triangulate::{TriangulateError, triangulate_polygon};
