//! Custom Macro B's jumps and loops in a run (behaviour 20.11–20.16):
//! where GOTO, IF … GOTO, WHILE … DO, DO and END lead, the loops running,
//! and the program's own alarm and message stop (`#3000`, `#3006`).
//!
//! A jump moves the reading with the subprograms' machinery
//! ([`Runner::read_at`] in `calls.rs`). Where a program's sequence numbers
//! and its DO … END ranges stand is read once per program, at its first
//! jump or loop ([`Structure`]), so a loop's thousandth pass searches
//! nothing. The loops running are the run's state and go into checkpoints
//! ([`Saved`]); the structures are made again from the text.
//!
//! The rules are the Fanuc 0i-MF/0i-TF operator's manuals' ("Custom
//! macro", "Branch and repetition"): the alarms those of the Fanuc alarm
//! list (PS0124 MISSING END STATEMENT, PS0126 ILLEGAL LOOP NUMBER, PS0128
//! ILLEGAL MACRO SEQUENCE NUMBER).

use std::collections::HashMap;

use super::{Runner, Step};
use crate::diag::{Diagnostic, Span, thousands};
use crate::machine::calls::MacroJump;
use crate::machine::{EventKind, Flow, Out};
use crate::macros::{Statement, StatementKind, Value, alarm};
use crate::syntax::{Address, Block, MacroBlock, Resume};

/// `#3000 = n (MESSAGE)`: the program's own alarm (behaviour 20.16).
pub(super) const ALARM: u32 = 3000;
/// `#3006 = 1 (MESSAGE)`: a stop with a message (behaviour 20.16).
pub(super) const MESSAGE_STOP: u32 = 3006;

/// The loops running and the jumps back, once the run has met a jump or
/// a loop.
#[derive(Default)]
pub(crate) struct Loops {
    /// The loops running, outermost first (those of callers first).
    open: Vec<Open>,
    /// GOTOs that jumped back (to a block before their own), and the last.
    back: u32,
    back_span: Option<Span>,
    /// Per program (by the byte offset of its start), its structure.
    programs: HashMap<usize, Structure>,
    /// LinuxCNC's o-words running (behaviour 22.7).
    pub(super) o: super::oword::State,
    /// Per program, where its o-words stand.
    pub(super) owords: HashMap<usize, super::oword::Structure>,
}

/// What a checkpoint keeps of the loops (the structures aside).
#[derive(Clone, Debug)]
pub(crate) struct Saved {
    open: Vec<Open>,
    back: u32,
    back_span: Option<Span>,
    o: super::oword::State,
}

/// A loop running.
#[derive(Clone, Debug)]
struct Open {
    /// m of DO m.
    label: u8,
    /// Where its WHILE (or DO) block is read again at its END.
    at: Resume,
    /// That block's byte offset and its statement.
    start: u32,
    span: Span,
    /// WHILE … DO, or DO alone.
    condition: bool,
    /// The subprogram depth and the program it runs in.
    level: usize,
    program: usize,
    /// Passes begun.
    passes: u32,
    /// The run's block index at its WHILE the first time.
    since: u32,
}

/// Where a program's sequence numbers and loops stand.
#[derive(Default)]
struct Structure {
    /// Per sequence number, its blocks in order: byte offset, line, and
    /// where a parser reads it.
    numbers: HashMap<u32, Vec<(u32, u32, Resume)>>,
    /// Each WHILE … DO or DO block, by its byte offset.
    ranges: HashMap<u32, Range>,
}

/// A DO … END range as written.
#[derive(Clone, Copy)]
struct Range {
    label: u8,
    /// Where a parser reads its WHILE or DO block.
    at: Resume,
    start: u32,
    line: u32,
    /// Its END m: the block's byte offset, its line and the place after.
    end: Option<(u32, u32, Resume)>,
    /// That END came while a loop opened inside this one was not closed:
    /// the inner loop's number and line.
    overlap: Option<(u8, u32)>,
}

impl Range {
    /// True when the block at byte `at` is inside the range (its END
    /// included, its DO not: a jump to the DO enters the loop from its
    /// start).
    fn holds(&self, at: u32) -> bool {
        self.start < at && self.end.is_none_or(|(end, _, _)| at <= end)
    }
}

impl Structure {
    /// Reads the program that starts at `start` once, as `parser` reads it.
    fn of(mut parser: crate::syntax::Blocks<'_>) -> Structure {
        let mut s = Structure::default();
        let mut block = Block::default();
        // The ranges open at the parser's place, innermost last.
        let mut open: Vec<u32> = Vec::new();
        loop {
            let before = parser.resume_point();
            if !parser.next_into(&mut block) {
                break;
            }
            if block.error {
                continue;
            }
            let (start, line) = (block.span.start, block.span.line);
            if let Some(n) = block.get(Address::N) {
                s.numbers
                    .entry(n.int())
                    .or_default()
                    .push((start, line, before));
            }
            let Some(statement) = block.macros.as_ref().and_then(|m| m.statement.as_ref()) else {
                continue;
            };
            match statement.kind {
                StatementKind::While(_, label) | StatementKind::Do(label) => {
                    s.ranges.insert(
                        start,
                        Range {
                            label,
                            at: before,
                            start,
                            line,
                            end: None,
                            overlap: None,
                        },
                    );
                    open.push(start);
                }
                StatementKind::End(label) => {
                    // END m closes the innermost open DO m (the manual's
                    // nesting); one opened inside it and still open makes
                    // the two overlap.
                    let found = open
                        .iter()
                        .rposition(|k| s.ranges.get(k).is_some_and(|r| r.label == label));
                    if let Some(i) = found {
                        let key = open.remove(i);
                        let inner = open.get(i).and_then(|k| s.ranges.get(k).copied());
                        if let Some(r) = s.ranges.get_mut(&key) {
                            r.end = Some((start, line, parser.resume_point()));
                            r.overlap = inner.map(|inner| (inner.label, inner.line));
                        }
                    }
                }
                _ => {}
            }
        }
        s
    }
}

impl Loops {
    pub(super) fn save(&self) -> Saved {
        Saved {
            open: self.open.clone(),
            back: self.back,
            back_span: self.back_span,
            o: self.o.clone(),
        }
    }
}

impl Saved {
    pub(super) fn restore(&self) -> Box<Loops> {
        Box::new(Loops {
            open: self.open.clone(),
            back: self.back,
            back_span: self.back_span,
            programs: HashMap::new(),
            o: self.o.clone(),
            owords: HashMap::new(),
        })
    }
}

/// The statement's keyword for a loop's messages.
fn keyword(condition: bool, label: u8) -> String {
    match condition {
        true => "WHILE".to_string(),
        false => format!("DO {label}"),
    }
}

impl<'t> Runner<'t> {
    /// Where the program being read starts (the text's start for the main
    /// program): the key of its structures.
    pub(super) fn program_start(&self) -> Resume {
        self.sequences
            .current
            .unwrap_or_else(|| self.sequences.main_start())
    }

    /// The block just run is a macro statement that jumps or loops: the
    /// run reads on where it leads, or stops at its alarm (the block then
    /// counts as not run, as a block whose alarm comes before it runs).
    #[cold]
    #[inline(never)]
    pub(super) fn macro_flow(&mut self, step: MacroJump) -> Step {
        self.note_place();
        let result = match step {
            MacroJump::OWord => self.oword_step(),
            step => self.flow_step(step),
        };
        match result {
            Ok(()) => Step::Ran(Flow::Jump),
            Err(d) => {
                self.index = self.index.saturating_sub(1);
                self.block_place = None;
                self.stopped = true;
                Step::Stopped(Some(d))
            }
        }
    }

    fn flow_step(&mut self, step: MacroJump) -> Result<(), Diagnostic> {
        let Some(m) = self.block.macros.as_deref() else {
            return Ok(());
        };
        let Some(statement) = m.statement.clone() else {
            return Ok(());
        };
        let start = self.block.span.start;
        let depth = self.sequences.depth;
        let program = self.program_start();
        let key = program.offset();
        let loops = self.loops.get_or_insert_with(Box::default);
        // The loops of programs returned from are over (behaviour 20.15).
        loops
            .open
            .retain(|o| o.level < depth || (o.level == depth && o.program == key));
        let sequences = &self.sequences;
        let structure = loops
            .programs
            .entry(key)
            .or_insert_with(|| Structure::of(sequences.parser_at(program)));
        let ours = |o: &Open| o.level == depth && o.program == key;
        let (note, target) = match step {
            MacroJump::Goto(n) => {
                let Some(places) = structure.numbers.get(&n) else {
                    return Err(not_found(&statement, m, n));
                };
                // Forward from the GOTO to the program's end, then from its
                // start (the Fanuc manual: a jump back searches longer).
                let after = self.parser.offset();
                let &(to, to_line, at) = places
                    .iter()
                    .find(|p| p.2.offset() >= after)
                    .or(places.first())
                    .ok_or_else(|| not_found(&statement, m, n))?;
                // A jump may leave loops, never enter one (the manual:
                // "branching into a loop is not allowed").
                let inside: Vec<&Range> =
                    structure.ranges.values().filter(|r| r.holds(to)).collect();
                if let Some(r) = inside
                    .iter()
                    .find(|r| !loops.open.iter().any(|o| ours(o) && o.start == r.start))
                {
                    return Err(alarm::LOOP_NUMBER.at(
                        statement.span,
                        format!(
                            "GOTO {n} leads into the loop DO {} of line {}, which is not running: a jump may leave a loop, never enter one",
                            r.label, r.line
                        ),
                    ));
                }
                loops
                    .open
                    .retain(|o| !ours(o) || inside.iter().any(|r| r.start == o.start));
                if to <= start {
                    loops.back = loops.back.saturating_add(1);
                    loops.back_span = Some(statement.span);
                }
                let note = match &statement.kind {
                    StatementKind::IfGoto(c, _) => {
                        format!("IF {} true: GOTO {n}, line {to_line}", m.text_of(c))
                    }
                    _ => format!("GOTO {n}: on at N{n}, line {to_line}"),
                };
                (note, Some(at))
            }
            MacroJump::While { holds: true, label } | MacroJump::Do(label) => {
                let condition = matches!(step, MacroJump::While { .. });
                let range = find_range(structure, start, &statement)?;
                let Some(_) = range.end else {
                    return Err(missing_end(&statement, condition, label));
                };
                let head = match &statement.kind {
                    StatementKind::While(c, _) => {
                        format!("WHILE {} true: DO {label}", m.text_of(c))
                    }
                    _ => format!("DO {label}: a loop without a condition"),
                };
                let note = match loops.open.last_mut() {
                    Some(o) if ours(o) && o.start == start => {
                        o.passes = o.passes.saturating_add(1);
                        format!("{head}, pass {}", o.passes)
                    }
                    _ => {
                        if let Some(o) = loops.open.iter().find(|o| ours(o) && o.label == label) {
                            return Err(alarm::LOOP_NUMBER.at(
                                statement.span,
                                format!(
                                    "DO {label} opens while the DO {label} of line {} is running: nested loops take different numbers (1, 2, 3)",
                                    o.span.line
                                ),
                            ));
                        }
                        loops.open.push(Open {
                            label,
                            at: range.at,
                            start,
                            span: statement.span,
                            condition,
                            level: depth,
                            program: key,
                            passes: 1,
                            since: self.index.saturating_sub(1),
                        });
                        head
                    }
                };
                (note, None)
            }
            MacroJump::While {
                holds: false,
                label,
            } => {
                let range = find_range(structure, start, &statement)?;
                let Some((_, end_line, after)) = range.end else {
                    return Err(missing_end(&statement, true, label));
                };
                if let Some((inner, inner_line)) = range.overlap {
                    return Err(alarm::LOOP_NUMBER.at(
                        statement.span,
                        format!(
                            "the END {label} of line {end_line} closes this loop while the DO {inner} of line {inner_line} inside it is open: loops nest, they never overlap"
                        ),
                    ));
                }
                if let Some(i) = loops.open.iter().position(|o| ours(o) && o.start == start) {
                    loops.open.truncate(i);
                }
                let c = match &statement.kind {
                    StatementKind::While(c, _) => m.text_of(c),
                    _ => "".into(),
                };
                let note = format!("WHILE {c} false: on after END {label} (line {end_line})");
                (note, Some(after))
            }
            MacroJump::OWord => return Ok(()),
            MacroJump::End(label) => match loops.open.last() {
                Some(o) if ours(o) && o.label == label => {
                    let what = match o.condition {
                        true => "WHILE".to_string(),
                        false => format!("DO {label}"),
                    };
                    let note = format!(
                        "END {label}: back to {what} at line {}, pass {}",
                        o.span.line,
                        o.passes.saturating_add(1)
                    );
                    (note, Some(o.at))
                }
                top => {
                    let message = match loops.open.iter().find(|o| ours(o) && o.label == label) {
                        Some(o) => format!(
                            "END {label} closes the DO {label} of line {} while the DO {} of line {} inside it is running: loops nest, they never overlap",
                            o.span.line,
                            top.map_or(0, |t| t.label),
                            top.map_or(0, |t| t.span.line)
                        ),
                        // No line in the sentence: the diagnostic has the
                        // END's (a run resumed after an edit renumbers
                        // diagnostics, not their text).
                        None => format!(
                            "END {label} has no DO {label} running: an END closes the loop its DO opened"
                        ),
                    };
                    return Err(alarm::LOOP_NUMBER.at(statement.span, message));
                }
            },
        };
        self.out.notes.push(note);
        if let Some(target) = target {
            self.open_calls();
            self.read_at(target);
        }
        Ok(())
    }

    /// The block limit reached in a loop that never ends: the error at
    /// the loop's WHILE or DO, or at the GOTO that jumped back (behaviour
    /// 20.15). False when no such loop ran.
    pub(super) fn explain_loop_limit(&self, d: &mut Diagnostic) -> bool {
        let Some(loops) = self.loops.as_deref() else {
            return false;
        };
        let limit = thousands(self.options.max_blocks as u64);
        if let Some(o) = loops.open.first() {
            d.message = format!(
                "{} at line {} ran {} blocks without ending ({} passes): the run stops at its block limit ({limit} blocks, see the limits in the README)",
                keyword(o.condition, o.label),
                o.span.line,
                thousands(u64::from(self.index.saturating_sub(o.since))),
                thousands(u64::from(o.passes))
            );
            d.span = o.span;
            return true;
        }
        match loops.back_span {
            Some(span) if loops.back > 0 && self.main_loops() == 0 => {
                d.message = format!(
                    "GOTO at line {} jumped back {} times: the program never ends, and the run stops at its block limit ({limit} blocks, see the limits in the README)",
                    span.line,
                    thousands(u64::from(loops.back))
                );
                d.span = span;
                true
            }
            _ => false,
        }
    }
}

/// The range of the WHILE or DO block at byte `start`.
fn find_range(s: &Structure, start: u32, statement: &Statement) -> Result<Range, Diagnostic> {
    s.ranges.get(&start).copied().ok_or_else(|| {
        alarm::STATEMENT.at(
            statement.span,
            "this loop's block is not where the program was read: the run stops here",
        )
    })
}

/// PS0128: no block has the sequence number.
fn not_found(statement: &Statement, m: &MacroBlock, n: u32) -> Diagnostic {
    let span = match &statement.kind {
        StatementKind::Goto(e) | StatementKind::IfGoto(_, e) => e.span,
        _ => statement.span,
    };
    alarm::SEQUENCE.at(
        span,
        format!(
            "{}: no block N{n} in this program (searched from here to its end, then from its start)",
            m.text_of_statement(statement)
        ),
    )
}

/// PS0124: a loop without its END.
fn missing_end(statement: &Statement, condition: bool, label: u8) -> Diagnostic {
    let what = match condition {
        true => format!("WHILE … DO {label}"),
        false => format!("DO {label}"),
    };
    alarm::MISSING_END.at(
        statement.span,
        format!("{what} has no END {label} after it in this program"),
    )
}

/// A read of `#3000` or `#3006`, which are only written.
pub(super) fn write_only(n: u32, span: Span) -> Diagnostic {
    let what = match n {
        ALARM => "writing it raises the program's alarm",
        _ => "writing it stops the program with a message",
    };
    Diagnostic::error(
        "macro-system-variable",
        span,
        format!("#{n} is only written ({what}): it has no value to read"),
    )
}

/// `#3000 = n (MESSAGE)`: the run stops with alarm 3000 + n; `#3006 = 1
/// (MESSAGE)`: the control stops with the message until cycle start, and
/// the run goes on (behaviour 20.16).
pub(super) fn message(
    n: u32,
    v: Value,
    s: &Statement,
    m: &MacroBlock,
    out: &mut Out,
) -> Result<(), Diagnostic> {
    let text = m.comment().unwrap_or("");
    // The assignment's own place, after THEN when there is one.
    let span = match &s.kind {
        StatementKind::IfThen(_, then) => then.span,
        _ => s.span,
    };
    if n == ALARM {
        let number = v.number().round();
        if !(0.0..=f64::from(u32::MAX - ALARM)).contains(&number) {
            return Err(alarm::ARGUMENT.at(
                span,
                format!("#3000 = {number}: the alarm number is 0 or more"),
            ));
        }
        let shown = match text {
            "" => "(no message)".to_string(),
            t => t.to_string(),
        };
        return Err(Diagnostic::error(
            "macro-alarm",
            span,
            format!("alarm {}: {shown}", ALARM + number as u32),
        ));
    }
    out.events.push(EventKind::ProgramStop);
    out.notes.push(format!(
        "#3006 = {v}: the control stops with the message \"{text}\" and waits for cycle start; the run goes on"
    ));
    Ok(())
}

impl Runner<'_> {
    /// The loops of the program left at subprogram depth `depth` and
    /// below it are over (an M99 returns out of them, behaviour 20.15).
    pub(super) fn leave_loops(&mut self, depth: usize) {
        if let Some(loops) = self.loops.as_deref_mut() {
            loops.open.retain(|o| o.level < depth);
        }
    }
}
