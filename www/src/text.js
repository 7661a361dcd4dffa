// A long text taken into CodeMirror's document in steps (issue 6, target 3):
// CodeMirror keeps every line as its own string in a tree, and building that
// tree for a 31 MB program at once was a main-thread task of half a second.
// Here it is built a chunk of lines per task, each chunk appended to the
// tree, so the page keeps handling input, drawing and the worker's messages.

import { Text } from '@codemirror/state';

/** Characters (UTF-16 units) taken per step. */
const CHUNK_CHARS = 256 * 1024;

/**
 * Lets the page handle input, draw and take the worker's messages before
 * the next step: a task of its own, queued behind those already waiting
 * (not scheduler.yield(), whose continuation goes first and kept the
 * worker's progress messages waiting until the whole text was taken; not
 * setTimeout, which waits at least 4 ms once nested).
 */
let channel = null;
const steps = [];
function yieldToPage() {
  if (!channel) {
    channel = new MessageChannel();
    channel.port1.onmessage = () => steps.shift()?.();
  }
  return new Promise((resolve) => {
    steps.push(resolve);
    channel.port2.postMessage(null);
  });
}

/** Line breaks as CodeMirror reads them (and the interpreter too): CR LF, LF and CR. */
const LINE_BREAK = /\r\n?|\n/;

/**
 * The first line break at or after `i` in `text` ({ at, next }: the chunk
 * before it ends at `at`, the next one starts at `next`, at the break's
 * last character, so that it splits into an empty first line), or null.
 * `cr`: the text has CRs (else only LF is looked for).
 */
function breakAfter(text, i, cr) {
  const lf = text.indexOf('\n', i);
  if (!cr) return lf < 0 ? null : { at: lf, next: lf };
  const c = text.indexOf('\r', i);
  if (c < 0 || (lf >= 0 && lf < c)) {
    if (lf < 0) return null;
    // `i` fell between the CR and the LF of a CR LF.
    return { at: text[lf - 1] === '\r' ? lf - 1 : lf, next: lf };
  }
  return { at: c, next: text[c + 1] === '\n' ? c + 1 : c };
}

/**
 * CodeMirror's document of `text`, built a chunk of lines per task, and its
 * text with LF line breaks: `{ doc, text }`; null if `stale()` turns true
 * meanwhile. Each chunk ends before a line break and the next one starts
 * with it, so the appended chunks have exactly the text's lines.
 * Not begun before the promise `after` settles. `chunk` and `pause`
 * (what waits between steps) are for the tests.
 */
export async function buildDocument(text, {
  stale = () => false, chunk = CHUNK_CHARS, pause = yieldToPage, after = null,
} = {}) {
  // Not before `after` (a promise) settles.
  if (after) await after;
  const cr = text.includes('\r');
  const pieces = [];
  let doc = null;
  let from = 0;
  for (;;) {
    await pause();
    if (stale()) return null;
    // Past the break the chunk starts with (at least one character on).
    const brk = breakAfter(text, from + Math.max(1, chunk), cr);
    const lines = text.slice(from, brk ? brk.at : text.length).split(cr ? LINE_BREAK : '\n');
    if (cr) pieces.push(lines.join('\n'));
    const part = Text.of(lines);
    doc = doc ? doc.append(part) : part;
    if (!brk) return { doc, text: cr ? pieces.join('') : text };
    from = brk.next;
  }
}

/**
 * `text` with `changes` (a ChangeSet of the document whose text it is)
 * applied, as `changes.apply(doc).toString()` would make it but without
 * going through every line of the document: an edit costs a copy of the
 * string at most (a 31 MB program's document takes a tenth of a second to
 * write out; issue 6, targets 3 and 4).
 */
export function applyChanges(text, changes) {
  let out = '';
  let pos = 0;
  changes.iterChanges((fromA, toA, fromB, toB, inserted) => {
    out += text.slice(pos, fromA) + inserted.toString();
    pos = toA;
  });
  return out + text.slice(pos);
}
