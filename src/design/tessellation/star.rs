//! The initial pattern (§2.1): a tuck inserted at every vertex of the input mesh — the star
//! of §2.1 or one of the §2.2 variations, built from the gaps described here by [`tuck`].
//!
//! Every face keeps its own corners; the corner of face `f` at vertex `v` is named by the
//! half-edge of `f` leaving `v`. For the half-edge `h = v → w` of face `f` whose twin
//! `t = w → v` lies in face `g`, the tuck at `v` gets the two triangles
//! `T1 = (k_v, corner(f, w), corner(f, v))` and `T2 = (k_v, corner(g, v), corner(f, w))`:
//! the gap that opens between `f` and `g` at `v`, closed at `w` (the star tip is
//! `corner(f, w)`). Which half-edges open a gap decides the layout:
//!
//! - **checkerboard** (all interior vertices of even valence ≥ 6, faces two-coloured): `h`
//!   opens at `v` when `f` is black (black on the left, white on the right, seen from `v`);
//!   when `f` is white the edge stays joined at `v`, so `corner(f, v)` and `corner(g, v)` are
//!   one vertex. A vertex of valence 2n gets an n-pointed star.
//! - **digon** (any other mesh): a zero-area digon (white) on every interior edge makes every
//!   input face black; every interior half-edge opens at its start, the digon collapses to the
//!   single crease `corner(g, v)`–`corner(f, w)`, and a vertex of valence n gets an n-pointed
//!   star.
//!
//! The key vertex `k_v` lies behind the surface, `d = l·cot(π/n)` along the area-weighted
//! vertex normal, with `l` the mean length of the edges at `v` and `n` the number of star
//! points; this makes the regular triangle, square and hexagon tilings exactly developable at
//! `s = 1` (Fig. 5). Then every input face is shrunk by `s` about its centroid. The variations
//! start from the same key vertex (see [`tuck`]).
//!
//! Deviations, all where the paper says nothing: a boundary vertex gets a partial star whose
//! `n` is the number of faces around it scaled to a full turn (`faces · 2π / Σ face angles`,
//! halved in the checkerboard layout, at least 2.2) so that the depth matches an interior
//! vertex of the same tiling; in the checkerboard layout a vertex shared by two faces after
//! the shrink sits at the mean of their two shrunk corners; polygon faces are fanned into
//! triangles from their first corner (§3 triangulates all faces), the diagonals flat.

use std::collections::{HashMap, VecDeque};
use std::f64::consts::PI;

use glam::DVec3;

use super::TessError;
use super::model::{EdgeRole, TessMesh};
use super::tuck::{self, Arm, Builder, TuckKind, TuckShape};
use crate::mesh::HalfEdgeMesh;

/// How gaps are chosen (§2.1).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum TuckLayout {
    /// Checkerboard when the mesh allows it (see [`TuckLayout::Checkerboard`]), else digons.
    #[default]
    Auto,
    /// Two-coloured faces; needs every interior vertex of even valence ≥ 6.
    Checkerboard,
    /// A zero-area digon on every interior edge; works on any mesh.
    Digon,
}

impl std::fmt::Display for TuckLayout {
    /// Lower-case names as on the command line (`--layout`).
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Self::Auto => "auto",
            Self::Checkerboard => "checkerboard",
            Self::Digon => "digon",
        })
    }
}

/// Parameters of the initial pattern.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StarOptions {
    /// Face shrink factor s, 0 < s ≤ 1 (1 leaves the tucks closed).
    pub shrink: f64,
    /// Gap layout.
    pub layout: TuckLayout,
    /// Tuck structure (§2.1 star or a §2.2 variation) and its parameters.
    pub tuck: TuckShape,
    /// Interior tucks with more points than this get a flat n-gon instead of a key vertex
    /// (a star becomes a truncated star, a twisted star a twist fold; Tachi 2014, §2.2),
    /// whatever [`StarOptions::tuck`] asks for. `None`: [`star_tucks`] caps nothing and
    /// [`tessellate`](super::tessellate) uses [`max_star_points`] of its vertex-angle limit;
    /// `Some(usize::MAX)` turns the cap off there too.
    pub max_star_points: Option<usize>,
}

/// The most points a star tuck (or twisted star) can have and still meet the vertex-angle
/// limit `min_angle` (radians, margin included): its key vertex is an interior vertex with
/// `2p` angles between neighbouring creases that sum to 360° once developable (Tachi 2014,
/// eq. 1), so the smallest is at most `180°/p`, and `p ≤ 180°/min_angle` is necessary.
/// A 12-valent pole in the checkerboard layout (a 6-pointed star) cannot keep 30°.
pub fn max_star_points(min_angle: f64) -> usize {
    if min_angle <= 0.0 {
        return usize::MAX;
    }
    (PI / min_angle).floor() as usize
}

impl Default for StarOptions {
    fn default() -> Self {
        StarOptions {
            shrink: 0.8,
            layout: TuckLayout::Auto,
            tuck: TuckShape::default(),
            max_star_points: None,
        }
    }
}

/// The initial tessellation and what was chosen while building it.
#[derive(Clone, Debug)]
pub struct InitialPattern {
    /// The tessellated triangle mesh (assignments not yet set).
    pub mesh: TessMesh,
    /// The layout used ([`TuckLayout::Checkerboard`] or [`TuckLayout::Digon`]).
    pub layout: TuckLayout,
    /// Key-vertex depth d = l·cot(π/n) per input vertex (`None`: no tuck), mesh units.
    pub depth: Vec<Option<f64>>,
    /// Star points n per input vertex (0: no tuck).
    pub points: Vec<usize>,
    /// The face shrink s used.
    pub shrink: f64,
    /// Input vertices whose tuck was truncated because its star would have had more than
    /// [`StarOptions::max_star_points`] points.
    pub truncated: Vec<u32>,
}

/// Inserts star tucks into `mesh` (§2.1). Errors: `shrink` outside (0, 1], a checkerboard
/// layout the mesh cannot take, or an interior vertex with fewer than three star points.
pub fn star_tucks(mesh: &HalfEdgeMesh, opts: &StarOptions) -> Result<InitialPattern, TessError> {
    star_tucks_shrunk(mesh, opts, None)
}

/// [`star_tucks`] with a shrink per input face (`face_shrink[f]` in (0, 1], overriding
/// `opts.shrink`): a smaller shrink where the tucks must open wider (Tachi 2014, Fig. 14: the
/// tucks that a uniform shrink makes too tight). [`InitialPattern::shrink`] is then the
/// smallest of them.
pub fn star_tucks_shrunk(
    mesh: &HalfEdgeMesh,
    opts: &StarOptions,
    face_shrink: Option<&[f64]>,
) -> Result<InitialPattern, TessError> {
    if !(opts.shrink > 0.0 && opts.shrink <= 1.0) {
        return Err(TessError::BadParameter(format!(
            "shrink must be in (0, 1], got {}",
            opts.shrink
        )));
    }
    if let Some(fs) = face_shrink {
        if fs.len() != mesh.faces().len() {
            return Err(TessError::BadParameter(format!(
                "{} face shrinks for {} faces",
                fs.len(),
                mesh.faces().len()
            )));
        }
        if let Some((f, s)) = fs
            .iter()
            .enumerate()
            .find(|(_, s)| !(**s > 0.0 && **s <= 1.0))
        {
            return Err(TessError::BadParameter(format!(
                "shrink of face {f} must be in (0, 1], got {s}"
            )));
        }
    }
    let shrink_of = |f: usize| face_shrink.map_or(opts.shrink, |fs| fs[f]);
    opts.tuck.validate().map_err(TessError::BadParameter)?;
    let colours = checkerboard_colours(mesh);
    let layout = match (opts.layout, colours.is_some()) {
        (TuckLayout::Checkerboard, false) => {
            return Err(TessError::BadParameter(
                "the checkerboard layout needs two-colourable faces with every interior vertex \
                 of even valence >= 6; use the digon layout"
                    .into(),
            ));
        }
        (TuckLayout::Digon, _) | (TuckLayout::Auto, false) => TuckLayout::Digon,
        _ => TuckLayout::Checkerboard,
    };
    let hes = mesh.half_edges();
    let opens = |h: usize| -> bool {
        hes[h].twin.is_some()
            && match (&colours, layout) {
                (Some(c), TuckLayout::Checkerboard) => c[hes[h].face as usize],
                _ => true,
            }
    };
    // Corners: one per half-edge; merge those joined at a vertex (checkerboard only).
    let mut uf: Vec<usize> = (0..hes.len()).collect();
    if layout == TuckLayout::Checkerboard {
        for h in 0..hes.len() {
            if let Some(t) = hes[h].twin
                && !opens(h)
            {
                union(&mut uf, h, hes[t as usize].next as usize);
            }
        }
    }
    let mut vertex_of_corner = vec![u32::MAX; hes.len()];
    let mut input_vertex = Vec::new();
    let mut sums: Vec<(DVec3, f64)> = Vec::new();
    for h in 0..hes.len() {
        let r = find(&mut uf, h);
        if vertex_of_corner[r] == u32::MAX {
            vertex_of_corner[r] = input_vertex.len() as u32;
            input_vertex.push(hes[h].from);
            sums.push((DVec3::ZERO, 0.0));
        }
        let id = vertex_of_corner[r];
        vertex_of_corner[h] = id;
        let f = hes[h].face as usize;
        let c = mesh.face_centroid(f);
        let p = c + shrink_of(f) * (mesh.positions()[hes[h].from as usize] - c);
        sums[id as usize].0 += p;
        sums[id as usize].1 += 1.0;
    }
    let positions: Vec<DVec3> = sums.iter().map(|(p, n)| *p / *n).collect();
    let corner = |h: u32| vertex_of_corner[h as usize];

    let corner_count = positions.len();
    let mut b = Builder {
        positions,
        triangles: Vec::new(),
        roles: HashMap::new(),
        input_vertex,
    };
    for f in 0..mesh.faces().len() {
        let hs: Vec<u32> = mesh.face_half_edges(f).collect();
        for k in 1..hs.len() - 1 {
            b.triangles
                .push([corner(hs[0]), corner(hs[k]), corner(hs[k + 1])]);
            if k > 1 {
                b.roles
                    .insert((corner(hs[0]), corner(hs[k])), EdgeRole::Diagonal);
            }
        }
    }
    let nv = mesh.positions().len();
    let mut key_of_input = vec![None; nv];
    let mut depth = vec![None; nv];
    let mut points = vec![0; nv];
    let mut truncated = Vec::new();
    for v in 0..nv {
        let arms: Vec<Arm> = mesh
            .fan(v)
            .iter()
            .copied()
            .filter(|&h| opens(h as usize))
            .filter_map(|h| {
                let e = hes[h as usize];
                let t = e.twin?;
                Some(Arm {
                    own: corner(h),
                    tip: corner(e.next),
                    other: corner(hes[t as usize].next),
                })
            })
            .collect();
        if arms.is_empty() {
            continue;
        }
        let (arms, cyclic) = tuck::chain(&arms).ok_or_else(|| {
            TessError::BadParameter(format!(
                "the gaps at input vertex {v} do not form one chain (a non-manifold vertex?)"
            ))
        })?;
        let n = star_points(mesh, v, arms.len(), layout);
        let l = mean_edge_length(mesh, v);
        let d = l / (PI / n).tan();
        let normal = mesh.vertex_normal(v);
        let key = mesh.positions()[v] - d * normal;
        let mut shape = opts.tuck;
        if cyclic && !shape.kind.truncated() && opts.max_star_points.is_some_and(|m| arms.len() > m)
        {
            shape.kind = if shape.kind.twisted() {
                TuckKind::TwistFold
            } else {
                TuckKind::Truncated
            };
            shape.validate().map_err(TessError::BadParameter)?;
            truncated.push(v as u32);
        }
        key_of_input[v] = tuck::insert(&mut b, v as u32, key, normal, &arms, cyclic, &shape);
        depth[v] = Some(d);
        points[v] = arms.len();
        if layout == TuckLayout::Digon {
            for a in &arms {
                b.roles.insert((a.other, a.tip), EdgeRole::Digon);
            }
        }
    }
    let tess = TessMesh::from_triangles(
        b.positions,
        b.triangles,
        &b.roles,
        key_of_input,
        b.input_vertex,
        corner_count,
    );
    Ok(InitialPattern {
        mesh: tess,
        layout,
        depth,
        points,
        shrink: face_shrink.map_or(opts.shrink, |fs| fs.iter().copied().fold(1.0, f64::min)),
        truncated,
    })
}

/// Star points n used in d = l·cot(π/n): the tuck's point count at an interior vertex; at a
/// boundary vertex the face count scaled to a full turn (see the module docs).
fn star_points(mesh: &HalfEdgeMesh, v: usize, tucked: usize, layout: TuckLayout) -> f64 {
    if !mesh.is_boundary(v) {
        return tucked as f64;
    }
    let fan = mesh.fan(v);
    let angle_sum: f64 = fan
        .iter()
        .map(|&h| {
            let e = mesh.half_edges()[h as usize];
            let prev = mesh.half_edges()[e.prev as usize].from;
            let o = mesh.positions()[v];
            (mesh.positions()[e.to as usize] - o).angle_between(mesh.positions()[prev as usize] - o)
        })
        .sum();
    let per_turn = fan.len() as f64 * 2.0 * PI / angle_sum.max(1e-9);
    let n = if layout == TuckLayout::Checkerboard {
        per_turn / 2.0
    } else {
        per_turn
    };
    n.max(2.2)
}

/// Mean length of the input edges at `v` (each outgoing edge and each face's incoming one).
fn mean_edge_length(mesh: &HalfEdgeMesh, v: usize) -> f64 {
    let hes = mesh.half_edges();
    let p = |i: u32| mesh.positions()[i as usize];
    let fan = mesh.fan(v);
    let total: f64 = fan
        .iter()
        .map(|&h| {
            let e = hes[h as usize];
            let prev = hes[e.prev as usize];
            0.5 * (p(e.to).distance(p(e.from)) + p(prev.to).distance(p(prev.from)))
        })
        .sum();
    total / fan.len() as f64
}

/// Face colours (true = black) when the faces are two-colourable across interior edges and
/// every interior vertex has even valence ≥ 6.
fn checkerboard_colours(mesh: &HalfEdgeMesh) -> Option<Vec<bool>> {
    let nv = mesh.positions().len();
    if (0..nv)
        .any(|v| !mesh.is_boundary(v) && (mesh.fan(v).len() % 2 == 1 || mesh.fan(v).len() < 6))
    {
        return None;
    }
    let hes = mesh.half_edges();
    let nf = mesh.faces().len();
    let mut colour: Vec<Option<bool>> = vec![None; nf];
    for seed in 0..nf {
        if colour[seed].is_some() {
            continue;
        }
        colour[seed] = Some(true);
        let mut queue = VecDeque::from([seed]);
        while let Some(f) = queue.pop_front() {
            let c = colour[f]?;
            for h in mesh.face_half_edges(f) {
                let Some(t) = hes[h as usize].twin else {
                    continue;
                };
                let g = hes[t as usize].face as usize;
                match colour[g] {
                    None => {
                        colour[g] = Some(!c);
                        queue.push_back(g);
                    }
                    Some(cg) if cg == c => return None,
                    Some(_) => {}
                }
            }
        }
    }
    colour.into_iter().collect()
}

fn find(uf: &mut [usize], mut x: usize) -> usize {
    while uf[x] != x {
        uf[x] = uf[uf[x]];
        x = uf[x];
    }
    x
}

fn union(uf: &mut [usize], a: usize, b: usize) {
    let (ra, rb) = (find(uf, a), find(uf, b));
    if ra != rb {
        uf[ra] = rb;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::design::tessellation::samples::spherical_cap;

    /// A uniform per-face shrink gives the pattern of the global one; a face left at shrink 1
    /// keeps its corners on the input vertices (digon layout: every face has its own
    /// corners), the others move towards their centroids by 1 − s.
    #[test]
    fn per_face_shrinks_move_each_face_by_its_own_factor() {
        let mesh = spherical_cap(6, 2, 40.0, 50.0);
        let he = HalfEdgeMesh::new(&mesh, 1e-9).expect("manifold");
        let opts = StarOptions {
            shrink: 0.7,
            layout: TuckLayout::Digon,
            ..StarOptions::default()
        };
        let global = star_tucks(&he, &opts).expect("pattern");
        let nf = mesh.faces().len();
        let uniform = star_tucks_shrunk(&he, &opts, Some(&vec![0.7; nf])).expect("pattern");
        assert_eq!(global.mesh.positions, uniform.mesh.positions);
        let mut shrinks = vec![0.7; nf];
        shrinks[0] = 1.0;
        let mixed = star_tucks_shrunk(&he, &opts, Some(&shrinks)).expect("pattern");
        assert_eq!(mixed.shrink, 0.7);
        let x = mesh.positions();
        let hes = he.half_edges();
        for h in he.face_half_edges(0) {
            // Corner h of face 0 is the pattern vertex made for half-edge h (digon layout).
            let v = hes[h as usize].from as usize;
            let found = mixed.mesh.positions[..mixed.mesh.corner_count]
                .iter()
                .any(|p| p.distance(x[v]) < 1e-12);
            assert!(found, "corner of face 0 at input vertex {v}");
        }
        let c = he.face_centroid(1);
        let v = mesh.faces()[1][0] as usize;
        let expected = c + 0.7 * (x[v] - c);
        assert!(
            mixed.mesh.positions[..mixed.mesh.corner_count]
                .iter()
                .any(|p| p.distance(expected) < 1e-12)
        );
        assert!(star_tucks_shrunk(&he, &opts, Some(&[0.5])).is_err());
        shrinks[3] = 0.0;
        assert!(star_tucks_shrunk(&he, &opts, Some(&shrinks)).is_err());
    }
}
