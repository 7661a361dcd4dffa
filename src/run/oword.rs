//! LinuxCNC's o-words in a run (behaviour 22.7): subroutines (`sub`,
//! `endsub`, `call`, `return`), branches (`if`, `elseif`, `else`,
//! `endif`) and loops (`while`/`endwhile`, `do`/`while`, `repeat`/
//! `endrepeat`, `break`, `continue`).
//!
//! As with Custom Macro B's loops (`flow.rs`), where each o-word's partners
//! stand is read once per program, at its first o-word ([`Structure`]);
//! the run's own part — the calls open with the caller's parameters, the
//! repeats counting, the branch being tested — is [`State`], kept in the
//! checkpoints with the macro loops. Every jump is a [`Runner::read_at`].
//!
//! Source: LinuxCNC 2.9 documentation, "O Codes"; where it is silent, what
//! LinuxCNC's interpreter `rs274` does with the programs of
//! `tests/linuxcnc/` (the oracle, `scripts/oracle-linuxcnc.py`).

use std::collections::{BTreeMap, HashMap};

use super::Runner;
use super::macros::{Vars, options};
use crate::diag::{Diagnostic, Span};
use crate::macros::{Evaluator, Expr, OLabel, OOp, Statement, StatementKind, Value};
use crate::syntax::{Block, Blocks, Resume};

/// Deepest o-word call nesting (LinuxCNC: `INTERP_SUB_ROUTINE_LEVELS`).
const MAX_CALLS: usize = 10;
/// Parameters a call sets: #1–#30 are a sub's own (LinuxCNC, "O Codes",
/// "Subroutines").
const PARAMS: usize = 30;

/// What an o-word block is, as its program's structure reads it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    Sub,
    EndSub,
    Call,
    Return,
    If,
    ElseIf,
    Else,
    EndIf,
    While,
    EndWhile,
    Do,
    /// The `while` that closes a `do` of its label.
    DoWhile,
    Repeat,
    EndRepeat,
    Break,
    Continue,
}

impl Kind {
    fn of(op: &OOp) -> Kind {
        match op {
            OOp::Sub => Kind::Sub,
            OOp::EndSub(_) => Kind::EndSub,
            OOp::Call(_) => Kind::Call,
            OOp::Return(_) => Kind::Return,
            OOp::If(_) => Kind::If,
            OOp::ElseIf(_) => Kind::ElseIf,
            OOp::Else => Kind::Else,
            OOp::EndIf => Kind::EndIf,
            OOp::While(_) => Kind::While,
            OOp::EndWhile => Kind::EndWhile,
            OOp::Do => Kind::Do,
            OOp::Repeat(_) => Kind::Repeat,
            OOp::EndRepeat => Kind::EndRepeat,
            OOp::Break => Kind::Break,
            OOp::Continue => Kind::Continue,
        }
    }
}

/// One o-word block of a program.
#[derive(Clone, Debug)]
struct Entry {
    label: OLabel,
    kind: Kind,
    /// Where a parser reads the block itself, and the place after it.
    at: Resume,
    after: Resume,
    line: u32,
    /// The partner: a branch's next branch; a loop's or sub's closing
    /// block; a closing block's opening one; a `break`'s or `continue`'s
    /// loop; a `return`'s sub.
    link: Option<u32>,
    /// A branch's `endif`.
    end: Option<u32>,
}

/// Where a program's o-words and their partners stand.
#[derive(Default)]
pub(super) struct Structure {
    blocks: HashMap<u32, Entry>,
    /// Each sub's `sub` block, by label (the first of a label).
    subs: HashMap<OLabel, u32>,
    /// The program's last block: where a search forward that finds
    /// nothing ends (rs274 reports it there).
    last: Option<Span>,
}

impl Structure {
    /// Reads the program `parser` reads once.
    pub(super) fn of(mut parser: Blocks<'_>) -> Structure {
        let mut s = Structure::default();
        let mut block = Block::default();
        // The blocks opened and not yet closed, innermost last.
        let mut open: Vec<u32> = Vec::new();
        // Each open `if`'s last branch, and all its branches.
        let mut branches: HashMap<u32, Vec<u32>> = HashMap::new();
        loop {
            let at = parser.resume_point();
            if !parser.next_into(&mut block) {
                break;
            }
            s.last = Some(block.span);
            let Some(StatementKind::OWord(o)) = block
                .macros
                .as_ref()
                .and_then(|m| m.statement.as_ref())
                .map(|s| &s.kind)
            else {
                continue;
            };
            let offset = block.span.start;
            let mut kind = Kind::of(&o.op);
            let label = o.label.clone();
            // The innermost open block of this label whose kind is `k`.
            let find = |s: &Structure, open: &[u32], k: &[Kind]| {
                open.iter().rposition(|b| {
                    s.blocks
                        .get(b)
                        .is_some_and(|e| e.label == label && k.contains(&e.kind))
                })
            };
            let mut link = None;
            match kind {
                Kind::Sub => {
                    s.subs.entry(label.clone()).or_insert(offset);
                    open.push(offset);
                }
                Kind::If | Kind::Do | Kind::Repeat => open.push(offset),
                Kind::While => match open.last().and_then(|b| s.blocks.get(b)) {
                    Some(e) if e.label == label && e.kind == Kind::Do => {
                        kind = Kind::DoWhile;
                        link = open.pop();
                    }
                    _ => open.push(offset),
                },
                Kind::ElseIf | Kind::Else => {
                    if let Some(i) = find(&s, &open, &[Kind::If]) {
                        let list = branches.entry(open[i]).or_insert_with(|| vec![open[i]]);
                        if let Some(e) = list.last().and_then(|b| s.blocks.get_mut(b)) {
                            e.link = Some(offset);
                        }
                        list.push(offset);
                    }
                }
                Kind::EndIf | Kind::EndWhile | Kind::EndRepeat | Kind::EndSub => {
                    let opener = match kind {
                        Kind::EndIf => Kind::If,
                        Kind::EndWhile => Kind::While,
                        Kind::EndRepeat => Kind::Repeat,
                        _ => Kind::Sub,
                    };
                    if let Some(i) = find(&s, &open, &[opener]) {
                        let start = open[i];
                        open.truncate(i);
                        link = Some(start);
                        if kind == Kind::EndIf {
                            let list = branches.remove(&start).unwrap_or_else(|| vec![start]);
                            for b in &list {
                                if let Some(e) = s.blocks.get_mut(b) {
                                    e.end = Some(offset);
                                }
                            }
                            if let Some(e) = list.last().and_then(|b| s.blocks.get_mut(b)) {
                                e.link = Some(offset);
                            }
                        } else if let Some(e) = s.blocks.get_mut(&start) {
                            e.link = Some(offset);
                        }
                    }
                }
                // rs274: break and continue leave or go on with a while or
                // a do loop, never a repeat ("no matching while/do label").
                Kind::Break | Kind::Continue => {
                    link = find(&s, &open, &[Kind::While, Kind::Do]).map(|i| open[i]);
                }
                Kind::Return => {
                    link = open
                        .iter()
                        .rev()
                        .find(|b| s.blocks.get(b).is_some_and(|e| e.kind == Kind::Sub))
                        .copied();
                }
                Kind::Call | Kind::DoWhile => {}
            }
            s.blocks.insert(
                offset,
                Entry {
                    label: o.label.clone(),
                    kind,
                    at,
                    after: parser.resume_point(),
                    line: block.span.line,
                    link,
                    end: None,
                },
            );
            // A do's closing while points back; the do forward.
            if kind == Kind::DoWhile
                && let Some(e) = link.and_then(|d| s.blocks.get_mut(&d))
            {
                e.link = Some(offset);
            }
        }
        s
    }
}

/// An o-word call open: where it returns and what it keeps of its caller.
#[derive(Clone, Debug)]
struct Frame {
    /// The place after the `call` block.
    back: Resume,
    /// The caller's #1–#30 and named locals, given back at the return.
    saved: Box<[Value; PARAMS]>,
    named: BTreeMap<Box<str>, f64>,
    /// The call's line.
    line: u32,
}

/// The o-words' part of a run's state.
#[derive(Clone, Debug, Default)]
pub(crate) struct State {
    calls: Vec<Frame>,
    /// The repeats counting: the call depth, the `repeat` block, passes
    /// left with the one running (one entry per block and depth).
    repeats: Vec<(usize, u32, u64)>,
    /// The branch a condition that did not hold jumped to: it is tested,
    /// not fallen into.
    branch: Option<u32>,
    /// The subs defined so far: met in the program's flow, or found
    /// ahead by a call (rs274 then refuses to meet them again).
    defined: Vec<(OLabel, u32)>,
}

/// Where an o-word step leads.
enum To {
    On,
    /// Read on at this place.
    At(Resume),
}

impl<'t> Runner<'t> {
    /// The block just run is an o-word: the run reads on where it leads
    /// (behaviour 22.7), or stops at its error.
    pub(super) fn oword_step(&mut self) -> Result<(), Diagnostic> {
        let Some(m) = self.block.macros.clone() else {
            return Ok(());
        };
        let Some(statement) = &m.statement else {
            return Ok(());
        };
        let StatementKind::OWord(o) = &statement.kind else {
            return Ok(());
        };
        let text = |e: &Expr| m.text_of(e).into_owned();
        let start = self.block.span.start;
        let program = self.program_start();
        let key = program.offset();
        let loops = self.loops.get_or_insert_with(Box::default);
        let sequences = &self.sequences;
        let structure = loops
            .owords
            .entry(key)
            .or_insert_with(|| Structure::of(sequences.parser_at(program)));
        let Some(e) = structure.blocks.get(&start).cloned() else {
            return Err(error(
                statement.span,
                "this o-word is not where the program was read: the run stops here",
            ));
        };
        let label = &o.label;
        let entry = |b: Option<u32>| b.and_then(|b| structure.blocks.get(&b)).cloned();
        // The partners this block may lead to, read before the run's
        // state is touched.
        let link = entry(e.link);
        let end = entry(e.end);
        let close = link.as_ref().and_then(|h| entry(h.link));
        let sub = entry(structure.subs.get(label).copied());
        let last = structure.last;
        let depth = loops.o.calls.len();
        let mut state = std::mem::take(&mut loops.o);
        let (note, to) = match (&o.op, e.kind) {
            (OOp::Sub, _) => {
                if let Some(&(_, at)) = state.defined.iter().find(|d| d.0 == *label) {
                    let why = match at == start {
                        true => format!(
                            "a call found {label} sub ahead of the program's flow, which then meets it"
                        ),
                        false => format!("{label} sub is defined twice"),
                    };
                    return Err(error(
                        statement.span,
                        format!(
                            "{why}: LinuxCNC refuses a sub met after it was defined (\"found in illegal location\", \"redefining sub\"); define each sub once, before its first call"
                        ),
                    ));
                }
                let Some(end) = link else {
                    return Err(no_end(statement, label, "endsub", last));
                };
                state.defined.push((label.clone(), start));
                (
                    format!(
                        "{label} sub: the definition is read, not run; on after {label} endsub (line {})",
                        end.line
                    ),
                    To::At(end.after),
                )
            }
            (OOp::EndSub(v) | OOp::Return(v), _) => {
                let Some(frame) = state.calls.pop() else {
                    let what = o.op.keyword();
                    return Err(error(
                        statement.span,
                        format!(
                            "{label} {what} outside a call: a sub's end is reached only by calling it"
                        ),
                    ));
                };
                let value = match v {
                    Some(v) => Some(self.number(v)?),
                    None => None,
                };
                state.repeats.retain(|r| r.0 < depth);
                self.leave_call(&frame, value);
                let said = match value {
                    Some(v) => format!(", #<_value> = {}", Value::Number(v)),
                    None => String::new(),
                };
                (
                    format!(
                        "{label} {}: back to the call at line {}{said}",
                        o.op.keyword(),
                        frame.line
                    ),
                    To::At(frame.back),
                )
            }
            (OOp::Call(args), _) => {
                let found = state.defined.iter().find(|d| d.0 == *label).map(|d| d.1);
                let sub = match found {
                    Some(at) => entry(Some(at)),
                    None => sub.filter(|s| s.at.offset() > start as usize),
                };
                let Some(sub) = sub else {
                    return Err(error(
                        statement.span,
                        format!(
                            "{label} call: no {label} sub is defined before the call or after it in the program (rs274 looks to the file's end: \"EOF … seeking o-word\")"
                        ),
                    ));
                };
                if found.is_none() {
                    let at = sub.at.offset() as u32;
                    state.defined.push((label.clone(), at));
                }
                if depth >= MAX_CALLS {
                    return Err(error(
                        statement.span,
                        format!(
                            "{label} call: calls nest at most {MAX_CALLS} deep (LinuxCNC's limit)"
                        ),
                    ));
                }
                if args.len() > PARAMS {
                    return Err(error(
                        statement.span,
                        format!("{label} call: a call passes at most {PARAMS} arguments (#1–#30)"),
                    ));
                }
                let mut values = [Value::Number(0.0); PARAMS];
                for (v, a) in values.iter_mut().zip(args) {
                    *v = Value::Number(self.number(a)?);
                }
                let frame = self.enter_call(&values);
                let said: Vec<String> = values[..args.len()]
                    .iter()
                    .enumerate()
                    .map(|(k, v)| format!("#{} = {v}", k + 1))
                    .collect();
                state.calls.push(frame);
                let args = match said.is_empty() {
                    true => String::new(),
                    false => format!(" with {}", said.join(", ")),
                };
                (
                    format!("{label} call{args}: the sub of line {}", sub.line),
                    To::At(sub.after),
                )
            }
            (OOp::If(c), _) | (OOp::ElseIf(c), _) => {
                let tested = matches!(o.op, OOp::If(_)) || state.branch == Some(start);
                if !tested {
                    // A branch ran to here: on after the endif.
                    let end = end.ok_or_else(|| no_end(statement, label, "endif", last))?;
                    (
                        format!(
                            "{label} elseif: a branch before ran; on after {label} endif (line {})",
                            end.line
                        ),
                        To::At(end.after),
                    )
                } else {
                    state.branch = None;
                    let kw = o.op.keyword();
                    match self.condition(c)? {
                        true => (format!("{label} {kw} {} true", text(c)), To::On),
                        false => {
                            let next =
                                link.ok_or_else(|| no_end(statement, label, "endif", last))?;
                            state.branch = Some(e.link.unwrap_or_default());
                            (
                                format!(
                                    "{label} {kw} {} false: on at {label} {} (line {})",
                                    text(c),
                                    kind_word(next.kind),
                                    next.line
                                ),
                                To::At(next.at),
                            )
                        }
                    }
                }
            }
            (OOp::Else, _) => match state.branch == Some(start) {
                true => {
                    state.branch = None;
                    (format!("{label} else: no condition before held"), To::On)
                }
                false => {
                    let end = end.ok_or_else(|| no_end(statement, label, "endif", last))?;
                    (
                        format!(
                            "{label} else: a branch before ran; on after {label} endif (line {})",
                            end.line
                        ),
                        To::At(end.after),
                    )
                }
            },
            (OOp::EndIf, _) => {
                state.branch = None;
                (format!("{label} endif"), To::On)
            }
            (OOp::While(c), Kind::While) => match self.condition(c)? {
                true => (format!("{label} while {} true", text(c)), To::On),
                false => {
                    let end = link.ok_or_else(|| no_end(statement, label, "endwhile", last))?;
                    (
                        format!(
                            "{label} while {} false: on after {label} endwhile (line {})",
                            text(c),
                            end.line
                        ),
                        To::At(end.after),
                    )
                }
            },
            (OOp::While(c), _) => {
                let Some(head) = link else {
                    return Err(error(
                        statement.span,
                        format!("{label} while closes no {label} do"),
                    ));
                };
                match self.condition(c)? {
                    true => (
                        format!(
                            "{label} while {} true: back to {label} do (line {})",
                            text(c),
                            head.line
                        ),
                        To::At(head.after),
                    ),
                    false => (
                        format!("{label} while {} false: the do loop ends", text(c)),
                        To::On,
                    ),
                }
            }
            (OOp::EndWhile | OOp::EndRepeat, _) => {
                // Back to the opening block, read again: a while tests
                // its condition there, a repeat counts its pass.
                let opener = match o.op {
                    OOp::EndWhile => "while",
                    _ => "repeat",
                };
                let head = link.ok_or_else(|| no_opener(statement, label, opener))?;
                (
                    format!(
                        "{label} {}: back to {label} {opener} (line {})",
                        o.op.keyword(),
                        head.line
                    ),
                    To::At(head.at),
                )
            }
            (OOp::Do, _) => (format!("{label} do"), To::On),
            // rs274's repeat: its endrepeat reads the repeat block again,
            // which counts a pass while the count it stored runs; so a
            // `continue` of a loop around it goes on counting (the
            // oracle's l30_repeat_in_while_continue).
            (OOp::Repeat(n), _) => {
                let end = link.ok_or_else(|| no_end(statement, label, "endrepeat", last))?;
                let running = state
                    .repeats
                    .iter()
                    .position(|r| r.0 == depth && r.1 == start);
                match running {
                    Some(i) if state.repeats[i].2 > 1 => {
                        state.repeats[i].2 -= 1;
                        let left = state.repeats[i].2;
                        (
                            format!("{label} repeat: another pass, {left} left with this one"),
                            To::On,
                        )
                    }
                    Some(i) => {
                        state.repeats.remove(i);
                        (
                            format!(
                                "{label} repeat: the passes are done; on after {label} endrepeat (line {})",
                                end.line
                            ),
                            To::At(end.after),
                        )
                    }
                    None => {
                        // rs274 rounds the count half to even (2.5 runs twice).
                        let times = self.number(n)?.round_ties_even();
                        match times >= 1.0 {
                            true => {
                                state.repeats.push((
                                    depth,
                                    start,
                                    times.min(u64::MAX as f64) as u64,
                                ));
                                (
                                    format!(
                                        "{label} repeat {}: {} passes",
                                        text(n),
                                        Value::Number(times)
                                    ),
                                    To::On,
                                )
                            }
                            false => (
                                format!(
                                    "{label} repeat {}: no pass; on after {label} endrepeat (line {})",
                                    text(n),
                                    end.line
                                ),
                                To::At(end.after),
                            ),
                        }
                    }
                }
            }
            (OOp::Break | OOp::Continue, _) => {
                let Some(head) = link else {
                    return Err(error(
                        statement.span,
                        format!(
                            "{label} {}: no {label} while, do or repeat loop is open here",
                            o.op.keyword()
                        ),
                    ));
                };
                let close = close.ok_or_else(|| no_end(statement, label, "end", last))?;
                let is_break = matches!(o.op, OOp::Break);
                if is_break && head.kind == Kind::Repeat {
                    state
                        .repeats
                        .retain(|r| !(r.0 == depth && Some(r.1) == e.link));
                }
                let kw = o.op.keyword();
                match (is_break, head.kind) {
                    (true, _) => (
                        format!(
                            "{label} break: on after the loop's end (line {})",
                            close.line
                        ),
                        To::At(close.after),
                    ),
                    // Continue: the loop's test (a while's, a do's closing
                    // while) or its count (endrepeat) decides.
                    (false, Kind::While) => (
                        format!("{label} {kw}: back to {label} while (line {})", head.line),
                        To::At(head.at),
                    ),
                    (false, _) => (
                        format!("{label} {kw}: on at the loop's end (line {})", close.line),
                        To::At(close.at),
                    ),
                }
            }
        };
        let loops = self.loops.get_or_insert_with(Box::default);
        loops.o = state;
        self.out.notes.push(note);
        if let To::At(target) = to {
            self.open_calls();
            self.read_at(target);
        }
        Ok(())
    }

    fn number(&mut self, e: &Expr) -> Result<f64, Diagnostic> {
        let options = options(&self.machine);
        let mut vars = Vars {
            machine: &mut self.machine,
            out: &mut self.out,
            message: None,
        };
        Ok(Evaluator::new(&mut vars, options).value(e)?.number())
    }

    fn condition(&mut self, e: &Expr) -> Result<bool, Diagnostic> {
        let options = options(&self.machine);
        let mut vars = Vars {
            machine: &mut self.machine,
            out: &mut self.out,
            message: None,
        };
        Evaluator::new(&mut vars, options).condition(e)
    }

    /// A call: the caller's #1–#30 and named locals kept, the sub's set
    /// (its arguments, 0 for the others), one level deeper.
    fn enter_call(&mut self, values: &[Value; PARAMS]) -> Frame {
        let mut saved = Box::new([Value::Vacant; PARAMS]);
        for (k, v) in saved.iter_mut().enumerate() {
            *v = self.machine.variables.get(k as u32 + 1).unwrap_or_default();
            self.machine.variables.set(k as u32 + 1, values[k]);
        }
        let m = self.machine.macro_calls_mut();
        let named = std::mem::take(&mut m.named.locals);
        m.level = m.level.saturating_add(1);
        Frame {
            back: self.parser.resume_point(),
            saved,
            named,
            line: self.block.span.line,
        }
    }

    /// A return: the caller's parameters back, and the value returned
    /// (LinuxCNC: `#<_value>`, and `#<_value_returned>` 1 or 0).
    fn leave_call(&mut self, frame: &Frame, value: Option<f64>) {
        for (k, v) in frame.saved.iter().enumerate() {
            self.machine.variables.set(k as u32 + 1, *v);
        }
        let m = self.machine.macro_calls_mut();
        m.named.locals = frame.named.clone();
        m.level = m.level.saturating_sub(1);
        let globals = &mut m.named.globals;
        // rs274: a return without a value sets both to 0.
        globals.insert(
            "_value_returned".into(),
            f64::from(u8::from(value.is_some())),
        );
        globals.insert("_value".into(), value.unwrap_or(0.0));
    }
}

fn kind_word(k: Kind) -> &'static str {
    match k {
        Kind::ElseIf => "elseif",
        Kind::Else => "else",
        Kind::EndIf => "endif",
        _ => "the next branch",
    }
}

fn error(span: Span, message: impl Into<String>) -> Diagnostic {
    Diagnostic::error("oword", span, message.into())
}

/// A search forward for `end` that reached the program's end: rs274
/// reports it at the last line, where the file ends without the block it
/// sought.
fn no_end(s: &Statement, label: &OLabel, end: &str, last: Option<Span>) -> Diagnostic {
    error(
        last.unwrap_or(s.span),
        format!(
            "{label} of line {} has no {label} {end} after it: the reading went to the file's end looking for it (rs274: \"File ended with no percent sign or program end\")",
            s.span.line
        ),
    )
}

fn no_opener(s: &Statement, label: &OLabel, opener: &str) -> Diagnostic {
    error(s.span, format!("{label} closes no {label} {opener}"))
}
