// The playground page: wires the editor, the panels and the worker together.
// The interpreter and the drawing live in a module worker (worker.js) that
// owns the canvas and the view state, so big toolpaths never cross into this
// thread. Every run request carries a generation number; answers to older
// generations are dropped.

import { createEditor } from './dist/editor.js';
import { showDiagnostics } from './modules/diagnostics.js';
import { DEFAULT_EXAMPLE, EXAMPLES, exampleById } from './modules/examples.js';
import { initOffsets, renderOffsets, setProgramRegisters } from './modules/offsets.js';
import { initSettings, openSetupJson, renderSettings } from './modules/settings.js';
import { cloneSetup, machineOf } from './modules/setup.js';
import { showState } from './modules/state.js';
import { initStepper, pause, stepReported } from './modules/stepper.js';
import { initStorage, loadWork, saveWork } from './modules/storage.js';
import { initView, setMachinePlanes, viewReported, viewState } from './modules/view.js';

/** Re-run this long after the last keystroke. */
const DEBOUNCE_MS = 150;

const $ = (id) => document.getElementById(id);
const canvas = $('view');
const summaryLine = $('summary');

initStorage((message) => showBanner(message, { kind: 'storage' }));
const saved = loadWork();
let setup = cloneSetup(saved?.setup ?? DEFAULT_EXAMPLE.setup);
let setupOverride = typeof saved?.setupText === 'string' ? saved.setupText : null; // JSON text that did not parse
let exampleId = saved ? saved.example ?? null : DEFAULT_EXAMPLE.id;
let pendingView = saved?.view ?? null; // applied by the worker after the next run
let blockCount = 0;
let currentBlock = null;
let previousWork = null;

const worker = new Worker(new URL('./worker.js', import.meta.url), { type: 'module' });
const post = (message) => worker.postMessage(message);

const editor = createEditor($('editor'), {
  doc: saved?.program ?? DEFAULT_EXAMPLE.program,
  label: 'Program (G-code)',
  onChange: (text) => {
    // Once the text is no longer the example's, its note no longer applies.
    if (exampleId && exampleById(exampleId)?.program !== text) {
      exampleId = null;
      showNote();
    }
    scheduleRun();
    persist();
  },
  onCursorLine: (line) => post({ type: 'line', line }),
});
$('undo').addEventListener('click', () => editor.undo());
$('redo').addEventListener('click', () => editor.redo());

// --- the setup: one object, edited by the offset table, the settings form
// and the raw JSON, which all follow it.
const getSetup = () => setup;
function change(mutate, source) {
  mutate(setup);
  setupOverride = null;
  if (source !== 'offsets') renderOffsets({ force: true });
  renderSettings();
  scheduleRun();
  persist();
}
function replace(parsed, text) {
  if (parsed && typeof parsed === 'object' && !Array.isArray(parsed)) {
    setup = parsed;
    setupOverride = null;
    renderOffsets({ force: true });
    renderSettings({ json: false });
  } else {
    setupOverride = text;
  }
  scheduleRun();
  persist();
}
initOffsets({ getSetup, change });
initSettings({ getSetup, change, replace });
renderOffsets({ force: true });
renderSettings();
if (setupOverride !== null) $('setup').value = setupOverride;

// --- runs
let requested = 0;
let timer = 0;
function requestRun() {
  clearTimeout(timer);
  delete document.body.dataset.pending;
  requested += 1;
  document.body.dataset.requested = String(requested);
  post({
    type: 'run',
    gen: requested,
    program: editor.getText(),
    setup: setupOverride ?? JSON.stringify(setup),
    view: pendingView,
  });
  pendingView = null;
}
function scheduleRun() {
  clearTimeout(timer);
  // Tests (and anyone curious) can tell an edit waiting for its run.
  document.body.dataset.pending = 'true';
  timer = setTimeout(requestRun, DEBOUNCE_MS);
}

function persist() {
  saveWork({ program: editor.getText(), setup, setupText: setupOverride, view: viewState(), example: exampleId });
}

// --- what the worker says
worker.addEventListener('message', (event) => {
  const m = event.data;
  if (m.type === 'result') {
    if (m.gen < requested) return; // stale: a newer request is on its way
    showResult(m);
    document.body.dataset.rendered = String(m.gen);
  } else if (m.type === 'state') {
    showViewState(m);
  } else if (m.type === 'drawn') {
    document.body.dataset.drawn = `${m.width}x${m.height}@${m.dpr}`;
  } else if (m.type === 'failure') {
    showFailure(m.message);
  }
});
worker.addEventListener('error', (event) => {
  event.preventDefault();
  showFailure(`the interpreter could not start: ${event.message || 'worker error'}`);
});

const plural = (n, word) => `${n} ${word}${n === 1 ? '' : 's'}`;
function endText(end) {
  switch (end.reason) {
    case 'program_end': return `program end at line ${end.line}`;
    case 'error': return end.line > 0 ? `stopped at line ${end.line}` : 'stopped: bad setup';
    default: return 'ran to the last block';
  }
}

function showResult({ summary, diagnostics }) {
  summaryLine.textContent = [
    plural(summary.blocks, 'block'), plural(summary.moves, 'move'), plural(summary.errors, 'error'),
    plural(summary.warnings, 'warning'), `${summary.machine}, ${summary.units}`, endText(summary.end),
  ].join(' · ');
  summaryLine.classList.toggle('has-errors', summary.errors > 0);
  showDiagnostics($('diagnostics'), diagnostics, {
    jump: (line, column, end) => editor.jumpTo(line, column, end),
    openSetup: openSetupJson,
  });
  editor.setDiagnostics(diagnostics);
  setProgramRegisters(summary.registers ?? []);
  setMachinePlanes(summary.machine);
}

function showViewState(m) {
  viewReported(m.view);
  blockCount = m.blocks;
  if (m.block !== undefined) currentBlock = m.block;
  if (m.step < 0) currentBlock = null;
  stepReported(m.step, m.blocks, currentBlock, m.stepSeq);
  showState($('state-panel'), currentBlock, { blocks: blockCount });
  editor.showCurrent(currentBlock ? currentBlock.line : null, m.cause !== 'line');
  if (['view', 'step', 'pick', 'line'].includes(m.cause)) persist();
}

function showFailure(text) {
  summaryLine.textContent = `Internal error: ${text}`;
  summaryLine.classList.add('has-errors');
  console.warn('offsetlab:', text);
}

// --- banner (storage problems, example loaded with a way back)
function showBanner(message, { kind, action, onAction } = {}) {
  const banner = $('banner');
  if (!message) {
    if (banner.dataset.kind === kind) banner.hidden = true;
    return;
  }
  banner.dataset.kind = kind;
  banner.querySelector('.text').textContent = message;
  const button = $('banner-action');
  button.hidden = !action;
  button.textContent = action ?? '';
  button.onclick = onAction ?? null;
  banner.hidden = false;
}
$('banner-close').addEventListener('click', () => {
  $('banner').hidden = true;
});

// --- examples
const exampleSelect = $('example');
for (const ex of EXAMPLES) exampleSelect.add(new Option(ex.title, ex.id));
if (exampleId) exampleSelect.value = exampleId;
function showNote() {
  $('example-note').textContent = exampleById(exampleId)?.note ?? '';
}
function loadDocument({ program, setup: next, view, example }) {
  pause();
  exampleId = example ?? null;
  setup = cloneSetup(next);
  setupOverride = null;
  editor.setText(program);
  renderOffsets({ force: true });
  renderSettings();
  showNote();
  const plane = view?.plane ?? (machineOf(setup) === 'lathe' ? 'ZX' : 'XY');
  pendingView = { plane, zoom: 1, pan: [0, 0], step: -1 };
  requestRun();
  persist();
}
$('examples').addEventListener('submit', (event) => {
  event.preventDefault();
  const ex = exampleById(exampleSelect.value);
  if (!ex) return;
  // Keep the user's own work (not an untouched example) one click away.
  const shown = exampleById(exampleId);
  const untouched = shown && shown.program === editor.getText() && JSON.stringify(shown.setup) === JSON.stringify(setup);
  if (!untouched) previousWork = { program: editor.getText(), setup: cloneSetup(setup), example: exampleId };
  loadDocument({ ...ex, example: ex.id });
  showBanner(`Loaded “${ex.title}”.`, {
    kind: 'example',
    action: previousWork ? 'Restore my previous program' : undefined,
    onAction: () => {
      if (previousWork) loadDocument(previousWork);
      previousWork = null;
      showBanner(null, { kind: 'example' });
    },
  });
});
showNote();

// --- help
function toggleHelp() {
  const help = $('help');
  help.hidden = !help.hidden;
  $('help-toggle').setAttribute('aria-expanded', String(!help.hidden));
}
$('help-toggle').addEventListener('click', toggleHelp);

// --- the view: the worker draws on the canvas from now on
const scheme = matchMedia('(prefers-color-scheme: dark)');
const theme = () => (scheme.matches ? 'dark' : 'light');
scheme.addEventListener('change', () => post({ type: 'theme', name: theme() }));

function canvasSize() {
  const box = canvas.getBoundingClientRect();
  return { width: Math.max(1, Math.round(box.width)), height: Math.max(1, Math.round(box.height)), dpr: window.devicePixelRatio || 1 };
}
const offscreen = canvas.transferControlToOffscreen();
worker.postMessage({ type: 'init', canvas: offscreen, theme: theme(), ...canvasSize() }, [offscreen]);

let lastSize = '';
let sizeFrame = 0;
function reportSize() {
  cancelAnimationFrame(sizeFrame);
  sizeFrame = requestAnimationFrame(() => {
    const size = canvasSize();
    const key = `${size.width}x${size.height}@${size.dpr}`;
    if (key === lastSize) return;
    lastSize = key;
    post({ type: 'resize', ...size });
  });
}
new ResizeObserver(reportSize).observe(canvas);
// Zooming the page or moving it to another screen changes devicePixelRatio.
function watchPixelRatio() {
  const query = matchMedia(`(resolution: ${window.devicePixelRatio || 1}dppx)`);
  query.addEventListener('change', () => {
    reportSize();
    watchPixelRatio();
  }, { once: true });
}
watchPixelRatio();

initView(canvas, post);
const centreZoom = (factor) => {
  const r = canvas.getBoundingClientRect();
  post({ type: 'view', op: 'zoom', x: r.width / 2, y: r.height / 2, factor });
};
initStepper(post, { fit: () => post({ type: 'view', op: 'fit' }), zoom: centreZoom, toggleHelp });

requestRun();

// For the console and later modules (share links): read-only views of the state.
window.offsetlab = Object.freeze({
  viewState,
  program: () => editor.getText(),
  selection: () => editor.selection(),
  setup: () => cloneSetup(setup),
});
