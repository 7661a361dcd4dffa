//! Cutter radius compensation C on the mill (behaviour 16): the machine's
//! side of it. A block runs as it always does, with the compensation's
//! vector standing still; then, as a control does with its buffer, the next
//! blocks are read ahead (on a copy of the machine, as the chamfer of
//! `corner.rs` reads its next move) to learn the next move in the plane,
//! the corner between the two is made by the family's rules
//! (`offsets/cutter/geometry.rs`), and the block's move is made to end
//! where the corner says, with the moves the corner adds. The alarms
//! (Fanuc PS0033, PS0034, PS0037–PS0042) stop the run at their block, the
//! path drawn up to it.
//!
//! `ahead.rs` reads the next move, `checks.rs` refuses what the
//! compensation forbids, `corners.rs` makes a block end at its corner, and
//! `codes.rs` does what G39, G40 without a move, I/J/K and the returns ask.

mod ahead;
mod checks;
mod codes;
mod corners;
mod linuxcnc_entry;
mod nose;

use super::arc::P2;
use super::corner::CORNER_WORDS;
use super::modal::FeedMode;
use super::words::MOTION_WORDS;
use super::{Ahead, Machine, Move, MoveKind, Out};
use crate::diag::Diagnostic;
use crate::geometry::Xyz;
use crate::offsets::cutter::geometry::{self as geo, Path};
use crate::offsets::cutter::{self as crc, Phase, Words};
use crate::syntax::codes::{CutterCompensation, Group, NonModal};
use crate::syntax::{Address, Block};

/// True when a block asks for the compensation while it is not engaged:
/// a group 07 code, or G39 (which is refused outside offset mode).
pub(super) fn concerns(b: &Block) -> bool {
    b.codes().cutter().is_some() || b.codes().non_modal() == Some(NonModal::CornerArc)
}

/// The codes that position on a point given apart from the work
/// coordinates, which cancel the compensation for their block (behaviour
/// 16.18): G27, G28, G30 and G53.
fn returns(code: NonModal) -> bool {
    match code {
        NonModal::ReferenceReturn
        | NonModal::OtherReference
        | NonModal::ReferenceCheck
        | NonModal::MachineCoordinates => true,
        NonModal::Dwell
        | NonModal::ExactStop
        | NonModal::Skip
        | NonModal::AiContour
        | NonModal::LookAhead
        | NonModal::Smoothness
        | NonModal::BlockLimit
        | NonModal::Cylindrical
        | NonModal::CirclePocket(_)
        | NonModal::Engraving
        | NonModal::PositionOffset(_)
        | NonModal::SetCoordinates
        | NonModal::LocalCoordinates
        | NonModal::PresetCoordinates
        | NonModal::Stored(_)
        | NonModal::CornerArc
        | NonModal::Repetitive(_)
        | NonModal::DataSetting => false,
    }
}

/// What follows the running block, as read ahead (behaviour 16.9).
#[derive(Clone, Copy, Debug)]
enum Next {
    /// A block that moves in the plane (or a G41/G42 with I/J/K's
    /// direction): its programmed path in the running block's work
    /// coordinates, and what it does with the compensation.
    Move {
        path: Path,
        /// The offset it asks for (0: it cancels).
        offset: f64,
    },
    /// The corner is not known: the vector ends perpendicular to the block.
    Unknown(Why),
}

/// Why the next move is not known.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Why {
    /// The program ends (M02/M30 or its text).
    End,
    /// The next block has an error (the run stops there).
    Error,
    /// A reference return or canned cycle follows (temporary cancel).
    Return,
    /// G39 follows: its arc turns the corner.
    CornerArc,
    /// G40 (or D00) without a move follows and takes the vector off there.
    CancelHere,
    /// More blocks without a move in the plane than the control reads.
    TooFar(usize),
    /// A block with macro syntax (on this line) follows, which the
    /// look-ahead does not evaluate (behaviour 20.8).
    Macro(u32),
}

impl Machine {
    /// The signed offset of the compensation now: + left, − right, the
    /// register's sign and mirror image (an odd number of mirrored plane
    /// axes turns G41 into G42, behaviour 16.15) included.
    pub(super) fn cutter_offset(&self, mode: CutterCompensation, radius: f64) -> f64 {
        let plane = self.state.modal.plane;
        let (ia, ib, _) = plane.axes();
        // The setting's mirror image and the programmable one (G51.1, or
        // G51 with a negative factor) each reverse the turn of a plane with
        // one mirrored axis (behaviour 13.8, 13.9).
        let reversed =
            (self.mirror[ia] != self.mirror[ib]) != self.state.modal.transforms.reverses(plane);
        let flip = if reversed { -1.0 } else { 1.0 };
        crc::side(mode) * radius * flip
    }

    /// Register D's value now (mm), read when the block runs (behaviour
    /// 4.12).
    /// On the lathe, the nose radius of the T code's offset register
    /// (behaviour 18.1).
    pub(super) fn cutter_radius(&self) -> f64 {
        if self.nose_lathe() {
            return self.nose_register().0;
        }
        if let Some(r) = self.state.table_radius {
            return r;
        }
        self.mm(self.setup.mill_value(self.state.position.d))
    }

    /// The register number the compensation reads: D on the mill, the T
    /// code's offset number on the lathe.
    fn cutter_number(&self) -> u16 {
        if self.nose_lathe() {
            self.state.lathe.offset
        } else {
            self.state.position.d
        }
    }

    /// A point in the compensation plane (on the lathe X as a radius).
    pub(super) fn in_plane(&self, p: Xyz) -> P2 {
        let (ia, ib, _) = self.state.modal.plane.axes();
        if self.nose_lathe() {
            return [p[ia], p[ib] * 0.5];
        }
        [p[ia], p[ib]]
    }

    /// The programmed path of a move in the plane, None when it does not
    /// move in the plane. `shift` takes its coordinates into the running
    /// block's work coordinates.
    #[inline]
    pub(super) fn move_path(&self, m: &Move, shift: Xyz) -> Option<Path> {
        let at = |p: Xyz| self.in_plane(crate::geometry::add(p, shift));
        let (from, to) = (at(m.programmed_from), at(m.programmed_to));
        match (&m.arc, m.kind) {
            (Some(info), MoveKind::ArcCw | MoveKind::ArcCcw) => Some(Path::Arc {
                from,
                to,
                center: at(info.programmed_center),
                ccw: info.programmed_sweep > 0.0,
            }),
            _ if geo::dist(from, to) > 1e-9 => Some(Path::Line { from, to }),
            _ => None,
        }
    }

    /// The direction I/J/K give in a G41/G42 block with no move in the
    /// plane (behaviour 16.14), after mirror image; None without them.
    pub(super) fn ijk_direction(&self, b: &Block) -> Option<P2> {
        let (ia, ib, _) = self.state.modal.plane.axes();
        let words = [Address::I, Address::J, Address::K];
        let (wa, wb) = (b.value(words[ia]), b.value(words[ib]));
        if wa.is_none() && wb.is_none() {
            return None;
        }
        let sign = |i: usize| if self.mirror[i] { -1.0 } else { 1.0 };
        let d = [wa.unwrap_or(0.0) * sign(ia), wb.unwrap_or(0.0) * sign(ib)];
        (d[0].hypot(d[1]) > 0.0).then(|| geo::unit(d))
    }

    /// The direction of a G41/G42 block's I/J/K when it moves in a
    /// straight line (behaviour 16.14: the IJ-type vector, on the lathe
    /// K/I; 18.4); None otherwise.
    pub(super) fn ij_vector(&self, b: &Block) -> Option<P2> {
        let code = b.codes().cutter()?;
        if code == CutterCompensation::Cancel || self.state.modal.motion.is_arc() {
            return None;
        }
        self.ijk_direction(b)
    }

    /// True when a block names an axis of the plane (on the lathe U and W
    /// too).
    pub(super) fn names_plane_axis(&self, b: &Block) -> bool {
        let (ia, ib, _) = self.state.modal.plane.axes();
        let axes = [Address::X, Address::Y, Address::Z];
        b.has(axes[ia])
            || b.has(axes[ib])
            || (self.nose_lathe() && (b.has(Address::U) || b.has(Address::W)))
    }

    /// The block after a cancel block that does not ask for the
    /// compensation: it is back in cancel mode (behaviour 16.2) and runs as
    /// any block does, a chamfer's look-ahead and the fast path included.
    /// True when that is so (the role is then set back to cancel).
    pub(super) fn cutter_after_cancel(&mut self, b: &Block) -> bool {
        let c = self.state.cutter;
        if c.mode == CutterCompensation::Cancel && c.phase == Phase::Cancelling && !concerns(b) {
            self.state.cutter.phase = Phase::Cancel;
            self.update_special();
            return true;
        }
        false
    }

    /// A mill block while cutter compensation is engaged, or one that
    /// asks for it (behaviour 16). While it stays engaged no block takes
    /// the fast path (`special`).
    pub(super) fn cutter_block(
        &mut self,
        b: &Block,
        out: &mut Out,
        ahead: &mut dyn Ahead,
    ) -> Result<(), Diagnostic> {
        let done = self.compensate(b, out, ahead);
        self.update_special();
        done
    }

    fn compensate(
        &mut self,
        b: &Block,
        out: &mut Out,
        ahead: &mut dyn Ahead,
    ) -> Result<(), Diagnostic> {
        let lathe = self.nose_lathe();
        // A block of motion words alone has nothing the checks refuse (no
        // plane, G45–G48, G39, group 07 or cycle code, no ,C/,R).
        let plain = b.holds_only(&MOTION_WORDS, &[Group::Motion]);
        if plain && !lathe && self.in_plain_offset_mode() {
            return self.offset_plain(b, out, ahead);
        }
        if lathe {
            // Before the plain case: a G90 cycle goes on with X and Z alone.
            self.nose_checks(b)?;
        }
        if !plain {
            self.cutter_checks(b)?;
            if self.setup.settings.control == crate::setup::Control::Linuxcnc {
                self.linuxcnc_tool_change_position(b, out)?;
            }
        }
        let before = self.state.cutter;
        let start = self.mark();
        let moves_before = out.moves.len();
        let g28 = b.codes().non_modal().is_some_and(returns);
        // The block runs with the compensation's vector off, so that its
        // arcs are solved on the programmed circle (carried by the other
        // offsets), then its moves are carried by the vector as it stood;
        // the corner moves their ends below.
        let saved = before.vector;
        self.state.cutter.vector = [0.0; 3];
        // `,C`/`,R` in offset mode (behaviour 16.19): the block cuts its
        // corner on the programmed path, which is then compensated.
        let corner_words = b.holds_any(&CORNER_WORDS);
        let ran = if corner_words {
            self.corner_block(b, out, ahead)
        } else if lathe {
            self.nose_run(b, out)
        } else if plain && self.state.modal.feed_mode != FeedMode::InverseTime {
            self.motion_block(b, out)
        } else {
            self.mill_general(b, out)
        };
        self.state.cutter.vector = saved;
        carry(&mut out.moves[moves_before..], saved);
        ran?;
        self.start_at_cut_end(out);
        let mode = self.state.cutter.mode;
        // The register is read when the block runs (behaviour 4.12); a block
        // without D or a group 07 code reads the one the block before read,
        // whose value the run cannot have changed.
        let number = self.cutter_number();
        let radius = if self.state.cutter.d != number
            || b.holds(Address::D)
            || (lathe && b.holds(Address::T))
            || b.codes().cutter().is_some()
            || b.codes().units().is_some()
        {
            self.cutter_radius()
        } else {
            self.state.cutter.radius
        };
        self.state.cutter.d = number;
        self.state.cutter.radius = radius;
        // The lathe's tip direction, read with the radius (behaviour 18.2).
        self.state.cutter.tip = lathe.then(|| self.nose_register().1);
        let o = self.cutter_offset(mode, radius);
        let engaged = matches!(before.phase, Phase::StartUp | Phase::Offset);
        if self.reading_ahead {
            // A copy reading ahead wants the modes and the programmed
            // moves only; the vector stands still.
            return Ok(());
        }
        if self.state.modal.cycle.is_some() {
            // Fanuc ignores the compensation in canned cycles (the vector
            // is off: `cutter_checks`).
            self.state.cutter.phase = Phase::Cancel;
            out.note(|| format!(
                "{}: cutter compensation is ignored in a canned cycle (its holes are drilled where programmed)",
                mode.gcode()
            ));
            return Ok(());
        }
        if g28 && engaged && self.names_plane_axis(b) {
            return self.cutter_return(out, moves_before, before);
        }
        // The block's own move in the plane (a plain loop: it runs at every
        // block in offset mode).
        let mut own = None;
        for i in moves_before..out.moves.len() {
            if let Some(p) = self.move_path(&out.moves[i], [0.0; 3]) {
                own = Some((i, p));
                break;
            }
        }
        let words = Words {
            mode,
            d: number,
            offset: o,
            units: self.units(),
            tip: self.state.cutter.tip,
        };
        if b.codes().non_modal() == Some(NonModal::CornerArc) {
            return self.corner_arc(b, out, ahead, words);
        }
        if !engaged {
            self.state.cutter.phase = Phase::Cancel;
            if o == 0.0 {
                if let Some(code) = b.codes().cutter()
                    && code != CutterCompensation::Cancel
                {
                    out.note(|| {
                        if lathe {
                            format!(
                                "{} with offset {number:02}: its nose radius is 0, no compensation until a T code whose offset has one",
                                code.gcode()
                            )
                        } else {
                            format!(
                                "{} with D{number:02} = 0: no radius, no compensation until a D with a value",
                                code.gcode()
                            )
                        }
                    });
                }
                return Ok(());
            }
            if let Some((i, path)) = own {
                if path.is_arc() && self.setup.settings.control == crate::setup::Control::Linuxcnc {
                    // LinuxCNC enters on an arc (behaviour 22.16).
                    self.linuxcnc_entry_checks(b, &out.moves[i], o)?;
                    return self.start_up(b, out, ahead, (i, path), words);
                }
                if path.is_arc() {
                    return Err(self.error(
                        "cutter-arc",
                        b.span,
                        format!(
                            "{} start-up in a {} block: compensation starts on a G00 or G01 move (Fanuc alarm PS0034)",
                            mode.gcode(),
                            self.state.modal.motion.gcode()
                        ),
                    ));
                }
                if let Some(d) = self.ij_vector(b) {
                    self.state.cutter.phase = Phase::StartUp;
                    return self.direction_vector(out, d, words, ("start-up", Some(i)));
                }
                return self.start_up(b, out, ahead, (i, path), words);
            }
            if let Some(d) = self.ijk_direction(b)
                && b.codes().cutter().is_some()
                && !self.state.modal.motion.is_arc()
            {
                self.state.cutter.phase = Phase::StartUp;
                return self.direction_vector(out, d, words, ("start-up", None));
            }
            if b.codes().cutter().is_some() || before.mode == CutterCompensation::Cancel {
                out.note(|| {
                    format!(
                        "{}: compensation starts up with the next move in the plane",
                        words.name()
                    )
                });
            }
            return Ok(());
        }
        if o == 0.0 {
            if corner_words {
                // D00 cancels: as G40 (behaviour 16.19, Fanuc PS0039).
                return Err(self.corner_in_cancel(b));
            }
            return self.cancel(b, out, own, before, (start, moves_before));
        }
        self.state.cutter.phase = Phase::Offset;
        if corner_words && self.corner_cut && out.moves.len() == moves_before + 2 {
            return self.offset_corner_cut(b, out, ahead, moves_before, before, words);
        }
        if let Some((i, path)) = own {
            if let Some(d) = self.ij_vector(b)
                && !path.is_arc()
            {
                return self.direction_vector(out, d, words, ("offset mode", Some(i)));
            }
            return self.offset_move(b, out, ahead, (i, path), before, words);
        }
        if let Some(d) = self.ijk_direction(b)
            && b.codes().cutter().is_some()
            && !self.state.modal.motion.is_arc()
        {
            return self.direction_vector(out, d, words, ("offset mode", None));
        }
        if before.radius != radius || before.mode != mode {
            out.note(|| {
                format!(
                    "{}: no move in the plane here; the next move ends on the new offset",
                    words.name()
                )
            });
        }
        Ok(())
    }
}

impl Machine {
    /// The block after a `,C`/`,R` corner runs from the virtual corner
    /// (behaviour 2.32); its move starts where the chamfer or the round
    /// ended, and is compensated from there (behaviour 16.19). The run
    /// sets the same start again after the block (a no-op then).
    #[inline(always)]
    fn start_at_cut_end(&self, out: &mut Out) {
        if let Some(end) = self.corner_end {
            Self::start_at_corner_end(out, end);
        }
    }

    /// True in offset mode on the mill where a block of motion words alone
    /// runs as [`Machine::offset_plain`] says: G41/G42 with a radius read
    /// from the D the block keeps, no canned cycle, no inverse time feed,
    /// not a copy reading ahead.
    #[inline(always)]
    fn in_plain_offset_mode(&self) -> bool {
        let s = &self.state;
        s.cutter.phase == Phase::Offset
            && s.cutter.mode != CutterCompensation::Cancel
            && s.cutter.radius != 0.0
            && s.cutter.d == s.position.d
            && s.modal.feed_mode != FeedMode::InverseTime
            && s.modal.cycle.is_none()
            && !self.reading_ahead
    }

    /// A block of motion words alone in offset mode on the mill (nearly
    /// every block of a compensated contour): what [`Machine::compensate`]
    /// does with it, without the steps that cannot apply — no check can
    /// refuse it, its radius is the one the block before read (no D, no
    /// group 07 or units code), it neither starts up nor cancels (the
    /// `check` instruction count with G41, docs/performance.md;
    /// `tests/cutter_props.rs` holds the two ways equal).
    fn offset_plain(
        &mut self,
        b: &Block,
        out: &mut Out,
        ahead: &mut dyn Ahead,
    ) -> Result<(), Diagnostic> {
        let before = self.state.cutter;
        let moves_before = out.moves.len();
        // As in `compensate`: the block runs with the vector off, its moves
        // are carried by the vector as it stood.
        let saved = before.vector;
        self.state.cutter.vector = [0.0; 3];
        let ran = self.motion_block(b, out);
        self.state.cutter.vector = saved;
        carry(&mut out.moves[moves_before..], saved);
        ran?;
        self.start_at_cut_end(out);
        self.state.cutter.tip = None;
        let mode = self.state.cutter.mode;
        let o = self.cutter_offset(mode, self.state.cutter.radius);
        let mut own = None;
        for i in moves_before..out.moves.len() {
            if let Some(p) = self.move_path(&out.moves[i], [0.0; 3]) {
                own = Some((i, p));
                break;
            }
        }
        // No move in the plane: the vector stands (the next move ends on it).
        let Some(own) = own else {
            return Ok(());
        };
        let words = Words {
            mode,
            d: self.state.cutter.d,
            offset: o,
            units: self.units(),
            tip: None,
        };
        self.offset_move(b, out, ahead, own, before, words)
    }
}

fn sub3(a: Xyz, b: Xyz) -> Xyz {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn add3(a: Xyz, b: Xyz) -> Xyz {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

/// The block's moves, made with the vector off, carried by the vector as
/// it stood (the programmed path stays where it is written).
fn carry(moves: &mut [crate::machine::Move], v: [f64; 3]) {
    for m in moves {
        m.from = add3(m.from, v);
        m.to = add3(m.to, v);
        if let Some(a) = &mut m.arc {
            a.center = add3(a.center, v);
        }
    }
}
