//! Program text → blocks of typed words, each with its span (behaviour 1).
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
mod headers;
mod hint;
mod lexer;
mod macro_call;
mod macro_words;
mod messages;
mod percent;
mod program;
mod read;
mod resume;
mod words;

pub use headers::{Header, program_headers};
pub use hint::{MachineHint, machine_hint};
pub use resume::Resume;
pub(crate) use resume::shift;

pub use block::{Address, Block, Word, WordKind};
pub use macro_call::{Argument, CallCode, MacroCall, is_argument};
pub use macro_words::{MacroBlock, MacroWord, first_comment, resolve};

use crate::diag::{Diagnostic, Span};
use crate::setup::{
    DecimalInput, DepthWord, DwellPDecimalPoint, GCodeSystem, MachineKind, SDecimalPoint,
    SameGroupCodes, Setup, Units,
};
use codes::{Code, CodeTable, GCode, Group, MCode, NonModal, Repetitive, g_group};
use lexer::{Number, NumberError};

/// Most diagnostics one program reports; past this one more says so.
pub const MAX_DIAGNOSTICS: usize = 1000;

/// Largest program text read, in bytes (256 MiB). Spans are 32-bit byte
/// offsets, and a larger program is no program a control holds; a longer
/// text is refused whole with `program-too-large` before parsing.
pub const MAX_PROGRAM_BYTES: usize = 256 * 1024 * 1024;

/// Longest block read, in bytes (256 KiB), from its first character to its
/// end of block. No manual at hand gives the Fanuc, Haas or YASNAC figure
/// (a real block is a line of a few dozen characters; LinuxCNC reads 256
/// characters a line); a longer block is `block-too-long` and not read, so
/// the memory a block's reading takes stays small whatever one line holds
/// (behaviour 1.25).
pub const MAX_BLOCK_BYTES: usize = 256 * 1024;

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
    /// The lathe's G-code system (behaviour 7.18; the mill has one table).
    pub system: GCodeSystem,
    /// Two G codes of one modal group in a block (behaviour 1.11, 7.17).
    pub same_group: SameGroupCodes,
    /// A decimal point in a dwell's P (behaviour 1.23, 7.26).
    pub dwell_p: DwellPDecimalPoint,
    /// A decimal point in S (behaviour 1.13, 7.57).
    pub s_point: SDecimalPoint,
    /// Fanuc's abbreviations of the macro words read (behaviour 20.19).
    pub macro_abbreviations: bool,
    /// How D reads in a lathe G71/G72/G74–G76 block (behaviour 15.2).
    pub depth_word: DepthWord,
    /// G47 on the mill is Haas text engraving (behaviour 7.60).
    pub g47_engraving: bool,
    /// `;` starts a comment to the end of the line instead of ending the
    /// block (behaviour 1.22, 7.61: LinuxCNC).
    pub semicolon_comments: bool,
    /// The LinuxCNC dialect: a line of only a `(MSG,…)` comment is a block,
    /// which says its message when it runs (behaviour 22.2).
    pub linuxcnc: bool,
}

impl ParseOptions {
    /// The table G numbers are read with.
    #[inline(always)]
    pub fn table(&self) -> CodeTable {
        CodeTable::new(self.machine, self.system)
            .with_engraving(self.g47_engraving)
            .with_linuxcnc(self.linuxcnc)
    }
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
            decimal_input: s.settings.decimal_input(),
            table_size: s.table_size,
            block_skip: s.settings.block_skip,
            system: s.settings.gcode_system(),
            same_group: s.settings.same_group_codes(),
            dwell_p: s.settings.dwell_p_decimal_point(),
            s_point: s.settings.s_decimal_point(),
            macro_abbreviations: s.settings.macro_abbreviations()
                == crate::setup::MacroAbbreviations::Fanuc,
            depth_word: s.settings.depth_word(),
            g47_engraving: s.settings.g47() == crate::setup::G47Code::Engraving,
            semicolon_comments: s.settings.semicolon() == crate::setup::Semicolon::Comment,
            linuxcnc: s.settings.control == crate::setup::Control::Linuxcnc,
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

#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
enum Tape {
    /// No `%` and no block seen yet.
    Before,
    /// The tape start `%` was read, and no block yet.
    Started,
    /// Reading blocks.
    Reading,
    /// A closing `%` was read: nothing after it is part of the program but
    /// another program (behaviour 1.3); or a later program's header stopped
    /// the reading of blocks to run (behaviour 1.21).
    Ended,
}

/// A word as lexed, before it is typed.
#[derive(Clone, Copy)]
struct RawWord {
    /// The letter, upper case (of a comma word, the letter after the comma).
    letter: u8,
    /// A comma word: `,C` or `,R` (behaviour 1.7).
    comma: bool,
    number: Result<Number, NumberError>,
    start: usize,
    end: usize,
}

/// True for the characters that end a block (behaviour 1.1).
fn is_end(c: u8) -> bool {
    c == b'\n' || c == b'\r' || c == b';'
}

impl Blocks<'_> {
    /// [`is_end`], but `;` begins a comment with setting `semicolon =
    /// comment` (behaviour 7.61).
    #[inline(always)]
    fn ends_block(&self, c: u8) -> bool {
        c == b'\n' || c == b'\r' || (c == b';' && !self.options.semicolon_comments)
    }
}

/// Why a word is refused (behaviour 1); [`Blocks::refusal_message`] says it.
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

/// Why the words before a word in its block exclude it (behaviour 1);
/// [`Blocks::clash_message`] says it.
#[derive(Clone, Debug)]
enum Clash {
    /// A G code this machine does not model, and why.
    UnknownGCode(String),
    /// A second G code of a modal group (with the setting
    /// `same_group_codes = last_wins` it replaces the first, behaviour 1.11).
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
    /// again: clearing a table of their indexes too cost every block, see
    /// the `check` instruction count in docs/performance.md).
    m_groups: [u32; 8],
    m_count: usize,
}

impl Checks {
    /// Adds `word` to `block` unless an earlier word excludes it.
    #[inline(always)]
    fn admit(&mut self, table: CodeTable, block: &mut Block, word: Word) -> Result<(), Clash> {
        let a = word.address;
        match a {
            Address::G => {
                let written = word.gcode();
                let Some(code) = Code::of(table, written) else {
                    let why = g_group(table, written).err().unwrap_or_default();
                    return Err(Clash::UnknownGCode(why));
                };
                return self.admit_code(block, word, code);
            }
            Address::M => self.admit_mcode(table.machine(), &word)?,
            _ => {
                // rs274 takes the last of repeated `@` `^` (the machine says
                // so; behaviour 22.12).
                if block.holds(a) && !matches!(a, Address::PolarDist | Address::PolarAngle) {
                    return Err(Clash::Duplicate);
                }
            }
        }
        block.push(word);
        Ok(())
    }

    /// Notes the M group of an M word unless an earlier word has it. Out of
    /// line: few blocks have an M word, and every block reads through
    /// [`Checks::admit`] (the `check` instruction count in
    /// docs/performance.md).
    #[inline(never)]
    fn admit_mcode(&mut self, machine: MachineKind, word: &Word) -> Result<(), Clash> {
        let g = MCode::of(machine, word.int()).group();
        if self.m_groups[..self.m_count].contains(&g) {
            return Err(Clash::MCode);
        }
        if self.m_count < self.m_groups.len() {
            self.m_groups[self.m_count] = g;
            self.m_count += 1;
        }
        Ok(())
    }

    /// [`Checks::admit`] for a G word whose code is resolved.
    #[inline(always)]
    fn admit_code(&mut self, block: &mut Block, word: Word, code: Code) -> Result<(), Clash> {
        let group = code.group();
        if block.holds_group(group) {
            return Err(Clash::Group(group));
        }
        block.set_code(code, group);
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
    /// `options.table()`, kept: every G word is looked up in it.
    table: CodeTable,
    /// G20/G21 as last written (decimal input depends on it).
    units: Units,
    /// A mill canned cycle is active (K is then a repeat count).
    in_cycle: bool,
    /// The lathe G70–G76 code of the block being read (P, Q, R, D read as
    /// that cycle reads them: behaviour 15.2); None between blocks.
    mrc: Option<Repetitive>,
    /// `in_cycle || mrc.is_some()`: a word's address alone does not say how
    /// it reads (one test per word, as the canned cycles' K had).
    context: bool,
    /// The block read in two passes holds G05.1, whose Q (Q1/Q0) is no
    /// dimension to warn about (behaviour 14.4); set afresh by each two-pass
    /// reading (the one-pass reading leaves a block with a warning due to it).
    whole_q: bool,
    tape: Tape,
    warned_integer: bool,
    /// Which program of the file the parser is in (behaviour 1.21, 1.22).
    programs: program::Programs,
    /// A program header read in the current block besides an O word: a
    /// `<NAME>` or a malformed number (behaviour 1.4, 1.21; two-pass
    /// reading only).
    header: Option<Span>,
    diagnostics: Vec<Diagnostic>,
    dropped: usize,
    raw: Vec<RawWord>,
    /// Blocks are read in one pass where they can be (false in tests that
    /// compare it with the two-pass reading).
    one_pass: bool,
    /// The G20/G21 and canned-cycle context the block being read in two
    /// passes started with (its macro words are typed in it, behaviour 20.8).
    before_block: (Units, bool),
    /// The start and end of the block whose macro syntax is being read
    /// (its end looked up once).
    macro_end: Option<(usize, usize)>,
    /// The reading ends with the program it started in (a subprogram read
    /// for a call, behaviour 19.1): what follows its end is not read.
    one_program: bool,
}

impl<'a> Blocks<'a> {
    /// Starts parsing `text`.
    pub fn new(text: &'a str, options: ParseOptions) -> Blocks<'a> {
        Blocks {
            text,
            // A UTF-8 byte order mark is an encoding mark, not text (behaviour 1.9).
            pos: if text.starts_with('\u{feff}') { 3 } else { 0 },
            line: 1,
            units: options.units,
            table: options.table(),
            options,
            in_cycle: false,
            mrc: None,
            context: false,
            whole_q: false,
            tape: Tape::Before,
            warned_integer: false,
            programs: program::Programs::default(),
            header: None,
            diagnostics: Vec::new(),
            dropped: 0,
            raw: Vec::with_capacity(16),
            one_pass: true,
            before_block: (options.units, false),
            macro_end: None,
            one_program: false,
        }
    }

    /// This parser, reading only the program it stands in: it ends at
    /// that program's end (its `%`, or the next program's header), where
    /// the parser of a whole text goes on to read the other programs for
    /// their diagnostics (a subprogram's blocks, read for a call: behaviour
    /// 19.1).
    pub fn one_program(self) -> Blocks<'a> {
        Blocks {
            one_program: true,
            ..self
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
            programs: self.programs,
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
            context: at.in_cycle,
            tape: at.tape,
            warned_integer: at.warned_integer,
            programs: at.programs,
            ..Blocks::new(text, options)
        }
    }

    /// A second parser standing where this one stands, with no diagnostics
    /// (look-ahead reads the blocks after the running one with it; the run's
    /// parser reads and reports them when they run).
    pub fn fork(&self) -> Blocks<'a> {
        Blocks {
            one_program: self.one_program,
            ..Blocks::resume(self.text, self.options, self.resume_point())
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

    /// True once a closing `%` ended the tape (behaviour 1.3).
    pub fn tape_ended(&self) -> bool {
        self.tape == Tape::Ended
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
        loop {
            while self.pos < bytes.len() && self.tape != Tape::Ended {
                let line = self.line;
                let (end, found) = self.parse_block::<true>(self.pos, line, block);
                self.pos = self.after_block(end);
                if found {
                    return true;
                }
            }
            // The tape's end, or a later program: out of line, rare.
            if !self.go_on_after_end(block) {
                return false;
            }
        }
    }

    /// The position after the end of block at `end` (its end-of-block
    /// character), counting the line it ends.
    #[inline(always)]
    fn after_block(&mut self, end: usize) -> usize {
        let bytes = self.text.as_bytes();
        match bytes.get(end) {
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
        }
    }

    /// Parses the block that starts at `start`, up to its end-of-block
    /// character (newline or `;` outside a comment). Returns the position of
    /// that character (or the end of the text) and whether it is a block to
    /// execute.
    ///
    /// `FAST`: the one-pass reading is tried first (the blocks to run); the
    /// later programs of a file, read for their diagnostics only, take the
    /// two-pass reading, which gives the same blocks (a copy of its own
    /// keeps the hot loop's as it was: the `check` instruction count in
    /// docs/performance.md).
    fn parse_block<const FAST: bool>(
        &mut self,
        start: usize,
        line: u32,
        block: &mut Block,
    ) -> (usize, bool) {
        let bytes = self.text.as_bytes();
        let n = bytes.len();
        let mut i = lexer::skip_blanks(bytes, start);
        if i >= n || (is_end(bytes[i]) && !(bytes[i] == b';' && self.options.semicolon_comments)) {
            return (i, false);
        }
        if bytes[i] == b'%' {
            if self.options.linuxcnc
                && let Some(end) = self.linuxcnc_bad_percent(i, line, block)
            {
                return (end, true);
            }
            // Tape start before any block, tape end after (behaviour 1.3); the rest
            // of the line is not read.
            self.tape = match self.tape {
                Tape::Before => Tape::Started,
                Tape::Started | Tape::Ended => Tape::Ended,
                Tape::Reading => {
                    self.programs.block = true;
                    Tape::Ended
                }
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
        block.speaks = false;
        block.table = self.table;

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
        if self.mrc.is_some() {
            // A G70–G76 code counts for its own block only.
            self.mrc = None;
            self.context = self.in_cycle;
        }
        let context = (self.units, self.in_cycle);
        let read = match FAST && self.one_pass {
            true => self.read_one_pass(i, line, counts, block),
            false => None,
        };
        let (end, mut last) = read.unwrap_or_else(|| {
            (self.units, self.in_cycle) = context;
            self.mrc = None;
            self.context = self.in_cycle;
            block.clear();
            self.read_two_pass(start, i, line, counts, block)
        });
        while last > first && matches!(bytes[last - 1], b' ' | b'\t') {
            last -= 1;
        }
        block.span = Span::new(first, last, line);
        // (A later program's header ends the reading: the tape stays Ended.)
        if self.tape < Tape::Reading {
            self.tape = Tape::Reading;
        }
        (
            end,
            !block.words.is_empty() || block.error || block.macros.is_some() || block.speaks,
        )
    }
}

/// True when a line holds a LinuxCNC comment that speaks: `(MSG,`,
/// `(DEBUG,` or `(PRINT,` (behaviour 22.2).
pub(super) fn speaks(line: &[u8]) -> bool {
    // The head as the machine reads it (`Machine::comment_messages`): the
    // text before the comment's first comma, blanks trimmed.
    line.split(|&c| c == b'(').skip(1).any(|c| {
        let Some(end) = c.iter().position(|&b| b == b',' || b == b')') else {
            return false;
        };
        let head = c[..end].trim_ascii();
        c[end] == b','
            && [&b"MSG"[..], b"DEBUG", b"PRINT"]
                .iter()
                .any(|k| head.eq_ignore_ascii_case(k))
    })
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

#[cfg(test)]
mod tests;
