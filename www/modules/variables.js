// The Variables panel (behaviour 10.10): the macro variables the program
// read or set up to the current block — the locals of the level standing
// after it, the common and system variables — each with its value after
// the block and the line that last set it (the block report's `watch`,
// behaviour 21.12). Hidden for a program that touched none. Set as text,
// never as markup.

/** "12.500", as the control's variable page shows a value; null: vacant. */
export function value(v) {
  if (v === null || v === undefined) return 'vacant';
  const s = Number(v).toFixed(3);
  return /^-0\.0*$/.test(s) ? s.slice(1) : s;
}

/** Which group a variable belongs to (behaviour 20.1). */
function group(n) {
  if (n >= 1 && n <= 33) return 'local';
  if (n >= 100 && n <= 199) return 'common';
  if (n >= 500 && n <= 999) return 'kept';
  return 'system';
}

const TITLES = {
  local: (level) => (level > 0 ? `Locals of macro level ${level}` : 'Locals (main program, level 0)'),
  common: () => 'Common #100–#199',
  kept: () => 'Common #500–#999 (kept)',
  system: () => 'System variables',
};

/**
 * Rows of the panel for one block report: [group, title] headings and
 * {variable, value, set, sentence, changed} rows, in the report's order.
 */
export function variableRows(block) {
  const watch = block?.watch;
  if (!watch) return [];
  const changed = new Set((block.variables_set ?? []).map((v) => v.variable));
  const rows = [];
  let last = '';
  for (const w of watch.variables) {
    const g = group(w.variable);
    if (g !== last) {
      rows.push({ heading: TITLES[g](watch.level), group: g });
      last = g;
    }
    const set = w.line === null || w.line === undefined ? 'read, never set' : `set at line ${w.line}`;
    rows.push({
      variable: w.variable,
      value: value(w.value),
      set,
      sentence: `#${w.variable} = ${value(w.value)}, ${set}`,
      changed: changed.has(w.variable),
      vacant: w.value === null || w.value === undefined,
    });
  }
  return rows;
}

export function showVariables(panel, block) {
  const rows = variableRows(block);
  panel.hidden = rows.length === 0;
  const body = panel.querySelector('tbody');
  const items = rows.map((r) => {
    const tr = document.createElement('tr');
    if (r.heading) {
      const th = document.createElement('th');
      th.colSpan = 3;
      th.scope = 'colgroup';
      th.textContent = r.heading;
      tr.className = 'group';
      tr.dataset.group = r.group;
      tr.append(th);
      return tr;
    }
    tr.dataset.variable = String(r.variable);
    tr.title = r.sentence;
    if (r.changed) tr.classList.add('changed');
    if (r.vacant) tr.classList.add('vacant');
    for (const [text, cls] of [[`#${r.variable}`, 'name'], [r.value, 'value'], [r.set, 'set']]) {
      const td = document.createElement('td');
      td.textContent = text;
      td.className = cls;
      tr.append(td);
    }
    return tr;
  });
  body.replaceChildren(...items);
  panel.dataset.block = block ? String(block.index) : '';
}
