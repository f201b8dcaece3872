//! Boundary non-overlap (Tachi 2014, eq. 2, the angle-based-flattening condition): walking the sheet's
//! boundary counter-clockwise, the flat turning angle `τ_v = π − Σ_ℓ θ_{v,ℓ}` at each boundary
//! vertex, summed over any run of consecutive vertices, never goes below −π. A violated run
//! becomes the equality `b = Σ τ_v + π − m = 0` for that step (m: the limits' margin).
//!
//! For every start vertex only the run with the smallest sum is checked (it dominates the
//! others from that start), so at most one row per boundary vertex is added
//! ([`BoundaryRuns::EveryStart`]). With [`BoundaryRuns::Dominant`], of the starts whose worst
//! runs end at the same vertex only the one with the smallest sum becomes a row: with prefix
//! sums `P`, a run `[i, e)` sums to `P_e − P_i`, so the start with the largest `P_i` implies
//! every other start ending at `e`. Kept as equalities, the dominated runs also hold every
//! turning angle between their starts at zero (their differences): a stiffer outline, and
//! many long rows that make each step slow on large meshes (measurements at
//! [`BoundaryRuns`]).

use std::collections::HashMap;
use std::f64::consts::PI;

use glam::DVec3;

use super::constraints::BoundaryRuns;
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
    which: BoundaryRuns,
) -> Vec<(f64, Blocks)> {
    let turn: Vec<f64> = loop_vertices
        .iter()
        .map(|v| PI - angle_rows.get(v).map_or(0.0, |r| r.0))
        .collect();
    let mut out = Vec::new();
    let runs = match which {
        BoundaryRuns::Dominant => dominant_runs(&turn),
        BoundaryRuns::EveryStart => worst_runs(&turn),
    };
    for (i, len, sum) in runs {
        if sum + PI >= hold * margin {
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

/// [`worst_runs`] with, of the runs ending at the same loop position, only the one with the
/// smallest sum (the first start on ties): it implies the others (see the module docs).
pub fn dominant_runs(turn: &[f64]) -> Vec<(usize, usize, f64)> {
    let m = turn.len();
    let runs = worst_runs(turn);
    let mut best: Vec<Option<usize>> = vec![None; m];
    for (k, &(i, len, sum)) in runs.iter().enumerate() {
        let slot = &mut best[(i + len) % m];
        if slot.is_none_or(|b| sum < runs[b].2) {
            *slot = Some(k);
        }
    }
    let mut keep: Vec<usize> = best.into_iter().flatten().collect();
    keep.sort_unstable();
    keep.into_iter().map(|k| runs[k]).collect()
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

    #[test]
    fn the_kept_runs_imply_every_run_they_replace() {
        // A zigzag outline with two deep inward bends: many starts' worst runs share an end.
        let mut rng = crate::test_rng::TestRng::new(7);
        let turn: Vec<f64> = (0..40)
            .map(|k| {
                let bend = if (10..16).contains(&k) || (25..29).contains(&k) {
                    -0.9
                } else {
                    0.3
                };
                bend + 0.2 * (rng.unit() - 0.5)
            })
            .collect();
        let all = worst_runs(&turn);
        let kept = dominant_runs(&turn);
        assert!(kept.len() < all.len(), "{} of {}", kept.len(), all.len());
        let m = turn.len();
        // Brute force over every run [i, i + len): whenever some kept run [j, e) ends where
        // it does, the kept run's sum is at most its own, so a kept run at its limit implies
        // it. Every end reached by some start's worst run keeps exactly one run.
        let ends = |runs: &[(usize, usize, f64)]| -> Vec<usize> {
            let mut e: Vec<usize> = runs.iter().map(|r| (r.0 + r.1) % m).collect();
            e.sort_unstable();
            e.dedup();
            e
        };
        assert_eq!(ends(&all), ends(&kept));
        assert_eq!(ends(&kept).len(), kept.len());
        for i in 0..m {
            let mut sum = 0.0;
            for len in 1..m {
                sum += turn[(i + len - 1) % m];
                let e = (i + len) % m;
                if let Some(k) = kept.iter().find(|r| (r.0 + r.1) % m == e) {
                    // Only starts whose own worst run ends at e are replaced.
                    let own = all[i];
                    if (own.0 + own.1) % m == e {
                        assert!(k.2 <= sum + 1e-12, "start {i} len {len}: {} > {sum}", k.2);
                    }
                }
            }
        }
    }
}
