//! Reading and writing crease patterns: FOLD 1.2, Origami-Simulator SVG, ORIPA `.cp` and
//! `.opx`.
//!
//! Each format module parses from text into an [`Imported`] pattern, or renders a pattern to
//! text, without touching the file system; [`load`] and [`save`] add file access, pick the
//! format from the extension, name the file in every error and write atomically (a temporary
//! file beside the target, then a rename), so a failed run never leaves a half-written output.

pub mod atomic;
pub mod cp;
pub mod fold;
pub mod opx;
pub mod svg;

use std::path::{Path, PathBuf};

use crate::pattern::{CreasePattern, FoldedState, PatternError, PlanarizeOptions, planarize};

pub use atomic::write_atomic;

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
            "opx" => Some(Format::Opx),
            _ => None,
        }
    }

    /// Extensions accepted, for help and error text.
    pub const EXTENSIONS: &'static str = ".fold, .svg, .cp, .opx";
}

/// A pattern read from a file, with what the reader had to say about it.
#[derive(Clone, Debug, Default)]
pub struct Imported {
    /// The crease pattern (validated).
    pub pattern: CreasePattern,
    /// The folded state, when the file holds one (a FOLD frame of class `foldedForm` in 3D).
    pub folded: Option<FoldedState>,
    /// Non-fatal remarks (off-palette colours, ignored elements, flattened 3D input, …).
    pub warnings: Vec<String>,
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
    /// The content parses but describes an invalid pattern.
    #[error("{path}: {source}")]
    Pattern {
        /// The file.
        path: PathBuf,
        /// The broken invariant.
        source: PatternError,
    },
}

fn format_of(path: &Path) -> Result<Format, FormatError> {
    Format::from_path(path).ok_or_else(|| FormatError::UnknownFormat {
        path: path.to_path_buf(),
        expected: Format::EXTENSIONS,
    })
}

/// Reads a text file, refusing files over [`MAX_INPUT_BYTES`] and invalid UTF-8.
pub fn read_text(path: &Path) -> Result<String, FormatError> {
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
    let bytes = std::fs::read(path).map_err(io)?;
    String::from_utf8(bytes).map_err(|e| FormatError::Parse {
        path: path.to_path_buf(),
        source: ParseError::new(
            format!("byte {}", e.utf8_error().valid_up_to()),
            "file is not valid UTF-8 text",
        ),
    })
}

/// The common end of the line-drawing readers (SVG, `.cp`): planarise the collected segments
/// (merging within `tolerance`, default when `None`), note merged duplicates ("N line(s)
/// `verb` over others were merged"), validate, and wrap up.
pub(crate) fn finish_drawing(
    mut pattern: CreasePattern,
    tolerance: Option<f64>,
    verb: &str,
    mut warnings: Vec<String>,
) -> Result<Imported, ParseError> {
    let options = PlanarizeOptions {
        tolerance,
        faces: false,
    };
    let report =
        planarize(&mut pattern, &options).map_err(|e| ParseError::new("file", e.to_string()))?;
    if report.duplicates_removed > 0 {
        warnings.push(format!(
            "{} line(s) {verb} over others were merged (the stronger assignment kept)",
            report.duplicates_removed
        ));
    }
    pattern
        .validate()
        .map_err(|e| ParseError::new("file", e.to_string()))?;
    Ok(Imported {
        pattern,
        folded: None,
        warnings,
    })
}

/// Parses text in the given format.
pub fn parse(format: Format, text: &str) -> Result<Imported, ParseError> {
    match format {
        Format::Fold => fold::read_str(text),
        Format::Svg => svg::read_str(text),
        Format::Cp => cp::read_str(text),
        Format::Opx => opx::read_str(text),
    }
}

/// Renders a pattern (and its folded state, where the format can hold one) as text.
pub fn render(format: Format, pattern: &CreasePattern, folded: Option<&FoldedState>) -> String {
    match format {
        Format::Fold => fold::write_string(pattern, folded),
        Format::Svg => svg::write_string(pattern),
        Format::Cp => cp::write_string(pattern),
        Format::Opx => opx::write_string(pattern),
    }
}

/// Reads a pattern from a file, the format chosen by extension; validates it.
pub fn load(path: &Path) -> Result<Imported, FormatError> {
    let format = format_of(path)?;
    let text = read_text(path)?;
    let imported = parse(format, &text).map_err(|source| FormatError::Parse {
        path: path.to_path_buf(),
        source,
    })?;
    imported
        .pattern
        .validate()
        .map_err(|source| FormatError::Pattern {
            path: path.to_path_buf(),
            source,
        })?;
    Ok(imported)
}

/// Writes a pattern to a file atomically, the format chosen by extension.
pub fn save(
    path: &Path,
    pattern: &CreasePattern,
    folded: Option<&FoldedState>,
) -> Result<(), FormatError> {
    let format = format_of(path)?;
    let text = render(format, pattern, folded);
    write_atomic(path, text.as_bytes()).map_err(|source| FormatError::Io {
        path: path.to_path_buf(),
        source,
    })
}
