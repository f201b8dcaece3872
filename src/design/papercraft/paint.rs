//! Which region of a cut-line drawing ([`super::sketch::regions`]) each part of the reference
//! mesh lies in, so the studio can colour the patches on the mesh along the cut lines.
//!
//! The triangles a cut line passes through (its samples projected onto the mesh, spaced at
//! most a quarter of the mean triangle edge) are walls; the other triangles are flooded
//! across shared edges from a seed per region: the triangle a small step to the left of each
//! of its half-edges (the region's side). Wall triangles then take the region of a flooded
//! neighbour, ring by ring. A triangle no seed reaches keeps `None`.
//!
//! A wall triangle is then cut into [`SUBDIVISIONS`]² pieces, and each piece takes the region
//! on its side of the nearest piece of cut line (the region whose half-edge has the piece on
//! its left), so the colours meet along the cut lines, within an eighth of a triangle, rather
//! than along the mesh's edges.

use std::collections::{HashMap, VecDeque};

use glam::DVec3;

use super::cut_line::CutLine;
use super::sketch::{HOLE_STEP, Regions, left_of, mesh_diagonal};
use crate::mesh::ReferenceMesh;

/// Cut-line samples are spaced at most this share of the mean triangle edge.
const SAMPLE_SPACING: f64 = 0.25;

/// Most samples per cut-line segment.
const MAX_SAMPLES_PER_SEGMENT: usize = 2000;

/// Pieces per side of a wall triangle (see the module docs).
pub const SUBDIVISIONS: usize = 8;

/// The regions painted on a mesh: index into `Regions::loops`, `None` where no region is.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Paint {
    /// The region of each fan triangle; for a triangle in `pieces`, the region of most of
    /// them.
    pub triangles: Vec<Option<usize>>,
    /// Triangles a cut line divides between regions, as pieces.
    pub pieces: Vec<Piece>,
}

/// A piece of a fan triangle that a cut line divides, in the triangle's plane and winding.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Piece {
    /// The fan triangle it is part of.
    pub triangle: usize,
    /// Its corners (mesh units).
    pub corners: [DVec3; 3],
    /// Its region.
    pub region: Option<usize>,
}

/// The region of each fan triangle of `mesh`, and of the pieces of those the cut lines
/// divide (see the module docs).
pub fn paint_regions(mesh: &ReferenceMesh, lines: &[CutLine], regions: &Regions) -> Paint {
    let count = mesh.triangle_count();
    // `+ 0.0` makes −0 and +0 one key.
    let key = |p: glam::DVec3| {
        [
            (p.x + 0.0).to_bits(),
            (p.y + 0.0).to_bits(),
            (p.z + 0.0).to_bits(),
        ]
    };
    let mut by_edge: HashMap<([u64; 3], [u64; 3]), Vec<usize>> = HashMap::new();
    let mut edge_sum = 0.0;
    for t in 0..count {
        let c = mesh.triangle(t);
        for i in 0..3 {
            let (a, b) = (c[i], c[(i + 1) % 3]);
            edge_sum += a.distance(b);
            let (ka, kb) = (key(a), key(b));
            let k = if ka <= kb { (ka, kb) } else { (kb, ka) };
            by_edge.entry(k).or_default().push(t);
        }
    }
    let mut neighbours: Vec<Vec<usize>> = vec![Vec::new(); count];
    for ts in by_edge.values() {
        for &a in ts {
            for &b in ts {
                if a != b {
                    neighbours[a].push(b);
                }
            }
        }
    }
    let spacing = SAMPLE_SPACING * edge_sum / (3 * count).max(1) as f64;
    let mut wall = vec![false; count];
    // The cut lines as chords between their projected samples, listed by the triangles
    // their ends lie in.
    let mut chords: Vec<Chord> = Vec::new();
    let mut chords_at: HashMap<usize, Vec<usize>> = HashMap::new();
    for (index, line) in lines.iter().enumerate() {
        let longest = (line.points().windows(2))
            .map(|w| w[0].distance(w[1]))
            .fold(0.0, f64::max);
        let per = ((longest / spacing).ceil() as usize).clamp(1, MAX_SAMPLES_PER_SEGMENT);
        let segs = line.segments() * per;
        let mut last: Option<(DVec3, usize)> = None;
        for k in 0..=segs {
            let p = mesh.project(line.at(k as f64 / per as f64));
            wall[p.triangle] = true;
            if let Some((a, ta)) = last {
                let c = chords.len();
                chords.push(Chord {
                    line: index,
                    a,
                    b: p.point,
                });
                chords_at.entry(ta).or_default().push(c);
                if ta != p.triangle {
                    chords_at.entry(p.triangle).or_default().push(c);
                }
            }
            last = Some((p.point, p.triangle));
        }
    }
    let mut label: Vec<Option<usize>> = vec![None; count];
    let diagonal = mesh_diagonal(mesh);
    for (r, sides) in regions.sides.iter().enumerate() {
        for &h in sides {
            for scale in [1.0, 2.0, 4.0] {
                let Some(p) = left_of(
                    mesh,
                    &lines[h / 2],
                    h % 2 == 1,
                    scale * HOLE_STEP * diagonal,
                ) else {
                    break;
                };
                let seed = mesh.project(p).triangle;
                if wall[seed] {
                    continue;
                }
                if label[seed].is_none() {
                    flood(seed, r, &wall, &neighbours, &mut label);
                }
                break;
            }
        }
    }
    // Wall triangles take a painted neighbour's region, ring by ring.
    loop {
        let before = label.clone();
        for t in (0..count).filter(|&t| wall[t] && before[t].is_none()) {
            label[t] = neighbours[t].iter().find_map(|&n| before[n]);
        }
        if label == before {
            break;
        }
    }
    // The region on the left of each half-edge.
    let mut left_region = vec![None; 2 * lines.len()];
    for (r, sides) in regions.sides.iter().enumerate() {
        for &h in sides {
            left_region[h] = Some(r);
        }
    }
    let mut pieces = Vec::new();
    for t in (0..count).filter(|&t| wall[t]) {
        let mut near: Vec<usize> = std::iter::once(t)
            .chain(neighbours[t].iter().copied())
            .flat_map(|n| chords_at.get(&n).into_iter().flatten().copied())
            .collect();
        near.sort_unstable();
        near.dedup();
        if near.is_empty() {
            continue;
        }
        let corners = mesh.triangle(t);
        let normal = mesh
            .project((corners[0] + corners[1] + corners[2]) / 3.0)
            .normal;
        let here: Vec<Piece> = subdivide(corners)
            .map(|corners| {
                let centre = (corners[0] + corners[1] + corners[2]) / 3.0;
                let region = side_region(centre, normal, &near, &chords, &left_region).or(label[t]);
                Piece {
                    triangle: t,
                    corners,
                    region,
                }
            })
            .collect();
        if let Some(main) = most_common(&here) {
            label[t] = main;
        }
        if here.iter().any(|p| p.region != label[t]) {
            pieces.extend(here);
        }
    }
    Paint {
        triangles: label,
        pieces,
    }
}

/// A piece of a cut line between two of its samples on the mesh.
struct Chord {
    line: usize,
    a: DVec3,
    b: DVec3,
}

/// The region on `p`'s side of the nearest of the chords `near` (`normal`: the mesh's there):
/// the region left of cut line `e` is its half-edge `2e`'s, right of it `2e + 1`'s.
fn side_region(
    p: DVec3,
    normal: DVec3,
    near: &[usize],
    chords: &[Chord],
    left_region: &[Option<usize>],
) -> Option<usize> {
    let (_, chord, q) = near
        .iter()
        .map(|&c| {
            let k = &chords[c];
            let q = closest_on_chord(p, k.a, k.b);
            (p.distance_squared(q), k, q)
        })
        .min_by(|x, y| x.0.total_cmp(&y.0))?;
    let left = normal.cross(chord.b - chord.a).dot(p - q) > 0.0;
    left_region[2 * chord.line + usize::from(!left)]
}

fn closest_on_chord(p: DVec3, a: DVec3, b: DVec3) -> DVec3 {
    let d = b - a;
    let len2 = d.length_squared();
    if len2 == 0.0 {
        return a;
    }
    a + d * ((p - a).dot(d) / len2).clamp(0.0, 1.0)
}

/// The [`SUBDIVISIONS`]² triangles of a regular split of `[a, b, c]`, in its winding.
fn subdivide([a, b, c]: [DVec3; 3]) -> impl Iterator<Item = [DVec3; 3]> {
    let n = SUBDIVISIONS;
    let at = move |i: usize, j: usize| {
        a + (b - a) * (i as f64 / n as f64) + (c - a) * (j as f64 / n as f64)
    };
    (0..n).flat_map(move |i| {
        (0..n - i).flat_map(move |j| {
            let up = [at(i, j), at(i + 1, j), at(i, j + 1)];
            let down = (j + 1 < n - i).then(|| [at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)]);
            std::iter::once(up).chain(down)
        })
    })
}

/// The region most of `pieces` take (the first such on a tie).
fn most_common(pieces: &[Piece]) -> Option<Option<usize>> {
    let mut counts: Vec<(Option<usize>, usize)> = Vec::new();
    for p in pieces {
        match counts.iter_mut().find(|(r, _)| *r == p.region) {
            Some((_, n)) => *n += 1,
            None => counts.push((p.region, 1)),
        }
    }
    counts
        .iter()
        .fold(
            None,
            |best: Option<(Option<usize>, usize)>, &(r, n)| match best {
                Some((_, m)) if m >= n => best,
                _ => Some((r, n)),
            },
        )
        .map(|(r, _)| r)
}

fn flood(
    seed: usize,
    region: usize,
    wall: &[bool],
    neighbours: &[Vec<usize>],
    label: &mut [Option<usize>],
) {
    let mut queue = VecDeque::from([seed]);
    label[seed] = Some(region);
    while let Some(t) = queue.pop_front() {
        for &n in &neighbours[t] {
            if !wall[n] && label[n].is_none() {
                label[n] = Some(region);
                queue.push_back(n);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::design::papercraft::sketch::regions;
    use std::f64::consts::PI;

    /// A 100 mm square of 20 × 20 cells, each cut into two triangles.
    fn square_sheet() -> ReferenceMesh {
        let n = 20;
        let mut obj = String::new();
        for j in 0..=n {
            for i in 0..=n {
                obj += &format!("v {} {} 0\n", 5 * i, 5 * j);
            }
        }
        let v = |i: usize, j: usize| j * (n + 1) + i + 1;
        for j in 0..n {
            for i in 0..n {
                obj += &format!("f {} {} {}\n", v(i, j), v(i + 1, j), v(i + 1, j + 1));
                obj += &format!("f {} {} {}\n", v(i, j), v(i + 1, j + 1), v(i, j + 1));
            }
        }
        ReferenceMesh::new(&crate::mesh::parse_obj(obj.as_bytes()).unwrap()).unwrap()
    }

    /// A disk of radius 30 mm cut out of the sheet by one closed cut line: painted area of
    /// the disk against π r² (the closed form), pieces and whole triangles together.
    #[test]
    fn colours_meet_along_a_cut_line_across_the_triangles() {
        let mesh = square_sheet();
        let (centre, r) = (DVec3::new(50.0, 50.0, 0.0), 30.0);
        let points: Vec<DVec3> = (0..=96)
            .map(|k| {
                let a = 2.0 * PI * k as f64 / 96.0 + 0.3;
                centre + DVec3::new(r * a.cos(), r * a.sin(), 0.0)
            })
            .collect();
        let lines = vec![CutLine::new(0, points).unwrap()];
        let found = regions(&mesh, &lines);
        let paint = paint_regions(&mesh, &lines, &found);
        assert!(!paint.pieces.is_empty());
        let area_of = |[a, b, c]: [DVec3; 3]| (b - a).cross(c - a).length() / 2.0;
        let divided: std::collections::HashSet<usize> =
            paint.pieces.iter().map(|p| p.triangle).collect();
        // The disk is the region holding the sheet's centre.
        let disk = paint.triangles[mesh.project(centre).triangle].expect("painted");
        let mut painted = 0.0;
        let mut whole = 0.0;
        for (t, region) in paint.triangles.iter().enumerate() {
            let a = area_of(mesh.triangle(t));
            if *region == Some(disk) {
                whole += a;
                if !divided.contains(&t) {
                    painted += a;
                }
            }
        }
        for p in paint.pieces.iter().filter(|p| p.region == Some(disk)) {
            painted += area_of(p.corners);
        }
        let exact = PI * r * r;
        // Whole triangles miss by up to a triangle along the whole rim; pieces by an eighth.
        let (err, err_whole) = ((painted / exact - 1.0).abs(), (whole / exact - 1.0).abs());
        assert!(err < 0.005, "disk painted {painted} mm² against {exact}");
        assert!(
            err < err_whole,
            "{err} against {err_whole} with whole triangles"
        );
        // Every piece lies on its own side: a piece inside the circle is the disk's.
        for p in &paint.pieces {
            let c = (p.corners[0] + p.corners[1] + p.corners[2]) / 3.0;
            let inside = c.distance(centre) < r - 0.5;
            let outside = c.distance(centre) > r + 0.5;
            assert!(!(inside && p.region != Some(disk)), "{p:?}");
            assert!(!(outside && p.region == Some(disk)), "{p:?}");
        }
    }
}
