//! Crease-pattern SVG in Origami Simulator's colour convention.
//!
//! **Reading** ([`read_str`]) uses usvg, so any SVG a browser draws is understood: paths,
//! lines, polylines, polygons, rectangles (and circles and ellipses, flattened), groups,
//! `<use>`, CSS, nested transforms and units. Each stroked element becomes edges:
//! - the stroke colour picks the assignment by [`palette`]: red mountain, blue valley, black
//!   boundary, green cut, yellow flat (facet), magenta unassigned; another colour maps to the
//!   nearest of these in RGB, with one warning per distinct colour;
//! - stroke opacity × the opacity of enclosing groups × 180° is the fold angle of mountain
//!   (negative) and valley (positive) lines; flat lines get 0°; boundary, cut and unassigned
//!   lines no angle;
//! - straight segments become edges; curves are flattened within 0.01 mm, with a warning;
//! - elements without a stroke, with gradient strokes, images and text are skipped, with a
//!   warning.
//!
//! The result is in millimetres with y up (see [`frame`] for the units and the origin), then
//! planarised so shared endpoints merge and crossings split, with a tolerance of
//! [`MERGE_TOLERANCE`] of the drawing's size (drawing programs round coordinates).
//!
//! **Writing** ([`write_string`]) produces what Origami Simulator opens: one `<line>` per edge,
//! all direct children of the root (Origami Simulator ignores grouped elements), in the exact
//! palette colours, `stroke-opacity` = |fold angle| / 180 on mountain and valley lines, sizes
//! in millimetres. See [`write`](mod@write) for the layout and number precision.
//!
//! **Precision of a round trip.** The writer's numbers are exact to 5e-11 of the pattern's
//! size, but usvg holds coordinates, transforms and opacities in `f32`: reading back gives
//! coordinates within about 1e-7 of their magnitude and fold angles within about 2e-5 degrees.
//!
//! **Losses.** SVG keeps no faces, face orders, isolated vertices or FOLD metadata beyond the
//! title and description; join edges come back as unassigned; unitless patterns come back in
//! millimetres (a user unit read as a CSS pixel, 25.4/96 mm).

mod collect;
pub mod flatten;
pub mod frame;
pub mod palette;
mod read;
pub mod write;

pub use collect::{CURVE_TOLERANCE_MM, MAX_SEGMENTS};
pub use read::{MERGE_TOLERANCE, merge_tolerance, read_str};
pub use write::write_string;
