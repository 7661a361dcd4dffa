// The playground page: wires the editor, the panels and the worker together.
// The interpreter and the drawing live in a module worker (worker.js) that
// owns the canvas and the view state, so big toolpaths never cross into this
// thread. Each concept has its module in modules/:
//
//   work.js       the work shown (setup, where it came from) and its autosave
//   storage.js    the autosave in localStorage, and the work a document displaced
//   saved.js      what is saved: the work's document (links' and --setup's format)
//   runner.js     run requests (generations, typing debounce) and calls to the worker
//   results.js    what the worker reports, shown: summary, diagnostics, current block
//   recovery.js   a worker that hung or crashed replaced (issue 7, supervisor.js watches)
//   documents.js  examples, links and files replace the work; the user's own is kept
//   links.js      links in the fragment opened; the address bar follows (address.js)
//   opening.js    files opened with Open… or dropped on the page
//   canvas.js     the <canvas> handed over to the worker, its size and colours
//   banner.js     the message banners
//   page.js       this page load: its address, embed mode, the tests' hooks
//
// and the panels: offsets.js, settings.js (positions.js), tools.js, stepper.js, view.js, share.js, export.js.

import { createEditor } from './dist/editor.js';
import { initBanners, showStorageProblem } from './modules/banner.js';
import { currentCanvas, initCanvas, makeInit } from './modules/canvas.js';
import { initDocuments } from './modules/documents.js';
import { DEFAULT_EXAMPLE } from './modules/examples.js';
import { initExport } from './modules/export.js';
import { initLinks, openFirst } from './modules/links.js';
import { initOffsets, renderOffsets } from './modules/offsets.js';
import { initOpening } from './modules/opening.js';
import {
  BUDGET_MS, EMBED, STARTUP_MS, base,
} from './modules/page.js';
import { initRecovery, onWorkerFailure, restarted, resultShown } from './modules/recovery.js';
import {
  initResults, setupRefused, showDrawn, showProgress, showResult, showViewState,
} from './modules/results.js';
import {
  call, callAnswered, flushRun, initRunner, latestRun, onFileRead, post, readingFile, resendRun, runAnswered,
  scheduleRun, taskBegun, workerDid,
} from './modules/runner.js';
import { initSettings, renderSettings, setMachine } from './modules/settings.js';
import { cloneSetup } from './modules/setup.js';
import { initShare } from './modules/share.js';
import { initStepper } from './modules/stepper.js';
import { initTools, renderTools } from './modules/tools.js';
import { disableStorage, initStorage, loadWork } from './modules/storage.js';
import { createSupervisor } from './modules/supervisor.js';
import { initView, viewState } from './modules/view.js';
import {
  edited, initWork, persist, work,
} from './modules/work.js';

const $ = (id) => document.getElementById(id);
if (EMBED) {
  document.documentElement.classList.add('embed');
  document.body.classList.add('embed');
  disableStorage();
}

initBanners();
initStorage(showStorageProblem);
const saved = loadWork();
const startWork = EMBED ? { program: '', setup: {} } : saved ?? { ...DEFAULT_EXAMPLE, example: DEFAULT_EXAMPLE.id };
initWork(startWork, () => editor.getText());

// The worker, supervised (created below, once the canvas is wired).
let supervisor = null;
initRunner({
  post: (message) => supervisor?.post(message),
  text: () => editor.getText(),
  takeEdit: () => editor.takeEdit(),
  // (0 while no worker runs: the next run starts one, which holds no text.)
  workerSerial: () => (supervisor?.running() ? supervisor.serial() : 0),
  view: startWork.view ?? null,
});

const editor = createEditor($('editor'), {
  doc: startWork.program,
  label: EMBED ? 'Program (G-code, read-only)' : 'Program (G-code)',
  readOnly: EMBED,
  onChange: () => {
    // A document being loaded is run and saved by loadDocument.
    if (work.loading) return;
    edited();
    scheduleRun();
    persist();
  },
  onCursorLine: (line) => post({ type: 'line', line }),
});
$('undo').addEventListener('click', () => editor.undo());
$('redo').addEventListener('click', () => editor.redo());
initResults(editor, { onSwitchMachine: (kind) => change((s) => setMachine(s, kind), 'settings') });

// --- the setup: one object, edited by the offset table, the settings form
// and the raw JSON, which all follow it.
const getSetup = () => work.setup;
function change(mutate, source) {
  mutate(work.setup);
  work.setupText = null;
  edited();
  if (source !== 'offsets') renderOffsets({ force: true });
  if (source !== 'tools') renderTools({ force: true });
  renderSettings();
  scheduleRun();
  persist();
}
function replace(parsed, text) {
  if (parsed && typeof parsed === 'object' && !Array.isArray(parsed)) {
    work.setup = parsed;
    work.setupText = null;
    renderOffsets({ force: true });
    renderTools({ force: true });
    renderSettings({ json: false });
  } else {
    work.setupText = text;
  }
  edited();
  scheduleRun();
  persist();
}
initOffsets({ getSetup, change });
initSettings({ getSetup, change, replace });
initTools({ getSetup, change });
renderOffsets({ force: true });
renderTools({ force: true });
renderSettings();
if (work.setupText !== null) $('setup').value = work.setupText;

// --- documents: examples, links and files
initDocuments(editor);
initOpening();
initLinks(editor);

// --- help
function toggleHelp() {
  if (EMBED) return;
  const help = $('help');
  help.hidden = !help.hidden;
  $('help-toggle').setAttribute('aria-expanded', String(!help.hidden));
}
$('help-toggle').addEventListener('click', toggleHelp);

// --- what the worker says
// While the page reads the text of a file the worker runs (modules/opening.js),
// what the worker says of runs waits for the editor to have that text.
const heldBack = [];
onFileRead(() => {
  for (const m of heldBack.splice(0)) onWorkerMessage(m);
});
function onWorkerMessage(m) {
  if (readingFile() && (m.type === 'result' || m.type === 'state' || m.type === 'drawn')) {
    heldBack.push(m);
    return;
  }
  switch (m.type) {
    case 'busy':
      taskBegun(m);
      break;
    case 'progress':
      if (m.gen === latestRun()) showProgress(m);
      break;
    case 'result':
      if (!runAnswered(m)) return; // stale: a newer request is on its way
      showResult(m);
      document.body.dataset.rendered = String(m.gen);
      resultShown();
      break;
    case 'state':
      // A restarted worker's empty session (generation 0) is not the page's state.
      if (m.gen === 0 && restarted()) return;
      showViewState(m);
      break;
    case 'read':
      workerDid('read', m.gen);
      break;
    case 'resend':
      resendRun(m.gen);
      break;
    case 'drawn':
      workerDid('drawn', m.gen);
      showDrawn(m);
      break;
    case 'reply':
      callAnswered(m);
      break;
    default:
      break;
  }
}

// --- the view: the worker draws on the canvas from now on
initCanvas($('view'));
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
initRecovery(() => supervisor.start());
supervisor.start();

initView(currentCanvas(), post);
const centreZoom = (factor) => {
  const r = currentCanvas().getBoundingClientRect();
  post({ type: 'view', op: 'zoom', x: r.width / 2, y: r.height / 2, factor });
};
initStepper(post, { fit: () => post({ type: 'view', op: 'fit' }), zoom: centreZoom, toggleHelp });

// --- share and export
initShare({ call, flush: flushRun, program: () => editor.getText(), base });
initExport({ call, flush: flushRun, program: () => editor.getText() });

openFirst(saved);

// For the console and the tests: read-only views of the state.
window.offsetlab = Object.freeze({
  viewState,
  program: () => editor.getText(),
  selection: () => editor.selection(),
  setup: () => cloneSetup(work.setup),
  embed: EMBED,
  /** The current document and its forms: { document, link, plain, json } (a Promise). */
  document: () => {
    flushRun();
    return call('document', { base, embed: false });
  },
  setupFailed: setupRefused,
});
