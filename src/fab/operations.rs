//! Which operation each edge of a crease pattern gets.
//!
//! The mapping comes from the material (overridden on the command line):
//! boundary and cut edges → `mapping.boundary` (usually [`Operation::Cut`]); mountain, valley
//! and unassigned creases → their own entries (perforate, score or plot); flat facet lines →
//! `mapping.flat` (skip or mark); join edges (two faces glued) are never machined.

use super::{Operation, PlanOptions};
use crate::machine::{MachineProfile, Material, OperationMapping};
use crate::pattern::{Assignment, CreasePattern, EdgeId};

/// The operation for an edge of `assignment` under `mapping`; `None` skips the edge.
pub fn operation_for(assignment: Assignment, mapping: &OperationMapping) -> Option<Operation> {
    match assignment {
        Assignment::Boundary | Assignment::Cut => mapping.boundary,
        Assignment::Mountain => mapping.mountain,
        Assignment::Valley => mapping.valley,
        Assignment::Unassigned => mapping.unassigned,
        Assignment::Flat => mapping.flat,
        Assignment::Join => None,
    }
}

/// The operation of every edge of `cp`, indexed by [`EdgeId::index`].
pub fn edge_operations(cp: &CreasePattern, mapping: &OperationMapping) -> Vec<Option<Operation>> {
    cp.edges
        .iter()
        .map(|e| operation_for(e.assignment, mapping))
        .collect()
}

/// Whether the edge leaves material weakened or removed along its whole length from its end
/// vertices: a through-cut, a score, or the sheet's outline (present whatever the mapping).
/// Such lines need the full clearance of [`super::perforation::continuous_clearance`] from
/// perforation dashes; marks and pen lines do not weaken the sheet.
pub fn is_continuous_weakening(cp: &CreasePattern, ops: &[Option<Operation>], e: EdgeId) -> bool {
    cp.edges[e.index()].assignment.is_boundary_like()
        || matches!(ops[e.index()], Some(Operation::Cut | Operation::Score))
}

/// Whether `machine` can leave a visible mark on `material`: the machine marks at all
/// ([`MachineProfile::supports`]), and a laser's `mark` power is above zero (a pen always
/// draws). Paper-craft edge numbers and calibration-grid labels are marked only then.
pub fn can_mark(machine: &MachineProfile, material: &Material) -> bool {
    machine.supports(Operation::Mark) && (machine.pen_tool() || material.settings.mark.power > 0.0)
}

/// The operation for labels drawn as flat lines (paper-craft edge numbers) when the user
/// chose none: [`Operation::Mark`] where [`can_mark`], else `None` (skipped).
pub fn label_operation(machine: &MachineProfile, material: &Material) -> Option<Operation> {
    can_mark(machine, material).then_some(Operation::Mark)
}

/// Makes a plan mark the labels a design draws as flat lines (paper-craft edge numbers), as
/// `foldcam papercraft --job` does when `--flat` is not given: flat lines get
/// [`label_operation`] ([`Operation::Mark`] where [`can_mark`], else skipped). Used by the
/// command line and the studio alike, so both write the same job for the same design.
///
/// Returns `false` when `machine` cannot mark `material` (a laser whose mark power is 0): the
/// labels are then left out, and the caller says so.
pub fn mark_labels(
    options: &mut PlanOptions,
    machine: &MachineProfile,
    material: &Material,
) -> bool {
    options.mapping.flat = label_operation(machine, material);
    options.mapping.flat.is_some()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::machine::{load_machine, load_material};

    #[test]
    fn labels_are_marked_where_the_machine_can_mark_the_material() {
        let machine = load_machine("grbl-diode").unwrap();
        let material = load_material("paper-160gsm").unwrap();
        let mut options =
            PlanOptions::for_machine(&machine, &material, &Default::default()).unwrap();
        options.mapping.flat = None;
        assert!(mark_labels(&mut options, &machine, &material));
        assert_eq!(options.mapping.flat, Some(Operation::Mark));
        // A material whose mark power is 0: the labels are left out, and the caller is told.
        let mut dark = material.clone();
        dark.settings.mark.power = 0.0;
        options.mapping.flat = Some(Operation::Mark);
        assert!(!mark_labels(&mut options, &machine, &dark));
        assert_eq!(options.mapping.flat, None);
    }

    #[test]
    fn join_is_never_machined_and_cut_follows_boundary() {
        let mapping = OperationMapping {
            mountain: Some(Operation::Perforate),
            valley: Some(Operation::Score),
            unassigned: None,
            flat: Some(Operation::Mark),
            boundary: Some(Operation::Cut),
        };
        assert_eq!(operation_for(Assignment::Join, &mapping), None);
        assert_eq!(
            operation_for(Assignment::Cut, &mapping),
            Some(Operation::Cut)
        );
        assert_eq!(
            operation_for(Assignment::Boundary, &mapping),
            Some(Operation::Cut)
        );
        assert_eq!(
            operation_for(Assignment::Valley, &mapping),
            Some(Operation::Score)
        );
        assert_eq!(operation_for(Assignment::Unassigned, &mapping), None);
    }
}
