// The browser benchmark's tables (scripts/bench-browser.mjs): the headline
// figures against each target, the details of each, or the results as JSON.

import { median, stats } from './bench-common.mjs';

// ------------------------------------------------------------------ output

export function fmtMs(ms) {
  if (ms === null || ms === undefined || !Number.isFinite(ms)) return '—';
  if (ms >= 1000) return `${(ms / 1000).toFixed(2)} s`;
  if (ms >= 100) return `${ms.toFixed(0)} ms`;
  return `${ms.toFixed(1)} ms`;
}
export function fmtMB(bytes) {
  if (bytes === null || bytes === undefined || !Number.isFinite(bytes)) return '—';
  return `${(bytes / 1e6).toFixed(0)} MB`;
}
const fmtN = (digits) => (v) => (Number.isFinite(v) ? v.toLocaleString('en', { maximumFractionDigits: digits, minimumFractionDigits: digits }) : '—');
const range = (s, f) => (s ? (s.n > 1 ? `${f(s.median)} (${f(s.min)}–${f(s.max)})` : f(s.median)) : '—');

function table(rows) {
  const widths = rows[0].map((_, i) => Math.max(...rows.map((r) => String(r[i]).length)));
  const line = (r) => `| ${r.map((c, i) => String(c).padEnd(widths[i])).join(' | ')} |`;
  return [line(rows[0]), `|${widths.map((w) => '-'.repeat(w + 2)).join('|')}|`, ...rows.slice(1).map(line)].join('\n');
}

/** The headline figures and whether each target is met. */
function headline(results) {
  const { t3runs, t4runs } = results;
  const t3 = t3runs.map((r) => r.t3).filter(Boolean);
  const drawn = t3.filter((x) => !x.timedOut);
  const t5 = t3runs.map((r) => r.t5).filter(Boolean);
  const t5small = t4runs.map((r) => r.t5).filter(Boolean);
  const editsOf = (kind) => t4runs.flatMap((r) => r.edits.filter((e) => !e.timedOut && (e.kind ?? 'n') === kind));
  const [edits, editsX, editsF] = ['n', 'x', 'f'].map(editsOf);
  const h = {
    keyToFrameX: stats(editsX.map((e) => e.keyToFrame)),
    requestToFrameX: stats(editsX.map((e) => e.requestToFrame)),
    keyToFrameF: stats(editsF.map((e) => e.keyToFrame)),
    requestToFrameF: stats(editsF.map((e) => e.requestToFrame)),
    total: stats(drawn.map((x) => x.total)),
    totalTimedOut: t3.length - drawn.length,
    pageDrawn: stats(t3.map((x) => x.pageDrawn)),
    longest: stats(t3.map((x) => x.main.longest)),
    gap: stats(t3.map((x) => x.main.maxFrameGap)),
    peak: stats(t3.map((x) => x.memory.rendererPeak)),
    // Issue 6's measure: the JS heaps (page and worker) and the wasm memory.
    heapsWasm: stats(t3.map((x) => {
      const { pageHeapPeak: page, workerHeapPeak: worker, wasm } = x.memory;
      return [page, worker, wasm].every((v) => typeof v === 'number') ? page + worker + wasm : null;
    }).filter((v) => v !== null)),
    keyToFrame: stats(edits.map((e) => e.keyToFrame)),
    keyToDrawnMessage: stats(edits.map((e) => e.keyToDrawnMessage)),
    debounce: stats(edits.map((e) => e.debounce)),
    requestToFrame: stats(edits.map((e) => e.requestToFrame)),
    fps: stats(t5.map((x) => x.fps)),
    fpsSmall: stats(t5small.map((x) => x.fps)),
    fpsOrbit: stats(t3runs.map((r) => r.t5orbit?.fps).filter((v) => typeof v === 'number')),
    orbitMovingMs: stats(t3runs.map((r) => r.t5orbit?.movingFrameMs?.median).filter((v) => typeof v === 'number')),
  };
  const verdict = (s, ok) => (s ? (ok(s.median) ? 'met' : 'not met') : 'not measured');
  h.status = {
    time: h.totalTimedOut && !h.total ? 'not met (timed out)' : verdict(h.total, (v) => v < 1000),
    responsive: verdict(h.longest, (v) => v < 100),
    memory: verdict(h.heapsWasm, (v) => v < 400e6),
    edit: verdict(h.keyToFrame, (v) => v < 16),
    editNoDebounce: verdict(h.requestToFrame, (v) => v < 16),
    editX: verdict(h.keyToFrameX, (v) => v < 16),
    editF: verdict(h.keyToFrameF, (v) => v < 16),
    fps: verdict(h.fps, (v) => v >= 30),
    fpsOrbit: verdict(h.fpsOrbit, (v) => v >= 30),
  };
  return h;
}

function report(results) {
  const { env, big, small, t3runs, t4runs } = results;
  const h = headline(results);
  const t3 = t3runs.map((r) => r.t3).filter(Boolean);
  const t5 = t3runs.map((r) => r.t5).filter((x) => x && !x.noFrame);
  const t5none = t3runs.map((r) => r.t5).filter((x) => x?.noFrame);
  const t5small = t4runs.map((r) => r.t5).filter(Boolean);
  const edits = t4runs.flatMap((r) => r.edits.filter((e) => !e.timedOut));
  const bigName = `${big.blocks.toLocaleString('en')} blocks`;
  const smallName = `${small.blocks.toLocaleString('en')} blocks`;
  const timedOut = h.totalTimedOut ? `${h.totalTimedOut} of ${t3.length} runs not drawn within ${results.limits.big / 1000} s` : '';
  const totalText = h.total ? `${range(h.total, fmtMs)}${timedOut ? `; ${timedOut}` : ''}` : (timedOut ? `timed out: ${timedOut}` : '—');
  const fps = (v) => v.toFixed(v < 10 ? 2 : 1);
  const rows = [
    ['#', 'target', 'measured: median (min–max)', 'goal', 'status'],
    ['3', `${bigName} (${fmtMB(big.bytes)}) opened (Open…) until drawn`, totalText, '< 1.0 s', h.status.time],
    ['3', '  until the page\'s `drawn` message (before rasterisation)', range(h.pageDrawn, fmtMs), '—', ''],
    ['3', '  until the editor holds the whole text (it takes a long one in steps)', range(stats(t3.map((x) => x.editorReady)), fmtMs), '—', ''],
    ['3', 'responsive: longest main-thread task meanwhile (until drawn and the editor done)', range(h.longest, fmtMs), '< 100 ms', h.status.responsive],
    ['3', '  longest gap between main-thread animation frames', range(h.gap, fmtMs), '—', ''],
    ['3', 'peak memory: JS heaps (page + worker) + wasm memory', range(h.heapsWasm, fmtMB), '< 400 MB', h.status.memory],
    ['3', '  the renderer process\'s peak RSS (page, worker, wasm, DOM, canvases)', range(h.peak, fmtMB), '—', ''],
    ['4', `${smallName}: one-character edit, keystroke until drawn`, range(h.keyToFrame, fmtMs), '< 16 ms', h.status.edit],
    ['4', '  of which keystroke to run request (editor, the page\'s debounce if any)', range(h.debounce, fmtMs), '—', ''],
    ['4', '  run request until drawn', range(h.requestToFrame, fmtMs), '< 16 ms', h.status.editNoDebounce],
    ['4', '  keystroke until the page\'s `drawn` message', range(h.keyToDrawnMessage, fmtMs), '—', ''],
    ['4b', `${smallName}: the same typed into the X word (the path and its bounds change), keystroke until drawn`, range(h.keyToFrameX, fmtMs), '< 16 ms', h.status.editX],
    ['4b', '  run request until drawn', range(h.requestToFrameX, fmtMs), '—', ''],
    ['4c', `${smallName}: the same typed after the X word's point (the path moves, its bounds stay), keystroke until drawn`, range(h.keyToFrameF, fmtMs), '< 16 ms', h.status.editF],
    ['4c', '  run request until drawn', range(h.requestToFrameF, fmtMs), '—', ''],
    ['5', `${bigName}: pan + zoom, frames drawn per second`,
      h.fps ? `${range(h.fps, fps)}${t5none.length ? ` (${t5none.length} of ${t5none.length + t5.length} runs: ${t5none[0].noFrame})` : ''}` : '—',
      '≥ 30', h.status.fps],
    ['5', `  the same on ${smallName} (for comparison)`, range(h.fpsSmall, fps), '≥ 30', h.fpsSmall ? (h.fpsSmall.median >= 30 ? 'met' : 'not met') : ''],
    ['5', `${bigName}: the 3D view turned (Shift+drag), frames drawn per second`, range(h.fpsOrbit, fps), '≥ 30', h.status.fpsOrbit],
    ['5', '  time per moving (sampled) frame while turned', range(h.orbitMovingMs, fmtMs), '—', ''],
  ];
  const out = [];
  out.push(`offsetlab browser benchmark, ${env.date}`);
  out.push(`Chromium ${env.chromium} headless (flags of tests/e2e/harness.mjs: --headless --no-sandbox --disable-gpu …; software rendering), `
    + `Node ${env.node}, ${env.cpus} CPUs, load average ${env.loadBefore.map((x) => x.toFixed(2)).join(' ')} before, `
    + `${(env.loadAfter ?? []).map((x) => x.toFixed(2)).join(' ')} after`);
  out.push(`Page: ${env.page}`);
  if (results.options.experiment) out.push(`EXPERIMENT (--canvas-experiment ${results.options.experiment.spec}): the worker's canvas context was patched; these are not the page's figures.`);
  out.push(`Load: ${env.loadNote}`);
  out.push(`Runs: ${env.runs} fresh browsers for targets 3 and 5, ${env.runs} for target 4 (${env.edits} edits each); `
    + `viewport 1280x800 at 2 device pixels per CSS pixel.`);
  out.push('');
  out.push(table(rows));

  if (t3.some((x) => x.phases)) {
    const ph = (k) => stats(t3.map((x) => x.phases?.[k]));
    const rowsP = [
      ['target 3: where the time goes (median over runs)', 'time', 'what'],
      ['read the file (Blob.text)', range(ph('readFile'), fmtMs), 'the first Blob.text() (main thread): the .nc, or its first 4 KiB from 1 MiB on (the worker reads the file)'],
      ['page until the run request', range(ph('beforePost'), fmtMs), 'CodeMirror setText, the text copied out of the editor, panels'],
      ['postMessage of the run request', range(ph('postMessage'), fmtMs), 'structured clone of the program text'],
      ['to the worker', range(ph('toWorker'), fmtMs), 'delivery, deserialisation, queue (a file handed over: its read), until Session.run starts'],
      ['Session.run (wasm)', range(ph('run'), fmtMs), 'text into wasm memory, parse, run, toolpath; summary out'],
      ['result handled by the page', range(ph('resultToPage'), fmtMs), 'from the run\'s end: summary, diagnostics, editor marks'],
      ['worker: wait for its animation frame', range(ph('waitFrame'), fmtMs), 'from the run\'s end to render()'],
      ['Session.render (wasm)', range(ph('render'), fmtMs), 'records the drawing (canvas calls)'],
      ['rasterisation of the frame', range(ph('raster'), fmtMs), 'Chromium/Skia paints the recorded paths (worker thread)'],
    ];
    out.push('');
    out.push(table(rowsP));
    const calls = t3.find((x) => x.calls)?.calls;
    if (calls) out.push('', `Canvas calls of that drawing: ${calls.lineTo.toLocaleString('en')} lineTo, ${calls.moveTo.toLocaleString('en')} moveTo, ${calls.stroke} stroke.`);
  }
  if (t3.length) {
    const m = (k) => stats(t3.map((x) => x.memory[k]));
    const mem = [
      ['target 3: memory (median over runs)', 'size'],
      ['renderer process RSS before opening the file', range(m('rendererBefore'), fmtMB)],
      ['renderer process peak RSS (sampled every 200 ms)', range(m('rendererPeak'), fmtMB)],
      ['  peak minus the RSS before', range(stats(t3.map((x) => x.memory.rendererPeak - x.memory.rendererBefore)), fmtMB)],
      ['  highest until the page\'s drawn message (run and render, before rasterisation)', range(m('rendererUntilDrawnMessage'), fmtMB)],
      ['page JS heap before', range(m('pageHeapBefore'), fmtMB)],
      ['page JS heap, highest sample', range(m('pageHeapPeak'), fmtMB)],
      ['worker JS heap, highest sample', range(m('workerHeapPeak'), fmtMB)],
      ['worker wasm memory after the run (its peak)', range(m('wasm'), fmtMB)],
    ];
    out.push('');
    out.push(table(mem));
    const lt = stats(t3.map((x) => x.main.total));
    const ltn = stats(t3.map((x) => x.main.count));
    const st = t3[0].storage;
    out.push('');
    out.push(`Main thread during target 3: ${range(ltn, fmtN(0))} long tasks, ${range(lt, fmtMs)} in all. `
      + `localStorage writes (run 1): ${st.length ? st.map((e) => `${(e.chars / 1e6).toFixed(1)} M characters in ${fmtMs(e.ms)}`).join(', ') : 'none'}.`);
    out.push(`Summary line of the page: ${t3.find((x) => x.summary)?.summary ?? '—'}`);
  }
  for (const [kind, label] of [['n', 'N number'], ['x', 'X word'], ['f', 'X word\'s decimals']]) {
    const these = edits.filter((x) => (x.kind ?? 'n') === kind);
    if (!these.length) continue;
    const e = (k) => stats(these.map((x) => x[k]));
    const rowsE = [
      [`target 4 (${label}): where the time goes (median over edits)`, 'time'],
      ['keystroke to run request (editor, the page\'s debounce if any)', range(e('debounce'), fmtMs)],
      ['postMessage of the run request', range(e('postMessage'), fmtMs)],
      ['to the worker (until Session.run starts)', range(e('toWorker'), fmtMs)],
      ['Session.run (wasm)', range(e('run'), fmtMs)],
      ['run end to result handled by the page', range(e('resultToPage'), fmtMs)],
      ['worker: wait for its animation frame', range(e('waitFrame'), fmtMs)],
      ['Session.render (wasm)', range(e('render'), fmtMs)],
      ['rasterisation of the frame', range(e('raster'), fmtMs)],
    ];
    out.push('');
    out.push(table(rowsE));
    const calls = these.find((x) => x.calls)?.calls;
    if (calls) out.push('', `Canvas calls of each drawing: ${calls.lineTo.toLocaleString('en')} lineTo, ${calls.moveTo.toLocaleString('en')} moveTo, ${calls.stroke} stroke.`);
  }
  if (edits.length) {
    const timed = t4runs.flatMap((r) => r.edits).filter((x) => x.timedOut).length;
    out.push('');
    out.push(`Edited line: ${t4runs.find((r) => r.line)?.line ?? '—'} (a 7 typed after the first digit of its N number, then Backspace, and the same in its X word); `
      + `for 4c ${t4runs.find((r) => r.plainLine)?.plainLine ?? '—'} (the same after its X word's point); `
      + `${edits.length} edits${timed ? `, ${timed} not drawn within ${results.limits.edit / 1000} s` : ''}. `
      + `Summary line of the page: ${t4runs.find((r) => r.summary)?.summary ?? '—'}`);
  }
  for (const [name, list] of [[bigName, t5], [smallName, t5small]]) {
    if (!list.length) continue;
    const f = (g) => stats(list.map(g));
    const rows5 = [
      [`target 5 on ${name}: detail (median over runs)`, 'value'],
      ['pan (drag): frames drawn per second', range(f((x) => x.pan.fps), fps)],
      ['zoom (wheel): frames drawn per second', range(f((x) => x.zoom.fps), fps)],
      ['  of which whole frames (the rest moved from the last whole frame)', range(f((x) => x.wholeFps), fps)],
      ['time per frame, render() to rasterised (median of each run)', range(f((x) => x.frameMs?.median), fmtMs)],
      ['  moved frames (median of each run)', range(f((x) => x.movingFrameMs?.median), fmtMs)],
      ['  whole frames (median of each run)', range(f((x) => x.wholeFrameMs?.median), fmtMs)],
      ['  of which Session.render (wasm)', range(f((x) => x.renderMs?.median), fmtMs)],
      ['  of which rasterisation', range(f((x) => x.rasterMs?.median), fmtMs)],
      ['frames begun and not finished 10 s after the input', range(f((x) => x.unfinished), fmtN(0))],
      ['input events sent per second', range(f((x) => x.inputsPerSecond), fmtN(0))],
      ['view messages the page sent the worker', range(f((x) => x.viewMessages), fmtN(0))],
      ['main thread: animation frames per second', range(f((x) => x.mainFramesPerSecond), fmtN(1))],
      ['main thread: longest task', range(f((x) => x.mainLongest), fmtMs)],
      ['main thread: long tasks in all', range(f((x) => x.mainLongTaskTotal), fmtMs)],
      ['localStorage writes', range(f((x) => x.storageWrites), fmtN(0))],
    ];
    out.push('');
    out.push(table(rows5));
  }
  const problems = [...t3runs, ...t4runs].filter((r) => r.error).map((r) => `run ${r.run}: ${r.error}`);
  const consoleProblems = [...new Set([...t3runs, ...t4runs].flatMap((r) => r.problems ?? []))];
  if (problems.length) out.push(`\nProblems: ${problems.join('; ')}`);
  if (consoleProblems.length) out.push(`\nConsole errors or failed requests: ${consoleProblems.slice(0, 5).join('; ')}`);
  if (env.timedOut) out.push(`\nThe benchmark stopped after ${Math.round(results.limits.total / 60000)} min: the figures above are what was measured by then.`);
  return `${out.join('\n')}\n`;
}

export function print(results) {
  if (results.options.json) process.stdout.write(`${JSON.stringify({ ...results, headline: headline(results) }, null, 2)}\n`);
  else process.stdout.write(report(results));
}
