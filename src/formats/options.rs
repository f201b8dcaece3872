//! Options of the drawing readers (SVG, DXF): the snapping tolerance, what a dashed line means
//! in a drawing of one colour, and the chordal tolerance for curves.

use std::fmt;
use std::str::FromStr;

use crate::pattern::Assignment;

/// What a dashed line means in a drawing whose lines all have one colour (Blender Paper
/// Model, most paper-craft and laser-cutter exports draw folds dashed and cuts solid).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum DashedAs {
    /// The origami diagram convention (Yoshizawa–Randlett): plain dashes are valley folds,
    /// dash-dot patterns (dashes of two or more lengths) mountain folds.
    #[default]
    Auto,
    /// Every dashed line is this assignment.
    Fixed(Assignment),
}

impl DashedAs {
    /// The assignment of a dashed line whose dash pattern is `dashes` (lengths, any unit).
    pub fn assignment(self, dashes: &[f64]) -> Assignment {
        match self {
            DashedAs::Fixed(a) => a,
            DashedAs::Auto if is_dash_dot(dashes) => Assignment::Mountain,
            DashedAs::Auto => Assignment::Valley,
        }
    }
}

/// True when the "on" dashes of a pattern have two or more clearly different lengths (a
/// dash-dot); the pattern repeats, as SVG's `stroke-dasharray` does when odd.
pub fn is_dash_dot(dashes: &[f64]) -> bool {
    let cycle: Vec<f64> = if dashes.len() % 2 == 1 {
        dashes.iter().chain(dashes).copied().collect()
    } else {
        dashes.to_vec()
    };
    let on: Vec<f64> = cycle.iter().step_by(2).copied().collect();
    let (lo, hi) = on.iter().fold((f64::INFINITY, 0.0_f64), |(lo, hi), &d| {
        (lo.min(d), hi.max(d))
    });
    on.len() >= 2 && hi > DASH_DOT_RATIO * lo
}

/// A dash at least this many times longer than the shortest one makes a dash-dot pattern.
pub const DASH_DOT_RATIO: f64 = 1.5;

impl FromStr for DashedAs {
    type Err = String;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        let fixed = |a| Ok(DashedAs::Fixed(a));
        match s.to_ascii_lowercase().as_str() {
            "auto" => Ok(DashedAs::Auto),
            "valley" | "v" => fixed(Assignment::Valley),
            "mountain" | "m" => fixed(Assignment::Mountain),
            "cut" | "c" => fixed(Assignment::Cut),
            "flat" | "mark" | "f" => fixed(Assignment::Flat),
            "unassigned" | "fold" | "u" => fixed(Assignment::Unassigned),
            "boundary" | "b" => fixed(Assignment::Boundary),
            other => Err(format!(
                "unknown meaning \"{other}\" for dashed lines (expected auto, valley, mountain, \
                 cut, flat, unassigned or boundary)"
            )),
        }
    }
}

impl fmt::Display for DashedAs {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            DashedAs::Auto => write!(f, "auto"),
            DashedAs::Fixed(a) => write!(f, "{}", a.name()),
        }
    }
}

/// How a pattern file is read: the frame of a FOLD file, and how drawings (SVG, DXF) are
/// read.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ReadOptions {
    /// The frame of a FOLD file to read: 0 is the key frame, `i` is `file_frames[i - 1]`
    /// (inheritance resolved). Other formats hold one frame and refuse any other.
    pub frame: usize,
    /// Line ends closer than this to a vertex or line are joined to it, in millimetres (in
    /// drawing units for unitless drawings); `None` picks [`super::snap::SNAP_RELATIVE`] of
    /// the drawing's diagonal, `Some(0.0)` turns snapping off.
    pub snap: Option<f64>,
    /// What a dashed line means in a single-colour drawing.
    pub dashed: DashedAs,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dash_patterns_are_told_apart() {
        assert!(!is_dash_dot(&[3.0, 2.0]));
        assert!(!is_dash_dot(&[3.0]));
        assert!(is_dash_dot(&[6.0, 2.0, 1.0, 2.0]));
        assert!(is_dash_dot(&[6.0, 2.0, 1.0]));
        let auto = DashedAs::Auto;
        assert_eq!(auto.assignment(&[3.0, 2.0]), Assignment::Valley);
        assert_eq!(auto.assignment(&[6.0, 2.0, 1.0, 2.0]), Assignment::Mountain);
        let cut: DashedAs = "cut".parse().unwrap_or_default();
        assert_eq!(cut.assignment(&[6.0, 2.0, 1.0, 2.0]), Assignment::Cut);
        assert!("sideways".parse::<DashedAs>().is_err());
    }
}
