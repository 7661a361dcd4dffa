// Browser end-to-end test of stepping into a G65 macro (issue 22, behaviour
// 21.1, 21.6): a bolt circle of two holes, one G65 each. Stepping onto the
// call shows its sentence (the arguments and their locals); stepping into
// the macro shows the program and the call stack with the macro's level,
// and the hole at its hand-computed place. Screenshot: macrocall.png.

import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { shoot, stateText, typeProgram, useBrowser, waitForView } from './harness.mjs';

const { withPage } = useBrowser();

const PROGRAM = [
  'O1000',
  'N10 G90 G21 G00 X0 Y0',
  'N20 G65 P9010 X10. Y5. R20. A45.',
  'N30 G65 P9010 X10. Y5. R20. A135.',
  'N40 M30',
  '%',
  'O9010',
  'N1 G00 X[#24+#18*COS[#1]] Y[#25+#18*SIN[#1]]',
  'N2 M99',
  '%',
].join('\n');

async function stepTo(page, n) {
  for (let i = 0; i <= n; i += 1) await page.locator('#step-next').click();
  await waitForView(page, (v, a) => v.step === a, n);
}

describe('macro calls', () => {
  test('stepping enters the G65 macro and the state panel names it, its level and its locals', async () => {
    await withPage(async (page) => {
      await typeProgram(page, PROGRAM);
      // O1000, N10, N20; O9010, N1, N2; N30; O9010, N1, N2; N40.
      // The run finishes after the typing: wait for its last report.
      await page.waitForFunction(() => /all 11 blocks/.test(document.querySelector('#step-position').textContent));
      assert.match(await page.locator('#step-position').textContent(), /all 11 blocks/);
      await stepTo(page, 2);
      assert.equal(await stateText(page, 'block'), 'line 3: N20 G65 P9010 X10. Y5. R20. A45.');
      assert.equal(await page.locator('#state-panel .explanation').textContent(),
        'G65 P9010: calls O9010 with X=#24=10.000, Y=#25=5.000, R=#18=20.000, A=#1=45.000; G65: local variable level 1; it returns to line 4.');
      // Block 4: N1 of the macro, at X 10 + 20 cos 45° = 24.142,
      // Y 5 + 20 sin 45° = 19.142.
      for (let i = 0; i < 2; i += 1) await page.locator('#step-next').click();
      await waitForView(page, (v, a) => v.step === a, 4);
      assert.equal(await stateText(page, 'block'), 'line 8: N1 G00 X[#24+#18*COS[#1]] Y[#25+#18*SIN[#1]]');
      assert.equal(await stateText(page, 'program'), 'O9010 · O1000 N20 (G65, level 1) → O9010');
      assert.equal(await stateText(page, 'programmed'), 'X24.142 Y19.142 Z0.000 mm');
      await shoot(page, 'macrocall');
    });
  });
});
