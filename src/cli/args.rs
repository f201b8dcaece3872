//! Argument groups shared by several subcommands, validated where they enter.

use anyhow::Result;
use clap::Args;

use foldcam::check::CheckOptions;
use foldcam::pattern::{CreasePattern, FoldedState, Scale};

/// Parses a finite number greater than zero.
pub fn positive(s: &str) -> Result<f64, String> {
    let v: f64 = s.parse().map_err(|_| format!("{s:?} is not a number"))?;
    if v.is_finite() && v > 0.0 {
        Ok(v)
    } else {
        Err(format!("{s} must be a finite number greater than 0"))
    }
}

/// Parses an angle in degrees within [0, 180].
pub fn degrees(s: &str) -> Result<f64, String> {
    let v: f64 = s.parse().map_err(|_| format!("{s:?} is not a number"))?;
    if v.is_finite() && (0.0..=180.0).contains(&v) {
        Ok(v)
    } else {
        Err(format!("{s} must be an angle between 0 and 180 degrees"))
    }
}

/// Giving a unitless pattern a physical size.
#[derive(Args, Clone, Debug, Default)]
pub struct ScaleArgs {
    /// Millimetres per pattern unit (for unitless inputs such as ORIPA files or FOLD files with
    /// frame_unit "unit"); also rescales patterns already in millimetres.
    #[arg(long, value_parser = positive, conflicts_with = "size")]
    pub scale: Option<f64>,
    /// Scale so the longer side of the pattern's bounding box is this many millimetres.
    #[arg(value_name = "MM", long, value_parser = positive)]
    pub size: Option<f64>,
}

impl ScaleArgs {
    /// Applies the scale, if one was given, to the pattern and its folded state; refuses a
    /// scale that pushes coordinates past the 1e9 mm limit. Other FOLD frames kept from the
    /// input would keep their old numbers, so they are dropped (with a warning).
    pub fn apply(&self, cp: &mut CreasePattern, folded: Option<&mut FoldedState>) -> Result<()> {
        let scale = match (self.scale, self.size) {
            (Some(f), _) => Scale::Factor(f),
            (None, Some(size)) => Scale::Size(size),
            (None, None) => return Ok(()),
        };
        let scaled = cp.scale_to(scale)?;
        for p in folded.into_iter().flat_map(|f| f.positions.iter_mut()) {
            *p *= scaled.factor;
        }
        if scaled.dropped_frames {
            errln!(
                "foldcam: warning: other frames (file_frames) were dropped: they are not rescaled"
            );
        }
        Ok(())
    }
}

/// Limits for `check` and `preview --check`.
#[derive(Args, Clone, Debug)]
pub struct CheckArgs {
    /// Smallest allowed angle between neighbouring creases at a vertex, degrees (Tachi 2014
    /// calls it δ_corner; 30 for 0.5 mm stainless is a common choice).
    #[arg(long, value_name = "DEG", value_parser = degrees)]
    pub min_vertex_angle: Option<f64>,
    /// Largest allowed |fold angle|, degrees: 180 minus the opening a fold must keep (Tachi
    /// 2014's δ_fold).
    #[arg(long, value_name = "DEG", value_parser = degrees)]
    pub max_fold_angle: Option<f64>,
    /// Shortest allowed edge, in the pattern's unit (mm unless unitless).
    #[arg(long, value_name = "LEN", value_parser = positive)]
    pub min_edge: Option<f64>,
    /// Tolerance of Kawasaki's alternating angle sum, degrees [default: 0.01; with --layers,
    /// fitted to the drawing: an error is the drawing's rounding when closing the vertex moves
    /// the end of its shortest crease by at most 1/300 of the pattern's shortest edge, and is
    /// listed as a warning beside the state count].
    #[arg(long, value_name = "DEG", value_parser = |s: &str| foldcam::limits::KAWASAKI_TOLERANCE.parse(s))]
    pub kawasaki_tolerance: Option<f64>,
    /// Skip Kawasaki and Maekawa (for patterns not meant to fold flat).
    #[arg(long)]
    pub no_flat_foldability: bool,
    /// Also look for a global layer order (after the local checks pass): count the valid
    /// ways to stack the folded layers, or show where none exists (Flat-Folder's method:
    /// Akitaya, Demaine & Ku 2023).
    #[arg(long, conflicts_with = "no_flat_foldability")]
    pub layers: bool,
    /// With --layers: stop counting each independent component at N states (the count is
    /// then a lower bound, reported as not exact).
    #[arg(
        long,
        value_name = "N",
        requires = "layers",
        default_value_t = foldcam::check::layers::DEFAULT_MAX_STATES
    )]
    pub max_states: u64,
    /// With --layers: stop the layer-order search after this many seconds (exit 2, naming
    /// the limit) instead of running as long as it takes.
    #[arg(long, value_name = "SECONDS", requires = "layers", value_parser = time_limit)]
    pub time_limit: Option<f64>,
}

/// Parses a time limit in seconds: a number greater than 0, at most a day.
pub fn time_limit(s: &str) -> Result<f64, String> {
    positive(s).and_then(|v| {
        if v <= 86_400.0 {
            Ok(v)
        } else {
            Err(format!("{s} must be at most 86400 seconds (a day)"))
        }
    })
}

impl CheckArgs {
    /// The layer solver's options these arguments describe.
    pub fn layer_options(&self) -> foldcam::check::layers::LayerOptions {
        foldcam::check::layers::LayerOptions {
            max_states: Some(self.max_states.max(1)),
            kawasaki: foldcam::check::layers::KawasakiTolerance::from_degrees(
                self.kawasaki_tolerance,
            ),
            time_limit: self.time_limit.map(std::time::Duration::from_secs_f64),
            ..Default::default()
        }
    }

    /// The library options these arguments describe.
    pub fn options(&self) -> CheckOptions {
        CheckOptions {
            flat_foldability: !self.no_flat_foldability,
            kawasaki_tolerance_deg: self
                .kawasaki_tolerance
                .unwrap_or(CheckOptions::default().kawasaki_tolerance_deg),
            min_vertex_angle_deg: self.min_vertex_angle,
            max_fold_angle_deg: self.max_fold_angle,
            min_edge_length: self.min_edge,
        }
    }
}
