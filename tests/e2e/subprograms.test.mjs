// Browser end-to-end test of stepping into a subprogram (issue 22 part 1,
// behaviour 19.7): a program that calls O2000 four times; stepping into the
// call shows the program and the call stack in the state panel, and the
// M98 block's sentence says what it calls. Screenshot: subprogram.png.

import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { shoot, stateText, typeProgram, useBrowser, waitForView } from './harness.mjs';

const { withPage } = useBrowser();

const PROGRAM = [
  'O1000',
  'N10 G90 G00 X0 Y0 Z5.',
  'N20 G01 Z0 F100',
  'N30 M98 P2000 L4',
  'N40 G90 G00 Z5.',
  'N50 M30',
  '%',
  'O2000',
  'N1 G91 G01 Z-1.',
  'N2 X10.',
  'N3 Y10.',
  'N4 X-10.',
  'N5 Y-10.',
  'N6 M99',
  '%',
].join('\n');

async function stepTo(page, n) {
  for (let i = 0; i <= n; i += 1) await page.locator('#step-next').click();
  await waitForView(page, (v, a) => v.step === a, n);
}

describe('subprograms', () => {
  test('stepping enters the subprogram and the state panel names it and the call stack', async () => {
    await withPage(async (page) => {
      await typeProgram(page, PROGRAM);
      // O1000, N10, N20, N30; then O2000 and N1–N6 four times; N40, N50.
      assert.match(await page.locator('#step-position').textContent(), /all 34 blocks/);
      await stepTo(page, 3);
      assert.equal(await stateText(page, 'block'), 'line 4: N30 M98 P2000 L4');
      assert.equal(await page.locator('#state-panel .explanation').textContent(),
        'M98: calls O2000, 4 times; it returns to line 5.');
      assert.equal(await page.locator('#state-panel dd[data-key="program"]').count(), 0);
      // Block 12: N1 of the second pass (blocks 4–10 are the first, 11 its
      // O2000 header), at Z-2.
      for (let i = 0; i < 9; i += 1) await page.locator('#step-next').click();
      await waitForView(page, (v, a) => v.step === a, 12);
      assert.equal(await stateText(page, 'block'), 'line 9: N1 G91 G01 Z-1.');
      assert.equal(await stateText(page, 'program'), 'O2000 · O1000 N30 → O2000');
      assert.equal(await stateText(page, 'programmed'), 'X0.000 Y0.000 Z-2.000 mm');
      await shoot(page, 'subprogram');
    });
  });
});
