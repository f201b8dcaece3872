//! ORIPA's native files (`.opx`): a Java `XMLEncoder` document of an `oripa.DataSet` whose
//! `lines` array holds `oripa.OriLineProxy` objects with the properties `type`, `x0`, `y0`,
//! `x1`, `y1`. The encoder leaves out properties at their default (0), so a missing one is 0.
//! Line types and the y axis are those of the `.cp` format ([`super::cp`]): 1 boundary, 2
//! mountain, 3 valley, anything else auxiliary (flat); y is negated to the pattern's y-up
//! frame. Other `DataSet` fields (title, editor, memo) are ignored. Patterns read are
//! [`Units::Unitless`].
//!
//! The writer puts every line in a `lines` array with all five properties, readable by ORIPA
//! and by this reader.

use std::fmt::Write as _;

use glam::DVec2;

use super::{FindingKind, Imported, ParseError};
use crate::pattern::{Assignment, CreasePattern, MAX_COORDINATE, Units};

/// Most lines read from one file.
pub const MAX_LINES: usize = 10_000_000;

/// Most XML nodes of one document (elements, text, attributes' owners): several per line of
/// [`MAX_LINES`] lines, and far fewer than would exhaust memory.
pub const MAX_NODES: u32 = 200_000_000;

/// The class of a line object.
const LINE_CLASS: &str = "oripa.OriLineProxy";

const LINE_OBJECT: &str = "<object class=\"oripa.OriLineProxy\">";

/// Parses an `.opx` document with an XML parser (`roxmltree`): only `object` elements of
/// class `oripa.OriLineProxy` are lines, so text in comments, CDATA sections, strings or
/// attribute values never becomes a crease. Documents with a DTD are refused (ORIPA writes
/// none, and entity definitions are how a small file expands into a large one).
pub fn read_str(text: &str) -> Result<Imported, ParseError> {
    let options = roxmltree::ParsingOptions {
        allow_dtd: false,
        nodes_limit: MAX_NODES,
        ..roxmltree::ParsingOptions::default()
    };
    let doc = roxmltree::Document::parse_with_options(text, options).map_err(|e| {
        let pos = e.pos();
        ParseError::new(
            format!("line {}, column {}", pos.row, pos.col),
            format!("not a readable XML document: {e}"),
        )
    })?;
    let mut pattern = CreasePattern {
        units: Units::Unitless,
        ..CreasePattern::default()
    };
    let mut zero_length = 0;
    let lines = doc
        .descendants()
        .filter(|n| n.has_tag_name("object") && n.attribute("class") == Some(LINE_CLASS));
    for (index, object) in lines.enumerate() {
        let (kind, a, b) =
            parse_line(object).map_err(|m| ParseError::new(format!("line object {index}"), m))?;
        if a == b {
            zero_length += 1;
            continue;
        }
        if pattern.edges.len() >= MAX_LINES {
            return Err(ParseError::new(
                format!("line object {index}"),
                format!("more than {MAX_LINES} lines, the most read"),
            ));
        }
        pattern.add_segment(a, b, super::cp::assignment_of(kind));
    }
    if pattern.edges.is_empty() {
        return Err(ParseError::new(
            "file",
            "no lines of non-zero length (expected oripa.OriLineProxy objects)",
        ));
    }
    let mut warnings = Vec::new();
    if zero_length > 0 {
        warnings.push(
            FindingKind::ZeroLengthLines
                .warning(format!("{zero_length} zero-length line(s) ignored")),
        );
    }
    super::finish_drawing(pattern, None, None, "lying", warnings)
}

/// Reads the properties of one line object, its `<void property="…">` children (missing
/// ones are 0).
fn parse_line(object: roxmltree::Node<'_, '_>) -> Result<(i64, DVec2, DVec2), String> {
    let mut kind = 0;
    let mut c = [0.0f64; 4];
    for property in object.children().filter(|n| n.has_tag_name("void")) {
        let Some(name) = property.attribute("property") else {
            continue;
        };
        let value_text =
            value_of(property).ok_or_else(|| format!("property {name:?} has no value"))?;
        match name {
            "type" => {
                kind = value_text
                    .parse()
                    .map_err(|_| format!("type {value_text:?} is not an integer"))?;
            }
            "x0" | "y0" | "x1" | "y1" => {
                let v: f64 = value_text
                    .parse()
                    .map_err(|_| format!("{name} {value_text:?} is not a number"))?;
                if !v.is_finite() || v.abs() > MAX_COORDINATE {
                    return Err(format!(
                        "{name} = {v} is not finite or beyond ±{MAX_COORDINATE:e}"
                    ));
                }
                let i = ["x0", "y0", "x1", "y1"]
                    .iter()
                    .position(|n| *n == name)
                    .unwrap_or(0);
                c[i] = v;
            }
            _ => {}
        }
    }
    Ok((kind, DVec2::new(c[0], -c[1]), DVec2::new(c[2], -c[3])))
}

/// The text of the property's first `<int>`, `<double>`, `<float>` or `<long>` element.
fn value_of<'a>(property: roxmltree::Node<'a, '_>) -> Option<&'a str> {
    let value = property.children().find(|n| n.is_element())?;
    if !matches!(value.tag_name().name(), "int" | "double" | "float" | "long") {
        return None;
    }
    Some(value.text().unwrap_or("").trim())
}

/// Renders a pattern as an `.opx` document (types as in `.cp`: cuts written as boundaries,
/// unassigned and join lines as auxiliary).
pub fn write_string(pattern: &CreasePattern) -> String {
    let lines: Vec<_> = pattern
        .edges
        .iter()
        .map(|e| {
            let kind = match e.assignment {
                Assignment::Boundary | Assignment::Cut => 1,
                Assignment::Mountain => 2,
                Assignment::Valley => 3,
                _ => 0,
            };
            let [a, b] = e.vertices.map(|v| pattern.position(v));
            (kind, a, b)
        })
        .collect();
    let mut out = String::from(
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<java version=\"1.8.0\" class=\"java.beans.XMLDecoder\">\n <object class=\"oripa.DataSet\" id=\"DataSet0\">\n  <void class=\"oripa.DataSet\" method=\"getField\">\n   <string>lines</string>\n   <void method=\"set\">\n    <object idref=\"DataSet0\"/>\n",
    );
    let _ = writeln!(
        out,
        "    <array class=\"oripa.OriLineProxy\" length=\"{}\">",
        lines.len()
    );
    for (i, (kind, a, b)) in lines.iter().enumerate() {
        let _ = writeln!(out, "     <void index=\"{i}\">\n      {LINE_OBJECT}");
        let _ = writeln!(
            out,
            "       <void property=\"type\">\n        <int>{kind}</int>\n       </void>"
        );
        for (name, v) in [("x0", a.x), ("x1", b.x), ("y0", -a.y), ("y1", -b.y)] {
            let _ = writeln!(
                out,
                "       <void property=\"{name}\">\n        <double>{v:?}</double>\n       </void>"
            );
        }
        out.push_str("      </object>\n     </void>\n");
    }
    out.push_str("    </array>\n   </void>\n  </void>\n </object>\n</java>\n");
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn missing_properties_default_to_zero() {
        let text = format!(
            "<java>{LINE_OBJECT}<void property=\"type\"><int>2</int></void>\
             <void property=\"x1\"><double>10.0</double></void></object>\
             {LINE_OBJECT}<void property=\"type\"><int>1</int></void>\
             <void property=\"x0\"><double>10.0</double></void>\
             <void property=\"y1\"><double>-5.0</double></void></object></java>"
        );
        let cp = read_str(&text).expect("parses").pattern;
        assert_eq!(cp.edges.len(), 2);
        let mountain = cp
            .edges
            .iter()
            .find(|e| e.assignment == Assignment::Mountain)
            .expect("M");
        let ends = mountain.vertices.map(|v| cp.position(v));
        assert!(ends.contains(&DVec2::ZERO) && ends.contains(&DVec2::new(10.0, 0.0)));
        // y is negated: the boundary runs from (10, 0) to (0, 5)
        assert!(cp.vertices.contains(&DVec2::new(0.0, 5.0)));
    }

    #[test]
    fn written_files_read_back() {
        let mut cp = CreasePattern::new();
        cp.add_segment(
            DVec2::new(0.0, 0.0),
            DVec2::new(1.5, 0.25),
            Assignment::Valley,
        );
        cp.add_segment(
            DVec2::new(3.0, 1.0),
            DVec2::new(4.0, -2.0),
            Assignment::Boundary,
        );
        let back = read_str(&write_string(&cp)).expect("reads").pattern;
        assert_eq!(back.edges.len(), 2);
        for e in &cp.edges {
            let [a, b] = e.vertices.map(|v| cp.position(v));
            assert!(back.edges.iter().any(|f| {
                let [c, d] = f.vertices.map(|v| back.position(v));
                f.assignment == e.assignment && ((a, b) == (c, d) || (a, b) == (d, c))
            }));
        }
    }

    #[test]
    fn bad_numbers_are_named() {
        let text = format!(
            "<java>{LINE_OBJECT}<void property=\"x0\"><double>abc</double></void></object></java>"
        );
        let err = read_str(&text).expect_err("refused");
        assert!(err.to_string().contains("x0"), "{err}");
        assert!(read_str("<java></java>").is_err());
    }

    #[test]
    fn lines_in_comments_cdata_and_strings_are_not_creases() {
        let line = |t: i32, x: f64| {
            format!(
                "{LINE_OBJECT}<void property=\"type\"><int>{t}</int></void>\
                 <void property=\"x1\"><double>{x}</double></void></object>"
            )
        };
        let text = format!(
            "<?xml version=\"1.0\"?><java><!-- {} --><string><![CDATA[{}]]></string>\
             <string>{}</string>{}</java>",
            line(2, 5.0),
            line(3, 6.0),
            line(2, 7.0).replace('<', "&lt;"),
            line(1, 10.0)
        );
        let cp = read_str(&text).expect("parses").pattern;
        assert_eq!(cp.edges.len(), 1);
        assert_eq!(cp.edges[0].assignment, Assignment::Boundary);
        let dtd = format!(
            "<!DOCTYPE java [<!ENTITY a \"x\">]><java>{}</java>",
            line(2, 1.0)
        );
        let err = read_str(&dtd).expect_err("a DTD is refused");
        assert!(err.message.contains("not a readable XML document"), "{err}");
    }
}
