// The editor's document of a long text built in steps (www/src/text.js,
// issue 6 target 3), checked in Node against CodeMirror's own reading of the
// whole text at once: every line break (LF, CR LF, a lone CR, at the end or
// not) and every place a step can end, including between the CR and the LF
// of a CR LF.

import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { Text } from '@codemirror/state';
import { buildDocument } from '../../www/src/text.js';

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
