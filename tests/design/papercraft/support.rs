//! Shared helpers: a seeded generator and polyline lengths.

use crate::cuts_clean;

use foldcam::design::papercraft::CutLine;
use foldcam::mesh::PolyMesh;
use glam::DVec3;

/// A small deterministic generator (SplitMix64) for fixed-seed test data.
pub struct Rng(u64);

impl Rng {
    pub fn new(seed: u64) -> Self {
        Rng(seed)
    }

    /// Uniform in [0, 1).
    pub fn unit(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Uniform in [lo, hi).
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }

    /// A point uniform in the cube [−h, h]³.
    pub fn cube(&mut self, h: f64) -> DVec3 {
        DVec3::new(self.range(-h, h), self.range(-h, h), self.range(-h, h))
    }
}

/// Length of the curve `f` on [a, b] by polylines with n and 2n pieces, Richardson-extrapolated
/// (error O(n⁻⁴) for a smooth curve).
pub fn curve_length(f: impl Fn(f64) -> DVec3, a: f64, b: f64, n: usize) -> f64 {
    let poly = |m: usize| {
        let pts: Vec<DVec3> = (0..=m)
            .map(|k| f(a + (b - a) * k as f64 / m as f64))
            .collect();
        pts.windows(2).map(|w| w[0].distance(w[1])).sum::<f64>()
    };
    (4.0 * poly(2 * n) - poly(n)) / 3.0
}

/// The cube's 8 corners and 12 edges as straight cut lines (3 points each).
pub fn cube_lines() -> (Vec<CutLine>, [[usize; 2]; 12]) {
    let edges = [
        [0, 1],
        [2, 3],
        [4, 5],
        [6, 7], // along x
        [0, 2],
        [1, 3],
        [4, 6],
        [5, 7], // along y
        [0, 4],
        [1, 5],
        [2, 6],
        [3, 7], // along z
    ];
    let lines = edges
        .iter()
        .enumerate()
        .map(|(k, &[a, b])| {
            let (p, q) = (cube_corner(a), cube_corner(b));
            CutLine::new(k, vec![p, p.lerp(q, 0.5), q]).unwrap()
        })
        .collect();
    (lines, edges)
}

/// The six faces, each as its four edges in order round it (directions as they come).
pub fn cube_patches() -> Vec<Vec<usize>> {
    vec![
        vec![0, 5, 1, 4],   // z = 0: 0-1, 1-3, 3-2 (reversed), 2-0 (reversed)
        vec![6, 3, 7, 2],   // z = 1, listed the other way round
        vec![0, 9, 2, 8],   // y = 0
        vec![1, 11, 3, 10], // y = 1
        vec![4, 10, 6, 8],  // x = 0
        vec![5, 11, 7, 9],  // x = 1
    ]
}

/// Corner i of the cube [−1, 1]³ (bit 0: x, bit 1: y, bit 2: z).
pub fn cube_corner(i: usize) -> DVec3 {
    2.0 * DVec3::new((i & 1) as f64, ((i >> 1) & 1) as f64, (i >> 2) as f64) - DVec3::ONE
}

/// The cube [−1, 1]³ with a centre vertex on every face (4 triangles per face, wound
/// outward), so every corner's area-weighted normal is exactly along its diagonal.
pub fn cube_mesh() -> PolyMesh {
    let mut positions: Vec<DVec3> = (0..8).map(cube_corner).collect();
    let mut faces = Vec::new();
    for axis in 0..3 {
        for side in [0usize, 1] {
            let on: Vec<u32> = (0..8u32)
                .filter(|&i| (i as usize >> axis) & 1 == side)
                .collect();
            let centre = on.iter().map(|&i| positions[i as usize]).sum::<DVec3>() / 4.0;
            let c = positions.len() as u32;
            positions.push(centre);
            // Order the four corners round the centre.
            let mut ring = on.clone();
            let (e1, e2) = (DVec3::AXES[(axis + 1) % 3], DVec3::AXES[(axis + 2) % 3]);
            ring.sort_by(|&a, &b| {
                let ang = |i: u32| {
                    let d = positions[i as usize] - centre;
                    d.dot(e2).atan2(d.dot(e1))
                };
                ang(a).total_cmp(&ang(b))
            });
            for k in 0..4 {
                let (a, b) = (ring[k], ring[(k + 1) % 4]);
                let n = (positions[a as usize] - centre).cross(positions[b as usize] - centre);
                if n.dot(centre) > 0.0 {
                    faces.push(vec![c, a, b]);
                } else {
                    faces.push(vec![c, b, a]);
                }
            }
        }
    }
    PolyMesh::new(positions, faces).unwrap()
}

/// Plans `cp` for a diode laser on 160 g/m² paper, writes G-code and runs it on the simulated
/// machine: no violations, every cut and crease covered as planned.
pub fn assert_cuts_clean_on_paper(name: &str, cp: &foldcam::pattern::CreasePattern) {
    cp.validate().unwrap();
    cuts_clean::assert_cuts_clean_on(name, cp, "grbl-diode", "paper-160gsm");
}

/// The glued length of cut line `e` on each part that has it.
pub fn side_lengths(made: &foldcam::design::papercraft::Made, e: usize) -> Vec<f64> {
    made.parts
        .iter()
        .flat_map(|part| {
            part.sides.iter().filter(|s| s.half_edge / 2 == e).map(|s| {
                (0..s.len)
                    .map(|k| {
                        part.point(s.start + k)
                            .distance(part.point(s.start + k + 1))
                    })
                    .sum::<f64>()
            })
        })
        .collect()
}

/// The bundled example design `examples/papercraft/NAME.craft.toml`, parsed.
pub fn example_design(name: &str) -> foldcam::design::papercraft::Design {
    let dir = std::path::Path::new("examples/papercraft");
    let text = std::fs::read_to_string(dir.join(format!("{name}.craft.toml"))).unwrap();
    foldcam::design::papercraft::parse_design(&text).unwrap()
}

/// Builds the bundled example `examples/papercraft/NAME.craft.toml` once per test binary
/// (the fish takes most of a second in a release build) and hands out copies.
pub fn build_example(name: &str) -> foldcam::design::papercraft::Made {
    use foldcam::design::papercraft::Made;
    use foldcam::mesh::ReferenceMesh;
    use std::collections::HashMap;
    use std::sync::{Arc, Mutex, OnceLock};
    static BUILT: OnceLock<Mutex<HashMap<String, Arc<OnceLock<Made>>>>> = OnceLock::new();
    let cell = BUILT
        .get_or_init(Default::default)
        .lock()
        .unwrap()
        .entry(name.to_string())
        .or_default()
        .clone();
    cell.get_or_init(|| {
        let design = example_design(name);
        let dir = std::path::Path::new("examples/papercraft");
        let mesh = foldcam::mesh::read_mesh(&dir.join(&design.mesh)).unwrap();
        design.build(&ReferenceMesh::new(&mesh).unwrap()).unwrap()
    })
    .clone()
}
