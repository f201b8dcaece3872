//! Generates a 6 × 6 grid of waterbomb bases, checks it and writes it.
//!
//! ```text
//! cargo run --example waterbomb -- [OUT.fold|OUT.svg|OUT.cp]   (default foldcam-examples/waterbomb.fold)
//! ```

use foldcam::check::{CheckOptions, check};
use foldcam::design::classic::Waterbomb;
use std::path::PathBuf;
use std::process::ExitCode;

fn main() -> ExitCode {
    let out = std::env::args_os().nth(1).map_or_else(
        || PathBuf::from("foldcam-examples/waterbomb.fold"),
        PathBuf::from,
    );
    if let Some(dir) = out.parent().filter(|d| !d.as_os_str().is_empty())
        && let Err(e) = std::fs::create_dir_all(dir)
    {
        eprintln!("waterbomb: {}: {e}", dir.display());
        return ExitCode::from(2);
    }
    let params = Waterbomb {
        columns: 6,
        rows: 6,
        size: 25.0,
    };
    let pattern = match params.build() {
        Ok(p) => p,
        Err(e) => {
            eprintln!("waterbomb: {e}");
            return ExitCode::from(2);
        }
    };
    let report = check(&pattern, &CheckOptions::default());
    println!(
        "{}: {} vertices, {} edges, flat-foldable at every interior vertex: {}",
        pattern.meta.title.as_deref().unwrap_or("waterbomb"),
        pattern.vertices.len(),
        pattern.edges.len(),
        report.passed()
    );
    if let Err(e) = foldcam::formats::save(&out, &pattern, None) {
        eprintln!("waterbomb: {e}");
        return ExitCode::from(2);
    }
    println!("wrote {}", out.display());
    ExitCode::SUCCESS
}
