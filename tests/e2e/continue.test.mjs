// Browser end-to-end test of issue 23's "continue past errors" (behaviour
// 2.24, setting 7.48): a program with an unknown G code mid-way stops there
// by default; the Settings panel's switch draws the rest, the summary line
// counts the skipped block, the diagnostics list it, and the share link
// carries the setting.

import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { COLORS, countColor, decodeLink, shootCanvas, typeProgram, useBrowser, waitForRun } from './harness.mjs';

const { withPage } = useBrowser();

// Worked by hand (as tests/continue.rs): line 4 cannot run; skipped, the
// tool stays at X10 in G01 G91 F100, and lines 5–7 go X15, Y10, X0.
// 7 blocks run, 5 moves: 10 mm rapid, 40 mm feed.
const PROGRAM = 'G90 G00 X0 Y0 Z10.\nG01 X10. F100.\nG91\nG99.9 X5.\nX5.\nY10.\nG90 X0\nM30\n';

describe('continue past errors', () => {
  test('the switch draws the blocks after an unknown code and counts the skip', async () => {
    await withPage(async (page, { context }) => {
      await typeProgram(page, PROGRAM);
      const stopped = await page.locator('#summary').textContent();
      assert.match(stopped, /^3 blocks · 2 moves · 1 error · 0 warnings · mill, mm · stopped at line 4/);
      const before = await shootCanvas(page, 'continue-off', (_, p) => countColor(p, COLORS.actualFeed) > 20);
      const box = page.getByLabel('Continue past errors');
      assert.equal(await box.isChecked(), false, 'off by default');
      assert.match(await page.locator('#continue_past_errors-help').textContent(), /skipped, the state before it kept/);
      await box.check();
      await waitForRun(page);
      const summary = await page.locator('#summary').textContent();
      assert.match(summary, /^7 blocks · 5 moves · 1 error · 1 warning · 1 block skipped · mill, mm · program end at line 8 · path 50\.0 mm \(10\.0 rapid\)/);
      const items = await page.locator('#diagnostics li').allTextContents();
      assert.equal(items.length, 2, items.join('\n'));
      assert.ok(items.some((t) => /G99\.9/.test(t)), items.join('\n'));
      assert.ok(items.some((t) => /did not run/.test(t)), items.join('\n'));
      const after = await shootCanvas(page, 'continue-on', (_, p) => countColor(p, COLORS.actualFeed) > countColor(before.png, COLORS.actualFeed));
      assert.ok(countColor(after.png, COLORS.actualFeed) > countColor(before.png, COLORS.actualFeed), 'more of the path is drawn');
      // The share link carries the setting (behaviour 9).
      await context.grantPermissions(['clipboard-read', 'clipboard-write'], { origin: new URL(page.url()).origin });
      await page.locator('#share-open').click();
      await page.waitForFunction(() => document.body.dataset.copied === 'true');
      const doc = decodeLink(await page.locator('#share-link').inputValue());
      assert.equal(doc.settings.continue_past_errors, true);
    });
  });
});
