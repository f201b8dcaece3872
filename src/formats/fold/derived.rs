//! The FOLD keys derived from a pattern's topology, as FOLD 1.2 defines them, for the writer.
//!
//! - `vertices_vertices`, `vertices_edges`: neighbours and edges counter-clockwise around each
//!   vertex (from [`VertexFans`]), aligned with each other.
//! - `vertices_faces`: aligned with them: entry `i` is the face between spokes `i` and `i + 1`
//!   (counter-clockwise), or `null`.
//! - `edges_faces`: `[left, right]` relative to `edges_vertices`, `null` where no face is.
//! - `edges_length`: Euclidean lengths in the pattern's unit.
//! - `faces_edges`: the edge joining `faces_vertices[f][i]` to the next vertex of the outer
//!   cycle (`null` when no edge joins them); `faces_faces`: the face across that edge.
//!
//! A face lies to the left of each directed edge of its cycles (outer counter-clockwise,
//! holes clockwise). When several edges join the same two vertices, the first is used.

use std::collections::HashMap;

use serde_json::Value;

use super::values::num;
use crate::pattern::vertex_fan::VertexFans;
use crate::pattern::{CreasePattern, EdgeId, Face, VertexId};

/// Face incidences computed once for all derived keys.
struct Incidence {
    /// Edge id of each vertex pair.
    edge_of: HashMap<(u32, u32), EdgeId>,
    /// `[left, right]` face of each edge.
    edge_faces: Vec<[Option<usize>; 2]>,
}

impl Incidence {
    fn new(cp: &CreasePattern) -> Self {
        let mut edge_of = HashMap::with_capacity(cp.edges.len());
        for (i, e) in cp.edges.iter().enumerate().rev() {
            edge_of.insert(pair(e.vertices[0], e.vertices[1]), EdgeId::new(i));
        }
        let mut edge_faces = vec![[None; 2]; cp.edges.len()];
        for (f, face) in cp.faces.iter().flatten().enumerate() {
            for (a, b) in directed_edges(face) {
                let Some(&e) = edge_of.get(&pair(a, b)) else {
                    continue;
                };
                let side = usize::from(cp.edges[e.index()].vertices[0] != a);
                edge_faces[e.index()][side] = Some(f);
            }
        }
        Incidence {
            edge_of,
            edge_faces,
        }
    }

    fn edge(&self, a: VertexId, b: VertexId) -> Option<EdgeId> {
        self.edge_of.get(&pair(a, b)).copied()
    }
}

/// The value of derived key `name`, `None` when it cannot be computed (a face key without
/// faces) or the name is not a derived key.
pub(super) fn derived_value(cp: &CreasePattern, name: &str, fans: &VertexFans) -> Option<Value> {
    let inc = || Incidence::new(cp);
    Some(match name {
        "vertices_vertices" => per_vertex(cp, fans, |s| Value::from(s.to.0)),
        "vertices_edges" => per_vertex(cp, fans, |s| Value::from(s.edge.0)),
        "vertices_faces" => vertices_faces(cp, fans, &inc(), cp.faces.as_ref()?),
        "edges_faces" => {
            cp.faces.as_ref()?;
            Value::Array(
                inc()
                    .edge_faces
                    .iter()
                    .map(|s| Value::from(s.to_vec()))
                    .collect(),
            )
        }
        "edges_length" => Value::Array(cp.edge_ids().map(|e| num(cp.edge_length(e))).collect()),
        "faces_edges" => faces_edges(cp.faces.as_ref()?, &inc()),
        "faces_faces" => faces_faces(cp, cp.faces.as_ref()?, &inc()),
        _ => return None,
    })
}

/// One array per vertex, one entry per spoke.
fn per_vertex(
    cp: &CreasePattern,
    fans: &VertexFans,
    entry: impl Fn(&crate::pattern::vertex_fan::Spoke) -> Value,
) -> Value {
    Value::Array(
        cp.vertex_ids()
            .map(|v| Value::Array(fans.of(v).iter().map(&entry).collect()))
            .collect(),
    )
}

/// `vertices_faces`: at vertex `w` reached by `u → w → x` along a face cycle, the face fills
/// the wedge from the spoke to `x` counter-clockwise to the spoke to `u`.
fn vertices_faces(cp: &CreasePattern, fans: &VertexFans, inc: &Incidence, faces: &[Face]) -> Value {
    let mut out: Vec<Vec<Value>> = cp
        .vertex_ids()
        .map(|v| vec![Value::Null; fans.of(v).len()])
        .collect();
    for (f, face) in faces.iter().enumerate() {
        for cycle in std::iter::once(&face.outer).chain(&face.holes) {
            let n = cycle.len();
            for i in 0..n {
                let (w, x) = (cycle[i], cycle[(i + 1) % n]);
                let Some(e) = inc.edge(w, x) else { continue };
                let Some(slot) = fans.of(w).iter().position(|s| s.edge == e) else {
                    continue;
                };
                if let Some(entry) = out.get_mut(w.index()).and_then(|row| row.get_mut(slot)) {
                    *entry = Value::from(f);
                }
            }
        }
    }
    Value::Array(out.into_iter().map(Value::Array).collect())
}

/// `faces_edges` of the outer cycles.
fn faces_edges(faces: &[Face], inc: &Incidence) -> Value {
    Value::Array(
        faces
            .iter()
            .map(|f| {
                let n = f.outer.len();
                (0..n)
                    .map(|i| Value::from(inc.edge(f.outer[i], f.outer[(i + 1) % n]).map(|e| e.0)))
                    .collect()
            })
            .collect(),
    )
}

/// `faces_faces` along the outer cycles.
fn faces_faces(cp: &CreasePattern, faces: &[Face], inc: &Incidence) -> Value {
    let across = |f: usize, a: VertexId, b: VertexId| -> Option<usize> {
        let e = inc.edge(a, b)?;
        let side = usize::from(cp.edges[e.index()].vertices[0] == a);
        inc.edge_faces[e.index()][side].filter(|&g| g != f)
    };
    Value::Array(
        faces
            .iter()
            .enumerate()
            .map(|(fi, f)| {
                let n = f.outer.len();
                (0..n)
                    .map(|i| Value::from(across(fi, f.outer[i], f.outer[(i + 1) % n])))
                    .collect()
            })
            .collect(),
    )
}

fn pair(a: VertexId, b: VertexId) -> (u32, u32) {
    (a.0.min(b.0), a.0.max(b.0))
}

/// Directed edges of a face's cycles.
fn directed_edges(face: &Face) -> impl Iterator<Item = (VertexId, VertexId)> + '_ {
    std::iter::once(&face.outer)
        .chain(&face.holes)
        .flat_map(|c| (0..c.len()).map(move |i| (c[i], c[(i + 1) % c.len()])))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pattern::Assignment;
    use glam::DVec2;
    use serde_json::json;

    /// The unit square split by the diagonal 1–3 (FOLD's diagonal example).
    fn diagonal() -> CreasePattern {
        let mut cp = CreasePattern::new();
        for (x, y) in [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)] {
            cp.add_vertex(DVec2::new(x, y));
        }
        for (a, b) in [(0, 1), (1, 2), (2, 3), (3, 0)] {
            cp.add_edge(VertexId(a), VertexId(b), Assignment::Boundary);
        }
        cp.add_edge(VertexId(3), VertexId(1), Assignment::Valley);
        let f = |v: [u32; 3]| Face::simple(v.iter().map(|&i| VertexId(i)).collect());
        cp.faces = Some(vec![f([0, 1, 3]), f([1, 2, 3])]);
        cp
    }

    #[test]
    fn matches_the_spec_definitions() {
        let cp = diagonal();
        let fans = VertexFans::new(&cp);
        let get = |k| derived_value(&cp, k, &fans).unwrap_or(Value::Null);
        // Vertex 1 at (1, 0): spokes counter-clockwise to 2 (up), 3 (up-left), 0 (left).
        assert_eq!(get("vertices_vertices")[1], json!([2, 3, 0]));
        assert_eq!(get("vertices_edges")[1], json!([1, 4, 0]));
        // Between spokes to 2 and 3 lies face 1, between 3 and 0 face 0, then outside.
        assert_eq!(get("vertices_faces")[1], json!([1, 0, null]));
        // Edge 4 runs 3 → 1 (down-right): face 1 (upper right) is on its left.
        assert_eq!(get("edges_faces")[4], json!([1, 0]));
        assert_eq!(get("edges_faces")[0], json!([0, null]));
        assert_eq!(get("faces_edges"), json!([[0, 4, 3], [1, 2, 4]]));
        assert_eq!(
            get("faces_faces"),
            json!([[null, 1, null], [null, null, 0]])
        );
        assert_eq!(get("edges_length")[4], json!(std::f64::consts::SQRT_2));
    }
}
