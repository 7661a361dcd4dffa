// The setup's library of programs (behaviour 9.10, 19.10): programs kept
// by number with the document and its link, for M98 and G65 to call. The
// settings panel lists them (number and first line after the header) with
// a remove button each, and adds the programs pasted in its box, each by
// its O or : header, as `offsetlab --program FILE` does.

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

/** The library section: a list and a box to paste programs in. */
export function librarySection({ getSetup, change }) {
  const box = document.createElement('details');
  box.className = 'library';
  box.id = 'library';
  const summary = document.createElement('summary');
  summary.textContent = 'Library programs';
  const help = document.createElement('p');
  help.className = 'help';
  help.textContent = 'Programs kept with the document and its link, for M98 and G65 to call by number. A program of the same number in the editor wins.';
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
  box.append(summary, help, list, paste, add, reason);
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
