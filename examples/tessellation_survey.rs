//! The tessellation issue's own set of everyday meshes, each tessellated in every tuck mode by
//! the default path of `foldcam tessellate` (0.5 mm stainless limits: fold at most 165 deg,
//! creases at least 30 deg apart; the face-shrink ladder over the triangulations; the one-minute time limit),
//! with one table row per run: result, iterations, time, worst fold and crease angle, face
//! pairs crossing, the input's area the form covers and its largest distance from the input.
//!
//! The set: saddles of three curvatures, a sinusoidal height field, a cylinder and a torus
//! patch (hexagonal patches of 6·RINGS² faces, `samples::sample_surface`), the bell, spherical
//! caps made two ways (`samples::spherical_cap`, `samples::uv_cap`) at 432, about 2,000 and
//! 10,092 faces, and a 60 mm patch cut from the Stanford bunny (npm `bunny`; the path in
//! `FOLDCAM_BUNNY_OBJ`, as `.ci/run` sets it, else `target/bunny.obj`; left out when absent).
//!
//! `cargo run --release --example tessellation_survey [-- NAME ...] [--modes star,truncated]`
//! runs the named meshes (all by default); `--write DIR` writes the meshes as OBJ files and
//! solves nothing; `--time-limit S` changes the limit.

use std::collections::{BTreeSet, HashMap};
use std::ops::ControlFlow;
use std::path::{Path, PathBuf};
use std::time::Instant;

use foldcam::design::source::TessellationOptions;
use foldcam::design::source::tess_design::tuck_by_name;
use foldcam::design::tessellation::measure::surface_fit;
use foldcam::design::tessellation::samples::{
    SampleSurface, sample_surface, spherical_cap, uv_cap,
};
use foldcam::design::tessellation::{Iteration, TuckKind, tessellate};
use foldcam::formats::write_atomic;
use foldcam::mesh::{PolyMesh, read_mesh};
use glam::DVec3;

type Error = Box<dyn std::error::Error>;

fn main() -> Result<(), Error> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let mut names = Vec::new();
    let mut modes = vec![
        TuckKind::Star,
        TuckKind::Truncated,
        TuckKind::Twisted,
        TuckKind::TwistFold,
    ];
    let mut write = None;
    let mut time_limit = 60.0;
    let mut it = args.iter();
    while let Some(a) = it.next() {
        match a.as_str() {
            "--modes" => {
                let list = it.next().ok_or("--modes needs a list")?;
                modes = list
                    .split(',')
                    .map(|m| tuck_by_name(m).ok_or(format!("unknown mode {m}")))
                    .collect::<Result<_, _>>()?;
            }
            "--write" => write = Some(PathBuf::from(it.next().ok_or("--write needs a DIR")?)),
            "--time-limit" => time_limit = it.next().ok_or("--time-limit needs S")?.parse()?,
            name => names.push(name.to_string()),
        }
    }
    let set = mesh_set()?;
    let chosen: Vec<&(String, PolyMesh)> = set
        .iter()
        .filter(|(n, _)| names.is_empty() || names.contains(n))
        .collect();
    if let Some(dir) = write {
        std::fs::create_dir_all(&dir)?;
        for (name, mesh) in chosen {
            let path = dir.join(format!("{name}.obj"));
            write_atomic(&path, mesh.to_obj().as_bytes())?;
            println!("wrote {} ({} faces)", path.display(), mesh.faces().len());
        }
        return Ok(());
    }
    println!(
        "| mesh | faces | mode | result | solved on faces, shrink | iterations | time s | worst fold deg | min crease angle deg | crossing pairs | area kept | farthest corner mm |"
    );
    println!("|---|---|---|---|---|---|---|---|---|---|---|---|");
    for (name, mesh) in chosen {
        for &kind in &modes {
            let options = TessellationOptions {
                tuck: kind,
                time_limit_s: Some(time_limit),
                ..TessellationOptions::default()
            };
            let opts = options.to_solver()?;
            let mut iterations = 0usize;
            let start = Instant::now();
            let t = tessellate(mesh, &opts, &mut |_: &Iteration| {
                iterations += 1;
                ControlFlow::Continue(())
            });
            let seconds = start.elapsed().as_secs_f64();
            let t = match t {
                Ok(t) => t,
                Err(e) => {
                    println!(
                        "| {name} | {} | {kind} | error: {e} | | | {seconds:.1} | | | | | |",
                        mesh.faces().len()
                    );
                    continue;
                }
            };
            let fit = surface_fit(mesh, &t.mesh);
            let result = match (t.problem(), fit.as_ref().and_then(|f| f.partial())) {
                (Some(p), _) => format!("refused: {}", short(&p)),
                (None, Some(p)) => format!("partial: {}", short(&p)),
                (None, None) => "usable".to_string(),
            };
            let r = &t.report.last;
            println!(
                "| {name} | {} | {kind} | {result} | {} {} | {iterations} | {seconds:.1} | {:.1} | {:.1} | {} | {} | {} |",
                mesh.faces().len(),
                t.remeshed.map_or(mesh.faces().len(), |r| r.faces[1]),
                t.initial.shrink,
                r.max_fold.to_degrees(),
                r.min_vertex_angle.to_degrees(),
                t.intersections.len(),
                fit.as_ref()
                    .map_or("-".into(), |f| format!("{:.1}%", 100.0 * f.covered)),
                fit.as_ref()
                    .map_or("-".into(), |f| format!("{:.1}", f.distance.max)),
            );
        }
    }
    Ok(())
}

/// The first clause of a refusal, for a table cell.
fn short(problem: &str) -> String {
    let first = problem.split(" (first").next().unwrap_or(problem);
    first.replace('|', "/")
}

/// The survey's meshes, by name.
fn mesh_set() -> Result<Vec<(String, PolyMesh)>, Error> {
    let mut set = Vec::new();
    for (name, surface) in [
        ("saddle-shallow", SampleSurface::ShallowSaddle),
        ("saddle", SampleSurface::Saddle),
        ("saddle-steep", SampleSurface::SteepSaddle),
        ("waves", SampleSurface::Waves),
        ("cylinder", SampleSurface::Cylinder),
        ("torus", SampleSurface::Torus),
        ("bell", SampleSurface::Bell),
    ] {
        set.push((name.to_string(), sample_surface(surface, 6, 10.0)));
    }
    set.push(("cap-60".into(), spherical_cap(12, 6, 60.0, 100.0)));
    set.push(("uv-cap-60".into(), uv_cap(24, 9, 60.0, 100.0)));
    set.push(("cap-30-2028".into(), spherical_cap(12, 13, 30.0, 100.0)));
    set.push(("cap-52-2028".into(), spherical_cap(12, 13, 52.0, 100.0)));
    set.push(("uv-cap-30-1960".into(), uv_cap(40, 25, 30.0, 100.0)));
    set.push(("cap-52-10092".into(), spherical_cap(12, 29, 52.0, 100.0)));
    let bunny = std::env::var_os("FOLDCAM_BUNNY_OBJ")
        .map(PathBuf::from)
        .unwrap_or_else(|| Path::new(env!("CARGO_MANIFEST_DIR")).join("target/bunny.obj"));
    if bunny.exists() {
        set.push((
            "bunny-patch".into(),
            bunny_patch(&read_mesh(&bunny)?, 30.0)?,
        ));
    } else {
        eprintln!(
            "{}: not found, the bunny patch is left out",
            bunny.display()
        );
    }
    Ok(set)
}

/// A geodesic disk of radius `reach` mm on the Stanford bunny scaled to 150 mm tall (y up):
/// the faces whose corners all lie within `reach` of a seed vertex, measured along the edges
/// (Dijkstra). The seed is the highest vertex below the ears whose patch is a disk (connected,
/// one boundary, Euler characteristic 1).
fn bunny_patch(bunny: &PolyMesh, reach: f64) -> Result<PolyMesh, Error> {
    let (lo, hi) = bunny.bounds();
    let scale = 150.0 / (hi.y - lo.y);
    let positions: Vec<DVec3> = bunny.positions().iter().map(|p| *p * scale).collect();
    let mut neighbours: Vec<Vec<u32>> = vec![Vec::new(); positions.len()];
    for f in bunny.faces() {
        for i in 0..f.len() {
            let (a, b) = (f[i], f[(i + 1) % f.len()]);
            neighbours[a as usize].push(b);
            neighbours[b as usize].push(a);
        }
    }
    // Seeds: the highest vertices below the ears (the top quarter), tried in turn.
    let below_ears = lo.y * scale + 0.75 * 150.0;
    let mut seeds: Vec<usize> = (0..positions.len())
        .filter(|&v| positions[v].y < below_ears)
        .collect();
    seeds.sort_by(|&a, &b| positions[b].y.total_cmp(&positions[a].y));
    for &seed in seeds.iter().step_by(7).take(40) {
        let distance = geodesic(&positions, &neighbours, seed, reach);
        let faces: Vec<Vec<u32>> = bunny
            .faces()
            .iter()
            .filter(|f| f.iter().all(|&v| distance[v as usize] <= reach))
            .cloned()
            .collect();
        if let Some(patch) = as_disk(&positions, &faces) {
            return Ok(patch);
        }
    }
    Err("no seed on the bunny's back gives a disk".into())
}

/// Distances along the edges from `seed`, up to `reach` (beyond: infinity).
fn geodesic(positions: &[DVec3], neighbours: &[Vec<u32>], seed: usize, reach: f64) -> Vec<f64> {
    let mut distance = vec![f64::INFINITY; positions.len()];
    distance[seed] = 0.0;
    let mut queue = BTreeSet::new();
    queue.insert((0u64, seed));
    while let Some((d, v)) = queue.pop_first() {
        let d = f64::from_bits(d);
        if d > distance[v] {
            continue;
        }
        for &w in &neighbours[v] {
            let w = w as usize;
            let e = d + positions[v].distance(positions[w]);
            if e < distance[w] && e <= reach {
                distance[w] = e;
                queue.insert((e.to_bits(), w));
            }
        }
    }
    distance
}

/// The faces as a mesh of their own vertices when they form one disk, else `None`.
fn as_disk(positions: &[DVec3], faces: &[Vec<u32>]) -> Option<PolyMesh> {
    if faces.is_empty() {
        return None;
    }
    let mut index = HashMap::new();
    let mut kept = Vec::new();
    let mut renumbered = Vec::new();
    for f in faces {
        renumbered.push(
            f.iter()
                .map(|&v| {
                    *index.entry(v).or_insert_with(|| {
                        kept.push(positions[v as usize]);
                        (kept.len() - 1) as u32
                    })
                })
                .collect::<Vec<u32>>(),
        );
    }
    let mesh = PolyMesh::new(kept, renumbered).ok()?;
    foldcam::design::tessellation::steps::disk(&mesh).ok()?;
    Some(mesh)
}
