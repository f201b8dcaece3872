//! `foldcam testgrid -m MACHINE -x MATERIAL -o grid.gcode`: a perforation calibration grid.

use std::path::PathBuf;

use anyhow::Result;
use foldcam::fab::testgrid::{TestGridOptions, short_number, spread, test_grid};
use foldcam::machine::{load_machine, load_material};

use super::Outcome;

/// A list of values given on the command line.
#[derive(Clone, Debug)]
pub struct Values(Vec<f64>);

/// Parses `A` (one value), `A,B,C` (a list) or `FROM:TO:N` (N values evenly from FROM to TO).
fn values(s: &str) -> Result<Values, String> {
    parse_values(s).map(Values)
}

fn parse_values(s: &str) -> Result<Vec<f64>, String> {
    let number = |t: &str| {
        t.trim()
            .parse::<f64>()
            .ok()
            .filter(|v| v.is_finite())
            .ok_or_else(|| format!("{t:?} is not a number"))
    };
    let parts: Vec<&str> = s.split(':').collect();
    match parts.as_slice() {
        [from, to, n] => {
            let n: usize = n
                .trim()
                .parse()
                .map_err(|_| format!("{n:?}: expected a count of values"))?;
            if !(1..=foldcam::fab::testgrid::MAX_VALUES).contains(&n) {
                return Err(format!(
                    "{n} values: expected 1 to {}",
                    foldcam::fab::testgrid::MAX_VALUES
                ));
            }
            let (from, to) = (number(from)?, number(to)?);
            let mut out = spread(from, to, n, 1e-4);
            out.dedup();
            Ok(out)
        }
        [list] => list.split(',').map(number).collect(),
        _ => Err(format!("{s}: expected A, A,B,C or FROM:TO:N")),
    }
}

/// Burn a calibration grid of perforated creases.
#[derive(clap::Args)]
#[command(
    long_about = "Writes a calibration grid: one coupon per combination of dash, bridge, power \
                  and speed, each with a short perforated crease across it and its values marked \
                  under the crease in stroke digits (upper line: dash and bridge in mm; lower \
                  line: power in per cent and speed in mm/min). Burn it, fold every coupon, and \
                  copy the values of the one that folds cleanly into the material profile: \
                  [perforation] cut_mm and bridge_mm, [settings.perforate] power (per cent / \
                  100) and speed_mm_min. Without options the values spread around the \
                  material's own: three dashes and three bridges from half to one and a half \
                  times its, three powers from 0.2 below to 0.2 above its, its speed. Output by \
                  extension: .gcode/.nc/.ngc (read back by the simulated machine first), .dxf, \
                  .svg, .lbrn2 (one LightBurn layer per cell).",
    after_help = "Examples:\n  foldcam testgrid -m grbl-diode -x card-300gsm -o grid.gcode\n  \
                  foldcam testgrid -m linuxcnc-fiber -x stainless-0.5 -o grid.ngc \\\n      --dash 2:4:3 --bridge 0.6,0.8,1 --power 1\n  \
                  foldcam testgrid -m lightburn -x paper-160gsm -o grid.lbrn2 --speed 1500:2500:3"
)]
pub struct Args {
    /// Machine profile: a shipped name or a TOML file.
    #[arg(long, short = 'm')]
    pub machine: String,
    /// Material profile: a shipped name or a TOML file.
    #[arg(long, short = 'x')]
    pub material: String,
    /// Output: .gcode/.nc/.ngc, .dxf, .svg or .lbrn2.
    #[arg(short, long)]
    pub output: PathBuf,
    /// Dash lengths, mm: A, A,B,C or FROM:TO:N.
    #[arg(long, value_name = "VALUES", value_parser = values)]
    pub dash: Option<Values>,
    /// Bridges (material left between dashes), mm: A, A,B,C or FROM:TO:N.
    #[arg(long, value_name = "VALUES", value_parser = values)]
    pub bridge: Option<Values>,
    /// Powers, fractions of the machine's range (0 to 1): A, A,B,C or FROM:TO:N.
    #[arg(long, value_name = "VALUES", value_parser = values)]
    pub power: Option<Values>,
    /// Speeds, mm/min: A, A,B,C or FROM:TO:N.
    #[arg(long, value_name = "VALUES", value_parser = values)]
    pub speed: Option<Values>,
    /// Crease length (coupon width), mm; default from the longest dash and bridge.
    #[arg(long, value_name = "MM")]
    pub crease: Option<f64>,
    /// Height of the label digits, mm.
    #[arg(long, value_name = "MM", default_value_t = 3.0)]
    pub label_height: f64,
    /// Distance from the bed's origin corner, mm.
    #[arg(long, value_name = "MM", default_value_t = 5.0)]
    pub margin: f64,
    /// Write DXF R12 instead of R2000.
    #[arg(long)]
    pub r12: bool,
    /// In a LightBurn project (.lbrn2), each coupon's crease as one path in LightBurn's
    /// perforation mode (its layer's cut and skip are the coupon's dash and gap) instead of
    /// one shape per dash.
    #[arg(long)]
    pub lightburn_perforation: bool,
    #[command(flatten)]
    pub stdout: super::pipe::ToArg,
}

/// Builds, writes and describes the grid.
pub fn run(args: Args) -> Result<Outcome> {
    let output = super::outputs::target(&args.output)?;
    super::outputs::check(&[Some(&output)], &[])?;
    let machine = load_machine(&args.machine)?;
    let material = load_material(&args.material)?;
    let mut opts = TestGridOptions::around(&material, &machine);
    let chosen = [
        (&mut opts.dash_mm, args.dash),
        (&mut opts.bridge_mm, args.bridge),
        (&mut opts.power, args.power),
        (&mut opts.speed_mm_min, args.speed),
    ];
    for (slot, given) in chosen {
        if let Some(Values(v)) = given {
            *slot = v;
        }
    }
    opts.crease_mm = args.crease.unwrap_or(opts.crease_mm);
    opts.label_mm = args.label_height;
    opts.margin_mm = args.margin;
    let grid = test_grid(&machine, &material, &opts)?;
    let choices = foldcam::job::WriterChoices {
        r12: args.r12,
        dasharray: false,
        lightburn_perforation: args.lightburn_perforation,
    };
    super::cut::write_plan(&output, &grid.plan, &machine, choices)?;
    outln!(
        "{} cells ({} mm creases): cell, dash mm, bridge mm, power %, speed mm/min",
        grid.cells.len(),
        short_number(opts.crease_mm)
    );
    for c in &grid.cells {
        outln!(
            "  {:>3}  {:>6}  {:>6}  {:>5}  {:>7}",
            c.number,
            short_number(c.dash_mm),
            short_number(c.bridge_mm),
            short_number(c.power * 100.0),
            short_number(c.speed_mm_min)
        );
    }
    outln!(
        "estimated time {:.1} s (the simulated machine's model)",
        grid.plan.stats.time_s
    );
    Ok(Outcome::Done)
}
