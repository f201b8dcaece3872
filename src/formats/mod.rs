//! Reading and writing crease patterns: FOLD 1.2, Origami-Simulator SVG, ORIPA `.cp` and
//! `.opx`; DXF drawings are read.
//!
//! Each format module parses from text into an [`Imported`] pattern, or renders a pattern to
//! text, without touching the file system; [`load`] and [`save`] add file access, pick the
//! format from the extension, name the file in every error and write atomically (a temporary
//! file beside the target, then a rename), so a failed run never leaves a half-written output.

pub(crate) mod atomic;
pub mod cp;
pub mod dxf;
pub(crate) mod finding;
pub mod fold;
pub(crate) mod options;
pub mod opx;
pub(crate) mod snap;
pub mod svg;

use std::path::{Path, PathBuf};

use crate::pattern::{
    CreasePattern, FoldedState, PatternError, PlanarizeError, PlanarizeOptions, PlanarizeReport,
    planarize,
};

pub use atomic::{OutputError, OutputSet, check_targets, remove_pending_temporaries, write_atomic};
pub use finding::{Finding, FindingKind, Severity};
pub use options::{DashedAs, ReadOptions};
pub use snap::SNAP_RELATIVE;

/// Most rounds of snapping (joining ends, merging junctions, planarising) on one drawing.
const SNAP_ROUNDS: usize = 3;

/// Largest input file read, in bytes (256 MiB): larger inputs are refused with an error rather
/// than exhausting memory.
pub const MAX_INPUT_BYTES: u64 = 256 * 1024 * 1024;

/// A file format, chosen from a path's extension.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    /// FOLD 1.2 (`.fold`, JSON).
    Fold,
    /// Crease-pattern SVG in Origami Simulator's colours (`.svg`).
    Svg,
    /// ORIPA line list (`.cp`).
    Cp,
    /// AutoCAD drawing exchange (`.dxf`, R12 and R2000 or later); read only.
    Dxf,
    /// ORIPA's XML document (`.opx`).
    Opx,
}

impl Format {
    /// The format for a path's extension (case-insensitive), `None` if unknown.
    pub fn from_path(path: &Path) -> Option<Format> {
        let ext = path.extension()?.to_str()?.to_ascii_lowercase();
        match ext.as_str() {
            "fold" | "json" => Some(Format::Fold),
            "svg" => Some(Format::Svg),
            "cp" => Some(Format::Cp),
            "dxf" => Some(Format::Dxf),
            "opx" => Some(Format::Opx),
            _ => None,
        }
    }

    /// Extensions read, for help and error text (each one [`Format::from_path`] takes; DXF
    /// is read only).
    pub const EXTENSIONS: &'static str = ".fold, .svg, .cp, .opx or .dxf";

    /// Extensions that can be written.
    pub const WRITABLE: &'static str = ".fold, .svg, .cp or .opx";

    /// True for formats that store fold angles (FOLD's `edges_foldAngle`, the SVG's stroke
    /// opacity); ORIPA's `.cp` and `.opx` do not, so a 3D target written to them reads back
    /// as folding flat.
    pub fn keeps_fold_angles(self) -> bool {
        matches!(self, Format::Fold | Format::Svg)
    }

    /// True for formats [`save`] can write.
    pub fn writable(self) -> bool {
        self != Format::Dxf
    }
}

/// A pattern read from a file, with what the reader had to say about it.
#[derive(Clone, Debug, Default)]
pub struct Imported {
    /// The crease pattern (validated).
    pub pattern: CreasePattern,
    /// The folded state, when the file holds one (a FOLD frame of class `foldedForm` in 3D).
    pub folded: Option<FoldedState>,
    /// What the reader (and [`Imported::clean`]) had to say, in order: warnings (off-palette
    /// colours, ignored elements, flattened 3D input, …) and notes (what the reader decided
    /// that the user should know without anything being wrong: the snapping tolerance used
    /// and how many line ends it joined).
    pub findings: Vec<Finding>,
}

impl Imported {
    /// The warnings among the findings.
    pub fn warnings(&self) -> impl Iterator<Item = &Finding> {
        self.findings.iter().filter(|f| f.is_warning())
    }

    /// The notes among the findings.
    pub fn notes(&self) -> impl Iterator<Item = &Finding> {
        self.findings.iter().filter(|f| !f.is_warning())
    }

    /// Refuses a pattern with no edges (nothing to check, draw or convert), naming `name`.
    ///
    /// # Errors
    /// [`FormatError::Empty`].
    pub fn require_edges(&self, name: &Path) -> Result<(), FormatError> {
        if self.pattern.edges.is_empty() {
            return Err(FormatError::Empty {
                path: name.to_path_buf(),
            });
        }
        Ok(())
    }

    /// Whether a finding of `kind` was made.
    pub fn found(&self, kind: FindingKind) -> bool {
        self.findings.iter().any(|f| f.kind == kind)
    }

    /// Cleans the pattern into a planar graph as every command and the studio do before using
    /// it (see [`planarize()`]: merged vertices, split crossings, removed zero-length and
    /// duplicate edges; faces traced when `options.faces`) and adds what happened to
    /// [`Imported::findings`]: overlapping mountain and valley lines
    /// ([`FindingKind::AssignmentConflicts`]); a folded state that no longer matches the
    /// changed pattern, dropped ([`FindingKind::FoldedStateDropped`]); what cleaning changed
    /// ([`FindingKind::Cleaned`]). Returns the planariser's report.
    ///
    /// # Errors
    /// The planariser's refusal (the file name is the caller's to add).
    pub fn clean(&mut self, options: &PlanarizeOptions) -> Result<PlanarizeReport, PlanarizeError> {
        let report = planarize(&mut self.pattern, options)?;
        if report.assignment_conflicts > 0 {
            self.findings
                .push(FindingKind::AssignmentConflicts.warning(format!(
                    "{} mountain and valley lines lie on top of each other; the first of each \
                     pair was kept",
                    report.assignment_conflicts
                )));
        }
        if !report.unchanged() {
            if self.folded.take().is_some() {
                self.findings.push(FindingKind::FoldedStateDropped.warning(
                    "the folded state was dropped: it does not match the cleaned pattern",
                ));
            }
            self.findings.push(FindingKind::Cleaned.note(format!(
                "cleaned the drawing: {} vertices merged, {} crossings, {} edge splits, {} \
                 zero-length and {} duplicate edges removed",
                report.merged_vertices,
                report.crossings,
                report.splits,
                report.zero_length_removed,
                report.duplicates_removed
            )));
        }
        Ok(report)
    }
}

/// A problem in a file's content, located without the file name (which [`load`] adds).
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("{place}: {message}")]
pub struct ParseError {
    /// Where: `line 12`, `key "edges_vertices"[3]`, `<path id="a">`, or `file`.
    pub place: String,
    /// What is wrong and, where useful, what was expected.
    pub message: String,
}

impl ParseError {
    /// A parse error at `place`.
    pub fn new(place: impl Into<String>, message: impl Into<String>) -> Self {
        ParseError {
            place: place.into(),
            message: message.into(),
        }
    }
}

/// An error reading or writing a file; always names the file.
#[derive(Debug, thiserror::Error)]
pub enum FormatError {
    /// The operating system refused.
    #[error("{path}: {source}")]
    Io {
        /// The file.
        path: PathBuf,
        /// The cause.
        source: std::io::Error,
    },
    /// The extension names no format we know.
    #[error("{path}: unknown file type (expected one of {expected})")]
    UnknownFormat {
        /// The file.
        path: PathBuf,
        /// The accepted extensions.
        expected: &'static str,
    },
    /// The file is larger than [`MAX_INPUT_BYTES`].
    #[error("{path}: file is {size} bytes, larger than the limit of {MAX_INPUT_BYTES} bytes")]
    TooLarge {
        /// The file.
        path: PathBuf,
        /// Its size.
        size: u64,
    },
    /// The content does not parse.
    #[error("{path}: {source}")]
    Parse {
        /// The file.
        path: PathBuf,
        /// Where and what.
        source: ParseError,
    },
    /// The pattern holds no edges.
    #[error(
        "{path}: the pattern holds no edges (and no faces to derive them from): nothing to \
         check, draw or convert"
    )]
    Empty {
        /// The file.
        path: PathBuf,
    },
    /// The content parses but describes an invalid pattern.
    #[error("{path}: {source}")]
    Pattern {
        /// The file.
        path: PathBuf,
        /// The broken invariant.
        source: PatternError,
    },
}

/// The format of `path`, from its extension.
///
/// # Errors
/// [`FormatError::UnknownFormat`] naming the file and the extensions read.
pub fn format_of(path: &Path) -> Result<Format, FormatError> {
    Format::from_path(path).ok_or_else(|| FormatError::UnknownFormat {
        path: path.to_path_buf(),
        expected: Format::EXTENSIONS,
    })
}

/// Reads a file's bytes, refusing files over [`MAX_INPUT_BYTES`].
pub fn read_bytes(path: &Path) -> Result<Vec<u8>, FormatError> {
    let io = |source| FormatError::Io {
        path: path.to_path_buf(),
        source,
    };
    let size = std::fs::metadata(path).map_err(io)?.len();
    if size > MAX_INPUT_BYTES {
        return Err(FormatError::TooLarge {
            path: path.to_path_buf(),
            size,
        });
    }
    std::fs::read(path).map_err(io)
}

/// Reads a text file, refusing files over [`MAX_INPUT_BYTES`] and invalid UTF-8.
pub fn read_text(path: &Path) -> Result<String, FormatError> {
    let bytes = read_bytes(path)?;
    String::from_utf8(bytes).map_err(|e| FormatError::Parse {
        path: path.to_path_buf(),
        source: ParseError::new(
            format!("byte {}", e.utf8_error().valid_up_to()),
            "file is not valid UTF-8 text",
        ),
    })
}

/// The common end of the line-drawing readers (SVG, DXF, `.cp`): planarise the collected
/// segments (merging within `tolerance`, default when `None`), note merged duplicates ("N
/// line(s) `verb` over others were merged"), then, with a snapping tolerance `snap` larger
/// than that (see [`snap`]), join line ends and merge junctions within it (as Origami
/// Simulator's importer merges vertices within its tolerance, but leaving the points of
/// chains such as flattened curves in place) and planarise again, noting the tolerance and
/// what it changed; validate, and wrap up.
pub(crate) fn finish_drawing(
    mut pattern: CreasePattern,
    tolerance: Option<f64>,
    snap: Option<f64>,
    verb: &str,
    mut findings: Vec<Finding>,
) -> Result<Imported, ParseError> {
    let options = PlanarizeOptions {
        tolerance,
        faces: false,
    };
    let report =
        planarize(&mut pattern, &options).map_err(|e| ParseError::new("file", e.to_string()))?;
    if report.duplicates_removed > 0 {
        findings.push(FindingKind::OverlapsMerged.warning(format!(
            "{} line(s) {verb} over others were merged (the stronger assignment kept)",
            report.duplicates_removed
        )));
    }
    if let Some(snap) = snap.filter(|&s| s > report.tolerance) {
        let (mut joined, mut merged) = (0, 0);
        // Joining can leave new short stubs where lines were split; a second round finds them.
        for _ in 0..SNAP_ROUNDS {
            let ends = snap::snap_ends(&mut pattern, snap);
            let junctions = snap::snap_junctions(&mut pattern, snap);
            if ends + junctions == 0 {
                break;
            }
            (joined, merged) = (joined + ends, merged + junctions);
            planarize(&mut pattern, &options)
                .map_err(|e| ParseError::new("file", e.to_string()))?;
        }
        let unit = pattern.units.label();
        // Said when it changed the drawing; a clean drawing reads without the note.
        if joined + merged > 0 {
            findings.push(FindingKind::Snapped.note(format!(
                "snap tolerance {snap:.4} {unit} (--snap): {joined} line end(s) joined to the \
                 line or corner they stopped short of, {merged} junction(s) merged with a \
                 neighbour"
            )));
        }
    }
    pattern
        .validate()
        .map_err(|e| ParseError::new("file", e.to_string()))?;
    Ok(Imported {
        pattern,
        folded: None,
        findings,
    })
}

/// Parses text in the given format with the default [`ReadOptions`].
pub fn parse(format: Format, text: &str) -> Result<Imported, ParseError> {
    parse_with(format, text, &ReadOptions::default())
}

/// Parses text in the given format: `options.frame` chooses a FOLD file's frame (other
/// formats refuse a frame other than 0), the other options apply to drawings (SVG, DXF).
pub fn parse_with(
    format: Format,
    text: &str,
    options: &ReadOptions,
) -> Result<Imported, ParseError> {
    if options.frame > 0 && format != Format::Fold {
        return Err(ParseError::new(
            format!("frame {}", options.frame),
            "only FOLD files hold frames (--fold-frame applies to FOLD input only)",
        ));
    }
    match format {
        Format::Fold => fold::read_frame_str(text, options.frame),
        Format::Svg => svg::read_str_with(text, options),
        Format::Cp => cp::read_str(text),
        Format::Dxf => dxf::read_str_with(text, options),
        Format::Opx => opx::read_str(text),
    }
}

/// Renders a pattern (and its folded state, where the format can hold one) as text.
///
/// DXF is read only: asking for it renders nothing ([`save`] refuses it first).
pub fn render(format: Format, pattern: &CreasePattern, folded: Option<&FoldedState>) -> String {
    match format {
        Format::Fold => fold::write_string(pattern, folded),
        Format::Svg => svg::write_string(pattern),
        Format::Cp => cp::write_string(pattern),
        Format::Opx => opx::write_string(pattern),
        Format::Dxf => String::new(),
    }
}

/// Reads a pattern from a file, the format chosen by extension; validates it.
///
/// ```
/// use foldcam::{Assignment, Units, load};
/// // A degree-4 vertex with three mountains and one valley (the file says so).
/// let cp = load("examples/patterns/flat-vertex.fold".as_ref())?.pattern;
/// assert_eq!(cp.units, Units::Millimetres);
/// let count = |a| cp.edges.iter().filter(|e| e.assignment == a).count();
/// assert_eq!((count(Assignment::Mountain), count(Assignment::Valley)), (3, 1));
/// // A missing file is an error naming the file, never a panic.
/// let err = load("no/such/pattern.fold".as_ref()).unwrap_err();
/// assert!(err.to_string().contains("no/such/pattern.fold"));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn load(path: &Path) -> Result<Imported, FormatError> {
    load_with(path, &ReadOptions::default())
}

/// [`load`] with [`ReadOptions`]: a FOLD file's frame, options for drawings (SVG, DXF).
pub fn load_with(path: &Path, options: &ReadOptions) -> Result<Imported, FormatError> {
    let format = format_of(path)?;
    load_bytes(path, format, &read_bytes(path)?, options)
}

/// Reads a pattern in `format` from `bytes` already in memory (an upload, standard input),
/// as [`load_with`] reads a file: the text decoded (DXF lossily, as older drawings are not
/// UTF-8; the other formats as UTF-8), parsed with `options`, the pattern validated. `name`
/// (a path, an upload's name, "standard input") names the input in every error.
///
/// # Errors
/// [`FormatError::Parse`] (not UTF-8 text, or the format's reader refused it) or
/// [`FormatError::Pattern`] (a broken invariant), naming `name`.
pub fn load_bytes(
    name: &Path,
    format: Format,
    bytes: &[u8],
    options: &ReadOptions,
) -> Result<Imported, FormatError> {
    let parse_error = |source| FormatError::Parse {
        path: name.to_path_buf(),
        source,
    };
    let text = match format {
        Format::Dxf => String::from_utf8_lossy(bytes),
        _ => std::str::from_utf8(bytes)
            .map(std::borrow::Cow::Borrowed)
            .map_err(|e| {
                parse_error(ParseError::new(
                    format!("byte {}", e.valid_up_to()),
                    "file is not valid UTF-8 text",
                ))
            })?,
    };
    let imported = parse_with(format, &text, options).map_err(parse_error)?;
    imported
        .pattern
        .validate()
        .map_err(|source| FormatError::Pattern {
            path: name.to_path_buf(),
            source,
        })?;
    Ok(imported)
}

/// The bytes [`save`] would write to `path` (format from its extension), for writing several
/// outputs together through an [`OutputSet`].
pub fn encode(
    path: &Path,
    pattern: &CreasePattern,
    folded: Option<&FoldedState>,
) -> Result<Vec<u8>, FormatError> {
    let format = format_of(path)?;
    if !format.writable() {
        return Err(FormatError::UnknownFormat {
            path: path.to_path_buf(),
            expected: Format::WRITABLE,
        });
    }
    Ok(render(format, pattern, folded).into_bytes())
}

/// Writes a pattern to a file atomically, the format chosen by extension.
pub fn save(
    path: &Path,
    pattern: &CreasePattern,
    folded: Option<&FoldedState>,
) -> Result<(), FormatError> {
    let bytes = encode(path, pattern, folded)?;
    write_atomic(path, &bytes).map_err(|source| FormatError::Io {
        path: path.to_path_buf(),
        source,
    })
}

#[cfg(test)]
mod table_tests {
    use super::Format;
    use std::path::Path;

    /// The extensions help and errors list, split at ", " and " or ".
    fn listed(text: &str) -> Vec<String> {
        text.replace(" or ", ", ")
            .split(", ")
            .map(|e| e.trim_start_matches('.').to_string())
            .collect()
    }

    /// The lists that help text is made from name exactly what the readers and writers take.
    #[test]
    fn the_listed_extensions_are_the_ones_read_and_written() {
        let read = listed(Format::EXTENSIONS);
        let formats: Vec<Format> = read
            .iter()
            .map(|e| Format::from_path(Path::new(&format!("x.{e}"))).expect(e))
            .collect();
        for f in [
            Format::Fold,
            Format::Svg,
            Format::Cp,
            Format::Dxf,
            Format::Opx,
        ] {
            assert!(formats.contains(&f), "{f:?} is not listed");
        }
        let written: Vec<Format> = listed(Format::WRITABLE)
            .iter()
            .map(|e| Format::from_path(Path::new(&format!("x.{e}"))).expect(e))
            .collect();
        let writable: Vec<Format> = formats.iter().copied().filter(|f| f.writable()).collect();
        assert_eq!(written, writable);
    }
}
