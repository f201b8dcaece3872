//! The fan of edges around each vertex, sorted counter-clockwise by direction: the basis of
//! face tracing and of every per-vertex check (Kawasaki, Maekawa, vertex angle).

use glam::DVec2;

use super::{CreasePattern, EdgeId, VertexId};
use crate::geom::angle::direction;

/// One edge leaving a vertex.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Spoke {
    /// The edge.
    pub edge: EdgeId,
    /// Its other end.
    pub to: VertexId,
    /// Direction angle in [0, 2π), radians, counter-clockwise from +x.
    pub angle: f64,
}

/// For every vertex, its spokes sorted by increasing angle (compressed rows: the spokes of
/// vertex `v` are `spokes[offsets[v]..offsets[v + 1]]`).
#[derive(Clone, Debug, Default)]
pub struct VertexFans {
    /// Row starts, one more than the number of vertices.
    pub offsets: Vec<u32>,
    /// All spokes, grouped by vertex.
    pub spokes: Vec<Spoke>,
}

impl VertexFans {
    /// Builds the fans of a pattern (edges that join a vertex to itself are skipped).
    pub fn new(cp: &CreasePattern) -> Self {
        let n = cp.vertices.len();
        let mut counts = vec![0u32; n + 1];
        for e in &cp.edges {
            if e.vertices[0] != e.vertices[1] {
                counts[e.vertices[0].index() + 1] += 1;
                counts[e.vertices[1].index() + 1] += 1;
            }
        }
        for i in 0..n {
            counts[i + 1] += counts[i];
        }
        let offsets = counts;
        let mut fill = offsets.clone();
        let placeholder = Spoke {
            edge: EdgeId(0),
            to: VertexId(0),
            angle: 0.0,
        };
        let mut spokes = vec![placeholder; offsets[n] as usize];
        for (i, e) in cp.edges.iter().enumerate() {
            let [a, b] = e.vertices;
            if a == b {
                continue;
            }
            let d: DVec2 = cp.position(b) - cp.position(a);
            for (from, to, dir) in [(a, b, d), (b, a, -d)] {
                let slot = &mut fill[from.index()];
                spokes[*slot as usize] = Spoke {
                    edge: EdgeId::new(i),
                    to,
                    angle: direction(dir),
                };
                *slot += 1;
            }
        }
        for v in 0..n {
            let row = &mut spokes[offsets[v] as usize..offsets[v + 1] as usize];
            row.sort_unstable_by(|x, y| x.angle.total_cmp(&y.angle));
        }
        VertexFans { offsets, spokes }
    }

    /// The spokes of `v`, counter-clockwise.
    #[inline]
    pub fn of(&self, v: VertexId) -> &[Spoke] {
        &self.spokes[self.offsets[v.index()] as usize..self.offsets[v.index() + 1] as usize]
    }

    /// Number of vertices.
    pub fn len(&self) -> usize {
        self.offsets.len().saturating_sub(1)
    }

    /// True when there are no vertices.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}
