//! A block with Custom Macro B in it (behaviour 20.8), between the parser
//! and the machine: its statement runs over the machine's variables, its
//! macro words are evaluated in program order and typed as the parser types
//! a word, and the block the machine runs is the one with their values.
//! Only blocks the parser marked take this way: the others run as before.

use crate::diag::Diagnostic;
use crate::diag::Span;
use crate::machine::{EventKind, Machine, Out, VariableSet};
use crate::macros::{
    self, Evaluator, Kind, Options, Outcome, StatementKind, Value, Variables, system_variable,
};
use crate::setup::{MacroAngles, MacroConditions};
use crate::syntax::{self, Block, MacroBlock, ParseOptions};

/// The evaluation options of the machine's setup (settings 7.39, 7.40).
pub(super) fn options(machine: &Machine) -> Options {
    let s = &machine.setup().settings;
    Options {
        signed_angles: s.macro_angles() == MacroAngles::Signed,
        numeric_conditions: s.macro_conditions() == MacroConditions::Numeric,
    }
}

/// The run's variables: the machine's store, and the system variables of
/// the offsets, which read and write the machine's tables (behaviour 20.10).
pub(super) struct Vars<'a> {
    pub(super) machine: &'a mut Machine,
    pub(super) out: &'a mut Out,
}

impl Variables for Vars<'_> {
    fn read(&mut self, n: u32, span: Span) -> Result<Value, Diagnostic> {
        match macros::kind(n) {
            Kind::System => match self.machine.read_system(n, span)? {
                Some(v) => Ok(Value::Number(v)),
                None => Err(system_variable(n, span)),
            },
            _ => self.machine.variables.read(n, span),
        }
    }

    fn write(&mut self, n: u32, v: Value, span: Span) -> Result<(), Diagnostic> {
        match macros::kind(n) {
            Kind::System => match self.machine.write_system(n, v.number(), span, self.out)? {
                true => Ok(()),
                false => Err(system_variable(n, span)),
            },
            _ => self.machine.variables.write(n, v, span),
        }
    }
}

/// Runs the block's statement and evaluates its macro words; the block the
/// machine runs, or the alarm that stops the run here.
#[inline(never)]
pub(super) fn resolve(
    block: &Block,
    m: &MacroBlock,
    machine: &mut Machine,
    out: &mut Out,
) -> Result<Block, Diagnostic> {
    let options = options(machine);
    if let Some(s) = &m.statement {
        let outcome = Evaluator::new(&mut Vars { machine, out }, options).execute(s)?;
        match outcome {
            Outcome::Assigned { number, value, was } => {
                let expr = match &s.kind {
                    StatementKind::Assign { value, .. } => value,
                    StatementKind::IfThen(_, then) => match &then.kind {
                        StatementKind::Assign { value, .. } => value,
                        _ => return Err(not_modelled(s.span, &s.kind)),
                    },
                    _ => return Err(not_modelled(s.span, &s.kind)),
                };
                let before = match was {
                    Value::Vacant => "was vacant".to_string(),
                    v => format!("was {v}"),
                };
                out.notes.push(format!(
                    "#{number} = {value} ({}), {before}",
                    m.text_of(expr)
                ));
                out.events.push(EventKind::VariableSet(VariableSet {
                    variable: number,
                    value: value.get(),
                    was: was.get(),
                }));
            }
            Outcome::NotTaken => {
                let what = match &s.kind {
                    StatementKind::IfGoto(..) => "no jump",
                    _ => "nothing is set",
                };
                out.notes.push(format!(
                    "{}: the condition does not hold, {what}",
                    m.text_of_statement(s)
                ));
            }
            Outcome::Goto(_) | Outcome::While { .. } | Outcome::Do(_) | Outcome::End(_) => {
                return Err(not_modelled(s.span, &s.kind));
            }
        }
    }
    let mut values = Vec::with_capacity(m.words.len());
    let increment = m.increment();
    for w in &m.words {
        let v =
            Evaluator::new(&mut Vars { machine, out }, options).word_value(&w.value, increment)?;
        if v.is_vacant() {
            // Fanuc: a vacant variable's address is left out (behaviour 20.4).
            out.notes.push(format!(
                "{}{} is vacant: the {} word is left out",
                w.address.letter(),
                m.text_of(&w.value),
                w.address.letter()
            ));
        }
        values.push(v.get());
    }
    if m.words.is_empty() && block.words.is_empty() {
        let mut empty = Block::default();
        empty.span = block.span;
        return Ok(empty);
    }
    let (resolved, diagnostics) =
        syntax::resolve(block, m, &values, ParseOptions::from(machine.setup()));
    for d in diagnostics {
        if d.is_error() {
            return Err(d);
        }
        out.warnings.push(d);
    }
    Ok(resolved)
}

/// The stop at a jump or a loop until the executor of issue 22 part 1
/// lands: never run wrongly or passed over (behaviour 20.8).
fn not_modelled(span: crate::diag::Span, kind: &StatementKind) -> Diagnostic {
    Diagnostic::error(
        "macro-not-modelled",
        span,
        format!(
            "{} needs the executor of issue 22 part 1 (jumps and loops): not modelled yet; the run stops here",
            kind.keyword()
        ),
    )
}
