// Browser end-to-end tests of the page (issue 2): the default example is
// drawn, typing re-draws, a syntax error is listed with line:column, and no
// console error or page exception happens on the way. Screenshots go to
// test-results/ (default.png, typed.png, error.png and their -canvas crops).

import assert from 'node:assert/strict';
import { after, before, describe, test } from 'node:test';
import {
  countDifferences, launchBrowser, openPage, shootCanvas, startServer, waitForRun,
} from './harness.mjs';

let server;
let browser;

before(async () => {
  server = await startServer();
  browser = await launchBrowser();
});

after(async () => {
  await browser?.close();
  await server?.stop();
});

/** Opens the page, runs `body`, then checks that nothing went wrong in the console. */
async function withPage(body, options) {
  const { context, page, problems } = await openPage(browser, server.url, options);
  try {
    await waitForRun(page);
    await body(page);
    assert.deepEqual(problems, [], 'no console errors, page exceptions or failed requests');
  } finally {
    await context.close();
  }
}

/** Replaces the program by typing it, key by key, as a user would. */
async function typeProgram(page, text) {
  const editor = page.locator('#program');
  await editor.click();
  await page.keyboard.press('ControlOrMeta+A');
  await page.keyboard.press('Delete');
  await editor.pressSequentially(text, { delay: 2 });
  // Wait for the debounce to fire and the answer to come back.
  await waitForRun(page);
}

const drawn = (c) => c.actualFeed > 300 && c.programmedFeed > 150;

describe('page', () => {
  test('draws the default example: seed 000 square, both paths, no problems', async () => {
    await withPage(async (page) => {
      const program = await page.locator('#program').inputValue();
      assert.match(program, /SEED 000: SQUARE WITH G45-G48/);
      assert.match(await page.locator('#setup').inputValue(), /"01": 6\.0/);
      await assert.doesNotReject(page.locator('#summary').filter({ hasText: '8 blocks' }).waitFor());
      const summary = await page.locator('#summary').textContent();
      assert.match(summary, /8 blocks · 7 moves · 0 errors · 0 warnings · mill, mm/);
      assert.equal(await page.locator('#diagnostics li.none').count(), 1);

      const { counts, png } = await shootCanvas(page, 'default', drawn);
      // Screenshot at devicePixelRatio 2: the canvas is drawn at device pixels.
      const box = await page.locator('#view').boundingBox();
      assert.equal(png.width, Math.round(box.width) * 2);
      assert.ok(counts.painted > 0.01 * counts.total, `painted ${counts.painted} of ${counts.total}`);
      assert.ok(counts.actualFeed > 300, `actual feed pixels: ${counts.actualFeed}`);
      assert.ok(counts.actualRapid > 100, `actual rapid pixels: ${counts.actualRapid}`);
      assert.ok(counts.programmedFeed > 150, `programmed feed pixels: ${counts.programmedFeed}`);
      assert.ok(counts.programmedRapid > 50, `programmed rapid pixels: ${counts.programmedRapid}`);
    });
  });

  test('typing a new program re-draws the path', async () => {
    await withPage(async (page) => {
      const before = await shootCanvas(page, 'before-typing', drawn);
      await typeProgram(page, 'G90 G00 X-20. Y-10.;\nG01 X100. Y0 F300.;\nG02 X100. Y60. R30.;\nG01 X0 Y60.;\nG00 X0 Y0;\n');
      const summary = await page.locator('#summary').textContent();
      assert.match(summary, /5 blocks · 5 moves · 0 errors/);
      const afterTyping = await shootCanvas(
        page,
        'typed',
        (c, png) => countDifferences(before.png, png) > 2000 && c.actualFeed > 300,
      );
      const changed = countDifferences(before.png, afterTyping.png);
      assert.ok(changed > 2000, `only ${changed} pixels changed`);
      assert.ok(afterTyping.counts.actualFeed > 300);
      assert.ok(afterTyping.counts.actualRapid > 50);
    });
  });

  test('a syntax error is listed with its line:column and the path before it is drawn', async () => {
    await withPage(async (page) => {
      await typeProgram(page, 'G00 X10. Y10.\nG01 X1.2.3 F100.\n');
      const items = page.locator('#diagnostics li.error');
      assert.equal(await items.count(), 1);
      assert.equal(await items.locator('.loc').textContent(), '2:5');
      assert.equal(await items.locator('.severity').textContent(), 'error');
      assert.equal(await items.locator('.code').textContent(), '[malformed-number]');
      assert.match(await items.locator('.message').textContent(), /1\.2\.3/);
      assert.match(await page.locator('#summary').textContent(), /1 error\b.*stopped at line 2/);
      // Clicking the diagnostic selects the bad word in the editor.
      await items.click();
      const selected = await page.locator('#program').evaluate(
        (el) => el.value.slice(el.selectionStart, el.selectionEnd),
      );
      assert.equal(selected, 'X1.2.3');
      const { counts } = await shootCanvas(page, 'error', (c) => c.actualRapid > 50);
      assert.ok(counts.actualRapid > 50, 'the rapid before the error is drawn');
    });
  });

  test('program text in diagnostics is shown as text, never as markup', async () => {
    await withPage(async (page) => {
      await typeProgram(page, 'G00 X<img src=x onerror=alert(1)>;\n');
      const list = page.locator('#diagnostics');
      assert.ok((await list.locator('li.error').count()) >= 1);
      assert.equal(await list.locator('img').count(), 0);
      assert.match(await list.textContent(), /</);
    });
  });

  test('a bad setup document is a diagnostic, not a crash', async () => {
    await withPage(async (page) => {
      await page.locator('#setup-panel summary').click();
      const setup = page.locator('#setup');
      await setup.fill('{ "offsets": { "01": "six" } }');
      await waitForRun(page);
      const item = page.locator('#diagnostics li.error').first();
      assert.equal(await item.locator('.loc').textContent(), 'setup');
      assert.match(await item.locator('.code').textContent(), /^\[setup-/);
      assert.match(await page.locator('#summary').textContent(), /stopped: bad setup/);
      // Fixing it draws the square again.
      await setup.fill('{ "offsets": { "01": 6.0 } }');
      await waitForRun(page);
      assert.match(await page.locator('#summary').textContent(), /0 errors/);
      await shootCanvas(page, 'setup-fixed', drawn);
    });
  });

  test('draws a lathe program in ZX with its centre line', async () => {
    await withPage(async (page) => {
      await page.locator('#setup-panel summary').click();
      await page.locator('#setup').fill(
        '{ "machine": "lathe", "lathe_offsets": { "08": { "x": 0.4, "z": -0.2 } } }',
      );
      await typeProgram(page, 'G50 X120. Z60.\nG00 S800 M03 T0108;\nX50. Z3.;\nG01 Z-20. F0.2;\nX80. Z-35.;\nG00 X120. Z60. T0100;\nM30;\n');
      assert.match(await page.locator('#summary').textContent(), /0 errors · 0 warnings · lathe, mm/);
      const { counts } = await shootCanvas(page, 'lathe', (c) => c.centreLine > 200 && c.actualFeed > 100);
      assert.ok(counts.centreLine > 200, `centre line pixels: ${counts.centreLine}`);
      assert.ok(counts.actualFeed > 100 && counts.programmedFeed > 50, JSON.stringify(counts));
    });
  });

  test('follows the canvas size and stays drawn on a narrow, low-DPI screen', async () => {
    await withPage(async (page) => {
      const { counts, png } = await shootCanvas(page, 'narrow', drawn);
      const box = await page.locator('#view').boundingBox();
      assert.equal(png.width, Math.round(box.width));
      assert.ok(counts.actualFeed > 150 && counts.programmedFeed > 50, JSON.stringify(counts));
      // Resizing the window re-draws at the new size (the worker reports
      // the size it drew at).
      await page.setViewportSize({ width: 700, height: 900 });
      const wanted = await page.locator('#view').evaluate((el) => {
        const r = el.getBoundingClientRect();
        return `${Math.round(r.width)}x${Math.round(r.height)}@${window.devicePixelRatio}`;
      });
      await page.waitForFunction((w) => document.body.dataset.drawn === w, wanted);
      const resized = await shootCanvas(page, 'resized', drawn);
      assert.ok(resized.png.width > png.width * 1.3, `${resized.png.width} vs ${png.width}`);
    }, { width: 480, height: 900, scale: 1 });
  });
});
