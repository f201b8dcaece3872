//! `foldcam papercraft DESIGN -o parts.fold`: paper-craft parts from developable patches
//! (Ōgaki 2016).

use std::path::{Path, PathBuf};

use anyhow::{Context, Result, anyhow};
use foldcam::design::papercraft::{GLUE_TOLERANCE_MM, GLUE_TOLERANCE_SHARE, Seam};
use foldcam::design::source::{DesignFile, craft, mesh_path_beside, read_design_file};
use foldcam::fab::mark_labels;
use foldcam::fab::{PlanOptions, plan};
use foldcam::formats::OutputSet;
use foldcam::machine::{MachineProfile, Material};
use foldcam::mesh::read_mesh;
use foldcam::render::{PreviewOptions, preview_png};

use super::Outcome;
use super::progress::DesignProgress;

/// Make paper-craft parts from a design file.
#[derive(clap::Args)]
#[command(
    long_about = "Builds paper-craft parts (Ōgaki 2016, developable patches with user cut lines) from a TOML design: cut lines \
                  traced on a reference mesh, and cylindrical patches given by a degree-4 \
                  B-spline directrix and a ruling direction. Sweeps boundary walls from the \
                  cut lines, trims each patch where it crosses its walls, unrolls it \
                  isometrically, adds glue tabs on one side of every shared boundary and packs \
                  the parts onto sheets. Writes one crease pattern per sheet: outlines cut, tab \
                  roots mountain folds, edge numbers flat lines. With several sheets, sheet \
                  n > 1 goes to NAME-n.EXT. With --job, --machine and --material it also \
                  plans every sheet and writes the machine job (as `cut` does, with its \
                  options), the edge numbers marked (--flat mark) by default wherever the \
                  machine can mark the material (a pen, or a laser whose mark power is above \
                  0); --flat skip leaves them out.",
    after_help = "Examples:\n  foldcam papercraft examples/papercraft/vase.craft.toml -o vase.fold --svg vase.svg --png vase.png\n  \
                  foldcam papercraft examples/papercraft/vase.craft.toml -o vase.fold --job vase.gcode \\\n      -m grbl-diode -x paper-160gsm\n  \
                  foldcam cut vase.fold --machine grbl-diode --material paper-160gsm --flat mark -o vase.gcode"
)]
pub struct Args {
    /// Design file (`.craft.toml`).
    pub design: PathBuf,
    #[command(flatten)]
    pub out: super::design_output::DesignOutput,
    /// Also write the sheets as SVG.
    #[arg(long)]
    pub svg: Option<PathBuf>,
    /// Also write PNG previews of the sheets.
    #[arg(long)]
    pub png: Option<PathBuf>,
    /// PNG width in pixels.
    #[arg(value_name = "PX", long, default_value_t = 1200)]
    pub width: u32,
    /// Write the machine job of every sheet here (.gcode/.nc/.ngc, .dxf, .svg, .lbrn2;
    /// sheet n > 1 to NAME-n.EXT) and keep -o for the crease pattern; needs --machine and
    /// --material. Without it, --machine makes -o the job.
    #[arg(long, value_name = "FILE", requires_all = ["machine", "material"])]
    pub job: Option<PathBuf>,
    /// Exit 0 even when a glued cut line is longer on one part than on the other (by more
    /// than 0.1 mm or 0.1%): the parts are written either way, and such seams are named.
    #[arg(long)]
    pub allow_mismatch: bool,
    #[command(flatten)]
    pub stdout: super::pipe::ToArg,
}

/// The plan options for the sheets' jobs: `cut`'s, with the edge numbers (flat lines) marked
/// where the machine can mark the material unless `--flat` says otherwise.
fn job_options(
    args: &Args,
    machine: &str,
    material: &str,
) -> Result<(MachineProfile, Material, PlanOptions)> {
    let (m, x, mut o) = args.out.fab.resolve(machine, material)?;
    if args.out.fab.flat.is_none() && !mark_labels(&mut o, &m, &x) {
        errln!(
            "foldcam: {} cannot mark {} (its mark power is 0): edge numbers left out",
            m.name,
            x.name
        );
    }
    Ok((m, x, o))
}

/// `path` for sheet 0, `stem-n.ext` for sheet n − 1 > 0.
fn sheet_path(path: &Path, sheet: usize) -> PathBuf {
    if sheet == 0 {
        return path.to_path_buf();
    }
    let stem = path
        .file_stem()
        .map(|s| s.to_string_lossy())
        .unwrap_or_default();
    let name = match path.extension() {
        Some(ext) => format!("{stem}-{}.{}", sheet + 1, ext.to_string_lossy()),
        None => format!("{stem}-{}", sheet + 1),
    };
    path.with_file_name(name)
}

/// Runs `papercraft`.
pub fn run(args: Args) -> Result<Outcome> {
    let path = &args.design;
    let err = |e: &dyn std::fmt::Display| anyhow!("{}: {e}", path.display());
    let output = args.out.target()?;
    let svg = super::outputs::optional(args.svg.as_ref())?;
    let png = super::outputs::optional(args.png.as_ref())?;
    let job = super::outputs::optional(args.job.as_ref())?;
    let given = [Some(&output), svg.as_ref(), png.as_ref(), job.as_ref()];
    super::outputs::check(&given, &[path])?;
    let bytes = read_design_file(path)?;
    let parsed = craft::parse(&DesignFile {
        name: path,
        bytes: &bytes,
    })?;
    // The mesh is named relative to the design's folder.
    let mesh_path = mesh_path_beside(path, &parsed.mesh_name());
    let mesh = read_mesh(&mesh_path).map_err(|e| anyhow!("{}: {e}", mesh_path.display()))?;
    let made = craft::build(parsed, &mesh_path, &mesh, &mut DesignProgress::default())?;
    // Every sheet's files are made first and written together: all of them, or none.
    let profiles = match (&args.out.machine, &args.out.material) {
        (Some(machine), Some(material)) => Some(job_options(&args, machine, material)?),
        _ => None,
    };
    if made.made.sheets.len() > 1 {
        for p in given.iter().flatten() {
            super::outputs::no_stdout(p, "a design of several sheets")?;
        }
    }
    // The jobs go to --job, or to -o when there is no --job.
    let job_path = job.as_ref().unwrap_or(&output);
    let mut outputs = OutputSet::new();
    let mut plans = Vec::new();
    for (s, cp) in made.made.sheets.iter().enumerate() {
        if let Some((m, x, o)) = &profiles {
            let sheet = sheet_path(job_path, s);
            let p = plan(cp, m, x, o).with_context(|| sheet.display().to_string())?;
            super::cut::stage_plan(&mut outputs, &sheet, &p, m, args.out.choices())?;
            plans.push(p);
        }
        if profiles.is_none() || job.is_some() {
            super::outputs::stage(&mut outputs, &sheet_path(&output, s), cp, None)?;
        }
        if let Some(svg) = &svg {
            super::outputs::stage(&mut outputs, &sheet_path(svg, s), cp, None)?;
        }
        if let Some(png) = &png {
            let options = PreviewOptions {
                width: args.width,
                dark_flat: true,
                ..PreviewOptions::default()
            };
            let bytes = preview_png(cp, &options, &[]).map_err(|e| err(&e))?;
            super::outputs::stage_image(&mut outputs, &sheet_path(png, s), bytes, "png")?;
        }
    }
    super::outputs::commit(outputs, &[&args.design])?;
    for p in &plans {
        out!("{}", super::plan::summary(p));
    }
    for line in &made.late_notes {
        errln!("foldcam: {line}");
    }
    for line in &made.summary {
        outln!("{line}");
    }
    glue_verdict(&made.made.seams, args.allow_mismatch)
}

/// Names every glued cut line whose two sides differ in length beyond the tolerance; exit 1
/// for them unless `allow` (`--allow-mismatch`).
fn glue_verdict(seams: &[Seam], allow: bool) -> Result<Outcome> {
    let bad: Vec<&Seam> = seams.iter().filter(|s| !s.glues()).collect();
    let worst = seams.iter().map(Seam::mismatch_mm).fold(0.0, f64::max);
    if bad.is_empty() {
        outln!(
            "{} glued cut line(s) match on both parts (largest difference {worst:.3} mm, \
             tolerance {GLUE_TOLERANCE_MM} mm or {}%)",
            seams.len(),
            100.0 * GLUE_TOLERANCE_SHARE
        );
        return Ok(Outcome::Done);
    }
    let severity = if allow { "warning" } else { "error" };
    for s in &bad {
        errln!("foldcam: {severity}: {s}: the glued edges do not match");
    }
    errln!(
        "foldcam: {} of {} glued cut line(s) differ by more than {GLUE_TOLERANCE_MM} mm or {}%: \
         a patch there does not follow the mesh (move its directrix or ruling, or draw the cut \
         lines where the surface is closer to a cylinder); the parts were written{}",
        bad.len(),
        seams.len(),
        100.0 * GLUE_TOLERANCE_SHARE,
        if allow {
            ""
        } else {
            " (--allow-mismatch exits 0)"
        }
    );
    Ok(if allow {
        Outcome::Done
    } else {
        Outcome::CheckFailed
    })
}
