// The polygon pop-up editor (Mitani & Suzuki 2004): the card's side section (depth y to the
// right, height z up; the back sheet is the line y = 0, the base the line z = 0). Each face or
// opening is a segment there: drag to add one, drag a segment to move it, drag an end to
// resize it; its extent along the fold is edited in the fields. The server replays the
// design after every edit (the paper's operations on the pattern) and checks it as
// `foldcam popup poly` does; the faces that do not stand up are drawn red and said in words.
// The card is shown opening from 0° to 180° (Mitani & Suzuki 2004, eq. 7, computed on the server).
import * as THREE from './vendor/three.module.min.js';
import { makeScene, onDrag } from './scene3d.js';
import { call } from './api.js';

const NS = 'http://www.w3.org/2000/svg';
/** Pick reach around the pointer, screen pixels. */
const PICK_PIXELS = 8;
/** Paper colours as in the Folded view: the front (the pattern as drawn) and the back. */
const FRONT = 0xf4efe6;
const BACK = 0x6a8fd8;

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

/** The segment of an operation in the side section: [[y, z], [y, z]]. */
function segment(op) {
  return op.plane === 'vertical'
    ? [[op.at, op.lo[1]], [op.at, op.hi[1]]]
    : [[op.lo[1], op.at], [op.hi[1], op.at]];
}

function distanceToSegment(p, [a, b]) {
  const d = [b[0] - a[0], b[1] - a[1]];
  const len2 = d[0] * d[0] + d[1] * d[1];
  const t = len2 > 0 ? Math.min(1, Math.max(0, ((p[0] - a[0]) * d[0] + (p[1] - a[1]) * d[1]) / len2)) : 0;
  return Math.hypot(a[0] + d[0] * t - p[0], a[1] + d[1] * t - p[1]);
}

export class PopupView {
  /**
   * `root` is the pop-up section; `onPattern(view)` receives the studio document made from
   * the saved design; `guarded(action)` runs an action showing its error in the page.
   */
  constructor(root, onPattern, guarded) {
    this.root = root;
    this.onPattern = onPattern;
    this.guarded = guarded;
    const $ = (id) => root.querySelector(`#${id}`);
    this.$ = $;
    this.svg = $('popup-side');
    this.cp = $('popup-cp');
    this.status = $('popup-status');
    this.findingList = $('popup-findings');
    this.info = $('popup-info');
    this.angle = $('popup-angle');
    this.angleLabel = $('popup-angle-label');
    this.saveLink = $('popup-save');
    this.tool = 'select';
    this.tools = [...root.querySelectorAll('button[data-popup-tool]')];
    for (const b of this.tools) b.addEventListener('click', () => this.setTool(b.dataset.popupTool));
    $('popup-new').addEventListener('click', () => guarded(() => this.newCard()));
    $('popup-file').addEventListener('change', (e) => {
      const file = e.target.files[0];
      if (file) guarded(() => this.openDesign(file));
      e.target.value = '';
    });
    $('popup-undo').addEventListener('click', () => guarded(() => this.step('undo')));
    $('popup-redo').addEventListener('click', () => guarded(() => this.step('redo')));
    $('popup-remove').addEventListener('click', () => guarded(() => this.removeSelected()));
    $('popup-apply-x').addEventListener('click', () => guarded(() => this.applyX()));
    $('popup-pattern').addEventListener('click', () => guarded(async () => {
      if (!this.view) return;
      await this.onPattern(await call(`/api/popup/${this.view.id}/pattern`, { method: 'POST' }));
    }));
    this.angle.addEventListener('input', () => this.loadCard());
    this.svg.addEventListener('pointerdown', (e) => this.down(e));
    this.svg.addEventListener('pointermove', (e) => this.pointerMove(e));
    this.svg.addEventListener('pointerup', (e) => guarded(() => this.up(e)));
    this.setupThree($('popup-3d'));
    document.querySelector("#tabs button[data-view='popup']")
      ?.addEventListener('click', () => guarded(() => this.enter()));
  }

  /** The tab is shown: start on a blank card the first time. */
  async enter() {
    if (!this.legend) this.legend = await call('/api/legend');
    if (!this.view) await this.newCard();
    else { this.draw(); this.drawThree(); }
  }

  setTool(tool) {
    this.tool = tool;
    for (const b of this.tools) b.classList.toggle('active', b.dataset.popupTool === tool);
    this.svg.dataset.tool = tool;
  }

  async newCard() {
    const n = (id) => Number(this.$(id).value);
    this.show(await post('/api/popup/new',
      { width: n('popup-width'), depth: n('popup-depth'), height: n('popup-height') }));
  }

  async openDesign(file) {
    this.show(await call(`/api/popup/design?name=${encodeURIComponent(file.name)}`,
      { method: 'POST', body: file }));
  }

  async step(which) {
    if (!this.view) return;
    this.show(await call(`/api/popup/${this.view.id}/${which}`, { method: 'POST' }));
  }

  async edit(body) {
    try {
      this.show(await post(`/api/popup/${this.view.id}/edit`, body));
    } catch (err) {
      this.draw();
      throw err;
    }
  }

  async removeSelected() {
    if (!this.view || !this.selected) return;
    const operation = this.selected;
    this.selected = null;
    await this.edit({ remove: { operation } });
  }

  /** The extent along the fold typed in the fields, for new faces and the selected one. */
  xRange() {
    const a = Number(this.$('popup-x0').value), b = Number(this.$('popup-x1').value);
    return [Math.min(a, b), Math.max(a, b)];
  }

  async applyX() {
    const op = this.view?.operations.find((o) => o.number === this.selected);
    if (!op) throw new Error('select a face first (click its line in the side section)');
    const [x0, x1] = this.xRange();
    await this.edit({ resize: { operation: op.number, lo: [x0, op.lo[1]], hi: [x1, op.hi[1]] } });
  }

  /** Shows a session view from the server. */
  show(view) {
    const first = !this.view || this.view.id !== view.id;
    this.view = view;
    if (first) {
      this.selected = null;
      this.frame();
      const [w] = view.card;
      this.$('popup-x0').value = +(w / 3).toFixed(1);
      this.$('popup-x1').value = +(2 * w / 3).toFixed(1);
    }
    if (!view.operations.some((o) => o.number === this.selected)) this.selected = null;
    this.$('popup-undo').disabled = !view.history.undo;
    this.$('popup-redo').disabled = !view.history.redo;
    this.saveLink.href = `/api/popup/${view.id}/design`;
    this.saveLink.setAttribute('download', view.name);
    this.status.textContent = view.valid ? 'pops up' : 'does not pop up';
    this.status.className = view.valid ? 'passed' : 'failed';
    const lines = view.findings.length ? view.findings.map((f) => f.words) : view.lines;
    this.findingList.replaceChildren(...lines.map((line, i) => {
      const li = document.createElement('li');
      li.textContent = line;
      const f = view.findings[i];
      if (f && f.operation) {
        li.classList.add('finding');
        li.addEventListener('click', () => { this.selected = f.operation; this.draw(); });
      }
      return li;
    }));
    this.draw();
    this.drawPattern();
    this.loadCard();
    const body = document.body.dataset;
    body.popupSession = String(view.id);
    body.popupOperations = String(view.operations.length);
    body.popupValid = String(view.valid);
  }

  /** Frames the side section: the base to the right, the back sheet up. */
  frame() {
    const [, depth, height] = this.view.card;
    const pad = 0.08 * Math.max(depth, height);
    this.svg.setAttribute('viewBox', [-pad, -height - pad, depth + 2 * pad, height + 2 * pad].join(' '));
  }

  /** Side-section coordinates (millimetres, z up) of a pointer event. */
  toSide(e) {
    const p = this.svg.createSVGPoint();
    p.x = e.clientX;
    p.y = e.clientY;
    const q = p.matrixTransform(this.layer.getScreenCTM().inverse());
    return [q.x, q.y];
  }

  mmPerPixel() {
    const m = this.layer?.getScreenCTM();
    return m ? 1 / Math.hypot(m.a, m.b) : 1;
  }

  /** Snaps a side point to the grid chosen, and to the card. */
  snap(p) {
    const step = Number(this.$('popup-snap').value);
    const [, depth, height] = this.view.card;
    const q = step > 0 ? p.map((v) => Math.round(v / step) * step) : p.slice();
    return [Math.min(depth, Math.max(0, q[0])), Math.min(height, Math.max(0, q[1]))];
  }

  /** Draws the side section: the sheets, every operation, the one being dragged. */
  draw() {
    if (!this.view) return;
    const [, depth, height] = this.view.card;
    this.svg.replaceChildren();
    this.layer = el('g', { transform: 'scale(1,-1)' }, this.svg);
    const step = Number(this.$('popup-snap').value);
    if (step > 0) {
      const grid = el('g', { class: 'popup-grid' }, this.layer);
      const hair = { 'vector-effect': 'non-scaling-stroke' };
      for (let y = 0; y <= depth + 1e-9; y += step) el('line', { x1: y, y1: 0, x2: y, y2: height, ...hair }, grid);
      for (let z = 0; z <= height + 1e-9; z += step) el('line', { x1: 0, y1: z, x2: depth, y2: z, ...hair }, grid);
    }
    const sheet = { class: 'popup-sheet', 'vector-effect': 'non-scaling-stroke' };
    el('line', { x1: 0, y1: 0, x2: 0, y2: height, ...sheet }, this.layer);
    el('line', { x1: 0, y1: 0, x2: depth, y2: 0, ...sheet }, this.layer);
    // Names of the two sheets, upright (outside the flipped layer).
    const size = 12 * this.mmPerPixel();
    el('text', { x: size * 0.4, y: -height + size, 'font-size': size, class: 'popup-label' }, this.svg)
      .textContent = `back sheet (y = 0), ${height} mm`;
    el('text', { x: depth, y: size * 1.3, 'font-size': size, 'text-anchor': 'end', class: 'popup-label' }, this.svg)
      .textContent = `base (z = 0), ${depth} mm`;
    const failing = new Set(this.view.findings.map((f) => f.operation).filter((n) => n));
    const drag = this.drag;
    for (const op of this.view.operations) {
      let [a, b] = segment(op);
      if (drag && drag.moved && drag.op === op.number) [a, b] = drag.segment;
      const cls = ['popup-op', op.plane, op.opening ? 'opening' : 'face'];
      if (failing.has(op.number)) cls.push('failing');
      if (this.selected === op.number) cls.push('selected');
      el('line', { x1: a[0], y1: a[1], x2: b[0], y2: b[1], class: cls.join(' '),
        'data-operation': op.number, 'vector-effect': 'non-scaling-stroke' }, this.layer);
      if (this.selected === op.number) {
        for (const p of [a, b]) {
          el('circle', { cx: p[0], cy: p[1], r: 4 * this.mmPerPixel(), class: 'popup-handle' }, this.layer);
        }
      }
    }
    if (drag && drag.adding && drag.segment) {
      const [a, b] = drag.segment;
      el('line', { x1: a[0], y1: a[1], x2: b[0], y2: b[1], class: `popup-op adding ${this.tool}`,
        'vector-effect': 'non-scaling-stroke' }, this.layer);
    }
    const op = this.view.operations.find((o) => o.number === this.selected);
    this.info.textContent = op
      ? `Operation ${op.number}: ${op.opening ? 'opening in the' : ''} ${op.plane} plane at ` +
        `${op.plane === 'vertical' ? 'y' : 'z'} = ${+op.at.toFixed(2)} mm, x from ` +
        `${+op.lo[0].toFixed(2)} to ${+op.hi[0].toFixed(2)} mm. Drag it to move, drag an end to resize.`
      : 'Choose a tool and drag in the side section to add; click a face to select it.';
  }

  /** The new operation a drag from `a` to `b` adds with the current tool. */
  addition(a, b) {
    const [x0, x1] = this.xRange();
    const vertical = this.tool === 'vertical'
      || (this.tool === 'opening' && Math.abs(b[1] - a[1]) >= Math.abs(b[0] - a[0]));
    if (vertical) {
      const [w0, w1] = [Math.min(a[1], b[1]), Math.max(a[1], b[1])];
      return { segment: [[a[0], w0], [a[0], w1]], op: { plane: 'vertical', at: a[0],
        polygon: [[x0, w0], [x1, w0], [x1, w1], [x0, w1]], add: this.tool === 'opening' ? 'opening' : 'face' } };
    }
    const [w0, w1] = [Math.min(a[0], b[0]), Math.max(a[0], b[0])];
    return { segment: [[w0, a[1]], [w1, a[1]]], op: { plane: 'horizontal', at: a[1],
      polygon: [[x0, w0], [x1, w0], [x1, w1], [x0, w1]], add: this.tool === 'opening' ? 'opening' : 'face' } };
  }

  down(e) {
    if (!this.view || e.button !== 0) return;
    const p = this.toSide(e);
    if (this.tool !== 'select') {
      this.drag = { adding: true, from: this.snap(p), moved: false };
      this.svg.setPointerCapture(e.pointerId);
      return;
    }
    const reach = PICK_PIXELS * this.mmPerPixel();
    // An end of the selected face first (resize), then any face (move).
    const sel = this.view.operations.find((o) => o.number === this.selected);
    if (sel) {
      const ends = segment(sel);
      const end = ends.findIndex((q) => Math.hypot(q[0] - p[0], q[1] - p[1]) <= reach);
      if (end >= 0) {
        this.drag = { op: sel.number, end, from: p, moved: false, segment: ends };
        this.svg.setPointerCapture(e.pointerId);
        return;
      }
    }
    let best = null;
    for (const op of this.view.operations) {
      const d = distanceToSegment(p, segment(op));
      if (d <= reach && (!best || d < best.d)) best = { op, d };
    }
    this.selected = best ? best.op.number : null;
    if (best) {
      this.$('popup-x0').value = +best.op.lo[0].toFixed(2);
      this.$('popup-x1').value = +best.op.hi[0].toFixed(2);
      this.drag = { op: best.op.number, end: -1, from: p, moved: false, segment: segment(best.op) };
      this.svg.setPointerCapture(e.pointerId);
    }
    this.draw();
  }

  pointerMove(e) {
    const drag = this.drag;
    if (!drag) return;
    drag.moved = true;
    const p = this.toSide(e);
    if (drag.adding) {
      drag.segment = this.addition(drag.from, this.snap(p)).segment;
    } else {
      const op = this.view.operations.find((o) => o.number === drag.op);
      drag.segment = this.dragged(op, drag, p).segment;
    }
    this.draw();
  }

  /** Where a move or resize drag of `op` to `p` puts it, and the edit it makes. */
  dragged(op, drag, p) {
    const [a, b] = segment(op);
    const vertical = op.plane === 'vertical';
    if (drag.end < 0) {
      // Move: the segment's first end goes where the grid puts it.
      const start = this.snap([a[0] + p[0] - drag.from[0], a[1] + p[1] - drag.from[1]]);
      const d = [start[0] - a[0], start[1] - a[1]];
      return { segment: [[a[0] + d[0], a[1] + d[1]], [b[0] + d[0], b[1] + d[1]]],
        edit: { move: { operation: op.number, by: [0, d[0], d[1]] } } };
    }
    // Resize: the end dragged follows the pointer along the segment's own line.
    const q = this.snap(p);
    const ends = [a.slice(), b.slice()];
    const k = vertical ? 1 : 0;
    ends[drag.end][k] = q[k];
    const lo = Math.min(ends[0][k], ends[1][k]), hi = Math.max(ends[0][k], ends[1][k]);
    return { segment: ends, edit: { resize: { operation: op.number, lo: [op.lo[0], lo], hi: [op.hi[0], hi] } } };
  }

  async up(e) {
    const drag = this.drag;
    if (!drag) return;
    this.drag = null;
    if (!drag.moved) { this.draw(); return; }
    const p = this.toSide(e);
    if (drag.adding) {
      const { op } = this.addition(drag.from, this.snap(p));
      // A click without extent on the plane adds nothing.
      if (op.polygon[2][1] - op.polygon[0][1] <= 0) { this.draw(); return; }
      await this.edit({ add: op });
      this.selected = this.view.operations.length;
      this.draw();
      return;
    }
    const op = this.view.operations.find((o) => o.number === drag.op);
    await this.edit(this.dragged(op, drag, p).edit);
  }

  /** The card's crease pattern with the failing faces filled. */
  drawPattern() {
    this.cp.replaceChildren();
    const [w, depth, height] = this.view.card;
    const pad = 0.04 * Math.max(w, depth + height);
    this.cp.setAttribute('viewBox', [-pad, -height - pad, w + 2 * pad, depth + height + 2 * pad].join(' '));
    const g = el('g', { transform: 'scale(1,-1)' }, this.cp);
    for (const f of this.view.findings) {
      const d = f.outline.map((ring) => `M${ring.map((p) => p.join(',')).join('L')}Z`).join('');
      el('path', { d, class: 'popup-failing', 'fill-rule': 'evenodd' }, g);
    }
    const pt = this.view.pattern;
    if (!pt) return;
    const styles = Object.fromEntries((this.legend?.assignments ?? []).map((a) => [a.letter, a]));
    for (const [[i, j], a] of pt.edges) {
      const [p, q] = [pt.vertices[i], pt.vertices[j]];
      const s = styles[a] ?? { colour: '#000', width: 1, dash: null };
      el('line', { x1: p[0], y1: p[1], x2: q[0], y2: q[1], stroke: s.colour,
        'stroke-width': s.width * 1.5, 'stroke-dasharray': s.dash ? s.dash.map((d) => d * 1.5).join(' ') : 'none',
        'vector-effect': 'non-scaling-stroke', class: `edge edge-${a}` }, g);
    }
  }

  setupThree(container) {
    this.container = container;
    // Seen from in front of the card and above it (z up), turned a little to one side. The
    // server's card is in the papers' axes (Mitani & Suzuki 2004), base in front at +y, which
    // a viewer in front sees mirrored; reflected through the back sheet's plane (y ↦ −y, as
    // the CLI's pictures are) it is the card in the reader's hands, front towards −y, x from
    // its left edge. three.js keeps the faces' sides right under a negative scale.
    Object.assign(this, makeScene(container, { sun: [-1, -3, 2], zUp: true }));
    this.model.scale.y = -1;
    container.cardView = this;
    onDrag(this.renderer.domElement, (dx, dy) => {
      this.model.rotation.z += dx * 0.01;
      this.model.rotation.x += dy * 0.01;
      this.drawThree();
    });
    new ResizeObserver(() => this.drawThree()).observe(container);
  }

  /** Fetches the card at the slider's angle, one request at a time (the latest wins). */
  async loadCard() {
    if (!this.view) return;
    this.wantAngle = Number(this.angle.value);
    this.angleLabel.textContent = `${this.wantAngle}°`;
    if (this.loading) return;
    this.loading = true;
    try {
      while (this.wantAngle !== null) {
        const angle = this.wantAngle;
        const id = this.view.id;
        this.wantAngle = null;
        try {
          this.showCard(await call(`/api/popup/${id}/card?angle=${angle}`));
          document.body.dataset.popupAngle = String(angle);
        } catch (err) {
          this.model.clear();
          this.drawThree();
          this.angleLabel.textContent = `${angle}°: ${err.message}`;
        }
      }
    } finally {
      this.loading = false;
    }
  }

  /** Builds the card's faces: each triangulated on the pattern, placed in space. */
  showCard(card) {
    this.card = card;
    this.model.clear();
    const positions = [];
    for (const f of card.faces) {
      const contour = f.flat[0].map((p) => new THREE.Vector2(p[0], p[1]));
      const holes = f.flat.slice(1).map((r) => r.map((p) => new THREE.Vector2(p[0], p[1])));
      const points = f.space.flat();
      for (const tri of THREE.ShapeUtils.triangulateShape(contour, holes)) {
        for (const k of tri) positions.push(...points[k]);
      }
    }
    const [w, depth, height] = this.view.card;
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(new Float32Array(positions), 3));
    geometry.translate(-w / 2, -depth / 3, -height / 4);
    geometry.computeVertexNormals();
    // The faces wind counter-clockwise on the pattern, so in space the card's inside (the
    // pattern's drawn side) is their back: drawn in the paper's front colour.
    const inside = new THREE.MeshLambertMaterial({ color: FRONT, side: THREE.BackSide });
    const outside = new THREE.MeshLambertMaterial({ color: BACK, side: THREE.FrontSide });
    const edges = new THREE.LineSegments(new THREE.EdgesGeometry(geometry, 20),
      new THREE.LineBasicMaterial({ color: 0x444444, transparent: true, opacity: 0.5 }));
    this.model.add(new THREE.Mesh(geometry, inside), new THREE.Mesh(geometry, outside), edges);
    const radius = Math.hypot(w, depth, height) / 2 || 1;
    this.camera.position.set(-0.9 * radius, -2.6 * radius, 1.7 * radius);
    this.camera.lookAt(0, 0, 0);
    this.camera.near = radius * 0.01;
    this.camera.far = radius * 20;
    this.drawThree();
  }

  drawThree() {
    const w = this.container.clientWidth, h = this.container.clientHeight;
    if (!w || !h) return;
    this.renderer.setSize(w, h);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
    this.renderer.render(this.scene, this.camera);
  }
}
