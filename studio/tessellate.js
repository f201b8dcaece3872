// The tessellation designer (Tachi 2014, "Freeform 3D Origami Tessellations for Fabrication"):
// load a mesh (upload or a bundled example), choose the tuck and the material's limits, solve
// on the server while the page polls its progress (iterations, residual, estimate), cancel,
// then see the folded form in 3D with every crease and vertex measured against the limits,
// and the crease pattern. "Save design" downloads the .tess.toml `foldcam tessellate` reads.
import * as THREE from './vendor/three.module.min.js';
import { makeScene, onDrag } from './scene3d.js';
import { call } from './api.js';

const NS = 'http://www.w3.org/2000/svg';
/** How often the page asks for progress while a solve runs, milliseconds. */
const POLL_MS = 200;
/** Paper colours, as in the Folded view. */
const FRONT = 0xf4efe6;
const BACK = 0x6a8fd8;
/** Crease colours: within the limit from "barely folded" to "at the limit", and the faults. */
const EASY = new THREE.Color(0x2e7d32);
const NEAR = new THREE.Color(0xf2a900);
const BEYOND = new THREE.Color(0xd50000);
const WRONG = new THREE.Color(0x8e24aa);
const BOUNDARY = new THREE.Color(0x444444);
const UNDER = new THREE.Color(0xff6d00);
const UNDEVELOPABLE = new THREE.Color(0xd50000);

function el(name, attrs = {}, parent = null) {
  const node = document.createElementNS(NS, name);
  for (const [k, v] of Object.entries(attrs)) node.setAttribute(k, v);
  if (parent) parent.appendChild(node);
  return node;
}

const hex = (c) => `#${c.getHexString()}`;
const post = (url, body) => call(url, {
  method: 'POST',
  headers: { 'content-type': 'application/json' },
  body: JSON.stringify(body ?? {}),
});

/** The 3D view: the input mesh before solving, the folded form with its limits after. */
class Shell {
  constructor(container) {
    this.container = container;
    Object.assign(this, makeScene(container));
    this.model.rotation.set(-1.0, 0, 0.6);
    onDrag(this.renderer.domElement, (dx, dy) => {
      this.model.rotation.z += dx * 0.01;
      this.model.rotation.x += dy * 0.01;
      this.draw();
    });
    new ResizeObserver(() => this.draw()).observe(container);
  }

  /** Positions (flat xyz) and triangle indices as paper, centred and framed. */
  paper(positions, triangles) {
    this.model.clear();
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(new Float32Array(positions.flat()), 3));
    geometry.setIndex(triangles.flat());
    geometry.computeBoundingSphere();
    // A copy: `translate` recomputes the bounding sphere in place, which would move a kept
    // reference to its centre to the origin and leave the lines drawn over the paper off it.
    const center = geometry.boundingSphere.center.clone();
    const radius = geometry.boundingSphere.radius;
    geometry.translate(-center.x, -center.y, -center.z);
    geometry.computeVertexNormals();
    this.centre = center;
    this.radius = radius || 1;
    this.camera.position.set(0, 0, this.radius * 4.2);
    this.camera.near = this.radius * 0.01;
    this.camera.far = this.radius * 20;
    // Pushed back a little in depth, so that the creases drawn on the paper stay visible.
    const paper = { polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1 };
    const front = new THREE.MeshLambertMaterial({ color: FRONT, side: THREE.FrontSide, ...paper });
    const back = new THREE.MeshLambertMaterial({ color: BACK, side: THREE.BackSide, ...paper });
    this.model.add(new THREE.Mesh(geometry, front), new THREE.Mesh(geometry, back));
  }

  local(p) {
    return [p[0] - this.centre.x, p[1] - this.centre.y, p[2] - this.centre.z];
  }

  /** The input mesh: its polygons fanned into triangles, edges drawn. */
  showMesh(mesh) {
    const triangles = [];
    for (const f of mesh.faces) for (let k = 1; k + 1 < f.length; k++) triangles.push([f[0], f[k], f[k + 1]]);
    this.paper(mesh.positions, triangles);
    const segments = [];
    for (const f of mesh.faces) {
      f.forEach((v, k) => segments.push(...this.local(mesh.positions[v]), ...this.local(mesh.positions[f[(k + 1) % f.length]])));
    }
    const g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.Float32BufferAttribute(segments, 3));
    this.model.add(new THREE.LineSegments(g, new THREE.LineBasicMaterial({ color: 0x333333 })));
    this.draw();
  }

  /** The folded form: creases coloured by their fold against the limit, faulty vertices marked. */
  showFolded(folded, limit) {
    this.paper(folded.positions, folded.triangles);
    const segments = [], colours = [];
    for (const c of folded.creases) {
      const colour = creaseColour(c, limit);
      for (const v of c.v) {
        segments.push(...this.local(folded.positions[v]));
        colours.push(colour.r, colour.g, colour.b);
      }
    }
    const g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.Float32BufferAttribute(segments, 3));
    g.setAttribute('color', new THREE.Float32BufferAttribute(colours, 3));
    this.model.add(new THREE.LineSegments(g, new THREE.LineBasicMaterial({ vertexColors: true })));
    const points = [], pointColours = [];
    folded.vertices.forEach((v, i) => {
      const colour = v.undevelopable ? UNDEVELOPABLE : v.under ? UNDER : null;
      if (!colour) return;
      points.push(...this.local(folded.positions[i]));
      pointColours.push(colour.r, colour.g, colour.b);
    });
    if (points.length) {
      const pg = new THREE.BufferGeometry();
      pg.setAttribute('position', new THREE.Float32BufferAttribute(points, 3));
      pg.setAttribute('color', new THREE.Float32BufferAttribute(pointColours, 3));
      this.model.add(new THREE.Points(pg, new THREE.PointsMaterial({ size: 7, sizeAttenuation: false,
        vertexColors: true, depthTest: false })));
    }
    this.draw();
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

/** A crease's colour: faults first, else how much of the fold-angle limit it uses. */
function creaseColour(c, limit) {
  if (c.a === 'B') return BOUNDARY;
  if (c.over) return BEYOND;
  if (c.wrong) return WRONG;
  return EASY.clone().lerp(NEAR, Math.min(1, Math.abs(c.fold) / limit));
}

export class TessellationView {
  /**
   * `root` is the tessellation section; `onPattern(view)` receives the studio document made
   * from the crease pattern; `guarded(action, label)` runs an action showing its error.
   */
  constructor(root, onPattern, guarded) {
    this.root = root;
    this.onPattern = onPattern;
    this.guarded = guarded;
    const $ = (id) => root.querySelector(`#${id}`);
    this.$ = $;
    this.shell = new Shell($('tess-canvas'));
    this.events = [];
    $('tess-load').addEventListener('click', () => guarded(() => this.loadExample($('tess-example').value)));
    $('tess-file').addEventListener('change', (e) => {
      const file = e.target.files[0];
      e.target.value = '';
      if (file) guarded(() => this.upload(file));
    });
    $('tess-material').addEventListener('change', () => this.materialChosen());
    $('tess-solve').addEventListener('click', () => guarded(() => this.solve()));
    $('tess-cancel').addEventListener('click', () => guarded(() => this.cancel()));
    $('tess-pattern').addEventListener('click', () => guarded(async () => {
      if (!this.job) return;
      await this.onPattern(await call(`/api/tess/jobs/${this.job}/pattern`, { method: 'POST' }));
    }));
    document.querySelector("#tabs button[data-view='tessellate']")
      ?.addEventListener('click', () => guarded(() => this.enter()));
    this.showLegend();
  }

  /** The mode is shown: the examples and materials the first time, then the dome. */
  async enter() {
    if (!this.setup) {
      this.setup = await call('/api/tess/setup');
      this.legend = await call('/api/legend');
      const options = (list, f) => list.map((x) => { const o = document.createElement('option'); f(o, x); return o; });
      this.$('tess-example').replaceChildren(...options(this.setup.examples, (o, n) => { o.value = n; o.textContent = n; }));
      this.$('tess-material').replaceChildren(
        ...options([{ name: '', description: "Tachi's stainless example (165°, 30°)" }, ...this.setup.materials], (o, m) => {
          o.value = m.name;
          o.textContent = m.name ? `${m.name}: ${m.description}` : m.description;
        }));
      const d = this.setup.defaults;
      this.$('tess-max-fold').value = d.max_fold_angle;
      this.$('tess-min-angle').value = d.min_vertex_angle;
      this.$('tess-truncation').value = d.truncation;
      this.$('tess-twist').value = d.twist;
      this.$('tess-iterations').value = d.max_iterations;
    }
    if (!this.mesh) await this.loadExample(this.setup.examples[0]);
    else this.shell.draw();
  }

  materialChosen() {
    const m = this.setup.materials.find((x) => x.name === this.$('tess-material').value);
    const d = this.setup.defaults;
    this.$('tess-max-fold').value = m ? m.max_fold_angle : d.max_fold_angle;
    this.$('tess-min-angle').value = m ? m.min_vertex_angle : d.min_vertex_angle;
  }

  async loadExample(name) {
    this.meshLoaded(await call(`/api/tess/example/${encodeURIComponent(name)}`, { method: 'POST' }));
  }

  async upload(file) {
    this.meshLoaded(await call(`/api/tess/mesh?name=${encodeURIComponent(file.name)}`,
      { method: 'POST', body: file }));
  }

  meshLoaded(mesh) {
    this.mesh = mesh;
    this.job = null;
    this.result = null;
    this.shell.showMesh(mesh);
    // No time is promised before one is measured: the progress line gives the time left
    // once two iterations of a solve are timed.
    this.$('tess-mesh-info').textContent = `${mesh.name}: ${mesh.positions.length} vertices, ` +
      `${mesh.faces.length} faces; the time left is measured while it solves`;
    this.$('tess-report').replaceChildren();
    this.$('tess-cp').replaceChildren();
    // Nothing of the previous mesh's solve stays: its progress, notes and plot.
    this.events = [];
    this.$('tess-progress').textContent = '';
    this.$('tess-notes').replaceChildren();
    this.$('tess-plot').replaceChildren();
    delete document.body.dataset.tessIterations;
    this.setStatus('ready');
  }

  /** The options as the API (and `foldcam tessellate`) names them. */
  options() {
    const $ = this.$;
    const number = (id) => ($(id).value === '' ? undefined : Number($(id).value));
    const o = {
      tuck: $('tess-tuck').value,
      layout: $('tess-layout').value,
      shrink: number('tess-shrink'),
      truncation: number('tess-truncation'),
      twist: number('tess-twist'),
      max_fold_angle: number('tess-max-fold'),
      min_vertex_angle: number('tess-min-angle'),
      ground: $('tess-ground').checked,
      fit: number('tess-fit'),
      remesh: $('tess-remesh').value,
      max_iterations: number('tess-iterations'),
    };
    if ($('tess-material').value) o.material = $('tess-material').value;
    return o;
  }

  async solve() {
    if (!this.mesh) throw new Error('load a mesh first');
    const { job } = await post(`/api/tess/mesh/${this.mesh.id}/solve`, this.options());
    this.job = job;
    this.events = [];
    this.result = null;
    this.$('tess-cp').replaceChildren();
    this.$('tess-report').replaceChildren();
    this.setStatus('running');
    await this.poll(job);
  }

  async cancel() {
    if (this.job !== null && this.job !== undefined) await post(`/api/tess/jobs/${this.job}/cancel`);
  }

  /** Asks for new events until the job ends, then shows its result. */
  async poll(job) {
    for (;;) {
      const state = await call(`/api/tess/jobs/${job}?since=${this.events.length}`);
      if (this.job !== job) return;
      this.events.push(...state.events);
      this.showProgress();
      if (state.status !== 'running') {
        if (state.status === 'done' || state.status === 'refused') {
          this.showResult(await call(`/api/tess/jobs/${job}/result`));
        }
        this.setStatus(state.status, state.error);
        return;
      }
      await new Promise((resolve) => setTimeout(resolve, POLL_MS));
    }
  }

  setStatus(status, error) {
    const running = status === 'running';
    this.$('tess-solve').disabled = running;
    this.$('tess-cancel').disabled = !running;
    const made = status === 'done';
    this.$('tess-pattern').disabled = !made;
    for (const [id, what] of [['tess-design', 'design'], ['tess-mesh', 'mesh']]) {
      const link = this.$(id);
      if (this.job !== null && this.job !== undefined) link.href = `/api/tess/jobs/${this.job}/${what}`;
      else link.removeAttribute('href');
    }
    document.body.dataset.tessStatus = status;
    const words = { ready: 'ready to solve', running: 'solving…', done: 'solved: within every limit',
      refused: 'solved, but refused (see the report)', cancelled: 'cancelled', failed: error ?? 'failed' };
    // A partial form (the command exits 1 for it unless --allow-partial) is said in amber.
    const partial = made ? this.result?.partial : null;
    this.$('tess-status').textContent = partial
      ? `solved, but partial: ${partial} (the command line exits 1 without --allow-partial)`
      : words[status] ?? status;
    this.$('tess-status').className = partial ? 'unchecked' : made ? 'pass' : status === 'refused' || status === 'failed' ? 'fail' : '';
  }

  /** The latest iteration in words, the notes, and the residual per iteration (log scale). */
  showProgress() {
    const iterations = this.events.filter((e) => e.kind === 'iteration');
    const notes = this.events.filter((e) => e.kind === 'note').map((e) => e.text);
    const last = iterations[iterations.length - 1];
    // The server's line is the one `foldcam tessellate`'s bar shows (solve of the schedule,
    // residual, time left in this solve).
    this.$('tess-progress').textContent = last
      ? `${last.progress}; max fold ${last.max_fold.toFixed(1)}°, min angle ${last.min_angle.toFixed(1)}°`
      : 'starting… (the time left is shown once two iterations are timed)';
    this.$('tess-notes').replaceChildren(...notes.map((n) => { const li = document.createElement('li'); li.textContent = n; return li; }));
    document.body.dataset.tessIterations = String(iterations.length);
    const svg = this.$('tess-plot');
    svg.replaceChildren();
    if (!iterations.length) return;
    const w = 240, h = 90;
    const y = (r) => { const l = Math.log10(Math.max(r, 1e-16)); return h - 4 - ((l + 16) / 18) * (h - 8); };
    const step = (w - 8) / Math.max(1, iterations.length - 1);
    el('line', { x1: 4, x2: w - 4, y1: y(1e-12), y2: y(1e-12), class: 'tess-tolerance' }, svg);
    el('polyline', { points: iterations.map((it, i) => `${4 + i * step},${y(it.developability)}`).join(' '),
      class: 'tess-residual' }, svg);
  }

  showResult(result) {
    this.result = result;
    this.shell.showFolded(result.folded, result.limits.max_fold_angle);
    const v = result.violations;
    const deg = (x) => `${Number(x.toFixed(2))}°`;
    const [fold, angle] = [deg(result.limits.max_fold_angle), deg(result.limits.min_vertex_angle)];
    this.$('tess-violations').textContent = v.creases || v.vertices
      ? `${v.creases} crease(s) and ${v.vertices} vertex(es) miss the limits (fold ≤ ${fold}, ` +
        `angle between creases ≥ ${angle})`
      : `every crease folds within ${fold} and every angle between creases is at least ${angle}`;
    this.$('tess-report').replaceChildren(...result.lines.join('\n').split('\n').map((l) => {
      const li = document.createElement('li'); li.textContent = l; return li;
    }));
    if (result.pattern) this.drawPattern(result.pattern);
    document.body.dataset.tessEdges = result.pattern ? String(result.pattern.edges.length) : '';
  }

  /** The crease pattern in the legend's colours. */
  drawPattern(pt) {
    const svg = this.$('tess-cp');
    svg.replaceChildren();
    const xs = pt.vertices.map((p) => p[0]), ys = pt.vertices.map((p) => p[1]);
    const lo = [Math.min(...xs), Math.min(...ys)], hi = [Math.max(...xs), Math.max(...ys)];
    const pad = 0.04 * Math.max(hi[0] - lo[0], hi[1] - lo[1]);
    svg.setAttribute('viewBox', [lo[0] - pad, -hi[1] - pad, hi[0] - lo[0] + 2 * pad, hi[1] - lo[1] + 2 * pad].join(' '));
    const g = el('g', { transform: 'scale(1,-1)' }, svg);
    const styles = Object.fromEntries((this.legend?.assignments ?? []).map((a) => [a.letter, a]));
    for (const [i, j, a] of pt.edges) {
      const [p, q] = [pt.vertices[i], pt.vertices[j]];
      const s = styles[a] ?? { colour: '#000', width: 1, dash: null };
      el('line', { x1: p[0], y1: p[1], x2: q[0], y2: q[1], stroke: s.colour, 'stroke-width': s.width,
        'stroke-dasharray': s.dash ? s.dash.join(' ') : 'none', 'vector-effect': 'non-scaling-stroke',
        class: `edge edge-${a}` }, g);
    }
  }

  /** What the colours of the 3D view mean. */
  showLegend() {
    const item = (swatch, text) => {
      const li = document.createElement('li');
      li.innerHTML = `${swatch} ${text}`;
      return li;
    };
    const line = (c) => `<svg width="34" height="10"><line x1="2" y1="5" x2="32" y2="5" stroke="${c}" stroke-width="3"/></svg>`;
    const dot = (c) => `<svg width="34" height="10"><circle cx="17" cy="5" r="4" fill="${c}"/></svg>`;
    const ramp = `<svg width="34" height="10"><defs><linearGradient id="tess-ramp"><stop offset="0" stop-color="${hex(EASY)}"/>` +
      `<stop offset="1" stop-color="${hex(NEAR)}"/></linearGradient></defs><rect x="2" y="2" width="30" height="6" fill="url(#tess-ramp)"/></svg>`;
    this.$('tess-legend').replaceChildren(
      item(ramp, 'crease: fold from 0 to the fold-angle limit'),
      item(line(hex(BEYOND)), 'crease beyond the fold-angle limit'),
      item(line(hex(WRONG)), 'crease folded against its mountain/valley'),
      item(line(hex(BOUNDARY)), 'sheet boundary'),
      item(dot(hex(UNDER)), 'vertex: creases closer than the vertex-angle limit'),
      item(dot(hex(UNDEVELOPABLE)), 'vertex: not developable (angles do not sum to 360°)'),
    );
  }
}
