// What the worker reports, shown: the summary line (and a long run's
// progress), the diagnostics in their list and as marks in the editor, the
// view state, the current block in the stepper, the editor and the state
// panel — or, after a failure, that the program shown was not run.

import { showBanner } from './banner.js';
import { showDiagnostics, showNotRun } from './diagnostics.js';
import { setProgramRegisters } from './offsets.js';
import { PROGRESS_AFTER_MS } from './page.js';
import { showPositions } from './positions.js';
import { openSetupJson } from './settings.js';
import { showState } from './state.js';
import { showVariables } from './variables.js';
import { stepReported } from './stepper.js';
import { saveWork } from './storage.js';
import { setMachinePlanes, viewReported } from './view.js';
import { currentWork, persist, work } from './work.js';

const $ = (id) => document.getElementById(id);
const summaryLine = $('summary');
let editor = null;
let blockCount = 0;
let currentBlock = null;
let setupFailed = false; // the last run refused the setup

let switchMachine = () => {};

/** `onSwitchMachine(kind)`: the user accepted to run the program on the other machine. */
export function initResults(theEditor, { onSwitchMachine } = {}) {
  editor = theEditor;
  if (onSwitchMachine) switchMachine = onSwitchMachine;
}

/** Offers the machine the program's words belong to (behaviour 1.24), or withdraws the offer. */
function offerMachine(hint) {
  if (!hint) {
    showBanner(null, { kind: 'machine' });
    return;
  }
  showBanner(`This looks like a ${hint.machine} program: ${hint.reasons.join('; ')}.`, {
    kind: 'machine',
    action: `Switch to the ${hint.machine}`,
    onAction: () => {
      showBanner(null, { kind: 'machine' });
      switchMachine(hint.machine);
    },
  });
}

/** The last run refused the setup (it ran with the default one). */
export const setupRefused = () => setupFailed;

/** A long run's progress (`progress` of the latest run). */
export function showProgress(m) {
  if (m.ms < PROGRESS_AFTER_MS) return;
  summaryLine.textContent = `Running… ${Math.floor(m.fraction * 100)} % of the program read (${(m.ms / 1000).toFixed(1)} s)`;
  document.body.dataset.progress = String(m.fraction);
}

const plural = (n, word) => `${n} ${word}${n === 1 ? '' : 's'}`;
function endText(end) {
  switch (end.reason) {
    case 'program_end': return `program end at line ${end.line}`;
    case 'error': return end.line > 0 ? `stopped at line ${end.line}` : 'stopped: bad setup';
    default: return 'ran to the last block';
  }
}

/** Path length and the time estimate (behaviour 6.10): `path 399.6 mm (91.6 rapid)`, `≈ 1 min 33 s`. */
function travelText({ travel, units, moves }) {
  if (!travel || moves === 0) return [];
  const d = units === 'inch' ? 2 : 1;
  const path = `path ${(travel.rapid + travel.feed).toFixed(d)} ${units} (${travel.rapid.toFixed(d)} rapid)`;
  const s = Math.round(travel.seconds);
  const time = s >= 3600 ? `${Math.floor(s / 3600)} h ${Math.floor((s % 3600) / 60)} min`
    : s >= 60 ? `${Math.floor(s / 60)} min ${s % 60} s` : `${travel.seconds.toFixed(1)} s`;
  const untimed = travel.untimed > 0 ? ` + ${plural(travel.untimed, 'feed move')} without a rate` : '';
  return [path, `≈ ${time}${untimed}`];
}

/** The extents of the run: `X-30…86 Y-20…56 Z0…0`. */
function extentsText({ bounds, units }) {
  if (!bounds) return [];
  const d = units === 'inch' ? 3 : 2;
  const n = (v) => String(Number(v.toFixed(d)));
  const axes = ['x', 'y', 'z'].filter((a) => typeof bounds.min?.[a] === 'number' && typeof bounds.max?.[a] === 'number');
  return [axes.map((a) => `${a.toUpperCase()}${n(bounds.min[a])}…${n(bounds.max[a])}`).join(' ')];
}

/** A run's result: the summary line, the diagnostics, the registers it names, the machine's planes. */
export function showResult({ summary, diagnostics }) {
  setupFailed = diagnostics.some((d) => d.line === 0 && d.code.startsWith('setup-'));
  summaryLine.textContent = [
    plural(summary.blocks, 'block'), plural(summary.moves, 'move'), plural(summary.errors, 'error'),
    plural(summary.warnings, 'warning'),
    // Behaviour 2.24: the blocks a run that continued past errors passed over.
    ...(summary.skipped > 0 ? [`${plural(summary.skipped, 'block')} skipped`] : []), `${summary.machine}${summary.gcode_system ? ` (G-code system ${summary.gcode_system})` : ''}, ${summary.units}`, endText(summary.end),
    ...travelText(summary), ...extentsText(summary),
  ].join(' · ');
  summaryLine.classList.toggle('has-errors', summary.errors > 0);
  showDiagnostics($('diagnostics'), diagnostics, {
    jump: (line, column, end) => editor.jumpTo(line, column, end),
    openSetup: openSetupJson,
  });
  editor.setDiagnostics(diagnostics);
  setProgramRegisters(summary.registers ?? [], summary.set_by_program ?? [], summary.offset_memory ?? null);
  setMachinePlanes(summary.machine);
  showPositions(summary);
  offerMachine(summary.machine_hint);
}

/** The worker's view state: the view, the current block and what changed it. */
export function showViewState(m) {
  if (m.gen > 0) work.viewKnown = true; // a state of a run, not the empty session's
  document.body.dataset.stateGen = String(m.gen); // the run whose state is shown (tests wait for it)
  viewReported(m.view);
  blockCount = m.blocks;
  if (m.block !== undefined) currentBlock = m.block;
  if (m.step < 0) currentBlock = null;
  stepReported(m.step, m.blocks, currentBlock, m.stepSeq);
  showState($('state-panel'), currentBlock, { blocks: blockCount, setup: work.setup });
  showVariables($('variables-panel'), currentBlock);
  // A library program's block is not in the editor's text (behaviour 19.10).
  editor.showCurrent(currentBlock && !currentBlock.library ? currentBlock.line : null, m.cause !== 'line');
  if (['view', 'step', 'pick', 'line'].includes(m.cause)) persist();
  // A run may move the current block (a shorter program): the autosave follows.
  else if (m.cause === 'run' && work.viewKnown) saveWork(currentWork);
}

/** The worker's `drawn`: which run the canvas shows and how long drawing it took (tests and the benchmark read them). */
export function showDrawn(m) {
  document.body.dataset.drawn = `${m.width}x${m.height}@${m.dpr}`;
  document.body.dataset.drawnGen = String(m.gen);
  document.body.dataset.drawMs = m.ms.toFixed(1);
  // A frame of a pan or zoom gesture, moved from the last whole one; the
  // whole frame follows when the gesture pauses.
  if (m.moving) document.body.dataset.drawnMoving = 'true';
  else delete document.body.dataset.drawnMoving;
}

/**
 * Shows that the program shown was not run (or not finished): banner,
 * summary, diagnostics, steps. `stepSeq`: the stepper's last request.
 */
export function showStopped(text, { kind, stepSeq }) {
  showBanner(text, { kind: 'worker' });
  summaryLine.textContent = text;
  summaryLine.classList.add('has-errors');
  showNotRun($('diagnostics'), text);
  editor.setDiagnostics([]);
  // Nothing of the failed run is shown: no blocks, no current block.
  blockCount = 0;
  currentBlock = null;
  stepReported(-1, 0, null, stepSeq);
  showState($('state-panel'), null, { blocks: 0 });
  showVariables($('variables-panel'), null);
  editor.showCurrent(null, false);
  document.body.dataset.stopped = kind;
}
