//! What reading and cleaning a pattern have to say about a file: each remark is a
//! [`Finding`] whose [`FindingKind`] tells a program what happened and whose text tells a
//! person, so the command line prints it and the studio (or `--json`) can sort, count and
//! show it without parsing sentences.

use std::fmt;

use serde::Serialize;

/// How much a finding matters.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Severity {
    /// Something was skipped, approximated or changed that the user may not have meant.
    Warning,
    /// What the reader decided, without anything being wrong.
    Note,
}

/// What a finding is about, one kind per remark a reader or the cleaning makes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
#[non_exhaustive]
pub enum FindingKind {
    /// Lines of zero length were left out (`.cp`, `.opx`).
    ZeroLengthLines,
    /// `.cp` lines of a type ORIPA does not define, read as auxiliary (flat) lines.
    UnknownLineType,
    /// Lines drawn over others were merged, the stronger assignment kept.
    OverlapsMerged,
    /// An SVG attribute value could not be read; its default was used.
    UnreadableAttribute,
    /// A stroke colour off Origami Simulator's palette, read as the nearest palette colour.
    OffPaletteColour,
    /// Elements without a plain stroke colour (no stroke, a gradient, a pattern) were ignored.
    Unstroked,
    /// Embedded images were ignored.
    Images,
    /// Curved segments were flattened into straight edges.
    CurvesFlattened,
    /// Text elements were ignored.
    Text,
    /// DXF entities that are not creases (or inserts of undefined blocks) were ignored.
    DxfEntities,
    /// DXF layers without a crease name, read by colour.
    DxfLayersByColour,
    /// Line ends were joined and junctions merged within the snapping tolerance.
    Snapped,
    /// Elements were read by their declared assignment (data attribute or class name) rather
    /// than their colour.
    DeclaredAssignment,
    /// How dashed lines were read.
    Dashes,
    /// A FOLD file without `edges_vertices`: edges taken from the faces.
    EdgesFromFaces,
    /// A FOLD file's 3D coordinates lie in one plane, rotated onto the xy plane.
    PlaneRotated,
    /// A FOLD frame says `foldedForm` but does not fold: read as a crease pattern.
    NotFolded,
    /// A FOLD file's faces were reversed to run counter-clockwise.
    FacesReversed,
    /// A folded FOLD frame was unfolded into a crease pattern.
    Unfolded,
    /// A FOLD frame of class `foldedForm` could not be used as the folded state.
    FoldedFrameIgnored,
    /// The folded state does not unfold exactly flat (rounded coordinates, or geometry that
    /// does not develop).
    NotDevelopable,
    /// Faces oriented against their neighbours were unfolded mirrored.
    MirroredFaces,
    /// Faces without area were not unfolded.
    DegenerateFaces,
    /// Vertices on no face keep their x and y.
    LooseVertices,
    /// Separate pieces were laid out side by side.
    Pieces,
    /// Mountain and valley lines lie on top of each other; the first of each pair was kept.
    AssignmentConflicts,
    /// The folded state was dropped: it does not match the cleaned pattern.
    FoldedStateDropped,
    /// The drawing was cleaned into a planar graph (vertices merged, crossings split, …).
    Cleaned,
}

/// One remark about a file, without the file's name (the front end adds it).
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct Finding {
    /// What it is about.
    pub kind: FindingKind,
    /// How much it matters.
    pub severity: Severity,
    /// The remark for a person, one sentence without the file name.
    pub text: String,
}

impl FindingKind {
    /// A warning of this kind saying `text`.
    pub fn warning(self, text: impl Into<String>) -> Finding {
        Finding {
            kind: self,
            severity: Severity::Warning,
            text: text.into(),
        }
    }

    /// A note of this kind saying `text`.
    pub fn note(self, text: impl Into<String>) -> Finding {
        Finding {
            kind: self,
            severity: Severity::Note,
            text: text.into(),
        }
    }
}

impl Finding {
    /// True for a warning.
    pub fn is_warning(&self) -> bool {
        self.severity == Severity::Warning
    }

    /// The line a front end prints for file `name`: `warning: NAME: TEXT` for a warning,
    /// `NAME: TEXT` for a note.
    pub fn line(&self, name: &str) -> String {
        match self.severity {
            Severity::Warning => format!("warning: {name}: {}", self.text),
            Severity::Note => format!("{name}: {}", self.text),
        }
    }
}

impl fmt::Display for Finding {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.text)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_warning_and_a_note_print_as_the_front_ends_print_them() {
        let w = FindingKind::Text.warning("2 text element(s) were ignored");
        let n = FindingKind::Snapped.note("snap tolerance 0.1 mm");
        assert!(w.is_warning() && !n.is_warning());
        assert_eq!(
            w.line("a.svg"),
            "warning: a.svg: 2 text element(s) were ignored"
        );
        assert_eq!(n.line("a.svg"), "a.svg: snap tolerance 0.1 mm");
        assert_eq!(w.to_string(), "2 text element(s) were ignored");
        let json = serde_json::to_string(&w).unwrap_or_default();
        assert!(json.contains("\"kind\":\"text\"") && json.contains("\"severity\":\"warning\""));
    }
}
