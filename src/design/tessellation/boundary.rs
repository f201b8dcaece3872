//! Boundary non-overlap (Tachi 2014, eq. 2, the angle-based-flattening condition): walking the sheet's
//! boundary counter-clockwise, the flat turning angle `τ_v = π − Σ_ℓ θ_{v,ℓ}` at each boundary
//! vertex, summed over any run of consecutive vertices, never goes below −π. A violated run
//! becomes the equality `b = Σ τ_v + π − m = 0` for that step (m: the limits' margin).
//!
//! For every start vertex only the run with the smallest sum is checked (it dominates the
//! others from that start), so at most one row per boundary vertex is added.

use std::collections::HashMap;
use std::f64::consts::PI;

use glam::DVec3;

use super::model::TessMesh;

/// A sparse gradient: (vertex, ∂/∂x) blocks.
pub type Blocks = Vec<(u32, DVec3)>;

/// Per boundary vertex: its angle sum Σθ_v and the gradient of that sum.
pub type AngleSums = HashMap<u32, (f64, Blocks)>;

/// Boundary vertices in counter-clockwise order (the first loop found; a disk has one).
pub fn boundary_loop(mesh: &TessMesh) -> Vec<u32> {
    let next: HashMap<u32, u32> = mesh
        .edges
        .iter()
        .filter(|e| !e.interior)
        .map(|e| (e.vertices[0], e.vertices[1]))
        .collect();
    let Some(&start) = next.keys().min() else {
        return Vec::new();
    };
    let mut out = vec![start];
    let mut v = start;
    while let Some(&w) = next.get(&v) {
        if w == start || out.len() > next.len() {
            break;
        }
        out.push(w);
        v = w;
    }
    out
}

/// The run `(start, length)` of consecutive loop positions with the smallest turning sum for
/// each start position, with that sum. `turn[k]` is τ at loop position k.
pub fn worst_runs(turn: &[f64]) -> Vec<(usize, usize, f64)> {
    let m = turn.len();
    (0..m)
        .map(|i| {
            let (mut sum, mut best, mut best_len) = (0.0, f64::INFINITY, 1);
            for len in 1..m {
                sum += turn[(i + len - 1) % m];
                if sum < best {
                    (best, best_len) = (sum, len);
                }
            }
            (i, best_len, best)
        })
        .collect()
}

/// Eq. 2 rows for the violated runs: `(value, entries)`, given per-vertex angle sums and
/// their gradients (`angle_rows[v]`: Σθ_v and ∂Σθ_v/∂X blocks) at the boundary vertices; a
/// run enters within `hold · margin` of the limit (see [`Limits::hold`](super::Limits::hold)).
pub fn rows(
    loop_vertices: &[u32],
    angle_rows: &AngleSums,
    margin: f64,
    hold: f64,
) -> Vec<(f64, Blocks)> {
    let turn: Vec<f64> = loop_vertices
        .iter()
        .map(|v| PI - angle_rows.get(v).map_or(0.0, |r| r.0))
        .collect();
    let mut out = Vec::new();
    let mut seen = std::collections::HashSet::new();
    for (i, len, sum) in worst_runs(&turn) {
        if sum + PI >= hold * margin || !seen.insert((i, len)) {
            continue;
        }
        // A run's gradient sums those of its vertices' angle sums (a map, not a search of
        // the entries so far: runs can span hundreds of vertices).
        let mut entries: Blocks = Vec::new();
        let mut slot: HashMap<u32, usize> = HashMap::new();
        for k in 0..len {
            let v = loop_vertices[(i + k) % loop_vertices.len()];
            for &(w, g) in angle_rows.get(&v).map_or(&[][..], |r| &r.1[..]) {
                match slot.get(&w) {
                    Some(&at) => entries[at].1 -= g,
                    None => {
                        slot.insert(w, entries.len());
                        entries.push((w, -g));
                    }
                }
            }
        }
        out.push((sum + PI - margin, entries));
    }
    out
}

/// Smallest `Σ τ + π` over all runs (eq. 2 holds when it is ≥ 0), from per-vertex angle sums.
pub fn worst_turn(loop_vertices: &[u32], angle_sums: &[f64]) -> f64 {
    let turn: Vec<f64> = loop_vertices
        .iter()
        .map(|&v| PI - angle_sums[v as usize])
        .collect();
    worst_runs(&turn)
        .iter()
        .map(|r| r.2 + PI)
        .fold(f64::INFINITY, f64::min)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_run_turning_back_more_than_half_a_turn_is_found() {
        // A square boundary (four +90° turns) never turns back.
        assert!(worst_runs(&[PI / 2.0; 4]).iter().all(|r| r.2 + PI > 0.0));
        // Two −100° turns in a row fold the outline back on itself.
        let turns = [
            PI / 2.0,
            -100f64.to_radians(),
            -100f64.to_radians(),
            PI / 2.0,
        ];
        let worst = worst_runs(&turns)
            .iter()
            .map(|r| r.2)
            .fold(f64::INFINITY, f64::min);
        assert!((worst + 200f64.to_radians()).abs() < 1e-12);
    }
}
