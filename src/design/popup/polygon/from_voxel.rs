//! From a voxel card (Mitani, Suzuki & Uno 2003) to a polygon card (Mitani & Suzuki 2004), so a voxel design can be refined
//! with slanted edges, cut-outs and openings.
//!
//! Every pattern cell of the voxel card lands on one plane ([`Surface`]); the cells of each
//! plane other than the two sheets are merged (vertical runs per column, then a union) into one
//! face, added with eq. 5. Cells of the back plane below the fold or of the base plane above it
//! (windows folded onto a sheet, §2.3 of Mitani, Suzuki & Uno (2003)) become faces too. The polygon card keeps the
//! voxel pattern's coordinates shifted by the margin: voxel pattern point `(u, v)` is polygon
//! pattern point `(u + margin, v)`, card point `(x, y, z)` becomes `(x + margin, y, z)`.

use std::collections::BTreeMap;

use i_overlay::core::fill_rule::FillRule;
use i_overlay::core::overlay::Overlay;
use i_overlay::core::overlay_rule::OverlayRule;

use super::grid::{Point, rect, to_units};
use super::model::{FaceKind, Plane, PolygonCard, PolygonError};
use crate::design::popup::voxel::VoxelCard;
use crate::design::popup::voxel::surface::{self, Surface};
use glam::DVec2;

/// The polygon card with the same surface as `card` (see the module docs).
pub fn from_voxel(card: &VoxelCard) -> Result<PolygonCard, PolygonError> {
    let s = card.cell_mm();
    let m = card.margin_mm();
    let (w, h) = card.sheet_mm();
    let depth = card.ny() as f64 * s + m;
    let mut out = PolygonCard::new(w, depth, h - depth)?;
    let surface = Surface::new(card);
    let mut runs: BTreeMap<Plane, Vec<Vec<Point>>> = BTreeMap::new();
    for x in 0..surface.nx {
        let mut r = 0;
        while r < surface.rows {
            let p = surface.plane(x as i64, r as i64);
            let start = r;
            while r < surface.rows && surface.plane(x as i64, r as i64) == p {
                r += 1;
            }
            let v = |row: usize| (row as f64 - card.ny() as f64) * s;
            let in_sheet = match p {
                surface::Plane::Vertical(0) => v(start) >= 0.0,
                surface::Plane::Horizontal(0) => v(r) <= 0.0,
                _ => false,
            };
            if in_sheet {
                continue;
            }
            let lo = to_units(DVec2::new(x as f64 * s + m, v(start)));
            let hi = to_units(DVec2::new((x + 1) as f64 * s + m, v(r)));
            runs.entry(plane_mm(p, s))
                .or_default()
                .push(rect(lo.x, lo.y, hi.x, hi.y));
        }
    }
    for (plane, rects) in runs {
        let capacity = rects.len() * 4;
        let mut overlay = Overlay::new(capacity);
        for r in &rects {
            overlay.add_contour(r, i_overlay::core::overlay::ShapeType::Subject);
        }
        let union = overlay.overlay(OverlayRule::Subject, FillRule::NonZero);
        out.add_pattern_shapes(plane, union)?;
    }
    Ok(out)
}

/// A voxel plane (cells) as a polygon plane (grid units).
fn plane_mm(p: surface::Plane, s: f64) -> Plane {
    let (kind, cells) = match p {
        surface::Plane::Vertical(y) => (FaceKind::Vertical, y),
        surface::Plane::Horizontal(z) => (FaceKind::Horizontal, z),
    };
    let t = to_units(DVec2::new(f64::from(cells) * s, 0.0)).x;
    Plane { kind, t }
}
