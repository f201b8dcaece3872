// The paper-craft editor (Ōgaki 2016): the reference mesh in 3D; click points on it to draw a
// cut line (the Catmull–Rom curve through them, projected onto the mesh by the server), finish
// it and the regions it closes become patches — coloured on the mesh — whose unrolled, packed
// parts show beside it. Errors show where they are: a region whose patch cannot be unrolled is
// red on the mesh and in the list, a part whose outline crosses itself is red on the sheet.
// "Save design" downloads the .craft.toml `foldcam papercraft` reads, with its mesh.
import * as THREE from './vendor/three.module.min.js';
import { makeScene } from './scene3d.js';
import { call } from './api.js';

const NS = 'http://www.w3.org/2000/svg';
/** A press that moves less than this (pixels) is a click (a point), more turns the model. */
const CLICK_PIXELS = 4;
/** Region colours (cycled); errors are ERROR. */
const COLOURS = [0x8ecae6, 0xffb703, 0x90be6d, 0xf4a261, 0xb5a1e6, 0x6fd3c2, 0xf28482, 0xc9d66b];
const ERROR = 0xd62828;
const NONE = 0xdddddd;
const hex = (c) => `#${c.toString(16).padStart(6, '0')}`;

const post = (url, body) => call(url, {
  method: 'POST',
  headers: { 'content-type': 'application/json' },
  body: JSON.stringify(body),
});

function el(name, attrs = {}, parent = null) {
  const node = document.createElementNS(NS, name);
  for (const [k, v] of Object.entries(attrs)) node.setAttribute(k, v);
  if (parent) parent.appendChild(node);
  return node;
}

export class CraftView {
  /** `root` is the craft section; `onPattern(view)` opens the parts as a document. */
  constructor(root, onPattern, guarded) {
    this.root = root;
    this.onPattern = onPattern;
    this.guarded = guarded;
    const $ = (id) => root.querySelector(`#${id}`);
    this.$ = $;
    this.clicked = [];
    this.container = $('craft-3d');
    Object.assign(this, makeScene(this.container, { light: [1.3, 1.8] }));
    this.model.rotation.set(-1.2, 0, 0.6);
    this.overlay = new THREE.Group();
    this.model.add(this.overlay);
    this.raycaster = new THREE.Raycaster();
    this.bindPointer();
    new ResizeObserver(() => this.draw()).observe(this.container);

    $('craft-example-open').addEventListener('click', () => guarded(() => this.open(
      post(`/api/craft/example/${encodeURIComponent($('craft-example').value)}`)), 'opening the example…'));
    $('craft-file').addEventListener('change', (e) => {
      const files = Array.from(e.target.files);
      if (files.length) guarded(() => this.openFiles(files), 'building the parts…');
      e.target.value = '';
    });
    $('craft-finish').addEventListener('click', () => guarded(() => this.finishLine(), 'building the parts…'));
    $('craft-cancel').addEventListener('click', () => { this.clicked = []; this.drawOverlay(); });
    $('craft-undo').addEventListener('click', () => guarded(() => this.change('undo'), 'building the parts…'));
    $('craft-pattern').addEventListener('click', () => guarded(async () => {
      if (!this.view) return;
      await this.onPattern(await call(`/api/craft/${this.view.id}/pattern`, { method: 'POST' }));
    }, 'opening the parts…'));
    document.addEventListener('keydown', (e) => {
      if (this.root.hidden || !this.view) return;
      if (e.key === 'Enter') guarded(() => this.finishLine(), 'building the parts…');
      if (e.key === 'Escape') { this.clicked = []; this.drawOverlay(); }
    });
    document.querySelector("#tabs button[data-view='craft']")
      ?.addEventListener('click', () => guarded(() => this.enter(), 'opening the example…'));
    // For the browser test: where a point of the mesh is on the screen.
    window.craftView = this;
  }

  /** The mode is shown: list the examples and open the first the first time. */
  async enter() {
    if (!this.examples) {
      this.examples = await call('/api/craft/examples');
      const select = this.$('craft-example');
      select.replaceChildren(...this.examples.map((x) => new Option(`${x.name} (${x.mesh})`, x.name)));
    }
    if (!this.view) await this.open(post(`/api/craft/example/${this.examples[0].name}`));
    else this.draw();
  }

  async openFiles(files) {
    const design = files.find((f) => f.name.toLowerCase().endsWith('.toml'));
    if (!design) {
      await this.open(call(`/api/craft/mesh?name=${encodeURIComponent(files[0].name)}`,
        { method: 'POST', body: files[0] }));
      return;
    }
    const others = files.filter((f) => f !== design);
    const parts = others.map((f) => ({ name: f.name, size: f.size }));
    const url = `/api/craft/design?name=${encodeURIComponent(design.name)}&with=${encodeURIComponent(JSON.stringify(parts))}`;
    await this.open(call(url, { method: 'POST', body: new Blob([design, ...others]) }));
  }

  async open(request) {
    const view = await request;
    this.clicked = [];
    this.setMesh(view.mesh);
    this.show(view);
  }

  async finishLine() {
    if (!this.view || this.clicked.length < 2) throw new Error('click at least two points on the mesh first');
    const points = this.clicked.map((p) => [p.x, p.y, p.z]);
    const view = await post(`/api/craft/${this.view.id}/line`, { points });
    this.clicked = [];
    this.show(view);
  }

  async change(what, body = {}) {
    if (!this.view) return;
    this.show(await post(`/api/craft/${this.view.id}/${what}`, body));
  }

  setMesh(mesh) {
    if (this.surface) {
      this.model.remove(this.surface);
      this.surface.geometry.dispose();
    }
    const geometry = new THREE.BufferGeometry();
    this.triangles = new Float32Array(mesh.triangles);
    geometry.setAttribute('position', new THREE.BufferAttribute(this.triangles, 3));
    geometry.computeBoundingSphere();
    const { center, radius } = geometry.boundingSphere;
    this.surface = new THREE.Mesh(geometry,
      new THREE.MeshLambertMaterial({ vertexColors: true, side: THREE.DoubleSide }));
    this.model.add(this.surface);
    this.centre = center.clone();
    this.radius = radius || 1;
    this.surface.position.copy(center).negate();
    this.overlay.position.copy(center).negate();
    this.camera.position.set(0, 0, this.radius * 3.4);
    this.camera.near = this.radius * 0.01;
    this.camera.far = this.radius * 20;
  }

  /**
   * Colours the mesh by region: whole triangles, and the triangles a cut line divides as the
   * server's pieces, so that the colours meet along the cut lines.
   */
  paint(view) {
    const pieces = view.pieces ?? { triangles: [], corners: [], regions: [] };
    const divided = new Set(pieces.triangles);
    const kept = view.paint.map((r, t) => t).filter((t) => !divided.has(t));
    const count = kept.length + pieces.regions.length;
    const positions = new Float32Array(9 * count);
    const colours = new Float32Array(9 * count);
    const c = new THREE.Color();
    const put = (i, corners, r) => {
      positions.set(corners, 9 * i);
      c.setHex(r < 0 ? NONE : this.regionColour(r));
      for (let k = 0; k < 3; k += 1) colours.set([c.r, c.g, c.b], 9 * i + 3 * k);
    };
    kept.forEach((t, i) => put(i, this.triangles.subarray(9 * t, 9 * t + 9), view.paint[t]));
    pieces.regions.forEach((r, i) => put(kept.length + i, pieces.corners.slice(9 * i, 9 * i + 9), r));
    const geometry = this.surface.geometry;
    geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
    geometry.setAttribute('color', new THREE.BufferAttribute(colours, 3));
    // computeVertexNormals refills an existing normal buffer of the old length: start anew.
    geometry.deleteAttribute('normal');
    geometry.computeVertexNormals();
    this.surface.userData.pieces = pieces.regions.length;
  }

  regionColour(r) {
    const region = this.view.regions[r];
    if (!region) return NONE;
    return region.error ? ERROR : COLOURS[r % COLOURS.length];
  }

  show(view) {
    this.view = view;
    this.paint(view);
    this.drawOverlay();
    this.drawParts();
    this.drawLists();
    const stem = view.name;
    const design = this.$('craft-save');
    design.href = `/api/craft/${view.id}/design`;
    design.download = `${stem}.craft.toml`;
    const mesh = this.$('craft-save-mesh');
    mesh.href = `/api/craft/${view.id}/mesh`;
    mesh.download = view.mesh_name;
    this.$('craft-undo').disabled = !view.can_undo;
    const fitted = view.regions.filter((r) => r.patch !== null).length;
    this.$('craft-info').textContent = `${view.name}: ${view.lines.length} cut lines, `
      + `${view.regions.length} regions, ${fitted} patches, ${view.parts.length} parts on `
      + `${view.sheets} sheet(s). Click points on the mesh, then Finish line (Enter); drag to turn.`;
    // Lines that enclose nothing yet: say what makes a region.
    const open = view.lines.filter((l) => l.open).length;
    this.$('craft-hint').textContent = view.lines.length && !view.regions.length
      ? `No region yet: a region is a part of the mesh closed all round by cut lines. ` +
        (open ? `${open} line(s) have a loose end (drawn dashed): end each line on another ` +
          'line or on the mesh\'s edge so that the lines close a loop.' : 'Draw more lines to close a loop.')
      : '';
    this.$('craft-error').textContent = view.error ? `The parts cannot be made: ${view.error}` : '';
    this.root.dataset.parts = String(view.parts.length);
    this.root.dataset.lines = String(view.lines.length);
    this.root.dataset.faults = String(view.regions.filter((r) => r.error).length);
  }

  /** Cut lines (open ones dashed), the points clicked so far and their curve. */
  drawOverlay() {
    for (const child of [...this.overlay.children]) {
      this.overlay.remove(child);
      child.geometry?.dispose();
    }
    if (!this.view) return;
    const v = (p) => new THREE.Vector3(p[0], p[1], p[2]);
    this.view.lines.forEach((line, i) => {
      const geometry = new THREE.BufferGeometry().setFromPoints(line.curve.map(v));
      const material = new THREE.LineBasicMaterial({
        color: this.highlight === i ? 0xd62828 : (line.open ? 0x9a6700 : 0x1b1b1b),
        depthTest: false,
      });
      const drawn = new THREE.Line(geometry, material);
      drawn.renderOrder = 2;
      this.overlay.add(drawn);
    });
    const dot = this.radius * 0.012;
    for (const p of this.clicked) {
      const m = new THREE.Mesh(new THREE.SphereGeometry(dot, 12, 8),
        new THREE.MeshBasicMaterial({ color: 0xd97706, depthTest: false }));
      m.position.copy(p);
      m.renderOrder = 3;
      this.overlay.add(m);
    }
    if (this.clicked.length >= 2) {
      const curve = new THREE.CatmullRomCurve3(this.clicked, false, 'catmullrom', 0.5);
      const geometry = new THREE.BufferGeometry().setFromPoints(curve.getPoints(16 * this.clicked.length));
      const drawn = new THREE.Line(geometry, new THREE.LineBasicMaterial({ color: 0xd97706, depthTest: false }));
      drawn.renderOrder = 3;
      this.overlay.add(drawn);
    }
    this.draw();
  }

  /** The packed parts, sheet by sheet, side by side. */
  drawParts() {
    const svg = this.$('craft-parts');
    svg.replaceChildren();
    const [w, h] = this.view.sheet;
    const sheets = Math.max(1, this.view.sheets);
    svg.setAttribute('viewBox', `-5 -5 ${sheets * (w + 10)} ${h + 10}`);
    for (let s = 0; s < sheets; s += 1) {
      el('rect', { x: s * (w + 10), y: 0, width: w, height: h, class: 'craft-sheet' }, svg);
    }
    const pts = (list, s) => list.map(([x, y]) => `${x + s * (w + 10)},${h - y}`).join(' ');
    this.view.parts.forEach((part, i) => {
      const g = el('g', { 'data-part': i, 'data-region': part.region ?? -1, 'data-sheet': part.sheet }, svg);
      const fill = hex(part.region === null ? NONE : this.regionColour(part.region));
      for (const tab of part.tabs) el('polygon', { points: pts(tab, part.sheet), class: 'craft-tab' }, g);
      el('polygon', {
        points: pts(part.outline, part.sheet), fill,
        class: part.overlapping ? 'craft-part overlapping' : 'craft-part',
      }, g);
      if (part.overlapping) {
        const title = el('title', {}, g);
        title.textContent = 'this part overlaps itself when unrolled: cut the region smaller';
      }
    });
  }

  /** Regions with their errors, and cut lines with a remove button each. */
  drawLists() {
    const regions = this.$('craft-regions');
    regions.replaceChildren(...this.view.regions.map((r, i) => {
      const li = document.createElement('li');
      const swatch = document.createElement('span');
      swatch.className = 'swatch';
      swatch.style.background = hex(this.regionColour(i));
      li.append(swatch, `cut lines ${r.lines.join(', ')}: `);
      if (r.error) {
        li.className = 'error';
        li.append(`no patch — ${r.error}`);
      } else {
        li.append(r.residual === null ? 'placed patch' : `fitted cylinder (residual ${r.residual.toFixed(2)})`);
      }
      return li;
    }), ...(this.view.unglued || []).map((seam) => {
      const li = document.createElement('li');
      li.className = 'error unglued';
      li.append(`cut line ${seam.cut_line}: ${seam.lengths_mm[0].toFixed(1)} mm on one part, ` +
        `${seam.lengths_mm[1].toFixed(1)} mm on the other — these glued edges do not match; ` +
        'draw the cut lines where the surface is closer to a cylinder');
      return li;
    }));
    const lines = this.$('craft-lines');
    lines.replaceChildren(...this.view.lines.map((line, i) => {
      const li = document.createElement('li');
      li.append(`${i}: ${line.points.length} points${line.open ? ' (loose end)' : ''} `);
      const remove = document.createElement('button');
      remove.textContent = 'Remove';
      remove.dataset.line = String(i);
      remove.addEventListener('click', () => this.guarded(() => this.change('remove', { line: i }), 'building the parts…'));
      li.addEventListener('mouseenter', () => { this.highlight = i; this.drawOverlay(); });
      li.addEventListener('mouseleave', () => { this.highlight = null; this.drawOverlay(); });
      li.append(remove);
      return li;
    }));
  }

  bindPointer() {
    const canvas = this.renderer.domElement;
    let press = null;
    canvas.addEventListener('pointerdown', (e) => {
      press = { x: e.clientX, y: e.clientY, last: [e.clientX, e.clientY], moved: false };
    });
    canvas.addEventListener('pointermove', (e) => {
      if (!press) return;
      if (Math.hypot(e.clientX - press.x, e.clientY - press.y) > CLICK_PIXELS) press.moved = true;
      if (!press.moved) return;
      this.model.rotation.z += (e.clientX - press.last[0]) * 0.01;
      this.model.rotation.x += (e.clientY - press.last[1]) * 0.01;
      press.last = [e.clientX, e.clientY];
      this.draw();
    });
    canvas.addEventListener('pointerup', (e) => {
      if (press && !press.moved) this.pick(e.clientX, e.clientY);
      press = null;
    });
    canvas.addEventListener('pointerleave', () => { press = null; });
    canvas.addEventListener('wheel', (e) => {
      e.preventDefault();
      this.camera.position.z *= Math.exp(e.deltaY * 0.001);
      this.draw();
    }, { passive: false });
  }

  /** A click: the mesh point under the pointer joins the line being drawn. */
  pick(clientX, clientY) {
    if (!this.surface) return;
    const rect = this.renderer.domElement.getBoundingClientRect();
    const ndc = new THREE.Vector2(((clientX - rect.left) / rect.width) * 2 - 1,
      -((clientY - rect.top) / rect.height) * 2 + 1);
    this.raycaster.setFromCamera(ndc, this.camera);
    const hit = this.raycaster.intersectObject(this.surface, false)[0];
    if (!hit) return;
    // Back to the mesh's own coordinates.
    const local = this.surface.worldToLocal(hit.point.clone());
    this.clicked.push(local);
    this.drawOverlay();
  }

  /** Where mesh point `p` ([x, y, z], mesh units) is on the screen, client pixels; null when
   * a part of the mesh hides it. */
  screenOf(p) {
    const world = this.surface.localToWorld(new THREE.Vector3(p[0], p[1], p[2]));
    const ndc = world.clone().project(this.camera);
    const rect = this.renderer.domElement.getBoundingClientRect();
    const x = rect.left + (ndc.x + 1) / 2 * rect.width;
    const y = rect.top + (1 - ndc.y) / 2 * rect.height;
    this.raycaster.setFromCamera(new THREE.Vector2(ndc.x, ndc.y), this.camera);
    const hit = this.raycaster.intersectObject(this.surface, false)[0];
    const visible = hit && hit.point.distanceTo(world) < this.radius * 0.01;
    return visible ? [x, y] : null;
  }

  draw() {
    const w = this.container.clientWidth, h = this.container.clientHeight;
    if (!w || !h) return;
    this.renderer.setSize(w, h);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
    this.renderer.render(this.scene, this.camera);
  }
}
