//! The demo's tessellation stage: the bundled dome (Tachi 2014) with truncated stars at the
//! 0.5 mm stainless limits, unfolded, drawn, and perforated on the fiber laser through the
//! simulated machine.

use std::path::Path;

use anyhow::{Context, Result, anyhow, bail};
use foldcam::design::tessellation::{Limits, TessellateOptions, TuckKind, tessellate};
use foldcam::formats::{self, write_atomic};
use foldcam::machine::load_material;
use foldcam::render::{View3d, render_folded_png};

/// Tessellates the bundled dome, writes `tessellation-dome.fold` (pattern and folded form),
/// its preview and the fiber-laser job into `dir`.
pub fn dome(dir: &Path, width: u32) -> Result<()> {
    let obj = include_bytes!("../../examples/tessellation/dome.obj");
    let mesh = foldcam::mesh::parse_obj(obj).map_err(|e| anyhow!("dome.obj: {e}"))?;
    let material = load_material("stainless-0.5")?;
    let mut opts = TessellateOptions::with_limits(Limits::from_degrees(
        material.limits.max_fold_angle_deg,
        material.limits.min_vertex_angle_deg,
    ));
    opts.star.tuck.kind = TuckKind::Truncated;
    let t = tessellate(&mesh, &opts, |_| {}).map_err(|e| anyhow!("dome.obj: {e}"))?;
    if let Some(problem) = t.problem() {
        bail!("dome.obj: {problem}");
    }
    let u = t.unfolded.as_ref().map_err(|e| anyhow!("dome.obj: {e}"))?;
    let name = "tessellation-dome";
    formats::save(
        &dir.join(format!("{name}.fold")),
        &u.pattern,
        Some(&u.folded),
    )?;
    let view = View3d {
        azimuth_deg: 30.0,
        elevation_deg: 35.0,
        ..View3d::with_width(width.min(800))
    };
    let png = render_folded_png(&u.folded, &view)?;
    write_atomic(&dir.join(format!("{name}.png")), &png).context("png")?;
    let job = super::demo::checked_job(&u.pattern, "linuxcnc-fiber", "stainless-0.5")?;
    let path = dir.join(format!("{name}.linuxcnc-fiber.ngc"));
    write_atomic(&path, job.gcode.as_bytes()).with_context(|| path.display().to_string())?;
    let clean = job.clean;
    let r = &t.report.last;
    println!(
        "\n{name} (tessellation, Tachi 2014): {} faces -> {} triangles with truncated stars, solved in {} \
         iterations (developable to {:.0e} rad, folds <= {:.1} deg, creases >= {:.1} deg apart); \
         linuxcnc-fiber/stainless-0.5 perforation {}; {name}.png shows it folded",
        mesh.faces().len(),
        t.mesh.triangles.len(),
        t.report.iterations,
        r.developability.max(1e-16),
        r.max_fold.to_degrees(),
        r.min_vertex_angle.to_degrees(),
        if clean { "clean" } else { "NOT clean" }
    );
    if !clean {
        bail!("{name}: the simulated machine found problems");
    }
    Ok(())
}
