//! SVG writer: the bed in millimetres, one Inkscape layer per operation.
//!
//! The root's `width` and `height` are the bed in `mm` and its `viewBox` the same numbers, so
//! one user unit is one millimetre. The drawing is the job in machine coordinates seen from
//! above: SVG's y grows downward, so machine y is flipped back (`y' = bed height − y`) unless
//! the bed's y already grows toward the front (`Bed::y_flipped`); x is kept. Coordinates are
//! printed on a 0.001 mm grid.
//!
//! Each operation present gets a layer (`<g id="layer3" inkscape:groupmode="layer"
//! inkscape:label="cut">`; and each settings override present one more, see
//! [`super::layers`]), in execution order, so later operations draw on top) stroked in
//! its LightBurn colour (see [`super::layer_style`]) with a 0.025 mm hairline and no fill;
//! LightBurn and Inkscape import one layer per colour or group. The groups are numbered
//! `layer1`, `layer2`, … in that order, and a label with digits of its own (a calibration
//! cell's, `perforate-cell-4`) starts with its layer's number (`2 perforate-cell-4`): vpype
//! (1.15) takes a layer's number from the first digits of its `inkscape:label`, then of its
//! `id`, so `vpype read` gives one layer per group, numbered in execution order.
//!
//! Every stroke is one `<path>`, perforation dashes included, so a pen plotter (or vpype,
//! which draws dash styles as solid lines) draws each dash. With `dasharray`, each perforation
//! toolpath is instead one `<path>` through all its dashes, whose `stroke-dasharray` lists
//! every dash and gap length exactly, for viewing in software that draws dash styles.

use std::fmt::Write;

use glam::DVec2;

use super::layers::{Layer, layers};
use super::number::{Grid, fixed};
use super::{PostError, layer_style};
use crate::fab::{FabPlan, Operation, Setup, Toolpath};
use crate::machine::Bed;

/// Decimals of printed SVG coordinates (a 0.001 mm grid).
const SVG_DECIMALS: usize = 3;
/// Stroke width, mm: a hairline for laser software.
const HAIRLINE_MM: &str = "0.025";

/// Page geometry: bed size and the y flip.
struct Page {
    grid: Grid,
    height_mm: f64,
    flip: bool,
}

/// The SVG document of `job`.
pub fn write(plan: &FabPlan, job: &Setup, bed: &Bed, dasharray: bool) -> Result<String, PostError> {
    let sane = |v: f64| v.is_finite() && v > 0.0 && v <= super::MAX_COORD_MM;
    if !(sane(bed.width_mm) && sane(bed.height_mm)) {
        return Err(PostError::BadBed {
            width_mm: bed.width_mm,
            height_mm: bed.height_mm,
        });
    }
    let page = Page {
        grid: Grid::decimal(SVG_DECIMALS),
        height_mm: bed.height_mm,
        flip: !bed.y_flipped,
    };
    let mut body = String::new();
    let mut number = 0;
    for l in layers(plan, job) {
        let paths: Vec<&Toolpath> = job.paths.iter().filter(|p| l.holds(plan, p)).collect();
        let dashed = dasharray && l.op == Operation::Perforate;
        let elements = layer_elements(&page, &paths, dashed);
        if !elements.is_empty() {
            number += 1;
            layer(&mut body, plan, &l, number, &elements);
        }
    }
    if body.is_empty() {
        return Err(PostError::EmptyJob {
            job: job.name.clone(),
        });
    }
    Ok(document(&page, bed, &job.name, &body))
}

/// The root element around `body`.
fn document(page: &Page, bed: &Bed, name: &str, body: &str) -> String {
    let (w, h) = (
        page.grid.round(bed.width_mm),
        page.grid.round(bed.height_mm),
    );
    let mut out = String::from("<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"no\"?>\n");
    out.push_str("<svg xmlns=\"http://www.w3.org/2000/svg\" ");
    out.push_str("xmlns:inkscape=\"http://www.inkscape.org/namespaces/inkscape\" ");
    let _ = writeln!(
        out,
        "version=\"1.1\" width=\"{w}mm\" height=\"{h}mm\" viewBox=\"0 0 {w} {h}\">"
    );
    let _ = writeln!(
        out,
        "  <title>foldcam job {}</title>",
        crate::formats::svg::write::escape(name)
    );
    out.push_str(body);
    out.push_str("</svg>\n");
    out
}

/// The Inkscape label of layer `number` named `name`: the name, with the number in front when
/// the name holds digits of its own (vpype takes a layer's number from the first digits of its
/// label, then of its id).
fn layer_label(name: &str, number: usize) -> String {
    if name.chars().any(|c| c.is_ascii_digit()) {
        format!("{number} {name}")
    } else {
        name.to_string()
    }
}

/// Layer group number `number` (from 1) holding `elements`, with the layer's settings in its
/// `<desc>`.
fn layer(out: &mut String, plan: &FabPlan, l: &Layer, number: usize, elements: &[String]) {
    let style = layer_style(l.op);
    let name = l.name.as_str();
    let label = crate::formats::svg::write::escape(&layer_label(name, number));
    let _ = writeln!(
        out,
        "  <g id=\"layer{number}\" inkscape:groupmode=\"layer\" inkscape:label=\"{label}\" \
         fill=\"none\" stroke=\"{}\" stroke-width=\"{HAIRLINE_MM}\" \
         stroke-linejoin=\"round\">",
        style.hex
    );
    let s = l.settings(plan, None);
    if s.speed_mm_min.is_finite() && s.power.is_finite() {
        let (speed, power) = (fixed(s.speed_mm_min, 3), fixed(s.power * 100.0, 3));
        let passes = match s.passes {
            1 => "1 pass".to_string(),
            n => format!("{n} passes"),
        };
        let desc = format!("{name}: {speed} mm/min, power {power} %, {passes}");
        let _ = writeln!(out, "    <desc>{desc}</desc>");
    }
    for element in elements {
        let _ = writeln!(out, "    {element}");
    }
    out.push_str("  </g>\n");
}

/// The `<path>` elements of one operation's toolpaths.
fn layer_elements(page: &Page, paths: &[&Toolpath], dasharray: bool) -> Vec<String> {
    if dasharray {
        return paths.iter().filter_map(|p| dashed(page, p)).collect();
    }
    let strokes = paths.iter().flat_map(|p| p.strokes.iter());
    strokes
        .filter_map(|s| page.snap(s))
        .map(|points| path_element(page, &points, None))
        .collect()
}

/// One `<path>` through all dashes of `path`, with a dash array of their exact lengths.
fn dashed(page: &Page, path: &Toolpath) -> Option<String> {
    let dashes: Vec<_> = path.strokes.iter().filter_map(|s| page.snap(s)).collect();
    let mut points: Vec<(i64, i64)> = Vec::new();
    let mut pattern: Vec<String> = Vec::new();
    for dash in &dashes {
        if let Some(&end) = points.last() {
            pattern.push(fixed(page.length(&[end, dash[0]]), 3));
        }
        pattern.push(fixed(page.length(dash), 3));
        points.extend_from_slice(dash);
    }
    // A last gap as long as the whole path, so the list never repeats onto the path.
    pattern.push(fixed(page.length(&points), 3));
    points.dedup();
    (points.len() >= 2).then(|| path_element(page, &points, Some(&pattern.join(" "))))
}

/// `<path d="M… L…"/>`, closed with `Z` when its ends meet.
fn path_element(page: &Page, points: &[(i64, i64)], dasharray: Option<&str>) -> String {
    let closed = points.len() > 3 && points.first() == points.last();
    let drawn = if closed {
        &points[..points.len() - 1]
    } else {
        points
    };
    let mut d = String::new();
    for (i, &(x, y)) in drawn.iter().enumerate() {
        let cmd = if i == 0 { 'M' } else { 'L' };
        let _ = write!(d, "{cmd}{} {}", page.grid.print(x), page.grid.print(y));
    }
    if closed {
        d.push('Z');
    }
    match dasharray {
        Some(a) => format!("<path d=\"{d}\" stroke-dasharray=\"{a}\"/>"),
        None => format!("<path d=\"{d}\"/>"),
    }
}

impl Page {
    /// `stroke` on the page grid without repeated points, or `None` if it has no length.
    fn snap(&self, stroke: &[DVec2]) -> Option<Vec<(i64, i64)>> {
        let mut points: Vec<_> = stroke.iter().map(|&p| self.place(p)).collect();
        points.dedup();
        (points.len() >= 2).then_some(points)
    }

    /// A machine point on the page, in grid counts.
    fn place(&self, p: DVec2) -> (i64, i64) {
        let y = if self.flip { self.height_mm - p.y } else { p.y };
        (self.grid.snap(p.x), self.grid.snap(y))
    }

    /// Length of a polyline in grid counts, mm.
    fn length(&self, points: &[(i64, i64)]) -> f64 {
        let step = self.grid.step();
        let segment = |w: &[(i64, i64)]| {
            let (dx, dy) = ((w[1].0 - w[0].0) as f64, (w[1].1 - w[0].1) as f64);
            dx.hypot(dy) * step
        };
        points.windows(2).map(segment).sum()
    }
}
