//! What a simulated run found: burns, travel, time and violations.

use glam::DVec2;
use serde::Serialize;

use crate::fab::Operation;
use crate::machine::{Dialect, PowerRange, SettingsByOperation};

/// Most violations kept in a report; further ones are only counted.
pub const MAX_VIOLATIONS: usize = 1000;

/// The kind of a problem found in a program.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum ViolationKind {
    /// A move ends outside the bed `[0, width] × [0, height]`.
    OutOfBed,
    /// A rapid (G0) with the tool burning or drawing, on a machine that does not blank it.
    LitTravel,
    /// `S` outside the profile's power range.
    PowerOutOfRange,
    /// A feed above the machine's maximum.
    FeedTooHigh,
    /// A feed move before any `F` was given.
    MissingFeed,
    /// A letter or G/M code the simulator does not know.
    UnknownWord,
    /// A known command the simulator does not model (arcs, offsets, block delete).
    Unsupported,
    /// A line that cannot be read (bad number, unclosed comment, repeated word).
    Malformed,
    /// A `*NN` checksum that does not match.
    Checksum,
    /// The program ends with the laser on or the pen down.
    ToolLeftOn,
}

impl std::fmt::Display for ViolationKind {
    /// Words a machine user knows, e.g. "power out of range".
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Self::OutOfBed => "outside the bed",
            Self::LitTravel => "rapid move with the tool on",
            Self::PowerOutOfRange => "power out of range",
            Self::FeedTooHigh => "feed above the machine's maximum",
            Self::MissingFeed => "feed move without a feed rate",
            Self::UnknownWord => "unknown word",
            Self::Unsupported => "unsupported command",
            Self::Malformed => "unreadable line",
            Self::Checksum => "checksum mismatch",
            Self::ToolLeftOn => "tool left on at the end",
        })
    }
}

/// One problem, with the 1-based line number it was found on.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Violation {
    /// Line number, counting from 1.
    pub line: usize,
    /// Kind of problem.
    pub kind: ViolationKind,
    /// What is wrong.
    pub message: String,
}

/// One straight burn (laser on) or stroke (pen down), machine coordinates.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Burn {
    /// Line number of the move.
    pub line: usize,
    /// Start, mm.
    pub from: DVec2,
    /// End, mm.
    pub to: DVec2,
    /// `S` in effect, clamped to the profile's range; 0 for pen strokes.
    pub power: f64,
    /// Feed the machine runs, mm/min (the programmed feed capped at the maximum; the travel
    /// feed for a lit rapid).
    pub feed_mm_min: f64,
}

impl Burn {
    /// Length, mm.
    pub fn length(&self) -> f64 {
        self.from.distance(self.to)
    }
}

/// One straight move with the tool off, machine coordinates.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Travel {
    /// Line number of the move.
    pub line: usize,
    /// Start, mm.
    pub from: DVec2,
    /// End, mm.
    pub to: DVec2,
}

/// The first line of a group of moves of one operation, as the program's comments name it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct OperationStart {
    /// Line number of the comment, from 1.
    pub line: usize,
    /// The operation it names.
    pub operation: Operation,
}

/// Burn length at one power level.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct PowerLength {
    /// `S` value.
    pub power: f64,
    /// Burn length, mm.
    pub length_mm: f64,
}

/// A key ordering `f64` as [`f64::total_cmp`] does.
fn total_order_key(x: f64) -> i64 {
    let bits = x.to_bits() as i64;
    bits ^ (((bits >> 63) as u64) >> 1) as i64
}

/// An axis-aligned box, mm.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Bounds {
    /// Lower-left corner.
    pub min: DVec2,
    /// Upper-right corner.
    pub max: DVec2,
}

impl Bounds {
    /// The box of one point.
    pub fn point(p: DVec2) -> Self {
        Bounds { min: p, max: p }
    }

    /// Grows the box to hold `p`.
    pub fn include(&mut self, p: DVec2) {
        self.min = self.min.min(p);
        self.max = self.max.max(p);
    }
}

/// Everything a simulated run found.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct SimReport {
    /// The profile's name.
    pub machine: String,
    /// The dialect the program was read as.
    pub dialect: Dialect,
    /// The profile's power range (to map `S` back to a fraction).
    pub power_range: PowerRange,
    /// Lines read.
    pub lines: usize,
    /// Burns (laser on or pen down), in program order.
    pub burns: Vec<Burn>,
    /// Tool-off moves, in program order.
    pub travels: Vec<Travel>,
    /// Total burn length, mm.
    pub burn_length_mm: f64,
    /// Burn length per `S` value, ascending.
    pub burn_by_power: Vec<PowerLength>,
    /// Total travel length, mm.
    pub travel_length_mm: f64,
    /// Moves that start a burn after the tool was off.
    pub pierces: usize,
    /// Estimated run time, s (motion with acceleration, plus dwells).
    pub time_s: f64,
    /// Time spent in `G4` dwells, s (included in `time_s`).
    pub dwell_s: f64,
    /// Dwell time with the laser burning in place, s (GRBL `M3`, or any lit dwell elsewhere).
    pub lit_dwell_s: f64,
    /// Box of all burns, `None` when nothing burns.
    pub burn_bounds: Option<Bounds>,
    /// Problems found, at most [`MAX_VIOLATIONS`], in line order.
    pub violations: Vec<Violation>,
    /// Number of problems found, including those not kept.
    pub violation_count: usize,
    /// Where the tool is at the end, mm.
    pub end_position: DVec2,
    /// Where the program's own comments start a group of one operation, in line order: a
    /// comment line whose text is exactly an operation's name (`; perforate`, `(cut)`), as
    /// foldcam's writers head every group. Kept only with the moves; empty for programs
    /// without such comments.
    #[serde(skip)]
    pub operations: Vec<OperationStart>,
    /// Keep every burn and travel in [`SimReport::burns`] and [`SimReport::travels`]
    /// (needed by coverage, pictures and JSON); without, the run takes memory independent of
    /// the job's length and only the totals are filled.
    #[serde(skip)]
    pub(crate) keep_moves: bool,
    /// Burn length per power, keyed by the power's bits in total order (see
    /// [`SimReport::total_by_power`]).
    #[serde(skip)]
    power_totals: std::collections::BTreeMap<i64, (f64, f64)>,
}

impl SimReport {
    /// An empty report.
    pub(crate) fn new(machine: &str, dialect: Dialect, power_range: PowerRange) -> Self {
        SimReport {
            machine: machine.to_string(),
            dialect,
            power_range,
            lines: 0,
            burns: Vec::new(),
            travels: Vec::new(),
            burn_length_mm: 0.0,
            burn_by_power: Vec::new(),
            travel_length_mm: 0.0,
            pierces: 0,
            time_s: 0.0,
            dwell_s: 0.0,
            lit_dwell_s: 0.0,
            burn_bounds: None,
            violations: Vec::new(),
            violation_count: 0,
            end_position: DVec2::ZERO,
            operations: Vec::new(),
            keep_moves: true,
            power_totals: std::collections::BTreeMap::new(),
        }
    }

    /// True when no violation was found.
    pub fn is_clean(&self) -> bool {
        self.violation_count == 0
    }

    /// The violations of one kind.
    pub fn violations_of(&self, kind: ViolationKind) -> impl Iterator<Item = &Violation> {
        self.violations.iter().filter(move |v| v.kind == kind)
    }

    /// Records a violation.
    pub(crate) fn flag(&mut self, line: usize, kind: ViolationKind, message: impl Into<String>) {
        self.violation_count += 1;
        if self.violations.len() < MAX_VIOLATIONS {
            self.violations.push(Violation {
                line,
                kind,
                message: message.into(),
            });
        }
    }

    /// Records a burn.
    pub(crate) fn add_burn(&mut self, burn: Burn) {
        self.burn_length_mm += burn.length();
        let bounds = self.burn_bounds.get_or_insert(Bounds::point(burn.from));
        bounds.include(burn.from);
        bounds.include(burn.to);
        let total = self
            .power_totals
            .entry(total_order_key(burn.power))
            .or_insert((burn.power, 0.0));
        total.1 += burn.length();
        if self.keep_moves {
            self.burns.push(burn);
        }
    }

    /// Lists the burn length per power level, ascending (once, at the end of a run).
    pub(crate) fn total_by_power(&mut self) {
        self.burn_by_power = self
            .power_totals
            .values()
            .map(|&(power, length_mm)| PowerLength { power, length_mm })
            .collect();
    }

    /// Records a tool-off move.
    pub(crate) fn add_travel(&mut self, travel: Travel) {
        self.travel_length_mm += travel.from.distance(travel.to);
        if self.keep_moves {
            self.travels.push(travel);
        }
    }

    /// Burn length per operation, mapping each burn's power back to the operation whose
    /// setting it matches within `tolerance` (a fraction of the range; the closest wins), in
    /// [`Operation::ALL`] order, as in a plan's statistics. Burns matching no operation are
    /// summed under `None`. Pen strokes belong to [`Operation::Plot`].
    pub fn burn_by_operation(
        &self,
        settings: &SettingsByOperation,
        tolerance: f64,
    ) -> Vec<(Option<Operation>, f64)> {
        let mut totals: Vec<(Option<Operation>, f64)> = Operation::ALL
            .iter()
            .map(|&op| (Some(op), 0.0))
            .chain([(None, 0.0)])
            .collect();
        for level in &self.burn_by_power {
            let op = self.operation_of(level.power, settings, tolerance);
            if let Some(t) = totals.iter_mut().find(|t| t.0 == op) {
                t.1 += level.length_mm;
            }
        }
        totals.retain(|t| t.1 > 0.0);
        totals
    }

    fn operation_of(
        &self,
        power: f64,
        settings: &SettingsByOperation,
        tolerance: f64,
    ) -> Option<Operation> {
        if self.dialect == Dialect::Plotter {
            return Some(Operation::Plot);
        }
        let f = self.power_fraction(power);
        Operation::ALL
            .into_iter()
            .filter(|&op| op != Operation::Plot)
            .map(|op| (op, (settings.get(op).power - f).abs()))
            .filter(|&(_, d)| d <= tolerance)
            .min_by(|a, b| a.1.total_cmp(&b.1))
            .map(|(op, _)| op)
    }

    /// The operation whose group holds line `line`, as the program's comments name it
    /// ([`SimReport::operations`]); `None` before the first such comment.
    pub fn operation_at(&self, line: usize) -> Option<Operation> {
        let k = self.operations.partition_point(|s| s.line <= line);
        k.checked_sub(1).map(|k| self.operations[k].operation)
    }

    /// The power of `s` as a fraction of the profile's range, 0..=1.
    pub fn power_fraction(&self, s: f64) -> f64 {
        let span = self.power_range.max - self.power_range.min;
        if span > 0.0 {
            ((s - self.power_range.min) / span).clamp(0.0, 1.0)
        } else {
            1.0
        }
    }
}
