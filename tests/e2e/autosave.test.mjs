// Browser end-to-end tests of what the autosave writes (issue 19, item 7):
// the work saved in localStorage is the versioned document of share links
// and `--setup` files (program, setup, view, step), which `offsetlab run
// --setup`, `offsetlab link` and the page's own document reader
// (read_document, through Open…) read, with the page's extras beside it in
// `page` only while they are needed (an untouched example or link, a setup
// being typed); saved work in the page's first shape ({ program, setup,
// setupText?, view?, example?, link? }, under both keys) comes back after
// the upgrade with its program, offsets, settings, view and step, and is
// written again as a document the first time it is read — not where the
// browser refuses, nor in embed mode.
// Screenshots: autosave-document.png, autosave-migrated.png,
// autosave-migrated-previous.png.

import assert from 'node:assert/strict';
import { mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { describe, test } from 'node:test';
import {
  ROOT, cli, decodeLink, loadExample, savedWork, shoot, typeProgram, useBrowser, viewOf, waitForLink, waitForRun,
  waitForView,
} from './harness.mjs';

const ctx = useBrowser();
const { withPage } = ctx;
const tmp = mkdtempSync(join(tmpdir(), 'offsetlab-e2e-'));

const KEY = 'offsetlab.work.v1';
const PREVIOUS_KEY = 'offsetlab.previous.v1';
/** The default example's program, seed 000's square. */
const SQUARE = readFileSync(join(ROOT, 'tests', 'data', 'seed000_square.nc'), 'utf8');

const MILL_PROGRAM = 'G90 G00 X0 Y0 Z50.;\nG43 Z10. H02;\n/G00 X500.;\nG01 X20. F100.;\nG91 G46 Y30. D01;\nM30;\n';
const LATHE_PROGRAM = 'G50 X120. Z60.\nG00 S800 M03 T0108\nX50. Z3.\nG01 Z-20. F0.2\nG00 X120. Z60. T0100\nM30\n';
const USER_PROGRAM = 'G90 G00 X10. Y10.;\nG01 X40. F100.;\n';

/** The fields a document may have (src/document.rs and src/setup.rs). */
const DOCUMENT_FIELDS = new Set(['version', 'machine', 'units', 'settings', 'table_size', 'start', 'reference',
  'work_offsets', 'offsets', 'lathe_offsets', 'program', 'view', 'step']);

function file(name, text) {
  const path = join(tmp, name);
  writeFileSync(path, text);
  return path;
}

/** A saved value without the page's extras: the document. */
function documentOf(saved) {
  const { page, ...document } = saved;
  return document;
}

/** `offsetlab run --format json --setup FILE` of a document. */
function cliRun(document, name) {
  return JSON.parse(cli(['run', '--format', 'json', '--setup', file(name, JSON.stringify(document))]));
}

/** The document as the CLI reads and writes it: `link --decode` of `link --setup FILE`. */
function cliDocument(document, name) {
  return decodeLink(cli(['link', '--base', ctx.server.url, '--setup', file(name, JSON.stringify(document))]).trim());
}

/**
 * An init script that puts `values` (key → JSON text) in localStorage before
 * the page's first load in this tab (not on a reload), and logs every write
 * to localStorage in `window.offsetlabTestWrites` as { key, value, requested }:
 * `requested` is the page's run count at that time (null: before its first
 * run request, as the page loads its saved work).
 */
function seeded(values) {
  return `(() => {
    const set = Storage.prototype.setItem;
    if (!sessionStorage.getItem('offsetlab-test-seeded')) {
      set.call(sessionStorage, 'offsetlab-test-seeded', '1');
      for (const [key, value] of ${JSON.stringify(Object.entries(values))}) set.call(localStorage, key, value);
    }
    window.offsetlabTestWrites = [];
    Storage.prototype.setItem = function setItem(key, value) {
      if (this === window.localStorage) {
        window.offsetlabTestWrites.push({ key, value: String(value), requested: document.body?.dataset.requested ?? null });
      }
      return set.call(this, key, value);
    };
  })();`;
}

/** The writes to `key` the page made as it loaded, before its first run (the migration), parsed. */
async function loadWrites(page, key) {
  const writes = await page.evaluate(() => window.offsetlabTestWrites);
  return writes.filter((w) => w.key === key && w.requested === null).map((w) => JSON.parse(w.value));
}

const stored = (page, key) => page.evaluate((k) => JSON.parse(localStorage.getItem(k)), key);

/** Asserts what the user sees of a mill setup with registers 01 = 5 and 02 = 95.3, W-0.05 and block skip on. */
async function assertMillPanels(page) {
  // The YASNAC profile's offset memory A: one value per number, a wear
  // part of the document taken into it (behaviour 17.1): 95.3 - 0.05.
  assert.equal(await page.locator('input[data-field="1.value"]').inputValue(), '5');
  assert.equal(await page.locator('input[data-field="2.value"]').inputValue(), '95.25');
  assert.equal(await page.getByLabel('Block skip').isChecked(), true);
}

describe('the autosave writes the document', () => {
  test('own work is saved as the document that `run --setup`, `link` and Open… (read_document) read, with program, setup, view and step', async () => {
    await withPage(async (page) => {
      await typeProgram(page, MILL_PROGRAM);
      await page.locator('input[data-field="2.value"]').fill('4.5');
      await page.getByLabel('Block skip').check();
      await page.locator('#plane').selectOption('XZ');
      await page.locator('#zoom-in').click();
      await page.locator('#step-first').click();
      await page.locator('#step-next').click();
      const view = await waitForView(page, (v) => v.plane === 'XZ' && v.zoom > 1.2 && v.step === 1);
      const saved = await savedWork(page);
      // The document's fields only: the user's own work needs no extras.
      assert.deepEqual(Object.keys(saved).filter((k) => !DOCUMENT_FIELDS.has(k)), []);
      assert.equal(saved.version, 1);
      assert.equal(saved.program, MILL_PROGRAM);
      assert.deepEqual(saved.offsets, { '01': 6, '02': 4.5 });
      assert.deepEqual(saved.settings, { block_skip: true });
      assert.deepEqual(saved.view, { plane: view.plane, zoom: view.zoom, pan: view.pan });
      assert.equal(saved.step, 1);
      // `offsetlab run --setup FILE` runs it: its program, registers and settings.
      const run = cliRun(saved, 'saved.json');
      assert.equal(run.summary.errors, 0);
      assert.ok(!run.blocks.some((b) => b.text.includes('X500.')), 'block skip came along');
      assert.equal(run.blocks[1].actual.z, 14.5, 'H02 = 4.5');
      assert.equal(run.blocks[3].position_offset.value, 6, 'D01 = 6');
      assert.match(await page.locator('#step-position').textContent(), new RegExp(`^block 2 of ${run.blocks.length} · line 2$`));
      // `offsetlab link --setup FILE` carries it whole: the same document as the page's own link.
      const linked = cliDocument(saved, 'saved-link.json');
      const { link } = await page.evaluate(() => window.offsetlab.document());
      const shown = decodeLink(link);
      assert.deepEqual({ ...linked, view: undefined }, { ...shown, view: undefined });
      assert.equal(linked.view.plane, 'XZ');
      assert.ok(Math.abs(linked.view.zoom - shown.view.zoom) < 1e-5, `${linked.view.zoom} ${shown.view.zoom}`);
      assert.ok(linked.view.pan.every((p, i) => Math.abs(p - shown.view.pan[i]) < 1e-3), JSON.stringify(linked.view));
      assert.equal(linked.step, 1);
      await shoot(page, 'autosave-document');
      // The page's document reader (read_document, the worker's `read`) opens it as a file.
      await page.locator('#open-file').setInputFiles({
        name: 'autosave.json', mimeType: 'application/json', buffer: Buffer.from(JSON.stringify(saved)),
      });
      await page.waitForFunction(() => document.body.dataset.opened === 'autosave.json');
      await waitForRun(page);
      assert.match(await page.locator('#banner .text').textContent(), /^Opened “autosave\.json”\./);
      assert.equal(await page.evaluate(() => window.offsetlab.program()), MILL_PROGRAM);
      assert.equal(await page.locator('input[data-field="2.value"]').inputValue(), '4.5');
      assert.equal(await page.getByLabel('Block skip').isChecked(), true);
      await waitForView(page, (v) => v.plane === 'XZ' && v.step === 1 && Math.abs(v.zoom - view.zoom) < 1e-5);
      // Opened from a file and untouched: the page's extra says so; the document is the same.
      const reopened = await savedWork(page);
      assert.deepEqual(reopened.page, { link: true });
      assert.deepEqual(cliDocument(documentOf(reopened), 'reopened.json'), linked);
    });
  });

  test('the page’s extras stay beside the document: an untouched example, an opened link, a setup being typed', async () => {
    await withPage(async (page) => {
      // The default example, untouched (a step saves it): seed 000's square (tests/data/seed000_square.nc).
      await page.locator('#step-next').click();
      await waitForView(page, (v) => v.step === 0);
      let saved = await savedWork(page);
      assert.deepEqual(saved.page, { example: 'square' });
      assert.equal(saved.step, 0);
      assert.equal(saved.program, SQUARE);
      assert.deepEqual(documentOf(saved), {
        version: 1, machine: 'mill', offsets: { '01': 6 }, program: SQUARE, view: { plane: 'XY', zoom: 1, pan: [0, 0] }, step: 0,
      });
      assert.equal(cliRun(documentOf(saved), 'square.json').summary.errors, 0);
      // A setup being typed that does not parse: it is kept as typed, beside the last one that parsed.
      const typed = '{ "offsets": { "01": 7';
      await page.locator('#advanced summary').click();
      await page.locator('#setup').fill(typed);
      await waitForRun(page);
      saved = await savedWork(page);
      assert.deepEqual(saved.page, { setupText: typed });
      assert.deepEqual(saved.offsets, { '01': 6 });
      await page.reload();
      await waitForRun(page);
      await page.locator('#advanced summary').click();
      assert.equal(await page.locator('#setup').inputValue(), typed);
      assert.equal(await page.locator('input[data-field="1.value"]').inputValue(), '6');
      assert.equal(await page.evaluate(() => window.offsetlab.program()), SQUARE);
      // Mended: the extra goes.
      await page.locator('#setup').fill('{ "offsets": { "01": 7 } }');
      await waitForRun(page);
      saved = await savedWork(page);
      assert.equal(saved.page, undefined);
      assert.deepEqual(saved.offsets, { '01': 7 });
      // An opened link, untouched: not the user's own work, across a reload.
      const link = cli(['link', '--base', ctx.server.url, '--machine', 'lathe', '--offset', '08=X0.4,Z-0.2', '--step', '2',
        file('lathe.nc', LATHE_PROGRAM)]).trim();
      await page.evaluate(() => { delete document.body.dataset.link; });
      await page.evaluate((hash) => { location.hash = hash; }, link.slice(link.indexOf('#')));
      assert.equal(await waitForLink(page), 'opened');
      await waitForView(page, (v) => v.step === 2);
      saved = await savedWork(page);
      assert.deepEqual(saved.page, { link: true });
      assert.deepEqual(documentOf(saved), { ...decodeLink(link), view: saved.view });
      await page.reload();
      assert.equal(await waitForLink(page), 'opened');
      await loadExample(page, 'contour');
      // The restore button brings back the user's work before the link (the mended setup), not the link.
      await page.locator('#restore-previous').click();
      await waitForRun(page);
      assert.equal(await page.evaluate(() => window.offsetlab.program()), SQUARE);
      assert.equal(await page.locator('input[data-field="1.value"]').inputValue(), '7');
    });
  });
});

/**
 * Values in the page's first saved shape and what the page writes for each.
 * `every` is what that page wrote for the user's own work (its work.js
 * currentWork(): every key, null and false where nothing was there).
 */
const OLD = {
  every: {
    old: {
      program: MILL_PROGRAM,
      setup: { machine: 'mill', offsets: { '01': 5, '02': { geometry: 95.3, wear: -0.05 } }, settings: { block_skip: true } },
      setupText: null,
      view: { plane: 'XZ', zoom: 2, pan: [1.5, -2], step: 2 },
      example: null,
      link: false,
    },
    migrated: {
      version: 1, machine: 'mill', offsets: { '01': 5, '02': { geometry: 95.3, wear: -0.05 } }, settings: { block_skip: true },
      program: MILL_PROGRAM, view: { plane: 'XZ', zoom: 2, pan: [1.5, -2] }, step: 2,
    },
  },
  noView: {
    old: { program: USER_PROGRAM, setup: { offsets: { '01': 6 } } },
    migrated: { version: 1, offsets: { '01': 6 }, program: USER_PROGRAM },
  },
  setupText: {
    old: {
      program: USER_PROGRAM, setup: { offsets: { '01': 6 } }, setupText: '{ "offsets": { "01": 7',
      view: { plane: 'XY', zoom: 1.5, pan: [0, 0], step: null },
    },
    migrated: {
      version: 1, offsets: { '01': 6 }, program: USER_PROGRAM, view: { plane: 'XY', zoom: 1.5, pan: [0, 0] },
      page: { setupText: '{ "offsets": { "01": 7' },
    },
  },
  example: {
    old: {
      program: SQUARE, setup: { machine: 'mill', offsets: { '01': 6 } },
      view: { plane: 'XY', zoom: 1, pan: [0, 0], step: 3 }, example: 'square',
    },
    migrated: {
      version: 1, machine: 'mill', offsets: { '01': 6 }, program: SQUARE, view: { plane: 'XY', zoom: 1, pan: [0, 0] }, step: 3,
      page: { example: 'square' },
    },
  },
  link: {
    old: {
      program: LATHE_PROGRAM, setup: { version: 1, machine: 'lathe', units: 'mm', lathe_offsets: { '08': { x: 0.4, z: -0.2 } } },
      view: { plane: 'ZX', zoom: 1, pan: [0, 0], step: 1 }, link: true,
    },
    migrated: {
      version: 1, machine: 'lathe', units: 'mm', lathe_offsets: { '08': { x: 0.4, z: -0.2 } },
      program: LATHE_PROGRAM, view: { plane: 'ZX', zoom: 1, pan: [0, 0] }, step: 1, page: { link: true },
    },
  },
};

/** Waits for the view the saved value asks for (the worker reports it a frame after the run). */
async function waitForSavedView(page, view) {
  return waitForView(page, (v, want) => v.plane === want.plane && v.zoom === want.zoom
    && v.pan[0] === want.pan[0] && v.pan[1] === want.pan[1] && v.step === want.step, view);
}

describe('saved work of the first shape', () => {
  test('the work key with every field: restored with program, offsets, settings, view and step, and written again as the document', async () => {
    const { old, migrated } = OLD.every;
    await withPage(async (page) => {
      assert.deepEqual(await loadWrites(page, KEY), [migrated], 'written again as the page loaded it');
      assert.equal(await page.evaluate(() => window.offsetlab.program()), MILL_PROGRAM);
      await assertMillPanels(page);
      await waitForSavedView(page, old.view);
      assert.equal(await page.locator('#plane').inputValue(), 'XZ');
      assert.match(await page.locator('#step-position').textContent(), /^block 3 of 5 · line 4$/);
      assert.deepEqual(await page.evaluate(() => window.offsetlab.setup()), old.setup);
      assert.match(await page.locator('#summary').textContent(), / 0 errors /);
      await shoot(page, 'autosave-migrated');
      // The document the CLI reads: the same run as the old value's program and setup.
      const run = cliRun(documentOf(await stored(page, KEY)), 'migrated.json');
      assert.deepEqual(run, JSON.parse(cli(['run', '--format', 'json', '--setup', file('old-setup.json', JSON.stringify(old.setup)),
        file('old.nc', old.program)])));
      // After a reload: the same work, read as the document, not written again.
      await page.reload();
      await waitForRun(page);
      assert.deepEqual(await loadWrites(page, KEY), []);
      assert.equal(await page.evaluate(() => window.offsetlab.program()), MILL_PROGRAM);
      await assertMillPanels(page);
      await waitForSavedView(page, old.view);
      const now = await savedWork(page);
      assert.equal(now.setup, undefined);
      assert.deepEqual(now, migrated);
    }, { init: seeded({ [KEY]: JSON.stringify(old) }) });
  });

  for (const name of ['noView', 'setupText', 'example', 'link']) {
    test(`the work key, ${name}: restored as it was saved and written again as the document`, async () => {
      const { old, migrated } = OLD[name];
      await withPage(async (page) => {
        assert.deepEqual(await loadWrites(page, KEY), [migrated]);
        for (let round = 0; round < 2; round += 1) {
          assert.equal(await page.evaluate(() => window.offsetlab.program()), old.program);
          const { version, ...setup } = old.setup;
          assert.deepEqual(await page.evaluate(() => window.offsetlab.setup()), setup, 'the default version is left out');
          if (old.view) await waitForSavedView(page, old.view);
          else assert.deepEqual(await viewOf(page), { plane: 'XY', zoom: 1, pan: [0, 0], step: null });
          if (name === 'setupText') {
            assert.equal(await page.locator('#setup').inputValue(), old.setupText);
            assert.equal(await page.locator('input[data-field="1.value"]').inputValue(), '6');
            assert.match(await page.locator('#summary').textContent(), /stopped: bad setup/);
          }
          if (name === 'example') {
            assert.equal(await page.locator('#example').inputValue(), 'square');
            assert.match(await page.locator('#example-note').textContent(), /^The programmed square 80 × 50/);
          }
          if (name === 'link') {
            assert.equal(await page.locator('input[data-field="8.x"]').inputValue(), '0.4');
            assert.equal(await page.locator('input[data-field="8.z"]').inputValue(), '-0.2');
          }
          if (round === 0) {
            await page.reload();
            await waitForRun(page);
            assert.deepEqual(await loadWrites(page, KEY), [], 'migrated once');
          }
        }
        // Still the migrated value (with the view shown, when the page saved it again since).
        const now = await savedWork(page);
        assert.deepEqual(now, old.view || !now.view ? migrated : { ...migrated, view: { plane: 'XY', zoom: 1, pan: [0, 0] } });
        // The document part is one that `run --setup` reads.
        assert.equal(cliRun(documentOf(migrated), `${name}.json`).summary.errors, 0);
        // An untouched example or link is not the user's own work: another example replaces it, nothing to restore.
        await loadExample(page, 'contour');
        assert.equal(await page.locator('#restore-previous').isVisible(), name === 'noView' || name === 'setupText');
      }, { init: seeded({ [KEY]: JSON.stringify(old) }) });
    });
  }

  test('the previous-work key (and the work key beside it): written again as documents; Restore brings back program, offsets, settings, view and step', async () => {
    const previous = {
      program: MILL_PROGRAM,
      setup: { offsets: { '01': 5, '02': { geometry: 95.3, wear: -0.05 } }, settings: { block_skip: true, length_offset_without_z: 'next_z' } },
      view: { plane: 'YZ', zoom: 3, pan: [2, 1], step: 1 },
    };
    const mine = { program: USER_PROGRAM, setup: {}, setupText: '{ "offsets": ' };
    await withPage(async (page) => {
      assert.deepEqual(await loadWrites(page, PREVIOUS_KEY), [{
        version: 1, ...previous.setup, program: MILL_PROGRAM, view: { plane: 'YZ', zoom: 3, pan: [2, 1] }, step: 1,
      }]);
      assert.deepEqual(await loadWrites(page, KEY), [{ version: 1, program: USER_PROGRAM, page: { setupText: mine.setupText } }]);
      assert.equal(await page.evaluate(() => window.offsetlab.program()), USER_PROGRAM);
      assert.equal(await page.locator('#setup').inputValue(), mine.setupText);
      assert.equal(await page.locator('#restore-previous').isVisible(), true);
      await page.locator('#restore-previous').click();
      await waitForRun(page);
      assert.equal(await page.evaluate(() => window.offsetlab.program()), MILL_PROGRAM);
      await assertMillPanels(page);
      assert.equal(await page.locator('#set-length_offset_without_z').inputValue(), 'next_z');
      await waitForSavedView(page, previous.view);
      assert.equal(await page.locator('#plane').inputValue(), 'YZ');
      assert.match(await page.locator('#step-position').textContent(), /^block 2 of 5 · line 2$/);
      await shoot(page, 'autosave-migrated-previous');
      // They changed places: the work shown before, setup text and all, is the previous work now.
      assert.deepEqual(await stored(page, PREVIOUS_KEY), {
        version: 1, program: USER_PROGRAM, view: { plane: 'XY', zoom: 1, pan: [0, 0] }, page: { setupText: mine.setupText },
      });
      await page.locator('#restore-previous').click();
      await waitForRun(page);
      assert.equal(await page.evaluate(() => window.offsetlab.program()), USER_PROGRAM);
      assert.equal(await page.locator('#setup').inputValue(), mine.setupText);
    }, { init: seeded({ [KEY]: JSON.stringify(mine), [PREVIOUS_KEY]: JSON.stringify(previous) }) });
  });

  test('where the browser refuses the new value, the old one stays as it was and is read', async () => {
    const old = JSON.stringify(OLD.every.old);
    await withPage(async (page, { problems }) => {
      assert.equal(await page.evaluate(() => window.offsetlab.program()), MILL_PROGRAM);
      await assertMillPanels(page);
      await waitForSavedView(page, OLD.every.old.view);
      assert.equal(await page.evaluate((k) => localStorage.getItem(k), KEY), old);
      // The next save is refused too, and says so; the old value is still there.
      await page.locator('#zoom-in').click();
      await page.locator('#storage-banner').waitFor({ state: 'visible' });
      assert.match(await page.locator('#storage-banner').textContent(), /not being saved: the browser’s storage is full/);
      assert.equal(await page.evaluate((k) => localStorage.getItem(k), KEY), old);
      await page.reload();
      await waitForRun(page);
      assert.equal(await page.evaluate(() => window.offsetlab.program()), MILL_PROGRAM);
      await waitForSavedView(page, OLD.every.old.view);
      problems.length = 0;
    }, {
      // localStorage full (sessionStorage, where the page keeps the address it wrote, is not).
      init: `${seeded({ [KEY]: old })}
        const setItem = Storage.prototype.setItem;
        Storage.prototype.setItem = function full(key, value) {
          if (this === window.localStorage) throw new DOMException('The quota has been exceeded.', 'QuotaExceededError');
          return setItem.call(this, key, value);
        };`,
    });
  });

  test('an embedded page neither reads nor rewrites saved work of the first shape', async () => {
    const old = JSON.stringify(OLD.every.old);
    const previous = JSON.stringify(OLD.noView.old);
    const link = cli(['link', '--plain', '--base', ctx.server.url, '--embed', file('embed.nc', USER_PROGRAM)]).trim();
    await withPage(async (page) => {
      assert.equal(await page.evaluate(() => window.offsetlab.embed), true);
      assert.equal(await page.evaluate(() => window.offsetlab.program()), USER_PROGRAM);
      assert.deepEqual(await page.evaluate(() => window.offsetlabTestWrites), []);
      assert.equal(await page.evaluate((k) => localStorage.getItem(k), KEY), old);
      assert.equal(await page.evaluate((k) => localStorage.getItem(k), PREVIOUS_KEY), previous);
    }, { hash: link.slice(link.indexOf('#')), init: seeded({ [KEY]: old, [PREVIOUS_KEY]: previous }) });
  });
});
