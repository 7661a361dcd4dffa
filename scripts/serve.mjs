#!/usr/bin/env node
// A dependency-free static server for www/ (the page, its modules and the
// wasm package), with the MIME types browsers insist on for modules and
// wasm, and no caching so a rebuilt package is always picked up. The
// Content-Security-Policy of <root>/index.html's <meta> tag is also sent as
// an HTTP header with every response (one policy, written once in the
// page; the header covers the worker's script too, which a <meta> cannot).
// A root without one (the tests' lesson-page fixtures) gets no policy.
//
//   node scripts/serve.mjs [--port 8000] [--host 127.0.0.1] [--root www]
//
// PORT and HOST in the environment work too; port 0 picks a free port. The
// first line printed is "offsetlab: serving <root> on http://HOST:PORT/".

import { createServer } from 'node:http';
import { createReadStream, readFileSync } from 'node:fs';
import { stat } from 'node:fs/promises';
import { extname, join, normalize, resolve, sep } from 'node:path';
import { fileURLToPath } from 'node:url';

const MIME = {
  '.html': 'text/html; charset=utf-8',
  '.js': 'text/javascript; charset=utf-8',
  '.mjs': 'text/javascript; charset=utf-8',
  '.css': 'text/css; charset=utf-8',
  '.json': 'application/json; charset=utf-8',
  '.map': 'application/json; charset=utf-8',
  '.wasm': 'application/wasm',
  '.svg': 'image/svg+xml',
  '.png': 'image/png',
  '.ico': 'image/x-icon',
  '.txt': 'text/plain; charset=utf-8',
  '.nc': 'text/plain; charset=utf-8',
  '.ts': 'text/plain; charset=utf-8',
};

function option(name, fallback) {
  const i = process.argv.indexOf(`--${name}`);
  if (i >= 0 && i + 1 < process.argv.length) return process.argv[i + 1];
  return fallback;
}

const here = fileURLToPath(new URL('.', import.meta.url));
const root = resolve(option('root', join(here, '..', 'www')));
const host = option('host', process.env.HOST || '127.0.0.1');
const port = Number(option('port', process.env.PORT || '8000'));

if (!Number.isInteger(port) || port < 0 || port > 65535) {
  console.error(`offsetlab: bad port ${JSON.stringify(String(port))}`);
  process.exit(2);
}

/** The policy of the root's index.html <meta http-equiv="Content-Security-Policy">, or null. */
function pagePolicy() {
  let html;
  try {
    html = readFileSync(join(root, 'index.html'), 'utf8');
  } catch {
    return null;
  }
  const meta = /<meta\s+http-equiv="Content-Security-Policy"\s+content="([^"]*)"/i.exec(html);
  return meta ? meta[1].replace(/\s+/g, ' ').trim() : null;
}
const policy = pagePolicy();
const security = policy ? { 'Content-Security-Policy': policy } : {};

function send(res, status, text) {
  res.writeHead(status, { 'Content-Type': 'text/plain; charset=utf-8', 'Cache-Control': 'no-store' });
  res.end(text);
}

async function handle(req, res) {
  if (req.method !== 'GET' && req.method !== 'HEAD') {
    send(res, 405, 'method not allowed\n');
    return;
  }
  let path;
  try {
    path = decodeURIComponent(new URL(req.url, 'http://localhost').pathname);
  } catch {
    send(res, 400, 'bad request\n');
    return;
  }
  if (path.includes('\0')) {
    send(res, 400, 'bad request\n');
    return;
  }
  let file = normalize(join(root, path));
  if (file !== root && !file.startsWith(root + sep)) {
    send(res, 403, 'forbidden\n');
    return;
  }
  let info;
  try {
    info = await stat(file);
    if (info.isDirectory()) {
      file = join(file, 'index.html');
      info = await stat(file);
    }
  } catch {
    send(res, 404, 'not found\n');
    return;
  }
  if (!info.isFile()) {
    send(res, 404, 'not found\n');
    return;
  }
  res.writeHead(200, {
    'Content-Type': MIME[extname(file).toLowerCase()] || 'application/octet-stream',
    'Content-Length': info.size,
    'Cache-Control': 'no-cache, no-store, must-revalidate',
    'X-Content-Type-Options': 'nosniff',
    ...security,
  });
  if (req.method === 'HEAD') {
    res.end();
    return;
  }
  createReadStream(file)
    .on('error', () => res.destroy())
    .pipe(res);
}

const server = createServer((req, res) => {
  handle(req, res).catch(() => send(res, 500, 'internal error\n'));
});

server.on('error', (error) => {
  console.error(`offsetlab: cannot serve on ${host}:${port}: ${error.message}`);
  process.exit(1);
});

server.listen(port, host, () => {
  const { port: actual } = server.address();
  console.log(`offsetlab: serving ${root} on http://${host}:${actual}/`);
});

for (const signal of ['SIGINT', 'SIGTERM']) {
  process.on(signal, () => server.close(() => process.exit(0)));
}
