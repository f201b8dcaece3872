//! Origami Simulator's crease colours and the mapping between stroke colour, stroke opacity
//! and the model's assignment and fold angle.
//!
//! The palette (Origami Simulator's documented convention):
//!
//! | colour | hex | assignment |
//! | --- | --- | --- |
//! | red | `#ff0000` | mountain (`M`) |
//! | blue | `#0000ff` | valley (`V`) |
//! | black | `#000000` | boundary (`B`) |
//! | green | `#00ff00` | cut (`C`) |
//! | yellow | `#ffff00` | facet / flat (`F`) |
//! | magenta | `#ff00ff` | unassigned, "undriven" (`U`) |
//!
//! Rabbit Ear's palette is known too and read exactly (no warning): crimson `#dc143c`
//! mountain, royal blue `#4169e1` valley, black boundary, lime green `#32cd32` cut, light grey
//! `#d3d3d3` flat, orchid `#da70d6` unassigned, and gold `#ffd700` **join** (Rabbit Ear draws
//! `J` edges gold; by nearest colour they would read as flat).
//!
//! Any other colour is matched to the nearest palette colour by Euclidean distance in 8-bit
//! RGB (ties go to the earlier row above); the reader warns about each such colour. The stroke
//! opacity of a mountain or valley line is the fraction of a full fold: opacity × 180° is the
//! fold angle's magnitude, signed by FOLD's convention (valley +, mountain −).

use crate::pattern::Assignment;

/// An 8-bit RGB colour.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Rgb(pub u8, pub u8, pub u8);

impl Rgb {
    /// The colour as `#rrggbb` (lower case).
    pub fn hex(self) -> String {
        format!("#{:02x}{:02x}{:02x}", self.0, self.1, self.2)
    }

    /// Squared Euclidean distance in RGB space.
    fn distance2(self, other: Rgb) -> u32 {
        let d = |a: u8, b: u8| (i32::from(a) - i32::from(b)).unsigned_abs().pow(2);
        d(self.0, other.0) + d(self.1, other.1) + d(self.2, other.2)
    }
}

/// The palette, in tie-breaking order.
pub const PALETTE: [(Rgb, Assignment); 6] = [
    (Rgb(0xff, 0x00, 0x00), Assignment::Mountain),
    (Rgb(0x00, 0x00, 0xff), Assignment::Valley),
    (Rgb(0x00, 0x00, 0x00), Assignment::Boundary),
    (Rgb(0x00, 0xff, 0x00), Assignment::Cut),
    (Rgb(0xff, 0xff, 0x00), Assignment::Flat),
    (Rgb(0xff, 0x00, 0xff), Assignment::Unassigned),
];

/// Rabbit Ear's crease colours (its SVG exports name them with CSS colour keywords), read as
/// exact matches.
pub const RABBIT_EAR: [(Rgb, Assignment); 6] = [
    (Rgb(0xdc, 0x14, 0x3c), Assignment::Mountain),
    (Rgb(0x41, 0x69, 0xe1), Assignment::Valley),
    (Rgb(0x32, 0xcd, 0x32), Assignment::Cut),
    (Rgb(0xd3, 0xd3, 0xd3), Assignment::Flat),
    (Rgb(0xda, 0x70, 0xd6), Assignment::Unassigned),
    (Rgb(0xff, 0xd7, 0x00), Assignment::Join),
];

/// The result of matching a stroke colour against the palette.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Match {
    /// The assignment of the nearest palette colour.
    pub assignment: Assignment,
    /// The nearest palette colour.
    pub palette: Rgb,
    /// True when the colour is exactly a palette colour.
    pub exact: bool,
}

/// The palette entry nearest to `colour`.
pub fn nearest(colour: Rgb) -> Match {
    if let Some(&(palette, assignment)) = RABBIT_EAR.iter().find(|(c, _)| *c == colour) {
        return Match {
            assignment,
            palette,
            exact: true,
        };
    }
    let mut best = PALETTE[0];
    for entry in PALETTE {
        if entry.0.distance2(colour) < best.0.distance2(colour) {
            best = entry;
        }
    }
    Match {
        assignment: best.1,
        palette: best.0,
        exact: best.0 == colour,
    }
}

/// The stroke colour written for an assignment. Join (`J`) has no colour in the palette and is
/// written as unassigned (magenta), the closest meaning: a crease whose folding is not driven.
pub fn colour_of(assignment: Assignment) -> Rgb {
    let wanted = match assignment {
        Assignment::Join => Assignment::Unassigned,
        other => other,
    };
    PALETTE
        .iter()
        .find(|(_, a)| *a == wanted)
        .map_or(Rgb(0xff, 0x00, 0xff), |(c, _)| *c)
}

/// The fold angle (degrees, FOLD sign) of a line of this assignment drawn with this opacity
/// (0..=1, already multiplied through groups): ±opacity × 180° for mountain and valley, 0 for
/// flat, none otherwise.
pub fn fold_angle(assignment: Assignment, opacity: f64) -> Option<f64> {
    let opacity = opacity.clamp(0.0, 1.0);
    match assignment {
        Assignment::Valley => Some(opacity * 180.0),
        Assignment::Mountain => Some(-opacity * 180.0),
        Assignment::Flat => Some(0.0),
        _ => None,
    }
}

/// The stroke opacity written for an edge: |fold angle| / 180 for mountain and valley lines
/// whose angle is known, 1 otherwise.
pub fn opacity_of(assignment: Assignment, fold_angle: Option<f64>) -> f64 {
    match (assignment.is_fold(), fold_angle) {
        (true, Some(a)) if a.is_finite() => (a.abs() / 180.0).min(1.0),
        _ => 1.0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn palette_colours_match_exactly() {
        for (c, a) in PALETTE {
            let m = nearest(c);
            assert!(m.exact);
            assert_eq!(m.assignment, a);
            assert_eq!(colour_of(a), c);
        }
    }

    #[test]
    fn rabbit_ear_colours_are_exact_and_gold_is_join() {
        let gold = nearest(Rgb(0xff, 0xd7, 0x00));
        assert!(gold.exact);
        assert_eq!(gold.assignment, Assignment::Join);
        assert_eq!(
            nearest(Rgb(0xdc, 0x14, 0x3c)).assignment,
            Assignment::Mountain
        );
    }

    #[test]
    fn near_colours_map_to_the_nearest() {
        assert_eq!(nearest(Rgb(200, 30, 20)).assignment, Assignment::Mountain);
        assert_eq!(nearest(Rgb(20, 20, 180)).assignment, Assignment::Valley);
        assert_eq!(nearest(Rgb(40, 40, 40)).assignment, Assignment::Boundary);
        assert_eq!(nearest(Rgb(250, 240, 10)).assignment, Assignment::Flat);
        assert!(!nearest(Rgb(40, 40, 40)).exact);
    }

    #[test]
    fn opacity_and_angle_are_inverse_for_folds() {
        for a in [-180.0, -90.0, -1.5, 0.0, 45.0, 180.0] {
            let assignment = if a < 0.0 {
                Assignment::Mountain
            } else {
                Assignment::Valley
            };
            let o = opacity_of(assignment, Some(a));
            let back = fold_angle(assignment, o).unwrap_or(f64::NAN);
            assert!(
                (back.abs() - f64::abs(a)).abs() < 1e-12,
                "{a} -> {o} -> {back}"
            );
        }
        assert_eq!(opacity_of(Assignment::Mountain, None), 1.0);
        assert_eq!(opacity_of(Assignment::Flat, Some(0.0)), 1.0);
        assert_eq!(fold_angle(Assignment::Flat, 0.3), Some(0.0));
        assert_eq!(fold_angle(Assignment::Boundary, 1.0), None);
        assert_eq!(
            colour_of(Assignment::Join),
            colour_of(Assignment::Unassigned)
        );
    }
}
