// Shared harness of the browser end-to-end tests: serves www/ with
// scripts/serve.mjs on a free port, drives Debian's Chromium through
// playwright-core (no browser download), records console errors and page
// exceptions, and decodes canvas screenshots to count path pixels.

import { execFileSync, spawn } from 'node:child_process';
import { existsSync, mkdirSync, writeFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { after, before } from 'node:test';
import assert from 'node:assert/strict';
import { chromium } from 'playwright-core';
import { PNG } from 'pngjs';

export const ROOT = join(dirname(fileURLToPath(import.meta.url)), '..', '..');
export const RESULTS = join(ROOT, 'test-results');

/** Colours of src/render/style.rs (keep in step with it). */
export const COLORS = {
  background: [0xff, 0xff, 0xff],
  actualFeed: [0x1c, 0x4f, 0xd8],
  actualRapid: [0xd9, 0x48, 0x0f],
  programmedFeed: [0x4d, 0xab, 0xf7],
  programmedRapid: [0xff, 0xa9, 0x4d],
  centreLine: [0x5f, 0x3d, 0xc4],
};

const CHROMIUM_ARGS = [
  '--headless',
  '--no-sandbox',
  '--disable-gpu',
  '--disable-dev-shm-usage',
  '--disable-background-networking',
  '--disable-component-update',
  '--no-first-run',
  '--disable-sync',
  '--disable-quic',
];

/**
 * Starts the static server on a free port (serving www/, or `root`);
 * resolves to { url, stop }.
 */
export async function startServer({ root } = {}) {
  if (!root && !existsSync(join(ROOT, 'www', 'pkg', 'offsetlab.js'))) {
    throw new Error('www/pkg is missing: build it first (make wasm)');
  }
  if (!root && !existsSync(join(ROOT, 'www', 'dist', 'editor.js'))) {
    throw new Error('www/dist is missing: build it first (make page)');
  }
  const args = [join(ROOT, 'scripts', 'serve.mjs'), '--port', '0', ...(root ? ['--root', root] : [])];
  const child = spawn(process.execPath, args, {
    stdio: ['ignore', 'pipe', 'inherit'],
  });
  const url = await new Promise((resolve, reject) => {
    let out = '';
    const timer = setTimeout(() => reject(new Error(`server did not start: ${out}`)), 10_000);
    child.stdout.on('data', (chunk) => {
      out += chunk;
      const match = /on (http:\/\/\S+\/)/.exec(out);
      if (match) {
        clearTimeout(timer);
        resolve(match[1]);
      }
    });
    child.on('exit', (code) => {
      clearTimeout(timer);
      reject(new Error(`server exited with ${code}: ${out}`));
    });
  });
  return {
    url,
    stop: () =>
      new Promise((resolve) => {
        child.removeAllListeners('exit');
        child.once('exit', resolve);
        child.kill('SIGTERM');
      }),
  };
}

/** The CLI binary (target/debug/offsetlab), built once if missing. */
export const CLI = join(ROOT, 'target', 'debug', 'offsetlab');

/** Runs `offsetlab ARGS...` and returns its standard output (throws on a non-zero exit). */
export function cli(args, { input } = {}) {
  if (!existsSync(CLI)) {
    execFileSync('cargo', ['build', '--quiet', '--bin', 'offsetlab'], { cwd: ROOT, stdio: 'inherit' });
  }
  return execFileSync(CLI, args, { cwd: ROOT, input, encoding: 'utf8', maxBuffer: 64 * 1024 * 1024 });
}

/** The document a link carries, as `offsetlab link --decode` prints it (parsed). */
export function decodeLink(link) {
  return JSON.parse(cli(['link', '--decode', link]));
}

/** Launches Chromium with a fresh, temporary profile. */
export function launchBrowser() {
  return chromium.launch({
    executablePath: process.env.CHROMIUM_PATH || '/usr/bin/chromium',
    args: CHROMIUM_ARGS,
    headless: true,
  });
}

/**
 * Opens the page in a new context and records every console error, page
 * exception and failed request (of the page and of its worker) in
 * `problems`.
 */
export async function openPage(browser, url, {
  width = 1280, height = 800, scale = 2, colorScheme = 'light', hasTouch = false, init,
} = {}) {
  const context = await browser.newContext({
    viewport: { width, height },
    deviceScaleFactor: scale,
    colorScheme,
    hasTouch,
  });
  if (init) await context.addInitScript(init);
  const page = await context.newPage();
  const problems = [];
  watch(page, problems);
  await page.goto(url);
  return { context, page, problems };
}

/** Records every console error, page exception and failed request of `page` (and its workers) in `problems`. */
export function watch(page, problems) {
  const onConsole = (where) => (message) => {
    if (message.type() === 'error') problems.push(`${where} console error: ${message.text()}`);
  };
  page.on('console', onConsole('page'));
  page.on('pageerror', (error) => problems.push(`page exception: ${error.message}`));
  page.on('worker', (worker) => worker.on('console', onConsole('worker')));
  page.on('requestfailed', (request) =>
    problems.push(`request failed: ${request.url()} ${request.failure()?.errorText}`));
  page.on('response', (response) => {
    if (response.status() >= 400) problems.push(`HTTP ${response.status()}: ${response.url()}`);
  });
}

/** Opens `url` in a new page of `context` (same storage), watched like the first. */
export async function openIn(context, url, problems) {
  const page = await context.newPage();
  watch(page, problems);
  await page.goto(url);
  return page;
}

/** Waits until the link in the fragment was opened or refused and its run shown; resolves to 'opened' or 'error'. */
export async function waitForLink(page) {
  await page.waitForFunction(() => ['opened', 'error'].includes(document.body.dataset.link), null, { timeout: 20_000 });
  await waitForRun(page);
  return page.evaluate(() => document.body.dataset.link);
}

/** Waits until the work is saved in localStorage, and returns it. */
export async function savedWork(page) {
  // The view state of the latest run comes a frame after its result and
  // saves the work again (the current block may have moved): wait for it
  // before waiting for the save.
  await page.waitForFunction(() => document.body.dataset.rendered === undefined
    || document.body.dataset.stateGen === document.body.dataset.rendered
    || document.body.dataset.stopped !== undefined, null, { timeout: 20_000 });
  await page.waitForFunction(() => document.body.dataset.unsaved === undefined);
  return page.evaluate(() => JSON.parse(localStorage.getItem('offsetlab.work.v1')));
}

/** Waits until no edit is waiting and the answer to the latest run request is shown. */
export async function waitForRun(page) {
  await page.waitForFunction(() => {
    const { requested, rendered, pending } = document.body.dataset;
    return pending === undefined && requested !== undefined && rendered === requested;
  }, null, { timeout: 20_000 });
}

/** Decodes a PNG buffer. */
export function decode(buffer) {
  return PNG.sync.read(buffer);
}

/** Pixels within `tolerance` (RGB distance) of each colour, and non-background ones. */
export function countColors(png, tolerance = 40) {
  const counts = Object.fromEntries(Object.keys(COLORS).map((k) => [k, 0]));
  let painted = 0;
  const { data } = png;
  for (let i = 0; i < data.length; i += 4) {
    const r = data[i];
    const g = data[i + 1];
    const b = data[i + 2];
    for (const [name, [cr, cg, cb]] of Object.entries(COLORS)) {
      const d = Math.hypot(r - cr, g - cg, b - cb);
      if (d <= tolerance) counts[name] += 1;
    }
    const [br, bg, bb] = COLORS.background;
    if (Math.hypot(r - br, g - bg, b - bb) > 24) painted += 1;
  }
  return { ...counts, painted, total: data.length / 4 };
}

/** Pixels that differ between two decoded images of the same size. */
export function countDifferences(a, b) {
  if (a.width !== b.width || a.height !== b.height) return a.width * a.height;
  let n = 0;
  for (let i = 0; i < a.data.length; i += 4) {
    if (
      Math.abs(a.data[i] - b.data[i]) > 16 ||
      Math.abs(a.data[i + 1] - b.data[i + 1]) > 16 ||
      Math.abs(a.data[i + 2] - b.data[i + 2]) > 16
    ) n += 1;
  }
  return n;
}

/**
 * Screenshots the canvas until `accept(counts, png)` holds (the worker's
 * OffscreenCanvas reaches the screen a frame or two after its answer).
 * Saves the page and the canvas to test-results/NAME.png and NAME-canvas.png.
 */
export async function shootCanvas(page, name, accept, timeout = 10_000) {
  mkdirSync(RESULTS, { recursive: true });
  const canvas = page.locator('#view');
  const deadline = Date.now() + timeout;
  let png;
  let counts;
  for (;;) {
    const buffer = await canvas.screenshot();
    png = decode(buffer);
    counts = countColors(png);
    if (accept(counts, png)) {
      writeFileSync(join(RESULTS, `${name}-canvas.png`), buffer);
      break;
    }
    if (Date.now() > deadline) {
      writeFileSync(join(RESULTS, `${name}-canvas.png`), buffer);
      break;
    }
    await page.waitForTimeout(100);
  }
  await page.screenshot({ path: join(RESULTS, `${name}.png`) });
  return { png, counts };
}

/** Colours of the light theme's arrow and tool marker (src/render/style.rs). */
export const MARKS = {
  arrow: [0xc2, 0x25, 0x5c],
  tool: [0x2b, 0x8a, 0x3e],
  ghost: [0xce, 0xd4, 0xda],
};

/** Pixels within `tolerance` of `color` in a decoded image, optionally inside a box (device px). */
export function countColor(png, color, { tolerance = 30, box } = {}) {
  const [cr, cg, cb] = color;
  const { width, data } = png;
  const x0 = box?.x ?? 0;
  const y0 = box?.y ?? 0;
  const x1 = box ? box.x + box.w : width;
  const y1 = box ? box.y + box.h : png.height;
  let n = 0;
  for (let y = Math.max(0, y0); y < Math.min(png.height, y1); y += 1) {
    for (let x = Math.max(0, x0); x < Math.min(width, x1); x += 1) {
      const i = (y * width + x) * 4;
      if (Math.hypot(data[i] - cr, data[i + 1] - cg, data[i + 2] - cb) <= tolerance) n += 1;
    }
  }
  return n;
}

/** Centroid (device px) of the pixels near `color`, or null. */
export function centroid(png, color, tolerance = 30) {
  const [cr, cg, cb] = color;
  let sx = 0;
  let sy = 0;
  let n = 0;
  for (let y = 0; y < png.height; y += 1) {
    for (let x = 0; x < png.width; x += 1) {
      const i = (y * png.width + x) * 4;
      if (Math.hypot(png.data[i] - cr, png.data[i + 1] - cg, png.data[i + 2] - cb) <= tolerance) {
        sx += x;
        sy += y;
        n += 1;
      }
    }
  }
  return n ? { x: sx / n, y: sy / n, n } : null;
}

/** Replaces the program by typing it in CodeMirror, key by key, as a user would. */
export async function typeProgram(page, text) {
  await page.locator('.cm-content').click();
  await page.keyboard.press('ControlOrMeta+A');
  await page.keyboard.press('Delete');
  await page.keyboard.type(text, { delay: 1 });
  await waitForRun(page);
}

/** The view state the page last got from the worker. */
export async function viewOf(page) {
  return page.evaluate(() => window.offsetlab.viewState());
}

/**
 * Waits until the worker reports a view state for which `predicate(view, arg)`
 * holds. The predicate runs here in Node, polling the page's `data-view`: the
 * page's Content-Security-Policy forbids `eval` and `new Function`, so it
 * cannot be compiled inside the page.
 */
export async function waitForView(page, predicate, arg, { timeout = 10_000 } = {}) {
  const deadline = Date.now() + timeout;
  for (;;) {
    const text = await page.evaluate(() => document.body.dataset.view);
    if (text !== undefined && predicate(JSON.parse(text), arg)) return viewOf(page);
    if (Date.now() > deadline) {
      throw new Error(`waitForView: ${predicate} did not hold within ${timeout} ms (last view ${text})`);
    }
    await new Promise((resolve) => setTimeout(resolve, 20));
  }
}

/** Loads a built-in example from the menu and waits for its run. */
export async function loadExample(page, id) {
  await page.locator('#example').selectOption(id);
  await page.locator('#load-example').click();
  await waitForRun(page);
}

/** Text of the state panel row with data-key `key`. */
export async function stateText(page, key) {
  return page.locator(`#state-panel dd[data-key="${key}"]`).textContent();
}

/** Saves a screenshot of the whole page in test-results/NAME.png. */
export async function shoot(page, name, options = {}) {
  mkdirSync(RESULTS, { recursive: true });
  await page.screenshot({ path: join(RESULTS, `${name}.png`), ...options });
}

/**
 * One server and one browser per test file; `withPage(body, options)` opens
 * a fresh context (so a fresh localStorage), waits for the first run, runs
 * `body(page, problems)` and then checks that no console error, page
 * exception or failed request happened.
 */
export function useBrowser() {
  const ctx = {};
  before(async () => {
    ctx.server = await startServer();
    ctx.browser = await launchBrowser();
  });
  after(async () => {
    await ctx.browser?.close();
    await ctx.server?.stop();
  });
  ctx.withPage = async (body, options = {}) => {
    const { context, page, problems } = await openPage(ctx.browser, ctx.server.url + (options.hash ?? ''), options);
    try {
      await waitForRun(page);
      // And its view state (the stepper, the state panel), which the worker
      // reports with the drawing, a frame after the run's result.
      await page.waitForFunction(() => document.body.dataset.stateGen === document.body.dataset.rendered
        || document.body.dataset.stopped !== undefined, null, { timeout: 20_000 });
      await body(page, { context, problems });
      assert.deepEqual(problems, [], 'no console errors, page exceptions or failed requests');
    } finally {
      await context.close();
    }
  };
  return ctx;
}

/** The bounding box (device px) of the pixels near `color`, or null. */
export function bbox(png, color, tolerance = 30) {
  let [x0, y0, x1, y1] = [Infinity, Infinity, -Infinity, -Infinity];
  for (let y = 0; y < png.height; y += 1) {
    for (let x = 0; x < png.width; x += 1) {
      const i = (y * png.width + x) * 4;
      if (Math.hypot(png.data[i] - color[0], png.data[i + 1] - color[1], png.data[i + 2] - color[2]) <= tolerance) {
        [x0, y0, x1, y1] = [Math.min(x0, x), Math.min(y0, y), Math.max(x1, x), Math.max(y1, y)];
      }
    }
  }
  return x1 >= x0 ? { x0, y0, x1, y1, w: x1 - x0, h: y1 - y0 } : null;
}

/** A mouse drag on the drawing from (x0, y0) by (dx, dy), in steps, with `modifier` held. */
export async function drag(page, [x0, y0], [dx, dy], modifier) {
  const box = await page.locator('#view').boundingBox();
  if (modifier) await page.keyboard.down(modifier);
  await page.mouse.move(box.x + x0, box.y + y0);
  await page.mouse.down();
  for (let i = 1; i <= 10; i += 1) {
    await page.mouse.move(box.x + x0 + (dx * i) / 10, box.y + y0 + (dy * i) / 10);
  }
  await page.mouse.up();
  if (modifier) await page.keyboard.up(modifier);
}
