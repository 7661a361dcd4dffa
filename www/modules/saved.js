// What the autosave writes (modules/storage.js): the work as the one
// versioned document of share links and `--setup` files (src/document.rs:
// the setup's fields, `program`, `view` {plane, zoom, pan} and `step` at one
// level, `"version": 1`), so that a saved value opens with `offsetlab run
// --setup FILE` as it is. What only the page needs is kept beside it, in
// `page`, and only while it is needed:
//
//   example    the id of the example shown while it is untouched (its note,
//              the menu; not the user's own work, so not kept when replaced)
//   link       true while the work of a link or file is untouched (the same)
//   setupText  the setup's JSON as the user is typing it, while it does not
//              parse (it runs as typed; `setup` is the last one that parsed)
//   setup      a setup that would collide with the document's own fields
//              (a `program`, `view`, `step` or `page` key); the document
//              then carries the default setup
//
// The document readers refuse unknown fields: the document is the saved
// value without `page`. The page's first saved shape, `{ program, setup,
// setupText?, view: {plane, zoom, pan, step}?, example?, link? }` (no
// top-level `version`), is still read, and storage.js writes it again in
// this shape.

/** The document version written (src/setup.rs SETUP_VERSION). */
const VERSION = 1;
/** The document's own fields besides the setup's, and the page's extras. */
const RESERVED = ['program', 'view', 'step', 'page'];

const isObject = (v) => typeof v === 'object' && v !== null;
const isPlain = (v) => isObject(v) && !Array.isArray(v);

/** The saved value of `w` { program, setup, setupText?, view?: {plane, zoom, pan, step}, example?, link? }. */
export function savedOf(w) {
  const setup = w.setup ?? {};
  const fits = isPlain(setup) && !RESERVED.some((key) => Object.hasOwn(setup, key));
  const saved = { version: VERSION, ...(fits ? setup : {}), program: w.program };
  if (isPlain(w.view)) {
    const { step, ...view } = w.view;
    // A null field stays as it is, as an absent one would (Session.set_view);
    // the document reads no null zoom or pan.
    saved.view = Object.fromEntries(Object.entries(view).filter(([, v]) => v !== null && v !== undefined));
    if (Number.isInteger(step) && step >= 0) saved.step = step;
  }
  const page = {};
  if (!fits) page.setup = setup;
  if (typeof w.setupText === 'string') page.setupText = w.setupText;
  if (w.example) page.example = w.example;
  if (w.link) page.link = true;
  if (Object.keys(page).length > 0) saved.page = page;
  return saved;
}

/** The work of a saved value of this shape: the inverse of savedOf(). */
function workOfDocument(value) {
  const {
    program, view, step, page, ...setup
  } = value;
  if (typeof program !== 'string') return null;
  const extras = isPlain(page) ? page : {};
  // The version every document carries is the setup's default: the page
  // leaves defaults out of the setup it edits (modules/setup.js).
  if (setup.version === VERSION) delete setup.version;
  const w = { program, setup: isObject(extras.setup) ? extras.setup : setup };
  if (typeof extras.setupText === 'string') w.setupText = extras.setupText;
  if (view !== undefined || step !== undefined) {
    w.view = { ...(isPlain(view) ? view : {}), step: Number.isInteger(step) ? step : null };
  }
  if (typeof extras.example === 'string') w.example = extras.example;
  if (extras.link === true) w.link = true;
  return w;
}

/**
 * The work of a saved value (parsed JSON), or null when it is not one:
 * `{ work, old }`, `old` when it is in the page's first shape (to be
 * written again in this one).
 */
export function readSaved(value) {
  if (!isPlain(value)) return null;
  if (Object.hasOwn(value, 'version')) {
    const w = workOfDocument(value);
    return w && { work: w, old: false };
  }
  if (typeof value.program !== 'string' || !isObject(value.setup)) return null;
  // Read as the new shape is, so that this load and the next agree.
  return { work: workOfDocument(savedOf(value)), old: true };
}
