//! A pattern opened in the studio: read from an upload's bytes or a file named on the command
//! line, and cleaned for each use exactly as the matching `foldcam` subcommand cleans it.

use std::path::Path;
use std::sync::OnceLock;

use glam::DVec2;
use serde::Serialize;

use super::error::{Stage, StudioError};
use crate::check::AssignmentCounts;
use crate::design::source::summary::text_lines;
use crate::design::source::{BuildNote, Design};
use crate::formats::{self, Imported, ReadOptions};
use crate::pattern::{CreasePattern, FoldedState, PlanarizeOptions};

/// A pattern the studio holds: the import as read (warnings and notes included), named as the
/// user named it.
#[derive(Clone, Debug)]
pub struct Document {
    /// The file name (an upload's own name, or the path given on the command line).
    pub name: String,
    /// The pattern as read, before cleaning.
    pub imported: Imported,
    /// For a design file: what was made of it, and the lines the matching command prints.
    pub design: Option<DesignNote>,
    /// The cleaning without faces, done once (snapping asks for it on every pointer move).
    clean: OnceLock<Result<Cleaned, StudioError>>,
}

/// What a design file became ([`crate::design::source`]).
#[derive(Clone, Debug)]
pub struct DesignNote {
    /// What was made (e.g. "origami tessellation (Tachi 2014)").
    pub made: &'static str,
    /// What the build said: its notes, then the command's summary lines.
    pub lines: Vec<String>,
    /// The pattern's flat lines are labels (a paper craft's edge numbers): planned as
    /// `foldcam papercraft --job` plans them, marked where the machine can
    /// ([`crate::fab::mark_labels`]) unless the user chose an operation for flat lines.
    pub labels: bool,
}

/// The pattern after cleaning, with what cleaning had to say.
#[derive(Clone, Debug)]
pub struct Cleaned {
    /// The planar pattern.
    pub pattern: CreasePattern,
    /// The folded state, kept only when cleaning changed nothing.
    pub folded: Option<FoldedState>,
    /// What `foldcam` prints on stderr about the reading and cleaning, without `foldcam: `
    /// (for a design file, what the build said first).
    pub messages: Vec<String>,
    /// For a design file, what was made of it.
    pub made: Option<&'static str>,
}

impl Document {
    /// Reads a file named on the command line, as `foldcam check FILE` reads it.
    ///
    /// # Errors
    /// The message `foldcam` prints for the same file.
    pub fn open(path: &Path) -> Result<Document, StudioError> {
        let imported = formats::load_with(path, &ReadOptions::default())
            .map_err(|e| StudioError::named(Stage::Read, e))?;
        Document::new(path.display().to_string(), imported)
    }

    /// Reads an upload: `name` chooses the format by its extension and names the file in
    /// messages; nothing is read from disk.
    ///
    /// # Errors
    /// The message `foldcam` prints for a file of that name and content.
    pub fn from_upload(name: &str, bytes: &[u8]) -> Result<Document, StudioError> {
        let path = Path::new(name);
        let imported = formats::format_of(path)
            .and_then(|format| formats::load_bytes(path, format, bytes, &ReadOptions::default()))
            .map_err(|e| StudioError::named(Stage::Read, e))?;
        Document::new(name.to_string(), imported)
    }

    /// A pattern made in the studio (a bundled example's generator, a blank sheet), named
    /// `name`.
    ///
    /// # Errors
    /// A pattern with no edges.
    pub fn from_pattern(name: String, pattern: CreasePattern) -> Result<Document, StudioError> {
        Document::new(
            name,
            Imported {
                pattern,
                folded: None,
                findings: Vec::new(),
            },
        )
    }

    /// A design built by [`crate::design::source::build_design`], named `name`; `notes` are
    /// what the build said while it ran.
    ///
    /// # Errors
    /// A design with no edges.
    pub fn from_design(
        name: String,
        design: Design,
        notes: Vec<BuildNote>,
    ) -> Result<Document, StudioError> {
        let mut doc = Document::new(
            name,
            Imported {
                pattern: design.pattern,
                folded: design.folded,
                findings: Vec::new(),
            },
        )?;
        let mut lines = text_lines(&notes);
        lines.extend(text_lines(&design.summary));
        doc.design = Some(DesignNote {
            made: design.made,
            lines,
            labels: design.kind.flat_lines_are_labels(),
        });
        Ok(doc)
    }

    /// The document after an edit: `pattern` (planar, from [`crate::pattern::edit`]) replaces
    /// the pattern as read; the folded state read with the file no longer applies and goes.
    pub fn edited(&self, pattern: CreasePattern) -> Document {
        Document {
            name: self.name.clone(),
            imported: Imported {
                pattern,
                folded: None,
                findings: self.imported.findings.clone(),
            },
            // What was made stays; the build's report no longer describes the pattern.
            design: self.design.as_ref().map(|d| DesignNote {
                made: d.made,
                lines: Vec::new(),
                labels: d.labels,
            }),
            clean: OnceLock::new(),
        }
    }

    fn new(name: String, imported: Imported) -> Result<Document, StudioError> {
        imported
            .require_edges(Path::new(&name))
            .map_err(|e| StudioError::named(Stage::Read, e))?;
        Ok(Document {
            name,
            imported,
            design: None,
            clean: OnceLock::new(),
        })
    }

    /// The pattern cleaned into a planar graph (faces traced when `faces`), as `foldcam check`
    /// (`faces` false) or `foldcam fold3d` (`faces` true) cleans it.
    ///
    /// # Errors
    /// The planariser's refusal, naming the file.
    pub fn cleaned(&self, faces: bool) -> Result<Cleaned, StudioError> {
        if faces {
            self.clean_now(true)
        } else {
            self.planar().cloned()
        }
    }

    /// [`Document::cleaned`] without faces, by reference (cleaned once per document).
    ///
    /// # Errors
    /// The planariser's refusal, naming the file.
    pub fn planar(&self) -> Result<&Cleaned, StudioError> {
        self.clean
            .get_or_init(|| self.clean_now(false))
            .as_ref()
            .map_err(Clone::clone)
    }

    fn clean_now(&self, faces: bool) -> Result<Cleaned, StudioError> {
        let name = &self.name;
        let mut imported = self.imported.clone();
        imported
            .clean(&PlanarizeOptions {
                tolerance: None,
                faces,
            })
            .map_err(|e| StudioError::about(Stage::Clean, name, e))?;
        let messages: Vec<String> = self
            .design
            .iter()
            .flat_map(|d| d.lines.iter().cloned())
            .chain(imported.findings.iter().map(|f| f.line(name)))
            .collect();
        let Imported {
            pattern, folded, ..
        } = imported;
        Ok(Cleaned {
            pattern,
            folded,
            messages,
            made: self.design.as_ref().map(|d| d.made),
        })
    }
}

/// One edge as the front end draws it.
#[derive(Clone, Debug, Serialize)]
pub struct EdgeView {
    /// End vertices (indices into [`PatternView::vertices`]).
    pub v: [usize; 2],
    /// FOLD assignment letter.
    pub a: char,
    /// Target fold angle, degrees (FOLD sign), when known.
    pub angle: Option<f64>,
}

/// The cleaned pattern as the front end draws it: numbers match `foldcam check`'s.
#[derive(Clone, Debug, Serialize)]
pub struct PatternView {
    /// The file name.
    pub name: String,
    /// `mm` or `units`.
    pub units: &'static str,
    /// Vertex positions (x right, y up).
    pub vertices: Vec<[f64; 2]>,
    /// Edges.
    pub edges: Vec<EdgeView>,
    /// Vertex and edge counts and edges per assignment.
    pub counts: Counts,
    /// What reading and cleaning reported.
    pub messages: Vec<String>,
    /// For a design file, what was made of it.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub made: Option<&'static str>,
}

/// Counts shown in the page.
#[derive(Clone, Debug, Serialize)]
pub struct Counts {
    /// Vertices.
    pub vertices: usize,
    /// Edges.
    pub edges: usize,
    /// Edges per assignment.
    pub assignments: AssignmentCounts,
}

impl PatternView {
    /// The view of a cleaned pattern.
    pub fn new(name: &str, cleaned: &Cleaned) -> PatternView {
        let cp = &cleaned.pattern;
        PatternView {
            name: name.to_string(),
            units: cp.units.label(),
            vertices: cp.vertices.iter().map(|p: &DVec2| [p.x, p.y]).collect(),
            edges: cp
                .edges
                .iter()
                .map(|e| EdgeView {
                    v: [e.vertices[0].index(), e.vertices[1].index()],
                    a: e.assignment.letter(),
                    angle: e.fold_angle,
                })
                .collect(),
            counts: Counts {
                vertices: cp.vertices.len(),
                edges: cp.edges.len(),
                assignments: AssignmentCounts::of(cp),
            },
            messages: cleaned.messages.clone(),
            made: cleaned.made,
        }
    }
}
