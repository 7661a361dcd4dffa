// Shared harness of the browser end-to-end tests: serves www/ with
// scripts/serve.mjs on a free port, drives Debian's Chromium through
// playwright-core (no browser download), records console errors and page
// exceptions, and decodes canvas screenshots to count path pixels.

import { spawn } from 'node:child_process';
import { existsSync, mkdirSync, writeFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
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

/** Starts the static server on a free port; resolves to { url, stop }. */
export async function startServer() {
  if (!existsSync(join(ROOT, 'www', 'pkg', 'offsetlab.js'))) {
    throw new Error('www/pkg is missing: build it first (make wasm)');
  }
  const child = spawn(process.execPath, [join(ROOT, 'scripts', 'serve.mjs'), '--port', '0'], {
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
export async function openPage(browser, url, { width = 1280, height = 800, scale = 2 } = {}) {
  const context = await browser.newContext({
    viewport: { width, height },
    deviceScaleFactor: scale,
  });
  const page = await context.newPage();
  const problems = [];
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
  await page.goto(url);
  return { context, page, problems };
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
