//! From a crease pattern to checked machine files in one place: plan, post-process, read back.
//!
//! [`Job::plan`] resolves the plan options for the machine and material
//! ([`PlanOptions::for_machine`]) and plans the pattern; [`Job::post`] renders every job of the
//! plan (one, or front and back) in a [`JobFormat`]; [`Job::verify`] runs each job's G-code on
//! the simulated machine and checks coverage against the pattern (every crease and cut
//! realised as planned, nothing burned elsewhere). The [`Job`] holds all three results.
//!
//! ```
//! use foldcam::job::{Job, JobFormat};
//! use foldcam::fab::PlanOverrides;
//! use foldcam::machine::{load_machine, load_material};
//!
//! let cp = foldcam::design::classic::MiuraOri::default().build()?;
//! let machine = load_machine("grbl-diode")?;
//! let card = load_material("card-300gsm")?;
//! let job = Job::plan(&cp, &machine, &card, &PlanOverrides::default())?
//!     .post(JobFormat::Gcode)?
//!     .verify()?;
//! assert!(job.is_clean());
//! assert_eq!(job.outputs.len(), job.plan.jobs.len());
//! let gcode = std::str::from_utf8(&job.outputs[0])?;
//! assert!(gcode.lines().any(|l| l.starts_with("G1")));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

mod format;
mod index;

use std::path::{Path, PathBuf};

pub use format::{JOB_EXTENSIONS, JobFormat, job_file_name, job_paths};
pub use index::{IndexJob, IndexPicture, index_html};

use crate::fab::{FabError, FabPlan, PlanOptions, PlanOverrides};
use crate::formats::OutputSet;
use crate::machine::{MachineProfile, Material};
use crate::pattern::CreasePattern;
use crate::post::{self, DxfVersion, PostError};
use crate::sim::{self, CoverageReport, SimError, SimReport};

/// Why a job could not be planned, rendered or read back.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum JobError {
    /// Planning failed (unitless pattern, does not fit, unsupported operation, …).
    #[error(transparent)]
    Plan(#[from] FabError),
    /// A writer refused the plan.
    #[error(transparent)]
    Post(#[from] PostError),
    /// The simulated machine could not read the program.
    #[error(transparent)]
    Sim(#[from] SimError),
    /// The simulated machine found problems in the program.
    #[error(
        "the simulated {machine} found {count} problem(s) in the job, first at line {line}: \
         {message}"
    )]
    Violations {
        /// The machine profile's name.
        machine: String,
        /// How many problems.
        count: usize,
        /// Line of the first problem.
        line: usize,
        /// The first problem.
        message: String,
    },
    /// [`Job::stage`] before [`Job::post`].
    #[error("the job has not been rendered to a file format yet")]
    NotPosted,
}

/// The simulated machine's reading of one job of the plan.
#[derive(Clone, Debug)]
pub struct Readback {
    /// What the machine did: violations, burns, lengths, time.
    pub sim: SimReport,
    /// Every planned crease and cut against what was burned.
    pub coverage: CoverageReport,
}

impl Readback {
    /// No violation, and every edge realised as planned with no stray burn.
    pub fn is_clean(&self) -> bool {
        self.sim.is_clean() && self.coverage.passed()
    }
}

/// A pattern planned for a machine and material, its files and their read-back.
#[derive(Clone, Debug)]
pub struct Job<'a> {
    /// The pattern planned (millimetres).
    pub pattern: &'a CreasePattern,
    /// The machine it is planned for.
    pub machine: &'a MachineProfile,
    /// The options the plan was made with.
    pub options: PlanOptions,
    /// The plan: one job, or front and back.
    pub plan: FabPlan,
    /// The format of `outputs`, once [`Job::post`] ran.
    pub format: Option<JobFormat>,
    /// One file's bytes per job of the plan, in order (empty before [`Job::post`]).
    pub outputs: Vec<Vec<u8>>,
    /// One read-back per job of the plan (empty before [`Job::verify`]).
    pub readback: Vec<Readback>,
}

impl<'a> Job<'a> {
    /// Plans `pattern` (millimetres) on `machine` in `material` with `overrides` on top of
    /// the material's defaults.
    pub fn plan(
        pattern: &'a CreasePattern,
        machine: &'a MachineProfile,
        material: &Material,
        overrides: &PlanOverrides,
    ) -> Result<Job<'a>, JobError> {
        let options = PlanOptions::for_machine(machine, material, overrides)?;
        Job::plan_with(pattern, machine, material, options)
    }

    /// Plans with options already resolved.
    pub fn plan_with(
        pattern: &'a CreasePattern,
        machine: &'a MachineProfile,
        material: &Material,
        options: PlanOptions,
    ) -> Result<Job<'a>, JobError> {
        let plan = crate::fab::plan(pattern, machine, material, &options)?;
        Ok(Job {
            pattern,
            machine,
            options,
            plan,
            format: None,
            outputs: Vec::new(),
            readback: Vec::new(),
        })
    }

    /// Renders every job of the plan in `format` ([`job_files`]: G-code read back by the
    /// simulated machine first); nothing is kept unless all render.
    ///
    /// # Errors
    /// The writer's refusal, or for G-code the simulated machine's.
    pub fn post(mut self, format: JobFormat) -> Result<Job<'a>, JobError> {
        self.outputs = job_files(format, &self.plan, self.machine)?;
        self.format = Some(format);
        Ok(self)
    }

    /// Runs every job on the simulated machine and checks coverage: the G-code of
    /// [`Job::post`] when that was G-code, otherwise G-code rendered for the purpose (the
    /// same plan the other formats draw). Fails only when the machine takes no G-code or a
    /// program cannot be read; problems found are in [`Job::readback`] (see
    /// [`Job::is_clean`]).
    pub fn verify(mut self) -> Result<Job<'a>, JobError> {
        let mut readback = Vec::with_capacity(self.plan.jobs.len());
        for (i, job) in self.plan.jobs.iter().enumerate() {
            let text = match (self.format, self.outputs.get(i)) {
                (Some(JobFormat::Gcode), Some(bytes)) => {
                    String::from_utf8_lossy(bytes).into_owned()
                }
                _ => post::gcode(&self.plan, job, self.machine)?,
            };
            let sim = sim::run(&text, self.machine)?;
            let coverage = sim::coverage(&sim, self.pattern, job, &self.plan);
            readback.push(Readback { sim, coverage });
        }
        self.readback = readback;
        Ok(self)
    }

    /// Verified, and every job read back clean (no violation, full coverage, no stray burn).
    pub fn is_clean(&self) -> bool {
        !self.readback.is_empty() && self.readback.iter().all(Readback::is_clean)
    }

    /// The file paths for `output`: itself for one job, `NAME.JOB.EXT` for several.
    pub fn paths(&self, output: &Path) -> Vec<PathBuf> {
        job_paths(output, &self.plan)
    }

    /// Adds the rendered files to `outputs` (written together, atomically, by
    /// [`OutputSet::commit`]); returns their paths.
    pub fn stage(&self, output: &Path, outputs: &mut OutputSet) -> Result<Vec<PathBuf>, JobError> {
        if self.format.is_none() {
            return Err(JobError::NotPosted);
        }
        let paths = self.paths(output);
        for (path, bytes) in paths.iter().zip(&self.outputs) {
            outputs.add(path, bytes.clone());
        }
        Ok(paths)
    }
}

/// One job of `plan` as a file in `format` for `machine`: the bytes `foldcam cut` writes and
/// the studio serves. G-code is first read back by the simulated machine ([`check_gcode`]),
/// so no caller is handed a program the machine would reject.
///
/// # Errors
/// The writer's refusal, or for G-code the simulated machine's ([`JobError::Sim`],
/// [`JobError::Violations`]).
pub fn job_file(
    format: JobFormat,
    plan: &FabPlan,
    job: &crate::fab::Setup,
    machine: &MachineProfile,
) -> Result<Vec<u8>, JobError> {
    let bytes = render(format, plan, job, machine)?;
    if format == JobFormat::Gcode {
        check_gcode(&String::from_utf8_lossy(&bytes), machine)?;
    }
    Ok(bytes)
}

/// Every job of `plan` as a file in `format` ([`job_file`]), in the plan's order (the files
/// [`job_paths`] names); nothing unless every one renders and reads back.
///
/// # Errors
/// The first job's refusal, as [`job_file`].
pub fn job_files(
    format: JobFormat,
    plan: &FabPlan,
    machine: &MachineProfile,
) -> Result<Vec<Vec<u8>>, JobError> {
    plan.jobs
        .iter()
        .map(|job| job_file(format, plan, job, machine))
        .collect()
}

/// Runs G-code `text` on the simulated `machine` and returns its report.
///
/// # Errors
/// [`JobError::Sim`] if the machine cannot read it, [`JobError::Violations`] naming the first
/// violation if it breaks the machine's limits.
pub fn check_gcode(text: &str, machine: &MachineProfile) -> Result<SimReport, JobError> {
    let report = sim::run(text, machine)?;
    match report.violations.first() {
        Some(v) => Err(JobError::Violations {
            machine: machine.name.clone(),
            count: report.violation_count,
            line: v.line,
            message: v.message.clone(),
        }),
        None => Ok(report),
    }
}

/// One job of `plan` in `format`, unchecked.
fn render(
    format: JobFormat,
    plan: &FabPlan,
    job: &crate::fab::Setup,
    machine: &MachineProfile,
) -> Result<Vec<u8>, PostError> {
    Ok(match format {
        JobFormat::Gcode => post::gcode(plan, job, machine)?.into_bytes(),
        JobFormat::Dxf(version) => post::dxf(plan, job, version)?,
        JobFormat::Svg { dasharray } => post::svg(plan, job, &machine.bed, dasharray)?.into_bytes(),
        JobFormat::Lbrn2 { perforation } => {
            post::lbrn2(plan, job, machine, perforation)?.into_bytes()
        }
    })
}

/// The writer choices a command line can make: DXF R12 instead of R2000, SVG perforations as
/// dashed strokes, LightBurn's perforation mode in a LightBurn project.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct WriterChoices {
    /// DXF R12 (`LINE`/`POLYLINE`) instead of R2000.
    pub r12: bool,
    /// SVG perforations as one path per crease with a `stroke-dasharray`.
    pub dasharray: bool,
    /// LightBurn projects use LightBurn's perforation mode (one layer per dash/gap pair)
    /// instead of dash shapes.
    pub lightburn_perforation: bool,
}

impl JobFormat {
    /// This format with the `choices` that apply to it (the others are ignored).
    pub fn with_choices(self, choices: WriterChoices) -> JobFormat {
        match self {
            JobFormat::Dxf(_) if choices.r12 => JobFormat::Dxf(DxfVersion::R12),
            JobFormat::Svg { .. } => JobFormat::Svg {
                dasharray: choices.dasharray,
            },
            JobFormat::Lbrn2 { .. } => JobFormat::Lbrn2 {
                perforation: if choices.lightburn_perforation {
                    post::LbrnPerforation::LightBurn
                } else {
                    post::LbrnPerforation::Dashes
                },
            },
            other => other,
        }
    }
}
