//! Framing: the outline a machine traces so the operator sees where a job lands on the sheet
//! before burning it (LightBurn's *Frame*).
//!
//! The frame is the axis-aligned bounding box of every stroke point of a job in machine
//! coordinates — exactly the area the tool visits while burning, kerf not included — traced
//! from its lower-left corner counter-clockwise back to the start. The G-code writer
//! (`post::gcode::frame`) traces it with the tool off or at a low power.

use glam::DVec2;

use super::Setup;

/// Lower-left and upper-right corners of every stroke point of `job`, mm; `None` when it has
/// no point or a coordinate is not finite.
pub fn bounds(job: &Setup) -> Option<(DVec2, DVec2)> {
    let mut points = job.paths.iter().flat_map(|p| p.strokes.iter().flatten());
    let first = *points.next()?;
    let (lo, hi) = points.fold((first, first), |(lo, hi), p| (lo.min(*p), hi.max(*p)));
    (lo.is_finite() && hi.is_finite()).then_some((lo, hi))
}

/// The frame of `job`: its [`bounds`] as a closed polyline of five points, lower-left,
/// lower-right, upper-right, upper-left, lower-left.
pub fn outline(job: &Setup) -> Option<Vec<DVec2>> {
    let (lo, hi) = bounds(job)?;
    Some(vec![
        lo,
        DVec2::new(hi.x, lo.y),
        hi,
        DVec2::new(lo.x, hi.y),
        lo,
    ])
}
