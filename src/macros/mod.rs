//! Fanuc Custom Macro B, the language (behaviour 20): variables and their
//! values, expressions and statements parsed with their spans, and their
//! evaluation over any [`Variables`]. Every error is a [`Diagnostic`] whose
//! message opens with the control's alarm.
//!
//! **Architecture invariant:** imports only `crate::diag`; the machine, the
//! parser of blocks and the run use this module, never the other way.

pub mod alarm;
mod ast;
mod eval;
mod parse;
mod store;
mod value;

pub use ast::{BinOp, CmpOp, Expr, ExprKind, Func, OLabel, OOp, OWord, Statement, StatementKind};
pub use eval::{Evaluator, MAX_MAGNITUDE, Options, Outcome, Setting, Variables, compare};
pub use parse::{
    Dialect, MAX_NESTING, abbreviated, expression, expression_with, opens_statement, opens_value,
    oword, setting, statement, statement_with, value, value_with,
};
pub use store::{Kind, Store, kind, no_variable, system_variable};
pub use value::Value;

use std::borrow::Cow;

/// The text of an expression as written (for the report's sentence).
pub fn text_of<'t>(text: &'t str, e: &Expr) -> &'t str {
    text.get(e.span.start as usize..e.span.end as usize)
        .unwrap_or("")
}

/// Text quoted in a block's sentence: as written up to [`EXCERPT`]
/// characters, else its start and end around `…`, so that a sentence stays
/// a sentence and a report's size does not grow with a block's length
/// (behaviour 20.17).
pub fn excerpt(text: &str) -> Cow<'_, str> {
    if text.chars().count() <= EXCERPT {
        return Cow::Borrowed(text);
    }
    // The first 40 characters and the last 19, cut at character bounds.
    let head = text
        .char_indices()
        .nth(EXCERPT * 2 / 3)
        .map_or(text.len(), |(i, _)| i);
    let tail = text
        .char_indices()
        .rev()
        .nth(EXCERPT / 3 - 2)
        .map_or(0, |(i, _)| i);
    Cow::Owned(format!("{}…{}", &text[..head], &text[tail..]))
}

/// The most characters of a program's text a sentence quotes.
pub const EXCERPT: usize = 60;
