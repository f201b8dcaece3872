//! Fuzzes the STL reader (mesh::read::parse_stl, stl_io underneath; ASCII and binary) on any
//! bytes: a mesh it returns has indices in range and finite positions.
#![no_main]

use foldcam::mesh::parse_stl;
use libfuzzer_sys::fuzz_target;

#[path = "mesh_common.rs"]
mod mesh_common;

fuzz_target!(|data: &[u8]| {
    mesh_common::check(parse_stl(data));
});
