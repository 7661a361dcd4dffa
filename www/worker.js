// The interpreter's worker: loads the wasm core, owns the Session and the
// OffscreenCanvas the page handed over, runs programs, keeps the view state
// (plane, zoom, pan, current block) and draws — at most once per animation
// frame however many view changes arrive. Only small results go back to the
// page: the summary, the diagnostics, the view state and the current block's
// report — and, when the page asks (call), a link, a document or an export.
//
// In:  init {canvas, width, height, dpr, theme, stepSeq, testHooks} · resize {width, height, dpr}
//      run {gen, program | edit | file, setup, view} (edit {base, from, to,
//        insert, length}: the program of run `base` with from..to replaced;
//        file: a File the page opened, read here straight into wasm memory)
//      · theme {name}
//      view {op: zoom {x, y, factor} | pan {dx, dy} | orbit {dx, dy} | fit | plane {plane} | set {view}}
//      step {index} · pick {x, y, tolerance} · line {line}
//      call {id, op, ...}: op document {base, embed, forms} · decode {text, base}
//        · read {text, base} · canonical {document} · export {format}
//        · tool-table {text} · tool-table-file {table}
// Out: ready (the core is loaded) · busy {task: 'run' | a call's op, gen | id}
//      read {gen} (the file of run gen is read)
//      result {gen, summary, diagnostics}
//      state {gen, view, step, blocks, block, cause} · drawn {width, height, dpr}
//      failure {gen, message} · reply {id, value | error}
//      resend {gen} (run gen's edit was not made on the text held here: the
//        page sends its whole text)
//
// Calls are answered in order with the runs, so a call posted after a run
// request sees that run.
//
// The page supervises this worker (modules/supervisor.js): it is terminated
// and replaced when a task takes longer than the page's time budget or when
// it reports a `failure`. A `failure` means this worker must not be used
// again: an exception from a run or a drawing, or a WebAssembly trap (a
// panic, out of memory) anywhere — after a trap the core's state may be
// broken ("recursive use of an object"), so only a new worker is safe.

import init, {
  Session, decode_link, document_json, encode_link, encode_plain, link_limits, read_document, read_tool_table, tool_table_file,
} from './pkg/offsetlab.js';

let session = null;
let size = { width: 300, height: 150, dpr: 1 };
let latest = 0; // newest run generation asked for
let shown = 0; // generation of the run the session holds
let frame = 0;
let stateCause = '';
let lastBlock = -2;
let stepSeq = 0; // the last step request handled (the page counts its own)
let canvas = null; // the OffscreenCanvas (also held by the session) for PNG export
let setupFailed = false; // the last run's setup was refused (it ran with the default setup)
const encoder = new TextEncoder();
let testHooks = false; // honour the test-only `fault` of a run (see fault())

/**
 * Alive: this worker holds a Web Lock named after it (the page names each
 * worker) for as long as it lives, so the page learns at once when it dies
 * (the lock is then granted to the page); without Web Locks the page notices
 * only when it stops answering.
 */
const alive = self.name && self.navigator?.locks
  ? new Promise((held) => {
    self.navigator.locks.request(self.name, () => {
      held();
      return new Promise(() => {}); // held until the worker ends
    }).catch(() => held());
  })
  : Promise.resolve();

let memory = null; // the wasm module's memory
const ready = Promise.all([init(), alive]).then(([exports]) => {
  memory = exports.memory;
  session = new Session();
  self.postMessage({ type: 'ready' });
});

// Messages are handled one at a time, in order, once the core is loaded.
let queue = ready;
self.addEventListener('message', (event) => {
  const message = event.data;
  if (message.type === 'run') latest = Math.max(latest, message.gen);
  queue = queue
    .then(() => handle(message))
    .catch((error) => {
      self.postMessage({ type: 'failure', gen: message.gen ?? 0, message: String(error?.message ?? error) });
    });
});

const nextFrame = typeof self.requestAnimationFrame === 'function'
  ? (f) => self.requestAnimationFrame(f)
  : (f) => setTimeout(f, 16);

// During a pan or zoom gesture a large path is drawn from the last whole
// frame's pixels, moved and scaled (Session.render_moving: a frame in the
// time of an image copy); the whole frame follows once the gesture has
// paused this long.
const SETTLE_MS = 150;
let gestureOnly = true; // every redraw asked for since the last frame was a pan or zoom step
let settle = 0;

/**
 * Asks for one redraw (and state report) on the next animation frame;
 * `gesture`: the redraw of a pan or zoom step, which may be a moving frame.
 */
function invalidate(cause, gesture = false) {
  if (cause) stateCause = cause;
  if (!gesture) gestureOnly = false;
  if (frame) return;
  frame = nextFrame(() => {
    frame = 0;
    const quick = gestureOnly;
    gestureOnly = true;
    try {
      const started = performance.now();
      let moving = false;
      if (quick) {
        moving = session.render_moving(size.width, size.height, size.dpr);
      } else {
        session.render(size.width, size.height, size.dpr);
      }
      clearTimeout(settle);
      if (moving) settle = setTimeout(() => invalidate('view'), SETTLE_MS);
      self.postMessage({ type: 'drawn', gen: shown, ms: performance.now() - started, moving, ...size });
      postState();
    } catch (error) {
      self.postMessage({ type: 'failure', gen: shown, message: String(error?.message ?? error) });
    }
  });
}

// The program of the last run request, as a string (null: a file run's,
// or not known), and the request's generation: what an edit is made on.
let text = null;
let textGen = -1;
// The run request whose program is in the session's buffer as it will be
// run (written, or made there from the last one by an edit), when it is
// ASCII (its UTF-16 units are its bytes); -1: none.
let bufferGen = -1;
const ASCII = /^[\x00-\x7f]*$/;

/**
 * Takes the program of run request `message`: its text, or its edit of the
 * last request's text (`{ base, from, to, insert, length }`), or none for a
 * file. False when the edit cannot be made (not on the text held, or not
 * giving the length the page has): the page then sends the whole text.
 */
function takeProgram(message) {
  if (typeof message.program === 'string') {
    [text, textGen, bufferGen] = [message.program, message.gen, -1];
    return true;
  }
  const edit = message.edit;
  if (!edit) {
    [text, textGen, bufferGen] = [null, -1, -1];
    return true;
  }
  const made = text !== null && textGen === edit.base
    ? text.slice(0, edit.from) + edit.insert + text.slice(edit.to)
    : null;
  if (made === null || made.length !== edit.length) {
    [text, textGen, bufferGen] = [null, -1, -1];
    return false;
  }
  [text, textGen] = [made, message.gen];
  // The same edit of the buffer (its bytes are its units): the text made
  // of the edit's pieces need not be written whole.
  bufferGen = bufferGen === edit.base && ASCII.test(edit.insert) && spliceProgram(edit)
    ? message.gen
    : -1;
  return true;
}

/**
 * Makes the edit in the session's buffer (ASCII: the base text was
 * `length - insert.length + (to - from)` bytes); false if it could not.
 */
function spliceProgram({ from, to, insert, length }) {
  const before = length - insert.length + (to - from);
  const at = session.program_splice(before, from, to, insert.length);
  if (at === 0) return false;
  if (insert.length > 0) encoder.encodeInto(insert, new Uint8Array(memory.buffer, at, insert.length));
  return true;
}

/** The program of run `message` in the session's buffer: its length in bytes. */
function programInBuffer(message) {
  if (bufferGen === message.gen) return text.length;
  const length = writeProgram(text);
  bufferGen = length === text.length ? message.gen : -1;
  return length;
}

/**
 * Writes `program` as UTF-8 into the session's program buffer, in wasm
 * memory, and returns its length in bytes (Session.program_buffer: far
 * quicker than passing the string). A UTF-16 unit is at most 3 bytes: a
 * text that is not ASCII may need a second, larger buffer.
 */
function writeProgram(program) {
  for (const room of [program.length, 3 * program.length]) {
    const at = session.program_buffer(room);
    if (at === 0) break;
    const { read, written } = encoder.encodeInto(program, new Uint8Array(memory.buffer, at, room));
    if (read === program.length) return written;
  }
  throw new Error('the program does not fit in memory');
}

/**
 * Reads `file` (a program the page opened) into the session's program
 * buffer, as UTF-8 bytes, and returns its length: no text is made of it
 * here, nor copied from the page (modules/opening.js). In one piece: read
 * as a stream (as fast), the page's thread had tasks of up to 0.17 s while
 * it read the text after it, against 0.10 s (a 31 MB file). A leading byte
 * order mark is dropped, as the page's `file.text()` drops it, so that
 * both read the same text.
 */
async function readProgram(file) {
  const data = new Uint8Array(await file.arrayBuffer());
  const bom = data.length >= 3 && data[0] === 0xef && data[1] === 0xbb && data[2] === 0xbf ? 3 : 0;
  const length = data.length - bom;
  const at = session.program_buffer(length);
  if (at === 0 && length > 0) throw new Error('the program does not fit in memory');
  new Uint8Array(memory.buffer, at, length).set(data.subarray(bom));
  return length;
}

function postState() {
  const view = session.view();
  const step = session.step();
  // The block report is sent only when the current block or the run changed.
  const block = step >= 0 && (step !== lastBlock || stateCause === 'run') ? session.block(step) : undefined;
  lastBlock = step;
  self.postMessage({
    type: 'state',
    gen: shown,
    view,
    step,
    blocks: session.block_count(),
    block: step < 0 ? null : block,
    cause: stateCause,
    stepSeq,
  });
  stateCause = '';
}

/** Runs the program of run request `message`, `length` bytes in the program buffer. */
function run(message, length) {
  const started = performance.now();
  // A long run tells the page how far it has got: after its first MiB,
  // then at most every 100 ms (the page shows it past PROGRESS_AFTER_MS,
  // modules/page.js). Posted during the run, these reach the page at
  // once: only this worker is busy.
  let told = -Infinity;
  const progress = (fraction) => {
    const now = performance.now();
    if (now - told < 100) return;
    told = now;
    self.postMessage({ type: 'progress', gen: message.gen, fraction, ms: now - started });
  };
  const result = session.run_buffer(length, message.setup, progress);
  setupFailed = result.diagnostics.some((d) => d.line === 0 && d.code.startsWith('setup-'));
  shown = message.gen;
  if (message.view) session.set_view(message.view);
  self.postMessage({
    type: 'result',
    gen: message.gen,
    summary: result.summary,
    diagnostics: result.diagnostics,
    ms: performance.now() - started,
  });
  invalidate('run');
}

function handle(message) {
  switch (message.type) {
    case 'init':
      canvas = message.canvas;
      session.attach_canvas(message.canvas);
      // A lost and restored 2D context (the browser freed its memory) is a
      // blank canvas: attached again, the session paints the next frame
      // whole rather than only where it changed (src/render/display.rs).
      canvas.addEventListener('contextrestored', () => {
        session.attach_canvas(canvas);
        invalidate();
      });
      session.set_theme(message.theme || 'light');
      size = { width: message.width, height: message.height, dpr: message.dpr };
      // A restarted worker continues the page's count of step requests.
      stepSeq = message.stepSeq ?? 0;
      testHooks = message.testHooks === true;
      invalidate('init');
      break;
    case 'resize':
      size = { width: message.width, height: message.height, dpr: message.dpr };
      invalidate('resize');
      break;
    case 'theme':
      session.set_theme(message.name);
      invalidate('theme');
      break;
    case 'run':
      // The program: the whole text, an edit of the last one (kept even
      // when this run is skipped: the next edit is made on it), or a file.
      if (!takeProgram(message)) {
        if (message.gen >= latest) self.postMessage({ type: 'resend', gen: message.gen });
        return undefined;
      }
      // A newer request is already queued: skip straight to it.
      if (message.gen < latest) return undefined;
      // The page's supervisor times each task from here.
      self.postMessage({ type: 'busy', task: 'run', gen: message.gen });
      if (message.file) {
        // (Read meanwhile: a newer request is run instead.)
        return readProgram(message.file).then((length) => {
          // The page reads the text for its editor from now on.
          self.postMessage({ type: 'read', gen: message.gen });
          if (message.gen >= latest) run(message, length);
        });
      }
      if (testHooks && fault(text)) return undefined;
      run(message, programInBuffer(message));
      break;
    case 'view':
      view(message);
      invalidate('view', message.op === 'zoom' || message.op === 'pan' || message.op === 'orbit');
      break;
    case 'step':
      session.set_step(message.index);
      stepSeq = message.seq ?? stepSeq;
      invalidate('step');
      break;
    case 'pick': {
      const block = session.pick(message.x, message.y, message.tolerance ?? 6);
      if (block >= 0) {
        session.set_step(block);
        invalidate('pick');
      }
      break;
    }
    case 'line': {
      const block = session.block_at_line(message.line);
      if (block >= 0) {
        session.set_step(block);
        invalidate('line');
      }
      break;
    }
    case 'call':
      return call(message);
    default:
      break;
  }
  return undefined;
}

/**
 * Answers a call; an exception becomes `{ error }`. A WebAssembly trap (or
 * running out of memory) is also reported as a `failure`: the page then
 * replaces this worker, whose core can no longer be trusted.
 */
async function call(message) {
  let reply;
  let trap = null;
  self.postMessage({ type: 'busy', task: message.op, id: message.id });
  try {
    reply = { type: 'reply', id: message.id, value: await answer(message) };
  } catch (error) {
    reply = { type: 'reply', id: message.id, error: String(error?.message ?? error) };
    if (error instanceof WebAssembly.RuntimeError || error instanceof RangeError) trap = error;
  }
  self.postMessage(reply);
  if (trap) self.postMessage({ type: 'failure', gen: shown, message: String(trap.message ?? trap) });
}

/** A program asking for a test fault: `(offsetlab-test-fault: hang)`, … */
const TEST_FAULT = /\(offsetlab-test-fault: (hang|trap|trap-in-first-worker|error|exit)\)/;

/**
 * Test-only faults, so the end-to-end tests can check the page's
 * supervision (real programs are bounded by the core's limits and cannot
 * hang it): a run whose program contains `(offsetlab-test-fault: KIND)`
 * hangs, traps (`trap-in-first-worker`: only in the page's first worker),
 * throws an uncaught error or ends the worker. Honoured only
 * when the page started this worker with `testHooks`, which it does only
 * when the tests set `window.offsetlabTest = { hooks: true }` before the
 * page loads (an init script; never from a link, a file or the program).
 * Returns true when the run must not go on.
 */
function fault(program) {
  const kind = TEST_FAULT.exec(program)?.[1];
  switch (kind) {
    case 'hang':
      // A runaway run: busy for ever, answering nothing (the page's budget stops it).
      while (testHooks) {
        // spin
      }
      return true;
    case 'trap':
      // What a panic in the core looks like from here.
      throw new WebAssembly.RuntimeError('unreachable (test fault)');
    case 'trap-in-first-worker':
      // A crash that does not come back: only the page's first worker traps.
      if (/-1$/.test(self.name)) throw new WebAssembly.RuntimeError('unreachable (test fault)');
      return false;
    case 'error':
      // An uncaught error: the worker's `error` event at the page.
      setTimeout(() => {
        throw new Error('test fault: an uncaught error in the worker');
      });
      return true;
    case 'exit':
      // The worker dies without a word: noticed when it stops answering.
      self.close();
      return true;
    default:
      return false;
  }
}

async function answer(message) {
  switch (message.op) {
    case 'document': {
      // The current document and the forms asked for (`forms`: any of
      // link, plain, json; all by default): the compact link, the plain one
      // (with `base#`), the JSON file. With a refused setup the session
      // holds the default one, so nothing is made from it.
      const document = session.document();
      const limits = link_limits();
      if (setupFailed) return { document, setupFailed: true, limits };
      const forms = message.forms ?? ['link', 'plain', 'json'];
      const embed = Boolean(message.embed);
      const out = { document, limits };
      if (forms.includes('link')) out.link = encode_link(message.base, document, embed);
      if (forms.includes('plain')) out.plain = `${message.base}#${encode_plain(document, embed)}`;
      if (forms.includes('json')) out.json = document_json(document);
      return out;
    }
    case 'decode': {
      const decoded = decode_link(message.text);
      if (decoded.error) return decoded;
      // "Open in playground": the same document, not embedded (none when
      // the page is not served over http(s)).
      let playground = null;
      try {
        playground = encode_link(message.base, decoded.document, false);
      } catch {
        playground = null;
      }
      return { ...decoded, playground };
    }
    case 'read':
      return read_document(message.text);
    case 'tool-table':
      // LinuxCNC's tool table file read by the core (behaviour 22.9).
      return read_tool_table(message.text);
    case 'tool-table-file':
      return tool_table_file(message.table);
    case 'canonical':
      // The document as the codec writes it, to tell two documents apart.
      return document_json(message.document);
    case 'export':
      return exportFile(message.format);
    default:
      throw new Error(`unknown call ${message.op}`);
  }
}

/** The current view or toolpath as a file's contents. */
async function exportFile(format) {
  switch (format) {
    case 'png': {
      if (!canvas) throw new Error('the drawing is not ready');
      // Draw now, so the file is exactly the current view.
      session.render(size.width, size.height, size.dpr);
      return canvas.convertToBlob({ type: 'image/png' });
    }
    case 'svg':
      return session.render_svg(size.width, size.height);
    case 'csv':
      return session.moves_csv();
    case 'json':
      return session.moves_json();
    default:
      throw new Error(`unknown export format ${format}`);
  }
}

function view(message) {
  switch (message.op) {
    case 'zoom':
      session.zoom_at(message.x, message.y, message.factor);
      break;
    case 'pan':
      session.pan_by(message.dx, message.dy);
      break;
    case 'orbit':
      session.orbit_by(message.dx, message.dy);
      break;
    case 'fit':
      session.fit();
      break;
    case 'plane':
      session.set_plane(message.plane);
      break;
    case 'set':
      session.set_view(message.view);
      break;
    default:
      break;
  }
}
