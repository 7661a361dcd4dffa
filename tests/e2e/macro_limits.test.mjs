// Browser end-to-end test of issue 32: what a hostile paste does to the
// page's worker. A flat macro chain of 30 000 terms is evaluated (behaviour
// 20.17) and its block's report quotes an excerpt; a macro loop that never
// ends runs to the block limit (8.2) and stops with the sentence that names
// it, its blocks' reports made again from checkpoints (8.15); the page stays
// usable and runs the next edit.

import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { COLORS, countColor, shoot, shootCanvas, typeProgram, useBrowser } from './harness.mjs';

const { withPage } = useBrowser();

/** Replaces the program with `text` in one edit (as a paste). */
async function pasteProgram(page, text) {
  await page.locator('.cm-content').click();
  await page.keyboard.press('ControlOrMeta+A');
  await page.keyboard.insertText(text);
}

/** waitForRun with room for a run of millions of blocks. */
async function waitForLongRun(page, timeout) {
  await page.waitForFunction(() => {
    const { requested, rendered, pending, stopped } = document.body.dataset;
    return stopped !== undefined || (pending === undefined && requested !== undefined && rendered === requested);
  }, null, { timeout });
  await page.waitForFunction(() => document.body.dataset.stateGen === document.body.dataset.rendered
    || document.body.dataset.stopped !== undefined, null, { timeout: 20_000 });
}

describe('no paste kills the page (issue 32)', () => {
  test('a flat chain of 30 000 terms is evaluated and its report quotes an excerpt', async () => {
    await withPage(async (page) => {
      const chain = `1${'+1'.repeat(30_000)}`;
      await pasteProgram(page, `G90 G00 X0 Y0\n#1=${chain}\nG01 X[#1/1000] Y10. F100.\nM30\n`);
      await waitForLongRun(page, 30_000);
      assert.equal(await page.evaluate(() => document.body.dataset.stopped), undefined);
      // X = 30 001 / 1000 = 30.001.
      assert.match(await page.locator('#summary').textContent(), / · 0 errors/);
      await page.locator('#step-first').click();
      await page.locator('#step-next').click();
      await page.waitForFunction(() => /#1 = 30001\.000/.test(document.querySelector('#state-panel .explanation')?.textContent ?? ''));
      const explanation = await page.locator('#state-panel .explanation').textContent();
      assert.ok(explanation.includes('…'), explanation);
      assert.ok(explanation.length < 200, explanation);
      await page.locator('#step-next').click();
      await page.waitForFunction(() => /X30\.001/.test(document.querySelector('#state-panel')?.textContent ?? ''));
      await shoot(page, 'macro-long-chain');
    });
  });

  test('an endless macro loop stops at the block limit with its sentence; the page answers and runs the next edit', async () => {
    await withPage(async (page) => {
      const loop = 'G90 G00 X0 Y0\n#1=0\nWHILE[1EQ1]DO1\n#1=#1+1\nG01 X[#1 MOD 100] Y[#1 MOD 7] F1000.\nEND1\nM30\n';
      await pasteProgram(page, loop);
      await waitForLongRun(page, 60_000);
      assert.equal(await page.evaluate(() => document.body.dataset.stopped), undefined, 'stopped by the block limit, not by the time budget');
      const diagnostics = await page.locator('#diagnostics').textContent();
      assert.match(diagnostics, /too-many-blocks\] WHILE at line 3 ran 4,999,998 blocks without ending \(1,250,000 passes\): the run stops at its block limit \(5,000,000 blocks/);
      assert.match(await page.locator('#summary').textContent(), /^5000000 blocks · \d+ moves · 1 error/);
      // The last block's report, made again from its checkpoint: the pass
      // count says how far the loop went (the 1 250 000th pass sets #1).
      await page.locator('#step-last').click();
      await page.waitForFunction(() => /\d/.test(document.getElementById('step-position')?.textContent ?? ''));
      await shootCanvas(page, 'macro-runaway-loop', (_, p) => countColor(p, COLORS.actualFeed) > 50);
      // Usable: the next edit runs and draws.
      await typeProgram(page, 'G90 G00 X0 Y0\nG01 X40. Y20. F100.\n');
      assert.match(await page.locator('#summary').textContent(), /^2 blocks · \d+ moves? · 0 errors/);
    });
  });
});
