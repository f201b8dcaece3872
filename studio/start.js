// Starting and saving: the opening screen (the bundled examples, grouped as Origami
// Simulator's Examples menu groups its own, and a blank sheet), the "New…" button that shows
// it again, and the Save menu (FOLD, SVG, .cp, .opx, the folded form as FOLD). Ctrl+S (⌘S)
// saves in the format used last, remembered in the browser's localStorage.
import { call } from './api.js';

/** What the Save menu offers: the `format` of `GET /api/docs/{id}/save` and its label. */
export const SAVE_FORMATS = [
  { format: 'fold', label: 'FOLD (.fold)' },
  { format: 'svg', label: 'SVG (.svg)' },
  { format: 'cp', label: 'ORIPA (.cp)' },
  { format: 'opx', label: 'ORIPA XML (.opx)' },
  { format: 'folded', label: 'Folded form (FOLD, opens in Origami Simulator)' },
];

/** The localStorage key of the format Ctrl+S uses. */
const LAST_FORMAT = 'foldcam.saveFormat';

function el(tag, attrs = {}, text = '') {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
  if (text) e.textContent = text;
  return e;
}

/** The format Ctrl+S saves in: the last one chosen, FOLD at first. */
function lastFormat() {
  let f = null;
  try { f = localStorage.getItem(LAST_FORMAT); } catch { /* storage off: FOLD */ }
  return SAVE_FORMATS.some((s) => s.format === f) ? f : 'fold';
}

/** The file name a download's Content-Disposition gives, or `fallback`. */
function fileName(response, fallback) {
  const d = response.headers.get('content-disposition') || '';
  const m = /filename="([^"]+)"/.exec(d);
  return m ? m[1] : fallback;
}

/** Saves document `id` as `format`: fetched first, so an error shows in the page instead of
 * being downloaded as a file. Resolves to the file name. */
export async function saveDocument(id, format) {
  const url = `/api/docs/${id}/save?format=${encodeURIComponent(format)}`;
  const response = await fetch(url);
  if (!response.ok) {
    const text = await response.text();
    let message = `${url}: ${response.status}`;
    try { message = JSON.parse(text).error || message; } catch { /* not JSON */ }
    throw new Error(message);
  }
  const name = fileName(response, `pattern.${format}`);
  const href = URL.createObjectURL(await response.blob());
  const a = el('a', { href, download: name });
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(href), 60000);
  return name;
}

/** The opening screen and the Save menu. */
export class StartScreen {
  /**
   * `onOpened(view)` shows a document the API opened; `guarded(action, label)` runs an
   * action and shows its error in the page.
   */
  constructor(onOpened, guarded) {
    const $ = (id) => document.getElementById(id);
    this.dialog = $('start');
    this.list = $('start-examples');
    this.onOpened = onOpened;
    this.guarded = guarded;
    this.saveButton = $('save-btn');
    this.saveMenu = $('save-menu');
    $('new-btn').addEventListener('click', () => this.show());
    $('start-close').addEventListener('click', () => this.hide());
    $('start-blank').addEventListener('click', () => this.open('/api/blank', 'opening a blank sheet…'));
    this.dialog.addEventListener('click', (e) => { if (e.target === this.dialog) this.hide(); });
    this.saveMenu.replaceChildren(...SAVE_FORMATS.map((s) => {
      const b = el('button', { 'data-format': s.format, role: 'menuitem' }, s.label);
      b.addEventListener('click', () => { this.closeMenu(); this.save(s.format); });
      return b;
    }));
    this.saveButton.addEventListener('click', (e) => {
      e.stopPropagation();
      if (this.saveMenu.hidden) this.openMenu(); else this.closeMenu();
    });
    document.addEventListener('click', (e) => { if (!this.saveMenu.contains(e.target)) this.closeMenu(); });
    document.addEventListener('keydown', (e) => this.key(e));
    this.showLast();
  }

  /** Reads the examples' list from the server and lists them by group. */
  async load() {
    const groups = await call('/api/examples');
    this.list.replaceChildren(...groups.map((g) => {
      const section = el('section', { class: 'start-group' });
      section.append(el('h3', {}, g.group));
      for (const x of g.examples) {
        const b = el('button', { 'data-example': x.name, title: x.description }, x.title);
        b.append(el('span', { class: 'muted' }, x.description));
        b.addEventListener('click', () => this.open(`/api/examples/${encodeURIComponent(x.name)}`,
          `opening ${x.file}…`));
        section.append(b);
      }
      return section;
    }));
  }

  show() {
    this.dialog.hidden = false;
    document.body.dataset.start = 'open';
    this.dialog.querySelector('button[data-example], #start-blank')?.focus();
  }

  hide() {
    this.dialog.hidden = true;
    delete document.body.dataset.start;
  }

  /** Opens what `url` (a POST) makes, closing the screen first. */
  open(url, label) {
    this.hide();
    return this.guarded(async () => this.onOpened(await call(url, { method: 'POST' })), label);
  }

  key(e) {
    if (e.key === 'Escape') {
      if (!this.dialog.hidden) this.hide();
      this.closeMenu();
      return;
    }
    if (e.key.toLowerCase() === 's' && (e.ctrlKey || e.metaKey) && !e.altKey && !e.shiftKey) {
      e.preventDefault();
      this.save(lastFormat());
    }
  }

  openMenu() {
    this.saveMenu.hidden = false;
    this.saveButton.setAttribute('aria-expanded', 'true');
  }

  closeMenu() {
    this.saveMenu.hidden = true;
    this.saveButton.setAttribute('aria-expanded', 'false');
  }

  /** Marks the format Ctrl+S uses in the menu. */
  showLast() {
    const last = lastFormat();
    for (const b of this.saveMenu.querySelectorAll('button')) {
      b.classList.toggle('last', b.dataset.format === last);
    }
    this.saveButton.title = `Save the pattern (Ctrl+S saves as ${SAVE_FORMATS.find((s) => s.format === last).label})`;
  }

  /** Saves the open document as `format` and remembers the format for Ctrl+S. */
  save(format) {
    return this.guarded(async () => {
      const id = document.body.dataset.doc;
      if (id === undefined) throw new Error('nothing to save yet: open an example, a blank sheet or a file first');
      try { localStorage.setItem(LAST_FORMAT, format); } catch { /* storage off: not remembered */ }
      this.showLast();
      const name = await saveDocument(id, format);
      document.body.dataset.saved = name;
      document.body.dataset.saves = String(Number(document.body.dataset.saves || 0) + 1);
    }, format === 'folded' ? 'folding to save the folded form…' : `saving as ${format}…`);
  }
}
