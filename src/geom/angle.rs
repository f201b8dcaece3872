//! Angles of directions in the plane.

use glam::DVec2;
use std::f64::consts::TAU;

/// Direction angle of `v` in [0, 2π), measured counter-clockwise from +x.
#[inline]
pub fn direction(v: DVec2) -> f64 {
    let a = v.y.atan2(v.x);
    if a < 0.0 { a + TAU } else { a }
}

/// Counter-clockwise angle from direction `a` to direction `b` (radians), in [0, 2π).
#[inline]
pub fn ccw_between(a: f64, b: f64) -> f64 {
    let d = b - a;
    if d < 0.0 { d + TAU } else { d }
}
