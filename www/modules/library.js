// The setup's library of programs (behaviour 9.10, 19.10): programs kept
// by number with the document and its link, for M98 and G65 to call. The
// settings panel lists them (number and first line after the header) with
// a remove button each, and adds the programs pasted in its box, or in
// files opened or dropped on it (several at once, or a whole folder), each
// by its O or : header, as `offsetlab --program FILE|DIR` does.

const HEADER = /^[ \t]*[O:](\d{1,8})(?![A-MO-Za-mo-z])/i;

/** The programs of `text` by their headers: [[number, text]], or null when
 * it has no header or blocks before its first. */
export function programsIn(text) {
  const lines = text.replace(/^\uFEFF/, '').split(/(?<=\r\n|\n|\r)/);
  const found = [];
  let current = null;
  for (const l of lines) {
    const m = HEADER.exec(l);
    if (m) {
      current = [Number(m[1]), l];
      found.push(current);
    } else if (current) {
      current[1] += l;
    } else if (l.trim() !== '' && l.trim() !== '%') {
      return null;
    }
  }
  return found.length ? found : null;
}

/** The largest file read into the library (a link carries every program). */
const MAX_FILE_BYTES = 1 << 20;

/** What files give the library: the programs, and a sentence for each file
 * left out and each number held already (never passed over in silence). */
export async function programsOfFiles(files, held) {
  const add = [];
  const said = [];
  const numbers = new Set(Object.keys(held || {}).map(Number));
  for (const file of files) {
    const name = file.webkitRelativePath || file.name;
    if (file.size > MAX_FILE_BYTES) {
      said.push(`${name}: left out, larger than 1 MiB`);
      continue;
    }
    const programs = programsIn(await file.text());
    if (!programs) {
      said.push(`${name}: left out, no program header (O1002) before its first block`);
      continue;
    }
    for (const [n, text] of programs) {
      const label = `O${String(n).padStart(4, '0')}`;
      if (numbers.has(n)) {
        said.push(`${name}: ${label} is in the library already; the first kept`);
      } else {
        numbers.add(n);
        add.push([n, text]);
      }
    }
  }
  return { add, said };
}

/** The library section: a list, a box to paste programs in, and files or a
 * folder opened or dropped. */
export function librarySection({ getSetup, change }) {
  const box = document.createElement('details');
  box.className = 'library';
  box.id = 'library';
  const summary = document.createElement('summary');
  summary.textContent = 'Library programs';
  const help = document.createElement('p');
  help.className = 'help';
  help.textContent = 'Programs kept with the document and its link, for M98 and G65 to call by number. Paste them, open files or a folder, or drop files here. A program of the same number in the editor wins.';
  const list = document.createElement('ul');
  list.id = 'library-list';
  const paste = document.createElement('textarea');
  paste.id = 'library-paste';
  paste.rows = 4;
  paste.placeholder = 'O1002\nG91 G01 X10.\nM99';
  paste.setAttribute('aria-label', 'Programs to add to the library');
  const add = document.createElement('button');
  add.type = 'button';
  add.id = 'library-add';
  add.textContent = 'Add to library';
  const reason = document.createElement('p');
  reason.className = 'help';
  reason.id = 'library-reason';
  add.addEventListener('click', () => {
    const programs = programsIn(paste.value);
    if (!programs) {
      reason.textContent = 'Each program opens with its header (O1002): the library keeps programs by number.';
      return;
    }
    reason.textContent = '';
    change((s) => {
      s.programs = { ...(s.programs || {}) };
      for (const [n, text] of programs) if (!(n in s.programs)) s.programs[n] = text;
    }, 'settings');
    paste.value = '';
  });
  // Reading files is asynchronous: each finished reading is counted on the
  // section, so a test (or a script) can tell when its files were read.
  let reads = 0;
  const fromFiles = async (files) => {
    const { add: programs, said } = await programsOfFiles([...files], getSetup()?.programs);
    const n = programs.length;
    const added = n ? [`${n} program${n === 1 ? '' : 's'} added`] : ['No program added'];
    reason.textContent = [...added, ...said].join('. ') + '.';
    if (n) {
      change((s) => {
        s.programs = { ...(s.programs || {}) };
        for (const [k, text] of programs) if (!(k in s.programs)) s.programs[k] = text;
      }, 'settings');
    }
    reads += 1;
    box.dataset.reads = String(reads);
  };
  const picker = (id, label, folder) => {
    const input = document.createElement('input');
    input.type = 'file';
    input.id = id;
    input.multiple = true;
    if (folder) input.webkitdirectory = true;
    input.setAttribute('aria-label', label);
    input.addEventListener('change', () => {
      fromFiles(input.files).finally(() => { input.value = ''; });
    });
    const wrap = document.createElement('label');
    wrap.className = 'library-pick';
    wrap.append(label, ' ', input);
    return wrap;
  };
  const files = picker('library-files', 'Open files', false);
  const dir = picker('library-folder', 'Open a folder', true);
  box.addEventListener('dragover', (e) => {
    if (e.dataTransfer?.types?.includes('Files')) {
      e.preventDefault();
      box.classList.add('dropping');
    }
  });
  box.addEventListener('dragleave', () => box.classList.remove('dropping'));
  box.addEventListener('drop', (e) => {
    if (!e.dataTransfer?.files?.length) return;
    e.preventDefault();
    box.classList.remove('dropping');
    box.open = true;
    fromFiles(e.dataTransfer.files);
  });
  box.append(summary, help, list, paste, add, files, dir, reason);
  const render = () => {
    const programs = getSetup()?.programs || {};
    const rows = Object.keys(programs).map((n) => {
      const li = document.createElement('li');
      const text = String(programs[n]);
      const first = text.split(/\r\n|\n|\r/).map((l) => l.trim()).filter((l) => l && l !== '%');
      const label = document.createElement('span');
      label.textContent = `O${String(n).padStart(4, '0')} — ${first[1] ?? ''}`;
      const remove = document.createElement('button');
      remove.type = 'button';
      remove.textContent = 'Remove';
      remove.dataset.program = n;
      remove.setAttribute('aria-label', `Remove O${String(n).padStart(4, '0')} from the library`);
      remove.addEventListener('click', () => change((s) => {
        const next = { ...(s.programs || {}) };
        delete next[n];
        if (Object.keys(next).length) s.programs = next;
        else delete s.programs;
      }, 'settings'));
      li.append(label, ' ', remove);
      return li;
    });
    list.replaceChildren(...rows);
  };
  return { element: box, render };
}
