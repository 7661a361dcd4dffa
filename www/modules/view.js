// The view's input: wheel zoom at the cursor, drag to pan, pinch with two
// fingers, turn the view in 3D (Shift or Alt+drag, the Orbit mode's drag,
// two fingers moving together in the 3D view, Alt+arrow keys on the focused
// drawing; the mill's views and the lathe's but its face view XC, behaviour
// 10.8, 10.18, 10.19), double-click to fit, a click on a segment selects its block,
// keyboard zoom/pan on the focused canvas, the plane selector and the
// zoom/fit buttons. The worker keeps the view state and draws; this module
// only forwards what the user does and remembers the state the worker
// reports, which `viewState()` hands to whoever needs it (share links).
// A restarted worker needs a new <canvas> (an OffscreenCanvas is handed
// over once only): `bindCanvas()` gives it the same input.

const CLICK_SLOP = 4; // px a press may move and still count as a click
// Alt+arrow turns the 3D view as a drag of this many CSS pixels the same
// way (2 px a degree, src/session/view.rs: 5° a press), behaviour 10.19.
const KEY_TURN_PX = 10;
const WHEEL_STEP = 1.0015; // zoom factor per wheel delta pixel

let post = () => {};
let state = { plane: 'XY', zoom: 1, pan: [0, 0], step: null };
const listeners = new Set();
let orbitMode = false; // the Orbit button: a plain drag turns the view

/** The view state last drawn: { plane, zoom, pan: [u, v], step }, `angles:
 * [yaw, pitch]` in the 3D view (behaviour 10.8), and
 * `swept: true` while the cutter's swept width is drawn (behaviour 16.20),
 * `legend: false` while the legend is folded away (behaviour 10.7). */
export function viewState() {
  const copy = { ...state, pan: [...state.pan] };
  if (state.angles) copy.angles = [...state.angles];
  return copy;
}

/** Calls `f(state)` after every change the worker reports. */
export function onViewChange(f) {
  listeners.add(f);
  return () => listeners.delete(f);
}

/** Called with each state message of the worker. */
export function viewReported(view) {
  state = { plane: view.plane, zoom: view.zoom, pan: view.pan, step: view.step };
  // Only in the 3D view, so the documents and links of the plane views stay as they were.
  if (view.angles) state.angles = view.angles;
  // Only when on, so the documents and links of views without it stay as they were.
  if (view.swept) state.swept = true;
  if (view.legend === false) state.legend = false;
  const select = document.getElementById('plane');
  if (select && select.value !== state.plane) select.value = state.plane;
  showTurnable();
  const swept = document.getElementById('swept');
  if (swept) swept.checked = Boolean(view.swept);
  const legend = document.getElementById('legend');
  if (legend) legend.checked = view.legend !== false;
  document.body.dataset.view = JSON.stringify(state);
  for (const f of listeners) f(viewState());
}

/** The lathe's views: ZX, and XC, the face of polar coordinate interpolation. */
const LATHE_PLANES = new Set(['ZX', 'XC']);
/** Views of both machines: the 3D view (the mill's or the lathe's, behaviour 10.18). */
const BOTH_PLANES = new Set(['3D']);

/** Whether the current view turns: all but the lathe's face view XC,
 * which no yaw and pitch show (behaviour 10.18). */
const turnable = () => state.plane !== 'XC';

/** The Orbit button is off in the face view, saying why. */
function showTurnable() {
  const orbit = document.getElementById('orbit');
  if (!orbit) return;
  orbit.disabled = !turnable();
  orbit.title = turnable()
    ? 'Dragging turns the view in 3D (also Shift+drag or Alt+drag, Alt+arrow keys on the focused drawing, or two fingers in 3D)'
    : 'The face view XC does not turn: choose ZX or 3D to turn the lathe in 3D';
  if (!turnable()) setOrbitMode(false);
}

function setOrbitMode(on) {
  orbitMode = on;
  const button = document.getElementById('orbit');
  if (button) button.setAttribute('aria-pressed', String(on));
  document.body.dataset.orbit = on ? 'on' : 'off';
}

/** Shows the planes the machine has (mill: XY XZ YZ; lathe: ZX and the face, XC;
 * both: 3D), and the swept width option on the mill only (cutter compensation is the mill's). */
export function setMachinePlanes(machine) {
  const option = document.getElementById('swept-option');
  if (option) option.hidden = machine === 'lathe';
  const select = document.getElementById('plane');
  for (const option of select.options) {
    const lathe = LATHE_PLANES.has(option.value);
    option.hidden = !BOTH_PLANES.has(option.value) && lathe !== (machine === 'lathe');
    option.disabled = option.hidden;
  }
  showTurnable();
}

const send = (op, extra = {}) => post({ type: 'view', op, ...extra });

export function initView(canvas, postMessage) {
  post = postMessage;
  bindCanvas(canvas);
  const centreZoom = (factor) => {
    // The current canvas (it is replaced when the worker restarts).
    const r = document.getElementById('view').getBoundingClientRect();
    send('zoom', { x: r.width / 2, y: r.height / 2, factor });
  };
  document.getElementById('zoom-in').addEventListener('click', () => centreZoom(1.25));
  document.getElementById('zoom-out').addEventListener('click', () => centreZoom(0.8));
  document.getElementById('fit').addEventListener('click', () => send('fit'));
  document.getElementById('orbit')?.addEventListener('click', () => setOrbitMode(!orbitMode));
  document.getElementById('plane').addEventListener('change', (event) => {
    send('plane', { plane: event.target.value });
  });
  document.getElementById('swept').addEventListener('change', (event) => {
    send('set', { view: { swept: event.target.checked } });
  });
  document.getElementById('legend').addEventListener('change', (event) => {
    send('set', { view: { legend: event.target.checked } });
  });
}

/** The drawing's own input (wheel, pointers, double-click, keys) on `canvas`. */
export function bindCanvas(canvas) {
  const local = (event) => {
    const r = canvas.getBoundingClientRect();
    return { x: event.clientX - r.left, y: event.clientY - r.top };
  };

  canvas.addEventListener('wheel', (event) => {
    event.preventDefault();
    const { x, y } = local(event);
    const pixels = event.deltaMode === 1 ? event.deltaY * 16 : event.deltaY;
    send('zoom', { x, y, factor: WHEEL_STEP ** -pixels });
  }, { passive: false });

  // Pointers: one drags, two pinch (zoom about their midpoint, pan with it).
  const pointers = new Map();
  let press = null;
  let pinch = null;
  const midpoint = () => {
    const [a, b] = [...pointers.values()];
    return { x: (a.x + b.x) / 2, y: (a.y + b.y) / 2, d: Math.hypot(a.x - b.x, a.y - b.y) };
  };
  canvas.addEventListener('pointerdown', (event) => {
    if (event.button !== 0 && event.pointerType === 'mouse') return;
    try {
      canvas.setPointerCapture(event.pointerId);
    } catch {
      // A synthetic pointer (tests, some assistive tools) cannot be captured.
    }
    pointers.set(event.pointerId, local(event));
    // A drag turns the view with Shift or Alt held or in the Orbit mode (not the face view).
    const orbit = turnable() && (orbitMode || event.shiftKey || event.altKey);
    if (pointers.size === 1) press = { ...local(event), moved: false, orbit };
    if (pointers.size === 2) {
      pinch = midpoint();
      press = null;
    }
  });
  canvas.addEventListener('pointermove', (event) => {
    if (!pointers.has(event.pointerId)) return;
    const before = pointers.get(event.pointerId);
    const now = local(event);
    pointers.set(event.pointerId, now);
    if (pointers.size >= 2 && pinch) {
      const m = midpoint();
      if (pinch.d > 0 && m.d > 0) send('zoom', { x: m.x, y: m.y, factor: m.d / pinch.d });
      // Two fingers moving together turn the 3D view (and any view in the
      // Orbit mode); in a plane view they pan it.
      const turn = turnable() && (orbitMode || state.plane === '3D');
      send(turn ? 'orbit' : 'pan', { dx: m.x - pinch.x, dy: m.y - pinch.y });
      pinch = m;
      return;
    }
    if (press && Math.hypot(now.x - press.x, now.y - press.y) > CLICK_SLOP) press.moved = true;
    if (press?.moved) {
      canvas.classList.add('dragging');
      send(press.orbit ? 'orbit' : 'pan', { dx: now.x - before.x, dy: now.y - before.y });
    }
  });
  const release = (event) => {
    if (!pointers.has(event.pointerId)) return;
    pointers.delete(event.pointerId);
    if (pointers.size < 2) pinch = null;
    if (event.type === 'pointerup' && press && !press.moved && pointers.size === 0) {
      const tolerance = event.pointerType === 'touch' ? 14 : 6;
      post({ type: 'pick', x: press.x, y: press.y, tolerance });
    }
    if (pointers.size === 0) {
      press = null;
      canvas.classList.remove('dragging');
    }
  };
  canvas.addEventListener('pointerup', release);
  canvas.addEventListener('pointercancel', release);
  canvas.addEventListener('dblclick', (event) => {
    event.preventDefault();
    send('fit');
  });

  // Keyboard on the focused view: Shift+arrows pan, Alt+arrows turn it in
  // 3D (behaviour 10.19: as a drag of KEY_TURN_PX that way, so Alt+→ turns
  // as a drag to the right), + and - zoom, 0 fits. Plain arrows stay the
  // stepper's; the editor never sees these (they are the canvas's own).
  canvas.addEventListener('keydown', (event) => {
    if (event.ctrlKey || event.metaKey) return;
    const turns = {
      ArrowLeft: [-KEY_TURN_PX, 0], ArrowRight: [KEY_TURN_PX, 0], ArrowUp: [0, -KEY_TURN_PX], ArrowDown: [0, KEY_TURN_PX],
    };
    if (event.altKey && !event.shiftKey && event.key in turns) {
      // Alt+←/→ is also the browser's Back/Forward: the focused drawing takes it.
      event.preventDefault();
      event.stopPropagation();
      if (turnable()) {
        const [dx, dy] = turns[event.key];
        send('orbit', { dx, dy });
      }
      return;
    }
    if (event.altKey) return;
    const r = canvas.getBoundingClientRect();
    const centre = { x: r.width / 2, y: r.height / 2 };
    const pans = { ArrowLeft: [40, 0], ArrowRight: [-40, 0], ArrowUp: [0, 40], ArrowDown: [0, -40] };
    if (event.key in pans && event.shiftKey) {
      const [dx, dy] = pans[event.key];
      send('pan', { dx, dy });
    } else if (event.key === '+' || event.key === '=') {
      send('zoom', { ...centre, factor: 1.25 });
    } else if (event.key === '-' || event.key === '_') {
      send('zoom', { ...centre, factor: 0.8 });
    } else if (event.key === '0') {
      send('fit');
    } else {
      return;
    }
    event.preventDefault();
    event.stopPropagation();
  });
}
