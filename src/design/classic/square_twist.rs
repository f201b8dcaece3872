//! The classic square twist: a central square with one pleat on each side, the pleats running
//! to the sheet edges.
//!
//! The pleat of side k is the strip between two parallel creases leaving the side's two
//! corners at the twist angle α outwards from the side's direction; its width is L sin α for a
//! square of side L, and folded flat the square turns by 2α against the rest of the sheet. The
//! square is turned by α so the pleats run straight to the edges. At each corner the four
//! creases (two sides, two pleat creases at right angles) leave sectors of 90° (inside),
//! 180° − α, 90°, α: the alternating sum vanishes (Kawasaki). The sides are valleys; the pleat
//! crease bounding the smallest sector (α, between it and the next side) is the mountain, the
//! other a valley (Maekawa: 3 valleys, 1 mountain; the small sector lies between opposite
//! creases, as the big-little-big rule needs). So each pleat is one mountain (from the side's
//! first corner) and one valley (from its second). Earlier versions put the pleat creases at
//! α from the sides' normals: every vertex passed, but the corners folded back over the
//! square and no layer order existed; the tests now run the layer solver on the result.

use std::f64::consts::{FRAC_PI_2, PI};

use glam::DVec2;

use super::{ClassicError, finish, positive};
use crate::pattern::{Assignment, CreasePattern};

/// Parameters of a square twist.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SquareTwist {
    /// Side of the sheet (a square), mm.
    pub sheet: f64,
    /// Side of the central square, mm.
    pub square: f64,
    /// Twist angle α in degrees, in (0°, 45°).
    pub twist_deg: f64,
}

impl Default for SquareTwist {
    fn default() -> Self {
        SquareTwist {
            sheet: 120.0,
            square: 30.0,
            twist_deg: 22.5,
        }
    }
}

impl SquareTwist {
    /// Builds the pattern.
    pub fn build(&self) -> Result<CreasePattern, ClassicError> {
        let w = positive("sheet", self.sheet)?;
        let l = positive("square", self.square)?;
        let alpha = self.twist_deg;
        if !(alpha.is_finite() && alpha > 0.0 && alpha < 45.0) {
            return Err(ClassicError {
                parameter: "twist_deg",
                value: alpha,
                expected: "must be between 0 and 45 degrees",
            });
        }
        if l * 2.0 >= w {
            return Err(ClassicError {
                parameter: "square",
                value: l,
                expected: "must be less than half the sheet",
            });
        }
        let alpha = alpha.to_radians();
        let half = 0.5 * w;
        // Corners of the central square, counter-clockwise, turned by α so that the pleats,
        // which leave each side at α outwards from the side's direction, run straight to the
        // sheet edges.
        let corners: Vec<DVec2> = (0..4)
            .map(|k| {
                let a = alpha - 0.75 * PI + k as f64 * FRAC_PI_2;
                DVec2::from_angle(a) * (l / std::f64::consts::SQRT_2)
            })
            .collect();
        let mut cp = CreasePattern::new();
        for k in 0..4 {
            let (c, next) = (corners[k], corners[(k + 1) % 4]);
            cp.add_segment(c, next, Assignment::Valley);
            // The side's direction turned outwards (clockwise) by α.
            let out = DVec2::from_angle(-alpha).rotate((next - c).normalize());
            cp.add_segment(c, ray_to_square(c, out, half), Assignment::Mountain);
            cp.add_segment(next, ray_to_square(next, out, half), Assignment::Valley);
        }
        let sq = [
            DVec2::new(-half, -half),
            DVec2::new(half, -half),
            DVec2::new(half, half),
            DVec2::new(-half, half),
        ];
        for k in 0..4 {
            cp.add_segment(sq[k], sq[(k + 1) % 4], Assignment::Boundary);
        }
        let deg = self.twist_deg;
        finish(cp, format!("Square twist {deg}°"))
    }
}

/// Where the ray from `p` (inside the square |x|, |y| ≤ `half`) along unit `d` leaves it.
fn ray_to_square(p: DVec2, d: DVec2, half: f64) -> DVec2 {
    let exit = |pc: f64, dc: f64| {
        if dc > 0.0 {
            (half - pc) / dc
        } else if dc < 0.0 {
            (-half - pc) / dc
        } else {
            f64::INFINITY
        }
    };
    p + d * exit(p.x, d.x).min(exit(p.y, d.y))
}
