//! Fuzzes the machine and material profile readers (machine::parse_machine,
//! machine::parse_material), each input tried as both: an error names the source and a key.
#![no_main]

use foldcam::machine::{parse_machine, parse_material};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    if let Err(e) = parse_machine(text, "fuzz.toml") {
        assert!(!e.key.is_empty() && !e.message.trim().is_empty(), "{e:?}");
    }
    if let Err(e) = parse_material(text, "fuzz.toml") {
        assert!(!e.key.is_empty() && !e.message.trim().is_empty(), "{e:?}");
    }
});
