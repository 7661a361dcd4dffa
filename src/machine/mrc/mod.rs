//! The lathe's multiple repetitive cycles G70–G76 (behaviour 15), after the
//! Fanuc 0i-TF / 30i-B operator's manuals (B-64604EN-1 and B-64484EN-1,
//! "Multiple repetitive cycle (G70–G76)") and the Haas lathe operator's
//! manual (G70–G76). This file reads each cycle's words in the forms real
//! programs write — Fanuc's two blocks (`G71 U… R…;` `G71 P… Q… U… W… F…;`)
//! and the one block of the Fanuc Series 10/11 format and Haas (`G71 P… Q…
//! U… W… D… F…`) — keeps the data the first blocks set (they are parameters
//! on the control, modal until set again), and passes over the contour
//! blocks a G71–G73 has cut. The contour is read in `contour.rs`, the
//! roughing and finishing passes are `rough.rs`, the peck cycles `peck.rs`
//! and threading `thread.rs`.

mod contour;
mod nose;
mod peck;
mod rough;
mod thread;

use super::program::ProgramText;
use super::{Machine, MoveKind, Out};
use crate::diag::Diagnostic;
use crate::geometry::show;
use crate::setup::FinishingExtraWords;
use crate::syntax::codes::{Code, CodeTable, NonModal, Repetitive};
use crate::syntax::{Address, Block};

pub(super) use thread::ThreadData;

/// Most passes (levels, repetitions, threading cuts) one cycle makes, and
/// most pecks of one G74/G75: past this the block is `mrc-passes`, never a
/// hang (behaviour 15.14).
pub(super) const MAX_PASSES: usize = 10_000;

/// +1, −1, or 0 within a ten-millionth of a millimetre (`f64::signum` is
/// 1 for a zero).
pub(super) fn sign(v: f64) -> f64 {
    if v > 1e-7 {
        1.0
    } else if v < -1e-7 {
        -1.0
    } else {
        0.0
    }
}

/// What the G70–G76 first blocks set, kept until set again (Fanuc keeps
/// them in parameters 5132–5143), and the contour passed over after a
/// G71–G73 (behaviour 15.4, 15.5).
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct MrcData {
    /// G71/G72 depth of cut Δd (mm; a radius value in G71) and escape e
    /// (Fanuc parameters 5132, 5133).
    rough_depth: Option<f64>,
    rough_retract: Option<f64>,
    /// G73 escape Δi (X, a radius value, mm), Δk (Z, mm) and the number
    /// of divisions d (parameters 5135–5137).
    pattern: Option<(f64, f64, u32)>,
    /// G74/G75 return amount e (parameter 5139).
    peck_return: Option<f64>,
    /// G76 finishing count m, chamfer r, angle a, minimum depth Δdmin and
    /// finishing allowance d (parameters 5142, 5130, 5143, 5140, 5141).
    thread: Option<ThreadData>,
    /// After a G71–G73 whose contour follows it: the blocks up to the one
    /// with sequence number Q are passed over (behaviour 15.5).
    skip: Option<Skip>,
}

/// The contour a G71–G73 ran, passed over by the run after it.
#[derive(Clone, Copy, Debug)]
struct Skip {
    cycle: Repetitive,
    /// The cycle block's line.
    line: u32,
    p: u32,
    q: u32,
}

impl Machine {
    /// True while the blocks of a G71–G73 contour are passed over.
    #[inline(always)]
    pub(super) fn passing_over(&self) -> bool {
        self.mrc.skip.is_some()
    }

    /// A block after a G71–G73 up to its contour's last block: not run, with
    /// a sentence saying why (behaviour 15.5: Fanuc goes on after the block
    /// with sequence number Q).
    pub(super) fn pass_over(&mut self, b: &Block, out: &mut Out) {
        let Some(s) = self.mrc.skip else { return };
        let n = b.get(Address::N).map(|w| w.int());
        out.notes.push(format!(
            "not run: the {} at line {} cut the contour N{}–N{} from here, and the run goes on after N{} (behaviour 15.5)",
            self.code_name(s.cycle),
            s.line,
            s.p,
            s.q,
            s.q
        ));
        if n == Some(s.q) {
            self.mrc.skip = None;
        }
    }

    /// The cycle's G code as this program writes it.
    pub(super) fn code_name(&self, cycle: Repetitive) -> &'static str {
        let code = Code::NonModal(NonModal::Repetitive(cycle));
        code.gcode(CodeTable::of(&self.setup))
    }

    /// A block with G70–G76 (behaviour 15).
    pub(super) fn repetitive(
        &mut self,
        b: &Block,
        cycle: Repetitive,
        out: &mut Out,
        program: &mut dyn ProgramText,
    ) -> Result<(), Diagnostic> {
        let axes = [Address::X, Address::U, Address::Z, Address::W]
            .iter()
            .any(|a| b.has(*a));
        let pq = b.has(Address::P) || b.has(Address::Q);
        match cycle {
            Repetitive::Finishing => {
                self.finishing_words(b, cycle, out)?;
                let (p, q) = self.sequence_numbers(b, cycle)?;
                self.t_for_cycle(b, out);
                self.finishing(b, p, q, out, program)
            }
            Repetitive::TurningStock | Repetitive::FacingStock if !pq && !b.has(Address::D) => {
                let depth = if cycle == Repetitive::TurningStock {
                    Address::U
                } else {
                    Address::W
                };
                self.words(b, cycle, &[depth, Address::R])?;
                // A T code is taken in every cycle block (behaviour 2.22).
                self.t_for_cycle(b, out);
                self.rough_first_block(b, cycle, depth, out)
            }
            Repetitive::TurningStock | Repetitive::FacingStock => {
                self.words(
                    b,
                    cycle,
                    &[Address::P, Address::Q, Address::U, Address::W, Address::D],
                )?;
                let (p, q) = self.sequence_numbers(b, cycle)?;
                self.t_for_cycle(b, out);
                self.stock_removal(b, cycle, p, q, out, program)
            }
            Repetitive::PatternRepeat if !pq => {
                self.words(b, cycle, &[Address::U, Address::W, Address::R])?;
                self.t_for_cycle(b, out);
                self.pattern_first_block(b, out)
            }
            Repetitive::PatternRepeat => {
                self.words(
                    b,
                    cycle,
                    &[
                        Address::P,
                        Address::Q,
                        Address::U,
                        Address::W,
                        Address::I,
                        Address::K,
                        Address::D,
                    ],
                )?;
                let (p, q) = self.sequence_numbers(b, cycle)?;
                self.t_for_cycle(b, out);
                self.pattern_repeat(b, p, q, out, program)
            }
            Repetitive::FacePeck | Repetitive::DiameterPeck if !axes => {
                self.words(b, cycle, &[Address::R])?;
                let e = self.length(b, Address::R).unwrap_or(0.0);
                if e < 0.0 {
                    return Err(self.mrc_error(
                        b,
                        "mrc-value",
                        "PS0062",
                        cycle,
                        "the return amount R(e) is not negative".into(),
                    ));
                }
                self.mrc.peck_return = Some(e);
                self.t_for_cycle(b, out);
                out.notes.push(format!(
                    "{}: return amount e = {} kept for the next {} (behaviour 15.10)",
                    self.code_name(cycle),
                    show(e, self.units()),
                    self.code_name(cycle)
                ));
                Ok(())
            }
            Repetitive::FacePeck | Repetitive::DiameterPeck => {
                self.words(
                    b,
                    cycle,
                    &[
                        Address::X,
                        Address::U,
                        Address::Z,
                        Address::W,
                        Address::P,
                        Address::Q,
                        Address::R,
                        Address::I,
                        Address::K,
                        Address::D,
                    ],
                )?;
                self.t_for_cycle(b, out);
                self.peck(b, cycle, out)
            }
            Repetitive::Threading if !axes => {
                self.words(b, cycle, &[Address::P, Address::Q, Address::R])?;
                self.t_for_cycle(b, out);
                self.thread_first_block(b, out)
            }
            Repetitive::Threading => {
                self.words(
                    b,
                    cycle,
                    &[
                        Address::X,
                        Address::U,
                        Address::Z,
                        Address::W,
                        Address::R,
                        Address::P,
                        Address::Q,
                        Address::I,
                        Address::K,
                        Address::D,
                        Address::A,
                    ],
                )?;
                self.t_for_cycle(b, out);
                self.threading(b, out)
            }
        }
    }

    /// Refuses a word the cycle does not read (never a silent skip): every
    /// cycle block may carry N, G, M, F, S and T besides `words`.
    fn words(&self, b: &Block, cycle: Repetitive, words: &[Address]) -> Result<(), Diagnostic> {
        const ALWAYS: [Address; 6] = [
            Address::N,
            Address::G,
            Address::M,
            Address::F,
            Address::S,
            Address::T,
        ];
        for w in &b.words {
            if !ALWAYS.contains(&w.address) && !words.contains(&w.address) {
                let list: Vec<String> = words.iter().map(|a| a.letter().to_string()).collect();
                return Err(self.error(
                    "mrc-word",
                    w.span,
                    format!(
                        "{} in this form reads {} (and F, S, T): {} is not one of its words (Fanuc PS0066, an unavailable command in the cycle block)",
                        self.code_name(cycle),
                        list.join(" "),
                        w.address.letter()
                    ),
                ));
            }
        }
        Ok(())
    }

    /// The words of a G70 block: P and Q, and the roughing cycle's words
    /// (U W D I K R, copied from the G71/G72 line above) passed over with a
    /// warning where the profile says so (behaviour 15.22: Haas).
    fn finishing_words(
        &self,
        b: &Block,
        cycle: Repetitive,
        out: &mut Out,
    ) -> Result<(), Diagnostic> {
        const ROUGHING: [Address; 6] = [
            Address::U,
            Address::W,
            Address::D,
            Address::I,
            Address::K,
            Address::R,
        ];
        if self.setup.settings.finishing_extra_words() == FinishingExtraWords::Error {
            return self.words(b, cycle, &[Address::P, Address::Q]);
        }
        let mut allowed = vec![Address::P, Address::Q];
        allowed.extend(ROUGHING);
        self.words(b, cycle, &allowed)?;
        let extra: Vec<&crate::syntax::Word> = b
            .words
            .iter()
            .filter(|w| ROUGHING.contains(&w.address))
            .collect();
        if let (Some(first), Some(last)) = (extra.first(), extra.last()) {
            let letters: Vec<String> = extra
                .iter()
                .map(|w| w.address.letter().to_string())
                .collect();
            let mut span = first.span;
            span.end = last.span.end;
            out.warnings.push(Diagnostic::warning(
                "mrc-ignored-word",
                span,
                format!(
                    "{}: {} {} the roughing cycle's (finishing allowance, depth, rough allowance); the finishing pass cuts the contour itself, so {} passed over (setting finishing_extra_words: warn, the Haas rule)",
                    self.code_name(cycle),
                    letters.join(" "),
                    if extra.len() == 1 { "is" } else { "are" },
                    if extra.len() == 1 { "it is" } else { "they are" },
                ),
            ));
        }
        Ok(())
    }

    /// P and Q of a G70–G73: the contour's first and last sequence numbers
    /// (Fanuc PS0061 when one is missing).
    fn sequence_numbers(&self, b: &Block, cycle: Repetitive) -> Result<(u32, u32), Diagnostic> {
        match (b.get(Address::P), b.get(Address::Q)) {
            (Some(p), Some(q)) => Ok((p.int(), q.int())),
            (p, _) => {
                let missing = if p.is_none() { 'P' } else { 'Q' };
                Err(self.mrc_error(
                    b,
                    "mrc-sequence",
                    "PS0061",
                    cycle,
                    format!(
                        "{missing} is missing: the cycle needs P and Q, the sequence numbers of the contour's first and last blocks"
                    ),
                ))
            }
        }
    }

    /// A T word in the cycle block: the offset applies from the cycle's
    /// first move (behaviour 15.13, as in the single cycles).
    fn t_for_cycle(&mut self, b: &Block, out: &mut Out) {
        if self.t_code(b, out) {
            out.notes.push(format!(
                "the new offset applies from the cycle's first move: X {} Z {}",
                show(self.state.lathe.target[0], self.units()),
                show(self.state.lathe.target[2], self.units())
            ));
        }
    }

    /// A length word in program units, in mm.
    fn length(&self, b: &Block, a: Address) -> Option<f64> {
        b.value(a).map(|v| self.mm(v))
    }

    /// A word written in least input increments without a decimal point
    /// (G74–G76's P and Q, behaviour 15.2), in mm.
    fn increments(&self, b: &Block, a: Address) -> Option<f64> {
        b.value(a).map(|v| self.mm(v * self.units().increment()))
    }

    /// D as a length (behaviour 7.24): a dimension word, or least input
    /// increments, as setting `depth_word` reads it.
    fn depth_word(&self, b: &Block) -> Option<f64> {
        match self.setup.settings.depth_word() {
            crate::setup::DepthWord::Dimension => self.length(b, Address::D),
            crate::setup::DepthWord::Increments => self.increments(b, Address::D),
        }
    }

    /// An error of a cycle, with the control's alarm it stands for.
    fn mrc_error(
        &self,
        b: &Block,
        code: &'static str,
        alarm: &str,
        cycle: Repetitive,
        why: String,
    ) -> Diagnostic {
        self.error(
            code,
            b.span,
            format!("{}: {why} (Fanuc alarm {alarm})", self.code_name(cycle)),
        )
    }

    /// One straight move of a cycle to (X diameter, Z), programmed.
    fn cycle_move(&mut self, out: &mut Out, x: f64, z: f64, kind: MoveKind) {
        let start = self.mark();
        self.state.programmed[0] = x;
        self.state.programmed[2] = z;
        self.emit(out, start, kind, kind == MoveKind::Feed, None);
    }

    /// Before a cycle's first move: the T offset the block asks for is
    /// carried from there on (behaviour 15.13).
    fn take_offset(&mut self) {
        self.state.lathe.vector = self.state.lathe.target;
    }

    /// The cycle's moves ran out of the run's move budget: stop making more.
    fn out_of_moves(&self) -> bool {
        self.overflow
    }

    /// What every pass over the contour does at a segment before its move
    /// (plain and compensated alike): the finishing pass takes the
    /// segment's F and S, and a dwell is reported there. True when the
    /// segment has a move to make.
    fn contour_segment(&mut self, out: &mut Out, s: &contour::Seg, finishing: bool) -> bool {
        if finishing {
            self.state.feed = s.feed;
            self.state.spindle = s.spindle;
        }
        if let Some(seconds) = s.dwell {
            if finishing {
                self.event(out, super::EventKind::Dwell { seconds });
            }
            return false;
        }
        true
    }
}
