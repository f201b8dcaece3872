//! One tessellation solve on a spherical cap (`spherical_cap`), optionally re-triangulated
//! first, with the time and state of every Newton iteration (Tachi 2014, §3.3), the result,
//! and where the folded form's intersecting face pairs lie (how deep, how far from the axis).
//! With `SHRINK_OUTER=S` the face shrink grows from SHRINK at the axis to S at the rim
//! (quadratically in the distance from the axis) instead of being uniform.
//! With `MAX_IT=N` the solve's iteration cap is N instead of the default.
//!
//! `cargo run --release --example tessellation_profile -- N RINGS DEG RADIUS MODE SHRINK [REMESH_FACES]`
//! MODE is star, truncated, twisted or twist.

use std::time::Instant;

use foldcam::design::tessellation::samples::spherical_cap;
use foldcam::design::tessellation::steps::remesh;
use foldcam::design::tessellation::{Limits, Schedule, TessellateOptions, TuckKind, tessellate};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let a: Vec<String> = std::env::args().skip(1).collect();
    if a.len() < 6 {
        return Err("usage: N RINGS DEG RADIUS MODE SHRINK [REMESH_FACES]".into());
    }
    let mut mesh = spherical_cap(a[0].parse()?, a[1].parse()?, a[2].parse()?, a[3].parse()?);
    if let Some(f) = a.get(6) {
        let t = Instant::now();
        let (m, r) = remesh(&mesh, f.parse()?)?;
        println!("{} ({:.2} s)", r.describe(), t.elapsed().as_secs_f64());
        mesh = m;
    }
    let mut opts = TessellateOptions::with_limits(Limits::from_degrees(165.0, 30.0));
    opts.star.tuck.kind = match a[4].as_str() {
        "star" => TuckKind::Star,
        "truncated" => TuckKind::Truncated,
        "twisted" => TuckKind::Twisted,
        "twist" => TuckKind::TwistFold,
        m => return Err(format!("unknown mode {m}").into()),
    };
    opts.star.shrink = a[5].parse()?;
    if let Some(cap) = std::env::var("MAX_IT").ok().and_then(|v| v.parse().ok()) {
        opts.solve.max_iterations = cap;
    }
    let start = Instant::now();
    let mut last = Instant::now();
    let outer: Option<f64> = std::env::var("SHRINK_OUTER")
        .ok()
        .and_then(|v| v.parse().ok());
    let mut progress = |it: &foldcam::design::tessellation::Iteration| {
        println!(
            "it {:3} {:6.3} s: dev {:.2e} fold {:.2} angle {:.2} illegal {} active {:?} step {:.3} cg {}",
            it.index,
            last.elapsed().as_secs_f64(),
            it.residuals.developability,
            it.residuals.max_fold.to_degrees(),
            it.residuals.min_vertex_angle.to_degrees(),
            it.residuals.illegal_creases,
            it.active,
            it.step,
            it.cg_iterations
        );
        last = Instant::now();
        std::ops::ControlFlow::Continue(())
    };
    let t = match outer {
        None => tessellate(&mesh, &opts, &mut progress)?,
        Some(outer) => {
            let x = mesh.positions();
            let r = |p: glam::DVec3| (p.x * p.x + p.y * p.y).sqrt();
            let rmax = x.iter().map(|&p| r(p)).fold(0.0, f64::max);
            let inner = opts.star.shrink;
            let shrinks: Vec<f64> = mesh
                .faces()
                .iter()
                .map(|f| {
                    let c = f.iter().map(|&v| x[v as usize]).sum::<glam::DVec3>() / f.len() as f64;
                    let u = r(c) / rmax;
                    inner + (outer - inner) * u * u
                })
                .collect();
            opts.schedule = Schedule::FaceShrinks(shrinks);
            tessellate(&mesh, &opts, &mut progress)?
        }
    };
    println!(
        "{} faces: {} in {:.2} s total; problem: {:?}",
        mesh.faces().len(),
        t.report.summary(),
        start.elapsed().as_secs_f64(),
        t.problem()
    );
    // How deep the intersecting pairs cross: per pair, the smaller of the two triangles'
    // straddles of the other's plane (the lesser of the largest distances on either side).
    let x = &t.mesh.positions;
    let mut depths: Vec<(f64, usize, usize, usize)> = t
        .intersections
        .iter()
        .map(|&(a, b)| {
            let ta = t.mesh.triangles[a].map(|v| x[v as usize]);
            let tb = t.mesh.triangles[b].map(|v| x[v as usize]);
            let straddle = |p: &[glam::DVec3; 3], q: &[glam::DVec3; 3]| {
                let n = (q[1] - q[0]).cross(q[2] - q[0]).normalize();
                let d = p.map(|v| n.dot(v - q[0]));
                let hi = d.iter().cloned().fold(f64::MIN, f64::max);
                let lo = d.iter().cloned().fold(f64::MAX, f64::min);
                hi.min(-lo)
            };
            let shared = t.mesh.triangles[a]
                .iter()
                .filter(|v| t.mesh.triangles[b].contains(v))
                .count();
            (straddle(&ta, &tb).min(straddle(&tb, &ta)), a, b, shared)
        })
        .collect();
    depths.sort_by(|p, q| q.0.total_cmp(&p.0));
    for d in depths.iter().take(5) {
        println!(
            "pair {} {}: depth {:.3e} mm, shared vertices {}",
            d.1, d.2, d.0, d.3
        );
    }
    let shared = depths.iter().filter(|d| d.3 > 0).count();
    println!("{} pairs, {} sharing a vertex", depths.len(), shared);
    let tris = &t.mesh.triangles;
    let radial = |f: usize| {
        let c = tris[f].iter().map(|&v| x[v as usize]).sum::<glam::DVec3>() / 3.0;
        (c.x * c.x + c.y * c.y).sqrt()
    };
    let rmax = x
        .iter()
        .map(|p| (p.x * p.x + p.y * p.y).sqrt())
        .fold(0.0, f64::max);
    let mut hist = [0usize; 10];
    for &(a, _) in &t.intersections {
        hist[((radial(a) / rmax * 10.0) as usize).min(9)] += 1;
    }
    println!("colliding pairs by radial tenth of {rmax:.1} mm: {hist:?}");
    for &(a, b) in t.intersections.iter().take(3) {
        println!("tri {a} {:?} tri {b} {:?}", tris[a], tris[b]);
    }
    Ok(())
}
