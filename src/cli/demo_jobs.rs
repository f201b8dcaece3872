//! The demo's machine jobs and its `index.html`: every job planned on a shipped machine and
//! material, posted as G-code, read back by the simulated machine, written as
//! `PATTERN.MACHINE.MATERIAL.EXT` with its toolpath picture, and listed in the folder's index
//! with the pictures the demo drew.

use std::path::Path;

use anyhow::{Context, Result, anyhow};
use foldcam::fab::PlanOverrides;
use foldcam::formats::write_atomic;
use foldcam::job::{IndexJob, IndexPicture, Job, JobFormat, index_html, job_file_name};
use foldcam::machine::{load_machine, load_material};
use foldcam::pattern::CreasePattern;
use foldcam::sim;

/// Width of the toolpath pictures, pixels.
const TOOLPATH_WIDTH: u32 = 900;

/// What the demo wrote, for its index.
#[derive(Default)]
pub(super) struct DemoIndex {
    jobs: Vec<IndexJob>,
    pictures: Vec<IndexPicture>,
}

impl DemoIndex {
    /// Lists picture `file` (a name in the demo's folder) with `caption`.
    pub fn picture(&mut self, file: impl Into<String>, caption: impl Into<String>) {
        self.pictures.push(IndexPicture {
            file: file.into(),
            caption: caption.into(),
        });
    }

    /// Writes `index.html` into `dir`.
    pub fn write(&self, dir: &Path) -> Result<()> {
        let html = index_html("foldcam demo", &self.jobs, &self.pictures);
        let path = dir.join("index.html");
        write_atomic(&path, html.as_bytes()).with_context(|| path.display().to_string())
    }
}

/// A pattern's first machine job, checked and written.
pub(super) struct WrittenJob {
    /// What the simulated machine found.
    pub run: sim::SimReport,
    /// No violations, and every crease and cut covered as planned.
    pub clean: bool,
    /// Edges not covered as planned.
    pub edges_off: usize,
    /// The job's file name in the demo's folder.
    pub file: String,
}

/// Plans `cp` (named `name`) for `machine` and `material` (shipped names), posts its first job
/// as G-code, runs it on the simulated machine, writes it and its toolpath picture into `dir`
/// and lists both in `index`.
pub(super) fn write_job(
    dir: &Path,
    index: &mut DemoIndex,
    name: &str,
    cp: &CreasePattern,
    machine: &str,
    material: &str,
) -> Result<WrittenJob> {
    write_job_with(
        dir,
        index,
        name,
        cp,
        (machine, material),
        &PlanOverrides::default(),
    )
}

/// [`write_job`] with the plan's settings overridden as `foldcam cut`'s options would.
pub(super) fn write_job_with(
    dir: &Path,
    index: &mut DemoIndex,
    name: &str,
    cp: &CreasePattern,
    (machine, material): (&str, &str),
    overrides: &PlanOverrides,
) -> Result<WrittenJob> {
    let machine = load_machine(machine)?;
    let material = load_material(material)?;
    // A design's pattern has no title of its own: its job names the demo's name as source.
    let mut titled = cp.clone();
    titled.meta.title.get_or_insert_with(|| name.to_string());
    let cp = &titled;
    let job = Job::plan(cp, &machine, &material, overrides)?
        .post(JobFormat::Gcode)?
        .verify()?;
    let clean = job.is_clean();
    let file = job_file_name(name, &machine, &material, None, JobFormat::Gcode);
    let picture = Path::new(&file)
        .with_extension("toolpath.png")
        .to_string_lossy()
        .into_owned();
    let first = job.readback.first().context("no job planned")?;
    let path = dir.join(&file);
    write_atomic(&path, &job.outputs[0]).with_context(|| path.display().to_string())?;
    let names = sim::JobNames {
        file: Some(&file),
        material: Some(&material.name),
    };
    let image = sim::render_png(&first.sim, &machine, TOOLPATH_WIDTH, &names)
        .map_err(|e| anyhow!("{e}"))?;
    let png = dir.join(&picture);
    write_atomic(&png, &image).with_context(|| png.display().to_string())?;
    index
        .jobs
        .push(IndexJob::of(&job, name, &file, Some(&picture)));
    Ok(WrittenJob {
        clean,
        edges_off: first.coverage.failed_edges().count(),
        run: first.sim.clone(),
        file,
    })
}
