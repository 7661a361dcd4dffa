// Runs and calls of the interpreter's worker. Every run request carries a
// generation number; answers to older generations are dropped. An edit runs
// again at once when the last run was quick, else after a pause in the
// typing. Calls (links, documents, exports) are answered in order with the
// runs, so a call posted after a run request sees that run. The program that
// stopped the interpreter (modules/recovery.js parks it) is not run again
// until it is edited.

import { setupDocument } from './work.js';

/** Re-run this long after the last keystroke. */
const DEBOUNCE_MS = 150;
// A program that ran in under this many milliseconds runs again at once on
// an edit — the request goes out in the keystroke's own task, before the
// editor draws it, so the worker runs while this thread updates the editor
// (typing in a small or mid-sized program redraws in the same frame); a
// slower one waits for a pause in the typing (DEBOUNCE_MS).
const QUICK_RUN_MS = 30;
/** Calls that need the session's run: refused while the shown program is not run. */
const NEEDS_RUN = new Set(['document', 'export']);

let send = () => {};
let program = () => '';
let takeEdit = () => null;
let workerSerial = () => 0;
// The run request whose program the worker holds as its text ({ gen,
// serial }: the worker it went to), which the next one may be sent as an
// edit of; null: send the whole text.
let base = null;
let lastRunMs = Infinity;
let lastStepSeq = 0; // the stepper's last request, continued by a restarted worker
let requested = 0;
let timer = 0;
let pendingView = null; // applied by the worker after the next run
let parked = null; // the document not run again until it is edited ({ program, setup })
let lastSent = null; // { program, setup, view } of the last run request
const sent = new Map(); // generation → { program, setup, view } of run requests not yet begun
let runningDoc = null; // the run the worker said it began and has not answered
let readingGen = 0; // the file run whose text the page is reading (0: none)
let fileDone = () => {};
const waits = []; // { what, gen, resolve } (workerDone)
let callId = 0;
const calls = new Map(); // call id → { resolve, reject }

/**
 * `post(message)` reaches the worker; `text()` is the editor's program,
 * `edit()` what changed in it since the last call (the editor's
 * `takeEdit`); `serial()` which worker `post` reaches; `view` the view of
 * the first run.
 */
export function initRunner({ post, text, takeEdit: edit = () => null, workerSerial: serial = () => 0, view = null }) {
  send = post;
  program = text;
  takeEdit = edit;
  workerSerial = serial;
  pendingView = view;
}

/** Sends `message` to the worker. */
export function post(message) {
  if (message.type === 'step' && message.seq) lastStepSeq = message.seq;
  send(message);
}

/** The stepper's last step request. */
export const stepSeq = () => lastStepSeq;

/** True when `a` and `b` are runs of the same program and setup. */
export const sameRun = (a, b) => Boolean(a && b) && a.program === b.program && a.setup === b.setup;

/** The document shown: { program, setup } (the setup as JSON text). */
export const currentDoc = () => ({ program: program(), setup: setupDocument() });

/** Asks the worker `op`; resolves to its answer. */
export function call(op, args = {}) {
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

/** Runs `text` (the editor's program) with the setup shown, and the view asked for. */
export function requestRun(text = program()) {
  const doc = { program: text, setup: setupDocument() };
  // The program that stopped the interpreter runs again only once edited.
  if (sameRun(doc, parked)) {
    cancelScheduledRun();
    return;
  }
  sendRun(doc, pendingView, { program: text });
  pendingView = null;
}

/**
 * Runs the program file `file` with the setup shown and `view`: the worker
 * reads it itself, straight into wasm memory, and this thread reads its
 * text for the editor once it has (modules/opening.js). Until the page has
 * the text (`fileRead`), the run's document has no program and what the
 * worker says of runs is held back (`readingFile`). Returns the run's
 * generation.
 */
export function requestFileRun(file, view) {
  sendRun({ program: null, setup: setupDocument() }, view, { file });
  readingGen = requested;
  return requested;
}

/** Sends the run request of `doc` { program, setup } with `view`; `what`: its program or file. */
function sendRun(doc, view, what) {
  cancelScheduledRun();
  parked = null;
  requested += 1;
  document.body.dataset.requested = String(requested);
  lastSent = { ...doc, view };
  sent.set(requested, lastSent);
  const message = { type: 'run', gen: requested, ...what, setup: doc.setup, view };
  // The editor's text goes as an edit of the last one sent to the same
  // worker: the whole text of a large program, copied to the worker at
  // every keystroke, took this thread's and the worker's time (bench-browser
  // target 4). The worker checks the length it makes and asks for the whole
  // text if they differ.
  const edit = takeEdit();
  const current = what.program !== undefined && edit !== null && what.program === program();
  if (current && base && base.serial === workerSerial()) {
    delete message.program;
    message.edit = { base: base.gen, ...edit, length: what.program.length };
  }
  post(message);
  base = current ? { gen: requested, serial: workerSerial() } : null;
}

/**
 * The worker could not make the text of run `gen` from the edit sent (it
 * had not the text the edit was made on): the whole text again, if that
 * run is still the latest.
 */
export function resendRun(gen) {
  base = null;
  if (gen !== requested || !lastSent || typeof lastSent.program !== 'string') return;
  post({ type: 'run', gen, program: lastSent.program, setup: lastSent.setup, view: lastSent.view });
}

/** Whether the page is reading the text of a file the worker runs. */
export const readingFile = () => readingGen !== 0;

/**
 * The text of the file run `gen` (null: it could not be read). Returns true
 * when that run is the latest one and now has its program; else (another
 * run was asked for meanwhile, or the text is unknown) the caller runs the
 * text anew. Then calls `onFileRead`'s callback (what was held back).
 */
export function fileRead(gen, text) {
  const mine = gen !== 0 && gen === requested && lastSent?.program === null && text !== null;
  if (mine) lastSent.program = text;
  if (gen !== 0 && gen === readingGen) {
    readingGen = 0;
    fileDone();
  }
  return mine;
}

/** `f()` follows every `fileRead`. */
export function onFileRead(f) {
  fileDone = f;
}

/**
 * A promise of the moment the worker has read the file of run `gen`
 * (`what`: 'read') or drawn run `gen` or a later one ('drawn'), or is
 * lost, or `ms` have passed. The page reads an opened file's text once the
 * worker has (the two reads at once made the page's thread stall for a
 * tenth of a second), and the editor takes it once the run is drawn
 * (modules/opening.js, modules/documents.js).
 */
export function workerDone(what, gen, ms = 5000) {
  return new Promise((resolve) => {
    const waiting = { what, gen, resolve };
    waits.push(waiting);
    setTimeout(() => settle(waiting), ms);
  });
}

function settle(waiting) {
  const i = waits.indexOf(waiting);
  if (i >= 0) waits.splice(i, 1);
  waiting.resolve();
}

/** The worker read the file of run `gen` (`read`) or drew run `gen` (`drawn`). */
export function workerDid(what, gen) {
  const done = (w) => w.what === what && (what === 'drawn' ? w.gen <= gen : w.gen === gen);
  for (const waiting of waits.filter(done)) settle(waiting);
}

/** An edit: runs now if the last run was quick, else after a pause in the typing. */
export function scheduleRun() {
  clearTimeout(timer);
  if (lastRunMs < QUICK_RUN_MS) {
    requestRun();
    return;
  }
  // Tests (and anyone curious) can tell an edit waiting for its run.
  document.body.dataset.pending = 'true';
  timer = setTimeout(requestRun, DEBOUNCE_MS);
}

/** Sends an edit still waiting for its run, so a call that follows sees it. */
export function flushRun() {
  if (document.body.dataset.pending) requestRun();
}

/** Forgets an edit waiting for its run (its run was sent already). */
export function cancelScheduledRun() {
  clearTimeout(timer);
  delete document.body.dataset.pending;
}

/** The view (and current block) the next run asks for. */
export function setPendingView(view) {
  pendingView = view;
}

/** The generation of the latest run request. */
export const latestRun = () => requested;

/** The last run request: { program, setup, view }, or null. */
export const lastRun = () => lastSent;

/** Whether the document shown stopped the interpreter and is not run until edited. */
export const isParked = () => parked !== null;

/** Parks `doc` ({ program, setup }): not run again until the program or setup changes. */
export function park(doc) {
  parked = doc;
}

function forget(gen) {
  for (const g of sent.keys()) if (g <= gen) sent.delete(g);
}

/** The worker began a task (`busy`). */
export function taskBegun(m) {
  if (m.task !== 'run') return;
  runningDoc = sent.get(m.gen) ?? null;
  forget(m.gen);
}

/** A run's result arrived; true when it is the latest run's (else it is stale and dropped). */
export function runAnswered(m) {
  runningDoc = null;
  forget(m.gen);
  if (typeof m.ms === 'number') {
    lastRunMs = m.ms;
    document.body.dataset.runMs = m.ms.toFixed(1); // the benchmark reads it
  }
  delete document.body.dataset.progress;
  return m.gen >= requested;
}

/** A call's reply arrived. */
export function callAnswered(m) {
  const pending = calls.get(m.id);
  calls.delete(m.id);
  if (!pending) return;
  if (m.error !== undefined) pending.reject(new Error(m.error));
  else pending.resolve(m.value);
}

/**
 * The worker failed on `task`: every call waiting is refused, and the
 * document it failed on is returned — the run it had begun, else the last
 * one asked for, else the one shown.
 */
export function workerLost(task) {
  for (const waiting of [...waits]) settle(waiting);
  for (const pending of calls.values()) pending.reject(new Error('the interpreter was stopped'));
  calls.clear();
  let doc = (task === 'run' ? runningDoc : null) ?? lastSent ?? currentDoc();
  // A file run whose text the page has not read yet: the text shown (the
  // file's, once read, is run anew: fileRead).
  if (doc.program === null) doc = { ...currentDoc(), view: doc.view };
  runningDoc = null;
  sent.clear();
  return doc;
}
