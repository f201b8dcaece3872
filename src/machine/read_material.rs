//! `machines/materials/NAME.toml` → [`Material`], every key checked.
//!
//! Layout (all keys are listed in `machines/README.md`): top-level `description`,
//! `thickness_mm`, `kerf_mm`; one table per operation `[settings.cut]`, `[settings.perforate]`,
//! `[settings.score]`, `[settings.mark]`, `[settings.plot]` (all five required); then
//! `[perforation]`, `[operations]` and `[limits]`. Ranges accepted (the numeric ones are those of
//! [`crate::limits`], shared with the command line):
//!
//! | key | range |
//! | --- | --- |
//! | `thickness_mm` | 0.01 – 50 mm |
//! | `kerf_mm` | 0 – 5 mm |
//! | `settings.*.speed_mm_min` | 1 – 1 000 000 mm/min |
//! | `settings.*.power` | 0 – 1 (fraction of the machine's range) |
//! | `settings.*.passes` | 1 – 100 |
//! | `perforation.cut_mm`, `perforation.bridge_mm` | 0.01 – 1000 mm |
//! | `perforation.min_dash_mm` | 0.01 mm – `cut_mm` |
//! | `perforation.min_web_mm` | 0.01 mm – `bridge_mm` |
//! | `perforation.vertex_clearance_mm` | 0 – 100 mm |
//! | `limits.min_vertex_angle_deg` | 0 – 120° |
//! | `limits.max_fold_angle_deg` | 1 – 180° |
//!
//! `[operations]` maps `mountain`, `valley`, `unassigned`, `flat` and `boundary` to an
//! operation name (`mark`, `score`, `perforate`, `cut`, `plot`) or `skip`. Only `boundary`
//! may be `cut`: a crease cut through does not fold, it falls apart. `unassigned` may be left
//! out and then follows `valley`.

use toml::Table;

use super::Operation;
use super::ProfileError;
use super::fields::Fields;
use super::material::{
    DesignLimits, Material, OperationMapping, OperationSettings, Perforation, SettingsByOperation,
};
use crate::limits;

/// The word that maps an assignment to no operation.
const SKIP: &str = "skip";

/// Reads and validates a material from the parsed TOML `table` of `source` named `name`.
pub(crate) fn material_from_table(
    name: &str,
    source: &str,
    table: &Table,
) -> Result<Material, ProfileError> {
    let mut f = Fields::root(source, table);
    let description = f.text_line("description")?;
    let thickness_mm = f.limited("thickness_mm", &limits::THICKNESS)?;
    let kerf_mm = f.limited("kerf_mm", &limits::KERF)?;
    let settings = read_settings(f.table("settings")?)?;
    let perforation = read_perforation(f.table("perforation")?)?;
    let mapping = read_mapping(f.table("operations")?)?;
    let limits = read_limits(f.table("limits")?)?;
    f.finish()?;
    Ok(Material {
        name: name.to_string(),
        description,
        thickness_mm,
        kerf_mm,
        settings,
        perforation,
        mapping,
        limits,
    })
}

fn read_settings(mut t: Fields) -> Result<SettingsByOperation, ProfileError> {
    let mut one = |op: Operation| read_operation(t.table(op.name())?);
    let settings = SettingsByOperation {
        cut: one(Operation::Cut)?,
        perforate: one(Operation::Perforate)?,
        score: one(Operation::Score)?,
        mark: one(Operation::Mark)?,
        plot: one(Operation::Plot)?,
    };
    t.finish()?;
    Ok(settings)
}

fn read_operation(mut t: Fields) -> Result<OperationSettings, ProfileError> {
    let speed_mm_min = t.limited("speed_mm_min", &limits::SPEED)?;
    let power = t.limited("power", &limits::POWER)?;
    let passes = t.counted("passes", &limits::PASSES)? as u32;
    t.finish()?;
    Ok(OperationSettings {
        speed_mm_min,
        power,
        passes,
    })
}

fn read_perforation(mut t: Fields) -> Result<Perforation, ProfileError> {
    let cut_mm = t.limited("cut_mm", &limits::DASH)?;
    let bridge_mm = t.limited("bridge_mm", &limits::BRIDGE)?;
    let min_dash_mm = t.number(
        "min_dash_mm",
        limits::MIN_DASH.min,
        cut_mm,
        "mm (at most cut_mm)",
    )?;
    let min_web_mm = t.number(
        "min_web_mm",
        limits::MIN_WEB.min,
        bridge_mm,
        "mm (at most bridge_mm)",
    )?;
    let vertex_clearance_mm = t.limited("vertex_clearance_mm", &limits::CLEARANCE)?;
    t.finish()?;
    Ok(Perforation {
        cut_mm,
        bridge_mm,
        min_dash_mm,
        min_web_mm,
        vertex_clearance_mm,
    })
}

fn read_mapping(mut t: Fields) -> Result<OperationMapping, ProfileError> {
    let mountain = read_op(&mut t, "mountain", false)?;
    let valley = read_op(&mut t, "valley", false)?;
    let unassigned = if t.has("unassigned") {
        read_op(&mut t, "unassigned", false)?
    } else {
        valley
    };
    let flat = read_op(&mut t, "flat", false)?;
    let boundary = read_op(&mut t, "boundary", true)?;
    t.finish()?;
    Ok(OperationMapping {
        mountain,
        valley,
        unassigned,
        flat,
        boundary,
    })
}

/// The operation named by `key` (`None` for `skip`); `cut` only where `may_cut`.
fn read_op(t: &mut Fields, key: &str, may_cut: bool) -> Result<Option<Operation>, ProfileError> {
    let names: Vec<&str> = Operation::ALL
        .iter()
        .map(|o| o.name())
        .chain([SKIP])
        .collect();
    let i = t.choice(key, &names)?;
    let op = Operation::ALL.get(i).copied();
    if op == Some(Operation::Cut) && !may_cut {
        let message =
            "got \"cut\": a crease cut through does not fold; use \"perforate\" or \"score\"";
        return Err(t.error(key, message));
    }
    Ok(op)
}

fn read_limits(mut t: Fields) -> Result<DesignLimits, ProfileError> {
    let min_vertex_angle_deg = t.number("min_vertex_angle_deg", 0.0, 120.0, "degrees")?;
    let max_fold_angle_deg = t.number("max_fold_angle_deg", 1.0, 180.0, "degrees")?;
    t.finish()?;
    Ok(DesignLimits {
        min_vertex_angle_deg,
        max_fold_angle_deg,
    })
}
