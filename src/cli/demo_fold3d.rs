//! The demo's 3D fold stage: the Miura-ori the demo wrote as SVG, read back like any
//! imported drawing, folded to 90 % by the compliant bar-and-hinge simulation (Ghassaei,
//! Demaine & Gershenfeld 2018), drawn shaded and as an animation.

use std::path::Path;

use anyhow::{Context, Result, anyhow, bail};
use foldcam::check::fold3d::{FoldOptions, Stop, fold};
use foldcam::formats::{self, write_atomic};
use foldcam::pattern::{PlanarizeOptions, planarize};
use foldcam::render::{View3d, render_folded_png, render_gif};

/// How far the demo folds, percent.
const PERCENT: f64 = 90.0;

/// Largest bar strain the demo accepts: the Miura-ori folds rigidly.
const STRAIN_LIMIT: f64 = 0.01;

/// Folds `miura-ori.svg` from `dir` and writes `fold3d-miura.{fold,png,gif}` there.
pub fn miura(dir: &Path, index: &mut super::demo_jobs::DemoIndex, width: u32) -> Result<()> {
    let svg = dir.join("miura-ori.svg");
    let mut imported = formats::load(&svg)?;
    let cp = &mut imported.pattern;
    planarize(
        cp,
        &PlanarizeOptions {
            faces: true,
            ..PlanarizeOptions::default()
        },
    )
    .map_err(|e| anyhow!("{}: {e}", svg.display()))?;
    let opts = FoldOptions {
        percent: PERCENT,
        frames: 24,
        ..FoldOptions::default()
    };
    let f = fold(cp, &opts).map_err(|e| anyhow!("{}: {e}", svg.display()))?;
    let view = View3d {
        azimuth_deg: 30.0,
        elevation_deg: 35.0,
        ..View3d::with_width(width.min(800))
    };
    let name = "fold3d-miura";
    let unit = cp.units.label();
    let shown = view
        .clone()
        .with_key(&format!("Miura-ori folded to {PERCENT}%"), unit);
    let png = render_folded_png(&f.folded, &shown)?;
    let mut states = vec![f.state_at(&f.model.rest)];
    states.extend(f.frames.iter().map(|x| f.state_at(&x.positions)));
    let folding = format!("Miura-ori folding from flat to {PERCENT}%");
    let gif = render_gif(&states, &view.with_key(&folding, unit), 80)?;
    formats::save(&dir.join(format!("{name}.fold")), cp, Some(&f.folded))?;
    for (ext, bytes, shows) in [
        ("png", png, format!("folded to {PERCENT}%")),
        ("gif", gif, "folding".into()),
    ] {
        let path = dir.join(format!("{name}.{ext}"));
        write_atomic(&path, &bytes).with_context(|| path.display().to_string())?;
        index.picture(
            format!("{name}.{ext}"),
            format!("{name}: the Miura-ori {shows} in 3D"),
        );
    }
    let r = &f.report;
    outln!(
        "\n{name}: miura-ori.svg read back and folded to {PERCENT}% in 3D ({} triangles, {}, \
         {:.2} s): largest bar strain {:.3}%, largest fold-angle error {:.1} deg, faces {}; \
         {name}.png and {name}.gif show it",
        r.triangles,
        r.produced(),
        r.seconds,
        100.0 * r.max_strain,
        r.max_angle_error_deg,
        if r.crossing_faces.is_empty() && r.past_flat.is_empty() {
            "clear of each other"
        } else {
            "PASS THROUGH each other"
        }
    );
    if r.stop != Stop::Settled || r.max_strain > STRAIN_LIMIT || !r.wrong_sign.is_empty() {
        bail!("{name}: the simulation did not fold the Miura-ori cleanly");
    }
    Ok(())
}
