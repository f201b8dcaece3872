//! PLACEHOLDER (fab-order work): the plan: placement, sides, order, statistics.

use super::{FabError, FabPlan, PlanOptions};
use crate::machine::{MachineProfile, Material};
use crate::pattern::CreasePattern;

/// Plans `cp` (millimetres) for `machine` and `material`.
pub fn plan(
    _cp: &CreasePattern,
    _machine: &MachineProfile,
    _material: &Material,
    _opts: &PlanOptions,
) -> Result<FabPlan, FabError> {
    todo!()
}
