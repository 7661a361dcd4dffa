//! Reading a block's words: in one pass where nothing is wrong and no G
//! code changes how the words before it are read, else in two (behaviour 1 as
//! written: lex, then type and check each word). Both give the same blocks
//! and diagnostics ([`super::Blocks::next_into`] chooses).

use super::messages::unexpected_message;
use super::program::{Lead, line_end};
use super::*;

/// The addresses whose reading a G code later in the block can change: K
/// (a mill canned cycle's repeat count) and P, Q, R, D, A (a lathe G70–G76
/// block's words, behaviour 15.2).
/// The words pushed so far are those before the G code: the block's own
/// record of its addresses says whether any is one of these (no work per
/// word; the `check` instruction count in docs/performance.md).
const CONTEXT_ADDRESSES: [Address; 6] = [
    Address::K,
    Address::P,
    Address::Q,
    Address::R,
    Address::D,
    Address::A,
];

impl Blocks<'_> {
    /// Reads the words of a block from `i` (after any `/`) in one pass,
    /// typing each word as it is lexed with the G20/G21 and canned-cycle
    /// context so far. Returns the end of the block and the end of its last
    /// word or comment, or None if the block must be read in two passes
    /// ([`Blocks::read_two_pass`]) instead: when it has anything to report
    /// (the two-pass reading reports the lexing errors first, then each
    /// word's, and the cap of [`MAX_DIAGNOSTICS`] keeps the first ones), or
    /// when a G code changes how a word already read is read. Nothing is
    /// reported here, so there is nothing to undo but the words pushed and
    /// the context, which the caller restores.
    pub(super) fn read_one_pass(
        &mut self,
        mut i: usize,
        line: u32,
        counts: bool,
        block: &mut Block,
    ) -> Option<(usize, usize)> {
        let bytes = self.text.as_bytes();
        let n = bytes.len();
        let from = i;
        let mut last = i;
        let mut checks = Checks::default();
        // A G20/G21 after a dimension word, or a cycle code changing the
        // cycle state after a K word, changes how that word is read.
        let mut read_dimension = false;
        loop {
            i = lexer::skip_blanks(bytes, i);
            let Some(&c) = bytes.get(i) else { break };
            let Some(address) = Address::from_byte(c) else {
                match c {
                    b'\n' | b'\r' => break,
                    // A `;` comment (setting `semicolon`) is read in two
                    // passes: one arm here, as before.
                    b';' if self.options.semicolon_comments => return None,
                    b';' => break,
                    b'(' => {
                        let (after, closed) = lexer::comment(&bytes[i..])?;
                        if !closed {
                            return None;
                        }
                        if self.options.linuxcnc && speaks(&bytes[i..n - after.len()]) {
                            block.speaks = true;
                        }
                        i = n - after.len();
                        last = i;
                        continue;
                    }
                    // A letter offsetlab does not read, a character outside
                    // a word (errors), and the rare comma words `,C` `,R`
                    // (behaviour 1.7) are read in two passes: a second shape
                    // of word here cost every block (the `check`
                    // instruction count in docs/performance.md).
                    _ => return None,
                }
            };
            let (word_end, next, number) = lexer::number(bytes, i + 1);
            let number = number.ok()?;
            if address == Address::G && counts {
                let before = (self.units, self.in_cycle, self.mrc);
                self.note_context(number);
                if (read_dimension && self.units != before.0)
                    || ((self.in_cycle, self.mrc) != (before.1, before.2)
                        && block.holds_any(&CONTEXT_ADDRESSES))
                {
                    return None;
                }
            }
            let span = Span::new(i, word_end, line);
            let (word, kind) = self.read_word(address, number, span).ok()?;
            if kind == WordKind::Dimension {
                if self.integer_warning_due(number) {
                    return None;
                }
                read_dimension = true;
            }
            checks.admit(self.table, block, word).ok()?;
            last = word_end;
            i = next;
        }
        // The two-pass reading refuses a block past the limit (1.25).
        if i - from > MAX_BLOCK_BYTES {
            return None;
        }
        Some((i, last))
    }

    /// Reads the words of a block from `i` (after any `/`; the block starts
    /// at `start`) in two passes:
    /// lexes the whole block (reporting comment and character errors, and
    /// noting the G codes that change how numbers are read), then types
    /// every word with the block's context and checks it against the words
    /// before it, reporting what is wrong with each. This is the reading of
    /// behaviour 1 as written; [`Blocks::read_one_pass`] gives the same blocks
    /// and diagnostics faster for the blocks it reads. Returns what
    /// [`Blocks::read_one_pass`] returns. Out of line: few blocks take it,
    /// and inlined it made the one-pass reading's loop slower (the `check`
    /// instruction count in docs/performance.md).
    #[inline(never)]
    pub(super) fn read_two_pass(
        &mut self,
        start: usize,
        mut i: usize,
        line: u32,
        counts: bool,
        block: &mut Block,
    ) -> (usize, usize) {
        let bytes = self.text.as_bytes();
        let n = bytes.len();
        let mark = self.mark();
        self.before_block = (self.units, self.in_cycle);
        self.macro_end = None;
        self.header = None;
        self.raw.clear();
        self.whole_q = false;
        i = lexer::skip_blanks(bytes, i);
        let mut last = i;

        // A block past the limit is refused whole before it is lexed, so
        // no word, expression or diagnostic of it is kept (1.25).
        let extent = block_end(bytes, i, self.options.semicolon_comments);
        if extent - start > MAX_BLOCK_BYTES {
            let message = format!(
                "this block is {} bytes long: a block is read up to {} bytes (256 KiB); \
                 write it as several blocks",
                extent - start,
                MAX_BLOCK_BYTES
            );
            self.error_at(block, "block-too-long", start, extent, line, &message);
            return (extent, extent);
        }

        // What a block may start with besides words: a program header, or
        // a line of another dialect (behaviour 1.4, 1.21, 1.22).
        if let Some(b'O' | b'o' | b':' | b'<' | b'$') = bytes.get(i) {
            match self.block_lead(i, line, block) {
                Lead::Words => {}
                Lead::Name(after) => (i, last) = (after, after),
                Lead::Refused(end) => (i, last) = (end, end),
            }
        }

        // Lex: comments, words, and anything else as an error. Words are
        // typed once the whole block is lexed, because a G code anywhere in
        // it (G20/G21, a canned cycle) changes how its numbers are read;
        // those G codes are noted as they are lexed.
        loop {
            i = lexer::skip_blanks(bytes, i);
            if i >= n || self.ends_block(bytes[i]) {
                break;
            }
            let c = bytes[i];
            if c == b';' {
                // Only a comment reaches here (`ends_block`).
                i = line_end(bytes, i);
            } else if super::macro_words::opens(bytes, i)
                || (self.options.linuxcnc && super::macro_words::opens_polar(bytes, i))
            {
                i = self.read_macro(start, i, line, block);
            } else if c.is_ascii_alphabetic() || c == b':' || (self.options.linuxcnc && polar(c)) {
                let (word_end, _, number) = lexer::number(bytes, i + 1);
                // `:` is the program number address in ISO code (behaviour 1.4).
                let letter = match c {
                    b':' => b'O',
                    _ => c.to_ascii_uppercase(),
                };
                if letter == b'G'
                    && counts
                    && let Ok(number) = number
                {
                    self.note_context(number);
                }
                self.raw.push(RawWord {
                    letter,
                    comma: false,
                    number,
                    start: i,
                    end: word_end,
                });
                i = word_end;
            } else if c == b','
                && let Some(&l) = bytes.get(i + 1)
                && Address::comma(l).is_some()
            {
                let (word_end, _, number) = lexer::number(bytes, i + 2);
                self.raw.push(RawWord {
                    letter: l.to_ascii_uppercase(),
                    comma: true,
                    number,
                    start: i,
                    end: word_end,
                });
                i = word_end;
            } else if c == b'(' {
                let (after, closed) = lexer::comment(&bytes[i..]).unwrap_or((&[], false));
                let comment_end = n - after.len();
                if self.options.linuxcnc && speaks(&bytes[i..comment_end]) {
                    block.speaks = true;
                }
                if !closed {
                    self.error_at(
                        block,
                        "unclosed-comment",
                        i,
                        comment_end,
                        line,
                        "this comment is not closed with `)` before the end of the line",
                    );
                }
                i = comment_end;
            } else {
                // Skip to the next thing that can start a word or a comment.
                let mut j = i + 1;
                while j < n
                    && !bytes[j].is_ascii_alphabetic()
                    && !matches!(bytes[j], b'(' | b':' | b';')
                    && !is_end(bytes[j])
                {
                    j += 1;
                }
                let ch = self.text[i..].chars().next().unwrap_or('?');
                let message = unexpected_message(ch);
                self.error_at(block, "unexpected-character", i, j, line, &message);
                i = j;
            }
            last = i;
        }
        let end = i;

        let raw = std::mem::take(&mut self.raw);
        // A macro call's G65/G66/G67 and its arguments (behaviour 21.1).
        let call = self.macro_call_code(&raw);
        // Type every word.
        let mut checks = Checks::default();
        for (k, w) in raw.iter().enumerate() {
            if let Some(c) = call
                && self.take_argument(c, k, w, start, line, block)
            {
                continue;
            }
            let Some(word) = self.type_word(w, line, block) else {
                continue;
            };
            match checks.admit(self.table, block, word) {
                Ok(()) => {}
                Err(Clash::Group(group)) if self.options.same_group == SameGroupCodes::LastWins => {
                    // Fanuc: the last code of the group specified is valid
                    // (behaviour 1.11): said, never silent.
                    let msg = self.replaced_message(block, &word, group);
                    self.report(Diagnostic::warning("modal-conflict", word.span, msg));
                    if let Some(code) = Code::of(self.table, word.gcode()) {
                        block.set_code(code, group);
                    }
                    block.push(word);
                }
                Err(clash) => {
                    let (code, msg) = self.clash_message(block, &word, clash);
                    self.error_word(block, code, &word, &msg);
                }
            }
        }
        self.raw = raw;
        if block.macros.is_some() {
            self.check_statement_alone(block);
        }
        // A program header (O, `:`, <NAME>, or a malformed number).
        let header = self
            .header
            .take()
            .or_else(|| block.get(Address::O).map(|w| w.span));
        if let Some(span) = header {
            self.program_header(span, block);
        }
        if block.error
            && start > 0
            && bytes[start - 1] == b';'
            && let Some(read) = self.semicolon_comment(mark, start, line, block)
        {
            return read;
        }
        (end, last)
    }
}

/// LinuxCNC's polar words `@` (distance) and `^` (angle) are words of its
/// dialect (behaviour 22.12); every other control refuses the characters.
fn polar(c: u8) -> bool {
    matches!(c, b'@' | b'^')
}

/// Where the block from `i` ends, as the two-pass lexing finds it: at the
/// first end of block outside a comment (a comment runs to `)` or to the
/// end of its line), or at the end of the text.
fn block_end(bytes: &[u8], mut i: usize, semicolon_comments: bool) -> usize {
    let n = bytes.len();
    while i < n {
        match bytes[i] {
            b';' if semicolon_comments => return line_end(bytes, i),
            b'\n' | b'\r' | b';' => return i,
            b'(' => {
                let (after, _) = lexer::comment(&bytes[i..]).unwrap_or((&[], false));
                i = n - after.len();
            }
            _ => i += 1,
        }
    }
    n
}
