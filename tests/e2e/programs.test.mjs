// Browser end-to-end tests of real shop programs in the page (issue 20):
// a Fanuc lathe program with G71 roughing and G70 finishing, and a mill
// program with a local zero, a rotation and a polar bolt circle — typed in,
// run under a control profile, stepped to a block whose sentence says what
// the control did, and drawn (screenshots looked at).

import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import {
  COLORS, countColor, shootCanvas, stateText, typeProgram, useBrowser, waitForRun, waitForView,
} from './harness.mjs';

const { withPage } = useBrowser();

const FACE = `O2002 (POLAR INTERPOLATION: A SQUARE ON THE FACE)
T0100
G98 G00 X40. Z2.
G01 Z-1. F100.
G12.1
G01 X20. C-10.
C10.
X-20.
C-10.
X20.
G13.1
G00 Z5.
M30`;

/** Puts the cursor on `line` (1-based): the current block follows it. */
async function cursorOn(page, line) {
  // At the line's start: a click at the middle of a line wider than the
  // editor would scroll it sideways first, which no user does.
  await page.locator('.cm-line').nth(line - 1).click({ position: { x: 2, y: 4 } });
}

const LATHE = `O2001 (G71 ROUGH AND G70 FINISH)
T0101
G50 S2500
G96 S200 M03
G00 X52. Z2. M08
G71 U2. R0.5
G71 P10 Q20 U0.4 W0.1 F0.25
N10 G00 X20.
G01 Z-15. F0.1
X30. Z-25.
Z-40.
X50. Z-50.
N20 X52.
G70 P10 Q20
G00 X100. Z100.
M30`;

const MILL = `O3001 (LOCAL ZERO, ROTATION, BOLT CIRCLE)
G90 G17 G21 G40 G49 G80
G90 G54 G00 X0 Y0
G43 Z50. H01
G52 X40. Y30.
G68 X0 Y0 R30.
G00 X0 Y0
G01 Z-2. F300.
X30. Y0
Y20.
X0
Y0
G69
G00 Z5.
G16
G81 X25. Y0 Z-5. R2. F100.
Y90.
Y180.
Y270.
G80 G15
G52 X0 Y0
G00 Z50.
M30`;

const NOSE = `G10 P10001 X0 Z0 R0.4 Q3
T0101
G00 X40. Z2.
G42 G01 Z0 F0.2
Z-20.
X60. Z-30.
G40 G00 X80. Z5.
M30`;

describe('real programs', () => {
  test('a Fanuc lathe program roughs with G71 and finishes with G70, the T offset on every pass', async () => {
    await withPage(async (page) => {
      await page.getByLabel('Machine').selectOption('lathe');
      await page.getByLabel('Control').selectOption('fanuc');
      await waitForRun(page);
      await typeProgram(page, LATHE);
      await page.locator('#offsets input[data-field="1.x"]').fill('0.2');
      await waitForRun(page);
      assert.match(await page.locator('#summary').textContent(), /0 errors/);
      // The G71 block: eight levels 2 mm apart (radius) from Ø52 to Ø20.4.
      await cursorOn(page, 7);
      await waitForView(page, (v) => v.step === 6);
      assert.match(await page.locator('#state-panel .explanation').textContent(), /G71 type I: 8 cuts at 8 levels/);
      assert.match(await stateText(page, 'modal'), /G01|G00/);
      // A contour block the cycle cut: not run on its own, said so.
      await cursorOn(page, 10);
      await waitForView(page, (v) => v.step === 9);
      assert.match(await page.locator('#state-panel .explanation').textContent(), /not run: the G71 at line 7 cut the contour N10–N20/);
      await page.locator('#step-last').click();
      const { png } = await shootCanvas(page, 'lathe-g71-g70', (_, p) => countColor(p, COLORS.actualFeed) > 500);
      assert.ok(countColor(png, COLORS.actualFeed) > 500, 'the passes are drawn');
    });
  });

  test('a lathe profile with tool nose radius compensation shows R and the tip in the state panel', async () => {
    await withPage(async (page) => {
      await page.getByLabel('Machine').selectOption('lathe');
      await page.getByLabel('Control').selectOption('fanuc');
      await waitForRun(page);
      // G10 gives offset 01 the nose radius 0.4 and tip 3 (behaviour 18).
      await typeProgram(page, NOSE);
      assert.match(await page.locator('#summary').textContent(), /0 errors/);
      await cursorOn(page, 4);
      await waitForView(page, (v) => v.step === 3);
      assert.equal(await stateText(page, 'cutter'), 'G42 · offset 01 · R 0.400 · tip 3 · start-up');
      assert.match(await page.locator('#state-panel .explanation').textContent(), /the imaginary tool nose \(tip 3\)/);
      // Line 5 ends at the inside corner: the nose centre at Z-19.834,
      // tip 3 back by 0.4: Z-20.234, X on the diameter.
      await cursorOn(page, 5);
      await waitForView(page, (v) => v.step === 4);
      assert.match(await stateText(page, 'actual'), /^X40\.000 Z-20\.234/);
      await page.locator('#step-last').click();
      const { png } = await shootCanvas(page, 'lathe-nose-radius', (_, p) => countColor(p, COLORS.actualFeed) > 100);
      assert.ok(countColor(png, COLORS.actualFeed) > 100, 'the compensated path is drawn');
    });
  });

  test('a mill program with G52, G68 and a G16 bolt circle is drawn where the transforms put it', async () => {
    await withPage(async (page) => {
      await page.getByLabel('Control').selectOption('fanuc');
      await typeProgram(page, MILL);
      assert.match(await page.locator('#summary').textContent(), /0 errors/);
      // X30. Y0 rotated 30° about the local zero: X25.981 Y15.000 in the
      // local system; the machine position adds G52's X40 Y30, and Z the
      // page's register 01 (6.000, the default example's).
      await cursorOn(page, 9);
      await waitForView(page, (v) => v.step === 8);
      assert.match(await stateText(page, 'programmed'), /^X25\.981 Y15\.000 Z-2\.000/);
      assert.match(await stateText(page, 'machine'), /^X65\.981 Y45\.000 Z4\.000/);
      assert.match(await page.locator('#state-panel .explanation').textContent(), /G68: X30\.000 Y0\.000 goes to X25\.981 Y15\.000/);
      // The third hole of the bolt circle: 25 at 180°.
      await cursorOn(page, 18);
      await waitForView(page, (v) => v.step === 17);
      assert.match(await stateText(page, 'programmed'), /^X-25\.000 Y0\.000/);
      await page.locator('#step-last').click();
      const { png } = await shootCanvas(page, 'mill-g52-g68-g16', (_, p) => countColor(p, COLORS.actualFeed) > 200);
      assert.ok(countColor(png, COLORS.actualFeed) > 200);
    });
  });

  test('a lathe face contour in G12.1 is drawn in the face view XC, the machine C and X in the state panel', async () => {
    await withPage(async (page) => {
      await page.getByLabel('Machine').selectOption('lathe');
      await page.getByLabel('Control').selectOption('fanuc');
      await waitForRun(page);
      await typeProgram(page, FACE);
      await waitForRun(page);
      assert.match(await page.locator('#summary').textContent(), /0 errors/);
      // C10. from (10, -10): C turns +90° to 45°, X is 2 × √200 = 28.284
      // (behaviour 14.16); T0100 takes no offset, so one move a side.
      await cursorOn(page, 7);
      await waitForView(page, (v) => v.step === 6);
      assert.match(await stateText(page, 'polar'), /C45\.000° from its place at G12\.1 · X28\.284 \(radius 14\.142\)/);
      assert.match(await page.locator('#state-panel .explanation').textContent(), /G01 in the XC plane of the face: a line to X20\.000 C10\.000/);
      await page.locator('#plane').selectOption('XC');
      await waitForView(page, (v) => v.plane === 'XC');
      await page.locator('#step-last').click();
      const { png } = await shootCanvas(page, 'lathe-g12-1-face-xc', (_, p) => countColor(p, COLORS.actualFeed) > 200);
      assert.ok(countColor(png, COLORS.actualFeed) > 200, 'the square is drawn on the face');
    });
  });
});
