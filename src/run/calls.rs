//! The run's side of subprogram calls (behaviour 19): where the run reads
//! after an M98, M97 or M99 the machine has checked ([`Jump`]), the call
//! stack of return places, and what each block's report says of them.
//!
//! A run without calls reads the text with one parser, start to end (the
//! `check` fast path, docs/performance.md). At the first call that parser
//! is set aside, where it stands, and the blocks come from parsers resumed
//! at the places the calls name, each reading one program
//! ([`Blocks::one_program`]); the first parser reads the whole text for
//! its diagnostics once the run is done or back where it left off. The
//! pieces a jump is made of — [`Sequences::find_in`] (the block with a
//! sequence number in a program) and [`Frame`]'s return place — are the
//! ones a GOTO and a DO/END loop need too.

use super::sequence::Sequences;
use super::{Runner, Step};
use crate::diag::{Diagnostic, Span, thousands};
use crate::machine::Flow;
use crate::machine::calls::Jump;
use crate::report::Place;
use crate::syntax::{Address, Block, Blocks, Resume};

/// A program being read: where it starts (None: the main program, from
/// the text's start) and what the reports call it.
#[derive(Clone, Debug)]
pub(crate) struct Program {
    pub(crate) start: Option<Resume>,
    pub(crate) label: String,
}

/// An open call: where to go back to and what to do again.
#[derive(Clone, Debug)]
pub(crate) struct Frame {
    /// The program that called.
    caller: Program,
    /// The place after the call's block: the return place.
    back: Resume,
    /// The call's block as the stack shows it (`O1000 N40`).
    site: String,
    /// Where the called blocks start (read again for each repeat).
    entry: Resume,
    /// The program called.
    callee: Program,
    /// Repeats after the one running.
    left: u32,
    /// Repeats in all.
    times: u32,
    /// A macro call's level of local variables (behaviour 21).
    level: Option<Box<super::macrocall::Level>>,
}

/// The calls of a run once it has made one.
pub(crate) struct Calls<'t> {
    /// The run's first parser, set aside while others read elsewhere
    /// (None once it reads again).
    main: Option<Blocks<'t>>,
    /// The program being read.
    current: Program,
    /// The open calls, outermost first.
    stack: Vec<Frame>,
    /// M99s in the main program so far, and the last one's block.
    loops: u32,
    loop_span: Option<Span>,
    /// The header lines of the programs called so far (their
    /// `program-not-run` warning is withdrawn, behaviour 1.21).
    called: Vec<u32>,
}

/// What a checkpoint keeps of the calls (the parsers aside).
#[derive(Clone, Debug)]
pub(crate) struct Saved {
    /// Where the first parser was set aside, if it was.
    main: Option<Resume>,
    current: Program,
    stack: Vec<Frame>,
    loops: u32,
    loop_span: Option<Span>,
    /// The header lines of the programs called so far (their
    /// `program-not-run` warning is withdrawn, behaviour 1.21).
    called: Vec<u32>,
}

impl<'t> Calls<'t> {
    /// The run's first parser when another reads the blocks.
    pub(super) fn main_parser(&mut self) -> Option<&mut Blocks<'t>> {
        self.main.as_mut()
    }

    pub(super) fn save(&self) -> Saved {
        Saved {
            main: self.main.as_ref().map(Blocks::resume_point),
            current: self.current.clone(),
            stack: self.stack.clone(),
            loops: self.loops,
            loop_span: self.loop_span,
            called: self.called.clone(),
        }
    }

    /// Where the block about to be read runs among the calls; None in
    /// the main program.
    fn place(&self) -> Option<Box<Place>> {
        if self.stack.is_empty() {
            return None;
        }
        let mut stack: Vec<String> = self.stack.iter().map(|f| f.site.clone()).collect();
        stack.push(self.current.label.clone());
        Some(Box::new(Place {
            program: self.current.label.clone(),
            stack,
            library: false,
        }))
    }
}

impl Saved {
    /// The calls at a checkpoint, and the parser reading there: the first
    /// parser for the calls' own, `at` another's place.
    pub(super) fn restore<'t>(
        &self,
        sequences: &Sequences<'t>,
        parser: Blocks<'t>,
    ) -> (Box<Calls<'t>>, Blocks<'t>) {
        let (main, parser) = match self.main {
            Some(main) => (
                Some(sequences.whole_parser_at(main, parser.diagnostics().to_vec())),
                sequences.parser_at(parser.resume_point()),
            ),
            None => (None, parser),
        };
        let calls = Calls {
            main,
            current: self.current.clone(),
            stack: self.stack.clone(),
            loops: self.loops,
            loop_span: self.loop_span,
            called: self.called.clone(),
        };
        (Box::new(calls), parser)
    }

    /// Points the text's searches at the programs open here.
    pub(super) fn aim(&self, sequences: &mut Sequences<'_>) {
        sequences.depth = self.stack.len();
        sequences.current = self.current.start;
        sequences.caller = self.stack.last().and_then(|f| f.caller.start);
    }
}

impl<'t> Runner<'t> {
    /// The block just run stopped the run, or asked for a jump (the
    /// machine's `jump`, checked): the run reads on where it leads.
    #[cold]
    #[inline(never)]
    pub(super) fn jump_or_stop(&mut self, step: Step) -> Step {
        match step {
            Step::Stopped(Some(mut d)) => {
                if d.code == "too-many-blocks" && !self.explain_loop_limit(&mut d) {
                    self.explain_limit(&mut d);
                }
                Step::Stopped(Some(d))
            }
            // A macro statement's jump leaves the block's flow as it was.
            Step::Ran(Flow::Jump | Flow::Continue) => match self.machine.jump.take() {
                Some(jump) => self.jump(jump),
                None => Step::Ran(Flow::Continue),
            },
            step => step,
        }
    }

    /// The block just run asked for `jump` (checked by the machine): the
    /// run reads on where it leads, and the block's report says where.
    fn jump(&mut self, jump: Jump) -> Step {
        let jump = match jump {
            Jump::Flow(step) => return self.macro_flow(step),
            jump => jump,
        };
        let from_depth = self.sequences.depth;
        self.open_calls();
        let Some(calls) = self.calls.as_deref_mut() else {
            return Step::Ran(Flow::Jump);
        };
        self.block_place = if self.options.keep_blocks {
            calls.place()
        } else {
            None
        };
        let context = self.parser.resume_point();
        let back = context;
        let (target, note) = match jump {
            Jump::Call { program, times }
            | Jump::Macro { program, times, .. }
            | Jump::Local {
                sequence: program,
                times,
            } => {
                let local = matches!(jump, Jump::Local { .. });
                let found = if local {
                    self.sequences
                        .find_in(calls.current.start, program)
                        .map(|at| (at, format!("{} N{program}", calls.current.label)))
                } else {
                    self.sequences.program(program).map(|h| {
                        let at = Resume::program_start(h.pos, h.line, &context);
                        (at, format!("O{program:04}"))
                    })
                };
                // The machine found it a moment ago.
                let Some((entry, label)) = found else {
                    return Step::Ran(Flow::Jump);
                };
                if !local && !calls.called.contains(&entry.line()) {
                    calls.called.push(entry.line());
                }
                let level = super::macrocall::enter(&mut self.machine, jump, self.block.span.line);
                let mut site = site(&calls.current.label, &self.block);
                if let Some(l) = &level {
                    site.push_str(&l.site());
                }
                let callee = Program {
                    start: if local {
                        calls.current.start
                    } else {
                        Some(entry)
                    },
                    label,
                };
                let code = match (&level, local) {
                    (Some(l), _) => l.code(),
                    (None, true) => "M97",
                    (None, false) => "M98",
                };
                let what = match &level {
                    Some(l) => l.said(),
                    None => format!("calls {}", callee.label),
                };
                let note = format!(
                    "{code}: {what}{}; it returns to line {}",
                    match times {
                        1 => String::new(),
                        n => format!(", {n} times"),
                    },
                    back.line()
                );
                let caller = std::mem::replace(&mut calls.current, callee.clone());
                calls.stack.push(Frame {
                    caller,
                    back,
                    site,
                    entry,
                    callee,
                    left: times - 1,
                    times,
                    level,
                });
                (entry, note)
            }
            // Taken at the top.
            Jump::Flow(_) => return Step::Ran(Flow::Jump),
            Jump::Return { to } => match calls.stack.last_mut() {
                Some(frame) if frame.left > 0 && to.is_none() => {
                    frame.left -= 1;
                    if let Some(l) = &frame.level {
                        l.again(&mut self.machine);
                    }
                    let time = frame.times - frame.left;
                    let note = format!(
                        "M99: {} again, time {time} of {}",
                        frame.callee.label, frame.times
                    );
                    (frame.entry, note)
                }
                Some(_) => {
                    let Some(frame) = calls.stack.pop() else {
                        return Step::Ran(Flow::Jump);
                    };
                    if let Some(l) = &frame.level {
                        l.leave(&mut self.machine);
                    }
                    let target = match to {
                        Some(n) => self.sequences.find_in(frame.caller.start, n),
                        None => Some(frame.back),
                    };
                    let Some(target) = target else {
                        return Step::Ran(Flow::Jump);
                    };
                    let note = match to {
                        Some(n) => format!(
                            "M99 P{n}: back to {} at N{n}, line {}",
                            frame.caller.label,
                            target.line()
                        ),
                        None => format!(
                            "M99: back to {}, line {}, after the call at {}",
                            frame.caller.label,
                            target.line(),
                            frame.site
                        ),
                    };
                    calls.current = frame.caller;
                    (target, note)
                }
                None => {
                    // M99 in the main program: back to its start, or to
                    // the sequence number P (behaviour 19.4).
                    calls.loops = calls.loops.saturating_add(1);
                    calls.loop_span = Some(self.block.span);
                    let target = match to {
                        Some(n) => self.sequences.find_in(None, n),
                        None => Some(self.sequences.main_start()),
                    };
                    let Some(target) = target else {
                        return Step::Ran(Flow::Jump);
                    };
                    let note = match to {
                        Some(n) => format!(
                            "M99 P{n} in the main program: on at N{n}, line {}",
                            target.line()
                        ),
                        None => format!(
                            "M99 in the main program: back to its start ({} time{})",
                            thousands(u64::from(calls.loops)),
                            if calls.loops == 1 { "" } else { "s" }
                        ),
                    };
                    (target, note)
                }
            },
        };
        self.sequences.depth = calls.stack.len();
        self.sequences.current = calls.current.start;
        self.sequences.caller = calls.stack.last().and_then(|f| f.caller.start);
        self.out.notes.push(note);
        if matches!(jump, Jump::Return { .. }) {
            // The loops of the program left are over (behaviour 20.15).
            self.leave_loops(from_depth);
        }
        self.read_at(target);
        Step::Ran(Flow::Jump)
    }

    /// The calls' record, made at the run's first jump (a call, a return
    /// or a macro statement's jump: behaviour 19, 20.11).
    pub(super) fn open_calls(&mut self) {
        if self.calls.is_none() {
            let label = match self.sequences.main_header(self.block.span.start as usize) {
                Some(h) => format!("O{:04}", h.number),
                None => "the main program".to_string(),
            };
            self.calls = Some(Box::new(Calls {
                main: None,
                current: Program { start: None, label },
                stack: Vec::new(),
                loops: 0,
                loop_span: None,
                called: Vec::new(),
            }));
        }
    }

    /// The run reads on at `target` in the program being read, in the
    /// context (units, canned cycle) the parser has now; once back where
    /// the first parser was set aside in the main program, that parser
    /// reads on. Needs [`Runner::open_calls`] first.
    pub(super) fn read_at(&mut self, target: Resume) {
        let Some(calls) = self.calls.as_deref_mut() else {
            return;
        };
        let context = self.parser.resume_point();
        let parser = self.sequences.parser_at(target.in_context(&context));
        let set_aside = std::mem::replace(&mut self.parser, parser);
        if calls.main.is_none() {
            calls.main = Some(set_aside);
        }
        // Back in the main program where the first parser stands: it reads
        // on (the fast path again, and its diagnostics in order).
        let home = calls.stack.is_empty()
            && calls.main.as_ref().is_some_and(|m| {
                m.offset() == target.offset() && m.resume_point().units() == context.units()
            });
        if home && let Some(main) = calls.main.take() {
            self.parser = main;
        }
    }

    /// The place of the block about to jump, for its report (kept only
    /// when the run keeps reports).
    pub(super) fn note_place(&mut self) {
        self.block_place = match (&self.calls, self.options.keep_blocks) {
            (Some(calls), true) => calls.place(),
            _ => None,
        };
    }

    /// The parser has read its last block: a subprogram's reading ended
    /// without M99, or the main program ended while another parser read
    /// it. The first parser reads the rest of the text for its
    /// diagnostics. None when the text is read.
    #[cold]
    #[inline(never)]
    pub(super) fn program_ends(&mut self) -> Option<Step> {
        let calls = self.calls.as_deref_mut()?;
        let main = calls.main.take()?;
        self.parser = main;
        let open = calls
            .stack
            .last()
            .map(|f| (f.callee.label.clone(), f.site.clone()));
        let was_running = !self.stopped;
        self.stopped = true;
        if let (true, Some((label, site))) = (was_running, open) {
            return Some(Step::Stopped(Some(Diagnostic::error(
                "missing-m99",
                self.block.span,
                format!(
                    "{label} (called at {site}) ends without M99: a subprogram returns with M99; the run stops here"
                ),
            ))));
        }
        Some(Step::Passed)
    }

    /// The main program's text ended: under linuxcnc a program that stops
    /// there without M2/M30 or a closing `%` is refused at its last block
    /// (rs274: "File ended with no percent sign or program end", behaviour
    /// 22.9); the Fanuc family stops at the end of the text.
    pub(super) fn text_ends(&mut self) -> Option<Step> {
        if self.stopped
            || self.machine.setup().settings.control != crate::setup::Control::Linuxcnc
            || self.parser.tape_ended()
        {
            return None;
        }
        self.stopped = true;
        Some(Step::Stopped(Some(Diagnostic::error(
            "no-program-end",
            self.block.span,
            "the program ends without M2, M30 or a closing %: LinuxCNC refuses it (\"File ended with no percent sign or program end\"); end it with M2",
        ))))
    }

    /// Where the block just run ran among the calls (its report's): the
    /// place before its jump for a call or return.
    pub(super) fn place_of(&mut self, flow: Flow) -> Option<Box<Place>> {
        match flow {
            Flow::Jump => self.block_place.take(),
            _ => self.calls.as_ref().and_then(|c| c.place()),
        }
    }

    /// M99s in the main program so far (behaviour 19.8).
    pub(super) fn main_loops(&self) -> u32 {
        self.calls.as_deref().map_or(0, |c| c.loops)
    }

    /// The block limit reached in a program that loops: the error at the
    /// M99 that made the loop, saying how often (behaviour 19.8).
    fn explain_limit(&self, d: &mut Diagnostic) {
        let Some(calls) = self.calls.as_deref() else {
            return;
        };
        if let (Some(span), true) = (calls.loop_span, calls.loops > 0) {
            d.message = format!(
                "M99 at line {} returned to the start {} times: the program never ends, and the run stops at its block limit ({} blocks, see the limits in the README)",
                span.line,
                thousands(u64::from(calls.loops)),
                thousands(self.options.max_blocks as u64)
            );
            d.span = span;
        } else if let Some(frame) = calls.stack.last() {
            d.message = format!(
                "the program runs more than {} blocks, in {} called at {} (see the limits in the README); the run stops here",
                thousands(self.options.max_blocks as u64),
                frame.callee.label,
                frame.site
            );
        }
    }
}

/// A call's block as the stack names it: its program and its sequence
/// number, or its line when it has none.
fn site(program: &str, block: &Block) -> String {
    match block.get(Address::N) {
        Some(n) => format!("{program} N{}", n.int()),
        None => format!("{program} line {}", block.span.line),
    }
}

impl Calls<'_> {
    /// Withdraws the `program-not-run` warning of each program the run
    /// called: it ran (behaviour 1.21).
    pub(super) fn withdraw_not_run(&self, diagnostics: &mut Vec<Diagnostic>) {
        if self.called.is_empty() {
            return;
        }
        diagnostics.retain(|d| !(d.code == "program-not-run" && self.called.contains(&d.line)));
    }
}
