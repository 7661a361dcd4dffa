// Documents replace the work: an example from the menu, a link, a file or
// the work kept before. The user's own work is kept first (storage.js
// keepPrevious), across reloads too, and one click away ("Restore my
// previous program"): opening a document never destroys it.

import { showBanner } from './banner.js';
import { EXAMPLES, exampleById } from './examples.js';
import { renderOffsets } from './offsets.js';
import { EMBED } from './page.js';
import {
  call, cancelScheduledRun, fileRead, requestRun, setPendingView, workerDone,
} from './runner.js';
import { renderSettings } from './settings.js';
import { cloneSetup, machineOf } from './setup.js';
import { pause } from './stepper.js';
import { keepPrevious, loadPrevious } from './storage.js';
import {
  currentWork, isOwn, persist, showNote, work,
} from './work.js';

const $ = (id) => document.getElementById(id);
let editor = null;
let exampleSelect = null;

/** The view a work asks for, the machine's defaults filled in. */
export function viewOf(w) {
  const v = w.view ?? {};
  return {
    plane: v.plane ?? (machineOf(w.setup) === 'lathe' ? 'ZX' : 'XY'),
    zoom: v.zoom ?? 1,
    pan: v.pan ?? [0, 0],
    step: v.step ?? -1,
    // The view's options, each as the document has it (absent: off, and
    // the legend shown), so a document opened does not keep the last one's.
    swept: Boolean(v.swept),
    legend: v.legend !== false,
    // The 3D view's yaw and pitch (behaviour 10.9), when the document has them.
    ...(Array.isArray(v.angles) ? { angles: v.angles } : {}),
  };
}

/**
 * Shows `w` { program, setup, setupText?, view?: {plane, zoom, pan, step}, example?, link? }:
 * the editor, the panels, then one run with its view and current block.
 */
export function loadDocument(w, { ran = 0 } = {}) {
  pause();
  work.loading = true;
  try {
    work.example = w.example ?? null;
    work.link = Boolean(w.link);
    work.setup = cloneSetup(w.setup);
    work.setupText = typeof w.setupText === 'string' ? w.setupText : null;
    setPendingView(viewOf(w));
    // The editor takes a long text in steps while the worker runs it; the
    // text of a file the worker is running already (`ran`) once its drawing
    // is made: on two cores, the editor's work at the same time slowed the
    // run and the drawing (bench-browser target 3).
    const { text } = editor.setText(w.program, ran ? { after: workerDone('drawn', ran) } : {});
    // A file the worker is running already (`ran`, modules/opening.js) is
    // not sent again.
    if (fileRead(ran, text)) setPendingView(null);
    else requestRun(text);
  } finally {
    work.loading = false;
  }
  // An edit waiting for its run is replaced by the run just sent.
  cancelScheduledRun();
  renderOffsets({ force: true });
  renderSettings();
  if (work.setupText !== null) $('setup').value = work.setupText;
  exampleSelect.value = work.example ?? '';
  showNote();
  persist();
}

/** Keeps the current work if it is the user's own; shows the restore button. */
function displaceCurrent() {
  const now = currentWork();
  if (isOwn(now)) keepPrevious(now);
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

/** Opens a document's work after keeping the user's own, with a banner saying what happened. */
export function openWork(w, message, options = {}) {
  displaceCurrent();
  loadDocument(w, options);
  const kept = Boolean(loadPrevious());
  showBanner(kept ? `${message} Your previous program is kept.` : message, {
    kind: 'opened',
    action: kept ? 'Restore my previous program' : undefined,
    onAction: restorePrevious,
  });
}

/** A document of the codec (the document JSON) as the page's work. */
export function workOf(doc, extra = {}) {
  const { program = '', view = null, step = null, ...docSetup } = doc;
  return { program, setup: docSetup, view: { ...(view ?? {}), step: step ?? -1 }, link: true, ...extra };
}

/** True when `a` and `b` carry the same program and setup (the codec's canonical JSON). */
export async function sameDocument(a, b) {
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

/** The examples menu and the restore button. */
export function initDocuments(theEditor) {
  editor = theEditor;
  exampleSelect = $('example');
  // Shown once the program is no longer an example as loaded (edited, or
  // a link or file opened): the menu never names what is not there.
  exampleSelect.add(new Option('Choose an example…', ''));
  for (const ex of EXAMPLES) exampleSelect.add(new Option(ex.title, ex.id));
  exampleSelect.value = work.example ?? '';
  $('restore-previous').addEventListener('click', restorePrevious);
  $('examples').addEventListener('submit', (event) => {
    event.preventDefault();
    const ex = exampleById(exampleSelect.value);
    if (!ex) return;
    openWork({ ...ex, example: ex.id }, `Loaded “${ex.title}”.`);
  });
  showNote();
  showRestore();
}
