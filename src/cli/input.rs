//! Loading an input pattern for a subcommand: read, report warnings, planarise.

use std::path::Path;

use anyhow::{Result, bail};
use foldcam::formats::{self, Finding, Imported};
use foldcam::pattern::{PlanarizeOptions, PlanarizeReport, Units};

/// The help of a pattern input, `what` followed by every extension the readers take
/// ([`formats::Format::EXTENSIONS`]).
pub fn pattern_help(what: &str) -> String {
    format!("{what} ({})", formats::Format::EXTENSIONS)
}

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
    /// Format of an input given as `-` (standard input): fold, svg, cp, opx or dxf.
    #[arg(long, value_name = "FORMAT")]
    pub from: Option<String>,
}

impl FrameArg {
    /// The reading options these arguments give.
    pub fn read_options(&self) -> formats::ReadOptions {
        formats::ReadOptions {
            frame: self.fold_frame.unwrap_or(0),
            snap: self.snap,
            dashed: self.dashed,
        }
    }
}

/// Reads `path` (frame `frame.fold_frame` for FOLD files), prints the reader's warnings to stderr,
/// and returns the import.
pub fn load(path: &Path, frame: &FrameArg) -> Result<Imported> {
    let options = frame.read_options();
    let imported = if super::pipe::is_stdio(path) {
        super::pipe::load_stdin(frame.from.as_deref(), &options)?
    } else {
        formats::load_with(path, &options)?
    };
    imported.require_edges(path)?;
    refuse_degenerate(path, &imported.pattern)?;
    print_findings(path, imported.warnings());
    note!(
        "foldcam: {}: {}",
        path.display(),
        size_read(&imported.pattern)
    );
    print_findings(path, imported.notes());
    Ok(imported)
}

/// Prints findings about `path`: warnings on stderr, notes there too unless `--quiet`.
fn print_findings<'a>(path: &Path, findings: impl IntoIterator<Item = &'a Finding>) {
    let name = path.display().to_string();
    for f in findings {
        if f.is_warning() {
            errln!("foldcam: {}", f.line(&name));
        } else {
            note!("foldcam: {}", f.line(&name));
        }
    }
}

/// The size a pattern was read at and where it lies, in the frame every position printed
/// later uses: "read 343.0 × 343.0 mm, 120 lines; x 0.0 to 343.0, y -343.0 to 0.0 (y up: an
/// SVG's page, whose y runs down, lies below y = 0)" (the bounding box, as the file's units
/// and the reader's scale made it; a unitless pattern says how to size it).
pub fn size_read(cp: &foldcam::pattern::CreasePattern) -> String {
    let (lo, hi) = cp.bounds().unwrap_or_default();
    let (w, h) = ((hi - lo).x, (hi - lo).y);
    let unit = match cp.units {
        Units::Millimetres => "mm",
        Units::Unitless => "units (no physical size: --size MM gives one)",
    };
    let below = if hi.y <= 0.0 && lo.y < 0.0 {
        " (y up: an SVG's page, whose y runs down, lies below y = 0)"
    } else {
        " (y up)"
    };
    format!(
        "read {w:.1} × {h:.1} {unit}, {} lines; x {:.1} to {:.1}, y {:.1} to {:.1}{below}",
        cp.edges.len(),
        lo.x,
        hi.x,
        lo.y,
        hi.y
    )
}

/// Cleans the pattern in place ([`Imported::clean`]: faces traced when asked, a folded state
/// that no longer matches dropped) and says on stderr what changed, if anything.
pub fn clean(
    path: &Path,
    imported: &mut Imported,
    tolerance: Option<f64>,
    faces: bool,
) -> Result<PlanarizeReport> {
    let before = imported.findings.len();
    let report = imported
        .clean(&PlanarizeOptions { tolerance, faces })
        .map_err(|e| anyhow::anyhow!("{}: {e}", path.display()))?;
    print_findings(path, &imported.findings[before..]);
    refuse_degenerate(path, &imported.pattern)?;
    Ok(report)
}

/// Refuses a pattern without a sheet (see [`foldcam::pattern::Degenerate`]): nothing to
/// check, fold, cut or convert.
fn refuse_degenerate(path: &Path, cp: &foldcam::pattern::CreasePattern) -> Result<()> {
    match cp.degeneracy() {
        Some(why) => bail!(
            "{}: {why}: nothing to check, fold, cut or convert",
            path.display()
        ),
        None => Ok(()),
    }
}
