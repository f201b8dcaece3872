//! The cut-line network (Ōgaki 2016, §3.3): a half-edge structure whose edges are cut lines, whose
//! vertices are the shared end points and whose faces are patches.
//!
//! Each patch is given as the list of its cut lines in the order they go around it once
//! ("一筆書き"). Building chains them head to tail: a cut line whose start does not meet the
//! previous one's end is used reversed (the thesis reverses its control points; the curve's
//! shape is unchanged, see [`super::cut_line`]). Cut line `e` owns half-edges `2e` (along its
//! points) and `2e + 1` (against them); a half-edge's twin is `h ^ 1`.
//!
//! Beyond the thesis: patches are oriented consistently (two patches sharing a cut line use
//! opposite half-edges) by flipping whole loops, breadth first from each component's first
//! patch, so the user may list a loop in either turning direction. A cut line with one patch
//! is a free boundary (the thesis allows non-manifold models); a patch may use one cut line
//! twice in opposite directions (a seam, e.g. round a vase). Errors: an open loop, a cut line
//! named that does not exist, more than two patches on one cut line, loops that cannot be
//! oriented consistently.

use std::collections::VecDeque;

use glam::DVec3;

use super::PapercraftError;
use super::cut_line::CutLine;

/// One side of a cut line.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct HalfEdge {
    /// The cut line.
    pub line: usize,
    /// Vertex it starts from.
    pub origin: usize,
    /// The patch on this side, if any.
    pub patch: Option<usize>,
    /// The next half-edge round the patch (`None` on a free side).
    pub next: Option<usize>,
}

/// The network of cut lines and patches.
#[derive(Clone, Debug)]
pub struct Network {
    vertices: Vec<DVec3>,
    half_edges: Vec<HalfEdge>,
    loops: Vec<Vec<usize>>,
}

impl Network {
    /// Builds the network from cut lines and each patch's loop of cut-line indices. End points
    /// closer than `tolerance` (mesh units, finite and ≥ 0) are one vertex.
    pub fn build(
        lines: &[CutLine],
        patches: &[Vec<usize>],
        tolerance: f64,
    ) -> Result<Network, PapercraftError> {
        if !(tolerance.is_finite() && tolerance >= 0.0) {
            return Err(PapercraftError::BadParameter(format!(
                "vertex tolerance {tolerance} must be finite and non-negative"
            )));
        }
        let (vertices, ends) = merge_ends(lines, tolerance);
        let mut oriented = Vec::with_capacity(patches.len());
        for (p, list) in patches.iter().enumerate() {
            oriented.push(chain(p, list, &ends)?);
        }
        orient(&mut oriented, lines.len())?;
        let mut half_edges: Vec<HalfEdge> = (0..2 * lines.len())
            .map(|h| HalfEdge {
                line: h / 2,
                origin: if h % 2 == 0 {
                    ends[h / 2][0]
                } else {
                    ends[h / 2][1]
                },
                patch: None,
                next: None,
            })
            .collect();
        let loops: Vec<Vec<usize>> = oriented
            .iter()
            .map(|l| l.iter().map(|&(e, rev)| 2 * e + rev as usize).collect())
            .collect();
        for (p, hs) in loops.iter().enumerate() {
            for (k, &h) in hs.iter().enumerate() {
                half_edges[h].patch = Some(p);
                half_edges[h].next = Some(hs[(k + 1) % hs.len()]);
            }
        }
        Ok(Network {
            vertices,
            half_edges,
            loops,
        })
    }

    /// Vertex positions (merged end points).
    pub fn vertices(&self) -> &[DVec3] {
        &self.vertices
    }

    /// All half-edges; `h ^ 1` is the twin of `h`.
    pub fn half_edges(&self) -> &[HalfEdge] {
        &self.half_edges
    }

    /// Number of patches (faces).
    pub fn patch_count(&self) -> usize {
        self.loops.len()
    }

    /// Patch `p`'s half-edges in order round it.
    pub fn patch_loop(&self, p: usize) -> &[usize] {
        &self.loops[p]
    }

    /// Whether half-edge `h` runs against its cut line's points.
    pub fn is_reversed(h: usize) -> bool {
        h % 2 == 1
    }

    /// The vertex half-edge `h` ends at.
    pub fn head(&self, h: usize) -> usize {
        self.half_edges[h ^ 1].origin
    }

    /// Patches across `p`'s cut lines (each once, without `p`).
    pub fn neighbours(&self, p: usize) -> Vec<usize> {
        let mut out: Vec<usize> = self.loops[p]
            .iter()
            .filter_map(|&h| self.half_edges[h ^ 1].patch)
            .filter(|&q| q != p)
            .collect();
        out.sort_unstable();
        out.dedup();
        out
    }

    /// Patches beside any cut line that ends at vertex `v` (the set p_v of §3.4), sorted.
    pub fn patches_at_vertex(&self, v: usize) -> Vec<usize> {
        let mut out: Vec<usize> = self
            .half_edges
            .iter()
            .enumerate()
            .filter(|(_, he)| he.origin == v)
            .flat_map(|(h, he)| [he.patch, self.half_edges[h ^ 1].patch])
            .flatten()
            .collect();
        out.sort_unstable();
        out.dedup();
        out
    }

    /// Structural checks (for tests): twins' origins are each other's heads, every loop closes
    /// head to tail, every half-edge's `next` starts where it ends.
    pub fn check_invariants(&self) -> Result<(), String> {
        for (h, he) in self.half_edges.iter().enumerate() {
            if let Some(n) = he.next {
                if self.half_edges[n].origin != self.head(h) {
                    return Err(format!(
                        "half-edge {h}: next {n} does not start at its head"
                    ));
                }
                if self.half_edges[n].patch != he.patch {
                    return Err(format!("half-edge {h}: next {n} is on another patch"));
                }
            }
        }
        for (p, hs) in self.loops.iter().enumerate() {
            if hs.iter().any(|&h| self.half_edges[h].patch != Some(p)) {
                return Err(format!("patch {p}: a half-edge names another patch"));
            }
        }
        Ok(())
    }
}

/// Merges cut-line end points closer than `tol`; returns the vertices and each line's
/// `[start, end]` vertex.
fn merge_ends(lines: &[CutLine], tol: f64) -> (Vec<DVec3>, Vec<[usize; 2]>) {
    let mut vertices: Vec<DVec3> = Vec::new();
    let mut find = |p: DVec3| match vertices.iter().position(|&q| q.distance(p) <= tol) {
        Some(i) => i,
        None => {
            vertices.push(p);
            vertices.len() - 1
        }
    };
    let ends = lines
        .iter()
        .map(|l| [find(l.start()), find(l.end())])
        .collect();
    (vertices, ends)
}

/// Chains patch `p`'s cut lines head to tail: `(line, reversed)` per entry.
fn chain(
    p: usize,
    list: &[usize],
    ends: &[[usize; 2]],
) -> Result<Vec<(usize, bool)>, PapercraftError> {
    if list.is_empty() {
        return Err(PapercraftError::BadLoop {
            patch: p,
            message: "no cut lines".into(),
        });
    }
    if let Some(&e) = list.iter().find(|&&e| e >= ends.len()) {
        return Err(PapercraftError::BadLoop {
            patch: p,
            message: format!("cut line {e} does not exist ({} cut lines)", ends.len()),
        });
    }
    let next_ends = ends[list[1 % list.len()]];
    let first = ends[list[0]];
    let first_reversed = !next_ends.contains(&first[1]) && next_ends.contains(&first[0]);
    let mut out = vec![(list[0], first_reversed)];
    let mut head = first[1 - first_reversed as usize];
    for w in list.windows(2) {
        let [a, b] = ends[w[1]];
        let reversed = match (a == head, b == head) {
            (true, _) => false,
            (false, true) => true,
            _ => {
                return Err(PapercraftError::OpenLoop {
                    patch: p,
                    from: w[0],
                    to: w[1],
                });
            }
        };
        head = if reversed { a } else { b };
        out.push((w[1], reversed));
    }
    if head != first[first_reversed as usize] {
        return Err(PapercraftError::OpenLoop {
            patch: p,
            from: list[list.len() - 1],
            to: list[0],
        });
    }
    Ok(out)
}

/// Flips whole loops so that no half-edge is used twice (breadth first over shared lines).
fn orient(loops: &mut [Vec<(usize, bool)>], line_count: usize) -> Result<(), PapercraftError> {
    let mut users: Vec<Vec<(usize, bool)>> = vec![Vec::new(); line_count];
    for (p, l) in loops.iter().enumerate() {
        for &(e, rev) in l {
            users[e].push((p, rev));
            if users[e].len() > 2 {
                return Err(PapercraftError::BadSharing {
                    line: e,
                    message: "more than two patch sides use it".into(),
                });
            }
        }
    }
    let mut flip: Vec<Option<bool>> = vec![None; loops.len()];
    for start in 0..loops.len() {
        if flip[start].is_some() {
            continue;
        }
        flip[start] = Some(false);
        let mut queue = VecDeque::from([start]);
        while let Some(p) = queue.pop_front() {
            let fp = flip[p].unwrap_or(false);
            for &(e, _) in &loops[p] {
                if let [(p1, r1), (p2, r2)] = users[e][..] {
                    let (q, want) = if p1 == p && p2 != p {
                        (p2, !(r1 ^ fp) ^ r2)
                    } else if p2 == p && p1 != p {
                        (p1, !(r2 ^ fp) ^ r1)
                    } else if r1 == r2 {
                        return Err(PapercraftError::BadSharing {
                            line: e,
                            message: format!("patch {p} uses it twice in the same direction"),
                        });
                    } else {
                        continue;
                    };
                    match flip[q] {
                        None => {
                            flip[q] = Some(want);
                            queue.push_back(q);
                        }
                        Some(f) if f != want => {
                            return Err(PapercraftError::BadSharing {
                                line: e,
                                message: "the patches cannot be oriented consistently".into(),
                            });
                        }
                        Some(_) => {}
                    }
                }
            }
        }
    }
    for (l, f) in loops.iter_mut().zip(flip) {
        if f == Some(true) {
            l.reverse();
            l.iter_mut().for_each(|(_, r)| *r = !*r);
        }
    }
    Ok(())
}
