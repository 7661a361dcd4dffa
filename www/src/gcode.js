// G-code highlighting for CodeMirror: a small stream tokenizer. Each word
// gets a class by its address letter, so the G, M, axis, offset (D/H) and
// tool (T) words, N numbers and comments read apart (style.css colours them
// for light and dark schemes).

import { HighlightStyle, StreamLanguage } from '@codemirror/language';
import { Tag } from '@lezer/highlight';

const KINDS = {
  g: 'tok-g', // G codes: motion, plane, offsets, cycles
  m: 'tok-m', // M codes: spindle, coolant, stops
  n: 'tok-n', // N sequence numbers
  program: 'tok-program', // O program numbers and %
  axis: 'tok-axis', // X Y Z U W I J K R, LinuxCNC's @ ^: positions and arc words
  offset: 'tok-offset', // D and H: offset register words
  tool: 'tok-tool', // T: tool (and lathe offset) words
  feed: 'tok-feed', // F and S
  param: 'tok-param', // P Q L A B C E… and the comma words ,C ,R ,A
  comment: 'tok-comment',
  macro: 'tok-macro', // IF WHILE GOTO DO END THEN, comparisons, functions
  macroVariable: 'tok-variable', // #1, #[…]
  macroBracket: 'tok-bracket', // [ ] of a macro expression
  macroOperator: 'tok-operator', // = + - * of a macro expression
  macroNumber: 'tok-number', // a constant of a macro expression (`3` in `[#1 LT 3]`, DO`1`)
  skip: 'tok-skip', // the / of an optional block skip
  end: 'tok-end', // ; end of block
  invalid: 'tok-invalid',
};

const TAGS = Object.fromEntries(Object.keys(KINDS).map((k) => [k, Tag.define()]));

const BY_LETTER = {
  G: 'g', M: 'm', N: 'n', O: 'program',
  X: 'axis', Y: 'axis', Z: 'axis', U: 'axis', W: 'axis', I: 'axis', J: 'axis', K: 'axis', R: 'axis',
  D: 'offset', H: 'offset', T: 'tool', F: 'feed', S: 'feed',
};

// (The token names are not CodeMirror's legacy ones, `variable`, `number`,
// `bracket`, `operator`, which it would map to its own tags.)
const WORD = /^[A-Za-z][ \t]*[+-]?[ \t]*[0-9.]*/;

// Custom Macro B's keywords, operators and functions (behaviour 20), and
// LinuxCNC's o-word keywords and EXISTS (behaviour 22.7): two
// letters or more, never followed by a letter (G-code words are one letter
// and a number, so none of these is one).
const KEYWORD = /^(ENDSUB|ENDWHILE|ENDREPEAT|ENDIF|ELSEIF|ELSE|SUB|CALL|RETURN|REPEAT|BREAK|CONTINUE|EXISTS|WHILE|GOTO|THEN|END|DO|IF|EQ|NE|GT|LT|GE|LE|AND|OR|XOR|MOD|SIN|COS|TAN|ASIN|ACOS|ATAN|SQRT|ABS|ROUND|FIX|FUP|LN|EXP|POW|BIN|BCD|ADP)(?![A-Za-z])/i;

const KEYWORDS = new RegExp(KEYWORD.source.slice(1), 'gi');

export const gcodeLanguage = StreamLanguage.define({
  name: 'gcode',
  // `begins`: nothing but blanks read yet in this block, where a `/` is
  // the optional block skip (behaviour 1); elsewhere it divides (`#1 / 2`,
  // `ATAN[#1]/[#2]`).
  startState: () => ({ begins: true }),
  copyState: (s) => ({ ...s }),
  token(stream, state) {
    if (stream.sol()) state.begins = true;
    if (stream.eatSpace()) return null;
    const begins = state.begins;
    state.begins = false;
    const ch = stream.peek();
    if (ch === '(') {
      if (stream.skipTo(')')) stream.next();
      else stream.skipToEnd();
      return 'comment';
    }
    if (ch === ';') {
      // Text after `;` that is no G-code (two letters in a row that are no
      // macro word) is a comment: LinuxCNC's `;` comment, or the text the
      // Fanuc-family profiles refuse as one (behaviour 1.22, 7.61).
      const rest = stream.string.slice(stream.pos + 1).replace(/\([^)]*\)?/g, '');
      if (/[A-Za-z]{2}/.test(rest.replace(KEYWORDS, ''))) {
        stream.skipToEnd();
        return 'comment';
      }
      stream.next();
      state.begins = true;
      return 'end';
    }
    if (ch === '%') {
      stream.next();
      return 'program';
    }
    if (ch === '/' && begins) {
      stream.next();
      stream.match(/^[0-9]/);
      state.begins = true; // `/N10 …` and `/ G01 …`: the block follows
      return 'skip';
    }
    if (ch === ':' && begins && stream.match(/^:[0-9]+/)) return 'program'; // `:1000`, a program header (behaviour 19.1)
    // LinuxCNC's `o<name>` label (behaviour 22.7); `o100` reads as an O word.
    if (begins && stream.match(/^[oO][ \t]*<[^>\r\n]*>/)) return 'program';
    if (stream.match(KEYWORD)) return 'macro';
    // LinuxCNC's named parameter `#<name>` (behaviour 22.6), then `#1`.
    if (stream.match(/^#<[^>\r\n]*>/) || stream.match(/^#[0-9]*/)) return 'macroVariable';
    if (ch === '[' || ch === ']') {
      stream.next();
      return 'macroBracket';
    }
    // `,C` `,R` (chamfer and corner R, behaviour 2.30) and `,A`: one word.
    if (stream.match(/^,[A-Za-z][ \t]*[+-]?[ \t]*[0-9.]*/)) return 'param';
    // LinuxCNC's polar words `@` (distance) and `^` (angle) of the XY end
    // point (behaviour 22.12): axis words, as its o-words are highlighted
    // whatever the control (the Fanuc-family profiles refuse them on the run).
    if (stream.match(/^[@^][ \t]*[+-]?[ \t]*[0-9.]*/)) return 'axis';
    if (ch === '=' || ch === '*' || ch === '/' || ch === '+' || ch === '-' || ch === ',') {
      stream.next();
      return 'macroOperator';
    }
    if (stream.match(/^[0-9.]+/)) return 'macroNumber';
    const word = stream.match(WORD);
    if (word) return BY_LETTER[word[0][0].toUpperCase()] ?? 'param';
    stream.next();
    return 'invalid';
  },
  tokenTable: TAGS,
  languageData: { commentTokens: { block: { open: '(', close: ')' } } },
});

export const gcodeHighlight = HighlightStyle.define(
  Object.entries(KINDS).map(([kind, cls]) => ({ tag: TAGS[kind], class: cls })),
);
