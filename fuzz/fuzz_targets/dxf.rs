//! Fuzzes the DXF reader (formats::dxf, the `dxf` crate underneath) on any bytes, decoded the
//! way the file loader does (`formats::dxf::read_text_lossy`: invalid UTF-8 replaced).
#![no_main]

use foldcam::formats::{Format, parse};
use libfuzzer_sys::fuzz_target;

#[path = "common.rs"]
mod common;

fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    common::check(parse(Format::Dxf, &text));
});
