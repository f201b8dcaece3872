//! Drawing the preview: lines by assignment, fault highlights, scale bar.

use glam::DVec2;
use tiny_skia::{Color, LineCap, Paint, PathBuilder, Pixmap, Rect, Stroke, StrokeDash, Transform};

use super::layout::{Layout, MAX_SIZE, MIN_SIZE, length_label, nice_length};
use super::style::{DRAW_ORDER, FAULT_COLOR, LineStyle, SCALE_BAR_COLOR, line_style};
use super::{PreviewOptions, RenderError};
use super::{chain, font};
use crate::check::Finding;
use crate::pattern::{Assignment, CreasePattern, Units};

/// Share of the drawable width the scale bar may take at most.
const SCALE_BAR_SHARE: f64 = 0.3;

/// Draws a pattern into a tiny-skia pixmap (premultiplied RGBA), highlighting `faults`.
pub fn render_pixmap(
    cp: &CreasePattern,
    opts: &PreviewOptions,
    faults: &[Finding],
) -> Result<Pixmap, RenderError> {
    check_options(opts)?;
    let (lo, hi) = edge_bounds(cp).ok_or(RenderError::Empty)?;
    let margin = opts.margin.min(opts.width / 8);
    let layout = Layout::new(lo, hi, opts.width, margin, opts.scale_bar);
    let mut pixmap = Pixmap::new(layout.width, layout.height).ok_or(RenderError::Allocation {
        width: layout.width,
        height: layout.height,
    })?;
    let [r, g, b, a] = opts.background;
    pixmap.fill(Color::from_rgba8(r, g, b, a));
    let lw = opts.line_width_px;
    draw_fault_edges(&mut pixmap, cp, &layout, faults, lw);
    for assignment in DRAW_ORDER {
        draw_lines(
            &mut pixmap,
            cp,
            &layout,
            assignment,
            &line_style(assignment, lw),
        );
    }
    draw_fault_rings(&mut pixmap, &layout, faults, lw);
    if opts.scale_bar {
        let unit = match cp.units {
            Units::Millimetres => "mm",
            Units::Unitless => "units",
        };
        draw_scale_bar(&mut pixmap, &layout, unit);
    }
    Ok(pixmap)
}

fn check_options(opts: &PreviewOptions) -> Result<(), RenderError> {
    if !(MIN_SIZE..=MAX_SIZE).contains(&opts.width) {
        return Err(RenderError::Width(opts.width));
    }
    let lw = opts.line_width_px;
    if !(lw.is_finite() && lw > 0.0 && lw <= 64.0) {
        return Err(RenderError::Option {
            name: "line_width_px",
            value: lw.to_string(),
            expected: "a width in pixels above 0 and at most 64",
        });
    }
    Ok(())
}

/// Bounds of the vertices that edges use (isolated vertices are not drawn); `None` when
/// there are no edges.
fn edge_bounds(cp: &CreasePattern) -> Option<(DVec2, DVec2)> {
    let points = cp
        .edges
        .iter()
        .flat_map(|e| e.vertices)
        .filter_map(|v| cp.vertices.get(v.index()).copied());
    crate::geom::Rect::of(points).map(crate::geom::Rect::corners)
}

fn paint(color: [u8; 4]) -> Paint<'static> {
    let mut paint = Paint::default();
    paint.set_color_rgba8(color[0], color[1], color[2], color[3]);
    paint.anti_alias = true;
    paint
}

/// The segment of an edge in pixels, `None` if it refers to a missing vertex.
fn edge_px(cp: &CreasePattern, layout: &Layout, i: usize) -> Option<(DVec2, DVec2)> {
    let e = cp.edges.get(i)?;
    let a = *cp.vertices.get(e.vertices[0].index())?;
    let b = *cp.vertices.get(e.vertices[1].index())?;
    Some((layout.to_px(a), layout.to_px(b)))
}

fn push_segment(pb: &mut PathBuilder, (a, b): (DVec2, DVec2)) {
    pb.move_to(a.x as f32, a.y as f32);
    pb.line_to(b.x as f32, b.y as f32);
}

/// Strokes every edge of one assignment as one path of straight polylines (see [`chain`]), so
/// dashes run on along a crease line.
fn draw_lines(
    pixmap: &mut Pixmap,
    cp: &CreasePattern,
    layout: &Layout,
    assignment: Assignment,
    style: &LineStyle,
) {
    let mut pb = PathBuilder::new();
    chain::for_each_polyline(cp, assignment, |points| {
        for (i, &p) in points.iter().enumerate() {
            let q = layout.to_px(p);
            if i == 0 {
                pb.move_to(q.x as f32, q.y as f32);
            } else {
                pb.line_to(q.x as f32, q.y as f32);
            }
        }
    });
    let Some(path) = pb.finish() else {
        return;
    };
    let stroke = Stroke {
        width: style.width,
        line_cap: LineCap::Butt,
        dash: style.dash.clone().and_then(|d| StrokeDash::new(d, 0.0)),
        ..Stroke::default()
    };
    pixmap.stroke_path(
        &path,
        &paint(style.color),
        &stroke,
        Transform::identity(),
        None,
    );
}

/// An orange halo under every edge a finding names (drawn before the lines).
fn draw_fault_edges(
    pixmap: &mut Pixmap,
    cp: &CreasePattern,
    layout: &Layout,
    faults: &[Finding],
    lw: f32,
) {
    let mut pb = PathBuilder::new();
    for e in faults.iter().filter_map(|f| f.edge) {
        if let Some(seg) = edge_px(cp, layout, e.index()) {
            push_segment(&mut pb, seg);
        }
    }
    let Some(path) = pb.finish() else {
        return;
    };
    let stroke = Stroke {
        width: 4.0 * lw + 2.0,
        line_cap: LineCap::Round,
        ..Stroke::default()
    };
    let [r, g, b, _] = FAULT_COLOR;
    let halo = paint([r, g, b, 170]);
    pixmap.stroke_path(&path, &halo, &stroke, Transform::identity(), None);
}

/// A semi-transparent ring around every finding's position (drawn on top); its radius is six
/// line widths, at least 10 px and 1/80 of the image width.
fn draw_fault_rings(pixmap: &mut Pixmap, layout: &Layout, faults: &[Finding], lw: f32) {
    let radius = (6.0 * lw).max(10.0).max(layout.width as f32 / 80.0);
    let mut pb = PathBuilder::new();
    for f in faults {
        let p = layout.to_px(f.position);
        if p.is_finite() {
            pb.push_circle(p.x as f32, p.y as f32, radius);
        }
    }
    let Some(path) = pb.finish() else {
        return;
    };
    let stroke = Stroke {
        width: (1.5 * lw).max(2.5),
        ..Stroke::default()
    };
    let [r, g, b, _] = FAULT_COLOR;
    pixmap.stroke_path(
        &path,
        &paint([r, g, b, 160]),
        &stroke,
        Transform::identity(),
        None,
    );
}

fn fill_rect(pixmap: &mut Pixmap, x: f64, y: f64, w: f64, h: f64, color: [u8; 4]) {
    if let Some(rect) = Rect::from_xywh(x as f32, y as f32, w as f32, h as f32) {
        let mut p = paint(color);
        p.anti_alias = false;
        pixmap.fill_rect(rect, &p, Transform::identity(), None);
    }
}

/// A bar of a nice length with end ticks, |____| , and its label, at the bottom left.
fn draw_scale_bar(pixmap: &mut Pixmap, layout: &Layout, unit: &str) {
    let fp = f64::from(layout.font_px);
    let drawable = f64::from(layout.width - 2 * layout.margin);
    let Some(length) = nice_length(drawable * SCALE_BAR_SHARE / layout.scale) else {
        return;
    };
    let bar = length * layout.scale;
    if bar < 2.0 {
        return;
    }
    let glyph_h = f64::from(font::GLYPH_HEIGHT) * fp;
    let thick = 2.0 * fp;
    let x0 = f64::from(layout.margin);
    let y0 = f64::from(layout.band_top) + 2.0 * fp;
    let c = SCALE_BAR_COLOR;
    fill_rect(pixmap, x0, y0, thick, glyph_h, c);
    fill_rect(pixmap, x0 + bar - thick, y0, thick, glyph_h, c);
    fill_rect(pixmap, x0, y0 + glyph_h - thick, bar, thick, c);
    let label = length_label(length, unit);
    let lx = x0 + bar + 4.0 * fp;
    font::for_each_dot(&label, |col, row| {
        let x = lx + f64::from(col) * fp;
        let y = y0 + f64::from(row) * fp;
        fill_rect(pixmap, x, y, fp, fp, c);
    });
}
