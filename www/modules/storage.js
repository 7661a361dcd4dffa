// No lost work: the program, the setup (offsets and settings) and the view
// are saved in localStorage as the user types (at most every SAVE_MS, when
// the page is idle, and at once when the page is hidden) and restored on the
// next visit; the work is made when it is saved, not at every keystroke. What
// is saved is the work's document, the format of links and `--setup` files,
// with the page's own extras beside it (modules/saved.js). When the browser
// refuses (storage full, disabled, private mode), the page says so:
// at load if storage cannot be used at all, and at every save that fails
// (the message goes again once a save succeeds). The message has its own
// banner, so that no other message (a link, an example) can hide it.
//
// Work that an opened link, document file or example displaced is kept
// under its own key (PREVIOUS_KEY) until it is restored, so it stays one
// click away across reloads. An embedded page (embed=1) reads and writes
// neither: a lesson's example must never touch the reader's own work.
//
// Both keys are those of the page's first saved shape: a value in that shape
// is read, and written again as a document the first time it is read (the
// old value stays until the new one is written; where the browser refuses,
// it stays and is read again next time).

import { readSaved, savedOf } from './saved.js';

const KEY = 'offsetlab.work.v1';
const PREVIOUS_KEY = 'offsetlab.previous.v1';
const SAVE_MS = 400;
/** A save waits at most this long for the page to be idle. */
const IDLE_WAIT_MS = 1000;
/**
 * Programs longer than this are never saved: no browser keeps that much for
 * a page (Chromium 10 MiB of UTF-16, about 5.2 million characters; Firefox
 * and Safari 5 MB), and trying would make the JSON of the whole program at
 * each save, a long task of the page's thread while a large file is open
 * (bench-browser target 3, its "localStorage writes").
 */
const MAX_SAVED_CHARS = 5 * 1024 * 1024;
const idle = typeof requestIdleCallback === 'function'
  ? (f) => requestIdleCallback(f, { timeout: IDLE_WAIT_MS })
  : (f) => setTimeout(f, 0);

let timer = 0;
let pending = null;
let onProblem = () => {};
let failing = false;
let enabled = true;
let unavailable = false; // the browser does not let this page use localStorage at all
let previousInMemory = null; // when storage refuses, the displaced work lives here
let tooLarge = null; // the program text the storage was too full for, while it stays the same

/** Turns saving off (embed mode): loadWork() is null, saveWork() does nothing. */
export function disableStorage() {
  enabled = false;
  pending = null;
  clearTimeout(timer);
  timer = 0;
}

/** Why the browser refused: its storage is full, or the error's own words. */
function reason(error) {
  const full = error?.name === 'QuotaExceededError' || error?.name === 'NS_ERROR_DOM_QUOTA_REACHED'
    || error?.code === 22 || error?.code === 1014;
  return full ? 'the browser’s storage is full' : (error?.message || 'storage is unavailable');
}

/** The work saved under `key`, or null; a value in the first shape is written again as a document. */
function readJson(key) {
  const text = localStorage.getItem(key);
  if (!text) return null;
  const read = readSaved(JSON.parse(text));
  if (!read) return null;
  if (read.old) {
    try {
      localStorage.setItem(key, JSON.stringify(savedOf(read.work)));
    } catch {
      // Refused (storage full): the old value stays, and is read again next time.
    }
  }
  return read.work;
}

/** The work an opened link, file or example displaced, or null. */
export function loadPrevious() {
  if (!enabled) return null;
  if (unavailable) return previousInMemory;
  try {
    return readJson(PREVIOUS_KEY) ?? previousInMemory;
  } catch {
    return previousInMemory;
  }
}

/** Keeps displaced work { program, setup, setupText?, view? } (null forgets it). */
export function keepPrevious(work) {
  if (!enabled) return;
  previousInMemory = work;
  try {
    if (work?.program.length > MAX_SAVED_CHARS) throw new DOMException('too large', 'QuotaExceededError');
    if (work) localStorage.setItem(PREVIOUS_KEY, JSON.stringify(savedOf(work)));
    else localStorage.removeItem(PREVIOUS_KEY);
  } catch (error) {
    // An older work kept there must not come back in place of this one.
    try {
      localStorage.removeItem(PREVIOUS_KEY);
    } catch {
      // storage unavailable: nothing is kept there
    }
    onProblem(`Your previous program is kept only until this page is closed: ${reason(error)}.`);
  }
}

/** The saved work { program, setup, setupText?, view? } or null. */
export function loadWork() {
  if (!enabled || unavailable) return null;
  try {
    return readJson(KEY);
  } catch (error) {
    onProblem(`Your saved work could not be read (${error.message}).`);
    return null;
  }
}

/** The storage refused `program` (it is full): said in the banner. */
function refused(error, program) {
  failing = true;
  tooLarge = reason(error) === 'the browser’s storage is full' ? program : null;
  document.body.dataset.saveFailed = 'true';
  onProblem(`Your work is not being saved: ${reason(error)}. Copy your program somewhere safe before you leave.`);
}

function flush() {
  clearTimeout(timer);
  timer = 0;
  if (!pending) return;
  const work = typeof pending === 'function' ? pending() : pending;
  pending = null;
  // A full storage stays full for the same program: a pan or a step does
  // not make a 30 MB program fit, and writing it again would make its JSON
  // again each time (bench-browser target 3). The message stays up.
  if (tooLarge !== null && work.program === tooLarge) return;
  if (work.program.length > MAX_SAVED_CHARS) {
    // Not a full storage: no browser keeps a program this large for a
    // page, so say what is true — it is open, and not kept.
    failing = true;
    tooLarge = work.program;
    document.body.dataset.saveFailed = 'true';
    const mb = (n) => (n / (1024 * 1024)).toFixed(1);
    onProblem(`This program (${mb(work.program.length)} million characters) is larger than the page saves in the browser (${mb(MAX_SAVED_CHARS)} million): it stays open until you close the page, and is not restored on your next visit. Open it again from its file then.`);
    return;
  }
  try {
    localStorage.setItem(KEY, JSON.stringify(savedOf(work)));
    tooLarge = null;
    document.body.dataset.saved = String(Date.now());
    if (failing) {
      failing = false;
      onProblem(null);
    }
  } catch (error) {
    refused(error, work.program);
    return;
  }
  delete document.body.dataset.saveFailed;
}

/**
 * Saves the work soon (throttled, when the page is idle): `work` is the work
 * or a function that makes it, called when it is saved.
 */
export function saveWork(work) {
  if (!enabled) return;
  pending = work;
  document.body.dataset.unsaved = 'true';
  if (!timer) {
    timer = setTimeout(() => idle(() => {
      if (!timer) return; // saved meanwhile (the page was hidden)
      flush();
      delete document.body.dataset.unsaved;
    }), SAVE_MS);
  }
}

/** `report(message | null)` shows or clears a storage problem. */
export function initStorage(report) {
  onProblem = report;
  if (enabled) {
    // Storage switched off (blocked cookies and site data) throws on access:
    // say so now, before the user has typed anything worth keeping.
    try {
      void window.localStorage.length;
    } catch (error) {
      failing = true;
      unavailable = true;
      document.body.dataset.saveFailed = 'true';
      onProblem(`Your work will not be saved: this browser does not allow this page to store data (${error?.message || error?.name || 'storage is disabled'}). Copy your program somewhere safe before you leave.`);
    }
  }
  const now = () => {
    flush();
    delete document.body.dataset.unsaved;
  };
  addEventListener('pagehide', now);
  document.addEventListener('visibilitychange', () => {
    if (document.visibilityState === 'hidden') now();
  });
}
