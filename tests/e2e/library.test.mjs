// Browser end-to-end test of the setup's library of programs (issue 22
// item 1, behaviour 9.10 and 19.10): the main program calls O1002, which
// the editor does not hold; pasted into the settings panel's library it is
// called, stepping into it shows its own line and text, the saved work
// keeps it, and removing it brings the alarm back. Screenshot: library.png.
// Files opened several at once, a folder, or files dropped on the library
// fill it too (issue 33 point 5), each file left out named with its reason.
// Screenshot: library-files.png.

import assert from 'node:assert/strict';
import { mkdtempSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { describe, test } from 'node:test';
import { savedWork, shoot, stateText, typeProgram, useBrowser, waitForRun, waitForView } from './harness.mjs';

const { withPage } = useBrowser();

const MAIN = ['O1000', 'G90 G00 X0 Y0 Z0', 'M98 P1002 L2', 'M30'].join('\n');
const STEP = ['O1002', 'G91 G01 X10. F100', 'M99'].join('\n');

// Files are read asynchronously: wait for the library's count of finished
// readings, then for the run their programs started.
async function filesRead(page, n) {
  await page.waitForFunction((k) => Number(document.getElementById('library')?.dataset.reads) >= k, n);
  await waitForRun(page);
}

describe('library', () => {
  test('a program pasted into the library is called, stepped into and kept', async () => {
    await withPage(async (page) => {
      await typeProgram(page, MAIN);
      // Nothing holds O1002 yet: PS0076 at the M98.
      assert.match(await page.locator('#diagnostics').textContent(), /program-not-found|PS0076/);
      await page.locator('#library > summary').click();
      await page.locator('#library-paste').fill(STEP);
      await page.locator('#library-add').click();
      await waitForRun(page);
      assert.equal(await page.locator('#library-list li').count(), 1);
      assert.match(await page.locator('#library-list li').textContent(), /O1002 — G91 G01 X10\. F100/);
      // Blocks: O1000 (0), G90 (1), M98 (2), O1002's header (3), its G01
      // (4) at X0 + 10 = 10.
      for (let i = 0; i <= 4; i += 1) await page.locator('#step-next').click();
      await waitForView(page, (v, a) => v.step === a, 4);
      assert.equal(await stateText(page, 'block'), 'O1002 line 2: G91 G01 X10. F100');
      assert.match(await stateText(page, 'program'), /O1002/);
      assert.match(await stateText(page, 'programmed'), /X10\.000/);
      await shoot(page, 'library');
      const saved = await savedWork(page);
      assert.match(JSON.stringify(saved), /O1002\\nG91 G01 X10\. F100/);
      // Removed, the call has nothing to call again.
      await page.locator('#library-list button[data-program="1002"]').click();
      await waitForRun(page);
      assert.equal(await page.locator('#library-list li').count(), 0);
      assert.match(await page.locator('#diagnostics').textContent(), /program-not-found|PS0076/);
    });
  });

  test('files opened, a folder opened and files dropped fill the library, each left out file said', async () => {
    await withPage(async (page) => {
      const MACRO = ['O3001', 'G91 G01 Y#1', 'M99'].join('\n');
      await typeProgram(page, [...MAIN.split('\n').slice(0, 3), 'G65 P3001 A3.', 'M30'].join('\n'));
      await page.locator('#library > summary').click();
      // Two files at once: one program each, and a note without a header.
      await page.locator('#library-files').setInputFiles([
        { name: 'o1002.nc', mimeType: 'text/plain', buffer: Buffer.from(`%\n${STEP}\n%\n`) },
        { name: 'notes.txt', mimeType: 'text/plain', buffer: Buffer.from('cut it twice\n') },
      ]);
      await filesRead(page, 1);
      assert.equal(await page.locator('#library-list li').count(), 1);
      const said = await page.locator('#library-reason').textContent();
      assert.match(said, /1 program added/);
      assert.match(said, /notes\.txt: left out, no program header/);
      // A folder: O3001 new, O1002 again (the first kept, and said).
      const dir = mkdtempSync(join(tmpdir(), 'offsetlab-library-'));
      writeFileSync(join(dir, 'macro.nc'), MACRO);
      writeFileSync(join(dir, 'step.nc'), STEP);
      await page.locator('#library-folder').setInputFiles(dir);
      await filesRead(page, 2);
      assert.equal(await page.locator('#library-list li').count(), 2);
      assert.match(await page.locator('#library-reason').textContent(), /O1002 is in the library already/);
      // O1002 twice (X 0 + 10 + 10 = 20), then O3001 with A3.: Y 0 + 3 = 3;
      // no alarm left.
      assert.doesNotMatch(await page.locator('#diagnostics').textContent(), /program-not-found|PS0076/);
      await shoot(page, 'library-files');
      // Dropped on the library: a file's programs join it.
      await page.locator('#library-list button[data-program="3001"]').click();
      await waitForRun(page);
      const drop = await page.evaluateHandle((text) => {
        const t = new DataTransfer();
        t.items.add(new File([text], 'macro.nc', { type: 'text/plain' }));
        return t;
      }, MACRO);
      await page.dispatchEvent('#library', 'drop', { dataTransfer: drop });
      await filesRead(page, 3);
      assert.equal(await page.locator('#library-list li').count(), 2);
      assert.match(await page.locator('#library-list').textContent(), /O3001 — G91 G01 Y#1/);
      const saved = JSON.stringify(await savedWork(page));
      assert.match(saved, /O3001\\nG91 G01 Y#1/);
    });
  });
});
