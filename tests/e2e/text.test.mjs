// www/src/text.js, checked in Node against CodeMirror itself: the editor's
// document of a long text built in steps (issue 6 target 3) against
// CodeMirror's reading of the whole text at once — every line break (LF,
// CR LF, a lone CR, at the end or not) and every place a step can end,
// including between the CR and the LF of a CR LF; and the editor's text
// kept through edits (applyChanges) against the document's own text.

import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { ChangeSet, Text } from '@codemirror/state';
import { applyChanges, buildDocument } from '../../www/src/text.js';

const now = () => Promise.resolve();
/** What CodeMirror makes of the text at once (EditorState.toText). */
const whole = (text) => Text.of(text.split(/\r\n?|\n/));

async function check(text, chunk) {
  const built = await buildDocument(text, { chunk, pause: now });
  const expected = whole(text);
  assert.equal(built.doc.lines, expected.lines, `lines of ${JSON.stringify(text)} in steps of ${chunk}`);
  assert.equal(built.doc.toString(), expected.toString(), `text of ${JSON.stringify(text)} in steps of ${chunk}`);
  assert.equal(built.text, expected.toString(), 'the text with LF line breaks');
  assert.ok(built.doc.eq(expected));
}

describe('a long text taken into the editor in steps', () => {
  test('every line break and every step boundary gives the lines CodeMirror reads at once', async () => {
    const texts = [
      '', 'G00', 'G00\n', '\n', '\n\n', 'a\nb\nc', 'a\nb\nc\n',
      'a\r\nb\r\nc\r\n', 'a\rb\rc', 'a\r\n\r\nb\n\rc\r', '\r\n', '\r', 'x\r\r\ny\n\nz',
      'N10 G01 X1.\r\nN20 Y2.;\nN30 (A\rB)\r\n\r\n',
    ];
    for (const text of texts) {
      for (let chunk = 0; chunk <= text.length + 1; chunk += 1) await check(text, chunk);
    }
  });

  test('a program of 50,000 lines in steps of 4 KiB, LF and CR LF', async () => {
    const lines = Array.from({ length: 50_000 }, (_, i) => `N${i} G01 X${i % 97}.5 Y${i % 13}.25`);
    await check(`${lines.join('\n')}\n`, 4096);
    await check(lines.join('\r\n'), 4096);
  });

  test('a newer text makes the build stop', async () => {
    let steps = 0;
    const built = await buildDocument('a\nb\nc\nd\n', { chunk: 1, pause: now, stale: () => (steps += 1) > 2 });
    assert.equal(built, null);
  });
});

describe('the editor’s text follows an edit without writing out the document', () => {
  test('random edits of a text give what CodeMirror makes of them', () => {
    let seed = 7;
    const random = (n) => {
      seed = (seed * 1103515245 + 12345) % 2147483648;
      return seed % n;
    };
    const words = ['', 'G', '7', '\n', 'X1.5 ', 'N10 G01\nY2.', '\n\n', ';'];
    let doc = Text.of('N10 G00 X0 Y0\nN20 G01 X10. F100.\nM30\n'.split('\n'));
    let text = doc.toString();
    for (let i = 0; i < 2000; i += 1) {
      const specs = [];
      for (let n = random(3) + 1, at = 0; n > 0 && at <= doc.length; n -= 1) {
        const from = at + random(doc.length - at + 1);
        const to = from + random(Math.min(5, doc.length - from) + 1);
        specs.push({ from, to, insert: words[random(words.length)] });
        at = to + 1;
      }
      const changes = ChangeSet.of(specs.filter((c) => c.to <= doc.length), doc.length);
      doc = changes.apply(doc);
      text = applyChanges(text, changes);
      assert.equal(text, doc.toString(), `edit ${i}`);
    }
  });
});
