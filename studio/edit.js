// Editing the crease pattern: draw a crease, drag a vertex, delete a line, change its
// assignment, undo and redo. The page only sends edits: snapping and the geometry (merging,
// splitting crossed lines) happen on the server, which answers with the new pattern.
import { call } from './api.js';

/** Snap reach around the pointer, screen pixels. */
const SNAP_PIXELS = 12;
/** Angle step of the snapping lines, degrees (origami's 22.5° designs). */
const ANGLE_STEP = 22.5;

export class Editor {
  /**
   * `view` is the PatternView; `controls` the toolbar; `onChange(view)` receives the pattern
   * view the server returns after each edit, undo or redo.
   */
  constructor(view, controls, onChange) {
    this.view = view;
    this.onChange = onChange;
    this.tool = 'pan';
    this.doc = null;
    this.start = null; // first end of a crease being drawn
    this.drag = null; // vertex being dragged
    this.pending = null; // pointer position waiting for a snap reply
    this.snapping = false;
    this.assignment = controls.querySelector('#edit-assignment');
    this.grid = controls.querySelector('#snap-grid');
    this.angles = controls.querySelector('#snap-angles');
    this.undoButton = controls.querySelector('#undo-btn');
    this.redoButton = controls.querySelector('#redo-btn');
    this.info = controls.querySelector('#edit-info');
    this.tools = [...controls.querySelectorAll('button[data-tool]')];
    for (const b of this.tools) b.addEventListener('click', () => this.setTool(b.dataset.tool));
    this.undoButton.addEventListener('click', () => this.history('undo'));
    this.redoButton.addEventListener('click', () => this.history('redo'));
    view.canPan = () => this.tool === 'pan';
    view.onEdgeClick = (i) => this.edgeClicked(i);
    const svg = view.svg;
    svg.addEventListener('pointerdown', (e) => this.down(e));
    svg.addEventListener('pointermove', (e) => this.move(e));
    svg.addEventListener('pointerup', (e) => this.up(e));
    document.addEventListener('keydown', (e) => this.key(e));
  }

  /** A new document (or version) is shown. */
  setDoc(doc) {
    this.doc = doc;
    this.start = null;
    this.drag = null;
    this.undoButton.disabled = !doc.history.undo;
    this.redoButton.disabled = !doc.history.redo;
  }

  setTool(tool) {
    this.tool = tool;
    this.start = null;
    this.drag = null;
    this.view.clearPreview();
    for (const b of this.tools) b.classList.toggle('active', b.dataset.tool === tool);
    this.view.svg.dataset.tool = tool;
    const hints = {
      pan: 'Drag pans, the wheel zooms.',
      draw: 'Click the two ends of the new crease (Esc cancels).',
      move: 'Drag a vertex; it snaps to vertices, lines, the grid and 22.5° directions.',
      assign: 'Click a line to give it the chosen assignment.',
      delete: 'Click a line to delete it.',
    };
    this.info.textContent = hints[tool];
  }

  key(e) {
    if (e.target.closest('input, select, textarea')) return;
    const z = e.key.toLowerCase() === 'z' && (e.ctrlKey || e.metaKey);
    if (z && !e.shiftKey) { e.preventDefault(); this.history('undo'); return; }
    if ((z && e.shiftKey) || (e.key.toLowerCase() === 'y' && (e.ctrlKey || e.metaKey))) {
      e.preventDefault();
      this.history('redo');
      return;
    }
    if (e.ctrlKey || e.metaKey || e.altKey) return;
    if (e.key === 'Escape') { this.setTool('pan'); return; }
    const letter = e.key.toUpperCase();
    if ([...this.assignment.options].some((o) => o.value === letter)) this.assignment.value = letter;
  }

  /** The snapping request for pointer position `p` (pattern units). */
  snapRequest(p, anchors, exclude = null) {
    return {
      point: p,
      radius: SNAP_PIXELS * this.view.unitsPerPixel(),
      grid: Number(this.grid.value),
      angle_step_deg: this.angles.checked ? ANGLE_STEP : null,
      anchors,
      exclude_vertex: exclude,
    };
  }

  snap(p, anchors, exclude = null) {
    return call(`/api/docs/${this.doc.id}/snap`, {
      method: 'POST',
      headers: { 'content-type': 'application/json' },
      body: JSON.stringify(this.snapRequest(p, anchors, exclude)),
    });
  }

  /** Anchors of the angle lines: the crease's start, or the dragged vertex's neighbours. */
  anchors() {
    if (this.drag) return this.drag.neighbours.map((v) => this.doc.vertices[v]);
    return this.start ? [this.start] : [];
  }

  /** Snaps the latest pointer position, one request at a time, and previews it. */
  async track(p) {
    this.pending = p;
    if (this.snapping) return;
    this.snapping = true;
    try {
      while (this.pending) {
        const q = this.pending;
        this.pending = null;
        const s = await this.snap(q, this.anchors(), this.drag ? this.drag.vertex : null);
        this.preview(s);
      }
    } catch (e) {
      this.info.textContent = e.message;
    } finally {
      this.snapping = false;
    }
  }

  preview(s) {
    this.last = s;
    if (this.tool === 'draw') this.view.previewCrease(this.start, s);
    if (this.tool === 'move' && this.drag) this.view.previewMove(this.drag.vertex, s);
    this.info.textContent = `(${s.point[0].toFixed(2)}, ${s.point[1].toFixed(2)}) ${s.kind}`;
  }

  async down(e) {
    if (!this.doc || e.button !== 0) return;
    const p = this.view.toPattern(e);
    if (this.tool === 'draw') {
      const s = await this.snap(p, this.anchors());
      if (!this.start) {
        this.start = s.point;
        this.view.previewCrease(this.start, s);
      } else {
        const from = this.start;
        this.start = null;
        this.view.clearPreview();
        await this.send({ op: 'add', from, to: s.point, assignment: this.assignment.value });
      }
    } else if (this.tool === 'move') {
      const v = this.view.nearestVertex(p, SNAP_PIXELS * this.view.unitsPerPixel());
      if (v == null) return;
      const neighbours = this.doc.edges.filter((ed) => ed.v.includes(v)).map((ed) => (ed.v[0] === v ? ed.v[1] : ed.v[0]));
      this.drag = { vertex: v, neighbours, moved: false };
      this.view.svg.setPointerCapture(e.pointerId);
    }
  }

  move(e) {
    if (!this.doc) return;
    if (this.tool === 'draw' || (this.tool === 'move' && this.drag)) {
      if (this.drag) this.drag.moved = true;
      this.track(this.view.toPattern(e));
    }
  }

  async up(e) {
    if (this.tool !== 'move' || !this.drag) return;
    const drag = this.drag;
    if (!drag.moved) { this.drag = null; return; }
    // The final position, snapped exactly where the pointer was let go.
    const s = await this.snap(this.view.toPattern(e), this.anchors(), drag.vertex);
    this.drag = null;
    this.view.clearPreview();
    await this.send({ op: 'move', vertex: drag.vertex, to: s.point });
  }

  async edgeClicked(i) {
    if (!this.doc) return;
    if (this.tool === 'delete') await this.send({ op: 'delete', edge: i });
    if (this.tool === 'assign') await this.send({ op: 'assign', edge: i, assignment: this.assignment.value });
  }

  async send(edit) {
    try {
      const view = await call(`/api/docs/${this.doc.id}/edit`, {
        method: 'POST',
        headers: { 'content-type': 'application/json' },
        body: JSON.stringify(edit),
      });
      await this.onChange(view);
    } catch (e) {
      this.info.textContent = e.message;
      this.view.show(this.doc, null, true);
    }
  }

  async history(which) {
    if (!this.doc) return;
    if (which === 'undo' && !this.doc.history.undo) return;
    if (which === 'redo' && !this.doc.history.redo) return;
    const view = await call(`/api/docs/${this.doc.id}/${which}`, { method: 'POST' });
    await this.onChange(view);
  }
}
