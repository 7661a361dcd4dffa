// The start and reference positions in effect (behaviour 6.13, 10.14): the
// core reports them with every run's summary — as the setup sets them, or
// as setting 7.49 (“Start and reference”) fills in the ones left at 0 0 0 —
// and the Settings panel shows them under the Start and Reference fields, so
// a field left at 0 0 0 says where the tool really starts and where G28
// really goes.

const $ = (id) => document.getElementById(id);

function fmt(v, units) {
  const s = Number(v).toFixed(units === 'inch' ? 4 : 3);
  return /^-0\.?0*$/.test(s) ? s.slice(1) : s;
}

function point(p, units, lathe) {
  if (!p) return '—';
  const axes = lathe ? ['x', 'z'] : ['x', 'y', 'z'];
  return axes.map((a) => `${a.toUpperCase()}${fmt(p[a] ?? 0, units)}`).join(' ');
}

const WHY = {
  typical: 'a typical machine’s, homed at the positive end of its travel',
  work_zero: 'at the work zero',
  work_zero_start: 'the start at the work zero, the reference a typical machine’s, above the work',
};

/** Shows the summary's `positions` (absent: the line is emptied). */
export function showPositions(summary) {
  const line = $('positions-effect');
  if (!line) return;
  // Under the Reference position field, which the settings form builds.
  const reference = document.querySelector('#settings-form [data-setting="reference"]');
  if (reference && line.previousElementSibling !== reference) reference.after(line);
  const p = summary?.positions;
  if (!p) {
    line.textContent = '';
    return;
  }
  const lathe = summary.machine === 'lathe';
  const unit = p.units === 'inch' ? 'in' : 'mm';
  line.textContent = `In effect: start ${point(p.start, p.units, lathe)} (G54), reference ${point(p.reference, p.units, lathe)} (machine) ${unit}`
    + ` — a field at 0 0 0 is ${WHY[p.machine_positions] ?? p.machine_positions}.`;
  line.dataset.machinePositions = p.machine_positions;
}
