//! The folded geometry of a flat fold: every face of the crease pattern placed in the plane by
//! reflecting it across the creases that lead to it from a fixed face.
//!
//! One face per connected piece of paper keeps its place (the lowest-numbered face of the
//! piece); crossing a mountain, valley or unassigned crease reflects the plane across that
//! crease's line, crossing a flat (F) or join (J) line keeps it, and boundaries and cuts join
//! nothing. A face reached by an odd number of reflections is *flipped*: its back side faces up.
//! Where two routes place a vertex at different points (a vertex that breaks Kawasaki, or
//! creases that do not close up around a hole), the pattern has no flat folded form and
//! [`fold_faces`] says which faces disagree and where.

use std::collections::HashMap;

use glam::{DAffine2, DMat2, DVec2};

use super::LayerError;
use crate::geom::polygon::contains_point;
use crate::pattern::{Assignment, CreasePattern, FaceId, VertexId};

/// A face placed in its folded position: polygons in folded coordinates, drawn through the
/// vertices' shared folded places (see [`FoldedFaces::point`]).
#[derive(Clone, Debug)]
pub struct FoldedFace {
    /// Maps crease-pattern coordinates to folded coordinates (an isometry).
    pub transform: DAffine2,
    /// True when the face shows its back side upwards (odd number of reflections).
    pub flipped: bool,
    /// Outer ring in folded coordinates (counter-clockwise when not flipped).
    pub outer: Vec<DVec2>,
    /// Hole rings in folded coordinates.
    pub holes: Vec<Vec<DVec2>>,
    /// Folded bounding box `(min, max)`.
    pub bounds: (DVec2, DVec2),
}

impl FoldedFace {
    /// True when `p` (folded coordinates) lies inside the face: inside the outer ring and
    /// outside every hole. Points on the outline may go either way.
    pub fn contains(&self, p: DVec2) -> bool {
        p.cmpge(self.bounds.0).all()
            && p.cmple(self.bounds.1).all()
            && contains_point(&self.outer, p)
            && !self.holes.iter().any(|h| contains_point(h, p))
    }
}

impl FoldedFace {
    /// True when `p` lies inside the face farther than `tol` from its every outline.
    fn holds_clearly(&self, p: DVec2, tol: f64) -> bool {
        self.contains(p)
            && std::iter::once(&self.outer)
                .chain(&self.holes)
                .flat_map(|ring| ring_pairs_of(ring))
                .all(|(a, b)| crate::geom::segment::distance_to_point(a, b, p) > tol)
    }
}

/// The sides of a closed ring of points.
fn ring_pairs_of(ring: &[DVec2]) -> impl Iterator<Item = (DVec2, DVec2)> + '_ {
    (0..ring.len()).map(move |i| (ring[i], ring[(i + 1) % ring.len()]))
}

/// Faces whose folded centre is tried by [`FoldedFaces::deepest_stack_at_least`].
pub const STACK_SAMPLES: usize = 64;

impl FoldedFaces {
    /// A lower bound on the most layers stacked over one point of the folded form: at the
    /// centre of up to [`STACK_SAMPLES`] faces spread over the pattern, the faces holding it
    /// farther from their outlines than `tol` and than a quarter of the shortest folded side
    /// (twice the largest merge distance of the arrangement, [`super::cells::arrange`]), so
    /// that the point lies in one cell of the arrangement with all of them. Cheap beside the
    /// arrangement: it needs no overlay.
    pub fn deepest_stack_at_least(&self, tol: f64) -> usize {
        let shortest = self
            .faces
            .iter()
            .flat_map(|f| ring_pairs_of(&f.outer))
            .map(|(a, b)| a.distance(b))
            .filter(|&d| d > 0.0)
            .fold(f64::INFINITY, f64::min);
        let tol = tol.max(shortest / 4.0);
        if !tol.is_finite() {
            return 0;
        }
        let n = self.faces.len();
        let step = n.div_ceil(STACK_SAMPLES).max(1);
        (0..n)
            .step_by(step)
            .map(|i| {
                let ring = &self.faces[i].outer;
                let centre = ring.iter().copied().sum::<DVec2>() / ring.len().max(1) as f64;
                self.faces
                    .iter()
                    .filter(|f| f.holds_clearly(centre, tol))
                    .count()
            })
            .max()
            .unwrap_or(0)
    }
}

/// The folded form of a pattern: faces placed, edges' neighbouring faces, folded vertices.
#[derive(Clone, Debug)]
pub struct FoldedFaces {
    /// Faces in pattern order.
    pub faces: Vec<FoldedFace>,
    /// For every edge, the face on its left (from `vertices[0]` to `vertices[1]`) and on its
    /// right, when there is one.
    pub edge_faces: Vec<[Option<u32>; 2]>,
    /// Folded position of every vertex (from the first face that holds it; a vertex on no face
    /// keeps its pattern position).
    pub vertices: Vec<DVec2>,
    /// Vertices on a cut (placed by each face on their own, see [`FoldedFaces::point`]).
    pub on_cut: Vec<bool>,
}

/// The reflection of the plane across the line through `a` and `b`.
fn reflection(a: DVec2, b: DVec2) -> DAffine2 {
    let d = (b - a).normalize_or_zero();
    let m = DMat2::from_cols(
        DVec2::new(2.0 * d.x * d.x - 1.0, 2.0 * d.x * d.y),
        DVec2::new(2.0 * d.x * d.y, 2.0 * d.y * d.y - 1.0),
    );
    DAffine2::from_mat2_translation(m, a - m * a)
}

/// Places every face of `cp` (whose faces must be traced: `cp.faces` is `Some`), see the module
/// docs. `tol` is the distance, in the pattern's unit, within which two placements of a vertex
/// count as the same point.
pub fn fold_faces(cp: &CreasePattern, tol: f64) -> Result<FoldedFaces, LayerError> {
    let faces = cp.faces.as_deref().ok_or(LayerError::NoFaces)?;
    if faces.is_empty() {
        return Err(LayerError::NoFaces);
    }
    let edge_of: HashMap<(u32, u32), u32> = cp
        .edges
        .iter()
        .enumerate()
        .map(|(i, e)| (key(e.vertices[0], e.vertices[1]), i as u32))
        .collect();
    let mut edge_faces = vec![[None, None]; cp.edges.len()];
    for (f, face) in faces.iter().enumerate() {
        for ring in std::iter::once(&face.outer).chain(&face.holes) {
            for (a, b) in ring_pairs(ring) {
                if let Some(&e) = edge_of.get(&key(a, b)) {
                    let side = usize::from(cp.edges[e as usize].vertices[0] != a);
                    edge_faces[e as usize][side] = Some(f as u32);
                }
            }
        }
    }
    let transforms = place(cp, faces, &edge_of, &edge_faces);
    let on_cut = cut_vertices(cp);
    // Each vertex's folded place: where the first face holding it puts it, checked against
    // every other face holding it.
    let mut placed: Vec<Option<(DVec2, u32)>> = vec![None; cp.vertices.len()];
    for (f, (face, &(t, _))) in faces.iter().zip(&transforms).enumerate() {
        for &v in &face.outer {
            let p = t.transform_point2(cp.position(v));
            match placed[v.index()] {
                None => placed[v.index()] = Some((p, f as u32)),
                Some((q, g)) if !on_cut[v.index()] && q.distance(p) > tol => {
                    return Err(LayerError::NotFlat {
                        faces: [FaceId(g), FaceId::new(f)],
                        vertex: v,
                        position: cp.position(v),
                        gap: q.distance(p),
                    });
                }
                _ => {}
            }
        }
    }
    let vertices: Vec<DVec2> = placed
        .iter()
        .zip(&cp.vertices)
        .map(|(v, &p)| v.map_or(p, |(q, _)| q))
        .collect();
    let mut out = Vec::with_capacity(faces.len());
    for (face, &(t, flipped)) in faces.iter().zip(&transforms) {
        // Every face draws a shared vertex at the vertex's one folded place (as Flat-Folder
        // does), so the folded edges meeting at a vertex meet exactly there and rounding in
        // the reflections leaves no slivers; a vertex on a cut belongs to each side apart.
        let map = |ring: &Vec<VertexId>| -> Vec<DVec2> {
            ring.iter()
                .map(|&v| {
                    if on_cut[v.index()] {
                        t.transform_point2(cp.position(v))
                    } else {
                        vertices[v.index()]
                    }
                })
                .collect()
        };
        let outer = map(&face.outer);
        let holes: Vec<Vec<DVec2>> = face.holes.iter().map(map).collect();
        let bounds = outer.iter().fold(
            (DVec2::splat(f64::MAX), DVec2::splat(f64::MIN)),
            |(lo, hi), &p| (lo.min(p), hi.max(p)),
        );
        out.push(FoldedFace {
            transform: t,
            flipped,
            outer,
            holes,
            bounds,
        });
    }
    Ok(FoldedFaces {
        faces: out,
        edge_faces,
        vertices,
        on_cut,
    })
}

impl FoldedFaces {
    /// The folded place of vertex `v` as face `f` draws it: the vertex's one folded place,
    /// or for a vertex on a cut, where `f`'s own reflection puts it.
    pub fn point(&self, cp: &CreasePattern, f: u32, v: VertexId) -> DVec2 {
        if self.on_cut[v.index()] {
            self.faces[f as usize]
                .transform
                .transform_point2(cp.position(v))
        } else {
            self.vertices[v.index()]
        }
    }
}

/// A face waiting to be placed: reached across a crease `length` long, `depth` creases from
/// its piece's fixed face. Ordered so that the heap pops the shallowest first and, among
/// equally deep ones, the one reached across the longest crease.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Reach {
    depth: u32,
    length: f64,
    face: u32,
    transform: DAffine2,
    flipped: bool,
}

impl Eq for Reach {}

impl PartialOrd for Reach {
    fn partial_cmp(&self, other: &Self) -> Option<std::cmp::Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Reach {
    fn cmp(&self, other: &Self) -> std::cmp::Ordering {
        other
            .depth
            .cmp(&self.depth)
            .then(self.length.total_cmp(&other.length))
            .then(other.face.cmp(&self.face))
    }
}

/// Places every face from the lowest face of each piece, over a spanning tree of the faces
/// that crosses as few creases as it can and, among those, the longest (as Flat-Folder's
/// folding does): a drawn line's direction carries the rounding of its ends divided by its
/// length, and every reflection passes that error on, so long creases place faces best.
fn place(
    cp: &CreasePattern,
    faces: &[crate::pattern::Face],
    edge_of: &HashMap<(u32, u32), u32>,
    edge_faces: &[[Option<u32>; 2]],
) -> Vec<(DAffine2, bool)> {
    let mut placed: Vec<Option<(DAffine2, bool)>> = vec![None; faces.len()];
    let mut heap = std::collections::BinaryHeap::new();
    for start in 0..faces.len() {
        if placed[start].is_some() {
            continue;
        }
        heap.push(Reach {
            depth: 0,
            length: f64::INFINITY,
            face: start as u32,
            transform: DAffine2::IDENTITY,
            flipped: false,
        });
        while let Some(r) = heap.pop() {
            let f = r.face as usize;
            if placed[f].is_some() {
                continue;
            }
            placed[f] = Some((r.transform, r.flipped));
            let face = &faces[f];
            for ring in std::iter::once(&face.outer).chain(&face.holes) {
                for (a, b) in ring_pairs(ring) {
                    let Some(&e) = edge_of.get(&key(a, b)) else {
                        continue;
                    };
                    let edge = &cp.edges[e as usize];
                    let Some(g) = edge_faces[e as usize]
                        .iter()
                        .flatten()
                        .copied()
                        .find(|&g| g as usize != f)
                    else {
                        continue;
                    };
                    if placed[g as usize].is_some() {
                        continue;
                    }
                    let (pa, pb) = cp.segment(crate::pattern::EdgeId(e));
                    let (transform, flipped) = match edge.assignment {
                        Assignment::Boundary | Assignment::Cut => continue,
                        Assignment::Flat | Assignment::Join => (r.transform, r.flipped),
                        Assignment::Mountain | Assignment::Valley | Assignment::Unassigned => {
                            (r.transform * reflection(pa, pb), !r.flipped)
                        }
                    };
                    heap.push(Reach {
                        depth: r.depth + 1,
                        length: pa.distance(pb),
                        face: g,
                        transform,
                        flipped,
                    });
                }
            }
        }
    }
    placed
        .into_iter()
        .map(|p| p.unwrap_or((DAffine2::IDENTITY, false)))
        .collect()
}

/// Vertices on a cut: pieces on either side of a cut may fold apart, so their placements are
/// not compared.
fn cut_vertices(cp: &CreasePattern) -> Vec<bool> {
    let mut mask = vec![false; cp.vertices.len()];
    for e in cp.edges.iter().filter(|e| e.assignment == Assignment::Cut) {
        for v in e.vertices {
            mask[v.index()] = true;
        }
    }
    mask
}

fn key(a: VertexId, b: VertexId) -> (u32, u32) {
    (a.0.min(b.0), a.0.max(b.0))
}

/// Consecutive vertex pairs of a closed ring.
pub(crate) fn ring_pairs(ring: &[VertexId]) -> impl Iterator<Item = (VertexId, VertexId)> + '_ {
    (0..ring.len()).map(move |i| (ring[i], ring[(i + 1) % ring.len()]))
}
