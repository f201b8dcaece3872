//! A blank square sheet: the outline only, to draw a pattern on.

use glam::DVec2;

use super::{ClassicError, finish, positive};
use crate::pattern::{Assignment, CreasePattern, Units};

/// Side of the blank sheet the studio's "Blank sheet" opens, millimetres (a common origami
/// paper size).
pub const BLANK_SHEET_MM: f64 = 150.0;

/// A square sheet of `side` millimetres with its lower left corner at the origin: four
/// boundary edges, one face, no creases.
///
/// # Errors
/// A `side` that is not a finite length greater than 0 and at most
/// [`super::MAX_LENGTH_MM`], naming the parameter `side`.
pub fn blank_sheet(side: f64) -> Result<CreasePattern, ClassicError> {
    let side = positive("side", side)?;
    let mut cp = CreasePattern::new();
    cp.units = Units::Millimetres;
    let corners = [
        DVec2::ZERO,
        DVec2::new(side, 0.0),
        DVec2::new(side, side),
        DVec2::new(0.0, side),
    ];
    for k in 0..4 {
        cp.add_segment(corners[k], corners[(k + 1) % 4], Assignment::Boundary);
    }
    finish(cp, format!("Blank sheet {side} mm"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_blank_sheet_is_its_outline_and_one_face() {
        let cp = blank_sheet(BLANK_SHEET_MM).unwrap();
        assert_eq!(cp.vertices.len(), 4);
        assert_eq!(cp.edges.len(), 4);
        assert!(
            cp.edges
                .iter()
                .all(|e| e.assignment == Assignment::Boundary)
        );
        assert_eq!(cp.faces.as_ref().map(Vec::len), Some(1));
        let (lo, hi) = cp.bounds().unwrap();
        assert_eq!((lo, hi), (DVec2::ZERO, DVec2::splat(BLANK_SHEET_MM)));
        assert_eq!(cp.units, Units::Millimetres);
        assert!(cp.validate().is_ok());
    }

    #[test]
    fn a_side_out_of_range_names_the_parameter() {
        for side in [0.0, -1.0, f64::NAN, f64::INFINITY, 2.0e6] {
            let e = blank_sheet(side).unwrap_err();
            assert_eq!(e.parameter, "side", "{side}");
            assert!(e.to_string().contains("1,000,000 mm"), "{e}");
        }
    }
}
