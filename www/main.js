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
//
// Supervision (issue 7, modules/supervisor.js): a task of the worker that
// takes longer than BUDGET_MS is stopped, and a worker that crashes is
// replaced; the new worker gets the page's state back (program, setup, view,
// theme and a new <canvas>) and a message says what happened. A program
// that stopped the interpreter is not run again until it is edited, so no
// program can make a restart loop; the work and its autosave are untouched.

import { createEditor } from './dist/editor.js';
import { addressChanged, initAddress, writtenFragment } from './modules/address.js';
import { showDiagnostics, showNotRun } from './modules/diagnostics.js';
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
import { createSupervisor } from './modules/supervisor.js';
import { bindCanvas, initView, setMachinePlanes, viewReported, viewState } from './modules/view.js';

/** Re-run this long after the last keystroke. */
const DEBOUNCE_MS = 150;
// A program that ran in under this many milliseconds runs again at once on
// an edit (typing in a small or mid-sized program redraws in the same
// frame); a slower one waits for a pause in the typing (DEBOUNCE_MS).
const QUICK_RUN_MS = 30;
let lastRunMs = Infinity;
// Past this, a running program shows how far it has got.
const PROGRESS_AFTER_MS = 200;
/** Files larger than this are not read (the interpreter reads 256 MiB of program). */
const MAX_FILE = 300 * 1024 * 1024;
/**
 * Hooks of the end-to-end tests, set by an init script before the page loads
 * (never by a link or a document): `{ budgetMs, startupMs, hooks }`; `hooks`
 * lets a program ask the worker for a test fault (see worker.js fault()).
 * Only a plain object counts (an element with that id is not one).
 */
const TEST = Object.getPrototypeOf(window.offsetlabTest ?? 0) === Object.prototype ? window.offsetlabTest : null;
const positive = (v) => (Number.isFinite(v) && v > 0 ? v : null);
/**
 * The time budget of one task the page waits for (a run, a link, an
 * export). The core stops every run at 5,000,000 blocks or moves; such a
 * run took 2.6 s in the worker on a 2-core machine (the slowest file of
 * tests/data/hostile, 3.4 s), so 30 s leaves a slow machine about ten times
 * that; past it the task is stopped as a runaway.
 */
const BUDGET_MS = positive(TEST?.budgetMs) ?? 30_000;
/** The worker must have loaded the core within this. */
const STARTUP_MS = positive(TEST?.startupMs) ?? 60_000;

const $ = (id) => document.getElementById(id);
let canvas = $('view'); // replaced by a new <canvas> when the worker restarts
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

initStorage(showStorageProblem);
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

// The worker, supervised (created below, once the canvas is wired).
let supervisor = null;
let lastStepSeq = 0; // the stepper's last request, continued by a restarted worker
function post(message) {
  if (message.type === 'step' && message.seq) lastStepSeq = message.seq;
  supervisor?.post(message);
}
// After a failure: the document that failed ({ program, setup, count }), and
// the document not run again until it is edited ({ program, setup }).
let failed = null;
let parked = null;
let restarts = 0;
let lastSent = null; // { program, setup, view } of the last run request
const sent = new Map(); // generation → { program, setup, view } of run requests not yet begun
let runningDoc = null; // the run the worker said it began and has not answered

// Calls answered by the worker (links, documents, exports), in order with the runs.
let callId = 0;
const calls = new Map();
/** Calls that need the session's run: refused while the shown program is not run. */
const NEEDS_RUN = new Set(['document', 'export']);
function call(op, args = {}) {
  if (parked && NEEDS_RUN.has(op)) {
    return Promise.reject(new Error('the program shown stopped the interpreter and was not run; edit it first'));
  }
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
const sameRun = (a, b) => Boolean(a && b) && a.program === b.program && a.setup === b.setup;
function requestRun(program = editor.getText()) {
  clearTimeout(timer);
  delete document.body.dataset.pending;
  const doc = { program, setup: setupOverride ?? JSON.stringify(setup) };
  // The program that stopped the interpreter runs again only once edited.
  if (sameRun(doc, parked)) return;
  parked = null;
  requested += 1;
  document.body.dataset.requested = String(requested);
  lastSent = { ...doc, view: pendingView };
  sent.set(requested, lastSent);
  post({ type: 'run', gen: requested, ...doc, view: pendingView });
  pendingView = null;
}
function scheduleRun() {
  clearTimeout(timer);
  // Tests (and anyone curious) can tell an edit waiting for its run.
  document.body.dataset.pending = 'true';
  timer = setTimeout(requestRun, lastRunMs < QUICK_RUN_MS ? 0 : DEBOUNCE_MS);
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
function forget(gen) {
  for (const g of sent.keys()) if (g <= gen) sent.delete(g);
}

function onWorkerMessage(m) {
  if (m.type === 'busy') {
    if (m.task === 'run') {
      runningDoc = sent.get(m.gen) ?? null;
      forget(m.gen);
    }
    return;
  }
  if (m.type === 'progress') {
    if (m.gen === requested && m.ms >= PROGRESS_AFTER_MS) {
      summaryLine.textContent = `Running… ${Math.floor(m.fraction * 100)} % of the program read (${(m.ms / 1000).toFixed(1)} s)`;
      document.body.dataset.progress = String(m.fraction);
    }
    return;
  }
  if (m.type === 'result') {
    runningDoc = null;
    forget(m.gen);
    if (typeof m.ms === 'number') {
      lastRunMs = m.ms;
      document.body.dataset.runMs = m.ms.toFixed(1); // the benchmark reads it
    }
    delete document.body.dataset.progress;
    if (m.gen < requested) return; // stale: a newer request is on its way
    showResult(m);
    document.body.dataset.rendered = String(m.gen);
    if (failed ? !sameRun(lastSent, failed) : document.body.dataset.stopped) recovered();
  } else if (m.type === 'state') {
    // A restarted worker's empty session (generation 0) is not the page's state.
    if (m.gen === 0 && restarts > 0) return;
    showViewState(m);
  } else if (m.type === 'drawn') {
    document.body.dataset.drawn = `${m.width}x${m.height}@${m.dpr}`;
    // Which run the canvas shows, and how long drawing it took (tests and
    // the benchmark read them).
    document.body.dataset.drawnGen = String(m.gen);
    document.body.dataset.drawMs = m.ms.toFixed(1);
    // A frame of a pan or zoom gesture, moved from the last whole one; the
    // whole frame follows when the gesture pauses.
    if (m.moving) document.body.dataset.drawnMoving = 'true';
    else delete document.body.dataset.drawnMoving;
  } else if (m.type === 'reply') {
    const pending = calls.get(m.id);
    calls.delete(m.id);
    if (!pending) return;
    if (m.error !== undefined) pending.reject(new Error(m.error));
    else pending.resolve(m.value);
  }
}

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
  document.body.dataset.stateGen = String(m.gen); // the run whose state is shown (tests wait for it)
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

// --- failures of the worker (modules/supervisor.js has terminated it)
const seconds = (ms) => `${Number((ms / 1000).toFixed(1))} s`;
const TASKS = { run: 'the run', document: 'making the link', export: 'the export', decode: 'opening the link', read: 'reading the file', canonical: 'comparing documents' };

function onWorkerFailure({ kind, detail, task }) {
  for (const pending of calls.values()) pending.reject(new Error('the interpreter was stopped'));
  calls.clear();
  const why = String(detail ?? '').slice(0, 200);
  console.warn(`offsetlab: the interpreter failed (${kind}): ${why}`);
  const body = document.body.dataset;
  body.failures = String(Number(body.failures ?? 0) + 1);
  body.failure = kind;
  // The document it failed on: the run it had begun, else the last one asked for.
  const doc = (task === 'run' ? runningDoc : null) ?? lastSent
    ?? { program: editor.getText(), setup: setupOverride ?? JSON.stringify(setup) };
  runningDoc = null;
  sent.clear();
  if (kind === 'start') {
    // Nothing to restart into: the next run or call tries a new worker.
    showStopped(`The interpreter could not start (${why}). Your work is kept; reload the page to try again.`, { kind });
    return;
  }
  failed = { program: doc.program, setup: doc.setup, count: sameRun(doc, failed) ? failed.count + 1 : 1 };
  // The view to give the new worker: the one the failed run was asked for, or the one shown.
  const view = doc.view ?? (viewKnown ? viewState() : null);
  const now = { program: editor.getText(), setup: setupOverride ?? JSON.stringify(setup) };
  const edited = !sameRun(now, doc); // the user changed it meanwhile: that runs
  const what = TASKS[task] ?? 'the interpreter';
  const took = `${what[0].toUpperCase()}${what.slice(1)} took longer than ${seconds(BUDGET_MS)} and was stopped`;
  if (failed.count >= 3 && !edited) {
    // It failed again with nothing new asked of it: no more restarts until an edit.
    parked = doc;
    pendingView = view;
    showStopped(`The interpreter keeps failing on this program (${why}). Your work is kept; edit the program or the setup to try again.`, { kind });
    return;
  }
  restarts += 1;
  document.body.dataset.restarts = String(restarts);
  document.body.dataset.interpreter = 'starting';
  supervisor.start();
  pendingView = view;
  // Run again: work the user changed meanwhile; or, the first time, after a
  // crash (it may not come back: memory, a one-off) or a call that hung (its
  // run had finished). A run that hung would only hang again.
  if (edited || (failed.count === 1 && (kind === 'crash' || task !== 'run'))) {
    requestRun();
    const restored = edited ? 'your changes' : 'your program, setup and view';
    showBanner(kind === 'hang'
      ? `${took}; the interpreter was restarted with ${restored}.`
      : `The interpreter crashed (${why}) and was restarted with ${restored}.`, { kind: 'worker' });
    return;
  }
  parked = doc;
  showStopped(kind === 'hang'
    ? `${took}; the page is usable — edit the program (or its setup) and it runs again.`
    : `The interpreter crashed again on this program (${why}) and was restarted without running it, so the page stays usable — edit the program or the setup and it runs again.`, { kind });
}

/** Shows that the program shown was not run (or not finished): banner, summary, diagnostics, steps. */
function showStopped(text, { kind }) {
  showBanner(text, { kind: 'worker' });
  summaryLine.textContent = text;
  summaryLine.classList.add('has-errors');
  showNotRun($('diagnostics'), text);
  editor.setDiagnostics([]);
  // Nothing of the failed run is shown: no blocks, no current block.
  blockCount = 0;
  currentBlock = null;
  stepReported(-1, 0, null, lastStepSeq);
  showState($('state-panel'), null, { blocks: 0 });
  editor.showCurrent(null, false);
  document.body.dataset.stopped = kind;
}

/** A run of another document succeeded after a failure: the message goes. */
function recovered() {
  failed = null;
  delete document.body.dataset.stopped;
  delete document.body.dataset.failure;
  showBanner(null, { kind: 'worker' });
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

/** Storage problems have their own banner: no other message may hide that the work is not saved. */
function showStorageProblem(message) {
  const banner = $('storage-banner');
  banner.querySelector('.text').textContent = message ?? '';
  banner.hidden = !message;
}
$('storage-banner-close').addEventListener('click', () => {
  $('storage-banner').hidden = true;
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
    pendingView = viewOf(work);
    // The run first: the worker runs a large program while this thread
    // gives it to the editor (half a second for 31 MB) — unless the editor
    // will change its line breaks (CR LF, CR): then it runs what it shows.
    const asGiven = !work.program.includes('\r');
    if (asGiven) requestRun(work.program);
    editor.setText(work.program);
    if (!asGiven) requestRun();
  } finally {
    loading = false;
  }
  // The editor's change asked for a run of the text just sent.
  clearTimeout(timer);
  delete document.body.dataset.pending;
  renderOffsets({ force: true });
  renderSettings();
  if (setupOverride !== null) $('setup').value = setupOverride;
  if (exampleId) exampleSelect.value = exampleId;
  showNote();
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

/**
 * "Open in playground": the codec's link to this page (never a `javascript:`
 * or other URL a link could smuggle in); anything but an http(s) link of
 * this page's own address falls back to the plain page.
 */
function playgroundHref(link) {
  try {
    const url = new URL(link, base);
    const page = new URL(base);
    if (['http:', 'https:'].includes(url.protocol) && url.origin === page.origin && url.pathname === page.pathname) {
      return url.href;
    }
  } catch {
    // not a URL: the plain page
  }
  return './';
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
    $('open-playground').href = playgroundHref(answer.playground);
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

let canvasHandedOver = false;
/**
 * A new worker's init message: the canvas (as an OffscreenCanvas), the
 * theme and size, the stepper's count. A canvas hands its control over once
 * only, so a restarted worker gets a new <canvas> in place of the old one —
 * the same element (id, attributes, focus) with the same input.
 */
function makeInit() {
  if (canvasHandedOver) {
    const fresh = canvas.cloneNode(false);
    fresh.classList.remove('dragging');
    const focused = document.activeElement === canvas;
    resizeObserver.unobserve(canvas);
    canvas.replaceWith(fresh);
    canvas = fresh;
    bindCanvas(canvas);
    resizeObserver.observe(canvas);
    if (focused) canvas.focus();
  }
  canvasHandedOver = true;
  const offscreen = canvas.transferControlToOffscreen();
  return {
    message: {
      type: 'init', canvas: offscreen, theme: theme(), ...canvasSize(), stepSeq: lastStepSeq, testHooks: TEST?.hooks === true,
    },
    transfer: [offscreen],
  };
}

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
const resizeObserver = new ResizeObserver(reportSize);
resizeObserver.observe(canvas);
// Zooming the page or moving it to another screen changes devicePixelRatio.
function watchPixelRatio() {
  const query = matchMedia(`(resolution: ${window.devicePixelRatio || 1}dppx)`);
  query.addEventListener('change', () => {
    reportSize();
    watchPixelRatio();
  }, { once: true });
}
watchPixelRatio();

supervisor = createSupervisor({
  url: new URL('./worker.js', import.meta.url),
  budgetMs: BUDGET_MS,
  startupMs: STARTUP_MS,
  makeInit,
  onMessage: onWorkerMessage,
  onFailure: onWorkerFailure,
  // For the tests (and the curious): the interpreter has loaded.
  onReady: () => { document.body.dataset.interpreter = 'ready'; },
});
supervisor.start();

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
  if (parked) return null; // not run: the worker has no document to make the link of
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
