// The Share panel: the compact link of the current document (program,
// setup, view and current block) copied to the clipboard, with its length;
// the plain, hand-writable form and the embed form for tutorial authors
// (with the <iframe> code); past the codec's long-link length (8,000
// characters) a warning and the document as a file instead. Where the
// clipboard API is missing or refused, the link is selected in a text field
// for the user to copy.

import { download, fileStem } from './files.js';

const $ = (id) => document.getElementById(id);
let ctx = null;
let latest = null; // the last answer of the worker: { link | plain, limits } or { setupFailed } or { error }
let serial = 0;

const number = (n) => n.toLocaleString('en-US');

/**
 * `call(op, args)` asks the worker; `flush()` sends an edit still waiting for
 * its run; `program()` is the editor's text; `base` the page's address
 * without the fragment.
 */
export function initShare({ call, flush, program, base }) {
  ctx = { call, flush, program, base };
  $('share-open').addEventListener('click', () => openShare());
  $('share-close').addEventListener('click', closeShare);
  $('share-copy').addEventListener('click', () => copy($('share-link').value));
  $('share-plain').addEventListener('change', () => refresh({ copyIt: true }));
  $('share-embed').addEventListener('change', () => refresh({ copyIt: true }));
  $('share-download').addEventListener('click', downloadDocument);
  $('share').addEventListener('keydown', (event) => {
    if (event.key === 'Escape') closeShare();
  });
}

/** Opens the panel, makes the link and copies it. */
export async function openShare() {
  const panel = $('share');
  panel.hidden = false;
  $('share-open').setAttribute('aria-expanded', 'true');
  await refresh({ copyIt: true });
  const field = $('share-link');
  if (document.body.dataset.copied !== 'false') {
    // Copied (or nothing to copy): show the link from its start.
    field.focus();
    field.setSelectionRange(0, 0);
    field.scrollLeft = 0;
  }
}

function closeShare() {
  $('share').hidden = true;
  $('share-open').setAttribute('aria-expanded', 'false');
  $('share-open').focus();
}

async function refresh({ copyIt }) {
  const mine = ++serial;
  const field = $('share-link');
  const status = $('share-status');
  const warning = $('share-warning');
  const embed = $('share-embed').checked;
  const plain = $('share-plain').checked;
  ctx.flush();
  status.textContent = 'Making the link…';
  let answer;
  try {
    answer = await ctx.call('document', { base: ctx.base, embed, forms: [plain ? 'plain' : 'link'] });
  } catch (error) {
    answer = { error: error.message };
  }
  if (mine !== serial) return; // a newer request is on its way
  latest = answer;
  delete document.body.dataset.copied;
  $('share-iframe-row').hidden = true;
  if (answer.error || answer.setupFailed) {
    field.value = '';
    $('share-length').textContent = '';
    warning.hidden = true;
    $('share-download').disabled = true;
    status.textContent = answer.setupFailed
      ? 'The setup document has errors (see Diagnostics): fix them first, so that the link carries your offsets and settings.'
      : `No link: ${answer.error}`;
    document.body.dataset.share = 'failed';
    return;
  }
  const text = plain ? answer.plain : answer.link;
  field.value = text;
  $('share-download').disabled = false;
  $('share-length').textContent = `${number(text.length)} characters`;
  document.body.dataset.shareLength = String(text.length);
  const long = text.length > answer.limits.long;
  warning.hidden = !long;
  $('share-download').classList.toggle('primary', long);
  if (long) {
    warning.textContent = `This link is ${number(text.length)} characters long: past ${number(answer.limits.long)} characters chat tools, forums and some browsers cut links short. Share the document as a file instead — “Download the document” below; it opens with “Open…”.`;
  }
  if (embed) {
    $('share-iframe').value = `<iframe src="${attribute(text)}" width="720" height="420" style="border: 1px solid #d0d7de; border-radius: 6px" title="offsetlab: ${attribute(fileStem(ctx.program()))}" loading="lazy"></iframe>`;
    $('share-iframe-row').hidden = false;
  }
  document.body.dataset.share = plain ? 'plain' : 'compact';
  document.body.dataset.shareSerial = String(mine);
  if (long) {
    status.textContent = 'Not copied: the link is too long to share safely.';
  } else if (copyIt) {
    await copy(text);
  } else {
    status.textContent = '';
  }
}

function attribute(text) {
  return text.replace(/&/g, '&amp;').replace(/"/g, '&quot;').replace(/</g, '&lt;');
}

async function copy(text) {
  const status = $('share-status');
  if (!text) return;
  try {
    if (!navigator.clipboard?.writeText) throw new Error('no clipboard');
    await navigator.clipboard.writeText(text);
    status.textContent = 'Copied to the clipboard.';
    document.body.dataset.copied = 'true';
  } catch {
    // The visible fallback: the link selected in its field.
    const field = $('share-link');
    field.focus();
    field.select();
    status.textContent = 'The clipboard is not available here: the link is selected in the field above — copy it with Ctrl+C (⌘C on a Mac).';
    document.body.dataset.copied = 'false';
  }
}

async function downloadDocument() {
  if (!latest || latest.error || latest.setupFailed) return;
  ctx.flush();
  const { json, setupFailed } = await ctx.call('document', { base: ctx.base, forms: ['json'] });
  if (setupFailed) return;
  download(json, `${fileStem(ctx.program())}-document.json`, 'application/json');
}
