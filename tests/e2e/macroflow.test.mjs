// Browser end-to-end test of stepping through a WHILE loop (issue 22 part 1,
// behaviour 20.13): each pass of the loop is a step of its own, and the
// state panel's sentence says what the WHILE and the END did; the editor
// marks the macro keywords, variables and brackets. Screenshot:
// macroflow.png.

import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { shoot, stateText, typeProgram, useBrowser, waitForView } from './harness.mjs';

const { withPage } = useBrowser();

const PROGRAM = [
  'O1000',
  'G90 G21 G00 X0 Y0 Z5.',
  '#1 = 0',
  'WHILE [#1 LT 3] DO1',
  'G01 X[#1*10] F100',
  '#1 = #1 + 1',
  'END1',
  'M30',
].join('\n');

async function stepTo(page, n) {
  for (let i = 0; i <= n; i += 1) await page.locator('#step-next').click();
  await waitForView(page, (v, a) => v.step === a, n);
}

async function next(page, n) {
  await page.locator('#step-next').click();
  await waitForView(page, (v, a) => v.step === a, n);
}

describe('macro loops', () => {
  test('a WHILE loop steps pass by pass and each WHILE and END says what it did', async () => {
    await withPage(async (page) => {
      await typeProgram(page, PROGRAM);
      // O1000, G90, #1 = 0 (3); WHILE, G01, #1, END three times (12); the
      // WHILE that finds [3 LT 3] false and M30 (2): 17 blocks.
      // (The run of the typed text may still be on its way: waited for.)
      await page.locator('#step-position', { hasText: /all 17 blocks/ }).waitFor({ timeout: 10_000 });
      assert.match(await page.locator('#step-position').textContent(), /all 17 blocks/);
      await stepTo(page, 3);
      assert.equal(await stateText(page, 'block'), 'line 4: WHILE [#1 LT 3] DO1');
      assert.equal(await page.locator('#state-panel .explanation').textContent(),
        'WHILE [#1 LT 3] true: DO 1.');
      // Block 6: the first END goes back to the WHILE on line 4.
      for (const n of [4, 5, 6]) await next(page, n);
      assert.equal(await stateText(page, 'block'), 'line 7: END1');
      assert.equal(await page.locator('#state-panel .explanation').textContent(),
        'END 1: back to WHILE at line 4, pass 2.');
      // Block 7 is line 4 again, block 8 the second pass's move: #1 = 1, X10.
      await next(page, 7);
      assert.equal(await stateText(page, 'block'), 'line 4: WHILE [#1 LT 3] DO1');
      assert.equal(await page.locator('#state-panel .explanation').textContent(),
        'WHILE [#1 LT 3] true: DO 1, pass 2.');
      await next(page, 8);
      assert.equal(await stateText(page, 'block'), 'line 5: G01 X[#1*10] F100');
      assert.equal(await stateText(page, 'programmed'), 'X10.000 Y0.000 Z5.000 mm');
      // The editor marks the macro keywords, variables and brackets, and
      // no number of an expression as invalid.
      const tokens = (cls) => page.locator(`.cm-content .${cls}`).allTextContents();
      const macro = await tokens('tok-macro');
      for (const k of ['WHILE', 'LT', 'DO', 'END']) assert.ok(macro.includes(k), k);
      assert.ok((await tokens('tok-variable')).includes('#1'));
      assert.ok((await tokens('tok-bracket')).includes('['));
      assert.deepEqual(await tokens('tok-invalid'), []);
      await shoot(page, 'macroflow');
    });
  });
});
