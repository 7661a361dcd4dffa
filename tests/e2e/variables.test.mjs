// Browser end-to-end test of the Variables panel (issue 22, behaviour 10.10
// and 21.12): a bolt circle drilled by a WHILE loop is pasted, stepped
// through pass by pass, and the panel shows each variable's value after
// the block and the line that set it; stepping enters an M98 subprogram
// and the state panel names the call stack; a loop that never ends stops
// at the block limit at its WHILE, and the page stays usable. Screenshots:
// variables-panel.png, variables-subprogram.png, variables-runaway.png.

import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { shoot, stateText, useBrowser, waitForRun, waitForView } from './harness.mjs';

const { withPage } = useBrowser();

const PROGRAM = [
  'O1000 (BOLT CIRCLE BY WHILE)', // 1
  'G90 G21 G17 G00 Z10.', // 2
  '#101 = 40. (RADIUS)', // 3
  '#102 = 4 (HOLES)', // 4
  '#1 = 0', // 5
  'WHILE [#1 LT #102] DO1', // 6
  '#2 = #1 * 360 / #102', // 7
  'G81 X[#101*COS[#2]] Y[#101*SIN[#2]] Z-5. R2. F100', // 8
  '#1 = #1 + 1', // 9
  'END1', // 10
  'G80 G00 Z[#104+10.]', // 11
  'M98 P1002', // 12
  'M30', // 13
  'O1002', // 14
  'G00 X0 Y0', // 15
  '#103 = #101 / 2', // 16
  'M99', // 17
].join('\n');

/** Pastes `text` into the editor, as a user pastes a program. */
async function paste(page, text) {
  await page.locator('.cm-content').click();
  await page.keyboard.press('ControlOrMeta+A');
  await page.keyboard.insertText(text);
  await waitForRun(page);
}

/** Steps to block `n` with the slider, as a user drags it. */
async function stepTo(page, n) {
  await page.locator('#step-slider').evaluate((el, v) => {
    el.value = String(v);
    el.dispatchEvent(new Event('input', { bubbles: true }));
  }, n);
  await waitForView(page, (v, a) => v.step === a, n);
  await page.waitForFunction((k) => document.getElementById('variables-panel').dataset.block === String(k), n);
}

/** The panel's rows as text: headings alone, variables as "name value set". */
async function rows(page) {
  return page.locator('#variables tbody tr').evaluateAll((trs) => trs.map((tr) => (
    tr.classList.contains('group')
      ? `— ${tr.textContent}`
      : [...tr.cells].map((c) => c.textContent).join(' | ') + (tr.classList.contains('changed') ? ' *' : '')
  )));
}

describe('variables panel', () => {
  test('stepping a WHILE bolt circle shows each variable after the block and the line that set it', async () => {
    await withPage(async (page) => {
      // A program without `#`: no panel.
      assert.equal(await page.locator('#variables-panel').isVisible(), false);
      await paste(page, PROGRAM);
      // O1000, G90, #101, #102, #1 (5); WHILE, #2, G81, #1, END four times
      // (20); the WHILE that finds [4 LT 4] false, G80, M98 (3); O1002, G00,
      // #103, M99 (4); M30 (1): 33 blocks.
      await page.locator('#summary', { hasText: /^33 blocks/ }).waitFor({ timeout: 10_000 });
      // Block 11: the second pass's #2 = 1 * 360 / 4 = 90 (line 7); #1 = 1
      // since the first pass's line 9; #101 = 40 (line 3), #102 = 4 (line 4).
      await stepTo(page, 11);
      assert.equal(await stateText(page, 'block'), 'line 7: #2 = #1 * 360 / #102');
      assert.equal(await page.locator('#variables-panel').isVisible(), true);
      assert.deepEqual(await rows(page), [
        '— Locals (main program, level 0)',
        '#1 | 1.000 | set at line 9',
        '#2 | 90.000 | set at line 7 *',
        '— Common #100–#199',
        '#101 | 40.000 | set at line 3',
        '#102 | 4.000 | set at line 4',
      ]);
      assert.equal(await page.locator('#variables tr[data-variable="2"]').getAttribute('title'),
        '#2 = 90.000, set at line 7');
      // Block 12, the hole it makes: X = 40 cos 90 = 0, Y = 40 sin 90 = 40.
      await page.locator('#step-next').click();
      await waitForView(page, (v) => v.step === 12);
      assert.equal(await stateText(page, 'programmed'), 'X0.000 Y40.000 Z10.000 mm');
      await page.locator('#variables-panel').scrollIntoViewIfNeeded();
      await shoot(page, 'variables-panel');

      // Block 26: G80 read #104, never set: vacant (10 + vacant = 10).
      await stepTo(page, 26);
      assert.equal(await stateText(page, 'block'), 'line 11: G80 G00 Z[#104+10.]');
      assert.deepEqual((await rows(page)).slice(-1), ['#104 | vacant | read, never set']);
      assert.equal(await page.locator('#variables tr[data-variable="104"]').getAttribute('class'), 'vacant');
    });
  });

  test('stepping enters the M98 subprogram: the call stack and its variable', async () => {
    await withPage(async (page) => {
      await paste(page, PROGRAM);
      await page.locator('#summary', { hasText: /^33 blocks/ }).waitFor({ timeout: 10_000 });
      // Block 30: #103 = #101 / 2 = 20 in O1002, called from line 12.
      await stepTo(page, 30);
      assert.equal(await stateText(page, 'block'), 'line 16: #103 = #101 / 2');
      assert.equal(await stateText(page, 'program'), 'O1002 · O1000 line 12 → O1002');
      // M98 opens no level: the main program's locals after the loop,
      // #1 = 4 and #2 = 3 * 90 = 270.
      assert.deepEqual(await rows(page), [
        '— Locals (main program, level 0)',
        '#1 | 4.000 | set at line 9',
        '#2 | 270.000 | set at line 7',
        '— Common #100–#199',
        '#101 | 40.000 | set at line 3',
        '#102 | 4.000 | set at line 4',
        '#103 | 20.000 | set at line 16 *',
        '#104 | vacant | read, never set',
      ]);
      await page.locator('#variables-panel').scrollIntoViewIfNeeded();
      await shoot(page, 'variables-subprogram');

      // The editor marks the macro syntax: keywords, functions, variables,
      // brackets; a `/` inside an expression divides, at a block's start it
      // is the block skip; `:1002` is a program header.
      await paste(page, '/G00 X1.\n#1 = ATAN[4]/[2] (ANGLE)\nIF [#1 GT 60] GOTO 10\n:1002\nN10 M99\n');
      const tokens = (cls) => page.locator(`.cm-content .${cls}`).allTextContents();
      assert.deepEqual(await tokens('tok-skip'), ['/']);
      assert.deepEqual(await tokens('tok-operator'), ['=', '/']);
      assert.deepEqual(await tokens('tok-macro'), ['ATAN', 'IF', 'GT', 'GOTO']);
      assert.deepEqual(await tokens('tok-variable'), ['#1', '#1']);
      assert.deepEqual(await tokens('tok-bracket'), ['[', ']', '[', ']', '[', ']']);
      assert.ok((await tokens('tok-program')).includes(':1002'));
      assert.deepEqual(await tokens('tok-invalid'), []);
      // A chamfer's or a corner R's comma word is one word, not an operator.
      await paste(page, 'G01 X50. ,R10.\nY0 ,C2.\n');
      assert.deepEqual(await tokens('tok-param'), [',R10.', ',C2.']);
      assert.deepEqual(await tokens('tok-operator'), []);
    });
  });

  test('a WHILE that never ends stops at the block limit at its line; the page stays usable', async () => {
    await withPage(async (page) => {
      const runaway = 'O1000\n#1 = 0\nWHILE [1 EQ 1] DO1\n#1 = #1 + 1\nEND1\nM30\n';
      await paste(page, runaway);
      // O1000 and #1 = 0, then 3 blocks a pass: 5,000,000 − 2 = 4,999,998
      // blocks of the loop, 1,666,666 passes.
      const error = page.locator('#diagnostics li').first();
      assert.match(await error.textContent(),
        /WHILE at line 3 ran 4,999,998 blocks without ending \(1,666,666 passes\)/);
      assert.match(await page.locator('#summary').textContent(), /5000000 blocks|5,000,000 blocks/);
      // The page stays usable: the last block is the last pass's END, and
      // #1 counted the passes.
      await page.locator('#step-last').click();
      await waitForView(page, (v) => v.step === 4_999_999, null, { timeout: 30_000 });
      await page.waitForFunction(() => document.getElementById('variables-panel').dataset.block === '4999999');
      assert.equal(await stateText(page, 'block'), 'line 5: END1');
      assert.deepEqual(await rows(page), ['— Locals (main program, level 0)', '#1 | 1666666.000 | set at line 4']);
      await page.locator('#variables-panel').scrollIntoViewIfNeeded();
      await shoot(page, 'variables-runaway');
      // An edit that ends the loop runs again: 2 + 3 passes × 3 + 1 + M30.
      await paste(page, 'O1000\n#1 = 0\nWHILE [#1 LT 3] DO1\n#1 = #1 + 1\nEND1\nM30\n');
      assert.match(await page.locator('#step-position').textContent(), /of 13 · line 6/);
      assert.equal(await page.locator('#banner').isVisible(), false);
    });
  });
});
