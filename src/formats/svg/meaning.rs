//! What an SVG element says it is, beyond its colour: `data-assignment` attributes (Rabbit
//! Ear's exports), class names, and `data-foldAngle`.
//!
//! usvg keeps an element's `id` but drops `class` and `data-*` attributes, and it drops lines
//! drawn without a stroke (Rabbit Ear may write `<line data-assignment="V">` with no stroke at
//! all). So the reader scans the XML first: every shape element (`path`, `line`, `polyline`,
//! `polygon`, `rect`, `circle`, `ellipse`) that carries a meaning, on itself or on the nearest
//! enclosing element that has one, is given an id if it has none and a stroke if it has none,
//! by rewriting the text at the element's start tag; the meanings are returned by id.
//!
//! Meanings, in order of precedence:
//! 1. `data-assignment`: a FOLD letter (`M`, `V`, `B`, `F`, `U`, `C`, `J`, either case) or an
//!    assignment's name;
//! 2. a class name: `mountain`, `valley`, `boundary`, `cut`, `flat`, `mark`, `facet`,
//!    `unassigned`, `join` (plural forms too), and Blender Paper Model's `convex` (mountain),
//!    `concave` (valley) and `outer` (boundary).
//!
//! `data-foldAngle` (degrees, FOLD's sign) gives the fold angle where present.

use std::collections::HashMap;

use usvg::roxmltree::{self, Node};

use crate::pattern::Assignment;

/// A meaning read from the XML.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Meaning {
    /// The assignment the element declares.
    pub assignment: Assignment,
    /// Its fold angle in degrees (FOLD's sign), from `data-foldAngle`.
    pub fold_angle: Option<f64>,
}

/// The result of [`scan`].
#[derive(Debug, Default)]
pub struct Scan {
    /// The document with ids and strokes added, when anything had to be added.
    pub text: Option<String>,
    /// The meaning of each element, by id.
    pub by_id: HashMap<String, Meaning>,
}

/// The shape elements usvg turns into paths.
const SHAPES: [&str; 7] = [
    "path", "line", "polyline", "polygon", "rect", "circle", "ellipse",
];

/// Prefix of the ids given to elements that have none.
const ID_PREFIX: &str = "foldcam-meaning-";

/// The assignment a class name stands for, if any.
pub fn class_assignment(class: &str) -> Option<Assignment> {
    Some(match class.to_ascii_lowercase().as_str() {
        "mountain" | "mountains" | "convex" => Assignment::Mountain,
        "valley" | "valleys" | "concave" => Assignment::Valley,
        "boundary" | "boundaries" | "border" | "outer" => Assignment::Boundary,
        "cut" | "cuts" => Assignment::Cut,
        "flat" | "mark" | "marks" | "facet" | "facets" => Assignment::Flat,
        "unassigned" | "hinge" => Assignment::Unassigned,
        "join" | "joins" => Assignment::Join,
        _ => return None,
    })
}

/// The assignment a `data-assignment` value names, if any.
pub fn data_assignment(value: &str) -> Option<Assignment> {
    let value = value.trim();
    let mut chars = value.chars();
    match (chars.next(), chars.next()) {
        (Some(c), None) => Assignment::from_letter(c),
        _ => class_assignment(value),
    }
}

/// The element's own meaning, if it declares one.
fn own_meaning(node: Node) -> Option<Assignment> {
    if let Some(a) = node.attribute("data-assignment").and_then(data_assignment) {
        return Some(a);
    }
    node.attribute("class")?
        .split_whitespace()
        .find_map(class_assignment)
}

/// The element's fold angle from `data-foldAngle` (on it or the nearest ancestor with one).
fn fold_angle(node: Node) -> Option<f64> {
    node.ancestors()
        .filter(Node::is_element)
        .find_map(|n| {
            n.attributes()
                .find(|a| a.name().eq_ignore_ascii_case("data-foldangle"))
        })
        .and_then(|a| a.value().trim().parse::<f64>().ok())
        .filter(|a| a.is_finite() && a.abs() <= 180.0)
}

/// True when the element sets a stroke itself (attribute or inline style).
fn has_own_stroke(node: Node) -> bool {
    node.attribute("stroke").is_some()
        || node
            .attribute("style")
            .is_some_and(|s| s.contains("stroke:") || s.contains("stroke :"))
}

/// Finds every shape with a meaning (see the module docs) and returns them by id, with the
/// text rewritten when ids or strokes had to be added.
pub fn scan(doc: &roxmltree::Document, text: &str) -> Scan {
    let mut by_id = HashMap::new();
    let mut inserts: Vec<(usize, String)> = Vec::new();
    let mut fresh = 0usize;
    for node in doc.descendants().filter(|n| is_shape(*n)) {
        let Some(assignment) = node
            .ancestors()
            .filter(Node::is_element)
            .find_map(own_meaning)
        else {
            continue;
        };
        let meaning = Meaning {
            assignment,
            fold_angle: fold_angle(node),
        };
        let mut added = String::new();
        let id = match node.attribute("id").filter(|id| !by_id.contains_key(*id)) {
            Some(id) => id.to_string(),
            None if node.attribute("id").is_some() => continue,
            None => {
                fresh += 1;
                let id = format!("{ID_PREFIX}{fresh}");
                added.push_str(&format!(" id=\"{id}\""));
                id
            }
        };
        if !has_own_stroke(node) && !ancestor_stroke(node) {
            added.push_str(" stroke=\"#000000\"");
        }
        if !added.is_empty() {
            inserts.push((tag_name_end(text, node.range().start), added));
        }
        by_id.insert(id, meaning);
    }
    Scan {
        text: (!inserts.is_empty()).then(|| insert_all(text, inserts)),
        by_id,
    }
}

/// True when an enclosing element sets a stroke that is not `none`.
fn ancestor_stroke(node: Node) -> bool {
    node.ancestors()
        .skip(1)
        .filter(Node::is_element)
        .any(|n| n.attribute("stroke").is_some_and(|s| s.trim() != "none"))
}

fn is_shape(node: Node) -> bool {
    node.is_element()
        && SHAPES.contains(&node.tag_name().name())
        && matches!(
            node.tag_name().namespace(),
            None | Some("http://www.w3.org/2000/svg")
        )
}

/// The byte just after the tag name of the start tag at `start` (which points at `<`).
fn tag_name_end(text: &str, start: usize) -> usize {
    let rest = &text[start..];
    let len = rest
        .char_indices()
        .skip(1)
        .find(|(_, c)| c.is_whitespace() || *c == '/' || *c == '>')
        .map_or(rest.len(), |(i, _)| i);
    start + len
}

/// The text with each string inserted at its byte offset.
fn insert_all(text: &str, mut inserts: Vec<(usize, String)>) -> String {
    inserts.sort_by_key(|(at, _)| *at);
    let mut out = String::with_capacity(text.len() + inserts.len() * 48);
    let mut from = 0;
    for (at, s) in inserts {
        out.push_str(&text[from..at]);
        out.push_str(&s);
        from = at;
    }
    out.push_str(&text[from..]);
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scanned(text: &str) -> Scan {
        let doc = roxmltree::Document::parse(text).unwrap_or_else(|e| panic!("{e}"));
        scan(&doc, text)
    }

    #[test]
    fn data_assignment_beats_class_and_lines_get_ids_and_strokes() {
        let text = "<svg xmlns=\"http://www.w3.org/2000/svg\"><g class=\"valley\">\
                    <line x1=\"0\" y1=\"0\" x2=\"1\" y2=\"1\"/>\
                    <line id=\"a\" class=\"cut\" data-assignment=\"m\" data-foldAngle=\"-90\" \
                    stroke=\"red\" x1=\"0\" y1=\"1\" x2=\"1\" y2=\"0\"/></g></svg>";
        let scan = scanned(text);
        let a = scan.by_id["a"];
        assert_eq!(a.assignment, Assignment::Mountain);
        assert_eq!(a.fold_angle, Some(-90.0));
        let added = scan.by_id[&format!("{ID_PREFIX}1")];
        assert_eq!(added.assignment, Assignment::Valley);
        let rewritten = scan.text.unwrap_or_default();
        assert!(rewritten.contains(&format!("<line id=\"{ID_PREFIX}1\" stroke=\"#000000\" x1")));
        assert!(roxmltree::Document::parse(&rewritten).is_ok());
    }

    #[test]
    fn plain_drawings_are_left_alone() {
        let scan = scanned(
            "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"creasePattern\">\
             <line stroke=\"red\" x1=\"0\" y1=\"0\" x2=\"1\" y2=\"1\"/></svg>",
        );
        assert!(scan.text.is_none() && scan.by_id.is_empty());
    }

    #[test]
    fn names_and_letters() {
        assert_eq!(data_assignment("B"), Some(Assignment::Boundary));
        assert_eq!(data_assignment("valley"), Some(Assignment::Valley));
        assert_eq!(data_assignment("x"), None);
        assert_eq!(class_assignment("Concave"), Some(Assignment::Valley));
        assert_eq!(class_assignment("edges"), None);
    }
}
