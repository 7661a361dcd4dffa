// Runs a program built for wasm32-wasip1 (examples/render_time, as the
// page's module is built) under Node's WASI, with /tmp readable: how
// docs/performance.md times the drawing in wasm outside the browser.
//   node scripts/wasi-run.mjs rt.wasm /tmp/p1m.nc 496 557 2 3
// (EDITED, if set, is passed on: render_time's edited program.)
import { readFileSync } from 'node:fs';
import { WASI } from 'node:wasi';

const [wasmPath, ...args] = process.argv.slice(2);
const wasi = new WASI({
  version: 'preview1',
  args: ['render_time', ...args],
  env: process.env.EDITED ? { EDITED: process.env.EDITED } : {},
  preopens: { '/tmp': '/tmp' },
  returnOnExit: true,
});
const module = await WebAssembly.compile(readFileSync(wasmPath));
const instance = await WebAssembly.instantiate(module, wasi.getImportObject());
process.exitCode = wasi.start(instance);
