// Worker supervision (issue 7): the interpreter's worker is watched so that
// no program can leave the page without an answer.
//
// - Hang: while the page waits for an answer (a run's result or a call's
//   reply), the worker must answer within `budgetMs` of starting the task.
//   It runs one task at a time, says `busy` when it begins one, and any
//   message from it means the task it was on is over, so "nothing heard for
//   budgetMs while something is awaited" is a task that took longer than
//   the budget. The worker is then
//   terminated (a busy worker cannot be interrupted any other way) and
//   `onFailure({ kind: 'hang' })` is called. A short grace period lets an
//   answer already queued behind a busy page thread arrive first.
// - Crash: an uncaught error in the worker (its `error` event) or an
//   exception it reports (`failure`, such as a WebAssembly trap: after a
//   trap the core's memory may be inconsistent, so it is never used again):
//   terminated, `onFailure({ kind: 'crash', detail })`. A worker that dies
//   without a word (it closed itself, its thread was killed) is a crash too:
//   it holds a Web Lock named after it while it lives, which the page asks
//   for and is granted when it dies. Where Web Locks are missing (a page not
//   in a secure context), such a death is noticed as a hang.
// - Start: a worker that fails (or takes `startupMs`) before it says
//   `ready` is `onFailure({ kind: 'start', detail })`.
//
// The supervisor never restarts by itself: the page decides (recovery.js), so
// that a program that fails again cannot make a restart loop. `start()`
// makes a fresh worker and sends it `makeInit()` (the page's state: a new
// canvas, the theme, the size); `post()` starts one when a run or a call
// needs it and none is running.

const GRACE_MS = 500;
let serial = 0; // names the workers (and their Web Locks) of this page
const pageId = Math.random().toString(36).slice(2, 10);

export function createSupervisor({ url, budgetMs, startupMs, makeInit, onMessage, onFailure, onReady = () => {} }) {
  let worker = null;
  let ready = false;
  let awaitedGen = 0; // newest run generation sent and not answered (0: none)
  const awaitedCalls = new Map(); // call id → op, sent and not answered
  let since = 0; // when the current task started (the last sign of life while awaiting)
  let current = null; // the task the worker said it began ('run' or a call's op)
  let timer = 0;
  let startTimer = 0;

  const awaiting = () => awaitedGen > 0 || awaitedCalls.size > 0;

  /** What the worker was busy with: 'run' or the name of a call. */
  function task() {
    if (current) return current;
    if (awaitedGen > 0) return 'run';
    const [op] = awaitedCalls.values();
    return op ?? 'run';
  }

  function arm() {
    clearTimeout(timer);
    timer = 0;
    if (!worker || !ready || !awaiting()) return;
    timer = setTimeout(check, Math.max(0, since + budgetMs - performance.now()));
  }

  function check(grace = false) {
    timer = 0;
    if (!worker || !awaiting()) return;
    const late = performance.now() - since - budgetMs;
    if (late < 0) {
      arm();
    } else if (!grace) {
      // Over budget: an answer may still be queued behind this thread's own work.
      timer = setTimeout(() => check(true), GRACE_MS);
    } else {
      fail('hang', `no answer within ${budgetMs} ms`);
    }
  }

  function fail(kind, detail) {
    const what = task();
    const wasReady = ready;
    stop();
    onFailure({ kind: wasReady ? kind : 'start', detail, task: what });
  }

  /** Terminates the worker (if any) and forgets what was awaited. */
  function stop() {
    clearTimeout(timer);
    clearTimeout(startTimer);
    timer = 0;
    startTimer = 0;
    if (worker) worker.terminate();
    worker = null;
    ready = false;
    current = null;
    awaitedGen = 0;
    awaitedCalls.clear();
  }

  function heard(m) {
    if (m.type === 'busy') current = m.task;
    if (m.type === 'result' || m.type === 'reply') current = null;
    if (m.type === 'result' && m.gen >= awaitedGen) awaitedGen = 0;
    if (m.type === 'reply') awaitedCalls.delete(m.id);
    since = performance.now();
    arm();
  }

  /** Starts a fresh worker (terminating the current one) and initialises it. */
  function start() {
    stop();
    serial += 1;
    const name = `offsetlab-interpreter-${pageId}-${serial}`;
    const w = new Worker(url, { type: 'module', name });
    worker = w;
    w.addEventListener('message', (event) => {
      if (w !== worker) return; // a terminated worker's last words
      const m = event.data;
      if (m.type === 'ready') {
        clearTimeout(startTimer);
        ready = true;
        since = performance.now();
        arm();
        // The worker holds the lock of its name while it lives: granted to us, it has died.
        navigator.locks?.request(name, () => {
          if (w === worker) fail('crash', 'its worker stopped');
        }).catch(() => {});
        onReady();
        return;
      }
      if (m.type === 'failure') {
        fail('crash', m.message);
        return;
      }
      heard(m);
      onMessage(m);
    });
    w.addEventListener('error', (event) => {
      // Handled here: not reported again as an uncaught error in the console.
      event.preventDefault();
      if (w !== worker) return;
      fail('crash', event.message || 'the worker stopped with an error');
    });
    w.addEventListener('messageerror', () => {
      if (w === worker) console.warn('offsetlab: a message from the interpreter could not be read');
    });
    startTimer = setTimeout(() => {
      if (w === worker && !ready) fail('start', `it did not load within ${Math.round(startupMs / 1000)} s`);
    }, startupMs);
    const { message, transfer } = makeInit();
    w.postMessage(message, transfer);
  }

  /**
   * Sends a message to the worker. A run or a call starts a worker when
   * none is running; anything else (view, step, size, theme) needs the
   * worker it was meant for and is dropped without one (a new worker gets
   * the size and theme in its init message). Returns false if dropped.
   */
  function post(message) {
    if (!worker) {
      if (message.type !== 'run' && message.type !== 'call') return false;
      start();
    }
    if (!awaiting()) since = performance.now();
    if (message.type === 'run') awaitedGen = Math.max(awaitedGen, message.gen);
    if (message.type === 'call') awaitedCalls.set(message.id, message.op);
    worker.postMessage(message);
    arm();
    return true;
  }

  return {
    start,
    stop,
    post,
    running: () => worker !== null,
    /** Which worker this is: a new one (restarted) has another number. */
    serial: () => serial,
  };
}
