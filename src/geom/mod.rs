//! Plane geometry shared by every stage: segments, polygons, angles, bounding boxes, a sparse
//! uniform grid for neighbour queries, disjoint sets for grouping, triangulation, isometric
//! unfolding.
//!
//! Vectors are glam's `DVec2`/`DVec3` (f64). Tolerances are explicit arguments; the shared
//! defaults are named in [`tolerance`].

pub mod angle;
pub mod disjoint;
pub mod grid;
pub mod polygon;
pub mod polyline;
pub mod rect;
pub mod segment;
pub mod stroke_digits;
pub mod tolerance;
pub mod triangulate;
pub mod unfold;

pub use disjoint::DisjointSets;
pub use glam::{DVec2, DVec3};
pub use grid::HashGrid;
pub use rect::Rect;
pub use segment::Segment;
