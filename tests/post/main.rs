//! Post-processors and machines: G-code, DXF, SVG and LightBurn output read back through the
//! simulated machine, motion models against the controllers' own planners, machine profiles.
//!
//! One test binary: each module is the tests of one part, so the crate is linked once.

#[path = "../common/bin.rs"]
mod bin;
#[path = "../common/post.rs"]
mod post_common;

mod controller_oracles;
mod lightburn_vpype;
mod machine_profiles;
mod motion;
mod post_dxf;
mod post_fuzz;
mod post_gcode;
mod post_svg;
mod preview;
mod shop_floor;
mod shop_grid;
mod sim;
