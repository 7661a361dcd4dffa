// The browser benchmark's instruments (scripts/bench-browser.mjs): what runs
// in the page and in its worker to time runs, renders and frames from
// outside (www/ is not changed), and the renderer processes' memory.

import { readdirSync, readFileSync } from 'node:fs';
import { sleep, within } from './bench-common.mjs';

// ------------------------------------------ processes (peak memory, Linux)

function readProc(pid, file) {
  try {
    return readFileSync(`/proc/${pid}/${file}`, 'utf8');
  } catch {
    return '';
  }
}

/** Every descendant process of `root` (from /proc/PID/stat's parent pid). */
function descendants(root) {
  const parent = new Map();
  for (const name of readdirSync('/proc')) {
    if (!/^\d+$/.test(name)) continue;
    const stat = readProc(name, 'stat');
    const m = /\) \S (\d+)/.exec(stat);
    if (m) parent.set(Number(name), Number(m[1]));
  }
  const out = [];
  const want = new Set([root]);
  let grew = true;
  while (grew) {
    grew = false;
    for (const [pid, ppid] of parent) {
      if (want.has(ppid) && !want.has(pid)) {
        want.add(pid);
        out.push(pid);
        grew = true;
      }
    }
  }
  return out;
}

/** Chromium renderer processes started by this script: { pid, rss, hwm } in bytes. */
export function renderers() {
  return descendants(process.pid)
    .filter((pid) => readProc(pid, 'cmdline').includes('--type=renderer'))
    .map((pid) => {
      const status = readProc(pid, 'status');
      const kb = (key) => Number(new RegExp(`^${key}:\\s+(\\d+) kB`, 'm').exec(status)?.[1] ?? NaN) * 1024;
      return { pid, rss: kb('VmRSS'), hwm: kb('VmHWM') };
    })
    .filter((p) => Number.isFinite(p.rss));
}

// -------------------------------------------------- page instrumentation

/**
 * Runs in the page before its scripts. Logs (page clock) the messages to and
 * from the worker, the body's data-rendered / data-drawn / data-opened
 * changes, key presses, the file input's change, file reads and
 * localStorage writes; keeps the main thread's long tasks and animation
 * frames; and collects the worker's own timings from the benchmark's
 * BroadcastChannel.
 */
export const PAGE_INIT = `(() => {
  const now = () => performance.now();
  const B = window.__bench = { log: [], worker: [], frames: [], longtasks: [], origin: performance.timeOrigin };
  try {
    new PerformanceObserver((list) => {
      for (const e of list.getEntries()) B.longtasks.push([e.startTime, e.duration]);
    }).observe({ type: 'longtask', buffered: true });
  } catch (e) { B.noLongtasks = String(e); }
  const frame = () => {
    B.frames.push(now());
    if (B.frames.length > 100000) B.frames.splice(0, 50000);
    requestAnimationFrame(frame);
  };
  requestAnimationFrame(frame);
  new BroadcastChannel('offsetlab-bench').onmessage = (e) => {
    const d = e.data;
    B.worker.push({ ...d, t: d.t - B.origin, end: d.end - B.origin, seen: now() });
  };
  const W = window.Worker;
  window.Worker = class extends W {
    constructor(...args) {
      super(...args);
      this.addEventListener('message', (e) => {
        const d = e.data || {};
        B.log.push({ t: now(), k: 'in', type: d.type, gen: d.gen });
      });
    }
    postMessage(m, ...rest) {
      const t = now();
      super.postMessage(m, ...rest);
      B.log.push({ t, end: now(), k: 'out', type: m && m.type, gen: m && m.gen, op: m && m.op });
    }
  };
  new MutationObserver((records) => {
    const t = now();
    for (const r of records) {
      if (r.target === document.body) B.log.push({ t, k: 'attr', name: r.attributeName, value: document.body.getAttribute(r.attributeName) });
    }
  }).observe(document, { subtree: true, attributes: true, attributeFilter: ['data-rendered', 'data-drawn', 'data-opened'] });
  addEventListener('keydown', (e) => B.log.push({ t: now(), k: 'key', key: e.key }), true);
  addEventListener('change', (e) => {
    if (e.target && e.target.id === 'open-file') B.log.push({ t: now(), k: 'change' });
  }, true);
  const text = Blob.prototype.text;
  Blob.prototype.text = function () {
    const t = now();
    const size = this.size;
    return text.call(this).then((v) => { B.log.push({ t, end: now(), k: 'blob-text', size }); return v; });
  };
  const setItem = Storage.prototype.setItem;
  Storage.prototype.setItem = function (key, value) {
    const t = now();
    try { return setItem.call(this, key, value); } finally {
      B.log.push({ t, end: now(), k: 'storage', key, chars: String(value).length });
    }
  };
  /**
   * Run \`gen\` as the page and the worker saw it, once it is drawn: the run
   * request, the result handled, the page's drawn message handled, the
   * worker's run, the render after it and the end of that frame.
   */
  B.settled = (gen) => {
    const L = B.log;
    const post = L.find((e) => e.k === 'out' && e.type === 'run' && e.gen === gen);
    let i = L.findIndex((e) => e.k === 'in' && e.type === 'result' && e.gen === gen);
    if (!post || i < 0) return null;
    const out = { gen, post: post.t, postEnd: post.end, result: L[i].t, rendered: null, drawnMessage: null };
    let drawnIn = null;
    for (i += 1; i < L.length && out.drawnMessage === null; i += 1) {
      const e = L[i];
      if (out.rendered === null && e.k === 'attr' && e.name === 'data-rendered') out.rendered = e.t;
      if (!drawnIn && e.k === 'in' && e.type === 'drawn') drawnIn = e;
      if (drawnIn && e.k === 'attr' && e.name === 'data-drawn' && e.t >= drawnIn.t) out.drawnMessage = e.t;
    }
    // worker.js starts the run in the microtask after the request arrives.
    out.run = B.worker.find((e) => e.name === 'run' && e.t >= post.t) || null;
    out.render = out.run && (B.worker.find((e) => e.name === 'render' && e.t >= out.run.end) || null);
    out.frame = out.render && (B.worker.find((e) => e.name === 'frame' && e.render === out.render.id) || null);
    return out;
  };
})();`;

/**
 * Evaluated in the worker: times Session.run and Session.render, and the end
 * of each frame (a timer set by render() fires once the worker thread is
 * free again, after the rasterisation that ends the animation frame); sends
 * each timing (absolute ms) to the page on the benchmark's BroadcastChannel.
 */
export async function instrumentWorker(page, { countCalls, experiment, limit }) {
  const worker = await within(
    (async () => {
      for (;;) {
        const [w] = page.workers();
        if (w) return w;
        await sleep(50);
      }
    })(),
    limit.step, 'the worker',
  );
  await within(worker.evaluate(async ([countCalls, experiment]) => {
    if (self.__bench) return;
    const m = await import(new URL('./pkg/offsetlab.js', self.location.href).href);
    const wasm = await m.default();
    const at = () => performance.timeOrigin + performance.now();
    const channel = new BroadcastChannel('offsetlab-bench');
    const B = { memory: wasm.memory, calls: null, id: 0 };
    self.__bench = B;
    if (experiment) {
      // --canvas-experiment: not the page as shipped.
      const C = OffscreenCanvasRenderingContext2D.prototype;
      const { lineTo, stroke, beginPath, moveTo, setLineDash } = C;
      if (experiment.nodash) C.setLineDash = function solid() { return setLineDash.call(this, []); };
      if (experiment.split > 0) {
        let n = 0;
        C.beginPath = function begin() { n = 0; return beginPath.call(this); };
        C.lineTo = function split(x, y) {
          lineTo.call(this, x, y);
          n += 1;
          if (n % experiment.split === 0) {
            stroke.call(this);
            beginPath.call(this);
            moveTo.call(this, x, y);
          }
        };
      }
    }
    if (countCalls) {
      const C = OffscreenCanvasRenderingContext2D.prototype;
      for (const name of ['lineTo', 'moveTo', 'stroke']) {
        const f = C[name];
        C[name] = function counted(...args) {
          if (B.calls) B.calls[name] += 1;
          return f.apply(this, args);
        };
      }
    }
    const P = m.Session.prototype;
    // The worker runs a program with run(), since 5f0e44d run_with_progress(),
    // since run_buffer() (the program written into wasm memory before the call).
    for (const name of ['run', 'run_with_progress', 'run_buffer']) {
      const run = P[name];
      if (typeof run !== 'function') continue;
      P[name] = function timedRun(...args) {
        const t = at();
        try {
          return run.apply(this, args);
        } finally {
          channel.postMessage({ name: 'run', t, end: at(), wasm: B.memory.buffer.byteLength });
        }
      };
    }
    // render() draws a whole frame; render_moving() (since the pixel layer)
    // a frame of a pan or zoom gesture, which returns true when it was the
    // last whole frame's pixels moved.
    for (const name of ['render', 'render_moving']) {
      const render = P[name];
      if (typeof render !== 'function') continue;
      P[name] = function timedRender(...args) {
        B.id += 1;
        const id = B.id;
        if (countCalls) B.calls = { lineTo: 0, moveTo: 0, stroke: 0 };
        const t = at();
        let result;
        try {
          result = render.apply(this, args);
          return result;
        } finally {
          const end = at();
          const calls = B.calls;
          B.calls = null;
          channel.postMessage({ name: 'render', id, t, end, calls, moving: result === true });
          setTimeout(() => channel.postMessage({ name: 'frame', render: id, t: end, end: at(), wasm: B.memory.buffer.byteLength }), 0);
        }
      };
    }
  }, [countCalls, experiment]), limit.step, 'instrumenting the worker');
  return worker;
}

/** A CDP session on the worker (through the browser's session), for Runtime.getHeapUsage. */
export async function workerCdp(browser) {
  const session = await browser.newBrowserCDPSession();
  const { targetInfos } = await session.send('Target.getTargets');
  const target = targetInfos.find((t) => t.type === 'worker' && t.url.endsWith('/worker.js'));
  if (!target) return null;
  const { sessionId } = await session.send('Target.attachToTarget', { targetId: target.targetId, flatten: false });
  let id = 0;
  const waiting = new Map();
  session.on('Target.receivedMessageFromTarget', (e) => {
    if (e.sessionId !== sessionId) return;
    const msg = JSON.parse(e.message);
    const w = waiting.get(msg.id);
    if (w) {
      waiting.delete(msg.id);
      w(msg.result ?? null);
    }
  });
  return {
    send(method, params = {}) {
      id += 1;
      const mine = id;
      return new Promise((resolve) => {
        waiting.set(mine, resolve);
        session.send('Target.sendMessageToTarget', { sessionId, message: JSON.stringify({ id: mine, method, params }) })
          .catch(() => resolve(null));
      });
    },
  };
}

/** Samples the JS heaps and the renderers' RSS every 200 ms until stopped; resolves to the highest of each. */
export function sampleMemory(pageCdp, worker, limit) {
  // byPid: the highest RSS (or VmHWM) seen of each renderer process.
  const peak = { pageHeap: 0, workerHeap: 0, workerSamples: 0, byPid: new Map() };
  let stop = false;
  let workerBusy = false;
  const loop = (async () => {
    while (!stop) {
      const r = await within(pageCdp.send('Runtime.getHeapUsage'), limit.cdp, 'page heap').catch(() => null);
      if (r) peak.pageHeap = Math.max(peak.pageHeap, r.usedSize);
      if (worker && !workerBusy) {
        workerBusy = true;
        // A busy worker answers when it is free: one question at a time.
        worker.send('Runtime.getHeapUsage').then((h) => {
          workerBusy = false;
          if (h) {
            peak.workerHeap = Math.max(peak.workerHeap, h.usedSize);
            peak.workerSamples += 1;
          }
        });
      }
      for (const p of renderers()) {
        peak.byPid.set(p.pid, Math.max(peak.byPid.get(p.pid) ?? 0, p.rss, p.hwm));
      }
      await sleep(200);
    }
  })();
  const done = async () => {
    stop = true;
    await loop;
    return peak;
  };
  done.peak = () => ({ ...peak, byPid: new Map(peak.byPid) });
  return done;
}

/**
 * The worker's renders (by id) and finished frames (each with the start of
 * its render), once the last frame begun by page time `last` has finished
 * (waited for at most `grace` ms: frames begun during the input may end a
 * little later).
 */
export async function workerFrames(page, last, grace) {
  await page.waitForFunction((t) => {
    const W = window.__bench.worker;
    const begun = W.filter((e) => e.name === 'render' && e.t <= t);
    const lastBegun = begun[begun.length - 1];
    return !lastBegun || W.some((e) => e.name === 'frame' && e.render === lastBegun.id);
  }, last, { timeout: grace }).catch(() => {});
  const W = await page.evaluate(() => window.__bench.worker);
  const renders = new Map(W.filter((e) => e.name === 'render').map((e) => [e.id, e]));
  const frames = W.filter((e) => e.name === 'frame').map((e) => ({ ...e, start: renders.get(e.render)?.t ?? e.t }));
  return { renders, frames };
}
