//! `foldcam generate KIND -o OUT`.

use anyhow::Result;
use clap::ValueEnum;
use foldcam::design::classic::{MiuraOri, SquareTwist, Waterbomb, Yoshimura};
use foldcam::pattern::CreasePattern;

use super::Outcome;
use super::args::positive;

/// The classic patterns.
#[derive(Clone, Copy, Debug, ValueEnum)]
pub enum Kind {
    /// Miura-ori (parallelogram cells; --shear 0 gives a square grid).
    Miura,
    /// Square twist around a central square.
    SquareTwist,
    /// Grid of waterbomb bases.
    Waterbomb,
    /// Yoshimura diamond pattern.
    Yoshimura,
}

/// Generate a classic pattern.
#[derive(clap::Args)]
#[command(
    after_help = "Examples:\n  foldcam generate miura -o miura.fold --columns 12 --rows 8\n  \
    foldcam generate square-twist -o twist.svg --twist 30\n  foldcam generate yoshimura -o yoshi.cp\n  \
    foldcam generate miura -m grbl-diode -x card-300gsm -o miura.gcode"
)]
pub struct Args {
    /// Which pattern.
    pub kind: Kind,
    #[command(flatten)]
    pub out: super::design_output::DesignOutput,
    /// Cells along x (Miura, waterbomb, Yoshimura).
    #[arg(value_name = "N", long)]
    pub columns: Option<usize>,
    /// Cells along y (Miura, waterbomb, Yoshimura).
    #[arg(value_name = "N", long)]
    pub rows: Option<usize>,
    /// Cell width in mm (Miura, Yoshimura), base size (waterbomb), sheet side (square twist).
    #[arg(value_name = "MM", long, value_parser = positive)]
    pub width: Option<f64>,
    /// Cell height in mm (Miura, Yoshimura), central square side (square twist).
    #[arg(value_name = "MM", long, value_parser = positive)]
    pub height: Option<f64>,
    /// Miura zigzag offset in mm.
    #[arg(value_name = "MM", long)]
    pub shear: Option<f64>,
    /// Square-twist angle in degrees (0 to 45).
    #[arg(value_name = "DEG", long)]
    pub twist: Option<f64>,
    /// Target fold angle of the mountain and valley creases in degrees (0 to 180), written to
    /// FOLD's edges_foldAngle and to SVG stroke opacity.
    #[arg(value_name = "DEG", long, value_parser = super::args::degrees, default_value_t = foldcam::design::classic::FOLD_ANGLE_DEG)]
    pub fold_angle: f64,
    #[command(flatten)]
    pub stdout: super::pipe::ToArg,
}

/// Builds the pattern the arguments describe.
pub fn build(args: &Args) -> Result<CreasePattern> {
    Ok(match args.kind {
        Kind::Miura => {
            let d = MiuraOri::default();
            MiuraOri {
                columns: args.columns.unwrap_or(d.columns),
                rows: args.rows.unwrap_or(d.rows),
                width: args.width.unwrap_or(d.width),
                height: args.height.unwrap_or(d.height),
                shear: args.shear.unwrap_or(d.shear),
            }
            .build()?
        }
        Kind::SquareTwist => {
            let d = SquareTwist::default();
            SquareTwist {
                sheet: args.width.unwrap_or(d.sheet),
                square: args.height.unwrap_or(d.square),
                twist_deg: args.twist.unwrap_or(d.twist_deg),
            }
            .build()?
        }
        Kind::Waterbomb => {
            let d = Waterbomb::default();
            Waterbomb {
                columns: args.columns.unwrap_or(d.columns),
                rows: args.rows.unwrap_or(d.rows),
                size: args.width.unwrap_or(d.size),
            }
            .build()?
        }
        Kind::Yoshimura => {
            let d = Yoshimura::default();
            Yoshimura {
                columns: args.columns.unwrap_or(d.columns),
                rows: args.rows.unwrap_or(d.rows),
                width: args.width.unwrap_or(d.width),
                height: args.height.unwrap_or(d.height),
            }
            .build()?
        }
    })
}

/// Generates and writes the pattern.
pub fn run(args: Args) -> Result<Outcome> {
    super::outputs::check(&[Some(args.out.target()?)], &[])?;
    let mut cp = build(&args)?;
    foldcam::design::classic::set_fold_angles(&mut cp, args.fold_angle);
    let mut outputs = foldcam::formats::OutputSet::new();
    args.out.stage(&mut outputs, &cp, None)?;
    super::outputs::commit(outputs, &[])?;
    note!(
        "foldcam: {}: {} vertices, {} edges",
        args.out.output.display(),
        cp.vertices.len(),
        cp.edges.len()
    );
    Ok(Outcome::Done)
}
