//! A block with Custom Macro B in it (behaviour 20.8), between the parser
//! and the machine: its statement runs over the machine's variables, its
//! macro words are evaluated in program order and typed as the parser types
//! a word, and the block the machine runs is the one with their values.
//! Only blocks the parser marked take this way: the others run as before.

use super::flow::{self, ALARM, MESSAGE_STOP};
use crate::diag::Diagnostic;
use crate::diag::Span;
use crate::machine::calls::{Jump, MacroJump};
use crate::machine::{EventKind, Machine, Out, VariableSet};
use crate::macros::{
    self, Evaluator, Kind, Options, Outcome, Setting, Statement, StatementKind, Value, Variables,
    system_variable,
};
use crate::setup::{MacroAngles, MacroConditions};
use crate::syntax::{self, Block, MacroBlock, ParseOptions};

/// The evaluation options of the machine's setup (settings 7.39, 7.40).
pub(super) fn options(machine: &Machine) -> Options {
    let s = &machine.setup().settings;
    Options {
        signed_angles: s.macro_angles() == MacroAngles::Signed,
        numeric_conditions: s.macro_conditions() == MacroConditions::Numeric,
        linuxcnc: s.control == crate::setup::Control::Linuxcnc,
    }
}

/// The run's variables: the machine's store, and the system variables of
/// the offsets, which read and write the machine's tables (behaviour 20.10).
pub(super) struct Vars<'a> {
    pub(super) machine: &'a mut Machine,
    pub(super) out: &'a mut Out,
    /// `#3000` or `#3006` written, with its value (behaviour 20.16).
    pub(super) message: Option<(u32, Value)>,
}

impl Vars<'_> {
    fn linuxcnc(&self) -> bool {
        self.machine.setup().settings.control == crate::setup::Control::Linuxcnc
    }
}

impl Variables for Vars<'_> {
    fn read(&mut self, n: u32, span: Span) -> Result<Value, Diagnostic> {
        if let ALARM | MESSAGE_STOP = n
            && !self.linuxcnc()
        {
            return Err(flow::write_only(n, span));
        }
        let v = match macros::kind(n) {
            // LinuxCNC's parameters: never set reads 0 (behaviour 22.10).
            _ if self.linuxcnc() => Value::Number(self.machine.read_parameter(n, span)?),
            Kind::System => match self.machine.read_system(n, span)? {
                Some(v) => Value::Number(v),
                None => return Err(system_variable(n, span)),
            },
            _ => self.machine.variables.read(n, span)?,
        };
        // The Variables panel shows what the program read (behaviour 21.12).
        self.machine.watch(n, span, false);
        Ok(v)
    }

    fn write(&mut self, n: u32, v: Value, span: Span) -> Result<(), Diagnostic> {
        if let ALARM | MESSAGE_STOP = n
            && !self.linuxcnc()
        {
            self.message = Some((n, v));
            return Ok(());
        }
        match macros::kind(n) {
            _ if self.linuxcnc() => {
                self.machine
                    .write_parameter(n, v.number(), span, self.out)?;
            }
            Kind::System => match self.machine.write_system(n, v.number(), span, self.out)? {
                true => {}
                false => return Err(system_variable(n, span)),
            },
            _ => self.machine.variables.write(n, v, span)?,
        }
        self.machine.watch(n, span, true);
        Ok(())
    }

    fn read_named(&mut self, name: &str, span: Span) -> Result<Option<f64>, Diagnostic> {
        if let Some(v) = super::named::predefined(self.machine, name, span)? {
            return Ok(Some(v));
        }
        let named = &self.machine.macro_calls_mut().named;
        let v = match name.starts_with('_') {
            true => named.globals.get(name).copied(),
            false => named.locals.get(name).copied(),
        };
        // A call's value is 0 until a sub returns one (behaviour 22.7).
        Ok(v.or(match name {
            "_value" | "_value_returned" => Some(0.0),
            _ => None,
        }))
    }

    fn write_named(&mut self, name: &str, v: f64, span: Span) -> Result<(), Diagnostic> {
        if super::named::is_predefined(self.machine, name) {
            return Err(Diagnostic::error(
                "named-parameter",
                span,
                format!(
                    "#<{name}> is one of LinuxCNC's predefined parameters, which a program reads and never sets"
                ),
            ));
        }
        let named = &mut self.machine.macro_calls_mut().named;
        let map = match name.starts_with('_') {
            true => &mut named.globals,
            false => &mut named.locals,
        };
        // Bounded: one entry per name the program writes, and a name is
        // written in the program's text.
        map.insert(name.into(), v);
        Ok(())
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
        let mut vars = Vars {
            machine,
            out,
            message: None,
        };
        let outcome = Evaluator::new(&mut vars, options).execute(s)?;
        if let Some((n, v)) = vars.message {
            // #3000 stops the run with the program's alarm; #3006 stops
            // with a message and the run goes on (behaviour 20.16).
            flow::message(n, v, s, m, out)?;
            return Ok(empty(block));
        }
        match outcome {
            Outcome::Assigned { number, value, was } => {
                // Only an assignment, alone or after THEN, assigns.
                let written = match &s.kind {
                    StatementKind::Assign { value, .. } => m.text_of(value),
                    StatementKind::IfThen(_, then) => match &then.kind {
                        StatementKind::Assign { value, .. } => m.text_of(value),
                        _ => m.text_of_statement(then),
                    },
                    _ => m.text_of_statement(s),
                };
                let before = match was {
                    Value::Vacant => "was vacant".to_string(),
                    v => format!("was {v}"),
                };
                out.notes
                    .push(format!("#{number} = {value} ({written}), {before}"));
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
            Outcome::AssignedNamed { value, was } => {
                let (name, written) = match &s.kind {
                    StatementKind::AssignNamed { name, value, .. } => (name, m.text_of(value)),
                    _ => {
                        return Err(Diagnostic::error(
                            "internal",
                            s.span,
                            "not a named assignment",
                        ));
                    }
                };
                let before = match was {
                    None => "was not set".to_string(),
                    Some(v) => format!("was {}", Value::Number(v)),
                };
                out.notes.push(format!(
                    "#<{name}> = {} ({written}), {before}",
                    Value::Number(value)
                ));
            }
            Outcome::OWord => machine.jump = Some(Jump::Flow(MacroJump::OWord)),
            // The run finds where these lead (behaviour 20.11–20.14).
            Outcome::Goto(n) => machine.jump = Some(Jump::Flow(MacroJump::Goto(n))),
            Outcome::While { holds, label } => {
                machine.jump = Some(Jump::Flow(MacroJump::While { holds, label }));
            }
            Outcome::Do(label) => machine.jump = Some(Jump::Flow(MacroJump::Do(label))),
            Outcome::End(label) => machine.jump = Some(Jump::Flow(MacroJump::End(label))),
        }
    }
    // LinuxCNC: the line's settings read their values with the
    // parameters as they were, as its words do (behaviour 22.10).
    let mut settings = Vec::with_capacity(m.settings.len());
    for s in &m.settings {
        let mut vars = Vars {
            machine: &mut *machine,
            out: &mut *out,
            message: None,
        };
        settings.push((s, Evaluator::new(&mut vars, options).setting(s)?));
    }
    let mut values = Vec::with_capacity(m.words.len());
    let increment = m.increment();
    for w in &m.words {
        let mut vars = Vars {
            machine: &mut *machine,
            out: &mut *out,
            message: None,
        };
        let v = Evaluator::new(&mut vars, options).word_value(&w.value, increment)?;
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
    for (s, (setting, span)) in settings {
        make_setting(s, setting, span, m, machine, out)?;
    }
    if m.words.is_empty() && block.words.is_empty() {
        return Ok(empty(block));
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

/// Makes one of the line's LinuxCNC settings, after its values are read
/// (behaviour 22.10): the note and event an assignment gives.
fn make_setting(
    s: &Statement,
    setting: Setting,
    span: Span,
    m: &MacroBlock,
    machine: &mut Machine,
    out: &mut Out,
) -> Result<(), Diagnostic> {
    let written = match &s.kind {
        StatementKind::Assign { value, .. } | StatementKind::AssignNamed { value, .. } => {
            m.text_of(value)
        }
        _ => m.text_of_statement(s),
    };
    let mut vars = Vars {
        machine,
        out,
        message: None,
    };
    match setting {
        Setting::Numbered(number, value) => {
            let was = vars.read(number, span).unwrap_or_default();
            vars.write(number, value, span)?;
            vars.out.notes.push(format!(
                "#{number} = {value} ({written}), was {was}; set after the line's values are read (LinuxCNC)"
            ));
            vars.out.events.push(EventKind::VariableSet(VariableSet {
                variable: number,
                value: value.get(),
                was: was.get(),
            }));
        }
        Setting::Named(name, value) => {
            let was = vars.read_named(&name, span).ok().flatten();
            vars.write_named(&name, value, span)?;
            let before = match was {
                None => "was not set".to_string(),
                Some(v) => format!("was {}", Value::Number(v)),
            };
            vars.out.notes.push(format!(
                "#<{name}> = {} ({written}), {before}; set after the line's values are read (LinuxCNC)",
                Value::Number(value)
            ));
        }
    }
    Ok(())
}

/// A block of nothing in `block`'s place.
fn empty(block: &Block) -> Block {
    let mut empty = Block::default();
    empty.span = block.span;
    empty
}
