// The crease-pattern view: the lines drawn on a canvas (one path per assignment, redrawn once
// per animation frame while panning or zooming), under a transparent SVG in pattern
// coordinates (y up) that takes the pointer and holds the few interactive marks: the hovered
// and the selected line, the findings' rings and the previews of edits (see edit.js). Pan by
// drag, zoom by wheel; hover and click find the line under the pointer in a SegmentGrid.
import { SegmentGrid } from './segments.js';

const NS = 'http://www.w3.org/2000/svg';
/** Screen width of the base line, pixels (legend widths and dashes are multiples of it). */
const BASE_WIDTH = 1.5;
/** Drawing order: faint lines first, outlines and cuts on top (as in our previews). */
const ORDER = ['F', 'J', 'U', 'V', 'M', 'B', 'C'];
/** How near the pointer a line is found (hover, click), screen pixels. */
export const PICK_PIXELS = 4.5;
/** Lines are drawn with their dashes only when the pattern's median edge is at least this
 * long on screen, pixels (two periods of the longest dash pattern, the mountain's 16.5 px);
 * shorter, they are drawn solid: the dashes would not show, and stroking every dash is what
 * slows a canvas down on big patterns. */
export const DASH_FROM_PIXELS = 33;
/** A press and release farther apart than this are a drag, not a click, screen pixels. */
const CLICK_SLOP = 4;

function el(name, attrs = {}, parent = null) {
  const node = document.createElementNS(NS, name);
  for (const [k, v] of Object.entries(attrs)) node.setAttribute(k, v);
  if (parent) parent.appendChild(node);
  return node;
}

/** Pan/zoom over an SVG's viewBox; `box` is [x, y, w, h] in SVG units. Dragging pans
 * while `canPan()` says so. */
export function panZoom(svg, getBox, setBox, canPan = () => true) {
  let drag = null;
  svg.addEventListener('wheel', (e) => {
    e.preventDefault();
    const [x, y, w, h] = getBox();
    const r = svg.getBoundingClientRect();
    const fx = (e.clientX - r.left) / r.width, fy = (e.clientY - r.top) / r.height;
    const k = Math.exp(e.deltaY * 0.0015);
    setBox([x + fx * w * (1 - k), y + fy * h * (1 - k), w * k, h * k]);
  }, { passive: false });
  svg.addEventListener('pointerdown', (e) => { drag = canPan() ? [e.clientX, e.clientY, getBox()] : null; });
  svg.addEventListener('pointermove', (e) => {
    if (!drag) return;
    const [sx, sy, [x, y, w, h]] = drag;
    const r = svg.getBoundingClientRect();
    const s = Math.max(w / r.width, h / r.height);
    setBox([x - (e.clientX - sx) * s, y - (e.clientY - sy) * s, w, h]);
  });
  for (const end of ['pointerup', 'pointerleave']) svg.addEventListener(end, () => { drag = null; });
}

export class PatternView {
  /**
   * `svg` is the transparent overlay that takes the pointer, `canvas` the canvas under it (the
   * same box), `info` the label that names the hovered line.
   */
  constructor(svg, canvas, info) {
    this.svg = svg;
    this.canvas = canvas;
    // A CPU canvas: under software GL (no GPU) it draws lines faster than an accelerated one.
    this.ctx = canvas.getContext('2d', { willReadFrequently: true });
    this.info = info;
    this.box = [0, 0, 1, 1];
    this.canPan = () => true;
    this.onEdgeClick = () => {};
    this.hovered = null;
    this.selected = null;
    /** Frames drawn on the canvas so far (the pan benchmark counts them). */
    this.frames = 0;
    this.pending = 0;
    // For the browser tests and the console: the view behind the canvas.
    canvas.patternView = this;
    panZoom(svg, () => this.box, (b) => this.setBox(b), () => this.canPan());
    svg.addEventListener('pointermove', (e) => this.pointerAt(e));
    svg.addEventListener('pointerleave', () => this.leave());
    // A click picks the line under it (a drag that pans is no click).
    let down = null;
    svg.addEventListener('pointerdown', (e) => { down = [e.clientX, e.clientY]; });
    svg.addEventListener('click', (e) => {
      if (down && Math.hypot(e.clientX - down[0], e.clientY - down[1]) > CLICK_SLOP) return;
      const i = this.edgeAt(e);
      if (this.canPan()) this.select(i);
      if (i != null) this.onEdgeClick(i);
    });
    new ResizeObserver(() => this.redraw()).observe(canvas);
  }

  /** Pattern coordinates (y up) of a pointer event. */
  toPattern(e) {
    const p = this.svg.createSVGPoint();
    p.x = e.clientX;
    p.y = e.clientY;
    const q = p.matrixTransform(this.root.getScreenCTM().inverse());
    return [q.x, q.y];
  }

  /** Pattern units per screen pixel at the current zoom. */
  unitsPerPixel() {
    const m = this.root.getScreenCTM();
    return 1 / Math.hypot(m.a, m.b);
  }

  /** The edge within PICK_PIXELS of the pointer event `e` (the nearest), or null. */
  edgeAt(e) {
    if (!this.grid || !this.root.getScreenCTM()) return null;
    const [x, y] = this.toPattern(e);
    const i = this.grid.nearest(x, y, PICK_PIXELS * this.unitsPerPixel());
    return i < 0 ? null : i;
  }

  /** Names the line under the pointer, or forgets the last one when there is none. */
  pointerAt(e) {
    const i = this.edgeAt(e);
    if (i == null) this.leave();
    else if (i !== this.hovered) this.hover(i);
  }

  /** The vertex nearest to `p` within `reach` (pattern units), or null. */
  nearestVertex(p, reach) {
    let best = null, bestD = reach;
    this.pattern.vertices.forEach((q, i) => {
      const d = Math.hypot(q[0] - p[0], q[1] - p[1]);
      if (d <= bestD) { best = i; bestD = d; }
    });
    return best;
  }

  /** Marks the snapped point `s` and the crease from `start` (if any) to it. */
  previewCrease(start, s) {
    this.clearPreview();
    if (start) {
      el('line', { x1: start[0], y1: start[1], x2: s.point[0], y2: s.point[1], class: 'preview-line',
        'vector-effect': 'non-scaling-stroke' }, this.previewLayer);
    }
    this.marker(s);
  }

  /** Draws vertex `v`'s edges as if it stood at the snapped point `s`. */
  previewMove(v, s) {
    this.clearPreview();
    for (const e of this.pattern.edges) {
      if (!e.v.includes(v)) continue;
      const other = this.pattern.vertices[e.v[0] === v ? e.v[1] : e.v[0]];
      el('line', { x1: other[0], y1: other[1], x2: s.point[0], y2: s.point[1], class: 'preview-line',
        'vector-effect': 'non-scaling-stroke' }, this.previewLayer);
    }
    this.marker(s);
  }

  marker(s) {
    el('circle', { cx: s.point[0], cy: s.point[1], r: 5 * this.unitsPerPixel(),
      class: `snap-marker snap-${s.kind}`, 'vector-effect': 'non-scaling-stroke' }, this.previewLayer);
  }

  clearPreview() {
    if (this.previewLayer) this.previewLayer.replaceChildren();
  }

  setBox(box) {
    this.box = box;
    this.svg.setAttribute('viewBox', box.join(' '));
    this.redraw();
  }

  /** Draws the canvas again at the next animation frame (once, however often it is asked). */
  redraw() {
    if (this.pending) return;
    this.pending = requestAnimationFrame(() => {
      this.pending = 0;
      this.draw();
    });
  }

  /**
   * Draws the lines on the canvas now, in the overlay's current view: the canvas's pixels
   * follow its CSS size times the device pixel ratio, and one path per assignment is stroked
   * with the pattern-to-canvas transform, widths and dashes divided by the zoom so that they
   * keep their screen size (dashed only as DASH_FROM_PIXELS says).
   */
  draw() {
    const canvas = this.canvas, ctx = this.ctx;
    const r = canvas.getBoundingClientRect();
    const dpr = window.devicePixelRatio || 1;
    const w = Math.round(r.width * dpr), h = Math.round(r.height * dpr);
    if (canvas.width !== w || canvas.height !== h) {
      canvas.width = w;
      canvas.height = h;
    }
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    ctx.clearRect(0, 0, w, h);
    const m = this.root && this.root.getScreenCTM();
    if (!this.paths || !m || !w || !h) return;
    ctx.setTransform(dpr * m.a, dpr * m.b, dpr * m.c, dpr * m.d, dpr * (m.e - r.left), dpr * (m.f - r.top));
    const scale = Math.hypot(m.a, m.b);
    const dashed = this.medianLength * scale >= DASH_FROM_PIXELS;
    for (const letter of ORDER) {
      const path = this.paths[letter];
      if (!path) continue;
      const s = this.styles[letter];
      ctx.strokeStyle = s.colour;
      ctx.lineWidth = (s.width * BASE_WIDTH) / scale;
      ctx.setLineDash(dashed && s.dash ? s.dash.map((d) => (d * BASE_WIDTH) / scale) : []);
      ctx.stroke(path);
    }
    if (canvas.dataset.dashed !== String(dashed)) canvas.dataset.dashed = String(dashed);
    this.frames += 1;
  }

  /** Draws `pattern` (the API's pattern view) with the `legend` styles (the last ones when
   * null); `keep` keeps the zoom (after an edit). The canvas's `data-lines-X` attributes
   * count the lines drawn of each assignment X (`data-lines-m` the mountains), `data-lines`
   * all of them. */
  show(pattern, legend, keep = false) {
    this.pattern = pattern;
    if (legend) this.styles = Object.fromEntries(legend.assignments.map((a) => [a.letter, a]));
    this.svg.replaceChildren();
    this.hovered = null;
    this.selected = null;
    let lo = [Infinity, Infinity], hi = [-Infinity, -Infinity];
    for (const p of pattern.vertices) {
      lo = [Math.min(lo[0], p[0]), Math.min(lo[1], p[1])];
      hi = [Math.max(hi[0], p[0]), Math.max(hi[1], p[1])];
    }
    if (!pattern.vertices.length) { lo = [0, 0]; hi = [1, 1]; }
    this.diagonal = Math.hypot(hi[0] - lo[0], hi[1] - lo[1]) || 1;
    const pad = 0.05 * this.diagonal;
    this.home = [lo[0] - pad, -hi[1] - pad, hi[0] - lo[0] + 2 * pad, hi[1] - lo[1] + 2 * pad];
    // y up: flip once, so pattern coordinates go in as they are.
    const root = el('g', { transform: 'scale(1,-1)' }, this.svg);
    this.root = root;
    this.selectionLayer = el('g', { id: 'cp-selection' }, root);
    this.hoverLayer = el('g', { id: 'cp-hover' }, root);
    this.rings = el('g', { id: 'cp-rings' }, root);
    this.previewLayer = el('g', { id: 'cp-preview' }, root);
    // The lines: their ends for the grid, one path per assignment for the canvas.
    const n = pattern.edges.length;
    const coords = new Float64Array(4 * n);
    const lengths = new Float64Array(n);
    const paths = {};
    const counts = Object.fromEntries(ORDER.map((a) => [a, 0]));
    pattern.edges.forEach((e, i) => {
      const [p, q] = [pattern.vertices[e.v[0]], pattern.vertices[e.v[1]]];
      coords.set([p[0], p[1], q[0], q[1]], 4 * i);
      lengths[i] = Math.hypot(q[0] - p[0], q[1] - p[1]);
      const path = paths[e.a] || (paths[e.a] = new Path2D());
      path.moveTo(p[0], p[1]);
      path.lineTo(q[0], q[1]);
      counts[e.a] = (counts[e.a] || 0) + 1;
    });
    lengths.sort();
    this.medianLength = n ? lengths[n >> 1] : 0;
    this.paths = paths;
    this.grid = new SegmentGrid(coords);
    for (const [a, count] of Object.entries(counts)) this.canvas.dataset[`lines${a}`] = String(count);
    this.canvas.dataset.lines = String(n);
    this.leave();
    if (!keep) this.setBox(this.home);
    else this.redraw();
  }

  /** A line drawn on the overlay along edge `i`, in `layer` with `cls`. */
  mark(layer, i, cls) {
    layer.replaceChildren();
    if (i == null) return;
    const e = this.pattern.edges[i];
    const [p, q] = [this.pattern.vertices[e.v[0]], this.pattern.vertices[e.v[1]]];
    el('line', { x1: p[0], y1: p[1], x2: q[0], y2: q[1], class: cls, 'data-edge': i,
      'vector-effect': 'non-scaling-stroke' }, layer);
  }

  /** The pointer left the lines: the label names the selected line, or none. */
  leave() {
    this.hovered = null;
    if (this.hoverLayer) this.hoverLayer.replaceChildren();
    delete this.svg.dataset.hovered;
    if (this.selected != null) {
      this.describe(this.selected);
      return;
    }
    this.info.textContent = 'Hover over a line to see it.';
    this.info.classList.add('muted');
  }

  /** Edge `i` is under the pointer: marked, and named in the label. */
  hover(i) {
    this.hovered = i;
    this.svg.dataset.hovered = String(i);
    this.mark(this.hoverLayer, i, 'hover-line');
    this.describe(i);
  }

  /** Selects edge `i` (a click on it with the pan tool), or nothing when null: marked, and
   * named when no other line is hovered, until the next pattern. */
  select(i) {
    this.selected = i;
    if (i == null) delete this.svg.dataset.selected;
    else this.svg.dataset.selected = String(i);
    this.mark(this.selectionLayer, i, 'selected-line');
  }

  /** Shows edge `i`'s assignment, fold angle and length in the label. */
  describe(i) {
    const pt = this.pattern, e = pt.edges[i];
    const [p, q] = [pt.vertices[e.v[0]], pt.vertices[e.v[1]]];
    const names = { M: 'mountain', V: 'valley', B: 'boundary', F: 'flat', U: 'unassigned', C: 'cut', J: 'join' };
    const angle = e.angle == null ? 'no fold angle' : `fold angle ${e.angle.toFixed(1)}°`;
    const length = Math.hypot(q[0] - p[0], q[1] - p[1]);
    this.info.textContent = `edge ${i}: ${names[e.a]} (${e.a}), ${angle}, length ${length.toFixed(2)} ${pt.units}`;
    this.info.classList.remove('muted');
  }

  /** Rings every finding (at its position); `selected` gets a thicker ring. */
  ring(findings, colour, selected = -1) {
    this.rings.replaceChildren();
    const r = 0.025 * this.diagonal;
    findings.forEach((f, k) => {
      el('circle', { cx: f.position.x ?? f.position[0], cy: f.position.y ?? f.position[1], r,
        fill: 'none', stroke: colour, 'stroke-width': k === selected ? 5 : 2.5,
        'vector-effect': 'non-scaling-stroke', class: 'finding-ring' }, this.rings);
    });
  }

  /** Rings the edges `ids` (a plan warning's), each drawn over in `colour` with a circle at
   * its middle, and zooms to show them all. */
  ringEdges(ids, colour) {
    this.rings.replaceChildren();
    const r = 0.02 * this.diagonal;
    let lo = [Infinity, Infinity], hi = [-Infinity, -Infinity];
    for (const i of ids) {
      const e = this.pattern.edges[i];
      if (!e) continue;
      const [p, q] = [this.pattern.vertices[e.v[0]], this.pattern.vertices[e.v[1]]];
      el('line', { x1: p[0], y1: p[1], x2: q[0], y2: q[1], stroke: colour, 'stroke-width': 4,
        'vector-effect': 'non-scaling-stroke', class: 'warning-edge', 'data-edge': i }, this.rings);
      el('circle', { cx: (p[0] + q[0]) / 2, cy: (p[1] + q[1]) / 2, r, fill: 'none', stroke: colour,
        'stroke-width': 2.5, 'vector-effect': 'non-scaling-stroke', class: 'finding-ring' }, this.rings);
      for (const v of [p, q]) {
        lo = [Math.min(lo[0], v[0]), Math.min(lo[1], v[1])];
        hi = [Math.max(hi[0], v[0]), Math.max(hi[1], v[1])];
      }
    }
    if (lo[0] === Infinity) return;
    const w = Math.max(hi[0] - lo[0], hi[1] - lo[1], 0.1 * this.diagonal) * 1.3;
    this.setBox([(lo[0] + hi[0]) / 2 - w / 2, -(lo[1] + hi[1]) / 2 - w / 2, w, w]);
  }

  /** Zooms to a point of the pattern (x, y up). */
  zoomTo(x, y) {
    const w = 0.2 * this.diagonal;
    this.setBox([x - w / 2, -y - w / 2, w, w]);
  }
}
