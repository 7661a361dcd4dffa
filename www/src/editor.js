// The program editor: CodeMirror 6 with line numbers, G-code highlighting
// (gcode.js), undo/redo, the interpreter's diagnostics as inline marks with
// their messages at the end of the line and the current block's line
// highlighted while stepping (marks.js), long texts taken in steps
// (text.js). Bundled by esbuild into www/dist/editor.js (see the Makefile);
// the page imports only what this module exports.

import { Annotation, EditorState, Transaction } from '@codemirror/state';
import {
  EditorView, drawSelection, highlightActiveLineGutter, highlightSpecialChars, keymap, lineNumbers,
} from '@codemirror/view';
import { defaultKeymap, history, historyKeymap, redo, undo } from '@codemirror/commands';
import { syntaxHighlighting } from '@codemirror/language';
import { lintGutter } from '@codemirror/lint';
import { gcodeHighlight, gcodeLanguage } from './gcode.js';
import {
  currentLineUpdate, diagnosticsUpdate, marks, offsetAt,
} from './marks.js';
import { applyChanges, buildDocument } from './text.js';

/** The page's own replacement of the whole text (setText): not an edit of the user's. */
const loaded = Annotation.define();

/** Texts longer than this (UTF-16 units) are taken in steps (text.js). */
const LARGE_TEXT = 2 * 1024 * 1024;

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
  // The changes of the text since the last takeEdit() (a ChangeSet), or null.
  let since = null;
  const noteChanges = (trs) => {
    for (const tr of trs) {
      if (tr.docChanged) since = since ? since.compose(tr.changes) : tr.changes;
    }
  };
  // A long text being taken in steps: { text } (see setText).
  let pending = null;
  const view = new EditorView({
    parent,
    dispatchTransactions(trs, v) {
      const edit = trs.some((tr) => tr.docChanged && !tr.annotation(loaded));
      // No edits while a new text is on its way: it would replace them.
      if (edit && pending) return;
      if (edit) keepText(trs);
      noteChanges(trs);
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
        marks,
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

  // A typed character is put in by the editor itself, as its keymap does
  // Backspace, instead of letting the browser edit the contenteditable DOM
  // for the editor to read back: Chromium's own insertion took 1.5–3.5 ms
  // a key in a 10k-line program, before the page could send the run
  // (issue 6, target 4: keystroke to run request 4 ms for a digit, 0.4 ms
  // for Backspace). Only plain typing: compositions (IME, dead keys) and
  // the mobile browsers, whose keyboards work through compositions and
  // where a cancelled beforeinput is not always honoured, are left to the
  // browser and CodeMirror. So is typing over a selection or into an empty
  // line: the editor's update then replaces the DOM nodes the browser's
  // selection sits in, Chromium can report that selection where it was
  // (CodeMirror's issue 218), and the editor took it back: the cursor
  // jumped to the line's start after the first character typed into an
  // emptied editor, one run in five of an end-to-end test on a loaded
  // machine (2026-12-03). Those keys are few, and cheap the browser's way.
  if (!readOnly && !/Android|iPhone|iPad|iPod/.test(navigator.userAgent)) {
    view.contentDOM.addEventListener('beforeinput', (event) => {
      if (event.inputType !== 'insertText' || !event.data || !event.cancelable) return;
      if (event.isComposing || view.composing || view.state.readOnly) return;
      const { main } = view.state.selection;
      if (!main.empty || view.state.doc.lineAt(main.head).length === 0) return;
      event.preventDefault();
      view.dispatch(view.state.replaceSelection(event.data), {
        scrollIntoView: true,
        userEvent: 'input.type',
      });
    });
  }

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
    /**
     * What changed in the text since the last call, as one replacement:
     * `{ from, to, insert }` (`from` to `to` in UTF-16 units of the text
     * at the last call; `insert` what is there now), or null when a long
     * text is on its way (`getText()` is not the editor's text yet). The
     * page sends a run the edit instead of the whole text (issue 6: the
     * copy of a 3 MB text to the worker took 10 ms a keystroke).
     */
    takeEdit() {
      const changes = since;
      since = null;
      if (pending) return null;
      if (!changes) return { from: 0, to: 0, insert: '' };
      let [fromA, toA, fromB, toB] = [Infinity, -1, Infinity, -1];
      changes.iterChangedRanges((fa, ta, fb, tb) => {
        [fromA, toA] = [Math.min(fromA, fa), Math.max(toA, ta)];
        [fromB, toB] = [Math.min(fromB, fb), Math.max(toB, tb)];
      });
      if (toA < 0) return { from: 0, to: 0, insert: '' };
      return { from: fromA, to: toA, insert: currentDoc().sliceString(fromB, toB) };
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
     * `after`: a promise; a long text is not taken before it settles.
     */
    setText(value, { undoable = true, after = null } = {}) {
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
      const shown = buildDocument(value, { stale: () => mine !== serial, after }).then((built) => {
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
    for (const spec of diagnosticsUpdate(view.state, list)) view.dispatch(spec);
  }

  function showCurrentLine(line, scroll) {
    const spec = currentLineUpdate(view.state, line, scroll);
    if (spec) view.dispatch(spec);
  }

  function jump(line, column, endColumn) {
    const doc = view.state.doc;
    if (line < 1 || line > doc.lines) return;
    const anchor = offsetAt(doc, line, column);
    const head = Math.max(anchor, offsetAt(doc, line, endColumn ?? column));
    // Scrolled to the start, not the head: a block's range ends where a
    // long comment does, and its line:column is where it starts.
    view.dispatch({
      selection: { anchor, head },
      effects: EditorView.scrollIntoView(anchor, { y: 'nearest', x: 'nearest' }),
      userEvent: 'select',
    });
    view.focus();
  }

  // The first text, if long: not an edit to undo.
  if (doc.length > LARGE_TEXT) api.setText(doc, { undoable: false });
  return api;
}
