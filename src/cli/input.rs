//! Loading an input pattern for a subcommand: read, report warnings, planarise.

use std::path::Path;

use anyhow::{Result, bail};
use foldcam::formats::{self, Imported};
use foldcam::pattern::{
    CreasePattern, FoldedState, PlanarizeOptions, PlanarizeReport, Units, planarize,
};

/// Choosing a frame of a FOLD file, and how drawings (SVG, DXF) are read.
#[derive(clap::Args, Clone, Debug, Default)]
pub struct FrameArg {
    /// Read frame N of a FOLD file (0 is the key frame; later frames come from file_frames,
    /// with frame_inherit resolved). Not `cut --frame`, which traces a job's outline.
    #[arg(long = "fold-frame", value_name = "N")]
    pub fold_frame: Option<usize>,
    /// SVG and DXF input: join line ends that stop within this distance (mm) of a line or
    /// corner; default 1/1000 of the drawing's diagonal, 0 turns it off.
    #[arg(long, value_name = "MM", value_parser = |s: &str| foldcam::limits::SNAP.parse(s))]
    pub snap: Option<f64>,
    /// SVG input: what dashed lines mean in a drawing of one colour (auto: dashes valley,
    /// dash-dot mountain; or valley, mountain, cut, flat, unassigned, boundary).
    #[arg(long, value_name = "MEANING", default_value = "auto")]
    pub dashed: formats::DashedAs,
}

impl FrameArg {
    /// The reading options these arguments give.
    pub fn read_options(&self) -> formats::ReadOptions {
        formats::ReadOptions {
            snap: self.snap,
            dashed: self.dashed,
        }
    }
}

/// Reads `path` (frame `frame.fold_frame` for FOLD files), prints the reader's warnings to stderr,
/// and returns the import.
pub fn load(path: &Path, frame: &FrameArg) -> Result<Imported> {
    let imported = match frame.fold_frame {
        _ if super::pipe::is_stdio(path) => {
            super::pipe::load_stdin(frame.fold_frame, &frame.read_options())?
        }
        None | Some(0) => formats::load_with(path, &frame.read_options())?,
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
    for n in &imported.notes {
        note!("foldcam: {}: {n}", path.display());
    }
    Ok(imported)
}

fn load_frame(path: &Path, n: usize) -> Result<Imported> {
    if formats::Format::from_path(path) != Some(formats::Format::Fold) {
        bail!(
            "{}: --fold-frame applies to FOLD files only",
            path.display()
        );
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
        note!(
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
    note!(
        "foldcam: wrote {} ({} vertices, {} edges)",
        path.display(),
        cp.vertices.len(),
        cp.edges.len()
    );
    Ok(())
}

/// Adds a pattern file (format from its extension) to `outputs`, written by [`commit`].
pub fn stage(
    outputs: &mut formats::OutputSet,
    path: &Path,
    cp: &CreasePattern,
    folded: Option<&FoldedState>,
) -> Result<()> {
    outputs.add(path, formats::encode(path, cp, folded)?);
    Ok(())
}

/// Adds an image to `outputs`, refusing a file name whose extension is not `ext` (so PNG data
/// never lands in `x.jpg`).
pub fn stage_image(
    outputs: &mut formats::OutputSet,
    path: &Path,
    bytes: Vec<u8>,
    ext: &str,
) -> Result<()> {
    let matches = path
        .extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| e.eq_ignore_ascii_case(ext));
    if !matches {
        anyhow::bail!(
            "{}: this output is a {} image: name it with the .{ext} extension",
            path.display(),
            ext.to_ascii_uppercase()
        );
    }
    outputs.add(path, bytes);
    Ok(())
}

/// Writes every staged output, or none of them when one fails; refuses an output that is one
/// of `inputs` (it would be overwritten before it is read again). Names each file written.
pub fn commit(outputs: formats::OutputSet, inputs: &[&Path]) -> Result<()> {
    let same = |a: &Path, b: &Path| match (a.canonicalize(), b.canonicalize()) {
        (Ok(a), Ok(b)) => a == b,
        _ => false,
    };
    for out in outputs.paths() {
        if let Some(input) = inputs.iter().find(|i| same(out, i)) {
            anyhow::bail!(
                "{}: the output would overwrite the input {}: choose another name",
                out.display(),
                input.display()
            );
        }
    }
    let mut outputs = outputs;
    let stdout = outputs
        .paths()
        .find(|p| super::pipe::is_stdout(p))
        .map(Path::to_path_buf);
    let piped = stdout.and_then(|p| outputs.take(&p));
    let written: Vec<std::path::PathBuf> = outputs.paths().map(Path::to_path_buf).collect();
    outputs.commit()?;
    for path in written {
        note!("foldcam: wrote {}", path.display());
    }
    if let Some(bytes) = piped {
        super::pipe::write_stdout(&bytes)?;
    }
    Ok(())
}

/// The unit label of a pattern for messages.
pub fn unit_label(units: Units) -> &'static str {
    match units {
        Units::Millimetres => "mm",
        Units::Unitless => "units",
    }
}
