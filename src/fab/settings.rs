//! The plan settings as a request names them: every override of `foldcam cut` and
//! `foldcam plan` by its option's name, deserialised from the studio's requests, resolved by
//! the same [`PlanOptions::for_machine`] the command line uses.

use glam::DVec2;
use serde::Deserialize;

use super::{DEFAULT_TAB_SPACING_MM, FabError, Operation, PlanOptions, PlanOverrides, Tabs};
use crate::machine::{MachineProfile, Material};

/// Every plan override of `foldcam cut` / `foldcam plan`, by the option's name with `_` for
/// `-` (`min_dash` is `--min-dash`); `None` keeps the material's or the planner's default.
/// Lengths are millimetres. The studio's plan requests deserialise into it and the command
/// line parses its options into it, so both resolve the same request with [`Self::options`].
#[derive(Clone, Debug, Default, Deserialize, PartialEq)]
pub struct PlanSettings {
    /// Operation for mountain creases (`mark`, `score`, `perforate`, `cut`, `plot`, `skip`).
    pub mountain: Option<String>,
    /// Operation for valley creases.
    pub valley: Option<String>,
    /// Operation for unassigned creases.
    pub unassigned: Option<String>,
    /// Operation for flat lines.
    pub flat: Option<String>,
    /// Operation for boundary and cut lines.
    pub boundary: Option<String>,
    /// Perforation dash length.
    pub dash: Option<f64>,
    /// Material left between dashes.
    pub bridge: Option<f64>,
    /// Cut share of each dash period, in (0, 1), instead of `bridge`.
    pub duty: Option<f64>,
    /// Shortest dash worth cutting.
    pub min_dash: Option<f64>,
    /// Least uncut material between two cuts.
    pub min_web: Option<f64>,
    /// Uncut clearance around every vertex.
    pub clearance: Option<f64>,
    /// Kerf width.
    pub kerf: Option<f64>,
    /// `true` is `--no-kerf-offset`.
    #[serde(default)]
    pub no_kerf_offset: bool,
    /// Mountains from the front, valleys from the back.
    #[serde(default)]
    pub two_sided: bool,
    /// Holding tab width.
    pub tabs: Option<f64>,
    /// Spacing between tabs ([`DEFAULT_TAB_SPACING_MM`] when absent, as on the command line).
    pub tab_spacing: Option<f64>,
    /// Lead-in length.
    pub lead_in: Option<f64>,
    /// Distance from the bed origin ([`crate::fab::DEFAULT_MARGIN_MM`] when absent, as on the
    /// command line).
    pub margin: Option<f64>,
    /// `true` is `--no-optimize`.
    #[serde(default)]
    pub no_optimize: bool,
    /// `corner` (default) or `centre`.
    pub origin: Option<String>,
    /// Shift of the placed job, `X,Y` in mm ([`parse_offset`]).
    pub offset: Option<String>,
}

/// Largest shift of a placed job along either axis, mm.
pub const MAX_OFFSET_MM: f64 = 1e5;

/// Parses a job's shift `X,Y` in millimetres (`--offset`), each within [`MAX_OFFSET_MM`].
///
/// # Errors
/// The text and what was expected.
pub fn parse_offset(s: &str) -> Result<DVec2, String> {
    let parts: Vec<&str> = s.split(',').map(str::trim).collect();
    let bad = || format!("{s}: expected X,Y in mm, e.g. 10,-5");
    let [x, y] = parts[..] else {
        return Err(bad());
    };
    let x: f64 = x.parse().map_err(|_| bad())?;
    let y: f64 = y.parse().map_err(|_| bad())?;
    if !(x.is_finite() && y.is_finite() && x.abs() <= MAX_OFFSET_MM && y.abs() <= MAX_OFFSET_MM) {
        return Err(format!(
            "{s}: offsets must be finite and within ±{MAX_OFFSET_MM} mm"
        ));
    }
    Ok(DVec2::new(x, y))
}

/// Parses an operation name or `skip` for `option`.
fn operation(option: &'static str, name: &str) -> Result<Option<Operation>, FabError> {
    Operation::choice(name).map_err(|message| FabError::BadOption { option, message })
}

impl PlanSettings {
    /// The plan options for `material` on `machine` with these overrides, resolved as
    /// `foldcam cut` resolves its options ([`PlanOptions::for_machine`]).
    ///
    /// # Errors
    /// [`FabError::BadOption`] naming the option (an unknown operation or origin, a length
    /// out of its range), or the planner's cross-check.
    pub fn options(
        &self,
        machine: &MachineProfile,
        material: &Material,
    ) -> Result<PlanOptions, FabError> {
        let op = |option: &'static str, value: &Option<String>| {
            value
                .as_deref()
                .map(|name| operation(option, name))
                .transpose()
        };
        let centre = match self.origin.as_deref() {
            None | Some("" | "corner") => false,
            Some("centre" | "center") => true,
            Some(other) => {
                return Err(FabError::BadOption {
                    option: "origin",
                    message: format!("{other:?} is not corner or centre"),
                });
            }
        };
        let overrides = PlanOverrides {
            mountain: op("mountain", &self.mountain)?,
            valley: op("valley", &self.valley)?,
            unassigned: op("unassigned", &self.unassigned)?,
            flat: op("flat", &self.flat)?,
            boundary: op("boundary", &self.boundary)?,
            dash_mm: self.dash,
            bridge_mm: self.bridge,
            duty: self.duty,
            min_dash_mm: self.min_dash,
            min_web_mm: self.min_web,
            vertex_clearance_mm: self.clearance,
            kerf_mm: self.kerf,
            kerf_offset: Some(!self.no_kerf_offset),
            two_sided: self.two_sided,
            tabs: self.tabs.map(|width_mm| Tabs {
                width_mm,
                spacing_mm: self.tab_spacing.unwrap_or(DEFAULT_TAB_SPACING_MM),
            }),
            lead_in_mm: self.lead_in,
            margin_mm: self.margin,
            optimize: Some(!self.no_optimize),
            centre,
            offset_mm: self
                .offset
                .as_deref()
                .map(parse_offset)
                .transpose()
                .map_err(|message| FabError::BadOption {
                    option: "offset",
                    message,
                })?,
        };
        PlanOptions::for_machine(machine, material, &overrides)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::machine::{load_machine, load_material};

    #[test]
    fn an_offset_is_parsed_once_for_both_front_ends_and_refused_out_of_range() {
        let machine = load_machine("grbl-diode").unwrap();
        let material = load_material("card-300gsm").unwrap();
        let settings = |offset: &str| PlanSettings {
            offset: Some(offset.to_string()),
            ..PlanSettings::default()
        };
        let o = settings(" 10 , -5 ").options(&machine, &material).unwrap();
        assert_eq!(o.placement.offset_mm, DVec2::new(10.0, -5.0));
        let none = PlanSettings::default()
            .options(&machine, &material)
            .unwrap();
        assert_eq!(none.placement.offset_mm, DVec2::ZERO);
        for bad in ["10", "1,2,3", "x,1", "1e6,0", "NaN,0"] {
            let err = settings(bad).options(&machine, &material).unwrap_err();
            match err {
                FabError::BadOption { option, message } => {
                    assert_eq!(option, "offset");
                    assert!(message.starts_with(bad), "{message}");
                }
                other => panic!("{bad}: {other}"),
            }
        }
    }
}
