// The 3D view's part of `make bench-browser` target 5 (issue 23 item 1,
// behaviour 10.8): frames the worker finishes per second while the view is
// turned (Shift+drag in the 3D view) over the 1M-block program. Called by
// scripts/bench-browser.mjs with its own helpers, so the two measure frames
// the same way.

import { workerFrames } from './bench-instrument.mjs';

/**
 * Chooses the 3D (iso) view, waits for its whole frame, then Shift+drags on
 * #view round a circle for `seconds` (CDP Input.dispatchMouseEvent, up to
 * four events in flight, as target 5's pan) and counts the frames the
 * worker finished meanwhile; then the plane view (XY) is chosen again.
 * `helpers`: { now, within, stats, sleep, limit } of bench-browser.mjs.
 */
export async function orbitFrames(page, seconds, { now, within, stats, sleep, limit }) {
  await page.locator('#plane').selectOption('3D');
  // The whole 3D frame of the big path, before the gesture.
  await page.waitForFunction(() => JSON.parse(document.body.dataset.view ?? '{}').plane === '3D', null, { timeout: limit.big });
  await sleep(1500);
  const cdp = await page.context().newCDPSession(page);
  const box = await page.locator('#view').boundingBox();
  const cx = box.x + box.width / 2;
  const cy = box.y + box.height / 2;
  const inflight = new Set();
  const send = async (params) => {
    while (inflight.size >= 4) await Promise.race(inflight);
    const p = cdp.send('Input.dispatchMouseEvent', params).catch(() => {}).finally(() => inflight.delete(p));
    inflight.add(p);
  };
  const SHIFT = 8; // CDP's modifiers bit for Shift
  const t0 = await now(page);
  const inputs = await within((async () => {
    let n = 0;
    await send({ type: 'mouseMoved', x: cx, y: cy, modifiers: SHIFT });
    await send({ type: 'mousePressed', x: cx, y: cy, button: 'left', buttons: 1, clickCount: 1, modifiers: SHIFT });
    const end = Date.now() + seconds * 1000;
    let x = cx;
    let y = cy;
    while (Date.now() < end) {
      // Round a circle of 120 px: the view turns both ways about both axes.
      const a = (n / 40) * 2 * Math.PI;
      x = cx + 120 * Math.cos(a) - 120;
      y = cy + 120 * Math.sin(a);
      await send({ type: 'mouseMoved', x, y, button: 'left', buttons: 1, modifiers: SHIFT });
      n += 1;
    }
    await send({ type: 'mouseReleased', x, y, button: 'left', buttons: 0, clickCount: 1, modifiers: SHIFT });
    return n;
  })(), seconds * 1000 + limit.step, 'orbit');
  await within(Promise.all(inflight), limit.step, 'orbit');
  const t1 = await now(page);
  const { renders, frames } = await workerFrames(page, t1, limit.grace);
  const done = frames.filter((f) => f.end >= t0 && f.end <= t1);
  const begun = frames.filter((f) => f.start >= t0 && f.start <= t1);
  const moving = (f) => renders.get(f.render)?.moving === true;
  const view = await page.evaluate(() => JSON.parse(document.body.dataset.view));
  await page.locator('#plane').selectOption('XY');
  return {
    fps: done.length / ((t1 - t0) / 1000),
    frames: done.length,
    seconds: (t1 - t0) / 1000,
    inputsPerSecond: inputs / ((t1 - t0) / 1000),
    movingFrameMs: stats(begun.filter(moving).map((f) => f.end - f.start)),
    wholeFrameMs: stats(begun.filter((f) => !moving(f)).map((f) => f.end - f.start)),
    renderMs: stats(begun.map((f) => renders.get(f.render).end - f.start)),
    angles: view.angles ?? null,
  };
}
