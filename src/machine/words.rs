//! Never a silent skip (behaviour 2.22): which words each kind of block
//! acts on, and the error at every other word; and the subprogram and
//! macro calls offsetlab does not run yet (behaviour 2.18), refused rather
//! than passed over (M198, G65).
//!
//! Each block path of the mill and the lathe has its list of addresses
//! below. A word outside its block's list stops the run at the word
//! (`unused-word`) — the words the parser reads but no rule models at all
//! are refused before (`unsupported-word`, [`Machine::refuse_unmodelled`],
//! which lets through the rotary words, E and the comma words a block
//! models), and the other machine's addresses too (`lathe-address`,
//! `mill-address`). The codes that check their own words (G31, G12/G13,
//! G05.1, G08, G187, G07.1 of section 14, the lathe's G70–G76 of section 15,
//! G10 of section 17)
//! take every address here and refuse with their own sentences. `tests/silent_skips.rs` runs every
//! address in every kind of block and holds each to being acted on or
//! refused.

use super::Machine;
use super::modal::Motion;
use crate::diag::Diagnostic;
use crate::setup::MachineKind;
use crate::syntax::codes::{CannedCycle, Code, Group, MCode, NonModal, RotationMode, ScalingMode};
use crate::syntax::{Address, Block, WordKind};

use Address::*;

/// The words of a block that only moves: sequence number, G codes of group
/// 01, axes, arc centre and radius, feed ([`Machine::motion_block`]).
pub(super) const MOTION_WORDS: [Address; 10] = [N, G, X, Y, Z, I, J, K, R, F];

/// The kinds of block, by what the block does (its one-shot code, else its
/// motion mode after the block's codes).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Path {
    /// Mill G00/G01, or no motion code but a straight mode: a straight move
    /// (or none).
    Line(Motion),
    /// Mill G02/G03.
    Arc(Motion),
    /// Mill, in a canned cycle mode.
    Cycle(Code),
    /// G04.
    Dwell,
    /// Mill G92, lathe G50 (or G92 in G-code system B/C).
    SetCoordinates,
    /// G28, G30 (with P, the reference position's number).
    ReferenceReturn(Code),
    /// G27, G52, G53, G92.1: axis words and, on the mill, the length offset
    /// (behaviour 13).
    Coordinates(Code),
    /// Mill G45–G48, in a straight (false) or an arc (true) mode.
    PositionOffset(Code, bool),
    /// Lathe G00/G01 (or no motion code in a straight mode).
    LatheLine(Motion),
    /// Lathe G02/G03.
    LatheArc(Motion),
    /// Lathe single cycle G90/G92/G94 (system A names).
    LatheCycle(Motion),
    /// Lathe, in polar coordinate interpolation: a line of the face plane
    /// (behaviour 14.15).
    PolarLine(Motion),
    /// Lathe, in polar coordinate interpolation: an arc of the face plane.
    PolarArc(Motion),
    /// A code that checks its own words (G31, G12/G13, G05.1, G08, G187,
    /// G07.1: behaviour 14; G70–G76: behaviour 15): every address passes here.
    OwnWords(Code),
    /// Mill G39: the corner arc, its direction from I/J/K (behaviour 16.14;
    /// an axis word is refused by the compensation, `cutter-g39`).
    CornerArc,
}

/// Every mill block acts on these: the sequence number and the program
/// number, its G and M codes (each by its own rule), the feed, the tool
/// number for the next M06 and the D register; and the words
/// [`Machine::refuse_unmodelled`] and the corner rules (`corner.rs`) rule on.
const MILL_COMMON: [Address; 13] = [N, O, G, M, F, T, D, A, B, C, E, CommaC, CommaR];
/// The lathe's, besides a path's own (T selects the tool and its offset).
const LATHE_COMMON: [Address; 12] = [N, O, G, M, F, S, A, B, C, E, CommaC, CommaR];
/// Every address: a code that checks its words itself.
const ALL: [Address; Address::COUNT] = Address::ALL;

impl Path {
    /// The addresses a block of this kind acts on (besides
    /// [`MILL_COMMON`] / [`LATHE_COMMON`], which the caller adds).
    fn own(self) -> &'static [Address] {
        match self {
            Path::Line(_) => &[S, X, Y, Z, H],
            Path::Arc(_) => &[S, X, Y, Z, I, J, K, R, H],
            // R level, Q peck or shift, P dwell, K/L repeats: kept as the
            // cycle's data even when this cycle does not use them (Fanuc M:
            // they are modal cycle data, behaviour 2.14).
            Path::Cycle(_) => &[S, X, Y, Z, R, Q, P, K, L, H],
            // Y, Z (and W on the lathe) are read to refuse them
            // (`dwell-words`, behaviour 2.9).
            Path::Dwell => &[S, P, X, Y, Z, U, W],
            // The mill's G92 S is Fanuc's spindle speed limit under constant
            // surface speed, not modelled: S is refused there.
            Path::SetCoordinates => &[X, Y, Z, U, W],
            Path::ReferenceReturn(_) => &[S, X, Y, Z, U, W, H, P],
            Path::Coordinates(_) => &[S, X, Y, Z, U, W, H],
            Path::PositionOffset(_, false) => &[S, X, Y, Z, H],
            Path::PositionOffset(_, true) => &[S, X, Y, Z, I, J, K, R, H],
            Path::LatheLine(_) => &[T, X, Z, U, W],
            Path::LatheArc(_) => &[T, X, Z, U, W, I, K, R],
            Path::LatheCycle(_) => &[T, X, Z, U, W, R],
            // The hypothetical axis is C or Y as the setting says; the other
            // one, H and T are refused before (`polar-words`, behaviour 14.18).
            Path::PolarLine(_) => &[X, Z, U, W, C, Y],
            Path::PolarArc(_) => &[X, Z, U, W, C, Y, I, J, R],
            Path::OwnWords(_) => &ALL,
            Path::CornerArc => &[S, I, J, K],
        }
    }

    /// What the block is, for a message ("a G01 block").
    fn name(self, m: &Machine) -> String {
        let table = m.state.table();
        match self {
            Path::Line(motion)
            | Path::Arc(motion)
            | Path::LatheLine(motion)
            | Path::LatheArc(motion)
            | Path::LatheCycle(motion)
            | Path::PolarLine(motion)
            | Path::PolarArc(motion) => Code::Motion(motion).gcode(table).to_string(),
            Path::Cycle(code) | Path::PositionOffset(code, _) => code.gcode(table).to_string(),
            Path::Dwell => "G04".to_string(),
            Path::SetCoordinates => Code::NonModal(NonModal::SetCoordinates)
                .gcode(table)
                .to_string(),
            Path::ReferenceReturn(code) | Path::Coordinates(code) | Path::OwnWords(code) => {
                code.gcode(table).to_string()
            }
            Path::CornerArc => "G39".to_string(),
        }
    }
}

impl Machine {
    /// The kind of a mill block: its one-shot code, else the motion mode
    /// or canned cycle in effect after its codes.
    pub(super) fn mill_path(&self, b: &Block) -> Path {
        let c = b.codes();
        let motion = c.motion().unwrap_or(self.state.modal.motion);
        match c.non_modal() {
            Some(NonModal::Dwell) => return Path::Dwell,
            Some(NonModal::SetCoordinates) => return Path::SetCoordinates,
            Some(code @ (NonModal::ReferenceReturn | NonModal::OtherReference)) => {
                return Path::ReferenceReturn(Code::NonModal(code));
            }
            Some(
                code @ (NonModal::ReferenceCheck
                | NonModal::LocalCoordinates
                | NonModal::MachineCoordinates
                | NonModal::PresetCoordinates
                | NonModal::Stored(_)),
            ) => return Path::Coordinates(Code::NonModal(code)),
            Some(NonModal::PositionOffset(p)) => {
                let code = Code::NonModal(NonModal::PositionOffset(p));
                return Path::PositionOffset(code, motion.is_arc());
            }
            Some(
                code @ (NonModal::Skip
                | NonModal::CirclePocket(_)
                | NonModal::Engraving
                | NonModal::AiContour
                | NonModal::LookAhead
                | NonModal::Smoothness
                | NonModal::BlockLimit
                | NonModal::Cylindrical
                | NonModal::Repetitive(_)
                | NonModal::DataSetting),
            ) => return Path::OwnWords(Code::NonModal(code)),
            Some(NonModal::CornerArc) => return Path::CornerArc,
            // G09 stops at the end of a block that moves as any other.
            Some(NonModal::ExactStop) | None => {}
        }
        let cycle = match (c.cycle(), c.motion()) {
            (Some(CannedCycle::Cycle(cycle)), _) => Some(cycle),
            (Some(CannedCycle::Cancel), _) | (None, Some(_)) => None,
            (None, None) => self.state.modal.cycle,
        };
        match (cycle, motion.is_arc()) {
            (Some(cycle), _) => Path::Cycle(Code::Cycle(CannedCycle::Cycle(cycle))),
            (None, true) => Path::Arc(motion),
            (None, false) => Path::Line(motion),
        }
    }

    /// The kind of a lathe block.
    pub(super) fn lathe_path(&self, b: &Block) -> Path {
        let c = b.codes();
        match c.non_modal() {
            Some(NonModal::Dwell) => return Path::Dwell,
            Some(NonModal::SetCoordinates) => return Path::SetCoordinates,
            Some(code @ (NonModal::ReferenceReturn | NonModal::OtherReference)) => {
                return Path::ReferenceReturn(Code::NonModal(code));
            }
            Some(
                code @ (NonModal::ReferenceCheck
                | NonModal::LocalCoordinates
                | NonModal::MachineCoordinates
                | NonModal::PresetCoordinates),
            ) => return Path::Coordinates(Code::NonModal(code)),
            // G70–G76 refuse what they do not read (`mrc-word`, behaviour
            // 15), G10 too (`g10-words`, behaviour 17.10).
            Some(code @ (NonModal::Skip | NonModal::Repetitive(_) | NonModal::DataSetting)) => {
                return Path::OwnWords(Code::NonModal(code));
            }
            // The parser gives the lathe none of the mill's one-shot codes
            // (seed 004, behaviour 14).
            Some(
                NonModal::PositionOffset(_)
                | NonModal::ExactStop
                | NonModal::AiContour
                | NonModal::LookAhead
                | NonModal::Smoothness
                | NonModal::BlockLimit
                | NonModal::Cylindrical
                | NonModal::CirclePocket(_)
                | NonModal::Engraving
                | NonModal::CornerArc
                | NonModal::Stored(_),
            )
            | None => {}
        }
        let motion = c.motion().unwrap_or(self.state.modal.motion);
        if self.in_polar_mode(b) {
            return match motion {
                m @ Motion::Arc(_) => Path::PolarArc(m),
                m => Path::PolarLine(m),
            };
        }
        match motion {
            m @ Motion::LatheCycle(_) => Path::LatheCycle(m),
            m @ Motion::Arc(_) => Path::LatheArc(m),
            m @ (Motion::Rapid | Motion::Linear) => Path::LatheLine(m),
        }
    }

    /// Refuses a word the block's kind does not act on, and a length-offset
    /// code in a G04 or G92 block (behaviour 2.22): an error at the word,
    /// never a word passed over.
    #[inline(never)]
    pub(super) fn refuse_unused(&self, b: &Block, path: Path) -> Result<(), Diagnostic> {
        let mill = self.setup.machine == MachineKind::Mill;
        let common: &[Address] = if mill { &MILL_COMMON } else { &LATHE_COMMON };
        let own = path.own();
        let mut allowed = [N; 3 * Address::COUNT];
        let mut n = 0;
        let mut add = |addresses: &[Address]| {
            allowed[n..n + addresses.len()].copy_from_slice(addresses);
            n += addresses.len();
        };
        add(common);
        add(own);
        let c = b.codes();
        // Codes of other groups that read words of their own, and refuse
        // what they do not read with their sentences (behaviour 13, 14):
        // G61–G64's P and Q (`mode-words`), G54.1/G154/G54's P (the work
        // system), G51's P or I/J/K (magnifications), G68's R (the angle).
        if c.cutting_mode().is_some() {
            add(&[P, Q]);
        }
        if c.work().is_some() {
            add(&[P]);
        }
        // LinuxCNC's G2/G3 P, the number of turns (22.16).
        if matches!(path, Path::Arc(_))
            && self.setup.settings.control == crate::setup::Control::Linuxcnc
        {
            add(&[P]);
        }
        // LinuxCNC's M61 reads Q, the tool now in the spindle (22.9).
        if b.holds(M)
            && self.setup.settings.control == crate::setup::Control::Linuxcnc
            && b.mcodes(self.setup.machine).any(|m| m.number() == 61)
        {
            add(&[Q]);
        }
        if c.scaling() == Some(ScalingMode::Start) {
            add(&[P, I, J, K]);
        }
        if c.rotation() == Some(RotationMode::Start) {
            add(&[R]);
        }
        // G40/G41/G42 read I/J/K as the direction of the vector (behaviour
        // 16.14); where they cannot, the compensation refused them first
        // (`cutter-ijk`).
        if c.cutter().is_some() && matches!(path, Path::Line(_) | Path::LatheLine(_)) {
            add(&[I, J, K]);
        }
        // The lathe's positioning codes refuse a T code themselves
        // (`t-in-positioning`, behaviour 13).
        if !mill
            && matches!(
                c.non_modal(),
                Some(
                    NonModal::ReferenceCheck
                        | NonModal::OtherReference
                        | NonModal::LocalCoordinates
                        | NonModal::MachineCoordinates
                )
            )
        {
            add(&[T]);
        }
        if let Some(w) = b.first_outside(&allowed[..n]) {
            let text = self.word_text(b, w.address);
            let msg = unused_message(&text, w.address, mill, path, &path.name(self));
            return Err(self.error("unused-word", w.span, msg));
        }
        if let (Some(code), Path::Dwell | Path::SetCoordinates) = (b.codes().length(), path) {
            return Err(self.error(
                "unused-word",
                b.code_span(Group::Length),
                format!(
                    "{} in a {} block: the tool length offset is not changed by a {} block; write G43/G44/G49 and H in a block of their own",
                    code.gcode(),
                    path.name(self),
                    path.name(self)
                ),
            ));
        }
        Ok(())
    }

    /// The fast path's words checked (behaviour 2.22): a block of motion words
    /// alone with I, J, K or R, which not every mode reads. Out of line:
    /// most such blocks are arcs, and a straight move's block skips it.
    #[inline(never)]
    pub(super) fn refuse_unused_motion_words(&self, b: &Block) -> Result<(), Diagnostic> {
        self.refuse_unused(b, self.mill_path(b))
    }

    /// M198: a subprogram kept outside the program memory (a memory card,
    /// a data server) is not in the text (behaviour 2.18); the run stops
    /// at the call rather than go on without its moves. M98, M97 and M99
    /// run (behaviour 19: `calls.rs`).
    pub(super) fn refuse_calls(&self, b: &Block) -> Result<(), Diagnostic> {
        if !b.holds(M) {
            return Ok(());
        }
        let machine = self.setup.machine;
        let call = b
            .words
            .iter()
            .filter(|w| w.address == M)
            .find(|w| MCode::of(machine, w.int()) == MCode::ExternalSubprogramCall);
        let Some(w) = call else { return Ok(()) };
        let with = match b.get(P) {
            Some(_) => format!(" ({})", self.word_text(b, P)),
            None => String::new(),
        };
        Err(self.error(
            "unsupported-m-code",
            w.span,
            format!(
                "M{:02} calls a subprogram kept outside the program memory{with}: that program is not in this file, so the run stops here rather than go on without its moves; put it in the file (or the setup's programs) and call it with M98",
                w.int()
            ),
        ))
    }

    /// A word as the manuals write it, for a message.
    pub(super) fn word_text(&self, b: &Block, a: Address) -> String {
        let letter = a.letter();
        match b.get(a) {
            Some(w) if w.point || a.kind() != WordKind::Integer => {
                // The word's value is in the program's units already.
                let d = self.units().decimals();
                format!("{letter}{:.d$}", crate::geometry::round6(w.value))
            }
            Some(w) if a == T => format!("T{:04}", w.int()),
            Some(w) if matches!(a, H | D) => format!("{letter}{:02}", w.int()),
            Some(w) => format!("{letter}{}", w.int()),
            None => letter.to_string(),
        }
    }
}

/// The `unused-word` sentence: what the address is, and that this kind of
/// block does not read it.
fn unused_message(text: &str, a: Address, mill: bool, path: Path, name: &str) -> String {
    let what = match (a, mill) {
        (I | J | K, true) => "I, J and K are the centre of a G02/G03 arc",
        (I | K, false) if matches!(path, Path::PolarLine(_) | Path::PolarArc(_)) => {
            "in polar coordinate interpolation I and J are the centre of a G02/G03 arc in the face plane (K, along Z, is not in it)"
        }
        (I | K, false) => "I and K are the centre of a G02/G03 arc",
        (J, false) => {
            "J is the centre of a G02/G03 arc along the hypothetical axis of polar coordinate interpolation"
        }
        (R, true) => "R is an arc's radius or a canned cycle's R level",
        (R, false) => "R is an arc's radius or the taper of a G90/G92/G94 cycle",
        (Q, true) => "Q is the peck depth (G73/G83) or the shift (G76/G87) of a canned cycle",
        (Q, false) => "Q is read by no lathe code offsetlab models",
        (P, _) => "P is a dwell time (G04, and a canned cycle's dwell at the bottom)",
        (L, _) => "L is a canned cycle's repeat count",
        (H, _) => "H is a tool length offset number",
        (S, _) => {
            return format!(
                "{text} in a {name} block: on Fanuc, S in G92 is the spindle speed limit of constant surface speed, which the mill does not model; write the spindle speed S in a block of its own"
            );
        }
        (T, _) => {
            return format!(
                "{text} in a {name} block: the T code's tool and offset are not taken in a {name} block; write the T code in a block of its own"
            );
        }
        _ => "this address is not read here",
    };
    let hint = match path {
        Path::Dwell | Path::SetCoordinates | Path::ReferenceReturn(_) | Path::Coordinates(_) => {
            format!("; write it in a block of its own, not in a {name} block")
        }
        _ => "; remove it".to_string(),
    };
    format!("{text}: {what}, which a {name} block does not read{hint}")
}
