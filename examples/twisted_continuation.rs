//! Scratch probe: limit continuation for twisted stars on a spherical cap.
//! `twisted_continuation N RINGS DEG RADIUS REMESH SHRINK MAXIT fold,angle [fold,angle ...]`
use std::time::Instant;

use foldcam::design::tessellation::*;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let a: Vec<String> = std::env::args().skip(1).collect();
    let mut mesh = spherical_cap(a[0].parse()?, a[1].parse()?, a[2].parse()?, a[3].parse()?);
    let faces: usize = a[4].parse()?;
    if faces > 0 {
        let (m, r) = remesh(&mesh, faces)?;
        println!("{}", r.describe());
        mesh = m;
    }
    let shrink: f64 = a[5].parse()?;
    let max_it: usize = a[6].parse()?;
    let stages: Vec<(f64, f64)> = a[7..]
        .iter()
        .map(|s| {
            let mut p = s.split(',').map(|v| v.parse::<f64>().unwrap());
            (p.next().unwrap(), p.next().unwrap())
        })
        .collect();
    let final_limits = Limits::from_degrees(165.0, 30.0);
    let he = disk(&mesh)?;
    let mut star = StarOptions {
        shrink,
        ..Default::default()
    };
    star.tuck.kind = TuckKind::Twisted;
    if let Ok(t) = std::env::var("TWIST") {
        star.tuck.twist = t.parse::<f64>()?.to_radians();
    }
    star.max_star_points = Some(max_star_points(
        final_limits.min_vertex_angle + final_limits.margin,
    ));
    let mut initial = star_tucks_shrunk(&he, &star, None)?;
    assign_folds(&mut initial.mesh);
    let mut m = initial.mesh.clone();
    let start = Instant::now();
    let verbose = std::env::var("VERBOSE").is_ok();
    let mut total = 0;
    for (fold, angle) in stages {
        let mut opts = SolveOptions {
            limits: Limits::from_degrees(fold, angle),
            max_iterations: max_it,
            ..Default::default()
        };
        opts.damped_fallback = std::env::var("LM").is_ok();
        if let Ok(t) = std::env::var("TOL") {
            opts.tolerance = t.parse()?;
        }
        let t = Instant::now();
        let r = solve(&mut m, &opts, |it| {
            if verbose {
                println!(
                    "  it {:3}: dev {:.2e} fold {:.2} angle {:.2} illegal {} pen {:.1e} bt {:.2} active {:?} step {:.3}",
                    it.index,
                    it.residuals.developability,
                    it.residuals.max_fold.to_degrees(),
                    it.residuals.min_vertex_angle.to_degrees(),
                    it.residuals.illegal_creases,
                    it.residuals.max_penalty,
                    it.residuals.boundary_turn.to_degrees(),
                    it.active,
                    it.step
                );
            }
            std::ops::ControlFlow::Continue(())
        })?;
        total += r.iterations;
        println!(
            "stage {fold},{angle}: {} it, {:.2} s: conv {} dev {:.2e} fold {:.2} angle {:.2} wrong {:.3} pen {:.1e} bt {:.2} flat {:.1e}",
            r.iterations,
            t.elapsed().as_secs_f64(),
            r.converged,
            r.last.developability,
            r.last.max_fold.to_degrees(),
            r.last.min_vertex_angle.to_degrees(),
            r.last.wrong_sign.to_degrees(),
            r.last.max_penalty,
            r.last.boundary_turn.to_degrees(),
            r.last.max_flat,
        );
    }
    let check = solve(
        &mut m,
        &SolveOptions {
            limits: final_limits,
            max_iterations: 0,
            ..Default::default()
        },
        |_| std::ops::ControlFlow::Continue(()),
    )?;
    assign_free_folds(&mut m);
    let inter = intersecting_triangles(&m.positions, &m.triangles, 1e-3)?;
    let unf = unfold(&m);
    println!(
        "total {total} it {:.2} s; final-limits converged {}; intersections {}; unfold ok {}",
        start.elapsed().as_secs_f64(),
        check.converged,
        inter.len(),
        unf.is_ok()
    );
    println!("{}", check.summary());
    if let Some(d) = corner_distance(&mesh, &m) {
        println!("distance max {:.2} mean {:.2}", d.max, d.mean);
    }
    Ok(())
}
