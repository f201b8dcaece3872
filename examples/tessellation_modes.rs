//! The table the tessellation issue asks for: every tuck mode on one mesh with the 0.5 mm
//! stainless limits and the default face-shrink schedule, with iterations, time, the largest
//! fold, the smallest angle between creases and the distance of the folded form's face corners
//! to the input surface.
//!
//! `cargo run --release --example tessellation_modes -- MESH.obj [MODE ...]`
//! `cargo run --release --example tessellation_modes -- cap N RINGS DEGREES RADIUS [MODE ...]`
//! `cargo run --release --example tessellation_modes -- dome|saddle|bell RINGS EDGE [MODE ...]`
//! MODE is star, truncated, twisted or twist (all four by default). With `ATTEMPTS=1` each
//! refused attempt is listed on stderr (shrink, iterations, time, convergence, pairs); with
//! `OLD_SCHEDULE=1` a crowded input is not coarsened first; with `REMESH_FACES=N` only the
//! re-triangulation with about N faces is solved.

use std::time::Instant;

use foldcam::design::tessellation::measure::corner_distance;
use foldcam::design::tessellation::samples::{SampleSurface, sample_surface, spherical_cap};
use foldcam::design::tessellation::{
    Iteration, Limits, Remesh, Schedule, TessellateOptions, Tessellation, TuckKind, Watch,
    tessellate,
};
use foldcam::mesh::read_mesh;
use std::ops::ControlFlow;

/// Two closures as a [`Watch`]: the refused results, then the iterations.
struct Both<R, I>(R, I);

impl<R, I> Watch for Both<R, I>
where
    R: FnMut(f64, &Tessellation) -> ControlFlow<()>,
    I: FnMut(&Iteration) -> ControlFlow<()>,
{
    fn iteration(&mut self, it: &Iteration) -> ControlFlow<()> {
        (self.1)(it)
    }

    fn refused(&mut self, s: f64, t: &Tessellation) -> ControlFlow<()> {
        (self.0)(s, t)
    }
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let (mesh, rest) = match args.first().map(String::as_str) {
        Some("cap") if args.len() >= 5 => {
            let n: usize = args[1].parse()?;
            let rings: usize = args[2].parse()?;
            let deg: f64 = args[3].parse()?;
            let radius: f64 = args[4].parse()?;
            (spherical_cap(n, rings, deg, radius), &args[5..])
        }
        Some(name @ ("dome" | "saddle" | "bell")) if args.len() >= 3 => {
            let surface = match name {
                "dome" => SampleSurface::Dome,
                "saddle" => SampleSurface::Saddle,
                _ => SampleSurface::Bell,
            };
            let rings: usize = args[1].parse()?;
            let edge: f64 = args[2].parse()?;
            (sample_surface(surface, rings, edge), &args[3..])
        }
        Some(path) => (read_mesh(std::path::Path::new(path))?, &args[1..]),
        None => {
            return Err(
                "usage: tessellation_modes MESH.obj|cap N RINGS DEG RADIUS|dome|saddle|bell RINGS EDGE [MODE...]".into(),
            );
        }
    };
    let modes: Vec<TuckKind> = if rest.is_empty() {
        vec![
            TuckKind::Star,
            TuckKind::Truncated,
            TuckKind::Twisted,
            TuckKind::TwistFold,
        ]
    } else {
        rest.iter()
            .map(|m| match m.as_str() {
                "star" => Ok(TuckKind::Star),
                "truncated" => Ok(TuckKind::Truncated),
                "twisted" => Ok(TuckKind::Twisted),
                "twist" => Ok(TuckKind::TwistFold),
                other => Err(format!("unknown mode {other}")),
            })
            .collect::<Result<_, _>>()?
    };
    println!(
        "{} faces, limits: fold <= 165 deg, creases >= 30 deg apart (0.5 mm stainless)",
        mesh.faces().len()
    );
    println!(
        "| mode | result | schedule | iterations (last solve / all) | time s (last / all) | max fold deg | min crease angle deg | corners to surface mm (max / mean) |"
    );
    println!("|---|---|---|---|---|---|---|---|");
    for kind in modes {
        let mut opts = TessellateOptions::with_limits(Limits::from_degrees(165.0, 30.0));
        opts.star.tuck.kind = kind;
        let start = Instant::now();
        let mut all_iterations = 0;
        let mut last_start = Instant::now();
        // Iterations of the running attempt as `progress` counts them (a retry with the
        // stiffer outline counts on from the first solve's).
        let counted = std::cell::Cell::new(0);
        let attempts = std::env::var_os("ATTEMPTS").is_some();
        // OLD_SCHEDULE=1: the re-triangulation at the input's face count named explicitly,
        // which leaves out the coarser one of a crowded input (the schedule before it).
        let mut remesh_faces = None;
        let mut remesh = Remesh::Auto;
        if std::env::var_os("OLD_SCHEDULE").is_some() {
            remesh_faces = Some(mesh.faces().len());
        }
        // REMESH_FACES=N: the re-triangulation with about N faces only (`--remesh N`).
        if let Some(n) = std::env::var("REMESH_FACES")
            .ok()
            .and_then(|n| n.parse().ok())
        {
            remesh_faces = Some(n);
            remesh = Remesh::Only;
        }
        opts.schedule = Schedule::Ladder {
            shrinks: foldcam::design::tessellation::steps::SHRINK_LADDER.to_vec(),
            remesh,
            remesh_faces,
        };
        let t = tessellate(
            &mesh,
            &opts,
            &mut Both(
                |s, t: &Tessellation| {
                    all_iterations += counted.get().max(t.report.iterations);
                    if attempts {
                        eprintln!(
                            "  {kind} shrink {s} on {} faces: {} it ({} counted), {:.2} s, \
                         converged {}, dev {:.2e}, pairs {}, crowded at rim {}",
                            t.crowding.faces,
                            t.report.iterations,
                            counted.get(),
                            last_start.elapsed().as_secs_f64(),
                            t.report.converged,
                            t.report.last.developability,
                            t.intersections.len(),
                            t.crowded_at_rim()
                        );
                    }
                    counted.set(0);
                    last_start = Instant::now();
                    ControlFlow::Continue(())
                },
                |it: &Iteration| {
                    counted.set(it.index);
                    ControlFlow::Continue(())
                },
            ),
        )?;
        let all = start.elapsed().as_secs_f64();
        let last = last_start.elapsed().as_secs_f64();
        all_iterations += counted.get().max(t.report.iterations);
        let d = corner_distance(&mesh, &t.mesh).ok_or("the input mesh has no area")?;
        let r = &t.report.last;
        println!(
            "| {kind} | {} | {} | {} / {} | {:.2} / {:.2} | {:.2} | {:.2} | {:.2} / {:.2} |",
            t.problem().unwrap_or_else(|| "ok".into()),
            match &t.remeshed {
                Some(r) => format!(
                    "remeshed{} to {} faces, shrink {}",
                    if t.coarsened.is_some() {
                        " (coarser: rim crowding)"
                    } else {
                        ""
                    },
                    r.faces[1],
                    t.initial.shrink
                ),
                None => format!("shrink {}", t.initial.shrink),
            },
            t.report.iterations,
            all_iterations,
            last,
            all,
            r.max_fold.to_degrees(),
            r.min_vertex_angle.to_degrees(),
            d.max,
            d.mean
        );
    }
    Ok(())
}
