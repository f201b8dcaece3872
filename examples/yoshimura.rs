//! Generates the Yoshimura diamond pattern of a crushed cylinder, checks it and writes it.
//!
//! ```text
//! cargo run --example yoshimura -- [OUT.fold|OUT.svg|OUT.cp]
//! ```

use foldcam::check::{CheckOptions, check};
use foldcam::design::classic::Yoshimura;
use std::path::PathBuf;
use std::process::ExitCode;

fn main() -> ExitCode {
    let out = std::env::args_os()
        .nth(1)
        .map_or_else(|| PathBuf::from("yoshimura.fold"), PathBuf::from);
    let params = Yoshimura::default();
    let pattern = match params.build() {
        Ok(p) => p,
        Err(e) => {
            eprintln!("yoshimura: {e}");
            return ExitCode::from(2);
        }
    };
    let report = check(&pattern, &CheckOptions::default());
    println!(
        "{}: {} vertices, {} edges, flat-foldable at every interior vertex: {}",
        pattern.meta.title.as_deref().unwrap_or("yoshimura"),
        pattern.vertices.len(),
        pattern.edges.len(),
        report.passed()
    );
    if let Err(e) = foldcam::formats::save(&out, &pattern, None) {
        eprintln!("yoshimura: {e}");
        return ExitCode::from(2);
    }
    println!("wrote {}", out.display());
    ExitCode::SUCCESS
}
