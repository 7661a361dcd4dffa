// The page: editor, summary and diagnostics. The interpreter and the
// drawing live in a module worker (worker.js) that owns the canvas, so big
// toolpaths never cross into this thread. Every run request carries a
// generation number; answers to older generations are dropped.

/** Seed 000 of the spec: the G45–G48 square, with register 01 = 6. */
const DEFAULT_PROGRAM = `(SEED 000: SQUARE WITH G45-G48, REGISTER 01 = 6.)
G90 G00 X-30. Y-20.;
G91 G00 G46 X30. Y20. D01;
G01 G47 X80. F200.;
G47 Y50.;
G47 X-80.;
G47 Y-50.;
G00 G46 X-30. Y-20.;
M30;
`;

const DEFAULT_SETUP = `{
  "machine": "mill",
  "offsets": { "01": 6.0 }
}
`;

/** Re-run this long after the last keystroke. */
const DEBOUNCE_MS = 150;

const programInput = document.getElementById('program');
const setupInput = document.getElementById('setup');
const summaryLine = document.getElementById('summary');
const diagnosticsList = document.getElementById('diagnostics');
const canvas = document.getElementById('view');

programInput.value = DEFAULT_PROGRAM;
setupInput.value = DEFAULT_SETUP;

const worker = new Worker(new URL('./worker.js', import.meta.url), { type: 'module' });
let requested = 0;
let timer = 0;

worker.addEventListener('message', (event) => {
  const message = event.data;
  if (message.type === 'result') {
    if (message.gen < requested) return; // stale: a newer request is on its way
    showResult(message);
    document.body.dataset.rendered = String(message.gen);
  } else if (message.type === 'drawn') {
    document.body.dataset.drawn = `${message.width}x${message.height}@${message.dpr}`;
  } else if (message.type === 'failure') {
    showFailure(message.message);
  }
});
worker.addEventListener('error', (event) => {
  event.preventDefault();
  showFailure(`the interpreter could not start: ${event.message || 'worker error'}`);
});

function canvasSize() {
  const box = canvas.getBoundingClientRect();
  return {
    width: Math.max(1, Math.round(box.width)),
    height: Math.max(1, Math.round(box.height)),
    dpr: window.devicePixelRatio || 1,
  };
}

// The worker draws on the canvas from now on; this thread only reports sizes.
const offscreen = canvas.transferControlToOffscreen();
worker.postMessage({ type: 'init', canvas: offscreen, ...canvasSize() }, [offscreen]);

let lastSize = '';
let sizeFrame = 0;
function reportSize() {
  cancelAnimationFrame(sizeFrame);
  sizeFrame = requestAnimationFrame(() => {
    const size = canvasSize();
    const key = `${size.width}x${size.height}@${size.dpr}`;
    if (key === lastSize) return;
    lastSize = key;
    worker.postMessage({ type: 'resize', ...size });
  });
}
new ResizeObserver(reportSize).observe(canvas);
// Zooming the page or moving it to another screen changes devicePixelRatio.
function watchPixelRatio() {
  const query = matchMedia(`(resolution: ${window.devicePixelRatio || 1}dppx)`);
  query.addEventListener('change', () => {
    reportSize();
    watchPixelRatio();
  }, { once: true });
}
watchPixelRatio();

function requestRun() {
  clearTimeout(timer);
  delete document.body.dataset.pending;
  requested += 1;
  document.body.dataset.requested = String(requested);
  worker.postMessage({
    type: 'run',
    gen: requested,
    program: programInput.value,
    setup: setupInput.value,
  });
}

function scheduleRun() {
  clearTimeout(timer);
  // Tests (and anyone curious) can tell an edit waiting for its run.
  document.body.dataset.pending = 'true';
  timer = setTimeout(requestRun, DEBOUNCE_MS);
}

programInput.addEventListener('input', scheduleRun);
setupInput.addEventListener('input', scheduleRun);
requestRun();

function plural(n, word) {
  return `${n} ${word}${n === 1 ? '' : 's'}`;
}

function endText(end) {
  switch (end.reason) {
    case 'program_end': return `program end at line ${end.line}`;
    case 'error': return end.line > 0 ? `stopped at line ${end.line}` : 'stopped: bad setup';
    default: return 'ran to the last block';
  }
}

function showResult({ summary, diagnostics }) {
  summaryLine.textContent = [
    plural(summary.blocks, 'block'),
    plural(summary.moves, 'move'),
    plural(summary.errors, 'error'),
    plural(summary.warnings, 'warning'),
    `${summary.machine}, ${summary.units}`,
    endText(summary.end),
  ].join(' · ');
  summaryLine.classList.toggle('has-errors', summary.errors > 0);
  showDiagnostics(diagnostics);
}

function showDiagnostics(diagnostics) {
  if (diagnostics.length === 0) {
    const none = document.createElement('li');
    none.className = 'none';
    none.textContent = 'No problems found.';
    diagnosticsList.replaceChildren(none);
    return;
  }
  diagnosticsList.replaceChildren(...diagnostics.map(diagnosticItem));
}

function diagnosticItem(d) {
  const item = document.createElement('li');
  item.className = d.severity;
  const loc = document.createElement('span');
  loc.className = 'loc';
  loc.textContent = d.line > 0 ? `${d.line}:${d.column}` : 'setup';
  const severity = document.createElement('span');
  severity.className = 'severity';
  severity.textContent = d.severity;
  const code = document.createElement('span');
  code.className = 'code';
  code.textContent = `[${d.code}]`;
  const message = document.createElement('span');
  message.className = 'message';
  message.textContent = d.message;
  item.append(loc, ' ', severity, ' ', code, ' ', message);
  if (d.line > 0) {
    item.tabIndex = 0;
    item.title = 'Show in the program';
    const jump = () => selectInProgram(d.line, d.column, d.end_column);
    item.addEventListener('click', jump);
    item.addEventListener('keydown', (e) => {
      if (e.key === 'Enter' || e.key === ' ') {
        e.preventDefault();
        jump();
      }
    });
  }
  return item;
}

/** Selects 1-based line:column..end_column (in characters) in the editor. */
function selectInProgram(line, column, endColumn) {
  const text = programInput.value;
  const breaks = /\r\n|\r|\n/g;
  let start = 0;
  for (let l = 1; l < line; l += 1) {
    const found = breaks.exec(text);
    if (!found) break;
    start = found.index + found[0].length;
  }
  const lineEnd = text.slice(start).search(/\r|\n/);
  const lineText = lineEnd < 0 ? text.slice(start) : text.slice(start, start + lineEnd);
  const chars = Array.from(lineText);
  const offset = (n) => chars.slice(0, Math.max(0, n - 1)).join('').length;
  programInput.focus();
  programInput.setSelectionRange(start + offset(column), start + offset(Math.max(column, endColumn)));
}

function showFailure(text) {
  summaryLine.textContent = `Internal error: ${text}`;
  summaryLine.classList.add('has-errors');
  console.warn('offsetlab:', text);
}
