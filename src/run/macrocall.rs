//! Macro calls (behaviour 21): `G65 P… L… <arguments>` calls a program
//! as a subprogram with a new level of local variables #1–#33, the
//! arguments assigned to them; `G66` makes the same call after each block
//! that moves, until `G67`. The call is a [`Jump::Macro`] the run makes as
//! it makes M98's (`calls.rs`), the call's [`Level`] on its frame: the
//! caller's locals kept there, given back at M99.
//!
//! Sources: Fanuc 16i/18i operator's manual (B-63684EN), 16 "Custom
//! macro", "Macro call" (simple call G65, modal call G66/G67, argument
//! specification I and II and their mixture, the decimal point of an
//! argument, call nesting and local variable levels); Fanuc 0i-MF/0i-TF
//! operator's manuals, the same chapter; the Fanuc alarm list (PS0076,
//! PS0077).

use super::{Runner, Step};
use crate::diag::{Diagnostic, Span};
use crate::machine::calls::Jump;
use crate::machine::macro_state::{Locals, ModalCall};
use crate::machine::program::ProgramText;
use crate::machine::{Flow, Machine, Out};
use crate::macros::{Evaluator, Value};
use crate::syntax::{Address, Block, CallCode, MacroBlock, MacroCall, is_argument};

/// A macro call's level, kept on its frame of the call stack.
#[derive(Clone, Debug)]
pub(crate) struct Level {
    /// The caller's locals, given back at M99.
    saved: Box<Locals>,
    /// The locals the call starts with (again at each repeat of L).
    args: Box<Locals>,
    /// The level the macro runs at (1 for a call from the main program).
    number: u8,
    /// Made by G66's modal call.
    modal: bool,
    /// The line of the call's block, where its arguments were set.
    line: u32,
}

impl Level {
    /// What the stack adds to the call's block (`O1000 N30 (G65, level 1)`).
    pub(super) fn site(&self) -> String {
        format!(" ({}, level {})", self.code(), self.number)
    }

    /// The code that made the call.
    pub(super) fn code(&self) -> &'static str {
        if self.modal { "G66" } else { "G65" }
    }

    /// The call's note (`local variable level 1`).
    pub(super) fn said(&self) -> String {
        format!("local variable level {}", self.number)
    }

    /// A repeat of L: the locals start again from the arguments.
    pub(super) fn again(&self, machine: &mut Machine) {
        machine.set_locals(&self.args);
        machine.watch_level(&self.args, self.line);
    }

    /// M99: the caller's locals and level come back (Fanuc: the locals of
    /// the level before are restored as they were stored at the call).
    pub(super) fn leave(&self, machine: &mut Machine) {
        machine.set_locals(&self.saved);
        let m = machine.macro_calls_mut();
        m.level = self.number.saturating_sub(1);
        if self.modal {
            m.in_modal = m.in_modal.saturating_sub(1);
        }
        machine.watch_leave();
    }
}

/// The run makes the call the machine asked for: for a macro, the caller's
/// locals are kept and the called level's set. None for M98 and M97.
pub(super) fn enter(machine: &mut Machine, jump: Jump, line: u32) -> Option<Box<Level>> {
    let Jump::Macro { modal, .. } = jump else {
        return None;
    };
    let saved = Box::new(machine.locals());
    let m = machine.macro_calls_mut();
    let args = m
        .pending
        .take()
        .unwrap_or_else(|| Box::new([Value::Vacant; 33]));
    m.level = m.level.saturating_add(1);
    if modal {
        m.in_modal = m.in_modal.saturating_add(1);
    }
    let number = m.level;
    // The arguments were written at the G65, or at the G66 for its modal
    // calls: the Variables panel names that line (behaviour 21.13).
    let line = match (&m.modal, modal) {
        (Some(call), true) => call.line,
        _ => line,
    };
    machine.set_locals(&args);
    machine.watch_level(&args, line);
    Some(Box::new(Level {
        saved,
        args,
        number,
        modal,
        line,
    }))
}

/// The step of a macro call's block, which ran (or stopped) outside the
/// machine's own run.
#[cold]
#[inline(never)]
pub(super) fn ran(result: Result<Flow, Diagnostic>, index: &mut u32, stopped: &mut bool) -> Step {
    match result {
        Ok(flow) => {
            *index += 1;
            *stopped = flow == Flow::End;
            Step::Ran(flow)
        }
        Err(d) => {
            *stopped = true;
            Step::Stopped(Some(d))
        }
    }
}

/// The local variable of an argument letter in specification I (Fanuc:
/// A #1, B #2, C #3, I #4, J #5, K #6, D #7, E #8, F #9, H #11, M #13,
/// Q #17, R #18, S #19, T #20, U #21, V #22, W #23, X #24, Y #25, Z #26).
fn variable_i(letter: u8) -> Option<usize> {
    Some(match letter {
        b'A' => 1,
        b'B' => 2,
        b'C' => 3,
        b'I' => 4,
        b'J' => 5,
        b'K' => 6,
        b'D' => 7,
        b'E' => 8,
        b'F' => 9,
        b'H' => 11,
        b'M' => 13,
        b'Q' => 17,
        b'R' => 18,
        b'S' => 19,
        b'T' => 20,
        b'U' => 21,
        b'V' => 22,
        b'W' => 23,
        b'X' => 24,
        b'Y' => 25,
        b'Z' => 26,
        _ => return None,
    })
}

/// One argument, its value found.
struct Arg {
    letter: u8,
    value: Value,
    span: Span,
}

/// Assigns the arguments, in the order written, to the locals (behaviour
/// 21.2): A, B, C to #1–#3; I, J, K in sets — a set ends when a letter
/// does not come after the one before it in I, J, K — set s's I, J, K to
/// #(4+3(s−1))… (specification II, up to 10 sets, #4–#33); every other
/// letter as specification I says. Specification I's I, J, K are set 1's,
/// so the two mix as Fanuc says: where two arguments name one variable,
/// the later one holds (`I-3. I4. D5.`: #7 is 5).
fn assign(args: &[Arg]) -> Result<(Locals, Vec<String>), Diagnostic> {
    let mut locals = [Value::Vacant; 33];
    let mut said = Vec::with_capacity(args.len());
    let (mut set, mut last) = (1usize, None::<usize>);
    for a in args {
        let n = match a.letter {
            b'I' | b'J' | b'K' => {
                let rank = usize::from(a.letter - b'I');
                if last.is_some_and(|l| rank <= l) {
                    set += 1;
                }
                last = Some(rank);
                if set > 10 {
                    return Err(Diagnostic::error(
                        "call-words",
                        a.span,
                        "an eleventh set of I, J, K: argument specification II passes at most 10 (#4 to #33)",
                    ));
                }
                4 + 3 * (set - 1) + rank
            }
            l => variable_i(l).ok_or_else(|| {
                Diagnostic::error(
                    "call-words",
                    a.span,
                    format!("{} passes no argument to a macro", l as char),
                )
            })?,
        };
        locals[n - 1] = a.value;
        said.push(format!("{}=#{n}={}", a.letter as char, a.value));
    }
    Ok((locals, said))
}

/// A G65, G66 or G67 block (behaviour 21.1–21.5): checked, its arguments
/// evaluated in the order written, and the call asked of the run (G65),
/// the modal call set (G66) or ended (G67).
pub(super) fn call(
    block: &Block,
    m: &MacroBlock,
    call: &MacroCall,
    machine: &mut Machine,
    out: &mut Out,
    program: &mut dyn ProgramText,
) -> Result<Flow, Diagnostic> {
    let code = call.code.text();
    // Only N, P and L are the call's own words; every other word is an
    // argument written after G65 (Fanuc: G65 before any argument).
    let own = |a: Address| matches!(a, Address::N | Address::P | Address::L);
    let stray = block
        .words
        .iter()
        .find(|w| !own(w.address) || (call.code == CallCode::Cancel && w.address != Address::N))
        .map(|w| (w.span, w.address.letter()))
        .or_else(|| {
            m.words
                .iter()
                .find(|w| {
                    !own(w.address)
                        && (w.span.start < call.span.start || call.code == CallCode::Cancel)
                })
                .map(|w| (w.span, w.address.letter()))
        });
    if let Some((span, letter)) = stray {
        return Err(Diagnostic::error(
            "call-words",
            span,
            match call.code {
                CallCode::Cancel => format!(
                    "{letter} in a G67 block: G67 ends the modal call and takes no other word; write it in a block of its own"
                ),
                _ => format!(
                    "{letter} in a {code} block: the words after {code} are the macro's arguments, and {code} is written before them (a code to run goes in a block of its own)"
                ),
            },
        ));
    }
    if m.statement.is_some() {
        return Err(crate::macros::alarm::NC_AND_MACRO.at(
            call.span,
            format!("{code} and a macro statement share a block; write them in two blocks"),
        ));
    }
    if call.code == CallCode::Cancel {
        let ended = machine.macro_calls_mut().modal.take();
        out.notes.push(match ended {
            Some(c) => format!(
                "G67: the modal call of O{:04} (G66 at line {}) ends",
                c.program, c.line
            ),
            None => "G67: no modal call was in force".to_string(),
        });
        // A jump without a target: the run on two threads hands the
        // program to one, whose runner watches the modal call.
        return Ok(Flow::Jump);
    }
    let options = super::macros::options(machine);
    let mut number = |a: Address| -> Result<Option<(f64, Span)>, Diagnostic> {
        if let Some(w) = block.get(a) {
            return Ok(Some((w.value, w.span)));
        }
        let Some(w) = m.words.iter().find(|w| w.address == a) else {
            return Ok(None);
        };
        let mut vars = super::macros::Vars {
            machine,
            out,
            message: None,
        };
        let v = Evaluator::new(&mut vars, options).value(&w.value)?;
        Ok(v.get().map(|v| (v.round(), w.span)))
    };
    let Some((p, p_span)) = number(Address::P)? else {
        return Err(Diagnostic::error(
            "missing-word",
            call.span,
            format!("{code} calls the program its P names: write {code} P9010"),
        ));
    };
    let times = match number(Address::L)? {
        None => 1,
        Some((l, span)) if !(1.0..=9999.0).contains(&l) => {
            return Err(Diagnostic::error(
                "out-of-range",
                span,
                format!("L{l}: a macro call runs its program 1 to 9999 times"),
            ));
        }
        Some((l, _)) => l as u32,
    };
    let p = p as u32;
    if !program.has_program(p) {
        return Err(Diagnostic::error(
            "program-not-found",
            p_span,
            format!(
                "{code} P{p}: no program O{p:04} in this file (alarm PS0076 PROGRAM NOT FOUND)"
            ),
        ));
    }
    // The arguments in the order written: numbers and macro words.
    let mut args: Vec<Arg> = call
        .args
        .iter()
        .map(|a| Arg {
            letter: a.letter,
            value: Value::Number(a.value),
            span: a.span,
        })
        .collect();
    for w in m
        .words
        .iter()
        .filter(|w| is_argument(w.address.letter().as_bytes()[0]))
    {
        let mut vars = super::macros::Vars {
            machine,
            out,
            message: None,
        };
        let value = Evaluator::new(&mut vars, options).value(&w.value)?;
        args.push(Arg {
            letter: w.address.letter().as_bytes()[0],
            value,
            span: w.span,
        });
    }
    args.sort_by_key(|a| a.span.start);
    let (locals, said) = assign(&args)?;
    let with = match said.is_empty() {
        true => "no arguments".to_string(),
        false => format!("with {}", said.join(", ")),
    };
    if call.code == CallCode::Modal {
        machine.macro_calls_mut().modal = Some(Box::new(ModalCall {
            program: p,
            times,
            locals,
            said: with.clone(),
            line: block.span.line,
        }));
        out.notes.push(format!(
            "G66 P{p}: O{p:04} is called after each block that moves, {with}, until G67"
        ));
        return Ok(Flow::Jump);
    }
    check_nesting(machine, call.span, code)?;
    out.notes.push(format!("G65 P{p}: calls O{p:04} {with}"));
    machine.macro_calls_mut().pending = Some(Box::new(locals));
    machine.jump = Some(Jump::Macro {
        program: p,
        times,
        modal: false,
    });
    Ok(Flow::Jump)
}

/// The call past the control's macro nesting (setting 7.45) is alarm
/// PS0077, before it is made.
fn check_nesting(machine: &Machine, span: Span, code: &str) -> Result<(), Diagnostic> {
    let most = machine.setup().settings.macro_nesting();
    if u32::from(machine.macro_level()) >= most {
        return Err(Diagnostic::error(
            "nesting-too-deep",
            span,
            format!(
                "{code}: {most} macro calls are open already, as many as the control nests (setting macro_nesting); alarm PS0077 TOO MANY SUB,MACRO NESTING"
            ),
        ));
    }
    Ok(())
}

impl Runner<'_> {
    /// The block just run asked for a jump, reached the block limit, or
    /// ran in a program that made a macro call: a G66 in force calls its
    /// macro after a move (behaviour 21.5), then the jump is made. A macro
    /// call's block that made no jump (G66, G67) reads on.
    #[cold]
    #[inline(never)]
    pub(super) fn after_block(&mut self, step: Step) -> Step {
        let step = match step {
            Step::Ran(Flow::Continue) if self.machine.jump.is_none() => {
                match after_move(&self.block, &mut self.machine, &mut self.out) {
                    Ok(flow) => Step::Ran(flow),
                    Err(d) => {
                        self.stopped = true;
                        Step::Stopped(Some(d))
                    }
                }
            }
            step => step,
        };
        self.jump_or_stop(step)
    }
}

/// True for a block with a move command: an axis word, as written or from
/// a variable, in a block whose axis words are a position (not a dwell's
/// time, a G10's value or a coordinate system's setting).
fn moves(block: &Block) -> bool {
    use crate::syntax::codes::NonModal;
    if let Some(
        NonModal::Dwell
        | NonModal::DataSetting
        | NonModal::SetCoordinates
        | NonModal::LocalCoordinates
        | NonModal::PresetCoordinates
        | NonModal::Stored(_),
    ) = block.codes().non_modal()
    {
        return false;
    }
    const AXES: [Address; 8] = [
        Address::X,
        Address::Y,
        Address::Z,
        Address::U,
        Address::W,
        Address::A,
        Address::B,
        Address::C,
    ];
    AXES.iter().any(|a| block.has(*a))
        || block
            .macros
            .as_ref()
            .is_some_and(|m| m.words.iter().any(|w| AXES.contains(&w.address)))
}

/// The block just run in G66's mode (behaviour 21.5): a block with an axis
/// word calls the macro after its move; a block inside a macro the modal
/// call made does not.
fn after_move(block: &Block, machine: &mut Machine, out: &mut Out) -> Result<Flow, Diagnostic> {
    let Some(state) = machine.macro_calls.as_deref() else {
        return Ok(Flow::Continue);
    };
    let Some(modal) = state.modal.as_deref() else {
        return Ok(Flow::Continue);
    };
    if state.in_modal > 0 || !moves(block) {
        return Ok(Flow::Continue);
    }
    let (program, times, locals) = (modal.program, modal.times, modal.locals);
    let note = format!(
        "G66 (line {}): after this move, calls O{program:04} {}",
        modal.line, modal.said
    );
    check_nesting(machine, block.span, "the G66 modal call")?;
    out.notes.push(note);
    machine.macro_calls_mut().pending = Some(Box::new(locals));
    machine.jump = Some(Jump::Macro {
        program,
        times,
        modal: true,
    });
    Ok(Flow::Jump)
}
