// Browser end-to-end test of issue 23's "a machine that starts where
// machines start" (behaviour 13.15, setting 7.49): on the Haas profile the
// mill starts homed at Z508 and `G91 G28 Z0.` rises there; the Settings
// panel's Reference position moves it, Start and reference puts it back at
// the work zero, and the share link carries what was set.

import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { COLORS, countColor, decodeLink, shoot, shootCanvas, typeProgram, useBrowser, waitForRun } from './harness.mjs';

const { withPage } = useBrowser();

// From the start down to X10 Y20 Z5, then G91 G28 Z0.: the intermediate
// point is where the tool is, so one move straight up to the reference.
const PROGRAM = 'G90 G00 X10. Y20. Z5.\nG91 G28 Z0.\nM30\n';

describe('a machine that starts where machines start', () => {
  test('on the Haas profile G28 rises to Z508, and the panel moves the reference', async () => {
    await withPage(async (page, { context }) => {
      await typeProgram(page, PROGRAM);
      // YASNAC (the default): the tool starts at the work zero and G28 goes
      // up to the typical reference, Z508 (issue 32): extents X0…10 Y0…20
      // Z0…508, and the panel's line says so.
      assert.match(await page.locator('#summary').textContent(), / · X0…10 Y0…20 Z0…508$/);
      assert.match(await page.locator('#positions-effect').textContent(), /reference X0\.000 Y0\.000 Z508\.000 \(machine\)/);
      await page.getByLabel('Control').selectOption('haas');
      await waitForRun(page);
      // Haas: start at X0 Y0 Z508 (a VF-2's Z travel above the work zero),
      // down to Z5, up to Z508: rapids 503.5 (√(10² + 20² + 503²) ≈ 503.50)
      // + 503 = 1006.5 mm; extents Z5…508.
      const summary = await page.locator('#summary').textContent();
      assert.match(summary, / · path 1006\.5 mm \(1006\.5 rapid\) · .* · X0…10 Y0…20 Z5…508$/);
      assert.match(await page.locator('#machine_positions-help').textContent(), /Z508 mm \(Haas VF-2\)/);
      await page.locator('#plane').selectOption('XZ');
      await shootCanvas(page, 'positions-haas-xz', (_, p) => countColor(p, COLORS.actualRapid) > 50);
      // The reference at machine Z300: G28 rises to 300, and the start (left
      // out) is the reference too.
      await page.getByLabel('Reference position Z').fill('300');
      await waitForRun(page);
      assert.match(await page.locator('#summary').textContent(), / · X0…10 Y0…20 Z5…300$/);
      await page.locator('#settings-form [data-setting="reference"]').scrollIntoViewIfNeeded();
      await shoot(page, 'positions-panel');
      // Start and reference: the work zero — the start stays 0 0 0 (left out)
      // but the reference the panel set (Z300) stays.
      await page.getByLabel('Start and reference').selectOption('work_zero');
      await waitForRun(page);
      assert.match(await page.locator('#summary').textContent(), / · X0…10 Y0…20 Z0…300$/);
      await context.grantPermissions(['clipboard-read', 'clipboard-write'], { origin: new URL(page.url()).origin });
      await page.locator('#share-open').click();
      await page.waitForFunction(() => document.body.dataset.copied === 'true');
      const doc = decodeLink(await page.locator('#share-link').inputValue());
      assert.deepEqual(doc.reference, { x: 0, y: 0, z: 300 });
      assert.equal(doc.settings.machine_positions, 'work_zero');
      assert.equal(doc.settings.control, 'haas');
    });
  });
});
