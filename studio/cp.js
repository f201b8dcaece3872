// The crease-pattern view: an SVG in pattern coordinates (y up), pan by drag, zoom by wheel,
// hover to read an edge, findings ringed; previews of edits (see edit.js).

const NS = 'http://www.w3.org/2000/svg';
/** Screen width of the base line, pixels (legend widths and dashes are multiples of it). */
const BASE_WIDTH = 1.5;
/** Drawing order: faint lines first, outlines and cuts on top (as in our previews). */
const ORDER = ['F', 'J', 'U', 'V', 'M', 'B', 'C'];

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
  constructor(svg, info) {
    this.svg = svg;
    this.info = info;
    this.box = [0, 0, 1, 1];
    this.canPan = () => true;
    this.onEdgeClick = () => {};
    panZoom(svg, () => this.box, (b) => this.setBox(b), () => this.canPan());
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
  }

  /** Draws `pattern` (the API's pattern view) with the `legend` styles (the last ones when
   * null); `keep` keeps the zoom (after an edit). */
  show(pattern, legend, keep = false) {
    this.pattern = pattern;
    if (legend) this.styles = Object.fromEntries(legend.assignments.map((a) => [a.letter, a]));
    const styles = this.styles;
    this.svg.replaceChildren();
    this.leave();
    const xs = pattern.vertices.map((p) => p[0]), ys = pattern.vertices.map((p) => p[1]);
    const lo = [Math.min(...xs), Math.min(...ys)], hi = [Math.max(...xs), Math.max(...ys)];
    this.diagonal = Math.hypot(hi[0] - lo[0], hi[1] - lo[1]) || 1;
    const pad = 0.05 * this.diagonal;
    this.home = [lo[0] - pad, -hi[1] - pad, hi[0] - lo[0] + 2 * pad, hi[1] - lo[1] + 2 * pad];
    if (!keep) this.setBox(this.home);
    // y up: flip once, so pattern coordinates go in as they are.
    const root = el('g', { transform: 'scale(1,-1)' }, this.svg);
    this.root = root;
    const lines = el('g', { id: 'cp-lines' }, root);
    const hits = el('g', { id: 'cp-hits' }, root);
    this.rings = el('g', { id: 'cp-rings' }, root);
    this.previewLayer = el('g', { id: 'cp-preview' }, root);
    const order = pattern.edges.map((e, i) => i)
      .sort((a, b) => ORDER.indexOf(pattern.edges[a].a) - ORDER.indexOf(pattern.edges[b].a));
    for (const i of order) {
      const e = pattern.edges[i];
      const [p, q] = [pattern.vertices[e.v[0]], pattern.vertices[e.v[1]]];
      const s = styles[e.a];
      const at = { x1: p[0], y1: p[1], x2: q[0], y2: q[1] };
      el('line', {
        ...at, stroke: s.colour, 'stroke-width': s.width * BASE_WIDTH,
        'stroke-dasharray': s.dash ? s.dash.map((d) => d * BASE_WIDTH).join(' ') : 'none',
        'vector-effect': 'non-scaling-stroke', 'data-edge': i, class: `edge edge-${e.a}`,
      }, lines);
      const hit = el('line', { ...at, stroke: 'transparent', 'stroke-width': 9,
        'vector-effect': 'non-scaling-stroke', 'data-edge': i }, hits);
      hit.addEventListener('mouseenter', () => this.hover(i));
      hit.addEventListener('mouseleave', () => this.leave(i));
      hit.addEventListener('click', () => this.onEdgeClick(i));
    }
  }

  /** The pointer left edge `i` (or any edge when undefined): the label no longer names it. */
  leave(i) {
    if (i !== undefined && this.hovered !== i) return;
    this.hovered = null;
    this.info.textContent = 'Hover over a line to see it.';
    this.info.classList.add('muted');
  }

  /** Shows edge `i`'s assignment, fold angle and length. */
  hover(i) {
    const pt = this.pattern, e = pt.edges[i];
    this.hovered = i;
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

  /** Zooms to a point of the pattern (x, y up). */
  zoomTo(x, y) {
    const w = 0.2 * this.diagonal;
    this.setBox([x - w / 2, -y - w / 2, w, w]);
  }
}
