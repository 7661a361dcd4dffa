// The setup document as the page edits it: a plain object shaped like the
// README's setup JSON, read and written with its defaults filled in or left
// out, and the validation of numbers typed into the forms.

export const MAX_OFFSET = 999.999;
export const MAX_POSITION = 99999.999;
export const WORK_SYSTEMS = ['G54', 'G55', 'G56', 'G57', 'G58', 'G59'];

// The settings whose default is the control's (same_group_codes,
// gcode_system, dwell_p_decimal_point, …) have none here: absent means "as
// the control".
export const DEFAULT_SETTINGS = {
  control: 'yasnac',
  decimal_input: 'increment',
  block_skip: false,
  length_offset_without_z: 'move',
  lathe_x_offset: 'diameter',
  mirror: [],
  rotation_angle: 'absolute',
  cutter_interference_check: 'alarm',
};

const NUMBER = /^[+-]?(\d+\.?\d*|\.\d+)$/;

/**
 * Validates a typed number. Returns { value } or { reason } (a short text
 * shown next to the field). `max` bounds the magnitude; `decimals` the
 * digits after the point (the least input increment).
 */
export function checkNumber(text, { max = MAX_OFFSET, decimals = 3, unit = 'mm' } = {}) {
  const t = String(text).trim();
  if (t === '') return { reason: 'empty: type a number (0 for none)' };
  if (!NUMBER.test(t)) return { reason: `“${t.slice(0, 12)}” is not a number such as -1.25` };
  const value = Number(t);
  if (!Number.isFinite(value) || Math.abs(value) > max) return { reason: `out of range: at most ±${max} ${unit}` };
  const point = t.indexOf('.');
  if (point >= 0 && t.length - point - 1 > decimals) {
    return { reason: `at most ${decimals} decimals (${(10 ** -decimals).toFixed(decimals)} ${unit})` };
  }
  return { value };
}

/** Decimals of the least input increment: 3 in mm, 4 in inches. */
export function decimalsFor(units) {
  return units === 'inch' ? 4 : 3;
}

export function unitName(units) {
  return units === 'inch' ? 'in' : 'mm';
}

/** Two-digit register key, as on the control: 1 → "01". */
export function registerKey(n) {
  return String(n).padStart(2, '0');
}

export function machineOf(setup) {
  return setup?.machine === 'lathe' ? 'lathe' : 'mill';
}

export function unitsOf(setup) {
  return setup?.units === 'inch' ? 'inch' : 'mm';
}

export function settingOf(setup, name) {
  const v = setup?.settings?.[name];
  return v === undefined ? DEFAULT_SETTINGS[name] : v;
}

/** Sets a setting, leaving defaults out of the document. */
export function setSetting(setup, name, value) {
  const settings = { ...(setup.settings || {}) };
  const same = JSON.stringify(value) === JSON.stringify(DEFAULT_SETTINGS[name]);
  if (same) delete settings[name];
  else settings[name] = value;
  if (Object.keys(settings).length === 0) delete setup.settings;
  else setup.settings = settings;
}

/**
 * The mill's offset memory type the setup names (behaviour 17.1, setting
 * 7.32), or null when it is left "as the control": the core gives that one
 * (the run's summary says which type it read the tables with).
 */
export function offsetMemorySetting(setup) {
  const set = setup?.settings?.offset_memory;
  return set === 'A' || set === 'B' || set === 'C' ? set : null;
}

/** A value of the table without the float noise of a sum (a millionth is finer than any increment). */
export function clean(v) {
  return Math.round(Number(v) * 1e6) / 1e6 + 0;
}

/**
 * A mill register in each form (0 when absent): `value` (memory A's one
 * value: geometry + wear), `geometry`/`wear` (memory B's pair, the H part),
 * and memory C's `h`, `h_wear`, `d`, `d_wear`. A register written as one
 * value or as {geometry, wear} gives H and D the same parts (behaviour 17.1).
 */
export function millRegister(setup, n) {
  const v = setup?.offsets?.[registerKey(n)];
  let h = [0, 0];
  let d = null;
  if (typeof v === 'number') h = [v, 0];
  else if (v && typeof v === 'object' && ('h' in v || 'h_wear' in v || 'd' in v || 'd_wear' in v)) {
    h = [Number(v.h ?? 0), Number(v.h_wear ?? 0)];
    d = [Number(v.d ?? 0), Number(v.d_wear ?? 0)];
  } else if (v && typeof v === 'object') h = [Number(v.geometry ?? 0), Number(v.wear ?? 0)];
  d = d ?? h;
  return {
    value: clean(h[0] + h[1]), geometry: h[0], wear: h[1], h: h[0], h_wear: h[1], d: d[0], d_wear: d[1],
  };
}

/**
 * Writes a mill register in the form its memory type keeps (behaviour
 * 17.2, as the core writes it): A one number; B a number or {geometry,
 * wear}; C as B when H and D read the same parts, else {h, h_wear, d,
 * d_wear} with zeros left out.
 */
export function setMillRegister(setup, n, reg, memory) {
  setup.offsets = { ...(setup.offsets || {}) };
  const key = registerKey(n);
  const pair = (g, w) => (w === 0 ? g : { geometry: g, wear: w });
  if (memory === 'A') setup.offsets[key] = clean(reg.value);
  else if (memory === 'B') setup.offsets[key] = pair(reg.geometry, reg.wear);
  else if (reg.h === reg.d && reg.h_wear === reg.d_wear) setup.offsets[key] = pair(reg.h, reg.h_wear);
  else {
    const out = {};
    for (const f of ['h', 'h_wear', 'd', 'd_wear']) if (reg[f] !== 0) out[f] = reg[f];
    setup.offsets[key] = out;
  }
}

/** A lathe register: { x, z, x_wear, z_wear, r, r_wear, t } (0 when absent). */
export function latheRegister(setup, n) {
  const v = setup?.lathe_offsets?.[registerKey(n)] || {};
  const out = {};
  for (const f of LATHE_FIELDS) out[f] = Number(v[f] ?? 0);
  return out;
}

const LATHE_FIELDS = ['x', 'z', 'x_wear', 'z_wear', 'r', 'r_wear', 't'];

/** Writes a lathe register: x and z always, the wear, nose radius and tip when not 0. */
export function setLatheRegister(setup, n, r) {
  setup.lathe_offsets = { ...(setup.lathe_offsets || {}) };
  const out = { x: r.x, z: r.z };
  for (const f of LATHE_FIELDS.slice(2)) if (r[f]) out[f] = r[f];
  setup.lathe_offsets[registerKey(n)] = out;
}

/** Register numbers present in the setup for the machine. */
export function registersIn(setup) {
  const table = machineOf(setup) === 'lathe' ? setup?.lathe_offsets : setup?.offsets;
  return Object.keys(table || {}).map(Number).filter((n) => Number.isInteger(n) && n > 0);
}

export function tableSize(setup) {
  const n = Number(setup?.table_size);
  return Number.isInteger(n) && n > 0 ? n : 99;
}

/** A point of the setup ({x, y, z}, 0 when absent). */
export function pointOf(p) {
  return { x: Number(p?.x ?? 0), y: Number(p?.y ?? 0), z: Number(p?.z ?? 0) };
}

export function workOffset(setup, name) {
  return pointOf(setup?.work_offsets?.[name]);
}

export function setWorkOffset(setup, name, point) {
  const all = { ...(setup.work_offsets || {}) };
  if (point.x === 0 && point.y === 0 && point.z === 0) delete all[name];
  else all[name] = point;
  if (Object.keys(all).length === 0) delete setup.work_offsets;
  else setup.work_offsets = all;
}

/** Sets `start` or `reference` (`name`); 0 0 0 is left out: setting machine_positions gives it (behaviour 13.15). */
export function setPoint(setup, name, point) {
  if (point.x === 0 && point.y === 0 && point.z === 0) delete setup[name];
  else setup[name] = point;
}


/** The document's JSON as people read it (two-space indent). */
export function setupText(setup) {
  return `${JSON.stringify(setup, null, 2)}\n`;
}

/** A copy that the caller may change. */
export function cloneSetup(setup) {
  return JSON.parse(JSON.stringify(setup ?? {}));
}
