//! Drawing the preview: lines by assignment, fault highlights (numbered rings, [`super::rings`]),
//! and the key under it (scale bar and legend, [`super::legend`]).

use glam::DVec2;
use tiny_skia::{Color, LineCap, Paint, PathBuilder, Pixmap, Stroke, StrokeDash, Transform};

use super::layout::{Layout, MAX_SIZE, MIN_SIZE};
use super::legend::{self, Key, LegendEntry, ScaleBar, Swatch};
use super::style::{DRAW_ORDER, FAULT_COLOR, LineStyle, line_style};
use super::{PreviewOptions, RenderError, chain, rings};
use crate::check::Finding;
use crate::geom::Segment;
use crate::pattern::{Assignment, CreasePattern};

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
    let lw = opts.line_width_px;
    // The key's height depends on its rows, not on the scale: lay out, then size the band.
    let first = Layout::new(lo, hi, opts.width, margin, 0);
    let key = preview_key(cp, opts, &first, faults);
    let inner = opts.width - 2 * margin;
    let band = key.height(inner, first.font_px) + margin / 2;
    let layout = Layout::new(lo, hi, opts.width, margin, band);
    let key = preview_key(cp, opts, &layout, faults);
    let mut pixmap = Pixmap::new(layout.width, layout.height).ok_or(RenderError::Allocation {
        width: layout.width,
        height: layout.height,
    })?;
    let [r, g, b, a] = opts.background;
    pixmap.fill(Color::from_rgba8(r, g, b, a));
    draw_fault_edges(&mut pixmap, cp, &layout, faults, lw);
    for assignment in DRAW_ORDER {
        let style = line_style(assignment, lw);
        let style = match (assignment, opts.dark_flat) {
            (Assignment::Flat, true) => dark_flat_style(lw),
            _ => style,
        };
        draw_lines(&mut pixmap, cp, &layout, assignment, &style);
    }
    rings::draw(&mut pixmap, &layout, faults, lw);
    let top = f64::from(layout.band_top);
    key.draw(&mut pixmap, f64::from(margin), top, inner, layout.font_px);
    Ok(pixmap)
}

/// Flat lines drawn as text (paper-craft edge numbers): dark and as wide as a crease.
fn dark_flat_style(lw: f32) -> LineStyle {
    LineStyle {
        color: legend::INK,
        width: lw,
        dash: None,
    }
}

/// The key under a preview: the scale bar, one entry per assignment drawn, and the rings.
fn preview_key(
    cp: &CreasePattern,
    opts: &PreviewOptions,
    layout: &Layout,
    faults: &[Finding],
) -> Key {
    let unit = cp.units.label();
    let drawable = f64::from(layout.width - 2 * layout.margin);
    let scale_bar = opts.scale_bar.then_some(ScaleBar {
        px_per_unit: layout.scale,
        unit,
        max_px: drawable * SCALE_BAR_SHARE,
    });
    let mut entries = Vec::new();
    if opts.legend {
        let lw = opts.line_width_px;
        for a in DRAW_ORDER.iter().rev() {
            if cp.edges.iter().any(|e| e.assignment == *a) {
                let s = match (*a, opts.dark_flat) {
                    (Assignment::Flat, true) => dark_flat_style(lw),
                    _ => line_style(*a, lw),
                };
                let label = match (*a, opts.dark_flat) {
                    (Assignment::Flat, true) => "flat, labels",
                    _ => a.name(),
                };
                entries.push(LegendEntry::line(label, s.color, s.width, s.dash));
            }
        }
        if !faults.is_empty() {
            entries.push(LegendEntry {
                swatch: Swatch::Ring { color: FAULT_COLOR },
                label: "finding, numbered as in the report".into(),
            });
        }
    }
    Key {
        scale_bar,
        entries,
        ..Key::default()
    }
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
fn edge_px(cp: &CreasePattern, layout: &Layout, i: usize) -> Option<Segment> {
    let e = cp.edges.get(i)?;
    let a = *cp.vertices.get(e.vertices[0].index())?;
    let b = *cp.vertices.get(e.vertices[1].index())?;
    Some(Segment::new(layout.to_px(a), layout.to_px(b)))
}

fn push_segment(pb: &mut PathBuilder, Segment { a, b }: Segment) {
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
