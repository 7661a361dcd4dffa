// Browser end-to-end test of embed mode (issue 5, item 5): the <iframe>
// example of docs/tutorials.md, pointed at the test server, inside a lesson
// page served by a second server (another origin): the drawing, the step
// controls and a read-only editor only, filling the frame, the link's step,
// "Open in playground" opening the same document editable in a new tab, and
// the reader's own saved work untouched. Screenshot: embed.png.

import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { after, before, describe, test } from 'node:test';
import {
  COLORS, ROOT, countColor, decode, decodeLink, savedWork, shoot, startServer, typeProgram, useBrowser, waitForRun,
  waitForView, watch,
} from './harness.mjs';

const ctx = useBrowser();
const fixtures = {};
before(async () => {
  fixtures.server = await startServer({ root: join(ROOT, 'tests', 'e2e', 'fixtures') });
});
after(async () => {
  await fixtures.server?.stop();
});

/** The src of the first <iframe> example in docs/tutorials.md (`&amp;` read as `&`). */
function tutorialFrameSrc() {
  const doc = readFileSync(join(ROOT, 'docs', 'tutorials.md'), 'utf8');
  const match = /<iframe\s+src="([^"]+)"/.exec(doc);
  assert.ok(match, 'docs/tutorials.md has an <iframe> example');
  return match[1].replaceAll('&amp;', '&');
}

/** The lesson page with the tutorial's frame pointed at the app under test. */
function lessonUrl(src, { width = 720, height = 420 } = {}) {
  const q = new URLSearchParams({ src, width: String(width), height: String(height) });
  return `${fixtures.server.url}embed.html?${q}`;
}

async function frameReady(page) {
  const handle = await page.locator('#lesson').elementHandle();
  const frame = await handle.contentFrame();
  await frame.waitForFunction(() => document.body.dataset.link === 'opened'
    && document.body.dataset.rendered === document.body.dataset.requested, null, { timeout: 20_000 });
  return frame;
}

describe('embed mode', () => {
  test('inside an <iframe> on a lesson page: drawing, steps and a read-only editor, sized to the frame; Open in playground', async () => {
    await ctx.withPage(async (page, { context, problems }) => {
      // The reader's own work in the playground (same origin as the frame).
      await typeProgram(page, 'G00 X3. Y4.;\n');
      const mine = await savedWork(page);
      const src = tutorialFrameSrc();
      assert.ok(src.startsWith('http://127.0.0.1:8000/#program=') && src.endsWith('&embed=1'), src);
      const appSrc = src.replace('http://127.0.0.1:8000/', ctx.server.url);
      const lesson = await context.newPage();
      watch(lesson, problems);
      await lesson.goto(lessonUrl(appSrc));
      const frame = await frameReady(lesson);
      // The link's program and step (the third block), in embed mode.
      assert.equal(await frame.evaluate(() => window.offsetlab.embed), true);
      assert.match(await frame.evaluate(() => window.offsetlab.program()), /^G90 G00 X-30\. Y-20\.\nG91 G00 G46 X30\. Y20\. D01\n/);
      assert.equal(await frame.evaluate(() => window.offsetlab.setup().offsets['01']), 6);
      await frame.waitForFunction(() => JSON.parse(document.body.dataset.view ?? '{}').step === 2);
      assert.equal(await frame.locator('#step-position').textContent(), 'block 3 of 8 · line 3');
      // The drawing, the step controls, the editor and the current block's
      // state with its sentence (the lesson's teaching content, issue 23);
      // not the playground's tools, offsets, settings or diagnostics.
      for (const hidden of ['#examples', '#share-open', '#open-file-button', '#help-toggle', '#offsets-panel', '#settings-panel', '#diagnostics', '#export', '#undo', '#summary', '#example-note']) {
        assert.equal(await frame.locator(hidden).isVisible(), false, `${hidden} hidden`);
      }
      for (const shown of ['#view', '#step-next', '#step-slider', '#plane', '.cm-content', '#open-playground', '#state-panel .explanation']) {
        assert.equal(await frame.locator(shown).isVisible(), true, `${shown} shown`);
      }
      // Block 3, G01 G47 X80. with D01 = 6: G47 extends the move twice the
      // offset, so the sentence names G47 and the state panel the register.
      const why = await frame.locator('#state-panel .explanation').textContent();
      assert.match(why, /G47/, why);
      // It is inside the frame, under the program (the left column).
      const placed = await frame.evaluate(() => {
        const b = document.querySelector('#state-panel .explanation').getBoundingClientRect();
        const e = document.getElementById('editor').getBoundingClientRect();
        return { top: b.top, bottom: b.bottom, left: b.left, editorBottom: e.bottom, innerWidth, innerHeight };
      });
      assert.ok(placed.top >= placed.editorBottom && placed.bottom <= placed.innerHeight
        && placed.left < placed.innerWidth / 2, JSON.stringify(placed));
      // Sized to its frame: nothing scrolls, the drawing takes most of it.
      const fit = await frame.evaluate(() => ({
        width: document.documentElement.scrollWidth, height: document.documentElement.scrollHeight,
        innerWidth, innerHeight, view: document.getElementById('view').getBoundingClientRect().toJSON(),
      }));
      assert.ok(fit.width <= fit.innerWidth && fit.height <= fit.innerHeight, JSON.stringify(fit));
      assert.ok(fit.view.width > fit.innerWidth * 0.5 && fit.view.height > fit.innerHeight * 0.6, JSON.stringify(fit));
      // The path is drawn.
      const png = decode(await frame.locator('#view').screenshot());
      assert.ok(countColor(png, COLORS.actualFeed) > 300, 'actual feed drawn');
      await shoot(lesson, 'embed');
      // The editor is read-only: typing changes nothing; a click on a line selects its block.
      await frame.locator('.cm-line').nth(4).click();
      await frame.waitForFunction(() => JSON.parse(document.body.dataset.view).step === 4);
      await lesson.keyboard.type('X99. ');
      await lesson.keyboard.press('Backspace');
      await lesson.keyboard.press('Enter');
      assert.match(await frame.evaluate(() => window.offsetlab.program()), /^G90 G00 X-30\. Y-20\.\n/);
      assert.equal(await frame.evaluate(() => window.offsetlab.program()).then((p) => p.includes('X99')), false);
      assert.equal(await frame.locator('.cm-content').getAttribute('aria-readonly'), 'true');
      // Steps work.
      await frame.locator('#step-next').click();
      await frame.waitForFunction(() => JSON.parse(document.body.dataset.view).step === 5);
      // The frame shares the app's storage here (same site), and wrote nothing to it.
      const stored = await frame.evaluate(() => JSON.parse(localStorage.getItem('offsetlab.work.v1')));
      assert.deepEqual(stored, mine);
      assert.equal(await frame.evaluate(() => localStorage.getItem('offsetlab.previous.v1')), null);
      // Open in playground: the same document without embed, in a new tab.
      const link = frame.locator('#open-playground');
      assert.equal(await link.getAttribute('target'), '_blank');
      const href = await link.getAttribute('href');
      assert.ok(!href.includes('embed'), href);
      const embedded = decodeLink(appSrc);
      assert.deepEqual(decodeLink(href), embedded);
      const opening = context.waitForEvent('page');
      await link.click();
      const playground = await opening;
      watch(playground, problems);
      await playground.waitForFunction(() => document.body.dataset.link === 'opened', null, { timeout: 20_000 });
      await waitForRun(playground);
      assert.equal(await playground.evaluate(() => window.offsetlab.embed), false);
      assert.equal(await playground.evaluate(() => window.offsetlab.program()), embedded.program);
      assert.equal(await playground.locator('.panels').isVisible(), true);
      await waitForView(playground, (v) => v.step === 2);
      // The reader's work is kept there (Restore).
      assert.equal(await playground.locator('#restore-previous').isVisible(), true);
      await playground.close();
      const previous = await page.evaluate(() => JSON.parse(localStorage.getItem('offsetlab.previous.v1')));
      assert.equal(previous.program, mine.program);
      // The saved value is a document: its setup is every field but the program, view, step and page extras.
      const setupOf = ({ program, view, step, page: extras, ...setup }) => setup;
      assert.deepEqual(setupOf(previous), setupOf(mine));
      assert.ok(Object.keys(setupOf(mine)).includes('version'), JSON.stringify(mine));
      // A narrow frame puts the drawing above the program.
      await lesson.goto(lessonUrl(appSrc, { width: 380, height: 520 }));
      const narrow = await frameReady(lesson);
      const boxes = await narrow.evaluate(() => ({
        view: document.getElementById('view').getBoundingClientRect().toJSON(),
        editor: document.getElementById('editor').getBoundingClientRect().toJSON(),
        height: document.documentElement.scrollHeight,
      }));
      assert.ok(boxes.view.bottom <= boxes.editor.top, JSON.stringify(boxes));
      assert.ok(boxes.height <= 520, JSON.stringify(boxes));
      await lesson.close();
    });
  });
});
