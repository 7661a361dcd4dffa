//! LinuxCNC's side of the macro text (behaviour 22.5–22.7): named
//! parameters, its operators' precedence with `**` and chained
//! comparisons, and the o-word lines.

use super::{COMPARISONS, Parser, alarm, chain, letters};
use crate::diag::Diagnostic;
use crate::macros::ast::{
    BinOp, CmpOp, Expr, ExprKind, OLabel, OOp, OWord, Statement, StatementKind,
};

/// LinuxCNC's o-word keywords.
const O_KEYWORDS: [&str; 15] = [
    "ENDSUB",
    "ENDWHILE",
    "ENDREPEAT",
    "ENDIF",
    "ELSEIF",
    "ELSE",
    "SUB",
    "CALL",
    "RETURN",
    "IF",
    "WHILE",
    "DO",
    "REPEAT",
    "BREAK",
    "CONTINUE",
];

/// Longest name of a named parameter or an o-word read (LinuxCNC's
/// LINELEN bounds a line; this keeps a name a name).
const MAX_NAME: usize = 255;

impl Parser<'_> {
    /// `<name>` at the parser's place (after `#` or `o`): lower case,
    /// blanks left out, as LinuxCNC keys a name (behaviour 22.6).
    pub(super) fn name(&mut self) -> Result<Box<str>, Diagnostic> {
        let open = self.pos;
        self.pos += 1;
        let Some(len) = self.bytes[self.pos..self.end]
            .iter()
            .position(|&c| c == b'>')
        else {
            return Err(Diagnostic::error(
                "named-parameter",
                self.span(open, self.end.max(open + 1)),
                "`<` opens a name that `>` closes on the same line (`#<depth>`, `o<pocket>`)",
            ));
        };
        let raw = &self.text[self.pos..self.pos + len];
        self.pos += len + 1;
        let name: String = raw
            .chars()
            .filter(|c| !c.is_whitespace())
            .flat_map(char::to_lowercase)
            .collect();
        if name.is_empty() || name.len() > MAX_NAME {
            return Err(Diagnostic::error(
                "named-parameter",
                self.span(open, self.pos),
                format!("a name holds 1 to {MAX_NAME} characters"),
            ));
        }
        Ok(name.into_boxed_str())
    }

    /// `AND OR XOR` level (LinuxCNC's lowest).
    pub(super) fn logic(&mut self) -> Result<Expr, Diagnostic> {
        let first = self.comparison()?;
        let mut rest = Vec::new();
        loop {
            let save = self.pos;
            let run = self.word();
            let op = match run.as_str() {
                "AND" => BinOp::And,
                "OR" => BinOp::Or,
                "XOR" => BinOp::Xor,
                _ => {
                    self.pos = save;
                    break;
                }
            };
            self.pos += run.len();
            rest.push((op, self.comparison()?));
        }
        Ok(chain(first, rest, self.line, self.pos))
    }

    /// The comparisons (LinuxCNC: above AND, below `+ -`), left to right
    /// in one chain, so that a line's length never deepens the tree
    /// (behaviour 20.17).
    fn comparison(&mut self) -> Result<Expr, Diagnostic> {
        let first = self.l_sum()?;
        let Some(op) = self.comparison_word() else {
            return Ok(first);
        };
        let right = self.l_sum()?;
        if self.peek_comparison() {
            let mut rest = vec![(BinOp::Cmp(op), right)];
            while let Some(op) = self.comparison_word() {
                rest.push((BinOp::Cmp(op), self.l_sum()?));
            }
            return Ok(chain(first, rest, self.line, self.pos));
        }
        Ok(Expr {
            span: self.span(first.span.start as usize, self.pos),
            kind: ExprKind::Compare(op, Box::new(first), Box::new(right)),
        })
    }

    fn peek_comparison(&mut self) -> bool {
        let save = self.pos;
        let found = self.comparison_word().is_some();
        self.pos = save;
        found
    }

    fn comparison_word(&mut self) -> Option<CmpOp> {
        let save = self.pos;
        let run = self.word();
        match COMPARISONS.iter().find(|(k, _)| run == *k) {
            Some(&(_, op)) => {
                self.pos += 2;
                Some(op)
            }
            None => {
                self.pos = save;
                None
            }
        }
    }

    /// LinuxCNC's `+ -`.
    fn l_sum(&mut self) -> Result<Expr, Diagnostic> {
        let first = self.l_product()?;
        let mut rest = Vec::new();
        loop {
            // Blanks before no operator stay unread: a chain ends at its
            // last operand.
            let save = self.pos;
            let op = match self.peek() {
                Some(b'+') => BinOp::Add,
                Some(b'-') => BinOp::Sub,
                _ => {
                    self.pos = save;
                    break;
                }
            };
            self.pos += 1;
            rest.push((op, self.l_product()?));
        }
        Ok(chain(first, rest, self.line, self.pos))
    }

    /// LinuxCNC's `* / MOD`.
    fn l_product(&mut self) -> Result<Expr, Diagnostic> {
        let first = self.l_power()?;
        let mut rest = Vec::new();
        loop {
            let save = self.pos;
            let op = match self.peek() {
                Some(b'*') if self.bytes.get(self.pos + 1) != Some(&b'*') => (BinOp::Mul, 1),
                Some(b'/') => (BinOp::Div, 1),
                Some(c) if c.is_ascii_alphabetic() && self.word() == "MOD" => (BinOp::Mod, 3),
                _ => {
                    self.pos = save;
                    break;
                }
            };
            self.pos += op.1;
            rest.push((op.0, self.l_power()?));
        }
        Ok(chain(first, rest, self.line, self.pos))
    }

    /// LinuxCNC's `**`, the tightest binary operator; a sign binds
    /// tighter still (`-2**2` is 4, as rs274 computes it).
    fn l_power(&mut self) -> Result<Expr, Diagnostic> {
        let first = self.unary(false)?;
        let mut rest = Vec::new();
        loop {
            let save = self.pos;
            if !(self.peek() == Some(b'*') && self.bytes.get(self.pos + 1) == Some(&b'*')) {
                self.pos = save;
                break;
            }
            self.pos += 2;
            rest.push((BinOp::Pow, self.unary(false)?));
        }
        Ok(chain(first, rest, self.line, self.pos))
    }

    /// A LinuxCNC o-word line (behaviour 22.7).
    pub(super) fn oword(&mut self) -> Result<Statement, Diagnostic> {
        let start = self.pos;
        self.pos = (self.pos + 1).min(self.end); // the `o`
        self.blanks();
        let label = if self.bytes.get(self.pos) == Some(&b'<') {
            OLabel::Name(self.name()?)
        } else {
            let at = self.pos;
            let digits = self.bytes[at..self.end]
                .iter()
                .take_while(|c| c.is_ascii_digit())
                .count();
            let n = self.text[at..at + digits].parse::<u32>().ok();
            self.pos = at + digits;
            match n {
                Some(n) => OLabel::Number(n),
                None => {
                    return Err(Diagnostic::error(
                        "oword",
                        self.span(start, self.pos.max(start + 1)),
                        "an o-word is `o` with a number or a name in < > (`o100`, `o<pocket>`)",
                    ));
                }
            }
        };
        let (kw, len) = (self.word(), letters(&self.bytes[..self.end], self.pos));
        let kw_at = self.pos;
        let Some(kw) = O_KEYWORDS.iter().find(|k| **k == kw) else {
            return Err(Diagnostic::error(
                "oword",
                self.span(start, (kw_at + len).max(start + 1)),
                format!(
                    "`{}` needs one of LinuxCNC's o-word keywords after its label: sub, endsub, call, return, if, elseif, else, endif, while, endwhile, do, repeat, endrepeat, break, continue",
                    crate::macros::excerpt(
                        &self.text[start..(kw_at + len).max(start + 1).min(self.end)]
                    )
                ),
            ));
        };
        self.pos = kw_at + len;
        let optional = |p: &mut Self| -> Result<Option<Expr>, Diagnostic> {
            match p.peek() {
                Some(b'[') => p.bracketed().map(Some),
                _ => Ok(None),
            }
        };
        let op = match *kw {
            "SUB" => OOp::Sub,
            "ENDSUB" => OOp::EndSub(optional(self)?),
            "RETURN" => OOp::Return(optional(self)?),
            "CALL" => {
                let mut args = Vec::new();
                // Each pass reads one bracket: bounded by the line.
                while self.peek() == Some(b'[') {
                    args.push(self.bracketed()?);
                }
                OOp::Call(args)
            }
            "IF" => OOp::If(self.bracketed()?),
            "ELSEIF" => OOp::ElseIf(self.bracketed()?),
            "ELSE" => OOp::Else,
            "ENDIF" => OOp::EndIf,
            "WHILE" => OOp::While(self.bracketed()?),
            "ENDWHILE" => OOp::EndWhile,
            "DO" => OOp::Do,
            "REPEAT" => OOp::Repeat(self.bracketed()?),
            "ENDREPEAT" => OOp::EndRepeat,
            "BREAK" => OOp::Break,
            _ => OOp::Continue,
        };
        let span = self.span(start, self.pos);
        self.blanks();
        if self.pos < self.end && self.bytes[self.pos] != b';' {
            return Err(self.alarm_here(
                alarm::FORMAT,
                "follows the o-word: an o-word line holds nothing else but comments",
            ));
        }
        Ok(Statement {
            kind: StatementKind::OWord(Box::new(OWord { label, op })),
            span,
        })
    }
}

/// Parses LinuxCNC's parameter setting at `start` (its `#`), up to `end`
/// (behaviour 22.10): `#i = v` or `#<name> = v`, the value one operand as
/// a word's is (a number, `#n`, `[…]`, a function, with signs: rs274
/// refuses `#1 = 1 + 2`); the statement and the byte after it, where the
/// line's other words and settings go on.
pub fn setting(
    text: &str,
    start: usize,
    end: usize,
    line: u32,
) -> Result<(Statement, usize), Diagnostic> {
    let mut p = Parser::new(text, start, end, line);
    p.linuxcnc = true;
    p.blanks();
    let start = p.pos;
    let target = p.variable()?;
    let target_span = target.span;
    p.expect(b'=', "is where `=` must follow the parameter")?;
    let value = p.unary(false)?;
    let span = p.span(start, p.pos);
    let kind = match target.kind {
        ExprKind::Named(name) => StatementKind::AssignNamed {
            name,
            target_span,
            value,
        },
        ExprKind::Var(index) => StatementKind::Assign {
            target: *index,
            target_span,
            value,
        },
        _ => {
            return Err(alarm::FORMAT.at(target_span, "a parameter must open the setting"));
        }
    };
    Ok((Statement { kind, span }, p.pos))
}
