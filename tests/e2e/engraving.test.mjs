// Browser end-to-end test of Haas G47 text engraving (issue 33 point 2,
// behaviour 14.20): with the Haas profile the page draws the strokes of
// "HAAS" and the state panel says what G47 did; the Fanuc profile reads the
// same G47 as the position offset and stops at P. Screenshot: engraving.png.

import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { shoot, stateText, typeProgram, useBrowser, waitForRun, waitForView } from './harness.mjs';

const { withPage } = useBrowser();

const PROGRAM = [
  'O4700 (ENGRAVE)',
  'G21 G17 G40 G80 G90',
  'G00 X0 Y0 Z5.',
  'G47 P0 (HAAS) X10. Y10. I15. J12. R2. Z-0.3 F300. E100.',
  'G00 Z20.',
  'M30',
].join('\n');

describe('engraving', () => {
  test('the Haas profile engraves the text of G47 P0 and says how', async () => {
    await withPage(async (page) => {
      await page.getByLabel('Control').selectOption('haas');
      await waitForRun(page);
      await typeProgram(page, PROGRAM);
      await page.waitForFunction(() => /0 errors/.test(document.querySelector('#summary').textContent));
      // Blocks: O4700 (0), G21 (1), G00 (2), G47 (3).
      for (let i = 0; i <= 3; i += 1) await page.locator('#step-next').click();
      await waitForView(page, (v) => v.step === 3);
      assert.match(await stateText(page, 'block'), /G47 P0 \(HAAS\)/);
      const said = await page.locator('#state-panel .explanation').textContent();
      assert.match(said, /G47 text engraving \(Haas\): "HAAS" from X10\.000 Y10\.000/);
      assert.match(said, /12\.000 high, at 15° — 8 strokes/);
      await page.locator('#step-last').click();
      await shoot(page, 'engraving');
      // Fanuc: G47 is the double extension, which takes no P.
      await page.getByLabel('Control').selectOption('fanuc');
      await page.waitForFunction(() => /1 error/.test(document.querySelector('#summary').textContent));
    });
  });
});
