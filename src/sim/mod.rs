//! The simulated machine: reads G-code back, runs it on a [`MachineProfile`] and reports what
//! the machine would do — burns, travel, pierces, time — and every problem it finds.
//!
//! [`run`] reads the dialects foldcam writes (GRBL 1.1 laser mode, Marlin with a laser,
//! LinuxCNC, GRBL-style pen plotters); [`coverage()`] compares a run with the crease pattern
//! and job it was made from; [`render_png`] draws it.
//!
//! # Semantics modelled
//! - Words, comments, checksums, `%` and `$` lines as described in `parse`; the G and M codes
//!   listed in `block`. The state starts at (0, 0), millimetres, absolute, rapid mode, laser
//!   off, pen up, no feed. `G20` converts inches (axes and feed) to millimetres; `G91` makes X
//!   and Y relative. `Z` is read and ignored (no focus or pen height is modelled).
//! - **Laser.** The beam is on when `M3` or `M4` is active and `S` is above the profile's
//!   minimum. A feed move (`G1`) with the beam on is a burn. **Rapids:** GRBL's laser mode
//!   blanks the beam during `G0` in firmware, so on GRBL a `G0` never burns and is not flagged.
//!   Marlin and LinuxCNC keep the output on during `G0` (Marlin only turns it off when built
//!   with an option we cannot assume), so on those dialects a `G0` with the beam on is recorded
//!   as a burn *and* flagged as [`ViolationKind::LitTravel`].
//! - **Pen tools** (plotters, drag knives, or the plotter dialect): the pen goes down or up on a
//!   line equal (comments, case and blanks aside) to a line of the profile's `pen_down` or
//!   `pen_up` commands that the other list does not share; such a line does nothing else.
//!   A move with the pen down draws (a burn of power 0); a `G0` with the pen down is flagged
//!   as lit travel. Pen delays count only where the program dwells (`G4`).
//! - **Dwell** `G4 P` is seconds on GRBL and LinuxCNC and milliseconds on Marlin (per the
//!   profile's dwell unit); Marlin's `G4 S` is seconds. A dwell with the beam on burns in place
//!   (`lit_dwell_s`), except GRBL `M4`, whose power follows speed and is zero at rest.
//! - **Time** is the acceleration model of [`crate::machine::motion`], over runs of moves
//!   separated by stops: a dwell, a change of laser state (`M3 M4 M5`), a pen command, `M0 M1
//!   M400`, coolant (`M7 M8 M9`), LinuxCNC's immediate outputs (`M64 M65 M68`), a `$`
//!   command, the end. `S` changes inline and LinuxCNC's synchronised outputs (`M62 M63 M67`,
//!   applied at the start of the next move) do not stop.
//! - **LinuxCNC motion outputs.** The profile's `laser_output` and `output_number` say which
//!   output carries the beam: a digital one is on or off (burns at full power), an analog one
//!   carries the power in `S` units (on above the power minimum).
//! - **Violations** (each with its line): a move ending outside the bed `[0, w] × [0, h]`
//!   (half the resolution of slack), lit travel, `S` outside the profile's power range, a feed
//!   above the maximum, a feed move before any `F`, unknown words and codes, unsupported
//!   commands (arcs), malformed text, wrong checksums, the tool left on without `M2`/`M30`.
//!
//! Not modelled: arcs, work offsets, per-axis limits, M4's power scaling (burns carry the
//! programmed `S`), spindle spin-up, anything after `M2`/`M30` (ignored as the firmware does).

mod block;
mod coverage;
mod execute;
mod grid;
mod parse;
mod raster;
mod render;
mod report;

pub use coverage::{
    CoverageOptions, CoverageReport, EdgeCoverage, StrayBurn, coverage, coverage_with,
};
pub use parse::MAX_NUMBER;
pub use render::{JobNames, render_png, toolpath_title};
pub use report::{
    Bounds, Burn, MAX_VIOLATIONS, OperationStart, PowerLength, SimReport, Travel, Violation,
    ViolationKind,
};

use crate::machine::{Dialect, MachineProfile};
use execute::Machine;
use parse::{Line, parse_line};

/// Most lines read from one program.
pub const MAX_LINES: usize = 5_000_000;
/// Longest line accepted, bytes.
pub const MAX_LINE_BYTES: usize = 1024;

/// Why a program could not be read at all (problems inside a readable program are
/// [`Violation`]s in the report).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SimError {
    /// More than [`MAX_LINES`] lines.
    #[error("the program has more than {limit} lines")]
    TooManyLines {
        /// The limit.
        limit: usize,
    },
    /// A line longer than [`MAX_LINE_BYTES`].
    #[error("line {line}: longer than {limit} bytes")]
    LineTooLong {
        /// Line number, from 1.
        line: usize,
        /// The limit.
        limit: usize,
    },
    /// The program could not be read.
    #[error("line {line}: {message}")]
    Read {
        /// Line number, from 1.
        line: usize,
        /// What went wrong.
        message: String,
    },
    /// The profile takes no G-code.
    #[error("machine {machine} takes no G-code (dialect file-only)")]
    NoGcode {
        /// The profile name.
        machine: String,
    },
}

/// Runs the G-code `text` on `machine` and reports what it does (every burn and travel kept
/// in the report).
pub fn run(text: &str, machine: &MachineProfile) -> Result<SimReport, SimError> {
    let mut m = start(machine, true)?;
    let mut last = 0;
    for (i, raw) in text.lines().enumerate() {
        last = i + 1;
        feed(&mut m, last, raw)?;
    }
    Ok(end(m, last))
}

/// Runs the G-code read from `reader` line by line, without holding the program: with
/// `keep_moves` false the report holds only totals (no [`SimReport::burns`] or
/// [`SimReport::travels`]), so memory does not grow with the job's length. `on_line` is called
/// with the bytes read so far every 65,536 lines (for a progress bar).
pub fn run_reader<R: std::io::BufRead>(
    mut reader: R,
    machine: &MachineProfile,
    keep_moves: bool,
    mut on_line: impl FnMut(u64),
) -> Result<SimReport, SimError> {
    use std::io::BufRead as _;
    let mut m = start(machine, keep_moves)?;
    let mut buf = Vec::with_capacity(MAX_LINE_BYTES + 2);
    let (mut last, mut bytes) = (0, 0u64);
    loop {
        buf.clear();
        let limit = (MAX_LINE_BYTES + 2) as u64;
        let n = std::io::Read::take(&mut reader, limit)
            .read_until(b'\n', &mut buf)
            .map_err(|e| SimError::Read {
                line: last + 1,
                message: e.to_string(),
            })?;
        if n == 0 {
            break;
        }
        last += 1;
        bytes += n as u64;
        if last % 65_536 == 0 {
            on_line(bytes);
        }
        let text = buf.strip_suffix(b"\n").unwrap_or(&buf);
        if text.len() == buf.len() && n as u64 == limit {
            let limit = MAX_LINE_BYTES;
            return Err(SimError::LineTooLong { line: last, limit });
        }
        let text = text.strip_suffix(b"\r").unwrap_or(text);
        let raw = std::str::from_utf8(text).map_err(|_| SimError::Read {
            line: last,
            message: "not UTF-8 text".into(),
        })?;
        feed(&mut m, last, raw)?;
    }
    Ok(end(m, last))
}

/// A machine ready to run on `machine`.
fn start(machine: &MachineProfile, keep_moves: bool) -> Result<Machine<'_>, SimError> {
    if machine.dialect == Dialect::FileOnly {
        return Err(SimError::NoGcode {
            machine: machine.name.clone(),
        });
    }
    let mut m = Machine::new(machine);
    m.report.keep_moves = keep_moves;
    Ok(m)
}

/// Runs line `line` (from 1), checking the line limits.
fn feed(m: &mut Machine, line: usize, raw: &str) -> Result<(), SimError> {
    if line > MAX_LINES {
        return Err(SimError::TooManyLines { limit: MAX_LINES });
    }
    if raw.len() > MAX_LINE_BYTES {
        let limit = MAX_LINE_BYTES;
        return Err(SimError::LineTooLong { line, limit });
    }
    if !m.ended {
        step(m, line, raw);
    }
    Ok(())
}

/// The report after `last` lines.
fn end(mut m: Machine, last: usize) -> SimReport {
    m.report.lines = last;
    m.finish(last.max(1))
}

/// Runs one line.
fn step(m: &mut Machine, line: usize, raw: &str) {
    if m.report.keep_moves {
        let named = parse::comment_only(raw).and_then(crate::fab::Operation::from_name);
        if let Some(operation) = named {
            m.report.operations.push(OperationStart { line, operation });
        }
    }
    if let Some(down) = m.pens.matches(raw) {
        m.set_pen(down);
        return;
    }
    match parse_line(raw) {
        Err(e) => m.report.flag(line, e.kind, e.message),
        Ok(Line::Empty | Line::Percent) => {}
        Ok(Line::System(cmd)) => system(m, line, &cmd),
        Ok(Line::Words(words)) => match block::decode(&words, m.report.dialect) {
            Ok(b) => m.execute(line, &b),
            Err(e) => m.report.flag(line, e.kind, e.message),
        },
    }
}

/// A GRBL `$` command: runs when the machine is idle, no effect on the job.
fn system(m: &mut Machine, line: usize, cmd: &str) {
    if m.report.dialect == Dialect::Grbl {
        m.stop();
    } else {
        let msg = format!("`${cmd}` is a GRBL system command");
        m.report.flag(line, ViolationKind::UnknownWord, msg);
    }
}

/// The profile's pen commands, normalised, keeping the lines that tell up from down.
pub(crate) struct PenCommands {
    down: Vec<String>,
    up: Vec<String>,
}

impl PenCommands {
    pub(crate) fn of(machine: &MachineProfile) -> Self {
        let norm = |v: &[String]| -> Vec<String> {
            v.iter()
                .map(|s| parse::normalize(s))
                .filter(|s| !s.is_empty())
                .collect()
        };
        let (down, up) = (norm(&machine.pen_down), norm(&machine.pen_up));
        let pen_tool = machine.kind != crate::machine::MachineKind::Laser
            || machine.dialect == Dialect::Plotter;
        if !pen_tool {
            return PenCommands {
                down: Vec::new(),
                up: Vec::new(),
            };
        }
        PenCommands {
            down: down.iter().filter(|d| !up.contains(d)).cloned().collect(),
            up: up.iter().filter(|u| !down.contains(u)).cloned().collect(),
        }
    }

    /// `Some(true)` for a pen-down line, `Some(false)` for pen up.
    fn matches(&self, raw: &str) -> Option<bool> {
        if self.down.is_empty() && self.up.is_empty() {
            return None;
        }
        let n = parse::normalize(raw);
        if self.down.contains(&n) {
            Some(true)
        } else if self.up.contains(&n) {
            Some(false)
        } else {
            None
        }
    }
}
