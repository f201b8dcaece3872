//! The output options every design command shares: `-o` a crease pattern (.fold, .svg, .cp),
//! or, with `-m` and `-x`, a machine job chosen by the extension (.gcode, .dxf, .svg, .lbrn2),
//! planned, read back and written with the design's other files, all or none.

use std::path::{Path, PathBuf};

use anyhow::{Context, Result, bail};
use clap::Args;
use foldcam::formats::OutputSet;
use foldcam::job::Job;
use foldcam::pattern::{CreasePattern, FoldedState};

use super::fab_args::FabArgs;

/// `-o`, and the machine job options.
#[derive(Args, Clone, Debug)]
pub struct DesignOutput {
    #[arg(short, long, help = format!(
        "Crease pattern to write ({}, millimetres); with --machine and --material, the \
         machine job ({})",
        foldcam::formats::Format::WRITABLE,
        foldcam::job::JOB_EXTENSIONS
    ))]
    pub output: PathBuf,
    /// Cut or plot the design directly: machine profile (a shipped name or a TOML path);
    /// needs --material.
    #[arg(long, short = 'm', requires = "material", help_heading = "Cutting")]
    pub machine: Option<String>,
    /// Material profile (a shipped name or a TOML path).
    #[arg(long, short = 'x', help_heading = "Cutting")]
    pub material: Option<String>,
    #[command(flatten, next_help_heading = "Cutting")]
    pub fab: FabArgs,
    /// With --machine and .dxf output: DXF R12 instead of R2000.
    #[arg(long, help_heading = "Cutting")]
    pub r12: bool,
    /// With --machine and .svg output: each perforated crease as one path with a dash style
    /// (for viewing) instead of one path per dash.
    #[arg(long, help_heading = "Cutting")]
    pub dasharray: bool,
    /// With --machine and .lbrn2 output: LightBurn's perforation mode, one layer per
    /// distinct dash and gap, instead of one shape per dash.
    #[arg(long, help_heading = "Cutting")]
    pub lightburn_perforation: bool,
}

impl DesignOutput {
    /// The writer choices asked for.
    pub fn choices(&self) -> foldcam::job::WriterChoices {
        foldcam::job::WriterChoices {
            r12: self.r12,
            dasharray: self.dasharray,
            lightburn_perforation: self.lightburn_perforation,
        }
    }

    /// `-o` as a target ([`super::outputs::target`]: `-` is standard output).
    pub fn target(&self) -> Result<PathBuf> {
        super::outputs::target(&self.output)
    }

    /// Stages `cp` as a pattern file at `path` (`-`: standard output), or as a machine job
    /// when --machine is given.
    pub fn stage_at(
        &self,
        outputs: &mut OutputSet,
        path: &Path,
        cp: &CreasePattern,
        folded: Option<&FoldedState>,
    ) -> Result<()> {
        let path = &super::outputs::target(path)?;
        let Some(machine) = &self.machine else {
            return super::outputs::stage(outputs, path, cp, folded);
        };
        let Some(material) = &self.material else {
            bail!("--machine needs --material");
        };
        let (machine, material, options) = self.fab.resolve(machine, material)?;
        let job = Job::plan_with(cp, &machine, &material, options)
            .with_context(|| path.display().to_string())?;
        super::cut::stage_job(outputs, path, &job, self.choices())?;
        out!("{}", super::plan::summary(&job.plan));
        Ok(())
    }

    /// Stages `cp` at `-o`.
    pub fn stage(
        &self,
        outputs: &mut OutputSet,
        cp: &CreasePattern,
        folded: Option<&FoldedState>,
    ) -> Result<()> {
        self.stage_at(outputs, &self.output, cp, folded)
    }
}

/// A design build's result as the command's: a design its own check refused prints the
/// report on standard output (`Ok(Err(Outcome::CheckFailed))`, exit 1); bad input is an error
/// (exit 2).
pub fn built<T>(
    result: std::result::Result<T, foldcam::design::source::SourceError>,
) -> Result<std::result::Result<T, super::Outcome>> {
    match result {
        Ok(t) => Ok(Ok(t)),
        Err(foldcam::design::source::SourceError::NotMade { lines }) => {
            for line in lines {
                outln!("{line}");
            }
            Ok(Err(super::Outcome::CheckFailed))
        }
        Err(e) => Err(e.into()),
    }
}
