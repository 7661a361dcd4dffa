// The Export menu: the current view as PNG (the worker's OffscreenCanvas,
// convertToBlob) and SVG (render_svg: both paths, arrows, legend), the
// toolpath as CSV and JSON (the CLI's `moves` fields, made in Rust), the
// program as .nc. Files are named after the program number or "offsetlab".

import { download, fileStem } from './files.js';

const FORMATS = {
  png: { suffix: '.png', type: 'image/png' },
  svg: { suffix: '.svg', type: 'image/svg+xml' },
  csv: { suffix: '-toolpath.csv', type: 'text/csv;charset=utf-8' },
  json: { suffix: '-toolpath.json', type: 'application/json' },
  nc: { suffix: '.nc', type: 'text/plain;charset=utf-8' },
};

/** `call(op, args)` asks the worker; `flush()` sends a waiting edit; `program()` is the text. */
export function initExport({ call, flush, program }) {
  const menu = document.getElementById('export');
  const status = document.getElementById('export-status');
  menu.addEventListener('click', async (event) => {
    const button = event.target.closest('button[data-export]');
    if (!button) return;
    const format = button.dataset.export;
    const { suffix, type } = FORMATS[format];
    menu.open = false;
    const text = program();
    const name = `${fileStem(text)}${suffix}`;
    status.textContent = '';
    try {
      if (format === 'nc') {
        download(text, name, type);
      } else {
        flush();
        download(await call('export', { format }), name, type);
      }
      status.textContent = `Saved ${name}`;
    } catch (error) {
      status.textContent = `Export failed: ${error.message}`;
    }
  });
  document.addEventListener('click', (event) => {
    if (menu.open && !menu.contains(event.target)) menu.open = false;
  });
  menu.addEventListener('keydown', (event) => {
    if (event.key === 'Escape' && menu.open) {
      menu.open = false;
      menu.querySelector('summary').focus();
    }
  });
}
