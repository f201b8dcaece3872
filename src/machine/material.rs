//! Material profiles: how a sheet is cut, perforated, scored, marked or plotted, and the
//! design limits it imposes on patterns.
//!
//! Lengths are millimetres, speeds mm/min, power a fraction 0..=1 of the machine's range
//! (the machine profile turns it into an `S` value), angles degrees. Values are validated where
//! they are read (`machines/materials/*.toml`, see the `machine` module); the types here trust
//! them. The numbers shipped are starting points for a test cut, not guarantees: laser power,
//! optics and sheet batches differ.

use serde::Serialize;

use super::MachineProfile;
use super::Operation;
use crate::check::CheckOptions;
use crate::design::source::TessellationOptions;
use crate::design::tessellation::Limits;
use crate::limits::{BRIDGE, CLEARANCE, DASH, LimitError, MIN_DASH, MIN_WEB, show};
use crate::pattern::Assignment;

/// Speed, power and passes for one operation.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct OperationSettings {
    /// Feed, mm/min.
    pub speed_mm_min: f64,
    /// Power as a fraction of the machine's range, 0..=1.
    pub power: f64,
    /// Repetitions.
    pub passes: u32,
}

/// Settings per operation.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct SettingsByOperation {
    /// Through-cut.
    pub cut: OperationSettings,
    /// Perforation dashes.
    pub perforate: OperationSettings,
    /// Scoring (partial depth).
    pub score: OperationSettings,
    /// Marking (surface, registration marks, flat lines).
    pub mark: OperationSettings,
    /// Pen plotting (power ignored).
    pub plot: OperationSettings,
}

impl SettingsByOperation {
    /// The settings of `op`.
    pub fn get(&self, op: Operation) -> OperationSettings {
        match op {
            Operation::Cut => self.cut,
            Operation::Perforate => self.perforate,
            Operation::Score => self.score,
            Operation::Mark => self.mark,
            Operation::Plot => self.plot,
        }
    }
}

/// Perforation geometry.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Perforation {
    /// Length of each cut dash, mm.
    pub cut_mm: f64,
    /// Length of each uncut bridge, mm.
    pub bridge_mm: f64,
    /// Shortest dash worth cutting, mm.
    pub min_dash_mm: f64,
    /// Least uncut material between two cuts, mm (the web).
    pub min_web_mm: f64,
    /// Least uncut distance kept around every vertex, mm (grows at sharp vertex angles).
    pub vertex_clearance_mm: f64,
}

/// Shortest toolpath dash kept when the kerf is taken off, as a share of the asked dash.
const MIN_TOOLPATH_DASH_SHARE: f64 = 0.1;

impl Perforation {
    /// Checks the perforation after the command line was laid over the material: every length in
    /// its range, the shortest dash at most the dash (a dash below it cannot be cut, so every
    /// perforated crease would become one continuous slot) and the web at most the bridge.
    pub fn check_limits(&self) -> Result<(), LimitError> {
        let p = self;
        for (limit, value) in [
            (DASH, p.cut_mm),
            (BRIDGE, p.bridge_mm),
            (MIN_DASH, p.min_dash_mm),
            (MIN_WEB, p.min_web_mm),
            (CLEARANCE, p.vertex_clearance_mm),
        ] {
            limit.check(value).map_err(|message| LimitError {
                setting: limit.name(),
                value: show(value),
                message,
            })?;
        }
        if p.cut_mm < p.min_dash_mm {
            return Err(LimitError {
                setting: DASH.name(),
                value: format!("{} mm", p.cut_mm),
                message: format!(
                    "shorter than the shortest dash worth cutting, {} mm ({}): no dash could be \
                     cut, so every perforated crease would become one continuous slot; give a \
                     longer dash or a smaller --min-dash",
                    p.min_dash_mm,
                    MIN_DASH.name()
                ),
            });
        }
        if p.bridge_mm < p.min_web_mm {
            return Err(LimitError {
                setting: BRIDGE.name(),
                value: format!("{} mm", p.bridge_mm),
                message: format!(
                    "shorter than the least web, {} mm ({}); give a longer bridge or a smaller \
                     --min-web",
                    p.min_web_mm,
                    MIN_WEB.name()
                ),
            });
        }
        Ok(())
    }

    /// The layout in toolpath terms for a beam `kerf_mm` wide. Each dash burns kerf/2 past
    /// both ends of its toolpath, so for the material to keep the asked bridges (and webs)
    /// the toolpath dashes are one kerf shorter and the bridges one kerf longer, the period
    /// unchanged; the dash keeps at least a tenth of its length (a kerf wider than that
    /// leaves shorter bridges, as the beam allows no better). The vertex clearance grows by
    /// half the kerf, so the metal left between a vertex and the nearest dash's burnt end is
    /// the clearance asked.
    pub fn for_kerf(&self, kerf_mm: f64) -> Perforation {
        let kerf = if kerf_mm.is_finite() {
            kerf_mm.max(0.0)
        } else {
            0.0
        };
        let shrink = kerf.min(self.cut_mm * (1.0 - MIN_TOOLPATH_DASH_SHARE));
        Perforation {
            cut_mm: self.cut_mm - shrink,
            bridge_mm: self.bridge_mm + shrink,
            min_dash_mm: (self.min_dash_mm - shrink)
                .max(self.min_dash_mm.min(self.cut_mm - shrink) * MIN_TOOLPATH_DASH_SHARE),
            min_web_mm: self.min_web_mm + shrink,
            vertex_clearance_mm: self.vertex_clearance_mm + kerf / 2.0,
        }
    }
}

/// Which operation each assignment gets.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct OperationMapping {
    /// For mountain creases.
    pub mountain: Option<Operation>,
    /// For valley creases.
    pub valley: Option<Operation>,
    /// For unassigned creases.
    pub unassigned: Option<Operation>,
    /// For flat (facet) lines; `None` skips them.
    pub flat: Option<Operation>,
    /// For boundary and cut edges.
    pub boundary: Option<Operation>,
}

/// Design limits the material imposes on patterns.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct DesignLimits {
    /// Smallest angle between neighbouring creases, degrees (Tachi's δ_corner).
    pub min_vertex_angle_deg: f64,
    /// Largest fold angle, degrees (180 − δ_fold).
    pub max_fold_angle_deg: f64,
}

/// A material, as loaded from `machines/materials/NAME.toml`.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Material {
    /// Short name (the file stem).
    pub name: String,
    /// Readable description.
    pub description: String,
    /// Sheet thickness, mm.
    pub thickness_mm: f64,
    /// Width of the cut, mm.
    pub kerf_mm: f64,
    /// Speed, power, passes per operation.
    pub settings: SettingsByOperation,
    /// Perforation geometry.
    pub perforation: Perforation,
    /// Default operation per assignment.
    pub mapping: OperationMapping,
    /// Design limits.
    pub limits: DesignLimits,
}

impl Material {
    /// What the material sets when nothing overrides it, in a line: the operation for each
    /// line kind and the design limits, e.g. `mountain score, valley score, unassigned score,
    /// flat skip, boundary cut; creases at least 20° apart, folds up to 180°`.
    pub fn defaults(&self) -> String {
        let m = &self.mapping;
        let op = |o: Option<Operation>| o.map_or("skip", Operation::name);
        format!(
            "mountain {}, valley {}, unassigned {}, flat {}, boundary {}; creases at least {}° \
             apart, folds up to {}°",
            op(m.mountain),
            op(m.valley),
            op(m.unassigned),
            op(m.flat),
            op(m.boundary),
            self.limits.min_vertex_angle_deg,
            self.limits.max_fold_angle_deg
        )
    }
}

impl OperationMapping {
    /// The operation for an edge assignment (cut edges follow the boundary; joins are never
    /// machined), or `None` when the assignment is skipped.
    pub fn get(&self, assignment: Assignment) -> Option<Operation> {
        match assignment {
            Assignment::Mountain => self.mountain,
            Assignment::Valley => self.valley,
            Assignment::Unassigned => self.unassigned,
            Assignment::Flat => self.flat,
            Assignment::Boundary | Assignment::Cut => self.boundary,
            Assignment::Join => None,
        }
    }
}

impl DesignLimits {
    /// Sets the vertex-angle and fold-angle limits of `opts` to these.
    pub fn apply_to(&self, opts: &mut CheckOptions) {
        opts.min_vertex_angle_deg = Some(self.min_vertex_angle_deg);
        opts.max_fold_angle_deg = Some(self.max_fold_angle_deg);
    }

    /// Sets the limits a tessellation is solved within (Tachi 2014: largest fold angle,
    /// smallest angle between creases) to these, as `foldcam tessellate --material` and the
    /// studio's tessellation with a material do.
    pub fn apply_to_tessellation(&self, opts: &mut TessellationOptions) {
        opts.max_fold_angle_deg = self.max_fold_angle_deg;
        opts.min_vertex_angle_deg = self.min_vertex_angle_deg;
    }

    /// The tessellation solver's limits with these angles.
    pub fn tessellation_limits(&self) -> Limits {
        Limits::from_degrees(self.max_fold_angle_deg, self.min_vertex_angle_deg)
    }
}

impl Material {
    /// Pattern-check options with this material's design limits (minimum vertex angle,
    /// maximum fold angle) and the other checks at their defaults.
    pub fn check_options(&self) -> CheckOptions {
        let mut opts = CheckOptions::default();
        self.limits.apply_to(&mut opts);
        opts
    }

    /// The operations the mapping uses that `machine` cannot carry out (a laser does not plot,
    /// a plotter does not cut), for a warning or an error before planning.
    pub fn unsupported_by(&self, machine: &MachineProfile) -> Vec<Operation> {
        let used = self.used_operations();
        used.into_iter()
            .filter(|op| !machine.supports(*op))
            .collect()
    }

    /// The operations the mapping uses, each once, in [`Operation::ALL`] order.
    pub fn used_operations(&self) -> Vec<Operation> {
        let m = &self.mapping;
        let used = [m.mountain, m.valley, m.unassigned, m.flat, m.boundary];
        Operation::ALL
            .into_iter()
            .filter(|op| used.contains(&Some(*op)))
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_dash_below_the_shortest_dash_is_refused() {
        let p = Perforation {
            cut_mm: 0.01,
            bridge_mm: 1.0,
            min_dash_mm: 0.5,
            min_web_mm: 0.5,
            vertex_clearance_mm: 1.0,
        };
        let e = p.check_limits().unwrap_err();
        assert!(e.to_string().contains("--dash"), "{e}");
        assert!(e.to_string().contains("continuous slot"), "{e}");
        let fine = Perforation { cut_mm: 2.0, ..p };
        assert_eq!(fine.check_limits(), Ok(()));
        let thin = Perforation {
            bridge_mm: 0.2,
            ..fine
        };
        assert!(thin.check_limits().is_err());
    }
}
