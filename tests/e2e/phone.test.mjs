// Browser end-to-end tests of issue 23's phone layout: at 360, 390 and 414
// CSS pixels (the common phone widths) nothing is wider than the screen —
// the top bar's Load button, the example list, the settings' choices, the
// panels — and the drawing comes right after the top bar, drawn, with the
// step buttons under it; the lathe's panels fit as well; and the legend
// folds away, giving the path the whole drawing (behaviour 10.7).

import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { shoot, shootCanvas, useBrowser, waitForRun, waitForView } from './harness.mjs';

const { withPage } = useBrowser();

/** What sticks out past the window's right edge (the editor's own scroller aside). */
function overflow(page) {
  return page.evaluate(() => ({
    scrollWidth: document.documentElement.scrollWidth,
    wide: [...document.querySelectorAll('body *')]
      .filter((e) => e.offsetParent && !e.closest('.cm-editor')
        && e.getBoundingClientRect().right > window.innerWidth + 0.5)
      .slice(0, 5)
      .map((e) => `${e.tagName.toLowerCase()}#${e.id}.${e.className} right ${Math.round(e.getBoundingClientRect().right)}`),
  }));
}

const box = (page, selector) => page.locator(selector).boundingBox();

describe('the page on a phone', () => {
  for (const width of [360, 390, 414]) {
    test(`at ${width} px nothing is wider than the screen and the drawing comes first`, async () => {
      await withPage(async (page) => {
        // The settings panel is open (as it starts), its long choices too.
        assert.equal(await page.locator('#settings-panel').getAttribute('open'), '');
        const o = await overflow(page);
        assert.equal(o.scrollWidth, width, `the page is as wide as the screen: ${o.wide.join(', ')}`);
        assert.deepEqual(o.wide, []);
        const load = await box(page, '#load-example');
        assert.ok(load.x + load.width <= width, `Load is on screen (right edge ${load.x + load.width})`);
        // The drawing starts under the top bar and the example's note, not
        // under the editor; the step buttons follow it.
        const view = await box(page, '#view');
        assert.ok(view.y < 400, `the drawing starts ${view.y} px down`);
        assert.ok(view.width >= width - 2, `the drawing is as wide as the screen (${view.width})`);
        const editor = await box(page, '#editor');
        assert.ok(editor.y > view.y + view.height, 'the editor comes after the drawing');
        const next = await box(page, '#step-next');
        assert.ok(next.y > view.y + view.height && next.x + next.width <= width, 'the step buttons are under it, on screen');
        const { counts } = await shootCanvas(page, `phone-${width}-canvas`, (c) => c.actualFeed > 200);
        assert.ok(counts.actualFeed > 200, `the path is drawn (${JSON.stringify(counts)})`);
        await shoot(page, `phone-${width}`);
      }, { width, height: 844, scale: 1 });
    });
  }

  test('at 390 px the legend folds away and the path is drawn larger, and stays folded after a reload', async () => {
    await withPage(async (page) => {
      const legend = page.locator('#legend');
      assert.equal(await legend.isChecked(), true, 'shown by default');
      const shown = await shootCanvas(page, 'phone-legend-shown', (c) => c.actualFeed > 200);
      await legend.uncheck();
      await waitForView(page, (v) => v.legend === false);
      const folded = await shootCanvas(page, 'phone-legend-folded',
        (c) => c.actualFeed > 1.15 * shown.counts.actualFeed, 10_000);
      // The seed square (116 × 82 mm with its approach) is fitted beside the
      // compact legend, then to the whole drawing: its lines are longer.
      assert.ok(folded.counts.actualFeed > 1.15 * shown.counts.actualFeed,
        `larger without the legend (${shown.counts.actualFeed} → ${folded.counts.actualFeed} pixels)`);
      await page.reload();
      await waitForRun(page);
      await waitForView(page, (v) => v.legend === false);
      assert.equal(await legend.isChecked(), false, 'still folded after a reload');
    }, { width: 390, height: 844, scale: 1 });
  });

  test('the lathe at 390 px fits too, its four-column offset table within the screen', async () => {
    await withPage(async (page) => {
      await page.getByLabel('Machine').selectOption('lathe');
      await waitForRun(page);
      const o = await overflow(page);
      assert.equal(o.scrollWidth, 390, o.wide.join(', '));
      const table = await box(page, '#offsets');
      assert.ok(table.x >= 0 && table.x + table.width <= 390, `the offset table fits (${table.x}…${table.x + table.width})`);
      await shoot(page, 'phone-390-lathe', { fullPage: true });
    }, { width: 390, height: 844, scale: 1 });
  });
});
