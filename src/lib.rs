//! foldcam: from fold designs to machine files.
//!
//! Every design source ends in one model, the [`pattern::CreasePattern`] (vertices in
//! millimetres, edges with FOLD assignments and fold angles). This crate reads and writes it
//! ([`formats`]: FOLD 1.2, Origami Simulator SVG, ORIPA `.cp`), cleans any line drawing into a
//! planar graph ([`pattern::planarize()`]), checks it ([`check`]: Kawasaki, Maekawa, vertex and
//! fold-angle limits) and draws previews ([`render`]). See `src/ARCHITECTURE.md` for the map.
#![warn(missing_docs)]

pub mod check;
pub mod design;
pub mod formats;
pub mod geom;
pub mod pattern;
pub mod render;
