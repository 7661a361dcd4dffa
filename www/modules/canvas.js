// The drawing's <canvas>: handed over to the worker as an OffscreenCanvas
// (the worker draws on it from then on), kept informed of the canvas's
// size, device-pixel ratio and colour scheme. A canvas hands its control
// over once only, so a restarted worker gets a new <canvas> in place of the
// old one — the same element (id, attributes, focus) with the same input.

import { TEST } from './page.js';
import { post, stepSeq } from './runner.js';
import { bindCanvas } from './view.js';

let canvas = null;
let handedOver = false;
let lastSize = '';
let sizeFrame = 0;
const resizeObserver = new ResizeObserver(reportSize);
const scheme = matchMedia('(prefers-color-scheme: dark)');
const theme = () => (scheme.matches ? 'dark' : 'light');

/** The <canvas> shown now (it is replaced when the worker restarts). */
export const currentCanvas = () => canvas;

function canvasSize() {
  const box = canvas.getBoundingClientRect();
  return { width: Math.max(1, Math.round(box.width)), height: Math.max(1, Math.round(box.height)), dpr: window.devicePixelRatio || 1 };
}

/**
 * A new worker's init message: the canvas (as an OffscreenCanvas), the
 * theme and size, the stepper's count.
 */
export function makeInit() {
  if (handedOver) {
    const fresh = canvas.cloneNode(false);
    fresh.classList.remove('dragging');
    const focused = document.activeElement === canvas;
    resizeObserver.unobserve(canvas);
    canvas.replaceWith(fresh);
    canvas = fresh;
    bindCanvas(canvas);
    resizeObserver.observe(canvas);
    if (focused) canvas.focus();
  }
  handedOver = true;
  const offscreen = canvas.transferControlToOffscreen();
  return {
    message: {
      type: 'init', canvas: offscreen, theme: theme(), ...canvasSize(), stepSeq: stepSeq(), testHooks: TEST?.hooks === true,
    },
    transfer: [offscreen],
  };
}

function reportSize() {
  cancelAnimationFrame(sizeFrame);
  sizeFrame = requestAnimationFrame(() => {
    const size = canvasSize();
    const key = `${size.width}x${size.height}@${size.dpr}`;
    if (key === lastSize) return;
    lastSize = key;
    post({ type: 'resize', ...size });
  });
}

// Zooming the page or moving it to another screen changes devicePixelRatio.
function watchPixelRatio() {
  const query = matchMedia(`(resolution: ${window.devicePixelRatio || 1}dppx)`);
  query.addEventListener('change', () => {
    reportSize();
    watchPixelRatio();
  }, { once: true });
}

/** Watches `element` (the page's <canvas>): its size, the device-pixel ratio, the colour scheme. */
export function initCanvas(element) {
  canvas = element;
  scheme.addEventListener('change', () => post({ type: 'theme', name: theme() }));
  resizeObserver.observe(canvas);
  watchPixelRatio();
}
