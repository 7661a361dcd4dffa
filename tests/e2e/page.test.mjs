// Browser end-to-end tests of the playground page as a whole (issue 4,
// items 4, 8, 9 and 10): the drawing (both paths, colours, arrows, planes,
// zoom at the cursor, pan, pinch, fit, high-DPI, dark scheme), the examples
// menu, autosave and restore, storage failure, tablet layout and keyboard
// access. Screenshots: default.png, light.png, dark.png, lathe.png,
// tablet.png, tablet-dark.png (and -canvas crops).

import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import {
  MARKS, countColor, countDifferences, decode, loadExample, shoot, shootCanvas, typeProgram,
  useBrowser, viewOf, waitForRun, waitForView,
} from './harness.mjs';

const { withPage } = useBrowser();
const drawn = (c) => c.actualFeed > 300 && c.programmedFeed > 150;

describe('view', () => {
  test('draws the default example: both paths in their colours, arrows where they differ, sharp at 2x', async () => {
    await withPage(async (page) => {
      assert.match(await page.evaluate(() => window.offsetlab.program()), /SEED 000: SQUARE WITH G45-G48/);
      assert.match(await page.locator('#summary').textContent(), /8 blocks · 7 moves · 0 errors · 0 warnings · mill, mm/);
      const { counts, png } = await shootCanvas(page, 'default', drawn);
      await shoot(page, 'light');
      const box = await page.locator('#view').boundingBox();
      assert.equal(png.width, Math.round(box.width) * 2, 'drawn at device pixels');
      assert.ok(counts.actualFeed > 600, `actual feed pixels: ${counts.actualFeed}`);
      assert.ok(counts.actualRapid > 100, `actual rapid pixels: ${counts.actualRapid}`);
      assert.ok(counts.programmedFeed > 300, `programmed feed pixels: ${counts.programmedFeed}`);
      assert.ok(counts.programmedRapid > 50, `programmed rapid pixels: ${counts.programmedRapid}`);
      // Five arrows (blocks 1–5 end off their programmed points).
      assert.ok(countColor(png, MARKS.arrow) > 150, `arrow pixels: ${countColor(png, MARKS.arrow)}`);
    });
  });

  test('wheel zooms at the cursor, drag pans, double-click and the Fit button fit', async () => {
    await withPage(async (page) => {
      const canvas = page.locator('#view');
      const box = await canvas.boundingBox();
      const before = decode(await canvas.screenshot());
      await page.mouse.move(box.x + box.width * 0.3, box.y + box.height * 0.6);
      await page.mouse.wheel(0, -400);
      const zoomed = await waitForView(page, (v) => v.zoom > 1.5);
      assert.notDeepEqual(zoomed.pan, [0, 0], 'zoom about the cursor, not the centre');
      await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
      await page.mouse.down();
      await page.mouse.move(box.x + box.width / 2 + 80, box.y + box.height / 2 + 30, { steps: 5 });
      await page.mouse.up();
      const panned = await waitForView(page, (v, p) => Math.abs(v.pan[0] - p[0]) > 1, zoomed.pan);
      assert.equal(panned.zoom, zoomed.zoom, 'a drag does not zoom');
      // The step did not change: a drag is not a click.
      assert.equal(panned.step, null);
      const moved = decode(await canvas.screenshot());
      assert.ok(countDifferences(before, moved) > 2000);
      await canvas.dblclick({ position: { x: 20, y: 20 } });
      await waitForView(page, (v) => v.zoom === 1 && v.pan[0] === 0 && v.pan[1] === 0);
      await page.locator('#zoom-in').click();
      await waitForView(page, (v) => v.zoom > 1.2);
      await page.locator('#fit').click();
      await waitForView(page, (v) => v.zoom === 1);
      // Keyboard on the focused drawing: + zooms, Shift+arrow pans, 0 fits.
      await canvas.focus();
      await page.keyboard.press('+');
      await waitForView(page, (v) => v.zoom > 1.2);
      await page.keyboard.press('Shift+ArrowLeft');
      await waitForView(page, (v) => v.pan[0] !== 0);
      await page.keyboard.press('0');
      await waitForView(page, (v) => v.zoom === 1 && v.pan[0] === 0);
    }, { scale: 1 });
  });

  test('two fingers pinch-zoom and pan (pointer events)', async () => {
    await withPage(async (page) => {
      await page.locator('#view').evaluate((canvas) => {
        const r = canvas.getBoundingClientRect();
        const at = (id, type, x, y) => canvas.dispatchEvent(new PointerEvent(type, {
          pointerId: id, pointerType: 'touch', isPrimary: id === 1, bubbles: true, clientX: r.left + x, clientY: r.top + y, button: 0,
        }));
        at(1, 'pointerdown', 200, 200);
        at(2, 'pointerdown', 260, 200);
        for (let i = 1; i <= 5; i += 1) {
          at(1, 'pointermove', 200 - i * 10, 200);
          at(2, 'pointermove', 260 + i * 10, 200);
        }
        at(1, 'pointerup', 150, 200);
        at(2, 'pointerup', 310, 200);
      });
      const v = await waitForView(page, (w) => w.zoom > 2);
      assert.ok(v.zoom > 2 && v.zoom < 3, `pinch 60 → 160 px zooms ~2.7×: ${v.zoom}`);
      assert.equal(v.step, null, 'a pinch is not a click');
    }, { hasTouch: true, scale: 1 });
  });

  test('the plane selector shows XZ and YZ; a lathe is drawn in ZX with its centre line', async () => {
    await withPage(async (page) => {
      await loadExample(page, 'length');
      await waitForView(page, (v) => v.plane === 'XZ');
      assert.equal(await page.locator('#plane').inputValue(), 'XZ');
      const xz = await shootCanvas(page, 'length-xz', (c) => c.actualFeed > 200 && c.actualRapid > 200);
      assert.ok(countColor(xz.png, MARKS.arrow) > 50, 'Z offsets drawn as arrows');
      await page.locator('#plane').selectOption('XY');
      await waitForView(page, (v) => v.plane === 'XY');
      await page.locator('#plane').selectOption('YZ');
      await waitForView(page, (v) => v.plane === 'YZ');
      await loadExample(page, 'lathe-taper');
      await waitForView(page, (v) => v.plane === 'ZX');
      // The lathe's views: ZX, the face of polar interpolation, XC, and its 3D view (10.18).
      const shown = await page.locator('#plane option:not([hidden])').evaluateAll((os) => os.map((o) => o.value));
      assert.deepEqual(shown, ['ZX', 'XC', '3D']);
      await page.waitForFunction(() => /0 errors · 0 warnings · lathe \(G-code system A\), mm/.test(document.querySelector('#summary').textContent));
      // The offset table's four lathe columns fit the panel (the Z wear inputs ran past its right edge).
      const overflow = await page.evaluate(() => {
        const panel = document.getElementById('offsets-panel').getBoundingClientRect();
        return [...document.querySelectorAll('#offsets input, #offsets th')]
          .map((el) => el.getBoundingClientRect().right - panel.right)
          .filter((d) => d > -1);
      });
      assert.deepEqual(overflow, [], 'every column ends inside the panel');
      const { counts } = await shootCanvas(page, 'lathe', (c) => c.centreLine > 200 && c.actualFeed > 100);
      assert.ok(counts.centreLine > 200, `centre line pixels: ${counts.centreLine}`);
      assert.ok(counts.actualFeed > 100 && counts.programmedFeed > 50, JSON.stringify(counts));
    });
  });

  test('follows the canvas size and stays drawn on a narrow, low-DPI screen', async () => {
    await withPage(async (page) => {
      const { counts, png } = await shootCanvas(page, 'narrow', (c) => c.actualFeed > 150);
      const box = await page.locator('#view').boundingBox();
      assert.equal(png.width, Math.round(box.width));
      assert.ok(counts.actualFeed > 150 && counts.programmedFeed > 50, JSON.stringify(counts));
      // Resizing the window re-draws at the new size (the worker reports the size it drew at).
      await page.setViewportSize({ width: 700, height: 900 });
      const wanted = await page.locator('#view').evaluate((el) => {
        const r = el.getBoundingClientRect();
        return `${Math.round(r.width)}x${Math.round(r.height)}@${window.devicePixelRatio}`;
      });
      await page.waitForFunction((w) => document.body.dataset.drawn === w, wanted);
      const resized = await shootCanvas(page, 'resized', (c) => c.actualFeed > 150);
      assert.ok(resized.png.width > png.width * 1.2, `${resized.png.width} vs ${png.width}`);
    }, { width: 480, height: 900, scale: 1 });
  });

  test('dark scheme: page and drawing are dark, the paths stay apart', async () => {
    await withPage(async (page) => {
      const bg = await page.evaluate(() => getComputedStyle(document.body).backgroundColor);
      assert.equal(bg, 'rgb(15, 17, 21)');
      const png = decode(await page.locator('#view').screenshot());
      const i = (5 * png.width + 5) * 4;
      assert.ok(png.data[i] < 40 && png.data[i + 1] < 40 && png.data[i + 2] < 50, 'dark canvas');
      assert.ok(countColor(png, [0x6e, 0xa8, 0xff]) > 300, 'dark actual feed');
      assert.ok(countColor(png, [0xa5, 0xd8, 0xff]) > 100, 'dark programmed feed');
      await shoot(page, 'dark');
    }, { colorScheme: 'dark' });
  });
});

describe('examples', () => {
  test('each example sets its program, setup and note, and runs without errors; the previous work is one click away', async () => {
    await withPage(async (page) => {
      const values = await page.locator('#example option').evaluateAll((os) => os.map((o) => o.value));
      // The first entry is the menu's "Choose an example…", shown once the program is no example.
      assert.equal(values[0], '');
      const ids = values.slice(1);
      assert.deepEqual(ids, ['square', 'contour', 'zero-moves', 'length', 'lathe-seed', 'lathe-taper', 'lathe-nose', 'cutter-contour', 'cutter-pocket', 'linuxcnc', 'cam']);
      await typeProgram(page, 'G00 X5. Y5.;\n');
      const notes = new Set();
      for (const id of ids.slice(1)) {
        await loadExample(page, id);
        // The pocket's lesson is the control's interference alarm (programs.test.mjs).
        const errors = id === 'cutter-pocket' ? / 1 error · 0 warnings / : / 0 errors · 0 warnings /;
        assert.match(await page.locator('#summary').textContent(), errors, id);
        const note = await page.locator('#example-note').textContent();
        assert.ok(note.length > 80, `${id} has a note`);
        notes.add(note);
        // The LinuxCNC example keeps its tools in a tool table (behaviour 22.9).
        if (id === 'linuxcnc') assert.ok(await page.locator('#tool-table').isVisible(), 'linuxcnc shows its tool table');
        else assert.ok((await page.locator('#offsets tbody tr.used').count()) >= 1, `${id} sets its registers`);
      }
      assert.equal(notes.size, ids.length - 1, 'every note is its own');
      await loadExample(page, 'zero-moves');
      assert.deepEqual((await page.evaluate(() => window.offsetlab.setup())).offsets, { 10: 5, 11: 3 });
      // The work before the first example comes back.
      await page.locator('#banner-action').click();
      await waitForRun(page);
      assert.equal(await page.evaluate(() => window.offsetlab.program()), 'G00 X5. Y5.;\n');
      assert.equal(await page.locator('#banner').isVisible(), false);
    });
  });
});

describe('no lost work', () => {
  test('program, offsets, settings and view survive a reload', async () => {
    await withPage(async (page) => {
      await typeProgram(page, 'G91 G00 G46 X30. Y20. D02;\nG01 G47 X50. F100.;\n');
      await page.locator('input[data-field="2.value"]').fill('4.5');
      await page.getByLabel('Block skip').check();
      await page.locator('#step-first').click();
      await waitForView(page, (v) => v.step === 0);
      await page.waitForFunction(() => document.body.dataset.unsaved === undefined && document.body.dataset.saved);
      await page.reload();
      await waitForRun(page);
      assert.equal(await page.evaluate(() => window.offsetlab.program()), 'G91 G00 G46 X30. Y20. D02;\nG01 G47 X50. F100.;\n');
      assert.equal(await page.locator('input[data-field="2.value"]').inputValue(), '4.5');
      assert.equal(await page.getByLabel('Block skip').isChecked(), true);
      await waitForView(page, (v) => v.step === 0);
    });
  });

  test('an edit reloaded at once, before its autosave was due, is not lost', async () => {
    await withPage(async (page) => {
      await typeProgram(page, 'G00 X2.;\n');
      await page.waitForFunction(() => document.body.dataset.unsaved === undefined);
      // The save waits for a pause and for the page to be idle; the page
      // being hidden (a reload, a closed tab) saves at once.
      await page.keyboard.type('G01 Y3. F100.;\n');
      assert.equal(await page.evaluate(() => document.body.dataset.unsaved), 'true', 'not saved yet');
      await page.reload();
      await waitForRun(page);
      assert.equal(await page.evaluate(() => window.offsetlab.program()), 'G00 X2.;\nG01 Y3. F100.;\n');
    });
  });

  test('when storage is full the page says so', async () => {
    await withPage(async (page, { problems }) => {
      await typeProgram(page, 'G00 X1.;\n');
      const banner = page.locator('#storage-banner');
      await banner.waitFor({ state: 'visible' });
      assert.match(await banner.textContent(), /not being saved: the browser’s storage is full/);
      problems.length = 0;
    }, {
      init: () => {
        Storage.prototype.setItem = () => {
          throw new DOMException('quota', 'QuotaExceededError');
        };
      },
    });
  });
});

describe('layout and access', () => {
  test('tablet width: one column, nothing wider than the screen, drawn in both schemes', async () => {
    for (const colorScheme of ['light', 'dark']) {
      await withPage(async (page) => {
        const wide = await page.evaluate(() => document.documentElement.scrollWidth);
        assert.ok(wide <= 768, `page is ${wide}px wide`);
        const editor = await page.locator('#editor').boundingBox();
        const view = await page.locator('#view').boundingBox();
        assert.ok(view.width > 700 && editor.width > 700, 'full-width editor and drawing');
        await page.locator('#step-next').click();
        await waitForView(page, (v) => v.step === 0);
        await shoot(page, colorScheme === 'light' ? 'tablet' : 'tablet-dark', { fullPage: true });
      }, { width: 768, height: 1024, scale: 2, colorScheme });
    }
  });

  test('laptop width: three columns without page scroll; keyboard focus order, visible focus and labels', async () => {
    await withPage(async (page) => {
      const height = await page.evaluate(() => document.documentElement.scrollHeight);
      assert.ok(height <= 768, `page is ${height}px tall`);
      // Every form control has an accessible name.
      const unnamed = await page.evaluate(() => [...document.querySelectorAll('input, select, textarea, button')]
        .filter((el) => !el.closest('[hidden]'))
        .filter((el) => !(el.getAttribute('aria-label') || el.labels?.length || el.textContent.trim()))
        .map((el) => el.outerHTML.slice(0, 80)));
      assert.deepEqual(unnamed, []);
      // Tab order: examples, open, share, help, undo, redo, editor, then the view's controls.
      await page.locator('h1').click();
      const order = [];
      for (let i = 0; i < 18; i += 1) {
        await page.keyboard.press('Tab');
        order.push(await page.evaluate(() => {
          const el = document.activeElement;
          return el.id || el.className || el.tagName;
        }));
      }
      const at = (id) => order.indexOf(id);
      assert.ok(at('example') >= 0 && at('example') < at('undo'), order.join(' '));
      assert.ok(at('undo') < order.findIndex((o) => o.includes('cm-content')), order.join(' '));
      assert.ok(order.findIndex((o) => o.includes('cm-content')) < at('plane'), order.join(' '));
      assert.ok(at('plane') < at('view') && at('view') < at('step-first'), order.join(' '));
      // The focused control shows an outline.
      await page.locator('#step-next').focus();
      const outline = await page.evaluate(() => getComputedStyle(document.activeElement).outlineStyle);
      assert.notEqual(outline, 'none');
      // The keyboard help opens with "?".
      await page.locator('h1').click();
      await page.keyboard.press('?');
      assert.equal(await page.locator('#help').isVisible(), true);
      assert.match(await page.locator('#help').textContent(), /next \/ previous block/);
    }, { width: 1366, height: 768, scale: 1 });
  });
});
