// The fold-sequence designer (Miyazaki, Yasuda, Yokoi & Toriwaki 1992): the folded sheet seen
// from above, layers drawn slightly apart; drag a corner (or a point of an edge) and the fold
// line follows as the perpendicular bisector of the move, with the paper's snapping (done on
// the server, which holds the simulator); letting go makes the step. Back and forward step
// through the states; the steps save as a fold script for `foldcam fold`.
import { call } from './api.js';
import { panZoom } from './cp.js';

const NS = 'http://www.w3.org/2000/svg';
/** Pick reach around the pointer, screen pixels. */
const PICK_PIXELS = 12;
/** Screen pixels between two drawn layers. */
const LAYER_PIXELS = 2.5;
/** Paper colours: the front (the sheet's +z side when flat) and the back, as in the 3D view. */
const FRONT = '#f4efe6';
const BACK = '#6a8fd8';

function el(name, attrs = {}, parent = null) {
  const node = document.createElementNS(NS, name);
  for (const [k, v] of Object.entries(attrs)) node.setAttribute(k, v);
  if (parent) parent.appendChild(node);
  return node;
}

const post = (url, body) => call(url, {
  method: 'POST',
  headers: { 'content-type': 'application/json' },
  body: JSON.stringify(body),
});

export class FoldingView {
  /**
   * `root` is the fold section; `onPattern(view)` receives the studio document made from the
   * crease pattern; `guarded(action)` runs an action showing its error in the page.
   */
  constructor(root, onPattern, guarded) {
    this.root = root;
    this.onPattern = onPattern;
    this.guarded = guarded;
    const $ = (id) => root.querySelector(`#${id}`);
    this.svg = $('folding-svg');
    this.cp = $('folding-cp');
    this.info = $('folding-info');
    this.stepList = $('folding-steps');
    this.angle = $('folding-angle');
    this.behind = $('folding-behind');
    this.backButton = $('folding-back');
    this.forwardButton = $('folding-forward');
    this.scriptLink = $('folding-script');
    this.operation = 'bend';
    this.ops = [...root.querySelectorAll('button[data-op]')];
    for (const b of this.ops) b.addEventListener('click', () => this.setOperation(b.dataset.op));
    $('folding-new').addEventListener('click', () => guarded(() => this.newSheet()));
    $('folding-file').addEventListener('change', (e) => {
      const file = e.target.files[0];
      if (file) guarded(() => this.openScript(file));
      e.target.value = '';
    });
    this.backButton.addEventListener('click', () => guarded(() => this.move('back')));
    this.forwardButton.addEventListener('click', () => guarded(() => this.move('forward')));
    $('folding-pattern').addEventListener('click', () => guarded(async () => {
      if (!this.view) return;
      await this.onPattern(await call(`/api/fold/${this.view.id}/pattern`, { method: 'POST' }));
    }));
    this.box = [0, 0, 1, 1];
    panZoom(this.svg, () => this.box, (b) => this.setBox(b), () => !this.drag);
    // Capture: decide before the pan handler whether this press starts a fold.
    this.svg.addEventListener('pointerdown', (e) => this.down(e), true);
    this.svg.addEventListener('pointermove', (e) => this.pointerMove(e));
    this.svg.addEventListener('pointerup', (e) => this.up(e));
    document.querySelector("#tabs button[data-view='folding']")
      ?.addEventListener('click', () => guarded(() => this.enter()));
  }

  /** The mode is shown: start on a square the first time. */
  async enter() {
    if (!this.legend) this.legend = await call('/api/legend');
    if (!this.view) await this.newSheet();
    else this.draw();
  }

  setOperation(op) {
    this.operation = op;
    for (const b of this.ops) b.classList.toggle('active', b.dataset.op === op);
  }

  async newSheet() {
    const side = Number(this.root.querySelector('#folding-size').value);
    this.show(await post('/api/fold/new', { sheet: { square: side } }), true);
  }

  async openScript(file) {
    this.show(await call(`/api/fold/script?name=${encodeURIComponent(file.name)}`,
      { method: 'POST', body: file }), true);
  }

  async move(which) {
    if (!this.view) return;
    this.show(await call(`/api/fold/${this.view.id}/${which}`, { method: 'POST' }));
  }

  /** Shows a session view from the server; `home` frames the sheet. */
  show(view, home = false) {
    this.view = view;
    this.preview = null;
    if (home || !this.home) this.frame(view);
    this.backButton.disabled = view.step === 0;
    this.forwardButton.disabled = view.step >= view.last;
    this.scriptLink.href = `/api/fold/${view.id}/script`;
    this.stepList.replaceChildren(...view.steps.map((s) => {
      const li = document.createElement('li');
      li.textContent = s.name ? `${s.name}: ${s.summary}` : s.summary;
      li.classList.toggle('undone', s.undone);
      return li;
    }));
    this.info.textContent = view.warnings.length ? view.warnings.join('; ')
      : 'Drag a corner: the fold line is the perpendicular bisector of the move.';
    this.draw();
    this.drawPattern();
    document.body.dataset.foldSession = String(view.id);
    document.body.dataset.foldStep = String(view.step);
  }

  /** Frames the sheet (as large as the sheet can get when folded anywhere). */
  frame(view) {
    const xs = view.sheet.map((p) => p[0]), ys = view.sheet.map((p) => p[1]);
    const lo = [Math.min(...xs), Math.min(...ys)], hi = [Math.max(...xs), Math.max(...ys)];
    const size = Math.max(hi[0] - lo[0], hi[1] - lo[1]);
    const c = [(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2];
    this.home = [c[0] - 0.8 * size, -c[1] - 0.8 * size, 1.6 * size, 1.6 * size];
    this.setBox(this.home);
  }

  setBox(box) {
    this.box = box;
    this.svg.setAttribute('viewBox', box.join(' '));
  }

  /** Sheet coordinates (millimetres, y up) of a pointer event. */
  toSheet(e) {
    const p = this.svg.createSVGPoint();
    p.x = e.clientX;
    p.y = e.clientY;
    const q = p.matrixTransform(this.layer.getScreenCTM().inverse());
    return [q.x, q.y];
  }

  mmPerPixel() {
    const m = this.layer.getScreenCTM();
    return m ? 1 / Math.hypot(m.a, m.b) : 1;
  }

  /** Draws the faces (the preview's when there is one), the fold line and the moved vertex. */
  draw() {
    if (!this.view) return;
    this.svg.replaceChildren();
    this.layer = el('g', { transform: 'scale(1,-1)' }, this.svg);
    const shift = LAYER_PIXELS * this.mmPerPixel();
    const faces = (this.preview && this.preview.faces) || this.view.faces;
    const group = el('g', { id: 'folding-faces', class: this.preview ? 'previewing' : '' }, this.layer);
    for (const f of faces) {
      const d = f.layer * shift;
      const points = f.corners.map((c) => `${c[0] - d},${c[1] + d}`).join(' ');
      el('polygon', { points, fill: f.front ? FRONT : BACK, stroke: '#444', 'stroke-width': 1,
        'stroke-linejoin': 'round', 'vector-effect': 'non-scaling-stroke',
        class: f.front ? 'face front' : 'face back' }, group);
    }
    const p = this.preview;
    if (!p) return;
    const [a, b] = p.line;
    const dir = [b[0] - a[0], b[1] - a[1]];
    const len = Math.hypot(dir[0], dir[1]) || 1;
    const far = 4 * Math.max(this.box[2], this.box[3]) / len;
    el('line', { x1: a[0] - dir[0] * far, y1: a[1] - dir[1] * far, x2: a[0] + dir[0] * far,
      y2: a[1] + dir[1] * far, class: p.refused ? 'fold-line refused' : 'fold-line',
      'vector-effect': 'non-scaling-stroke' }, this.layer);
    const [from, to] = p.vertex;
    el('line', { x1: from[0], y1: from[1], x2: to[0], y2: to[1], class: 'fold-move',
      'vector-effect': 'non-scaling-stroke' }, this.layer);
    el('circle', { cx: to[0], cy: to[1], r: 5 * this.mmPerPixel(), class: 'snap-marker',
      'vector-effect': 'non-scaling-stroke' }, this.layer);
  }

  /** The shown step's crease pattern, in the legend's colours. */
  drawPattern() {
    const pt = this.view.pattern;
    this.cp.replaceChildren();
    const xs = pt.vertices.map((p) => p[0]), ys = pt.vertices.map((p) => p[1]);
    const lo = [Math.min(...xs), Math.min(...ys)], hi = [Math.max(...xs), Math.max(...ys)];
    const pad = 0.04 * Math.max(hi[0] - lo[0], hi[1] - lo[1]);
    this.cp.setAttribute('viewBox', [lo[0] - pad, -hi[1] - pad, hi[0] - lo[0] + 2 * pad,
      hi[1] - lo[1] + 2 * pad].join(' '));
    const g = el('g', { transform: 'scale(1,-1)' }, this.cp);
    const styles = Object.fromEntries((this.legend?.assignments ?? []).map((a) => [a.letter, a]));
    for (const [[i, j], a] of pt.edges) {
      const [p, q] = [pt.vertices[i], pt.vertices[j]];
      const s = styles[a] ?? { colour: '#000', width: 1, dash: null };
      el('line', { x1: p[0], y1: p[1], x2: q[0], y2: q[1], stroke: s.colour,
        'stroke-width': s.width * 1.5, 'stroke-dasharray': s.dash ? s.dash.map((d) => d * 1.5).join(' ') : 'none',
        'vector-effect': 'non-scaling-stroke', class: `edge edge-${a}` }, g);
    }
  }

  /** The drag request from the press at `from` to the pointer at `to`. */
  request(from, to) {
    return {
      from,
      to,
      pick: PICK_PIXELS * this.mmPerPixel(),
      operation: this.operation,
      angle: Number(this.angle.value),
      behind: this.behind.value === 'mountain',
    };
  }

  /** Starts a fold when the press is near a corner or an edge of the sheet seen from above
   * (the server picks the corner first, else the point of the edge). */
  down(e) {
    if (!this.view || e.button !== 0) return;
    const p = this.toSheet(e);
    const reach = PICK_PIXELS * this.mmPerPixel();
    const toSegment = (a, b) => {
      const d = [b[0] - a[0], b[1] - a[1]];
      const len2 = d[0] * d[0] + d[1] * d[1];
      const t = len2 > 0 ? Math.min(1, Math.max(0, ((p[0] - a[0]) * d[0] + (p[1] - a[1]) * d[1]) / len2)) : 0;
      return Math.hypot(a[0] + d[0] * t - p[0], a[1] + d[1] * t - p[1]);
    };
    const near = this.view.faces.some((f) => f.corners.some((c, i) =>
      toSegment(c, f.corners[(i + 1) % f.corners.length]) <= reach));
    if (!near) return;
    this.drag = { from: p, moved: false };
    this.svg.setPointerCapture(e.pointerId);
  }

  pointerMove(e) {
    if (!this.drag) return;
    this.drag.moved = true;
    this.track(this.toSheet(e));
  }

  /** Previews the latest pointer position, one request at a time. */
  async track(p) {
    this.pending = p;
    if (this.previewing) return;
    this.previewing = true;
    try {
      while (this.pending && this.drag) {
        const q = this.pending;
        this.pending = null;
        try {
          const preview = await post(`/api/fold/${this.view.id}/preview`, this.request(this.drag.from, q));
          if (!this.drag) break;
          this.preview = preview;
          const snapped = this.preview.snapped.length ? ` (snapped: ${this.preview.snapped.join(', ')})` : '';
          this.info.textContent = this.preview.refused
            ? `Cannot fold: ${this.preview.refused}`
            : `Fold by ${Math.abs(this.preview.angle).toFixed(1)}°${snapped}`;
        } catch (err) {
          if (!this.drag) break;
          this.preview = null;
          this.info.textContent = err.message;
        }
        if (this.drag) this.draw();
      }
    } finally {
      this.previewing = false;
    }
  }

  async up(e) {
    const drag = this.drag;
    if (!drag) return;
    this.drag = null;
    this.pending = null;
    this.preview = null;
    if (!drag.moved) { this.draw(); return; }
    const body = this.request(drag.from, this.toSheet(e));
    await this.guarded(async () => {
      try {
        this.show(await post(`/api/fold/${this.view.id}/drag`, body));
      } catch (err) {
        this.draw();
        throw err;
      }
    });
  }
}
