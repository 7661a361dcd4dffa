// Files in and out: downloads (a Blob or text saved under a name) and the
// name files get — the program number (O2001 → "O2001") or "offsetlab".

/** The stem of exported file names: `O<number>` of the program, or "offsetlab". */
export function fileStem(program) {
  const match = /^[ \t]*(?:\/\d?[ \t]*)?(?:N[ \t]*\d+[ \t]*)?O[ \t]*(\d{1,5})(?!\d)/im.exec(program ?? '');
  return match ? `O${match[1]}` : 'offsetlab';
}

/** Saves `data` (a Blob or text) as a download named `name`. */
export function download(data, name, type = 'text/plain;charset=utf-8') {
  const blob = data instanceof Blob ? data : new Blob([data], { type });
  const url = URL.createObjectURL(blob);
  const a = document.createElement('a');
  a.href = url;
  a.download = name;
  a.hidden = true;
  document.body.append(a);
  a.click();
  a.remove();
  // The browser has started the download by now; the URL can go later.
  setTimeout(() => URL.revokeObjectURL(url), 60_000);
}
