// The playground page: wires the editor, the panels and the worker together.
// The interpreter and the drawing live in a module worker (worker.js) that
// owns the canvas and the view state, so big toolpaths never cross into this
// thread. Every run request carries a generation number; answers to older
// generations are dropped.
//
// Links (issue 5): a link in the fragment — compact `#v1.…` or plain
// `#program=…` — is decoded by the worker (the Rust codec) on load and on
// `hashchange` and opened without destroying the user's own work, which is
// kept one click away ("Restore my previous program", across reloads too).
// The address bar follows the document (modules/address.js); `embed=1` shows
// the drawing, the step controls and a read-only editor only.

import { createEditor } from './dist/editor.js';
import { addressChanged, initAddress, writtenFragment } from './modules/address.js';
import { showDiagnostics } from './modules/diagnostics.js';
import { DEFAULT_EXAMPLE, EXAMPLES, exampleById } from './modules/examples.js';
import { initExport } from './modules/export.js';
import { initOffsets, renderOffsets, setProgramRegisters } from './modules/offsets.js';
import { initSettings, openSetupJson, renderSettings } from './modules/settings.js';
import { cloneSetup, machineOf } from './modules/setup.js';
import { initShare } from './modules/share.js';
import { showState } from './modules/state.js';
import { initStepper, pause, stepReported } from './modules/stepper.js';
import {
  disableStorage, initStorage, keepPrevious, loadPrevious, loadWork, saveWork,
} from './modules/storage.js';
import { initView, setMachinePlanes, viewReported, viewState } from './modules/view.js';

/** Re-run this long after the last keystroke. */
const DEBOUNCE_MS = 150;
/** Files larger than this are not read (the interpreter reads 256 MiB of program). */
const MAX_FILE = 300 * 1024 * 1024;

const $ = (id) => document.getElementById(id);
const canvas = $('view');
const summaryLine = $('summary');
/** The page's address without the fragment: the base of the links it makes. */
const base = location.href.split('#')[0];
/** Embed mode (`embed=1` in the link): known before the link is decoded, so the page never flashes the full layout. */
const EMBED = /(?:^#|&)embed=(?:1|true)(?:&|$)/.test(location.hash);
if (EMBED) {
  document.documentElement.classList.add('embed');
  document.body.classList.add('embed');
  disableStorage();
}

initStorage((message) => showBanner(message, { kind: 'storage' }));
const saved = loadWork();
const startWork = EMBED ? { program: '', setup: {} } : saved ?? { ...DEFAULT_EXAMPLE, example: DEFAULT_EXAMPLE.id };
let setup = cloneSetup(startWork.setup);
let setupOverride = typeof startWork.setupText === 'string' ? startWork.setupText : null; // JSON text that did not parse
// Where the work came from while it is untouched: an example's id, or a link
// or file (fromLink). Untouched work is not kept when another replaces it.
let exampleId = startWork.example ?? null;
let fromLink = Boolean(startWork.link);
let loading = false; // a document is being loaded: its edits are not the user's
let pendingView = startWork.view ?? null; // applied by the worker after the next run
let blockCount = 0;
let currentBlock = null;
let setupFailed = false; // the last run refused the setup
let viewKnown = false; // the worker has reported a view state

const worker = new Worker(new URL('./worker.js', import.meta.url), { type: 'module' });
const post = (message) => worker.postMessage(message);

// Calls answered by the worker (links, documents, exports), in order with the runs.
let callId = 0;
const calls = new Map();
function call(op, args = {}) {
  callId += 1;
  const id = callId;
  return new Promise((resolve, reject) => {
    calls.set(id, { resolve, reject });
    post({ type: 'call', id, op, ...args });
  });
}

const editor = createEditor($('editor'), {
  doc: startWork.program,
  label: EMBED ? 'Program (G-code, read-only)' : 'Program (G-code)',
  readOnly: EMBED,
  onChange: () => {
    edited();
    scheduleRun();
    persist();
  },
  onCursorLine: (line) => post({ type: 'line', line }),
});
$('undo').addEventListener('click', () => editor.undo());
$('redo').addEventListener('click', () => editor.redo());

/** The user changed the program or the setup: the work is now their own. */
function edited() {
  if (loading) return;
  fromLink = false;
  if (exampleId) {
    exampleId = null;
    showNote();
  }
}

// --- the setup: one object, edited by the offset table, the settings form
// and the raw JSON, which all follow it.
const getSetup = () => setup;
function change(mutate, source) {
  mutate(setup);
  setupOverride = null;
  edited();
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
  edited();
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
/** Sends an edit still waiting for its run, so a call that follows sees it. */
function flushRun() {
  if (document.body.dataset.pending) requestRun();
}

/** The work as the page holds it (what autosave keeps). */
function currentWork() {
  // Before the worker first reports its view, the view is still the saved one.
  const view = viewKnown ? viewState() : startWork.view ?? viewState();
  return {
    program: editor.getText(), setup: cloneSetup(setup), setupText: setupOverride, view,
    example: exampleId, link: fromLink,
  };
}

function persist() {
  saveWork(currentWork());
  addressChanged();
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
  } else if (m.type === 'reply') {
    const pending = calls.get(m.id);
    calls.delete(m.id);
    if (!pending) return;
    if (m.error !== undefined) pending.reject(new Error(m.error));
    else pending.resolve(m.value);
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
  setupFailed = diagnostics.some((d) => d.line === 0 && d.code.startsWith('setup-'));
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
  if (m.gen > 0) viewKnown = true; // a state of a run, not the empty session's
  viewReported(m.view);
  blockCount = m.blocks;
  if (m.block !== undefined) currentBlock = m.block;
  if (m.step < 0) currentBlock = null;
  stepReported(m.step, m.blocks, currentBlock, m.stepSeq);
  showState($('state-panel'), currentBlock, { blocks: blockCount });
  editor.showCurrent(currentBlock ? currentBlock.line : null, m.cause !== 'line');
  if (['view', 'step', 'pick', 'line'].includes(m.cause)) persist();
  // A run may move the current block (a shorter program): the autosave follows.
  else if (m.cause === 'run' && viewKnown) saveWork(currentWork());
}

function showFailure(text) {
  summaryLine.textContent = `Internal error: ${text}`;
  summaryLine.classList.add('has-errors');
  console.warn('offsetlab:', text);
}

// --- banner (storage problems, a link or example opened with a way back, a broken link)
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

// --- documents: examples, links and files replace the work; the user's own
// work is kept (storage.js keepPrevious) and one click away.
const exampleSelect = $('example');
for (const ex of EXAMPLES) exampleSelect.add(new Option(ex.title, ex.id));
if (exampleId) exampleSelect.value = exampleId;
function showNote() {
  $('example-note').textContent = exampleById(exampleId)?.note ?? '';
}

/** Work worth keeping: written or changed by the user (not an untouched example, link or file). */
function isOwn(work) {
  if (!work || work.example || work.link) return false;
  return work.program.trim() !== '' || typeof work.setupText === 'string' || Object.keys(work.setup ?? {}).length > 0;
}

/**
 * Shows `work` { program, setup, setupText?, view?: {plane, zoom, pan, step}, example?, link? }:
 * the editor, the panels, then one run with its view and current block.
 */
function loadDocument(work) {
  pause();
  loading = true;
  try {
    exampleId = work.example ?? null;
    fromLink = Boolean(work.link);
    setup = cloneSetup(work.setup);
    setupOverride = typeof work.setupText === 'string' ? work.setupText : null;
    editor.setText(work.program);
  } finally {
    loading = false;
  }
  renderOffsets({ force: true });
  renderSettings();
  if (setupOverride !== null) $('setup').value = setupOverride;
  if (exampleId) exampleSelect.value = exampleId;
  showNote();
  pendingView = viewOf(work);
  requestRun();
  persist();
}

/** The view a work asks for, the machine's defaults filled in. */
function viewOf(work) {
  const v = work.view ?? {};
  return {
    plane: v.plane ?? (machineOf(work.setup) === 'lathe' ? 'ZX' : 'XY'),
    zoom: v.zoom ?? 1,
    pan: v.pan ?? [0, 0],
    step: v.step ?? -1,
  };
}

/** Keeps the current work if it is the user's own; shows the restore button. */
function displaceCurrent() {
  const work = currentWork();
  if (isOwn(work)) keepPrevious(work);
  showRestore();
}

function showRestore() {
  $('restore-previous').hidden = EMBED || !loadPrevious();
}

function restorePrevious() {
  const previous = loadPrevious();
  if (!previous) return;
  // Restoring never destroys own work either: it changes places.
  const now = currentWork();
  keepPrevious(isOwn(now) ? now : null);
  loadDocument({ ...previous, example: null, link: false });
  showRestore();
  showBanner(null, { kind: 'opened' });
  document.body.dataset.restored = String(Date.now());
}
$('restore-previous').addEventListener('click', restorePrevious);

/** Opens a document's work after keeping the user's own, with a banner saying what happened. */
function openWork(work, message) {
  displaceCurrent();
  loadDocument(work);
  const kept = Boolean(loadPrevious());
  showBanner(kept ? `${message} Your previous program is kept.` : message, {
    kind: 'opened',
    action: kept ? 'Restore my previous program' : undefined,
    onAction: restorePrevious,
  });
}

$('examples').addEventListener('submit', (event) => {
  event.preventDefault();
  const ex = exampleById(exampleSelect.value);
  if (!ex) return;
  openWork({ ...ex, example: ex.id }, `Loaded “${ex.title}”.`);
});
showNote();
showRestore();

/** A document of the codec (the document JSON) as the page's work. */
function workOf(doc, extra = {}) {
  const { program = '', view = null, step = null, ...docSetup } = doc;
  return { program, setup: docSetup, view: { ...(view ?? {}), step: step ?? -1 }, link: true, ...extra };
}

/** True when `a` and `b` carry the same program and setup (the codec's canonical JSON). */
async function sameDocument(a, b) {
  if (typeof a.setupText === 'string' || typeof b.setupText === 'string') return false;
  try {
    const [x, y] = await Promise.all([
      call('canonical', { document: { ...a.setup, program: a.program } }),
      call('canonical', { document: { ...b.setup, program: b.program } }),
    ]);
    return x === y;
  } catch {
    return false;
  }
}

function showLinkError(error, what = 'This link') {
  const kept = EMBED ? '' : ' Your own work is unchanged.';
  showBanner(`${what} could not be opened: ${error.message} (${error.code}).${kept}`, { kind: 'link-error' });
  document.body.dataset.linkError = error.code;
}

/**
 * Opens the link in the fragment. `initial`: on page load (the saved work is
 * in the editor and has not run yet). Resolves when the page shows the result.
 */
async function openLink(fragment, { initial = false } = {}) {
  document.body.dataset.link = 'opening';
  let answer;
  try {
    answer = await call('decode', { text: fragment, base });
  } catch (error) {
    answer = { error: { code: 'link-internal', message: error.message } };
  }
  if (answer.error) {
    showLinkError(answer.error);
    if (initial) requestRun();
    document.body.dataset.link = 'error';
    return;
  }
  delete document.body.dataset.linkError;
  showBanner(null, { kind: 'link-error' });
  const work = workOf(answer.document);
  if (answer.embed !== EMBED && !initial) {
    // A link of the other mode pasted into this tab: load the page afresh in its mode.
    location.reload();
    return;
  }
  if (EMBED) {
    $('open-playground').href = answer.playground ?? base;
    loadDocument(work);
  } else if (await sameDocument(work, currentWork())) {
    // The work shown already (say, a reload of an opened link): only its view and step.
    pendingView = viewOf(work);
    requestRun();
  } else {
    openWork(work, 'Opened the program of a shared link, with its offsets and settings.');
  }
  document.body.dataset.link = 'opened';
}

// --- files: a document (.json), a link saved as text or a program (.nc)
async function openFile(file) {
  if (!file) return;
  const what = `The file “${file.name}”`;
  if (file.size > MAX_FILE) {
    showLinkError({ code: 'file-too-large', message: `it is ${Math.round(file.size / 1048576)} MiB; at most ${MAX_FILE / 1048576} MiB are read` }, what);
    return;
  }
  let text;
  try {
    text = await file.text();
  } catch (error) {
    showLinkError({ code: 'file-unreadable', message: error.message }, what);
    return;
  }
  const trimmed = text.trim();
  let answer;
  if (trimmed.startsWith('{')) {
    answer = await call('read', { text });
  } else if (!trimmed.includes('\n') && /^(?:https?:\/\/[^\s#]*)?#?(?:v\d+\.|program=)/.test(trimmed)) {
    answer = await call('decode', { text: trimmed, base });
  } else {
    // A program: it runs with the setup shown.
    answer = { document: { ...cloneSetup(setup), program: text } };
    if (setupOverride !== null) answer.setupText = setupOverride;
  }
  if (answer.error) {
    showLinkError(answer.error, what);
    return;
  }
  const work = workOf(answer.document);
  if (answer.setupText !== undefined) work.setupText = answer.setupText;
  openWork(work, `Opened “${file.name}”.`);
  document.body.dataset.opened = file.name;
}
$('open-file-button').addEventListener('click', () => $('open-file').click());
$('open-file').addEventListener('change', (event) => {
  const [file] = event.target.files;
  event.target.value = '';
  openFile(file);
});
if (!EMBED) {
  // Drop a file anywhere on the page (not into the editor, which takes text).
  const hasFiles = (event) => [...(event.dataTransfer?.types ?? [])].includes('Files');
  document.addEventListener('dragover', (event) => {
    if (!hasFiles(event)) return;
    event.preventDefault();
    event.dataTransfer.dropEffect = 'copy';
    document.body.classList.add('dropping');
  });
  document.addEventListener('dragleave', (event) => {
    if (event.relatedTarget === null) document.body.classList.remove('dropping');
  });
  document.addEventListener('drop', (event) => {
    document.body.classList.remove('dropping');
    if (!hasFiles(event)) return;
    event.preventDefault();
    openFile(event.dataTransfer.files[0]);
  });
}

// --- help
function toggleHelp() {
  if (EMBED) return;
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

// --- share, export and the address bar
/** Programs longer than this are not put in the address bar (their link would be too long to be of use there). */
const ADDRESS_MAX_PROGRAM = 256 * 1024;
/** Links longer than this leave the address bar without a fragment. */
const ADDRESS_MAX_LINK = 32 * 1024;
/**
 * The current document's compact fragment (no `#`); '' for none (a program
 * too long for the address bar); null to leave the address as it is (the
 * setup is refused).
 */
async function currentFragment() {
  if (editor.view.state.doc.length > ADDRESS_MAX_PROGRAM) return '';
  flushRun();
  const answer = await call('document', { base, forms: ['link'] });
  if (answer.setupFailed) return null;
  if (answer.link.length > ADDRESS_MAX_LINK) return '';
  return answer.link.slice(answer.link.indexOf('#') + 1);
}
initShare({ call, flush: flushRun, program: () => editor.getText(), base });
initExport({ call, flush: flushRun, program: () => editor.getText() });

addEventListener('hashchange', () => {
  const fragment = location.hash.slice(1);
  if (!fragment || fragment === writtenFragment()) return;
  openLink(fragment);
});

async function start() {
  const fragment = location.hash.slice(1);
  // The tab's own address (a reload): the autosave is at least as new.
  const own = fragment && fragment === writtenFragment() && saved;
  if (fragment && !own) await openLink(fragment, { initial: true });
  else requestRun();
  if (!EMBED) initAddress(currentFragment);
}
start();

// For the console and the tests: read-only views of the state.
window.offsetlab = Object.freeze({
  viewState,
  program: () => editor.getText(),
  selection: () => editor.selection(),
  setup: () => cloneSetup(setup),
  embed: EMBED,
  /** The current document and its forms: { document, link, plain, json } (a Promise). */
  document: () => {
    flushRun();
    return call('document', { base, embed: false });
  },
  setupFailed: () => setupFailed,
});
