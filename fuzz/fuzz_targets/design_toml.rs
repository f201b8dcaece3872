//! Fuzzes the design files written in TOML, each input tried as all three: fold scripts
//! (design::folding: parsed, then folded step by step as `foldcam fold` does), polygon pop-up
//! designs (design::popup::polygon: parsed, then built) and paper-craft designs
//! (design::papercraft: parsed; building needs a mesh file). Errors must say something.
#![no_main]

use foldcam::design::folding::{parse_script, run_script};
use foldcam::design::papercraft::parse_design as parse_papercraft;
use foldcam::design::popup::polygon::parse_design as parse_popup;
use libfuzzer_sys::fuzz_target;

fn said<E: std::fmt::Display>(e: E) {
    assert!(!e.to_string().trim().is_empty(), "an empty error");
}

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    match parse_script(text) {
        Ok(script) => {
            if let Err(e) = run_script(&script) {
                said(e);
            }
        }
        Err(e) => said(e),
    }
    match parse_popup(text) {
        Ok(design) => {
            if let Err(e) = design.build() {
                said(e);
            }
        }
        Err(e) => said(e),
    }
    if let Err(e) = parse_papercraft(text) {
        said(e);
    }
});
