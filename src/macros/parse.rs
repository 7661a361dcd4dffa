//! Macro text to its parsed form (behaviour 20.2, 20.3, 20.7): a
//! hand-written recursive descent over the block's bytes, with the bracket
//! nesting bounded at five levels (PS0118), which also bounds the
//! recursion; a run of signs is read in a loop, never recursively.

use super::alarm::{self, Alarm};
use super::ast::{BinOp, CmpOp, Expr, ExprKind, Func, Statement, StatementKind};
use crate::diag::{Diagnostic, Span};

mod linuxcnc;
pub use linuxcnc::setting;

/// Deepest bracket nesting, function brackets included (Fanuc: five
/// levels, alarm PS0118 past them).
pub const MAX_NESTING: u32 = 5;

/// The comparison operators (behaviour 20.5; LinuxCNC's the same words).
const COMPARISONS: [(&str, CmpOp); 6] = [
    ("EQ", CmpOp::Eq),
    ("NE", CmpOp::Ne),
    ("GT", CmpOp::Gt),
    ("LT", CmpOp::Lt),
    ("GE", CmpOp::Ge),
    ("LE", CmpOp::Le),
];

/// Longest constant read, in characters (a control reads a fixed number of
/// digits; this only keeps a constant a number).
const MAX_CONSTANT: usize = 40;

/// The statement keywords, as a block may open with them.
const KEYWORDS: [&str; 5] = ["IF", "WHILE", "GOTO", "END", "DO"];

/// True if the text at `i` opens a macro statement: `#`, or one of the
/// keywords IF, WHILE, GOTO, END, DO (either case) not followed by a letter.
pub fn opens_statement(bytes: &[u8], i: usize) -> bool {
    match bytes.get(i) {
        Some(b'#') => true,
        Some(c) if c.is_ascii_alphabetic() => {
            // Six letters tell (WHILE has five): a long run of letters
            // costs no more at each of them.
            let n = bytes[i..]
                .iter()
                .take(6)
                .take_while(|c| c.is_ascii_alphabetic())
                .count();
            let word = &bytes[i..i + n];
            // Fanuc's WH, GO, EN too (behaviour 20.19): a profile that
            // reads them in full refuses them with the word they stand for.
            KEYWORDS
                .iter()
                .chain(&["WH", "GO", "EN"])
                .any(|k| word.eq_ignore_ascii_case(k.as_bytes()))
        }
        _ => false,
    }
}

/// True if a word's value at `i` (after its letter and any blanks) is a
/// macro value: `#…`, `[…]`, or a sign before either.
pub fn opens_value(bytes: &[u8], i: usize) -> bool {
    match bytes.get(i) {
        Some(b'#' | b'[') => true,
        Some(b'-' | b'+') => matches!(bytes.get(i + 1), Some(b'#' | b'[')),
        _ => false,
    }
}

/// True when the letters `run` after an operand are the operator `keyword`
/// alone or written against a function's name (`ANDABS` of
/// `#1ANDABS[#2]`, `GTABS` of `IF[#1GTABS[#2]]`): the control reads its
/// keywords one after the other, blanks or none (behaviour 20.3).
fn glued(run: &str, keyword: &str) -> bool {
    match run.strip_prefix(keyword) {
        Some("") => true,
        Some(rest) => rest == "POW" || Func::of(rest).is_some(),
        None => false,
    }
}

fn letters(bytes: &[u8], i: usize) -> usize {
    bytes[i..]
        .iter()
        .take_while(|c| c.is_ascii_alphabetic())
        .count()
}

/// Fanuc's two-letter abbreviations of the macro words a program may be
/// written with (behaviour 20.19): the statements' and functions' words
/// whose first two letters name no other word. POW and POPEN share theirs,
/// so neither has one here.
const ABBREVIATIONS: [(&str, &str); 21] = [
    ("WH", "WHILE"),
    ("GO", "GOTO"),
    ("EN", "END"),
    ("TH", "THEN"),
    ("AB", "ABS"),
    ("AC", "ACOS"),
    ("AD", "ADP"),
    ("AN", "AND"),
    ("AS", "ASIN"),
    ("AT", "ATAN"),
    ("BC", "BCD"),
    ("BI", "BIN"),
    ("CO", "COS"),
    ("EX", "EXP"),
    ("FI", "FIX"),
    ("FU", "FUP"),
    ("RO", "ROUND"),
    ("SI", "SIN"),
    ("SQ", "SQRT"),
    ("TA", "TAN"),
    ("XO", "XOR"),
];

/// The macro word an abbreviation stands for.
pub fn abbreviated(word: &str) -> Option<&'static str> {
    ABBREVIATIONS
        .iter()
        .find(|(a, _)| a.eq_ignore_ascii_case(word))
        .map(|&(_, w)| w)
}

/// How a profile writes its macro language.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Dialect {
    /// Fanuc's abbreviations of the macro words read as the words
    /// (behaviour 20.19), else refused with the word they stand for.
    pub abbreviations: bool,
    /// LinuxCNC's expressions (behaviour 22.5, 22.6): `#<name>`, `**`,
    /// EXISTS, and its precedence (`**`; `* / MOD`; `+ -`; the
    /// comparisons; `AND OR XOR`).
    pub linuxcnc: bool,
}

/// Parses the statement at `start` of `text`, up to `end` (the block's end),
/// its words written in full.
pub fn statement(text: &str, start: usize, end: usize, line: u32) -> Result<Statement, Diagnostic> {
    statement_with(text, start, end, line, Dialect::default())
}

/// [`statement`] in a profile's [`Dialect`].
pub fn statement_with(
    text: &str,
    start: usize,
    end: usize,
    line: u32,
    dialect: Dialect,
) -> Result<Statement, Diagnostic> {
    let mut p = Parser::new(text, start, end, line);
    p.abbreviations = dialect.abbreviations;
    p.linuxcnc = dialect.linuxcnc;
    let s = p.statement()?;
    p.blanks();
    if p.pos < p.end {
        return Err(p.alarm_here(
            alarm::FORMAT,
            "is left over after the macro statement: a block holds one statement",
        ));
    }
    Ok(s)
}

/// Parses a word's value at `start` (`#1`, `-#1`, `[#1+2]`, `-[…]`);
/// returns the expression and the byte after it.
pub fn value(text: &str, start: usize, end: usize, line: u32) -> Result<(Expr, usize), Diagnostic> {
    value_with(text, start, end, line, Dialect::default())
}

/// [`value`] in a profile's [`Dialect`].
pub fn value_with(
    text: &str,
    start: usize,
    end: usize,
    line: u32,
    dialect: Dialect,
) -> Result<(Expr, usize), Diagnostic> {
    let mut p = Parser::new(text, start, end, line);
    p.abbreviations = dialect.abbreviations;
    p.linuxcnc = dialect.linuxcnc;
    let e = p.unary(true)?;
    Ok((e, p.pos))
}

/// Parses a LinuxCNC o-word line at `start` (its `o`), up to `end`
/// (behaviour 22.7): the label, the keyword and its expressions; the
/// statement and the byte after it (only comments may follow).
pub fn oword(
    text: &str,
    start: usize,
    end: usize,
    line: u32,
) -> Result<(Statement, usize), Diagnostic> {
    let mut p = Parser::new(text, start, end, line);
    p.linuxcnc = true;
    let s = p.oword()?;
    Ok((s, p.pos))
}

/// Parses an expression that fills `start..end` (tests and tools).
pub fn expression(text: &str, line: u32) -> Result<Expr, Diagnostic> {
    expression_with(text, line, Dialect::default())
}

/// [`expression`] in a profile's [`Dialect`].
pub fn expression_with(text: &str, line: u32, dialect: Dialect) -> Result<Expr, Diagnostic> {
    let mut p = Parser::new(text, 0, text.len(), line);
    p.abbreviations = dialect.abbreviations;
    p.linuxcnc = dialect.linuxcnc;
    let e = p.expr()?;
    p.blanks();
    if p.pos < p.end {
        return Err(p.alarm_here(alarm::FORMAT, "is left over after the expression"));
    }
    Ok(e)
}

struct Parser<'a> {
    text: &'a str,
    bytes: &'a [u8],
    pos: usize,
    end: usize,
    line: u32,
    depth: u32,
    /// Fanuc's abbreviations read as their words (behaviour 20.19).
    abbreviations: bool,
    /// LinuxCNC's expressions ([`Dialect::linuxcnc`]).
    linuxcnc: bool,
}

impl<'a> Parser<'a> {
    fn new(text: &'a str, start: usize, end: usize, line: u32) -> Parser<'a> {
        let end = end.min(text.len());
        Parser {
            text,
            bytes: text.as_bytes(),
            pos: start.min(end),
            end,
            line,
            depth: 0,
            abbreviations: false,
            linuxcnc: false,
        }
    }

    fn span(&self, start: usize, end: usize) -> Span {
        Span::new(start, end, self.line)
    }

    /// An alarm at the character at the parser's place (or the block's end).
    fn alarm_here(&self, a: Alarm, what: &str) -> Diagnostic {
        let end = self.next_char_end();
        let shown = if self.pos < self.end {
            format!("`{}` {what}", &self.text[self.pos..end])
        } else {
            format!("the block ends where {what}")
        };
        a.at(self.span(self.pos, end), shown)
    }

    fn next_char_end(&self) -> usize {
        let mut e = (self.pos + 1).min(self.end);
        while e < self.end && !self.text.is_char_boundary(e) {
            e += 1;
        }
        e
    }

    /// Skips blanks and comments.
    fn blanks(&mut self) {
        while self.pos < self.end {
            match self.bytes[self.pos] {
                b' ' | b'\t' => self.pos += 1,
                b'(' => {
                    while self.pos < self.end && self.bytes[self.pos] != b')' {
                        self.pos += 1;
                    }
                    self.pos = (self.pos + 1).min(self.end);
                }
                _ => break,
            }
        }
    }

    fn peek(&mut self) -> Option<u8> {
        self.blanks();
        (self.pos < self.end).then(|| self.bytes[self.pos])
    }

    fn eat(&mut self, c: u8) -> bool {
        if self.peek() == Some(c) {
            self.pos += 1;
            true
        } else {
            false
        }
    }

    /// The letters at the parser's place, upper case, without moving.
    fn word(&mut self) -> String {
        self.blanks();
        let n = letters(&self.bytes[..self.end], self.pos);
        self.text[self.pos..self.pos + n].to_ascii_uppercase()
    }

    /// The letters at the parser's place as [`Parser::word`] reads them,
    /// an abbreviation as the word it stands for when the profile reads
    /// them; and how many bytes they take.
    fn keyword(&mut self) -> (String, usize) {
        let raw = self.word();
        let len = raw.len();
        match abbreviated(&raw) {
            Some(full) if self.abbreviations => (full.to_string(), len),
            _ => (raw, len),
        }
    }

    /// The refusal of an abbreviation the profile does not read.
    fn not_abbreviated(&self, word: &str, start: usize) -> Option<Diagnostic> {
        let full = abbreviated(word)?;
        Some(alarm::FORMAT.at(
            self.span(start, start + word.len()),
            format!(
                "`{}` is Fanuc's abbreviation of {full}; this profile reads the macro words in full (setting macro_abbreviations: fanuc reads it)",
                super::excerpt(word)
            ),
        ))
    }

    fn expect(&mut self, c: u8, what: &str) -> Result<(), Diagnostic> {
        if self.eat(c) {
            Ok(())
        } else {
            Err(self.alarm_here(alarm::FORMAT, what))
        }
    }

    fn open(&mut self) -> Result<usize, Diagnostic> {
        self.blanks();
        let at = self.pos;
        self.expect(b'[', "is where `[` must open the expression")?;
        self.depth += 1;
        if self.depth > MAX_NESTING {
            return Err(alarm::NESTING.at(
                self.span(at, at + 1),
                format!(
                    "brackets nest more than {MAX_NESTING} levels deep here (function brackets count)"
                ),
            ));
        }
        Ok(at)
    }

    fn close(&mut self) -> Result<(), Diagnostic> {
        self.expect(b']', "is where `]` must close the bracket")?;
        self.depth -= 1;
        Ok(())
    }

    fn statement(&mut self) -> Result<Statement, Diagnostic> {
        self.blanks();
        let start = self.pos;
        if self.peek() == Some(b'#') {
            return self.assignment();
        }
        let (kw, kw_len) = self.keyword();
        let kw_end = self.pos + kw_len;
        self.pos = kw_end;
        let kind = match kw.as_str() {
            "GOTO" => StatementKind::Goto(self.expr()?),
            "IF" => {
                let cond = self.bracketed()?;
                let (then, len) = self.keyword();
                if let (false, Some(d)) =
                    (self.abbreviations, self.not_abbreviated(&then, self.pos))
                {
                    return Err(d);
                }
                match then.as_str() {
                    "GOTO" => {
                        self.pos += len;
                        StatementKind::IfGoto(cond, self.expr()?)
                    }
                    "THEN" => {
                        self.pos += len;
                        self.blanks();
                        if self.peek() != Some(b'#') {
                            return Err(self.alarm_here(
                                alarm::STATEMENT,
                                "follows THEN: offsetlab reads `IF [...] THEN #i = ...`",
                            ));
                        }
                        let then = self.assignment()?;
                        StatementKind::IfThen(cond, Box::new(then))
                    }
                    _ => {
                        return Err(self.alarm_here(
                            alarm::STATEMENT,
                            "follows IF [...]: GOTO n or THEN #i = ... must",
                        ));
                    }
                }
            }
            "WHILE" => {
                let cond = self.bracketed()?;
                if self.word() != "DO" {
                    return Err(self.alarm_here(alarm::STATEMENT, "follows WHILE [...]: DO m must"));
                }
                self.pos += 2;
                StatementKind::While(cond, self.loop_number()?)
            }
            "DO" => StatementKind::Do(self.loop_number()?),
            "END" => StatementKind::End(self.loop_number()?),
            _ => {
                if let Some(d) = self.not_abbreviated(&kw, start) {
                    return Err(d);
                }
                return Err(alarm::STATEMENT.at(
                    self.span(start, kw_end.max(start + 1)),
                    format!("`{}` is not a macro statement", super::excerpt(&kw)),
                ));
            }
        };
        Ok(Statement {
            kind,
            span: self.span(start, self.pos),
        })
    }

    /// `#i = e`.
    fn assignment(&mut self) -> Result<Statement, Diagnostic> {
        self.blanks();
        let start = self.pos;
        let target = self.variable()?;
        let target_span = target.span;
        if let ExprKind::Named(name) = target.kind {
            self.expect(b'=', "is where `=` must follow the parameter")?;
            let value = self.expr()?;
            return Ok(Statement {
                span: self.span(start, self.pos),
                kind: StatementKind::AssignNamed {
                    name,
                    target_span,
                    value,
                },
            });
        }
        let ExprKind::Var(index) = target.kind else {
            return Err(alarm::FORMAT.at(target_span, "a variable must open the assignment"));
        };
        self.expect(b'=', "is where `=` must follow the variable")?;
        let value = self.expr()?;
        Ok(Statement {
            span: self.span(start, self.pos),
            kind: StatementKind::Assign {
                target: *index,
                target_span,
                value,
            },
        })
    }

    /// `[e]` (the condition of IF and WHILE).
    fn bracketed(&mut self) -> Result<Expr, Diagnostic> {
        let at = self.open()?;
        let e = self.expr()?;
        self.close()?;
        Ok(Expr {
            span: self.span(at, self.pos),
            kind: ExprKind::Bracket(Box::new(e)),
        })
    }

    /// The m of DO m / END m: 1, 2 or 3 (PS0126).
    fn loop_number(&mut self) -> Result<u8, Diagnostic> {
        self.blanks();
        let at = self.pos;
        let n = self.constant()?;
        match n {
            Some(v) if v == 1.0 || v == 2.0 || v == 3.0 => Ok(v as u8),
            _ => Err(alarm::LOOP_NUMBER.at(
                self.span(at, self.pos.max(at + 1)),
                "the loop number of DO and END is 1, 2 or 3",
            )),
        }
    }

    /// A constant at the parser's place, or None (nothing moved).
    fn constant(&mut self) -> Result<Option<f64>, Diagnostic> {
        self.blanks();
        let start = self.pos;
        let mut i = start;
        let mut point = false;
        while i < self.end && (self.bytes[i].is_ascii_digit() || (self.bytes[i] == b'.' && !point))
        {
            point |= self.bytes[i] == b'.';
            i += 1;
        }
        let digits = &self.text[start..i];
        if digits.is_empty() || digits == "." {
            return Ok(None);
        }
        self.pos = i;
        if digits.len() > MAX_CONSTANT {
            return Err(alarm::FORMAT.at(
                self.span(start, i),
                format!("a constant of {} characters is too long", digits.len()),
            ));
        }
        // Digits and one point: always a number (`5.` and `.5` too).
        let v = digits.parse::<f64>().unwrap_or(0.0);
        Ok(Some(v))
    }

    /// `#n` or `#[e]`.
    fn variable(&mut self) -> Result<Expr, Diagnostic> {
        self.blanks();
        let start = self.pos;
        self.expect(b'#', "is where `#` must open a variable")?;
        if self.linuxcnc && self.bytes.get(self.pos) == Some(&b'<') {
            let name = self.name()?;
            return Ok(Expr {
                span: self.span(start, self.pos),
                kind: ExprKind::Named(name),
            });
        }
        let index = if self.bytes.get(self.pos) == Some(&b'[') {
            self.bracketed()?
        } else {
            let at = self.pos;
            let digits = self.bytes[at..self.end]
                .iter()
                .take_while(|c| c.is_ascii_digit())
                .count();
            if digits == 0 || self.bytes.get(at + digits) == Some(&b'.') {
                return Err(alarm::FORMAT.at(
                    self.span(start, (at + digits).max(at) + 1),
                    "`#` takes a whole variable number (`#12`) or an expression in brackets (`#[#1+2]`)",
                ));
            }
            self.pos = at + digits;
            // Digits only: a number (a long run is out of range later).
            let n = self.text[at..self.pos].parse::<f64>().unwrap_or(f64::MAX);
            Expr {
                kind: ExprKind::Number(n),
                span: self.span(at, self.pos),
            }
        };
        Ok(Expr {
            span: self.span(start, self.pos),
            kind: ExprKind::Var(Box::new(index)),
        })
    }

    /// Comparison level (lowest).
    fn expr(&mut self) -> Result<Expr, Diagnostic> {
        if self.linuxcnc {
            return self.logic();
        }
        let left = self.sum()?;
        let save = self.pos;
        let run = self.word();
        let Some(&(_, op)) = COMPARISONS.iter().find(|(k, _)| glued(&run, k)) else {
            self.pos = save;
            return Ok(left);
        };
        self.pos += 2;
        let right = self.sum()?;
        Ok(Expr {
            span: self.span(left.span.start as usize, self.pos),
            kind: ExprKind::Compare(op, Box::new(left), Box::new(right)),
        })
    }

    /// `+ - OR XOR` level.
    fn sum(&mut self) -> Result<Expr, Diagnostic> {
        let first = self.product()?;
        let mut rest = Vec::new();
        // Each pass reads an operand: bounded by the text.
        while let Some(op) = self.operator(false) {
            rest.push((op, self.product()?));
        }
        Ok(chain(first, rest, self.line, self.pos))
    }

    /// `* / AND MOD` level.
    fn product(&mut self) -> Result<Expr, Diagnostic> {
        let first = self.unary(false)?;
        let mut rest = Vec::new();
        while let Some(op) = self.operator(true) {
            rest.push((op, self.unary(false)?));
        }
        Ok(chain(first, rest, self.line, self.pos))
    }

    /// The operator of the level at the parser's place, consumed; None
    /// (nothing moved) for any other.
    fn operator(&mut self, multiplicative: bool) -> Option<BinOp> {
        let save = self.pos;
        let (op, len) = match self.peek()? {
            b'+' => (BinOp::Add, 1),
            b'-' => (BinOp::Sub, 1),
            b'*' => (BinOp::Mul, 1),
            b'/' => (BinOp::Div, 1),
            c if c.is_ascii_alphabetic() => {
                let run = self.word();
                const WORDS: [(&str, BinOp); 4] = [
                    ("XOR", BinOp::Xor),
                    ("AND", BinOp::And),
                    ("MOD", BinOp::Mod),
                    ("OR", BinOp::Or),
                ];
                let short = match abbreviated(&run) {
                    Some("XOR") if self.abbreviations => Some((BinOp::Xor, 2)),
                    Some("AND") if self.abbreviations => Some((BinOp::And, 2)),
                    _ => None,
                };
                match WORDS.iter().find(|(k, _)| glued(&run, k)) {
                    Some(&(k, op)) => (op, k.len()),
                    None if short.is_some() => short?,
                    None => {
                        self.pos = save;
                        return None;
                    }
                }
            }
            _ => {
                self.pos = save;
                return None;
            }
        };
        if op.multiplicative() != multiplicative {
            self.pos = save;
            return None;
        }
        self.pos += len;
        Some(op)
    }

    /// Signs, then an operand. `word`: a word's value, where only `#…` and
    /// `[…]` may follow the sign (Fanuc: `X-#1`, `Z-[#3+1.]`).
    fn unary(&mut self, word: bool) -> Result<Expr, Diagnostic> {
        self.blanks();
        let start = self.pos;
        let mut negative = false;
        loop {
            match self.peek() {
                Some(b'-') => negative = !negative,
                Some(b'+') => {}
                _ => break,
            }
            self.pos += 1;
        }
        let operand = if word {
            match self.peek() {
                Some(b'#') => self.variable()?,
                Some(b'[') => self.bracketed()?,
                _ => {
                    return Err(self.alarm_here(
                        alarm::FORMAT,
                        "cannot open a word's macro value: `#n`, `#[...]` or `[...]` must",
                    ));
                }
            }
        } else {
            self.primary()?
        };
        if self.pos == start || !negative {
            return Ok(operand);
        }
        Ok(Expr {
            span: self.span(start, self.pos),
            kind: ExprKind::Neg(Box::new(operand)),
        })
    }

    fn primary(&mut self) -> Result<Expr, Diagnostic> {
        let start = self.pos;
        match self.peek() {
            Some(b'#') => self.variable(),
            Some(b'[') => self.bracketed(),
            Some(c) if c.is_ascii_digit() || c == b'.' => match self.constant()? {
                Some(v) => Ok(Expr {
                    kind: ExprKind::Number(v),
                    span: self.span(start, self.pos),
                }),
                None => Err(self.alarm_here(alarm::FORMAT, "is not a number")),
            },
            Some(c) if c.is_ascii_alphabetic() => self.function(),
            _ => Err(self.alarm_here(
                alarm::FORMAT,
                "is where a value must be: a number, `#n`, `[...]` or a function",
            )),
        }
    }

    fn function(&mut self) -> Result<Expr, Diagnostic> {
        let start = self.pos;
        let (name, len) = self.keyword();
        let name_end = start + len;
        self.pos = name_end;
        if self.linuxcnc && name == "EXISTS" {
            self.open()?;
            self.blanks();
            let at = self.pos;
            if !(self.eat(b'#') && self.bytes.get(self.pos) == Some(&b'<')) {
                self.pos = at;
                return Err(self.alarm_here(
                    alarm::FORMAT,
                    "is where EXISTS takes a named parameter, `EXISTS[#<name>]`",
                ));
            }
            let name = self.name()?;
            self.close()?;
            return Ok(Expr {
                kind: ExprKind::Exists(name),
                span: self.span(start, self.pos),
            });
        }
        if name == "POW" {
            self.open()?;
            let a = self.expr()?;
            self.expect(b',', "is where `,` must part POW's two arguments")?;
            let b = self.expr()?;
            self.close()?;
            return Ok(Expr {
                kind: ExprKind::Pow(Box::new(a), Box::new(b)),
                span: self.span(start, self.pos),
            });
        }
        let Some(func) = Func::of(&name) else {
            if let Some(d) = self.not_abbreviated(&name, start) {
                return Err(d);
            }
            return Err(alarm::FORMAT.at(
                self.span(start, name_end),
                format!(
                    "`{}` is not a macro function or operator",
                    super::excerpt(&name)
                ),
            ));
        };
        self.open()?;
        let a = self.expr()?;
        if func == Func::Atan && self.eat(b',') {
            let b = self.expr()?;
            self.close()?;
            return Ok(atan2(a, b, self.span(start, self.pos)));
        }
        self.close()?;
        if func == Func::Atan {
            // ATAN[a]/[b]: the two-argument form, not a division.
            let save = self.pos;
            if self.eat(b'/') && self.peek() == Some(b'[') {
                let b = self.bracketed()?;
                return Ok(atan2(a, b, self.span(start, self.pos)));
            }
            self.pos = save;
        }
        Ok(Expr {
            kind: ExprKind::Call(func, Box::new(a)),
            span: self.span(start, self.pos),
        })
    }
}

fn atan2(a: Expr, b: Expr, span: Span) -> Expr {
    Expr {
        kind: ExprKind::Atan2(Box::new(a), Box::new(b)),
        span,
    }
}

/// One operand alone, or the chain of a level's operators.
fn chain(first: Expr, rest: Vec<(BinOp, Expr)>, line: u32, end: usize) -> Expr {
    if rest.is_empty() {
        return first;
    }
    Expr {
        span: Span::new(first.span.start as usize, end, line),
        kind: ExprKind::Chain(Box::new(first), rest),
    }
}
