//! Edge assignments as defined by FOLD 1.2 (`edges_assignment`).

use std::fmt;
use std::str::FromStr;

/// What an edge of a crease pattern does, with the FOLD 1.2 letters.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Assignment {
    /// `B`: the sheet's outline.
    Boundary,
    /// `M`: mountain fold.
    Mountain,
    /// `V`: valley fold.
    Valley,
    /// `F`: flat (unfolded) crease, a facet line.
    Flat,
    /// `U`: unassigned crease (folds, direction unknown).
    Unassigned,
    /// `C`: cut through the sheet (both sides are boundary).
    Cut,
    /// `J`: join: two faces glued along this edge.
    Join,
}

impl Assignment {
    /// Every assignment, in FOLD's order of mention.
    pub const ALL: [Assignment; 7] = [
        Assignment::Boundary,
        Assignment::Mountain,
        Assignment::Valley,
        Assignment::Flat,
        Assignment::Unassigned,
        Assignment::Cut,
        Assignment::Join,
    ];

    /// The FOLD letter.
    pub fn letter(self) -> char {
        match self {
            Assignment::Boundary => 'B',
            Assignment::Mountain => 'M',
            Assignment::Valley => 'V',
            Assignment::Flat => 'F',
            Assignment::Unassigned => 'U',
            Assignment::Cut => 'C',
            Assignment::Join => 'J',
        }
    }

    /// Parses a FOLD letter (upper or lower case, as FOLD readers commonly accept).
    pub fn from_letter(c: char) -> Option<Assignment> {
        Some(match c.to_ascii_uppercase() {
            'B' => Assignment::Boundary,
            'M' => Assignment::Mountain,
            'V' => Assignment::Valley,
            'F' => Assignment::Flat,
            'U' => Assignment::Unassigned,
            'C' => Assignment::Cut,
            'J' => Assignment::Join,
            _ => return None,
        })
    }

    /// A readable English name.
    pub fn name(self) -> &'static str {
        match self {
            Assignment::Boundary => "boundary",
            Assignment::Mountain => "mountain",
            Assignment::Valley => "valley",
            Assignment::Flat => "flat",
            Assignment::Unassigned => "unassigned",
            Assignment::Cut => "cut",
            Assignment::Join => "join",
        }
    }

    /// True for mountain and valley, the creases that fold with a known direction.
    pub fn is_fold(self) -> bool {
        matches!(self, Assignment::Mountain | Assignment::Valley)
    }

    /// True for creases that may fold: mountain, valley, unassigned.
    pub fn may_fold(self) -> bool {
        matches!(
            self,
            Assignment::Mountain | Assignment::Valley | Assignment::Unassigned
        )
    }

    /// True where the sheet ends: boundary and cut.
    pub fn is_boundary_like(self) -> bool {
        matches!(self, Assignment::Boundary | Assignment::Cut)
    }

    /// Priority when two drawn edges coincide and one must be kept: a cut or outline beats a
    /// fold, a fold beats an unassigned crease, which beats a flat facet line.
    pub fn strength(self) -> u8 {
        match self {
            Assignment::Cut => 6,
            Assignment::Boundary => 5,
            Assignment::Join => 4,
            Assignment::Mountain => 3,
            Assignment::Valley => 3,
            Assignment::Unassigned => 2,
            Assignment::Flat => 1,
        }
    }

    /// The fold angle (degrees, FOLD sign) that a fully folded crease of this kind has:
    /// valley +180, mountain −180, flat 0; `None` where the angle is not defined.
    pub fn flat_folded_angle(self) -> Option<f64> {
        match self {
            Assignment::Valley => Some(180.0),
            Assignment::Mountain => Some(-180.0),
            Assignment::Flat => Some(0.0),
            _ => None,
        }
    }
}

impl fmt::Display for Assignment {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.letter())
    }
}

/// Error of [`Assignment::from_str`].
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("unknown edge assignment {0:?} (FOLD 1.2 defines B, M, V, F, U, C, J)")]
pub struct UnknownAssignment(pub String);

impl FromStr for Assignment {
    type Err = UnknownAssignment;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        let mut chars = s.chars();
        match (chars.next(), chars.next()) {
            (Some(c), None) => Assignment::from_letter(c),
            _ => None,
        }
        .ok_or_else(|| UnknownAssignment(s.to_string()))
    }
}
