// The offset table: the registers the program names first, then the other
// registers of the setup, then any the user adds. Its columns are those of
// the offset memory (behaviour 17.1): the mill's memory A one value per
// number (read by H and D), memory B a geometry and a wear (their sum read
// by H and D), memory C an H table and a D table, each geometry and wear;
// the lathe's X and Z with their wear, the tool nose radius R with its wear
// and the imaginary tip direction T (17.3). Every field is checked as it is
// typed (number format, ±999.999, the least increment; T a digit 0–9) with
// the reason shown beside it; a valid value changes the setup at once, which
// re-runs. What the program's G10 blocks set (the summary's set_by_program,
// behaviour 17.8) is shown apart, in the cell and in a list under the
// table: the user's value stays the setup's.

import { addForm, checkedField } from './fields.js';
import {
  MAX_OFFSET, checkNumber, clean, decimalsFor, latheRegister, machineOf, millRegister,
  offsetMemorySetting, registerKey, registersIn, setLatheRegister, setMillRegister, tableSize,
  unitName, unitsOf,
} from './setup.js';
import { renderSets, showValue } from './g10sets.js';

/**
 * The layout of each table: its column heads, and its parts — one row per
 * register for memory A and B, a geometry row and a wear row for memory C
 * and the lathe, as the controls' offset pages show them — each naming the
 * field of every column (null: none).
 */
const LAYOUT = {
  A: { heads: ['value'], parts: [[null, ['value']]] },
  B: { heads: ['geometry', 'wear'], parts: [[null, ['geometry', 'wear']]], sum: true },
  C: { heads: ['H (length)', 'D (radius)'], parts: [['geometry', ['h', 'd']], ['wear', ['h_wear', 'd_wear']]] },
  lathe: {
    heads: ['X', 'Z', 'R', 'T'],
    parts: [['geometry', ['x', 'z', 'r', 't']], ['wear', ['x_wear', 'z_wear', 'r_wear', null]]],
  },
};

/** What each field is, for its label. */
const LABEL = {
  value: 'value', geometry: 'geometry', wear: 'wear',
  h: 'H geometry', h_wear: 'H wear', d: 'D geometry', d_wear: 'D wear',
  x: 'X', x_wear: 'X wear', z: 'Z', z_wear: 'Z wear',
  r: 'nose radius R', r_wear: 'nose radius R wear', t: 'tip direction T',
};

/** One line under the table: what the memory type keeps and who reads it. */
const MEMORY_NOTE = {
  A: 'Offset memory A: one value per number, read by H (G43/G44) and by D (G41/G42, G45–G48) alike.',
  B: 'Offset memory B: a geometry and a wear per number; H and D both read their sum.',
  C: 'Offset memory C: H01 and D01 are apart. H (G43/G44) reads H geometry + H wear, D (G41/G42, G45–G48) reads D geometry + D wear.',
  lathe: 'The T code’s offset moves X and Z (geometry + wear); R is the tool nose radius and T the imaginary tip direction (0–9) that nose radius compensation reads.',
};

/** The summary's `set_by_program` field of a table → the column it is in. */
const SET_FIELD = {
  value: 'value', geometry: 'geometry', wear: 'wear',
  h_geometry: 'h', h_wear: 'h_wear', d_geometry: 'd', d_wear: 'd_wear',
};

let ctx = null;
let used = [];
let added = [];
let sets = [];
let runMemory = null;
let shownKey = '';

export function initOffsets({ getSetup, change }) {
  ctx = {
    getSetup,
    change,
    table: document.getElementById('offsets'),
    units: document.getElementById('offsets-units'),
    note: document.getElementById('offsets-memory'),
    sets: document.getElementById('offsets-g10'),
    addForm: document.getElementById('add-register'),
    addInput: document.getElementById('new-register'),
    addReason: document.getElementById('new-register-reason'),
  };
  addForm(ctx.addForm, ctx.addInput, ctx.addReason, addRegister);
}

/**
 * What the run's summary says of the tables: the `registers` the program
 * names, `set_by_program` (each value a G10 block set, with its line) and
 * `offset_memory`, the type the mill's tables were read with (the core
 * knows each control's default; the page does not repeat it).
 */
export function setProgramRegisters(registers, setByProgram = [], memory = null) {
  used = [...registers];
  sets = [...setByProgram];
  if (memory) runMemory = memory;
  renderOffsets();
}

function addRegister(text) {
  const setup = ctx.getSetup();
  const max = tableSize(setup);
  const n = Number(String(text).trim());
  let reason = '';
  if (!/^\d{1,3}$/.test(String(text).trim())) reason = 'a register number such as 5 or 12';
  else if (n < 1 || n > max) reason = `registers are 01 to ${registerKey(max)}`;
  if (reason) return reason;
  if (!added.includes(n)) added.push(n);
  ctx.addInput.value = '';
  renderOffsets();
  ctx.table.querySelector(`input[data-register="${n}"]`)?.focus();
  return '';
}

function rowsFor(setup) {
  const seen = new Set();
  const rows = [];
  for (const n of [...used, ...registersIn(setup).sort((a, b) => a - b), ...added]) {
    if (n > 0 && !seen.has(n)) {
      seen.add(n);
      rows.push(n);
    }
  }
  return rows;
}

/**
 * The table's kind: the lathe's, or the mill's memory type — the setting
 * when the setup names one (shown at once), else the last run's.
 */
function kindOf(setup) {
  if (machineOf(setup) === 'lathe') return 'lathe';
  return offsetMemorySetting(setup) ?? runMemory ?? 'A';
}

/** The G10 sets of the table shown, by "register.column". */
function setsByCell(kind) {
  const table = kind === 'lathe' ? 'lathe_offsets' : 'offsets';
  const cells = new Map();
  for (const s of sets) {
    if (s.table !== table) continue;
    const column = kind === 'lathe' ? s.field : SET_FIELD[s.field];
    if (column) cells.set(`${Number(s.key)}.${column}`, s);
  }
  return cells;
}

/** Rebuilds the table when its rows or columns change (or `force`). */
export function renderOffsets({ force = false } = {}) {
  if (!ctx) return;
  const setup = ctx.getSetup();
  const machine = machineOf(setup);
  const kind = kindOf(setup);
  const units = unitsOf(setup);
  const rows = rowsFor(setup);
  const key = `${kind}|${units}|${rows.join(',')}|${used.join(',')}|${JSON.stringify(sets)}`;
  if (!force && key === shownKey) return;
  shownKey = key;
  const focused = document.activeElement;
  const keep = ctx.table.contains(focused) ? focused.dataset.field : null;
  const layout = LAYOUT[kind];
  ctx.units.textContent = `(${unitName(units)}${machine === 'lathe' ? ', X as a diameter' : ''})`;
  ctx.note.textContent = MEMORY_NOTE[kind];
  const cells = setsByCell(kind);
  const parted = layout.parts.length > 1;

  const head = document.createElement('tr');
  const texts = ['Register', ...(parted ? [''] : []), ...layout.heads, ...(layout.sum ? ['sum'] : [])];
  for (const text of texts) {
    const th = document.createElement('th');
    th.scope = 'col';
    th.textContent = text;
    if (text === '') {
      th.className = 'part';
      th.setAttribute('aria-label', 'geometry or wear');
    }
    head.append(th);
  }
  const body = rows.flatMap((n) => registerRows(n, setup, kind, layout, cells));
  if (rows.length === 0) {
    const tr = document.createElement('tr');
    const td = document.createElement('td');
    td.colSpan = texts.length;
    td.className = 'none';
    td.textContent = 'The program names no register. Add one below.';
    tr.append(td);
    body.push(tr);
  }
  ctx.table.classList.toggle('lathe', machine === 'lathe');
  ctx.table.dataset.memory = kind;
  ctx.table.tHead.replaceChildren(head);
  ctx.table.tBodies[0].replaceChildren(...body);
  renderSets(ctx.sets, sets, setup);
  if (keep) ctx.table.querySelector(`[data-field="${keep}"]`)?.focus();
}

/** Checks a typed value of `field`: the tip T is a digit 0–9, the rest offsets. */
function check(field, text, units) {
  if (field === 't') {
    const t = String(text).trim();
    return /^\d$/.test(t) ? { value: Number(t) } : { reason: 'the tip direction is a whole number 0 to 9' };
  }
  return checkNumber(text, { max: MAX_OFFSET, decimals: decimalsFor(units), unit: unitName(units) });
}

/** The row (memory A, B) or the geometry and wear rows (memory C, lathe) of register `n`. */
function registerRows(n, setup, kind, layout, cells) {
  const lathe = kind === 'lathe';
  const reg = lathe ? latheRegister(setup, n) : millRegister(setup, n);
  const units = unitsOf(setup);
  const sum = document.createElement('td');
  sum.className = 'sum';
  const showSum = () => {
    sum.textContent = clean(reg.geometry + reg.wear).toFixed(decimalsFor(units));
  };
  const set = [...cells.keys()].some((k) => k.startsWith(`${n}.`));
  return layout.parts.map(([part, fields], i) => {
    const tr = document.createElement('tr');
    if (used.includes(n)) tr.classList.add('used');
    if (set) tr.classList.add('set-by-g10');
    if (i === 0) {
      const th = document.createElement('th');
      th.scope = 'row';
      th.rowSpan = layout.parts.length;
      th.textContent = registerKey(n);
      if (used.includes(n)) {
        const badge = document.createElement('span');
        badge.className = 'badge';
        badge.textContent = 'in program';
        th.append(' ', badge);
      }
      tr.append(th);
    } else {
      tr.classList.add('wear-row');
    }
    if (part) {
      const td = document.createElement('td');
      td.className = 'part';
      td.textContent = part;
      tr.append(td);
    }
    for (const field of fields) {
      tr.append(field ? cell(n, field, reg, kind, units, cells, () => layout.sum && showSum()) : document.createElement('td'));
    }
    if (layout.sum) {
      showSum();
      tr.append(sum);
    }
    return tr;
  });
}

/** The input of one value, its reason and, when a G10 set it, the program's value. */
function cell(n, field, reg, kind, units, cells, changed) {
  const lathe = kind === 'lathe';
  const label = LABEL[field];
  const td = document.createElement('td');
  const { input, reason } = checkedField({
    value: reg[field],
    numeric: field === 't',
    check: (text) => check(field, text, units),
    apply: (value) => {
      reg[field] = value;
      // Memory A's one value is geometry + wear: a wear of an older
      // document is taken into it (behaviour 17.1).
      if (field === 'value') Object.assign(reg, { geometry: value, wear: 0 });
      if (field === 'geometry' || field === 'wear') {
        Object.assign(reg, { h: reg.geometry, h_wear: reg.wear, d: reg.geometry, d_wear: reg.wear });
      }
      changed();
      ctx.change((s) => (lathe ? setLatheRegister(s, n, reg) : setMillRegister(s, n, reg, kind)), 'offsets');
    },
  });
  input.dataset.register = String(n);
  input.dataset.field = `${n}.${field}`;
  const unit = field === 't' ? '0–9' : unitName(units);
  input.setAttribute('aria-label', `Register ${registerKey(n)} ${label} (${unit})`);
  reason.id = `reason-${n}-${field}`;
  const described = [reason.id];
  td.append(input, reason);
  const set = cells.get(`${n}.${field}`);
  if (set) {
    // Shown apart: the table keeps the user's value, the run used the
    // program's from the G10's line on.
    td.classList.add('g10');
    const note = document.createElement('span');
    note.className = 'g10-note';
    note.id = `g10-${n}-${field}`;
    note.textContent = `G10 line ${set.line}: ${showValue(set, units)}`;
    described.push(note.id);
    td.append(note);
  }
  input.setAttribute('aria-describedby', described.join(' '));
  return td;
}
