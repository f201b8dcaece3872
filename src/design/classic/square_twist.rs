//! The square twist: a central square whose corners each send out two perpendicular pleat
//! creases, rotated by the twist angle α.
//!
//! Around each corner, counter-clockwise from the side towards the next corner, the sectors
//! are 90° (inside the square), 90° − α, 90°, 90° + α: the alternating sum vanishes
//! (Kawasaki). The square's sides are valleys; of the two pleat creases the one bounding the
//! smallest sector (90° − α) is the mountain, the other a valley (3 valleys, 1 mountain:
//! Maekawa), so each pleat pair (parallel creases from neighbouring corners) is one mountain
//! and one valley.

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
        // Corners of the central square, counter-clockwise, tilted by α so pleats leave at
        // generic angles.
        let corners: Vec<DVec2> = (0..4)
            .map(|k| {
                let a =
                    alpha + std::f64::consts::FRAC_PI_4 + k as f64 * std::f64::consts::FRAC_PI_2;
                DVec2::from_angle(a) * (l / std::f64::consts::SQRT_2)
            })
            .collect();
        let mut cp = CreasePattern::new();
        for k in 0..4 {
            let c = corners[k];
            let next = corners[(k + 1) % 4];
            cp.add_segment(c, next, Assignment::Valley);
            let dir = (next - c).normalize();
            let out_a = DVec2::from_angle(std::f64::consts::PI - alpha).rotate(dir);
            let out_b = DVec2::from_angle(1.5 * std::f64::consts::PI - alpha).rotate(dir);
            cp.add_segment(c, ray_to_square(c, out_a, half), Assignment::Mountain);
            cp.add_segment(c, ray_to_square(c, out_b, half), Assignment::Valley);
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
