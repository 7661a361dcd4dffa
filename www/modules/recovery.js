// What the page does when its worker fails (modules/supervisor.js has
// terminated it, issue 7): a task that took longer than BUDGET_MS, a crash,
// a worker that could not start. The new worker gets the page's state back
// (program, setup, view, theme and a new <canvas>) and a message says what
// happened. A program that stopped the interpreter is not run again until
// it is edited, so no program can make a restart loop; the work and its
// autosave are untouched.

import { showBanner } from './banner.js';
import { BUDGET_MS } from './page.js';
import { showStopped } from './results.js';
import {
  currentDoc, lastRun, park, requestRun, sameRun, setPendingView, stepSeq, workerLost,
} from './runner.js';
import { viewState } from './view.js';
import { work } from './work.js';

const seconds = (ms) => `${Number((ms / 1000).toFixed(1))} s`;
const TASKS = { run: 'the run', document: 'making the link', export: 'the export', decode: 'opening the link', read: 'reading the file', canonical: 'comparing documents' };

let restart = () => {};
// After a failure: the document that failed ({ program, setup, count }).
let failed = null;
let restarts = 0;

/** `start()` starts a new worker. */
export function initRecovery(start) {
  restart = start;
}

/** The worker was replaced at least once (a new worker's empty session is not the page's state). */
export const restarted = () => restarts > 0;

const stopped = (text, kind) => showStopped(text, { kind, stepSeq: stepSeq() });

/** The supervisor's onFailure: { kind: 'hang' | 'crash' | 'start', detail, task }. */
export function onWorkerFailure({ kind, detail, task }) {
  const why = String(detail ?? '').slice(0, 200);
  console.warn(`offsetlab: the interpreter failed (${kind}): ${why}`);
  const body = document.body.dataset;
  body.failures = String(Number(body.failures ?? 0) + 1);
  body.failure = kind;
  const doc = workerLost(task);
  if (kind === 'start') {
    // Nothing to restart into: the next run or call tries a new worker.
    stopped(`The interpreter could not start (${why}). Your work is kept; reload the page to try again.`, kind);
    return;
  }
  failed = { program: doc.program, setup: doc.setup, count: sameRun(doc, failed) ? failed.count + 1 : 1 };
  // The view to give the new worker: the one the failed run was asked for, or the one shown.
  const view = doc.view ?? (work.viewKnown ? viewState() : null);
  const edited = !sameRun(currentDoc(), doc); // the user changed it meanwhile: that runs
  const what = TASKS[task] ?? 'the interpreter';
  const took = `${what[0].toUpperCase()}${what.slice(1)} took longer than ${seconds(BUDGET_MS)} and was stopped`;
  if (failed.count >= 3 && !edited) {
    // It failed again with nothing new asked of it: no more restarts until an edit.
    park(doc);
    setPendingView(view);
    stopped(`The interpreter keeps failing on this program (${why}). Your work is kept; edit the program or the setup to try again.`, kind);
    return;
  }
  restarts += 1;
  document.body.dataset.restarts = String(restarts);
  document.body.dataset.interpreter = 'starting';
  restart();
  setPendingView(view);
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
  park(doc);
  stopped(kind === 'hang'
    ? `${took}; the page is usable — edit the program (or its setup) and it runs again.`
    : `The interpreter crashed again on this program (${why}) and was restarted without running it, so the page stays usable — edit the program or the setup and it runs again.`, kind);
}

/** A run's result was shown: if it is of another document than the one that failed, the message goes. */
export function resultShown() {
  if (failed ? sameRun(lastRun(), failed) : !document.body.dataset.stopped) return;
  failed = null;
  delete document.body.dataset.stopped;
  delete document.body.dataset.failure;
  showBanner(null, { kind: 'worker' });
}
