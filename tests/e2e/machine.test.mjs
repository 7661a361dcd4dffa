// Browser end-to-end tests of issue 23's "the machine follows the program":
// a lathe program pasted while the mill is chosen gets an offer to switch
// (behaviour 1.24), one click runs it on the lathe, and the examples menu
// stops naming an example once the program is no longer that example.

import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { COLORS, countColor, loadExample, shoot, shootCanvas, typeProgram, useBrowser, waitForRun } from './harness.mjs';

const { withPage } = useBrowser();

const LATHE = `O4001 (A LATHE PROGRAM PASTED ON THE MILL)
G50 S2500
T0101
G00 X40. Z2.
G01 Z-20. F0.2
U10. W-5.
G00 X100. Z100.
M30`;

describe('the machine follows the program', () => {
  test('a lathe program on the mill is offered the lathe, and one click runs it there', async () => {
    await withPage(async (page) => {
      await typeProgram(page, LATHE);
      assert.match(await page.locator('#summary').textContent(), /[1-9]\d* errors?/);
      const banner = page.locator('#banner');
      await banner.waitFor({ state: 'visible' });
      const text = await banner.locator('.text').textContent();
      assert.match(text, /This looks like a lathe program/);
      for (const why of ['T0101', 'U and W', 'G50 S']) assert.ok(text.includes(why), `${why}: ${text}`);
      await shoot(page, 'machine-offer');
      await page.locator('#banner-action').click();
      await waitForRun(page);
      assert.equal(await page.getByLabel('Machine').inputValue(), 'lathe');
      const summary = await page.locator('#summary').textContent();
      assert.match(summary, /0 errors/);
      // Behaviour 6.10's readouts: the path length, the time, the extents.
      // The two feed moves are per revolution (G99) with no S: not timed.
      // Rapids: Ø0 Z0 → Ø40 Z2 (radius 20, Z 2): 20.100; Ø50 Z-25 → Ø100 Z100
      // (25, 125): 127.475; 147.575. Feeds: Z2 → Z-20: 22; U10. W-5.: 7.071.
      // Time: the rapids' longest axes 20 + 125 at 24,000 mm/min = 0.36 s.
      assert.match(summary, / · path 176\.6 mm \(147\.6 rapid\) · ≈ 0\.4 s \+ 2 feed moves without a rate · X0…100 Z-25…100$/);
      assert.ok(await banner.isHidden(), 'the offer is withdrawn on the lathe');
      const { png } = await shootCanvas(page, 'machine-switched-lathe', (_, p) => countColor(p, COLORS.actualFeed) > 50);
      assert.ok(countColor(png, COLORS.actualFeed) > 50, 'the lathe path is drawn');
    });
  });

  test('the examples menu names the example only while it is loaded as it was', async () => {
    await withPage(async (page) => {
      await loadExample(page, 'cutter-contour');
      assert.equal(await page.locator('#example').inputValue(), 'cutter-contour');
      await page.locator('.cm-content').click();
      await page.keyboard.press('ControlOrMeta+End');
      await page.keyboard.type('\n(EDITED)');
      await waitForRun(page);
      assert.equal(await page.locator('#example').inputValue(), '');
      assert.match(await page.locator('#example option:checked').textContent(), /Choose an example/);
      assert.equal(await page.locator('#example-note').textContent(), '');
    });
  });
});
