// The machine view: choose a shipped machine and material, draw the planned toolpath over
// the sheet on the bed (travel in its own colour), show lengths, pierces and time, and offer
// the job files exactly as `foldcam cut` writes them.
import { call } from './api.js';
import { panZoom } from './cp.js';

const NS = 'http://www.w3.org/2000/svg';
/** Colour of tool-off travel. */
const TRAVEL = '#ff8c00';
/** Colour of the sheet's lines under the toolpath. */
const SHEET = '#c8c8c8';

function el(name, attrs = {}, parent = null) {
  const node = document.createElementNS(NS, name);
  for (const [k, v] of Object.entries(attrs)) node.setAttribute(k, v);
  if (parent) parent.appendChild(node);
  return node;
}

function clock(seconds) {
  const t = Math.round(Math.max(0, seconds));
  const pad = (n) => String(n).padStart(2, '0');
  return `${Math.floor(t / 3600)}:${pad(Math.floor(t / 60) % 60)}:${pad(t % 60)}`;
}

export class MachineView {
  constructor(root) {
    this.svg = root.querySelector('#toolpath-svg');
    this.stats = root.querySelector('#plan-stats');
    this.downloads = root.querySelector('#downloads');
    this.machine = root.querySelector('#machine');
    this.material = root.querySelector('#material');
    this.size = root.querySelector('#size');
    this.options = [...root.querySelectorAll('[data-option]')];
    const ops = ['', 'mark', 'score', 'perforate', 'cut', 'plot', 'skip'];
    for (const select of this.options.filter((o) => o.tagName === 'SELECT' && o.dataset.option !== 'origin')) {
      select.replaceChildren(...ops.map((op) => new Option(op || 'material default', op)));
    }
    for (const kind of ['machine', 'material']) {
      root.querySelector(`#${kind}-file`).addEventListener('change', (e) => {
        const file = e.target.files[0];
        if (file) this.onError(this.uploadProfile(kind, file));
      });
    }
    this.onError = (promise) => promise;
    this.box = [0, 0, 1, 1];
    panZoom(this.svg, () => this.box, (b) => this.setBox(b));
  }

  setBox(box) {
    this.box = box;
    this.svg.setAttribute('viewBox', box.join(' '));
  }

  /** Reads a TOML profile as the command line reads a profile file, and chooses it. */
  async uploadProfile(kind, file) {
    const reply = await call(`/api/profiles/${kind}?name=${encodeURIComponent(file.name)}`,
      { method: 'POST', body: file });
    await this.load();
    (kind === 'machine' ? this.machine : this.material).value = reply.name;
    document.body.dataset.profile = reply.name;
  }

  /** Fills the machine and material lists from the shipped and uploaded profiles. */
  async load() {
    const chosen = [this.machine.value, this.material.value];
    const [machines, materials] = await Promise.all([call('/api/machines'), call('/api/materials')]);
    this.machines = Object.fromEntries(machines.map((m) => [m.name, m]));
    for (const [select, list] of [[this.machine, machines], [this.material, materials]]) {
      select.replaceChildren(...list.map((p) => new Option(`${p.name} — ${p.description}`, p.name)));
    }
    if (chosen[0]) this.machine.value = chosen[0];
    if (chosen[1]) this.material.value = chosen[1];
  }

  /** The query naming the current choice. */
  query() {
    const q = new URLSearchParams({ machine: this.machine.value, material: this.material.value });
    if (this.size.value) q.set('size', this.size.value);
    for (const o of this.options) {
      if (o.type === 'checkbox') {
        if (o.checked) q.set(o.dataset.option, 'true');
      } else if (o.value !== '') {
        q.set(o.dataset.option, o.value);
      }
    }
    return q;
  }

  /** Plans document `id` and draws the result. */
  async plan(id) {
    const q = this.query();
    const plan = await call(`/api/docs/${id}/plan?${q}`);
    this.draw(plan);
    this.showStats(plan);
    this.offer(id, plan, q);
    if (plan.gcode) {
      const sim = await call(`/api/docs/${id}/simulate?${q}`);
      // An HTML paragraph (the module's `el` makes SVG elements, which an HTML page does not
      // show).
      document.getElementById('sim-result')?.remove();
      const p = document.createElement('p');
      p.id = 'sim-result';
      p.textContent = `Simulated ${sim.machine}: ${sim.lines} lines, ${clock(sim.time_s)} with acceleration, ` +
        `${sim.violation_count} problem(s).`;
      this.stats.appendChild(p);
    }
    return plan;
  }

  draw(plan) {
    const [bw, bh] = plan.bed;
    const flip = plan.y_flipped ? 1 : -1;
    this.svg.replaceChildren();
    const job = plan.jobs[0];
    // The view: the job (its sheet and burns) with a margin, so a small job on a large bed
    // is not a speck; the bed shows around it as far as the margin reaches. A job with
    // nothing drawn shows the whole bed.
    const xs = [];
    const ys = [];
    for (const s of job.sheet) { xs.push(s[0], s[2]); ys.push(s[1], s[3]); }
    for (const path of job.paths) {
      for (const stroke of path.strokes) for (const p of stroke) { xs.push(p[0]); ys.push(p[1]); }
    }
    let [x0, y0, x1, y1] = xs.length
      ? [Math.min(...xs), Math.min(...ys), Math.max(...xs), Math.max(...ys)]
      : [0, 0, bw, bh];
    const pad = Math.max(0.08 * Math.max(x1 - x0, y1 - y0), 5);
    [x0, y0, x1, y1] = [x0 - pad, y0 - pad, x1 + pad, y1 + pad];
    this.setBox(flip < 0 ? [x0, -y1, x1 - x0, y1 - y0] : [x0, y0, x1 - x0, y1 - y0]);
    this.svg.dataset.view = [x0, y0, x1, y1].map((v) => v.toFixed(2)).join(' ');
    const root = el('g', { transform: `scale(1,${flip})` }, this.svg);
    el('rect', { x: 0, y: 0, width: bw, height: bh, fill: '#fafafa', stroke: '#999',
      'vector-effect': 'non-scaling-stroke' }, root);
    const line = (g, s, attrs) => el('line', { x1: s[0], y1: s[1], x2: s[2], y2: s[3],
      'vector-effect': 'non-scaling-stroke', ...attrs }, g);
    const sheet = el('g', { id: 'tp-sheet' }, root);
    for (const s of job.sheet) line(sheet, s, { stroke: SHEET, 'stroke-width': 1 });
    const burns = el('g', { id: 'tp-burns' }, root);
    for (const path of job.paths) {
      for (const stroke of path.strokes) {
        el('polyline', { points: stroke.map((p) => p.join(',')).join(' '), fill: 'none',
          stroke: path.colour, 'stroke-width': 1.6, 'vector-effect': 'non-scaling-stroke',
          class: `op-${path.op}` }, burns);
      }
    }
    const travel = el('g', { id: 'tp-travel' }, root);
    for (const s of job.travel) {
      line(travel, s, { stroke: TRAVEL, 'stroke-width': 1, 'stroke-dasharray': '4 3' });
    }
  }

  showStats(plan) {
    const s = plan.stats;
    const rows = s.length_mm.map(([op, mm]) => `<tr><td>${op}</td><td>${mm.toFixed(1)} mm</td></tr>`);
    rows.push(`<tr><td>pierces</td><td id="plan-pierces">${s.pierces}</td></tr>`);
    rows.push(`<tr><td>travel <span class="travel-key">(dashed)</span></td><td>${s.travel_mm.toFixed(1)} mm</td></tr>`);
    rows.push(`<tr><td>time (estimated)</td><td id="plan-time">${clock(s.time_s)}</td></tr>`);
    this.stats.innerHTML = `<table>${rows.join('')}</table>`;
    // Each warning in words; one about lines of the pattern shows them there when clicked.
    for (const w of plan.warnings) {
      const p = document.createElement('p');
      p.className = 'muted plan-warning';
      p.dataset.kind = w.kind;
      p.textContent = `warning: ${w.text}`;
      if (w.edges.length && this.onShowEdges) {
        const b = document.createElement('button');
        b.className = 'show-edges';
        b.textContent = `show ${w.edges.length === 1 ? 'it' : `the ${w.edges.length} lines`} on the pattern`;
        b.addEventListener('click', () => this.onShowEdges(w.edges));
        p.append(' ', b);
      }
      this.stats.append(p);
    }
  }

  offer(id, plan, q) {
    const kinds = plan.gcode ? ['gcode', 'dxf', 'svg', 'lbrn2'] : ['dxf', 'svg', 'lbrn2'];
    this.downloads.replaceChildren();
    for (const job of plan.jobs) {
      for (const kind of kinds) {
        const a = document.createElement('a');
        const jq = new URLSearchParams(q);
        jq.set('format', kind);
        jq.set('job', job.name);
        a.href = `/api/docs/${id}/cut?${jq}`;
        a.id = plan.jobs.length > 1 ? `dl-${job.name}-${kind}` : `dl-${kind}`;
        a.textContent = `${plan.jobs.length > 1 ? job.name + ' ' : ''}.${kind}`;
        a.setAttribute('download', '');
        this.downloads.appendChild(a);
      }
    }
  }
}
