#!/usr/bin/env node
// The length of the share link of each built-in example, compact and plain,
// as made by `offsetlab link` (the codec the page uses), for the README
// table. The e2e tests check that the page's Share panel gives the same
// lengths and that the README shows them.
//
//   node scripts/link-lengths.mjs           print the table (markdown)
//   node scripts/link-lengths.mjs --write   replace the table in README.md
//
// Needs target/debug/offsetlab (cargo build).

import { execFileSync } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { EXAMPLES } from '../www/modules/examples.js';

const ROOT = join(dirname(fileURLToPath(import.meta.url)), '..');
const CLI = join(ROOT, 'target', 'debug', 'offsetlab');
const START = '<!-- link-lengths: made by scripts/link-lengths.mjs -->';
const END = '<!-- /link-lengths -->';

if (!existsSync(CLI)) execFileSync('cargo', ['build', '--quiet', '--bin', 'offsetlab'], { cwd: ROOT, stdio: 'inherit' });
const tmp = mkdtempSync(join(tmpdir(), 'offsetlab-lengths-'));

/** The links of an example as the page's Share panel makes them (default base). */
export function exampleLinks(example) {
  const program = join(tmp, `${example.id}.nc`);
  const setup = join(tmp, `${example.id}.json`);
  writeFileSync(program, example.program);
  writeFileSync(setup, JSON.stringify(example.setup));
  const args = ['link', '--setup', setup, ...(example.view?.plane ? ['--plane', example.view.plane] : []), program];
  return {
    compact: execFileSync(CLI, args, { encoding: 'utf8' }).trim(),
    plain: execFileSync(CLI, [...args.slice(0, 1), '--plain', ...args.slice(1)], { encoding: 'utf8' }).trim(),
  };
}

export function table() {
  const rows = EXAMPLES.map((example) => {
    const { compact, plain } = exampleLinks(example);
    return `| ${example.title} | ${example.program.length.toLocaleString('en-US')} | ${compact.length.toLocaleString('en-US')} | ${plain.length.toLocaleString('en-US')} |`;
  });
  return [
    START,
    '| example | program (characters) | compact link | plain link |',
    '| --- | ---: | ---: | ---: |',
    ...rows,
    END,
  ].join('\n');
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  const text = table();
  if (process.argv.includes('--write')) {
    const readme = join(ROOT, 'README.md');
    const before = readFileSync(readme, 'utf8');
    const start = before.indexOf(START);
    const end = before.indexOf(END);
    if (start < 0 || end < start) {
      console.error(`README.md has no ${START} … ${END} block`);
      process.exit(1);
    }
    writeFileSync(readme, before.slice(0, start) + text + before.slice(end + END.length));
    console.log('README.md: link lengths updated');
  } else {
    console.log(text);
  }
}
