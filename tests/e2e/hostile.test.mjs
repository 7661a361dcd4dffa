// Browser end-to-end tests of reliability and security (issue 7, items 3–5):
// the Content-Security-Policy is in force and normal use violates nothing;
// programs, links and diagnostics carrying markup are shown as text (no
// element made from them, no dialog); hostile links are refused with a
// message, and embed mode's "Open in playground" stays an http(s) link of
// the page; a runaway run is stopped at the time budget and a crashed worker
// is replaced, with the page's state restored and no restart loop; the
// autosave survives a bad link, a crash and reloads; a full or disabled
// storage says so; every file of the hostile corpus (tests/data/hostile/)
// opens through Open… with the page usable.
// Screenshots: runaway-stopped.png, hostile-link-refused.png.
//
// The runaway and the crashes are made with the worker's test faults: with
// `window.offsetlabTest = { hooks: true }` set by an init script, a program
// containing `(offsetlab-test-fault: KIND)` makes the worker spin (hang),
// throw what a WebAssembly trap throws (trap; trap-in-first-worker only in
// the page's first worker), throw an uncaught error (error), or close itself
// (exit) — www/worker.js fault(). `budgetMs` shortens the time budget.

import assert from 'node:assert/strict';
import { mkdtempSync, readFileSync, readdirSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { describe, test } from 'node:test';
import {
  COLORS, ROOT, cli, countColor, decode, openIn, savedWork, shoot, typeProgram, useBrowser, viewOf, waitForLink,
  waitForRun, waitForView,
} from './harness.mjs';

const ctx = useBrowser();
const { withPage } = ctx;
const tmp = mkdtempSync(join(tmpdir(), 'offsetlab-hostile-'));

/** Init script: the test hooks with a short time budget (ms). */
const hooks = (budgetMs) => ({
  init: `window.offsetlabTest = { hooks: true, budgetMs: ${budgetMs} };`,
});

/** Replaces the program with `text` in one edit (as a paste), without waiting for its run. */
async function pasteProgram(page, text) {
  await page.locator('.cm-content').click();
  await page.keyboard.press('ControlOrMeta+A');
  await page.keyboard.insertText(text);
}

/** Waits until the page says the interpreter was stopped (`kind`: hang, crash, start). */
async function waitForStopped(page, kind, timeout = 20_000) {
  await page.waitForFunction((k) => document.body.dataset.stopped === k, kind, { timeout });
}

/** Waits until the (restarted) interpreter has loaded, so a reload does not abort its loading. */
async function interpreterReady(page) {
  await page.waitForFunction(() => document.body.dataset.interpreter === 'ready');
}

/** The canvas shows the actual path (feed colour) within a few frames. */
async function drawn(page) {
  for (let i = 0; i < 50; i += 1) {
    const png = decode(await page.locator('#view').screenshot());
    if (countColor(png, COLORS.actualFeed) > 100) return true;
    await page.waitForTimeout(100);
  }
  return false;
}

/**
 * Elements the page's own markup and code make: anything else came from
 * data. (CodeMirror puts empty `<img class="cm-widgetBuffer">` beside its
 * widgets, the messages at the end of lines; those have no source.)
 */
async function foreignElements(page) {
  return page.evaluate(() => ({
    scripts: [...document.querySelectorAll('script')].map((s) => s.getAttribute('src')),
    imgs: [...document.querySelectorAll('img')].filter((i) => !i.classList.contains('cm-widgetBuffer') || i.hasAttribute('src')).length,
    handlers: document.querySelectorAll('[onerror], [onload], [onclick], [srcdoc]').length,
    iframes: document.querySelectorAll('iframe').length,
    svgs: document.querySelectorAll('svg').length,
    bold: document.querySelectorAll('b').length,
    injected: window.__offsetlabInjected === true,
  }));
}

const NO_FOREIGN = { scripts: ['main.js'], imgs: 0, handlers: 0, iframes: 0, svgs: 0, bold: 0, injected: false };

/** Counts dialogs (alert, confirm, prompt) of `page`, dismissing them. */
function countDialogs(page) {
  const seen = { n: 0 };
  page.on('dialog', (dialog) => {
    seen.n += 1;
    dialog.dismiss().catch(() => {});
  });
  return seen;
}

describe('Content-Security-Policy', () => {
  test('the policy is in force (no inline script, no eval) and loading, typing, stepping, sharing and exporting violate nothing', async () => {
    await withPage(async (page, { problems }) => {
      // The same policy as a <meta> tag and as the server's header.
      const meta = await page.locator('meta[http-equiv="Content-Security-Policy"]').getAttribute('content');
      for (const directive of ["default-src 'self'", "script-src 'self' 'wasm-unsafe-eval'", "object-src 'none'",
        "base-uri 'none'", "form-action 'none'", "worker-src 'self'"]) {
        assert.ok(meta.includes(directive), `${directive} in ${meta}`);
      }
      assert.ok(!/script-src[^;]*'unsafe-(inline|eval)'/.test(meta), 'no unsafe script sources');
      const response = await page.reload();
      await waitForRun(page);
      assert.equal(response.headers()['content-security-policy'], meta.replace(/\s+/g, ' ').trim());

      // Normal use: type, step, share, export (PNG, SVG, CSV), another example.
      await typeProgram(page, 'G90 G00 X0 Y0;\nG01 G45 X30. D01 F100.;\nG01 Y20.;\n');
      await page.locator('#step-first').click();
      await waitForView(page, (v) => v.step === 0);
      await page.locator('#step-last').click();
      await waitForView(page, (v) => v.step === 2);
      await page.locator('#share-open').click();
      await page.waitForFunction(() => ['compact', 'failed'].includes(document.body.dataset.share));
      assert.equal(await page.evaluate(() => document.body.dataset.share), 'compact');
      await page.locator('#share-close').click();
      for (const format of ['png', 'svg', 'csv']) {
        await page.locator('#export > summary').click();
        const downloading = page.waitForEvent('download');
        await page.locator(`#export button[data-export="${format}"]`).click();
        await (await downloading).path();
      }
      await page.locator('#example').selectOption('lathe-seed');
      await page.locator('#load-example').click();
      await waitForRun(page);
      assert.deepEqual(await page.evaluate(() => window.__violations), [], 'no violation in normal use');

      // Enforced: an inline script and an inline handler do not run, eval
      // throws, and each is reported. (Run from a timer: code evaluated by
      // the test driver itself may use eval while it is on the stack.)
      const attempt = await page.evaluate(() => new Promise((resolve) => {
        setTimeout(() => {
          let evalRefused = false;
          try {
            (0, eval)('window.__offsetlabInjected = true');
          } catch (error) {
            evalRefused = error instanceof EvalError;
          }
          const script = document.createElement('script');
          script.textContent = 'window.__offsetlabInjected = true;';
          document.body.append(script);
          const handler = document.createElement('div');
          document.body.append(handler);
          handler.setAttribute('onclick', 'window.__offsetlabInjected = true');
          handler.click();
          script.remove();
          handler.remove();
          setTimeout(() => resolve({
            evalRefused, injected: window.__offsetlabInjected === true, violations: window.__violations,
          }), 200);
        });
      }));
      assert.equal(attempt.evalRefused, true, 'eval refused');
      assert.equal(attempt.injected, false, 'no injected code ran');
      assert.ok(attempt.violations.some((v) => v.startsWith('script-src') && v.includes('eval')), JSON.stringify(attempt.violations));
      assert.ok(attempt.violations.some((v) => v.startsWith('script-src') && v.includes('inline')), JSON.stringify(attempt.violations));
      // The console reports the refusals this test provoked, and nothing else.
      const provoked = /Refused to (evaluate a string as JavaScript|execute inline (script|event handler))|Content Security Policy/;
      const others = problems.filter((p) => !provoked.test(p));
      problems.length = 0;
      problems.push(...others);
    }, {
      init: () => {
        window.__violations = [];
        document.addEventListener('securitypolicyviolation', (event) => {
          window.__violations.push(`${event.effectiveDirective} ${event.blockedURI} ${event.sourceFile}:${event.lineNumber}`);
        });
      },
    });
  });
});

describe('markup in programs, diagnostics and links is text', () => {
  // Parentheses end a comment, so these two make diagnostics that quote markup.
  const ERRORS = 'G00 X1. (<script>alert(1)</script>)\nG00 Y1. (<img src=x onerror=alert(1)>)\n';
  // Comments without parentheses inside: blocks that run, markup in their text.
  const RUNS = 'G90 G00 X0 Y0 (<b>bold</b> <img src=x onerror=alert`1`>)\nG01 X40. Y20. F100. (<script>window.__offsetlabInjected=true</script>)\nM30\n';

  test('a program with <script> and <img onerror> is shown literally in the editor, the diagnostics and the state panel', async () => {
    await withPage(async (page) => {
      const dialogs = countDialogs(page);
      await pasteProgram(page, ERRORS);
      await waitForRun(page);
      assert.equal(await page.evaluate(() => window.offsetlab.program()), ERRORS);
      const editorText = await page.locator('.cm-content').textContent();
      assert.ok(editorText.includes('(<script>alert(1)</script>)'), editorText);
      assert.ok(editorText.includes('(<img src=x onerror=alert(1)>)'), editorText);
      const diagnostics = await page.locator('#diagnostics').textContent();
      assert.match(diagnostics, /`<` is not part of a word/);
      assert.match(diagnostics, /`>` is not part of a word/);
      assert.ok(await page.locator('#diagnostics li').count() > 2);
      // The messages at the end of the editor's lines are text too.
      assert.match(await page.locator('.cm-diag-message').first().textContent(), /`<`|`>`|number/);

      await pasteProgram(page, RUNS);
      await waitForRun(page);
      assert.match(await page.locator('#summary').textContent(), /^3 blocks · 1 move · 0 errors/);
      await page.locator('#step-first').click();
      await waitForView(page, (v) => v.step === 0);
      assert.equal(await page.locator('#state-panel dd[data-key="block"]').textContent(),
        'line 1: G90 G00 X0 Y0 (<b>bold</b> <img src=x onerror=alert`1`>)');
      await page.locator('#step-next').click();
      await waitForView(page, (v) => v.step === 1);
      assert.equal(await page.locator('#state-panel dd[data-key="block"]').textContent(),
        'line 2: G01 X40. Y20. F100. (<script>window.__offsetlabInjected=true</script>)');
      assert.ok(await page.getByText('(<script>window.__offsetlabInjected=true</script>)').first().isVisible());
      assert.deepEqual(await foreignElements(page), NO_FOREIGN);
      assert.equal(dialogs.n, 0, 'no dialog');
    });
  });

  test('a link carrying such a program opens it as text; embedded, "Open in playground" is an http link of the page', async () => {
    await withPage(async (page, { context, problems }) => {
      const linkTo = (name, text, ...args) => {
        const file = join(tmp, name);
        writeFileSync(file, text);
        return cli(['link', '--base', ctx.server.url, ...args, file]).trim();
      };
      // The program with errors: the editor and the diagnostics.
      let opened = await openIn(context, linkTo('errors.nc', ERRORS), problems);
      let dialogs = countDialogs(opened);
      assert.equal(await waitForLink(opened), 'opened');
      assert.equal(await opened.evaluate(() => window.offsetlab.program()), ERRORS);
      const editorText = await opened.locator('.cm-content').textContent();
      assert.ok(editorText.includes('(<script>alert(1)</script>)') && editorText.includes('(<img src=x onerror=alert(1)>)'), editorText);
      assert.match(await opened.locator('#diagnostics').textContent(), /`<` is not part of a word/);
      assert.deepEqual(await foreignElements(opened), NO_FOREIGN);
      assert.equal(dialogs.n, 0);
      await opened.close();
      // The program that runs, at its second block: the state panel.
      const link = linkTo('runs.nc', RUNS, '--step', '1');
      opened = await openIn(context, link, problems);
      dialogs = countDialogs(opened);
      assert.equal(await waitForLink(opened), 'opened');
      assert.equal(await opened.evaluate(() => window.offsetlab.program()), RUNS);
      await waitForView(opened, (v) => v.step === 1);
      assert.match(await opened.locator('#state-panel dd[data-key="block"]').textContent(), /\(<script>window\.__offsetlabInjected=true<\/script>\)$/);
      assert.deepEqual(await foreignElements(opened), NO_FOREIGN);
      assert.equal(dialogs.n, 0);
      await opened.close();

      // Embed mode: the same document read-only; its way out is this page's own http link.
      const embedded = await openIn(context, `${link}&embed=1`, problems);
      assert.equal(await waitForLink(embedded), 'opened');
      assert.equal(await embedded.evaluate(() => window.offsetlab.embed), true);
      const href = await embedded.locator('#open-playground').getAttribute('href');
      assert.ok(href.startsWith(ctx.server.url + '#v1.'), href);
      assert.ok(!/javascript:|embed/i.test(href), href);
      assert.ok((await embedded.locator('.cm-content').textContent()).includes('<b>bold</b>'));
      assert.deepEqual(await foreignElements(embedded), NO_FOREIGN);
      await embedded.close();
    });
  });

  test('links with markup, javascript: URLs, huge and truncated payloads are refused with a message as text; the work and its autosave stay', async () => {
    await withPage(async (page, { context, problems }) => {
      await typeProgram(page, 'G90 G00 X12. Y8.;\nG01 X30. F100.;\n');
      const work = await savedWork(page);
      const good = cli(['link', '--base', ctx.server.url, join(ROOT, 'tests', 'data', 'hostile', 'truncated-mid-word.nc')]).trim();
      const payload = good.slice(good.indexOf('#v1.') + 4);
      const refused = [
        ['#javascript:alert(1)', 'link-plain'],
        ['#javascript:alert(document.domain)//&embed=1', 'link-plain'],
        ['#v1.<script>alert(1)</script>', 'link-base64'],
        ['#program=G00&machine=%3Cscript%3Ealert(1)%3C%2Fscript%3E', 'link-plain'],
        ['#program=G00&embed=javascript:alert(1)', 'link-plain'],
        [`#v1.${payload.slice(0, Math.floor(payload.length / 2 / 4) * 4)}`, 'link-deflate'],
        // Huge: near the longest address Chromium opens (2 MiB).
        [`#v1.${'A'.repeat(1_900_000)}`, null],
      ];
      for (const [hash, code] of refused) {
        const tab = await openIn(context, ctx.server.url + hash, problems);
        const dialogs = countDialogs(tab);
        assert.equal(await waitForLink(tab), 'error', hash.slice(0, 60));
        const shown = await tab.evaluate(() => document.body.dataset.linkError);
        if (code) assert.equal(shown, code, hash.slice(0, 60));
        else assert.match(shown, /^link-/);
        const banner = tab.locator('#banner .text');
        assert.ok(await banner.isVisible());
        // Embedded (`&embed=1`), the page neither shows nor touches the saved work.
        const embed = /&embed=1$/.test(hash);
        assert.match(await banner.textContent(), embed
          ? /^This link could not be opened: .+\(link-[a-z0-9-]+\)\.$/s
          : /^This link could not be opened: .+\(link-[a-z0-9-]+\)\. Your own work is unchanged\.$/s);
        if (hash.includes('machine=%3Cscript')) {
          // The markup of the link is quoted in the message, as text.
          assert.match(await banner.textContent(), /`<script>alert\(1\)<\/script>`/);
          await shoot(tab, 'hostile-link-refused');
        }
        // The work is the user's, shown and saved as it was; the page still runs programs.
        assert.equal(await tab.evaluate(() => window.offsetlab.program()), embed ? '' : work.program);
        assert.deepEqual(await tab.evaluate(() => JSON.parse(localStorage.getItem('offsetlab.work.v1'))), work);
        assert.deepEqual(await foreignElements(tab), NO_FOREIGN);
        assert.equal(dialogs.n, 0);
        await tab.close();
      }
      // The autosave survives the bad links and a reload.
      await page.reload();
      await waitForRun(page);
      assert.equal(await page.evaluate(() => window.offsetlab.program()), work.program);
      await typeProgram(page, 'G00 X3.;\n');
      assert.match(await page.locator('#summary').textContent(), /^1 block · 1 move · 0 errors/);
    });
  });
});

describe('worker supervision', () => {
  test('the time budget is 30 s, as the README says', () => {
    const page = readFileSync(join(ROOT, 'www', 'modules', 'page.js'), 'utf8');
    assert.match(page, /export const BUDGET_MS = positive\(TEST\?\.budgetMs\) \?\? 30_000;/);
    const readme = readFileSync(join(ROOT, 'README.md'), 'utf8');
    assert.ok(readme.includes("| time per task of the page's worker | 30 s |"), 'README Limits row');
    assert.ok(readme.includes('that takes longer than 30 s is stopped'), 'README page section');
  });

  test('a runaway run is stopped at the time budget; the page keeps its state and draws again after an edit', async () => {
    await withPage(async (page) => {
      await typeProgram(page, 'G90 G00 X0 Y0;\nG01 X40. Y20. F100.;\n');
      await page.locator('#zoom-in').click();
      const zoomed = await waitForView(page, (v) => v.zoom > 1.2);
      await page.evaluate(() => { document.getElementById('view').offsetlabFirst = true; });
      // Its attributes but the pixel size (the worker sets that, after the banner moved the layout).
      const attributesOf = (c) => [...c.attributes].map((a) => `${a.name}=${a.value}`).filter((a) => !/^(width|height)=/.test(a));
      const canvasAttributes = await page.locator('#view').evaluate(attributesOf);

      const runaway = 'G90 G00 X0 Y0;\nG01 X40. Y20. F100.;\n(offsetlab-test-fault: hang)\n';
      await pasteProgram(page, runaway);
      await waitForStopped(page, 'hang');
      const message = 'The run took longer than 1.5 s and was stopped; the page is usable — edit the program (or its setup) and it runs again.';
      assert.equal(await page.locator('#banner .text').textContent(), message);
      assert.equal(await page.locator('#banner').isVisible(), true);
      assert.equal(await page.locator('#summary').textContent(), message);
      assert.equal(await page.locator('#diagnostics li').textContent(), message);
      assert.equal(await page.locator('#step-position').textContent(), 'no blocks ran');
      // A new <canvas> in place of the handed-over one, with the same attributes.
      assert.equal(await page.locator('canvas').count(), 1);
      assert.equal(await page.evaluate(() => document.getElementById('view').offsetlabFirst), undefined, 'a new canvas');
      assert.deepEqual(await page.locator('#view').evaluate(attributesOf), canvasAttributes);
      // The work is kept (and saved), and not run again by itself: no restart loop.
      assert.equal(await page.evaluate(() => window.offsetlab.program()), runaway);
      assert.equal((await savedWork(page)).program, runaway);
      await page.waitForTimeout(2500);
      assert.equal(await page.evaluate(() => document.body.dataset.failures), '1');
      assert.equal(await page.evaluate(() => document.body.dataset.restarts), '1');
      await shoot(page, 'runaway-stopped');
      // Share and export say why they cannot work yet; the page is otherwise usable.
      await page.locator('#share-open').click();
      await page.waitForFunction(() => document.body.dataset.share === 'failed');
      assert.match(await page.locator('#share-status').textContent(), /stopped the interpreter/);
      await page.locator('#share-close').click();

      // An edit runs again and draws, in the view the page had (zoom), on the new canvas.
      await typeProgram(page, 'G90 G00 X0 Y0;\nG01 X40. Y20. F100.;\nG01 X0 Y0;\n');
      assert.match(await page.locator('#summary').textContent(), /^3 blocks · 2 moves · 0 errors/);
      assert.equal(await page.locator('#banner').isVisible(), false);
      assert.equal(await page.evaluate(() => document.body.dataset.stopped), undefined);
      assert.ok(await drawn(page), 'the path is drawn');
      assert.ok(Math.abs((await viewOf(page)).zoom - zoomed.zoom) < 1e-6, 'the view is restored');
      // The new canvas has the drawing's input: the wheel zooms, the keys step.
      const box = await page.locator('#view').boundingBox();
      await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
      await page.mouse.wheel(0, -300);
      await waitForView(page, (v, z) => v.zoom > z * 1.2, zoomed.zoom);
      await page.locator('#view').focus();
      await page.keyboard.press('Home');
      await waitForView(page, (v) => v.step === 0);
      assert.equal(await page.locator('#step-position').textContent(), 'block 1 of 3 · line 1');
    }, hooks(1500));
  });

  test('a crashed worker is replaced: after a trap, an uncaught error or a silent death the program runs once more, then is left until an edit', async () => {
    await withPage(async (page) => {
      for (const [kind, pattern] of [
        ['trap', /^The interpreter crashed again on this program \(unreachable \(test fault\)\)/],
        ['error', /^The interpreter crashed again on this program \(.*test fault: an uncaught error/],
        // The worker ends without a word: its Web Lock tells the page at once.
        ['exit', /^The interpreter crashed again on this program \(its worker stopped\)/],
      ]) {
        const before = Number(await page.evaluate(() => document.body.dataset.failures ?? 0));
        await pasteProgram(page, `G00 X${kind.length}.;\n(offsetlab-test-fault: ${kind})\n`);
        await waitForStopped(page, 'crash');
        // Twice: the crash and the one retry; then no more.
        await page.waitForTimeout(1000);
        assert.equal(Number(await page.evaluate(() => document.body.dataset.failures)), before + 2, kind);
        assert.match(await page.locator('#banner .text').textContent(), pattern);
        assert.match(await page.locator('#summary').textContent(), pattern);
        // An edit runs and draws.
        await typeProgram(page, 'G90 G00 X0 Y0;\nG01 X30. Y30. F100.;\n');
        assert.match(await page.locator('#summary').textContent(), /^2 blocks · 1 move · 0 errors/);
        assert.ok(await drawn(page), `drawn after the ${kind}`);
        assert.equal(await page.locator('#banner').isVisible(), false);
        assert.equal(await page.locator('canvas').count(), 1);
      }
    }, hooks(30_000)); // every failure here is noticed without waiting for the budget
  });

  test('a crash that does not come back: the program runs again in the new worker and is drawn, with a message', async () => {
    await withPage(async (page) => {
      await page.locator('#zoom-out').click();
      const view = await waitForView(page, (v) => v.zoom < 0.9);
      const program = 'G90 G00 X0 Y0;\nG01 X40. Y10. F100.;\n(offsetlab-test-fault: trap-in-first-worker)\n';
      await pasteProgram(page, program);
      await page.waitForFunction(() => document.body.dataset.restarts === '1');
      await waitForRun(page);
      assert.match(await page.locator('#banner .text').textContent(),
        /^The interpreter crashed \(unreachable \(test fault\)\) and was restarted with your program, setup and view\.$/);
      assert.match(await page.locator('#summary').textContent(), /^2 blocks · 1 move · 0 errors/);
      assert.equal(await page.evaluate(() => document.body.dataset.stopped), undefined);
      assert.ok(await drawn(page));
      assert.ok(Math.abs((await viewOf(page)).zoom - view.zoom) < 1e-6, 'the view is restored');
      assert.equal(await page.evaluate(() => document.body.dataset.failures), '1');
      // Share works again: the new worker holds the document.
      const { document: doc } = await page.evaluate(() => window.offsetlab.document());
      assert.equal(doc.program, program);
    }, hooks(30_000));
  });
});

describe('no lost work', () => {
  test('the autosave survives a crash and reloads; a saved program that crashes the worker does not lock the page', async () => {
    await withPage(async (page) => {
      const crashing = 'G90 G00 X5. Y5.;\n(offsetlab-test-fault: trap)\n';
      await pasteProgram(page, crashing);
      await waitForStopped(page, 'crash');
      assert.equal((await savedWork(page)).program, crashing);
      // Reloaded, the saved work is back; it crashes again and the page stays usable.
      await interpreterReady(page);
      await page.reload();
      await waitForStopped(page, 'crash');
      assert.equal(await page.evaluate(() => window.offsetlab.program()), crashing);
      await page.waitForTimeout(1000);
      assert.equal(await page.evaluate(() => document.body.dataset.failures), '2', 'one retry, no loop');
      await typeProgram(page, 'G90 G00 X5. Y5.;\nG01 X25. F100.;\n');
      assert.ok(await drawn(page));
      await page.reload();
      await waitForRun(page);
      assert.equal(await page.evaluate(() => window.offsetlab.program()), 'G90 G00 X5. Y5.;\nG01 X25. F100.;\n');
    }, hooks(1500));
  });

  test('a full storage says so in its own banner, beside the other messages', async () => {
    await withPage(async (page, { problems }) => {
      await typeProgram(page, 'G00 X1.;\n');
      const banner = page.locator('#storage-banner');
      await banner.waitFor({ state: 'visible' });
      assert.match(await banner.textContent(), /Your work is not being saved: the browser’s storage is full\. Copy your program somewhere safe/);
      assert.equal(await page.evaluate(() => document.body.dataset.saveFailed), 'true');
      // Another message (an example loaded) does not hide it.
      await page.locator('#example').selectOption('contour');
      await page.locator('#load-example').click();
      await waitForRun(page);
      assert.equal(await page.locator('#banner').isVisible(), true);
      assert.equal(await banner.isVisible(), true);
      problems.length = 0;
    }, {
      init: () => {
        Storage.prototype.setItem = function setItem() {
          throw new DOMException('The quota has been exceeded.', 'QuotaExceededError');
        };
      },
    });
  });

  test('storage switched off is said at load; the page works', async () => {
    await withPage(async (page) => {
      const banner = page.locator('#storage-banner');
      assert.equal(await banner.isVisible(), true);
      assert.match(await banner.textContent(), /Your work will not be saved: this browser does not allow this page to store data/);
      await typeProgram(page, 'G00 X1. Y2.;\n');
      assert.match(await page.locator('#summary').textContent(), /^1 block · 1 move · 0 errors/);
      assert.match(await banner.textContent(), /not be(ing)? saved/);
    }, {
      init: () => {
        Object.defineProperty(window, 'localStorage', {
          get() {
            throw new DOMException('Access is denied for this document.', 'SecurityError');
          },
        });
      },
    });
  });
});

describe('the hostile corpus', () => {
  test('every file of tests/data/hostile opens through Open… with diagnostics as text and the page usable', async () => {
    await withPage(async (page) => {
      const dialogs = countDialogs(page);
      const dir = join(ROOT, 'tests', 'data', 'hostile');
      const files = readdirSync(dir).filter((name) => name !== 'README.md').sort();
      assert.ok(files.length >= 25, files.join(' '));
      for (const name of files) {
        await page.evaluate(() => { delete document.body.dataset.opened; });
        await page.locator('#open-file').setInputFiles(join(dir, name));
        await page.waitForFunction((n) => document.body.dataset.opened === n, name, { timeout: 30_000 });
        await waitForRun(page);
        assert.equal(await page.evaluate(() => document.body.dataset.stopped), undefined, name);
        assert.match(await page.locator('#summary').textContent(), /^\d+ blocks? · \d+ moves? · \d+ errors? · \d+ warnings? · mill, mm · /, name);
        const items = await page.locator('#diagnostics li').allTextContents();
        assert.ok(items.length >= 1, name);
        // Every diagnostic is "line:column severity [code] message", as text.
        for (const item of items.slice(0, 50)) {
          assert.match(item, /^(\d+:\d+|setup) (error|warning) \[[a-z0-9-]+\] .+|^No problems found\.$/s, `${name}: ${item.slice(0, 80)}`);
        }
        assert.match(await page.locator('#banner .text').textContent(), new RegExp(`^Opened “${name.replace(/\./g, '\\.')}”\\.`));
        assert.deepEqual(await foreignElements(page), NO_FOREIGN, name);
      }
      assert.equal(dialogs.n, 0);
      // Still usable (with M30: an opened file may have chosen LinuxCNC,
      // which refuses a program without its end, behaviour 22.9).
      await typeProgram(page, 'G90 G00 X0 Y0;\nG01 X10. Y10. F100.;\nM30;\n');
      assert.match(await page.locator('#summary').textContent(), /^3 blocks · 1 move · 0 errors/);
      assert.ok(await drawn(page));
    }, { init: 'window.offsetlabTest = { budgetMs: 120000 };' });
  });
});
