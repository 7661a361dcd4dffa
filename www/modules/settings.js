// The settings panel: machine, units, the settings where controls disagree,
// start position and work offsets, each with one line saying what it
// changes — and the raw setup document (JSON) under "Advanced", kept in step
// with the form both ways.

import { librarySection } from './library.js';
import { toolTableSection } from './tooltable.js';
import {
  MAX_POSITION, WORK_SYSTEMS, checkNumber, decimalsFor, machineOf, pointOf, setPoint, setSetting,
  setWorkOffset, settingOf, setupText, unitName, unitsOf, workOffset,
} from './setup.js';

const CHOICES = [
  {
    id: 'machine', label: 'Machine', options: [['mill', 'Mill'], ['lathe', 'Lathe']],
    get: (s) => machineOf(s),
    set: (s, v) => setMachine(s, v),
    help: 'Mill: X Y Z with G43/G44 length (H) and G45–G48 position (D) offsets. Lathe: X as a diameter and Z, T-code offsets.',
  },
  {
    id: 'units', label: 'Units', options: [['mm', 'mm (G21)'], ['inch', 'inch (G20)']],
    get: (s) => unitsOf(s), set: (s, v) => { s.units = v; },
    help: 'Units at program start, and of the offsets, start position and work offsets below.',
  },
  {
    id: 'control', label: 'Control', options: [['yasnac', 'YASNAC'], ['fanuc', 'Fanuc 0i/30i'], ['haas', 'Haas'], ['linuxcnc', 'LinuxCNC 2.9']],
    help: 'The control the program is written for: it chooses each setting left “as the control”. YASNAC: the seeds’ manuals (PC NC, J50). Fanuc: 0i-MF/TF and 30i. Haas: NGC mills and lathes. LinuxCNC: the RS274/NGC dialect, checked against LinuxCNC’s own interpreter.',
  },
  {
    id: 'same_group_codes', label: 'Two G codes of a group', controlDefault: true,
    options: [['error', 'an error'], ['last_wins', 'the last one wins']],
    help: 'G91 … G90 in one block: YASNAC refuses the block; Fanuc and Haas take the last one and offsetlab warns.',
  },
  {
    id: 'gcode_system', label: 'G-code system', machine: 'lathe', controlDefault: true,
    options: [['A', 'A (G90 turning cycle)'], ['B', 'B (G90/G91 absolute/incremental)'], ['C', 'C (G90/G91, G70/G71 inch/metric)']],
    help: 'Lathe G-code table. A on every control (Fanuc B and C by parameter): G90/G92/G94 cycles, G50 coordinates. B: G77/G78/G79 cycles, G92 coordinates, G94/G95 feed. C: as B with G20/G21/G24 cycles.',
  },
  {
    id: 'g47', label: 'G47 (mill)', machine: 'mill', controlDefault: true,
    options: [['engraving', 'text engraving (Haas)'], ['position_offset', 'position offset, double extension']],
    help: 'G47 on the mill: Haas engraves text (G47 P0 (TEXT) X Y I angle J height R Z F E; P1 a serial number from #599) in offsetlab’s single-stroke font; Fanuc and YASNAC extend the move by twice the D register.',
  },
  {
    id: 'circle_pocket', label: 'G12/G13 (mill)', machine: 'mill', controlDefault: true,
    options: [['haas', 'a circular pocket (Haas)'], ['alarm', 'an alarm']],
    help: 'G12/G13 on the mill: Haas cuts a circular pocket (I, K, Q, L, D, Z); Fanuc and YASNAC mills have no such code and alarm.',
  },
  {
    id: 'reference_return_without_axes', label: 'G28/G30 without axes', controlDefault: true,
    options: [['all_axes', 'every axis returns'], ['no_axis', 'no axis moves']],
    help: 'G28 or G30 with no axis word: Haas returns every axis; Fanuc returns only the axes named, so none (YASNAC as Fanuc), and offsetlab warns.',
  },
  {
    id: 'extended_work_offsets', label: 'Additional work offsets', controlDefault: true,
    options: [['g54_1', 'G54.1 P1–P48 (Fanuc)'], ['g154', 'G154 P1–P99 (Haas)']],
    help: 'How a program names the additional work systems: Fanuc G54.1 Pn or G54 Pn, Haas G154 Pn (YASNAC as Fanuc). Their zero points are the setup document’s extended_work_offsets.',
  },
  {
    id: 'rotation_angle', label: 'G68 R in G91', machine: 'mill',
    options: [['absolute', 'the angle itself'], ['distance_mode', 'added in G91']],
    help: 'G68 R… is the angle whatever G90/G91 say (Fanuc RIN = 0), or in G91 it adds to the rotation in force (RIN = 1).',
  },
  {
    id: 'depth_word', label: 'D of G71–G76', machine: 'lathe', controlDefault: true,
    options: [['dimension', 'a length (D0.5)'], ['increments', 'least increments (D500)']],
    help: 'The one-block G71/G72 depth of cut, G74/G75 relief and G76 first depth: Haas and YASNAC write a length with a decimal point; Fanuc’s Series 10/11 format counts least increments, no decimal point.',
  },
  {
    id: 'trailing_rapids', label: 'G00 ending a G71 contour', machine: 'lathe', controlDefault: true,
    options: [['shape', 'part of the shape'], ['exit', 'the tool’s exit']],
    help: 'G00 blocks that end a G71/G72 contour going back toward the start: Fanuc checks them as the shape (alarm PS0064); the Haas profile takes them as the exit, with a warning.',
  },
  {
    id: 'polar_interpolation', label: 'G12.1/G112 words', machine: 'lathe', controlDefault: true,
    options: [['fanuc', 'X diameter, C (Fanuc)'], ['haas', 'X radius, Y (Haas)']],
    help: 'The face plane of polar coordinate interpolation: Fanuc writes X as a diameter and C for the hypothetical axis, moving with G01–G03 only; Haas’s G112 writes X as a radius and Y (XY to XC) and also moves at rapid (YASNAC as Fanuc).',
  },
  {
    id: 'nose_in_contour', label: 'G41/G42 in a G70–G73 contour', machine: 'lathe', controlDefault: true,
    options: [['contour', 'where written (Haas)'], ['before_cycle', 'before the cycle (Fanuc)']],
    help: 'Tool nose radius compensation in G70–G73: Haas programs start it in the contour’s first block and cancel it in the last; Fanuc wants G41/G42 before the cycle and stops on G40–G42 inside the contour (alarm PS0325). Either way the cycle roughs and finishes the compensated shape.',
  },
  {
    id: 'nose_single_cycles', label: 'G90/G94 in G41/G42', machine: 'lathe',
    options: [['tip', 'compensated by the tip'], ['off', 'as programmed']],
    help: 'A G90 or G94 while G41/G42 is on: its legs compensated on the side the tool’s tip direction gives, whatever G41/G42 says (Fanuc), or run as programmed with a warning. G92 threading is never compensated.',
  },
  {
    id: 'dwell_p_decimal_point', label: 'Decimal point in P', controlDefault: true,
    options: [['error', 'an error'], ['seconds', 'seconds'], ['always', 'seconds, point or not']],
    help: 'G04 P3. (and a canned cycle’s dwell P): YASNAC and Fanuc take P in milliseconds without a point and refuse P3.; Haas reads P3. as 3 seconds and P3 as 3 milliseconds; LinuxCNC reads P3 and P3. as 3 seconds.',
  },
  {
    id: 'finishing_extra_words', label: 'U W D on G70', machine: 'lathe', controlDefault: true,
    options: [['error', 'an error'], ['warn', 'passed over, with a warning']],
    help: 'G70 P10 Q20 U0.02 W0.005: G70 reads P and Q; YASNAC and Fanuc stop at U (PS0066); Haas programs copy G71’s U W onto it, and the finishing pass runs the contour as programmed.',
  },
  {
    id: 'macro_abbreviations', label: 'Macro words abbreviated', controlDefault: true,
    options: [['fanuc', 'read (WH = WHILE)'], ['off', 'refused']],
    help: 'WH[…]DO1, EN1, GO20, SQ[…]: Fanuc reads the macro words by their first two letters; the Haas and YASNAC macro chapters write them in full, and an abbreviation is refused with the word it stands for.',
  },
  {
    id: 's_decimal_point', label: 'Decimal point in S', controlDefault: true,
    options: [['error', 'an error'], ['value', 'its value']],
    help: 'S5000. with a decimal point: YASNAC and Fanuc take S as a whole number and refuse it (Fanuc PS0007); Haas programs write it, and it reads as S5000.',
  },
  {
    id: 'machine_positions', label: 'Start and reference', controlDefault: true,
    options: [['work_zero_start', 'start at the work zero, reference above'], ['typical', 'a typical machine'], ['work_zero', 'the work zero']],
    help: 'Start and reference left at 0 0 0: the tool starts at the work zero and G28 goes up to a typical machine’s reference (YASNAC, the seeds); or as on a typical machine, homed there (Fanuc, Haas); or both at the work zero, so G28 returns to it. The typical reference: mill X0 Y0 Z508 mm (Haas VF-2), lathe turret home X406.4 Z355.6 mm (Haas ST-10).',
  },
  {
    id: 'decimal_input', label: 'Decimal input', controlDefault: true, options: [['increment', 'increment'], ['calculator', 'calculator']],
    help: 'A dimension without a point: X12345 is 12.345 mm (increment, Fanuc/YASNAC/Haas) or 12345 mm (calculator, LinuxCNC).',
  },
  {
    id: 'length_offset_without_z', label: 'G43 H without Z', machine: 'mill', controlDefault: true,
    options: [['move', 'Z moves now'], ['next_z', 'at the next Z move']],
    help: 'G43/G44 H… in a block with no Z word: Z moves by the offset in that block (seed 001, YASNAC) or only at the next Z move (Fanuc TOS, LinuxCNC).',
  },
  {
    id: 'offset_memory', label: 'Offset memory', machine: 'mill', controlDefault: true,
    options: [['A', 'A: one value per number'], ['B', 'B: geometry + wear'], ['C', 'C: H and D apart']],
    help: 'Where H and D values are kept. YASNAC: A, the seeds’ one tool offset memory, H01 and D01 the same value (G10 L11). Fanuc and Haas: C, an H table and a D table, each with geometry and wear (G10 L10/L11 H, L12/L13 D). B: one geometry and wear per number, shared by H and D (G10 L10/L11).',
  },
  {
    id: 'cutter_start_up', label: 'G41/G42 start-up and cancel', controlDefault: true,
    options: [['A', 'type A'], ['B', 'type B'], ['corner', 'LinuxCNC: the entry as a corner']],
    help: 'Type A (every profile: Fanuc SUP = 0, Haas setting 43 = A): the start-up ends perpendicular to the next block. Type B: the corner is compensated too (intersection, or a vector on each side).',
  },
  {
    id: 'cutter_outside_corner', label: 'G41/G42 outside corners', controlDefault: true,
    options: [['vectors', 'intersection / extra vectors'], ['arc', 'an arc round the corner']],
    help: 'Fanuc (every profile): the intersection at 90° or more, the extra vectors under 90°. Arc: round the corner on the tool radius (Haas setting 58 = YASNAC, as offsetlab reads it).',
  },
  {
    id: 'cutter_cancel_without_motion', label: 'G40 without a move', controlDefault: true,
    options: [['move', 'the vector comes off there'], ['next_move', 'at the next X/Y move']],
    help: 'G40 (or D00) in a block with no move in the plane: Fanuc and YASNAC take the vector off in that block; Haas waits for the next X/Y move.',
  },
  {
    id: 'cutter_blocks_without_motion', label: 'G41/G42 blocks read past', controlDefault: true,
    options: [0, 1, 2, 3, 4, 5, 6].map((n) => [String(n), String(n)]),
    get: (s) => {
      const v = settingOf(s, 'cutter_blocks_without_motion');
      return v === undefined || v === null ? '' : String(v);
    },
    set: (s, v) => setSetting(s, 'cutter_blocks_without_motion', v === undefined ? undefined : Number(v)),
    help: 'Blocks without a move in the plane the control reads past to find the next corner (2 on every profile; Fanuc sets it by parameter). More, and the corner is not seen: overcut.',
  },
  {
    id: 'cutter_interference_check', label: 'G41/G42 interference check',
    options: [['alarm', 'on (alarm PS0041)'], ['off', 'off (overcut drawn)']],
    help: 'A block whose offset path runs backwards (a groove or an inside arc smaller than the tool) stops the program, as Fanuc parameter CNC = 0 does; off draws the overcut with a warning.',
  },
  {
    id: 'main_m99', label: 'M99 in the main program',
    options: [['once', 'one pass, then end'], ['loop', 'loop (the control)']],
    help: 'Every control goes back to the start and runs the program again until stopped. One pass draws it once and ends there; loop repeats it until the run’s block limit.',
  },
  {
    id: 'lathe_x_offset', label: 'Lathe X offsets', machine: 'lathe',
    options: [['diameter', 'diameter values'], ['radius', 'radius values']],
    help: 'X values of the lathe offset table are diameters, or radii that are doubled on the diameter axis.',
  },
];

const SWITCHES = [
  { id: 'mirror_x', axis: 'x', label: 'Mirror X', machine: 'mill', help: 'Moves along X are reversed about the start point; G02/G03 turn the other way and G45–G48 follow (seed 003).' },
  { id: 'mirror_y', axis: 'y', label: 'Mirror Y', machine: 'mill', help: 'The same along Y.' },
  { id: 'block_skip', label: 'Block skip', help: 'The optional block skip switch: when on, blocks starting with / are not run.' },
  { id: 'continue_past_errors', label: 'Continue past errors', help: 'Off, the run stops at the first error, as a control does. On, a block that cannot run is listed and skipped, the state before it kept, and the rest drawn.' },
];

// Behaviour 13.15: start and reference at 0 0 0 are left out of the document, and setting machine_positions gives them.
const POINTS = [
  { id: 'start', label: 'Start position', help: 'Where the tool is when the program starts, in G54 coordinates (the lathe’s X is a diameter). 0 0 0: as “Start and reference” says.' },
  { id: 'reference', label: 'Reference position', help: 'Where G28 (and G30 unless the document sets the others) returns to, in machine coordinates. 0 0 0: as “Start and reference” says.' },
  ...WORK_SYSTEMS.map((name) => ({ id: name, label: `Work offset ${name}`, help: '', describedBy: 'works-help' })),
];

let ctx = null;

function line(help, id) {
  const p = document.createElement('p');
  p.className = 'help';
  p.id = `${id}-help`;
  p.textContent = help;
  return p;
}

function field(def, control) {
  const wrap = document.createElement('div');
  wrap.className = 'setting';
  wrap.dataset.setting = def.id;
  if (def.machine) wrap.dataset.machine = def.machine;
  const label = document.createElement('label');
  label.htmlFor = `set-${def.id}`;
  label.textContent = def.label;
  control.id = `set-${def.id}`;
  if (def.help) control.setAttribute('aria-describedby', `${def.id}-help`);
  wrap.append(label, control);
  if (def.help) wrap.append(line(def.help, def.id));
  return wrap;
}

function pointField(def) {
  const wrap = document.createElement('fieldset');
  wrap.className = 'setting point';
  wrap.dataset.setting = def.id;
  const legend = document.createElement('legend');
  legend.textContent = def.label;
  wrap.append(legend);
  for (const axis of ['x', 'y', 'z']) {
    const label = document.createElement('label');
    label.className = `axis axis-${axis}`;
    const input = document.createElement('input');
    input.type = 'text';
    input.inputMode = 'decimal';
    input.dataset.point = def.id;
    input.dataset.axis = axis;
    input.setAttribute('aria-label', `${def.label} ${axis.toUpperCase()}`);
    if (def.help || def.describedBy) input.setAttribute('aria-describedby', def.describedBy ?? `${def.id}-help`);
    label.append(axis.toUpperCase(), input);
    wrap.append(label);
    input.addEventListener('input', () => pointInput(def, input));
  }
  const reason = document.createElement('span');
  reason.className = 'reason';
  reason.setAttribute('aria-live', 'polite');
  wrap.append(reason);
  if (def.help) wrap.append(line(def.help, def.id));
  return wrap;
}

function pointInput(def, input) {
  const setup = ctx.getSetup();
  const units = unitsOf(setup);
  const reason = input.closest('fieldset').querySelector('.reason');
  const checked = checkNumber(input.value, { max: MAX_POSITION, decimals: decimalsFor(units), unit: unitName(units) });
  reason.textContent = checked.reason ? `${input.dataset.axis.toUpperCase()}: ${checked.reason}` : '';
  if (checked.reason) {
    input.setAttribute('aria-invalid', 'true');
    return;
  }
  input.removeAttribute('aria-invalid');
  const own = def.id === 'start' || def.id === 'reference';
  ctx.change((s) => {
    const p = own ? pointOf(s[def.id]) : workOffset(s, def.id);
    p[input.dataset.axis] = checked.value;
    if (own) setPoint(s, def.id, p);
    else setWorkOffset(s, def.id, p);
  }, 'settings');
}

/** Puts `setup` on the machine `kind` (`mill` or `lathe`). */
export function setMachine(setup, kind) {
  setup.machine = kind;
  // Mirror image is a mill switch: a lathe setup with it is refused.
  if (kind === 'lathe') setSetting(setup, 'mirror', []);
}

export function initSettings({ getSetup, change, replace }) {
  ctx = { getSetup, change, form: document.getElementById('settings-form'), json: document.getElementById('setup') };
  const parts = [];
  for (const def of CHOICES) {
    const select = document.createElement('select');
    // A setting whose default is the control's: "as the control" leaves it
    // out of the document (the core reads the control's default).
    if (def.controlDefault) select.add(new Option('as the control', ''));
    for (const [value, text] of def.options) select.add(new Option(text, value));
    select.addEventListener('change', () => {
      const value = def.controlDefault && select.value === '' ? undefined : select.value;
      ctx.change((s) => (def.set ? def.set(s, value) : setSetting(s, def.id, value)), 'settings');
      renderSettings();
    });
    parts.push(field(def, select));
  }
  for (const def of SWITCHES) {
    const box = document.createElement('input');
    box.type = 'checkbox';
    box.addEventListener('change', () => ctx.change((s) => {
      if (def.axis) {
        const mirror = new Set(settingOf(s, 'mirror'));
        if (box.checked) mirror.add(def.axis);
        else mirror.delete(def.axis);
        setSetting(s, 'mirror', ['x', 'y'].filter((a) => mirror.has(a)));
      } else {
        setSetting(s, def.id, box.checked);
      }
    }, 'settings'));
    const wrap = field(def, box);
    wrap.classList.add('switch');
    parts.push(wrap);
  }
  parts.push(pointField(POINTS[0]), pointField(POINTS[1]));
  // Work offsets: six small forms, folded away until wanted.
  const works = document.createElement('details');
  works.className = 'works';
  const summary = document.createElement('summary');
  summary.textContent = 'Work offsets G54–G59';
  works.append(summary, line('Zero point of each work coordinate system as a machine position; G54 is active at start. The additional systems (extended_work_offsets) and the second to fourth reference positions are set in the document below.', 'works'));
  for (const def of POINTS.slice(2)) works.append(pointField(def));
  parts.push(works);
  ctx.library = librarySection({ getSetup, change });
  parts.push(ctx.library.element);
  ctx.toolTable = toolTableSection({ getSetup, change });
  parts.push(ctx.toolTable.element);
  ctx.form.replaceChildren(...parts);
  ctx.form.addEventListener('submit', (e) => e.preventDefault());

  const reason = document.getElementById('setup-reason');
  ctx.json.addEventListener('input', () => {
    let parsed;
    try {
      parsed = JSON.parse(ctx.json.value);
    } catch (error) {
      reason.textContent = `Not valid JSON (${error.message}); the form keeps the last valid document.`;
      ctx.json.setAttribute('aria-invalid', 'true');
      replace(null, ctx.json.value);
      return;
    }
    reason.textContent = '';
    ctx.json.removeAttribute('aria-invalid');
    replace(parsed, ctx.json.value);
  });
}

/** Shows the setup in the form (and the JSON, unless it is being edited). */
export function renderSettings({ json = true } = {}) {
  if (!ctx) return;
  const setup = ctx.getSetup();
  const machine = machineOf(setup);
  for (const def of CHOICES) {
    ctx.form.querySelector(`#set-${def.id}`).value = (def.get ? def.get(setup) : settingOf(setup, def.id)) ?? '';
  }
  const mirror = settingOf(setup, 'mirror') || [];
  for (const def of SWITCHES) {
    ctx.form.querySelector(`#set-${def.id}`).checked = def.axis ? mirror.includes(def.axis) : Boolean(settingOf(setup, def.id));
  }
  for (const input of ctx.form.querySelectorAll('input[data-point]')) {
    if (input === document.activeElement) continue;
    const id = input.dataset.point;
    const p = id === 'start' || id === 'reference' ? pointOf(setup[id]) : workOffset(setup, id);
    input.value = String(p[input.dataset.axis]);
    input.removeAttribute('aria-invalid');
  }
  for (const el of ctx.form.querySelectorAll('[data-machine]')) el.hidden = el.dataset.machine !== machine;
  ctx.form.classList.toggle('lathe', machine === 'lathe');
  ctx.library?.render();
  ctx.toolTable?.render();
  if (json && document.activeElement !== ctx.json) ctx.json.value = setupText(setup);
}

/** Opens the advanced section and focuses the setup document. */
export function openSetupJson() {
  const details = document.getElementById('advanced');
  details.open = true;
  document.getElementById('settings-panel').open = true;
  ctx.json.focus();
}
