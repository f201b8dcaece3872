//! The SVG reader: XML and SVG errors, the root element, title and description, and the
//! hand-off to [`super::collect`] and planarisation.

use usvg::roxmltree;

use super::collect::Collector;
use super::{attributes, frame, meaning};
use crate::formats::{Finding, FindingKind, Imported, ParseError, ReadOptions, snap};
use crate::limits::MIN_TOLERANCE;
use crate::pattern::CreasePattern;

/// Merge tolerance relative to the drawing's size (1e-5: 2 µm on a 200 mm sheet).
///
/// Larger than planarisation's default on purpose: drawing programs print SVG coordinates
/// with two to four decimals of a pixel, so endpoints meant to coincide differ by up to
/// 1e-3 px, and usvg holds coordinates in `f32` (relative error 6e-8 of their magnitude,
/// before transforms). Both would leave endpoints unmerged, and slivers of a few µm, at
/// planarisation's default of 1e-7.
pub const MERGE_TOLERANCE: f64 = 1e-5;

/// The SVG namespace.
const SVG_NS: &str = "http://www.w3.org/2000/svg";

/// Parses an SVG crease pattern with the default [`ReadOptions`] (see [`read_str_with`]).
pub fn read_str(text: &str) -> Result<Imported, ParseError> {
    read_str_with(text, &ReadOptions::default())
}

/// Parses an SVG crease pattern: declared meanings first (`data-assignment`, class names; see
/// [`super::meaning`]), then Origami Simulator's colours, with dashed lines in a
/// single-colour drawing read as folds by `options.dashed`.
///
/// The pattern comes back in millimetres with y pointing up, planarised (coincident endpoints
/// merged, crossings split, duplicates removed), line ends within the snapping tolerance
/// joined (`options.snap`, default [`crate::formats::snap::SNAP_RELATIVE`] of the diagonal;
/// the tolerance used is in [`Imported::notes`]), its title and description taken from the
/// root's `<title>` and `<desc>`. Warnings name off-palette colours, ignored elements and
/// flattened curves.
///
/// # Errors
/// Text that is not XML (naming the line and column), a root element other than `<svg>`, an
/// SVG usvg refuses (no valid size, too many elements), coordinates beyond
/// [`crate::pattern::MAX_COORDINATE`], more than [`super::MAX_SEGMENTS`] segments, or
/// no stroked line at all.
pub fn read_str_with(text: &str, options: &ReadOptions) -> Result<Imported, ParseError> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    if text.trim().is_empty() {
        return Err(ParseError::new(
            "file",
            "the file is empty, not an SVG document",
        ));
    }
    let parsing = || roxmltree::ParsingOptions {
        allow_dtd: true,
        ..Default::default()
    };
    attributes::check_attribute_counts(text)?;
    let doc = roxmltree::Document::parse_with_options(text, parsing()).map_err(xml_error)?;
    check_root(doc.root_element())?;
    let attribute_warnings = attributes::check_values(&doc)?;
    check_miter_limits(&doc)?;
    let scan = meaning::scan(&doc, text);
    let rewritten_doc;
    let source = match &scan.text {
        Some(rewritten) => {
            rewritten_doc =
                roxmltree::Document::parse_with_options(rewritten, parsing()).map_err(xml_error)?;
            &rewritten_doc
        }
        None => &doc,
    };
    let tree = usvg::Tree::from_xmltree(source, &usvg::Options::default()).map_err(usvg_error)?;
    let size = tree.size();
    let canvas = (f64::from(size.width()), f64::from(size.height()));
    let mut collector = Collector::new(frame::canvas_to_pattern(doc.root_element(), canvas))
        .with_meanings(scan.by_id);
    collector.group(tree.root(), 1.0)?;
    if collector.is_empty() {
        return Err(ParseError::new("file", collector.empty_message()));
    }
    let dash_note = collector.apply_dashes(options.dashed);
    let mut warnings = attribute_warnings;
    warnings.extend(collector.warnings());
    warnings.extend(text_warning(&doc));
    let declared = collector.declared();
    let mut pattern = collector.pattern;
    pattern.meta.title = child_text(doc.root_element(), "title");
    pattern.meta.description = child_text(doc.root_element(), "desc");
    let tolerance = merge_tolerance(&pattern);
    let snap = options.snap.unwrap_or_else(|| snap::default_snap(&pattern));
    let mut imported =
        super::super::finish_drawing(pattern, Some(tolerance), Some(snap), "drawn", warnings)?;
    if declared > 0 {
        imported
            .findings
            .push(FindingKind::DeclaredAssignment.note(format!(
                "{declared} element(s) read by their data-assignment or class name rather than \
             their colour"
            )));
    }
    imported.findings.extend(dash_note);
    Ok(imported)
}

/// Distance below which endpoints merge (and a point splits a line it touches), in
/// millimetres: [`MERGE_TOLERANCE`] of the larger of the drawing's diagonal and its largest
/// coordinate magnitude.
pub fn merge_tolerance(pattern: &CreasePattern) -> f64 {
    let Some((lo, hi)) = pattern.bounds() else {
        return MIN_TOLERANCE;
    };
    let magnitude = lo.abs().max(hi.abs()).max_element();
    (lo.distance(hi).max(magnitude) * MERGE_TOLERANCE).max(MIN_TOLERANCE)
}

/// True for an element of this local name in the SVG namespace (or in none).
fn is_svg_element(node: roxmltree::Node, name: &str) -> bool {
    let tag = node.tag_name();
    node.is_element() && tag.name() == name && matches!(tag.namespace(), None | Some(SVG_NS))
}

fn check_root(root: roxmltree::Node) -> Result<(), ParseError> {
    if is_svg_element(root, "svg") {
        return Ok(());
    }
    let pos = root.document().text_pos_at(root.range().start);
    Err(ParseError::new(
        format!("line {}", pos.row),
        format!(
            "the root element is <{}>, not <svg>: this is not an SVG document",
            root.tag_name().name()
        ),
    ))
}

/// The trimmed text of the first child element `name` of the root, if not empty.
fn child_text(root: roxmltree::Node, name: &str) -> Option<String> {
    let node = root.children().find(|n| is_svg_element(*n, name))?;
    let text: String = node
        .descendants()
        .filter(|n| n.is_text())
        .filter_map(|n| n.text())
        .collect();
    let text = text.split_whitespace().collect::<Vec<_>>().join(" ");
    (!text.is_empty()).then_some(text)
}

/// A warning when the document holds text, which is not read.
fn text_warning(doc: &roxmltree::Document) -> Option<Finding> {
    let count = doc
        .descendants()
        .filter(|n| is_svg_element(*n, "text"))
        .count();
    (count > 0).then(|| FindingKind::Text.warning(format!("{count} text element(s) were ignored")))
}

fn xml_error(e: roxmltree::Error) -> ParseError {
    let pos = e.pos();
    ParseError::new(
        format!("line {}, column {}", pos.row, pos.col),
        format!("not well-formed XML: {e}"),
    )
}

fn usvg_error(e: usvg::Error) -> ParseError {
    match e {
        usvg::Error::ParsingFailed(roxmltree::Error::NodesLimitReached) => ParseError::new(
            "file",
            "elements are nested more than 1024 levels deep (or `<use>` references loop), \
             beyond what the SVG reader accepts",
        ),
        usvg::Error::ParsingFailed(x) => xml_error(x),
        usvg::Error::InvalidSize => ParseError::new(
            "<svg>",
            "the SVG has no valid size: width and height must be positive (or a viewBox given)",
        ),
        other => ParseError::new("file", format!("not a usable SVG: {other}")),
    }
}

/// The largest `f32`, where usvg keeps its numbers.
const USVG_MAX_NUMBER: f64 = f32::MAX as f64;

/// Refuses a `stroke-miterlimit` (attribute, `style` attribute or `<style>` sheet) beyond
/// [`USVG_MAX_NUMBER`]: usvg would turn it into infinity and stop on its own internal
/// assertion (a panic in debug builds), so the reader names it first.
fn check_miter_limits(doc: &roxmltree::Document) -> Result<(), ParseError> {
    const NAME: &str = "stroke-miterlimit";
    for node in doc.descendants() {
        let texts = node
            .attributes()
            .filter(|a| a.name() == NAME || a.name() == "style")
            .map(|a| (a.name() == NAME, a.value()))
            .chain(
                node.text()
                    .filter(|_| is_svg_element(node.parent().unwrap_or(node), "style"))
                    .map(|t| (false, t)),
            );
        for (bare, text) in texts {
            let values: Vec<&str> = if bare {
                vec![text]
            } else {
                text.match_indices(NAME)
                    .map(|(i, _)| {
                        text[i + NAME.len()..].trim_start_matches([' ', '\t', '\n', '\r', ':'])
                    })
                    .collect()
            };
            for value in values {
                let number: String = value
                    .trim_start()
                    .chars()
                    .take_while(|c| c.is_ascii_digit() || matches!(c, '.' | 'e' | 'E' | '+' | '-'))
                    .collect();
                if number
                    .parse::<f64>()
                    .is_ok_and(|v| v.abs() > USVG_MAX_NUMBER)
                {
                    let pos = doc.text_pos_at(node.range().start);
                    return Err(ParseError::new(
                        format!("line {}", pos.row),
                        format!(
                            "{NAME} {number} is beyond {USVG_MAX_NUMBER:.1e}, the largest number the SVG reader takes"
                        ),
                    ));
                }
            }
        }
    }
    Ok(())
}
