//! A uniform grid over triangles' bounding boxes, for nearest-triangle queries.
//!
//! Each cell lists the triangles whose bounding box overlaps it. A query visits rings of
//! cells around the query's cell (Chebyshev distance r = 0, 1, …; only the ring's shell is
//! enumerated) and stops once no unvisited cell can hold anything closer than the best
//! candidate: a point of a cell at ring ≥ r + 1 is at least `r · h_min − d_out` away, where
//! `h_min` is the smallest cell side and `d_out` the distance from the query to the grid box.
//! Within a ring, a cell whose box is no nearer than the best candidate is skipped, and so is
//! a triangle whose bounding box is no nearer (which also makes a triangle listed in several
//! cells cheap to meet again).

use glam::DVec3;

use crate::geom::tolerance::RELATIVE;

/// Triangles binned into axis-aligned cells.
#[derive(Clone, Debug)]
pub(crate) struct TriangleGrid {
    origin: DVec3,
    cell: DVec3,
    dims: [usize; 3],
    /// `starts[c]..starts[c + 1]` indexes `items` for cell `c`.
    starts: Vec<u32>,
    items: Vec<u32>,
    /// Each triangle's bounding box.
    boxes: Vec<(DVec3, DVec3)>,
}

impl TriangleGrid {
    /// Bins `boxes` (min, max per triangle) into about `2 · boxes.len()` cells.
    pub(crate) fn new(boxes: Vec<(DVec3, DVec3)>) -> Self {
        let (mut lo, mut hi) = (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY));
        for &(a, b) in &boxes {
            lo = lo.min(a);
            hi = hi.max(b);
        }
        let extent = (hi - lo).max(DVec3::splat(RELATIVE * (hi - lo).max_element().max(1.0)));
        let target = (2 * boxes.len()).clamp(1, 1 << 21) as f64;
        let side = (extent.x * extent.y * extent.z / target).cbrt();
        let dim = |e: f64| ((e / side).ceil() as usize).clamp(1, 256);
        let dims = [dim(extent.x), dim(extent.y), dim(extent.z)];
        let mut grid = TriangleGrid {
            origin: lo,
            cell: DVec3::ONE,
            dims,
            starts: Vec::new(),
            items: Vec::new(),
            boxes,
        };
        grid.cell = extent / grid.dims_f();
        grid.fill();
        grid
    }

    fn fill(&mut self) {
        let count = self.dims.iter().product::<usize>();
        let mut counts = vec![0u32; count + 1];
        self.for_each_cell_of(|c, _| counts[c + 1] += 1);
        for c in 0..count {
            counts[c + 1] += counts[c];
        }
        let mut next = counts.clone();
        self.items = vec![0; counts[count] as usize];
        let mut items = std::mem::take(&mut self.items);
        self.for_each_cell_of(|c, t| {
            items[next[c] as usize] = t;
            next[c] += 1;
        });
        self.items = items;
        self.starts = counts;
    }

    fn for_each_cell_of(&self, mut f: impl FnMut(usize, u32)) {
        for (t, &(a, b)) in self.boxes.iter().enumerate() {
            let (ia, ib) = (self.cell_of(a), self.cell_of(b));
            for z in ia[2]..=ib[2] {
                for y in ia[1]..=ib[1] {
                    for x in ia[0]..=ib[0] {
                        f(self.index([x, y, z]), t as u32);
                    }
                }
            }
        }
    }

    fn cell_of(&self, p: DVec3) -> [usize; 3] {
        let q = (p - self.origin) / self.cell;
        let clamp = |v: f64, d: usize| (v.floor().max(0.0) as usize).min(d - 1);
        [
            clamp(q.x, self.dims[0]),
            clamp(q.y, self.dims[1]),
            clamp(q.z, self.dims[2]),
        ]
    }

    fn index(&self, [x, y, z]: [usize; 3]) -> usize {
        (z * self.dims[1] + y) * self.dims[0] + x
    }

    /// Visits triangles near `p` in rings; `visit(t)` returns the candidate's distance and the
    /// search stops when no farther ring can beat the best distance seen. Triangles and cells
    /// whose boxes are no nearer than the best distance so far are not visited.
    pub(crate) fn nearest(&self, p: DVec3, mut visit: impl FnMut(u32) -> f64) {
        let max = self.origin + self.cell * self.dims_f();
        let d_out = (p - p.clamp(self.origin, max)).length();
        let h_min = self.cell.min_element();
        let c = self.cell_of(p);
        let rings = *self.dims.iter().max().unwrap_or(&1);
        let mut best = f64::INFINITY;
        for r in 0..rings {
            self.visit_ring(c, r, |cell| {
                let lo = self.origin + self.cell * DVec3::from(cell.map(|i| i as f64));
                if box_distance(p, lo, lo + self.cell) >= best {
                    return;
                }
                let i = self.index(cell);
                let (s, e) = (self.starts[i] as usize, self.starts[i + 1] as usize);
                for &t in &self.items[s..e] {
                    let (a, b) = self.boxes[t as usize];
                    if box_distance(p, a, b) < best {
                        best = best.min(visit(t));
                    }
                }
            });
            if r as f64 * h_min - d_out >= best {
                return;
            }
        }
    }

    fn dims_f(&self) -> DVec3 {
        DVec3::from(self.dims.map(|d| d as f64))
    }

    /// Calls `f` on every cell at Chebyshev distance exactly `r` from `c` (inside the grid).
    fn visit_ring(&self, c: [usize; 3], r: usize, mut f: impl FnMut([usize; 3])) {
        let range = |i: usize, d: usize| (i.saturating_sub(r), (i + r).min(d - 1));
        let (x0, x1) = range(c[0], self.dims[0]);
        let (y0, y1) = range(c[1], self.dims[1]);
        let (z0, z1) = range(c[2], self.dims[2]);
        for z in z0..=z1 {
            for y in y0..=y1 {
                let on_shell = z.abs_diff(c[2]) == r || y.abs_diff(c[1]) == r;
                if on_shell {
                    (x0..=x1).for_each(|x| f([x, y, z]));
                } else {
                    // Only the two x faces of the shell can be at distance r.
                    if c[0] >= r {
                        f([c[0] - r, y, z]);
                    }
                    if c[0] + r < self.dims[0] {
                        f([c[0] + r, y, z]);
                    }
                }
            }
        }
    }
}

/// Distance from `p` to the box `[lo, hi]` (0 inside).
fn box_distance(p: DVec3, lo: DVec3, hi: DVec3) -> f64 {
    (p - p.clamp(lo, hi)).length()
}
