// Files opened with Open… or dropped on the page: a document (.json), a link
// saved as text, or a program (.nc and the like), which runs with the setup
// shown. What cannot be read is said in the banner; the work stays.

import { openWork, viewOf, workOf } from './documents.js';
import { showLinkError } from './links.js';
import { EMBED, base } from './page.js';
import {
  call, fileRead, requestFileRun, requestRun, workerDone,
} from './runner.js';
import { dialectOf } from './dialect.js';
import { cloneSetup } from './setup.js';
import { work } from './work.js';

/** Files larger than this are not read (the interpreter reads 256 MiB of program). */
const MAX_FILE = 300 * 1024 * 1024;

/**
 * A program file at least this large is read by the worker itself, straight
 * into wasm memory, and run; this thread reads its text for the editor once
 * the worker has read it: reading the text here, copying it to the worker
 * and there into wasm memory came before the run (bench-browser target 3).
 */
const WORKER_READS_FROM = 1024 * 1024;

const $ = (id) => document.getElementById(id);

/** Whether a file starting with `head` is a document (JSON) or a link rather than a program. */
function documentOrLink(head, whole) {
  const trimmed = head.trim();
  if (trimmed.startsWith('{')) return true;
  // A link is one line (all of the file when `whole`).
  return !(whole ? trimmed : head).includes('\n')
    && /^(?:https?:\/\/[^\s#]*)?#?(?:v\d+\.|program=)/.test(trimmed);
}

/** A copy of `setup` under the control `dialect` names, if it names one. */
function named(setup, dialect) {
  const copy = cloneSetup(setup);
  if (dialect && copy.settings?.control !== dialect.control) {
    copy.settings = { ...(copy.settings ?? {}), control: dialect.control };
  }
  return copy;
}

async function openFile(file) {
  if (!file) return;
  const what = `The file “${file.name}”`;
  if (file.size > MAX_FILE) {
    showLinkError({ code: 'file-too-large', message: `it is ${Math.round(file.size / 1048576)} MiB; at most ${MAX_FILE / 1048576} MiB are read` }, what);
    return;
  }
  let ran = 0;
  // The control the program's text names (behaviour 22.8), from its start.
  let dialect = null;
  if (file.size >= WORKER_READS_FROM) {
    let head;
    try {
      head = await file.slice(0, 256 * 1024).text();
    } catch (error) {
      showLinkError({ code: 'file-unreadable', message: error.message }, what);
      return;
    }
    // A program: the worker runs it from the file now, with the setup shown.
    if (!documentOrLink(head, false)) {
      dialect = dialectOf(head);
      ran = requestFileRun(file, viewOf({ setup: named(work.setup, dialect) }));
    }
  }
  let text;
  // Once the worker has read the file: the two reads at once stalled this
  // thread (bench-browser target 3, its longest main-thread task).
  if (ran) await workerDone('read', ran, 2000);
  try {
    text = await file.text();
  } catch (error) {
    // The run of the file (if the worker could read it) is not shown: the
    // text shown runs again.
    if (ran) {
      fileRead(ran, null);
      requestRun();
    }
    showLinkError({ code: 'file-unreadable', message: error.message }, what);
    return;
  }
  const trimmed = text.trim();
  let answer;
  let said = '';
  if (ran || !documentOrLink(text, true)) {
    // A program: it runs with the setup shown, under the control its text
    // names (behaviour 22.8), said in the banner.
    if (!ran) dialect = dialectOf(text);
    const setup = named(work.setup, dialect);
    if (setup.settings?.control !== work.setup.settings?.control) {
      said = ` The control is set to LinuxCNC 2.9: ${dialect.why} is LinuxCNC’s.`;
    }
    answer = { document: { ...setup, program: text } };
    if (work.setupText !== null && !said) answer.setupText = work.setupText;
  } else if (trimmed.startsWith('{')) {
    answer = await call('read', { text });
  } else {
    answer = await call('decode', { text: trimmed, base });
  }
  if (answer.error) {
    showLinkError(answer.error, what);
    return;
  }
  const w = workOf(answer.document);
  if (answer.setupText !== undefined) w.setupText = answer.setupText;
  openWork(w, `Opened “${file.name}”.${said}`, { ran });
  document.body.dataset.opened = file.name;
}

export function initOpening() {
  $('open-file-button').addEventListener('click', () => $('open-file').click());
  $('open-file').addEventListener('change', (event) => {
    const [file] = event.target.files;
    event.target.value = '';
    openFile(file);
  });
  if (EMBED) return;
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
