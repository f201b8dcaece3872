//! Classic crease patterns generated from parameters: Miura-ori, the square twist, the
//! waterbomb base and tessellation, the Yoshimura pattern, and a flat-foldable square grid.
//!
//! All lengths are millimetres; every generator returns a pattern whose interior vertices
//! satisfy Kawasaki's and Maekawa's theorems (tests check this with [`crate::check`]) with the
//! sheet outline as boundary edges and faces computed. Invalid parameters give a
//! [`ClassicError`] naming the parameter.

mod miura;
mod square_twist;
mod waterbomb;
mod yoshimura;

pub use miura::{MiuraOri, grid};
pub use square_twist::SquareTwist;
pub use waterbomb::{Waterbomb, waterbomb_base};
pub use yoshimura::Yoshimura;

use crate::pattern::{CreasePattern, PlanarizeOptions, planarize};

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
    Ok(cp)
}
