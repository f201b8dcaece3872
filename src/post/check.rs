//! Validation before writing: no NaN, infinity or out-of-range number reaches a machine file.
//!
//! Every writer checks the job's coordinates; the G-code writer also checks the machine and
//! the settings it uses. Limits: coordinates within ±[`MAX_COORD_MM`], resolutions from
//! [`MIN_RESOLUTION_MM`] to [`MAX_RESOLUTION_MM`], feeds positive, power fractions in 0..=1,
//! at least one pass, pen delays up to a minute, command lines without line breaks.

use super::PostError;
use super::number::Grid;
use crate::fab::{Operation, Setup};
use crate::machine::{MachineProfile, OperationSettings};

/// Largest coordinate magnitude written, mm.
pub const MAX_COORD_MM: f64 = 1e9;
/// Longest pen delay accepted, seconds.
pub const MAX_PEN_DELAY_S: f64 = 60.0;
/// Finest machine resolution accepted, mm.
pub const MIN_RESOLUTION_MM: f64 = 1e-6;
/// Coarsest machine resolution accepted, mm.
pub const MAX_RESOLUTION_MM: f64 = 10.0;

/// Every coordinate of `job` is finite and within ±[`MAX_COORD_MM`].
pub fn job(job: &Setup) -> Result<(), PostError> {
    for (path, toolpath) in job.paths.iter().enumerate() {
        for (stroke, points) in toolpath.strokes.iter().enumerate() {
            let bad = points.iter().any(|p| {
                !(p.x.is_finite() && p.y.is_finite())
                    || p.x.abs() > MAX_COORD_MM
                    || p.y.abs() > MAX_COORD_MM
            });
            if bad {
                return Err(PostError::BadCoordinate {
                    job: job.name.clone(),
                    path,
                    stroke,
                });
            }
        }
    }
    Ok(())
}

/// The settings of `op` are usable: a positive finite feed, at least one pass and, when
/// `uses_power`, a power fraction in 0..=1.
pub fn settings(op: Operation, s: &OperationSettings, uses_power: bool) -> Result<(), PostError> {
    let bad = |key, value, expected| PostError::BadSetting {
        op: op.name(),
        key,
        value,
        expected,
    };
    if !(s.speed_mm_min.is_finite() && s.speed_mm_min > 0.0) {
        return Err(bad(
            "speed_mm_min",
            s.speed_mm_min,
            "a positive feed in mm/min",
        ));
    }
    if uses_power && !(0.0..=1.0).contains(&s.power) {
        return Err(bad("power", s.power, "a fraction from 0 to 1"));
    }
    if s.passes == 0 {
        return Err(bad("passes", 0.0, "at least 1"));
    }
    Ok(())
}

/// The machine numbers the G-code writer uses are sane (power only when `uses_power`, the
/// travel feed only when `uses_travel_feed`); returns the coordinate grid.
pub fn machine(
    m: &MachineProfile,
    uses_power: bool,
    uses_travel_feed: bool,
) -> Result<Grid, PostError> {
    let bad = |key, message: String| PostError::BadMachine {
        machine: m.name.clone(),
        key,
        message,
    };
    let res = m.resolution_mm;
    if !(MIN_RESOLUTION_MM..=MAX_RESOLUTION_MM).contains(&res) {
        let msg = format!("{res}: expected {MIN_RESOLUTION_MM} to {MAX_RESOLUTION_MM} mm");
        return Err(bad("resolution_mm", msg));
    }
    if !(m.max_feed_mm_min.is_finite() && m.max_feed_mm_min > 0.0) {
        let msg = format!("{}: expected a positive feed", m.max_feed_mm_min);
        return Err(bad("max_feed_mm_min", msg));
    }
    let travel = m.travel_feed_mm_min;
    if uses_travel_feed && !(travel.is_finite() && travel > 0.0) {
        return Err(bad(
            "travel_feed_mm_min",
            format!("{travel}: expected a positive feed"),
        ));
    }
    let power_ok = m.power.min.is_finite() && m.power.max.is_finite() && m.power.min <= m.power.max;
    if uses_power && !(power_ok && m.power.min >= 0.0) {
        let msg = format!("{}..{}: expected 0 <= min <= max", m.power.min, m.power.max);
        return Err(bad("power", msg));
    }
    if !(0.0..=MAX_PEN_DELAY_S).contains(&m.pen_delay_s) {
        let msg = format!("{}: expected 0 to {MAX_PEN_DELAY_S} seconds", m.pen_delay_s);
        return Err(bad("pen_delay_s", msg));
    }
    command_lines(m, &bad)?;
    Grid::new(res).ok_or_else(|| bad("resolution_mm", format!("{res}")))
}

/// Preamble, postamble and pen lines hold one line each.
fn command_lines(
    m: &MachineProfile,
    bad: &dyn Fn(&'static str, String) -> PostError,
) -> Result<(), PostError> {
    let lists: [(&'static str, &Vec<String>); 4] = [
        ("preamble", &m.preamble),
        ("postamble", &m.postamble),
        ("pen_up", &m.pen_up),
        ("pen_down", &m.pen_down),
    ];
    for (key, lines) in lists {
        if let Some(line) = lines.iter().find(|l| l.contains(['\n', '\r'])) {
            return Err(bad(key, format!("{line:?}: expected one line per entry")));
        }
    }
    Ok(())
}
