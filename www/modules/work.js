// The page's work: the program (the editor holds it), the setup and where
// they came from, as the runs, the links and the autosave read them. The
// setup is one object, edited by the offset table, the settings form and
// the raw JSON, which all follow it; `setupText` is the raw JSON's text
// when it does not parse (it runs as typed, and the run says what is wrong).
// Work that came from an example, a link or a file is not the user's own
// until they change it: it is not kept when another replaces it.

import { addressChanged } from './address.js';
import { exampleById } from './examples.js';
import { cloneSetup } from './setup.js';
import { saveWork } from './storage.js';
import { viewState } from './view.js';

/** The work shown, besides its program. */
export const work = {
  setup: {},
  /** JSON text of the setup that did not parse, or null. */
  setupText: null,
  /** The id of the example shown while it is untouched, or null. */
  example: null,
  /** From a link or file, while untouched. */
  link: false,
  /** A document is being loaded: its edits are not the user's. */
  loading: false,
  /** The worker has reported a view state of a run. */
  viewKnown: false,
};

let program = () => '';
let startView = null;

/** `start`: the work the page opens with; `text()`: the editor's program. */
export function initWork(start, text) {
  program = text;
  startView = start.view ?? null;
  work.setup = cloneSetup(start.setup);
  work.setupText = typeof start.setupText === 'string' ? start.setupText : null;
  work.example = start.example ?? null;
  work.link = Boolean(start.link);
}

/** The setup as the worker reads it: the JSON text. */
export function setupDocument() {
  return work.setupText ?? JSON.stringify(work.setup);
}

/** The note of the example shown, and the menu naming it (neither once it is edited). */
export function showNote() {
  document.getElementById('example-note').textContent = exampleById(work.example)?.note ?? '';
  const menu = document.getElementById('example');
  if (menu && menu.options.length > 0) menu.value = work.example ?? '';
}

/** The user changed the program or the setup: the work is now their own. */
export function edited() {
  if (work.loading) return;
  work.link = false;
  if (work.example) {
    work.example = null;
    showNote();
  }
}

/** The work as the page holds it (what autosave keeps). */
export function currentWork() {
  // Before the worker first reports its view, the view is still the saved one.
  const view = work.viewKnown ? viewState() : startView ?? viewState();
  return {
    program: program(), setup: cloneSetup(work.setup), setupText: work.setupText, view,
    example: work.example, link: work.link,
  };
}

/** Saves the work (throttled; it is made when saved) and lets the address bar follow. */
export function persist() {
  saveWork(currentWork);
  addressChanged();
}

/** Work worth keeping: written or changed by the user (not an untouched example, link or file). */
export function isOwn(w) {
  if (!w || w.example || w.link) return false;
  return w.program.trim() !== '' || typeof w.setupText === 'string' || Object.keys(w.setup ?? {}).length > 0;
}
