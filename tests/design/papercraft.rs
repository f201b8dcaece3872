//! Paper craft from developable patches (Ōgaki 2016): reference-mesh projection, Catmull–Rom
//! cut lines, the half-edge cut-line network (§3.3) and cylindrical patches with their
//! isometric unrolling (§3.2 Step 2).

#[path = "papercraft/support.rs"]
mod support;

#[path = "papercraft/reference.rs"]
mod reference;

#[path = "papercraft/cut_lines.rs"]
mod cut_lines;

#[path = "papercraft/network.rs"]
mod network;

#[path = "papercraft/walls.rs"]
mod walls;

#[path = "papercraft/parts.rs"]
mod parts;

#[path = "papercraft/design.rs"]
mod design;

#[path = "papercraft/cylinder.rs"]
mod cylinder;

#[path = "papercraft/neighbour.rs"]
mod neighbour;

#[path = "papercraft/labels.rs"]
mod labels;

#[path = "papercraft/packing.rs"]
mod packing;
