// Browser end-to-end test of the linuxcnc profile's program text (issue 34,
// behaviour 22): with the LinuxCNC control chosen, `;` comments are
// comments, `X10` is 10 mm, and a (MSG,…) line is a note at its place; the
// Fanuc profile stops at the first `;` comment; a program opened with
// o-words chooses the control (behaviour 22.8). Screenshots: linuxcnc.png,
// linuxcnc-owords.png.

import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { loadExample, shoot, stateText, typeProgram, useBrowser, waitForRun, waitForView } from './harness.mjs';

const { withPage } = useBrowser();

const PROGRAM = [
  '; a LinuxCNC square, numbers without points',
  'G21 G90 G17',
  '(MSG, square of 30 mm)',
  'G0 X0 Y0 Z5 ; above the corner',
  'G1 Z-1 F100',
  'G1 X30',
  'G1 Y30',
  'G3 X0 Y30 R15 ; half circle over the top',
  'G1 Y0',
  'G0 Z5',
  'M2',
].join('\n');

// Steps to the last block and waits for its actual position to read `want`.
async function lastActual(page, want) {
  await page.locator('#step-last').click();
  await page.waitForFunction((source) => new RegExp(source).test(
    document.querySelector('#state-panel dd[data-key="actual"]')?.textContent ?? '',
  ), want.source);
  assert.match(await stateText(page, 'actual'), want);
}

describe('linuxcnc', () => {
  test('the LinuxCNC profile reads ; comments, whole numbers and MSG', async () => {
    await withPage(async (page) => {
      await page.getByLabel('Control').selectOption('linuxcnc');
      await waitForRun(page);
      await typeProgram(page, PROGRAM);
      await page.waitForFunction(() => /0 errors/.test(document.querySelector('#summary').textContent));
      // Blocks: G21 (0), MSG (1), G0 (2), G1 Z-1 (3), G1 X30 (4).
      for (let i = 0; i <= 1; i += 1) await page.locator('#step-next').click();
      await waitForView(page, (v) => v.step === 1);
      assert.match(await page.locator('#state-panel .explanation').textContent(), /\(MSG\) square of 30 mm/);
      for (let i = 0; i < 3; i += 1) await page.locator('#step-next').click();
      await waitForView(page, (v) => v.step === 4);
      assert.match(await stateText(page, 'block'), /G1 X30/);
      assert.match(await page.locator('#state-panel').textContent(), /X30\.000/);
      // The editor shows the `;` comments as comments.
      const comments = await page.locator('.cm-content .tok-comment').allTextContents();
      assert.ok(comments.includes('; above the corner'), JSON.stringify(comments));
      assert.ok(comments.includes('(MSG, square of 30 mm)'), JSON.stringify(comments));
      await page.locator('#step-last').click();
      await shoot(page, 'linuxcnc');
      // Fanuc: `;` ends a block, and the comment after it is no G-code.
      await page.getByLabel('Control').selectOption('fanuc');
      await page.waitForFunction(() => /[1-9]\d* errors?/.test(document.querySelector('#summary').textContent));
    });
  });

  test('a program opened with o-words runs under the LinuxCNC control, said in the banner', async () => {
    await withPage(async (page) => {
      assert.notEqual(await page.getByLabel('Control').inputValue(), 'linuxcnc');
      // Four holes by a while loop and a sub: X 0, 10, 20, 30.
      const program = [
        '(four holes from a LinuxCNC sub)',
        'o<hole> sub',
        '  G0 X#1 Y0 Z2',
        '  G1 Z-1 F100',
        '  G0 Z2',
        'o<hole> endsub',
        'G21 G90',
        '#<k> = 0',
        'o10 while [#<k> LT 4]',
        '  o<hole> call [#<k> * 10]',
        '  #<k> = [#<k> + 1]',
        'o10 endwhile',
        'M2',
        '',
      ].join('\n');
      await page.locator('#open-file').setInputFiles({
        name: 'holes.ngc', mimeType: 'text/plain', buffer: Buffer.from(program),
      });
      await page.waitForFunction(() => document.body.dataset.opened === 'holes.ngc');
      await waitForRun(page);
      assert.equal(await page.getByLabel('Control').inputValue(), 'linuxcnc');
      assert.match(await page.locator('#banner .text').textContent(), /control is set to LinuxCNC 2\.9: its o-word “o<hole> sub”/);
      const summary = await page.locator('#summary').textContent();
      assert.match(summary, /0 errors/);
      assert.match(summary, /12 moves/);
      // The editor reads the o-words and named parameters as LinuxCNC's.
      assert.equal(await page.locator('.cm-content .tok-invalid').count(), 0);
      const variables = await page.locator('.cm-content .tok-variable').allTextContents();
      assert.ok(variables.includes('#<k>'), JSON.stringify(variables));
      await shoot(page, 'linuxcnc-owords');
    });
  });

  test('the LinuxCNC example runs to its end under its own control', async () => {
    await withPage(async (page) => {
      await loadExample(page, 'linuxcnc');
      assert.equal(await page.getByLabel('Control').inputValue(), 'linuxcnc');
      const summary = await page.locator('#summary').textContent();
      assert.match(summary, /0 errors/);
      assert.match(summary, /program end at line 20/);
      await shoot(page, 'linuxcnc-example');
    });
  });

  test('the tool table is edited as a LinuxCNC file; T, G43 read it; an error says its line', async () => {
    await withPage(async (page) => {
      await loadExample(page, 'linuxcnc');
      await page.locator('#tool-table > summary').click();
      const text = page.locator('#tool-table-text');
      // The example's table, written out in the file format.
      await page.waitForFunction(() => /T2 P2 Z42 D5 ;5 mm drill/.test(document.getElementById('tool-table-text')?.value));
      assert.match(await text.inputValue(), /^T1 P1 Z50 D6 ;6 mm end mill$/m);
      // The run ends at G0 Z20 with tool 2's 42: Z 62 on the machine.
      await lastActual(page, /Z62\.000/);
      // Tool 2 shorter by 2 mm: the same block ends at Z 60.
      await text.fill('T1 P1 Z50 D6 ;6 mm end mill\nT2 P2 Z40 D5 ;5 mm drill, reground\n');
      await page.waitForFunction(() => Number(document.getElementById('tool-table')?.dataset.reads) >= 1);
      await waitForRun(page);
      await lastActual(page, /Z60\.000/);
      assert.match(await page.locator('#tool-table-reason').textContent(), /2 tools read/);
      // Tool 2 left out of the table: T2 is refused at its word.
      await text.fill('T1 P1 Z50 D6\n');
      await page.waitForFunction(() => Number(document.getElementById('tool-table')?.dataset.reads) >= 2);
      await waitForRun(page);
      assert.match(await page.locator('#diagnostics').textContent(), /tool-not-in-table[\s\S]*tool 2 is not in the tool table/);
      // A line the format does not read: said at its line and column, the
      // last table read kept.
      await text.fill('T1 P1 Z50 D6\nT2 P2 Zq\n');
      await page.waitForFunction(() => Number(document.getElementById('tool-table')?.dataset.reads) >= 3);
      assert.match(await page.locator('#tool-table-reason').textContent(), /line 2, column 7: Zq: Z needs a number/);
      assert.equal(await text.getAttribute('aria-invalid'), 'true');
      await shoot(page, 'linuxcnc-tool-table');
    });
  });
});
