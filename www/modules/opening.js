// Files opened with Open… or dropped on the page: a document (.json), a link
// saved as text, or a program (.nc and the like), which runs with the setup
// shown. What cannot be read is said in the banner; the work stays.

import { openWork, workOf } from './documents.js';
import { showLinkError } from './links.js';
import { EMBED, base } from './page.js';
import { call, post } from './runner.js';
import { cloneSetup } from './setup.js';
import { work } from './work.js';

/** Files larger than this are not read (the interpreter reads 256 MiB of program). */
const MAX_FILE = 300 * 1024 * 1024;

const $ = (id) => document.getElementById(id);

async function openFile(file) {
  if (!file) return;
  const what = `The file “${file.name}”`;
  if (file.size > MAX_FILE) {
    showLinkError({ code: 'file-too-large', message: `it is ${Math.round(file.size / 1048576)} MiB; at most ${MAX_FILE / 1048576} MiB are read` }, what);
    return;
  }
  // The worker makes the memory of a large program's run ready while the
  // file is read (Session.expect).
  post({ type: 'expect', bytes: file.size });
  let text;
  try {
    text = await file.text();
  } catch (error) {
    showLinkError({ code: 'file-unreadable', message: error.message }, what);
    return;
  }
  const trimmed = text.trim();
  let answer;
  if (trimmed.startsWith('{')) {
    answer = await call('read', { text });
  } else if (!trimmed.includes('\n') && /^(?:https?:\/\/[^\s#]*)?#?(?:v\d+\.|program=)/.test(trimmed)) {
    answer = await call('decode', { text: trimmed, base });
  } else {
    // A program: it runs with the setup shown.
    answer = { document: { ...cloneSetup(work.setup), program: text } };
    if (work.setupText !== null) answer.setupText = work.setupText;
  }
  if (answer.error) {
    showLinkError(answer.error, what);
    return;
  }
  const w = workOf(answer.document);
  if (answer.setupText !== undefined) w.setupText = answer.setupText;
  openWork(w, `Opened “${file.name}”.`);
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
