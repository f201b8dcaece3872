//! The overlap arrangement of a folded form: every folded edge drawn in one plane and cut into
//! a planar graph whose faces are the *cells* (maximal regions covered by the same set of
//! pattern faces), after Flat-Folder's overlap graph (Ku; Akitaya, Demaine & Ku 2023).
//!
//! For each cell: the pattern faces that cover it (tested at one interior point, so a cell's
//! faces are exact as long as the point is not on a face's outline, which a cell's interior
//! never is). For each segment of the arrangement: the cells on its two sides and the pattern
//! edges that lie along it.

use glam::DVec2;

use super::LayerError;
use super::folded::FoldedFaces;
use crate::clock::Deadline;
use crate::geom::DisjointSets;
use crate::pattern::faces::find_faces;
use crate::pattern::{Assignment, CreasePattern, PlanarizeOptions, VertexId, planarize};

/// Cells and segments of the folded arrangement.
#[derive(Clone, Debug, Default)]
pub struct Arrangement {
    /// Pattern faces covering each cell, sorted ascending.
    pub cell_faces: Vec<Vec<u32>>,
    /// An interior point of each cell (folded coordinates).
    pub cell_points: Vec<DVec2>,
    /// Each cell's outline and holes (folded coordinates).
    pub cell_rings: Vec<Vec<Vec<DVec2>>>,
    /// Segments: the cells on the left and right (from `ends[0]` to `ends[1]`).
    pub segment_cells: Vec<[Option<u32>; 2]>,
    /// Segment end points (folded coordinates).
    pub segment_ends: Vec<[DVec2; 2]>,
    /// Pattern edges lying along each segment.
    pub segment_edges: Vec<Vec<u32>>,
}

/// A uniform grid of bounding boxes, for point and box queries.
pub(crate) struct BoxGrid {
    origin: DVec2,
    cell: f64,
    nx: usize,
    ny: usize,
    bins: Vec<Vec<u32>>,
}

impl BoxGrid {
    /// A grid over `boxes` with about one box per bin.
    pub(crate) fn new(boxes: &[(DVec2, DVec2)]) -> BoxGrid {
        let (lo, hi) = boxes.iter().fold(
            (DVec2::splat(f64::MAX), DVec2::splat(f64::MIN)),
            |(lo, hi), b| (lo.min(b.0), hi.max(b.1)),
        );
        let (lo, hi) = if boxes.is_empty() {
            (DVec2::ZERO, DVec2::ONE)
        } else {
            (lo, hi)
        };
        let size = (hi - lo).max(DVec2::splat(crate::geom::tolerance::ROUNDOFF));
        let per_side = (boxes.len() as f64).sqrt().ceil().clamp(1.0, 1024.0);
        let cell = size.max_element() / per_side;
        let nx = ((size.x / cell).ceil() as usize).clamp(1, 1024);
        let ny = ((size.y / cell).ceil() as usize).clamp(1, 1024);
        let mut grid = BoxGrid {
            origin: lo,
            cell,
            nx,
            ny,
            bins: vec![Vec::new(); nx * ny],
        };
        for (i, b) in boxes.iter().enumerate() {
            let (x0, y0) = grid.bin(b.0);
            let (x1, y1) = grid.bin(b.1);
            for y in y0..=y1 {
                for x in x0..=x1 {
                    grid.bins[y * nx + x].push(i as u32);
                }
            }
        }
        grid
    }

    fn bin(&self, p: DVec2) -> (usize, usize) {
        let q = (p - self.origin) / self.cell;
        (
            (q.x.max(0.0) as usize).min(self.nx - 1),
            (q.y.max(0.0) as usize).min(self.ny - 1),
        )
    }

    /// Calls `visit` with every id whose box may meet the box `lo`..`hi` (an id may come
    /// more than once).
    fn near(&self, lo: DVec2, hi: DVec2, mut visit: impl FnMut(u32)) {
        let (x0, y0) = self.bin(lo);
        let (x1, y1) = self.bin(hi);
        for y in y0..=y1 {
            for x in x0..=x1 {
                self.bins[y * self.nx + x].iter().for_each(|&i| visit(i));
            }
        }
    }

    /// Ids whose box may hold `p`.
    pub(crate) fn at(&self, p: DVec2) -> &[u32] {
        let (x, y) = self.bin(p);
        &self.bins[y * self.nx + x]
    }
}

/// Halvings of the merge distance tried, from 1/8 of the shortest edge down to 1/2^27 of it
/// (Flat-Folder's 25 steps; each is a planarisation of every folded edge).
const TOLERANCE_STEPS: std::ops::RangeInclusive<i32> = 3..=27;

/// How many successive halvings must give the same numbers of points and segments.
const STABLE_REPEATS: usize = 3;

/// Folded segments that lie along one line to within `tol` (each end of either within `tol`
/// of the other's line, overlapping by more than `tol` along it), moved onto one line: the line of the
/// longest segment of each such group, each end projected onto it when it lies within twice
/// `tol` of it. A group whose segments all move onto the line is returned as the pieces
/// between their ends, each stretch once (in the place of the group's first segment): layers
/// of a folded form pile dozens of creases on one line, and planarising the pile itself made
/// its members cross one another at tiny angles, at places that moved with the merge
/// distance (extra cells and constraints, and a false contradiction in Hashimoto's Venusaur). Creases of different faces that fold onto one line differ by the rounding of
/// the file's coordinates (often single precision); left apart they cross at a very small
/// angle at places that move with every merge distance, and the arrangement never settles.
/// `None` when `deadline` passes first.
fn snap_to_common_lines(
    segments: &[[DVec2; 2]],
    tol: f64,
    deadline: &Deadline,
) -> Option<Vec<[DVec2; 2]>> {
    let n = segments.len();
    let boxes: Vec<(DVec2, DVec2)> = segments
        .iter()
        .map(|[a, b]| (a.min(*b) - tol, a.max(*b) + tol))
        .collect();
    let grid = BoxGrid::new(&boxes);
    let line_distance = |[a, b]: [DVec2; 2], p: DVec2| {
        let d = b - a;
        let len = d.length();
        if len == 0.0 {
            a.distance(p)
        } else {
            d.perp_dot(p - a).abs() / len
        }
    };
    // Both ends of each within `tol` of the other's line, and overlapping by more than `tol`
    // along it: segments that only meet end to end at a small angle are a real bend.
    let along = |s: [DVec2; 2], t: [DVec2; 2]| {
        let u = (s[1] - s[0]).normalize_or_zero();
        let (t0, t1) = ((t[0] - s[0]).dot(u), (t[1] - s[0]).dot(u));
        let overlap = t0.max(t1).min(s[0].distance(s[1])) - t0.min(t1).max(0.0);
        overlap > 0.0
            && t.iter().all(|&p| line_distance(s, p) <= tol)
            && s.iter().all(|&p| line_distance(t, p) <= tol)
    };
    let mut groups = DisjointSets::new(n);
    for i in 0..n {
        if deadline.passed() {
            return None;
        }
        let (lo, hi) = boxes[i];
        let mut close = Vec::new();
        grid.near(lo, hi, |j| {
            if (j as usize) > i {
                close.push(j);
            }
        });
        close.sort_unstable();
        close.dedup();
        for j in close {
            let (jlo, jhi) = boxes[j as usize];
            if jlo.cmple(hi).all()
                && lo.cmple(jhi).all()
                && along(segments[i], segments[j as usize])
            {
                groups.union(i, j as usize);
            }
        }
    }
    // The longest segment of each group gives its line.
    let mut longest: Vec<Option<u32>> = vec![None; n];
    let length = |i: u32| segments[i as usize][0].distance(segments[i as usize][1]);
    let mut grouped = vec![false; n];
    for i in 0..n as u32 {
        let r = groups.find(i as usize);
        if r != i as usize {
            grouped[r] = true;
            grouped[i as usize] = true;
        }
        if longest[r].is_none_or(|k| length(k) < length(i)) {
            longest[r] = Some(i);
        }
    }
    // Each grouped segment whose two ends both move onto its group's line, as the parameters
    // of its ends along that line; the others as they are, or moved end by end.
    let mut out: Vec<[DVec2; 2]> = Vec::with_capacity(n);
    let mut on_line: Vec<Vec<(f64, f64)>> = vec![Vec::new(); n];
    let mut first_of: Vec<Option<usize>> = vec![None; n];
    for i in 0..n as u32 {
        let s = segments[i as usize];
        if !grouped[i as usize] {
            out.push(s);
            continue;
        }
        let r = groups.find(i as usize);
        let Some(k) = longest[r] else {
            out.push(s);
            continue;
        };
        let [a, b] = segments[k as usize];
        let u = (b - a).normalize_or_zero();
        let t = s.map(|p| (p - a).dot(u));
        let q = t.map(|t| a + u * t);
        if q[0].distance(s[0]) <= 2.0 * tol && q[1].distance(s[1]) <= 2.0 * tol {
            on_line[r].push((t[0].min(t[1]), t[0].max(t[1])));
            if first_of[r].is_none() {
                // The group's pieces take the place of its first segment.
                first_of[r] = Some(out.len());
                out.push([DVec2::ZERO; 2]);
            }
            continue;
        }
        out.push(std::array::from_fn(|j| {
            if q[j].distance(s[j]) <= 2.0 * tol {
                q[j]
            } else {
                s[j]
            }
        }));
    }
    // A pile of overlapping segments on one line becomes the pieces between its ends, each
    // once: the same points and the same covered stretches, without the pile's every pair to
    // test for crossings.
    let mut pieces_at: Vec<(usize, Vec<[DVec2; 2]>)> = Vec::new();
    for r in 0..n {
        let Some(slot) = first_of[r] else {
            continue;
        };
        let Some(k) = longest[r] else {
            continue;
        };
        let [a, b] = segments[k as usize];
        let u = (b - a).normalize_or_zero();
        let intervals = &mut on_line[r];
        intervals.sort_by(|x, y| x.0.total_cmp(&y.0));
        let mut ends: Vec<f64> = intervals.iter().flat_map(|&(lo, hi)| [lo, hi]).collect();
        ends.sort_by(f64::total_cmp);
        ends.dedup();
        let mut pieces = Vec::new();
        let (mut next, mut reach) = (0, f64::NEG_INFINITY);
        for w in ends.windows(2) {
            while next < intervals.len() && intervals[next].0 <= w[0] {
                reach = reach.max(intervals[next].1);
                next += 1;
            }
            if reach >= w[1] {
                pieces.push([a + u * w[0], a + u * w[1]]);
            }
        }
        pieces_at.push((slot, pieces));
    }
    pieces_at.sort_by_key(|p| std::cmp::Reverse(p.0));
    for (slot, pieces) in pieces_at {
        out.splice(slot..=slot, pieces);
    }
    Some(out)
}

/// The deadline of an arrangement passed before it was done.
struct TimedOut;

/// The folded edges cut into a planar graph, and the merge distance chosen for it.
///
/// Like Flat-Folder, the distance is the shortest folded edge divided by 2^i for i = 3, 4, …,
/// halved until the numbers of points and segments stay the same [`STABLE_REPEATS`] times;
/// the largest distance of that stable run is used (when no run gets that long before
/// `floor`, the largest distance of the first longest run). Coordinates written to single precision
/// by other tools then still meet where they should, and fine details are not merged away.
/// `floor` is the smallest distance tried. `Err` when `deadline` passes first.
fn planar_sheet(
    segments: &[Option<[DVec2; 2]>],
    floor: f64,
    deadline: &Deadline,
) -> Result<Option<(CreasePattern, f64)>, TimedOut> {
    let segments: Vec<[DVec2; 2]> = segments.iter().flatten().copied().collect();
    let raw = |tol: f64| {
        let mut raw = CreasePattern::new();
        for s in snap_to_common_lines(&segments, tol, deadline).ok_or(TimedOut)? {
            raw.add_segment(s[0], s[1], Assignment::Boundary);
        }
        Ok(raw)
    };
    let shortest = segments
        .iter()
        .map(|[a, b]| a.distance(*b))
        .filter(|&d| d > 0.0)
        .fold(f64::MAX, f64::min);
    if shortest == f64::MAX {
        return Ok(None);
    }
    // The current run of equal counts (its coarsest sheet, counts, length) and the longest
    // run met so far (the first of that length).
    let mut run: Option<(CreasePattern, f64)> = None;
    let mut last = (usize::MAX, usize::MAX);
    let mut length = 0;
    let mut best: Option<(CreasePattern, f64)> = None;
    let mut best_length = 0;
    for i in TOLERANCE_STEPS {
        let tol = shortest / 2f64.powi(i);
        if tol < floor {
            break;
        }
        let mut sheet = raw(tol)?;
        let options = PlanarizeOptions {
            tolerance: Some(tol),
            faces: false,
        };
        let failed = planarize(&mut sheet, &options).is_err();
        if failed {
            (run, last, length) = (None, (usize::MAX, usize::MAX), 0);
            continue;
        }
        let counts = (sheet.vertices.len(), sheet.edges.len());
        if counts == last {
            length += 1;
        } else {
            (run, last, length) = (Some((sheet, tol)), counts, 1);
        }
        if length > best_length {
            best_length = length;
            best.clone_from(&run);
            if best_length >= STABLE_REPEATS {
                break;
            }
        }
    }
    Ok(best)
}

/// Builds the arrangement of `folded` (the folded form of `cp`); `floor` is the smallest merge
/// distance tried (see [`planar_sheet`]). Returns the arrangement and the distance used.
pub fn arrange(cp: &CreasePattern, folded: &FoldedFaces, floor: f64) -> (Arrangement, f64) {
    match arrange_by(cp, folded, floor, &Deadline::after(None)) {
        Ok(done) => done,
        // Without a time limit the deadline never passes.
        Err(_) => (Arrangement::default(), floor),
    }
}

/// [`arrange`], giving up when `deadline` passes.
pub(crate) fn arrange_by(
    cp: &CreasePattern,
    folded: &FoldedFaces,
    floor: f64,
    deadline: &Deadline,
) -> Result<(Arrangement, f64), LayerError> {
    let segments = folded_segments(cp, folded);
    let planar = planar_sheet(&segments, floor, deadline)
        .map_err(|TimedOut| LayerError::out_of_time(deadline, "arranging the folded layers"))?;
    let Some((sheet, tol)) = planar else {
        return Ok((Arrangement::default(), floor));
    };
    if sheet.edges.is_empty() {
        return Ok((Arrangement::default(), tol));
    }
    let traced = find_faces(&sheet);
    let mut arr = Arrangement::default();
    for cell in &traced.faces {
        let rings: Vec<Vec<DVec2>> = std::iter::once(&cell.outer)
            .chain(&cell.holes)
            .map(|r| r.iter().map(|&v| sheet.position(v)).collect())
            .collect();
        arr.cell_points.push(interior_point(&rings));
        arr.cell_rings.push(rings);
    }
    let mut side_of = std::collections::HashMap::new();
    for (c, cell) in traced.faces.iter().enumerate() {
        for ring in std::iter::once(&cell.outer).chain(&cell.holes) {
            for (a, b) in super::folded::ring_pairs(ring) {
                side_of.insert((a, b), c as u32);
            }
        }
    }
    let edge_boxes: Vec<(DVec2, DVec2)> = segments
        .iter()
        .map(|s| match s {
            Some([a, b]) => (a.min(*b) - tol, a.max(*b) + tol),
            None => (DVec2::splat(f64::MAX), DVec2::splat(f64::MIN)),
        })
        .collect();
    let edge_grid = BoxGrid::new(&edge_boxes);
    for e in &sheet.edges {
        let [a, b]: [VertexId; 2] = e.vertices;
        let ends = [sheet.position(a), sheet.position(b)];
        let mid = (ends[0] + ends[1]) * 0.5;
        let mut along: Vec<u32> = edge_grid
            .at(mid)
            .iter()
            .copied()
            .filter(|&i| {
                segments[i as usize].is_some_and(|[p, q]| {
                    [ends[0], mid, ends[1]]
                        .iter()
                        .all(|&x| crate::geom::segment::distance_to_point(p, q, x) <= tol)
                })
            })
            .collect();
        along.sort_unstable();
        arr.segment_cells
            .push([side_of.get(&(a, b)).copied(), side_of.get(&(b, a)).copied()]);
        arr.segment_ends.push(ends);
        arr.segment_edges.push(along);
    }
    arr.cell_faces = coverage(cp, folded, &arr, tol);
    Ok((arr, tol))
}

/// Largest difference between a face's area and the area of the cells its flood fill
/// reached, relative to the face's area, before the fill is distrusted (on top of what
/// merging points within the arrangement's distance can move: that distance times the
/// face's perimeter, twice).
const FILL_AREA_AGREEMENT: f64 = 1e-6;

/// The pattern faces covering each cell, sorted.
///
/// Each face is flood-filled through the arrangement from the cell beside one of its edges,
/// never crossing a segment that carries one of its own edges: the cells reached are the
/// face's, decided by the arrangement's topology rather than by testing points against the
/// face's outline (a point of a thin cell can fall on the wrong side of an outline that the
/// arrangement merged with a neighbouring line). A fill that leaks out of the paper or whose
/// cells' area differs from the face's (an edge of the face not found along its segments)
/// falls back to testing each cell's interior point.
fn coverage(
    cp: &CreasePattern,
    folded: &FoldedFaces,
    arr: &Arrangement,
    tol: f64,
) -> Vec<Vec<u32>> {
    let n_cells = arr.cell_rings.len();
    let mut cell_segments: Vec<Vec<u32>> = vec![Vec::new(); n_cells];
    let mut edge_segments: Vec<Vec<u32>> = vec![Vec::new(); cp.edges.len()];
    for (s, sides) in arr.segment_cells.iter().enumerate() {
        for c in sides.iter().flatten() {
            cell_segments[*c as usize].push(s as u32);
        }
        for &e in &arr.segment_edges[s] {
            edge_segments[e as usize].push(s as u32);
        }
    }
    let cell_area: Vec<f64> = arr
        .cell_rings
        .iter()
        .map(|rings| rings.iter().map(|r| signed_area(r)).sum::<f64>().abs())
        .collect();
    let mut face_edges: Vec<Vec<u32>> = vec![Vec::new(); folded.faces.len()];
    for (e, sides) in folded.edge_faces.iter().enumerate() {
        for f in sides.iter().flatten() {
            face_edges[*f as usize].push(e as u32);
        }
    }
    let mut out: Vec<Vec<u32>> = vec![Vec::new(); n_cells];
    let mut mark = vec![u32::MAX; n_cells];
    let mut fallback = Vec::new();
    for (f, face) in folded.faces.iter().enumerate() {
        let fid = f as u32;
        let borders = |s: u32| {
            arr.segment_edges[s as usize]
                .iter()
                .any(|&e| folded.edge_faces[e as usize].contains(&Some(fid)))
        };
        let seed = face_edges[f].iter().find_map(|&e| {
            let e = e as usize;
            let side = folded.edge_faces[e].iter().position(|&g| g == Some(fid))?;
            let &s = edge_segments[e].first()?;
            let [p, q] = arr.segment_ends[s as usize];
            let [a, b] = cp.edges[e]
                .vertices
                .map(|v| face.transform.transform_point2(cp.position(v)));
            // The face lies on the left of its edge (side 0) in the pattern; a reflection
            // swaps left and right.
            let left = (side == 0) != face.flipped;
            let same = (q - p).dot(b - a) > 0.0;
            arr.segment_cells[s as usize][usize::from(left != same)]
        });
        let area = signed_area(&face.outer).abs()
            - face.holes.iter().map(|h| signed_area(h).abs()).sum::<f64>();
        let mut reached = Vec::new();
        let mut leaked = seed.is_none();
        if let Some(seed) = seed {
            mark[seed as usize] = fid;
            reached.push(seed);
            let mut k = 0;
            while k < reached.len() && !leaked {
                let c = reached[k];
                k += 1;
                for &s in &cell_segments[c as usize] {
                    if borders(s) {
                        continue;
                    }
                    let sides = arr.segment_cells[s as usize];
                    let other = if sides[0] == Some(c) {
                        sides[1]
                    } else {
                        sides[0]
                    };
                    match other {
                        None => {
                            leaked = true;
                            break;
                        }
                        Some(o) if mark[o as usize] != fid => {
                            mark[o as usize] = fid;
                            reached.push(o);
                        }
                        Some(_) => {}
                    }
                }
            }
        }
        let filled: f64 = reached.iter().map(|&c| cell_area[c as usize]).sum();
        let perimeter: f64 = std::iter::once(&face.outer)
            .chain(&face.holes)
            .flat_map(|r| (0..r.len()).map(move |i| r[i].distance(r[(i + 1) % r.len()])))
            .sum();
        if leaked || (filled - area).abs() > FILL_AREA_AGREEMENT * area + 2.0 * tol * perimeter {
            fallback.push(fid);
            continue;
        }
        for c in reached {
            out[c as usize].push(fid);
        }
    }
    if !fallback.is_empty() {
        let boxes: Vec<(DVec2, DVec2)> = fallback
            .iter()
            .map(|&f| folded.faces[f as usize].bounds)
            .collect();
        let grid = BoxGrid::new(&boxes);
        for (c, &p) in arr.cell_points.iter().enumerate() {
            for &i in grid.at(p) {
                let f = fallback[i as usize];
                if folded.faces[f as usize].contains(p) {
                    out[c].push(f);
                }
            }
        }
    }
    for faces in &mut out {
        faces.sort_unstable();
    }
    out
}

/// Signed area of a closed ring (positive counter-clockwise).
fn signed_area(ring: &[DVec2]) -> f64 {
    (0..ring.len())
        .map(|i| ring[i].perp_dot(ring[(i + 1) % ring.len()]))
        .sum::<f64>()
        * 0.5
}

/// The folded segment of every edge that borders a face (`None` for edges on no face), drawn
/// through the vertices' shared folded places.
fn folded_segments(cp: &CreasePattern, folded: &FoldedFaces) -> Vec<Option<[DVec2; 2]>> {
    cp.edges
        .iter()
        .zip(&folded.edge_faces)
        .map(|(e, sides)| {
            let f = *sides.iter().flatten().next()?;
            Some(e.vertices.map(|v| folded.point(cp, f, v)))
        })
        .collect()
}

/// A point strictly inside a polygon with holes: the middle of the widest interval cut from a
/// horizontal line halfway between the two most distant neighbouring vertex heights.
pub fn interior_point(rings: &[Vec<DVec2>]) -> DVec2 {
    let mut ys: Vec<f64> = rings.iter().flatten().map(|p| p.y).collect();
    ys.sort_by(f64::total_cmp);
    let y = ys
        .windows(2)
        .max_by(|a, b| (a[1] - a[0]).total_cmp(&(b[1] - b[0])))
        .map_or(ys.first().copied().unwrap_or(0.0), |w| (w[0] + w[1]) * 0.5);
    let mut xs = Vec::new();
    for ring in rings {
        for i in 0..ring.len() {
            let (a, b) = (ring[i], ring[(i + 1) % ring.len()]);
            if (a.y > y) != (b.y > y) {
                xs.push(a.x + (y - a.y) / (b.y - a.y) * (b.x - a.x));
            }
        }
    }
    xs.sort_by(f64::total_cmp);
    let best = xs
        .chunks_exact(2)
        .max_by(|a, b| (a[1] - a[0]).total_cmp(&(b[1] - b[0])));
    match best {
        Some(w) => DVec2::new((w[0] + w[1]) * 0.5, y),
        None => rings
            .first()
            .and_then(|r| r.first())
            .copied()
            .unwrap_or(DVec2::ZERO),
    }
}

#[cfg(test)]
mod tests {
    use super::snap_to_common_lines;
    use glam::DVec2;

    #[test]
    fn a_pile_of_collinear_segments_becomes_its_pieces_once() {
        let p = |x: f64, y: f64| DVec2::new(x, y);
        // Three overlapping strokes along y = 0 (one a rounding error off it), and one
        // stroke crossing them.
        let segments = [
            [p(0.0, 0.0), p(2.0, 0.0)],
            [p(1.0, 1e-12), p(3.0, 0.0)],
            [p(2.5, 0.0), p(1.5, 0.0)],
            [p(1.2, -1.0), p(1.2, 1.0)],
        ];
        let out = snap_to_common_lines(&segments, 1e-6, &crate::clock::Deadline::after(None))
            .expect("no limit");
        // The cross stroke is left as it is.
        assert!(out.contains(&segments[3]));
        let mut pieces: Vec<(f64, f64)> = out
            .iter()
            .filter(|s| s[0].y.abs() < 1e-9 && s[1].y.abs() < 1e-9)
            .map(|s| (s[0].x.min(s[1].x), s[0].x.max(s[1].x)))
            .collect();
        pieces.sort_by(|a, b| a.0.total_cmp(&b.0));
        // Cut at every end: 0, 1, 1.5, 2, 2.5, 3; each stretch once.
        let expected = [(0.0, 1.0), (1.0, 1.5), (1.5, 2.0), (2.0, 2.5), (2.5, 3.0)];
        assert_eq!(pieces.len(), expected.len(), "{pieces:?}");
        for (got, want) in pieces.iter().zip(expected) {
            assert!(
                (got.0 - want.0).abs() < 1e-9 && (got.1 - want.1).abs() < 1e-9,
                "{pieces:?}"
            );
        }
        assert_eq!(out.len(), expected.len() + 1);
    }

    #[test]
    fn separate_stretches_of_one_line_leave_their_gap_open() {
        let p = |x: f64| DVec2::new(x, 0.0);
        let segments = [[p(0.0), p(2.0)], [p(1.0), p(1.5)], [p(3.0), p(4.0)]];
        let out = snap_to_common_lines(&segments, 1e-6, &crate::clock::Deadline::after(None))
            .expect("no limit");
        // The first two overlap and are one group; the third only shares their line.
        assert!(out.contains(&segments[2]));
        assert!(
            !out.iter()
                .any(|s| s[0].x.min(s[1].x) < 2.5 && s[0].x.max(s[1].x) > 2.5)
        );
        assert_eq!(out.len(), 4, "{out:?}");
    }
}
