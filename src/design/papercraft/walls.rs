//! Boundary walls (Ōgaki 2016, §3.4): each cut line swept away from the reference mesh, so a patch that
//! floats off the mesh can still be trimmed along it.
//!
//! Each patch gets its rough direction `n_p = normalize(Σ_{n ∈ N_p} n)`, N_p the mesh normals
//! at the samples of its cut lines; each network vertex moves to the swept vertex
//! `v_s = v + k · normalize(Σ_{p ∈ p_v} n_p)` (§3.4's equation), p_v the patches beside any
//! cut line ending at v. Between swept vertices the wall's far edge is the cut line scaled by
//! `|b_s − a_s| / |b − a|` (the thesis's ratio) and, our addition, rotated by the smallest
//! rotation taking `b − a` to `b_s − a_s` and moved so that its ends land on a_s and b_s.
//!
//! The wall is ruled by ribs: the rib at cut-line parameter s runs from `2c(s) − w(s)` to
//! `w(s)`, where c(s) is the cut line projected onto the mesh and w(s) its swept image. The
//! thesis sweeps only outward; we extend each rib as far inside the mesh, because §4 reports
//! patches that dip into the reference model.
//!
//! Deviations: a closed cut line (start = end) has no chord to scale, so its far edge is
//! `c(s) + k·m(s)` with m the mesh normal at c(s), blended over the first and last segment
//! into the swept vertex's direction so the walls still meet at the vertex. A vertex with no
//! patch (a cut line in no loop) sweeps along the mesh normal.

use glam::{DQuat, DVec3};

use super::PapercraftError;
use super::cut_line::CutLine;
use super::network::Network;
use crate::mesh::ReferenceMesh;

/// The walls of every cut line.
#[derive(Clone, Debug)]
pub struct Walls {
    k: f64,
    patch_normals: Vec<DVec3>,
    vertices: Vec<DVec3>,
    swept: Vec<DVec3>,
    lines: Vec<CutLine>,
    /// `[start, end]` network vertex of each cut line.
    ends: Vec<[usize; 2]>,
}

impl Walls {
    /// Builds the walls with sweep length `k` (mesh units, finite and > 0), averaging normals
    /// over `per_segment` samples per cut-line segment.
    pub fn build(
        mesh: &ReferenceMesh,
        lines: &[CutLine],
        network: &Network,
        k: f64,
        per_segment: usize,
    ) -> Result<Walls, PapercraftError> {
        if !(k.is_finite() && k > 0.0) {
            return Err(PapercraftError::BadParameter(format!(
                "wall length k = {k} must be finite and positive"
            )));
        }
        let hs = network.half_edges();
        let ends: Vec<[usize; 2]> = (0..lines.len())
            .map(|e| [hs[2 * e].origin, hs[2 * e + 1].origin])
            .collect();
        let vertices: Vec<DVec3> = network
            .vertices()
            .iter()
            .map(|&v| mesh.project(v).point)
            .collect();
        let patch_normals = (0..network.patch_count())
            .map(|p| {
                let sum: DVec3 = network
                    .patch_loop(p)
                    .iter()
                    .flat_map(|&h| lines[h / 2].sample(mesh, per_segment))
                    .map(|x| mesh.project(x).normal)
                    .sum();
                sum.try_normalize()
                    .ok_or(PapercraftError::NoPatchDirection { patch: p })
            })
            .collect::<Result<Vec<_>, _>>()?;
        let swept = (0..vertices.len())
            .map(|v| {
                let sum: DVec3 = network
                    .patches_at_vertex(v)
                    .iter()
                    .map(|&p| patch_normals[p])
                    .sum();
                let dir = sum
                    .try_normalize()
                    .unwrap_or_else(|| mesh.project(vertices[v]).normal);
                vertices[v] + k * dir // §3.4: v_s = v + k Σn_p / ‖Σn_p‖
            })
            .collect();
        Ok(Walls {
            k,
            patch_normals,
            vertices,
            swept,
            lines: lines.to_vec(),
            ends,
        })
    }

    /// The rough direction n_p of each patch (unit).
    pub fn patch_normals(&self) -> &[DVec3] {
        &self.patch_normals
    }

    /// The swept vertex v_s of each network vertex.
    pub fn swept_vertices(&self) -> &[DVec3] {
        &self.swept
    }

    /// The network vertices projected onto the mesh (the v of §3.4).
    pub fn vertices(&self) -> &[DVec3] {
        &self.vertices
    }

    /// The point c(s) of cut line `e` on the mesh: its spline projected, with the ends exactly
    /// at the projected network vertices.
    pub fn cut_point(&self, mesh: &ReferenceMesh, e: usize, s: f64) -> DVec3 {
        let line = &self.lines[e];
        let n = line.segments() as f64;
        if s <= 0.0 {
            self.vertices[self.ends[e][0]]
        } else if s >= n {
            self.vertices[self.ends[e][1]]
        } else {
            mesh.project(line.at(s)).point
        }
    }

    /// The rib of cut line `e`'s wall at parameter `s ∈ [0, segments]`: `(inner, outer)`
    /// ends, from `2c(s) − w(s)` to `w(s)`.
    pub fn rib(&self, mesh: &ReferenceMesh, e: usize, s: f64) -> (DVec3, DVec3) {
        let c = self.cut_point(mesh, e, s);
        let w = self.swept_point(mesh, e, s, c);
        (2.0 * c - w, w)
    }

    fn swept_point(&self, mesh: &ReferenceMesh, e: usize, s: f64, c: DVec3) -> DVec3 {
        let [ia, ib] = self.ends[e];
        let (a, b) = (self.vertices[ia], self.vertices[ib]);
        let (a_s, b_s) = (self.swept[ia], self.swept[ib]);
        let chord = b - a;
        let swept_chord = b_s - a_s;
        match (chord.try_normalize(), swept_chord.try_normalize()) {
            (Some(from), Some(to)) if ia != ib => {
                let scale = swept_chord.length() / chord.length();
                a_s + scale * (DQuat::from_rotation_arc(from, to) * (c - a))
            }
            _ => {
                let n = self.lines[e].segments() as f64;
                let blend = s.min(n - s).clamp(0.0, 1.0);
                let at_vertex = (a_s - a) / self.k;
                let m = at_vertex.lerp(mesh.project(c).normal, blend);
                c + self.k * m.try_normalize().unwrap_or(at_vertex)
            }
        }
    }

    /// Number of segments of cut line `e` (its parameter range is `[0, segments]`).
    pub fn segments(&self, e: usize) -> usize {
        self.lines[e].segments()
    }
}
