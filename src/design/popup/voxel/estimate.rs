//! An up-front estimate of the time and memory the conversion of a depth field into a card
//! takes ([`super::card_from_depths`]: bump removal, filling under overhangs, windows and the
//! thin-top search of Mitani, Suzuki & Uno 2003, section 3), printed before the work starts.
//!
//! The model is empirical: time grows with the cells of the field, `nx · ny · nz` (each of the
//! section 3 steps sweeps columns of the field and checks the pop-up on face strips), and memory
//! with the cells of the pattern, `nx · (ny + nz)`. The constants were measured on the release
//! build on a two-core machine with the bundled `building.obj` at `--resolution` 250 to 2000
//! (0.29 s to 162 s, 10 to 112 MB); other models and machines differ by a factor of about two
//! either way, which is what an estimate is for.

use super::DepthField;
pub use crate::design::estimate::Estimate;

/// Seconds per cell of the field (`nx · ny · nz`), measured (see the module docs).
pub const SECONDS_PER_CELL: f64 = 7e-8;
/// Bytes per cell of the pattern (`nx · (ny + nz)`), measured.
pub const BYTES_PER_PATTERN_CELL: f64 = 28.0;
/// Memory of the program before the card is built, bytes.
pub const BASE_BYTES: f64 = 8e6;

/// The estimate for converting `field` (see the module docs for the model).
pub fn conversion_estimate(field: &DepthField) -> Estimate {
    let (nx, ny, nz) = (field.nx as f64, field.ny as f64, field.nz as f64);
    Estimate {
        seconds: SECONDS_PER_CELL * nx * ny * nz,
        bytes: BASE_BYTES + BYTES_PER_PATTERN_CELL * nx * (ny + nz),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_estimate_grows_with_the_cube_of_the_resolution() {
        let field = |n: usize| DepthField {
            nx: n,
            ny: n / 2,
            nz: n / 2,
            depths: Vec::new(),
        };
        let (a, b) = (
            conversion_estimate(&field(500)),
            conversion_estimate(&field(1000)),
        );
        assert!((b.seconds / a.seconds - 8.0).abs() < 1e-9);
        assert!(b.bytes > a.bytes);
    }
}
