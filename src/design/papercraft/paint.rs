//! Which region of a cut-line drawing ([`super::sketch::regions`]) each triangle of the
//! reference mesh lies in, so the studio can colour the patches on the mesh.
//!
//! The triangles a cut line passes through (its samples projected onto the mesh, spaced at
//! most a quarter of the mean triangle edge) are walls; the other triangles are flooded
//! across shared edges from a seed per region: the triangle a small step to the left of each
//! of its half-edges (the region's side). Wall triangles then take the region of a flooded
//! neighbour, ring by ring. A triangle no seed reaches keeps `None`.

use std::collections::{HashMap, VecDeque};

use super::ReferenceMesh;
use super::cut_line::CutLine;
use super::sketch::{HOLE_STEP, Regions, left_of, mesh_diagonal};

/// Cut-line samples are spaced at most this share of the mean triangle edge.
const SAMPLE_SPACING: f64 = 0.25;

/// Most samples per cut-line segment.
const MAX_SAMPLES_PER_SEGMENT: usize = 2000;

/// The region of each fan triangle of `mesh` (indices into `regions.loops`).
pub fn paint_regions(
    mesh: &ReferenceMesh,
    lines: &[CutLine],
    regions: &Regions,
) -> Vec<Option<usize>> {
    let count = mesh.triangle_count();
    // `+ 0.0` makes −0 and +0 one key.
    let key = |p: glam::DVec3| {
        [
            (p.x + 0.0).to_bits(),
            (p.y + 0.0).to_bits(),
            (p.z + 0.0).to_bits(),
        ]
    };
    let mut by_edge: HashMap<([u64; 3], [u64; 3]), Vec<usize>> = HashMap::new();
    let mut edge_sum = 0.0;
    for t in 0..count {
        let c = mesh.triangle(t);
        for i in 0..3 {
            let (a, b) = (c[i], c[(i + 1) % 3]);
            edge_sum += a.distance(b);
            let (ka, kb) = (key(a), key(b));
            let k = if ka <= kb { (ka, kb) } else { (kb, ka) };
            by_edge.entry(k).or_default().push(t);
        }
    }
    let mut neighbours: Vec<Vec<usize>> = vec![Vec::new(); count];
    for ts in by_edge.values() {
        for &a in ts {
            for &b in ts {
                if a != b {
                    neighbours[a].push(b);
                }
            }
        }
    }
    let spacing = SAMPLE_SPACING * edge_sum / (3 * count).max(1) as f64;
    let mut wall = vec![false; count];
    for line in lines {
        let longest = (line.points().windows(2))
            .map(|w| w[0].distance(w[1]))
            .fold(0.0, f64::max);
        let per = ((longest / spacing).ceil() as usize).clamp(1, MAX_SAMPLES_PER_SEGMENT);
        let segs = line.segments() * per;
        for k in 0..=segs {
            wall[mesh.project(line.at(k as f64 / per as f64)).triangle] = true;
        }
    }
    let mut label: Vec<Option<usize>> = vec![None; count];
    let diagonal = mesh_diagonal(mesh);
    for (r, sides) in regions.sides.iter().enumerate() {
        for &h in sides {
            for scale in [1.0, 2.0, 4.0] {
                let Some(p) = left_of(
                    mesh,
                    &lines[h / 2],
                    h % 2 == 1,
                    scale * HOLE_STEP * diagonal,
                ) else {
                    break;
                };
                let seed = mesh.project(p).triangle;
                if wall[seed] {
                    continue;
                }
                if label[seed].is_none() {
                    flood(seed, r, &wall, &neighbours, &mut label);
                }
                break;
            }
        }
    }
    // Wall triangles take a painted neighbour's region, ring by ring.
    loop {
        let before = label.clone();
        for t in (0..count).filter(|&t| wall[t] && before[t].is_none()) {
            label[t] = neighbours[t].iter().find_map(|&n| before[n]);
        }
        if label == before {
            break;
        }
    }
    label
}

fn flood(
    seed: usize,
    region: usize,
    wall: &[bool],
    neighbours: &[Vec<usize>],
    label: &mut [Option<usize>],
) {
    let mut queue = VecDeque::from([seed]);
    label[seed] = Some(region);
    while let Some(t) = queue.pop_front() {
        for &n in &neighbours[t] {
            if !wall[n] && label[n].is_none() {
                label[n] = Some(region);
                queue.push_back(n);
            }
        }
    }
}
