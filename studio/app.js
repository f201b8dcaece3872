// The studio page: opens patterns (command-line files, the file picker, drag and drop),
// shows counts, legend and check findings, and drives the three views.
import { call, stream, upload, mainFile } from './api.js';
import { PatternView } from './cp.js';
import { FoldView } from './fold.js';
import { MachineView } from './machine.js';
import { Editor } from './edit.js';
import { FlatView } from './flat.js';
import { FoldingView } from './folding.js';
import { TessellationView } from './tessellate.js';
import { VoxelView } from './voxel.js';
import { PopupView } from './popup.js';
import { CraftView } from './craft.js';
import { StartScreen } from './start.js';

const $ = (id) => document.getElementById(id);
const state = { doc: null, legend: null, findings: [], fold: null, foldView: null, planned: false };
const patternView = new PatternView($('cp-svg'), $('cp-canvas'), $('hover-info'));
const machineView = new MachineView($('view-machine'));
const editor = new Editor(patternView, $('edit-tools'), (view) => guarded(() => edited(view)));
const flatView = new FlatView($('view-flat'));
machineView.onError = (promise) => guarded(() => promise);
// A plan warning about lines of the pattern rings them there.
machineView.onShowEdges = (edges) => guarded(async () => {
  await switchView('pattern');
  patternView.ringEdges(edges, state.legend.fault);
});
// The fold-sequence designer; its crease pattern opens as a document in the pattern view.
new FoldingView($('view-folding'), async (view) => { await opened(view); await switchView('pattern'); }, guarded);
// A test hook: browser tests compare the lines drawn on the paper with the paper.
window.tessellationView = new TessellationView($('view-tessellate'), async (view) => { await opened(view); await switchView('pattern'); }, guarded);
// The voxel pop-up editor; its crease pattern opens as a document the same way.
new VoxelView($('view-voxel'), async (view) => { await opened(view); await switchView('pattern'); }, guarded);
// The polygon pop-up editor; its saved design opens as a document in the pattern view.
new PopupView($('view-popup'), async (view) => { await opened(view); await switchView('pattern'); }, guarded);
new CraftView($('view-craft'), async (view) => { await opened(view); await switchView('pattern'); }, guarded);
// The opening screen (examples, blank sheet) and the Save menu.
const startScreen = new StartScreen(async (view) => { await opened(view); await switchView('pattern'); }, guarded);
// A test hook: browser tests wait for the first end of a crease being drawn.
window.patternEditor = editor;
let edits = 0;

/** Shows `e` (or hides the box for null) above the view, in the page's flow so that it covers
 * nothing, with a button that closes it. */
/** The file name of `path` (after its last `/` or `\\`): the page shows it, with the whole
 * path on hover. */
function shortName(path) {
  return String(path).split(/[\\/]/).pop() || String(path);
}

function showError(e) {
  const box = $('error');
  box.replaceChildren();
  if (e) {
    const message = document.createElement('span');
    message.id = 'error-text';
    message.textContent = String(e.message || e);
    const close = document.createElement('button');
    close.id = 'error-close';
    close.textContent = '×';
    close.title = 'Close';
    close.setAttribute('aria-label', 'Close the message');
    close.addEventListener('click', () => showError(null));
    box.append(message, close);
  }
  box.hidden = !e;
}

/** Runs an async action, showing its error (the server's message) in the page, and `label`
 * (what is being done) while it runs. */
async function guarded(action, label = '') {
  try {
    showError(null);
    document.body.dataset.busy = 'true';
    $('busy').textContent = label;
    $('busy').hidden = !label;
    return await action();
  } catch (e) {
    showError(e);
  } finally {
    delete document.body.dataset.busy;
    $('busy').hidden = true;
  }
}

const DESIGN = /\.(txt|png|obj|stl|toml)$/i;
const MESH = /\.(obj|stl)$/i;

/** What the page says while `name` is opened: design files are built first (a tessellation
 * solves for seconds). */
function openingLabel(name) {
  if (!DESIGN.test(name)) return `opening ${name}…`;
  const make = $('mesh-make').value;
  const what = MESH.test(name) ? (make === 'auto' ? 'a tessellation or pop-up card' : make === 'popup' ? 'a pop-up card' : 'a tessellation')
    : 'the design';
  return `building ${what} from ${name}… (this can take a while)`;
}

/** Opens files dropped or picked together; a mesh set is kept to rebuild when the choice of
 * what a mesh makes changes. */
function openFiles(list) {
  const files = Array.from(list);
  if (!files.length) return;
  const main = mainFile(files);
  state.meshFiles = MESH.test(main.name) ? files : null;
  guarded(async () => opened(await upload(files, $('mesh-make').value)), openingLabel(main.name));
}

function showLegend(legend) {
  $('legend').replaceChildren(...legend.assignments.map((a) => {
    const li = document.createElement('li');
    const dash = a.dash ? a.dash.map((d) => d * 1.5).join(' ') : 'none';
    li.innerHTML = `<svg width="46" height="10"><line x1="2" y1="5" x2="44" y2="5" stroke="${a.colour}" ` +
      `stroke-width="${a.width * 1.5}" stroke-dasharray="${dash}"/></svg> ${a.name} (${a.letter})`;
    return li;
  }));
}

function showCounts(view) {
  const a = view.counts.assignments;
  $('count-vertices').textContent = view.counts.vertices;
  $('count-edges').textContent = view.counts.edges;
  $('count-M').textContent = a.mountain;
  $('count-V').textContent = a.valley;
  $('count-B').textContent = a.boundary;
  $('count-other').textContent = `${a.flat}, ${a.unassigned}, ${a.cut}, ${a.join}`;
  $('doc-name').textContent = shortName(view.name);
  $('doc-name').title = view.name;
  $('made').textContent = view.made ? `Built from a design file: ${view.made}.` : '';
  $('messages').replaceChildren(...view.messages.map((m) => {
    const li = document.createElement('li');
    li.textContent = m;
    return li;
  }));
}

function selectFinding(k) {
  const f = state.findings[k];
  document.querySelectorAll('#findings li').forEach((li, i) => li.classList.toggle('selected', i === k));
  patternView.ring(state.findings, state.legend.fault, k);
  patternView.zoomTo(f.position[0], f.position[1]);
}

async function runCheck() {
  showFindings(await call(`/api/docs/${state.doc.id}/check`));
}

/** The Kawasaki tolerance query of the layer-order calls: empty fits it to the drawing. */
function toleranceQuery() {
  const t = $('kawasaki-tolerance').value.trim();
  return t ? `kawasaki_tolerance=${encodeURIComponent(t)}` : '';
}

async function runLayers() {
  $('layers-result').textContent = 'solving…';
  let result;
  try {
    result = await call(`/api/docs/${state.doc.id}/layers?${toleranceQuery()}`);
  } catch (e) {
    $('layers-result').textContent = '';
    throw e;
  }
  $('layers-result').textContent = result.text;
  showFindings(result.check);
}

function showFindings(report) {
  state.findings = report.findings;
  const status = $('check-status');
  const warnings = (report.warnings || []).length;
  let passed = warnings ? `passed, ${warnings} Kawasaki error(s) within the drawing's precision` : 'passed';
  // Vertices whose creases fold to less than 180° (a 3D target) are not judged by Kawasaki and
  // Maekawa: a pass there has not shown that the pattern folds (as the CLI's verdict says).
  const unchecked = report.unchecked_vertices || 0;
  if (unchecked) {
    passed += `, but not checked at ${unchecked} ${unchecked === 1 ? 'vertex' : 'vertices'}: 3D targets (a crease folds to less than 180°)`;
  }
  status.textContent = report.findings.length ? `${report.findings.length} finding(s)` : passed;
  status.className = report.findings.length ? 'fail' : unchecked ? 'unchecked' : 'pass';
  $('findings').replaceChildren(...report.findings.map((f, k) => {
    const li = document.createElement('li');
    li.textContent = f.message;
    li.title = f.hint;
    li.className = `finding finding-${f.kind}`;
    li.addEventListener('click', () => selectFinding(k));
    return li;
  }));
  patternView.ring(report.findings, state.legend.fault);
}

/** Forgets what was computed from the previous pattern (fold, plan, layer order). */
function forgetDerived() {
  state.fold = null;
  state.flat = false;
  flatView.clear();
  delete document.body.dataset.flat;
  state.planned = false;
  delete document.body.dataset.foldPercent;
  delete document.body.dataset.foldStage;
  delete document.body.dataset.planned;
  $('fold-label').textContent = 'not folded yet';
  $('fold-report').textContent = '';
  $('layers-result').textContent = '';
  $('plan-stats').replaceChildren();
  $('downloads').replaceChildren();
  $('toolpath-svg').replaceChildren();
}

/** Shows the pattern after an edit, undo or redo, and checks it again. */
async function edited(view) {
  state.doc = view;
  forgetDerived();
  showCounts(view);
  patternView.show(view, null, true);
  editor.setDoc(view);
  await runCheck();
  edits += 1;
  document.body.dataset.edits = String(edits);
}

/** Shows a newly opened document (the API's pattern view with its id). */
async function opened(view) {
  startScreen.hide();
  state.doc = view;
  forgetDerived();
  showCounts(view);
  patternView.show(view, state.legend);
  editor.setDoc(view);
  await runCheck();
  document.body.dataset.doc = view.id;
  const active = document.querySelector('#tabs button.active').dataset.view;
  await enterView(active);
}

/** Folds the document in 3D: the flat sheet first, at once (`fold3d?flat=true`), then the
 * simulation, which starts from that sheet; its frames are shown as they arrive
 * (`fold3d?stream=true`), then the whole fold. `body[data-fold-stage]` says which is shown
 * (`flat`, `folding` from the first folded frame, then `folded`). */
async function foldNow() {
  if (!state.foldView) state.foldView = new FoldView($('fold-canvas'));
  const doc = state.doc;
  $('fold-label').textContent = 'folding…';
  const flat = await call(`/api/docs/${doc.id}/fold3d?flat=true`);
  if (state.doc !== doc) return;
  state.fold = flat;
  state.foldView.show(flat);
  showFoldFrame();
  document.body.dataset.foldStage = 'flat';
  $('fold-label').textContent = 'the flat sheet; folding…';
  let fold = null;
  await stream(`/api/docs/${doc.id}/fold3d?stream=true`, (line) => {
    if (state.doc !== doc) return;
    if (line.error) throw new Error(line.error.error);
    if (line.frame) {
      state.foldView.showFrame(line.frame);
      $('fold-label').textContent = `folding… ${line.frame.percent.toFixed(0)}% reached`;
      document.body.dataset.foldStage = 'folding';
    }
    if (line.done) fold = line.done;
  });
  if (state.doc !== doc) return;
  if (!fold) throw new Error('the fold ended without its result');
  state.fold = fold;
  state.foldView.show(fold);
  const r = fold.report;
  const method = r.static_solve && r.static_solve.used
    ? `static solve, ${r.static_solve.linear_solves} linear solves`
    : `${r.steps} steps`;
  $('fold-report').textContent = `Bar-and-hinge simulation (Ghassaei, Demaine & Gershenfeld 2018): ` +
    `${r.triangles} triangles, ${method}, ${r.stop.replace('_', ' ')}, ${r.seconds.toFixed(1)} s; largest bar strain ` +
    `${(100 * r.max_strain).toFixed(3)}%; ${r.crossing_faces.length} pair(s) of faces passing through each other` +
    (r.past_flat.length ? `; ${r.past_flat.length} crease(s) folded past flat (their faces pass through each other).` : '.');
  showFoldFrame();
  document.body.dataset.foldStage = 'folded';
}

function showFoldFrame() {
  const frame = state.foldView.showPercent(Number($('fold-slider').value));
  $('fold-label').textContent = `${frame.percent.toFixed(0)}% of every fold angle` +
    (frame.settled ? '' : frame.blended ? ' (blended between two computed states)' : ' (while folding)');
  document.body.dataset.foldPercent = frame.percent.toFixed(1);
}

async function enterView(name) {
  if (!state.doc) return;
  if (name === 'fold' && !state.fold) await guarded(foldNow);
  if (name === 'fold' && state.foldView) state.foldView.draw();
  if (name === 'flat' && !state.flat) await guarded(showFlat);
}

async function showFlat() {
  state.flat = true;
  const view = await flatView.load(state.doc.id);
  document.body.dataset.flat = `${view.state}/${view.states}`;
}

function switchView(name) {
  document.querySelectorAll('#tabs button').forEach((b) => b.classList.toggle('active', b.dataset.view === name));
  document.querySelectorAll('.view').forEach((v) => { v.hidden = v.id !== `view-${name}`; });
  return enterView(name);
}

async function start() {
  state.legend = await call('/api/legend');
  showLegend(state.legend);
  await machineView.load();
  const files = await call('/api/files');
  $('cli-files').replaceChildren(...files.map((f) => {
    const b = document.createElement('button');
    b.textContent = shortName(f.name);
    b.title = f.name;
    const open = async () => opened(await call(`/api/files/${f.index}?make=${$('mesh-make').value}`, { method: 'POST' }));
    b.addEventListener('click', () => guarded(open, openingLabel(f.name)));
    return b;
  }));
  document.querySelectorAll('#tabs button').forEach((b) => b.addEventListener('click', () => switchView(b.dataset.view)));
  $('file-input').addEventListener('change', (e) => {
    // Taken, then cleared: the next pick is a new set (and the same file can be picked again).
    const files = Array.from(e.target.files);
    e.target.value = '';
    openFiles(files);
  });
  $('mesh-make').addEventListener('change', () => { if (state.meshFiles) openFiles(state.meshFiles); });
  document.body.addEventListener('dragover', (e) => { e.preventDefault(); document.body.classList.add('dragging'); });
  document.body.addEventListener('dragleave', () => document.body.classList.remove('dragging'));
  document.body.addEventListener('drop', (e) => {
    e.preventDefault();
    document.body.classList.remove('dragging');
    openFiles(e.dataTransfer.files);
  });
  $('layers-btn').addEventListener('click', () => guarded(async () => {
    if (!state.doc) throw new Error('open a pattern first');
    await runLayers();
  }));
  $('flat-btn').addEventListener('click', () => guarded(async () => {
    if (!state.doc) throw new Error('open a pattern first');
    await showFlat();
  }));
  $('fold-slider').addEventListener('input', () => { if (state.fold) showFoldFrame(); });
  $('plan-btn').addEventListener('click', () => guarded(async () => {
    if (!state.doc) throw new Error('open a pattern first');
    await machineView.plan(state.doc.id);
    state.planned = true;
    document.body.dataset.planned = 'true';
  }));
  await startScreen.load();
  if (files.length) {
    await guarded(async () => opened(await call(`/api/files/0?make=${$('mesh-make').value}`, { method: 'POST' })),
      openingLabel(files[0].name));
  } else {
    startScreen.show();
  }
  document.body.dataset.ready = 'true';
}

guarded(start);
