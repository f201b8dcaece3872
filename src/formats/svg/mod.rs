//! Crease-pattern SVG in Origami Simulator's colour convention.
//!
//! **Reading** ([`read_str`], [`read_str_with`]) uses usvg, so any SVG a browser draws is
//! understood: paths, lines, polylines, polygons, rectangles (and circles and ellipses,
//! flattened), groups, `<use>`, CSS, nested transforms and units. Each stroked element becomes
//! edges:
//! - a declared meaning wins over colour: `data-assignment` (Rabbit Ear), then class names
//!   (`mountain`, `valley`, `boundary`, `cut`, `flat`/`mark`, …; see [`meaning`]), with
//!   `data-foldAngle` as the fold angle; such elements are read even without a stroke;
//! - in a drawing whose lines (read by colour) all have one colour, a dashed line
//!   (`stroke-dasharray`) is a fold: by default plain dashes are valley and dash-dot mountain
//!   folds (the origami diagram convention), or as [`crate::formats::DashedAs`] says;
//! - otherwise the stroke colour picks the assignment by [`palette`]: red mountain, blue valley, black
//!   boundary, green cut, yellow flat (facet), magenta unassigned; another colour maps to the
//!   nearest of these in RGB, with one warning per distinct colour;
//! - stroke opacity × the opacity of enclosing groups × 180° is the fold angle of mountain
//!   (negative) and valley (positive) lines; flat lines get 0°; boundary, cut and unassigned
//!   lines no angle;
//! - straight segments become edges; curves are flattened within 0.01 mm, with a warning;
//! - elements without a stroke, with gradient strokes, images and text are skipped, with a
//!   warning;
//! - geometric attributes that are not numbers or beyond ±1e9, and elements with more than
//!   1000 attributes, are refused with the element and line; a presentation attribute that
//!   cannot be parsed is warned about ([`attributes`]).
//!
//! The result is in millimetres with y up (see [`frame`] for the units and the origin), then
//! planarised so shared endpoints merge and crossings split, with a tolerance of
//! [`MERGE_TOLERANCE`] of the drawing's size (drawing programs round coordinates); then line
//! ends that stop short of a line or corner by less than the snapping tolerance are joined to
//! it ([`crate::formats::snap`]).
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

pub(crate) mod attributes;
mod collect;
pub(crate) mod flatten;
pub(crate) mod frame;
pub(crate) mod meaning;
pub(crate) mod palette;
mod read;
pub(crate) mod write;

pub use collect::{CURVE_TOLERANCE_MM, MAX_SEGMENTS};
pub use read::{MERGE_TOLERANCE, merge_tolerance, read_str, read_str_with};
pub use write::write_string;
