//! The layers of a job, shared by the DXF, SVG and LightBurn writers: one per operation
//! present, plus one per settings override present ([`FabPlan::overrides`], the cells of a
//! calibration grid), so every distinct speed/power/passes lands on a layer of its own.
//!
//! Order: [`Operation::ALL`] (execution-group order: marks first, cuts last); within an
//! operation its own settings first, then the overrides in their plan order. Names: the
//! operation's (`perforate`), or the operation's and the override's (`perforate-cell-4`);
//! DXF names are the same in upper case with every character outside `A–Z 0–9 - _` made `_`
//! (R12 symbol-table names allow no more).

use crate::fab::{FabPlan, Operation, Setup, Toolpath};
use crate::machine::{MachineProfile, OperationSettings};

/// One layer of a job.
#[derive(Clone, Debug, PartialEq)]
pub struct Layer {
    /// The operation.
    pub op: Operation,
    /// The override in [`FabPlan::overrides`], or `None` for the operation's own settings.
    pub overrides: Option<usize>,
    /// Layer name (SVG, LightBurn).
    pub name: String,
    /// DXF layer name.
    pub dxf_name: String,
}

impl Layer {
    /// The settings of the layer: its override's, else the operation's as `machine` takes
    /// them, or as the material gives them without a machine.
    pub fn settings(&self, plan: &FabPlan, machine: Option<&MachineProfile>) -> OperationSettings {
        match (self.overrides, machine) {
            (Some(i), _) => plan.overrides[i].settings,
            (None, Some(m)) => m.settings_for(&plan.settings, self.op),
            (None, None) => plan.settings.get(self.op),
        }
    }

    /// Whether `path` is drawn on this layer.
    pub fn holds(&self, plan: &FabPlan, path: &Toolpath) -> bool {
        path.op == self.op && plan.override_of(path) == self.overrides
    }
}

/// The layers of `job` that hold at least one toolpath with a stroke, in order.
pub fn layers(plan: &FabPlan, job: &Setup) -> Vec<Layer> {
    let mut keys: Vec<(Operation, Option<usize>)> = job
        .paths
        .iter()
        .filter(|p| !p.strokes.is_empty())
        .map(|p| (p.op, plan.override_of(p)))
        .collect();
    let rank = |op: Operation| Operation::ALL.iter().position(|&o| o == op);
    keys.sort_by_key(|&(op, o)| (rank(op), o.map_or(0, |i| i + 1)));
    keys.dedup();
    keys.into_iter()
        .map(|(op, overrides)| {
            let name = match overrides {
                None => op.name().to_string(),
                Some(i) => format!("{}-{}", op.name(), plan.overrides[i].name),
            };
            let dxf_name = name
                .to_ascii_uppercase()
                .chars()
                .map(|c| {
                    if c.is_ascii_alphanumeric() || c == '-' || c == '_' {
                        c
                    } else {
                        '_'
                    }
                })
                .collect();
            Layer {
                op,
                overrides,
                name,
                dxf_name,
            }
        })
        .collect()
}

/// The index in `layers` of the layer holding `path`.
pub fn layer_of(layers: &[Layer], plan: &FabPlan, path: &Toolpath) -> Option<usize> {
    layers.iter().position(|l| l.holds(plan, path))
}
