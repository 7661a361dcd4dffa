// What the program's G10 blocks set (the run summary's set_by_program,
// behaviour 17.8), listed under the offset table, apart from the user's
// values: "D01 geometry = 5.000 (was 4.000), set by G10 at line 2". Text
// only.

import { decimalsFor, unitsOf } from './setup.js';

/** A value as the table shows it (the tip T a digit). */
export function showValue(set, units) {
  return set.field === 't' ? String(set.value) : Number(set.value).toFixed(decimalsFor(units));
}

/** What a G10 set names: "D01 geometry", "offset 05 R wear", "G54 X". */
function setName(s) {
  const n = s.key;
  if (s.table === 'offsets') {
    return {
      value: `register ${n}`, geometry: `register ${n} geometry`, wear: `register ${n} wear`,
      h_geometry: `H${n} geometry`, h_wear: `H${n} wear`, d_geometry: `D${n} geometry`, d_wear: `D${n} wear`,
    }[s.field] ?? `register ${n} ${s.field}`;
  }
  if (s.table === 'lathe_offsets') {
    const part = {
      x: 'X', z: 'Z', x_wear: 'X wear', z_wear: 'Z wear', r: 'R (nose radius)', r_wear: 'R wear', t: 'tip T',
    }[s.field] ?? s.field;
    return `offset ${n} ${part}`;
  }
  if (s.table === 'extended_work_offsets') return `additional work offset P${Number(n)} ${s.field.toUpperCase()}`;
  return `${n} ${s.field.toUpperCase()}`;
}

/** The list of what the program set, in `box` (hidden when nothing). */
export function renderSets(box, sets, setup) {
  const units = unitsOf(setup);
  const items = sets.map((s) => {
    const li = document.createElement('li');
    li.dataset.table = s.table;
    li.dataset.key = s.key;
    li.dataset.field = s.field;
    const name = document.createElement('span');
    name.className = 'name';
    name.textContent = `${setName(s)} = ${showValue(s, units)}`;
    li.append(name, ` (was ${showValue({ ...s, value: s.was }, units)}), set by G10 at line ${s.line}`);
    return li;
  });
  const list = box.querySelector('ul');
  list.replaceChildren(...items);
  box.hidden = items.length === 0;
}
