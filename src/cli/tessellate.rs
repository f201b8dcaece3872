//! `foldcam tessellate MESH -o shell.fold`: freeform origami tessellations (Tachi 2014).

use std::path::PathBuf;

use anyhow::{Result, anyhow, bail};
use clap::ValueEnum;
use foldcam::design::source::tess_design::{self, TessSettings};
use foldcam::design::source::tessellate::{
    DEFAULT_TIME_LIMIT_S, TessellationOptions, solve_plan, tessellate_mesh,
};
use foldcam::design::source::{
    DesignFile, DesignKind, SourceError, mesh_path_beside, read_design_file,
};
use foldcam::design::tessellation::rigid::{RigidModel, RigidOptions, simulate};
use foldcam::design::tessellation::{Remesh, TuckKind, TuckLayout};
use foldcam::formats::OutputSet;
use foldcam::machine::load_material;
use foldcam::mesh::read_mesh;
use foldcam::render::{
    PreviewOptions, View3d, preview_png, render_folded_png, with_marked_triangles,
};

use super::Outcome;

/// Red, for the input's area a partial tessellation leaves uncovered.
const MISSING_COLOUR: [u8; 3] = [214, 40, 40];
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
    /// Input mesh (.obj or .stl), a disk with one boundary, in millimetres; or a tessellation
    /// design (.tess.toml, as the studio saves it) naming its mesh and options, which the
    /// options given here override.
    pub mesh: PathBuf,
    #[command(flatten)]
    pub out: super::design_output::DesignOutput,
    /// Tuck structure [default: star].
    #[arg(long, value_enum)]
    pub tuck: Option<Tuck>,
    /// Gap layout of the star tucks [default: auto].
    #[arg(long, value_enum)]
    pub layout: Option<Layout>,
    /// Face shrink s in (0, 1]: smaller opens the tucks more. Without it, 0.8, 0.7, 0.6, 0.5,
    /// 0.45 and 0.4 are tried in turn until the result converges without face collisions.
    #[arg(value_name = "SHARE", long)]
    pub shrink: Option<f64>,
    /// Truncated star and twist fold: initial size of the flat n-gon, the fraction in (0, 1)
    /// of the way from the key vertex towards each face corner (the solver then adapts it)
    /// [default: 0.3].
    #[arg(value_name = "SHARE", long)]
    pub truncation: Option<f64>,
    /// Twisted star and twist fold: initial twist about the vertex normal, degrees (non-zero,
    /// within ±90; the sign picks the handedness) [default: 15].
    #[arg(value_name = "DEG", long, allow_negative_numbers = true)]
    pub twist: Option<f64>,
    /// Largest fold angle, degrees: 180 minus the opening a fold must keep (Tachi 2014's
    /// δ_fold).
    #[arg(value_name = "DEG", long, value_parser = degrees)]
    pub max_fold_angle: Option<f64>,
    /// Smallest angle between neighbouring creases, degrees (Tachi 2014 calls it δ_corner).
    #[arg(value_name = "DEG", long, value_parser = degrees)]
    pub min_vertex_angle: Option<f64>,
    /// Ground contact: every boundary vertex on the horizontal plane (z) through the lowest
    /// one, so the shell stands on a table.
    #[arg(long)]
    pub ground: bool,
    /// Surface fit after solving (Tachi 2014), with this tangential weight w in [0, 1].
    #[arg(long, value_name = "SHARE")]
    pub fit: Option<f64>,
    /// Re-triangulate the surface near-regularly (valence 6, no pole fans) before
    /// tessellating, with about FACES faces (default: as many as the input has). Without it
    /// both the input's own triangles and the re-triangulation are tried, the latter first
    /// when the input has face corners sharper than the vertex-angle limit; before both, a
    /// coarser re-triangulation when the rim crowding index predicts the tucks near the
    /// sheet's edge to collide (Tachi 2014, Fig. 14; the report then names the new face
    /// count and why).
    #[arg(long, value_name = "FACES", num_args = 0..=1, default_missing_value = "0")]
    pub remesh: Option<usize>,
    /// Newton iteration cap [default: 200].
    #[arg(value_name = "N", long)]
    pub max_iterations: Option<usize>,
    /// Stop after this many seconds, solved or not: the solve under way keeps what it reached
    /// and the best attempt is reported with the reason; 0 for no limit.
    #[arg(value_name = "SECONDS", long, default_value_t = DEFAULT_TIME_LIMIT_S)]
    pub time_limit: f64,
    /// Write a preview of the folded form.
    #[arg(long)]
    pub png: Option<PathBuf>,
    /// Write a preview of the crease pattern.
    #[arg(value_name = "PNG", long)]
    pub cp_png: Option<PathBuf>,
    /// Image width in pixels for the previews.
    #[arg(value_name = "PX", long, default_value_t = 800)]
    pub width: u32,
    /// Exit 0 even when the folded form is partial: it covers less than 95% of the input's
    /// area, or a face corner lies farther than 5% of the input's size from it (the files are
    /// written either way; without this the exit status is 1).
    #[arg(long)]
    pub allow_partial: bool,
    /// After solving, simulate rigid folding from flat to the result in STEPS increments.
    #[arg(long, value_name = "N", num_args = 0..=1, default_missing_value = "100")]
    pub rigid: Option<usize>,
    #[command(flatten)]
    pub stdout: super::pipe::ToArg,
}

/// Runs `foldcam tessellate`.
pub fn run(args: Args) -> Result<Outcome> {
    let (mesh_path, from_file) = design_or_mesh(&args)?;
    let output = args.out.target()?;
    let png = super::outputs::optional(args.png.as_ref())?;
    let cp_png = super::outputs::optional(args.cp_png.as_ref())?;
    super::outputs::check(
        &[Some(&output), png.as_ref(), cp_png.as_ref()],
        &[&args.mesh, &mesh_path],
    )?;
    let mesh = read_mesh(&mesh_path).map_err(|e| anyhow!("{}: {e}", mesh_path.display()))?;
    let mut options = TessellationOptions::default();
    if let Some(name) = &args.out.material {
        load_material(name)?
            .limits
            .apply_to_tessellation(&mut options);
    }
    // The design file's options over the material's, the command line's over both.
    from_file.apply_to(&mut options);
    settings(&args).apply_to(&mut options);
    options.time_limit_s = (args.time_limit != 0.0).then_some(args.time_limit);
    let mut progress = DesignProgress::solving(solve_plan(&mesh, &options)?);
    let result = tessellate_mesh(&mesh_path, &mesh, &options, &mut progress);
    // The report is printed whether or not the result is usable.
    let lines: Vec<String> = match &result {
        Ok(t) => t.summary.iter().map(ToString::to_string).collect(),
        Err(SourceError::NotMade { lines }) => lines.clone(),
        Err(_) => Vec::new(),
    };
    for line in lines {
        outln!("{line}");
    }
    let (unfolded, fit, missing) = match result {
        Ok(t) => (t.unfolded, t.fit, t.missing),
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
            |s, r| errln!("  rigid step {s:4}: loop-closure residual {r:.2e}"),
        )?;
        outln!("{}", report.summary());
    }
    // The pattern and its pictures are written together: all of them, or none.
    let mut outputs = OutputSet::new();
    args.out
        .stage(&mut outputs, &unfolded.pattern, Some(&unfolded.folded))?;
    if let Some(png) = &png {
        let view = View3d {
            azimuth_deg: 30.0,
            elevation_deg: 35.0,
            ..View3d::with_width(args.width)
        }
        .with_key(
            if missing.is_empty() {
                "the tessellation folded"
            } else {
                "the tessellation folded, with the mesh's area it leaves uncovered in red"
            },
            unfolded.pattern.units.label(),
        );
        let (state, view) = with_marked_triangles(&unfolded.folded, &missing, MISSING_COLOUR, view);
        let bytes =
            render_folded_png(&state, &view).map_err(|e| anyhow!("{}: {e}", png.display()))?;
        super::outputs::stage_image(&mut outputs, png, bytes, "png")?;
    }
    if let Some(png) = &cp_png {
        let bytes = preview_png(
            &unfolded.pattern,
            &PreviewOptions::with_width(args.width),
            &[],
        )
        .map_err(|e| anyhow!("{}: {e}", png.display()))?;
        super::outputs::stage_image(&mut outputs, png, bytes, "png")?;
    }
    super::outputs::commit(outputs, &[&args.mesh, &mesh_path])?;
    if let Some(why) = fit.as_ref().and_then(|f| f.partial()) {
        errln!(
            "foldcam: {}: the tessellation is partial: {why}{}",
            mesh_path.display(),
            if args.allow_partial {
                " (accepted: --allow-partial)"
            } else {
                "; written all the same, exit status 1 (--allow-partial accepts it)"
            }
        );
        if !args.allow_partial {
            return Ok(Outcome::CheckFailed);
        }
    }
    Ok(Outcome::Done)
}

/// The mesh to read and the options a design file sets: a `.tess.toml` (or a `.toml` with
/// `[tessellation]`) names its mesh relative to its own folder; anything else is the mesh.
fn design_or_mesh(args: &Args) -> Result<(PathBuf, TessSettings)> {
    let lower = args.mesh.to_string_lossy().to_ascii_lowercase();
    if !lower.ends_with(".toml") {
        return Ok((args.mesh.clone(), TessSettings::default()));
    }
    let bytes = read_design_file(&args.mesh)?;
    let file = DesignFile {
        name: &args.mesh,
        bytes: &bytes,
    };
    if DesignKind::recognise(&args.mesh, &bytes) != Some(DesignKind::Tessellation) {
        bail!(
            "{}: not a tessellation design (a .tess.toml with mesh = \"...\" and \
             [tessellation]) nor a mesh (.obj, .stl)",
            args.mesh.display()
        );
    }
    let design = tess_design::parse(&file)?;
    Ok((mesh_path_beside(&args.mesh, &design.mesh), design.settings))
}

/// The options given on the command line.
fn settings(args: &Args) -> TessSettings {
    TessSettings {
        tuck: args.tuck.map(|t| match t {
            Tuck::Star => TuckKind::Star,
            Tuck::Truncated => TuckKind::Truncated,
            Tuck::Twisted => TuckKind::Twisted,
            Tuck::Twist => TuckKind::TwistFold,
        }),
        layout: args.layout.map(|l| match l {
            Layout::Auto => TuckLayout::Auto,
            Layout::Checkerboard => TuckLayout::Checkerboard,
            Layout::Digon => TuckLayout::Digon,
        }),
        shrink: args.shrink,
        truncation: args.truncation,
        twist_deg: args.twist,
        max_fold_angle_deg: args.max_fold_angle,
        min_vertex_angle_deg: args.min_vertex_angle,
        ground: args.ground.then_some(true),
        fit: args.fit,
        remesh: args.remesh.map(|_| Remesh::Only),
        remesh_faces: args.remesh.filter(|&f| f > 0),
        max_iterations: args.max_iterations,
    }
}
