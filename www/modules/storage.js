// No lost work: the program, the setup (offsets and settings) and the view
// are saved in localStorage as the user types (at most every SAVE_MS, and at
// once when the page is hidden) and restored on the next visit. When the
// browser refuses (storage full, disabled, private mode), the page says so.

const KEY = 'offsetlab.work.v1';
const SAVE_MS = 400;

let timer = 0;
let pending = null;
let onProblem = () => {};
let failing = false;

/** The saved work { program, setup, setupText?, view? } or null. */
export function loadWork() {
  try {
    const text = localStorage.getItem(KEY);
    if (!text) return null;
    const work = JSON.parse(text);
    if (typeof work?.program !== 'string' || typeof work.setup !== 'object' || work.setup === null) return null;
    return work;
  } catch (error) {
    onProblem(`Your saved work could not be read (${error.message}).`);
    return null;
  }
}

function flush() {
  clearTimeout(timer);
  timer = 0;
  if (!pending) return;
  const work = pending;
  pending = null;
  try {
    localStorage.setItem(KEY, JSON.stringify(work));
    document.body.dataset.saved = String(Date.now());
    if (failing) {
      failing = false;
      onProblem(null);
    }
  } catch (error) {
    failing = true;
    const why = error?.name === 'QuotaExceededError' ? 'the browser’s storage is full' : (error?.message || 'storage is unavailable');
    onProblem(`Your work is not being saved: ${why}. Copy your program somewhere safe before you leave.`);
  }
}

/** Saves `work` soon (throttled). */
export function saveWork(work) {
  pending = work;
  document.body.dataset.unsaved = 'true';
  if (!timer) {
    timer = setTimeout(() => {
      flush();
      delete document.body.dataset.unsaved;
    }, SAVE_MS);
  }
}

/** `report(message | null)` shows or clears a storage problem. */
export function initStorage(report) {
  onProblem = report;
  const now = () => {
    flush();
    delete document.body.dataset.unsaved;
  };
  addEventListener('pagehide', now);
  document.addEventListener('visibilitychange', () => {
    if (document.visibilityState === 'hidden') now();
  });
}
