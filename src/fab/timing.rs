//! How long a job takes on its machine: the plan's estimate, with the motion model the
//! simulated machine uses ([`crate::machine::motion`]) over the program the G-code writer
//! makes of the job.
//!
//! The job is walked in the writer's order, on its coordinates (rounded to the machine's
//! resolution, repeated points dropped): the arming (pen up and its delay on a plotter),
//! the profile's preamble, then per toolpath and pass every stroke — a rapid to its start
//! unless the tool is already there (inside a pass on a LinuxCNC laser, feed moves at the
//! travel feed that leave and reach the burns along them, and burns with short end pieces
//! merged, as the writer makes them: [`MachineProfile::links_burns_with_feed_moves`],
//! [`crate::machine::sync_links`]), the tool switched on, the burns at the operation's feed
//! (capped at the machine's maximum), the tool switched off — with, between operations, the
//! air assist switched and a plotter's pen-change pause; then the postamble. What switching
//! costs comes from the profile ([`MachineProfile::switch_cost`]): pens stop and wait their
//! delay, LinuxCNC's spindle words stop, GRBL's and Marlin's inline power and LinuxCNC's
//! synchronised outputs do not. Coolant words (air assist) and pauses stop. The profile's
//! own lines are read with [`crate::machine::commands::effects`].
//!
//! Not counted: the operator's time at a pause, spindle or source start-up delays. Cost
//! O(points).

use glam::DVec2;

use super::{Operation, Setup, Toolpath};
use crate::machine::commands::{Effect, effects};
use crate::machine::motion::{Kinematics, Move, Timeline};
use crate::machine::sync_links;
use crate::machine::{MachineProfile, OperationSettings};

/// Seconds to run `job` on `machine`, each toolpath with the speed and passes `settings`
/// gives it (as the writer takes them: [`super::FabPlan::settings_of`]), from rest at the
/// machine origin.
pub fn job_time(
    job: &Setup,
    settings: &dyn Fn(&Toolpath) -> OperationSettings,
    machine: &MachineProfile,
) -> f64 {
    let mut clock = Clock {
        timeline: Timeline::new(Kinematics::of(machine), DVec2::ZERO),
        seconds: 0.0,
        machine,
        switches_sync: machine.links_burns_with_feed_moves(),
        sync: false,
    };
    let cost = machine.switch_cost();
    let pen = machine.pen_tool();
    let same = machine.resolution_mm / 2.0;
    let links = machine.links_burns_with_feed_moves();
    let link_feed = machine.travel_feed_mm_min.min(machine.max_feed_mm_min);
    let step = machine.resolution_mm;
    let mm = |p: (i64, i64)| DVec2::new(p.0 as f64 * step, p.1 as f64 * step);
    let min_piece = sync_links::MIN_PIECE_MM / step;
    let tangent = sync_links::tangent_limit_rad(machine);
    // Arming: the laser at zero (a stop) or the pen up with its delay.
    clock.switch(pen, &machine.pen_up, cost.dwell_s, true);
    // The arming zero is an immediate output (`M68`, `M65`), not a synchronised one.
    clock.sync = false;
    clock.lines(&machine.preamble);
    let mut group: Option<Operation> = None;
    let mut air = false;
    for path in &job.paths {
        let strokes: Vec<Vec<(i64, i64)>> = path
            .strokes
            .iter()
            .map(|s| as_written(s, machine))
            .filter(|s| s.len() >= 2)
            .collect();
        if strokes.is_empty() {
            continue;
        }
        if group != Some(path.op) {
            if group.is_some() && machine.pauses_between_layers() {
                clock.lines(&machine.control.pen_change);
            }
            if machine.air_for(path.op) != air {
                air = !air;
                clock.stop();
            }
            group = Some(path.op);
        }
        let s = settings(path);
        for _ in 0..s.passes {
            for (i, stroke) in strokes.iter().enumerate() {
                if clock.timeline.at().distance(mm(stroke[0])) > same {
                    if i > 0 && links {
                        // Inside a pass, a LinuxCNC laser links the burns with feed moves,
                        // leaving and arriving along the burns.
                        for p in sync_links::link(&strokes[i - 1], stroke, min_piece, tangent) {
                            clock.go(mm(p), false, link_feed);
                        }
                    } else {
                        clock.go(mm(stroke[0]), true, link_feed);
                    }
                }
                clock.switch(pen, &machine.pen_down, cost.dwell_s, cost.stops);
                for &p in &stroke[1..] {
                    clock.go(mm(p), false, s.speed_mm_min);
                }
                clock.switch(pen, &machine.pen_up, cost.dwell_s, cost.stops);
            }
        }
    }
    clock.stop();
    clock.lines(&machine.postamble);
    clock.stop();
    clock.seconds
}

/// `stroke` as the writer writes it, in grid counts of the machine's resolution: each point
/// rounded, repeated points dropped (so the estimate sees the short and slightly turned pieces
/// the machine reads), and, where the machine links burns with feed moves, short end pieces
/// merged ([`sync_links::tidy_ends`]).
fn as_written(stroke: &[DVec2], machine: &MachineProfile) -> Vec<(i64, i64)> {
    let step = machine.resolution_mm;
    let mut out: Vec<(i64, i64)> = stroke
        .iter()
        .map(|p| ((p.x / step).round() as i64, (p.y / step).round() as i64))
        .collect();
    out.dedup();
    if machine.links_burns_with_feed_moves() && out.len() >= 2 {
        sync_links::tidy_ends(
            &mut out,
            sync_links::MIN_PIECE_MM / step,
            sync_links::max_deviation_mm(machine) / step,
        );
    }
    out
}

/// A timeline with the seconds of its finished runs and dwells.
struct Clock<'a> {
    timeline: Timeline,
    seconds: f64,
    machine: &'a MachineProfile,
    /// The laser switches on a synchronised output (a LinuxCNC `M62`/`M63`/`M67`, which the
    /// next move carries: [`Move::sync`]).
    switches_sync: bool,
    /// A switch waits for the next move.
    sync: bool,
}

impl Clock<'_> {
    fn stop(&mut self) {
        self.seconds += self.timeline.stop();
    }

    fn dwell(&mut self, s: f64) {
        self.stop();
        self.seconds += s;
    }

    fn go(&mut self, to: DVec2, rapid: bool, feed_mm_min: f64) {
        self.timeline.push(Move {
            to,
            feed_mm_min,
            rapid,
            sync: std::mem::take(&mut self.sync),
        });
    }

    /// A tool switch: a pen's command lines and delay, a laser's stop when `stops`, or a
    /// synchronised output that the next move carries.
    fn switch(&mut self, pen: bool, pen_lines: &[String], delay_s: f64, stops: bool) {
        if !pen && self.switches_sync {
            self.sync = true;
        }
        if pen {
            self.lines(pen_lines);
            if delay_s > 0.0 {
                self.dwell(delay_s);
            }
        } else if stops {
            self.stop();
        }
    }

    /// The profile's command lines.
    fn lines(&mut self, lines: &[String]) {
        for e in effects(lines, self.timeline.at(), self.machine) {
            match e {
                Effect::Move {
                    to,
                    rapid,
                    feed_mm_min,
                } => self.go(to, rapid, feed_mm_min),
                Effect::Dwell(s) => self.dwell(s),
                Effect::Stop => self.stop(),
            }
        }
    }
}
