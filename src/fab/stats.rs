//! Plan statistics: burn lengths, pierces, travel and estimated time.
//!
//! # Passes
//! A toolpath with `passes = k` is burned k times in a row, all its strokes each time, as the
//! G-code writer does (`post::gcode`): every pass of every stroke is a tool-on event (a
//! pierce), so pierces = Σ strokes × passes and burn length = Σ stroke length × passes.
//!
//! # Settings
//! Each toolpath counts with the settings it runs with on the machine,
//! [`FabPlan::settings_of`]: its override's (a calibration grid's cell), else its operation's
//! as the machine takes them — on a plotter every operation is drawn at the `plot` settings,
//! so lengths, pierces and time all use those, as the writer and [`super::timing`] do.
//!
//! # Time
//! Each job is timed by [`super::timing::job_time`] (the program the G-code writer makes of
//! it, on the motion model of the simulated machine) from the machine origin; jobs add up.

use glam::DVec2;

use super::operations::operation_for;
use super::order::travel_mm;
use super::{FabPlan, Operation, PlanStats, Toolpath};
use crate::machine::{MachineProfile, OperationMapping};
use crate::pattern::CreasePattern;

/// Length of a polyline, mm.
pub fn stroke_length(stroke: &[DVec2]) -> f64 {
    stroke.windows(2).map(|w| w[0].distance(w[1])).sum()
}

/// Burn length per operation (× passes), for the operations that occur, in
/// [`Operation::ALL`] order.
pub fn burn_lengths(plan: &FabPlan, machine: &MachineProfile) -> Vec<(Operation, f64)> {
    Operation::ALL
        .into_iter()
        .filter_map(|op| {
            let mut paths = plan
                .jobs
                .iter()
                .flat_map(|j| &j.paths)
                .filter(|p| p.op == op)
                .peekable();
            paths.peek()?;
            let total: f64 = paths
                .map(|p| {
                    let once: f64 = p.strokes.iter().map(|s| stroke_length(s)).sum();
                    once * f64::from(plan.settings_of(p, machine).passes)
                })
                .sum();
            Some((op, total))
        })
        .collect()
}

/// Tool-on events: strokes × passes.
pub fn pierces(plan: &FabPlan, machine: &MachineProfile) -> usize {
    plan.jobs
        .iter()
        .flat_map(|j| &j.paths)
        .map(|p| p.strokes.len() * plan.settings_of(p, machine).passes as usize)
        .sum()
}

/// Length of the edges of `cp` that `mapping` perforates, mm: the crease length a perforation
/// plan should weaken.
pub fn perforated_crease_mm(cp: &CreasePattern, mapping: &OperationMapping) -> f64 {
    cp.edge_ids()
        .filter(|&e| {
            operation_for(cp.edges[e.index()].assignment, mapping) == Some(Operation::Perforate)
        })
        .map(|e| cp.edge_length(e))
        .sum()
}

/// Length of the perforation dashes of `plan` (toolpath length, each dash once), mm.
pub fn dash_length(plan: &FabPlan) -> f64 {
    plan.jobs
        .iter()
        .flat_map(|j| &j.paths)
        .filter(|p| p.op == Operation::Perforate)
        .flat_map(|p| &p.strokes)
        .map(|s| stroke_length(s))
        .sum()
}

/// The totals of `plan` on `machine`; `naive_travel_mm` is the travel of the unoptimised
/// order, `crease_mm` the length of the creases the plan perforates
/// ([`perforated_crease_mm`]).
pub fn plan_stats(
    plan: &FabPlan,
    naive_travel_mm: f64,
    crease_mm: f64,
    machine: &MachineProfile,
) -> PlanStats {
    PlanStats {
        crease_mm,
        perforated_mm: dash_length(plan),
        length_mm: burn_lengths(plan, machine),
        pierces: pierces(plan, machine),
        travel_mm: plan
            .jobs
            .iter()
            .map(|j| travel_mm(&j.paths, DVec2::ZERO))
            .sum(),
        naive_travel_mm,
        time_s: plan
            .jobs
            .iter()
            .map(|j| {
                let settings = |p: &Toolpath| plan.settings_of(p, machine);
                super::timing::job_time(j, &settings, machine)
            })
            .sum(),
    }
}
