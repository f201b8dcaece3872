//! Loading an input pattern for a subcommand: read, report warnings, planarise.

use std::path::Path;

use anyhow::{Result, bail};
use foldcam::formats::{self, Imported};
use foldcam::pattern::{
    CreasePattern, FoldedState, PlanarizeOptions, PlanarizeReport, Units, planarize,
};

/// Choosing a frame of a FOLD file.
#[derive(clap::Args, Clone, Debug, Default)]
pub struct FrameArg {
    /// Read frame N of a FOLD file (0 is the key frame; later frames come from file_frames,
    /// with frame_inherit resolved).
    #[arg(long, value_name = "N")]
    pub frame: Option<usize>,
}

/// Reads `path` (frame `frame.frame` for FOLD files), prints the reader's warnings to stderr,
/// and returns the import.
pub fn load(path: &Path, frame: &FrameArg) -> Result<Imported> {
    let imported = match frame.frame {
        None | Some(0) => formats::load(path)?,
        Some(n) => load_frame(path, n)?,
    };
    if imported.pattern.edges.is_empty() {
        bail!(
            "{}: the pattern holds no edges (and no faces to derive them from): nothing to \
             check, draw or convert",
            path.display()
        );
    }
    for w in &imported.warnings {
        eprintln!("foldcam: warning: {}: {w}", path.display());
    }
    Ok(imported)
}

fn load_frame(path: &Path, n: usize) -> Result<Imported> {
    if formats::Format::from_path(path) != Some(formats::Format::Fold) {
        bail!("{}: --frame applies to FOLD files only", path.display());
    }
    let text = formats::read_text(path)?;
    let imported = formats::fold::read_frame_str(&text, n)
        .map_err(|e| anyhow::anyhow!("{}: {e}", path.display()))?;
    imported
        .pattern
        .validate()
        .map_err(|e| anyhow::anyhow!("{}: {e}", path.display()))?;
    Ok(imported)
}

/// Planarises the pattern in place (tracing faces when asked) and says on stderr what
/// changed, if anything. A folded state no longer matches a changed pattern and is dropped.
pub fn clean(
    path: &Path,
    imported: &mut Imported,
    tolerance: Option<f64>,
    faces: bool,
) -> Result<PlanarizeReport> {
    let options = PlanarizeOptions { tolerance, faces };
    let report = planarize(&mut imported.pattern, &options)
        .map_err(|e| anyhow::anyhow!("{}: {e}", path.display()))?;
    if report.assignment_conflicts > 0 {
        eprintln!(
            "foldcam: warning: {}: {} mountain and valley lines lie on top of each other; the \
             first of each pair was kept",
            path.display(),
            report.assignment_conflicts
        );
    }
    if !report.unchanged() && imported.folded.take().is_some() {
        eprintln!(
            "foldcam: warning: {}: the folded state was dropped: it does not match the cleaned \
             pattern",
            path.display()
        );
    }
    if !report.unchanged() {
        eprintln!(
            "foldcam: {}: cleaned the drawing: {} vertices merged, {} crossings, {} edge splits, \
             {} zero-length and {} duplicate edges removed",
            path.display(),
            report.merged_vertices,
            report.crossings,
            report.splits,
            report.zero_length_removed,
            report.duplicates_removed
        );
    }
    Ok(report)
}

/// Writes the pattern (and folded state) and says so on stderr.
pub fn save(path: &Path, cp: &CreasePattern, folded: Option<&FoldedState>) -> Result<()> {
    formats::save(path, cp, folded)?;
    eprintln!(
        "foldcam: wrote {} ({} vertices, {} edges)",
        path.display(),
        cp.vertices.len(),
        cp.edges.len()
    );
    Ok(())
}

/// The unit label of a pattern for messages.
pub fn unit_label(units: Units) -> &'static str {
    match units {
        Units::Millimetres => "mm",
        Units::Unitless => "units",
    }
}
