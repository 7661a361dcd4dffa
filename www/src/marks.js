// The interpreter's findings in the editor: its diagnostics as lint marks
// with their messages after the end of the line (text only), and the
// current block's line while stepping; columns as the interpreter counts
// them (characters) turned into document offsets. An update that changes
// nothing is not made: each is an editor update over the whole document.

import { StateEffect, StateField } from '@codemirror/state';
import { Decoration, EditorView, WidgetType } from '@codemirror/view';
import { diagnosticCount, setDiagnostics } from '@codemirror/lint';

const setCurrent = StateEffect.define();
const setMessages = StateEffect.define();

/** The line of the current block (stepping), as a line decoration. */
const currentLine = StateField.define({
  create: () => Decoration.none,
  update(deco, tr) {
    deco = deco.map(tr.changes);
    for (const e of tr.effects) {
      if (!e.is(setCurrent)) continue;
      const n = e.value;
      if (n === null || n < 1 || n > tr.state.doc.lines) return Decoration.none;
      const line = tr.state.doc.line(n);
      return Decoration.set([Decoration.line({ class: 'cm-current-block' }).range(line.from)]);
    }
    return deco;
  },
  provide: (f) => EditorView.decorations.from(f),
});

/** A diagnostic's message shown after the end of its line (text only). */
class MessageWidget extends WidgetType {
  constructor(severity, text) {
    super();
    this.severity = severity;
    this.text = text;
  }

  eq(other) {
    return other.severity === this.severity && other.text === this.text;
  }

  toDOM() {
    const span = document.createElement('span');
    span.className = `cm-diag-message cm-diag-${this.severity}`;
    span.textContent = this.text;
    return span;
  }
}

const messages = StateField.define({
  create: () => Decoration.none,
  update(deco, tr) {
    deco = deco.map(tr.changes);
    for (const e of tr.effects) if (e.is(setMessages)) deco = e.value;
    return deco;
  },
  provide: (f) => EditorView.decorations.from(f),
});

/**
 * Document offsets of 1-based columns (in characters, as the interpreter
 * counts them) on 1-based lines. A line without characters outside the
 * Basic Multilingual Plane maps columns directly; a line with some is
 * mapped once and the map kept for the other columns asked for, so a
 * thousand diagnostics on a 1 MiB line stay fast (issue 7).
 */
export function columnOffsets(doc) {
  const maps = new Map(); // line number → UTF-16 offset of each character, or null (one unit each)
  return (line, column) => {
    const l = doc.line(Math.min(Math.max(1, line), doc.lines));
    if (!maps.has(l.number)) {
      let map = null;
      if (/[\uD800-\uDBFF]/.test(l.text)) {
        map = [];
        for (let i = 0; i < l.text.length; i += 1) {
          map.push(i);
          // A surrogate pair is one character (as Array.from counts); a lone surrogate is one too.
          const c = l.text.charCodeAt(i);
          const next = l.text.charCodeAt(i + 1);
          if (c >= 0xd800 && c <= 0xdbff && next >= 0xdc00 && next <= 0xdfff) i += 1;
        }
      }
      maps.set(l.number, map);
    }
    const map = maps.get(l.number);
    const index = Math.max(0, column - 1);
    if (!map) return l.from + Math.min(index, l.length);
    return l.from + (index < map.length ? map[index] : l.length);
  };
}

/** Document offset of 1-based `column` (in characters) on 1-based `line`. */
export function offsetAt(doc, line, column) {
  return columnOffsets(doc)(line, column);
}

/** The decorations of this module, for the editor's extensions. */
export const marks = [currentLine, messages];

/**
 * The transactions (none, or one) that show `list` (the interpreter's
 * diagnostics [{severity, code, message, line, column, end_column}], line
 * > 0) in `state`: none when there is none before and none now.
 */
export function diagnosticsUpdate(state, list) {
  const { doc } = state;
  const inDoc = list.filter((d) => d.line > 0 && d.line <= doc.lines);
  if (inDoc.length === 0 && diagnosticCount(state) === 0 && state.field(messages).size === 0) return [];
  const at = columnOffsets(doc);
  const lint = inDoc.map((d) => {
    const from = at(d.line, d.column);
    const to = Math.max(from, at(d.line, d.end_column));
    return { from, to, severity: d.severity === 'error' ? 'error' : 'warning', message: `${d.code}: ${d.message}` };
  });
  const firstOnLine = new Map();
  for (const d of inDoc) if (!firstOnLine.has(d.line)) firstOnLine.set(d.line, { d, more: 0 });
  for (const d of inDoc) if (firstOnLine.get(d.line).d !== d) firstOnLine.get(d.line).more += 1;
  const widgets = [...firstOnLine.values()]
    .sort((a, b) => a.d.line - b.d.line)
    .map(({ d, more }) => Decoration.widget({
      widget: new MessageWidget(d.severity, more ? `${d.message} (+${more} more)` : d.message),
      side: 1,
    }).range(doc.line(d.line).to));
  const { effects } = setDiagnostics(state, lint);
  return [{ effects: [].concat(effects, setMessages.of(Decoration.set(widgets, true))) }];
}

/**
 * The transaction that highlights 1-based `line` as the current block
 * (null: none), scrolled into view if `scroll`; null when there is no
 * current line before and none now.
 */
export function currentLineUpdate(state, line, scroll) {
  if ((line === null || line < 1) && state.field(currentLine).size === 0) return null;
  const effects = [setCurrent.of(line)];
  if (scroll && line >= 1 && line <= state.doc.lines) {
    effects.push(EditorView.scrollIntoView(state.doc.line(line).from, { y: 'nearest' }));
  }
  return { effects };
}
