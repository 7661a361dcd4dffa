// Browser end-to-end tests of the offset table and the settings panel
// (issue 4, items 2 and 3): values checked as typed with the reason shown,
// every valid edit re-runs at once, registers the program names come first,
// registers can be added, lathe columns; settings with their explanations,
// kept in step with the raw setup document both ways.

import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import {
  countDifferences, decode, loadExample, shoot, stateText, typeProgram, useBrowser, waitForRun,
  waitForView,
} from './harness.mjs';

const { withPage } = useBrowser();

const field = (page, register, name) =>
  page.locator(`#offsets input[data-field="${register}.${name}"]`);
const reasonOf = (page, register, name) =>
  page.locator(`#reason-${register}-${name}`);
const setupJson = (page) => page.evaluate(() => window.offsetlab.setup());

describe('offset table', () => {
  test('lists the program’s registers first, checks values as typed and re-runs on every valid edit', async () => {
    await withPage(async (page) => {
      assert.equal(await page.locator('#offsets-units').textContent(), '(mm)');
      const first = page.locator('#offsets tbody tr').first();
      assert.match(await first.locator('th').textContent(), /^01 in program$/);
      // The YASNAC profile's memory A: one value per number.
      assert.deepEqual(await page.locator('#offsets thead th').allTextContents(), ['Register', 'value']);
      assert.equal(await field(page, 1, 'value').inputValue(), '6');
      // Memory B: a geometry and a wear per number, their sum read.
      await page.locator('#set-offset_memory').selectOption('B');
      await waitForRun(page);
      assert.deepEqual(await page.locator('#offsets thead th').allTextContents(), ['Register', 'geometry', 'wear', 'sum']);
      assert.equal(await field(page, 1, 'geometry').inputValue(), '6');
      assert.equal(await first.locator('td.sum').textContent(), '6.000');
      const before = decode(await page.locator('#view').screenshot());

      const geometry = field(page, 1, 'geometry');
      const cases = [
        ['abc', /not a number/],
        ['1000', /out of range: at most ±999\.999 mm/],
        ['6.0001', /at most 3 decimals \(0\.001 mm\)/],
        ['', /empty/],
      ];
      for (const [text, reason] of cases) {
        await geometry.fill(text);
        assert.match(await reasonOf(page, 1, 'geometry').textContent(), reason, text);
        assert.equal(await geometry.getAttribute('aria-invalid'), 'true');
      }
      assert.equal((await setupJson(page)).offsets['01'], 6, 'an invalid value never reaches the setup');
      assert.equal((await setupJson(page)).settings.offset_memory, 'B');

      // A valid value: the reason goes, the sum follows, the program re-runs.
      await geometry.fill('10');
      assert.equal(await reasonOf(page, 1, 'geometry').textContent(), '');
      assert.equal(await geometry.getAttribute('aria-invalid'), null);
      await field(page, 1, 'wear').fill('-0.5');
      assert.equal(await first.locator('td.sum').textContent(), '9.500');
      await waitForRun(page);
      assert.deepEqual((await setupJson(page)).offsets['01'], { geometry: 10, wear: -0.5 });
      await page.locator('#step-next').click();
      await page.locator('#step-next').click();
      await page.locator('#step-next').click();
      await waitForView(page, (v) => v.step === 2);
      assert.equal(await stateText(page, 'position'), 'D01 = 9.500');
      assert.equal(await stateText(page, 'actual'), 'X89.500 Y-9.500 Z0.000 mm');
      const after = decode(await page.locator('#view').screenshot());
      assert.ok(countDifferences(before, after) > 500, 'the drawing changed');
      // The raw document follows the table.
      await page.locator('#advanced summary').click();
      assert.match(await page.locator('#setup').inputValue(), /"wear": -0\.5/);
    });
  });

  test('a register can be added; bad register numbers are refused with a reason', async () => {
    await withPage(async (page) => {
      const input = page.locator('#new-register');
      await input.fill('abc');
      await page.locator('#add-register button').click();
      assert.match(await page.locator('#new-register-reason').textContent(), /register number/);
      await input.fill('150');
      await input.press('Enter');
      assert.match(await page.locator('#new-register-reason').textContent(), /01 to 99/);
      await input.fill('5');
      await input.press('Enter');
      assert.equal(await page.locator('#offsets tbody tr').count(), 2);
      // The new row gets the focus; a value typed there is a new register.
      assert.equal(await page.evaluate(() => document.activeElement.dataset.field), '5.value');
      await page.keyboard.press('ControlOrMeta+A');
      await page.keyboard.type('2.5');
      await waitForRun(page);
      assert.equal((await setupJson(page)).offsets['05'], 2.5);
      // Used by the program: D05 makes it a register "in program".
      await page.locator('.cm-line', { hasText: 'G47 Y50.;' }).click();
      await page.keyboard.press('End');
      await page.keyboard.type(' D05');
      await waitForRun(page);
      const rows = await page.locator('#offsets tbody th').allTextContents();
      assert.deepEqual(rows, ['01 in program', '05 in program']);
    });
  });

  test('a lathe setup has X and Z columns with wear, the nose radius R with wear and the tip T', async () => {
    await withPage(async (page) => {
      await loadExample(page, 'lathe-taper');
      assert.match(await page.locator('#offsets-units').textContent(), /mm, X as a diameter/);
      const head = await page.locator('#offsets thead th').allTextContents();
      assert.deepEqual(head, ['Register', '', 'X', 'Z', 'R', 'T']);
      assert.deepEqual(
        await page.locator('#offsets tbody th').allTextContents(),
        ['01 in program', '02 in program', '12 in program'],
      );
      assert.equal(await field(page, 12, 'x_wear').inputValue(), '0.1');
      await field(page, 2, 'z').fill('0.25');
      await waitForRun(page);
      assert.deepEqual((await setupJson(page)).lathe_offsets['02'], { x: -0.3, z: 0.25 });
    });
  });
});

describe('settings', () => {
  test('every setting says what it changes, and the form changes the run', async () => {
    await withPage(async (page) => {
      const settings = page.locator('#settings-form .setting:visible');
      const count = await settings.count();
      assert.ok(count >= 7, `${count} settings shown`);
      for (let i = 0; i < count; i += 1) {
        const help = settings.nth(i).locator('.help');
        assert.equal(await help.count(), 1, `setting ${i} has one explanation`);
        assert.ok((await help.textContent()).length > 15);
      }
      // Mirror X: the square turns to negative X.
      await page.getByLabel('Mirror X').check();
      await waitForRun(page);
      assert.deepEqual((await setupJson(page)).settings.mirror, ['x']);
      assert.match(await page.locator('#summary').textContent(), /0 errors/);
      await page.locator('#step-last').click();
      await waitForView(page, (v) => v.step === 7);
      assert.match(await stateText(page, 'actual'), /^X30\.000 Y-20\.000/);
      // Start position.
      await page.getByLabel('Start position X').fill('5');
      await waitForRun(page);
      assert.deepEqual((await setupJson(page)).start, { x: 5, y: 0, z: 0 });
      await page.getByLabel('Start position Y').fill('1e5');
      assert.match(await page.locator('[data-setting="start"] .reason').textContent(), /not a number/);
      // Work offsets fold out; G55 takes a value.
      await page.locator('.works summary').click();
      await page.getByLabel('Work offset G55 X').fill('-250');
      await waitForRun(page);
      assert.deepEqual((await setupJson(page)).work_offsets, { G55: { x: -250, y: 0, z: 0 } });
      // Block skip, decimal input, G43 without Z.
      await page.getByLabel('Block skip').check();
      await page.getByLabel('Decimal input').selectOption('calculator');
      await page.getByLabel('G43 H without Z').selectOption('next_z');
      await waitForRun(page);
      assert.deepEqual((await setupJson(page)).settings, {
        mirror: ['x'], block_skip: true, decimal_input: 'calculator', length_offset_without_z: 'next_z',
      });
      // Machine: lathe shows the lathe setting and the ZX plane.
      assert.equal(await page.getByLabel('Lathe X offsets').isVisible(), false);
      await page.getByLabel('Machine').selectOption('lathe');
      await waitForRun(page);
      assert.equal(await page.getByLabel('Lathe X offsets').isVisible(), true);
      assert.equal(await page.getByLabel('Mirror X').isVisible(), false);
      // The lathe's summary names the G-code system it reads the program in (7.18).
      await page.waitForFunction(() => /lathe \(G-code system A\), mm/.test(document.querySelector('#summary').textContent));
      await page.getByLabel('G-code system', { exact: true }).selectOption('B');
      await page.waitForFunction(() => /lathe \(G-code system B\), mm/.test(document.querySelector('#summary').textContent));
      await page.getByLabel('G-code system', { exact: true }).selectOption('A');
      await waitForRun(page);
      assert.equal((await setupJson(page)).settings.mirror, undefined, 'mirror is for the mill only');
      await waitForView(page, (v) => v.plane === 'ZX');
      await page.getByLabel('Units').selectOption('inch');
      await waitForRun(page);
      assert.match(await page.locator('#offsets-units').textContent(), /^\(in/);
    });
  });

  test('the control profile gives the defaults of the settings left “as the control”', async () => {
    await withPage(async (page) => {
      // Behaviour 1.11, 7.17, 12: two codes of group 01 in a block.
      await typeProgram(page, 'G00 G01 X10. F100.');
      const codes = () => page.locator('#diagnostics .code').allTextContents();
      assert.match((await codes()).join(' '), /modal-conflict/);
      assert.match(await page.locator('#summary').textContent(), /1 errors?/);
      const help = await page.locator('[data-setting="same_group_codes"] .help').textContent();
      assert.match(help, /YASNAC/);
      assert.match(help, /Fanuc and Haas/);
      assert.equal(await page.getByLabel('Two G codes of a group').inputValue(), '');
      await page.getByLabel('Control').selectOption('fanuc');
      await waitForRun(page);
      assert.deepEqual((await setupJson(page)).settings, { control: 'fanuc' });
      assert.match(await page.locator('#summary').textContent(), /0 errors · 1 warning/);
      await shoot(page, 'settings-control-fanuc');
      // A setting set wins over the profile; "as the control" leaves it out again.
      await page.getByLabel('Two G codes of a group').selectOption('error');
      await waitForRun(page);
      assert.deepEqual((await setupJson(page)).settings, { control: 'fanuc', same_group_codes: 'error' });
      assert.match(await page.locator('#summary').textContent(), /1 errors?/);
      await page.getByLabel('Two G codes of a group').selectOption('');
      await waitForRun(page);
      assert.deepEqual((await setupJson(page)).settings, { control: 'fanuc' });
      // The lathe's G-code system: B makes G90/G91 the distance codes.
      assert.equal(await page.getByLabel('G-code system').isVisible(), false);
      await page.getByLabel('Machine').selectOption('lathe');
      await page.getByLabel('G-code system', { exact: true }).selectOption('B');
      await typeProgram(page, 'G92 X100. Z50.\nG00 G91 X-20. W-5.');
      assert.match(await page.locator('#summary').textContent(), /0 errors/);
      await page.locator('#step-last').click();
      await waitForView(page, (v) => v.step === 1);
      assert.match(await stateText(page, 'modal'), /G91/);
      assert.match(await stateText(page, 'actual'), /^X80\.000 Z45\.000/);
    });
  });

  test('the raw setup document and the form stay in step both ways', async () => {
    await withPage(async (page) => {
      await page.locator('#advanced summary').click();
      const json = page.locator('#setup');
      assert.deepEqual(JSON.parse(await json.inputValue()), { machine: 'mill', offsets: { '01': 6 } });
      await json.fill('{ "machine": "mill", "offsets": { "01": 3, "07": 1.5 }, "settings": { "mirror": ["y"] } }');
      await waitForRun(page);
      assert.equal(await field(page, 1, 'value').inputValue(), '3');
      assert.equal(await field(page, 7, 'value').inputValue(), '1.5');
      assert.equal(await page.getByLabel('Mirror Y').isChecked(), true);
      // Not JSON: the reason is shown, the run reports the setup error, the form keeps its values.
      await json.fill('{ "offsets": ');
      await waitForRun(page);
      assert.match(await page.locator('#setup-reason').textContent(), /Not valid JSON/);
      assert.match(await page.locator('#diagnostics .code').first().textContent(), /setup-syntax/);
      assert.equal(await field(page, 1, 'value').inputValue(), '3');
      // The form wins again: a form edit rewrites the document.
      await field(page, 1, 'value').fill('4');
      await waitForRun(page);
      assert.match(await page.locator('#summary').textContent(), /0 errors/);
      assert.equal(JSON.parse(await json.inputValue()).offsets['01'], 4);
    });
  });
});
