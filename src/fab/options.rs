//! Plan options resolved once: the material's defaults, a user's overrides, fitted to the
//! machine.

use glam::DVec2;

use super::placement::Placement;
use super::{FabError, Operation, PlanOptions, Tabs};
use crate::limits::{self, Limit};
use crate::machine::{MachineProfile, Material};

/// Every plan setting a user may override; `None` keeps the material's (or the plan's)
/// default. Lengths in millimetres.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct PlanOverrides {
    /// Operation for mountain creases (`Some(None)` skips them).
    pub mountain: Option<Option<Operation>>,
    /// Operation for valley creases.
    pub valley: Option<Option<Operation>>,
    /// Operation for unassigned creases.
    pub unassigned: Option<Option<Operation>>,
    /// Operation for flat (facet) lines.
    pub flat: Option<Option<Operation>>,
    /// Operation for boundary and cut lines.
    pub boundary: Option<Option<Operation>>,
    /// Perforation dash length, mm.
    pub dash_mm: Option<f64>,
    /// Perforation bridge (material left between dashes), mm.
    pub bridge_mm: Option<f64>,
    /// Cut share of each dash period in (0, 1); sets the bridge to dash × (1 − duty) / duty
    /// and wins over `bridge_mm`.
    pub duty: Option<f64>,
    /// Shortest dash worth cutting, mm.
    pub min_dash_mm: Option<f64>,
    /// Least uncut material between two cuts, mm.
    pub min_web_mm: Option<f64>,
    /// Uncut clearance around every vertex, mm.
    pub vertex_clearance_mm: Option<f64>,
    /// Kerf width, mm.
    pub kerf_mm: Option<f64>,
    /// Offset closed contours by half the kerf (default on).
    pub kerf_offset: Option<bool>,
    /// Mountains from the front, valleys from the back (default off).
    pub two_sided: bool,
    /// Holding tabs in closed contours.
    pub tabs: Option<Tabs>,
    /// Lead-in length on the scrap side of closed contours, mm.
    pub lead_in_mm: Option<f64>,
    /// Distance from the bed origin corner to the pattern, mm (default 5).
    pub margin_mm: Option<f64>,
    /// Order toolpaths to shorten travel (default on).
    pub optimize: Option<bool>,
    /// Bed centre instead of the origin corner.
    pub centre: bool,
    /// Shift after placing, mm (x right, y towards the back of the bed).
    pub offset_mm: Option<DVec2>,
}

/// Spacing between holding tabs when tabs are asked for without one (`--tab-spacing`), mm.
pub const DEFAULT_TAB_SPACING_MM: f64 = 50.0;

/// Distance from the bed origin to the pattern when none is given (`--margin`), mm.
pub const DEFAULT_MARGIN_MM: f64 = 5.0;

impl PlanOverrides {
    /// Checks every length against its range in [`crate::limits`] (the ranges the command
    /// line's options take), the duty cycle in (0, 1), and that a bridge and a duty cycle are
    /// not both given.
    ///
    /// # Errors
    /// [`FabError::BadOption`] naming the first option out of range and the range.
    pub fn validate(&self) -> Result<(), FabError> {
        let lengths: [(&Limit, Option<f64>); 10] = [
            (&limits::DASH, self.dash_mm),
            (&limits::BRIDGE, self.bridge_mm),
            (&limits::MIN_DASH, self.min_dash_mm),
            (&limits::MIN_WEB, self.min_web_mm),
            (&limits::CLEARANCE, self.vertex_clearance_mm),
            (&limits::KERF, self.kerf_mm),
            (&limits::TAB_WIDTH, self.tabs.map(|t| t.width_mm)),
            (&limits::TAB_SPACING, self.tabs.map(|t| t.spacing_mm)),
            (&limits::LEAD_IN, self.lead_in_mm),
            (&limits::MARGIN, self.margin_mm),
        ];
        for (limit, value) in lengths {
            if let Some(v) = value {
                limit.check(v).map_err(|message| FabError::BadOption {
                    option: limit.option.trim_start_matches("--"),
                    message,
                })?;
            }
        }
        if self.duty.is_some() && self.bridge_mm.is_some() {
            return Err(FabError::BadOption {
                option: "duty",
                message: "and --bridge both given: give one of them".into(),
            });
        }
        Ok(())
    }
}

impl PlanOptions {
    /// The options to plan with on `machine` in `material`: the material's defaults, then the
    /// operation overrides, fitted to the machine ([`PlanOptions::adapt_to_machine`]), then the
    /// geometry overrides. Fails when the machine cannot do an operation the mapping asks for,
    /// or an override is out of range (negative or infinite margin, duty outside (0, 1)).
    ///
    /// ```
    /// use foldcam::fab::{Operation, PlanOptions, PlanOverrides};
    /// use foldcam::machine::{load_machine, load_material};
    /// let plotter = load_machine("grbl-pen-plotter")?;
    /// let card = load_material("card-300gsm")?;
    /// let o = PlanOptions::for_machine(&plotter, &card, &PlanOverrides::default())?;
    /// // A pen plotter draws: no mapping asks it to score or cut.
    /// for op in [o.mapping.mountain, o.mapping.valley, o.mapping.boundary].into_iter().flatten() {
    ///     assert!(!matches!(op, Operation::Score | Operation::Cut));
    /// }
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn for_machine(
        machine: &MachineProfile,
        material: &Material,
        overrides: &PlanOverrides,
    ) -> Result<PlanOptions, FabError> {
        overrides.validate()?;
        let v = overrides;
        let mut o = PlanOptions::from_material(material);
        let m = &mut o.mapping;
        for (slot, arg) in [
            (&mut m.mountain, v.mountain),
            (&mut m.valley, v.valley),
            (&mut m.unassigned, v.unassigned),
            (&mut m.flat, v.flat),
            (&mut m.boundary, v.boundary),
        ] {
            if let Some(op) = arg {
                *slot = op;
            }
        }
        o.adapt_to_machine(machine)?;
        let p = &mut o.perforation;
        p.cut_mm = v.dash_mm.unwrap_or(p.cut_mm);
        p.bridge_mm = v.bridge_mm.unwrap_or(p.bridge_mm);
        if let Some(duty) = v.duty {
            if !(duty > 0.0 && duty < 1.0) {
                return Err(FabError::BadOption {
                    option: "duty",
                    message: format!(
                        "{duty} must be between 0 and 1 (the cut share of each period)"
                    ),
                });
            }
            p.bridge_mm = p.cut_mm * (1.0 - duty) / duty;
        }
        p.min_dash_mm = v.min_dash_mm.unwrap_or(p.min_dash_mm);
        p.min_web_mm = v.min_web_mm.unwrap_or(p.min_web_mm);
        p.vertex_clearance_mm = v.vertex_clearance_mm.unwrap_or(p.vertex_clearance_mm);
        o.kerf_mm = v.kerf_mm.unwrap_or(o.kerf_mm);
        o.kerf_offset = v.kerf_offset.unwrap_or(o.kerf_offset);
        o.two_sided = v.two_sided;
        o.tabs = v.tabs;
        o.lead_in_mm = v.lead_in_mm;
        o.margin_mm = v.margin_mm.unwrap_or(o.margin_mm);
        o.optimize = v.optimize.unwrap_or(o.optimize);
        o.placement = Placement {
            centre: v.centre,
            offset_mm: v.offset_mm.unwrap_or(DVec2::ZERO),
        };
        o.validate()?;
        Ok(o)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn overrides_out_of_range_name_the_option_and_its_range() {
        let bad = |o: PlanOverrides| match o.validate() {
            Err(e @ FabError::BadOption { .. }) => e.to_string(),
            other => format!("not refused: {other:?}"),
        };
        let dash = bad(PlanOverrides {
            dash_mm: Some(-1.0),
            ..PlanOverrides::default()
        });
        assert!(
            dash.starts_with("--dash ") && dash.contains("0.01 to 1000"),
            "{dash}"
        );
        let spacing = bad(PlanOverrides {
            tabs: Some(Tabs {
                width_mm: 2.0,
                spacing_mm: 0.5,
            }),
            ..PlanOverrides::default()
        });
        assert!(spacing.starts_with("--tab-spacing "), "{spacing}");
        let both = bad(PlanOverrides {
            bridge_mm: Some(1.0),
            duty: Some(0.5),
            ..PlanOverrides::default()
        });
        assert!(
            both.contains("--duty") && both.contains("--bridge"),
            "{both}"
        );
        let fine = PlanOverrides {
            dash_mm: Some(2.0),
            margin_mm: Some(DEFAULT_MARGIN_MM),
            ..PlanOverrides::default()
        };
        assert!(fine.validate().is_ok());
    }
}
