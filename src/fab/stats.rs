//! Plan statistics: burn lengths, pierces, travel and estimated time.
//!
//! # Passes
//! An operation with `passes = k` burns each stroke k times in a row before moving on: an open
//! stroke alternates direction (forwards, backwards, …) so repeating it needs no travel, a
//! closed stroke is repeated forwards. Every pass counts as a tool-on event (a pierce), so
//! pierces = Σ strokes × passes and burn length = Σ stroke length × passes. Repeating
//! stroke by stroke (rather than the whole group) keeps the precedence of cuts: a contour is
//! through before anything that depends on it.
//!
//! # Time
//! Each job is timed by [`super::timing::job_time`] (the program the G-code writer makes of
//! it, on the motion model of the simulated machine) from the machine origin; jobs add up.
//! [`moves`] lists the bare moves (stroke by stroke, open strokes alternating direction)
//! without the stops a dialect makes.

use glam::DVec2;

use super::order::{SAME_POINT_MM, travel_mm};
use super::{Job, Operation, PlanStats, Toolpath};
use crate::machine::motion::Move;
use crate::machine::{MachineProfile, SettingsByOperation};

/// Length of a polyline, mm.
pub fn stroke_length(stroke: &[DVec2]) -> f64 {
    stroke.windows(2).map(|w| w[0].distance(w[1])).sum()
}

/// Burn length per operation (× passes), for the operations that occur, in
/// [`Operation::ALL`] order.
pub fn burn_lengths(jobs: &[Job], settings: &SettingsByOperation) -> Vec<(Operation, f64)> {
    Operation::ALL
        .into_iter()
        .filter_map(|op| {
            let mut paths = all_paths(jobs).filter(|p| p.op == op).peekable();
            paths.peek()?;
            let once: f64 = paths
                .flat_map(|p| &p.strokes)
                .map(|s| stroke_length(s))
                .sum();
            Some((op, once * f64::from(settings.get(op).passes)))
        })
        .collect()
}

/// Tool-on events: strokes × passes.
pub fn pierces(jobs: &[Job], settings: &SettingsByOperation) -> usize {
    all_paths(jobs)
        .map(|p| p.strokes.len() * settings.get(p.op).passes as usize)
        .sum()
}

/// The moves of `paths` run from the machine origin (see the module docs on passes).
pub fn moves(paths: &[Toolpath], settings: &SettingsByOperation) -> Vec<Move> {
    let mut out = Vec::new();
    for p in paths {
        let s = settings.get(p.op);
        for stroke in p.strokes.iter().filter(|s| !s.is_empty()) {
            out.push(rapid(stroke[0]));
            let closed =
                stroke.len() > 2 && stroke[0].distance(stroke[stroke.len() - 1]) <= SAME_POINT_MM;
            for pass in 0..s.passes {
                let burn = |&to| Move {
                    to,
                    feed_mm_min: s.speed_mm_min,
                    rapid: false,
                };
                if closed || pass % 2 == 0 {
                    out.extend(stroke[1..].iter().map(burn));
                } else {
                    out.extend(stroke[..stroke.len() - 1].iter().rev().map(burn));
                }
            }
        }
    }
    out
}

/// The totals of `jobs`; `naive_travel_mm` is the travel of the unoptimised order.
pub fn plan_stats(
    jobs: &[Job],
    naive_travel_mm: f64,
    settings: &SettingsByOperation,
    machine: &MachineProfile,
) -> PlanStats {
    PlanStats {
        length_mm: burn_lengths(jobs, settings),
        pierces: pierces(jobs, settings),
        travel_mm: jobs.iter().map(|j| travel_mm(&j.paths, DVec2::ZERO)).sum(),
        naive_travel_mm,
        time_s: jobs
            .iter()
            .map(|j| super::timing::job_time(j, settings, machine))
            .sum(),
    }
}

fn rapid(to: DVec2) -> Move {
    Move {
        to,
        feed_mm_min: 0.0,
        rapid: true,
    }
}

fn all_paths(jobs: &[Job]) -> impl Iterator<Item = &Toolpath> {
    jobs.iter().flat_map(|j| &j.paths)
}
