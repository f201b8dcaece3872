//! Where and when the folded form of a tessellated spherical cap passes through itself: the
//! solve (Tachi 2014, §3.3) is run in chunks of iterations and after each chunk the
//! intersecting face pairs are counted; at the end every pair is classified (shrunk input face
//! or tuck, the input vertices it belongs to, whether they lie on the input boundary, how many
//! input edges apart the two owners are) and re-checked by an independent segment–triangle
//! test.
//!
//! `cargo run --release --example tessellation_collisions -- N RINGS DEG RADIUS MODE SHRINK REMESH_FACES [CHUNK]`
//! MODE is star, truncated, twisted or twist; REMESH_FACES 0 keeps the input triangles.
//! With DUMP set, the pairs the independent test does not confirm are printed.
//! With COLLISION_GAP=MM the solve has collision rows keeping that gap; with GROUND set, the boundary is held on the plane of its lowest vertex (Tachi 2014, §6).
//! With FLIP set, every face is turned over first (the tucks then lie on the convex side).
//! With TUCK_DEPTH=A,B every tuck's own vertices (key vertex or flat n-gon) are moved from
//! their input vertex by A (at the pole) to B (at the rim) times their initial offset,
//! quadratically in the polar angle.
//! With COLLISION_AFTER=MM the solve runs without collision rows until it converges, then
//! continues from that state with rows keeping that gap (a continuation, up to 400 iterations
//! in all).

use std::collections::{HashSet, VecDeque};
use std::time::Instant;

use foldcam::design::tessellation::samples::spherical_cap;
use foldcam::design::tessellation::steps::{
    assign_folds, disk, intersecting_triangles, max_star_points, remesh, solve, star_tucks,
};
use foldcam::design::tessellation::{Limits, SolveOptions, StarOptions, TessMesh, TuckKind};
use foldcam::geom::segment_through_triangle;
use glam::DVec3;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let a: Vec<String> = std::env::args().skip(1).collect();
    if a.len() < 7 {
        return Err("usage: N RINGS DEG RADIUS MODE SHRINK REMESH_FACES [CHUNK]".into());
    }
    let mut mesh = spherical_cap(a[0].parse()?, a[1].parse()?, a[2].parse()?, a[3].parse()?);
    if std::env::var("FLIP").is_ok() {
        let faces: Vec<Vec<u32>> = mesh
            .faces()
            .iter()
            .map(|f| f.iter().rev().copied().collect())
            .collect();
        mesh = foldcam::mesh::PolyMesh::new(mesh.positions().to_vec(), faces)?;
    }
    let faces: usize = a[6].parse()?;
    if faces > 0 {
        let (m, r) = remesh(&mesh, faces)?;
        println!("{}", r.describe());
        mesh = m;
    }
    let chunk: usize = a.get(7).map_or(Ok(10), |c| c.parse())?;
    let mut limits = Limits::from_degrees(165.0, 30.0);
    let mut star = StarOptions::default();
    star.tuck.kind = match a[4].as_str() {
        "star" => TuckKind::Star,
        "truncated" => TuckKind::Truncated,
        "twisted" => TuckKind::Twisted,
        "twist" => TuckKind::TwistFold,
        m => return Err(format!("unknown mode {m}").into()),
    };
    star.shrink = a[5].parse()?;
    star.max_star_points = Some(max_star_points(limits.min_vertex_angle + limits.margin));
    let he = disk(&mesh)?;
    let boundary: Vec<bool> = (0..mesh.positions().len())
        .map(|v| he.is_boundary(v))
        .collect();
    let mut init = star_tucks(&he, &star)?;
    if let Ok(spec) = std::env::var("TUCK_DEPTH") {
        let ab: Vec<f64> = spec
            .split(',')
            .map(|v| v.parse())
            .collect::<Result<_, _>>()?;
        let (inner, outer) = (ab[0], ab[1]);
        let x = mesh.positions();
        let cap_deg: f64 = a[2].parse()?;
        let radius: f64 = a[3].parse()?;
        let m = &mut init.mesh;
        for v in m.corner_count..m.positions.len() {
            let iv = m.input_vertex[v] as usize;
            let p = x[iv];
            let u = (1.0 + p.z / radius).clamp(-1.0, 1.0).acos().to_degrees() / cap_deg;
            let scale = inner + (outer - inner) * u * u;
            m.positions[v] = p + scale * (m.positions[v] - p);
        }
    }
    assign_folds(&mut init.mesh);
    let mut t = init.mesh.clone();
    limits.collision_gap = std::env::var("COLLISION_GAP").map_or(Ok(0.0), |g| g.parse())?;
    if std::env::var("GROUND").is_ok() {
        limits.ground_z = t
            .positions
            .iter()
            .zip(&t.interior)
            .filter(|(_, inside)| !**inside)
            .map(|(p, _)| p.z)
            .reduce(f64::min);
        println!("ground at z = {:?}", limits.ground_z);
    }
    let tol = 1e-3;
    let count = |m: &TessMesh| intersecting_triangles(&m.positions, &m.triangles, tol).unwrap();
    println!(
        "initial pattern: {} triangles, {} intersecting pairs",
        t.triangles.len(),
        count(&t).len()
    );
    let start = Instant::now();
    let mut done = 0;
    let after: Option<f64> = std::env::var("COLLISION_AFTER")
        .ok()
        .map(|g| g.parse())
        .transpose()?;
    let mut switched = false;
    loop {
        // The collision rows do not enter the solver's convergence test: in the continuation
        // it runs on (a tolerance nothing reaches) until the pairs are gone or it stalls.
        let opts = SolveOptions {
            limits,
            max_iterations: chunk,
            tolerance: if switched { 1e-300 } else { 1e-12 },
            ..SolveOptions::default()
        };
        let r = solve(&mut t, &opts, ())?;
        done += r.iterations;
        let pairs = count(&t);
        println!(
            "after {done:4} it ({:.1} s): dev {:.2e} fold {:.2} angle {:.2} boundary turn {:.1} deg, {} pairs ({} sharing no vertex){}",
            start.elapsed().as_secs_f64(),
            r.last.developability,
            r.last.max_fold.to_degrees(),
            r.last.min_vertex_angle.to_degrees(),
            r.last.boundary_turn.to_degrees(),
            pairs.len(),
            pairs
                .iter()
                .filter(|&&(p, q)| !t.triangles[p].iter().any(|v| t.triangles[q].contains(v)))
                .count(),
            if r.converged { ", converged" } else { "" }
        );
        if switched && pairs.is_empty() && r.last.developability <= 1e-12 {
            println!("continuation: no pairs left, developability within 1e-12 rad");
            break;
        }
        if r.converged
            && !switched
            && let Some(gap) = after
            && !pairs.is_empty()
        {
            println!("converged without collision rows; continuing with a {gap} mm gap");
            limits.collision_gap = gap;
            switched = true;
            continue;
        }
        // A solve that stops short of its chunk without converging has stalled.
        if r.converged || r.iterations < chunk || done >= 400 {
            break;
        }
    }
    let pairs = count(&t);
    // Owners: a shrunk input face (all three vertices are face corners) names its three input
    // vertices; a tuck triangle names the input vertex of its tuck vertex.
    let owner = |tri: [u32; 3]| -> Vec<u32> {
        if let Some(&v) = tri.iter().find(|&&v| v as usize >= t.corner_count) {
            vec![t.input_vertex[v as usize]]
        } else {
            tri.iter().map(|&v| t.input_vertex[v as usize]).collect()
        }
    };
    let mut neighbours = vec![Vec::new(); mesh.positions().len()];
    for f in mesh.faces() {
        for k in 0..f.len() {
            let (p, q) = (f[k] as usize, f[(k + 1) % f.len()] as usize);
            neighbours[p].push(q);
            neighbours[q].push(p);
        }
    }
    let hops = |from: &[u32], to: &[u32]| -> usize {
        let goal: HashSet<usize> = to.iter().map(|&v| v as usize).collect();
        let mut seen = vec![false; neighbours.len()];
        let mut queue: VecDeque<(usize, usize)> = from.iter().map(|&v| (v as usize, 0)).collect();
        while let Some((v, d)) = queue.pop_front() {
            if goal.contains(&v) {
                return d;
            }
            if std::mem::replace(&mut seen[v], true) {
                continue;
            }
            queue.extend(neighbours[v].iter().map(|&w| (w, d + 1)));
        }
        usize::MAX
    };
    let x = &t.positions;
    let mut kinds = std::collections::BTreeMap::new();
    let mut confirmed = 0;
    let mut longest = 0.0f64;
    for &(p, q) in &pairs {
        let (tp, tq) = (t.triangles[p], t.triangles[q]);
        let (op, oq) = (owner(tp), owner(tq));
        let kind = |o: &Vec<u32>| {
            let edge = o.iter().any(|&v| boundary[v as usize]);
            match (o.len(), edge) {
                (1, false) => "tuck",
                (1, true) => "boundary tuck",
                (_, false) => "face",
                (_, true) => "boundary face",
            }
        };
        let shared = tp.iter().filter(|v| tq.contains(v)).count();
        let mut names = [kind(&op), kind(&oq)];
        names.sort();
        let key = format!(
            "{} / {}, {} input edges apart, sharing {} vertices",
            names[0],
            names[1],
            hops(&op, &oq),
            shared
        );
        *kinds.entry(key).or_insert(0) += 1;
        let len = cut_length(&tp.map(|v| x[v as usize]), &tq.map(|v| x[v as usize]));
        longest = longest.max(len);
        if len > tol {
            confirmed += 1;
        } else if std::env::var("DUMP").is_ok() {
            println!(
                "unconfirmed {p} {tp:?} {:?} / {q} {tq:?} {:?}",
                tp.map(|v| x[v as usize].to_array()),
                tq.map(|v| x[v as usize].to_array())
            );
        }
    }
    println!(
        "{} pairs at tolerance {tol} mm; the independent test confirms {confirmed} (longest cut {longest:.3} mm)",
        pairs.len()
    );
    for (k, n) in &kinds {
        println!("  {n:5} {k}");
    }
    // Where the pairs are: the polar angle of the first owner's input vertex, 5 deg bins.
    let radius: f64 = a[3].parse()?;
    let polar = |v: u32| {
        let p = mesh.positions()[v as usize];
        (1.0 + p.z / radius).clamp(-1.0, 1.0).acos().to_degrees()
    };
    let mut bins = std::collections::BTreeMap::new();
    for &(p, q) in &pairs {
        let angle = owner(t.triangles[p])
            .into_iter()
            .chain(owner(t.triangles[q]))
            .map(polar)
            .fold(0.0, f64::max);
        *bins.entry((angle / 5.0) as usize * 5).or_insert(0) += 1;
    }
    println!("pairs by polar angle of their outermost owner (deg: count): {bins:?}");
    Ok(())
}

/// Length of the segment where triangles `a` and `b` meet, found independently of the
/// library: every edge of either triangle that pierces the other contributes its piercing
/// point (Möller–Trumbore), and the segment spans those points.
fn cut_length(a: &[DVec3; 3], b: &[DVec3; 3]) -> f64 {
    let mut pts = Vec::new();
    for (s, t) in [(a, b), (b, a)] {
        for k in 0..3 {
            if let Some(p) = segment_through_triangle(s[k], s[(k + 1) % 3], t) {
                pts.push(p);
            }
        }
    }
    let mut best = 0.0f64;
    for i in 0..pts.len() {
        for j in i + 1..pts.len() {
            best = best.max(pts[i].distance(pts[j]));
        }
    }
    best
}
