//! Generates `examples/popup/building.obj`, the small building mesh the voxel pop-up card is
//! made from (`foldcam popup voxel examples/popup/building.obj ...`).
//!
//! ```text
//! cargo run --example popup_building -- [OUT.obj]
//! ```
//!
//! Metres, z up, the front facing −y: a hall with a gable roof and eaves, two towers with
//! pyramid roofs (slanted outlines in the front view, the case of §3.3), a porch roof on four
//! pillars (overhangs that become windows, §3.2 c), balconies without pillars, front steps and
//! window sills thinner than a cell (bumps for §3.2 a).

use std::path::PathBuf;
use std::process::ExitCode;

use foldcam::mesh::PolyMesh;
use glam::DVec3;

#[derive(Default)]
struct Builder {
    positions: Vec<DVec3>,
    faces: Vec<Vec<u32>>,
}

impl Builder {
    fn corners(&mut self, points: &[DVec3]) -> u32 {
        let base = self.positions.len() as u32;
        self.positions.extend_from_slice(points);
        base
    }

    fn face(&mut self, base: u32, corners: &[u32]) {
        self.faces.push(corners.iter().map(|c| base + c).collect());
    }

    /// An axis-aligned box `lo..hi`, faces wound outwards.
    fn cuboid(&mut self, lo: [f64; 3], hi: [f64; 3]) {
        let p = |i: usize| {
            DVec3::new(
                if i & 1 == 0 { lo[0] } else { hi[0] },
                if i & 2 == 0 { lo[1] } else { hi[1] },
                if i & 4 == 0 { lo[2] } else { hi[2] },
            )
        };
        let b = self.corners(&(0..8).map(p).collect::<Vec<_>>());
        for quad in [
            [0, 2, 3, 1],
            [4, 5, 7, 6],
            [0, 1, 5, 4],
            [2, 6, 7, 3],
            [0, 4, 6, 2],
            [1, 3, 7, 5],
        ] {
            self.face(b, &quad);
        }
    }

    /// A gable roof along x over `x0..x1`, eaves at `y0` and `y1` at height `z0`, the ridge at
    /// `ridge_y`, `z1`.
    fn gable(&mut self, x: [f64; 2], y: [f64; 2], ridge_y: f64, z: [f64; 2]) {
        let section = [
            DVec3::new(0.0, y[0], z[0]),
            DVec3::new(0.0, y[1], z[0]),
            DVec3::new(0.0, ridge_y, z[1]),
        ];
        let pts: Vec<DVec3> = x
            .iter()
            .flat_map(|&xx| section.map(|p| p.with_x(xx)))
            .collect();
        let b = self.corners(&pts);
        self.face(b, &[0, 2, 1]);
        self.face(b, &[3, 4, 5]);
        self.face(b, &[0, 1, 4, 3]);
        self.face(b, &[0, 3, 5, 2]);
        self.face(b, &[1, 2, 5, 4]);
    }

    /// A pyramid on the rectangle `lo..hi` at height `z0`, apex at height `apex`.
    fn pyramid(&mut self, lo: [f64; 2], hi: [f64; 2], z0: f64, apex: f64) {
        let b = self.corners(&[
            DVec3::new(lo[0], lo[1], z0),
            DVec3::new(hi[0], lo[1], z0),
            DVec3::new(hi[0], hi[1], z0),
            DVec3::new(lo[0], hi[1], z0),
            DVec3::new(0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1]), apex),
        ]);
        self.face(b, &[0, 3, 2, 1]);
        for k in 0..4u32 {
            self.face(b, &[k, (k + 1) % 4, 4]);
        }
    }
}

fn building() -> Builder {
    let mut m = Builder::default();
    // The hall, its eave slab and gable roof.
    m.cuboid([2.0, 4.0, 0.0], [14.0, 16.0, 5.0]);
    m.cuboid([1.8, 3.4, 4.8], [14.2, 16.0, 5.2]);
    m.gable([2.0, 14.0], [3.4, 16.0], 10.0, [5.2, 8.0]);
    // Towers with pyramid roofs, balconies without pillars, sills thinner than a cell.
    for x0 in [0.0, 13.0] {
        m.cuboid([x0, 2.0, 0.0], [x0 + 3.0, 8.0, 6.5]);
        m.pyramid([x0 - 0.2, 1.8], [x0 + 3.2, 8.2], 6.5, 8.0);
        m.cuboid([x0 + 0.5, 1.2, 4.4], [x0 + 2.5, 2.0, 4.6]);
        m.cuboid([x0 + 0.5, 1.2, 4.6], [x0 + 2.5, 1.3, 5.2]);
        m.cuboid([x0 + 0.8, 1.88, 2.6], [x0 + 2.2, 2.0, 2.7]);
    }
    // The porch roof on four pillars, and front steps.
    m.cuboid([5.0, 0.5, 3.2], [11.0, 4.0, 3.8]);
    for x0 in [5.2, 7.0, 8.5, 10.3] {
        m.cuboid([x0, 0.8, 0.0], [x0 + 0.5, 1.3, 3.2]);
    }
    m.cuboid([6.5, 0.0, 0.0], [9.5, 0.8, 0.3]);
    m
}

fn main() -> ExitCode {
    let out = std::env::args_os().nth(1).map_or_else(
        || PathBuf::from("examples/popup/building.obj"),
        PathBuf::from,
    );
    let b = building();
    let mesh = match PolyMesh::new(b.positions, b.faces) {
        Ok(m) => m,
        Err(e) => {
            eprintln!("popup_building: {e}");
            return ExitCode::FAILURE;
        }
    };
    let text = format!(
        "# A small building for the voxel pop-up card (metres, z up, front towards -y).\n\
         # Made by `cargo run --example popup_building`.\n{}",
        mesh.to_obj()
    );
    if let Err(e) = foldcam::formats::write_atomic(&out, text.as_bytes()) {
        eprintln!("popup_building: {}: {e}", out.display());
        return ExitCode::FAILURE;
    }
    println!(
        "{}: {} vertices, {} faces",
        out.display(),
        mesh.positions().len(),
        mesh.faces().len()
    );
    ExitCode::SUCCESS
}
