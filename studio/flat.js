// The flat-folded view: the layer solver's state seen from above (as `foldcam fold-flat
// --png` draws it), cells shaded by the number of layers, the folded outline in black.
import { call } from './api.js';
import { panZoom } from './cp.js';

const NS = 'http://www.w3.org/2000/svg';

function el(name, attrs = {}, parent = null) {
  const node = document.createElementNS(NS, name);
  for (const [k, v] of Object.entries(attrs)) node.setAttribute(k, v);
  if (parent) parent.appendChild(node);
  return node;
}

export class FlatView {
  constructor(root) {
    this.svg = root.querySelector('#flat-svg');
    this.label = root.querySelector('#flat-label');
    this.stateInput = root.querySelector('#flat-state');
    this.xray = root.querySelector('#flat-xray');
    this.box = [0, 0, 1, 1];
    panZoom(this.svg, () => this.box, (b) => this.setBox(b));
    this.xray.addEventListener('change', () => { if (this.view) this.draw(this.view); });
  }

  setBox(box) {
    this.box = box;
    this.svg.setAttribute('viewBox', box.join(' '));
  }

  clear() {
    this.view = null;
    this.svg.replaceChildren();
    this.label.textContent = 'not folded yet';
  }

  /** Folds document `id` flat and draws the state chosen in the page. */
  async load(id) {
    this.label.textContent = 'folding flat…';
    const k = Math.max(0, Math.floor(Number(this.stateInput.value) || 0));
    try {
      const t = document.getElementById('kawasaki-tolerance')?.value.trim();
      const tolerance = t ? `&kawasaki_tolerance=${encodeURIComponent(t)}` : '';
      this.view = await call(`/api/docs/${id}/flat?state=${k}${tolerance}`);
    } catch (e) {
      this.label.textContent = e.message;
      this.svg.replaceChildren();
      throw e;
    }
    this.draw(this.view);
    return this.view;
  }

  draw(view) {
    this.svg.replaceChildren();
    const pts = view.cells.flatMap((c) => c.rings.flat());
    const xs = pts.map((p) => p[0]), ys = pts.map((p) => p[1]);
    const lo = [Math.min(...xs), Math.min(...ys)], hi = [Math.max(...xs), Math.max(...ys)];
    const pad = 0.05 * Math.hypot(hi[0] - lo[0], hi[1] - lo[1]);
    this.setBox([lo[0] - pad, -hi[1] - pad, hi[0] - lo[0] + 2 * pad, hi[1] - lo[1] + 2 * pad]);
    const root = el('g', { transform: 'scale(1,-1)' }, this.svg);
    const cells = el('g', { id: 'flat-cells' }, root);
    const xray = this.xray.checked;
    for (const c of view.cells) {
      const d = c.rings.map((r) => `M${r.map((p) => p.join(',')).join('L')}Z`).join('');
      el('path', { d, fill: xray ? c.xray : c.fill, 'fill-rule': 'evenodd', stroke: 'none',
        'data-layers': c.layers, class: c.flipped ? 'cell back' : 'cell front' }, cells);
    }
    const lines = el('g', { id: 'flat-lines' }, root);
    for (const [[x1, y1, x2, y2], outline] of view.segments) {
      el('line', { x1, y1, x2, y2, stroke: outline ? '#000' : '#5a5a5a',
        'stroke-width': outline ? 1.5 : 0.5, 'vector-effect': 'non-scaling-stroke' }, lines);
    }
    this.label.textContent = `state ${view.state} of ${view.states}${view.exact ? '' : ' or more'} ` +
      `valid layer order(s) (Akitaya, Demaine & Ku 2023); up to ${view.deepest} layers, darker where deeper`;
  }
}
