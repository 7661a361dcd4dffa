// Browser end-to-end tests of the program editor (issue 4, items 1 and 7):
// CodeMirror with line numbers, G-code highlighting, undo/redo, diagnostics
// as inline marks with their messages, and the diagnostics list whose
// entries jump to their line:column. Screenshot: error.png.

import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import {
  countDifferences, loadExample, shoot, shootCanvas, typeProgram, useBrowser, waitForRun,
} from './harness.mjs';

const { withPage } = useBrowser();
const drawn = (c) => c.actualFeed > 300 && c.programmedFeed > 150;

describe('editor', () => {
  test('has line numbers and highlights G, M, axis, offset and tool words, comments and N numbers', async () => {
    await withPage(async (page) => {
      const numbers = page.locator('.cm-lineNumbers .cm-gutterElement');
      assert.ok((await numbers.count()) >= 9, 'a line number per line');
      const text = (cls) => page.locator(`.cm-content .${cls}`).allTextContents();
      assert.ok((await text('tok-g')).includes('G47'), 'G words');
      assert.ok((await text('tok-m')).includes('M30'), 'M words');
      assert.deepEqual(await text('tok-offset'), ['D01'], 'the offset word D01 stands apart');
      assert.ok((await text('tok-axis')).includes('X80.'), 'axis words');
      assert.ok((await text('tok-feed')).includes('F200.'), 'feed words');
      assert.match((await text('tok-comment'))[0], /^\(SEED 000/);
      // Colours differ: a G word, an offset word and a comment are painted apart.
      const colours = await page.evaluate(() => ['tok-g', 'tok-offset', 'tok-comment', 'tok-axis'].map(
        (c) => getComputedStyle(document.querySelector(`.cm-content .${c}`)).color,
      ));
      assert.equal(new Set(colours).size, 4, colours.join(' '));
      // The CAM example has N numbers, T and H words.
      await loadExample(page, 'cam');
      assert.ok((await text('tok-n')).includes('N10'));
      assert.ok((await text('tok-tool')).includes('T1'));
      assert.ok((await text('tok-offset')).includes('H01'));
    });
  });

  test('typing a program re-draws it; undo and redo work from the keyboard and the buttons', async () => {
    await withPage(async (page) => {
      const before = await shootCanvas(page, 'before-typing', drawn);
      await typeProgram(page, 'G90 G00 X-20. Y-10.;\nG01 X100. Y0 F300.;\nG02 X100. Y60. R30.;\nG01 X0 Y60.;\nG00 X0 Y0;\n');
      assert.match(await page.locator('#summary').textContent(), /5 blocks · 5 moves · 0 errors/);
      const typed = await shootCanvas(page, 'typed', (c, png) => countDifferences(before.png, png) > 2000 && c.actualFeed > 300);
      assert.ok(countDifferences(before.png, typed.png) > 2000, 'the drawing changed');
      assert.ok(typed.counts.actualRapid > 50);
      // Undo from the keyboard until the seed square is back, redo with the button.
      await page.locator('.cm-content').click();
      for (let i = 0; i < 200; i += 1) {
        const program = await page.evaluate(() => window.offsetlab.program());
        if (program.includes('SEED 000')) break;
        await page.keyboard.press('ControlOrMeta+Z');
      }
      await waitForRun(page);
      assert.match(await page.evaluate(() => window.offsetlab.program()), /SEED 000/);
      assert.match(await page.locator('#summary').textContent(), /^8 blocks/);
      await page.locator('#redo').click();
      await waitForRun(page);
      assert.doesNotMatch(await page.evaluate(() => window.offsetlab.program()), /SEED 000/);
      await page.locator('#undo').click();
      await waitForRun(page);
      assert.match(await page.evaluate(() => window.offsetlab.program()), /SEED 000/);
    });
  });

  test('typed characters replace the selection, land where the cursor is, and undo as one step', async () => {
    await withPage(async (page) => {
      // The editor puts typed characters in itself (not the browser's
      // contenteditable editing): what a user sees must be the same.
      await typeProgram(page, 'G00 X10. Y10.\nG01 X20. F100.\n');
      const program = () => page.evaluate(() => window.offsetlab.program());
      // "20." on line 2 selected with the keys.
      await page.locator('.cm-line').nth(1).click();
      await page.keyboard.press('Home');
      for (let i = 0; i < 5; i += 1) await page.keyboard.press('ArrowRight');
      for (let i = 0; i < 3; i += 1) await page.keyboard.press('Shift+ArrowRight');
      await page.keyboard.type('35.5');
      assert.equal(await program(), 'G00 X10. Y10.\nG01 X35.5 F100.\n');
      await waitForRun(page);
      assert.match(await page.locator('#summary').textContent(), /2 blocks · 2 moves · 0 errors/);
      // The cursor follows the typed text.
      await page.keyboard.type('7');
      assert.equal(await program(), 'G00 X10. Y10.\nG01 X35.57 F100.\n');
      // One undo takes the whole run of typing back, selection and all.
      await page.keyboard.press('ControlOrMeta+Z');
      assert.equal(await program(), 'G00 X10. Y10.\nG01 X20. F100.\n');
      assert.equal(await page.evaluate(() => getSelection().toString()), '20.');
    });
  });

  test('edits go to the worker as changes, and it runs the text the editor shows', async () => {
    // The page sends an edit of the last text sent, not the whole text
    // (a 100k-block program's 3 MB each keystroke): what runs must be
    // what the editor shows, edit after edit.
    const init = () => {
      const W = window.Worker;
      window.__runs = [];
      window.Worker = class extends W {
        postMessage(m, ...rest) {
          if (m && m.type === 'run') window.__runs.push(m.edit ? 'edit' : typeof m.program === 'string' ? 'text' : 'file');
          super.postMessage(m, ...rest);
        }
      };
    };
    await withPage(async (page) => {
      await typeProgram(page, 'G00 X10. Y10.\nG01 X20. F100.\nG01 Y30.\n');
      await page.locator('.cm-line').nth(1).click();
      await page.keyboard.press('End');
      await page.keyboard.type(' Z-1.');
      await page.keyboard.press('ControlOrMeta+Home');
      await page.keyboard.type('N1 ');
      await page.keyboard.press('ControlOrMeta+End');
      await page.keyboard.type('G00 Z5.\n');
      for (let i = 0; i < 4; i += 1) await page.keyboard.press('Shift+ArrowLeft');
      await page.keyboard.press('Backspace');
      await page.keyboard.press('ControlOrMeta+Z');
      await page.keyboard.press('ControlOrMeta+Shift+Z');
      await waitForRun(page);
      const shown = await page.evaluate(() => window.offsetlab.program());
      assert.match(shown, /^N1 G00 X10\. Y10\.\nG01 X20\. F100\. Z-1\.\n/);
      const ran = await page.evaluate(async () => (await window.offsetlab.document()).document.program);
      assert.equal(ran, shown);
      const runs = await page.evaluate(() => window.__runs);
      assert.ok(runs.filter((k) => k === 'edit').length >= 10, runs.join(' '));
    }, { init });
  });

  test('an edit the worker cannot make is answered with the whole text', async () => {
    // The first edit sent is spoilt on its way (its length is wrong): the
    // worker asks for the whole text, and runs what the editor shows.
    const init = () => {
      const W = window.Worker;
      window.__spoilt = 0;
      window.__texts = 0;
      window.Worker = class extends W {
        postMessage(m, ...rest) {
          if (m && m.type === 'run' && m.edit && window.__spoil && !window.__spoilt) {
            window.__spoilt = m.gen;
            super.postMessage({ ...m, edit: { ...m.edit, length: m.edit.length + 1 } }, ...rest);
            return;
          }
          if (m && m.type === 'run' && typeof m.program === 'string') window.__texts += 1;
          super.postMessage(m, ...rest);
        }
      };
    };
    await withPage(async (page) => {
      await typeProgram(page, 'G00 X10. Y10.\nG01 X20. F100.\n');
      await page.evaluate(() => { window.__spoil = true; });
      const texts = await page.evaluate(() => window.__texts);
      await page.keyboard.type('G01 Y5.\n');
      await waitForRun(page);
      assert.ok(await page.evaluate(() => window.__spoilt) > 0, 'an edit was spoilt');
      assert.ok(await page.evaluate(() => window.__texts) > texts, 'the whole text was sent again');
      const shown = await page.evaluate(() => window.offsetlab.program());
      assert.equal(shown, 'G00 X10. Y10.\nG01 X20. F100.\nG01 Y5.\n');
      const ran = await page.evaluate(async () => (await window.offsetlab.document()).document.program);
      assert.equal(ran, shown);
      assert.match(await page.locator('#summary').textContent(), /3 blocks · 3 moves · 0 errors/);
    }, { init });
  });

  test('a syntax error is marked inline with its message and listed with line:column; click and Enter jump to it', async () => {
    await withPage(async (page) => {
      await typeProgram(page, 'G00 X10. Y10.\nG01 X1.2.3 F100.\nG01 X20.\n');
      // Inline: the bad word is underlined and the message follows the line.
      const mark = page.locator('.cm-lintRange-error');
      assert.equal(await mark.count(), 1);
      assert.equal(await mark.textContent(), 'X1.2.3');
      const message = page.locator('.cm-line .cm-diag-message.cm-diag-error');
      assert.match(await message.textContent(), /1\.2\.3/);
      assert.equal(await page.locator('.cm-gutter-lint .cm-lint-marker-error').count(), 1);
      // Listed with severity, code, message and line:column.
      const items = page.locator('#diagnostics li.error');
      assert.equal(await items.count(), 1);
      assert.equal(await items.locator('.loc').textContent(), '2:5');
      assert.equal(await items.locator('.severity').textContent(), 'error');
      assert.equal(await items.locator('.code').textContent(), '[malformed-number]');
      assert.match(await items.locator('.message').textContent(), /1\.2\.3/);
      assert.match(await page.locator('#summary').textContent(), /1 error\b.*stopped at line 2/);
      // Click: the bad word is selected in the editor, which has the focus.
      await items.click();
      assert.equal(await page.evaluate(() => window.offsetlab.selection()), 'X1.2.3');
      assert.ok(await page.evaluate(() => document.activeElement.closest('.cm-editor') !== null));
      // Keyboard: move the cursor away, focus the entry, Enter.
      await page.keyboard.press('ControlOrMeta+Home');
      assert.equal(await page.evaluate(() => window.offsetlab.selection()), '');
      await items.focus();
      await page.keyboard.press('Enter');
      assert.equal(await page.evaluate(() => window.offsetlab.selection()), 'X1.2.3');
      const { counts } = await shootCanvas(page, 'error', (c) => c.actualRapid > 50);
      assert.ok(counts.actualRapid > 50, 'the rapid before the error is drawn');
      await shoot(page, 'error');
    });
  });

  test('a program beyond ASCII runs as written: its error is where the CLI puts it (line:column in characters)', async () => {
    await withPage(async (page) => {
      // The worker writes the program into wasm memory as UTF-8, in a
      // second, larger buffer when the text is not all ASCII
      // (writeProgram in worker.js): both must give the program typed.
      const program = 'G00 X10. (Fräsen — 2 µm, 𝑥 ≤ 3)\n(ß) G01 X1.2.3 F100.\n';
      await page.locator('.cm-content').click();
      await page.keyboard.press('ControlOrMeta+A');
      await page.keyboard.insertText(program);
      await waitForRun(page);
      assert.equal(await page.evaluate(() => window.offsetlab.program()), program);
      const item = page.locator('#diagnostics li.error');
      assert.equal(await item.count(), 1);
      assert.equal(await item.locator('.loc').textContent(), '2:9');
      assert.equal(await item.locator('.code').textContent(), '[malformed-number]');
      assert.equal(await page.locator('.cm-lintRange-error').textContent(), 'X1.2.3');
      assert.match(await page.locator('#summary').textContent(), /^1 block · 1 move · 1 error\b/);
    });
  });

  test('program text in diagnostics and inline messages is text, never markup', async () => {
    await withPage(async (page) => {
      await typeProgram(page, 'G00 X<img src=x onerror=alert(1)>;\n');
      const list = page.locator('#diagnostics');
      assert.ok((await list.locator('li.error').count()) >= 1);
      // (CodeMirror's own img.cm-widgetBuffer has no src.)
      assert.equal(await page.locator('#diagnostics img, .cm-editor img[src], .cm-editor img[onerror]').count(), 0);
      assert.match(await list.textContent(), /</);
    });
  });

  test('a setup problem is listed as "setup" and opens the setup document', async () => {
    await withPage(async (page) => {
      await page.locator('#advanced summary').click();
      await page.locator('#setup').fill('{ "offsets": { "01": "six" } }');
      await waitForRun(page);
      const item = page.locator('#diagnostics li.error').first();
      assert.equal(await item.locator('.loc').textContent(), 'setup');
      assert.match(await item.locator('.code').textContent(), /^\[setup-/);
      assert.match(await page.locator('#summary').textContent(), /stopped: bad setup/);
      await page.locator('#advanced summary').click(); // close it again
      await item.click();
      assert.equal(await page.evaluate(() => document.activeElement.id), 'setup');
      await page.locator('#setup').fill('{ "offsets": { "01": 6.0 } }');
      await waitForRun(page);
      assert.match(await page.locator('#summary').textContent(), /0 errors/);
      await shootCanvas(page, 'setup-fixed', drawn);
    });
  });
});
