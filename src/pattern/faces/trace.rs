//! Tracing the half-edge cycles of a planar graph.

use super::super::vertex_fan::VertexFans;
use super::super::{CreasePattern, VertexId};

/// Every cycle, and for every half-edge (a spoke index of the fans) the cycle it is on.
pub(super) struct Traced {
    /// Vertex cycles, each with the face on its left.
    pub cycles: Vec<Vec<VertexId>>,
    /// Cycle index per half-edge.
    pub cycle_of: Vec<u32>,
}

/// Follows every half-edge once: from `u→v`, the next half-edge leaves `v` along the spoke
/// just clockwise of `v→u`, which keeps the face on the left.
pub(super) fn trace(cp: &CreasePattern, fans: &VertexFans) -> Traced {
    let owner = spoke_owners(fans);
    let twin = spoke_twins(cp, fans);
    let mut cycle_of = vec![u32::MAX; fans.spokes.len()];
    let mut cycles = Vec::new();
    for start in 0..fans.spokes.len() {
        if cycle_of[start] != u32::MAX {
            continue;
        }
        let id = cycles.len() as u32;
        let mut cycle = Vec::new();
        let mut h = start;
        while cycle_of[h] == u32::MAX {
            cycle_of[h] = id;
            cycle.push(owner[h]);
            // Arrive at the far end through the twin, then turn to its clockwise neighbour.
            let t = twin[h] as usize;
            let v = owner[t];
            let lo = fans.offsets[v.index()] as usize;
            let hi = fans.offsets[v.index() + 1] as usize;
            h = if t == lo { hi - 1 } else { t - 1 };
        }
        cycles.push(cycle);
    }
    Traced { cycles, cycle_of }
}

/// A shoelace sum at most this share of the sum of its terms' magnitudes is zero: the terms
/// cancelled (a tree traced around both sides). Above round-off (10⁻¹² for a few terms) by a
/// margin for long cycles, far below the area of any real face relative to its edges.
const CANCELLED: f64 = 1e-10;

/// Signed area of a cycle, or 0 when it is zero up to rounding (a tree traced around both
/// sides, whose terms cancel): the shoelace terms are taken about the first vertex and the
/// sum is compared with the sum of their magnitudes.
pub(super) fn cycle_area(cp: &CreasePattern, cycle: &[VertexId]) -> f64 {
    let o = cp.position(cycle[0]);
    let (mut sum, mut mag) = (0.0, 0.0);
    for w in cycle.windows(2).skip(1) {
        let t = (cp.position(w[0]) - o).perp_dot(cp.position(w[1]) - o);
        sum += t;
        mag += t.abs();
    }
    if sum.abs() <= CANCELLED * mag {
        0.0
    } else {
        0.5 * sum
    }
}

/// The vertex each spoke leaves.
pub(super) fn spoke_owners(fans: &VertexFans) -> Vec<VertexId> {
    let mut owner = Vec::with_capacity(fans.spokes.len());
    for v in 0..fans.len() {
        let n = (fans.offsets[v + 1] - fans.offsets[v]) as usize;
        owner.extend(std::iter::repeat_n(VertexId::new(v), n));
    }
    owner
}

/// For each spoke, the index of the spoke of the same edge at its other end.
fn spoke_twins(cp: &CreasePattern, fans: &VertexFans) -> Vec<u32> {
    let mut first = vec![u32::MAX; cp.edges.len()];
    let mut twin = vec![0u32; fans.spokes.len()];
    for (i, s) in fans.spokes.iter().enumerate() {
        let e = s.edge.index();
        if first[e] == u32::MAX {
            first[e] = i as u32;
        } else {
            let j = first[e] as usize;
            twin[i] = j as u32;
            twin[j] = i as u32;
        }
    }
    twin
}
