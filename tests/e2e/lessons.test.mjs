// Browser end-to-end tests of issue 21's lessons in the page: the cutter
// compensation examples (the cutter's circle drawn, the state panel's
// cutter rows, the interference alarm at its line:column with the path
// drawn up to it), the offset table's columns per offset memory type and
// the lathe's nose radius and tip, carried by links, and the registers a
// program set with G10 shown apart from the user's.
// Screenshots: lesson-cutter-contour.png, lesson-cutter-contour-swept.png,
// lesson-cutter-pocket.png,
// lesson-offsets-c-g10.png, lesson-offsets-lathe.png.

import assert from 'node:assert/strict';
import { mkdtempSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { describe, test } from 'node:test';
import {
  COLORS, MARKS, RESULTS, cli, countColor, decodeLink, loadExample, openIn, shoot, shootCanvas, stateText,
  typeProgram, useBrowser, waitForLink, waitForRun, waitForView,
} from './harness.mjs';

const ctx = useBrowser();
const { withPage } = ctx;
const tmp = mkdtempSync(join(tmpdir(), 'offsetlab-lessons-'));

const setupJson = (page) => page.evaluate(() => window.offsetlab.setup());
const head = (page) => page.locator('#offsets thead th').allTextContents();
const field = (page, register, name) => page.locator(`#offsets input[data-field="${register}.${name}"]`);

/** Puts the cursor on `line` (1-based): the current block follows it. */
async function cursorOn(page, line) {
  // At the line's start: a click at the middle of a line wider than the
  // editor would scroll it sideways first, which no user does.
  await page.locator('.cm-line').nth(line - 1).click({ position: { x: 2, y: 4 } });
}

/** The 1-based line of the program text that starts with `n` (a sequence number). */
async function lineOf(page, n) {
  const program = await page.evaluate(() => window.offsetlab.program());
  const i = program.split('\n').findIndex((l) => l.startsWith(`${n} `));
  assert.ok(i >= 0, `${n} is in the program`);
  return i + 1;
}

describe('cutter compensation lessons', () => {
  test('the outside contour: start-up, offset mode and cancel in the state panel, the cutter circle drawn', async () => {
    await withPage(async (page) => {
      await loadExample(page, 'cutter-contour');
      assert.match(await page.locator('#summary').textContent(), / 0 errors · 0 warnings /);
      assert.match(await page.locator('#example-note').textContent(), /start(s)? up \(type A\)/);
      // Before G41: cancel mode, no circle; the tool marker alone.
      const n25 = await lineOf(page, 'N25');
      await cursorOn(page, n25);
      await waitForView(page, (v, s) => v.step === s, n25 - 3);
      assert.equal(await stateText(page, 'cutter'), 'G40 · cancel mode');
      const plain = await shootCanvas(page, 'lesson-cutter-contour-n25', (_, p) => countColor(p, MARKS.tool) > 50);
      const marker = countColor(plain.png, MARKS.tool);
      // N30, the start-up: G41 with D01 = 5; type A ends 5 left of N35's
      // start (X0 Y-10 going +Y: left is -X), at X-5 Y-10.
      const n30 = await lineOf(page, 'N30');
      await cursorOn(page, n30);
      await waitForView(page, (v, s) => v.step === s, n30 - 3);
      assert.equal(await stateText(page, 'cutter'), 'G41 · D01 = 5.000 · start-up');
      assert.match(await stateText(page, 'actual'), /^X-5\.000 Y-10\.000 Z-3\.000/);
      assert.match(await stateText(page, 'cutter-vector'), /X-5\.000 Y\+?0\.000/);
      // N40, the outside arc R10 about X10 Y40: the tool on radius 15, its
      // end X10 Y55 (5 beyond Y50, perpendicular to the arc's end).
      const n40 = await lineOf(page, 'N40');
      await cursorOn(page, n40);
      await waitForView(page, (v, s) => v.step === s, n40 - 3);
      assert.equal(await stateText(page, 'cutter'), 'G41 · D01 = 5.000 · offset mode');
      assert.match(await stateText(page, 'actual'), /^X10\.000 Y55\.000/);
      const { png } = await shootCanvas(page, 'lesson-cutter-contour',
        (_, p) => countColor(p, MARKS.tool) > marker + 300 && countColor(p, COLORS.actualFeed) > 300);
      // The cutter's circle (radius 5 at the fitted scale) adds a ring of
      // the tool's colour round the marker.
      assert.ok(countColor(png, MARKS.tool) > marker + 300, `tool pixels ${countColor(png, MARKS.tool)} against ${marker}`);
      assert.ok(countColor(png, COLORS.actualFeed) > 300, 'the compensated path is drawn');
      // N65 cancels on its move.
      const n65 = await lineOf(page, 'N65');
      await cursorOn(page, n65);
      await waitForView(page, (v, s) => v.step === s, n65 - 3);
      assert.match(await stateText(page, 'cutter'), /^G40 · D01 = 5\.000 · cancel \(this block\)$/);
    });
  });

  test('the outside contour: the swept width band drawn when ticked', async () => {
    await withPage(async (page) => {
      await loadExample(page, 'cutter-contour');
      // The light theme's band, rgba(43, 138, 62, 0.22) on white:
      // 255 − 0.22 × (255 − c) per channel = (208, 229, 212).
      const band = [208, 229, 212];
      const n40 = await lineOf(page, 'N40');
      await cursorOn(page, n40);
      await waitForView(page, (v, s) => v.step === s, n40 - 3);
      assert.ok(await page.locator('#swept-option').isVisible(), 'offered on the mill');
      assert.equal(await page.locator('#swept').isChecked(), false, 'off by default');
      const plain = await shootCanvas(page, 'lesson-cutter-contour-unswept', (_, p) => countColor(p, MARKS.tool) > 50);
      const before = countColor(plain.png, band, { tolerance: 12 });
      await page.locator('#swept').check();
      await waitForView(page, (v) => v.swept === true);
      // N40's arc R10 swept by a cutter of radius 5: a band 10 mm wide
      // along a quarter circle of radius 15, hundreds of pixels of it.
      const { png } = await shootCanvas(page, 'lesson-cutter-contour-swept',
        (_, p) => countColor(p, band, { tolerance: 12 }) > before + 300);
      assert.ok(countColor(png, band, { tolerance: 12 }) > before + 300, 'the band is drawn');
      // The document carries it.
      assert.equal((await page.evaluate(() => window.offsetlab.viewState())).swept, true);
      await page.locator('#swept').uncheck();
      await waitForView(page, (v) => v.swept === undefined);
    });
  });

  test('the pocket stops with the interference alarm at the too-small arc, its line:column listed and the path drawn up to it', async () => {
    await withPage(async (page) => {
      await loadExample(page, 'cutter-pocket');
      const n45 = await lineOf(page, 'N45');
      assert.match(await page.locator('#summary').textContent(), new RegExp(` 1 error · 0 warnings · mill, mm · stopped at line ${n45} · `));
      const item = page.locator('#diagnostics li.error');
      assert.equal(await item.count(), 1);
      assert.equal(await item.locator('.loc').textContent(), `${n45}:1`);
      assert.equal(await item.locator('.code').textContent(), '[cutter-interference]');
      assert.match(await item.locator('.message').textContent(), /PS0041/);
      // The inside corner before it: the offset lines meet at X55 Y5.
      const n35 = await lineOf(page, 'N35');
      await cursorOn(page, n35);
      await waitForView(page, (v, s) => v.step === s, n35 - 3);
      assert.match(await stateText(page, 'actual'), /^X55\.000 Y5\.000/);
      assert.equal(await stateText(page, 'cutter'), 'G41 · D01 = 5.000 · offset mode');
      // The last block run is N40: the run stops at N45.
      await page.locator('#step-last').click();
      await waitForView(page, (v, s) => v.step === s, n45 - 4);
      assert.match(await page.locator('#state-panel .explanation').textContent(), /./);
      const { png } = await shootCanvas(page, 'lesson-cutter-pocket',
        (_, p) => countColor(p, COLORS.actualFeed) > 150 && countColor(p, MARKS.tool) > 300);
      assert.ok(countColor(png, COLORS.actualFeed) > 150, 'the path up to the alarm is drawn');
      assert.ok(countColor(png, MARKS.tool) > 300, 'with the cutter at its end');
      // The message, with its line, in the diagnostics list; a click on it
      // selects the block and shows its start (11:1), not the end of its
      // long comment.
      await item.click();
      await page.waitForFunction(() => window.offsetlab.selection().includes('N45'));
      assert.ok(await page.locator('.cm-scroller').evaluate((e) => e.scrollLeft) < 8, 'scrolled to the line start');
      await shoot(page, 'lesson-cutter-pocket-page');
    });
  });
});

describe('offset memory in the page', () => {
  test('the table has the columns of memory A, B and C; memory C keeps H and D apart, and a G10 set is shown apart', async () => {
    await withPage(async (page, { context }) => {
      // The square's register 01 = 6 under each type.
      assert.deepEqual(await head(page), ['Register', 'value']);
      assert.match(await page.locator('#offsets-memory').textContent(), /memory A: one value per number/);
      const help = await page.locator('[data-setting="offset_memory"] .help').textContent();
      assert.match(help, /YASNAC: A/);
      assert.match(help, /Fanuc and Haas: C/);
      await page.locator('#set-offset_memory').selectOption('B');
      await waitForRun(page);
      assert.deepEqual(await head(page), ['Register', 'geometry', 'wear', 'sum']);
      // The Fanuc profile: memory C.
      await page.locator('#set-offset_memory').selectOption('');
      await page.getByLabel('Control').selectOption('fanuc');
      await waitForRun(page);
      assert.deepEqual(await head(page), ['Register', '', 'H (length)', 'D (radius)']);
      assert.equal(await field(page, 1, 'h').inputValue(), '6');
      assert.equal(await field(page, 1, 'd').inputValue(), '6');
      // D01 alone: 4 - 0.1 = 3.9; H01 stays 6.
      await field(page, 1, 'd').fill('4');
      await field(page, 1, 'd_wear').fill('-0.1');
      await waitForRun(page);
      assert.deepEqual((await setupJson(page)).offsets['01'], { h: 6, d: 4, d_wear: -0.1 });
      await page.locator('#step-next').click();
      await page.locator('#step-next').click();
      await page.locator('#step-next').click();
      await waitForView(page, (v) => v.step === 2);
      assert.equal(await stateText(page, 'position'), 'D01 = 3.900');

      // A program's G10 at line 2 sets D01's geometry to 5: the run reads
      // 5 - 0.1 = 4.9 from there; the table keeps the user's 4 and shows
      // the program's value apart.
      await typeProgram(page, 'G90 G00 X0 Y0\nG10 L12 P1 R5.\nG91 G45 X10. D01\nM30\n');
      assert.match(await page.locator('#summary').textContent(), / 0 errors /);
      assert.equal(await field(page, 1, 'd').inputValue(), '4');
      assert.equal(await page.locator('#g10-1-d').textContent(), 'G10 line 2: 5.000');
      assert.equal(await page.locator('#offsets-g10').isVisible(), true);
      assert.deepEqual(await page.locator('#offsets-g10 li').allTextContents(),
        ['D01 geometry = 5.000 (was 4.000), set by G10 at line 2']);
      await page.locator('#step-last').click();
      await waitForView(page, (v) => v.step === 3);
      await cursorOn(page, 3);
      await waitForView(page, (v) => v.step === 2);
      // G45 X10. with D01 = 4.9: X 10 + 4.9.
      assert.match(await stateText(page, 'actual'), /^X14\.900 /);
      await shoot(page, 'lesson-offsets-c-g10');
      await page.locator('#offsets-panel').screenshot({ path: join(RESULTS, 'lesson-offsets-c-g10-panel.png') });

      // The Share button's link carries memory C's tables.
      await context.grantPermissions(['clipboard-read', 'clipboard-write'], { origin: new URL(ctx.server.url).origin });
      await page.locator('#share-open').click();
      await page.waitForFunction(() => document.body.dataset.copied !== undefined);
      const link = await page.locator('#share-link').inputValue();
      const doc = decodeLink(link);
      assert.deepEqual(doc.offsets['01'], { h: 6, d: 4, d_wear: -0.1 });
      assert.equal(doc.settings.control, 'fanuc');
    });
  });

  test('a lathe table has R, R wear and the tip T, checked as typed; a link made by `offsetlab link` opens with them and the page’s link carries them back', async () => {
    await withPage(async (page, { context, problems }) => {
      const program = join(tmp, 'nose.nc');
      writeFileSync(program, 'G50 X100. Z50.\nG10 P10005 R0.4 Q2\nG00 T0105\nG01 Z-10. F0.2\nM30\n');
      const link = cli(['link', '--base', ctx.server.url, '--plain', '--machine', 'lathe',
        '--offset', '05=X0.4,Z-0.2,R0.8,RW-0.02,T3', program]).trim();
      assert.match(link, /offset=05:X0\.4,Z-0\.2,R0\.8,RW-0\.02,T3/);
      const opened = await openIn(context, link, problems);
      assert.equal(await waitForLink(opened), 'opened');
      assert.deepEqual(await head(opened), ['Register', '', 'X', 'Z', 'R', 'T']);
      assert.equal(await field(opened, 5, 'r').inputValue(), '0.8');
      assert.equal(await field(opened, 5, 'r_wear').inputValue(), '-0.02');
      assert.equal(await field(opened, 5, 't').inputValue(), '3');
      // The program's G10 set the geometry R to 0.4 and the tip to 2 at
      // line 2: shown apart, the table keeps 0.8 and 3.
      assert.equal(await opened.locator('#g10-5-r').textContent(), 'G10 line 2: 0.400');
      assert.equal(await opened.locator('#g10-5-t').textContent(), 'G10 line 2: 2');
      assert.deepEqual(await opened.locator('#offsets-g10 li').allTextContents(), [
        'offset 05 R (nose radius) = 0.400 (was 0.800), set by G10 at line 2',
        'offset 05 tip T = 2 (was 3), set by G10 at line 2',
      ]);
      // The tip is a digit 0–9.
      const tip = field(opened, 5, 't');
      await tip.fill('12');
      assert.match(await opened.locator('#reason-5-t').textContent(), /whole number 0 to 9/);
      assert.equal(await tip.getAttribute('aria-invalid'), 'true');
      await tip.fill('8');
      await field(opened, 5, 'r').fill('1.2');
      await waitForRun(opened);
      assert.deepEqual((await setupJson(opened)).lathe_offsets['05'], { x: 0.4, z: -0.2, r: 1.2, r_wear: -0.02, t: 8 });
      // The panel holds its eight columns.
      const overflow = await opened.evaluate(() => {
        const panel = document.getElementById('offsets-panel').getBoundingClientRect();
        return [...document.querySelectorAll('#offsets input, #offsets th')]
          .map((el) => el.getBoundingClientRect().right - panel.right)
          .filter((d) => d > -1);
      });
      assert.deepEqual(overflow, [], 'every column ends inside the panel');
      await shoot(opened, 'lesson-offsets-lathe');
      await opened.locator('#offsets-panel').screenshot({ path: join(RESULTS, 'lesson-offsets-lathe-panel.png') });
      // The page's own link (plain form) carries R, RW and T back.
      await context.grantPermissions(['clipboard-read', 'clipboard-write'], { origin: new URL(ctx.server.url).origin });
      await opened.locator('#share-open').click();
      await opened.waitForFunction(() => document.body.dataset.copied !== undefined);
      const back = decodeLink(await opened.locator('#share-link').inputValue());
      assert.deepEqual(back.lathe_offsets['05'], { x: 0.4, z: -0.2, r: 1.2, r_wear: -0.02, t: 8 });
      assert.equal(back.machine, 'lathe');
    });
  });

  test('the lathe profile: G42 with the nose radius and tip 3 in the state panel, the chamfer moved off the programmed line', async () => {
    await withPage(async (page) => {
      await loadExample(page, 'lathe-nose');
      assert.match(await page.locator('#summary').textContent(), /0 errors/);
      // N25, the start-up (line 7): the nose centre 0.8 right of the face's
      // start (+Z), the imaginary nose 0.8 below it: X -1.600 as a diameter.
      await cursorOn(page, 7);
      await waitForView(page, (v) => v.step === 4);
      assert.match(await stateText(page, 'cutter'), /G42 · offset 01 · R 0\.800 · tip 3 · start-up/);
      assert.match(await stateText(page, 'actual'), /^X-1\.600 Z0\.000/);
      // N40 (line 10), the diameter: cut on the programmed line (X40.), the
      // tool 0.8 on in Z at the corner the arc makes.
      await cursorOn(page, 10);
      await waitForView(page, (v) => v.step === 7);
      assert.match(await stateText(page, 'actual'), /^X40\.000 Z-20\.800/);
      assert.match(await page.locator('#state-panel .explanation').textContent(), /nose R 0\.800 right, tip 3/);
      const { png } = await shootCanvas(page, 'lesson-lathe-nose', (_, p) => countColor(p, COLORS.actualFeed) > 200);
      assert.ok(countColor(png, COLORS.actualFeed) > 200);
    });
  });
});
