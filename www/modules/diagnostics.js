// The diagnostics list: severity, code, message and line:column of every
// problem the interpreter found; a click (or Enter/Space) jumps the editor
// there. Setup problems (line 0) open the setup document instead. Text only.

export function showDiagnostics(list, diagnostics, { jump, openSetup }) {
  if (diagnostics.length === 0) {
    const none = document.createElement('li');
    none.className = 'none';
    none.textContent = 'No problems found.';
    list.replaceChildren(none);
    return;
  }
  list.replaceChildren(...diagnostics.map((d) => item(d, { jump, openSetup })));
}

function item(d, { jump, openSetup }) {
  const li = document.createElement('li');
  li.className = d.severity;
  const part = (cls, text) => {
    const span = document.createElement('span');
    span.className = cls;
    span.textContent = text;
    return span;
  };
  const where = d.line > 0 ? `${d.line}:${d.column}` : 'setup';
  li.append(
    part('loc', where), ' ',
    part('severity', d.severity), ' ',
    part('code', `[${d.code}]`), ' ',
    part('message', d.message),
  );
  li.tabIndex = 0;
  li.setAttribute('role', 'button');
  li.title = d.line > 0 ? `Show line ${d.line} in the program` : 'Show the setup document';
  li.setAttribute('aria-label', `${d.severity} ${d.code} at ${where}: ${d.message}`);
  const go = () => (d.line > 0 ? jump(d.line, d.column, d.end_column) : openSetup());
  li.addEventListener('click', go);
  li.addEventListener('keydown', (e) => {
    if (e.key === 'Enter' || e.key === ' ') {
      e.preventDefault();
      go();
    }
  });
  return li;
}

/** Shows that the program was not run (the interpreter was stopped): one line of text. */
export function showNotRun(list, text) {
  const li = document.createElement('li');
  li.className = 'error stopped';
  li.textContent = text;
  list.replaceChildren(li);
}
