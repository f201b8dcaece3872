//! `foldcam plan PATTERN --machine M --material X`: the plan's statistics.

use anyhow::Result;
use foldcam::fab::FabPlan;

use super::Outcome;
use super::fab_args::PlanRequest;

/// Print what cutting a pattern would do: lengths per operation, pierces, travel, time.
#[derive(clap::Args)]
#[command(
    after_help = "Examples:\n  foldcam plan miura.fold --machine grbl-diode --material card-300gsm\n  \
    foldcam plan tess.svg -m linuxcnc-fiber -x stainless-0.5 --two-sided --json"
)]
pub struct Args {
    #[command(flatten)]
    pub request: PlanRequest,
    /// Print the statistics as JSON.
    #[arg(long)]
    pub json: bool,
}

/// Plans and prints the statistics.
pub fn run(args: Args) -> Result<Outcome> {
    let (_, p) = args.request.plan()?;
    if args.json {
        outln!("{}", serde_json::to_string_pretty(&p.stats)?);
    } else {
        out!("{}", summary(&p));
    }
    Ok(Outcome::Done)
}

/// A readable summary of a plan: jobs, lengths per operation, pierces, travel, time.
pub fn summary(p: &FabPlan) -> String {
    use std::fmt::Write;
    let mut s = String::new();
    for job in &p.jobs {
        let _ = writeln!(s, "job {:<6} {} toolpaths", job.name, job.paths.len());
    }
    for (op, mm) in &p.stats.length_mm {
        let _ = writeln!(s, "  {:<10} {:>12.1} mm", op.name(), mm);
    }
    let st = &p.stats;
    let saved = if st.naive_travel_mm > 0.0 {
        100.0 * (1.0 - st.travel_mm / st.naive_travel_mm)
    } else {
        0.0
    };
    if let Some(share) = st.perforated_share() {
        let _ = writeln!(
            s,
            "  perforated {:>12.1} mm of dashes along {:.1} mm of crease ({:.0}%)",
            st.perforated_mm,
            st.crease_mm,
            100.0 * share
        );
    }
    let _ = writeln!(s, "  pierces    {:>12}", st.pierces);
    let _ = writeln!(
        s,
        "  travel     {:>12.1} mm ({:.0}% less than in pattern order: {:.1} mm)",
        st.travel_mm, saved, st.naive_travel_mm
    );
    let _ = writeln!(s, "  time       {:>12} (estimated)", clock(st.time_s));
    for w in &p.warnings {
        let _ = writeln!(s, "warning: {w}");
    }
    s
}

fn clock(seconds: f64) -> String {
    let t = seconds.max(0.0).round() as u64;
    format!("{}:{:02}:{:02}", t / 3600, t / 60 % 60, t % 60)
}
