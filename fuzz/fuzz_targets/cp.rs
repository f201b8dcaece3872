//! Fuzzes the ORIPA .cp line lists (formats::cp::read_str): any UTF-8 text (the file loader refuses other bytes first).
#![no_main]

use foldcam::formats::{Format, parse};
use libfuzzer_sys::fuzz_target;

#[path = "common.rs"]
mod common;

fuzz_target!(|data: &[u8]| {
    if let Ok(text) = std::str::from_utf8(data) {
        common::check(parse(Format::Cp, text));
    }
});
