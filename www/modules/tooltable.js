// LinuxCNC's tool table on the page (behaviour 22.9): the file as a
// LinuxCNC machine keeps it, one tool a line (`T1 P1 Z0.511 D0.125 ;1/8 end
// mill`), edited as text and read by the core (in the worker), so the page
// and `--tool-table FILE` read it alike. Shown under the LinuxCNC control,
// whose T, G43 and G41/G42 read it.

import { call } from './runner.js';
import { settingOf } from './setup.js';

const PLACEHOLDER = 'T1 P1 Z0.511 D0.125 ;1/8 end mill\nT2 P2 Z0.1 D0.0625 ;1/16 end mill';

/** The tool table section: its text, its units and what the core said. */
export function toolTableSection({ getSetup, change }) {
  const box = document.createElement('details');
  box.className = 'tool-table';
  box.id = 'tool-table';
  const summary = document.createElement('summary');
  summary.textContent = 'Tool table (LinuxCNC)';
  const help = document.createElement('p');
  help.className = 'help';
  help.textContent = 'The machine’s tool table file, one tool a line: T the tool, P its pocket, Z its length offset, D its diameter, ; a comment. T must name one of its tools; G43 reads its Z, G41/G42 half its D; G10 L1/L10/L11 change it while the program runs. Empty, the offset registers stand for it.';
  const text = document.createElement('textarea');
  text.id = 'tool-table-text';
  text.rows = 5;
  text.spellcheck = false;
  text.placeholder = PLACEHOLDER;
  text.setAttribute('aria-label', 'Tool table, LinuxCNC file format');
  const units = document.createElement('select');
  units.id = 'tool-table-units';
  units.setAttribute('aria-label', 'Tool table lengths in');
  for (const [value, label] of [['', 'the setup’s units'], ['mm', 'mm'], ['inch', 'inch']]) {
    const o = document.createElement('option');
    o.value = value;
    o.textContent = label;
    units.append(o);
  }
  const unitsLabel = document.createElement('label');
  unitsLabel.append('Lengths in ', units);
  const reason = document.createElement('p');
  reason.className = 'help';
  reason.id = 'tool-table-reason';
  reason.setAttribute('aria-live', 'polite');
  box.append(summary, help, text, unitsLabel, reason);

  let shownFor = null; // the tool_table value the text was written from
  let reads = 0;
  const apply = async () => {
    const value = text.value;
    if (!value.trim()) {
      text.removeAttribute('aria-invalid');
      reason.textContent = '';
      change((s) => { delete s.tool_table; }, 'settings');
      return;
    }
    const read = await call('tool-table', { text: value });
    reads += 1;
    box.dataset.reads = String(reads);
    if (text.value !== value) return; // typed on meanwhile: a later read answers
    const said = (p) => `line ${p.line}, column ${p.column}: ${p.message}`;
    if (!read.table) {
      text.setAttribute('aria-invalid', 'true');
      reason.textContent = `Not read (the program runs with the last table read): ${read.errors.map(said).join('; ')}`;
      return;
    }
    text.removeAttribute('aria-invalid');
    const n = Object.keys(read.table.tools).length;
    reason.textContent = [`${n} tool${n === 1 ? '' : 's'} read`, ...read.warnings.map(said)].join('. ') + '.';
    change((s) => {
      const table = { ...read.table };
      if (units.value) table.units = units.value;
      else delete table.units;
      s.tool_table = table;
      shownFor = JSON.stringify(table);
    }, 'settings');
  };
  let timer = 0;
  text.addEventListener('input', () => {
    clearTimeout(timer);
    timer = setTimeout(apply, 250);
  });
  units.addEventListener('change', () => change((s) => {
    if (!s.tool_table) return;
    if (units.value) s.tool_table.units = units.value;
    else delete s.tool_table.units;
  }, 'settings'));

  const render = () => {
    const setup = getSetup() || {};
    box.hidden = settingOf(setup, 'control') !== 'linuxcnc' && !setup.tool_table;
    const table = setup.tool_table;
    units.value = table?.units ?? '';
    const key = JSON.stringify(table ?? null);
    // The text is the user's while they edit it; a table from elsewhere
    // (a link, a document, the JSON) is written out in the file format.
    if (key === shownFor || document.activeElement === text) return;
    shownFor = key;
    if (!table) {
      text.value = '';
      return;
    }
    call('tool-table-file', { table }).then((file) => {
      if (shownFor === key && document.activeElement !== text) text.value = file;
    }, () => {});
  };
  return { element: box, render };
}
