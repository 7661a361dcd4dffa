//! A macro call's block (behaviour 21.1, 21.2): `G65 P… L… <arguments>`,
//! `G66 P… L… <arguments>` and `G67`. The call code and its arguments go
//! into the block's [`super::MacroBlock`] rather than its words: an
//! argument is no command (Fanuc: the words after G65 are passed to the
//! macro, never executed), an argument letter may repeat (argument
//! specification II's I, J, K) and any letter may carry a fraction (`D2.5`).
//! Only the two-pass reading meets them: G65–G67 are no code of the
//! one-pass reading's table, so a program without macro calls reads as
//! before.

use super::*;

/// Which macro call a block makes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CallCode {
    /// G65: the macro is called once (L times) at this block.
    Simple,
    /// G66: the macro is called after each block that moves, until G67.
    Modal,
    /// G67: the modal call ends.
    Cancel,
}

impl CallCode {
    /// The code as written (`G65`).
    pub fn text(self) -> &'static str {
        match self {
            CallCode::Simple => "G65",
            CallCode::Modal => "G66",
            CallCode::Cancel => "G67",
        }
    }
}

/// A macro call's code and its arguments, in the order written.
#[derive(Clone, Debug, PartialEq)]
pub struct MacroCall {
    /// G65, G66 or G67.
    pub code: CallCode,
    /// The call code's word.
    pub span: Span,
    /// The arguments written as numbers (an argument written with a
    /// variable or an expression is one of the block's macro words).
    pub args: Vec<Argument>,
}

/// One argument as written: its letter and its number.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Argument {
    /// The letter, upper case.
    pub letter: u8,
    /// The number: as written with a decimal point; without one, a
    /// dimension letter's in least input increments, any other whole (Fanuc
    /// 16i/18i operator's manual, 16 "Custom macro", "Position of the
    /// decimal point": the unit of an argument without a point is the least
    /// input increment of its address).
    pub value: f64,
    /// The word.
    pub span: Span,
}

/// The letters that pass an argument: all but G, L, N, O and P (Fanuc,
/// argument specification I).
pub fn is_argument(letter: u8) -> bool {
    letter.is_ascii_uppercase() && !matches!(letter, b'G' | b'L' | b'N' | b'O' | b'P')
}

impl Blocks<'_> {
    /// The block's first G65, G66 or G67 among its lexed words: its index
    /// and code.
    pub(super) fn macro_call_code(&self, raw: &[RawWord]) -> Option<(usize, CallCode)> {
        raw.iter().enumerate().find_map(|(k, w)| {
            if w.letter != b'G' || w.comma {
                return None;
            }
            let n = w.number.ok()?;
            if n.negative || n.point {
                return None;
            }
            let code = match n.mantissa {
                65 => CallCode::Simple,
                66 => CallCode::Modal,
                67 => CallCode::Cancel,
                _ => return None,
            };
            Some((k, code))
        })
    }

    /// Takes the `k`th lexed word of a block with a macro call at `at`:
    /// the call code itself, or an argument after a G65/G66 (Fanuc: G65 is
    /// written before any argument). False for a word typed as usual.
    pub(super) fn take_argument(
        &mut self,
        (at, code): (usize, CallCode),
        k: usize,
        w: &RawWord,
        start: usize,
        line: u32,
        block: &mut Block,
    ) -> bool {
        let span = Span::new(w.start, w.end, line);
        if k == at {
            self.macro_part(block, start).call = Some(Box::new(MacroCall {
                code,
                span,
                args: Vec::new(),
            }));
            return true;
        }
        if k < at || code == CallCode::Cancel || w.comma || !is_argument(w.letter) {
            return false;
        }
        let Ok(n) = w.number else { return false };
        let value = match Address::from_letter(w.letter) {
            Some(a) if a.kind() == WordKind::Dimension => self.dimension(n),
            _ => n.value(),
        };
        let Some(call) = block.macros.as_mut().and_then(|m| m.call.as_mut()) else {
            return false;
        };
        call.args.push(Argument {
            letter: w.letter,
            value,
            span,
        });
        true
    }
}
