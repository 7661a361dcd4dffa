// The program editor: CodeMirror 6 with line numbers, G-code highlighting,
// undo/redo, the interpreter's diagnostics as inline marks (with their
// messages at the end of the line), and the current block's line
// highlighted while stepping. Bundled by esbuild into www/dist/editor.js
// (see the Makefile); the page imports only what this module exports.

import {
  Annotation, EditorState, StateEffect, StateField, Transaction,
} from '@codemirror/state';
import {
  Decoration, EditorView, WidgetType, drawSelection, highlightActiveLineGutter,
  highlightSpecialChars, keymap, lineNumbers,
} from '@codemirror/view';
import { defaultKeymap, history, historyKeymap, redo, undo } from '@codemirror/commands';
import { syntaxHighlighting } from '@codemirror/language';
import { lintGutter, setDiagnostics } from '@codemirror/lint';
import { gcodeHighlight, gcodeLanguage } from './gcode.js';
import { applyChanges, buildDocument } from './text.js';

const setCurrent = StateEffect.define();
const setMessages = StateEffect.define();
/** The page's own replacement of the whole text (setText): not an edit of the user's. */
const loaded = Annotation.define();

/** Texts longer than this (UTF-16 units) are taken in steps (text.js). */
const LARGE_TEXT = 2 * 1024 * 1024;

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
function columnOffsets(doc) {
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
function offsetAt(doc, line, column) {
  return columnOffsets(doc)(line, column);
}

const theme = EditorView.theme({
  '&': { color: 'var(--ink)', backgroundColor: 'var(--field)', height: '100%' },
  '.cm-content': { fontFamily: 'var(--mono)', caretColor: 'var(--ink)' },
  '.cm-gutters': { backgroundColor: 'var(--panel-2)', color: 'var(--muted)', borderRight: '1px solid var(--line)' },
  '.cm-activeLineGutter': { backgroundColor: 'var(--line)' },
  '&.cm-focused .cm-cursor': { borderLeftColor: 'var(--ink)' },
  '&.cm-focused > .cm-scroller > .cm-selectionLayer .cm-selectionBackground, .cm-selectionBackground':
    { backgroundColor: 'var(--selection) !important' },
  '.cm-scroller': { overflow: 'auto' },
});

/**
 * Creates the editor in `parent` (`readOnly`: no edits by the user).
 * `onChange()` follows every edit (`getText()` has the new text): it is
 * called before the editor updates its view, so that the page can send the
 * program to the worker at once and the worker runs it while this thread
 * draws the edit (issue 6, target 4: the view update is most of the time
 * of a keystroke). `onCursorLine(line)` is called when the user moves the
 * cursor (click or arrow keys) without editing.
 */
export function createEditor(parent, { doc = '', label = 'Program', readOnly = false, onChange, onCursorLine } = {}) {
  // The document of the edit being dispatched, before the view has it.
  let incoming = null;
  // A long text being taken in steps: { text } (see setText).
  let pending = null;
  const view = new EditorView({
    parent,
    dispatchTransactions(trs, v) {
      const edit = trs.some((tr) => tr.docChanged && !tr.annotation(loaded));
      // No edits while a new text is on its way: it would replace them.
      if (edit && pending) return;
      if (edit) keepText(trs);
      if (edit && onChange) {
        incoming = trs[trs.length - 1].newDoc;
        try {
          onChange();
        } finally {
          incoming = null;
          v.update(trs);
        }
      } else {
        v.update(trs);
      }
    },
    state: EditorState.create({
      // A long first text is taken in steps too (below).
      doc: doc.length > LARGE_TEXT ? '' : doc,
      extensions: [
        lineNumbers(),
        highlightActiveLineGutter(),
        highlightSpecialChars(),
        history(),
        drawSelection(),
        gcodeLanguage,
        syntaxHighlighting(gcodeHighlight),
        lintGutter(),
        currentLine,
        messages,
        theme,
        keymap.of([...defaultKeymap, ...historyKeymap]),
        // Read-only (embed mode): the text can be read, selected and copied,
        // and a click still selects the block on its line, but not edited.
        EditorState.readOnly.of(readOnly),
        EditorView.contentAttributes.of({
          ...(readOnly ? { 'aria-readonly': 'true' } : {}),
          'aria-label': label,
          spellcheck: 'false',
          autocapitalize: 'off',
          autocorrect: 'off',
        }),
        EditorView.updateListener.of((update) => {
          if (!update.docChanged && update.selectionSet && update.transactions.some((t) => t.isUserEvent('select'))) {
            const head = update.state.selection.main.head;
            onCursorLine?.(update.state.doc.lineAt(head).number);
          }
        }),
      ],
    }),
  });

  // The text of a document is made once, and an edit changes it rather
  // than making it again: a page handler may ask for it several times per
  // edit (run, autosave, address), and writing out a 30 MB program's
  // document takes a tenth of a second each time.
  let textOf = null;
  let text = '';
  const currentDoc = () => incoming ?? view.state.doc;
  /** The text made already follows an edit of its document. */
  function keepText(trs) {
    if (textOf !== trs[0].startState.doc) return;
    for (const tr of trs) text = applyChanges(text, tr.changes);
    textOf = trs[trs.length - 1].newDoc;
  }
  // Diagnostics shown, so that a run without any costs no editor update
  // (each is one over the whole document).
  let marked = false;
  // What the page asked to show while a text is on its way, shown with it.
  let later = [];
  let serial = 0;

  /** The whole document replaced by `insert` (its text is `value`): one edit, undoable or not. */
  function replaceDocument(insert, value, undoable) {
    view.dispatch({
      changes: { from: 0, to: view.state.doc.length, insert },
      annotations: [loaded.of(true), Transaction.addToHistory.of(undoable)],
      filter: false,
    });
    textOf = view.state.doc;
    text = value;
    const todo = later;
    later = [];
    for (const f of todo) f();
  }

  /** Runs `f` now, or once the text on its way is shown. */
  const whenShown = (key, f) => {
    if (!pending) {
      f();
      return;
    }
    later = later.filter((g) => g.key !== key);
    f.key = key;
    later.push(f);
  };

  const api = {
    view,
    getText() {
      if (pending) return pending.text;
      const d = currentDoc();
      if (d !== textOf) {
        textOf = d;
        text = textOf.toString();
      }
      return text;
    },
    /** The length of the text (without making it). */
    length: () => (pending ? pending.text.length : currentDoc().length),
    /** The selected text (for tests and the console). */
    selection: () => view.state.sliceDoc(view.state.selection.main.from, view.state.selection.main.to),
    /**
     * Replaces the whole text as one undoable edit (not an edit of the
     * user's: `onChange` is not called). Returns `{ text, shown }`: the text
     * as the editor holds it now and a promise of the moment it is shown. A
     * long text (LARGE_TEXT) is taken in steps: meanwhile `getText()` is
     * already the new text (with its line breaks as given: CR LF and CR,
     * which the interpreter reads as CodeMirror does, become LF once the
     * editor has it), the editor takes no edits, diagnostics, the current
     * line and jumps wait for it, and the editor is `aria-busy`.
     * `undoable: false`: not an edit to undo (the editor's first text).
     */
    setText(value, { undoable = true } = {}) {
      serial += 1;
      const mine = serial;
      later = []; // what was asked for the text before this one
      if (value.length <= LARGE_TEXT) {
        pending = null;
        parent.removeAttribute('aria-busy');
        const given = value.includes('\r') ? value.replace(/\r\n?/g, '\n') : value;
        replaceDocument(given, given, undoable);
        return { text: given, shown: Promise.resolve() };
      }
      pending = { text: value };
      parent.setAttribute('aria-busy', 'true');
      const shown = buildDocument(value, { stale: () => mine !== serial }).then((built) => {
        if (mine !== serial || !built) return; // a newer text replaced it
        pending = null;
        parent.removeAttribute('aria-busy');
        replaceDocument(built.doc, built.text, undoable);
      }, (error) => {
        // Never left waiting: the text in one go, as CodeMirror reads it.
        console.warn('offsetlab: the editor could not take the text in steps:', error?.message ?? error);
        if (mine !== serial) return;
        pending = null;
        parent.removeAttribute('aria-busy');
        const whole = value.replace(/\r\n?/g, '\n');
        replaceDocument(whole, whole, undoable);
      });
      return { text: value, shown };
    },
    undo: () => undo(view),
    redo: () => redo(view),
    focus: () => view.focus(),
    /** Diagnostics [{severity, message, line, column, end_column}] (line > 0). */
    setDiagnostics(list) {
      whenShown('diagnostics', () => showDiagnostics(list));
    },
    /** Highlights 1-based `line` as the current block (null: none). */
    showCurrent(line, scroll = true) {
      whenShown('current', () => showCurrentLine(line, scroll));
    },
    /** Selects line:column..endColumn and focuses the editor. */
    jumpTo(line, column, endColumn) {
      whenShown('jump', () => jump(line, column, endColumn));
    },
  };

  function showDiagnostics(list) {
    const doc = view.state.doc;
    const inDoc = list.filter((d) => d.line > 0 && d.line <= doc.lines);
    // None before and none now: nothing to change (marks follow the edits).
    if (inDoc.length === 0 && !marked) return;
    marked = inDoc.length > 0;
    const at = columnOffsets(doc);
    const marks = inDoc.map((d) => {
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
    view.dispatch(setDiagnostics(view.state, marks));
    view.dispatch({ effects: setMessages.of(Decoration.set(widgets, true)) });
  }

  function showCurrentLine(line, scroll) {
    // No current line before and none now: nothing to change.
    if ((line === null || line < 1) && view.state.field(currentLine).size === 0) return;
    const effects = [setCurrent.of(line)];
    if (scroll && line >= 1 && line <= view.state.doc.lines) {
      effects.push(EditorView.scrollIntoView(view.state.doc.line(line).from, { y: 'nearest' }));
    }
    view.dispatch({ effects });
  }

  function jump(line, column, endColumn) {
    const doc = view.state.doc;
    if (line < 1 || line > doc.lines) return;
    const anchor = offsetAt(doc, line, column);
    const head = Math.max(anchor, offsetAt(doc, line, endColumn ?? column));
    view.dispatch({ selection: { anchor, head }, scrollIntoView: true, userEvent: 'select' });
    view.focus();
  }

  // The first text, if long: not an edit to undo.
  if (doc.length > LARGE_TEXT) api.setText(doc, { undoable: false });
  return api;
}
