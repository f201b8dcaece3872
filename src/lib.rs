//! foldcam: from fold designs to machine files.
//!
//! Every design source ends in one model, the [`pattern::CreasePattern`] (vertices in
//! millimetres, edges with FOLD assignments and fold angles). This crate reads and writes it
//! ([`formats`]: FOLD 1.2, Origami Simulator SVG, ORIPA `.cp`), cleans any line drawing into a
//! planar graph ([`pattern::planarize()`]), checks it ([`check`](mod@check): Kawasaki, Maekawa, vertex and
//! fold-angle limits) and draws previews ([`render`]). [`Job`] turns a pattern into checked
//! machine files: plan ([`fab`]) → post-process ([`post`]: G-code, DXF, SVG, LightBurn) → read
//! back on the simulated machine with coverage ([`sim`]). See `ARCHITECTURE.md` at the
//! repository root for the map.
//!
//! The items most programs need are re-exported here; the areas keep their own `pub use`
//! lists (`pattern`, `formats`, `check`, `machine`, `fab`, `sim`, `job`).
//!
//! The command line is the `cli` feature (on by default: clap, anyhow, ctrlc, indicatif and the studio's
//! web server, feature `studio`); the library
//! alone builds with `cargo build --lib --no-default-features`.
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
#![deny(unused_crate_dependencies)]

pub mod check;
pub mod clock;
pub mod design;
pub mod fab;
pub mod formats;
pub mod geom;
pub mod job;
pub mod limits;
pub mod machine;
pub mod mesh;
pub mod pattern;
pub mod post;
pub mod render;
pub mod sim;
#[cfg(feature = "studio")]
pub mod studio;
#[cfg(test)]
mod test_rng;

// The curated surface: a pattern, its files, its checks, its machine job.
pub use check::{CheckOptions, CheckReport, check};
pub use fab::plan::plan;
pub use fab::{FabError, FabPlan, PlanOptions, PlanOverrides};
pub use formats::{Format, FormatError, Imported, OutputSet, load, save};
pub use job::{Job, JobError, JobFormat};
pub use machine::{MachineProfile, Material, Operation, load_machine, load_material};
pub use pattern::planarize::planarize;
pub use pattern::{
    Assignment, CreasePattern, EdgeId, FaceId, FoldedState, PlanarizeOptions, Scale, Units,
    VertexId,
};
pub use post::DxfVersion;
pub use sim::{CoverageReport, SimReport};

// The binary's dependencies (feature `cli`) and the test-only ones, which the library itself
// does not use: named so `unused_crate_dependencies` checks every other one.
#[cfg(feature = "cli")]
use {
    anyhow as _, clap as _, clap_complete as _, clap_mangen as _, ctrlc as _, indicatif as _,
    mimalloc as _,
};
#[cfg(test)]
use {
    criterion as _, fantoccini as _, hyper_util as _, proptest as _, roxmltree as _, tempfile as _,
};
