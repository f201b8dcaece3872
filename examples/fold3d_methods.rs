//! The two ways of settling the bar-and-hinge model (Ghassaei, Demaine & Gershenfeld 2018)
//! side by side on Miura-ori sheets: the explicit dynamics (the default) and the static
//! solve by load steps and Levenberg–Marquardt iterations (`FoldOptions::implicit`). Prints
//! time, steps or linear solves, residual, strain, angle error, and how far apart the two
//! folded forms lie (the largest difference of a fold angle).
//!
//! `cargo run --release --example fold3d_methods -- [SIDE] [PERCENT] [TOLERANCE] [FRAMES]`
//! (default 71 × 71 cells, about 10,000 triangles, folded to 90 %, the default residual
//! tolerance, no frames; with frames the static solve takes one load step per frame).

use foldcam::check::fold3d::{FoldOptions, fold};
use foldcam::design::classic::MiuraOri;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let side: usize = args.first().and_then(|s| s.parse().ok()).unwrap_or(71);
    let percent: f64 = args.get(1).and_then(|s| s.parse().ok()).unwrap_or(90.0);
    let tolerance: f64 = args
        .get(2)
        .and_then(|s| s.parse().ok())
        .unwrap_or(FoldOptions::default().tolerance);
    let frames: usize = args.get(3).and_then(|s| s.parse().ok()).unwrap_or(0);
    // `build` cleans the drawing and traces its faces, as the simulation needs.
    let cp = MiuraOri {
        columns: side,
        rows: side,
        ..MiuraOri::default()
    }
    .build()
    .expect("miura");
    let mut forms = Vec::new();
    for implicit in [false, true] {
        let opts = FoldOptions {
            percent,
            implicit,
            tolerance,
            frames,
            ..FoldOptions::default()
        };
        let f = fold(&cp, &opts).expect("fold");
        let r = &f.report;
        let work = match r.static_solve {
            Some(s) => format!(
                "{} explicit steps to start, {} linear solves, {} factorizations, {}",
                r.steps,
                s.linear_solves,
                s.factorizations,
                if s.used { "used" } else { "not used" }
            ),
            None => format!("{} steps", r.steps),
        };
        println!(
            "{:>8}: {} triangles, {:.2} s, {work}, {:?}, residual {:.1e}, strain {:.2e}, angle \
             error {:.3} deg, wrong sign {}, crossing faces {}, {} frames",
            if implicit { "static" } else { "explicit" },
            r.triangles,
            r.seconds,
            r.stop,
            r.residual,
            r.max_strain,
            r.max_angle_error_deg,
            r.wrong_sign.len(),
            r.crossing_faces.len(),
            f.frames.len()
        );
        forms.push(r.fold_angles.clone());
    }
    // Fold angles compare the forms whatever rigid motion separates them.
    let apart = forms[0]
        .iter()
        .zip(&forms[1])
        .filter_map(|(a, b)| Some((a.as_ref()? - b.as_ref()?).abs()))
        .fold(0.0, f64::max);
    println!("largest fold-angle difference between the two forms: {apart:.3} deg");
}
