// The page of another commit for scripts/bench-browser.mjs --ref: built
// once per commit in target/bench-browser/ref-SHA/ (see buildRef), so that
// figures can be measured again on a commit's page while www/ and src/ move on.

import { spawnSync } from 'node:child_process';
import { createHash } from 'node:crypto';
import { existsSync, mkdirSync, readdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { ROOT } from '../tests/e2e/harness.mjs';

let opts = { log: () => {}, timeout: 20 * 60_000 };

/** Runs a command for the build of --ref, its output on standard error; throws when it fails. */
function build(cmd, args, options) {
  opts.log(`  ${cmd} ${args.join(' ')}`);
  const r = spawnSync(cmd, args, { stdio: ['ignore', process.stderr, process.stderr], timeout: opts.timeout, ...options });
  if (r.status !== 0) throw new Error(`${cmd} ${args.join(' ')} failed (${r.error?.message ?? `exit ${r.status}`})`);
  return r;
}

/** The md5 of a file (the built wasm module: which code a page runs). */
function md5(path) {
  return createHash('md5').update(readFileSync(path)).digest('hex');
}

/**
 * What a ref directory's stamp says: written after its build succeeded. A
 * directory without one (an interrupted build, or one made before the stamp
 * was: those could hold another commit's wasm) is built again.
 */
const STAMP = 'bench-ref.json';
const STAMP_VERSION = 2;

function readStamp(dir) {
  try {
    const stamp = JSON.parse(readFileSync(join(dir, STAMP), 'utf8'));
    return stamp.version === STAMP_VERSION ? stamp : null;
  } catch {
    return null;
  }
}

/**
 * The page of commit `rev`, built once in `options.dir`/ref-SHA/ (bench-browser's
 * target/bench-browser; `options.log` for progress, `options.timeout` ms per
 * build step): { root, sha, wasm (md5) }.
 *
 * The refs share one cargo target directory (the dependencies are built
 * once), so cargo must see each snapshot's sources as changed: `git archive`
 * gives every file its commit's time, older than the last build's outputs,
 * and cargo (whose fingerprint of a path package is the sources' times
 * against its outputs', whatever directory they sit in) took the crate for
 * fresh and handed every ref the wasm of the first one built. The files are
 * extracted with the time of extraction instead (tar -m), newer than any
 * output. The module is then optimised as `make wasm` optimises the working
 * tree's (binaryen's wasm-opt -O3, the repository's node_modules), so a ref
 * and the working tree compare.
 */
export function buildRef(rev, options) {
  opts = { ...opts, ...options };
  const BENCH_DIR = options.dir;
  const { log } = opts;
  const git = (args) => spawnSync('git', args, { cwd: ROOT, encoding: 'utf8' }).stdout.trim();
  const sha = git(['rev-parse', '--verify', `${rev}^{commit}`]);
  if (!/^[0-9a-f]{40}$/.test(sha)) throw new Error(`--ref ${rev}: not a commit`);
  // The tree of the sources the module is built from (src/ and the manifest).
  const sources = ['src', 'Cargo.toml', 'Cargo.lock'].map((p) => git(['rev-parse', `${sha}:${p}`])).join(' ');
  const dir = join(BENCH_DIR, `ref-${sha.slice(0, 12)}`);
  const www = join(dir, 'www');
  const wasmPath = join(www, 'pkg', 'offsetlab_bg.wasm');
  const stamp = readStamp(dir);
  if (stamp && stamp.sha === sha && existsSync(wasmPath) && md5(wasmPath) === stamp.wasm
    && existsSync(join(www, 'pkg', 'offsetlab.js')) && existsSync(join(www, 'dist', 'editor.js'))) {
    log(`page of ${sha.slice(0, 12)}: built before in ${dir} (wasm md5 ${stamp.wasm})`);
    return { root: www, sha, wasm: stamp.wasm };
  }
  log(`building the page of ${sha.slice(0, 12)} in ${dir}${existsSync(dir) ? ' (its earlier build has no valid stamp: built again)' : ''}`);
  rmSync(dir, { recursive: true, force: true });
  mkdirSync(dir, { recursive: true });
  build('sh', ['-c', `git -C "${ROOT}" archive ${sha} | tar -x -m -C "${dir}"`]);
  build('wasm-pack', ['build', '--target', 'web', '--out-dir', 'www/pkg'], {
    // Not the repository's target directory: cargo would take the snapshot's
    // build for the working tree's (same package, same fingerprint).
    cwd: dir, env: { ...process.env, CARGO_TARGET_DIR: join(BENCH_DIR, 'cargo') },
  });
  const wasmOpt = join(ROOT, 'node_modules', 'binaryen', 'bin', 'wasm-opt');
  if (existsSync(wasmOpt)) {
    build('node', [wasmOpt, '-O3', wasmPath, '-o', wasmPath]);
  } else {
    log('  no node_modules/binaryen: the module is left unoptimised (not as `make wasm` builds the working tree)');
  }
  // The snapshot's own build:page script, with the repository's node_modules.
  build('npm', ['run', '--silent', 'build:page'], {
    cwd: dir, env: { ...process.env, PATH: `${join(ROOT, 'node_modules', '.bin')}:${process.env.PATH}` },
  });
  const wasm = md5(wasmPath);
  log(`  wasm md5 ${wasm} (sources ${sources})`);
  // Another ref of other sources with this very module: right when the
  // change did not reach the page's module (comments, tests, the CLI), or a
  // build that was not its own; said, for whoever bisects to judge.
  for (const other of readdirSync(BENCH_DIR).filter((n) => n.startsWith('ref-'))) {
    const o = readStamp(join(BENCH_DIR, other));
    if (o && o.sha !== sha && o.wasm === wasm && o.sources !== sources) {
      log(`  note: the same wasm as ${o.sha.slice(0, 12)}'s, whose src/ or manifest differ (a change the module does not contain?)`);
    }
  }
  writeFileSync(join(dir, STAMP), `${JSON.stringify({ version: STAMP_VERSION, sha, sources, wasm }, null, 2)}\n`);
  return { root: www, sha, wasm };
}
