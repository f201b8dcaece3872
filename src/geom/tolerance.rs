//! The shared numeric tolerances of the geometry: how much f64 round-off a comparison absorbs,
//! when two lengths of one model count as equal, and the floor that keeps a division finite.
//!
//! Every constant is *relative* unless its name carries a unit: multiply it by the scale of
//! the quantities compared (a length, a product of two lengths, a diagonal) before comparing.
//! Module-specific tolerances (a snapping distance, a solver's stopping rule) stay named where
//! they are used; these are the ones many modules share. A caller that must choose its own
//! tolerance passes it as an argument (as [`crate::geom::segment::intersect`] takes `eps`);
//! these constants are the defaults such callers pass.

/// Relative round-off of a short chain of f64 operations: about 4,500 units in the last
/// place (`f64::EPSILON` is 2.2 × 10⁻¹⁶). Used where a test should absorb only rounding: a
/// cross product against the product of the lengths (parallel segments), a degenerate extent
/// against the model's size, a determinant against its terms.
pub const ROUNDOFF: f64 = 1e-12;

/// Squared [`ROUNDOFF`], for comparisons of squared lengths or of areas against the squared
/// scale (1 × 10⁻²⁴).
pub const ROUNDOFF_SQUARED: f64 = 1e-24;

/// Relative size below which a length of a model is taken as zero after a few steps of
/// arithmetic on it (intersections, transforms, accumulated sums): 1 nm on a 1 m sheet,
/// still a thousand times the round-off of [`ROUNDOFF`]. Also the relative slack of an
/// "at most" test (fits on the sheet, within the interval) so rounding never flips it.
pub const RELATIVE: f64 = 1e-9;

/// Squared [`RELATIVE`], for areas against the squared model size (1 × 10⁻¹⁸).
pub const RELATIVE_SQUARED: f64 = 1e-18;

/// Fold angles, in degrees, closer than this are equal (a fold of less than 10⁻⁶° is flat,
/// one within it of ±180° is a full fold). Angles come from `atan2` on unit vectors, good
/// to about 10⁻¹³ rad, so this only absorbs accumulated rounding.
pub const ANGLE_DEG: f64 = 1e-6;

/// Floor for a scale before dividing by it: far below any length or area a pattern can hold
/// (coordinates are at most 10⁹ mm), yet a normal f64 (not subnormal), so that `x / TINY`
/// stays finite for every validated `x`.
pub const TINY: f64 = 1e-300;
