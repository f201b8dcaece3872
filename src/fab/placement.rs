//! Placement on the bed: from pattern millimetres to machine coordinates.
//!
//! # Frames
//! - **Pattern**: millimetres, x right, y up, anywhere.
//! - **Bed view**: the bed seen from above, x to the right, y towards the back, (0, 0) at the
//!   front-left corner, the bed covering [0, width] × [0, height]. The pattern keeps its
//!   orientation here (the part looks like the drawing when seen from above).
//! - **Machine**: what the G-code addresses. x counts from the left edge of the bed, or from
//!   the right edge (growing to the left) when [`Bed::origin`] is a right-hand corner; y counts
//!   from the front edge, or from the back edge (growing towards the front) when
//!   [`Bed::y_flipped`]. Every point of the bed, and so of the job, lies in
//!   [0, width] × [0, height]. For the usual profiles (bottom-left with y up, top-left with y
//!   down, …) machine (0, 0) is the origin corner.
//!
//! # Placement
//! The content (pattern bounds, toolpaths and any registration marks) is treated as a sheet:
//! its bounding box grown by the margin on every side. That sheet is put into the bed's
//! origin corner (so the job starts near where the machine homes) and must fit the bed, else
//! [`FabError::DoesNotFit`]. The transform is a translation in the bed view followed by the
//! axis flips of the machine frame: a rigid motion or a reflection, never a scaling.

use glam::{DAffine2, DVec2};

use super::{FabError, Toolpath};
use crate::machine::{Bed, Corner};

/// Relative slack when comparing sizes with the bed, so a sheet exactly as large as the bed
/// fits despite rounding.
const FIT_SLACK: f64 = 1e-9;

/// Bed view → machine coordinates for `bed` (see the module docs).
pub fn bed_to_machine(bed: &Bed) -> DAffine2 {
    let right = matches!(bed.origin, Corner::BottomRight | Corner::TopRight);
    let (sx, tx) = if right {
        (-1.0, bed.width_mm)
    } else {
        (1.0, 0.0)
    };
    let (sy, ty) = if bed.y_flipped {
        (-1.0, bed.height_mm)
    } else {
        (1.0, 0.0)
    };
    DAffine2::from_scale_angle_translation(DVec2::new(sx, sy), 0.0, DVec2::new(tx, ty))
}

/// Pattern → machine transform that puts `extent` (pattern min and max corners) `margin_mm`
/// from the bed's origin corner. Fails with [`FabError::DoesNotFit`] when the extent plus a
/// margin on each side is larger than the bed.
pub fn place(extent: (DVec2, DVec2), bed: &Bed, margin_mm: f64) -> Result<DAffine2, FabError> {
    let margin = if margin_mm.is_finite() {
        margin_mm.max(0.0)
    } else {
        0.0
    };
    let size = (extent.1 - extent.0).max(DVec2::ZERO);
    let needed = size + DVec2::splat(2.0 * margin);
    let fits = |need: f64, have: f64| need <= have * (1.0 + FIT_SLACK) + FIT_SLACK;
    if !fits(needed.x, bed.width_mm) || !fits(needed.y, bed.height_mm) {
        return Err(FabError::DoesNotFit {
            width: needed.x,
            height: needed.y,
            bed_width: bed.width_mm,
            bed_height: bed.height_mm,
        });
    }
    let right = matches!(bed.origin, Corner::BottomRight | Corner::TopRight);
    let top = matches!(bed.origin, Corner::TopLeft | Corner::TopRight);
    let x0 = if right {
        bed.width_mm - margin - size.x
    } else {
        margin
    };
    let y0 = if top {
        bed.height_mm - margin - size.y
    } else {
        margin
    };
    let to_bed = DAffine2::from_translation(DVec2::new(x0, y0) - extent.0);
    Ok(bed_to_machine(bed) * to_bed)
}

/// Where the job goes on the bed (`--origin`, `--offset`).
#[derive(Clone, Copy, Debug, PartialEq, Default, serde::Serialize)]
pub struct Placement {
    /// Centre the sheet on the bed instead of putting it in the origin corner.
    pub centre: bool,
    /// Shift after placing, mm, in the bed view (x right, y towards the back).
    pub offset_mm: DVec2,
}

/// [`place`] with a [`Placement`]: the sheet (extent plus margin) in the origin corner or
/// centred on the bed, then shifted by the offset. Fails with [`FabError::DoesNotFit`] when
/// the sheet is larger than the bed, and with [`FabError::Geometry`] when the offset pushes
/// it off the bed (naming how far).
pub fn place_with(
    extent: (DVec2, DVec2),
    bed: &Bed,
    margin_mm: f64,
    placement: Placement,
) -> Result<DAffine2, FabError> {
    let corner = place(extent, bed, margin_mm)?;
    if !placement.centre && placement.offset_mm == DVec2::ZERO {
        return Ok(corner);
    }
    let margin = if margin_mm.is_finite() {
        margin_mm.max(0.0)
    } else {
        0.0
    };
    let size = (extent.1 - extent.0).max(DVec2::ZERO);
    let sheet = size + DVec2::splat(2.0 * margin);
    let bed_size = DVec2::new(bed.width_mm, bed.height_mm);
    // The sheet's lower-left corner in the bed view.
    let mut at = if placement.centre {
        (bed_size - sheet) / 2.0
    } else {
        let to_bed = bed_to_machine(bed).inverse() * corner;
        to_bed.transform_point2(extent.0) - DVec2::splat(margin)
    };
    at += placement.offset_mm;
    let slack = FIT_SLACK * bed_size.max_element().max(1.0);
    let low = at.min_element() < -slack;
    let high = (at + sheet - bed_size).max_element() > slack;
    if low || high || !at.is_finite() {
        return Err(FabError::Geometry {
            step: "placement",
            message: format!(
                "the {:.1} × {:.1} mm sheet placed at ({:.1}, {:.1}) mm leaves the {} × {} mm bed",
                sheet.x, sheet.y, at.x, at.y, bed.width_mm, bed.height_mm
            ),
        });
    }
    let to_bed = DAffine2::from_translation(at + DVec2::splat(margin) - extent.0);
    Ok(bed_to_machine(bed) * to_bed)
}

/// Applies `t` to every point of `paths`.
pub fn transform_paths(paths: &mut [Toolpath], t: &DAffine2) {
    for p in paths
        .iter_mut()
        .flat_map(|p| p.strokes.iter_mut())
        .flatten()
    {
        *p = t.transform_point2(*p);
    }
}

/// Bounding box (min, max) of every point of `paths`, `None` when there is none.
pub fn bounds_of(paths: &[Toolpath]) -> Option<(DVec2, DVec2)> {
    let points = paths.iter().flat_map(|p| &p.strokes).flatten().copied();
    crate::geom::Rect::of(points).map(crate::geom::Rect::corners)
}

/// The smallest box holding both boxes (either may be missing).
pub fn union(a: Option<(DVec2, DVec2)>, b: Option<(DVec2, DVec2)>) -> Option<(DVec2, DVec2)> {
    match (a, b) {
        (Some(a), Some(b)) => Some((a.0.min(b.0), a.1.max(b.1))),
        (a, None) => a,
        (None, b) => b,
    }
}
