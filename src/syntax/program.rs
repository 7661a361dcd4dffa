//! The program around the blocks (behaviour 1.3, 1.4, 1.21–1.23): program
//! headers (`O1234`, `:1234`, `<NAME>`) and the programs of a file, the
//! forms a Fanuc-family control does not read but other dialects write
//! (`;` comments, LinuxCNC o-words, CNCSimulator `$` directives, names after
//! O), each refused once with what to write instead, and a dwell's P written
//! with a decimal point.
//!
//! Everything here runs for the rare blocks that need it: the one-pass
//! reading of an ordinary block never reaches it (the `check` instruction
//! count in docs/performance.md).

use super::lexer::{self, Number, NumberError};
use super::{Address, Block, Blocks, Refusal, Tape, Word, WordKind, count_lines, is_end};
use crate::diag::{Diagnostic, Span};
use crate::setup::{DwellPDecimalPoint, SDecimalPoint};

/// Where the parser stands among the programs of a file.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(super) struct Programs {
    /// A program header has been read: the next one starts another program
    /// (behaviour 1.21).
    pub header: bool,
    /// A block was read before a closing `%`.
    pub block: bool,
    /// The tape has ended (a closing `%`) and the parser went on to another
    /// program: after a block, that is another program, header or none.
    pub ended: bool,
    /// The parser is past the first program: blocks are read for their
    /// diagnostics and not run.
    pub later: bool,
    /// A later program's header has just stopped the reading of blocks to
    /// run ([`Blocks::go_on_after_end`] goes on reading them for their
    /// diagnostics).
    pub stop: bool,
    /// The line where this program was told that `;` ends a block (0: not
    /// yet): the hint is given once a program (behaviour 1.22).
    pub semicolon_hint: u32,
}

/// What the first characters of a block are, read by
/// [`Blocks::block_lead`].
pub(super) enum Lead {
    /// Words, read as usual.
    Words,
    /// A program name `<NAME>` (Fanuc 30i): the words go on after it.
    Name(usize),
    /// A line refused whole (a diagnostic says why): the reading goes on at
    /// this position, the end of the line.
    Refused(usize),
}

/// True when the `o` at `i` is a label alone on its line, or before a
/// comment (`O1000 (NAME)`): rs274 reads it as the program's number and
/// runs on, as the Fanuc family reads a header (behaviour 22.7).
fn bare_label(bytes: &[u8], i: usize, line_end: usize) -> bool {
    let mut j = lexer::skip_blanks(bytes, i + 1);
    if bytes.get(j) == Some(&b'<') {
        match bytes[j..line_end].iter().position(|&c| c == b'>') {
            Some(k) => j += k + 1,
            None => return false,
        }
    } else {
        while j < line_end && bytes[j].is_ascii_digit() {
            j += 1;
        }
    }
    let j = lexer::skip_blanks(bytes, j);
    j >= line_end || matches!(bytes[j], b'(' | b';')
}

/// LinuxCNC o-word keywords (RS274NGC subroutines and control flow).
const O_WORD_KEYWORDS: [&str; 15] = [
    "sub",
    "endsub",
    "call",
    "return",
    "if",
    "elseif",
    "else",
    "endif",
    "while",
    "endwhile",
    "do",
    "repeat",
    "endrepeat",
    "break",
    "continue",
];

impl Blocks<'_> {
    /// Reads what a Fanuc-family control would not take at the start of a
    /// block at `i`: a name after O, a LinuxCNC o-word, a CNCSimulator `$`
    /// directive; or a `<NAME>` program name, which it takes. Only the
    /// two-pass reading asks (each of these fails the one-pass reading).
    pub(super) fn block_lead(&mut self, i: usize, line: u32, block: &mut Block) -> Lead {
        let bytes = self.text.as_bytes();
        let line_end = line_end(bytes, i);
        match bytes[i] {
            b'$' => {
                let word: String = self.text[i + 1..line_end]
                    .chars()
                    .take_while(char::is_ascii_alphanumeric)
                    .take(32)
                    .collect();
                let msg = format!(
                    "`${word}` is a CNCSimulator Pro directive, not G-code: a Fanuc-family control reads no `$` line; delete the line or keep it as a comment in ( )"
                );
                self.refuse_line(block, "other-dialect", i, line_end, line, &msg)
            }
            b'<' => match name_end(bytes, i, line_end) {
                Some(after) => {
                    // Fanuc 30i: a file name in < > opens the program
                    // section (behaviour 1.4).
                    self.header = Some(Span::new(i, after, line));
                    Lead::Name(after)
                }
                None => {
                    let msg = "`<` opens a program name, which `>` closes on the same line (<NAME>, Fanuc 30i)";
                    let end = comment_or_end(bytes, i, line_end);
                    self.refuse_line(block, "program-name", i, end, line, msg)
                }
            },
            _ => self.program_number_lead(i, line, line_end, block),
        }
    }

    /// [`Blocks::block_lead`] for a block starting with `O` or `:`.
    fn program_number_lead(
        &mut self,
        i: usize,
        line: u32,
        line_end: usize,
        block: &mut Block,
    ) -> Lead {
        let bytes = self.text.as_bytes();
        if self.options.linuxcnc && bytes[i] != b':' && !bare_label(bytes, i, line_end) {
            // LinuxCNC: `o100 sub`, `o<name> call [1]` (behaviour 22.7).
            return match self.read_oword(i, line, block) {
                Ok(after) => Lead::Name(after),
                Err(()) => Lead::Refused(line_end),
            };
        }
        let (end, next, number) = lexer::number(bytes, i + 1);
        let (keyword_at, name) = match number {
            Ok(_) => {
                // O7997A: digits run straight into a letter with no number.
                let letter_follows = bytes.get(end).is_some_and(u8::is_ascii_alphabetic)
                    && lexer::number(bytes, end + 1).2 == Err(NumberError::Missing);
                (next, letter_follows)
            }
            Err(NumberError::Missing) => match bytes.get(next) {
                Some(b'<') => match name_end(bytes, next, line_end) {
                    Some(after) => (lexer::skip_blanks(bytes, after), true),
                    None => (next, true),
                },
                Some(c) if c.is_ascii_alphanumeric() || *c == b'[' => (next, true),
                // `O` alone, `:(…)`: the usual missing number.
                _ => return Lead::Words,
            },
            Err(_) => return Lead::Words,
        };
        if let Some(keyword) = o_word_keyword(bytes, keyword_at) {
            let kind = match keyword {
                "sub" | "endsub" | "call" | "return" => "a subroutine",
                _ => "control flow",
            };
            let msg = format!(
                "`{}` is a LinuxCNC o-word ({kind}): the program is written in LinuxCNC's RS274NGC dialect, not for a Fanuc-family control, which calls subprograms with M98 and loops with macro B; choose the LinuxCNC control (`--control linuxcnc`, the page's Control menu) to run it",
                quote(&self.text[i..line_end])
            );
            return self.refuse_line(block, "other-dialect", i, line_end, line, &msg);
        }
        if !name {
            return Lead::Words;
        }
        let end = trim_end(bytes, i, comment_or_end(bytes, i, line_end));
        let msg = format!(
            "`{}` is a program name written after O: Fanuc and Haas controls take only digits there (O1234, O01234) and would not register the program; offsetlab reads it as the program's name and runs on. Write O1234 (NAME), or, on a Fanuc 30i, <NAME> alone on the line",
            quote(&self.text[i..end])
        );
        // A header like any other (behaviour 1.4, 1.21): it moves nothing,
        // so the run goes on, with a warning that says what a control does.
        self.header = Some(Span::new(i, end, line));
        self.report(Diagnostic::warning(
            "program-name",
            Span::new(i, end, line),
            msg,
        ));
        Lead::Name(end)
    }

    /// Reports `msg` over `start..end` and skips the rest of the line.
    fn refuse_line(
        &mut self,
        block: &mut Block,
        code: &'static str,
        start: usize,
        end: usize,
        line: u32,
        msg: &str,
    ) -> Lead {
        let end = trim_end(self.text.as_bytes(), start, end);
        self.error_at(block, code, start, end, line, msg);
        Lead::Refused(line_end(self.text.as_bytes(), start))
    }

    /// A block with a program header (an O word, `<NAME>`, or a malformed
    /// number): the first header opens the program that runs, with the
    /// blocks before it; every later one, and one past a closing `%` after
    /// a block, starts a program that is not run, read from a fresh
    /// context, with a warning naming it (behaviour 1.21).
    pub(super) fn program_header(&mut self, span: Span, block: &mut Block) {
        let programs = &mut self.programs;
        if !(programs.header || programs.ended && programs.block) {
            programs.header = true;
            return;
        }
        let ordinal = if programs.later {
            "another"
        } else {
            "a second"
        };
        *programs = Programs {
            header: true,
            later: true,
            stop: true,
            semicolon_hint: 0,
            ..*programs
        };
        // The header's block is not run, nor any after it; the reading of
        // blocks to run ends here.
        block.clear();
        block.error = false;
        self.tape = Tape::Ended;
        (self.units, self.in_cycle) = (self.options.units, false);
        self.warned_integer = false;
        let name = quote(&self.text[span.start as usize..span.end as usize]);
        self.report(Diagnostic::warning(
            "program-not-run",
            span,
            format!(
                "`{name}` starts {ordinal} program in this file: a file's first program runs, and the others run when a program calls them (M98 P…, G65 P…); this one is not called"
            ),
        ));
    }

    /// The reading of blocks to run has stopped: at the text's end, at a
    /// closing `%`, or at the header of a later program. Reads the later
    /// programs for their diagnostics, and says so of text after the tape
    /// end that is no program (behaviour 1.3, 1.21). True when blocks to run
    /// follow after all (a first program after the tape marks).
    #[inline(never)]
    pub(super) fn go_on_after_end(&mut self, block: &mut Block) -> bool {
        if self.one_program {
            // A subprogram read for a call ends with its program.
            return false;
        }
        let bytes = self.text.as_bytes();
        loop {
            if self.programs.stop {
                self.programs.stop = false;
                self.tape = Tape::Reading;
            } else if self.tape != Tape::Ended || !self.program_after_tape_end() {
                break;
            } else if !self.programs.later {
                return true;
            }
            while self.pos < bytes.len() && self.tape != Tape::Ended {
                let line = self.line;
                let (end, _) = self.parse_block::<false>(self.pos, line, block);
                self.pos = self.after_block(end);
            }
        }
        if self.tape == Tape::Ended {
            let rest = &self.text[self.pos.min(self.text.len())..];
            if let Some(off) = rest.find(|c: char| !c.is_whitespace()) {
                let at = self.pos + off;
                let line = self.line + count_lines(&bytes[self.pos..at]);
                self.report(Diagnostic::warning(
                    "text-after-tape-end",
                    Span::new(at, at + 1, line),
                    "text after the closing % is not read: % marks the end of the tape",
                ));
            }
            self.pos = bytes.len();
        }
        false
    }

    /// After the closing `%`: true if another program follows (its header
    /// the first text past blanks, comments and `%` lines), with the parser
    /// moved to it; the tape is read again (behaviour 1.3).
    pub(super) fn program_after_tape_end(&mut self) -> bool {
        let bytes = self.text.as_bytes();
        let (mut p, mut lines) = (self.pos, 0u32);
        while p < bytes.len() {
            match bytes[p] {
                b'\r' if bytes.get(p + 1) == Some(&b'\n') => {
                    lines += 1;
                    p += 2;
                }
                b'\n' | b'\r' => {
                    lines += 1;
                    p += 1;
                }
                b' ' | b'\t' => p += 1,
                b';' if self.options.semicolon_comments => p = line_end(bytes, p),
                b'(' | b'%' => {
                    p = match bytes[p] {
                        b'(' => lexer::comment(&bytes[p..])
                            .map_or(p + 1, |(rest, _)| bytes.len() - rest.len()),
                        _ => line_end(bytes, p),
                    }
                }
                b'O' | b'o' | b':' | b'<' => {
                    self.pos = p;
                    self.line += lines;
                    self.tape = Tape::Started;
                    self.programs.ended = true;
                    return true;
                }
                _ => return false,
            }
        }
        false
    }

    /// A block after a `;` on its line that has errors of text that is not
    /// words: the program uses `;` to start a comment, as LinuxCNC and
    /// Mach3 do. One error for the rest of the line, the diagnostics of its
    /// words taken back, and the hint given once a program (behaviour 1.22).
    /// None when the block is not such text.
    pub(super) fn semicolon_comment(
        &mut self,
        since: Mark,
        start: usize,
        line: u32,
        block: &mut Block,
    ) -> Option<(usize, usize)> {
        let text_like = self.diagnostics[since.diagnostics.min(self.diagnostics.len())..]
            .iter()
            .any(|d| {
                matches!(
                    d.code,
                    "missing-number"
                        | "unexpected-character"
                        | "unsupported-address"
                        | "other-dialect"
                        | "program-name"
                )
            });
        if !text_like {
            return None;
        }
        let bytes = self.text.as_bytes();
        self.diagnostics.truncate(since.diagnostics);
        self.dropped = since.dropped;
        self.warned_integer = since.warned_integer;
        (self.units, self.in_cycle) = since.context;
        // The words' context taken back too: the one-pass reading of the
        // next block reads K by it (a G80 in the text after `;` cancels no
        // cycle).
        self.context = self.in_cycle || self.mrc.is_some();
        self.header = None;
        let first = lexer::skip_blanks(bytes, start);
        let end = line_end(bytes, first);
        let last = trim_end(bytes, first, end);
        block.clear();
        let msg = match self.programs.semicolon_hint {
            0 => {
                self.programs.semicolon_hint = line;
                "the text after `;` is read as words, and it is not G-code: `;` ends a block on Fanuc-family controls; write comments in ( )".to_string()
            }
            hint => format!(
                "the text after `;` is read as words, and it is not G-code (`;` ends a block: see line {hint})"
            ),
        };
        self.error_at(block, "semicolon-comment", first, last, line, &msg);
        Some((end, last))
    }

    /// What the parser reported and read up to now, to take back a block's
    /// diagnostics ([`Blocks::semicolon_comment`]).
    pub(super) fn mark(&self) -> Mark {
        Mark {
            diagnostics: self.diagnostics.len(),
            dropped: self.dropped,
            warned_integer: self.warned_integer,
            context: (self.units, self.in_cycle),
        }
    }

    /// A P word written with a decimal point: with setting
    /// `dwell_p_decimal_point = seconds` (Haas) a dwell in seconds, the
    /// word keeping its point (the machine reads it); an S word with one,
    /// with `s_decimal_point = value` (Haas), its value; otherwise refused
    /// (behaviour 1.23, 7.57). Called by the reading of a word only for a whole-
    /// number word with a point.
    #[cold]
    #[inline(never)]
    pub(super) fn decimal_allowed(
        &self,
        address: Address,
        n: Number,
        span: Span,
    ) -> Result<(Word, WordKind), Refusal> {
        let allowed = match address {
            Address::P => self.options.dwell_p != DwellPDecimalPoint::Error,
            // Haas: `S5000.` is the speed 5000 (behaviour 7.57).
            Address::S => self.options.s_point == SDecimalPoint::Value,
            _ => false,
        };
        if !allowed {
            return Err(Refusal::DecimalPoint);
        }
        let value = n.value();
        if n.negative && n.mantissa != 0 || value > super::MAX_INTEGER as f64 {
            return Err(Refusal::Integer(super::MAX_INTEGER));
        }
        let word = Word {
            address,
            value,
            point: true,
            span,
        };
        Ok((word, WordKind::Integer))
    }
}

/// What a block's reading may have to take back.
#[derive(Clone, Copy)]
pub(super) struct Mark {
    diagnostics: usize,
    dropped: usize,
    warned_integer: bool,
    context: (crate::setup::Units, bool),
}

/// The position of the end of the line holding `i` (its line feed or
/// carriage return, or the end of the text).
pub(super) fn line_end(bytes: &[u8], i: usize) -> usize {
    let mut j = i;
    while j < bytes.len() && bytes[j] != b'\n' && bytes[j] != b'\r' {
        j += 1;
    }
    j
}

/// The end of a block's text before its first comment or its end (of
/// block or of `line_end`).
fn comment_or_end(bytes: &[u8], i: usize, line_end: usize) -> usize {
    (i..line_end)
        .find(|&j| bytes[j] == b'(' || is_end(bytes[j]))
        .unwrap_or(line_end)
}

/// `end` moved back over blanks, not before `start`.
fn trim_end(bytes: &[u8], start: usize, mut end: usize) -> usize {
    while end > start && matches!(bytes[end - 1], b' ' | b'\t') {
        end -= 1;
    }
    end
}

/// The position after the `>` that closes the `<` at `i` on its line, if
/// one does (no end of block between).
fn name_end(bytes: &[u8], i: usize, line_end: usize) -> Option<usize> {
    (i + 1..line_end)
        .take_while(|&j| !is_end(bytes[j]))
        .find(|&j| bytes[j] == b'>')
        .map(|j| j + 1)
}

/// The LinuxCNC keyword written at `i` (any case), if one is: a whole word,
/// followed by no letter or digit.
fn o_word_keyword(bytes: &[u8], i: usize) -> Option<&'static str> {
    let len = bytes[i.min(bytes.len())..]
        .iter()
        .take_while(|c| c.is_ascii_alphanumeric() || **c == b'_')
        .count();
    let word = &bytes[i.min(bytes.len())..i.min(bytes.len()) + len];
    O_WORD_KEYWORDS
        .iter()
        .find(|k| k.as_bytes().eq_ignore_ascii_case(word))
        .copied()
}

/// Program text quoted in a message: printable ASCII only (no control or
/// invisible character reaches a message), at most 40 characters.
fn quote(text: &str) -> String {
    let mut out: String = text
        .trim()
        .chars()
        .filter(|c| c.is_ascii_graphic() || *c == ' ')
        .take(41)
        .collect();
    if out.chars().count() > 40 {
        out.truncate(39);
        out.push('…');
    }
    out
}
