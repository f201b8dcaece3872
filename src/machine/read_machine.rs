//! `machines/NAME.toml` → [`MachineProfile`], every key checked.
//!
//! Layout (all keys are listed in `machines/README.md`): top-level `description`, `kind`,
//! `dialect`, feeds, acceleration, junction deviation, resolution, `laser_mode`, `dwell_unit`,
//! `preamble`, `postamble`; tables `[bed]`, `[power]` and `[pen]`. Ranges accepted:
//!
//! | key | range |
//! | --- | --- |
//! | `bed.width_mm`, `bed.height_mm` | 1 – 10 000 mm |
//! | `max_feed_mm_min` | 1 – 1 000 000 mm/min; `travel_feed_mm_min` at most that |
//! | `acceleration_mm_s2` | 1 – 100 000 mm/s² |
//! | `junction_deviation_mm` | 0 – 1 mm |
//! | `blend_tolerance_mm` (LinuxCNC lasers) | 0.0001 – 1 mm |
//! | `step_idle_delay_ms` (GRBL, plotter) | 0 – 255 ms (255: no wait) |
//! | `resolution_mm` | 0.00001 – 0.1 mm |
//! | `power.min` < `power.max` | 0 – 1 000 000 (`S` units) |
//! | `pen.delay_s` | 0 – 10 s |
//!
//! `[power]` and `laser_mode` are required for a laser that takes G-code, `[pen]` for a
//! plotter or drag knife that does; elsewhere they may be left out (power defaults to GRBL's
//! `S0–1000`, the mode to `constant`). `dwell_unit` may be left out; when given it must match
//! the dialect (`G4 P` is seconds on GRBL and LinuxCNC, milliseconds on Marlin), since a
//! mismatch makes every dwell 1000 times too long or too short.

use toml::Table;

use super::ProfileError;
use super::control::{AirAssist, LaserOutput, MachineControl};
use super::fields::Fields;
use super::profile::{
    Bed, Corner, Dialect, DwellUnit, LaserMode, MachineKind, MachineProfile, PowerRange,
};
use crate::limits;

/// GRBL's default `$30` (`S` at full power), used when a non-laser profile has no `[power]`.
const DEFAULT_S_MAX: f64 = 1000.0;

/// Reads and validates a machine from the parsed TOML `table` of `source` named `name`.
pub(crate) fn machine_from_table(
    name: &str,
    source: &str,
    table: &Table,
) -> Result<MachineProfile, ProfileError> {
    let mut f = Fields::root(source, table);
    let description = f.text_line("description")?;
    let kind = MachineKind::ALL[f.choice("kind", &MachineKind::ALL.map(MachineKind::name))?];
    let dialect = Dialect::ALL[f.choice("dialect", &Dialect::ALL.map(Dialect::name))?];
    check_kind_dialect(&f, kind, dialect)?;
    let needs_laser = kind == MachineKind::Laser && dialect != Dialect::FileOnly;
    let needs_pen = kind != MachineKind::Laser && dialect != Dialect::FileOnly;
    let bed = read_bed(f.table("bed")?)?;
    let max_feed_mm_min = f.limited("max_feed_mm_min", &limits::FEED)?;
    let travel_feed_mm_min = f.number(
        "travel_feed_mm_min",
        1.0,
        max_feed_mm_min,
        "mm/min (at most max_feed_mm_min)",
    )?;
    let acceleration_mm_s2 = f.number("acceleration_mm_s2", 1.0, 1e5, "mm/s²")?;
    let junction_deviation_mm = f.number("junction_deviation_mm", 0.0, 1.0, "mm")?;
    let resolution_mm = f.limited("resolution_mm", &limits::MACHINE_RESOLUTION)?;
    let power = read_power(&mut f, needs_laser)?;
    let laser_mode = read_laser_mode(&mut f, needs_laser)?;
    let dwell_unit = read_dwell_unit(&mut f, dialect)?;
    let (pen_up, pen_down, pen_delay_s) = read_pen(&mut f, needs_pen)?;
    let preamble = f.lines("preamble")?;
    let postamble = f.lines("postamble")?;
    let control = read_control(&mut f, kind, dialect)?;
    f.finish()?;
    Ok(MachineProfile {
        name: name.to_string(),
        description,
        kind,
        dialect,
        bed,
        max_feed_mm_min,
        travel_feed_mm_min,
        acceleration_mm_s2,
        junction_deviation_mm,
        power,
        laser_mode,
        dwell_unit,
        resolution_mm,
        pen_up,
        pen_down,
        pen_delay_s,
        preamble,
        postamble,
        control,
    })
}

/// A plotter dialect drives no laser.
fn check_kind_dialect(f: &Fields, kind: MachineKind, dialect: Dialect) -> Result<(), ProfileError> {
    if kind == MachineKind::Laser && dialect == Dialect::Plotter {
        let message = "got \"plotter\", which has no laser power; a laser takes \"grbl\", \
                       \"marlin\", \"linuxcnc\" or \"file-only\"";
        return Err(f.error("dialect", message));
    }
    Ok(())
}

fn read_bed(mut t: Fields) -> Result<Bed, ProfileError> {
    let width_mm = t.limited("width_mm", &limits::BED_SIZE)?;
    let height_mm = t.limited("height_mm", &limits::BED_SIZE)?;
    let origin = Corner::ALL[t.choice("origin", &Corner::ALL.map(Corner::name))?];
    let y_flipped = t.bool_or("y_flipped", false)?;
    t.finish()?;
    Ok(Bed {
        width_mm,
        height_mm,
        origin,
        y_flipped,
    })
}

fn read_power(f: &mut Fields, required: bool) -> Result<PowerRange, ProfileError> {
    let table = if required {
        Some(f.table("power")?)
    } else {
        f.opt_table("power")?
    };
    let Some(mut t) = table else {
        return Ok(PowerRange {
            min: 0.0,
            max: DEFAULT_S_MAX,
        });
    };
    let min = t.number("min", 0.0, 1e6, "(S units)")?;
    let max = t.number("max", 0.0, 1e6, "(S units)")?;
    if max <= min {
        return Err(t.error(
            "max",
            format!("got {max}, which is not above power.min = {min}"),
        ));
    }
    t.finish()?;
    Ok(PowerRange { min, max })
}

fn read_laser_mode(f: &mut Fields, required: bool) -> Result<LaserMode, ProfileError> {
    let names = LaserMode::ALL.map(LaserMode::name);
    let index = if required {
        Some(f.choice("laser_mode", &names)?)
    } else {
        f.opt_choice("laser_mode", &names)?
    };
    Ok(index.map_or(LaserMode::Constant, |i| LaserMode::ALL[i]))
}

fn read_dwell_unit(f: &mut Fields, dialect: Dialect) -> Result<DwellUnit, ProfileError> {
    let expected = dialect.dwell_unit();
    let Some(i) = f.opt_choice("dwell_unit", &DwellUnit::ALL.map(DwellUnit::name))? else {
        return Ok(expected);
    };
    let unit = DwellUnit::ALL[i];
    if unit != expected {
        let message = format!(
            "got \"{}\", but {} reads G4 P in {}",
            unit.name(),
            dialect.name(),
            expected.name()
        );
        return Err(f.error("dwell_unit", message));
    }
    Ok(unit)
}

type Pen = (Vec<String>, Vec<String>, f64);

fn read_pen(f: &mut Fields, required: bool) -> Result<Pen, ProfileError> {
    let table = if required {
        Some(f.table("pen")?)
    } else {
        f.opt_table("pen")?
    };
    let Some(mut t) = table else {
        return Ok((Vec::new(), Vec::new(), 0.0));
    };
    let up = t.lines("up")?;
    let down = t.lines("down")?;
    for (key, lines) in [("up", &up), ("down", &down)] {
        if lines.is_empty() {
            return Err(t.error(key, "missing or empty; expected at least one command line"));
        }
    }
    let delay = t.number("delay_s", 0.0, 10.0, "s")?;
    t.finish()?;
    Ok((up, down, delay))
}

/// Highest LinuxCNC motion I/O number (`num_dio`/`num_aio` go up to 64).
const MAX_OUTPUT_NUMBER: i64 = 63;

/// Accepted `blend_tolerance_mm` (LinuxCNC's `G64 P`), mm: above zero (`G64 P0` would let
/// LinuxCNC blend without any tolerance) and at most 1 mm, as `junction_deviation_mm`.
const BLEND_TOLERANCE_MM: (f64, f64) = (0.0001, 1.0);

/// The optional shop-floor keys: `laser_output`, `output_number` and `blend_tolerance_mm`
/// (LinuxCNC lasers only), `step_idle_delay_ms` (GRBL's `$1`),
/// `air_assist` (`M7` or `M8`) with `air_assist_operations`, `pen_change` (plotters).
fn read_control(
    f: &mut Fields,
    kind: MachineKind,
    dialect: Dialect,
) -> Result<MachineControl, ProfileError> {
    let mut control = MachineControl::default();
    let linuxcnc_laser = kind == MachineKind::Laser && dialect == Dialect::LinuxCnc;
    for key in ["laser_output", "output_number", "blend_tolerance_mm"] {
        if f.has(key) && !linuxcnc_laser {
            return Err(f.error(key, "applies only to a laser with dialect \"linuxcnc\""));
        }
    }
    if let Some(i) = f.opt_choice("laser_output", &LaserOutput::ALL.map(LaserOutput::name))? {
        control.laser_output = LaserOutput::ALL[i];
    }
    if f.has("output_number") {
        control.output_number = f.integer("output_number", 0, MAX_OUTPUT_NUMBER)? as u32;
    }
    if f.has("step_idle_delay_ms") {
        if !matches!(dialect, Dialect::Grbl | Dialect::Plotter) {
            let message = "applies only to dialect \"grbl\" or \"plotter\" (GRBL's $1)";
            return Err(f.error("step_idle_delay_ms", message));
        }
        // GRBL's $1 is 0-255 ms; 255 keeps the steppers enabled and does not wait.
        let ms = f.integer("step_idle_delay_ms", 0, 255)?;
        control.step_idle_delay_s = if ms == 255 { 0.0 } else { ms as f64 / 1000.0 };
    }
    if f.has("blend_tolerance_mm") {
        let (lo, hi) = BLEND_TOLERANCE_MM;
        control.blend_tolerance_mm = Some(f.number("blend_tolerance_mm", lo, hi, "mm")?);
    }
    let air = f.opt_choice("air_assist", &["M7", "M8"])?;
    let ops = f.lines("air_assist_operations")?;
    match air {
        Some(i) => {
            let mut operations = Vec::new();
            for (j, name) in ops.iter().enumerate() {
                let op = super::Operation::from_name(name).ok_or_else(|| {
                    f.error(
                        &format!("air_assist_operations[{j}]"),
                        format!("got \"{name}\"; expected mark, score, perforate, cut or plot"),
                    )
                })?;
                operations.push(op);
            }
            if operations.is_empty() {
                let message = "missing or empty; name the operations that run with air assist";
                return Err(f.error("air_assist_operations", message));
            }
            control.air_assist = Some(AirAssist {
                on: ["M7", "M8"][i],
                operations,
            });
        }
        None if !ops.is_empty() => {
            return Err(f.error("air_assist_operations", "given without air_assist"));
        }
        None => {}
    }
    if f.has("pen_change") {
        if kind != MachineKind::Plotter {
            return Err(f.error("pen_change", "applies only to a plotter"));
        }
        control.pen_change = f.lines("pen_change")?;
    }
    Ok(control)
}
