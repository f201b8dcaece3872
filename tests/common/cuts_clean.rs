//! Shared by the design tests: a pattern planned for a machine and material, posted as
//! G-code and run on the simulated machine must give no violations and cover every crease
//! and cut as planned.

use foldcam::fab::{PlanOptions, plan};
use foldcam::machine::{load_machine, load_material};
use foldcam::pattern::CreasePattern;
use foldcam::{post, sim};

/// Plans `cp` on the shipped `machine` and `material` and checks every job on the
/// simulated machine; `name` labels failures.
pub fn assert_cuts_clean_on(name: &str, cp: &CreasePattern, machine: &str, material: &str) {
    let machine = load_machine(machine).unwrap();
    let material = load_material(material).unwrap();
    let mut options = PlanOptions::from_material(&material);
    options.adapt_to_machine(&machine).unwrap();
    let p = plan(cp, &machine, &material, &options).unwrap_or_else(|e| panic!("{name}: {e}"));
    assert!(!p.jobs.is_empty());
    for job in &p.jobs {
        let gcode = post::gcode(&p, job, &machine).unwrap();
        let run = sim::run(&gcode, &machine).unwrap();
        assert!(run.is_clean(), "{name}: {:?}", run.violations.first());
        let cov = sim::coverage(&run, cp, job, &p);
        assert!(
            cov.passed(),
            "{name}: {:?}, stray {:?}",
            cov.failed_edges().next(),
            cov.stray.first()
        );
    }
}
