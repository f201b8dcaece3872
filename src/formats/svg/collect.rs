//! Walks usvg's tree and turns every stroked path into crease segments.
//!
//! usvg has already turned lines, polylines, polygons, rectangles, circles and ellipses into
//! paths, resolved CSS and inheritance, and instantiated `<use>`. For each path this module
//! takes the stroke colour (matched to the palette), the stroke opacity times the opacity of
//! every enclosing group (element `opacity` attributes become such groups), and the path's
//! absolute transform; straight segments become edges, curves are flattened into chords of at
//! most [`CURVE_TOLERANCE_MM`] deviation. Elements without a stroke, stroked with a gradient or
//! pattern, and images are skipped and counted for the warnings.
//!
//! An element with a declared meaning ([`super::meaning`], found by id) takes its assignment
//! from it instead of its colour. Dashed elements read by colour are remembered: when every
//! element read by colour has the same colour (a single-colour drawing), the dashed ones are
//! folds, assigned by [`DashedAs`] ([`Collector::apply_dashes`]).
//!
//! Precision: usvg stores coordinates, transforms and opacities as `f32`, so coordinates carry
//! a relative error of about 1e-7 of their magnitude and fold angles about 1e-5 degrees.

use std::collections::{BTreeMap, BTreeSet, HashMap};

use glam::{DAffine2, DVec2};

use super::flatten;
use super::meaning::Meaning;
use super::palette::{self, Match, Rgb};
use crate::formats::{DashedAs, Finding, FindingKind, ParseError};
use crate::pattern::{Assignment, CreasePattern, MAX_COORDINATE, Units};

/// Largest chord deviation allowed when flattening curves, in millimetres.
pub const CURVE_TOLERANCE_MM: f64 = 0.01;

/// Most edges read from one file; larger drawings are refused with an error.
pub const MAX_SEGMENTS: usize = 10_000_000;

/// At most this many element ids are named in one warning.
const IDS_NAMED: usize = 3;

/// At most this many off-palette colours get a warning of their own; the rest share one.
const COLOURS_NAMED: usize = 12;

/// One off-palette colour: how many elements used it and which ids.
#[derive(Debug)]
struct OffPalette {
    matched: Match,
    elements: usize,
    ids: Vec<String>,
}

/// The pattern collected so far and the counts behind the warnings.
pub struct Collector {
    to_pattern: DAffine2,
    /// The segments read, as unmerged vertex pairs.
    pub pattern: CreasePattern,
    elements: usize,
    no_stroke: usize,
    non_colour: usize,
    images: usize,
    curves: usize,
    chords: usize,
    off_palette: BTreeMap<Rgb, OffPalette>,
    meanings: HashMap<String, Meaning>,
    /// Elements whose assignment came from a declared meaning.
    declared: usize,
    /// Stroke colours of the elements read by colour.
    colours: BTreeSet<Rgb>,
    /// Dashed elements read by colour: their edges, dash pattern and opacity.
    dashed: Vec<DashedRun>,
}

/// The edges of one dashed element read by colour.
struct DashedRun {
    edges: std::ops::Range<usize>,
    dashes: Vec<f64>,
    opacity: f64,
}

/// The style of one stroked element.
#[derive(Clone, Copy)]
struct Style {
    assignment: Assignment,
    fold_angle: Option<f64>,
}

impl Collector {
    /// A collector mapping canvas pixels to the pattern with `to_pattern`.
    pub fn new(to_pattern: DAffine2) -> Self {
        Collector {
            to_pattern,
            pattern: CreasePattern {
                units: Units::Millimetres,
                ..CreasePattern::default()
            },
            elements: 0,
            no_stroke: 0,
            non_colour: 0,
            images: 0,
            curves: 0,
            chords: 0,
            off_palette: BTreeMap::new(),
            meanings: HashMap::new(),
            declared: 0,
            colours: BTreeSet::new(),
            dashed: Vec::new(),
        }
    }

    /// The same collector reading the meanings declared in the XML (by element id).
    pub fn with_meanings(mut self, meanings: HashMap<String, Meaning>) -> Self {
        self.meanings = meanings;
        self
    }

    /// Elements whose assignment came from `data-assignment` or a class name.
    pub fn declared(&self) -> usize {
        self.declared
    }

    /// In a single-colour drawing (every element read by colour has the same stroke colour),
    /// reassigns the dashed elements by `rule`; returns how many were reassigned and the
    /// assignment counts as a note, if any.
    pub fn apply_dashes(&mut self, rule: DashedAs) -> Option<Finding> {
        if self.colours.len() != 1 || self.dashed.is_empty() {
            return None;
        }
        let mut counts: BTreeMap<&'static str, usize> = BTreeMap::new();
        for run in &self.dashed {
            let assignment = rule.assignment(&run.dashes);
            *counts.entry(assignment.name()).or_default() += 1;
            let angle = palette::fold_angle(assignment, run.opacity);
            for edge in &mut self.pattern.edges[run.edges.clone()] {
                edge.assignment = assignment;
                edge.fold_angle = angle;
            }
        }
        let counts: Vec<String> = counts.iter().map(|(a, n)| format!("{n} {a}")).collect();
        Some(FindingKind::Dashes.note(format!(
            "single-colour drawing: its {} dashed line(s) are folds ({}; --dashed {rule}), its \
             solid lines read by colour",
            self.dashed.len(),
            counts.join(", ")
        )))
    }

    /// Collects every path below `group`, whose accumulated opacity is `opacity`.
    pub fn group(&mut self, group: &usvg::Group, opacity: f64) -> Result<(), ParseError> {
        for child in group.children() {
            match child {
                usvg::Node::Group(g) => self.group(g, opacity * f64::from(g.opacity().get()))?,
                usvg::Node::Path(p) => self.path(p, opacity)?,
                usvg::Node::Image(_) => self.images += 1,
                usvg::Node::Text(_) => {}
            }
        }
        Ok(())
    }

    fn path(&mut self, path: &usvg::Path, opacity: f64) -> Result<(), ParseError> {
        self.elements += 1;
        let Some(stroke) = path.stroke() else {
            self.no_stroke += 1;
            return Ok(());
        };
        let usvg::Paint::Color(c) = stroke.paint() else {
            self.non_colour += 1;
            return Ok(());
        };
        let alpha = opacity * f64::from(stroke.opacity().get());
        let transform = self.to_pattern * affine(path.abs_transform());
        if let Some(meaning) = self.meanings.get(path.id()).copied() {
            self.declared += 1;
            let style = Style {
                assignment: meaning.assignment,
                fold_angle: meaning
                    .fold_angle
                    .or_else(|| palette::fold_angle(meaning.assignment, alpha)),
            };
            return self
                .segments(path, transform, style)
                .map_err(|message| ParseError::new(self.place(path), message));
        }
        let colour = Rgb(c.red, c.green, c.blue);
        let matched = palette::nearest(colour);
        if !matched.exact {
            self.note_off_palette(colour, matched, path.id());
        }
        self.colours.insert(colour);
        let style = Style {
            assignment: matched.assignment,
            fold_angle: palette::fold_angle(matched.assignment, alpha),
        };
        let first = self.pattern.edges.len();
        self.segments(path, transform, style)
            .map_err(|message| ParseError::new(self.place(path), message))?;
        if let Some(dashes) = stroke.dasharray().filter(|d| d.iter().any(|&x| x > 0.0)) {
            self.dashed.push(DashedRun {
                edges: first..self.pattern.edges.len(),
                dashes: dashes.iter().map(|&x| f64::from(x)).collect(),
                opacity: alpha,
            });
        }
        Ok(())
    }

    fn note_off_palette(&mut self, colour: Rgb, matched: Match, id: &str) {
        let entry = self.off_palette.entry(colour).or_insert(OffPalette {
            matched,
            elements: 0,
            ids: Vec::new(),
        });
        entry.elements += 1;
        if !id.is_empty() && entry.ids.len() < IDS_NAMED {
            entry.ids.push(id.to_string());
        }
    }

    /// Names the current element for an error message.
    fn place(&self, path: &usvg::Path) -> String {
        if path.id().is_empty() {
            format!("stroked element {} (in document order)", self.elements)
        } else {
            format!("element id=\"{}\"", path.id())
        }
    }

    /// Adds the segments of one path.
    fn segments(&mut self, path: &usvg::Path, t: DAffine2, style: Style) -> Result<(), String> {
        use usvg::tiny_skia_path::PathSegment;
        let map = |p: usvg::tiny_skia_path::Point| {
            t.transform_point2(DVec2::new(f64::from(p.x), f64::from(p.y)))
        };
        let (mut start, mut current) = (DVec2::ZERO, DVec2::ZERO);
        for segment in path.data().segments() {
            match segment {
                PathSegment::MoveTo(p) => (start, current) = (map(p), map(p)),
                PathSegment::LineTo(p) => current = self.line(current, map(p), style)?,
                PathSegment::QuadTo(p1, p) => {
                    let points = flatten::quad(current, map(p1), map(p), CURVE_TOLERANCE_MM);
                    current = self.polyline(current, &points, style)?;
                }
                PathSegment::CubicTo(p1, p2, p) => {
                    let points =
                        flatten::cubic(current, map(p1), map(p2), map(p), CURVE_TOLERANCE_MM);
                    current = self.polyline(current, &points, style)?;
                }
                PathSegment::Close => current = self.line(current, start, style)?,
            }
        }
        Ok(())
    }

    /// Adds the chords of a flattened curve starting at `from`; returns the end point.
    fn polyline(&mut self, from: DVec2, points: &[DVec2], style: Style) -> Result<DVec2, String> {
        self.curves += 1;
        self.chords += points.len();
        let mut current = from;
        for &p in points {
            current = self.line(current, p, style)?;
        }
        Ok(current)
    }

    /// Adds one straight segment (skipping zero-length ones); returns its end.
    fn line(&mut self, a: DVec2, b: DVec2, style: Style) -> Result<DVec2, String> {
        for p in [a, b] {
            if !(p.is_finite() && p.abs().max_element() <= MAX_COORDINATE) {
                return Err(format!(
                    "point ({}, {}) mm lies outside ±{MAX_COORDINATE:e} mm",
                    p.x, p.y
                ));
            }
        }
        if a == b {
            return Ok(b);
        }
        if self.pattern.edges.len() >= MAX_SEGMENTS {
            return Err(format!(
                "the drawing has more than {MAX_SEGMENTS} line segments, the most read"
            ));
        }
        let e = self.pattern.add_segment(a, b, style.assignment);
        self.pattern.edges[e.index()].fold_angle = style.fold_angle;
        Ok(b)
    }

    /// True when no segment was read.
    pub fn is_empty(&self) -> bool {
        self.pattern.edges.is_empty()
    }

    /// Why an SVG without segments was refused.
    pub fn empty_message(&self) -> String {
        let mut message = String::from(
            "the SVG holds no stroked lines in the crease palette (Origami Simulator draws \
             each crease as a stroked line: red mountain, blue valley, black boundary, green \
             cut, yellow facet, magenta unassigned)",
        );
        if self.elements > 0 {
            message.push_str(&format!(
                "; of its {} shapes, {} have no stroke and {} a gradient or pattern stroke",
                self.elements, self.no_stroke, self.non_colour
            ));
        }
        message
    }

    /// The warnings for everything skipped or approximated.
    pub fn warnings(&self) -> Vec<Finding> {
        let mut out: Vec<Finding> = self
            .off_palette
            .iter()
            .take(COLOURS_NAMED)
            .map(|c| FindingKind::OffPaletteColour.warning(off_palette_warning(c)))
            .collect();
        if self.off_palette.len() > COLOURS_NAMED {
            let rest = &self
                .off_palette
                .values()
                .skip(COLOURS_NAMED)
                .collect::<Vec<_>>();
            out.push(FindingKind::OffPaletteColour.warning(format!(
                "{} more off-palette stroke colours on {} element(s) were read as the nearest \
                 palette colour",
                rest.len(),
                rest.iter().map(|o| o.elements).sum::<usize>()
            )));
        }
        if self.no_stroke > 0 {
            out.push(FindingKind::Unstroked.warning(format!(
                "{} element(s) without a stroke were ignored (creases are stroked lines)",
                self.no_stroke
            )));
        }
        if self.non_colour > 0 {
            out.push(FindingKind::Unstroked.warning(format!(
                "{} element(s) stroked with a gradient or pattern were ignored (creases need \
                 a plain stroke colour)",
                self.non_colour
            )));
        }
        if self.images > 0 {
            out.push(
                FindingKind::Images
                    .warning(format!("{} embedded image(s) were ignored", self.images)),
            );
        }
        if self.curves > 0 {
            out.push(FindingKind::CurvesFlattened.warning(format!(
                "{} curved segment(s) were flattened into {} straight edges (within \
                 {CURVE_TOLERANCE_MM} mm); creases are straight",
                self.curves, self.chords
            )));
        }
        out
    }
}

fn off_palette_warning((colour, off): (&Rgb, &OffPalette)) -> String {
    let ids = if off.ids.is_empty() {
        String::from("no id")
    } else {
        let named: Vec<String> = off.ids.iter().map(|id| format!("\"{id}\"")).collect();
        let more = if off.elements > off.ids.len() {
            ", …"
        } else {
            ""
        };
        format!("id {}{more}", named.join(", "))
    };
    format!(
        "stroke colour {} is not in the crease palette: {} element(s) ({ids}) read as {} \
         (nearest palette colour {})",
        colour.hex(),
        off.elements,
        off.matched.assignment.name(),
        off.matched.palette.hex()
    )
}

/// usvg's `f32` transform as an `f64` affine map.
fn affine(t: usvg::Transform) -> DAffine2 {
    let f = f64::from;
    DAffine2::from_cols(
        DVec2::new(f(t.sx), f(t.ky)),
        DVec2::new(f(t.kx), f(t.sy)),
        DVec2::new(f(t.tx), f(t.ty)),
    )
}
