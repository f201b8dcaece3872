//! `foldcam tessellate MESH -o shell.fold`: freeform origami tessellations (Tachi 2014).

use std::path::PathBuf;

use anyhow::{Result, anyhow, bail};
use clap::ValueEnum;
use foldcam::design::source::SourceError;
use foldcam::design::source::tessellate::{
    DEFAULT_MAX_FOLD_DEG, DEFAULT_MIN_VERTEX_DEG, MAX_ITERATIONS, TessellationOptions,
    tessellate_mesh,
};
use foldcam::design::tessellation::rigid::{RigidModel, RigidOptions, simulate};
use foldcam::design::tessellation::{Remesh, TuckKind, TuckLayout};
use foldcam::formats::OutputSet;
use foldcam::machine::load_material;
use foldcam::mesh::read_mesh;
use foldcam::render::{PreviewOptions, View3d, preview_png, render_folded_png};

use super::Outcome;
use super::args::degrees;
use super::progress::DesignProgress;

/// Tuck structure (Tachi 2014, sections 2.1 and 2.2).
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Tuck {
    /// Star tuck.
    Star,
    /// Truncated star: the key vertex becomes a flat n-gon (--truncation).
    Truncated,
    /// Twisted star: a fold in each star triangle (--twist).
    Twisted,
    /// Twist fold: a twisted star with a flat n-gon (--truncation, --twist).
    Twist,
}

/// Gap layout of the star tucks.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Layout {
    /// Checkerboard when every interior vertex has even valence >= 6, else digons.
    Auto,
    /// Two-coloured faces (Resch's triangle pattern).
    Checkerboard,
    /// A zero-area digon on every edge (any mesh).
    Digon,
}

/// Make an origami tessellation from a mesh.
#[derive(clap::Args)]
#[command(
    long_about = "Turns a disk-like polygon mesh (OBJ or STL, millimetres) into a Resch-like \
                  origami tessellation (Tachi 2014, Freeform 3D Origami Tessellations for Fabrication): a tuck behind \
                  every vertex (a star, or a truncated star, twisted star or twist fold), \
                  then a generalized Newton-Raphson solve for developability (the angles \
                  round every vertex sum to 360 deg), mountain/valley fold ranges with the \
                  fold-angle limit and the vertex-angle limit, then the unfolded crease pattern. The output FOLD \
                  holds the crease pattern (frame 0, mm) and the folded form (frame 1).\n\n\
                  Limits default to the material's (--material) or to Tachi's stainless-steel example \
                  (fold angle <= 165 deg, vertex angle >= 30 deg).\n\nExit status: 0 written, \
                  1 the solver did not converge, the pattern overlaps or the folded form \
                  intersects itself (nothing is written), \
                  2 bad input.",
    after_help = "Examples:\n  cargo run --example tessellation_meshes\n  \
                  foldcam tessellate examples/tessellation/dome.obj -o dome.fold --png dome.png --cp-png dome-cp.png\n  \
                  foldcam tessellate saddle.obj --material stainless-0.5 --shrink 0.7 -o saddle.fold\n  \
                  foldcam cut dome.fold -m linuxcnc-fiber -x stainless-0.5 -o dome.ngc"
)]
pub struct Args {
    /// Input mesh (.obj or .stl), a disk with one boundary, in millimetres.
    pub mesh: PathBuf,
    #[command(flatten)]
    pub out: super::design_output::DesignOutput,
    /// Tuck structure.
    #[arg(long, value_enum, default_value = "star")]
    pub tuck: Tuck,
    /// Gap layout of the star tucks.
    #[arg(long, value_enum, default_value = "auto")]
    pub layout: Layout,
    /// Face shrink s in (0, 1]: smaller opens the tucks more. Without it, 0.8, 0.7, 0.6, 0.5,
    /// 0.45 and 0.4 are tried in turn until the result converges without face collisions.
    #[arg(long)]
    pub shrink: Option<f64>,
    /// Truncated star and twist fold: initial size of the flat n-gon, the fraction in (0, 1)
    /// of the way from the key vertex towards each face corner (the solver then adapts it).
    #[arg(long, default_value_t = 0.3)]
    pub truncation: f64,
    /// Twisted star and twist fold: initial twist about the vertex normal, degrees (non-zero,
    /// within ±90; the sign picks the handedness).
    #[arg(long, default_value_t = 15.0, allow_negative_numbers = true)]
    pub twist: f64,
    /// Largest fold angle, degrees (180 − δ_fold).
    #[arg(long, value_parser = degrees)]
    pub max_fold_angle: Option<f64>,
    /// Smallest angle between neighbouring creases, degrees (δ_corner).
    #[arg(long, value_parser = degrees)]
    pub min_vertex_angle: Option<f64>,
    /// Ground contact: every boundary vertex on the horizontal plane (z) through the lowest
    /// one, so the shell stands on a table.
    #[arg(long)]
    pub ground: bool,
    /// Surface fit after solving (Tachi 2014), with this tangential weight w in [0, 1].
    #[arg(long, value_name = "W")]
    pub fit: Option<f64>,
    /// Re-triangulate the surface near-regularly (valence 6, no pole fans) before
    /// tessellating, with about FACES faces (default: as many as the input has). Without it
    /// both the input's own triangles and the re-triangulation are tried, the latter first
    /// when the input has face corners sharper than the vertex-angle limit.
    #[arg(long, value_name = "FACES", num_args = 0..=1, default_missing_value = "0")]
    pub remesh: Option<usize>,
    /// Newton iteration cap.
    #[arg(long, default_value_t = 200)]
    pub max_iterations: usize,
    /// Write a preview of the folded form.
    #[arg(long)]
    pub png: Option<PathBuf>,
    /// Write a preview of the crease pattern.
    #[arg(long)]
    pub cp_png: Option<PathBuf>,
    /// Image width in pixels for the previews.
    #[arg(long, default_value_t = 800)]
    pub width: u32,
    /// After solving, simulate rigid folding from flat to the result in STEPS increments.
    #[arg(long, value_name = "STEPS", num_args = 0..=1, default_missing_value = "100")]
    pub rigid: Option<usize>,
}

/// Runs `foldcam tessellate`.
pub fn run(args: Args) -> Result<Outcome> {
    if args.max_iterations == 0 || args.max_iterations > MAX_ITERATIONS {
        bail!("--max-iterations must be between 1 and {MAX_ITERATIONS}");
    }
    let mesh = read_mesh(&args.mesh).map_err(|e| anyhow!("{}: {e}", args.mesh.display()))?;
    let (mut fold, mut corner) = (DEFAULT_MAX_FOLD_DEG, DEFAULT_MIN_VERTEX_DEG);
    if let Some(name) = &args.out.material {
        let m = load_material(name)?;
        (fold, corner) = (m.limits.max_fold_angle_deg, m.limits.min_vertex_angle_deg);
    }
    let options = TessellationOptions {
        tuck: match args.tuck {
            Tuck::Star => TuckKind::Star,
            Tuck::Truncated => TuckKind::Truncated,
            Tuck::Twisted => TuckKind::Twisted,
            Tuck::Twist => TuckKind::TwistFold,
        },
        layout: match args.layout {
            Layout::Auto => TuckLayout::Auto,
            Layout::Checkerboard => TuckLayout::Checkerboard,
            Layout::Digon => TuckLayout::Digon,
        },
        shrink: args.shrink,
        truncation: args.truncation,
        twist_deg: args.twist,
        max_fold_angle_deg: args.max_fold_angle.unwrap_or(fold),
        min_vertex_angle_deg: args.min_vertex_angle.unwrap_or(corner),
        ground: args.ground,
        fit: args.fit,
        max_iterations: args.max_iterations,
        remesh: if args.remesh.is_some() {
            Remesh::Only
        } else {
            Remesh::Auto
        },
        remesh_faces: args.remesh.filter(|&f| f > 0),
    };
    let mut progress = DesignProgress::counting(args.max_iterations as u64);
    let result = tessellate_mesh(&args.mesh, &mesh, &options, &mut progress);
    // The report is printed whether or not the result is usable.
    let lines: &[String] = match &result {
        Ok(t) => &t.summary,
        Err(SourceError::NotMade { lines }) => lines,
        Err(_) => &[],
    };
    for line in lines {
        println!("{line}");
    }
    let unfolded = match result {
        Ok(t) => t.unfolded,
        Err(SourceError::NotMade { .. }) => return Ok(Outcome::CheckFailed),
        Err(e) => return Err(e.into()),
    };
    if let Some(steps) = args.rigid {
        let opts = RigidOptions {
            steps,
            ..RigidOptions::default()
        };
        let model = RigidModel::new(&unfolded.pattern)?;
        let report = simulate(
            &model,
            &model.targets_from(&unfolded.pattern),
            &opts,
            |s, r| eprintln!("  rigid step {s:4}: loop-closure residual {r:.2e}"),
        )?;
        println!("{}", report.summary());
    }
    // The pattern and its pictures are written together: all of them, or none.
    let mut outputs = OutputSet::new();
    args.out
        .stage(&mut outputs, &unfolded.pattern, Some(&unfolded.folded))?;
    if let Some(png) = &args.png {
        let view = View3d {
            azimuth_deg: 30.0,
            elevation_deg: 35.0,
            ..View3d::with_width(args.width)
        };
        let bytes = render_folded_png(&unfolded.folded, &view)
            .map_err(|e| anyhow!("{}: {e}", png.display()))?;
        super::input::stage_image(&mut outputs, png, bytes, "png")?;
    }
    if let Some(png) = &args.cp_png {
        let bytes = preview_png(
            &unfolded.pattern,
            &PreviewOptions::with_width(args.width),
            &[],
        )
        .map_err(|e| anyhow!("{}: {e}", png.display()))?;
        super::input::stage_image(&mut outputs, png, bytes, "png")?;
    }
    super::input::commit(outputs, &[&args.mesh])?;
    Ok(Outcome::Done)
}
