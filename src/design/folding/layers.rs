//! Consistency of the layer orders of flat-folded groups: no face passes through another.
//!
//! A crease folded flat (180°) joins two faces `f`, `g` of one group; seen from the side it is
//! a "taco". Two conditions must hold in every face stack (the standard local conditions of
//! flat folding, checked here as a test of the simulator's stack update, Miyazaki et al. (1992) §4.5):
//! - **taco–tortilla**: no face lying between `f` and `g` in the stack runs across the crease;
//! - **taco–taco**: two flat creases along the same segment, opening to the same side, have
//!   nested or disjoint stack intervals, never interleaved ones.

use glam::DVec2;

use super::geometry::{Line2, double_area, segment_crosses_interior, shared_segment};
use super::search::Layer;
use super::state::{Folding, State};
use crate::geom::Segment;

/// A flat crease in a group: its segment in plane coordinates and the two stack positions.
struct Taco {
    p: DVec2,
    q: DVec2,
    low: usize,
    high: usize,
    /// Side of the segment (+1 left, −1 right) the two faces lie on.
    side: f64,
}

/// A violation of the local flat-folding conditions in one group's face stack (faces are
/// indices into the state's faces, groups into its groups); `Display` says it in words.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum LayerProblem {
    /// Taco–tortilla: `face` lies between the two faces of a flat crease and runs across it.
    FaceAcrossCrease {
        /// The group.
        group: usize,
        /// The face in between.
        face: usize,
    },
    /// Taco–taco: two flat creases on one segment, opening to the same side, interleave
    /// (`first` and `second`: each crease's two faces, lower in the stack first).
    InterleavedCreases {
        /// The group.
        group: usize,
        /// The first crease's faces.
        first: [usize; 2],
        /// The second crease's faces.
        second: [usize; 2],
    },
}

impl std::fmt::Display for LayerProblem {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match *self {
            LayerProblem::FaceAcrossCrease { group, face } => write!(
                f,
                "group {group}: face {face} lies between the two faces of a flat crease and runs \
                 across it"
            ),
            LayerProblem::InterleavedCreases {
                group,
                first: [a, b],
                second: [c, d],
            } => write!(
                f,
                "group {group}: two flat creases on one segment interleave (faces {a} {b} and \
                 {c} {d})"
            ),
        }
    }
}

/// Every violation in the state (empty when consistent).
pub fn layer_problems(folding: &Folding, state: &State) -> Vec<LayerProblem> {
    let mut out = Vec::new();
    for g in 0..state.groups.len() {
        group_problems(folding, state, g, &mut out);
    }
    out
}

fn group_problems(folding: &Folding, state: &State, g: usize, out: &mut Vec<LayerProblem>) {
    let tol = folding.tol * 100.0;
    let group = &state.groups[g];
    let (u, v) = super::geometry::plane_basis(group.normal);
    let frame = (group.origin, u, v);
    // A dummy line: only the plane projection of the layer is used.
    let line = Line2 {
        point: DVec2::new(-1e12, -1e12),
        dir: DVec2::X,
    };
    let layer = Layer::new(folding, state, g, frame, line, 1.0);
    let polys: Vec<Vec<DVec2>> = (0..layer.stack.len())
        .map(|i| {
            let mut p = layer.moving_part(i).to_vec();
            if double_area(&p) < 0.0 {
                p.reverse();
            }
            p
        })
        .collect();
    let mut pos = vec![usize::MAX; state.faces.len()];
    for (i, &f) in group.stack.iter().enumerate() {
        pos[f] = i;
    }
    let mut tacos = Vec::new();
    for (a, &f) in group.stack.iter().enumerate() {
        for n in &state.faces[f].neighbours {
            let (k, Segment { a: s0, b: s1 }) = (n.face, n.edge);
            let b = pos[k];
            if b == usize::MAX || b < a || state.face_normal(f).dot(state.face_normal(k)) > 0.0 {
                continue;
            }
            let face = &state.faces[f];
            let map = |s: DVec2| layer.to_plane(face.transform.transform_point3(s.extend(0.0)));
            let (p, q) = (map(s0), map(s1));
            let centroid = polys[a].iter().copied().sum::<DVec2>() / polys[a].len() as f64;
            let side = Line2::through(p, q, 0.0).map_or(1.0, |l| l.side(centroid).signum());
            tacos.push(Taco {
                p,
                q,
                low: a,
                high: b,
                side,
            });
        }
    }
    for t in &tacos {
        for (h, poly) in polys.iter().enumerate().take(t.high).skip(t.low + 1) {
            if segment_crosses_interior(t.p, t.q, poly, tol) {
                out.push(LayerProblem::FaceAcrossCrease {
                    group: g,
                    face: group.stack[h],
                });
            }
        }
    }
    for (i, a) in tacos.iter().enumerate() {
        for b in &tacos[i + 1..] {
            let interleaved = (a.low < b.low && b.low < a.high && a.high < b.high)
                || (b.low < a.low && a.low < b.high && b.high < a.high);
            if interleaved && a.side == b.side && shared_segment(a.p, a.q, b.p, b.q, tol).is_some()
            {
                out.push(LayerProblem::InterleavedCreases {
                    group: g,
                    first: [group.stack[a.low], group.stack[a.high]],
                    second: [group.stack[b.low], group.stack[b.high]],
                });
            }
        }
    }
}
