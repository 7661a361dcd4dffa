//! Subprogram calls and returns as a block asks for them (behaviour 19):
//! M98 P (a program by number, repeated L times), Haas's M97 P (blocks of
//! the same program from sequence number P), M99 (back to the caller; with
//! P, to that sequence number). The machine checks the words and that the
//! target exists, and hands the run a [`Jump`]; the run reads on from
//! there (`run/calls.rs`). The block's other words run first: a control
//! makes the block's move, then calls (Fanuc 0i-MF, "Subprogram call":
//! a move command in the M98 block is executed before the call).

use super::Machine;
use super::program::ProgramText;
use crate::diag::Diagnostic;
use crate::setup::SubprogramP;
use crate::syntax::codes::{MCode, NonModal};
use crate::syntax::{Address, Block, Word};

/// Where the run goes on after a block (behaviour 19).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Jump {
    /// M98: program O`program`, `times` times over.
    Call { program: u32, times: u32 },
    /// M97 (Haas): this program's blocks from sequence number `sequence`
    /// up to an M99, `times` times over.
    Local { sequence: u32, times: u32 },
    /// M99: back to the block after the call, or with P to the caller's
    /// block with that sequence number; in the main program, to its start
    /// (or that sequence number).
    Return { to: Option<u32> },
    /// G65 (or a G66 modal call, `modal`): program O`program`, `times`
    /// times over, with a new level of local variables (behaviour 21).
    Macro {
        program: u32,
        times: u32,
        modal: bool,
    },
    /// A macro statement's jump or loop (behaviour 20.11–20.14): the run
    /// finds where it leads.
    Flow(MacroJump),
}

/// What a macro statement asks of the run's reading (behaviour 20.11–20.14).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum MacroJump {
    /// GOTO n, or IF [..] GOTO n whose condition holds.
    Goto(u32),
    /// WHILE [..] DO m: whether the condition holds.
    While { holds: bool, label: u8 },
    /// DO m without WHILE.
    Do(u8),
    /// END m.
    End(u8),
    /// A LinuxCNC o-word (behaviour 22.7): the run reads its statement.
    OWord,
}

/// The biggest program number the repeat-and-number form of P writes in
/// its last four digits (behaviour 7.36).
const FOUR_DIGITS: u32 = 10_000;

impl Machine {
    /// The call or return the block asks for, checked, with the block's
    /// other words (the call's M, P and L taken out); None for a block
    /// with none. The alarms are the Fanuc ones (alarm list: PS0076
    /// PROGRAM NOT FOUND, PS0077 TOO MANY SUB,MACRO NESTING, PS0078
    /// SEQUENCE NUMBER NOT FOUND), at the word that names the target.
    pub(super) fn subprogram_jump(
        &self,
        b: &Block,
        program: &mut dyn ProgramText,
    ) -> Result<Option<(Jump, Block)>, Diagnostic> {
        let machine = self.setup.machine;
        let is_call = |w: &&Word| {
            w.address == Address::M
                && matches!(
                    MCode::of(machine, w.int()),
                    MCode::SubprogramCall | MCode::SubprogramReturn | MCode::LocalSubprogramCall
                )
        };
        let mut calls = b.words.iter().filter(is_call);
        let Some(m) = calls.next().copied() else {
            return Ok(None);
        };
        if let Some(second) = calls.next() {
            return Err(self.error(
                "two-calls",
                second.span,
                format!(
                    "M{:02} and M{:02} in one block: a block calls or returns once",
                    m.int(),
                    second.int()
                ),
            ));
        }
        let (p, l) = (b.get(Address::P), b.get(Address::L));
        let reads_p = b.codes().non_modal() == Some(NonModal::Dwell) || b.codes().cycle().is_some();
        if let (true, Some(p)) = (reads_p, p) {
            return Err(self.error(
                "call-words",
                p.span,
                format!(
                    "P in a block with M{:02} and a dwell or canned cycle: P would be both the call's and the dwell's; write the call in a block of its own",
                    m.int()
                ),
            ));
        }
        let jump = match MCode::of(machine, m.int()) {
            MCode::SubprogramCall => self.program_call(&m, p, l, program)?,
            MCode::LocalSubprogramCall => {
                let p = p.ok_or_else(|| {
                    self.error(
                        "missing-word",
                        m.span,
                        "M97 calls the blocks of this program from the sequence number its P names: write M97 P1000",
                    )
                })?;
                let times = repeats(l, 1);
                self.check_repeats(times, l.unwrap_or(p))?;
                if !program.has_local(p.int()) {
                    return Err(self.error(
                        "sequence-not-found",
                        p.span,
                        format!(
                            "M97 P{0}: no block N{0} in this program (alarm PS0078 SEQUENCE NUMBER NOT FOUND)",
                            p.int()
                        ),
                    ));
                }
                Jump::Local {
                    sequence: p.int(),
                    times,
                }
            }
            _ => {
                if let Some(l) = l {
                    return Err(self.error(
                        "unsupported-word",
                        l.span,
                        "L in an M99 block (a new repeat count for the caller) is not modelled: offsetlab stops here rather than repeat a different number of times",
                    ));
                }
                let to = p.map(Word::int);
                if let (Some(n), Some(p)) = (to, p)
                    && !program.has_return(n)
                {
                    let whose = match program.depth() {
                        0 => "this program",
                        _ => "the program M99 returns to",
                    };
                    return Err(self.error(
                        "sequence-not-found",
                        p.span,
                        format!(
                            "M99 P{n}: no block N{n} in {whose} (alarm PS0078 SEQUENCE NUMBER NOT FOUND)"
                        ),
                    ));
                }
                Jump::Return { to }
            }
        };
        let depth = self.setup.settings.subprogram_nesting();
        // Macro calls have their own count (behaviour 21.4).
        let open = program
            .depth()
            .saturating_sub(usize::from(self.macro_level()));
        if !matches!(jump, Jump::Return { .. }) && open >= depth as usize {
            return Err(self.error(
                "nesting-too-deep",
                m.span,
                format!(
                    "M{:02}: {depth} subprogram calls are open already, as many as the control nests (setting subprogram_nesting); alarm PS0077 TOO MANY SUB,MACRO NESTING",
                    m.int()
                ),
            ));
        }
        let call_word = |w: &Word| w.span == m.span || matches!(w.address, Address::P | Address::L);
        Ok(Some((jump, b.without(call_word))))
    }

    /// M98's program and repeat count (behaviour 19.3, setting 7.36).
    fn program_call(
        &self,
        m: &Word,
        p: Option<&Word>,
        l: Option<&Word>,
        program: &mut dyn ProgramText,
    ) -> Result<Jump, Diagnostic> {
        let p = p.ok_or_else(|| {
            self.error(
                "missing-word",
                m.span,
                "M98 calls the program its P names: write M98 P1000",
            )
        })?;
        let value = p.int();
        let (number, times) = match (self.setup.settings.subprogram_p(), l) {
            (_, Some(l)) => (value, l.int()),
            // P LLLLNNNN: the digits before the last four repeat.
            (SubprogramP::RepeatAndNumber, None) if value >= FOUR_DIGITS => {
                (value % FOUR_DIGITS, value / FOUR_DIGITS)
            }
            _ => (value, 1),
        };
        self.check_repeats(times, l.unwrap_or(p))?;
        if !program.has_program(number) {
            return Err(self.error(
                "program-not-found",
                p.span,
                format!(
                    "M98 P{value}: no program O{number:04} in this file or the setup's programs (alarm PS0076 PROGRAM NOT FOUND)"
                ),
            ));
        }
        Ok(Jump::Call {
            program: number,
            times,
        })
    }

    fn check_repeats(&self, times: u32, word: &Word) -> Result<(), Diagnostic> {
        if times == 0 {
            return Err(self.error(
                "out-of-range",
                word.span,
                "a repeat count of 0: a call runs its subprogram 1 to 9999 times",
            ));
        }
        Ok(())
    }
}

/// L's repeat count, or `default`.
fn repeats(l: Option<&Word>, default: u32) -> u32 {
    l.map_or(default, Word::int)
}
