//! The demo's paper-craft stage: the bundled vase (Ōgaki 2016) built from its design file into
//! parts with glue tabs, packed on A4, drawn, and cut on the diode laser through the simulated
//! machine.

use std::path::Path;

use anyhow::{Context, Result, anyhow, bail};
use foldcam::design::papercraft::parse_design;
use foldcam::formats::{self, write_atomic};
use foldcam::mesh::ReferenceMesh;
use foldcam::render::{PreviewOptions, preview_png};

use super::demo_jobs::{DemoIndex, write_job};

/// Builds the bundled vase, writes `papercraft-vase-N.fold`, a preview and the diode-laser job
/// of every sheet into `dir`.
pub fn vase(dir: &Path, index: &mut DemoIndex, width: u32) -> Result<()> {
    let design = parse_design(include_str!("../../examples/papercraft/vase.craft.toml"))
        .map_err(|e| anyhow!("vase.craft.toml: {e}"))?;
    let obj = include_bytes!("../../examples/papercraft/vase.obj");
    let mesh = foldcam::mesh::parse_obj(obj).map_err(|e| anyhow!("vase.obj: {e}"))?;
    let reference = ReferenceMesh::new(&mesh).map_err(|e| anyhow!("vase.obj: {e}"))?;
    let made = design
        .build(&reference)
        .map_err(|e| anyhow!("vase.craft.toml: {e}"))?;
    let (machine, material) = ("grbl-diode", "paper-160gsm");
    let mut clean = true;
    for (s, cp) in made.sheets.iter().enumerate() {
        let name = format!("papercraft-vase-{}", s + 1);
        formats::save(&dir.join(format!("{name}.fold")), cp, None)?;
        let options = PreviewOptions {
            width,
            dark_flat: true,
            ..PreviewOptions::default()
        };
        let png = preview_png(cp, &options, &[]).map_err(|e| anyhow!("{name}: {e}"))?;
        write_atomic(&dir.join(format!("{name}.png")), &png).context("png")?;
        index.picture(
            format!("{name}.png"),
            format!("{name}: sheet {} of the vase's parts", s + 1),
        );
        let job = write_job(dir, index, &name, cp, machine, material)?;
        clean &= job.clean;
    }
    let tabs: usize = made.parts.iter().map(|p| p.tabs.len()).sum();
    outln!(
        "\npapercraft-vase (paper craft, Ōgaki 2016): {} gores with {tabs} glue tabs on {} A4 sheet(s), packed \
         on their shapes; {machine}/{material} cut {}; papercraft-vase-1.png shows the sheet",
        made.parts.len(),
        made.sheets.len(),
        if clean { "clean" } else { "NOT clean" }
    );
    if !clean {
        bail!("papercraft-vase: the simulated machine found problems");
    }
    Ok(())
}
