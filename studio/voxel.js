// The voxel pop-up editor (Mitani, Suzuki & Uno 2003, §2.7): click cells of the front view
// (one square per row (x, z), shaded by how far it stands out) and of the side view of one
// column (y across, z up) to add and remove voxels — the server adds the cells below and
// behind a new one and removes those above and in front of a deleted one, so the card stays a
// staircase — mark windows and left-out tops, and watch the card open from 0° to 180° (eq. 6,
// computed on the server). Faults (no pop-up, loose pieces, beyond the closed card) are
// listed and marked on both views and on the 3D card.
import * as THREE from './vendor/three.module.min.js';
import { makeScene, onDrag } from './scene3d.js';
import { call } from './api.js';

const NS = 'http://www.w3.org/2000/svg';
/** Screen pixels per grid square at most. */
const MAX_SQUARE = 28;
const PAPER = 0xf4efe6;
const FAULT = 0xd0342c;

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

/** The card in 3D (three.js): triangles from the server at the slider's angle. */
class CardView3d {
  constructor(container) {
    this.container = container;
    // The card reflected through the back sheet's plane (y ↦ −y), as the reader holds it and
    // the CLI's pictures show it: the papers' axes (Mitani, Suzuki & Uno 2003) put the base in
    // front at +y, which a viewer in front sees mirrored. three.js keeps the faces' sides
    // right under a negative scale.
    Object.assign(this, makeScene(container, { sun: [-1, -2, 3], light: [1.3, 1.8], zUp: true }));
    this.model.scale.y = -1;
    container.cardView = this;
    this.turn = [-0.6, 0.45];
    onDrag(this.renderer.domElement, (dx, dy) => {
      this.turn[0] -= dx * 0.01;
      this.turn[1] = Math.max(-1.4, Math.min(1.4, this.turn[1] + dy * 0.01));
      this.draw();
    });
    new ResizeObserver(() => this.draw()).observe(container);
  }

  /** Shows the API's open view; `sheet` is the sheet size (mm) to frame. */
  show(open, sheet, selected) {
    this.model.clear();
    const geometry = new THREE.BufferGeometry();
    geometry.setIndex(open.triangles.flat());
    geometry.setAttribute('position', new THREE.BufferAttribute(new Float32Array(open.positions.flat()), 3));
    geometry.computeVertexNormals();
    const paper = new THREE.MeshLambertMaterial({ color: PAPER, side: THREE.DoubleSide,
      polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1 });
    this.model.add(new THREE.Mesh(geometry, paper));
    this.model.add(new THREE.LineSegments(new THREE.EdgesGeometry(geometry, 1),
      new THREE.LineBasicMaterial({ color: 0x666666 })));
    const quads = open.faults.flatMap((f, k) => (selected === null || selected === k ? f : []));
    if (quads.length) {
      const g = new THREE.BufferGeometry();
      g.setAttribute('position', new THREE.BufferAttribute(new Float32Array(quads.flatMap((q) =>
        [q[0], q[1], q[2], q[0], q[2], q[3]].flat())), 3));
      this.model.add(new THREE.Mesh(g, new THREE.MeshBasicMaterial({ color: FAULT, side: THREE.DoubleSide,
        transparent: true, opacity: 0.85 })));
    }
    this.open = open;
    this.centre = new THREE.Vector3(sheet[0] / 2, -sheet[1] / 4, sheet[1] / 4);
    this.radius = Math.max(sheet[0], sheet[1]) * 0.75;
    this.draw();
  }

  draw() {
    const w = this.container.clientWidth, h = this.container.clientHeight;
    if (!w || !h || !this.radius) return;
    this.renderer.setSize(w, h, false);
    this.camera.aspect = w / h;
    const [az, el] = this.turn;
    const d = this.radius * 3;
    this.camera.position.set(this.centre.x + d * Math.sin(az) * Math.cos(el),
      this.centre.y - d * Math.cos(az) * Math.cos(el), this.centre.z + d * Math.sin(el));
    this.camera.near = this.radius * 0.01;
    this.camera.far = this.radius * 20;
    this.camera.lookAt(this.centre);
    this.camera.updateProjectionMatrix();
    this.renderer.render(this.scene, this.camera);
  }
}

export class VoxelView {
  /**
   * `root` is the editor's section; `onPattern(view)` receives the studio document made from
   * the saved card; `guarded(action)` runs an action showing its error in the page.
   */
  constructor(root, onPattern, guarded) {
    this.root = root;
    this.onPattern = onPattern;
    this.guarded = guarded;
    const $ = (id) => root.querySelector(`#${id}`);
    this.$ = $;
    this.front = $('voxel-front');
    this.side = $('voxel-side');
    this.slider = $('voxel-angle');
    this.angleLabel = $('voxel-angle-label');
    this.faultList = $('voxel-faults');
    this.info = $('voxel-info');
    this.saveLink = $('voxel-save');
    this.tool = 'add';
    this.column = 0;
    this.selected = null;
    this.edits = 0;
    this.tools = [...root.querySelectorAll('button[data-voxel-tool]')];
    for (const b of this.tools) b.addEventListener('click', () => this.setTool(b.dataset.voxelTool));
    $('voxel-new').addEventListener('click', () => guarded(() => this.newCard()));
    $('voxel-file').addEventListener('change', (e) => {
      const file = e.target.files[0];
      e.target.value = '';
      if (file) guarded(() => this.load(file), `reading ${file.name}…`);
    });
    $('voxel-undo').addEventListener('click', () => guarded(() => this.step('undo')));
    $('voxel-redo').addEventListener('click', () => guarded(() => this.step('redo')));
    $('voxel-pattern').addEventListener('click', () => guarded(async () => {
      if (!this.view) return;
      await this.onPattern(await call(`/api/voxel/${this.view.id}/pattern`, { method: 'POST' }));
    }, 'building the crease pattern…'));
    this.slider.addEventListener('input', () => this.openAt(Number(this.slider.value)));
    // Made on first use (WebGL starts only when the editor is shown).
    this.view3d = null;
    document.querySelector("#tabs button[data-view='voxel']")
      ?.addEventListener('click', () => guarded(() => this.enter()));
  }

  /** The editor is shown: start on an empty card the first time. */
  async enter() {
    if (!this.view) await this.newCard();
    else this.view3d?.draw();
  }

  setTool(tool) {
    this.tool = tool;
    for (const b of this.tools) b.classList.toggle('active', b.dataset.voxelTool === tool);
  }

  async newCard() {
    const n = (id) => Number(this.$(id).value);
    await this.show(await post('/api/voxel/new', { nx: n('voxel-nx'), ny: n('voxel-ny'), nz: n('voxel-nz'),
      cell_mm: n('voxel-cell'), margin_mm: n('voxel-margin') }));
  }

  /** Opens a .voxel.txt, or a height map or mesh converted with the Conversion options. */
  async load(file) {
    const n = (id) => Number(this.$(id).value);
    const query = new URLSearchParams({ name: file.name, resolution: n('voxel-resolution'), depth: n('voxel-depth'),
      card_width: n('voxel-width'), card_margin: n('voxel-margin'), morphology: n('voxel-morphology'),
      thin_top: n('voxel-thin'), windows: this.$('voxel-windows').checked });
    await this.show(await call(`/api/voxel/load?${query}`, { method: 'POST', body: file }));
  }

  async step(which) {
    if (!this.view) return;
    await this.show(await call(`/api/voxel/${this.view.id}/${which}`, { method: 'POST' }));
  }

  async edit(body) {
    if (!this.view) return;
    await this.show(await post(`/api/voxel/${this.view.id}/edit`, body));
  }

  /** Shows a card view from the server. */
  async show(view) {
    const fresh = !this.view || this.view.id !== view.id;
    this.view = view;
    if (fresh || this.column >= view.nx) this.column = Math.floor(view.nx / 2);
    this.selected = null;
    for (const [id, v] of [['voxel-nx', view.nx], ['voxel-ny', view.ny], ['voxel-nz', view.nz],
      ['voxel-cell', view.cell_mm], ['voxel-margin', view.margin_mm]]) this.$(id).value = v;
    this.$('voxel-undo').disabled = !view.undo;
    this.$('voxel-redo').disabled = !view.redo;
    this.saveLink.href = `/api/voxel/${view.id}/save`;
    this.$('voxel-status').textContent = view.makes_a_card
      ? (view.faults.length ? 'pops up (with a warning)' : 'pops up') : 'cannot be made';
    this.$('voxel-status').className = view.makes_a_card ? 'pass' : 'fail';
    this.faultList.replaceChildren(...view.faults.map((f, k) => {
      const li = document.createElement('li');
      li.textContent = f.more ? `${f.message} (${f.more} more cells not marked)` : f.message;
      li.className = `fault fault-${f.kind}`;
      li.addEventListener('click', () => this.select(k));
      return li;
    }));
    if (view.change) {
      const [added, removed] = view.change;
      this.info.textContent = added || removed ? `${added} voxel(s) added, ${removed} removed.` : 'Done.';
    } else {
      this.info.textContent = 'Front view: click a row to push it out (Add) or in (Remove). '
        + 'Side view: click a cell of the chosen column.';
    }
    this.drawGrids();
    this.edits += 1;
    document.body.dataset.voxelId = String(view.id);
    document.body.dataset.voxelEdits = String(this.edits);
    await this.openAt(Number(this.slider.value));
  }

  /** Marks fault `k` alone (again: all). */
  select(k) {
    this.selected = this.selected === k ? null : k;
    [...this.faultList.children].forEach((li, i) => li.classList.toggle('selected', i === this.selected));
    this.drawGrids();
    if (this.open && this.view3d) this.view3d.show(this.open, this.view.sheet_mm, this.selected);
  }

  /** The faces of the marked faults. */
  marked() {
    const faults = this.view.faults.filter((_, k) => this.selected === null || this.selected === k);
    return faults.flatMap((f) => f.faces.map((face) => ({ ...face, fault: f.kind })));
  }

  /** Fetches and shows the card opened `angle` degrees; one request at a time, the latest wins. */
  async openAt(angle) {
    this.pendingAngle = angle;
    if (this.opening) return;
    this.opening = true;
    try {
      while (this.pendingAngle !== null) {
        const a = this.pendingAngle;
        this.pendingAngle = null;
        this.open = await call(`/api/voxel/${this.view.id}/open?angle=${a}`);
        if (!this.view3d) this.view3d = new CardView3d(this.$('voxel-3d'));
        this.view3d.show(this.open, this.view.sheet_mm, this.selected);
        this.angleLabel.textContent = `${a.toFixed(0)}° (0° shut, 90° standing, 180° flat)`;
        document.body.dataset.voxelAngle = String(a);
      }
    } catch (e) {
      this.info.textContent = e.message;
    } finally {
      this.opening = false;
    }
  }

  /** Square size (pixels) for a grid of `cols` × `rows` in `svg`. */
  square(svg, cols, rows) {
    const w = svg.clientWidth || 400, h = svg.clientHeight || 300;
    return Math.max(4, Math.min(MAX_SQUARE, (w - 30) / cols, (h - 30) / rows));
  }

  drawGrids() {
    const v = this.view;
    const marked = this.marked();
    // Front view: x across, z up; grey level by depth.
    const s = this.square(this.front, v.nx, v.nz);
    this.front.replaceChildren();
    this.front.setAttribute('viewBox', `-20 -6 ${v.nx * s + 26} ${v.nz * s + 26}`);
    const fg = el('g', {}, this.front);
    for (let x = 0; x < v.nx; x++) {
      for (let z = 0; z < v.nz; z++) {
        const d = v.depth[x][z];
        const shade = Math.round(245 - 150 * d / v.ny);
        const cls = ['cell'];
        if (d) cls.push('filled');
        if (v.window[x][z]) cls.push('window');
        if (v.omitted[x][z]) cls.push('omitted');
        const r = el('rect', { x: x * s, y: (v.nz - 1 - z) * s, width: s, height: s,
          fill: `rgb(${shade},${shade},${Math.min(255, shade + 10)})`, class: cls.join(' '),
          'data-x': x, 'data-z': z }, fg);
        r.addEventListener('click', () => this.guarded(() => this.frontClick(x, z)));
        const t = el('title', {}, r);
        t.textContent = `row x ${x}, z ${z}: ${d} cell(s) deep${v.window[x][z] ? ', window' : ''}` +
          `${v.omitted[x][z] ? ', top left out' : ''}`;
        if (d && s >= 12) {
          const label = el('text', { x: (x + 0.5) * s, y: (v.nz - 0.5 - z) * s, class: 'depth' }, fg);
          label.textContent = v.window[x][z] ? `${d}w` : String(d);
        }
      }
    }
    el('rect', { x: this.column * s, y: 0, width: s, height: v.nz * s, class: 'column' }, fg);
    for (const m of marked.filter((m) => m.kind !== 'base')) {
      el('rect', { x: m.cell[0] * s + 2, y: (v.nz - 1 - m.cell[2]) * s + 2, width: s - 4, height: s - 4,
        class: `mark mark-${m.fault}`, 'data-x': m.cell[0], 'data-z': m.cell[2] }, fg);
    }
    // Side view of the chosen column: y across (back sheet on the left), z up, the base below.
    const x = this.column;
    const t = this.square(this.side, v.ny, v.nz + 1);
    this.side.replaceChildren();
    this.side.setAttribute('viewBox', `-20 -6 ${v.ny * t + 26} ${(v.nz + 1) * t + 26}`);
    const sg = el('g', {}, this.side);
    for (let y = 0; y < v.ny; y++) {
      for (let z = 0; z < v.nz; z++) {
        const filled = y < v.depth[x][z];
        const r = el('rect', { x: y * t, y: (v.nz - 1 - z) * t, width: t, height: t,
          class: filled ? 'cell filled' : 'cell', 'data-y': y, 'data-z': z }, sg);
        r.addEventListener('click', () => this.guarded(() => this.sideClick(x, y, z)));
      }
    }
    el('line', { x1: 0, y1: 0, x2: 0, y2: v.nz * t, class: 'sheet' }, sg);
    el('line', { x1: 0, y1: v.nz * t, x2: v.ny * t, y2: v.nz * t, class: 'sheet' }, sg);
    for (const m of marked.filter((m) => m.cell[0] === x)) {
      const [, y, z] = m.cell;
      const at = {
        front: [(y + 1) * t - 3, (v.nz - 1 - z) * t, 6, t],
        top: [y * t, (v.nz - 1 - z) * t - 3, t, 6],
        back: [-3, (v.nz - 1 - z) * t, 6, t],
        base: [y * t, v.nz * t - 3, t, 6],
      }[m.kind];
      el('rect', { x: at[0], y: at[1], width: at[2], height: at[3], class: `mark mark-${m.fault}` }, sg);
    }
    const caption = el('text', { x: 0, y: (v.nz + 1) * t + 10, class: 'caption' }, sg);
    caption.textContent = `column x ${x}: back sheet on the left`;
    this.$('voxel-side-label').textContent = `Side view of column ${x}`;
  }

  async frontClick(x, z) {
    this.column = x;
    const v = this.view;
    switch (this.tool) {
      case 'add': return this.edit({ op: 'push_out', x, z });
      case 'remove': return this.edit({ op: 'push_in', x, z });
      case 'window': return this.edit({ op: 'window', x, z, on: !v.window[x][z] });
      case 'top': return this.edit({ op: 'omit_top', x, z, on: !v.omitted[x][z] });
      default: return this.drawGrids();
    }
  }

  async sideClick(x, y, z) {
    const v = this.view;
    switch (this.tool) {
      case 'add': return this.edit({ op: 'add', x, y, z });
      case 'remove': return this.edit({ op: 'delete', x, y, z });
      case 'window': return this.edit({ op: 'window', x, z, on: !v.window[x][z] });
      case 'top': return this.edit({ op: 'omit_top', x, z, on: !v.omitted[x][z] });
      default: return undefined;
    }
  }
}
