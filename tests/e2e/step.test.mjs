// Browser end-to-end tests of stepping through a program (issue 4, items 5
// and 6): buttons, slider, keyboard and play; the tool marker, the path up
// to the current block and the highlighted editor line; a click on a
// segment and the editor cursor select blocks; the state panel shows the
// offsets of the current block. Screenshot: stepped.png.

import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import {
  COLORS, MARKS, centroid, countColor, decode, loadExample, shoot, stateText, useBrowser, waitForView,
} from './harness.mjs';

const { withPage } = useBrowser();

const atStep = (n) => waitForViewStep(n);
function waitForViewStep(n) {
  return (page) => waitForView(page, (v, a) => v.step === a, n);
}

async function currentLineText(page) {
  return page.locator('.cm-line.cm-current-block').textContent();
}

async function canvasPng(page) {
  return decode(await page.locator('#view').screenshot());
}

describe('step-through', () => {
  test('buttons, slider and keys move the current block; the editor line and the state panel follow', async () => {
    await withPage(async (page) => {
      assert.match(await page.locator('#step-position').textContent(), /all 8 blocks/);
      await page.locator('#step-next').click();
      await atStep(0)(page);
      assert.equal(await currentLineText(page), 'G90 G00 X-30. Y-20.;');
      await page.locator('#step-next').click();
      await page.locator('#step-next').click();
      await atStep(2)(page);
      assert.equal(await currentLineText(page), 'G01 G47 X80. F200.;');
      assert.equal(await page.locator('#step-position').textContent(), 'block 3 of 8 · line 4');
      // Item 6: the state panel of block 2 (seed 000's G47 X80. with D01 = 6).
      assert.equal(await stateText(page, 'block'), 'line 4: G01 G47 X80. F200.');
      assert.equal(await stateText(page, 'programmed'), 'X80.000 Y0.000 Z0.000 mm');
      assert.equal(await stateText(page, 'actual'), 'X86.000 Y-6.000 Z0.000 mm');
      // Behaviour 13.1: G54 at machine zero, so the machine position is the actual one.
      assert.equal(await stateText(page, 'machine'), 'X86.000 Y-6.000 Z0.000 mm');
      assert.equal(await stateText(page, 'coordinates'), 'zero at machine X0.000 Y0.000 Z0.000');
      assert.equal(await stateText(page, 'position'), 'D01 = 6.000');
      assert.equal(await stateText(page, 'vector'), 'X+6.000 Y-6.000 Z0.000');
      assert.match(await page.locator('#state-panel dt').allTextContents().then((t) => t.join('|')),
        /Offset distance from the programmed end point/);
      assert.match(await stateText(page, 'modal'), /^G01 G17 G91 G21 G94 G40 G49 G80 G98 G54 G97 G64 G50 G69 G15 G50\.1$/);
      assert.equal(await stateText(page, 'length'), 'G49 · H00 (none) · Z vector 0.000');
      assert.match(await stateText(page, 'feed'), /^F200 · — · T00$/);
      assert.equal(await page.locator('#state-panel .explanation').textContent(),
        'G47 (double extension): X move 80.000 extended by 2 × D01 (6.000) to 92.000.');
      await shoot(page, 'stepped');
      // The tool marker sits at the actual end (86, -6), right of and below
      // the programmed corner ring; the moves after the block are ghosted.
      const png = await canvasPng(page);
      const tool = centroid(png, MARKS.tool);
      assert.ok(tool && tool.n > 40, `tool marker pixels: ${tool?.n}`);
      assert.ok(countColor(png, MARKS.ghost) > 300, 'later moves drawn faint');
      assert.ok(countColor(png, MARKS.arrow) > 20, 'arrows up to the block');
      // Slider, then keys (focus on the page body, not a text field).
      await page.locator('#step-slider').fill('5');
      await atStep(5)(page);
      assert.equal(await currentLineText(page), 'G47 Y-50.;');
      await page.locator('h1').click();
      await page.keyboard.press('Home');
      await atStep(0)(page);
      // Repeated keys count from the block last asked for, not the last drawn.
      for (let i = 0; i < 3; i += 1) await page.keyboard.press('ArrowRight');
      await atStep(3)(page);
      await page.keyboard.press('End');
      await atStep(7)(page);
      await page.keyboard.press('ArrowLeft');
      await atStep(6)(page);
      await page.locator('#step-first').click();
      await atStep(0)(page);
      await page.locator('#step-last').click();
      await atStep(7)(page);
      await page.locator('#step-previous').click();
      await atStep(6)(page);
    }, { scale: 1 });
  });

  test('play advances block by block and pause stops it', async () => {
    await withPage(async (page) => {
      await page.locator('#step-play').click();
      assert.equal(await page.locator('#step-play').getAttribute('aria-pressed'), 'true');
      await waitForView(page, (v) => v.step >= 2);
      await page.locator('#step-play').click();
      assert.equal(await page.locator('#step-play').textContent(), 'Play');
      const stopped = (await waitForView(page, (v) => v.step >= 2)).step;
      await page.waitForTimeout(900);
      assert.equal((await page.evaluate(() => window.offsetlab.viewState())).step, stopped, 'paused');
      // Space toggles play from the keyboard.
      await page.locator('h1').click();
      await page.keyboard.press(' ');
      await page.waitForFunction(() => document.body.dataset.playing === 'true');
      await page.keyboard.press(' ');
      await page.waitForFunction(() => document.body.dataset.playing === 'false');
    });
  });

  test('a click on a segment of the drawing selects its block', async () => {
    await withPage(async (page) => {
      // Find the actual path's top edge (Y56, block 4: G47 X-80.) in the
      // screenshot: the topmost row with many actual-feed pixels.
      const png = await canvasPng(page);
      const rows = new Map();
      const [r, g, b] = COLORS.actualFeed;
      for (let y = 0; y < png.height; y += 1) {
        for (let x = 0; x < png.width; x += 1) {
          const i = (y * png.width + x) * 4;
          // Loose: a 2.25 px line may fall on two rows, each a lighter blue.
          if (Math.hypot(png.data[i] - r, png.data[i + 1] - g, png.data[i + 2] - b) < 90) {
            if (!rows.has(y)) rows.set(y, []);
            rows.get(y).push(x);
          }
        }
      }
      const [top, xs] = [...rows.entries()].filter(([, x]) => x.length > 100).sort((a, c) => a[0] - c[0])[0];
      const middle = xs[Math.floor(xs.length / 2)];
      await page.locator('#view').click({ position: { x: middle, y: top + 1 } });
      await atStep(4)(page);
      assert.equal(await currentLineText(page), 'G47 X-80.;');
      assert.equal(await stateText(page, 'actual'), 'X-6.000 Y56.000 Z0.000 mm');
      // A click far from every segment changes nothing.
      await page.locator('#view').click({ position: { x: middle, y: top + 60 } });
      await page.waitForTimeout(200);
      assert.equal((await page.evaluate(() => window.offsetlab.viewState())).step, 4);
    }, { scale: 1 });
  });

  test('moving the editor cursor selects the block on that line', async () => {
    await withPage(async (page) => {
      await page.locator('.cm-line', { hasText: 'G47 Y50.;' }).click();
      await atStep(3)(page);
      assert.equal(await stateText(page, 'block'), 'line 5: G47 Y50.');
      await page.keyboard.press('ArrowDown');
      await atStep(4)(page);
      await page.keyboard.press('ArrowDown');
      await atStep(5)(page);
      // A comment line before any block selects nothing new.
      await page.keyboard.press('ControlOrMeta+Home');
      await page.waitForTimeout(200);
      assert.equal((await page.evaluate(() => window.offsetlab.viewState())).step, 5);
    });
  });

  test('the state panel shows H with its value and vector, and lathe T offsets', async () => {
    await withPage(async (page) => {
      await loadExample(page, 'length');
      await page.locator('.cm-line', { hasText: 'G43 Z50. H02' }).click();
      await atStep(1)(page);
      assert.equal(await stateText(page, 'length'), 'G43 · H02 = 15.000 · Z vector +15.000');
      assert.equal(await stateText(page, 'actual'), 'X0.000 Y0.000 Z65.000 mm');
      await page.locator('.cm-line', { hasText: /^H03;/ }).click();
      await atStep(8)(page);
      assert.equal(await stateText(page, 'length'), 'G43 · H03 = 25.000 · Z vector +25.000');
      assert.match(await page.locator('#state-panel .explanation').textContent(), /moves by the difference, \+10\.000/);
      await loadExample(page, 'lathe-seed');
      await page.locator('.cm-line', { hasText: 'G00 S800 M03 T0108' }).click();
      await atStep(1)(page);
      assert.equal(await stateText(page, 'lathe'), 'T0108 · tool 01 · offset 08 = X0.400 Z-0.200');
      assert.equal(await stateText(page, 'vector'), 'X+0.400 Z-0.200');
      assert.equal(await stateText(page, 'actual'), 'X120.400 Z59.800 mm');
      assert.equal(await page.locator('#state-panel dd[data-key="position"]').count(), 0);
    });
  });
});
