//! A PNG of a simulated run: the whole bed (or, for a job under a quarter of the bed both ways,
//! the corner of the bed from its origin to just past the job, said in the key), seen from
//! above with its front at the bottom, the burns, the travel, and under it a key ([`crate::render::legend`]): a scale bar in
//! millimetres and what every colour means.
//!
//! **Colours.** Where the program heads its groups with comments naming the operation (`;
//! perforate`, `(cut)`, as foldcam's writers do: [`SimReport::operations`]), each burn takes
//! its operation's layer colour, the LightBurn palette of the SVG and DXF output
//! ([`crate::post::layer_style`]): cut red, perforate green, score blue, mark black, plot magenta.
//! A program without such comments is coloured by power in 32 steps, blue for the profile's
//! lowest power through red for its highest (pen strokes black), and the key names both
//! ends. Travel is drawn thin, dashed and faint in orange, its own colour.
//!
//! Travel and burns are drawn by [`super::raster`] in time linear in the moves; the bed
//! outline, the key and the text by tiny-skia.
//!
//! **Title.** A line above the bed names the job file, the machine and the material
//! ([`toolpath_title`], from the [`JobNames`] the caller knows); it sits in the top margin
//! (which grows to hold it in narrow pictures) and is stored in the PNG as its `Title` text.
//!
//! Machine x runs to the right. Machine y runs up the image unless the bed is `y_flipped`
//! (origin at the back), when it runs down. Moves outside the bed are drawn where they go,
//! clipped by the image.

use glam::DVec2;
use tiny_skia::{Color, PathBuilder, Pixmap, Stroke, Transform};

use super::raster::{Pen, draw_segment};
use super::report::SimReport;
use crate::fab::Operation;
use crate::machine::{Dialect, MachineProfile};
use crate::render::legend::{self, Key, LegendEntry, ScaleBar, paint};
use crate::render::{MAX_SIZE, MIN_SIZE, RenderError};

/// Margin around the bed, as a share of the width.
const MARGIN_SHARE: f64 = 0.04;
/// Share of the bed's drawn width the scale bar may take at most.
const SCALE_BAR_SHARE: f64 = 0.25;
/// Colour of travel moves, RGBA: a faint orange.
pub const TRAVEL_COLOR: [u8; 4] = [255, 140, 0, 150];
/// Colour of the bed outline, RGBA.
pub const BED_COLOR: [u8; 4] = [110, 110, 110, 255];

/// Maps machine millimetres on the bed to pixels.
struct View {
    scale: f64,
    margin: f64,
    /// Pixels above the region drawn: the top margin, holding the title.
    top: f64,
    /// Height of the region drawn (from the bed's origin), mm.
    height: f64,
    /// Width of the region drawn, mm.
    width: f64,
    y_flipped: bool,
}

impl View {
    fn px(&self, p: DVec2) -> (f32, f32) {
        let y = if self.y_flipped {
            p.y
        } else {
            self.height - p.y
        };
        (
            (self.margin + p.x * self.scale) as f32,
            (self.top + y * self.scale) as f32,
        )
    }
}

/// The RGBA colour of an operation's layer (`#RRGGBB` of [`crate::post::layer_style`]).
pub fn operation_color(op: Operation) -> [u8; 4] {
    let hex = crate::post::layer_style(op).hex;
    let byte = |i: usize| u8::from_str_radix(hex.get(i..i + 2).unwrap_or("00"), 16).unwrap_or(0);
    [byte(1), byte(3), byte(5), 255]
}

/// How burns are coloured.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Colouring {
    /// By the operation the program's comments name.
    Operation,
    /// By power, low blue to high red (black for pen strokes).
    Power,
}

fn colouring(report: &SimReport) -> Colouring {
    let named = !report.operations.is_empty()
        && report
            .burns
            .iter()
            .all(|b| report.operation_at(b.line).is_some());
    if named {
        Colouring::Operation
    } else {
        Colouring::Power
    }
}

/// What a toolpath picture's title names besides the machine (whose profile the picture is
/// drawn with): the job's file and the material, each when the caller knows it.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct JobNames<'a> {
    /// The job's file name as the user knows it ("miura.grbl-diode.card-300gsm.gcode").
    pub file: Option<&'a str>,
    /// The material's name ("card-300gsm").
    pub material: Option<&'a str>,
}

/// The title of a toolpath picture: "FILE: machine MACHINE, material MATERIAL", leaving out
/// what `names` does not give (the file first, so that a long name wraps alone).
pub fn toolpath_title(machine: &MachineProfile, names: &JobNames) -> String {
    let mut about = format!("machine {}", machine.name);
    if let Some(material) = names.material {
        about.push_str(&format!(", material {material}"));
    }
    match names.file {
        Some(file) => format!("{file}: {about}"),
        None => about,
    }
}

/// Draws `report` on the bed of `machine` (see the module docs for the region) as PNG bytes,
/// `width` pixels wide (16 to 16384), titled with [`toolpath_title`] (in the picture and as
/// the PNG's `Title` text); the height follows the bed's aspect ratio plus the title and the
/// key's band, at most 16384 pixels.
pub fn render_png(
    report: &SimReport,
    machine: &MachineProfile,
    width: u32,
    names: &JobNames,
) -> Result<Vec<u8>, RenderError> {
    let pixmap = render_pixmap(report, machine, width, names)?;
    legend::png_with_text(&pixmap, &[("Title", &toolpath_title(machine, names))])
}

/// As [`render_png`], into a pixmap (premultiplied RGBA).
pub fn render_pixmap(
    report: &SimReport,
    machine: &MachineProfile,
    width: u32,
    names: &JobNames,
) -> Result<Pixmap, RenderError> {
    if !(MIN_SIZE..=MAX_SIZE).contains(&width) {
        return Err(RenderError::Width(width));
    }
    let colouring = colouring(report);
    let font_px = legend::font_px_for(width);
    let title = toolpath_title(machine, names);
    let view = layout(machine, report, width, &title)?;
    let inner = (f64::from(width) - 2.0 * view.margin).max(1.0) as u32;
    let key = key(report, machine, &view, colouring);
    let band = key.height(inner, font_px);
    let bed_h = (view.top + view.height * view.scale + view.margin).ceil() as u32;
    let height = (bed_h + band).clamp(1, MAX_SIZE);
    let mut pixmap = Pixmap::new(width, height).ok_or(RenderError::Allocation { width, height })?;
    pixmap.fill(Color::WHITE);
    let lw = (width as f32 / 800.0).max(1.0);
    draw_bed(&mut pixmap, &view, machine, lw);
    draw_travel(&mut pixmap, &view, report, lw);
    draw_burns(&mut pixmap, &view, report, lw, colouring);
    // The title, over anything drawn past the bed's top.
    let title_h = f64::from(legend::title_height(&title, inner, font_px));
    let title_top = ((view.top - title_h) / 2.0).floor().max(0.0);
    let cover = title_top + title_h;
    legend::fill_rect(
        &mut pixmap,
        0.0,
        0.0,
        f64::from(width),
        cover,
        legend::PAPER,
    );
    legend::draw_title(&mut pixmap, view.margin, title_top, &title, inner, font_px);
    // The key's band, cleared of anything drawn past the bed.
    let top = f64::from(bed_h) - view.margin / 2.0;
    legend::fill_rect(
        &mut pixmap,
        0.0,
        top,
        f64::from(width),
        f64::from(height) - top,
        legend::PAPER,
    );
    key.draw(&mut pixmap, view.margin, top, inner, font_px);
    Ok(pixmap)
}

/// Share of the bed, both ways, under which a job is drawn on the bed's corner only.
const SMALL_JOB_SHARE: f64 = 0.25;

/// The region drawn, from the bed's origin: the whole bed, or, for a job under
/// [`SMALL_JOB_SHARE`] of the bed both ways, the corner of the bed that holds it (with a 5 %
/// border), so a small job on a large bed is not a speck.
fn region(report: &SimReport, bed: &crate::machine::Bed) -> DVec2 {
    let whole = DVec2::new(bed.width_mm, bed.height_mm);
    let points = report
        .burns
        .iter()
        .flat_map(|b| [b.from, b.to])
        .chain(report.travels.iter().flat_map(|t| [t.from, t.to]))
        .filter(|p| p.is_finite());
    let hi = points.fold(DVec2::ZERO, |hi, p| hi.max(p));
    if hi.x > SMALL_JOB_SHARE * whole.x
        || hi.y > SMALL_JOB_SHARE * whole.y
        || hi.max_element() <= 0.0
    {
        return whole;
    }
    (hi + DVec2::splat(0.05 * hi.max_element())).min(whole)
}

/// The mapping of the bed to pixels, with room for `title` at the top.
fn layout(
    machine: &MachineProfile,
    report: &SimReport,
    width: u32,
    title: &str,
) -> Result<View, RenderError> {
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
    let font_px = legend::font_px_for(width);
    let inner = (f64::from(width) - 2.0 * margin).max(1.0) as u32;
    let title = legend::title_height(title, inner, font_px) + 2 * font_px;
    let top = margin.max(f64::from(title));
    let size = region(report, &bed);
    let scale = (f64::from(width) - 2.0 * margin) / size.x;
    // Leave a quarter of the largest height for the key.
    let max_h = 0.75 * f64::from(MAX_SIZE) - top - margin;
    Ok(View {
        scale: scale.min(max_h / size.y),
        margin,
        top,
        height: size.y,
        width: size.x,
        y_flipped: bed.y_flipped,
    })
}

/// The key: scale bar, the bed, each operation (or the power ends) drawn, travel.
fn key(report: &SimReport, machine: &MachineProfile, view: &View, colouring: Colouring) -> Key {
    let lw = 2.0;
    let bed = &machine.bed;
    let whole = view.width >= bed.width_mm && view.height >= bed.height_mm;
    let part = if whole { "" } else { ", its corner" };
    let mut entries = vec![LegendEntry::line(
        &format!("bed {} × {} mm{part}", bed.width_mm, bed.height_mm),
        BED_COLOR,
        lw,
        None,
    )];
    match colouring {
        Colouring::Operation => {
            for op in Operation::ALL {
                let used = report
                    .burns
                    .iter()
                    .any(|b| report.operation_at(b.line) == Some(op));
                if used {
                    entries.push(LegendEntry::line(op.name(), operation_color(op), 3.0, None));
                }
            }
        }
        Colouring::Power if report.dialect == Dialect::Plotter => {
            entries.push(LegendEntry::line("pen down", [0, 0, 0, 255], 3.0, None));
        }
        Colouring::Power => {
            let range = report.power_range;
            for (s, step) in [(range.min, 0), (range.max, POWER_STEPS - 1)] {
                let label = format!("burn at S{s}");
                entries.push(LegendEntry::line(
                    &label,
                    step_color(report, step),
                    3.0,
                    None,
                ));
            }
        }
    }
    if !report.travels.is_empty() {
        let dash = Some(vec![6.0, 6.0]);
        entries.push(LegendEntry::line(
            "travel, tool off",
            TRAVEL_COLOR,
            lw,
            dash,
        ));
    }
    let width = view.scale * view.width;
    Key {
        scale_bar: Some(ScaleBar {
            px_per_unit: view.scale,
            unit: "mm",
            max_px: width * SCALE_BAR_SHARE,
        }),
        entries,
        ..Key::default()
    }
}

fn segment(pb: &mut PathBuilder, view: &View, a: DVec2, b: DVec2) {
    let (ax, ay) = view.px(a);
    let (bx, by) = view.px(b);
    pb.move_to(ax, ay);
    pb.line_to(bx, by);
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
    if let Some(path) = pb.finish() {
        pixmap.stroke_path(
            &path,
            &paint(BED_COLOR),
            &stroke,
            Transform::identity(),
            None,
        );
    }
}

fn draw_travel(pixmap: &mut Pixmap, view: &View, report: &SimReport, lw: f32) {
    let pen = Pen {
        color: TRAVEL_COLOR,
        width: lw * 0.5,
        dash: Some(3.0 * lw),
    };
    for t in &report.travels {
        draw_segment(pixmap, view.px(t.from), view.px(t.to), &pen);
    }
}

/// Colour steps from the lowest to the highest power.
const POWER_STEPS: usize = 32;

/// Burns, each in its operation's colour or its power step's.
fn draw_burns(pixmap: &mut Pixmap, view: &View, report: &SimReport, lw: f32, colouring: Colouring) {
    for b in &report.burns {
        let color = match colouring {
            Colouring::Operation => report
                .operation_at(b.line)
                .map_or(legend::INK, operation_color),
            Colouring::Power => step_color(report, power_step(report, b.power)),
        };
        let pen = Pen {
            color,
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
    if report.dialect == Dialect::Plotter {
        return [0, 0, 0, 255];
    }
    let f = step as f64 / (POWER_STEPS - 1) as f64;
    let r = (40.0 + 215.0 * f) as u8;
    let b = (255.0 - 215.0 * f) as u8;
    [r, 30, b, 255]
}
