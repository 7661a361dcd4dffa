// The Tools section of the Settings panel: the setup's tool list
// (behaviour 7.53, 13.16) — per tool number, what the tool physically is:
// the mill cutter's diameter, the lathe insert's nose radius and tip, and
// its length. The drawing shows the current tool at that size (10.13);
// compensation still reads the D/H registers (the lathe: the T code's
// offset), as the control does, and the list never stands in for them.
// Every field is checked as it is typed (a number 0 to 999.999 at the least
// increment; the tip a digit 0–9); a valid value changes the setup at once.

import { addForm, checkedField } from './fields.js';
import {
  MAX_OFFSET, checkNumber, decimalsFor, machineOf, registerKey, unitName, unitsOf,
} from './setup.js';

/** Highest tool number of the list (the core's MAX_TOOL). */
const MAX_TOOL = 9999;

/** The columns of each machine's list: [field, head, label]. */
const COLUMNS = {
  mill: [['diameter', 'Diameter', 'diameter'], ['length', 'Length', 'length']],
  lathe: [['nose_radius', 'Nose R', 'nose radius'], ['tip', 'Tip', 'tip direction'], ['length', 'Length', 'length']],
};

let ctx = null;
let shownKey = '';

export function initTools({ getSetup, change }) {
  ctx = {
    getSetup,
    change,
    table: document.getElementById('tools'),
    units: document.getElementById('tools-units'),
    addForm: document.getElementById('add-tool'),
    addInput: document.getElementById('new-tool'),
    addReason: document.getElementById('new-tool-reason'),
  };
  addForm(ctx.addForm, ctx.addInput, ctx.addReason, addTool);
}

function toolsOf(setup) {
  return setup.tools && typeof setup.tools === 'object' ? setup.tools : {};
}

/** The tool numbers of the list, ascending. */
function numbers(setup) {
  return Object.keys(toolsOf(setup)).map(Number).filter(Number.isInteger).sort((a, b) => a - b);
}

/** The entry of tool `n` (its document key written with two digits). */
function entry(setup, n) {
  const tools = toolsOf(setup);
  return tools[registerKey(n)] ?? tools[String(n)] ?? {};
}

/** Writes tool `n`'s `field` (0 leaves it out, as the core writes it). */
function setField(setup, n, field, value) {
  const tools = { ...toolsOf(setup) };
  const key = Object.keys(tools).find((k) => Number(k) === n) ?? registerKey(n);
  const tool = { ...(tools[key] ?? {}) };
  if (value === 0) delete tool[field];
  else tool[field] = value;
  tools[key] = tool;
  setup.tools = tools;
}

function removeTool(setup, n) {
  const tools = { ...toolsOf(setup) };
  for (const k of Object.keys(tools)) if (Number(k) === n) delete tools[k];
  if (Object.keys(tools).length === 0) delete setup.tools;
  else setup.tools = tools;
}

function addTool(text) {
  const t = String(text).trim();
  const n = Number(t);
  if (!/^\d{1,4}$/.test(t) || n < 1 || n > MAX_TOOL) return `a tool number is 1 to ${MAX_TOOL}`;
  ctx.addInput.value = '';
  ctx.change((s) => {
    if (!numbers(s).includes(n)) setField(s, n, 'length', 0);
  }, 'tools');
  renderTools({ force: true });
  ctx.table.querySelector(`input[data-tool="${n}"]`)?.focus();
  return '';
}

function check(field, text, units) {
  if (field === 'tip') {
    const t = String(text).trim();
    return /^\d$/.test(t) ? { value: Number(t) } : { reason: 'the tip direction is a whole number 0 to 9' };
  }
  const checked = checkNumber(text, { max: MAX_OFFSET, decimals: decimalsFor(units), unit: unitName(units) });
  if (checked.value !== undefined && checked.value < 0) return { reason: 'a size is 0 or more' };
  return checked;
}

function toolRow(n, setup, columns, units) {
  const tr = document.createElement('tr');
  const th = document.createElement('th');
  th.scope = 'row';
  th.textContent = `T${registerKey(n)}`;
  tr.append(th);
  const tool = entry(setup, n);
  for (const [field, , label] of columns) {
    const td = document.createElement('td');
    const { input, reason } = checkedField({
      value: tool[field] ?? 0,
      numeric: field === 'tip',
      check: (text) => check(field, text, units),
      apply: (value) => ctx.change((s) => setField(s, n, field, value), 'tools'),
    });
    input.size = field === 'tip' ? 2 : 8;
    input.dataset.tool = String(n);
    input.dataset.field = field;
    input.setAttribute('aria-label', `Tool ${registerKey(n)} ${label}`);
    td.append(input, reason);
    tr.append(td);
  }
  const td = document.createElement('td');
  const remove = document.createElement('button');
  remove.type = 'button';
  remove.textContent = 'Remove';
  remove.setAttribute('aria-label', `Remove tool ${registerKey(n)}`);
  remove.addEventListener('click', () => {
    ctx.change((s) => removeTool(s, n), 'tools');
    renderTools({ force: true });
  });
  td.append(remove);
  tr.append(td);
  return tr;
}

/** Rebuilds the list when its rows or columns change (or `force`). */
export function renderTools({ force = false } = {}) {
  if (!ctx) return;
  const setup = ctx.getSetup();
  const machine = machineOf(setup);
  const units = unitsOf(setup);
  const rows = numbers(setup);
  const key = `${machine}|${units}|${rows.join(',')}|${JSON.stringify(toolsOf(setup))}`;
  // A field being typed in keeps its text (and the caret) while it edits the setup.
  if (!force && (key === shownKey || ctx.table.contains(document.activeElement))) return;
  shownKey = key;
  const columns = COLUMNS[machine];
  ctx.units.textContent = `(${unitName(units)})`;
  const head = document.createElement('tr');
  for (const text of ['Tool', ...columns.map((c) => c[1]), '']) {
    const th = document.createElement('th');
    th.scope = 'col';
    th.textContent = text;
    head.append(th);
  }
  const body = rows.map((n) => toolRow(n, setup, columns, units));
  if (rows.length === 0) {
    const tr = document.createElement('tr');
    const td = document.createElement('td');
    td.colSpan = columns.length + 2;
    td.className = 'none';
    td.textContent = 'No tool listed: the tool is drawn as a dot. Add one below.';
    tr.append(td);
    body.push(tr);
  }
  ctx.table.tHead.replaceChildren(head);
  ctx.table.tBodies[0].replaceChildren(...body);
}

/**
 * The state panel's line for the current tool (behaviour 13.16): its size
 * from the list, and a hint when compensation is on with an empty register
 * although the list knows the tool — the control reads the register, so
 * the run does too.
 */
export function toolText(block, setup, fmt) {
  const lathe = Boolean(block.lathe_offset);
  const tool = entry(setup, block.tool);
  const u = block.units;
  const parts = [];
  if (!lathe && tool.diameter) parts.push(`diameter ${fmt(tool.diameter, u)}`);
  if (lathe && tool.nose_radius) parts.push(`nose R ${fmt(tool.nose_radius, u)} · tip ${tool.tip ?? 0}`);
  if (tool.length) parts.push(`length ${fmt(tool.length, u)}`);
  if (parts.length === 0) return null;
  let text = `T${registerKey(block.tool)} · ${parts.join(' · ')}`;
  const c = block.cutter;
  const size = lathe ? tool.nose_radius : tool.diameter;
  if (c && c.mode !== 'G40' && c.radius === 0 && size) {
    const reg = lathe ? `offset ${registerKey(c.d)} has no nose radius` : `D${registerKey(c.d)} holds 0`;
    text += ` — ${reg}: compensation reads the register, as the control does, not this list`;
  }
  return text;
}
