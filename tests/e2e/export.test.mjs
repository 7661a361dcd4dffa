// Browser end-to-end tests of the Export menu (issue 5, item 6): each
// export produces a file with the expected content, caught by Playwright's
// download event — the drawing as PNG (decoded: device pixels, path colours)
// and SVG (parsed: both paths, arrows, legend), the toolpath as CSV and JSON
// (compared with `offsetlab run --format json` of the same program and
// setup) and the program as .nc; files are named after the program number.

import assert from 'node:assert/strict';
import { mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { describe, test } from 'node:test';
import { COLORS, MARKS, cli, countColor, countColors, decode, loadExample, shoot, useBrowser, waitForView } from './harness.mjs';

const { withPage } = useBrowser();
const tmp = mkdtempSync(join(tmpdir(), 'offsetlab-export-'));

/** Clicks Export → `format` and returns { name, path } of the downloaded file. */
async function exportAs(page, format) {
  await page.locator('#export > summary').click();
  const downloading = page.waitForEvent('download');
  await page.locator(`#export button[data-export="${format}"]`).click();
  const download = await downloading;
  const name = download.suggestedFilename();
  const path = join(tmp, `${format}-${name}`);
  await download.saveAs(path);
  return { name, path };
}

/** A CSV (no quoted commas in these files) as rows of cells. */
function parseCsv(text) {
  assert.ok(text.endsWith('\r\n'), 'RFC 4180 line ends');
  return text.slice(0, -2).split('\r\n').map((line) => line.split(','));
}

/** `offsetlab run --format json` of what the page shows. */
async function cliRun(page) {
  const program = await page.evaluate(() => window.offsetlab.program());
  const setup = await page.evaluate(() => window.offsetlab.setup());
  const programPath = join(tmp, 'program.nc');
  const setupPath = join(tmp, 'setup.json');
  writeFileSync(programPath, program);
  writeFileSync(setupPath, JSON.stringify(setup));
  return { program, run: JSON.parse(cli(['run', '--format', 'json', '--setup', setupPath, programPath])) };
}

describe('export', () => {
  test('PNG, SVG, CSV, JSON and .nc of the contour example (O2001) have the expected contents', async () => {
    await withPage(async (page) => {
      await loadExample(page, 'contour');
      await page.locator('#step-last').click();
      await waitForView(page, (v) => v.step === 17);
      const { program, run } = await cliRun(page);
      assert.ok(run.moves.length > 10 && run.moves.some((m) => m.arc), 'a toolpath with an arc');

      const nc = await exportAs(page, 'nc');
      assert.equal(nc.name, 'O2001.nc');
      assert.equal(readFileSync(nc.path, 'utf8'), program);

      const json = await exportAs(page, 'json');
      assert.equal(json.name, 'O2001-toolpath.json');
      const file = JSON.parse(readFileSync(json.path, 'utf8'));
      assert.deepEqual(file.moves, run.moves, 'the CLI’s moves, field for field');
      assert.deepEqual(file.summary, run.summary);

      const csv = await exportAs(page, 'csv');
      assert.equal(csv.name, 'O2001-toolpath.csv');
      const [header, ...rows] = parseCsv(readFileSync(csv.path, 'utf8'));
      assert.deepEqual(header.slice(0, 10), ['line', 'block', 'kind', 'rate', 'from_x', 'from_y', 'from_z', 'to_x', 'to_y', 'to_z']);
      assert.ok(header.includes('arc_center_x') && header.includes('arc_sweep_degrees'));
      assert.equal(rows.length, run.moves.length);
      // Every field of every move, flattened, is its column.
      const flat = (value, prefix = '', out = {}) => {
        for (const [k, v] of Object.entries(value)) {
          const key = prefix ? `${prefix}_${k}` : k;
          if (v && typeof v === 'object') flat(v, key, out);
          else out[key] = v;
        }
        return out;
      };
      run.moves.forEach((move, i) => {
        const cells = Object.fromEntries(header.map((h, j) => [h, rows[i][j]]));
        for (const [key, value] of Object.entries(flat(move))) {
          if (typeof value === 'number') assert.equal(Number(cells[key]), value, `move ${i} ${key}`);
          else assert.equal(cells[key], value, `move ${i} ${key}`);
        }
        if (!move.arc) assert.equal(cells.arc_plane, '', `move ${i} has no arc`);
      });

      const svg = await exportAs(page, 'svg');
      assert.equal(svg.name, 'O2001.svg');
      const text = readFileSync(svg.path, 'utf8');
      const parsed = await page.evaluate((source) => {
        const doc = new DOMParser().parseFromString(source, 'image/svg+xml');
        const groups = (name) => doc.querySelectorAll(`g.${name}`).length;
        return {
          error: doc.querySelector('parsererror')?.textContent ?? null,
          root: doc.documentElement.localName,
          actual: groups('actual'),
          programmed: groups('programmed'),
          legend: doc.querySelector('g.legend')?.textContent ?? '',
          paths: doc.querySelectorAll('g.actual path, g.actual polyline, g.actual line').length,
        };
      }, text);
      assert.equal(parsed.error, null);
      assert.equal(parsed.root, 'svg');
      assert.equal(parsed.actual, 1);
      assert.equal(parsed.programmed, 1);
      assert.ok(parsed.paths > 0, 'the actual path is drawn');
      // The SVG is the view as shown: at 1280 x 800 the view is under 720 px
      // wide and gets the short legend (src/render/mod.rs COMPACT_BELOW).
      const box = await page.locator('#view').boundingBox();
      const entries = box.width < 720 || box.height < 440
        ? ['mill · XY · mm', 'actual', 'programmed', 'rapid', 'offset']
        : ['mill · XY · mm', 'actual, feed', 'actual, rapid', 'programmed, feed', 'programmed, rapid'];
      for (const entry of entries) {
        assert.ok(parsed.legend.includes(entry), `legend has “${entry}”: ${parsed.legend}`);
      }

      const png = await exportAs(page, 'png');
      assert.equal(png.name, 'O2001.png');
      const image = decode(readFileSync(png.path));
      assert.equal(image.width, Math.round(box.width) * 2, 'device pixels (2x)');
      assert.equal(image.height, Math.round(box.height) * 2);
      const counts = countColors(image);
      assert.ok(counts.actualFeed > 500, `actual feed pixels: ${counts.actualFeed}`);
      assert.ok(counts.programmedFeed > 200, `programmed feed pixels: ${counts.programmedFeed}`);
      assert.ok(counts.actualRapid > 100, `actual rapid pixels: ${counts.actualRapid}`);
      assert.ok(countColor(image, MARKS.arrow) > 50, 'arrows');
      assert.ok(countColor(image, MARKS.tool) > 40, 'the tool marker at the current block');
      assert.ok(countColor(image, COLORS.background) > image.width * image.height * 0.5, 'light background');
      assert.match(await page.locator('#export-status').textContent(), /^Saved O2001\.png$/);
    });
  });

  test('a program without a number is exported as offsetlab.*; a lathe toolpath has no y columns', async () => {
    await withPage(async (page) => {
      const nc = await exportAs(page, 'nc');
      assert.equal(nc.name, 'offsetlab.nc');
      await loadExample(page, 'lathe-seed');
      const { run } = await cliRun(page);
      const csv = await exportAs(page, 'csv');
      assert.equal(csv.name, 'offsetlab-toolpath.csv');
      const [header, ...rows] = parseCsv(readFileSync(csv.path, 'utf8'));
      assert.ok(!header.some((h) => h.endsWith('_y')), header.join(','));
      assert.equal(rows.length, run.moves.length);
      const svg = readFileSync((await exportAs(page, 'svg')).path, 'utf8');
      assert.ok(svg.includes('centre line') && svg.includes('lathe · ZX · mm'));
    });
  });

  test('the CAM example’s G83 holes are rings in the top view and its SVG (behaviour 6.11)', async () => {
    await withPage(async (page) => {
      await loadExample(page, 'cam');
      // N155–N170: G83 at X5 Y5, X35 Y5, X35 Y25, X5 Y25, after H02's
      // length offset (Z only): four rings, at those X Y.
      const svg = readFileSync((await exportAs(page, 'svg')).path, 'utf8');
      const group = svg.split('<g class="holes">')[1]?.split('</g>')[0] ?? '';
      assert.equal((group.match(/<circle /g) ?? []).length, 4, group);
      assert.ok(svg.includes('>hole (canned cycle)<') || svg.includes('>hole<'), 'the legend names them');
      await shoot(page, 'holes-cam');
    });
  });
});
