#!/usr/bin/env node
// Browser benchmark of issue 6's targets 3–5. Not a test: it never fails the
// build, it measures and prints a table. It drives the real page in headless
// Chromium through playwright-core the way the end-to-end tests do (it
// imports tests/e2e/harness.mjs: the same static server, the same Chromium
// and flags) and measures with instrumentation added from outside (an init
// script in the page and code evaluated in the worker; www/ is not changed):
//
//   3  the 1M-block program opened with Open… (the page's file input, as a
//      user opens a .nc file) until its drawing is on the canvas; the
//      longest main-thread task meanwhile (is the page responsive?); the
//      peak JS heaps + wasm memory (and the renderer process's peak RSS).
//   4  with the 10k-block program open, a one-character edit typed in the
//      editor (a 7 typed after the first digit of an N number in the middle
//      of the program, then Backspace, alternately) until the re-run is
//      drawn, with the time to the run request (the page's debounce, if
//      any) shown apart; then the same typed into the X word of that line
//      (4b: the edit moves the path, which is drawn again: X101.318 becomes
//      X1701.318, the next arc's end is no longer on its circle and the run
//      stops there, the bounds grow, the view follows: every frame is a
//      whole frame); then the same typed after the X word's decimal point
//      (4c: X101.318 becomes X101.7318, the path moves by 0.4 mm and keeps
//      its bounds: the frame is drawn again only around the moves changed).
//   5  the 1M-block path panned (mouse drag on #view) and zoomed (wheel)
//      for a few seconds: frames the worker finished per second; then the
//      3D view turned (Shift+drag in the 3D view, scripts/bench-orbit.mjs)
//      for half as long: the same count while orbiting.
//
// Usage (make bench-browser builds the wasm package and the page first):
//
//   node scripts/bench-browser.mjs [--blocks 1000000] [--edit-blocks 10000]
//        [--runs 3] [--edits 30] [--seconds 3] [--limit 120] [--ref REV] [--count-calls]
//        [--canvas-experiment split=N,nodash] [--only 3,4,5] [--json]
//
//   --blocks N       size of the program of targets 3 and 5 (default 1000000)
//   --edit-blocks N  size of the program of target 4 (default 10000)
//   --runs N         fresh browsers per measurement (default 3); medians are
//                    over runs (target 4: over every edit of every run)
//   --edits N        one-character edits per run of target 4 (default 30)
//   --seconds S      pan + zoom time per run of target 5 (default 3)
//   --limit S        time limit of target 3, the big program opened until
//                    drawn (default 120)
//   --ref REV        measure the page of commit REV instead of the working
//                    tree's www/: `git archive REV` into
//                    target/bench-browser/ref-SHA/ (files dated now, so
//                    cargo builds them), its wasm package built there with
//                    wasm-pack (CARGO_TARGET_DIR=target/bench-browser/cargo,
//                    shared by the refs) and wasm-opt -O3 as `make wasm`,
//                    its editor bundle with esbuild (once per commit; a
//                    directory without the stamp of a finished build is
//                    built again; the wasm's md5 is printed, with a note
//                    when another ref of other sources has the same):
//                    figures others can reproduce while www/ and src/
//                    move on
//   --count-calls    also count the canvas calls of each drawing (lineTo,
//                    moveTo, stroke; adds a little to the drawing time)
//   --canvas-experiment SPEC
//                    an experiment, not the page as it is: the worker's
//                    OffscreenCanvas 2D context is patched before the runs.
//                    split=N strokes each path every N lineTo calls and goes
//                    on with a new one; nodash draws dashed lines solid.
//                    What would change if the renderer did the same.
//   --only LIST      measure only these targets (3 and 5 share their runs),
//                    e.g. --only 4
//   --json           print the results as JSON instead of the tables
//
// The programs come from the repository's deterministic generator
// (`cargo run --release --example generate -- N FILE`, which also writes the
// setup FILE.json, register 01 = 100) in target/bench-browser/. Progress goes
// to standard error (BENCH_DEBUG=1 adds an error's stack). Every wait has a
// time limit (--limit, 120 s, for the 1M-block program to be drawn; at least
// 30 min in all): what does not finish in time is reported as "timed out"
// (with the time it had), never waited for.
//
// What the figures are:
//   - times are the page's performance.now(); the worker's are converted
//     through performance.timeOrigin (the two agree to about a millisecond;
//     a gap between them is never shown below 0) and reach the page on a
//     BroadcastChannel of the benchmark's own (the page's messages are not
//     touched).
//   - "drawn": the frame is on the canvas — the worker thread is free again
//     after the Session.render() that followed the run. In software
//     rendering (headless, --disable-gpu) Chromium rasterises the
//     OffscreenCanvas's recorded drawing on the worker thread when the
//     animation frame ends, after render() returned and after the worker
//     posted its `drawn` message, so that message comes first; the time to
//     it is shown too ("the page's `drawn` message").
//   - "longest main-thread task": PerformanceObserver('longtask') (tasks over
//     50 ms). The page counts as responsive when no main-thread task takes
//     100 ms or more (RAIL's input budget).
//   - memory: issue 6's "peak JS heap + wasm memory": the highest sampled
//     JS heaps of the page and of the worker plus the worker's wasm memory;
//     beside it, the peak resident set of the renderer process that hosts the
//     page and its worker (JS heaps, wasm memory, the editor's DOM, canvas
//     buffers together): the highest of its VmRSS and VmHWM (/proc) sampled
//     every 200 ms — VmHWM alone will not do: it went down during runs
//     (Chromium's memory dumps reset the peak through /proc/self/clear_refs);
//     also the highest sampled JS heaps (CDP
//     Runtime.getHeapUsage, page and worker) and the worker's wasm linear
//     memory (it never shrinks: its last size is its peak).
//   - frames per second: frames the worker finished (rendered and
//     rasterised) while the input was driven, per second; the input events
//     sent per second are printed beside them.

import { spawnSync } from 'node:child_process';
import { mkdirSync, readdirSync, readFileSync, statSync } from 'node:fs';
import { cpus, loadavg } from 'node:os';
import { basename, join } from 'node:path';
import { ROOT, launchBrowser, openPage, startServer, waitForRun } from '../tests/e2e/harness.mjs';
import { orbitFrames } from './bench-orbit.mjs';
import { buildRef } from './bench-ref.mjs';
import { TimedOut, median, sleep, stats, within } from './bench-common.mjs';
import { PAGE_INIT, instrumentWorker, renderers, sampleMemory, workerCdp, workerFrames } from './bench-instrument.mjs';
import { fmtMB, fmtMs, print } from './bench-report.mjs';

// ---------------------------------------------------------------- options

function parseArgs(argv) {
  const opts = { blocks: 1_000_000, editBlocks: 10_000, runs: 3, edits: 30, seconds: 3, limit: 120, json: false, ref: null, countCalls: false, experiment: null, only: new Set(['3', '4', '5']) };
  const numeric = { '--blocks': 'blocks', '--edit-blocks': 'editBlocks', '--runs': 'runs', '--edits': 'edits', '--seconds': 'seconds', '--limit': 'limit' };
  for (let i = 0; i < argv.length; i += 1) {
    const a = argv[i];
    if (a === '--json') {
      opts.json = true;
    } else if (a === '--count-calls') {
      opts.countCalls = true;
    } else if (a === '--canvas-experiment') {
      const spec = argv[i + 1] ?? '';
      if (!/^(?:split=\d+|nodash)(?:,(?:split=\d+|nodash))*$/.test(spec)) usage('--canvas-experiment needs split=N and/or nodash, e.g. split=256,nodash');
      opts.experiment = { spec, split: Number(/split=(\d+)/.exec(spec)?.[1] ?? 0), nodash: spec.split(',').includes('nodash') };
      i += 1;
    } else if (a === '--only') {
      const list = (argv[i + 1] ?? '').split(',');
      if (!list.length || list.some((t) => !['3', '4', '5'].includes(t))) usage('--only needs targets among 3, 4, 5, e.g. --only 4 or --only 3,5');
      opts.only = new Set(list);
      i += 1;
    } else if (a === '--ref') {
      if (!argv[i + 1]) usage('--ref needs a commit');
      opts.ref = argv[i + 1];
      i += 1;
    } else if (a === '--help' || a === '-h') {
      // The header comment.
      const lines = readFileSync(new URL(import.meta.url), 'utf8').split('\n').slice(1);
      const end = lines.findIndex((l) => !l.startsWith('//'));
      process.stdout.write(`${lines.slice(0, end).map((l) => l.slice(3)).join('\n')}\n`);
      process.exit(0);
    } else if (numeric[a]) {
      const v = Number(argv[i + 1]);
      if (!Number.isFinite(v) || v <= 0) usage(`${a} needs a positive number`);
      opts[numeric[a]] = v;
      i += 1;
    } else {
      usage(`unknown argument ${a}`);
    }
  }
  opts.blocks = Math.round(opts.blocks);
  opts.editBlocks = Math.round(opts.editBlocks);
  opts.runs = Math.round(opts.runs);
  opts.edits = Math.round(opts.edits);
  return opts;
}

function usage(message) {
  process.stderr.write(`bench-browser: ${message}\nusage: node scripts/bench-browser.mjs [--blocks N] [--edit-blocks N] [--runs N] [--edits N] [--seconds S] [--limit S] [--ref REV] [--count-calls] [--canvas-experiment SPEC] [--only 3,4,5] [--json]\n`);
  process.exit(2);
}

const OPTS = parseArgs(process.argv.slice(2));
const log = (...a) => process.stderr.write(`${a.join(' ')}\n`);

/** Time limits (ms). */
const LIMIT = {
  total: Math.max(30 * 60_000, OPTS.runs * (OPTS.limit * 1000 + 120_000) + 10 * 60_000),
  generate: 20 * 60_000,
  big: OPTS.limit * 1000, // the big program opened, run and drawn (--limit)
  small: 30_000, // the small program opened, run and drawn
  edit: 20_000, // one edit re-run and drawn
  step: 20_000, // anything else
  cdp: 5_000,
  grace: 10_000, // frames begun during pan and zoom may finish this much later
};

// ------------------------------------------------------ the programs

const BENCH_DIR = join(ROOT, 'target', 'bench-browser');

/**
 * Writes bench-N.nc and bench-N.json with the repository's generator; returns
 * their paths. The generator is `cargo run --release --example generate`; when
 * the crate does not build (someone is in the middle of an edit), the same
 * source is compiled on its own with rustc: examples/generate.rs uses nothing
 * but benches/programs.rs, so the programs are byte for byte the same.
 */
function generate(blocks) {
  mkdirSync(BENCH_DIR, { recursive: true });
  const program = join(BENCH_DIR, `bench-${blocks}.nc`);
  const setup = join(BENCH_DIR, `bench-${blocks}.json`);
  const run = (cmd, args) => spawnSync(cmd, args, {
    cwd: ROOT, stdio: ['ignore', process.stderr, process.stderr], timeout: LIMIT.generate,
  });
  log(`generating ${blocks} blocks: cargo run --release --example generate -- ${blocks} ${program}`);
  let r = run('cargo', ['run', '--quiet', '--release', '--example', 'generate', '--', String(blocks), program]);
  if (r.status !== 0) {
    const exe = join(BENCH_DIR, 'generate');
    log('bench-browser: the crate does not build now; compiling examples/generate.rs on its own with rustc');
    r = run('rustc', ['--edition', '2021', '-O', '-o', exe, join(ROOT, 'examples', 'generate.rs')]);
    if (r.status === 0) r = run(exe, [String(blocks), program]);
  }
  if (r.status !== 0) throw new Error(`the generator failed (${r.error?.message ?? `exit ${r.status}`})`);
  return { program, setup, bytes: statSync(program).size, blocks };
}

// ------------------------------------------------------------ page steps

async function openFresh(browser, server) {
  const { context, page, problems } = await within(
    openPage(browser, server.url, { init: PAGE_INIT }), LIMIT.step, 'opening the page',
  );
  await waitForRun(page);
  return { context, page, problems };
}

const now = (page) => page.evaluate(() => performance.now());

/** Opens `path` with the page's Open… input; resolves to the gen of the run it asked for and the change event's time. */
async function openFile(page, path, timeout) {
  const name = basename(path);
  const from = await page.evaluate(() => window.__bench.log.length);
  await within(page.setInputFiles('#open-file', path), timeout, `opening ${name}`);
  await page.waitForFunction((n) => document.body.dataset.opened === n, name, { timeout });
  return page.evaluate((f) => ({
    gen: Number(document.body.dataset.requested),
    change: window.__bench.log.slice(f).find((e) => e.k === 'change')?.t ?? null,
    from: f,
  }), from);
}

/** Resolves to B.settled(gen) once the page's drawn message is handled (`frame`: and the frame is finished too). */
async function waitSettled(page, gen, timeout, { frame = true } = {}) {
  const handle = await page.waitForFunction(([g, f]) => {
    const s = window.__bench.settled(g);
    return s && s.drawnMessage !== null && (!f || s.frame) ? s : null;
  }, [gen, frame], { timeout, polling: 10 });
  return handle.jsonValue();
}

/** The main thread's long tasks and largest gap between animation frames within [t0, t1]. */
async function mainThread(page, t0, t1) {
  return page.evaluate(([a, b]) => {
    const B = window.__bench;
    const tasks = B.longtasks.filter(([s, d]) => s + d > a && s < b);
    const frames = [a, ...B.frames.filter((f) => f > a && f < b), b];
    let gap = 0;
    for (let i = 1; i < frames.length; i += 1) gap = Math.max(gap, frames[i] - frames[i - 1]);
    return {
      longest: tasks.reduce((m, [, d]) => Math.max(m, d), 0),
      total: tasks.reduce((s, [, d]) => s + d, 0),
      count: tasks.length,
      frames: frames.length - 2,
      maxFrameGap: gap,
      observer: B.noLongtasks ?? 'ok',
    };
  }, [t0, t1]);
}

const summaryText = (page) => within(page.locator('#summary').textContent(), LIMIT.step, 'the summary line');
const isTimeout = (error) => error instanceof TimedOut || error?.name === 'TimeoutError' || /timeout|timed out/i.test(String(error?.message));
const firstLine = (error) => String(error?.message ?? error).split('\n')[0];

// -------------------------------------------------------- targets 3 and 5

/** One fresh browser: the big program opened and drawn (target 3), then panned and zoomed (target 5). */
async function runBig(server, big, run) {
  const out = { run };
  const browser = await within(launchBrowser(), LIMIT.step, 'launching Chromium');
  let stopSampling = null;
  try {
    const { context, page, problems } = await openFresh(browser, server);
    out.problems = problems;
    await instrumentWorker(page, { countCalls: OPTS.countCalls, experiment: OPTS.experiment, limit: LIMIT });
    const wcdp = await within(workerCdp(browser), LIMIT.step, 'attaching to the worker').catch(() => null);
    const pcdp = await context.newCDPSession(page);

    // The setup first (register 01 = 100), untimed.
    const s = await openFile(page, big.setup, LIMIT.step);
    await waitSettled(page, s.gen, LIMIT.step);
    await sleep(500);
    const before = renderers();
    const heapBefore = await pcdp.send('Runtime.getHeapUsage');

    // Target 3: from the file input's change event to the frame's end.
    stopSampling = sampleMemory(pcdp, wcdp, LIMIT);
    const deadline = Date.now() + LIMIT.big;
    const t3 = { timedOut: false };
    out.t3 = t3;
    const opened = await openFile(page, big.program, LIMIT.big);
    let settled = null;
    let untilDrawnMessage = null;
    try {
      // The run's memory: the highest RSS until the page has the drawn
      // message, before the rasterisation of the frame begins.
      await waitSettled(page, opened.gen, Math.max(1000, deadline - Date.now()), { frame: false });
      const sofar = stopSampling.peak().byPid;
      for (const p of renderers()) sofar.set(p.pid, Math.max(sofar.get(p.pid) ?? 0, p.rss, p.hwm));
      untilDrawnMessage = sofar;
      settled = await waitSettled(page, opened.gen, Math.max(1000, deadline - Date.now()));
    } catch (error) {
      if (!isTimeout(error)) throw error;
      t3.timedOut = true;
      t3.limit = LIMIT.big;
      // What was reached in time.
      settled = await page.evaluate((g) => window.__bench.settled(g), opened.gen);
    }
    const peak = await stopSampling();
    stopSampling = null;
    const change = opened.change;
    const plog = await page.evaluate((f) => window.__bench.log.slice(f), opened.from);
    const read = plog.find((e) => e.k === 'blob-text');
    const drawnAt = settled?.frame ? settled.frame.end : await now(page);
    // The editor may still be taking the text in steps (it is aria-busy
    // meanwhile): the main thread is watched until both are done.
    const editorReady = await page.waitForFunction(() => !document.querySelector('#editor[aria-busy]') && performance.now(),
      null, { timeout: LIMIT.step, polling: 10 }).then((h) => h.jsonValue()).catch(() => null);
    const end = Math.max(drawnAt, editorReady ?? 0);
    t3.editorReady = editorReady === null ? null : editorReady - change;
    t3.main = await mainThread(page, change, end);
    t3.storage = plog.filter((e) => e.k === 'storage' && e.t >= change && e.t <= end).map((e) => ({ chars: e.chars, ms: e.end - e.t }));
    const at = (x) => (x === null || x === undefined ? null : x - change);
    if (settled) {
      const { run: wrun, render, frame } = settled;
      t3.pageDrawn = at(settled.drawnMessage);
      t3.total = frame ? frame.end - change : null;
      t3.phases = {
        readFile: read ? read.end - change : null,
        beforePost: read ? settled.post - read.end : null,
        postMessage: settled.postEnd - settled.post,
        toWorker: wrun ? Math.max(0, wrun.t - settled.postEnd) : null,
        run: wrun ? wrun.end - wrun.t : null,
        resultToPage: wrun ? (settled.rendered ?? settled.result) - wrun.end : null,
        waitFrame: render ? render.t - wrun.end : null,
        render: render ? render.end - render.t : null,
        raster: frame ? frame.end - frame.t : null,
      };
      t3.calls = render?.calls ?? null;
      t3.wasm = frame?.wasm ?? wrun?.wasm ?? null;
    }
    for (const p of renderers()) peak.byPid.set(p.pid, Math.max(peak.byPid.get(p.pid) ?? 0, p.rss, p.hwm));
    // The page's renderer: the one that grew most (it holds the program several times over).
    const [minePid, minePeak] = [...peak.byPid].reduce((a, b) => (b[1] > a[1] ? b : a), [null, null]);
    t3.memory = {
      rendererPeak: minePeak,
      rendererBefore: before.find((p) => p.pid === minePid)?.rss ?? null,
      rendererUntilDrawnMessage: untilDrawnMessage?.get(minePid) ?? null,
      pageHeapBefore: heapBefore.usedSize,
      pageHeapPeak: peak.pageHeap,
      workerHeapPeak: peak.workerSamples ? peak.workerHeap : null,
      wasm: t3.wasm ?? null,
    };
    t3.summary = await summaryText(page).catch(() => null);
    log(`  run ${run}: target 3: ${t3.timedOut ? `not drawn within ${LIMIT.big / 1000} s` : `${fmtMs(t3.total)} to drawn`} `
      + `(page's drawn message ${fmtMs(t3.pageDrawn)}, worker run ${fmtMs(t3.phases?.run)}, render ${fmtMs(t3.phases?.render)}, `
      + `raster ${fmtMs(t3.phases?.raster)}); longest main-thread task ${fmtMs(t3.main.longest)}; renderer peak ${fmtMB(minePeak)}; ${t3.summary}`);

    // Target 5, once the worker is free (else it would only measure the frame still being drawn).
    if (t3.timedOut) {
      // No frame can follow while the worker is still rasterising the first one.
      out.t5 = { fps: 0, noFrame: `no frame: the worker was still rasterising the first drawing (over ${LIMIT.big / 1000} s)` };
    } else {
      await sleep(1500);
      out.t5 = await panZoom(page);
      log(`  run ${run}: target 5: ${out.t5.fps.toFixed(2)} frames/s (pan ${out.t5.pan.fps.toFixed(2)}, zoom ${out.t5.zoom.fps.toFixed(2)}), `
        + `frame median ${fmtMs(out.t5.frameMs?.median)}, input ${out.t5.inputsPerSecond.toFixed(0)} events/s`);
      // The 3D view turned (issue 23), where the page has one.
      if (await page.locator('#plane option[value="3D"]').count()) {
        out.t5orbit = await orbitFrames(page, OPTS.seconds / 2, { now, within, stats, sleep, limit: LIMIT });
        log(`  run ${run}: target 5, 3D view turned: ${out.t5orbit.fps.toFixed(2)} frames/s, `
          + `moving frame median ${fmtMs(out.t5orbit.movingFrameMs?.median)}, whole frame median ${fmtMs(out.t5orbit.wholeFrameMs?.median)}`);
      }
    }
    await context.close();
  } catch (error) {
    out.error = firstLine(error);
    out.timedOut = isTimeout(error);
    if (process.env.BENCH_DEBUG) log(error?.stack);
    log(`  run ${run}: ${out.error}`);
  } finally {
    if (stopSampling) await stopSampling().catch(() => {});
    // Closing the browser also ends a worker still drawing.
    await browser.close().catch(() => {});
  }
  return out;
}

/**
 * Drags on #view, then turns the wheel, each for half of --seconds; counts
 * the frames the worker finished. The input goes through CDP
 * Input.dispatchMouseEvent with up to four events in flight (awaiting each,
 * as page.mouse does, allows only about one event per animation frame, which
 * would cap the rate at the very figure measured).
 */
async function panZoom(page) {
  const cdp = await page.context().newCDPSession(page);
  const box = await page.locator('#view').boundingBox();
  const cx = box.x + box.width / 2;
  const cy = box.y + box.height / 2;
  const half = (OPTS.seconds * 1000) / 2;
  const inflight = new Set();
  const send = async (params) => {
    while (inflight.size >= 4) await Promise.race(inflight);
    const p = cdp.send('Input.dispatchMouseEvent', params).catch(() => {}).finally(() => inflight.delete(p));
    inflight.add(p);
  };
  const phase = async (name, body) => {
    const t0 = await now(page);
    const inputs = await within(body(), half + LIMIT.step, name);
    await within(Promise.all(inflight), LIMIT.step, name);
    const t1 = await now(page);
    return { name, t0, t1, inputs };
  };
  const pan = await phase('pan', async () => {
    let n = 0;
    await send({ type: 'mouseMoved', x: cx, y: cy });
    await send({ type: 'mousePressed', x: cx, y: cy, button: 'left', buttons: 1, clickCount: 1 });
    const end = Date.now() + half;
    let x = cx;
    let y = cy;
    while (Date.now() < end) {
      // Round a circle of 120 px: the path moves about under the pointer.
      const a = (n / 40) * 2 * Math.PI;
      x = cx + 120 * Math.cos(a) - 120;
      y = cy + 120 * Math.sin(a);
      await send({ type: 'mouseMoved', x, y, button: 'left', buttons: 1 });
      n += 1;
    }
    await send({ type: 'mouseReleased', x, y, button: 'left', buttons: 0, clickCount: 1 });
    return n;
  });
  const zoom = await phase('zoom', async () => {
    let n = 0;
    await send({ type: 'mouseMoved', x: cx, y: cy });
    const end = Date.now() + half;
    while (Date.now() < end) {
      // Ten notches in, ten out: the view stays around the whole path.
      await send({ type: 'mouseWheel', x: cx, y: cy, deltaX: 0, deltaY: Math.floor(n / 10) % 2 ? 60 : -60 });
      n += 1;
    }
    return n;
  });
  // Frames begun during the input may finish a little later (their time is kept, not counted in the rate).
  const last = zoom.t1;
  const { renders, frames } = await workerFrames(page, last, LIMIT.grace);
  const isMoving = (f) => renders.get(f.render)?.moving === true;
  const each = (p) => {
    const done = frames.filter((f) => f.end >= p.t0 && f.end <= p.t1);
    const seconds = (p.t1 - p.t0) / 1000;
    const whole = done.filter((f) => !isMoving(f)).length;
    return { fps: done.length / seconds, frames: done.length, whole, wholeFps: whole / seconds, seconds, inputs: p.inputs };
  };
  const begunIn = frames.filter((f) => f.start >= pan.t0 && f.start <= zoom.t1);
  const unfinished = [...renders.values()].filter((r) => r.t >= pan.t0 && r.t <= zoom.t1 && !frames.some((f) => f.render === r.id));
  const mainPan = await mainThread(page, pan.t0, pan.t1);
  const mainZoom = await mainThread(page, zoom.t0, zoom.t1);
  const plog = await page.evaluate(([a, b]) => window.__bench.log.filter((e) => e.t >= a && e.t <= b), [pan.t0, zoom.t1]);
  const p = each(pan);
  const z = each(zoom);
  const seconds = p.seconds + z.seconds;
  return {
    fps: (p.frames + z.frames) / seconds,
    pan: { ...p, main: mainPan },
    zoom: { ...z, main: mainZoom },
    wholeFps: (p.whole + z.whole) / seconds,
    movingFrameMs: stats(begunIn.filter(isMoving).map((f) => f.end - f.start)),
    wholeFrameMs: stats(begunIn.filter((f) => !isMoving(f)).map((f) => f.end - f.start)),
    frameMs: stats(begunIn.map((f) => f.end - f.start)),
    renderMs: stats(begunIn.map((f) => renders.get(f.render).end - f.start)),
    rasterMs: stats(begunIn.map((f) => f.end - f.t)),
    unfinished: unfinished.length,
    inputsPerSecond: (pan.inputs + zoom.inputs) / seconds,
    viewMessages: plog.filter((e) => e.k === 'out' && e.type === 'view').length,
    storageWrites: plog.filter((e) => e.k === 'storage').length,
    mainLongest: Math.max(mainPan.longest, mainZoom.longest),
    mainLongTaskTotal: mainPan.total + mainZoom.total,
    mainFramesPerSecond: (mainPan.frames + mainZoom.frames) / seconds,
  };
}

// ---------------------------------------------------------------- target 4

/** Types a 7 and Backspace in turn where the editor's cursor is, `OPTS.edits` times. */
async function typeEdits(page, kind, out, run) {
    for (let i = 0; i < OPTS.edits; i += 1) {
      const key = i % 2 === 0 ? '7' : 'Backspace';
      const from = await page.evaluate(() => window.__bench.log.length);
      await page.keyboard.press(key);
      let settled;
      try {
        const h = await page.waitForFunction((f) => {
          const B = window.__bench;
          const post = B.log.slice(f).find((e) => e.k === 'out' && e.type === 'run');
          const s = post && B.settled(post.gen);
          return s && s.drawnMessage !== null && s.frame ? s : null;
        }, from, { timeout: LIMIT.edit, polling: 10 });
        settled = await h.jsonValue();
      } catch (error) {
        if (!isTimeout(error)) throw error;
        out.edits.push({ kind, key, timedOut: true });
        log(`  run ${run}: edit ${i + 1} not drawn within ${LIMIT.edit / 1000} s`);
        await sleep(2000);
        continue;
      }
      const keyT = await page.evaluate(([f, k]) => window.__bench.log.slice(f).find((e) => e.k === 'key' && e.key === k).t, [from, key]);
      const { run: wrun, render, frame } = settled;
      out.edits.push({
        kind,
        key,
        keyToFrame: frame.end - keyT,
        keyToDrawnMessage: settled.drawnMessage - keyT,
        debounce: settled.post - keyT,
        requestToFrame: frame.end - settled.post,
        postMessage: settled.postEnd - settled.post,
        toWorker: Math.max(0, wrun.t - settled.postEnd),
        run: wrun.end - wrun.t,
        resultToPage: (settled.rendered ?? settled.result) - wrun.end,
        waitFrame: render.t - wrun.end,
        render: render.end - render.t,
        raster: frame.end - frame.t,
        calls: render.calls,
      });
      // A typist's pause, so the autosave and the address bar get their turn too.
      await sleep(150);
    }
}

async function runEdits(server, small, run) {
  const out = { run, edits: [] };
  const browser = await within(launchBrowser(), LIMIT.step, 'launching Chromium');
  try {
    const { context, page, problems } = await openFresh(browser, server);
    out.problems = problems;
    await instrumentWorker(page, { countCalls: OPTS.countCalls, experiment: OPTS.experiment, limit: LIMIT });
    const s = await openFile(page, small.setup, LIMIT.step);
    await waitSettled(page, s.gen, LIMIT.step);
    const p = await openFile(page, small.program, LIMIT.small);
    await waitSettled(page, p.gen, LIMIT.small);
    out.summary = await summaryText(page);

    // Scroll the editor to the middle of the program and put the cursor
    // after the first digit of the N number of a G01 line there.
    await page.evaluate(() => {
      const scroller = document.querySelector('.cm-scroller');
      scroller.scrollTop = (scroller.scrollHeight - scroller.clientHeight) / 2;
    });
    await sleep(300);
    // The G01 line nearest the middle of the editor; for 4c the nearest one
    // followed by another G01 (an edit of a line before an arc moves the
    // arc's end off its circle: an error, and the run stops there).
    const targets = await page.evaluate(() => {
      const box = document.querySelector('.cm-scroller').getBoundingClientRect();
      const mid = box.top + box.height / 2;
      const best = [null, null];
      for (const line of document.querySelectorAll('.cm-line')) {
        const r = line.getBoundingClientRect();
        if (r.top < box.top || r.bottom > box.bottom || !/^N\d+ G01 X/.test(line.textContent)) continue;
        const here = { x: r.left + 4, y: r.top + r.height / 2, text: line.textContent };
        const plain = /^N\d+ G01 X/.test(line.nextElementSibling?.textContent ?? '');
        for (const k of plain ? [0, 1] : [0]) {
          if (!best[k] || Math.abs(here.y - mid) < Math.abs(best[k].y - mid)) best[k] = here;
        }
      }
      return best;
    });
    const [target, plain] = targets;
    if (!target || !plain) throw new Error('no G01 line visible in the middle of the editor');
    out.line = target.text;
    out.plainLine = plain.text;
    // The N number's first digit, then the X word's (after the sign), then
    // the X word's first decimal.
    const xAt = (text) => 1 + /X-?/.exec(text).index + /X-?/.exec(text)[0].length - 1;
    const dotAt = plain.text.indexOf('.', xAt(plain.text));
    for (const [kind, column, line] of [['n', 2, target], ['x', xAt(target.text) + 1, target], ['f', dotAt + 1, plain]]) {
      await page.mouse.click(line.x, line.y);
      await page.keyboard.press('Home');
      for (let c = 0; c < column; c += 1) await page.keyboard.press('ArrowRight');
      await sleep(1000);
      await typeEdits(page, kind, out, run);
    }
    // Target 5 on this smaller path, for comparison.
    await sleep(500);
    out.t5 = await panZoom(page);
    log(`  run ${run}: target 5 on ${small.blocks} blocks: ${out.t5.fps.toFixed(2)} frames/s, frame median ${fmtMs(out.t5.frameMs?.median)}`);
    const ok = out.edits.filter((e) => !e.timedOut);
    log(`  run ${run}: target 4: ${ok.length} edits, keystroke to drawn median ${fmtMs(median(ok.map((e) => e.keyToFrame)))} `
      + `(to the run request ${fmtMs(median(ok.map((e) => e.debounce)))}, worker run ${fmtMs(median(ok.map((e) => e.run)))}, `
      + `render ${fmtMs(median(ok.map((e) => e.render)))}, raster ${fmtMs(median(ok.map((e) => e.raster)))})`);
    await context.close();
  } catch (error) {
    out.error = firstLine(error);
    out.timedOut = isTimeout(error);
    if (process.env.BENCH_DEBUG) log(error?.stack);
    log(`  run ${run}: ${out.error}`);
  } finally {
    await browser.close().catch(() => {});
  }
  return out;
}

// -------------------------------------------------------------------- main

async function main() {
  const started = Date.now();
  const env = {
    date: new Date().toISOString().replace(/\.\d+Z$/, 'Z'),
    cpus: cpus().length,
    node: process.version,
    loadBefore: loadavg(),
    runs: OPTS.runs,
    edits: OPTS.edits,
    loadNote: 'the machine was loaded (other builds and tests ran at the same time), so the figures are noisy: medians of several runs.',
  };
  let root;
  if (OPTS.ref) {
    const built = buildRef(OPTS.ref, { dir: BENCH_DIR, log, timeout: LIMIT.generate });
    root = built.root;
    env.page = `commit ${built.sha.slice(0, 12)} (--ref ${OPTS.ref}), built in ${built.root.slice(ROOT.length + 1)}, wasm md5 ${built.wasm}`;
  } else {
    const git = (args) => spawnSync('git', args, { cwd: ROOT, encoding: 'utf8' }).stdout.trim();
    const dirty = git(['status', '--porcelain', '--', 'www', 'src']) ? ', with uncommitted changes in www/ or src/' : '';
    env.page = `the working tree's www/ (HEAD ${git(['rev-parse', '--short=12', 'HEAD'])}${dirty})`;
  }
  const big = generate(OPTS.blocks);
  const small = generate(OPTS.editBlocks);
  const server = await startServer(root ? { root } : {});
  const results = { env, options: OPTS, limits: LIMIT, big, small, t3runs: [], t4runs: [] };
  let finished = false;
  const watchdog = setTimeout(() => {
    if (finished) return;
    log(`bench-browser: stopped after ${Math.round(LIMIT.total / 60000)} min; printing what was measured`);
    env.loadAfter = loadavg();
    env.timedOut = true;
    print(results);
    process.exit(1);
  }, LIMIT.total);
  try {
    const probe = await within(launchBrowser(), LIMIT.step, 'launching Chromium');
    env.chromium = probe.version();
    await probe.close();
    for (let run = 1; run <= OPTS.runs && (OPTS.only.has('3') || OPTS.only.has('5')); run += 1) {
      log(`targets 3 and 5, run ${run}/${OPTS.runs}`);
      results.t3runs.push(await runBig(server, big, run));
    }
    for (let run = 1; run <= OPTS.runs && OPTS.only.has('4'); run += 1) {
      log(`target 4, run ${run}/${OPTS.runs}`);
      results.t4runs.push(await runEdits(server, small, run));
    }
  } finally {
    finished = true;
    clearTimeout(watchdog);
    await server.stop();
  }
  env.loadAfter = loadavg();
  env.seconds = (Date.now() - started) / 1000;
  print(results);
}

main().catch((error) => {
  log(`bench-browser: ${error?.stack ?? error}`);
  process.exit(1);
});
