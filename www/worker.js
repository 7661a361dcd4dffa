// The interpreter's worker: loads the wasm core, owns the Session and the
// OffscreenCanvas the page handed over, runs programs and draws them. Only
// small results (summary, diagnostics) go back to the page.

import init, { Session } from './pkg/offsetlab.js';

let session = null;
let size = { width: 300, height: 150, dpr: 1 };
let latest = 0;

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

function draw() {
  session.render(size.width, size.height, size.dpr);
  self.postMessage({ type: 'drawn', ...size });
}

function handle(message) {
  switch (message.type) {
    case 'init':
      session.attach_canvas(message.canvas);
      size = { width: message.width, height: message.height, dpr: message.dpr };
      draw();
      break;
    case 'resize':
      size = { width: message.width, height: message.height, dpr: message.dpr };
      draw();
      break;
    case 'run': {
      // A newer request is already queued: skip straight to it.
      if (message.gen < latest) return;
      const started = performance.now();
      const result = session.run(message.program, message.setup);
      draw();
      self.postMessage({
        type: 'result',
        gen: message.gen,
        summary: result.summary,
        diagnostics: result.diagnostics,
        ms: performance.now() - started,
      });
      break;
    }
    default:
      break;
  }
}
