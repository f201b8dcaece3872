//! Motion time: how long a machine takes to run a sequence of straight moves.
//!
//! The model is the one GRBL's planner (`grbl/planner.c`, Sungeun Jeon's junction-deviation
//! planner, also used by Marlin) uses, reduced to one acceleration for all directions:
//!
//! - **Trapezoidal moves.** Each move accelerates at `a` from its entry speed, cruises at its
//!   nominal speed (the programmed feed capped at the machine's maximum; rapids run at the
//!   travel feed) and decelerates at `a` to its exit speed. A move too short to reach the
//!   nominal speed has a triangular profile peaking at `v_p² = (2aL + v₀² + v₁²) / 2`.
//! - **Junction speed.** Between two moves the speed is limited by the junction-deviation
//!   rule. Let θ be the angle at the corner between the incoming move reversed and the outgoing
//!   move (θ = 180° for a straight continuation, θ = 0° for a full reversal). Fit a circle of
//!   radius R tangent to both moves; its centre lies on the corner's bisector at distance
//!   `R / sin(θ/2)` from the corner, so the circle passes within `δ = R (1/sin(θ/2) − 1)` of
//!   the corner. Taking δ as the machine's junction deviation and requiring the centripetal
//!   acceleration `v² / R` to stay within `a` gives
//!   `v_junction² = a · δ · sin(θ/2) / (1 − sin(θ/2))`,
//!   with `sin(θ/2) = √((1 − cos θ) / 2)`. A straight continuation has no limit, a reversal
//!   must stop. The junction speed is further capped by both moves' nominal speeds. On
//!   LinuxCNC the corner is a blend arc leaving the path by at most `G64 P` (the same circle,
//!   δ = P) that uses √3/2 of the acceleration across the path
//!   ([`BLEND_ACC_RATIO_NORMAL`]).
//! - **Look-ahead.** A backward pass lowers each entry speed so the move can still slow down to
//!   the next entry (the job ends at rest); a forward pass lowers it so it is reachable from the
//!   previous entry. GRBL plans over a finite buffer; we plan over the whole list, which is what
//!   the buffer converges to when the stream keeps it full.
//!
//! - **Rapid ↔ feed switches** (LinuxCNC only): LinuxCNC's trajectory planner cannot blend a
//!   rapid (`G0`) into a feed move (`G1`) or back (`tpCheckCanonType` in `tp.c` sets the
//!   previous segment's end to an exact stop), so on a LinuxCNC machine the junction between a
//!   rapid and a feed move is a stop ([`Kinematics::stops_between_rapid_and_feed`]). GRBL and
//!   Marlin plan rapids and feed moves alike.
//!
//! - **Blends beside a switch** (LinuxCNC only): LinuxCNC joins moves with blend arcs that
//!   leave the path by at most `G64 P` and take at most half of each neighbouring move
//!   (`BLEND_DIST_FRACTION` 0.5 in `tc.h`), with a normal acceleration of √3/2 · a
//!   (`BLEND_ACC_RATIO_NORMAL`): an arc of half-angle θ' = θ/2 cut back by d along each move has
//!   radius tan θ' · d and runs at up to √(√3/2 · a · tan θ' · d). A short move is usually
//!   consumed whole by the arc (`blendCheckConsume`), but not a move that switches a
//!   synchronised output (`tcCanConsume`), nor the move before it when that switch continues
//!   it without a corner (LinuxCNC's tangent case, no arc). So at a corner beside such a move
//!   ([`Move::sync`]; the corner sharper than LinuxCNC's tangent limit,
//!   [`Kinematics::switch_blends`]) the junction speed is also capped by that arc with d half
//!   of that move. Measured on LinuxCNC 2.9 with `linuxcnc-fiber`'s limits, this is a lower
//!   bound: the 933 dashes of `HexSpiralTess.svg` at 200 mm run 51.2 s where this model says
//!   49.1 s (46.9 s without the cap and with the full acceleration at corners; on a 15 mm
//!   circle of 0.5 mm chords, a switch that splits a chord costs LinuxCNC 9-18 ms and this
//!   cap 2-11 ms).
//!
//! - **Stops.** When the moves come to rest with nothing queued (a spindle or pen word, a
//!   dwell, a pause waits for that), GRBL's stepper goes idle and holds the motors for its step
//!   idle delay `$1` (25 ms by default) before the next line runs (`st_go_idle` in
//!   `stepper.c`): [`Kinematics::stop_delay_s`], counted once per run of moves that ends at a
//!   stop. GRBL 1.1h's own planner and stepper run 100 stop-to-stop 1 mm moves in 11.44 s with
//!   `$1=25` and in 8.97 s with `$1=255` (the trapezoids alone: 8.94 s).
//!
//! - **Limits per axis** (GRBL and GRBL-style plotters, [`Kinematics::per_axis`]): GRBL
//!   limits each axis, not the path (`limit_value_by_axis_maximum` in `planner.c`): a move
//!   along unit vector u accelerates at `a / max(|uₓ|, |u_y|)` and runs at up to the maximum
//!   (or rapid) feed times the same factor, and a corner's acceleration is scaled the same way
//!   along the change of direction. A diagonal gets up to √2 times an axis's limits. Profiles
//!   give one acceleration and one maximum feed for both axes.
//!
//! Not modelled: per-axis limits on Marlin (no controller to check against here) and limits
//! that differ between X and Y, jerk,
//! step timing, GRBL's minimum junction speed (0 by default), and the stops a controller makes
//! when its buffer starves. Zero-length moves are skipped; they do not break a junction.
//! When the acceleration is not a positive finite number, moves run at constant speed.

use glam::DVec2;

use super::MachineProfile;
use crate::geom::tolerance::ROUNDOFF;

/// The share of LinuxCNC's acceleration its blend arcs use across the path
/// (`BLEND_ACC_RATIO_NORMAL` in `blendmath.h`: √(1 − 0.5²), 0.5 being left along the arc).
pub const BLEND_ACC_RATIO_NORMAL: f64 = 0.866_025_403_784_438_6;

/// One straight move.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Move {
    /// Target position, machine coordinates, mm.
    pub to: DVec2,
    /// Feed, mm/min (ignored for rapids, which use the machine's travel feed).
    pub feed_mm_min: f64,
    /// A rapid (tool-off travel) move.
    pub rapid: bool,
    /// The move switches a synchronised output as it starts (LinuxCNC `M62`/`M63`/`M67` before
    /// it; see the module docs on blends beside a switch).
    pub sync: bool,
}

/// The speed limits and acceleration of one run of moves, in mm and seconds.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Kinematics {
    /// Acceleration, mm/s².
    pub accel_mm_s2: f64,
    /// Junction deviation δ, mm.
    pub junction_deviation_mm: f64,
    /// Fastest feed, mm/min.
    pub max_feed_mm_min: f64,
    /// Rapid feed, mm/min.
    pub travel_feed_mm_min: f64,
    /// The machine comes to rest between a rapid and a feed move (LinuxCNC, see the module
    /// docs).
    pub stops_between_rapid_and_feed: bool,
    /// Seconds the controller waits each time its moves come to rest (GRBL's step idle delay
    /// `$1`, see the module docs).
    pub stop_delay_s: f64,
    /// The acceleration and the speeds are limits per axis (GRBL: a move, or a junction,
    /// along a diagonal gets more than along an axis; see the module docs), rather than
    /// along the path.
    pub per_axis: bool,
    /// LinuxCNC: corners beside a move that switches a synchronised output are blend arcs
    /// that take at most half of that move; the value is LinuxCNC's tangent limit (radians),
    /// the turn below which there is no corner (see the module docs). `None` elsewhere.
    pub switch_blends: Option<f64>,
    /// The share of the acceleration a corner may use across the path: LinuxCNC's blend arcs
    /// use √3/2 (`BLEND_ACC_RATIO_NORMAL`, the rest is left for the speed along the arc), other
    /// controllers 1.
    pub corner_accel_ratio: f64,
}

impl Kinematics {
    /// The kinematics of a machine profile. A LinuxCNC machine's corners deviate by its
    /// `G64 P` tolerance (`blend_tolerance_mm`) when it has one: a blend arc that leaves the
    /// corner by at most P is the junction-deviation circle of δ = P.
    pub fn of(machine: &MachineProfile) -> Self {
        let linuxcnc = machine.dialect == super::Dialect::LinuxCnc;
        let deviation = match machine.control.blend_tolerance_mm {
            Some(p) if linuxcnc => p,
            _ => machine.junction_deviation_mm,
        };
        Kinematics {
            accel_mm_s2: machine.acceleration_mm_s2,
            junction_deviation_mm: deviation,
            max_feed_mm_min: machine.max_feed_mm_min,
            travel_feed_mm_min: machine.travel_feed_mm_min,
            stops_between_rapid_and_feed: linuxcnc,
            stop_delay_s: machine.control.step_idle_delay_s,
            per_axis: matches!(
                machine.dialect,
                super::Dialect::Grbl | super::Dialect::Plotter
            ),
            switch_blends: linuxcnc.then(|| super::sync_links::tangent_limit_rad(machine)),
            corner_accel_ratio: if linuxcnc {
                BLEND_ACC_RATIO_NORMAL
            } else {
                1.0
            },
        }
    }

    /// The cruise speed of a move along unit direction `dir`, mm/s (0 when the feed is not a
    /// positive number). With limits per axis the maximum and rapid feeds grow along a
    /// diagonal ([`Kinematics::axis_scale`]).
    pub fn nominal_speed(&self, m: &Move, dir: DVec2) -> f64 {
        let scale = self.axis_scale(dir);
        let feed = if m.rapid {
            self.travel_feed_mm_min * scale
        } else {
            m.feed_mm_min.min(self.max_feed_mm_min * scale)
        };
        if feed.is_finite() && feed > 0.0 {
            feed / 60.0
        } else {
            0.0
        }
    }

    /// How much more than an axis's limit the path may take along unit vector `u`: with
    /// limits per axis (the same on X and Y), `1 / max(|uₓ|, |u_y|)` (√2 on a diagonal; GRBL's
    /// `limit_value_by_axis_maximum`), else 1.
    pub fn axis_scale(&self, u: DVec2) -> f64 {
        let largest = u.x.abs().max(u.y.abs());
        if self.per_axis && largest > 0.0 && largest.is_finite() {
            1.0 / largest
        } else {
            1.0
        }
    }

    fn has_acceleration(&self) -> bool {
        self.accel_mm_s2.is_finite() && self.accel_mm_s2 > 0.0
    }
}

/// Highest speed, mm/s, at which a machine may pass from a move along unit direction `d_in` to
/// one along unit direction `d_out` (junction deviation, see the module docs): 0 for a
/// reversal, infinite for a straight continuation.
pub fn junction_speed(d_in: DVec2, d_out: DVec2, accel_mm_s2: f64, deviation_mm: f64) -> f64 {
    // cos θ with θ between the reversed incoming and the outgoing direction.
    let cos_theta = (-d_in.dot(d_out)).clamp(-1.0, 1.0);
    let sin_half = ((1.0 - cos_theta) / 2.0).max(0.0).sqrt();
    if sin_half >= 1.0 - ROUNDOFF {
        return f64::INFINITY;
    }
    let v2 = accel_mm_s2 * deviation_mm * sin_half / (1.0 - sin_half);
    if v2.is_finite() && v2 > 0.0 {
        v2.sqrt()
    } else {
        0.0
    }
}

/// Seconds to run `length` mm entering at `v_entry`, leaving at `v_exit` and cruising at most at
/// `v_nominal` (mm/s), with acceleration `accel` (mm/s²). The caller guarantees the end speeds
/// are reachable (as the look-ahead passes do); they are clamped to `v_nominal`.
pub fn trapezoid_time(length: f64, v_entry: f64, v_exit: f64, v_nominal: f64, accel: f64) -> f64 {
    if length <= 0.0 || v_nominal <= 0.0 {
        return 0.0;
    }
    if !(accel.is_finite() && accel > 0.0) {
        return length / v_nominal;
    }
    let (v0, v1) = (v_entry.min(v_nominal), v_exit.min(v_nominal));
    let d_accel = (v_nominal * v_nominal - v0 * v0) / (2.0 * accel);
    let d_decel = (v_nominal * v_nominal - v1 * v1) / (2.0 * accel);
    if d_accel + d_decel <= length {
        (v_nominal - v0) / accel
            + (v_nominal - v1) / accel
            + (length - d_accel - d_decel) / v_nominal
    } else {
        let peak = ((2.0 * accel * length + v0 * v0 + v1 * v1) / 2.0)
            .sqrt()
            .max(v0.max(v1));
        (peak - v0) / accel + (peak - v1) / accel
    }
}

/// A move reduced to what the planner needs.
#[derive(Clone, Copy, Debug)]
struct Block {
    length: f64,
    rapid: bool,
    /// Acceleration along the move, mm/s².
    accel: f64,
    dir: DVec2,
    nominal: f64,
    /// Highest entry speed the junction allows.
    max_entry: f64,
    /// Planned entry speed.
    entry: f64,
    /// The move switches a synchronised output.
    sync: bool,
}

/// Seconds each move of `moves` takes from `start`, at rest before the first move and after
/// the last, with GRBL-style look-ahead (see the module docs). Zero-length moves and moves
/// without a positive feed take 0 s.
pub fn move_times(start: DVec2, moves: &[Move], kin: &Kinematics) -> Vec<f64> {
    let (blocks, index) = blocks(start, moves, kin);
    let entries = plan_entries(&blocks, kin.has_acceleration());
    let mut times = vec![0.0; moves.len()];
    for (i, b) in blocks.iter().enumerate() {
        let exit = entries.get(i + 1).copied().unwrap_or(0.0);
        times[index[i]] = if kin.has_acceleration() {
            trapezoid_time(b.length, entries[i], exit, b.nominal, b.accel)
        } else {
            b.length / b.nominal
        };
    }
    times
}

/// Seconds to run `moves` from `start`, at rest at both ends.
pub fn job_time(start: DVec2, moves: &[Move], machine: &MachineProfile) -> f64 {
    move_times(start, moves, &Kinematics::of(machine))
        .iter()
        .sum()
}

/// The moving blocks and, for each, the index of its move.
fn blocks(start: DVec2, moves: &[Move], kin: &Kinematics) -> (Vec<Block>, Vec<usize>) {
    let mut at = start;
    let mut out: Vec<Block> = Vec::with_capacity(moves.len());
    let mut index = Vec::with_capacity(moves.len());
    // A switch on a move that does not move waits for the next move that does.
    let mut sync = false;
    for (i, m) in moves.iter().enumerate() {
        let delta = m.to - at;
        let length = delta.length();
        let dir = delta / length;
        let nominal = kin.nominal_speed(m, dir);
        sync |= m.sync;
        if !(length.is_finite() && length > 0.0 && nominal > 0.0) {
            at = if m.to.is_finite() { m.to } else { at };
            continue;
        }
        let max_entry = match out.last() {
            None => 0.0,
            Some(prev) if kin.stops_between_rapid_and_feed && prev.rapid != m.rapid => 0.0,
            Some(prev) => {
                // The corner's centripetal acceleration points along the change of direction.
                let turn = (dir - prev.dir).normalize_or_zero();
                let accel = kin.accel_mm_s2 * kin.axis_scale(turn) * kin.corner_accel_ratio;
                junction_speed(prev.dir, dir, accel, kin.junction_deviation_mm)
                    .min(prev.nominal)
                    .min(nominal)
            }
        };
        out.push(Block {
            length,
            rapid: m.rapid,
            accel: kin.accel_mm_s2 * kin.axis_scale(dir),
            dir,
            nominal,
            max_entry,
            entry: 0.0,
            sync: std::mem::take(&mut sync),
        });
        index.push(i);
        at = m.to;
    }
    if let Some(tangent_rad) = kin.switch_blends {
        let normal_accel = kin.accel_mm_s2 * kin.corner_accel_ratio;
        cap_blends_beside_switches(&mut out, normal_accel, tangent_rad);
    }
    (out, index)
}

/// Caps each corner beside a move that switches a synchronised output, or beside the move
/// before one, by LinuxCNC's blend arc taking at most half of that move, with normal
/// acceleration `normal_accel` mm/s² (see the module docs); `tangent_rad` is LinuxCNC's tangent
/// limit (no corner below it).
fn cap_blends_beside_switches(blocks: &mut [Block], normal_accel: f64, tangent_rad: f64) {
    // Moves a blend arc cannot consume: a switch, and the move before it.
    let pinned: Vec<bool> = (0..blocks.len())
        .map(|i| blocks[i].sync || blocks.get(i + 1).is_some_and(|b| b.sync))
        .collect();
    for i in 1..blocks.len() {
        let (prev, this) = (&blocks[i - 1], &blocks[i]);
        // sin and cos of θ' (half the angle between the reversed incoming and the outgoing
        // move): θ' is 90° for a straight continuation.
        let sin_half = ((1.0 + prev.dir.dot(this.dir)) / 2.0)
            .clamp(0.0, 1.0)
            .sqrt();
        let cos_half = (1.0 - sin_half * sin_half).max(0.0).sqrt();
        let turn = prev.dir.perp_dot(this.dir).abs();
        let corner = turn > tangent_rad || prev.dir.dot(this.dir) <= 0.0;
        let halves = [(pinned[i - 1], prev.length), (pinned[i], this.length)]
            .iter()
            .filter(|(p, _)| *p)
            .map(|&(_, l)| l / 2.0)
            .fold(f64::INFINITY, f64::min);
        if !corner || !halves.is_finite() || cos_half <= 0.0 {
            continue;
        }
        let v = (normal_accel * sin_half / cos_half * halves).sqrt();
        blocks[i].max_entry = blocks[i].max_entry.min(v);
    }
}

/// Entry speeds after the backward (can stop in time) and forward (can get there) passes.
fn plan_entries(blocks: &[Block], accelerates: bool) -> Vec<f64> {
    let mut b: Vec<Block> = blocks.to_vec();
    if !accelerates {
        return b.iter().map(|x| x.max_entry).collect();
    }
    let mut next_entry = 0.0_f64;
    for blk in b.iter_mut().rev() {
        blk.entry = blk
            .max_entry
            .min((next_entry * next_entry + 2.0 * blk.accel * blk.length).sqrt());
        next_entry = blk.entry;
    }
    let mut prev: Option<(f64, f64, f64)> = None; // (entry, length, accel) of the previous block
    for blk in b.iter_mut() {
        if let Some((e, l, a)) = prev {
            blk.entry = blk.entry.min((e * e + 2.0 * a * l).sqrt());
        }
        prev = Some((blk.entry, blk.length, blk.accel));
    }
    b.iter().map(|x| x.entry).collect()
}

/// Moves timed in runs between stops: what a controller does when some commands (a spindle
/// word, a dwell, a pause) wait for motion to finish. The simulated machine and the plan's
/// estimate both time their moves through this.
#[derive(Clone, Debug)]
pub struct Timeline {
    kin: Kinematics,
    run: Vec<Move>,
    run_start: DVec2,
    at: DVec2,
    /// Seconds of the pieces of the current run already timed (see [`MAX_RUN_MOVES`]).
    banked_s: f64,
}

/// Most moves timed together: a longer run without a stop is timed in pieces of this many
/// moves, each ending at rest, so memory stays bounded however long the job is. A real
/// controller plans only a few dozen moves ahead (GRBL 1.1: 16), so the extra stop every
/// 65,536 moves costs far less time than the estimate's own error.
pub const MAX_RUN_MOVES: usize = 65_536;

impl Timeline {
    /// At rest at `start`.
    pub fn new(kin: Kinematics, start: DVec2) -> Self {
        Timeline {
            kin,
            run: Vec::new(),
            run_start: start,
            at: start,
            banked_s: 0.0,
        }
    }

    /// Where the last move ends, mm.
    pub fn at(&self) -> DVec2 {
        self.at
    }

    /// Adds a move to the current run.
    pub fn push(&mut self, m: Move) {
        self.run.push(m);
        self.at = m.to;
        if self.run.len() >= MAX_RUN_MOVES {
            self.banked_s += self.time_run();
        }
    }

    /// Brings the machine to rest; returns the seconds of the run since the last stop, with the
    /// controller's stop delay when there was a run (see [`Kinematics::stop_delay_s`]).
    pub fn stop(&mut self) -> f64 {
        let mut t = self.time_run() + self.banked_s;
        if t > 0.0 {
            t += self.kin.stop_delay_s;
        }
        self.banked_s = 0.0;
        t
    }

    /// Times the moves held, from rest to rest, and lets them go.
    fn time_run(&mut self) -> f64 {
        let t = move_times(self.run_start, &self.run, &self.kin)
            .iter()
            .sum();
        self.run.clear();
        self.run_start = self.at;
        t
    }
}
