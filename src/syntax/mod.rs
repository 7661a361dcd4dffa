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
use codes::{Group, g_group, m_group};
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
        let is_end = |c: u8| c == b'\n' || c == b'\r' || c == b';';
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
        let mut last = i;
        block.skip = false;
        block.clear();
        block.error = false;
        self.raw.clear();

        if bytes[i] == b'/' {
            block.skip = true;
            i += 1;
            // `/1`…`/9` name a skip switch; offsetlab has one switch for all.
            if i < n && (b'1'..=b'9').contains(&bytes[i]) {
                i += 1;
            }
            last = i;
        }
        // A skipped block's G20/G21 do not count when block skip is on.
        let counts = !(block.skip && self.options.block_skip);

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
                let (after, number) = lexer::number(&bytes[i + 1..]);
                let word_end = n - after.len();
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
        while last > first && matches!(bytes[last - 1], b' ' | b'\t') {
            last -= 1;
        }
        block.span = Span::new(first, last, line);
        let end = i;

        let raw = std::mem::take(&mut self.raw);
        // Type every word.
        let mut seen = 0u32;
        let mut m_groups: [(u32, usize); 8] = [(0, 0); 8];
        let mut m_count = 0;
        for w in &raw {
            if let Some(word) = self.type_word(w, line, block) {
                let a = word.address;
                let idx = block.words.len();
                match a {
                    Address::G => match g_group(self.options.machine, word.gcode()) {
                        Ok(group) => {
                            if let Some(other) = block.group_word(group) {
                                let first = other.gcode();
                                let msg = format!(
                                    "{first} and {} are both in group {}; a block may hold one of them{}",
                                    word.gcode(),
                                    group.label(),
                                    conflict_hint(self.options.machine, group)
                                );
                                self.error_word(block, "modal-conflict", &word, &msg);
                                continue;
                            }
                            block.set_group(group);
                        }
                        Err(why) => {
                            self.error_word(block, "unsupported-g-code", &word, &why);
                            continue;
                        }
                    },
                    Address::M => {
                        let g = m_group(word.int());
                        if let Some(&(_, other)) =
                            m_groups[..m_count].iter().find(|(gr, _)| *gr == g)
                        {
                            let msg = format!(
                                "M{:02} and M{:02} exclude each other; a block may hold one of them",
                                block.words[other].int(),
                                word.int()
                            );
                            self.error_word(block, "modal-conflict", &word, &msg);
                            continue;
                        }
                        if m_count < m_groups.len() {
                            m_groups[m_count] = (g, idx);
                            m_count += 1;
                        }
                    }
                    _ => {
                        if seen & a.bit() != 0 {
                            let first = block.get(a).map(|f| f.span).unwrap_or(word.span);
                            let msg = format!(
                                "{} appears twice in this block ({} and {}); each address may appear once",
                                a.letter(),
                                &self.text[first.start as usize..first.end as usize],
                                &self.text[word.span.start as usize..word.span.end as usize],
                            );
                            self.error_word(block, "duplicate-address", &word, &msg);
                            continue;
                        }
                        seen |= a.bit();
                    }
                }
                block.push(word);
            }
        }
        self.raw = raw;
        if self.tape == Tape::Before {
            self.tape = Tape::Reading;
        }
        (end, !block.words.is_empty() || block.error)
    }

    /// Tracks the G codes that change how numbers are read: G20/G21 (least
    /// increment) and mill canned cycles (K is then a repeat count).
    fn note_context(&mut self, n: Number) {
        if n.frac_digits != 0 || n.negative {
            return;
        }
        match (self.options.machine, n.mantissa) {
            (_, 20) => self.units = Units::Inch,
            (_, 21) => self.units = Units::Mm,
            (MachineKind::Mill, 73 | 74 | 76 | 81..=89) => self.in_cycle = true,
            (MachineKind::Mill, 0..=3 | 80) => self.in_cycle = false,
            _ => {}
        }
    }

    /// Types one lexed word, reporting what is wrong with it.
    fn type_word(&mut self, w: &RawWord, line: u32, block: &mut Block) -> Option<Word> {
        let span = Span::new(w.start, w.end, line);
        // The word as written, sliced only for a message.
        let all = self.text;
        let text = || &all[w.start..w.end];
        let letter = w.letter as char;
        let Some(address) = Address::from_letter(w.letter) else {
            let msg = match letter {
                'A' | 'B' | 'C' => format!("{letter}: rotary axes are not modelled by offsetlab"),
                'E' => "E (thread lead) is not supported".to_string(),
                _ => format!("{letter} is not an address offsetlab reads"),
            };
            self.error_span(block, "unsupported-address", span, &msg);
            return None;
        };
        let n = match w.number {
            Ok(n) => n,
            Err(NumberError::Missing) => {
                let msg = format!("{letter} has no number: an address letter needs a value");
                self.error_span(block, "missing-number", span, &msg);
                return None;
            }
            Err(NumberError::Malformed) => {
                let msg = format!("{}: `{}` is not a number", text(), text()[1..].trim());
                self.error_span(block, "malformed-number", span, &msg);
                return None;
            }
            Err(NumberError::TooLong) => {
                let msg = format!("{}: too many digits for a control to read", text());
                self.error_span(block, "out-of-range", span, &msg);
                return None;
            }
        };
        let kind = if address == Address::K && self.in_cycle {
            WordKind::Integer
        } else {
            address.kind()
        };
        let value = match kind {
            WordKind::Integer if address == Address::G => {
                if n.negative || n.frac_digits > 1 || (n.point && n.frac_digits == 0) {
                    let msg = format!("{}: a G code is a number such as G01 or G05.1", text());
                    self.error_span(block, "malformed-number", span, &msg);
                    return None;
                }
                n.value()
            }
            WordKind::Integer => {
                if n.point {
                    let msg = format!(
                        "{}: {letter} takes a whole number, written without a decimal point",
                        text()
                    );
                    self.error_span(block, "decimal-point", span, &msg);
                    return None;
                }
                let limit = integer_limit(self.options, address, self.in_cycle);
                if n.negative && n.mantissa != 0 || n.mantissa > limit {
                    let msg = integer_range_message(text(), letter, address, limit, self.options);
                    self.error_span(block, "out-of-range", span, &msg);
                    return None;
                }
                if address == Address::T
                    && self.options.machine == MachineKind::Lathe
                    && n.mantissa % 100 > u64::from(self.options.table_size)
                {
                    let msg = format!(
                        "{}: offset number {:02} is beyond the offset table (00 to {:02})",
                        text(),
                        n.mantissa % 100,
                        self.options.table_size
                    );
                    self.error_span(block, "out-of-range", span, &msg);
                    return None;
                }
                n.mantissa as f64
            }
            WordKind::Feed => {
                let v = n.value();
                if !(0.0..=999_999.0).contains(&v) {
                    let msg = format!("{}: a feed rate is 0 to 999999", text());
                    self.error_span(block, "out-of-range", span, &msg);
                    return None;
                }
                v
            }
            WordKind::Dimension => {
                let units = self.units;
                let v = if n.point || self.options.decimal_input == DecimalInput::Calculator {
                    n.value()
                } else {
                    n.scaled(units.decimals() as u8)
                };
                let max = units.max_dimension();
                if v.abs() > max + 1e-9 {
                    let msg = format!(
                        "{} is outside ±{max:.*} {} (spec 1)",
                        text(),
                        units.decimals(),
                        units.as_str()
                    );
                    self.error_span(block, "out-of-range", span, &msg);
                    return None;
                }
                if !n.point
                    && n.mantissa != 0
                    && self.options.decimal_input == DecimalInput::Increment
                    && !self.warned_integer
                {
                    self.warned_integer = true;
                    let d = units.decimals();
                    let text = text();
                    let msg = format!(
                        "{text} has no decimal point: read as {v:.d$} {u} (least input increment {inc:.d$} {u}); \
                         write {letter}{v:.d$} for {v:.d$} {u}, or {text}. for {whole} {u} (setting decimal_input)",
                        u = units.as_str(),
                        inc = units.increment(),
                        whole = n.value(),
                    );
                    self.report(Diagnostic::warning("integer-dimension", span, msg));
                }
                v
            }
        };
        Some(Word {
            address,
            value,
            point: n.point,
            span,
        })
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
