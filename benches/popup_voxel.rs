//! Voxel pop-up cards (Mitani, Suzuki & Uno 2003): from a depth map to a checked card and its crease pattern.
//!
//! The paper reports 60 ms of bump removal and 2.5 s of constraint and windows for an
//! 80 × 40 × 40 model on a 1.2 GHz PC (mesh input, §3). `mesh_to_card` measures the same
//! path on the bundled `examples/popup/building.obj` (parsed once): depth from the front,
//! opening and closing, eq. 7, the window and thin-top searches, and the final check, at 80
//! and 800 cells along the fold (80 × 41 × 41 and 800 × 392 × 392 cells, one row and one cell
//! of margin included). On a synthetic stepped "city" depth map it also measures the later
//! stages: `card` (depth map → staircase card by eq. 7), `check` (§2.6 floods) and `pattern`
//! (Table 1 crease pattern, merged lines, planarised), at 80 × 40 × 40 and 800 × 400 × 400.
//!
//! `mesh_to_card/bumpy_320` is a real-mesh case of the Stanford bunny's complexity, made here:
//! a bumpy body, a head and two ears leaning forward over it (overhangs under which eq. 7
//! fills, thin steps all over the curved surface), seen from the front at `--resolution`
//! 320; its first line on standard error gives the searches' counts (thin tops, windows,
//! pop-up checks and those over the whole card).
//!
//! Run with `cargo bench --bench popup_voxel` (`-- bumpy` for the mesh of bunny complexity
//! alone).

use criterion::{Criterion, criterion_group, criterion_main};
use foldcam::design::popup::voxel::{
    ConvertOptions, DepthMap, MeshPlacement, card_from_depth_map, card_from_depths, check_popup,
    crease_pattern, depth_field_from_mesh,
};

/// A `w × h` depth map of rectangular blocks with heights that step down towards the top, as
/// buildings on a street front: grey levels from a fixed linear congruential sequence.
fn city(w: usize, h: usize) -> Vec<u16> {
    let mut seed = 0x9e37_79b9_7f4a_7c15u64;
    let mut next = move || {
        seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (seed >> 33) as u32
    };
    let block = (w / 10).max(2);
    let mut levels = vec![0u16; w * h];
    for x0 in (block..w.saturating_sub(block)).step_by(block) {
        let top = h / 4 + next() as usize % (h / 2);
        let grey = 8000 + (next() % 50000) as u16;
        for x in x0..(x0 + block * 3 / 4).min(w) {
            for row in (h - top)..h {
                levels[row * w + x] = grey;
            }
        }
    }
    levels
}

/// One closed UV sphere of `n` segments around and `n / 2` up, centred at `c` with radii `r`,
/// its radius scaled by `bump(around, up)` (angles in radians), leaning by `lean` radians
/// about the x axis; appended to `obj` as vertices and triangles.
fn blob(
    obj: &mut String,
    c: [f64; 3],
    r: [f64; 3],
    lean: f64,
    n: usize,
    bump: impl Fn(f64, f64) -> f64,
) {
    use std::fmt::Write as _;
    let first = obj.lines().filter(|l| l.starts_with("v ")).count() + 1;
    let (m, tau) = (n / 2, std::f64::consts::TAU);
    for j in 0..=m {
        let up = j as f64 / m as f64 * std::f64::consts::PI;
        for i in 0..n {
            let around = i as f64 / n as f64 * tau;
            let k = bump(around, up);
            let p = [
                r[0] * k * up.sin() * around.cos(),
                r[1] * k * up.sin() * around.sin(),
                r[2] * k * up.cos(),
            ];
            let (y, z) = (
                p[1] * lean.cos() - p[2] * lean.sin(),
                p[1] * lean.sin() + p[2] * lean.cos(),
            );
            let _ = writeln!(obj, "v {} {} {}", c[0] + p[0], c[1] + y, c[2] + z);
        }
    }
    let id = |i: usize, j: usize| first + j * n + i % n;
    for j in 0..m {
        for i in 0..n {
            let (a, b, c, d) = (id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
            let _ = writeln!(obj, "f {a} {b} {c}\nf {a} {c} {d}");
        }
    }
}

/// A mesh of the bunny's complexity (see the module docs), z up, y towards the viewer.
fn bumpy_mesh() -> foldcam::mesh::PolyMesh {
    let mut obj = String::new();
    let body = |a: f64, u: f64| {
        1.0 + 0.06 * (5.0 * a).sin() * (4.0 * u).sin() + 0.03 * (13.0 * a + 3.0 * u).sin()
    };
    blob(&mut obj, [0.0, 0.0, 1.0], [1.2, 0.9, 1.0], 0.0, 96, body);
    let head = |a: f64, u: f64| 1.0 + 0.04 * (7.0 * a).sin() * (5.0 * u).cos();
    blob(&mut obj, [0.9, 0.5, 1.9], [0.5, 0.45, 0.45], 0.0, 64, head);
    let ear = |a: f64, u: f64| 1.0 + 0.05 * (3.0 * a + 9.0 * u).sin();
    for x in [0.7, 1.15] {
        blob(&mut obj, [x, 0.7, 2.6], [0.12, 0.18, 0.6], 0.8, 48, ear);
    }
    foldcam::mesh::parse_obj(obj.as_bytes()).expect("bumpy mesh")
}

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("popup_voxel");
    g.sample_size(10);
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/examples/popup/building.obj");
    let mesh = foldcam::mesh::read_mesh(std::path::Path::new(path)).expect("building mesh");
    for resolution in [80, 800] {
        let placement = MeshPlacement {
            resolution,
            ..MeshPlacement::default()
        };
        let to_card = || {
            let (field, _) = depth_field_from_mesh(&mesh, &placement).expect("depth");
            let (card, report) =
                card_from_depths(&field, 1.0, &ConvertOptions::default()).expect("card");
            assert!(check_popup(&card).passed());
            (card, report)
        };
        let (card, report) = to_card();
        let name = format!("{}x{}x{}", card.nx(), card.ny(), card.nz());
        eprintln!("mesh {name}: {report:?}");
        g.bench_function(format!("mesh_to_card/{name}"), |b| b.iter(to_card));
    }
    let bumpy = bumpy_mesh();
    let placement = MeshPlacement {
        resolution: 320,
        ..MeshPlacement::default()
    };
    let bumpy_card = || {
        let (field, _) = depth_field_from_mesh(&bumpy, &placement).expect("depth");
        card_from_depths(&field, 1.0, &ConvertOptions::default()).expect("card")
    };
    let (card, report) = bumpy_card();
    assert!(check_popup(&card).passed());
    eprintln!(
        "bumpy {}x{}x{}: {} of {} thin tops left out, {} of {} window candidates, {} pop-up \
         checks ({} over the whole card)",
        card.nx(),
        card.ny(),
        card.nz(),
        report.tops_omitted,
        report.thin_tops,
        report.window_rows,
        report.window_candidates,
        report.checks,
        report.full_checks
    );
    g.bench_function("mesh_to_card/bumpy_320", |b| b.iter(bumpy_card));
    for (w, d, h) in [(80, 40, 40), (800, 400, 400)] {
        let levels = city(w, h);
        let map = DepthMap {
            width: w,
            height: h,
            levels: &levels,
        };
        let card = card_from_depth_map(map, d, 1.0).expect("card");
        let name = format!("{w}x{d}x{h}");
        let cp = crease_pattern(&card).expect("pattern");
        eprintln!(
            "{name}: pops up {}, {} edges",
            check_popup(&card).passed(),
            cp.edges.len()
        );
        g.bench_function(format!("card/{name}"), |b| {
            b.iter(|| card_from_depth_map(map, d, 1.0).expect("card"))
        });
        g.bench_function(format!("check/{name}"), |b| b.iter(|| check_popup(&card)));
        g.bench_function(format!("pattern/{name}"), |b| {
            b.iter(|| crease_pattern(&card).expect("pattern"))
        });
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
