// Browser end-to-end test of the 3D view (issue 23 item 1, behaviour 10.8
// and 10.9), driven as a user would: the 3D (iso) preset, Shift+drag to
// turn the view, the Orbit button's plain drag, two fingers in the 3D view,
// a click picking a block in 3D, the link carrying the angles, the lathe's
// views (its own 3D among them). Screenshots: view3d-iso.png, view3d-orbit.png,
// view3d-touch.png (and -canvas crops), view3d-readme.png (the README's).

import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import {
  countDifferences, decode, drag, loadExample, shoot, shootCanvas, useBrowser, waitForView,
} from './harness.mjs';

const { withPage } = useBrowser();
const drawn = (c) => c.actualFeed > 200;

describe('3D view', () => {
  test('the iso preset, Shift+drag and the Orbit button turn the view; the link keeps the angles', async () => {
    await withPage(async (page) => {
      await loadExample(page, 'cam');
      const flat = decode(await page.locator('#view').screenshot());
      // The 3D (iso) preset.
      await page.locator('#plane').selectOption('3D');
      const iso = await waitForView(page, (v) => v.plane === '3D');
      assert.deepEqual(iso.angles, [45, 35.264]);
      const { png: isoPng } = await shootCanvas(page, 'view3d-iso', drawn);
      assert.ok(countDifferences(flat, isoPng) > 2000, 'the iso view is another picture than the top view');
      // Shift+drag turns it: 100 px right is 50° less yaw, 40 px up 20° less pitch.
      await drag(page, [300, 300], [100, -40], 'Shift');
      const turned = await waitForView(page, (v) => v.plane === '3D' && Math.abs(v.angles[0] - 355) < 0.01);
      assert.ok(Math.abs(turned.angles[0] - 355) < 0.01, `yaw 45 − 50 = −5 → 355: ${turned.angles}`);
      assert.ok(Math.abs(turned.angles[1] - 15.264) < 0.01, `pitch 35.264 − 20 = 15.264: ${turned.angles}`);
      assert.equal(turned.zoom, 1, 'a turn is not a zoom');
      assert.deepEqual(turned.pan, [0, 0], 'nor a pan');
      // The whole frame after the gesture (the sample of a large path is for the gesture only).
      await page.waitForTimeout(400);
      const { png: orbitPng } = await shootCanvas(page, 'view3d-orbit', drawn);
      assert.ok(countDifferences(isoPng, orbitPng) > 2000, 'the turned view is another picture');
      // A plain drag pans; in the Orbit mode it turns: 60 px down, 30° more pitch.
      await drag(page, [300, 300], [0, 60]);
      await waitForView(page, (v) => v.pan[1] !== 0);
      await page.locator('#orbit').click();
      assert.equal(await page.locator('#orbit').getAttribute('aria-pressed'), 'true');
      await drag(page, [300, 300], [0, 60]);
      await waitForView(page, (v) => Math.abs(v.angles[1] - 45.264) < 0.01);
      await page.locator('#orbit').click();
      // The link carries the view (behaviour 10.9): plane=3D and the angles.
      const { plain } = await page.evaluate(() => window.offsetlab.document());
      assert.match(plain, /plane=3D&angles=355,45\.264/);
      // The top preset is the XY plane again, with no angles.
      await page.locator('#plane').selectOption('XY');
      const top = await waitForView(page, (v) => v.plane === 'XY');
      assert.equal(top.angles, undefined);
      // Opening the link (its plain form: the address bar holds the compact
      // one) shows the turned view again.
      await page.evaluate((l) => { location.hash = l.slice(l.indexOf('#')); }, plain);
      await waitForView(page, (v) => v.plane === '3D' && Math.abs(v.angles[1] - 45.264) < 0.01);
      assert.equal(await page.locator('#plane').inputValue(), '3D');
    });
  });

  test('a click picks a block in 3D, Shift+drag from the top view turns it, the README screenshot', async () => {
    await withPage(async (page) => {
      await loadExample(page, 'cam');
      await waitForView(page, (v) => v.plane === 'XY');
      // Shift+drag from the top view (yaw 0, pitch 90): 60 px left is 30°
      // of yaw, 60 px up 30° less pitch.
      await drag(page, [400, 300], [-60, -60], 'Shift');
      const v = await waitForView(page, (w) => w.plane === '3D' && w.angles[0] === 30);
      assert.deepEqual(v.angles, [30, 60]);
      await page.locator('#plane').selectOption('3D');
      await waitForView(page, (w) => w.angles?.[0] === 45);
      // A click on the drawing picks the block under it: search the drawing's
      // pixels of the actual feed path for one that picks a block.
      const { png } = await shootCanvas(page, 'view3d-pick', drawn);
      const box = await page.locator('#view').boundingBox();
      const scale = png.width / box.width;
      let picked = null;
      for (let y = 40; y < png.height && picked === null; y += 23) {
        for (let x = 60; x < png.width && picked === null; x += 7) {
          const i = (y * png.width + x) * 4;
          const [r, g, b] = png.data.slice(i, i + 3);
          // The actual feed path's blue (src/render/style.rs), roughly.
          if (!(b > 150 && r < 90 && g < 140)) continue;
          await page.mouse.click(box.x + x / scale, box.y + y / scale);
          // The worker answers the click: under load its answer can come
          // after the click returns, so wait a little for it.
          const step = await page
            .waitForFunction(() => {
              const s = JSON.parse(document.body.dataset.view).step;
              return s === null ? null : { s };
            }, null, { timeout: 1500 })
            .then(async (h) => (await h.jsonValue()).s)
            .catch(() => null);
          if (step !== null) picked = step;
        }
      }
      assert.ok(picked !== null, 'a click on the 3D drawing picks a block');
      // The README's screenshot: the CAM example in the iso view, stepped into the pocket.
      await page.locator('#plane').selectOption('3D');
      await shoot(page, 'view3d-readme');
    }, { width: 1500, height: 860, scale: 1 });
  });

  test('two fingers turn the 3D view; the lathe has its own 3D', async () => {
    await withPage(async (page) => {
      await loadExample(page, 'cam');
      await page.locator('#plane').selectOption('3D');
      await waitForView(page, (v) => v.plane === '3D');
      // Two touch pointers moving together 40 px right: 20° less yaw.
      await page.locator('#view').evaluate((canvas) => {
        const r = canvas.getBoundingClientRect();
        const at = (id, type, x, y) => canvas.dispatchEvent(new PointerEvent(type, {
          pointerId: id, pointerType: 'touch', isPrimary: id === 1, bubbles: true, clientX: r.left + x, clientY: r.top + y, button: 0,
        }));
        at(1, 'pointerdown', 200, 200);
        at(2, 'pointerdown', 260, 200);
        for (let i = 1; i <= 4; i += 1) {
          at(1, 'pointermove', 200 + i * 10, 200);
          at(2, 'pointermove', 260 + i * 10, 200);
        }
        at(1, 'pointerup', 240, 200);
        at(2, 'pointerup', 300, 200);
      });
      const v = await waitForView(page, (w) => Math.abs(w.angles?.[0] - 25) < 0.01);
      assert.ok(Math.abs(v.angles[0] - 25) < 0.01, `yaw 45 − 20 = 25: ${v.angles}`);
      assert.ok(Math.abs(v.zoom - 1) < 1e-9, 'fingers moving together do not zoom');
      await shootCanvas(page, 'view3d-touch', drawn);
      await loadExample(page, 'lathe-taper');
      await waitForView(page, (w) => w.plane === 'ZX');
      // The lathe turns in 3D too (behaviour 10.18, tests/e2e/toolview.test.mjs).
      assert.equal(await page.locator('#orbit').isVisible(), true, 'the Orbit button on the lathe');
      const shown = await page.locator('#plane option:not([hidden])').evaluateAll((os) => os.map((o) => o.value));
      assert.deepEqual(shown, ['ZX', 'XC', '3D']);
    }, { hasTouch: true, scale: 1 });
  });
});
