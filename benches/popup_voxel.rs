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
//! Run with `cargo bench --bench popup_voxel`.

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
