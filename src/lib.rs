//! foldcam: from fold designs to machine files.
//!
//! Every design source ends in one model, the [`pattern::CreasePattern`] (vertices in
//! millimetres, edges with FOLD assignments and fold angles). This crate reads and writes it
//! ([`formats`]: FOLD 1.2, Origami Simulator SVG, ORIPA `.cp`), cleans any line drawing into a
//! planar graph ([`pattern::planarize()`]), checks it ([`check`]: Kawasaki, Maekawa, vertex and
//! fold-angle limits) and draws previews ([`render`]). See `ARCHITECTURE.md` at the repository root for the map.
//!
//! ```
//! use foldcam::check::{CheckOptions, check};
//! use foldcam::design::classic::MiuraOri;
//! use foldcam::formats::{Format, parse, render};
//!
//! // Generate a Miura-ori sheet (millimetres) and check it folds flat at every vertex.
//! let miura = MiuraOri { columns: 6, rows: 4, ..MiuraOri::default() }.build()?;
//! assert!(check(&miura, &CheckOptions::default()).passed());
//!
//! // Write it as FOLD and read it back: nothing is lost.
//! let text = render(Format::Fold, &miura, None);
//! let back = parse(Format::Fold, &text)?.pattern;
//! assert_eq!(back.vertices, miura.vertices);
//! assert_eq!(back.edges, miura.edges);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
#![warn(missing_docs)]

pub mod check;
pub mod design;
pub mod fab;
pub mod formats;
pub mod geom;
pub mod limits;
pub mod machine;
pub mod mesh;
pub mod pattern;
pub mod post;
pub mod render;
pub mod sim;
pub mod studio;
#[cfg(test)]
mod test_rng;
