// Browser end-to-end test of issue 23's leftovers (behaviour 10.16–10.19),
// driven as a user would: a tool listed with its diameter and length drawn
// as its outline in the front view (XZ) and in 3D, all of it inside the
// fitted view; Alt+arrow keys on the focused drawing turn it without
// stepping the blocks or leaving the page; the lathe turned in 3D from its
// ZX view, its face view XC refusing to turn. Screenshots:
// tool-silhouette-xz.png, tool-3d.png, lathe-3d.png (and -canvas crops).

import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import {
  drag, MARKS, countDifferences, decode, loadExample, shootCanvas, stateText, useBrowser, waitForView, bbox,
} from './harness.mjs';

const { withPage } = useBrowser();

// Tool 1 rapids to X20 Y10 Z5, plunges to Z-5 and feeds to X60 then Y40,
// and leaves up to Z50: stepped to block 3 (X60.) the tool stands at
// X60 Y10 Z-5.
const PROGRAM = 'T1 M06\nG90 G00 X20. Y10. Z5.\nG01 Z-5. F100.\nX60.\nY40.\nG00 Z50.\nM30\n';

const near = (a, b) => Math.abs(a - b) < 0.01;

describe('the tool in every view, the lathe in 3D, turning by keyboard', () => {
  test('the listed tool is drawn as its outline in XZ and in 3D, inside the fitted view; Alt+arrows turn it', async () => {
    await withPage(async (page) => {
      // The legend folded away: its tool symbol would widen the tool's box.
      await page.locator('#legend').uncheck();
      await page.locator('#plane').selectOption('XZ');
      await page.locator('#step-slider').fill('3');
      await waitForView(page, (v) => v.step === 3 && v.plane === 'XZ');
      // The front view: a rectangle 10 wide and 60 tall (D 10, L 60) from
      // the tool point up: six times as tall as wide, give or take the
      // marker's disc at its foot and the line widths.
      const tall = (_, p) => {
        const b = bbox(p, MARKS.tool);
        return b !== null && b.h > b.w * 4;
      };
      const { png } = await shootCanvas(page, 'tool-silhouette-xz', tall);
      const tool = bbox(png, MARKS.tool);
      const ratio = tool.h / tool.w;
      assert.ok(ratio > 5 && ratio < 6.6, `the tool's outline ${tool.w} × ${tool.h} px: ${ratio}`);
      assert.equal(await stateText(page, 'tool'), 'T01 · diameter 10.000 · length 60.000');
      // All of it inside the drawing at zoom 1 (the fit holds the tool, 10.17).
      assert.ok(tool.x0 > 4 && tool.y0 > 4 && tool.x1 < png.width - 4 && tool.y1 < png.height - 4, JSON.stringify(tool));

      // The 3D view: the cylinder's outline, still taller than wide.
      await page.locator('#plane').selectOption('3D');
      await waitForView(page, (v) => v.plane === '3D');
      const { png: png3d } = await shootCanvas(page, 'tool-3d', (_, p) => {
        const b = bbox(p, MARKS.tool);
        return b !== null && b.h > b.w * 3;
      });
      const tool3d = bbox(png3d, MARKS.tool);
      assert.ok(tool3d.h > tool3d.w * 3, `the cylinder's outline ${tool3d.w} × ${tool3d.h} px`);
      assert.ok(tool3d.x0 > 4 && tool3d.y0 > 4 && tool3d.y1 < png3d.height - 4, JSON.stringify(tool3d));
      assert.ok(countDifferences(png, png3d) > 2000, 'the 3D view is another picture');

      // Alt+arrows on the focused drawing turn it, 5° a press, as a drag
      // of 10 px that way: Alt+→ yaw 45 − 5 = 40, Alt+↓ pitch 35.264 + 5.
      // (The address bar's link follows the view, so the page is compared by its history.)
      const history = await page.evaluate(() => history.length);
      await page.locator('#view').focus();
      await page.keyboard.press('Alt+ArrowRight');
      await waitForView(page, (v) => near(v.angles?.[0], 40));
      await page.keyboard.press('Alt+ArrowDown');
      const v = await waitForView(page, (w) => near(w.angles?.[1], 40.264));
      assert.deepEqual(v.angles, [40, 40.264]);
      await page.keyboard.press('Alt+ArrowLeft');
      await page.keyboard.press('Alt+ArrowLeft');
      const w = await waitForView(page, (x) => near(x.angles?.[0], 50));
      // The arrows did not step the blocks nor leave the page (Alt+← is Back).
      assert.equal(w.step, 3);
      assert.equal(await page.evaluate(() => history.length), history);
      assert.equal(await page.locator('#view').getAttribute('aria-keyshortcuts').then((k) => k.includes('Alt+ArrowLeft')), true);
      // From a plane view Alt+↑ turns into the 3D view: from the top (pitch 90) to 85.
      await page.locator('#plane').selectOption('XY');
      await waitForView(page, (x) => x.plane === 'XY');
      await page.locator('#view').focus();
      await page.keyboard.press('Alt+ArrowUp');
      const top = await waitForView(page, (x) => x.plane === '3D');
      assert.deepEqual(top.angles, [0, 85]);
      // Plain arrows still step the blocks.
      await page.keyboard.press('ArrowLeft');
      await waitForView(page, (x) => x.step === 2);
    }, { hash: `#program=${encodeURIComponent(PROGRAM)}&tool=1:D10,L60` });
  });

  test('the lathe turns in 3D from its ZX view; its face view XC does not turn', async () => {
    await withPage(async (page) => {
      await loadExample(page, 'lathe-taper');
      await waitForView(page, (v) => v.plane === 'ZX');
      const shown = await page.locator('#plane option:not([hidden])').evaluateAll((os) => os.map((o) => o.value));
      assert.deepEqual(shown, ['ZX', 'XC', '3D']);
      assert.equal(await page.locator('#orbit').isVisible(), true, 'the Orbit button on the lathe');
      const flat = decode(await page.locator('#view').screenshot());
      // Shift+drag from ZX (yaw 0, pitch 0): 60 px left is 30° of yaw, 40 px down 20° of pitch.
      await drag(page, [300, 250], [-60, 40], 'Shift');
      const turned = await waitForView(page, (v) => v.plane === '3D' && near(v.angles?.[0], 30));
      assert.deepEqual(turned.angles, [30, 20]);
      await page.waitForTimeout(400);
      const { png } = await shootCanvas(page, 'lathe-3d', (c) => c.actualFeed > 100);
      assert.ok(countDifferences(flat, png) > 2000, 'the lathe in 3D is another picture than ZX');
      // The link carries it (10.9, 10.18).
      const { plain } = await page.evaluate(() => window.offsetlab.document());
      assert.match(plain, /plane=3D&angles=30,20/);
      assert.match(plain, /machine=lathe/);
      // The 3D preset is the isometric view.
      await page.locator('#plane').selectOption('3D');
      const iso = await waitForView(page, (v) => near(v.angles?.[0], 45));
      assert.deepEqual(iso.angles, [45, 35.264]);
      // The face view: the Orbit button off, saying why; Alt+arrows and a
      // Shift+drag do not turn it.
      await page.locator('#plane').selectOption('XC');
      await waitForView(page, (v) => v.plane === 'XC');
      assert.equal(await page.locator('#orbit').isDisabled(), true);
      assert.match(await page.locator('#orbit').getAttribute('title'), /face view XC does not turn/);
      await page.locator('#view').focus();
      await page.keyboard.press('Alt+ArrowRight');
      await drag(page, [300, 250], [-60, 40], 'Shift');
      await page.waitForTimeout(300);
      const face = await waitForView(page, (v) => v.plane === 'XC');
      assert.equal(face.angles, undefined);
      // Back in ZX the Orbit button is on again.
      await page.locator('#plane').selectOption('ZX');
      await waitForView(page, (v) => v.plane === 'ZX');
      assert.equal(await page.locator('#orbit').isDisabled(), false);
    }, { scale: 1 });
  });
});
