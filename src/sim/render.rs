//! A PNG of a simulated run: the bed outline, travel as thin dashed grey lines, burns coloured
//! by power in 32 steps (blue for the profile's lowest power through red for its highest; pen
//! strokes in black), seen from above with the bed's front at the bottom.
//!
//! Travel and burns are drawn by [`super::raster`] in time linear in the moves; the bed outline
//! by tiny-skia.
//!
//! Machine x runs to the right. Machine y runs up the image unless the bed is `y_flipped`
//! (origin at the back), when it runs down. Moves outside the bed are drawn where they go,
//! clipped by the image.

use glam::DVec2;
use tiny_skia::{Color, Paint, PathBuilder, Pixmap, Stroke, Transform};

use super::raster::{Pen, draw_segment};
use super::report::SimReport;
use crate::machine::MachineProfile;
use crate::render::{MAX_SIZE, MIN_SIZE, RenderError};

/// Margin around the bed, as a share of the width.
const MARGIN_SHARE: f64 = 0.04;

/// Maps machine millimetres in the visible region to pixels.
struct View {
    scale: f64,
    margin: f64,
    /// Lower corner of the visible region, machine mm.
    lo: DVec2,
    /// Height of the visible region, mm.
    height: f64,
    y_flipped: bool,
}

impl View {
    fn px(&self, p: DVec2) -> (f32, f32) {
        let y = if self.y_flipped {
            p.y - self.lo.y
        } else {
            self.lo.y + self.height - p.y
        };
        (
            (self.margin + (p.x - self.lo.x) * self.scale) as f32,
            (self.margin + y * self.scale) as f32,
        )
    }
}

/// The region drawn: the whole bed, or, when the job (with the origin it starts from) covers
/// less than half of the bed both ways, the job's bounds with a 5 % border, so a small job on
/// a large bed is not a speck.
fn region(report: &SimReport, bed: &crate::machine::Bed) -> (DVec2, DVec2) {
    let whole = (DVec2::ZERO, DVec2::new(bed.width_mm, bed.height_mm));
    let points = report
        .burns
        .iter()
        .flat_map(|b| [b.from, b.to])
        .chain(report.travels.iter().flat_map(|t| [t.from, t.to]))
        .filter(|p| p.is_finite());
    let (lo, hi) = points.fold((DVec2::ZERO, DVec2::ZERO), |(lo, hi), p| {
        (lo.min(p), hi.max(p))
    });
    let size = hi - lo;
    if size.x > 0.5 * bed.width_mm || size.y > 0.5 * bed.height_mm || size.max_element() <= 0.0 {
        return whole;
    }
    let border = DVec2::splat(0.05 * size.max_element());
    (lo - border, size + 2.0 * border)
}

/// Draws `report` on the bed of `machine` as PNG bytes, `width` pixels wide (16 to 16384; the
/// height follows the drawn region's aspect ratio, at most 16384 pixels). The region is the bed,
/// or the job's neighbourhood when the job is small on a large bed.
pub fn render_png(
    report: &SimReport,
    machine: &MachineProfile,
    width: u32,
) -> Result<Vec<u8>, RenderError> {
    if !(MIN_SIZE..=MAX_SIZE).contains(&width) {
        return Err(RenderError::Width(width));
    }
    let (view, height) = layout(machine, region(report, &machine.bed), width)?;
    let mut pixmap = Pixmap::new(width, height).ok_or(RenderError::Allocation { width, height })?;
    pixmap.fill(Color::WHITE);
    let lw = (width as f32 / 800.0).max(1.0);
    draw_bed(&mut pixmap, &view, machine, lw);
    draw_travel(&mut pixmap, &view, report, lw);
    draw_burns(&mut pixmap, &view, report, lw);
    pixmap
        .encode_png()
        .map_err(|e| RenderError::Encode(e.to_string()))
}

fn layout(
    machine: &MachineProfile,
    (lo, size): (DVec2, DVec2),
    width: u32,
) -> Result<(View, u32), RenderError> {
    let bed = machine.bed;
    let valid = |v: f64| v.is_finite() && v > 0.0;
    if !(valid(bed.width_mm) && valid(bed.height_mm)) {
        return Err(RenderError::Option {
            name: "bed",
            value: format!("{} × {}", bed.width_mm, bed.height_mm),
            expected: "a bed with positive, finite width and height",
        });
    }
    let margin = (f64::from(width) * MARGIN_SHARE).round();
    let mut scale = (f64::from(width) - 2.0 * margin) / size.x;
    let max_h = f64::from(MAX_SIZE) - 2.0 * margin;
    scale = scale.min(max_h / size.y);
    let height = (size.y * scale + 2.0 * margin).ceil().max(1.0) as u32;
    let view = View {
        scale,
        margin,
        lo,
        height: size.y,
        y_flipped: bed.y_flipped,
    };
    Ok((view, height.min(MAX_SIZE)))
}

fn paint(rgba: [u8; 4]) -> Paint<'static> {
    let mut p = Paint::default();
    p.set_color_rgba8(rgba[0], rgba[1], rgba[2], rgba[3]);
    p.anti_alias = true;
    p
}

fn segment(pb: &mut PathBuilder, view: &View, a: DVec2, b: DVec2) {
    let (ax, ay) = view.px(a);
    let (bx, by) = view.px(b);
    pb.move_to(ax, ay);
    pb.line_to(bx, by);
}

fn stroke_path(pixmap: &mut Pixmap, pb: PathBuilder, color: [u8; 4], stroke: &Stroke) {
    if let Some(path) = pb.finish() {
        pixmap.stroke_path(&path, &paint(color), stroke, Transform::identity(), None);
    }
}

fn draw_bed(pixmap: &mut Pixmap, view: &View, machine: &MachineProfile, lw: f32) {
    let (w, h) = (machine.bed.width_mm, machine.bed.height_mm);
    let corners = [(0.0, 0.0), (w, 0.0), (w, h), (0.0, h)].map(|(x, y)| DVec2::new(x, y));
    let mut pb = PathBuilder::new();
    for i in 0..4 {
        segment(&mut pb, view, corners[i], corners[(i + 1) % 4]);
    }
    let stroke = Stroke {
        width: lw,
        ..Stroke::default()
    };
    stroke_path(pixmap, pb, [60, 60, 60, 255], &stroke);
}

fn draw_travel(pixmap: &mut Pixmap, view: &View, report: &SimReport, lw: f32) {
    let pen = Pen {
        color: [150, 150, 150, 200],
        width: lw * 0.5,
        dash: Some(3.0 * lw),
    };
    for t in &report.travels {
        draw_segment(pixmap, view.px(t.from), view.px(t.to), &pen);
    }
}

/// Colour steps from the lowest to the highest power.
const POWER_STEPS: usize = 32;

/// Burns, each in the colour of its power step.
fn draw_burns(pixmap: &mut Pixmap, view: &View, report: &SimReport, lw: f32) {
    for b in &report.burns {
        let pen = Pen {
            color: step_color(report, power_step(report, b.power)),
            width: lw * 1.5,
            dash: None,
        };
        draw_segment(pixmap, view.px(b.from), view.px(b.to), &pen);
    }
}

/// The colour step of a power: its fraction of the profile's range, quantised.
fn power_step(report: &SimReport, power: f64) -> usize {
    let f = report.power_fraction(power);
    ((f * (POWER_STEPS - 1) as f64).round() as usize).min(POWER_STEPS - 1)
}

/// Blue (low) to red (high) through purple; black for pen strokes on a plotter.
fn step_color(report: &SimReport, step: usize) -> [u8; 4] {
    if report.dialect == crate::machine::Dialect::Plotter {
        return [0, 0, 0, 255];
    }
    let f = step as f64 / (POWER_STEPS - 1) as f64;
    let r = (40.0 + 215.0 * f) as u8;
    let b = (255.0 - 215.0 * f) as u8;
    [r, 30, b, 255]
}
