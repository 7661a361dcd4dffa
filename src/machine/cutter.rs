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

use super::arc::{self, P2};
use super::mill::MOTION_WORDS;
use super::modal::FeedMode;
use super::{Ahead, ArcInfo, Machine, Mark, Move, MoveKind, NoneAhead, Out};
use crate::diag::Diagnostic;
use crate::geometry::{Xyz, show};
use crate::offsets::cutter::geometry::{
    self as geo, Corner, NoIntersection, Outside, Path, Rule, Step, Type,
};
use crate::offsets::cutter::{self as crc, Phase, Words};
use crate::setup::{
    CutterCancelWithoutMotion, CutterInterference, CutterOutsideCorner, CutterStartUp,
};
use crate::syntax::codes::{CannedCycle, CutterCompensation, Group, Motion, NonModal};
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
        | NonModal::Cylindrical
        | NonModal::CirclePocket(_)
        | NonModal::PositionOffset(_)
        | NonModal::SetCoordinates
        | NonModal::LocalCoordinates
        | NonModal::PresetCoordinates
        | NonModal::CornerArc
        | NonModal::Repetitive(_) => false,
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
}

impl Machine {
    /// The signed offset of the compensation now: + left, − right, the
    /// register's sign and mirror image (an odd number of mirrored plane
    /// axes turns G41 into G42, behaviour 16.15) included.
    fn cutter_offset(&self, mode: CutterCompensation, radius: f64) -> f64 {
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
    fn cutter_radius(&self) -> f64 {
        self.mm(self.setup.mill_value(self.state.position.d))
    }

    fn in_plane(&self, p: Xyz) -> P2 {
        let (ia, ib, _) = self.state.modal.plane.axes();
        [p[ia], p[ib]]
    }

    /// The programmed path of a move in the plane, None when it does not
    /// move in the plane. `shift` takes its coordinates into the running
    /// block's work coordinates.
    fn move_path(&self, m: &Move, shift: Xyz) -> Option<Path> {
        let (ia, ib, _) = self.state.modal.plane.axes();
        let at = |p: Xyz| [p[ia] + shift[ia], p[ib] + shift[ib]];
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
    fn ijk_direction(&self, b: &Block) -> Option<P2> {
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

    /// Reads ahead to the next move in the plane (behaviour 16.9): the
    /// blocks after this one run on a copy of the machine, as the machine
    /// will run them, until one moves in the plane, past at most
    /// `cutter_blocks_without_motion` blocks that do not.
    fn cutter_next(&self, ahead: &mut dyn Ahead, out: &mut Out) -> Next {
        let mut scratch = out.scratch.take().unwrap_or_default();
        scratch.quiet = true;
        let next = self.read_next(ahead, &mut scratch);
        out.scratch = Some(scratch);
        next
    }

    fn read_next(&self, ahead: &mut dyn Ahead, scratch: &mut Out) -> Next {
        if let Some(next) = ahead.peek(0)
            && let Some(path) = self.plain_next_path(next)
        {
            // A plain move reads the register this block read.
            let offset = self.cutter_offset(self.state.cutter.mode, self.state.cutter.radius);
            return Next::Move { path, offset };
        }
        let limit = usize::from(self.setup.settings.cutter_blocks_without_motion());
        let mut probe = self.clone();
        probe.reading_ahead = true;
        // The copy wants programmed moves: no vector to solve arcs with,
        // and plain moves take the fast path.
        probe.state.cutter.vector = [0.0; 3];
        probe.corner_cut = false;
        probe.corner_end = None;
        probe.moves_left = usize::MAX;
        probe.update_special();
        for k in 0..=limit {
            let Some(next) = ahead.peek(k) else {
                return Next::Unknown(Why::End);
            };
            if next.error {
                return Next::Unknown(Why::Error);
            }
            let codes = next.codes();
            match codes.non_modal() {
                Some(NonModal::CornerArc) => return Next::Unknown(Why::CornerArc),
                Some(code) if returns(code) && self.names_plane_axis(next) => {
                    return Next::Unknown(Why::Return);
                }
                _ => {}
            }
            if matches!(codes.cycle(), Some(CannedCycle::Cycle(_))) {
                return Next::Unknown(Why::Return);
            }
            let before = probe.state.cutter;
            let radius_before = probe.cutter_radius();
            scratch.clear();
            let index = self.index.saturating_add(1 + k as u32);
            let flow = match probe.execute(
                next,
                index,
                scratch,
                &mut NoneAhead,
                &mut super::program::NoText,
            ) {
                Ok(flow) => flow,
                Err(_) => return Next::Unknown(Why::Error),
            };
            let shift = sub3(probe.state.coords.zero, self.state.coords.zero);
            let mode = probe.state.cutter.mode;
            let radius = probe.cutter_radius();
            let offset = probe.cutter_offset(mode, radius);
            if let Some(path) = scratch.moves.iter().find_map(|m| self.move_path(m, shift)) {
                return Next::Move { path, offset };
            }
            if matches!(
                codes.cutter(),
                Some(CutterCompensation::Left | CutterCompensation::Right)
            ) && let Some(d) = probe.ijk_direction(next)
                && !probe.state.modal.motion.is_arc()
            {
                let at = self.in_plane(add3(probe.state.programmed, shift));
                let path = Path::Line {
                    from: at,
                    to: [at[0] + d[0], at[1] + d[1]],
                };
                return Next::Move { path, offset };
            }
            let was_on = before.mode != CutterCompensation::Cancel && radius_before != 0.0;
            if offset == 0.0
                && was_on
                && self.setup.settings.cutter_cancel_without_motion()
                    == CutterCancelWithoutMotion::Move
            {
                return Next::Unknown(Why::CancelHere);
            }
            if flow == super::Flow::End {
                return Next::Unknown(Why::End);
            }
        }
        Next::Unknown(Why::TooFar(limit))
    }

    /// The programmed path of the next block when it is a plain move
    /// (motion words alone, no transformation, no canned cycle): what the
    /// machine would make of its words, worked out here without running it
    /// on a copy (the copy costs as much as the block: the 1M-block check
    /// with G41, docs/performance.md). None when it is not such a block, or
    /// makes no move in the plane, or its arc needs the machine's checks:
    /// the copy reads it then.
    fn plain_next_path(&self, b: &Block) -> Option<Path> {
        if b.error
            || !self.plain_words
            || self.state.modal.cycle.is_some()
            || !b.holds_only(&MOTION_WORDS, &[Group::Motion])
        {
            return None;
        }
        let motion = b.codes().motion().unwrap_or(self.state.modal.motion);
        let (ia, ib, _) = self.state.modal.plane.axes();
        let incremental = self.state.modal.distance == super::modal::Distance::Incremental;
        let axes = [Address::X, Address::Y, Address::Z];
        let mut to = self.state.programmed;
        for axis in [ia, ib] {
            if let Some(v) = b.value(axes[axis]) {
                to[axis] = self.target(axis, self.mm(v), incremental);
            }
        }
        let from = self.in_plane(self.state.programmed);
        let to = self.in_plane(to);
        match motion {
            Motion::Rapid | Motion::Linear => {
                (geo::dist(from, to) > 1e-9).then_some(Path::Line { from, to })
            }
            Motion::Arc(direction) => {
                let ccw = (direction == super::modal::ArcDirection::Ccw)
                    != (self.mirror[ia] != self.mirror[ib]);
                if let Some(r) = b.value(Address::R) {
                    if geo::dist(from, to) < 1e-9 {
                        return None;
                    }
                    let center =
                        arc::center_of_radius(from, to, self.mm(r), ccw, self.arc_tolerance())?;
                    return Some(Path::Arc {
                        from,
                        to,
                        center,
                        ccw,
                    });
                }
                let centre_words = [Address::I, Address::J, Address::K];
                let (ci, cj) = (b.value(centre_words[ia]), b.value(centre_words[ib]));
                if ci.is_none() && cj.is_none() {
                    return None;
                }
                let sign = |i: usize| if self.mirror[i] { -1.0 } else { 1.0 };
                let center = [
                    from[0] + self.mm(ci.unwrap_or(0.0)) * sign(ia),
                    from[1] + self.mm(cj.unwrap_or(0.0)) * sign(ib),
                ];
                let r0 = geo::dist(from, center);
                let r1 = geo::dist(to, center);
                if r0 < 1e-9 || (r0 - r1).abs() > self.arc_tolerance() {
                    return None;
                }
                Some(Path::Arc {
                    from,
                    to,
                    center,
                    ccw,
                })
            }
            Motion::LatheCycle(_) => None,
        }
    }

    /// True when a block names an axis of the plane.
    fn names_plane_axis(&self, b: &Block) -> bool {
        let (ia, ib, _) = self.state.modal.plane.axes();
        let axes = [Address::X, Address::Y, Address::Z];
        b.has(axes[ia]) || b.has(axes[ib])
    }

    /// The refusals of behaviour 16.16–16.19, before the block runs.
    fn cutter_checks(&self, b: &Block) -> Result<(), Diagnostic> {
        let now = self.state.cutter;
        // G41/G42 is the mode, or a vector is on (a cancel block's own
        // role, `cancelling`, has none left).
        let vector_on = matches!(now.phase, Phase::StartUp | Phase::Offset);
        let engaged = now.mode != CutterCompensation::Cancel || vector_on;
        let codes = b.codes();
        if engaged
            && let Some(plane) = codes.plane()
            && plane != self.state.modal.plane
        {
            return Err(self.error(
                "cutter-plane",
                b.code_span(crate::syntax::codes::Group::Plane),
                format!(
                    "{}: the plane cannot change while {} is the mode or its vector is on: cancel with G40 first (Fanuc alarm PS0037)",
                    plane.gcode(),
                    now.mode.gcode()
                ),
            ));
        }
        if engaged && let Some(NonModal::PositionOffset(p)) = codes.non_modal() {
            return Err(self.error(
                "cutter-position-offset",
                b.code_span(crate::syntax::codes::Group::NonModal),
                format!(
                    "{}: tool position offset cannot be used in cutter compensation ({}): cancel with G40 first (Fanuc alarm PS0042)",
                    p.gcode(),
                    now.mode.gcode()
                ),
            ));
        }
        if let Some(w) = b.get(Address::CommaC).or_else(|| b.get(Address::CommaR)) {
            let changes = codes.cutter().is_some_and(|c| c != now.mode);
            let why = if changes || !engaged {
                "a chamfer or corner rounding cannot be made in a block that starts, cancels or changes cutter compensation (Fanuc alarm PS0039)"
            } else {
                "a chamfer or corner rounding in cutter compensation is not modelled yet"
            };
            return Err(self.error(
                if changes || !engaged {
                    "cutter-corner-words"
                } else {
                    "corner-not-modelled"
                },
                w.span,
                format!("{}: {why}", w.address.letter()),
            ));
        }
        if codes.non_modal() == Some(NonModal::CornerArc) {
            let on = now.mode != CutterCompensation::Cancel
                && codes.cutter().is_none_or(|c| c == now.mode)
                && matches!(now.phase, Phase::StartUp | Phase::Offset);
            if !on {
                return Err(self.error(
                    "cutter-g39",
                    b.code_span(crate::syntax::codes::Group::NonModal),
                    "G39 (corner arc) works in offset mode only: after a G41/G42 start-up, before G40",
                ));
            }
            if let Some(w) = [Address::X, Address::Y, Address::Z]
                .iter()
                .find_map(|a| b.get(*a))
            {
                return Err(self.error(
                    "cutter-g39",
                    w.span,
                    format!(
                        "{}: a G39 block makes the corner arc only and takes no move (write the move in the next block)",
                        w.address.letter()
                    ),
                ));
            }
        }
        let arc_mode = codes.motion().unwrap_or(self.state.modal.motion).is_arc();
        let direction_block = codes.non_modal() == Some(NonModal::CornerArc)
            || (!arc_mode
                && matches!(
                    codes.cutter(),
                    Some(CutterCompensation::Left | CutterCompensation::Right)
                ));
        if direction_block {
            let (_, _, normal) = self.state.modal.plane.axes();
            let word = [Address::I, Address::J, Address::K][normal];
            if let Some(w) = b.get(word) {
                return Err(self.error(
                    "cutter-ijk",
                    w.span,
                    format!(
                        "{}: the direction of the vector lies in the {} plane, which {} is not a word of",
                        w.address.letter(),
                        self.state.modal.plane.gcode(),
                        w.address.letter()
                    ),
                ));
            }
        }
        if let Some(code) = codes.cutter()
            && b.holds_any(&[Address::I, Address::J, Address::K])
        {
            let arc = codes.motion().unwrap_or(self.state.modal.motion).is_arc();
            if !arc && (code == CutterCompensation::Cancel || self.names_plane_axis(b)) {
                let w = b
                    .get(Address::I)
                    .or_else(|| b.get(Address::J))
                    .or_else(|| b.get(Address::K));
                return Err(self.error(
                    "cutter-ijk",
                    w.map_or(b.span, |w| w.span),
                    format!(
                        "{}: I/J/K in a {} block with a move (the direction of the corner vector) are not modelled yet; offsetlab models them in a G41/G42 block without a move",
                        w.map_or("I", |w| w.address.letter()),
                        code.gcode()
                    ),
                ));
            }
        }
        if matches!(codes.cycle(), Some(CannedCycle::Cycle(_))) && vector_on {
            return Err(self.error(
                "cutter-in-cycle",
                b.code_span(crate::syntax::codes::Group::Cycle),
                format!(
                    "a canned cycle cannot start while the compensation's vector is on ({}): cancel with G40 first (Fanuc ignores cutter compensation in canned cycles)",
                    now.mode.gcode()
                ),
            ));
        }
        Ok(())
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
        self.cutter_checks(b)?;
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
        let ran = if b.holds_only(&MOTION_WORDS, &[Group::Motion])
            && self.state.modal.feed_mode != FeedMode::InverseTime
        {
            self.motion_block(b, out)
        } else {
            self.mill_general(b, out)
        };
        self.state.cutter.vector = saved;
        for m in &mut out.moves[moves_before..] {
            m.from = add3(m.from, saved);
            m.to = add3(m.to, saved);
            if let Some(a) = &mut m.arc {
                a.center = add3(a.center, saved);
            }
        }
        ran?;
        let mode = self.state.cutter.mode;
        // The register is read when the block runs (behaviour 4.12); a block
        // without D or a group 07 code reads the one the block before read,
        // whose value the run cannot have changed.
        let radius = if self.state.cutter.d != self.state.position.d
            || b.holds(Address::D)
            || b.codes().cutter().is_some()
            || b.codes().units().is_some()
        {
            self.cutter_radius()
        } else {
            self.state.cutter.radius
        };
        self.state.cutter.d = self.state.position.d;
        self.state.cutter.radius = radius;
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
        let own = (moves_before..out.moves.len())
            .find_map(|i| self.move_path(&out.moves[i], [0.0; 3]).map(|p| (i, p)));
        let words = Words {
            mode,
            d: self.state.position.d,
            offset: o,
            units: self.units(),
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
                        format!(
                            "{} with D{:02} = 0: no radius, no compensation until a D with a value",
                            code.gcode(),
                            self.state.position.d
                        )
                    });
                }
                return Ok(());
            }
            if let Some((i, path)) = own {
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
                return self.start_up(b, out, ahead, (i, path), words);
            }
            if let Some(d) = self.ijk_direction(b)
                && b.codes().cutter().is_some()
                && !self.state.modal.motion.is_arc()
            {
                self.state.cutter.phase = Phase::StartUp;
                return self.direction_vector(out, d, words, "start-up");
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
            return self.cancel(b, out, own, before, (start, moves_before));
        }
        self.state.cutter.phase = Phase::Offset;
        if let Some((i, path)) = own {
            return self.offset_move(b, out, ahead, (i, path), before, words);
        }
        if let Some(d) = self.ijk_direction(b)
            && b.codes().cutter().is_some()
            && !self.state.modal.motion.is_arc()
        {
            return self.direction_vector(out, d, words, "offset mode");
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

    /// Sets the compensation's vector to `v` (plane) and returns the actual
    /// position with it.
    fn set_cutter_vector(&mut self, v: P2) -> Xyz {
        let (ia, ib, _) = self.state.modal.plane.axes();
        let mut vector = [0.0; 3];
        vector[ia] = v[0];
        vector[ib] = v[1];
        self.state.cutter.vector = vector;
        self.actual()
    }

    /// A start-up block (behaviour 16.3, 16.4): from the programmed start to
    /// the corner its type makes with the next move.
    fn start_up(
        &mut self,
        b: &Block,
        out: &mut Out,
        ahead: &mut dyn Ahead,
        (i, path): (usize, Path),
        words: Words,
    ) -> Result<(), Diagnostic> {
        self.state.cutter.phase = Phase::StartUp;
        let t = match self.setup.settings.cutter_start_up() {
            CutterStartUp::A => Type::A,
            CutterStartUp::B => Type::B,
        };
        let o = words.offset;
        let next = self.cutter_next(ahead, out);
        let (rule, next_path) = match next {
            Next::Move { path: n, .. } => (Rule::StartUp(t), Some(n)),
            Next::Unknown(why) => {
                self.look_ahead_note(b, out, why);
                (Rule::Perpendicular, None)
            }
        };
        let next_for_corner = next_path.unwrap_or(path);
        let corner = self.corner_or_alarm(b, &path, &next_for_corner, o, o, rule)?;
        out.note(|| crc::start_up_note(&words, t, &corner, &path, next_path.as_ref()));
        self.apply_corner(b, out, i, &corner, false)
    }

    /// A block in offset mode that moves in the plane (behaviour 16.5–16.10,
    /// 16.12): its end is the corner with the next move.
    fn offset_move(
        &mut self,
        b: &Block,
        out: &mut Out,
        ahead: &mut dyn Ahead,
        (i, path): (usize, Path),
        before: crc::CutterState,
        words: Words,
    ) -> Result<(), Diagnostic> {
        let o = words.offset;
        let t = match self.setup.settings.cutter_start_up() {
            CutterStartUp::A => Type::A,
            CutterStartUp::B => Type::B,
        };
        let outside = match self.setup.settings.cutter_outside_corner() {
            CutterOutsideCorner::Vectors => Outside::Vectors,
            CutterOutsideCorner::Arc => Outside::Arc,
        };
        let next = self.cutter_next(ahead, out);
        let (corner, next_path, o2, cancels) = match next {
            Next::Move {
                path: n,
                offset: 0.0,
            } => {
                let c = self.corner_or_alarm(b, &path, &n, o, o, Rule::Cancel(t))?;
                (c, n, o, true)
            }
            Next::Move { path: n, offset } => {
                // The corner is made with this block's radius on both
                // sides: a new D counts from the next block's end
                // (behaviour 16.8).
                let o2 = o.abs() * offset.signum();
                let c = self.corner_or_alarm(b, &path, &n, o, o2, Rule::Offset(outside))?;
                (c, n, o2, false)
            }
            Next::Unknown(why) => {
                self.look_ahead_note(b, out, why);
                let c = self.corner_or_alarm(b, &path, &path, o, o, Rule::Perpendicular)?;
                (c, path, o, false)
            }
        };
        out.note(|| {
            if cancels {
                crc::before_cancel_note(&words, t, &corner, &path, &next_path)
            } else {
                crc::corner_note(&words, &corner, &path, &next_path, o2)
            }
        });
        if before.radius != self.state.cutter.radius {
            out.note(|| format!(
                "the radius changed from {} to {}: this block starts on the old offset and ends on the new one",
                show(before.radius.abs(), self.units()),
                show(self.state.cutter.radius.abs(), self.units())
            ));
        }
        self.apply_corner(b, out, i, &corner, true)
    }

    /// The corner by `rule`, or the alarm when an intersection it needs
    /// does not exist (behaviour 16.12: Fanuc PS0033).
    fn corner_or_alarm(
        &self,
        b: &Block,
        prev: &Path,
        next: &Path,
        o1: f64,
        o2: f64,
        rule: Rule,
    ) -> Result<Corner, Diagnostic> {
        geo::corner(prev, next, o1, o2, rule).map_err(|NoIntersection| {
            self.error(
                "cutter-no-intersection",
                b.span,
                format!(
                    "the offset paths of this block and the next do not meet at their inside corner: the tool of radius {} cannot reach it (Fanuc alarm PS0033)",
                    show(o1.abs(), self.units())
                ),
            )
        })
    }

    /// Says why the corner at this block's end is not known, and warns when
    /// the control cannot see the next move (behaviour 16.9).
    fn look_ahead_note(&self, b: &Block, out: &mut Out, why: Why) {
        let text = match why {
            Why::End => "the program ends: no next move in the plane".to_string(),
            Why::Error => "the next block cannot run (its error stops the run there)".to_string(),
            Why::Return => {
                "a reference return or canned cycle follows: the compensation is cancelled for it"
                    .to_string()
            }
            Why::CornerArc => "G39 follows: its arc turns the corner".to_string(),
            Why::CancelHere => "the next block cancels without a move".to_string(),
            Why::TooFar(n) => {
                let msg = format!(
                    "no move in the plane within the next {} blocks: the control cannot see the corner, so the tool ends perpendicular to this block and the next move starts from there (overcut or undercut at the corner; setting cutter_blocks_without_motion = {n})",
                    n + 1
                );
                out.warnings.push(Diagnostic::warning(
                    "cutter-look-ahead",
                    b.span,
                    msg.clone(),
                ));
                msg
            }
        };
        out.note(|| text);
    }

    /// Makes move `i` of the block end at the corner's first point and adds
    /// its other steps; checks the move for interference when `check`
    /// (offset mode: behaviour 16.12).
    fn apply_corner(
        &mut self,
        b: &Block,
        out: &mut Out,
        i: usize,
        corner: &Corner,
        check: bool,
    ) -> Result<(), Diagnostic> {
        let p1 = self.in_plane(self.state.programmed);
        let Some(first) = corner.steps().first() else {
            return Ok(());
        };
        let e = first.end();
        let end = self.set_cutter_vector([e[0] - p1[0], e[1] - p1[1]]);
        self.finish_offset_move(b, out, i, end, check)?;
        let kind = match self.state.modal.motion {
            Motion::Rapid => MoveKind::Rapid,
            Motion::Linear | Motion::Arc(_) | Motion::LatheCycle(_) => MoveKind::Feed,
        };
        for step in &corner.steps()[1..] {
            let from = self.mark();
            let e = step.end();
            self.set_cutter_vector([e[0] - p1[0], e[1] - p1[1]]);
            match *step {
                Step::Line(_) => self.emit(out, from, kind, kind == MoveKind::Feed, None),
                Step::Arc { center, ccw, .. } => {
                    let info = self.corner_arc_info(from, center, ccw)?;
                    let kind = if info.sweep > 0.0 {
                        MoveKind::ArcCcw
                    } else {
                        MoveKind::ArcCw
                    };
                    self.emit(out, from, kind, true, Some(info));
                }
            }
        }
        Ok(())
    }

    /// Ends move `i` at `end` (actual): a straight move as it is, an arc
    /// about its programmed centre with the offset radius; with `check`,
    /// the interference check (behaviour 16.12).
    fn finish_offset_move(
        &self,
        b: &Block,
        out: &mut Out,
        i: usize,
        end: Xyz,
        check: bool,
    ) -> Result<(), Diagnostic> {
        let (ia, ib, _) = self.state.modal.plane.axes();
        let m = out.moves[i];
        let p = |x: Xyz| [x[ia], x[ib]];
        let interferes;
        let mut arc_info = None;
        let mut kind = m.kind;
        if let Some(info) = m.arc {
            // The actual centre is the programmed one carried by the
            // vectors other than the compensation's (constant in an arc
            // block: G45–G48 are refused, the length offset cannot change
            // in G02/G03).
            let shift = self.other_vectors();
            let c = [
                info.programmed_center[ia] + shift[ia],
                info.programmed_center[ib] + shift[ib],
            ];
            let ccw = info.programmed_sweep > 0.0;
            let (a0, a1) = (p(m.from), p(end));
            let (r0, r1) = (geo::dist(a0, c), geo::dist(a1, c));
            let tol = self.arc_tolerance();
            if r0 < 1e-6 || r1 < 1e-6 {
                return Err(self.error(
                    "cutter-arc-center",
                    b.span,
                    format!(
                        "the offset arc's {} is its centre: the tool radius equals the arc's radius {} (Fanuc alarm PS0038)",
                        if r0 < 1e-6 { "start" } else { "end" },
                        show(info.programmed_radius, self.units())
                    ),
                ));
            }
            if (r0 - r1).abs() > tol {
                return Err(self.error(
                    "cutter-arc-radius",
                    b.span,
                    format!(
                        "the offset arc starts {} and ends {} from its centre (difference over {}): the compensation radius changed in an arc block (change D on a straight move)",
                        show(r0, self.units()),
                        show(r1, self.units()),
                        show(tol, self.units())
                    ),
                ));
            }
            let circle = arc::from_center(a0, a1, c, ccw, tol).map_err(|_| {
                self.error("cutter-arc-radius", b.span, "the offset arc cannot be made")
            })?;
            let path = Path::Arc {
                from: p(m.programmed_from),
                to: p(m.programmed_to),
                center: p(info.programmed_center),
                ccw,
            };
            let offset_radius = path
                .offset_radius(self.cutter_offset(self.state.cutter.mode, self.state.cutter.radius))
                .unwrap_or(r0);
            interferes = geo::arc_interferes(info.programmed_sweep, circle.sweep, offset_radius);
            let mut center = m.from;
            center[ia] = c[0];
            center[ib] = c[1];
            arc_info = Some(ArcInfo {
                center,
                radius: circle.radius,
                sweep: circle.sweep,
                start_angle: circle.start_angle,
                ..info
            });
            kind = if circle.sweep > 0.0 {
                MoveKind::ArcCcw
            } else {
                MoveKind::ArcCw
            };
        } else {
            interferes = geo::line_reverses(
                (p(m.programmed_from), p(m.programmed_to)),
                (p(m.from), p(end)),
            );
        }
        if check && interferes {
            let what = if m.arc.is_some() {
                "the tool does not fit this arc: its offset path runs the other way round"
            } else {
                "the offset path of this block runs against its programmed direction"
            };
            match self.setup.settings.cutter_interference_check {
                CutterInterference::Alarm => {
                    return Err(self.error(
                        "cutter-interference",
                        b.span,
                        format!(
                            "interference: {what}; the tool would cut into the part — alarm PS0041 stops the program here (the path is drawn up to the block before)"
                        ),
                    ));
                }
                CutterInterference::Off => {
                    out.warnings.push(Diagnostic::warning(
                        "cutter-interference",
                        b.span,
                        format!(
                            "interference: {what}; with the check off (setting cutter_interference_check) the tool cuts into the part here"
                        ),
                    ));
                    out.note(|| format!("interference: {what} (check off: overcut)"));
                }
            }
        }
        let m = &mut out.moves[i];
        m.to = end;
        m.kind = kind;
        if arc_info.is_some() {
            m.arc = arc_info;
        }
        Ok(())
    }

    /// Actual − programmed now, less the compensation's vector: what the
    /// other offsets carry.
    fn other_vectors(&self) -> Xyz {
        sub3(
            sub3(self.actual(), self.state.programmed),
            self.state.cutter.vector,
        )
    }

    /// The radius check's tolerance (behaviour 2.13).
    fn arc_tolerance(&self) -> f64 {
        match self.units() {
            crate::setup::Units::Mm => 0.01,
            crate::setup::Units::Inch => 0.0005 * 25.4,
        }
    }

    /// The arc of a corner (G39, or setting cutter_outside_corner = arc)
    /// from `from` about the programmed corner `center` to where the tool
    /// stands now: the programmed path stays at the corner.
    fn corner_arc_info(&self, from: Mark, center: P2, ccw: bool) -> Result<ArcInfo, Diagnostic> {
        let plane = self.state.modal.plane;
        let (ia, ib, _) = plane.axes();
        let to = self.actual();
        // The actual centre: the corner carried by every vector but the
        // compensation's.
        let other = self.other_vectors();
        let c = [center[0] + other[ia], center[1] + other[ib]];
        let (a0, a1) = ([from.act[ia], from.act[ib]], [to[ia], to[ib]]);
        let circle = arc::from_center(a0, a1, c, ccw, self.arc_tolerance()).map_err(|_| {
            self.error(
                "cutter-arc-radius",
                self.span,
                "the corner arc cannot be made (its ends are not the radius from the corner)",
            )
        })?;
        let mut actual_center = from.act;
        actual_center[ia] = c[0];
        actual_center[ib] = c[1];
        let mut programmed_center = from.prog;
        programmed_center[ia] = center[0];
        programmed_center[ib] = center[1];
        Ok(ArcInfo {
            plane,
            center: actual_center,
            programmed_center,
            radius: circle.radius,
            programmed_radius: 0.0,
            sweep: circle.sweep,
            programmed_sweep: circle.sweep,
            start_angle: circle.start_angle,
            programmed_start_angle: circle.start_angle,
            diameter_x: false,
        })
    }

    /// G39 (behaviour 16.14): an arc of the compensation radius about the
    /// corner, from the vector perpendicular to the last block (where it
    /// ended, since the look-ahead saw the G39) to the vector perpendicular
    /// to the next move, or to the direction I/J/K give; clockwise with
    /// the tool on the left.
    fn corner_arc(
        &mut self,
        b: &Block,
        out: &mut Out,
        ahead: &mut dyn Ahead,
        words: Words,
    ) -> Result<(), Diagnostic> {
        self.state.cutter.phase = Phase::Offset;
        let o = words.offset;
        let dir = match self.ijk_direction(b) {
            Some(d) => d,
            None => match self.cutter_next(ahead, out) {
                Next::Move { path, .. } => path.start_tangent(),
                Next::Unknown(_) => {
                    return Err(self.error(
                        "cutter-g39",
                        b.span,
                        "G39 without I/J/K needs the next move in the plane for the arc's end, and none follows",
                    ));
                }
            },
        };
        let p = self.in_plane(self.state.programmed);
        let n = geo::left(dir);
        let from = self.mark();
        self.set_cutter_vector([n[0] * o, n[1] * o]);
        let info = self.corner_arc_info(from, p, o < 0.0)?;
        let kind = if info.sweep > 0.0 {
            MoveKind::ArcCcw
        } else {
            MoveKind::ArcCw
        };
        out.note(|| format!(
            "G39: an arc of radius {} about the corner {} turns the tool {} to {} of the next move ({:.1}°)",
            show(o.abs(), self.units()),
            self.corner_name(p),
            if o < 0.0 { "counter-clockwise" } else { "clockwise" },
            crc::which(o),
            info.sweep.abs().to_degrees()
        ));
        self.emit(out, from, kind, true, Some(info));
        Ok(())
    }

    /// "X50.000 Y0.000": a plane point as the control writes it.
    fn corner_name(&self, p: P2) -> String {
        let (ia, ib, _) = self.state.modal.plane.axes();
        let names = ['X', 'Y', 'Z'];
        format!(
            "{}{} {}{}",
            names[ia],
            show(p[0], self.units()),
            names[ib],
            show(p[1], self.units())
        )
    }

    /// G41/G42 with I/J/K and no move (behaviour 16.14): the vector is the
    /// offset perpendicular to the direction they give, made in this block
    /// as offset motion.
    fn direction_vector(
        &mut self,
        out: &mut Out,
        d: P2,
        words: Words,
        what: &str,
    ) -> Result<(), Diagnostic> {
        let from = self.mark();
        let n = geo::left(d);
        let o = words.offset;
        self.set_cutter_vector([n[0] * o, n[1] * o]);
        let at_feed = self.state.modal.motion == Motion::Linear;
        self.emit(out, from, MoveKind::Offset, at_feed, None);
        out.note(|| format!(
            "{} ({what}) with I/J/K: the tool centre goes {} {} of the direction they give, perpendicular to it",
            words.name(),
            show(o.abs(), self.units()),
            crc::which(o)
        ));
        Ok(())
    }

    /// A block that turns the compensation off (G40 or D00) while its
    /// vector is on (behaviour 16.10, 16.11).
    fn cancel(
        &mut self,
        b: &Block,
        out: &mut Out,
        own: Option<(usize, Path)>,
        before: crc::CutterState,
        (start, moves_before): (Mark, usize),
    ) -> Result<(), Diagnostic> {
        let code = if self.state.cutter.mode == CutterCompensation::Cancel {
            "G40".to_string()
        } else {
            format!("D{:02} (0)", self.state.position.d)
        };
        if let Some((i, path)) = own {
            if path.is_arc() {
                return Err(self.error(
                    "cutter-arc",
                    b.span,
                    format!(
                        "{code} cancels in a {} block: compensation is cancelled on a G00 or G01 move (Fanuc alarm PS0034)",
                        self.state.modal.motion.gcode()
                    ),
                ));
            }
            let end = self.set_cutter_vector([0.0, 0.0]);
            out.moves[i].to = end;
            self.state.cutter.phase = Phase::Cancelling;
            out.note(|| format!(
                "{code} cancel: the tool leaves the offset path and ends on the programmed point {}",
                self.corner_name(self.in_plane(self.state.programmed))
            ));
            return Ok(());
        }
        let here = b.codes().cutter() == Some(CutterCompensation::Cancel) || b.has(Address::D);
        if here
            && self.setup.settings.cutter_cancel_without_motion() == CutterCancelWithoutMotion::Move
        {
            let v = before.vector;
            let end = self.set_cutter_vector([0.0, 0.0]);
            self.state.cutter.phase = Phase::Cancelling;
            if out.moves.len() > moves_before
                && let Some(m) = out.moves.last_mut()
            {
                m.to = end;
            } else {
                let at_feed = self.state.modal.motion == Motion::Linear;
                self.emit(out, start, MoveKind::Offset, at_feed, None);
            }
            let (ia, ib, _) = self.state.modal.plane.axes();
            let names = ['X', 'Y', 'Z'];
            out.note(|| format!(
                "{code} without a move in the plane: the tool moves back by the vector {}{} {}{} onto the programmed point in this block",
                names[ia],
                crate::geometry::show_signed(-v[ia], self.units()),
                names[ib],
                crate::geometry::show_signed(-v[ib], self.units())
            ));
            return Ok(());
        }
        // Haas: the vector stays until the next move in the plane.
        self.state.cutter.phase = Phase::Offset;
        if here {
            out.note(|| format!(
                "{code} without a move in the plane: the vector stays until the next move in the plane cancels it (setting cutter_cancel_without_motion = next_move)"
            ));
        }
        Ok(())
    }

    /// G27, G28, G30 or G53 naming an axis of the plane in offset mode
    /// (behaviour 16.18): the vector comes off on the way to the
    /// intermediate point (G53: to its point), and the next move in the
    /// plane starts compensation up again.
    fn cutter_return(
        &mut self,
        out: &mut Out,
        moves_before: usize,
        before: crc::CutterState,
    ) -> Result<(), Diagnostic> {
        let v = before.vector;
        self.set_cutter_vector([0.0, 0.0]);
        for (k, m) in out.moves[moves_before..].iter_mut().enumerate() {
            if k > 0 {
                m.from = sub3(m.from, v);
            }
            m.to = sub3(m.to, v);
        }
        self.state.cutter.phase = Phase::Cancel;
        out.note(|| format!(
            "{}: the compensation is cancelled for this return (on the way to its first point) and starts up again at the next move in the plane",
            self.state.cutter.mode.gcode()
        ));
        Ok(())
    }
}

fn sub3(a: Xyz, b: Xyz) -> Xyz {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn add3(a: Xyz, b: Xyz) -> Xyz {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}
