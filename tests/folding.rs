//! Fold-sequence simulator (seed 003): isometry after every step, consistent layer orders,
//! flat-foldable crease patterns, exact undo, the fabrication pipeline on the bird base.

use std::path::PathBuf;

use foldcam::check::{CheckOptions, FindingKind, check};
use foldcam::design::folding::Folding;
use foldcam::design::folding::crease::{crease_pattern, step_states};
use foldcam::design::folding::layers::layer_problems;
use foldcam::design::folding::script::{parse_script, run_script};
use foldcam::pattern::Assignment;

fn example(name: &str) -> Folding {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("examples/folding")
        .join(name);
    let text = std::fs::read_to_string(&path).expect("example readable");
    let script = parse_script(&text).unwrap_or_else(|e| panic!("{name}: {e}"));
    run_script(&script).unwrap_or_else(|e| panic!("{name}: {e}"))
}

#[test]
fn waterbomb_base_debug() {
    let f = example("waterbomb-base.toml");
    for s in f.steps() {
        eprintln!("{}: {:?}", s.summary, s.state.groups);
    }
    let sp = crease_pattern(&f);
    for e in &sp.pattern.edges {
        eprintln!(
            "{:?} {:?} {:?} {:?}",
            sp.pattern.vertices[e.vertices[0].index()],
            sp.pattern.vertices[e.vertices[1].index()],
            e.assignment,
            e.fold_angle
        );
    }
    eprintln!("{:?}", layer_problems(&f, f.current()));
    let r = check(&sp.pattern, &CheckOptions::default());
    eprintln!("{:?}", r.findings);
    let _ = step_states(&f, &sp);
    let _ = (FindingKind::Kawasaki, Assignment::Valley);
}
