//! Macro statements and words whose value is a variable or an expression
//! (behaviour 20.8). The parser reads them into the block's
//! [`MacroBlock`] (only the two-pass reading meets them: `#` and `[` stop
//! the one-pass reading, so a program without macros reads as before);
//! once the run has evaluated the words, [`resolve`] types them as the
//! parser types a word written with its number, by reading the block again
//! with the values written in, and gives every word and diagnostic the
//! span it has in the program.

use super::*;
use crate::macros::{self, Expr, Statement};
use std::borrow::Cow;

/// What a block holds of Custom Macro B.
#[derive(Clone, Debug, PartialEq)]
pub struct MacroBlock {
    /// A statement (`#1 = …`, `IF …`, `WHILE …`, `GOTO …`, `END …`).
    pub statement: Option<Statement>,
    /// LinuxCNC's parameter settings (`#1 = 2` among the line's words),
    /// made after the line's values are read (behaviour 22.10).
    pub settings: Vec<Statement>,
    /// The words whose value is `#…` or `[…]`.
    pub words: Vec<MacroWord>,
    /// A macro call's code and arguments (G65, G66, G67: behaviour 21).
    pub call: Option<Box<super::macro_call::MacroCall>>,
    /// The block's text and where it starts, to read it again with the
    /// values written in.
    source: String,
    start: usize,
    /// The parser's G20/G21 and canned-cycle context before the block.
    units: Units,
    in_cycle: bool,
}

/// A word whose value is a variable or an expression (`X#1`, `Z-[#3+1.]`).
#[derive(Clone, Debug, PartialEq)]
pub struct MacroWord {
    /// The address.
    pub address: Address,
    /// The value as written.
    pub value: Expr,
    /// The word, letter through value.
    pub span: Span,
}

impl MacroBlock {
    /// The least input increment of the block's units: what a dimension
    /// word's value is rounded to, and ROUND in a word rounds to
    /// (behaviour 20.6).
    pub fn increment(&self) -> f64 {
        match self.units {
            Units::Mm => 0.001,
            Units::Inch => 0.0001,
        }
    }

    /// The text of a statement of the block, as written (an excerpt when
    /// long, [`macros::excerpt`]).
    pub fn text_of_statement(&self, st: &Statement) -> Cow<'_, str> {
        let s = (st.span.start as usize).saturating_sub(self.start);
        let t = (st.span.end as usize).saturating_sub(self.start);
        macros::excerpt(self.source.get(s..t).unwrap_or(""))
    }

    /// The block's first comment, without its parentheses (the message of
    /// `#3000 = 1 (TOOL NOT FOUND)`, behaviour 20.16).
    pub fn comment(&self) -> Option<&str> {
        first_comment(&self.source).map(str::trim)
    }

    /// The text of an expression of the block, as written (an excerpt
    /// when long, [`macros::excerpt`]).
    pub fn text_of(&self, e: &Expr) -> Cow<'_, str> {
        let s = (e.span.start as usize).saturating_sub(self.start);
        let t = (e.span.end as usize).saturating_sub(self.start);
        macros::excerpt(self.source.get(s..t).unwrap_or(""))
    }
}

/// The first comment of a block's text, without its parentheses (to the
/// text's end when it is not closed): the text a code reads from its
/// block (`#3000`'s message, Haas G47's text).
pub fn first_comment(text: &str) -> Option<&str> {
    let open = text.find('(')?;
    let rest = &text[open + 1..];
    Some(&rest[..rest.find(')').unwrap_or(rest.len())])
}

/// The end of the block that starts at `i`: its end-of-block character
/// outside a comment, or the text's end.
fn block_end(bytes: &[u8], mut i: usize) -> usize {
    let mut comment = false;
    while i < bytes.len() {
        match bytes[i] {
            b'\n' | b'\r' => break,
            b';' if !comment => break,
            b'(' => comment = true,
            b')' => comment = false,
            _ => {}
        }
        i += 1;
    }
    i
}

impl Blocks<'_> {
    /// The block's macro part, made at its first macro syntax.
    pub(super) fn macro_part<'b>(
        &mut self,
        block: &'b mut Block,
        start: usize,
    ) -> &'b mut MacroBlock {
        let end = self.block_end(start);
        let (units, in_cycle) = self.before_block;
        block.macros.get_or_insert_with(|| {
            Box::new(MacroBlock {
                statement: None,
                settings: Vec::new(),
                words: Vec::new(),
                call: None,
                source: self.text[start..end].to_string(),
                start,
                units,
                in_cycle,
            })
        })
    }

    /// [`block_end`] of the block being read, found once per block: a line
    /// of many macro words looks it up at each (linear, not quadratic).
    fn block_end(&mut self, from: usize) -> usize {
        match self.macro_end {
            Some((start, end)) if start <= from && from <= end => end,
            _ => {
                let end = block_end(self.text.as_bytes(), from);
                self.macro_end = Some((from, end));
                end
            }
        }
    }

    /// How the profile writes its macro language.
    pub(super) fn dialect(&self) -> macros::Dialect {
        macros::Dialect {
            abbreviations: self.options.macro_abbreviations,
            linuxcnc: self.options.linuxcnc,
        }
    }

    /// Reads the LinuxCNC o-word at `i` into the block (behaviour 22.7);
    /// where the reading goes on (after it, or at the line's end when it
    /// is refused).
    pub(super) fn read_oword(
        &mut self,
        i: usize,
        line: u32,
        block: &mut Block,
    ) -> Result<usize, ()> {
        let end = block_end(self.text.as_bytes(), i);
        match macros::oword(self.text, i, end, line) {
            Ok((s, after)) => {
                self.macro_part(block, i).statement = Some(s);
                Ok(after)
            }
            Err(d) => {
                block.error = true;
                self.report(d);
                Err(())
            }
        }
    }

    /// Reads the statement at `i` (to the block's end) into the block;
    /// returns where the reading goes on.
    pub(super) fn read_statement(
        &mut self,
        block_start: usize,
        i: usize,
        line: u32,
        block: &mut Block,
    ) -> usize {
        let end = block_end(self.text.as_bytes(), i);
        match macros::statement_with(self.text, i, end, line, self.dialect()) {
            Ok(s) => self.macro_part(block, block_start).statement = Some(s),
            Err(d) => {
                block.error = true;
                self.report(d);
            }
        }
        end
    }

    /// Reads LinuxCNC's parameter setting at `i` into the block (behaviour
    /// 22.10); returns where the reading goes on: after it, among the
    /// line's words, or at the line's end when it is refused.
    fn read_setting(
        &mut self,
        block_start: usize,
        i: usize,
        line: u32,
        block: &mut Block,
    ) -> usize {
        let end = self.block_end(i);
        match macros::setting(self.text, i, end, line) {
            Ok((s, after)) => {
                self.macro_part(block, block_start).settings.push(s);
                after
            }
            Err(d) => {
                block.error = true;
                self.report(d);
                end
            }
        }
    }

    /// Reads a word's macro value at `value` (after the letter at `i`);
    /// returns where the reading goes on.
    pub(super) fn read_macro_word(
        &mut self,
        block_start: usize,
        (i, value): (usize, usize),
        (letter, comma): (u8, bool),
        line: u32,
        block: &mut Block,
    ) -> usize {
        let end = self.block_end(value);
        // `,C` and `,R` take a value as any dimension does (behaviour 1.7).
        let address = match comma {
            true => Address::comma(letter),
            false => Address::from_letter(letter).filter(|a| !matches!(a, Address::O | Address::N)),
        };
        let written_as = &self.text[i..i + 1 + usize::from(comma)];
        match macros::value_with(self.text, value, end, line, self.dialect()) {
            Ok((_, after))
                if matches!(
                    self.text
                        .as_bytes()
                        .get(lexer::skip_blanks(self.text.as_bytes(), after)),
                    Some(b'+' | b'-' | b'*' | b'/' | b'=')
                ) =>
            {
                // `X#140/2`: Fanuc takes an expression in a word only in
                // brackets (the `/` would otherwise read as a block skip).
                let op = lexer::skip_blanks(self.text.as_bytes(), after);
                let word = &self.text[i..after];
                let msg = format!(
                    "{}: an expression in a word is written in brackets: `{}[{}{o}…]`, not `{word}{o}…`",
                    macros::alarm::FORMAT.alarm,
                    written_as,
                    &self.text[value..after],
                    o = &self.text[op..op + 1]
                );
                self.error_span(
                    block,
                    macros::alarm::FORMAT.code,
                    Span::new(i, op + 1, line),
                    &msg,
                );
                end
            }
            Ok((expr, after)) => {
                let span = Span::new(i, after, line);
                match address {
                    Some(address) => self.macro_part(block, block_start).words.push(MacroWord {
                        address,
                        value: expr,
                        span,
                    }),
                    None => {
                        let msg = format!(
                            "{}: `{}` takes no variable or expression (O and N never do, and offsetlab reads no other such letter)",
                            macros::alarm::FORMAT.alarm,
                            letter as char
                        );
                        self.error_span(block, macros::alarm::FORMAT.code, span, &msg);
                    }
                }
                after
            }
            Err(d) => {
                block.error = true;
                self.report(d);
                end
            }
        }
    }

    /// A block with a statement holds no NC word but its sequence number
    /// (PS0127).
    pub(super) fn check_statement_alone(&mut self, block: &mut Block) {
        let Some(m) = &block.macros else { return };
        let Some(s) = &m.statement else { return };
        let other = block
            .words
            .iter()
            .find(|w| w.address != Address::N)
            .map(|w| w.span)
            .or_else(|| m.words.first().map(|w| w.span));
        if let Some(span) = other {
            let msg = format!(
                "{}: an NC word and the macro statement `{}` share a block; write them in two blocks",
                macros::alarm::NC_AND_MACRO.alarm,
                s.kind.keyword()
            );
            self.error_span(block, macros::alarm::NC_AND_MACRO.code, span, &msg);
        }
    }
}

/// How a value is written for the parser to read it as the word's number:
/// a dimension rounded to `increment` with its point, a feed with its
/// point, a G code to one decimal, any other whole word rounded to a whole
/// number (Fanuc rounds a variable's value to the address's digits). With
/// `exact` (LinuxCNC, behaviour 22.5) a dimension keeps every digit.
fn written(address: Address, v: f64, increment: f64, in_cycle: bool, exact: bool) -> String {
    let kind = match address {
        Address::K if in_cycle => WordKind::Integer,
        a => a.kind(),
    };
    let letter = address.letter();
    match kind {
        WordKind::Dimension if exact => {
            // Within the reader's 15 digits: 1e-10 of a unit at most.
            let whole = v.abs().max(1.0).log10().floor() as usize + 1;
            let digits = 14usize.saturating_sub(whole).min(10);
            let t = format!("{v:.digits$}");
            let t = if t.contains('.') {
                t.trim_end_matches('0')
            } else {
                &t
            };
            format!("{letter}{t}")
        }
        WordKind::Dimension => {
            let digits = if increment < 0.001 { 4 } else { 3 };
            let v = (v / increment).round() * increment;
            format!("{letter}{v:.digits$}")
        }
        WordKind::Feed => {
            let s = format!("{v:.6}");
            let s = s.trim_end_matches('0');
            format!("{letter}{s}")
        }
        WordKind::Integer if address == Address::G => {
            let v = (v * 10.0).round() / 10.0;
            if v.fract() == 0.0 {
                format!("G{v:.0}")
            } else {
                format!("G{v:.1}")
            }
        }
        WordKind::Integer => format!("{letter}{:.0}", v.round()),
    }
}

/// The block with its macro words typed: `values` holds each macro word's
/// value (None: vacant, the word is left out, behaviour 20.4). The words
/// are read again, with the values written in, by the parser in the
/// context the block had; every word and diagnostic keeps the span it has
/// in the program. Errors stop the block as a parse error would.
pub fn resolve(
    block: &Block,
    m: &MacroBlock,
    values: &[Option<f64>],
    options: ParseOptions,
) -> (Block, Vec<Diagnostic>) {
    // Every word in text order: (its span, its text for the parser).
    let mut items: Vec<(Span, String, bool)> =
        Vec::with_capacity(block.words.len() + m.words.len());
    for w in &block.words {
        let s = (w.span.start as usize).saturating_sub(m.start);
        let t = (w.span.end as usize).saturating_sub(m.start);
        items.push((w.span, m.source.get(s..t).unwrap_or("").to_string(), false));
    }
    let increment = m.increment();
    for (w, v) in m.words.iter().zip(values) {
        if let Some(v) = v {
            items.push((
                w.span,
                written(w.address, *v, increment, m.in_cycle, options.linuxcnc),
                true,
            ));
        }
    }
    items.sort_by_key(|(span, ..)| span.start);
    let mut text = String::new();
    let mut ranges = Vec::with_capacity(items.len());
    for (span, t, is_macro) in &items {
        let at = text.len();
        text.push_str(t);
        ranges.push((at, text.len(), *span, *is_macro));
        text.push(' ');
    }
    // The ranges are in order: the word at a byte is found by halving.
    let original = |at: u32| {
        let i = ranges.partition_point(|(_, e, ..)| *e < at as usize);
        ranges
            .get(i)
            .filter(|(s, e, ..)| (*s..=*e).contains(&(at as usize)))
            .map(|r| (r.2, r.3))
    };
    let at = Resume {
        pos: 0,
        line: block.span.line,
        units: m.units,
        in_cycle: m.in_cycle,
        tape: Tape::Reading,
        // The block's own warnings were given when it was first read.
        warned_integer: true,
        programs: program::Programs::default(),
    };
    let mut parser = Blocks::resume(&text, options, at);
    let mut out = Block::default();
    if !parser.next_into(&mut out) {
        out.clear();
    }
    for w in &mut out.words {
        if let Some((span, _)) = original(w.span.start) {
            w.span = span;
        }
    }
    out.span = block.span;
    out.skip = block.skip;
    out.macros = None;
    let diagnostics = parser
        .into_diagnostics()
        .into_iter()
        .filter_map(|mut d| {
            let (span, is_macro) = original(d.span.start)?;
            // The literal words' diagnostics were reported when first read.
            (is_macro || d.is_error()).then(|| {
                d.span = span;
                d.line = span.line;
                d
            })
        })
        .collect();
    (out, diagnostics)
}

/// True if the text at `i` (a block's next thing) opens a macro statement
/// or a word with a macro value (a comma word's too: `,R#144`).
pub(super) fn opens(bytes: &[u8], i: usize) -> bool {
    macros::opens_statement(bytes, i)
        || (bytes[i].is_ascii_alphabetic()
            && macros::opens_value(bytes, lexer::skip_blanks(bytes, i + 1)))
        || comma_value(bytes, i)
}

/// A LinuxCNC polar word (`@`, `^`) with an expression or a parameter as
/// its value at `i` (`@[#1*2]`, behaviour 22.12); the caller checks the
/// profile.
pub(super) fn opens_polar(bytes: &[u8], i: usize) -> bool {
    matches!(bytes[i], b'@' | b'^') && macros::opens_value(bytes, lexer::skip_blanks(bytes, i + 1))
}

/// A comma word (`,C`, `,R`) with a macro value at `i`.
fn comma_value(bytes: &[u8], i: usize) -> bool {
    bytes[i] == b','
        && bytes
            .get(i + 1)
            .is_some_and(|&l| Address::comma(l).is_some())
        && macros::opens_value(bytes, lexer::skip_blanks(bytes, i + 2))
}

impl Blocks<'_> {
    /// Reads the statement or the macro word at `i` ([`opens`] said which
    /// may be there); returns where the reading goes on.
    pub(super) fn read_macro(
        &mut self,
        start: usize,
        i: usize,
        line: u32,
        block: &mut Block,
    ) -> usize {
        let bytes = self.text.as_bytes();
        if self.options.linuxcnc && bytes[i] == b'#' {
            return self.read_setting(start, i, line, block);
        }
        if macros::opens_statement(bytes, i) {
            return self.read_statement(start, i, line, block);
        }
        let comma = comma_value(bytes, i);
        let letter_at = i + usize::from(comma);
        let value = lexer::skip_blanks(bytes, letter_at + 1);
        self.read_macro_word(
            start,
            (i, value),
            (bytes[letter_at].to_ascii_uppercase(), comma),
            line,
            block,
        )
    }
}
