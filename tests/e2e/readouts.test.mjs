// Browser end-to-end test of issue 23's readouts (behaviour 6.12, 6.13,
// 7.53, 10.13, 13.16): a user lists tool 1 as a 10 mm cutter in the
// Settings panel's Tools, sees it drawn at its size round the tool marker,
// steps and reads each block's distance to go in the state panel; the
// Settings panel says where the tool starts and where G28 goes. Screenshots:
// tool-at-size.png, distance-to-go.png, positions-in-effect.png.

import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import {
  bbox, COLORS, MARKS, shoot, shootCanvas, stateText, typeProgram, useBrowser, waitForRun, waitForView,
} from './harness.mjs';

const { withPage } = useBrowser();

// Tool 1, a rapid from the work zero to X20 Y10, then feeds round to X0
// Y20: at the rapid's end the tool stands in the middle of the drawing, the
// rapid 20 mm wide beside it.
const PROGRAM = 'T1 M06\nG90 G00 X20. Y10.\nG01 X40. F200.\nY20.\nX0.\nM30\n';

const step = (page, n) => waitForView(page, (v, a) => v.step === a, n);

describe('readouts', () => {
  test('a listed tool is drawn at its size, and each block shows its distance to go', async () => {
    await withPage(async (page) => {
      await typeProgram(page, PROGRAM);
      // The legend folded away: its tool symbol would widen the marker's box.
      await page.locator('#legend').uncheck();
      await page.locator('#step-slider').fill('1');
      await step(page, 1);
      const before = await shootCanvas(page, 'tool-dot', (_, p) => bbox(p, MARKS.tool) !== null);
      const dot = bbox(before.png, MARKS.tool);

      // The user lists tool 1: Add tool 1, diameter 10.
      await page.locator('#new-tool').fill('1');
      await page.locator('#add-tool button').click();
      await page.getByLabel('Tool 01 diameter').fill('10');
      await waitForRun(page);
      assert.deepEqual((await page.evaluate(() => window.offsetlab.setup())).tools, { '01': { diameter: 10 } });
      const atSize = (_, p) => (bbox(p, MARKS.tool)?.w ?? 0) > dot.w * 2;
      const { png } = await shootCanvas(page, 'tool-at-size', atSize);
      const tool = bbox(png, MARKS.tool);
      // The rapid spans X0 to X20: 20 mm. The circle spans the diameter,
      // 10 mm: half the rapid's width (give or take the line widths).
      const rapid = bbox(png, COLORS.actualRapid);
      const ratio = tool.w / rapid.w;
      assert.ok(ratio > 0.45 && ratio < 0.56, `tool ${tool.w} px of rapid ${rapid.w} px: ${ratio}`);
      // Centred on the marker at the rapid's end, X20 Y10 (the fit now
      // leaves room for the tool, 10.17, so the view is not the one of the
      // dot drawn alone before): the circle is 10 mm across, so a mm is
      // tool.w / 10 px, and X20 Y10 is 20 mm right of and 10 mm above the
      // rapid's start at the work zero.
      const mm = tool.w / 10;
      const centre = (b) => [(b.x0 + b.x1) / 2, (b.y0 + b.y1) / 2];
      const [cx, cy] = centre(tool);
      const [ex, ey] = [rapid.x0 + 20 * mm, rapid.y1 - 10 * mm];
      assert.ok(Math.hypot(cx - ex, cy - ey) < 5, `${JSON.stringify(tool)} vs (${ex}, ${ey})`);
      // The state panel names the tool's size from the list.
      // No length listed: the drawing leaves the tool open at the top, and says so (10.16).
      assert.equal(await stateText(page, 'tool'), 'T01 · diameter 10.000 · no length: drawn open at the top');
      await page.locator('#tools-panel').scrollIntoViewIfNeeded();
      await shoot(page, 'tool-at-size');

      // Distance to go: the page shows each block as it starts — its whole
      // motion. Line 2 from the work zero to X20 Y10; line 3 from there to X40.
      assert.equal(await stateText(page, 'to-go'), 'X+20.000 Y+10.000 Z0.000 mm');
      await page.locator('#step-next').click();
      await step(page, 2);
      assert.equal(await stateText(page, 'to-go'), 'X+20.000 Y0.000 Z0.000 mm');
      await page.locator('#step-next').click();
      await step(page, 3);
      assert.equal(await stateText(page, 'to-go'), 'X0.000 Y+10.000 Z0.000 mm');
      await page.locator('#step-last').click();
      await step(page, 5);
      // M30 moves nothing.
      assert.equal(await stateText(page, 'to-go'), 'X0.000 Y0.000 Z0.000 mm');
      await page.locator('#step-slider').fill('4');
      await step(page, 4);
      assert.equal(await stateText(page, 'to-go'), 'X-40.000 Y0.000 Z0.000 mm');
      await page.locator('#state-panel').scrollIntoViewIfNeeded();
      await shoot(page, 'distance-to-go');
    });
  });

  test('an empty D register is not filled in from the tool list: the panel says so', async () => {
    // A plain link with tool 1 of 10 mm and no register (9.9): D01 is empty.
    const text = 'T1 M06\nG90 G00 X0 Y0\nG41 G01 X20. D01 F100.\nY20.\n';
    await withPage(async (page) => {
      await page.locator('#step-slider').fill('3');
      await step(page, 3);
      assert.deepEqual((await page.evaluate(() => window.offsetlab.setup())).tools, { '01': { diameter: 10 } });
      assert.match(await stateText(page, 'tool'), /^T01 · diameter 10\.000 · no length: drawn open at the top — D01 holds 0: compensation reads the register/);
      // The actual path is the programmed one: no offset came from the list.
      assert.equal(await stateText(page, 'actual'), await stateText(page, 'programmed'));
    }, { hash: `#program=${encodeURIComponent(text)}&tool=1:D10` });
  });

  test('the Settings panel shows the start and reference positions in effect', async () => {
    await withPage(async (page) => {
      await typeProgram(page, 'G00 X10.\n');
      const line = page.locator('#positions-effect');
      // YASNAC: the start at the work zero, the reference above it (13.15).
      assert.match(await line.textContent(), /^In effect: start X0\.000 Y0\.000 Z0\.000 \(G54\), reference X0\.000 Y0\.000 Z508\.000 \(machine\) mm — a field at 0 0 0 is the start at the work zero, the reference a typical machine’s, above the work\.$/);
      // Fanuc: a typical machine's, Z508 (13.15).
      await page.getByLabel('Control').selectOption('fanuc');
      await waitForRun(page);
      assert.match(await line.textContent(), /start X0\.000 Y0\.000 Z508\.000 \(G54\), reference X0\.000 Y0\.000 Z508\.000 \(machine\) mm — a field at 0 0 0 is a typical machine’s, homed at the positive end of its travel\.$/);
      // It sits under the Reference position fields.
      assert.equal(await line.evaluate((p) => p.previousElementSibling?.dataset.setting), 'reference');
      // The lathe: the turret's home X406.4 Z355.6, X and Z only.
      await page.locator('#set-machine').selectOption('lathe');
      await waitForRun(page);
      assert.match(await line.textContent(), /start X406\.400 Z355\.600 \(G54\), reference X406\.400 Z355\.600 \(machine\)/);
      await line.scrollIntoViewIfNeeded();
      await shoot(page, 'positions-in-effect');
    });
  });
});
