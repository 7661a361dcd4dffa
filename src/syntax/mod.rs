//! Program text → blocks of typed words, each with its span (spec 1).
//!
//! The grammar of one block (words, numbers, comments) is in [`lexer`], written
//! with nom; this module splits the text into blocks, types every word, checks
//! ranges and modal groups, and keeps going after an error so that every parse
//! error of the whole program is reported.
//!
//! Parsing is streaming ([`Blocks`]): the interpreter pulls one block at a
//! time into a reused buffer, so a million-block program is never held as a
//! tree. [`parse`] collects the blocks for tools and tests.

mod block;
pub mod codes;
mod lexer;

pub use block::{Address, Block, Word, WordKind};

use crate::diag::{Diagnostic, Span};
use crate::setup::{DecimalInput, MachineKind, Setup, Units};
use codes::{Group, g_group, group_of, m_group};
use lexer::{Number, NumberError};

/// Most diagnostics one program reports; past this one more says so.
pub const MAX_DIAGNOSTICS: usize = 1000;

/// Largest program text read, in bytes (256 MiB). Spans are 32-bit byte
/// offsets, and a larger program is no program a control holds; a longer
/// text is refused whole with `program-too-large` before parsing.
pub const MAX_PROGRAM_BYTES: usize = 256 * 1024 * 1024;

/// The `program-too-large` error for a text over [`MAX_PROGRAM_BYTES`]
/// (line 0: it belongs to the program as a whole).
pub fn check_size(text: &str) -> Option<Diagnostic> {
    (text.len() > MAX_PROGRAM_BYTES).then(|| {
        Diagnostic::error(
            "program-too-large",
            Span::default(),
            format!(
                "the program is {} bytes; at most {} MiB ({MAX_PROGRAM_BYTES} bytes) are read",
                text.len(),
                MAX_PROGRAM_BYTES / (1024 * 1024)
            ),
        )
    })
}

/// Largest value of words that are always integers (eight digits).
const MAX_INTEGER: u64 = 99_999_999;

/// Largest repeat count (K/L) of a canned cycle.
pub const MAX_REPEATS: u64 = 9999;

/// What the parser needs to know from the setup.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ParseOptions {
    /// Which G codes exist and what they mean.
    pub machine: MachineKind,
    /// Units at program start (G20/G21 in the text change them).
    pub units: Units,
    /// Dimension words without a decimal point.
    pub decimal_input: DecimalInput,
    /// Highest D/H/T offset number.
    pub table_size: u16,
    /// Skipped blocks (`/`) do not change the parser's G20/G21 state.
    pub block_skip: bool,
}

impl Default for ParseOptions {
    fn default() -> Self {
        ParseOptions::from(&Setup::default())
    }
}

impl From<&Setup> for ParseOptions {
    fn from(s: &Setup) -> Self {
        ParseOptions {
            machine: s.machine,
            units: s.units,
            decimal_input: s.settings.decimal_input,
            table_size: s.table_size,
            block_skip: s.settings.block_skip,
        }
    }
}

/// A parsed program: its blocks and every parse diagnostic.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Program {
    /// Blocks with at least one word or a parse error, in order.
    pub blocks: Vec<Block>,
    /// Parse diagnostics, with line and column.
    pub diagnostics: Vec<Diagnostic>,
}

/// Parses a whole program (nothing of a text over [`MAX_PROGRAM_BYTES`]:
/// its one diagnostic is `program-too-large`).
pub fn parse(text: &str, options: &ParseOptions) -> Program {
    if let Some(d) = check_size(text) {
        return Program {
            blocks: Vec::new(),
            diagnostics: vec![d],
        };
    }
    let mut blocks = Blocks::new(text, *options);
    let mut out = Vec::new();
    let mut block = Block::default();
    while blocks.next_into(&mut block) {
        out.push(block.clone());
    }
    let mut diagnostics = blocks.into_diagnostics();
    crate::diag::finish(&mut diagnostics, text);
    Program {
        blocks: out,
        diagnostics,
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Tape {
    /// No `%` and no block seen yet.
    Before,
    /// Reading blocks.
    Reading,
    /// A closing `%` was read: nothing after it is part of the program.
    Ended,
}

/// Where the parser stands between two blocks: enough to go on from there
/// (a run's checkpoint; the diagnostics so far are not part of it).
#[derive(Clone, Copy, Debug)]
pub struct Resume {
    pos: usize,
    line: u32,
    units: Units,
    in_cycle: bool,
    tape: Tape,
    warned_integer: bool,
}

impl Resume {
    /// Byte offset of the next unread character.
    pub fn offset(&self) -> usize {
        self.pos
    }

    /// The line of the next unread character (1-based).
    pub fn line(&self) -> u32 {
        self.line
    }

    /// True when a parser at `other` reads the same text the way one here
    /// does: the same G20/G21 and canned-cycle context, tape state and
    /// warnings given (the place in the text aside).
    pub fn same_course(&self, other: &Resume) -> bool {
        (self.units, self.in_cycle, self.tape, self.warned_integer)
            == (
                other.units,
                other.in_cycle,
                other.tape,
                other.warned_integer,
            )
    }

    /// The same state `bytes` further on and `lines` lines further down
    /// (the place of this point in a text edited before it).
    pub fn shifted(self, bytes: i64, lines: i64) -> Resume {
        Resume {
            pos: shift(self.pos as i64, bytes) as usize,
            line: shift(i64::from(self.line), lines) as u32,
            ..self
        }
    }
}

/// `at + by`, never below 0 (places after an edit are past its start).
pub(crate) fn shift(at: i64, by: i64) -> i64 {
    (at + by).max(0)
}

/// A word as lexed, before it is typed.
#[derive(Clone, Copy)]
struct RawWord {
    letter: u8,
    number: Result<Number, NumberError>,
    start: usize,
    end: usize,
}

/// True for the characters that end a block (spec 1).
fn is_end(c: u8) -> bool {
    c == b'\n' || c == b'\r' || c == b';'
}

/// Why a word is refused (spec 1); [`Blocks::refusal_message`] says it.
#[derive(Clone, Copy, Debug)]
enum Refusal {
    /// A letter offsetlab does not read.
    Address,
    /// The number is missing, malformed or too long.
    Number(NumberError),
    /// A G code written otherwise than `G01` or `G05.1`.
    GCode,
    /// A decimal point in a word that takes a whole number.
    DecimalPoint,
    /// A whole number beyond its limit.
    Integer(u64),
    /// A lathe T code's offset number beyond the offset table.
    LatheOffset,
    /// A feed rate beyond 0 to 999999.
    Feed,
    /// A dimension beyond the units' range.
    Dimension,
}

/// Why the words before a word in its block exclude it (spec 1);
/// [`Blocks::clash_message`] says it.
#[derive(Clone, Debug)]
enum Clash {
    /// A G code this machine does not model, and why.
    UnknownGCode(String),
    /// A second G code of a modal group.
    Group(Group),
    /// An M code of the same group as an earlier one.
    MCode,
    /// A second word of an address that may appear once.
    Duplicate,
}

/// What a block's words so far exclude of the next one: a second word of an
/// address (but G and M), a second G code of a modal group (the block keeps
/// those), a second M code of an M group.
/// (The block's own record of its addresses says which it holds.)
#[derive(Default)]
struct Checks {
    /// The M groups seen (the first eight; the message finds their words
    /// again: clearing a table of their indexes too took a tenth of a short
    /// block's instructions, callgrind).
    m_groups: [u32; 8],
    m_count: usize,
}

impl Checks {
    /// Adds `word` to `block` unless an earlier word excludes it.
    #[inline(always)]
    fn admit(&mut self, machine: MachineKind, block: &mut Block, word: Word) -> Result<(), Clash> {
        let a = word.address;
        match a {
            Address::G => {
                let code = word.gcode();
                let Some(group) = group_of(machine, code) else {
                    let why = g_group(machine, code).err().unwrap_or_default();
                    return Err(Clash::UnknownGCode(why));
                };
                if block.holds_group(group) {
                    return Err(Clash::Group(group));
                }
                block.set_group(group);
            }
            Address::M => {
                let g = m_group(word.int());
                if self.m_groups[..self.m_count].contains(&g) {
                    return Err(Clash::MCode);
                }
                if self.m_count < self.m_groups.len() {
                    self.m_groups[self.m_count] = g;
                    self.m_count += 1;
                }
            }
            _ => {
                if block.holds(a) {
                    return Err(Clash::Duplicate);
                }
            }
        }
        block.push(word);
        Ok(())
    }
}

/// Streaming parser: yields one block at a time and collects diagnostics.
pub struct Blocks<'a> {
    text: &'a str,
    pos: usize,
    line: u32,
    options: ParseOptions,
    /// G20/G21 as last written (decimal input depends on it).
    units: Units,
    /// A mill canned cycle is active (K is then a repeat count).
    in_cycle: bool,
    tape: Tape,
    warned_integer: bool,
    diagnostics: Vec<Diagnostic>,
    dropped: usize,
    raw: Vec<RawWord>,
    /// Blocks are read in one pass where they can be (false in tests that
    /// compare it with the two-pass reading).
    one_pass: bool,
}

impl<'a> Blocks<'a> {
    /// Starts parsing `text`.
    pub fn new(text: &'a str, options: ParseOptions) -> Blocks<'a> {
        Blocks {
            text,
            pos: 0,
            line: 1,
            units: options.units,
            options,
            in_cycle: false,
            tape: Tape::Before,
            warned_integer: false,
            diagnostics: Vec::new(),
            dropped: 0,
            raw: Vec::with_capacity(16),
            one_pass: true,
        }
    }

    /// Where the parser stands (between blocks).
    pub fn resume_point(&self) -> Resume {
        Resume {
            pos: self.pos,
            line: self.line,
            units: self.units,
            in_cycle: self.in_cycle,
            tape: self.tape,
            warned_integer: self.warned_integer,
        }
    }

    /// Goes on parsing `text` from a point an earlier parser of the same
    /// text and options reached; it yields the blocks that one yielded next.
    pub fn resume(text: &'a str, options: ParseOptions, at: Resume) -> Blocks<'a> {
        Blocks {
            pos: at.pos.min(text.len()),
            line: at.line,
            units: at.units,
            in_cycle: at.in_cycle,
            tape: at.tape,
            warned_integer: at.warned_integer,
            ..Blocks::new(text, options)
        }
    }

    /// [`Blocks::resume`] with the diagnostics reported before `at` (they
    /// count against [`MAX_DIAGNOSTICS`] as they did then).
    pub fn resume_after(
        text: &'a str,
        options: ParseOptions,
        at: Resume,
        diagnostics: Vec<Diagnostic>,
    ) -> Blocks<'a> {
        Blocks {
            diagnostics,
            ..Blocks::resume(text, options, at)
        }
    }

    /// The diagnostics so far (without columns; see [`crate::diag::finish`]).
    pub fn diagnostics(&self) -> &[Diagnostic] {
        &self.diagnostics
    }

    /// Diagnostics passed over so far for being past [`MAX_DIAGNOSTICS`].
    pub fn dropped(&self) -> usize {
        self.dropped
    }

    /// Adds diagnostics reported elsewhere for text after this point (a
    /// run made again takes those of the earlier run's end), under the cap.
    pub(crate) fn report_all(&mut self, diagnostics: impl IntoIterator<Item = Diagnostic>) {
        for d in diagnostics {
            self.report(d);
        }
    }

    /// Every diagnostic, once parsing is done.
    pub fn into_diagnostics(mut self) -> Vec<Diagnostic> {
        if self.dropped > 0 {
            let span = self.diagnostics.last().map(|d| d.span).unwrap_or_default();
            self.diagnostics.push(Diagnostic::warning(
                "too-many-diagnostics",
                span,
                format!(
                    "{} more diagnostics were not reported (at most {MAX_DIAGNOSTICS} are)",
                    self.dropped
                ),
            ));
        }
        self.diagnostics
    }

    /// The current line (1-based): after the last block, the line it ended on.
    pub fn line(&self) -> u32 {
        self.line
    }

    /// Byte offset of the next unread character.
    pub fn offset(&self) -> usize {
        self.pos
    }

    /// Keeps a diagnostic unless [`MAX_DIAGNOSTICS`] are kept already (then
    /// it is counted in the closing `too-many-diagnostics` warning). The
    /// run's warnings share this cap with the parser's diagnostics.
    pub(crate) fn report(&mut self, d: Diagnostic) {
        if self.diagnostics.len() < MAX_DIAGNOSTICS {
            self.diagnostics.push(d);
        } else {
            self.dropped += 1;
        }
    }

    /// Reads the next block into `block`. Returns false at the end of the
    /// program. Blank and comment-only lines yield nothing.
    pub fn next_into(&mut self, block: &mut Block) -> bool {
        let bytes = self.text.as_bytes();
        while self.pos < bytes.len() && self.tape != Tape::Ended {
            let line = self.line;
            let (end, found) = self.parse_block(self.pos, line, block);
            self.pos = match bytes.get(end) {
                None => end,
                Some(b'\r') if bytes.get(end + 1) == Some(&b'\n') => {
                    self.line += 1;
                    end + 2
                }
                Some(b'\n' | b'\r') => {
                    self.line += 1;
                    end + 1
                }
                Some(_) => end + 1,
            };
            if found {
                return true;
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

    /// Parses the block that starts at `start`, up to its end-of-block
    /// character (newline or `;` outside a comment). Returns the position of
    /// that character (or the end of the text) and whether it is a block to
    /// execute.
    fn parse_block(&mut self, start: usize, line: u32, block: &mut Block) -> (usize, bool) {
        let bytes = self.text.as_bytes();
        let n = bytes.len();
        let mut i = lexer::skip_blanks(bytes, start);
        if i >= n || is_end(bytes[i]) {
            return (i, false);
        }
        if bytes[i] == b'%' {
            // Tape start before any block, tape end after (spec 1); the rest
            // of the line is not read.
            self.tape = if self.tape == Tape::Before {
                Tape::Reading
            } else {
                Tape::Ended
            };
            while i < n && bytes[i] != b'\n' && bytes[i] != b'\r' {
                i += 1;
            }
            return (i, false);
        }
        let first = i;
        block.skip = false;
        block.clear();
        block.error = false;

        if bytes[i] == b'/' {
            block.skip = true;
            i += 1;
            // `/1`…`/9` name a skip switch; offsetlab has one switch for all.
            if i < n && (b'1'..=b'9').contains(&bytes[i]) {
                i += 1;
            }
        }
        // A skipped block's G20/G21 do not count when block skip is on.
        let counts = !(block.skip && self.options.block_skip);

        // Nearly every block reads in one pass; the rest is read again, from
        // the context the block started with, the way the two-pass reading
        // (its specification) reads it.
        let context = (self.units, self.in_cycle);
        let read = match self.one_pass {
            true => self.read_one_pass(i, line, counts, block),
            false => None,
        };
        let (end, mut last) = read.unwrap_or_else(|| {
            (self.units, self.in_cycle) = context;
            block.clear();
            self.read_two_pass(i, line, counts, block)
        });
        while last > first && matches!(bytes[last - 1], b' ' | b'\t') {
            last -= 1;
        }
        block.span = Span::new(first, last, line);
        if self.tape == Tape::Before {
            self.tape = Tape::Reading;
        }
        (end, !block.words.is_empty() || block.error)
    }

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
    fn read_one_pass(
        &mut self,
        mut i: usize,
        line: u32,
        counts: bool,
        block: &mut Block,
    ) -> Option<(usize, usize)> {
        let bytes = self.text.as_bytes();
        let n = bytes.len();
        let mut last = i;
        let mut checks = Checks::default();
        // A G20/G21 after a dimension word, or a cycle code changing the
        // cycle state after a K word, changes how that word is read.
        let mut read_dimension = false;
        let mut read_k = false;
        loop {
            i = lexer::skip_blanks(bytes, i);
            let Some(&c) = bytes.get(i) else { break };
            let Some(address) = Address::from_byte(c) else {
                match c {
                    b'\n' | b'\r' | b';' => break,
                    b'(' => {
                        let (after, closed) = lexer::comment(&bytes[i..])?;
                        if !closed {
                            return None;
                        }
                        i = n - after.len();
                        last = i;
                        continue;
                    }
                    // A letter offsetlab does not read, a character outside
                    // a word: errors.
                    _ => return None,
                }
            };
            let (word_end, next, number) = lexer::number(bytes, i + 1);
            let number = number.ok()?;
            if address == Address::G && counts {
                let before = (self.units, self.in_cycle);
                self.note_context(number);
                if (read_dimension && self.units != before.0)
                    || (read_k && self.in_cycle != before.1)
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
            read_k |= address == Address::K;
            checks.admit(self.options.machine, block, word).ok()?;
            last = word_end;
            i = next;
        }
        Some((i, last))
    }

    /// Reads the words of a block from `i` (after any `/`) in two passes:
    /// lexes the whole block (reporting comment and character errors, and
    /// noting the G codes that change how numbers are read), then types
    /// every word with the block's context and checks it against the words
    /// before it, reporting what is wrong with each. This is the reading of
    /// spec 1 as written; [`Blocks::read_one_pass`] gives the same blocks
    /// and diagnostics faster for the blocks it reads. Returns what
    /// [`Blocks::read_one_pass`] returns.
    fn read_two_pass(
        &mut self,
        mut i: usize,
        line: u32,
        counts: bool,
        block: &mut Block,
    ) -> (usize, usize) {
        let bytes = self.text.as_bytes();
        let n = bytes.len();
        let mut last = i;
        self.raw.clear();

        // Lex: comments, words, and anything else as an error. Words are
        // typed once the whole block is lexed, because a G code anywhere in
        // it (G20/G21, a canned cycle) changes how its numbers are read;
        // those G codes are noted as they are lexed.
        loop {
            i = lexer::skip_blanks(bytes, i);
            if i >= n || is_end(bytes[i]) {
                break;
            }
            let c = bytes[i];
            if c.is_ascii_alphabetic() {
                let (word_end, _, number) = lexer::number(bytes, i + 1);
                let letter = c.to_ascii_uppercase();
                if letter == b'G'
                    && counts
                    && let Ok(number) = number
                {
                    self.note_context(number);
                }
                self.raw.push(RawWord {
                    letter,
                    number,
                    start: i,
                    end: word_end,
                });
                i = word_end;
            } else if c == b'(' {
                let (after, closed) = lexer::comment(&bytes[i..]).unwrap_or((&[], false));
                let comment_end = n - after.len();
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
                    && bytes[j] != b'('
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
        // Type every word.
        let mut checks = Checks::default();
        for w in &raw {
            let Some(word) = self.type_word(w, line, block) else {
                continue;
            };
            if let Err(clash) = checks.admit(self.options.machine, block, word) {
                let (code, msg) = self.clash_message(block, &word, clash);
                self.error_word(block, code, &word, &msg);
            }
        }
        self.raw = raw;
        (end, last)
    }

    /// Tracks the G codes that change how numbers are read: G20/G21 (least
    /// increment) and mill canned cycles (K is then a repeat count).
    fn note_context(&mut self, n: Number) {
        if n.frac_digits != 0 || n.negative {
            return;
        }
        // G00–G03 first: nearly every block has one.
        match (self.options.machine, n.mantissa) {
            (MachineKind::Mill, 0..=3 | 80) => self.in_cycle = false,
            (_, 20) => self.units = Units::Inch,
            (_, 21) => self.units = Units::Mm,
            (MachineKind::Mill, 73 | 74 | 76 | 81..=89) => self.in_cycle = true,
            _ => {}
        }
    }

    /// Types a word of an address offsetlab reads with the context the
    /// parser has now (units, canned cycle): the word and how its number was
    /// read, or why it is refused (spec 1). Both readings of a block type
    /// words with this.
    #[inline(always)]
    fn read_word(
        &self,
        address: Address,
        n: Number,
        span: Span,
    ) -> Result<(Word, WordKind), Refusal> {
        let kind = if address == Address::K && self.in_cycle {
            WordKind::Integer
        } else {
            address.kind()
        };
        let value = match kind {
            WordKind::Integer if address == Address::G => {
                if n.negative || n.frac_digits > 1 || (n.point && n.frac_digits == 0) {
                    return Err(Refusal::GCode);
                }
                n.value()
            }
            WordKind::Integer => {
                if n.point {
                    return Err(Refusal::DecimalPoint);
                }
                let limit = integer_limit(self.options, address, self.in_cycle);
                if n.negative && n.mantissa != 0 || n.mantissa > limit {
                    return Err(Refusal::Integer(limit));
                }
                if address == Address::T
                    && self.options.machine == MachineKind::Lathe
                    && n.mantissa % 100 > u64::from(self.options.table_size)
                {
                    return Err(Refusal::LatheOffset);
                }
                n.mantissa_f64()
            }
            WordKind::Feed => {
                let v = n.value();
                if !(0.0..=999_999.0).contains(&v) {
                    return Err(Refusal::Feed);
                }
                v
            }
            WordKind::Dimension => {
                let v = self.dimension(n);
                if v.abs() > self.units.max_dimension() + 1e-9 {
                    return Err(Refusal::Dimension);
                }
                v
            }
        };
        let word = Word {
            address,
            value,
            point: n.point,
            span,
        };
        Ok((word, kind))
    }

    /// The value of a dimension word in the current units (decimal input,
    /// spec 1).
    fn dimension(&self, n: Number) -> f64 {
        if n.point || self.options.decimal_input == DecimalInput::Calculator {
            n.value()
        } else {
            n.scaled(self.units.decimals() as u8)
        }
    }

    /// True if this dimension word's number is read in least increments and
    /// the program has not been warned about it yet (one warning a program).
    fn integer_warning_due(&self, n: Number) -> bool {
        !n.point
            && n.mantissa != 0
            && self.options.decimal_input == DecimalInput::Increment
            && !self.warned_integer
    }

    /// Types one lexed word, reporting what is wrong with it.
    fn type_word(&mut self, w: &RawWord, line: u32, block: &mut Block) -> Option<Word> {
        let span = Span::new(w.start, w.end, line);
        let read = Address::from_letter(w.letter)
            .ok_or(Refusal::Address)
            .and_then(|a| Ok((a, w.number.map_err(Refusal::Number)?)))
            .and_then(|(a, n)| self.read_word(a, n, span));
        match read {
            Ok((word, kind)) => {
                if kind == WordKind::Dimension
                    && let Ok(n) = w.number
                    && self.integer_warning_due(n)
                {
                    self.warned_integer = true;
                    let msg = self.integer_warning(w, n);
                    self.report(Diagnostic::warning("integer-dimension", span, msg));
                }
                Some(word)
            }
            Err(refusal) => {
                let (code, msg) = self.refusal_message(w, refusal);
                self.error_span(block, code, span, &msg);
                None
            }
        }
    }

    /// The `integer-dimension` warning's sentence.
    fn integer_warning(&self, w: &RawWord, n: Number) -> String {
        let units = self.units;
        let d = units.decimals();
        let v = self.dimension(n);
        let letter = w.letter as char;
        let text = &self.text[w.start..w.end];
        format!(
            "{text} has no decimal point: read as {v:.d$} {u} (least input increment {inc:.d$} {u}); \
             write {letter}{v:.d$} for {v:.d$} {u}, or {text}. for {whole} {u} (setting decimal_input)",
            u = units.as_str(),
            inc = units.increment(),
            whole = n.value(),
        )
    }

    /// The diagnostic code and sentence of a refused word.
    fn refusal_message(&self, w: &RawWord, refusal: Refusal) -> (&'static str, String) {
        // The word as written.
        let text = &self.text[w.start..w.end];
        let letter = w.letter as char;
        match refusal {
            Refusal::Address => {
                let msg = match letter {
                    'A' | 'B' | 'C' => {
                        format!("{letter}: rotary axes are not modelled by offsetlab")
                    }
                    'E' => "E (thread lead) is not supported".to_string(),
                    _ => format!("{letter} is not an address offsetlab reads"),
                };
                ("unsupported-address", msg)
            }
            Refusal::Number(NumberError::Missing) => (
                "missing-number",
                format!("{letter} has no number: an address letter needs a value"),
            ),
            Refusal::Number(NumberError::Malformed) => (
                "malformed-number",
                format!("{text}: `{}` is not a number", text[1..].trim()),
            ),
            Refusal::Number(NumberError::TooLong) => (
                "out-of-range",
                format!("{text}: too many digits for a control to read"),
            ),
            Refusal::GCode => (
                "malformed-number",
                format!("{text}: a G code is a number such as G01 or G05.1"),
            ),
            Refusal::DecimalPoint => (
                "decimal-point",
                format!("{text}: {letter} takes a whole number, written without a decimal point"),
            ),
            Refusal::Integer(limit) => {
                let address = Address::from_letter(w.letter).unwrap_or(Address::N);
                let msg = integer_range_message(text, letter, address, limit, self.options);
                ("out-of-range", msg)
            }
            Refusal::LatheOffset => {
                let offset = w.number.map_or(0, |n| n.mantissa % 100);
                let msg = format!(
                    "{text}: offset number {offset:02} is beyond the offset table (00 to {:02})",
                    self.options.table_size
                );
                ("out-of-range", msg)
            }
            Refusal::Feed => (
                "out-of-range",
                format!("{text}: a feed rate is 0 to 999999"),
            ),
            Refusal::Dimension => {
                let units = self.units;
                let msg = format!(
                    "{text} is outside ±{max:.*} {} (spec 1)",
                    units.decimals(),
                    units.as_str(),
                    max = units.max_dimension(),
                );
                ("out-of-range", msg)
            }
        }
    }

    /// The diagnostic code and sentence of a word the block's earlier words
    /// exclude.
    fn clash_message(&self, block: &Block, word: &Word, clash: Clash) -> (&'static str, String) {
        match clash {
            Clash::UnknownGCode(why) => ("unsupported-g-code", why),
            Clash::Group(group) => {
                let first = block.group_word(group).map_or(word.gcode(), Word::gcode);
                let msg = format!(
                    "{first} and {} are both in group {}; a block may hold one of them{}",
                    word.gcode(),
                    group.label(),
                    conflict_hint(self.options.machine, group)
                );
                ("modal-conflict", msg)
            }
            Clash::MCode => {
                // The block holds one M code of the group: the earlier one.
                let group = m_group(word.int());
                let earlier = block
                    .mcodes()
                    .map(|(m, _)| m)
                    .find(|m| m_group(*m) == group)
                    .unwrap_or_default();
                let msg = format!(
                    "M{earlier:02} and M{:02} exclude each other; a block may hold one of them",
                    word.int()
                );
                ("modal-conflict", msg)
            }
            Clash::Duplicate => {
                let a = word.address;
                let first = block.get(a).map_or(word.span, |f| f.span);
                let msg = format!(
                    "{} appears twice in this block ({} and {}); each address may appear once",
                    a.letter(),
                    &self.text[first.start as usize..first.end as usize],
                    &self.text[word.span.start as usize..word.span.end as usize],
                );
                ("duplicate-address", msg)
            }
        }
    }

    fn error_span(&mut self, block: &mut Block, code: &'static str, span: Span, msg: &str) {
        block.error = true;
        self.report(Diagnostic::error(code, span, msg));
    }

    fn error_word(&mut self, block: &mut Block, code: &'static str, word: &Word, msg: &str) {
        self.error_span(block, code, word.span, msg);
    }

    fn error_at(
        &mut self,
        block: &mut Block,
        code: &'static str,
        start: usize,
        end: usize,
        line: u32,
        msg: &str,
    ) {
        self.error_span(block, code, Span::new(start, end, line), msg);
    }
}

fn count_lines(bytes: &[u8]) -> u32 {
    let mut n = 0u32;
    let mut i = 0;
    while i < bytes.len() {
        match bytes[i] {
            b'\r' if bytes.get(i + 1) == Some(&b'\n') => {
                n += 1;
                i += 1;
            }
            b'\n' | b'\r' => n += 1,
            _ => {}
        }
        i += 1;
    }
    n
}

fn integer_limit(options: ParseOptions, address: Address, in_cycle: bool) -> u64 {
    match address {
        Address::D | Address::H => u64::from(options.table_size),
        Address::T if options.machine == MachineKind::Lathe => 9999,
        Address::L => MAX_REPEATS,
        Address::K if in_cycle => MAX_REPEATS,
        _ => MAX_INTEGER,
    }
}

fn integer_range_message(
    text: &str,
    letter: char,
    address: Address,
    limit: u64,
    options: ParseOptions,
) -> String {
    match address {
        Address::D | Address::H => format!(
            "{text}: offset number is beyond the offset table (00 to {:02})",
            options.table_size
        ),
        Address::T if options.machine == MachineKind::Lathe => {
            format!("{text}: a lathe T code is Tttoo, tool tt and offset oo (at most T9999)")
        }
        _ => format!("{text}: {letter} is a whole number from 0 to {limit}"),
    }
}

fn conflict_hint(machine: MachineKind, group: Group) -> &'static str {
    match (machine, group) {
        (MachineKind::Lathe, Group::Motion) => {
            " (on the lathe, G-code system A, G90/G92/G94 are turning cycles; X/Z are absolute and U/W incremental)"
        }
        (_, Group::NonModal) => " (one-shot codes such as G45–G48 take one per block, seed 003)",
        _ => "",
    }
}

fn unexpected_message(ch: char) -> String {
    match ch {
        '#' | '[' | ']' | '=' => {
            format!(
                "`{ch}` is not part of a word: macro variables and expressions are not supported"
            )
        }
        '/' => "`/` (optional block skip) must start the block".to_string(),
        '%' => "`%` marks the tape start or end and must be alone on its line".to_string(),
        ')' => "`)` closes no comment".to_string(),
        '\u{feff}' => "character '\\u{feff}' (a byte order mark) is not part of a program: save the file as UTF-8 without BOM".to_string(),
        // Controls and invisible characters (zero-width, bidirectional
        // overrides, combining marks) are written escaped, so that the
        // message shows them and cannot reorder the text around it.
        c if c.is_control() || c.escape_debug().nth(1).is_some() => {
            format!("character {:?} is not part of a program", c)
        }
        c => format!("`{c}` is not part of a word"),
    }
}

#[cfg(test)]
mod tests;
