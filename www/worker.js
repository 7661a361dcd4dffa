// The interpreter's worker: loads the wasm core, owns the Session and the
// OffscreenCanvas the page handed over, runs programs, keeps the view state
// (plane, zoom, pan, current block) and draws — at most once per animation
// frame however many view changes arrive. Only small results go back to the
// page: the summary, the diagnostics, the view state and the current block's
// report.
//
// In:  init {canvas, width, height, dpr, theme} · resize {width, height, dpr}
//      run {gen, program, setup} · theme {name}
//      view {op: zoom {x, y, factor} | pan {dx, dy} | fit | plane {plane} | set {view}}
//      step {index} · pick {x, y, tolerance} · line {line}
// Out: result {gen, summary, diagnostics} · state {gen, view, step, blocks, block, cause}
//      drawn {width, height, dpr} · failure {gen, message}

import init, { Session } from './pkg/offsetlab.js';

let session = null;
let size = { width: 300, height: 150, dpr: 1 };
let latest = 0; // newest run generation asked for
let shown = 0; // generation of the run the session holds
let frame = 0;
let stateCause = '';
let lastBlock = -2;
let stepSeq = 0; // the last step request handled (the page counts its own)

const ready = init().then(() => {
  session = new Session();
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

/** Asks for one redraw (and state report) on the next animation frame. */
function invalidate(cause) {
  if (cause) stateCause = cause;
  if (frame) return;
  frame = nextFrame(() => {
    frame = 0;
    try {
      session.render(size.width, size.height, size.dpr);
      self.postMessage({ type: 'drawn', ...size });
      postState();
    } catch (error) {
      self.postMessage({ type: 'failure', gen: shown, message: String(error?.message ?? error) });
    }
  });
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

function handle(message) {
  switch (message.type) {
    case 'init':
      session.attach_canvas(message.canvas);
      session.set_theme(message.theme || 'light');
      size = { width: message.width, height: message.height, dpr: message.dpr };
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
    case 'run': {
      // A newer request is already queued: skip straight to it.
      if (message.gen < latest) return;
      const started = performance.now();
      const result = session.run(message.program, message.setup);
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
      break;
    }
    case 'view':
      view(message);
      invalidate('view');
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
    default:
      break;
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
