// Browser end-to-end tests of share links (issue 5, items 2–4): links made
// by `offsetlab link` (compact and plain) open with the same program,
// offsets, settings, plane and step; broken and hostile links show their
// error as text and leave the page usable and the autosaved work intact;
// opening a link keeps the user's work one click away, across a reload; the
// Share button copies a link that decodes back to the document (and falls
// back to a selected field without a clipboard); a long link warns and
// offers the document file, which Open… and drag-drop load again; the
// address bar follows the document with throttled replaceState.
// Screenshots: share.png, link-error.png.

import assert from 'node:assert/strict';
import { mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { deflateRawSync } from 'node:zlib';
import { describe, test } from 'node:test';
import {
  ROOT, cli, decodeLink, loadExample, openIn, savedWork, shoot, typeProgram, useBrowser, waitForLink, waitForRun,
  waitForView,
} from './harness.mjs';

const ctx = useBrowser();
const { withPage } = ctx;
const tmp = mkdtempSync(join(tmpdir(), 'offsetlab-e2e-'));

const MILL_PROGRAM = `%
O4001 (LINK TEST: LENGTH AND POSITION OFFSETS)
G90 G00 X0 Y0 Z50.
G43 Z10. H02
G01 Z-2. F200.
G91 G45 X40. D01
G46 Y30.
/G01 X500.
G90 G00 Z50.
M30
%
`;
const LATHE_PROGRAM = `G50 X120. Z60.
G00 S800 M03 T0108
X50. Z3.
G01 Z-20. F0.2
X80. Z-35.
G00 X120. Z60. T0100
M30
`;
const USER_PROGRAM = 'G90 G00 X10. Y10.;\nG01 X40. F100.;\n';

function file(name, text) {
  const path = join(tmp, name);
  writeFileSync(path, text);
  return path;
}

/** The page's current document (the worker's Session.document()). */
async function pageDocument(page) {
  const { document } = await page.evaluate(() => window.offsetlab.document());
  return document;
}

/** A document as `link --decode` prints it, with the page's null view/step and program filled in. */
function normal(doc) {
  return { program: '', view: null, step: null, ...doc };
}

/** Types the user's own work and waits until it is saved. */
async function ownWork(page) {
  await typeProgram(page, USER_PROGRAM);
  const work = await savedWork(page);
  assert.equal(work.program, USER_PROGRAM);
  return work;
}

describe('opening links', () => {
  test('a compact link made by `offsetlab link` opens with its program, offsets, settings, plane and step; the user’s work stays one click away, across a reload', async () => {
    await withPage(async (page, { context, problems }) => {
      await ownWork(page);
      const setup = file('settings.json', JSON.stringify({
        settings: { block_skip: true, length_offset_without_z: 'next_z' },
        start: { x: 0, y: 0, z: 50 },
      }));
      const link = cli(['link', '--base', ctx.server.url, '--setup', setup, '--offset', '01=5', '--offset', '02=95.3,W-0.05',
        '--plane', 'XZ', '--step', '3', file('o4001.nc', MILL_PROGRAM)]).trim();
      assert.match(link, /^http:\/\/127\.0\.0\.1:\d+\/#v1\./);
      const opened = await openIn(context, link, problems);
      assert.equal(await waitForLink(opened), 'opened');
      await waitForView(opened, (v) => v.plane === 'XZ' && v.step === 3);
      // What the user sees: the program, the offset table, the settings, the plane and the block.
      assert.equal(await opened.evaluate(() => window.offsetlab.program()), MILL_PROGRAM);
      // Offset memory A (the YASNAC profile): one value, 95.3 - 0.05.
      assert.equal(await opened.locator('input[data-field="1.value"]').inputValue(), '5');
      assert.equal(await opened.locator('input[data-field="2.value"]').inputValue(), '95.25');
      assert.equal(await opened.getByLabel('Block skip').isChecked(), true);
      assert.equal(await opened.locator('#set-length_offset_without_z').inputValue(), 'next_z');
      assert.equal(await opened.locator('#plane').inputValue(), 'XZ');
      const run = JSON.parse(cli(['run', '--format', 'json', '--setup', setup, '--offset', '01=5', '--offset', '02=95.3,W-0.05',
        file('o4001-run.nc', MILL_PROGRAM)]));
      assert.equal(await opened.locator('#step-position').textContent(),
        `block 4 of ${run.blocks.length} · line ${run.blocks[3].line}`);
      assert.ok(!run.blocks.some((b) => b.text.includes('X500.')), 'the block skip setting came along');
      assert.match(await opened.locator('#summary').textContent(), / 0 errors /);
      // And the page's document is the link's, field for field.
      assert.deepEqual(await pageDocument(opened), normal(decodeLink(link)));
      // The user's work is kept and offered back.
      const banner = opened.locator('#banner');
      assert.match(await banner.textContent(), /Opened the program of a shared link.*Your previous program is kept/);
      assert.equal(await opened.locator('#restore-previous').isVisible(), true);
      // A reload of the opened link shows it again, the restore button still there.
      await opened.reload();
      assert.equal(await waitForLink(opened), 'opened');
      await waitForView(opened, (v) => v.plane === 'XZ' && v.step === 3);
      assert.equal(await opened.evaluate(() => window.offsetlab.program()), MILL_PROGRAM);
      await opened.locator('#restore-previous').click();
      await waitForRun(opened);
      assert.equal(await opened.evaluate(() => window.offsetlab.program()), USER_PROGRAM);
      assert.equal(await opened.locator('#restore-previous').isVisible(), false);
      assert.equal((await savedWork(opened)).program, USER_PROGRAM);
      await opened.close();
    });
  });

  test('the plain form made by `offsetlab link --plain` opens a lathe program with its offsets and step; so does a hash change', async () => {
    await withPage(async (page) => {
      const link = cli(['link', '--plain', '--base', ctx.server.url, '--machine', 'lathe', '--offset', '08=X0.4,Z-0.2',
        '--step', '2', file('lathe.nc', LATHE_PROGRAM)]).trim();
      assert.ok(link.includes('#program=G50%20X120.%20Z60.%0A'), link);
      assert.ok(link.includes('&machine=lathe') && link.includes('&offset=08:X0.4,Z-0.2') && link.includes('&step=2'), link);
      // Typed into the address bar of the open page: a hash change, no reload.
      await page.evaluate(() => { delete document.body.dataset.link; });
      await page.evaluate((hash) => { location.hash = hash; }, link.slice(link.indexOf('#')));
      assert.equal(await waitForLink(page), 'opened');
      await waitForView(page, (v) => v.plane === 'ZX' && v.step === 2);
      assert.equal(await page.evaluate(() => window.offsetlab.program()), LATHE_PROGRAM);
      assert.equal(await page.locator('#set-machine').inputValue(), 'lathe');
      assert.equal(await page.locator('input[data-field="8.x"]').inputValue(), '0.4');
      assert.equal(await page.locator('input[data-field="8.z"]').inputValue(), '-0.2');
      assert.match(await page.locator('#step-position').textContent(), /^block 3 of 7 · line 3$/);
      assert.deepEqual(await pageDocument(page), normal(decodeLink(link)));
      // The default example was not the user's work: nothing to restore.
      assert.equal(await page.locator('#restore-previous').isVisible(), false);
    });
  });

  test('broken links show their error as text; the page stays usable and the autosaved work intact', async () => {
    await withPage(async (page, { context, problems }) => {
      const work = await ownWork(page);
      const good = cli(['link', '--base', ctx.server.url, '--offset', '01=6', file('o4001b.nc', MILL_PROGRAM)]).trim();
      const payload = good.slice(good.indexOf('#v1.') + 4);
      const packed = (bytes) => `#v1.${deflateRawSync(bytes).toString('base64url')}`;
      let dialogs = 0;
      const onLoad = [
        ['#v1.!!!!', 'link-base64', /not base64url/],
        [`#v1.${payload.slice(0, Math.floor((payload.length - 8) / 4) * 4)}`, 'link-deflate', /does not decompress/],
        ['#v2.AAAA', 'link-version', /newer offsetlab \(format v2\)/],
        ['#program=G00%20X1.&colour=red', 'link-plain', /unknown key `colour`/],
      ];
      for (const [hash, code, message] of onLoad) {
        const broken = await openIn(context, ctx.server.url + hash, problems);
        broken.on('dialog', (d) => { dialogs += 1; d.dismiss(); });
        assert.equal(await waitForLink(broken), 'error', hash);
        assert.equal(await broken.evaluate(() => document.body.dataset.linkError), code);
        const text = await broken.locator('#banner .text').textContent();
        assert.match(text, message, hash);
        assert.match(text, new RegExp(`\\(${code}\\)\\. Your own work is unchanged\\.$`));
        // The user's work is shown and saved as it was.
        assert.equal(await broken.evaluate(() => window.offsetlab.program()), USER_PROGRAM, hash);
        assert.deepEqual(await broken.evaluate(() => JSON.parse(localStorage.getItem('offsetlab.work.v1'))), work);
        if (code === 'link-deflate') await shoot(broken, 'link-error');
        await broken.close();
      }
      // More classes, hostile values and huge payloads, through hash changes on one page.
      const onChange = [
        [packed(Buffer.alloc(3 * 1024 * 1024, 0x20)), 'link-too-large'],
        [packed(Buffer.from([0xff, 0xfe, 0xfd])), 'link-utf8'],
        [packed(Buffer.from('{"program": "G00", ')), 'link-json'],
        [packed(Buffer.from('{"offsets":{"01":5000},"program":"G00"}')), 'link-document'],
        ['#v1.', 'link-empty'],
        ['#program=G00&machine=%3Cimg%20src=x%20onerror=alert(1)%3E', 'link-plain'],
        ['#program=%E2%82', 'link-plain'],
        ['#program=G00&offset=01:<b>6</b>', 'link-plain'],
      ];
      page.on('dialog', (d) => { dialogs += 1; d.dismiss(); });
      for (const [hash, code] of onChange) {
        await page.evaluate(() => { delete document.body.dataset.link; });
        await page.evaluate((h) => { location.hash = h; }, hash);
        assert.equal(await waitForLink(page), 'error', hash.slice(0, 60));
        assert.equal(await page.evaluate(() => document.body.dataset.linkError), code, hash.slice(0, 60));
      }
      // Markup in a value is shown as text, never as markup.
      assert.equal(await page.locator('#banner img, #banner b').count(), 0);
      assert.equal(dialogs, 0, 'no script ran');
      // Still usable: an edit runs and is saved; a good link opens after the broken ones.
      await typeProgram(page, 'G00 X5.;\n');
      assert.match(await page.locator('#summary').textContent(), /^1 block · 1 move · 0 errors/);
      assert.equal((await savedWork(page)).program, 'G00 X5.;\n');
      await page.evaluate(() => { delete document.body.dataset.link; });
      await page.evaluate((h) => { location.hash = h; }, good.slice(good.indexOf('#')));
      assert.equal(await waitForLink(page), 'opened');
      assert.equal(await page.evaluate(() => window.offsetlab.program()), MILL_PROGRAM);
      assert.equal(await page.locator('#banner').getAttribute('data-kind'), 'opened');
      await page.locator('#banner-action').click();
      await waitForRun(page);
      assert.equal(await page.evaluate(() => window.offsetlab.program()), 'G00 X5.;\n');
    });
  });
});

describe('the Share button', () => {
  test('copies the compact link of the document (program, setup, view, step), shows its length; the plain and embed forms decode to it too', async () => {
    await withPage(async (page, { context }) => {
      await context.grantPermissions(['clipboard-read', 'clipboard-write'], { origin: new URL(ctx.server.url).origin });
      await page.locator('input[data-field="1.value"]').fill('7.5');
      await waitForRun(page);
      await page.locator('#plane').selectOption('YZ');
      await page.locator('#zoom-in').click();
      await waitForView(page, (v) => v.plane === 'YZ' && v.zoom > 1.2);
      await page.locator('#step-next').click();
      await page.locator('#step-next').click();
      await waitForView(page, (v) => v.step === 1);
      await page.locator('#share-open').click();
      await page.waitForFunction(() => document.body.dataset.copied === 'true');
      const link = await page.locator('#share-link').inputValue();
      assert.equal(await page.evaluate(() => navigator.clipboard.readText()), link);
      assert.ok(link.startsWith(`${ctx.server.url}#v1.`), link);
      assert.equal(await page.locator('#share-length').textContent(), `${link.length} characters`);
      assert.equal(await page.locator('#share-status').textContent(), 'Copied to the clipboard.');
      assert.equal(await page.locator('#share-warning').isVisible(), false);
      const doc = decodeLink(link);
      assert.equal(doc.offsets['01'], 7.5);
      assert.equal(doc.view.plane, 'YZ');
      assert.equal(doc.view.zoom, 1.25);
      assert.equal(doc.step, 1);
      assert.match(doc.program, /^\(SEED 000: SQUARE/);
      assert.deepEqual(await pageDocument(page), normal(doc));
      await shoot(page, 'share');
      // The plain form, for tutorial authors.
      await page.locator('#share-plain').check();
      await page.waitForFunction(() => document.body.dataset.share === 'plain' && document.body.dataset.copied === 'true');
      const plain = await page.locator('#share-link').inputValue();
      assert.ok(plain.startsWith(`${ctx.server.url}#program=(SEED%20000:`), plain);
      assert.ok(plain.includes('&offset=01:7.5&plane=YZ&zoom=1.25') && plain.endsWith('&step=1'), plain);
      assert.equal(await page.evaluate(() => navigator.clipboard.readText()), plain);
      assert.deepEqual(decodeLink(plain), doc);
      // The embed form with its <iframe> code.
      await page.locator('#share-embed').check();
      await page.waitForFunction(() => document.body.dataset.copied === 'true' && document.getElementById('share-link').value.endsWith('&embed=1'));
      const code = await page.locator('#share-iframe').inputValue();
      assert.match(code, /^<iframe src="http:\/\/127\.0\.0\.1:\d+\/#program=\(SEED%20000:.*&amp;embed=1" width="720" height="420"/);
      await page.locator('#share-close').click();
      assert.equal(await page.locator('#share').isVisible(), false);
    });
  });

  test('without a clipboard the link is selected in its field for the user to copy', async () => {
    await withPage(async (page) => {
      await page.locator('#share-open').click();
      await page.waitForFunction(() => document.body.dataset.copied === 'false');
      assert.match(await page.locator('#share-status').textContent(), /clipboard is not available here.*Ctrl\+C/);
      const selected = await page.evaluate(() => {
        const field = document.getElementById('share-link');
        return document.activeElement === field && field.selectionStart === 0 && field.selectionEnd === field.value.length
          && field.value.includes('#v1.');
      });
      assert.equal(selected, true);
    }, { init: () => Object.defineProperty(Navigator.prototype, 'clipboard', { get: () => undefined }) });
  });

  test('past 8,000 characters it warns and offers the document as a file, which Open… and drag-drop load again', async () => {
    await withPage(async (page, { context, problems }) => {
      // A long program from a file (Open…): random numbers do not compress.
      let seed = 7;
      const random = () => {
        seed = (seed * 48271) % 2147483647;
        return (seed % 200000) / 1000 - 100;
      };
      const lines = ['G90 G00 X0 Y0'];
      for (let i = 0; i < 900; i += 1) lines.push(`G01 X${random().toFixed(3)} Y${random().toFixed(3)} F500.`);
      const program = `${lines.join('\n')}\nM30\n`;
      const chooser = page.waitForEvent('filechooser');
      await page.locator('#open-file-button').click();
      await (await chooser).setFiles(file('long.nc', program));
      await page.waitForFunction(() => document.body.dataset.opened === 'long.nc');
      await waitForRun(page);
      assert.equal(await page.evaluate(() => window.offsetlab.program()), program);
      await page.locator('#share-open').click();
      await page.waitForFunction(() => document.body.dataset.share === 'compact');
      const length = Number(await page.evaluate(() => document.body.dataset.shareLength));
      assert.ok(length > 8000, `${length} characters`);
      assert.match(await page.locator('#share-warning').textContent(), /past 8,000 characters .* Share the document as a file instead/);
      assert.equal(await page.locator('#share-status').textContent(), 'Not copied: the link is too long to share safely.');
      const downloading = page.waitForEvent('download');
      await page.locator('#share-download').click();
      const download = await downloading;
      assert.equal(download.suggestedFilename(), 'offsetlab-document.json');
      const saved = join(tmp, 'long-document.json');
      await download.saveAs(saved);
      const document = JSON.parse(readFileSync(saved, 'utf8'));
      assert.equal(document.program, program);
      assert.equal(document.offsets['01'], 6);
      // The CLI reads it as a setup document with a program.
      assert.match(cli(['check', '--setup', saved]), /0 errors/);
      // A fresh visitor opens the file with Open…
      const other = await openIn(await ctx.browser.newContext(), ctx.server.url, problems);
      await waitForRun(other);
      const chooser2 = other.waitForEvent('filechooser');
      await other.locator('#open-file-button').click();
      await (await chooser2).setFiles(saved);
      await other.waitForFunction(() => document.body.dataset.opened === 'long-document.json');
      await waitForRun(other);
      assert.equal(await other.evaluate(() => window.offsetlab.program()), program);
      await other.context().close();
      // … or drops it on the page (here a lathe document).
      const lathe = cli(['link', '--decode', cli(['link', '--machine', 'lathe', '--offset', '08=X0.4,Z-0.2', file('lathe2.nc', LATHE_PROGRAM)]).trim()]);
      await page.evaluate((text) => {
        const data = new DataTransfer();
        data.items.add(new File([text], 'lathe.json', { type: 'application/json' }));
        document.body.dispatchEvent(new DragEvent('dragover', { dataTransfer: data, bubbles: true, cancelable: true }));
        document.body.dispatchEvent(new DragEvent('drop', { dataTransfer: data, bubbles: true, cancelable: true }));
      }, lathe);
      await page.waitForFunction(() => document.body.dataset.opened === 'lathe.json');
      await waitForRun(page);
      assert.equal(await page.evaluate(() => window.offsetlab.program()), LATHE_PROGRAM);
      assert.equal(await page.locator('#set-machine').inputValue(), 'lathe');
      // A broken document file is refused with its reason; the work stays.
      await page.evaluate(() => {
        const data = new DataTransfer();
        data.items.add(new File(['{"offsets": {"01": 5000}}'], 'bad.json'));
        document.body.dispatchEvent(new DragEvent('drop', { dataTransfer: data, bubbles: true, cancelable: true }));
      });
      await page.waitForFunction(() => document.body.dataset.linkError === 'setup-range');
      assert.match(await page.locator('#banner .text').textContent(), /^The file “bad\.json” could not be opened: .*999\.999/);
      assert.equal(await page.evaluate(() => window.offsetlab.program()), LATHE_PROGRAM);
    });
  });
});

describe('link lengths', () => {
  test('the README table of the examples’ link lengths is what the Share panel gives', async () => {
    const readme = readFileSync(join(ROOT, 'README.md'), 'utf8');
    const block = readme.slice(readme.indexOf('<!-- link-lengths'), readme.indexOf('<!-- /link-lengths -->'));
    const rows = new Map(block.split('\n').filter((l) => l.startsWith('| ') && !l.startsWith('| example') && !l.startsWith('| ---'))
      .map((l) => l.split('|').map((c) => c.trim())).map(([, title, , compact, plain]) => [title, {
        compact: Number(compact.replace(/,/g, '')), plain: Number(plain.replace(/,/g, '')),
      }]));
    await withPage(async (page) => {
      // Every option but the menu's "Choose an example…" (value '').
      const titles = await page.locator('#example option').evaluateAll((os) => os.filter((o) => o.value).map((o) => [o.value, o.textContent]));
      assert.equal(rows.size, titles.length, 'a row per example (node scripts/link-lengths.mjs --write)');
      // The README's lengths are for the default base http://127.0.0.1:8000/.
      const extra = ctx.server.url.length - 'http://127.0.0.1:8000/'.length;
      const serial = () => page.evaluate(() => Number(document.body.dataset.shareSerial ?? 0));
      const refreshed = async (action) => {
        const before = await serial();
        await action();
        await page.waitForFunction((n) => Number(document.body.dataset.shareSerial ?? 0) > n, before);
        return (await page.locator('#share-link').inputValue()).length - extra;
      };
      for (const [id, title] of titles) {
        await loadExample(page, id);
        const compact = await refreshed(() => page.locator('#share-open').click());
        const plain = await refreshed(() => page.locator('#share-plain').check());
        assert.deepEqual({ compact, plain }, rows.get(title), title);
        await refreshed(() => page.locator('#share-plain').uncheck());
        await page.locator('#share-close').click();
      }
    });
  });
});

describe('the address bar', () => {
  test('follows the document with replaceState at most once a second, never pushState; a reload keeps the newest work', async () => {
    await withPage(async (page) => {
      const before = await page.evaluate(() => history.length);
      assert.equal(await page.evaluate(() => location.hash), '', 'nothing written before a change');
      // Zoom, pan and step for about 2.5 s: many view changes.
      const canvas = page.locator('#view');
      await canvas.focus();
      const started = Date.now();
      for (let i = 0; i < 24; i += 1) {
        await page.keyboard.press(i % 3 === 0 ? 'Shift+ArrowLeft' : '+');
        await page.waitForTimeout(100);
      }
      await page.locator('#step-next').click();
      await waitForView(page, (v) => v.step === 0);
      const final = await page.evaluate(() => window.offsetlab.viewState());
      // The last change reaches the address bar after the pause.
      await page.waitForFunction(() => document.body.dataset.addressWrites && location.hash.length > 10
        && !document.body.dataset.pending, null, { timeout: 5000 });
      await page.waitForFunction((z) => {
        const calls = window.__address;
        return calls.length > 0 && Date.now() - calls[calls.length - 1].at > 1200;
      }, final.zoom, { timeout: 5000 });
      const calls = await page.evaluate(() => window.__address);
      const elapsed = Date.now() - started;
      assert.equal(calls.filter((c) => c.kind === 'push').length, 0, 'no pushState');
      const replaces = calls.filter((c) => c.kind === 'replace');
      assert.ok(replaces.length >= 2, `${replaces.length} replaceState calls`);
      assert.ok(replaces.length <= Math.ceil(elapsed / 1000) + 1, `${replaces.length} replaceState calls in ${elapsed} ms`);
      for (let i = 1; i < replaces.length; i += 1) {
        assert.ok(replaces[i].at - replaces[i - 1].at >= 950, `calls ${replaces[i].at - replaces[i - 1].at} ms apart`);
      }
      assert.equal(await page.evaluate(() => history.length), before, 'no history entries');
      // The address carries the last state.
      const doc = decodeLink(await page.evaluate(() => location.href));
      assert.equal(doc.step, 0);
      assert.equal(doc.view.zoom, (await pageDocument(page)).view.zoom);
      assert.ok(Math.abs(doc.view.zoom - final.zoom) / final.zoom < 1e-5);
      // A reload of the tab's own address shows the newest work, no banner.
      await typeProgram(page, 'G00 X7.;\n');
      await savedWork(page);
      await page.reload();
      await waitForRun(page);
      assert.equal(await page.evaluate(() => window.offsetlab.program()), 'G00 X7.;\n');
      assert.equal(await page.locator('#banner').isVisible(), false);
      // A program too long for the address bar (over 256 KiB) leaves it without a fragment.
      const big = `G90 G00 X0 Y0\n${'G01 X10. Y10. F500.\nG01 X0 Y0\n'.repeat(9000)}M30\n`;
      assert.ok(big.length > 256 * 1024);
      const writes = Number(await page.evaluate(() => document.body.dataset.addressWrites ?? 0));
      const chooser = page.waitForEvent('filechooser');
      await page.locator('#open-file-button').click();
      await (await chooser).setFiles(file('big.nc', big));
      await page.waitForFunction((n) => Number(document.body.dataset.addressWrites ?? 0) > n, writes, { timeout: 10_000 });
      assert.equal(await page.evaluate(() => location.href), ctx.server.url, 'no fragment');
    }, {
      init: () => {
        window.__address = [];
        for (const kind of ['push', 'replace']) {
          const original = History.prototype[`${kind}State`];
          History.prototype[`${kind}State`] = function record(...args) {
            window.__address.push({ kind, at: Date.now() });
            return original.apply(this, args);
          };
        }
      },
    });
  });

  test('a reload that took the address before its last write still keeps the newest work', async () => {
    await withPage(async (page) => {
      // Two writes of the address: the first program's, then the second's.
      await typeProgram(page, 'G00 X1.;\n');
      await page.waitForFunction(() => Number(document.body.dataset.addressWrites ?? 0) >= 1 && !document.body.dataset.pending);
      const older = await page.evaluate(() => location.hash);
      await typeProgram(page, 'G00 X2.;\n');
      await page.waitForFunction((h) => location.hash !== h, older, { timeout: 10_000 });
      await savedWork(page);
      // A write that lands while the tab reloads changes the old page's
      // address after the reload took it: the new page opens with the older one.
      await page.evaluate((h) => history.replaceState(history.state, '', h), older);
      await page.reload();
      await waitForRun(page);
      assert.equal(await page.evaluate(() => window.offsetlab.program()), 'G00 X2.;\n');
      assert.equal(await page.locator('#banner').isVisible(), false);
    });
  });
});
