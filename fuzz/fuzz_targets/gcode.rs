//! Fuzzes the G-code reader of the simulated machine (sim::run) on a GRBL laser, a Marlin laser and a pen
//! plotter: any UTF-8 text runs to a report or an error, and the report's numbers are finite.
#![no_main]

use std::sync::OnceLock;

use foldcam::machine::{MachineProfile, load_machine};
use foldcam::sim::run;
use libfuzzer_sys::fuzz_target;

fn machines() -> &'static [MachineProfile] {
    static MACHINES: OnceLock<Vec<MachineProfile>> = OnceLock::new();
    MACHINES.get_or_init(|| {
        ["grbl-diode", "marlin-laser", "grbl-pen-plotter"]
            .iter()
            .map(|name| load_machine(name).expect("a shipped profile"))
            .collect()
    })
}

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    for machine in machines() {
        match run(text, machine) {
            Ok(report) => assert!(report.time_s.is_finite(), "time {}", report.time_s),
            Err(e) => assert!(!e.to_string().trim().is_empty()),
        }
    }
});
