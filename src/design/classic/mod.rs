//! Classic crease patterns generated from parameters: Miura-ori, the square twist, the
//! waterbomb base and tessellation, the Yoshimura pattern, a flat-foldable square grid, and a
//! blank square sheet to draw on.
//!
//! All lengths are millimetres; every generator returns a pattern whose interior vertices
//! satisfy Kawasaki's and Maekawa's theorems (tests check this with [`crate::check`](mod@crate::check)) with the
//! sheet outline as boundary edges and faces computed. Every mountain and valley crease
//! carries the target fold angle [`FOLD_ANGLE_DEG`] (set in one place, [`set_fold_angles`]),
//! so FOLD viewers fold it and the material checks have a number to test. Invalid parameters
//! give a [`ClassicError`] naming the parameter.

mod blank;
mod miura;
mod square_twist;
mod waterbomb;
mod yoshimura;

pub use blank::{BLANK_SHEET_MM, blank_sheet};
pub use miura::{MiuraOri, grid};
pub use square_twist::SquareTwist;
pub use waterbomb::{Waterbomb, waterbomb_base};
pub use yoshimura::Yoshimura;

use crate::pattern::{Assignment, CreasePattern, PlanarizeOptions, planarize};

/// A generator parameter out of range.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{parameter} = {value}: {expected}")]
pub struct ClassicError {
    /// The parameter's name.
    pub parameter: &'static str,
    /// The value given.
    pub value: f64,
    /// What is allowed.
    pub expected: &'static str,
}

/// Longest length a generator takes, in millimetres (1 km): beyond it coordinates leave the
/// range every reader accepts, and cleaning the drawing would never end.
pub const MAX_LENGTH_MM: f64 = 1.0e6;

/// Checks that a length is finite, positive and at most [`MAX_LENGTH_MM`].
fn positive(parameter: &'static str, value: f64) -> Result<f64, ClassicError> {
    if value.is_finite() && value > 0.0 && value <= MAX_LENGTH_MM {
        Ok(value)
    } else {
        Err(ClassicError {
            parameter,
            value,
            expected: "must be a length greater than 0 and at most 1,000,000 mm",
        })
    }
}

/// Checks a count is between 1 and `max`.
fn count(parameter: &'static str, value: usize, max: usize) -> Result<usize, ClassicError> {
    if (1..=max).contains(&value) {
        Ok(value)
    } else {
        Err(ClassicError {
            parameter,
            value: value as f64,
            expected: "must be a whole number between 1 and the generator's limit",
        })
    }
}

/// Target fold angle of the generated mountain and valley creases, in degrees: folded nearly
/// flat. A real sheet does not fold to a full 180° (its thickness and spring-back leave a few
/// degrees), and 170° lies within the largest fold angle of card and paper (180°: they fold
/// flat), so a generated pattern cut on them raises no fold-angle warning; thick sheets that
/// allow less (0.5 mm stainless: 165°) still warn. Being short of 180°, the generated creases
/// are a 3D target that `check` does not judge without a 3D frame (`--fold-angle 180` gives
/// a flat target that it does).
pub const FOLD_ANGLE_DEG: f64 = 170.0;

/// Sets every mountain crease to −`degrees` and every valley crease to +`degrees` (FOLD's
/// sign), flat lines to 0; other edges keep theirs. `degrees` is clamped to [0, 180].
pub fn set_fold_angles(cp: &mut CreasePattern, degrees: f64) {
    let d = if degrees.is_finite() {
        degrees.clamp(0.0, 180.0)
    } else {
        180.0
    };
    for e in &mut cp.edges {
        e.fold_angle = match e.assignment {
            Assignment::Mountain => Some(-d),
            Assignment::Valley => Some(d),
            Assignment::Flat => Some(0.0),
            _ => e.fold_angle,
        };
    }
}

/// Cleans a generated drawing (merging shared vertices, splitting outline edges where creases
/// end on them) and traces its faces.
fn finish(mut cp: CreasePattern, title: String) -> Result<CreasePattern, ClassicError> {
    cp.meta.title = Some(title);
    cp.meta.creator = Some("foldcam".into());
    let options = PlanarizeOptions {
        tolerance: None,
        faces: true,
    };
    planarize(&mut cp, &options).map_err(|_| ClassicError {
        parameter: "size",
        value: cp.edges.len() as f64,
        expected: "too many edges to clean: use fewer cells",
    })?;
    if cp.degeneracy().is_some() {
        let size = cp.bounds().map_or(0.0, |(lo, hi)| lo.distance(hi));
        return Err(ClassicError {
            parameter: "size",
            value: size,
            expected: "the lengths given leave no sheet (every vertex merges into one point or \
                       onto one line): give lengths nearer to each other",
        });
    }
    set_fold_angles(&mut cp, FOLD_ANGLE_DEG);
    Ok(cp)
}
