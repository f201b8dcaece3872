// A uniform grid over line segments: the segment nearest to a point within a reach, found by
// looking only at the segments of the grid cells around the point (the pattern view's hover
// and click on patterns of 100k edges, where a loop over every edge per pointer move is slow).

/** Mean number of cells a segment is aimed to cover (the cell side is about a segment's
 * mean length). */
const CELL_OVER_MEAN = 1;
/** Most cells of a grid: memory stays bounded on sparse, very spread segments. */
const MAX_CELLS = 1 << 20;

/** Distance from point (px, py) to segment (x1, y1)–(x2, y2), in their units. */
export function segmentDistance(px, py, x1, y1, x2, y2) {
  const dx = x2 - x1, dy = y2 - y1;
  const l2 = dx * dx + dy * dy;
  let t = l2 > 0 ? ((px - x1) * dx + (py - y1) * dy) / l2 : 0;
  t = t < 0 ? 0 : t > 1 ? 1 : t;
  return Math.hypot(px - (x1 + t * dx), py - (y1 + t * dy));
}

export class SegmentGrid {
  /**
   * Indexes the segments of `coords`: four numbers a segment (x1, y1, x2, y2) in the model's
   * units, segment k at `coords[4k .. 4k + 4]`. The grid keeps `coords` (not a copy): change
   * it and build a new grid. Every segment is listed in every cell its length passes through,
   * so a query finds each segment within its reach.
   */
  constructor(coords) {
    this.coords = coords;
    const n = Math.floor(coords.length / 4);
    this.count = n;
    let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity, total = 0;
    for (let k = 0; k < n; k++) {
      const a = coords[4 * k], b = coords[4 * k + 1], c = coords[4 * k + 2], d = coords[4 * k + 3];
      x0 = Math.min(x0, a, c); x1 = Math.max(x1, a, c);
      y0 = Math.min(y0, b, d); y1 = Math.max(y1, b, d);
      total += Math.hypot(c - a, d - b);
    }
    if (!n) { x0 = y0 = 0; x1 = y1 = 1; }
    const w = x1 - x0, h = y1 - y0;
    const span = Math.max(w, h) || 1;
    // About a mean segment per cell side, but no more than MAX_CELLS cells in all.
    let side = n ? (total / n) * CELL_OVER_MEAN : span;
    side = Math.max(side, span * 1e-6, Math.sqrt((w * h) / MAX_CELLS));
    let cols = Math.max(1, Math.ceil(w / side)), rows = Math.max(1, Math.ceil(h / side));
    while (cols * rows > MAX_CELLS) {
      side *= 1.5;
      cols = Math.max(1, Math.ceil(w / side));
      rows = Math.max(1, Math.ceil(h / side));
    }
    Object.assign(this, { x0, y0, side, cols, rows });
    // Two passes: count each cell's segments, then fill one flat list (start offsets per cell).
    const start = new Int32Array(cols * rows + 1);
    for (let k = 0; k < n; k++) this.eachCell(k, (cell) => { start[cell + 1] += 1; });
    for (let c = 0; c < cols * rows; c++) start[c + 1] += start[c];
    const fill = start.slice(0, cols * rows);
    const items = new Int32Array(start[cols * rows]);
    for (let k = 0; k < n; k++) this.eachCell(k, (cell) => { items[fill[cell]++] = k; });
    this.start = start;
    this.items = items;
    this.seen = new Uint32Array(n);
    this.stamp = 0;
  }

  /** The column of x (clamped to the grid). */
  col(x) {
    return Math.min(this.cols - 1, Math.max(0, Math.floor((x - this.x0) / this.side)));
  }

  /** The row of y (clamped to the grid). */
  row(y) {
    return Math.min(this.rows - 1, Math.max(0, Math.floor((y - this.y0) / this.side)));
  }

  /** Calls `visit(cell)` for every cell segment `k` passes through (row by row: the part of
   * the segment within the row's band, widened by a rounding margin, gives the columns). */
  eachCell(k, visit) {
    const c = this.coords;
    const ax = c[4 * k], ay = c[4 * k + 1], bx = c[4 * k + 2], by = c[4 * k + 3];
    const margin = this.side * 1e-9;
    const r0 = this.row(Math.min(ay, by) - margin), r1 = this.row(Math.max(ay, by) + margin);
    for (let r = r0; r <= r1; r++) {
      let lo = Math.min(ax, bx), hi = Math.max(ax, bx);
      if (ay !== by) {
        // The segment's x where it enters and leaves the row's band.
        const band0 = this.y0 + r * this.side - margin, band1 = band0 + this.side + 2 * margin;
        let t0 = (band0 - ay) / (by - ay), t1 = (band1 - ay) / (by - ay);
        if (t0 > t1) [t0, t1] = [t1, t0];
        t0 = Math.max(0, t0);
        t1 = Math.min(1, t1);
        const xa = ax + t0 * (bx - ax), xb = ax + t1 * (bx - ax);
        lo = Math.min(xa, xb);
        hi = Math.max(xa, xb);
      }
      const c0 = this.col(lo - margin), c1 = this.col(hi + margin);
      for (let col = c0; col <= c1; col++) visit(r * this.cols + col);
    }
  }

  /**
   * The index of the segment nearest to (x, y) at a distance of at most `reach` (the same
   * units as the coordinates), or -1 when there is none; of two at the same distance, the
   * lower index.
   */
  nearest(x, y, reach) {
    if (!this.count || !(reach >= 0)) return -1;
    this.stamp += 1;
    if (this.stamp === 0xffffffff) { this.seen.fill(0); this.stamp = 1; }
    const c = this.coords;
    let best = -1, bestD = reach;
    const r0 = this.row(y - reach), r1 = this.row(y + reach);
    const c0 = this.col(x - reach), c1 = this.col(x + reach);
    for (let r = r0; r <= r1; r++) {
      for (let col = c0; col <= c1; col++) {
        const cell = r * this.cols + col;
        for (let i = this.start[cell]; i < this.start[cell + 1]; i++) {
          const k = this.items[i];
          if (this.seen[k] === this.stamp) continue;
          this.seen[k] = this.stamp;
          const d = segmentDistance(x, y, c[4 * k], c[4 * k + 1], c[4 * k + 2], c[4 * k + 3]);
          if (d < bestD || (d === bestD && (best < 0 || k < best))) { best = k; bestD = d; }
        }
      }
    }
    return best;
  }
}
