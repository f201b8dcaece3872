//! The top view of a flat-folded state, as origami designers look at one (Flat-Folder's
//! folded view): every cell of the overlap arrangement filled with the colour of the face
//! seen from above (paper front or back), darker where more layers lie, with the folded
//! outline drawn black and the inner folded edges thin grey. Optionally the X-ray view: every
//! cell shaded by its number of layers only.

use glam::DVec2;
use tiny_skia::{FillRule, Paint, PathBuilder, Pixmap, Stroke, Transform};

use super::RenderError;
use super::layout::{Layout, MAX_SIZE, MIN_SIZE};
use crate::check::layers::{TopCell, TopView};

/// Colour of the paper's front side (the crease pattern's upper side).
const FRONT: [u8; 3] = [250, 236, 200];
/// Colour of the back side.
const BACK: [u8; 3] = [120, 170, 215];
/// Share of the colour kept in the cell with the most layers (depth shading).
const DEEPEST: f64 = 0.45;
/// Margin around the drawing, pixels.
const MARGIN: u32 = 24;

/// The most layers in any cell of `view` (at least 2, so one layer is never the deepest).
pub fn deepest_layers(view: &TopView) -> usize {
    view.cells
        .iter()
        .map(|c| c.layers)
        .max()
        .unwrap_or(1)
        .max(2)
}

/// The fill of `cell`: the colour of the face on top (front cream, back blue; light grey in
/// the X-ray view), darkened linearly with the number of layers down to [`DEEPEST`] of it in
/// the cell of `deepest` layers ([`deepest_layers`]).
pub fn cell_colour(cell: &TopCell, deepest: usize, xray: bool) -> [u8; 3] {
    let depth = (cell.layers.saturating_sub(1)) as f64 / (deepest.max(2) - 1) as f64;
    let keep = 1.0 - (1.0 - DEEPEST) * depth.min(1.0);
    let base = if xray {
        [235, 235, 235]
    } else if cell.top_flipped {
        BACK
    } else {
        FRONT
    };
    base.map(|c| (f64::from(c) * keep).round() as u8)
}

/// Draws `view` as a PNG `width` pixels wide; with `xray`, cells are shaded by their number of
/// layers instead of by the face on top.
pub fn render_top_view_png(view: &TopView, width: u32, xray: bool) -> Result<Vec<u8>, RenderError> {
    if !(MIN_SIZE..=MAX_SIZE).contains(&width) {
        return Err(RenderError::Width(width));
    }
    let (lo, hi) = view
        .cells
        .iter()
        .flat_map(|c| c.rings.iter().flatten())
        .fold(None, |acc: Option<(DVec2, DVec2)>, &p| {
            Some(acc.map_or((p, p), |(lo, hi)| (lo.min(p), hi.max(p))))
        })
        .ok_or(RenderError::NoFaces)?;
    let layout = Layout::new(lo, hi, width, MARGIN.min(width / 8), 0);
    let mut pixmap = Pixmap::new(layout.width, layout.height).ok_or(RenderError::Allocation {
        width: layout.width,
        height: layout.height,
    })?;
    pixmap.fill(tiny_skia::Color::WHITE);
    let deepest = deepest_layers(view);
    for cell in &view.cells {
        let rgb = cell_colour(cell, deepest, xray);
        let mut pb = PathBuilder::new();
        for ring in &cell.rings {
            for (i, &p) in ring.iter().enumerate() {
                let q = layout.to_px(p);
                if i == 0 {
                    pb.move_to(q.x as f32, q.y as f32);
                } else {
                    pb.line_to(q.x as f32, q.y as f32);
                }
            }
            pb.close();
        }
        if let Some(path) = pb.finish() {
            let mut paint = Paint::default();
            paint.set_color_rgba8(rgb[0], rgb[1], rgb[2], 255);
            pixmap.fill_path(
                &path,
                &paint,
                FillRule::EvenOdd,
                Transform::identity(),
                None,
            );
        }
    }
    let lw = (width as f32 / 800.0).max(1.0);
    for (outline, color, w) in [(false, [90, 90, 90], 0.5 * lw), (true, [0, 0, 0], 1.5 * lw)] {
        let mut pb = PathBuilder::new();
        for &([a, b], on_outline) in &view.segments {
            if on_outline == outline {
                let (p, q) = (layout.to_px(a), layout.to_px(b));
                pb.move_to(p.x as f32, p.y as f32);
                pb.line_to(q.x as f32, q.y as f32);
            }
        }
        if let Some(path) = pb.finish() {
            let mut paint = Paint::default();
            paint.set_color_rgba8(color[0], color[1], color[2], 255);
            paint.anti_alias = true;
            let stroke = Stroke {
                width: w,
                ..Stroke::default()
            };
            pixmap.stroke_path(&path, &paint, &stroke, Transform::identity(), None);
        }
    }
    pixmap
        .encode_png()
        .map_err(|e| RenderError::Encode(e.to_string()))
}
