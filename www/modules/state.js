// The state panel: what the control knows after the current block — its
// modal codes, the programmed and actual positions, the active offsets with
// their values and vectors, feed, spindle, and the sentence saying what the
// offsets did. Everything is set as text (textContent), never as markup.

import { toolText } from './tools.js';

function decimals(units) {
  return units === 'inch' ? 4 : 3;
}

function fmt(v, units) {
  if (v === null || v === undefined || !Number.isFinite(v)) return '—';
  const s = v.toFixed(decimals(units));
  return /^-0\.?0*$/.test(s) ? s.slice(1) : s;
}

function signed(v, units) {
  const s = fmt(v, units);
  return v > 0 ? `+${s}` : s;
}

/** "X86.000 Y-6.000 Z0.000" (a lathe position has no Y). */
export function position(p, units) {
  if (!p) return '—';
  const parts = [`X${fmt(p.x, units)}`];
  if (p.y !== undefined && p.y !== null) parts.push(`Y${fmt(p.y, units)}`);
  parts.push(`Z${fmt(p.z, units)}`);
  return parts.join(' ');
}

function vector(p, units) {
  if (!p) return '—';
  const parts = [`X${signed(p.x, units)}`];
  if (p.y !== undefined && p.y !== null) parts.push(`Y${signed(p.y, units)}`);
  parts.push(`Z${signed(p.z, units)}`);
  return parts.join(' ');
}

const two = (n) => String(n).padStart(2, '0');

const zero = (p) => !p || [p.x, p.y ?? 0, p.z].every((v) => Math.abs(v) < 1e-9);

/** "zero at machine X… Y… Z… · G92 shift … · G52 local …" (behaviour 13). */
function coordinates(c, u) {
  const parts = [`zero at machine ${position(c.zero, u)}`];
  if (!zero(c.shift)) parts.push(`G92 shift ${vector(c.shift, u)}`);
  if (!zero(c.local)) parts.push(`G52 local ${vector(c.local, u)}`);
  return parts.join(' · ');
}

/** The mill's mirror image, scaling and rotation in force (behaviour 13.8–13.10). */
function transforms(t, u) {
  const parts = [];
  if (t.mirror) {
    const axes = ['x', 'y', 'z'].filter((k) => t.mirror[k] !== null && t.mirror[k] !== undefined);
    parts.push(`G51.1 mirror ${axes.map((k) => `${k.toUpperCase()} about ${fmt(t.mirror[k], u)}`).join(', ')}`);
  }
  if (t.scaling) {
    const f = t.scaling.factors;
    const same = f.x === f.y && f.y === f.z;
    const by = same ? `×${f.x}` : `×X${f.x} Y${f.y} Z${f.z}`;
    parts.push(`G51 scaling ${by} about ${position(t.scaling.center, u)}`);
  }
  if (t.rotation) {
    const r = t.rotation;
    parts.push(`G68 rotation ${r.degrees.toFixed(3)}° about ${position(r.center, u)} (${r.plane})`);
  }
  return parts.join(' · ');
}

/**
 * Rows [label, value, key] of the panel for one block report; `setup`
 * (optional) gives the tool list's line for the current tool (13.16).
 */
export function stateRows(b, setup = {}) {
  const u = b.units;
  const unit = u === 'inch' ? 'in' : 'mm';
  const rows = [
    // A library program's block: its line in that program (behaviour 19.10).
    ['Block', `${b.library ? `${b.program} ` : ''}line ${b.line}: ${b.text}`, 'block'],
    // Inside a subprogram call (behaviour 19.7): the program and the calls
    // open, outermost first.
    ...(b.program ? [['Program · calls', `${b.program} · ${(b.stack ?? []).join(' → ')}`, 'program']] : []),
    // Every modal group the core reports, in its order (src/machine/modal.rs).
    ['Modal', Object.values(b.modal ?? {}).filter(Boolean).join(' '), 'modal'],
    ['Programmed', `${position(b.programmed, u)} ${unit}`, 'programmed'],
    ['Actual', `${position(b.actual, u)} ${unit}`, 'actual'],
    ['Machine position', `${position(b.machine, u)} ${unit}`, 'machine'],
    // Behaviour 6.12: as the block starts, the whole of its motion is to go
    // (the page steps by whole blocks).
    ...(b.distance_to_go ? [['Distance to go (at the block’s start)', `${vector(b.distance_to_go, u)} ${unit}`, 'to-go']] : []),
  ];
  if (b.coordinates) rows.push(['Coordinate system', coordinates(b.coordinates, u), 'coordinates']);
  if (b.transforms) rows.push(['Transformations', transforms(b.transforms, u), 'transforms']);
  if (b.polar) {
    // Polar coordinate interpolation (behaviour 14.16): the face point is
    // the position's X and Y; the machine turns C and moves X to follow.
    rows.push([
      'Polar interpolation (machine)',
      `C${b.polar.c.toFixed(3)}° from its place at G12.1 · X${fmt(b.polar.x, u)} (radius ${fmt(b.polar.radius, u)})`,
      'polar',
    ]);
  }
  if (b.rotary) {
    const axes = ['a', 'b', 'c'].filter((k) => b.rotary[k] !== undefined && b.rotary[k] !== null);
    rows.push(['Rotary axes (not drawn)', axes.map((k) => `${k.toUpperCase()}${b.rotary[k].toFixed(3)}°`).join(' '), 'rotary']);
  }
  if (b.length_offset) {
    const l = b.length_offset;
    const h = l.h > 0 ? `H${two(l.h)} = ${fmt(l.value, u)}` : 'H00 (none)';
    let text = `${l.mode} · ${h} · Z vector ${signed(l.vector, u)}`;
    if (Math.abs(l.target - l.vector) > 1e-9) text += ` (reaches ${signed(l.target, u)} at the next Z move)`;
    rows.push(['Tool length (H)', text, 'length']);
  }
  if (b.position_offset) {
    const p = b.position_offset;
    const d = p.d > 0 ? `D${two(p.d)} = ${fmt(p.value, u)}` : 'D00 (none)';
    rows.push(['Tool position (D)', d, 'position']);
    // With G41/G42 on, the actual end differs by the cutter's vector too
    // (its own row below): this row is G45–G48's part alone.
    const cutterOn = b.cutter && b.cutter.mode !== 'G40';
    rows.push([
      cutterOn ? 'G45–G48 offset distance from the programmed end point' : 'Offset distance from the programmed end point',
      vector(p.vector, u), 'vector',
    ]);
  }
  if (b.cutter) {
    // Cutter radius compensation C (behaviour 16): the mode, D and its
    // radius, the block's role and the offset vector at its end.
    const c = b.cutter;
    const role = {
      cancel: 'cancel mode', start_up: 'start-up', offset: 'offset mode', cancelling: 'cancel (this block)',
    }[c.phase] ?? c.phase;
    // On the lathe (behaviour 18) the register is the T code's offset, its
    // nose radius R and imaginary tool nose direction.
    const lathe = Boolean(b.lathe_offset);
    let d;
    if (lathe) d = c.d > 0 ? `offset ${two(c.d)} · R ${fmt(c.radius, u)} · tip ${c.tip ?? 0}` : 'offset 00 (none)';
    else d = c.d > 0 ? `D${two(c.d)} = ${fmt(c.radius, u)}` : 'D00 (none)';
    const text = c.mode === 'G40' && c.phase === 'cancel' ? 'G40 · cancel mode' : `${c.mode} · ${d} · ${role}`;
    rows.push([lathe ? 'Nose radius (G41/G42)' : 'Cutter radius (G41/G42)', text, 'cutter']);
    rows.push([lathe ? 'Nose offset vector (X diameter)' : 'Cutter offset vector', vector(c.vector, u), 'cutter-vector']);
  }
  if (b.lathe_offset) {
    const t = b.lathe_offset;
    const reg = t.offset > 0
      ? `offset ${two(t.offset)} = X${fmt(t.value?.x, u)} Z${fmt(t.value?.z, u)}`
      : 'no offset';
    rows.push(['Lathe tool (T)', `T${two(t.tool)}${two(t.offset)} · tool ${two(t.tool)} · ${reg}`, 'lathe']);
    rows.push(['Offset vector (X diameter)', vector(t.vector, u), 'vector']);
  }
  const feed = b.feed === null ? '—' : `F${b.feed}`;
  const spindle = b.spindle === null ? '—' : `S${b.spindle}`;
  rows.push(['Feed · spindle · tool', `${feed} · ${spindle} · T${two(b.tool)}`, 'feed']);
  const tool = toolText(b, setup ?? {}, fmt);
  if (tool) rows.push(['Tool (tool list)', tool, 'tool']);
  return rows;
}

export function showState(panel, block, { blocks = 0, setup = {} } = {}) {
  const list = panel.querySelector('dl');
  const why = panel.querySelector('.explanation');
  if (!block) {
    list.replaceChildren();
    why.textContent = blocks > 0
      ? 'Step through the program (Next, → or a click on the path) to see what the control knows after each block.'
      : 'No block ran.';
    panel.dataset.block = '';
    return;
  }
  const items = stateRows(block, setup).flatMap(([label, value, key]) => {
    const dt = document.createElement('dt');
    dt.textContent = label;
    const dd = document.createElement('dd');
    dd.textContent = value;
    dd.dataset.key = key;
    return [dt, dd];
  });
  list.replaceChildren(...items);
  why.textContent = block.explanation;
  panel.dataset.block = String(block.index);
}
