//! The demo's tessellation stage: the bundled dome (Tachi 2014) with truncated stars and the
//! bundled face mask with star tucks, both at the 0.5 mm stainless limits, unfolded, drawn,
//! and perforated on the fiber laser through the simulated machine.

use std::path::Path;

use anyhow::{Context, Result, anyhow, bail};
use foldcam::design::tessellation::measure::surface_fit;
use foldcam::design::tessellation::steps::SHRINK_LADDER;
use foldcam::design::tessellation::{
    Remesh, Schedule, TessellateOptions, Tessellation, TuckKind, tessellate,
};
use foldcam::fab::PlanOverrides;
use foldcam::formats::{self, write_atomic};
use foldcam::machine::load_material;
use foldcam::mesh::PolyMesh;
use foldcam::render::{View3d, render_folded_png};

use super::demo_jobs::{DemoIndex, write_job_with};

/// The face shrink the default ladder reaches on the mask (0.8 and 0.7 leave limits unmet):
/// starting there saves the demo two failing solves (about 5 s of a release build).
const MASK_FIRST_SHRINK: f64 = 0.6;

/// The stainless limits of the demo's tessellations.
fn stainless() -> Result<TessellateOptions> {
    let material = load_material("stainless-0.5")?;
    Ok(TessellateOptions::with_limits(
        material.limits.tessellation_limits(),
    ))
}

/// Tessellates the bundled dome, writes `tessellation-dome.fold` (pattern and folded form),
/// its preview and the fiber-laser job into `dir`.
pub fn dome(dir: &Path, index: &mut DemoIndex, width: u32) -> Result<()> {
    let obj = include_bytes!("../../examples/tessellation/dome.obj");
    let mesh = foldcam::mesh::parse_obj(obj).map_err(|e| anyhow!("dome.obj: {e}"))?;
    let mut opts = stainless()?;
    opts.star.tuck.kind = TuckKind::Truncated;
    let t = tessellate(&mesh, &opts, &mut ()).map_err(|e| anyhow!("dome.obj: {e}"))?;
    let view = View3d {
        azimuth_deg: 30.0,
        elevation_deg: 35.0,
        ..View3d::with_width(width.min(800))
    };
    cut(
        dir,
        index,
        "tessellation-dome",
        (&mesh, &t),
        &view,
        "truncated star",
        None,
    )
}

/// The vertex clearance the mask is perforated with, mm: some creases between its tucks are
/// 3.4 mm long, and a 0.5 mm dash does not fit between the stainless profile's 1.5 mm
/// clearances (the planner would leave them uncut, and the simulated machine would find them
/// not perforated).
const MASK_CLEARANCE_MM: f64 = 0.8;

/// Tessellates the bundled face mask as `foldcam tessellate` does by default (star tucks, the
/// face-shrink ladder, a re-triangulation when the input's own triangles fail) but starting
/// the ladder at [`MASK_FIRST_SHRINK`], writes
/// `tessellation-mask.fold`, its preview (seen from in front, slightly below) and the
/// fiber-laser job into `dir`.
pub fn mask(dir: &Path, index: &mut DemoIndex, width: u32) -> Result<()> {
    let obj = include_bytes!("../../examples/tessellation/mask.obj");
    let mesh = foldcam::mesh::parse_obj(obj).map_err(|e| anyhow!("mask.obj: {e}"))?;
    let mut opts = stainless()?;
    opts.schedule = Schedule::Ladder {
        shrinks: SHRINK_LADDER
            .into_iter()
            .filter(|&s| s <= MASK_FIRST_SHRINK)
            .collect(),
        remesh: Remesh::Auto,
        remesh_faces: None,
    };
    let t = tessellate(&mesh, &opts, &mut ()).map_err(|e| anyhow!("mask.obj: {e}"))?;
    let view = View3d {
        azimuth_deg: 20.0,
        elevation_deg: 60.0,
        ..View3d::with_width(width.min(800))
    };
    cut(
        dir,
        index,
        "tessellation-mask",
        (&mesh, &t),
        &view,
        "star",
        Some(MASK_CLEARANCE_MM),
    )
}

/// Writes `NAME.fold`, `NAME.png` (the folded form seen through `view`) and the checked
/// `NAME.linuxcnc-fiber.ngc` of the tessellation `t` of `mesh` (with `tucks`; perforated with
/// `clearance` mm around the vertices when given, else the material's) into `dir`, and prints
/// one line about them; fails when `t` is unusable or the simulated machine finds a problem.
fn cut(
    dir: &Path,
    index: &mut DemoIndex,
    name: &str,
    (mesh, t): (&PolyMesh, &Tessellation),
    view: &View3d,
    tucks: &str,
    clearance: Option<f64>,
) -> Result<()> {
    if let Some(problem) = t.problem() {
        bail!("{name}: {problem}");
    }
    let u = t.unfolded.as_ref().map_err(|e| anyhow!("{name}: {e}"))?;
    formats::save(
        &dir.join(format!("{name}.fold")),
        &u.pattern,
        Some(&u.folded),
    )?;
    let view = view.clone().with_key(
        &format!("the folded form with {tucks} tucks"),
        u.pattern.units.label(),
    );
    let png = render_folded_png(&u.folded, &view)?;
    write_atomic(&dir.join(format!("{name}.png")), &png).context("png")?;
    index.picture(format!("{name}.png"), format!("{name}: the folded form"));
    let overrides = PlanOverrides {
        vertex_clearance_mm: clearance,
        ..PlanOverrides::default()
    };
    let job = write_job_with(
        dir,
        index,
        name,
        &u.pattern,
        ("linuxcnc-fiber", "stainless-0.5"),
        &overrides,
    )?;
    let clean = job.clean;
    let r = &t.report.last;
    // The fit `foldcam tessellate` reports, and whether it would call the form partial.
    let distance = surface_fit(mesh, &t.mesh).map_or(String::new(), |f| {
        let partial = f.partial().map_or(String::new(), |why| {
            format!(" (partial: {why}; `foldcam tessellate` exits 1 without --allow-partial)")
        });
        format!(
            ", covering {:.1}% of the input's area, face corners within {:.1} mm of it (mean \
             {:.1} mm){partial}",
            100.0 * f.covered,
            f.distance.max,
            f.distance.mean
        )
    });
    let remeshed = t.remeshed.map_or(String::new(), |r| {
        format!(" (re-triangulated to {})", r.faces[1])
    });
    outln!(
        "\n{name} (tessellation, Tachi 2014): {} faces{remeshed} -> {} triangles with {} tucks, \
         shrink {}, solved in {} iterations (developable to {:.0e} rad, folds <= {:.1} deg, \
         creases >= {:.1} deg apart){distance}; linuxcnc-fiber/stainless-0.5 perforation{} {}; \
         {name}.png shows it folded",
        mesh.faces().len(),
        t.mesh.triangles.len(),
        tucks,
        t.initial.shrink,
        t.report.iterations,
        r.developability.max(1e-16),
        r.max_fold.to_degrees(),
        r.min_vertex_angle.to_degrees(),
        clearance.map_or(String::new(), |c| format!(
            " (vertex clearances {c} mm: some creases are too short for a dash between the \
             material's)"
        )),
        if clean { "clean" } else { "NOT clean" }
    );
    if !clean {
        bail!("{name}: the simulated machine found problems");
    }
    Ok(())
}
