// Step-through: first / previous / next / last, play / pause, the slider
// over the executed blocks, and the page's keyboard shortcuts. The worker
// owns the current block; this module asks it for another and shows what it
// reports.

const PLAY_MS = 600; // per block while playing

let post = () => {};
let blocks = 0;
let step = -1; // -1: no current block, the whole program is shown
// Keys repeat faster than the worker answers: steps are counted from the
// block last asked for until the worker has seen every request (seq).
let target = -1;
let seq = 0;
let timer = 0;
const el = {};

function request(index) {
  if (blocks === 0) return;
  target = Math.max(0, Math.min(blocks - 1, index));
  seq += 1;
  post({ type: 'step', index: target, seq });
}

export const stepper = {
  first: () => request(0),
  last: () => request(blocks - 1),
  next: () => request(target < 0 ? 0 : target + 1),
  previous: () => request(target < 0 ? blocks - 1 : target - 1),
  toggle: () => (timer ? pause() : play()),
};

function play() {
  if (blocks === 0) return;
  if (target < 0 || target >= blocks - 1) request(0);
  timer = setInterval(() => {
    if (target >= blocks - 1) pause();
    else stepper.next();
  }, PLAY_MS);
  showPlaying();
}

export function pause() {
  clearInterval(timer);
  timer = 0;
  showPlaying();
}

function showPlaying() {
  el.play.textContent = timer ? 'Pause' : 'Play';
  el.play.setAttribute('aria-pressed', String(Boolean(timer)));
  document.body.dataset.playing = String(Boolean(timer));
}

/** Shows the worker's current block and the block count; `answered` is
 * the last step request the worker had handled. */
export function stepReported(current, count, block, answered = seq) {
  step = current;
  blocks = count;
  if (answered >= seq) target = current;
  const none = blocks === 0;
  for (const b of [el.first, el.previous, el.next, el.last, el.play]) b.disabled = none;
  el.slider.disabled = none;
  el.slider.max = String(Math.max(0, blocks - 1));
  el.slider.value = String(step < 0 ? Math.max(0, blocks - 1) : step);
  if (none) {
    el.position.textContent = 'no blocks ran';
  } else if (step < 0) {
    el.position.textContent = `all ${blocks} blocks — step to see one`;
  } else {
    // A block of the setup's library names its program (behaviour 19.10).
    const where = block ? ` · ${block.library ? `${block.program} ` : ''}line ${block.line}` : '';
    el.position.textContent = `block ${step + 1} of ${blocks}${where}`;
  }
  el.slider.setAttribute('aria-valuetext', el.position.textContent);
  if (timer && step >= blocks - 1 && target >= blocks - 1) pause();
}

function typing(target) {
  return target instanceof Element
    && (target.closest('.cm-editor, input, textarea, select, [contenteditable="true"]') !== null);
}

export function initStepper(postMessage, { fit, zoom, toggleHelp }) {
  post = postMessage;
  for (const id of ['first', 'previous', 'next', 'last', 'play', 'slider', 'position']) {
    el[id] = document.getElementById(`step-${id}`);
  }
  el.first.addEventListener('click', stepper.first);
  el.previous.addEventListener('click', stepper.previous);
  el.next.addEventListener('click', stepper.next);
  el.last.addEventListener('click', stepper.last);
  el.play.addEventListener('click', stepper.toggle);
  el.slider.addEventListener('input', () => request(Number(el.slider.value)));
  showPlaying();

  // Shortcuts work anywhere but in text fields and the editor, where keys
  // are for typing (the slider and buttons keep their own keys too).
  document.addEventListener('keydown', (event) => {
    if (event.ctrlKey || event.metaKey || event.altKey || typing(event.target)) return;
    const onSlider = event.target === el.slider;
    const keys = {
      ArrowRight: stepper.next, ArrowLeft: stepper.previous, j: stepper.next, k: stepper.previous,
      Home: stepper.first, End: stepper.last, ' ': stepper.toggle, p: stepper.toggle,
      f: fit, '+': () => zoom(1.25), '=': () => zoom(1.25), '-': () => zoom(0.8), '?': toggleHelp,
    };
    const action = keys[event.key];
    if (!action || event.shiftKey && event.key.startsWith('Arrow')) return;
    if (onSlider && event.key !== ' ' && event.key !== 'p') return;
    if (event.key === ' ' && event.target instanceof HTMLButtonElement) return;
    event.preventDefault();
    action();
  });
}
