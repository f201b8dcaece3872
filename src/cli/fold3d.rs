//! `foldcam fold3d PATTERN -o folded.fold`: fold any pattern in 3D with the compliant
//! bar-and-hinge simulation (Ghassaei, Demaine & Gershenfeld 2018).

use std::path::PathBuf;
use std::time::Duration;

use anyhow::{Result, anyhow};
use foldcam::check::fold3d::{Fold, FoldOptions, Stop, fold};
use foldcam::formats::OutputSet;
use foldcam::formats::fold::write_string;
use foldcam::render::{ColourScale, heat_color};
use foldcam::render::{View3d, render_folded_png, render_gif};

use super::Outcome;
use super::{input, outputs};

/// Strain drawn red by `--strain` at least (the scale tops at the largest strain above it).
const STRAIN_SCALE_MIN: f64 = 0.01;

/// Strain above which the report warns that the pattern stretches to fold.
const STRAIN_WARNING: f64 = 0.01;

/// Frames of the `--gif` animation while folding (plus the flat sheet).
const GIF_FRAMES: usize = 30;

/// Fold a pattern in 3D with a compliant simulation.
#[derive(clap::Args)]
#[command(
    long_about = "Folds a crease pattern in 3D on the CPU with the bar-and-hinge model of Origami \
                  Simulator (Ghassaei, Demaine & Gershenfeld 2018): every face triangulated, \
                  bars keep the sheet's lengths, crease hinges turn towards percent x their fold \
                  angle (a mountain without one -180 deg, a valley +180 deg), facet hinges keep \
                  faces flat, cuts split the sheet. Patterns without faces are cleaned into a \
                  planar graph first. Writes a FOLD file whose key frame is the crease pattern and \
                  whose foldedForm frame holds the 3D positions and the reached fold angles; on \
                  request a shaded PNG (--strain colours faces by bar strain, blue none to red \
                  the largest, at least 1%) and a GIF folding from flat.\n\n\
                  Prints the largest strain and where it is, the largest fold-angle error and \
                  whether faces pass through each other (the simulation has no contact).\n\n\
                  Exit status: 0 settled, 1 stopped by the step or time cap before settling \
                  (the files are still written) or diverged (nothing is written), 2 bad input \
                  (nothing is written).",
    after_help = "Examples:\n  foldcam generate miura -o miura.fold && foldcam fold3d miura.fold -o folded.fold \\\n      --percent 90 --png folded.png\n  \
                  foldcam fold3d bird.cp -o bird3d.fold --percent 50 --gif bird.gif\n  \
                  foldcam fold3d tess.svg -o tess3d.fold --png tess3d.png --strain --steps 50000"
)]
pub struct Args {
    #[arg(help = input::pattern_help("Input pattern"))]
    pub input: PathBuf,
    #[command(flatten)]
    pub frame: input::FrameArg,
    /// FOLD file to write (crease pattern and the folded form).
    #[arg(short, long)]
    pub output: PathBuf,
    /// How far to fold, percent of every crease's fold angle (0 to 100).
    #[arg(long, default_value_t = 100.0, value_parser = percent)]
    pub percent: f64,
    /// Write a shaded 3D picture of the folded form (PNG).
    #[arg(long)]
    pub png: Option<PathBuf>,
    /// Write an animated GIF folding from flat to --percent.
    #[arg(long)]
    pub gif: Option<PathBuf>,
    /// Colour the PNG's faces by bar strain instead of paper colours.
    #[arg(long)]
    pub strain: bool,
    /// Adaptive ramp: raise the target up to 20 times faster while the sheet keeps up
    /// (about half the steps for a rigid-foldable sheet such as a Miura-ori; a sheet that is
    /// not rigid-foldable from flat may settle on another branch).
    #[arg(long)]
    pub adaptive_ramp: bool,
    /// How to find the folded form: `static` solves for it directly, in load steps of sparse
    /// Levenberg–Marquardt iterations (a 10,000-triangle Miura-ori at 90% in about 2.5 s),
    /// and hands over to the explicit run when it does not settle or leaves a crease against
    /// its assignment; `explicit` runs only the damped dynamics of Origami Simulator
    /// (thousands of steps; --adaptive-ramp and --steps apply to it).
    #[arg(long, value_enum, default_value_t = Method::Static)]
    pub method: Method,
    /// Most solver steps.
    #[arg(value_name = "N", long, default_value_t = 200_000, value_parser = clap::value_parser!(u64).range(1..=100_000_000))]
    pub steps: u64,
    /// Longest solver run, seconds.
    #[arg(value_name = "SECONDS", long, default_value_t = 60.0, value_parser = super::args::positive)]
    pub time_limit: f64,
    /// Picture width, pixels.
    #[arg(value_name = "PX", long, default_value_t = 800)]
    pub width: u32,
    #[command(flatten)]
    pub stdout: super::pipe::ToArg,
}

/// How `fold3d` finds the folded form.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Method {
    /// Load steps of Levenberg–Marquardt iterations on the model's energy.
    Static,
    /// Explicit damped dynamics alone.
    Explicit,
}

fn percent(s: &str) -> Result<f64, String> {
    let v: f64 = s.parse().map_err(|_| format!("{s:?} is not a number"))?;
    if v.is_finite() && (0.0..=100.0).contains(&v) {
        Ok(v)
    } else {
        Err(format!("{s} must be a percentage from 0 to 100"))
    }
}

/// Runs `foldcam fold3d`.
pub fn run(args: Args) -> Result<Outcome> {
    let output = outputs::target(&args.output)?;
    let png = outputs::optional(args.png.as_ref())?;
    let gif = outputs::optional(args.gif.as_ref())?;
    outputs::require_extension(&output, "fold", "the folded form")?;
    if let Some(p) = &png {
        outputs::require_extension(p, "png", "the picture")?;
    }
    if let Some(g) = &gif {
        outputs::require_extension(g, "gif", "the animation")?;
    }
    outputs::check(&[Some(&output), png.as_ref(), gif.as_ref()], &[&args.input])?;
    let name = args.input.display().to_string();
    let mut imported = input::load(&args.input, &args.frame)?;
    input::clean(&args.input, &mut imported, None, true)?;
    let cp = &imported.pattern;
    let opts = FoldOptions {
        percent: args.percent,
        max_steps: usize::try_from(args.steps).unwrap_or(usize::MAX),
        adaptive_ramp: args.adaptive_ramp,
        implicit: args.method == Method::Static,
        max_time: Duration::from_secs_f64(args.time_limit.min(1e6)),
        frames: if gif.is_some() { GIF_FRAMES } else { 0 },
        ..FoldOptions::default()
    };
    let bar = super::progress::spinner("folding");
    let result = fold(cp, &opts);
    bar.finish_and_clear();
    let result = result.map_err(|e| anyhow!("{name}: {e}"))?;
    if result.report.stop == Stop::Diverged {
        print_report(&name, &result, cp.units.label());
        errln!(
            "foldcam: {name}: the simulation diverged (its positions grew without bound): \
             nothing written; a sheet this small or stiff may need a lower --percent"
        );
        return Ok(Outcome::CheckFailed);
    }
    let mut staged = OutputSet::new();
    staged.add(&output, write_string(cp, Some(&result.folded)).into_bytes());
    let view = View3d {
        azimuth_deg: 30.0,
        elevation_deg: 35.0,
        ..View3d::with_width(args.width)
    };
    let unit = cp.units.label();
    let percent = args.percent;
    if let Some(png) = &png {
        let shows = if args.strain {
            format!("folded to {percent}%, coloured by bar strain")
        } else {
            format!("folded to {percent}%")
        };
        let mut v = view.clone().with_key(&shows, unit);
        if args.strain {
            let r = &result.report;
            let top = r.max_strain.max(STRAIN_SCALE_MIN);
            v.face_colors = Some(r.face_strain.iter().map(|&s| heat_color(s, top)).collect());
            if let Some(key) = &mut v.key {
                key.colour_scale = Some(ColourScale {
                    label: "bar strain".into(),
                    low: 0.0,
                    high: 100.0 * top,
                    unit: "%".into(),
                });
            }
        }
        let bytes =
            render_folded_png(&result.folded, &v).map_err(|e| anyhow!("{}: {e}", png.display()))?;
        staged.add(png, bytes);
    }
    if let Some(gif) = &gif {
        let mut states = vec![result.state_at(&result.model.rest)];
        states.extend(result.frames.iter().map(|x| result.state_at(&x.positions)));
        let view = view
            .clone()
            .with_key(&format!("folding from flat to {percent}%"), unit);
        let bytes =
            render_gif(&states, &view, 80).map_err(|e| anyhow!("{}: {e}", gif.display()))?;
        staged.add(gif, bytes);
    }
    outputs::commit(staged, &[&args.input])?;
    print_report(&name, &result, cp.units.label());
    Ok(match result.report.stop {
        Stop::Settled => Outcome::Done,
        _ => Outcome::CheckFailed,
    })
}

/// The summary: how the run ended, strain, fold-angle error, crossings.
fn print_report(name: &str, f: &Fold, unit: &str) {
    let r = &f.report;
    let stop = match r.stop {
        Stop::Settled => "settled".to_string(),
        Stop::StepCap => format!("NOT settled: the step cap ({} steps) ran out", r.steps),
        Stop::TimeCap => "NOT settled: the time cap ran out".to_string(),
        Stop::Diverged => "NOT settled: the simulation diverged (last finite state kept)".into(),
    };
    outln!(
        "{name}: folded to {}% with {} triangles ({}, {:.2} s), {stop}; largest leftover \
         force {:.1e} of a bar's stiffness EA (Young's modulus × cross-section)",
        r.percent,
        r.triangles,
        r.produced(),
        r.seconds,
        r.residual
    );
    if let Some(solve) = &r.static_solve {
        let how = if solve.used && r.stop == Stop::TimeCap {
            "stopped by the time cap (its state is the result; raise --time-limit)"
        } else if solve.used {
            "settled"
        } else {
            "did not settle within the tolerance with every crease on its side: the explicit run \
             folded it"
        };
        outln!(
            "  static solve: {} linear solves, {} factorizations; {how}",
            solve.linear_solves,
            solve.factorizations
        );
    }
    for slow in &r.slower_ramps {
        outln!(
            "  a ramp of {} steps left {} crease(s) folded against their assignment: folded \
             again from flat with a ramp {}× slower",
            slow.ramp_steps,
            slow.wrong_sign,
            foldcam::check::fold3d::SLOWER_RAMP_FACTOR
        );
    }
    let at = r
        .max_strain_at
        .map(|p| {
            format!(
                " at face {} near ({:.2}, {:.2}) {unit}",
                r.max_strain_face.map_or(0, |f| f.index()),
                p.x,
                p.y
            )
        })
        .unwrap_or_default();
    outln!("  largest bar strain {:.3}%{at}", 100.0 * r.max_strain);
    if r.max_strain > STRAIN_WARNING {
        outln!(
            "  warning: the sheet stretches more than {:.0}% to fold: the pattern is not \
             foldable to these angles without bending its faces (strain concentrates around the \
             face named above)",
            100.0 * STRAIN_WARNING
        );
    }
    match r.max_angle_error_edge {
        Some(e) => outln!(
            "  largest fold-angle error {:.2} deg at edge {} (target {:.1} deg, reached {:.1} deg)",
            r.max_angle_error_deg,
            e.index(),
            r.targets[e.index()].unwrap_or(0.0),
            r.fold_angles[e.index()].unwrap_or(0.0)
        ),
        None => outln!("  no crease with a target"),
    }
    if !r.wrong_sign.is_empty() {
        outln!(
            "  {} crease(s) folded against their assignment (first: edge {})",
            r.wrong_sign.len(),
            r.wrong_sign[0].index()
        );
    }
    if let Some(first) = r.past_flat.first() {
        outln!(
            "  {} crease(s) folded past flat: the faces on either side pass through each other \
             (first: edge {}; written as ±180 deg)",
            r.past_flat.len(),
            first.index()
        );
    }
    match r.crossing_faces.first() {
        None if r.past_flat.is_empty() => outln!("  no faces pass through each other"),
        None => {}
        Some((a, b)) => outln!(
            "  faces pass through each other: {} pair(s), e.g. faces {} and {}",
            r.crossing_faces.len(),
            a.index(),
            b.index()
        ),
    }
}
