//! Fuzzes the Wavefront OBJ reader (mesh::read::parse_obj, tobj underneath) on any bytes: a
//! mesh it returns has faces of at least three corners, indices in range and finite positions.
#![no_main]

use foldcam::mesh::parse_obj;
use libfuzzer_sys::fuzz_target;

#[path = "mesh_common.rs"]
mod mesh_common;

fuzz_target!(|data: &[u8]| {
    mesh_common::check(parse_obj(data));
});
