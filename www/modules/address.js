// The address bar kept current: the compact link of the document in the
// URL's fragment, written with history.replaceState (never pushState: no
// history entries), at most once per MIN_INTERVAL_MS and again after the
// last change. The fragments this tab wrote last are remembered in
// sessionStorage, so a reload knows the address is its own state (the
// autosave, which is at least as new, wins) and not a link someone opened.
// The one before the last counts too: a write that lands while the tab is
// being reloaded changes the old page's address after the reload took it.

const MIN_INTERVAL_MS = 1000;
const SETTLE_MS = 300; // wait this long after a change before writing
const WROTE_KEY = 'offsetlab.address.v1';
const WROTE_BEFORE_KEY = 'offsetlab.address.before.v1';

let getFragment = async () => null;
let timer = 0;
let last = -Infinity; // when the last write began (it asks the worker for the link)
let lastReplace = -Infinity; // when the address was last written
let dirty = false;
let writing = false;
let wrote = null;
let wroteBefore = null;
let enabled = false;

try {
  wrote = sessionStorage.getItem(WROTE_KEY);
  wroteBefore = sessionStorage.getItem(WROTE_BEFORE_KEY);
} catch {
  wrote = null;
}

/** The fragment (without `#`) this tab last wrote, or null. */
export function writtenFragment() {
  return wrote;
}

/** Whether `fragment` (without `#`) is the one this tab wrote last or the one before. */
export function ownFragment(fragment) {
  return Boolean(fragment) && (fragment === wrote || fragment === wroteBefore);
}

/**
 * `fragment()` resolves to the current document's fragment; '' to write the
 * address without one; null to leave it as it is.
 */
export function initAddress(fragment) {
  getFragment = fragment;
  enabled = true;
}

/** Something in the document changed: write the address soon. */
export function addressChanged() {
  if (!enabled) return;
  dirty = true;
  schedule();
}

function schedule() {
  if (timer || writing) return;
  const wait = Math.max(SETTLE_MS, last + MIN_INTERVAL_MS - performance.now());
  timer = setTimeout(write, wait);
}

async function write() {
  timer = 0;
  dirty = false;
  writing = true;
  last = performance.now();
  try {
    const fragment = await getFragment();
    const hash = fragment ? `#${fragment}` : '';
    if (fragment !== null && hash !== location.hash) {
      // The worker's answer to the last write may have come later than this
      // one's (a busy worker): the address is still written at most once per
      // MIN_INTERVAL_MS.
      const early = lastReplace + MIN_INTERVAL_MS - performance.now();
      if (early > 0) await new Promise((resolve) => { setTimeout(resolve, early); });
      // No fragment at all (not even `#`) when the document is too long for the address.
      history.replaceState(history.state, '', hash || location.href.split('#')[0]);
      lastReplace = performance.now();
      wroteBefore = wrote;
      wrote = fragment;
      try {
        if (wroteBefore !== null) sessionStorage.setItem(WROTE_BEFORE_KEY, wroteBefore);
        sessionStorage.setItem(WROTE_KEY, fragment);
      } catch {
        // Without sessionStorage a reload compares documents instead.
      }
      const body = document.body.dataset;
      body.addressWrites = String(Number(body.addressWrites ?? 0) + 1);
    }
  } catch (error) {
    console.warn('offsetlab: the address could not be updated:', error?.message ?? error);
  } finally {
    writing = false;
    document.body.dataset.addressAt = String(Date.now());
    if (dirty) schedule();
  }
}
