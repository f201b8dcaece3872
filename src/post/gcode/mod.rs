//! G-code writers: GRBL, Marlin, LinuxCNC and pen plotters.
//!
//! Every program opens with a title comment (job and machine), a comment saying what the
//! firmware must be set to (GRBL laser mode `$32=1`, a plotter's `$32=0`, Marlin's build
//! options, LinuxCNC's output), one naming the source (the pattern's title, as generators and
//! most files give one) and the material, and one per operation with its settings (power as a
//! fraction and as the `S` written, speed, passes; dash and gap for a perforation), all in
//! ASCII without `;` or `%` inside, then millimetres (`G21`) and absolute (`G90`) once, the
//! dialect's arming line (laser at zero power, or pen up), then the machine's preamble without the lines already written,
//! then one comment per group of toolpaths of one operation (`; cut`, or `(cut)` on LinuxCNC)
//! with the air-assist word when it changes (`M7`/`M8`/`M9`, see
//! [`crate::machine::MachineControl`]) and, on a plotter, the pen-change lines (`M0`) between
//! groups; the toolpaths, the tool made safe, air off, the postamble without the lines already
//! written, and the dialect's program end, once. Travel is `G0` (on LinuxCNC, inside a pass,
//! `G1` at the travel feed: see below), burns are `G1`.
//!
//! **Numbers.** Coordinates are rounded to the machine's `resolution_mm` and printed exactly
//! (see `number`): no float noise, no `-0`, no exponents. Moves that round to zero length are
//! skipped, and so are strokes left without length. Feed `F` is the operation's speed clamped
//! to `max_feed_mm_min`, written on the first burn move and again only when it changes. Power
//! `S` = `power.min` + fraction × (`power.max` − `power.min`).
//!
//! **Passes.** A toolpath with `passes` = n is burned n times in a row, all its strokes each
//! time (pass after pass over the whole toolpath, not stroke by stroke), so a perforation line
//! cools between passes and a closed contour repeats without travel.
//!
//! **Dialects** (facts from the firmware documentation):
//!
//! - GRBL 1.1 with laser mode `$32=1` ([`grbl`]): `M4 S0` (dynamic power) or `M3 S0`
//!   (constant) once after the preamble; changing M3/M4/M5 makes GRBL stop, changing `S`
//!   inline does not, so every burn's first `G1` carries its `S`, and every travel is
//!   `G0 … S0`. GRBL already blanks the laser on `G0` in laser mode; the explicit `S0` keeps
//!   the laser off even on a controller left in spindle mode. `M5` before the postamble, `M2`.
//! - Marlin with `LASER_FEATURE` ([`marlin`]): `M3`/`M4` and `M5` wait for all moves to finish,
//!   so power is set inline instead: `M3 S0 I1` (or `M4 S0 I1`; Marlin reads a bool word as true
//!   when it is bare or non-zero, and `I1` keeps every word letter+number) once enables inline
//!   mode, then
//!   `G1 … S<power>` burns. Marlin's `G0` turns the laser off only when built with
//!   `LASER_MOVE_G0_OFF`, so every travel carries `S0` (needs `LASER_POWER_INLINE` and
//!   `LASER_MOVE_POWER`, Marlin 2.0.8 or later). Marlin's `G0` shares the modal feed with
//!   `G1` unless built with `VARIABLE_G0_FEEDRATE`, so travel writes `F<travel feed>` and the
//!   next burn its own `F` again. `M5` at the end; Marlin has no `M2`.
//! - LinuxCNC ([`linuxcnc`]): no laser mode; the profile's `laser_output` frames each stroke
//!   with `M3 S<power>` … `M5` (the spindle: LinuxCNC stops motion at each, so every dash is
//!   an exact stop), `M62 P<n>` … `M63 P<n>` (a digital output) or `M67 E<n> Q<power>` …
//!   `M67 E<n> Q0` (an analog output); the motion outputs are synchronised: they change at the
//!   start of the next move, without stopping. The immediate `M65`/`M68` turn the output off
//!   at the start and the end. Comments use parentheses; `M2` ends the program; no `%`
//!   framing. `M3` is used for both laser modes (`M4` is reverse rotation on LinuxCNC).
//!   LinuxCNC's planner cannot blend a rapid into a feed move (an exact stop at every
//!   `G0`↔`G1` switch), so on a synchronised output the travel between two burns of one pass
//!   of a toolpath (the dashes of a perforation, the strokes of one chain) is
//!   `G1 … F<travel feed>` with the beam off, and `G0` only leads to a toolpath or a pass
//!   ([`crate::machine::MachineProfile::links_burns_with_feed_moves`]); the profile's
//!   `blend_tolerance_mm` is written as `G64 P<mm>` after the arming line. LinuxCNC slows
//!   hard at a corner into a move that switches a synchronised output, so on a curve that
//!   travel leaves each burn along its last piece and reaches the next along its first (one
//!   corner in between), and a burn's very short end pieces are merged where the path allows
//!   ([`crate::machine::sync_links`]).
//! - Pen plotters ([`plotter`]), chosen by the `Plotter` dialect or by a machine that is not a
//!   laser: the profile's `pen_up` lines before every travel (and at the start and end), its
//!   `pen_down` lines before every stroke, each followed by `G4 P<pen delay>` in the profile's
//!   dwell unit (seconds on GRBL and LinuxCNC, milliseconds on Marlin); no `S` words except
//!   those the profile's own pen commands hold. Comments, travel feed and program end follow
//!   the dialect.
//! - `FileOnly` machines take no G-code: [`PostError::NoGcode`].

pub(crate) mod grbl;
pub(crate) mod linuxcnc;
pub(crate) mod marlin;
pub(crate) mod plotter;
mod program;

use super::{PostError, check};
use crate::fab::{FabPlan, Setup};
use crate::machine::{Dialect, MachineKind, MachineProfile};

/// What differs between dialects: arming, switching the tool, comments, the program end.
pub trait Flavour {
    /// A comment line holding `text`.
    fn comment(&self, text: &str) -> String {
        format!("; {}", one_line(text))
    }
    /// What the firmware must be set to for this program, for the header comment.
    fn expectation(&self) -> Option<String> {
        None
    }
    /// Whether burns use the `S` (power) word.
    fn uses_power(&self) -> bool;
    /// Lines after the preamble, before the first move.
    fn start(&self) -> Vec<String>;
    /// Words appended to every travel move (with a leading space), e.g. ` S0`.
    fn travel_words(&self) -> &str {
        ""
    }
    /// Whether travel moves carry the travel feed (`G0 … F…`) because the firmware's `G0`
    /// shares the modal feed with `G1`; the next burn then writes its feed again.
    fn travel_sets_feed(&self) -> bool {
        false
    }
    /// Lines before a stroke burned at power `s` (the printed `S` value).
    fn tool_on(&self, s: &str) -> Vec<String>;
    /// A word for the first burn move of a stroke at power `s`, e.g. `S350`.
    fn burn_word(&self, s: &str) -> Option<String>;
    /// Lines after a stroke.
    fn tool_off(&self) -> Vec<String>;
    /// Lines after the last stroke, before the postamble.
    fn finish(&self) -> Vec<String>;
    /// The program end line after the postamble, if the dialect has one.
    fn program_end(&self) -> Option<&str>;
}

/// The G-code of `job` on `machine` (see the module docs).
pub fn write(plan: &FabPlan, job: &Setup, machine: &MachineProfile) -> Result<String, PostError> {
    let flavour = flavour(machine)?;
    let grid = check::machine(machine, flavour.uses_power(), flavour.travel_sets_feed())?;
    check::job(job)?;
    for path in &job.paths {
        check::settings(
            path.op,
            &plan.settings_of(path, machine),
            flavour.uses_power(),
        )?;
    }
    program::write(plan, job, machine, flavour.as_ref(), grid)
}

/// A framing job for `job` on `machine` (LightBurn's Frame): the job's bounding box
/// ([`crate::fab::frame::outline`]) traced from its lower-left corner counter-clockwise, with
/// the tool off (travel moves only: no beam, the pen up) when `power` is 0 or the machine is a
/// pen tool, else burned once at `power` (a fraction of the machine's range) at the
/// material's `mark` speed. Header and trailer as in [`write`](fn@write).
///
/// # Errors
/// As [`write`](fn@write); [`PostError::BadSetting`] for a power outside 0..=1.
pub fn frame(
    plan: &FabPlan,
    job: &Setup,
    machine: &MachineProfile,
    power: f64,
) -> Result<String, PostError> {
    let flavour = flavour(machine)?;
    let grid = check::machine(machine, flavour.uses_power(), flavour.travel_sets_feed())?;
    check::job(job)?;
    let Some(outline) = crate::fab::frame::outline(job) else {
        return Err(PostError::EmptyJob {
            job: job.name.clone(),
        });
    };
    let lit = (power > 0.0 && !machine.pen_tool()).then_some(crate::machine::OperationSettings {
        power,
        passes: 1,
        ..plan.settings.mark
    });
    if let Some(s) = &lit {
        check::settings(crate::fab::Operation::Mark, s, flavour.uses_power())?;
    } else if !(0.0..=1.0).contains(&power) {
        return Err(PostError::BadSetting {
            op: "frame",
            key: "power",
            value: power,
            expected: "a fraction from 0 to 1",
        });
    }
    program::write_frame(plan, job, &outline, lit, machine, flavour.as_ref(), grid)
}

/// The writer for the machine's dialect and kind.
pub fn flavour(machine: &MachineProfile) -> Result<Box<dyn Flavour>, PostError> {
    let pen = machine.kind != MachineKind::Laser;
    Ok(match (machine.dialect, pen) {
        (Dialect::FileOnly, _) => {
            return Err(PostError::NoGcode {
                machine: machine.name.clone(),
            });
        }
        (Dialect::Plotter, _) | (_, true) => Box::new(plotter::Pen::new(machine)),
        (Dialect::Grbl, false) => Box::new(grbl::GrblLaser::new(machine.laser_mode)),
        (Dialect::Marlin, false) => Box::new(marlin::MarlinLaser::new(machine.laser_mode)),
        (Dialect::LinuxCnc, false) => Box::new(linuxcnc::LinuxCncLaser::new(
            machine.control.laser_output,
            machine.control.output_number,
            machine.control.blend_tolerance_mm,
        )),
    })
}

/// A command line compared loosely (see [`crate::machine::commands::normalize`]).
pub use crate::machine::commands::normalize;

/// `text` on one line: control characters become spaces.
pub fn one_line(text: &str) -> String {
    text.chars()
        .map(|c| if c.is_control() { ' ' } else { c })
        .collect()
}
