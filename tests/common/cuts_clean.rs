//! Shared by the design tests: a pattern planned for a machine and material, posted as
//! G-code and run on the simulated machine must give no violations and cover every crease
//! and cut as planned.

use foldcam::fab::PlanOverrides;
use foldcam::job::{Job, JobFormat};
use foldcam::machine::{load_machine, load_material};
use foldcam::pattern::CreasePattern;

/// Plans `cp` on the shipped `machine` and `material` and checks every job on the
/// simulated machine; `name` labels failures.
pub fn assert_cuts_clean_on(name: &str, cp: &CreasePattern, machine: &str, material: &str) {
    assert_cuts_clean_with(name, cp, machine, material, &PlanOverrides::default());
}

/// [`assert_cuts_clean_on`] with the plan's settings overridden as `foldcam cut`'s options
/// would.
pub fn assert_cuts_clean_with(
    name: &str,
    cp: &CreasePattern,
    machine: &str,
    material: &str,
    overrides: &PlanOverrides,
) {
    let machine = load_machine(machine).unwrap();
    let material = load_material(material).unwrap();
    let job = Job::plan(cp, &machine, &material, overrides)
        .and_then(|j| j.post(JobFormat::Gcode))
        .and_then(|j| j.verify())
        .unwrap_or_else(|e| panic!("{name}: {e}"));
    assert!(!job.plan.jobs.is_empty());
    assert_eq!(job.readback.len(), job.plan.jobs.len());
    for r in &job.readback {
        assert!(r.sim.is_clean(), "{name}: {:?}", r.sim.violations.first());
        assert!(
            r.coverage.passed(),
            "{name}: {:?}, stray {:?}",
            r.coverage.failed_edges().next(),
            r.coverage.stray.first()
        );
    }
}
