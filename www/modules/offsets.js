// The offset table: the registers the program names first, then the other
// registers of the setup, then any the user adds. Mill registers have a
// geometry and a wear value (their sum is what D and H read); lathe
// registers have X and Z, each with wear. Every field is checked as it is
// typed (number format, ±999.999, the least increment) with the reason shown
// beside it; a valid value changes the setup at once, which re-runs.

import {
  MAX_OFFSET, checkNumber, decimalsFor, latheRegister, machineOf, millRegister, registerKey,
  registersIn, setLatheRegister, setMillRegister, tableSize, unitName, unitsOf,
} from './setup.js';

const MILL = [['geometry', 'geometry'], ['wear', 'wear']];
const LATHE = [['x', 'X'], ['x_wear', 'X wear'], ['z', 'Z'], ['z_wear', 'Z wear']];

let ctx = null;
let used = [];
let added = [];
let shownKey = '';

export function initOffsets({ getSetup, change }) {
  ctx = {
    getSetup,
    change,
    table: document.getElementById('offsets'),
    units: document.getElementById('offsets-units'),
    addForm: document.getElementById('add-register'),
    addInput: document.getElementById('new-register'),
    addReason: document.getElementById('new-register-reason'),
  };
  ctx.addForm.addEventListener('submit', (event) => {
    event.preventDefault();
    addRegister(ctx.addInput.value);
  });
  ctx.addInput.addEventListener('input', () => {
    ctx.addReason.textContent = '';
    ctx.addInput.removeAttribute('aria-invalid');
  });
}

/** The registers the program names (summary.registers). */
export function setProgramRegisters(registers) {
  used = [...registers];
  renderOffsets();
}

function addRegister(text) {
  const setup = ctx.getSetup();
  const max = tableSize(setup);
  const n = Number(String(text).trim());
  let reason = '';
  if (!/^\d{1,3}$/.test(String(text).trim())) reason = 'a register number such as 5 or 12';
  else if (n < 1 || n > max) reason = `registers are 01 to ${registerKey(max)}`;
  if (reason) {
    ctx.addReason.textContent = reason;
    ctx.addInput.setAttribute('aria-invalid', 'true');
    return;
  }
  if (!added.includes(n)) added.push(n);
  ctx.addInput.value = '';
  renderOffsets();
  ctx.table.querySelector(`input[data-register="${n}"]`)?.focus();
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

/** Rebuilds the table when its rows or columns change (or `force`). */
export function renderOffsets({ force = false } = {}) {
  if (!ctx) return;
  const setup = ctx.getSetup();
  const machine = machineOf(setup);
  const units = unitsOf(setup);
  const rows = rowsFor(setup);
  const key = `${machine}|${units}|${rows.join(',')}|${used.join(',')}`;
  if (!force && key === shownKey) return;
  shownKey = key;
  const focused = document.activeElement;
  const keep = ctx.table.contains(focused) ? focused.dataset.field : null;
  const columns = machine === 'lathe' ? LATHE : MILL;
  ctx.units.textContent = `(${unitName(units)}${machine === 'lathe' ? ', X as a diameter' : ''})`;

  const head = document.createElement('tr');
  const cells = ['Register', ...columns.map(([, label]) => label)];
  if (machine === 'mill') cells.push('sum');
  for (const text of cells) {
    const th = document.createElement('th');
    th.scope = 'col';
    th.textContent = text;
    head.append(th);
  }
  const body = rows.map((n) => row(n, setup, machine, columns));
  if (rows.length === 0) {
    const tr = document.createElement('tr');
    const td = document.createElement('td');
    td.colSpan = cells.length;
    td.className = 'none';
    td.textContent = 'The program names no register. Add one below.';
    tr.append(td);
    body.push(tr);
  }
  ctx.table.classList.toggle('lathe', machine === 'lathe');
  ctx.table.tHead.replaceChildren(head);
  ctx.table.tBodies[0].replaceChildren(...body);
  if (keep) ctx.table.querySelector(`[data-field="${keep}"]`)?.focus();
}

function row(n, setup, machine, columns) {
  const tr = document.createElement('tr');
  const th = document.createElement('th');
  th.scope = 'row';
  th.textContent = registerKey(n);
  if (used.includes(n)) {
    const badge = document.createElement('span');
    badge.className = 'badge';
    badge.textContent = 'in program';
    th.append(' ', badge);
    tr.classList.add('used');
  }
  tr.append(th);
  const reg = machine === 'lathe' ? latheRegister(setup, n) : millRegister(setup, n);
  const sum = document.createElement('td');
  sum.className = 'sum';
  const units = unitsOf(setup);
  const showSum = () => {
    sum.textContent = (reg.geometry + reg.wear).toFixed(decimalsFor(units));
  };
  for (const [field, label] of columns) {
    const td = document.createElement('td');
    const input = document.createElement('input');
    input.type = 'text';
    input.inputMode = 'decimal';
    input.autocomplete = 'off';
    input.spellcheck = false;
    input.value = String(reg[field]);
    input.dataset.register = String(n);
    input.dataset.field = `${n}.${field}`;
    input.setAttribute('aria-label', `Register ${registerKey(n)} ${label} (${unitName(units)})`);
    const reason = document.createElement('span');
    reason.className = 'reason';
    reason.id = `reason-${n}-${field}`;
    reason.setAttribute('aria-live', 'polite');
    input.setAttribute('aria-describedby', reason.id);
    input.addEventListener('input', () => {
      const checked = checkNumber(input.value, { max: MAX_OFFSET, decimals: decimalsFor(units), unit: unitName(units) });
      reason.textContent = checked.reason ?? '';
      if (checked.reason) {
        input.setAttribute('aria-invalid', 'true');
        return;
      }
      input.removeAttribute('aria-invalid');
      reg[field] = checked.value;
      if (machine === 'mill') showSum();
      ctx.change((s) => (machine === 'lathe' ? setLatheRegister(s, n, reg) : setMillRegister(s, n, reg)), 'offsets');
    });
    td.append(input, reason);
    tr.append(td);
  }
  if (machine === 'mill') {
    showSum();
    tr.append(sum);
  }
  return tr;
}
