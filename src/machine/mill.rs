//! The milling machine's block: linear and circular motion, G28, G92. The
//! two mill offsets' rules and sentences are their families' —
//! [`crate::offsets::length`] (G43/G44/G49, behaviour 3) and
//! [`crate::offsets::position`] (G45–G48, behaviour 4); this file moves the tool
//! by them.

use super::MoveKind;
use super::corner::CORNER_WORDS;
use super::modal::{ArcDirection, Distance, FeedMode, Motion, Plane};
use super::{AXES, Ahead, ArcRequest, Machine, Out};
use crate::diag::Diagnostic;
use crate::geometry::Xyz;
use crate::offsets::length::{LengthState, LengthWords, ZAfter};
use crate::offsets::position::{self, PositionChange};
use crate::setup::LengthOffsetWithoutZ;
use crate::syntax::Address;
use crate::syntax::Block;
use crate::syntax::codes::{CannedCycle, Group, NonModal, PositionOffset};

use super::words::MOTION_WORDS;

// Modules of the machine's, declared here where their one call is (the
// machine's module list is at its file's line limit).
#[path = "linuxcnc_dwell.rs"]
mod linuxcnc_dwell;
#[path = "linuxcnc_motion.rs"]
mod linuxcnc_motion;
#[path = "linuxcnc_offsets.rs"]
pub(super) mod linuxcnc_offsets;
#[path = "linuxcnc_polar.rs"]
mod linuxcnc_polar;

impl Machine {
    /// A mill block. `ahead` gives the blocks after it to the rules that need
    /// the next move: the chamfer and corner words `,C`/`,R` (`corner.rs`)
    /// and cutter radius compensation (`cutter/`), which every block
    /// passes through while G41/G42 is the mode or a vector is on.
    pub(super) fn mill_block(
        &mut self,
        b: &Block,
        out: &mut Out,
        ahead: &mut dyn Ahead,
        program: &mut dyn super::program::ProgramText,
    ) -> Result<(), Diagnostic> {
        // While cutter compensation is engaged `special` is set: every
        // block goes through the compensation below.
        if !self.special && b.holds_only(&MOTION_WORDS, &[Group::Motion]) {
            return self.motion_block(b, out);
        }
        if self.setup.settings.control == crate::setup::Control::Linuxcnc {
            self.linuxcnc_motion_mode(b)?;
        }
        // LinuxCNC's `@` `^` become the block's X and Y (behaviour 22.12);
        // only its profile reads them. Its G4 dwells, then moves by the
        // block's axis words (22.13).
        if b.holds_any(&[Address::PolarDist, Address::PolarAngle]) {
            return self.polar_block(b, out, ahead, program);
        }
        if self.dwell_moves(b)? {
            return self.dwell_then_move(b, out, ahead, program);
        }
        if b.codes().non_modal() == Some(NonModal::Engraving) {
            // Haas G47 reads the text of its block's comment (behaviour 14.20).
            if self.state.cutter.engaged() {
                return Err(self.error(
                    "g47-words",
                    b.code_span(Group::NonModal),
                    "G47 engraves with the tool's centre on the letters' strokes: cancel cutter compensation with G40 first (our convention; Tormach PathPilot's G47 refuses it too)",
                ));
            }
            self.engraving_text = program
                .block_text(b.span)
                .and_then(crate::syntax::first_comment)
                .map(str::to_string);
        }
        if self.state.cutter.engaged() && !self.cutter_after_cancel(b) || super::cutter::concerns(b)
        {
            return self.cutter_block(b, out, ahead);
        }
        if b.holds_any(&CORNER_WORDS) {
            return self.corner_block(b, out, ahead);
        }
        self.mill_general(b, out)
    }

    /// A mill block that is more than motion words (its codes, offsets,
    /// cycles, G28/G92/G04), without look-ahead.
    pub(super) fn mill_general(&mut self, b: &Block, out: &mut Out) -> Result<(), Diagnostic> {
        self.refuse_unmodelled(b)?;
        let lathe_words = b.holds(Address::U) || b.holds(Address::W);
        for w in b.words.iter().filter(|_| lathe_words) {
            if matches!(w.address, Address::U | Address::W) {
                return Err(self.error(
                    "lathe-address",
                    w.span,
                    format!(
                        "{}: U and W are the lathe's incremental axes; the mill uses X, Y, Z and G91",
                        w.address.letter()
                    ),
                ));
            }
        }
        self.refuse_calls(b)?;
        // G10 checks its own words and codes (behaviour 17.10).
        if b.codes().non_modal() == Some(NonModal::DataSetting) {
            return self.data_setting(b, out);
        }
        self.refuse_unused(b, self.mill_path(b))?;
        let before = self.state.modal;
        // A T in the M06 block names the tool that M06 puts in the spindle
        // (Haas "T1 M06", RS274/NGC M6), so it is read before the M codes
        // (behaviour 2.18).
        if let Some(t) = b.get(Address::T) {
            self.state.next_tool = match self.has_tool_table() {
                true => self.table_t_word(t)?,
                false => t.int(),
            };
        }
        self.common_words(b, out)?;
        self.mode_codes(b, out, before)?;
        let c = b.codes();
        if self.state.modal.feed_mode == FeedMode::InverseTime {
            self.check_inverse_time(b)?;
        }
        let linuxcnc = self.setup.settings.control == crate::setup::Control::Linuxcnc;
        if linuxcnc {
            self.linuxcnc_d(b)?;
        }
        if let Some(d) = b
            .get(Address::D)
            .filter(|_| self.state.table_radius.is_none())
        {
            let n = d.int() as u16;
            let value = self.mm(self.setup.d_value(n));
            self.state.position.select(n, value);
        }

        if let (Some(m), Some(CannedCycle::Cycle(cy))) = (c.motion(), c.cycle()) {
            return Err(self.error(
                "motion-and-cycle",
                b.code_span(Group::Cycle),
                format!(
                    "{} and {} in one block: a group 01 code cancels the canned cycle",
                    m.gcode(),
                    cy.gcode()
                ),
            ));
        }
        if let Some(m) = c.motion() {
            self.state.modal.motion = m;
            // A group 01 code cancels the canned cycle (Fanuc/YASNAC M).
            self.cancel_cycle();
        }
        match c.cycle() {
            Some(CannedCycle::Cancel) => self.cancel_cycle(),
            Some(CannedCycle::Cycle(cycle)) => self.start_cycle(cycle),
            None => {}
        }

        let non_modal = c.non_modal();
        if b.holds_any(&[Address::A, Address::B, Address::C]) {
            let set = matches!(
                non_modal,
                Some(NonModal::SetCoordinates | NonModal::MachineCoordinates)
            );
            self.rotary_words(b, set, out);
        }
        let centre_words = self.transform_codes(b, out)?;
        self.work_words(b, out)?;
        if non_modal == Some(NonModal::MachineCoordinates) && self.g53(b, out)? {
            return Ok(());
        }
        match non_modal {
            Some(NonModal::Dwell) => return self.dwell(b, out),
            Some(NonModal::SetCoordinates) => {
                if linuxcnc {
                    self.refuse_in_compensation(
                        b,
                        "sets the G92 offset",
                        "Cannot change axis offsets with cutter radius comp",
                    )?;
                }
                self.g92(b)?;
                if linuxcnc {
                    // #5210–#5213, what G92.3 takes back (behaviour 22.14).
                    self.keep_g92_parameters(true);
                }
                return Ok(());
            }
            Some(NonModal::Stored(code)) => return self.stored_code(b, code, out),
            Some(code @ (NonModal::ReferenceReturn | NonModal::OtherReference)) => {
                return self.mill_reference(b, code, out);
            }
            Some(NonModal::ReferenceCheck) => return self.g27(b, out),
            Some(NonModal::LocalCoordinates) => {
                self.g52(b, out)?;
                let old_length = self.length_words(b, out)?;
                return self.length_only_motion(out, old_length);
            }
            Some(NonModal::PresetCoordinates) => {
                self.g92_1(b, out)?;
                let old_length = self.length_words(b, out)?;
                return self.length_only_motion(out, old_length);
            }
            // G53 in G91 is ignored: the block runs on (behaviour 13.1).
            Some(NonModal::MachineCoordinates) => {}
            Some(NonModal::PositionOffset(code)) => {
                return self.position_offset_block(b, code, out);
            }
            Some(NonModal::Skip) => return self.skip(b, out),
            // The corner arc is cutter compensation's (`cutter/`), which
            // runs the block's other words through here first.
            Some(NonModal::CornerArc) => return Ok(()),
            Some(NonModal::CirclePocket(direction)) => {
                return self.circle_pocket(b, direction, out);
            }
            Some(NonModal::Engraving) => return self.engrave(b, out),
            // Their words and sentences were taken by `mode_codes`; the
            // block moves as any other (behaviour 14).
            Some(
                NonModal::ExactStop
                | NonModal::AiContour
                | NonModal::LookAhead
                | NonModal::Smoothness
                | NonModal::BlockLimit
                | NonModal::Cylindrical,
            )
            | None => {}
            // G70–G76 are the lathe's (on the mill the parser reads those
            // numbers as its canned cycles); G10 was taken above.
            Some(NonModal::Repetitive(_) | NonModal::DataSetting) => {}
        }
        let old_length = self.length_words(b, out)?;
        if centre_words || (linuxcnc && self.axes_are_offsets(b)) {
            // The axis words were G51's, G68's or G51.1's: no axis moves
            // by them (behaviour 13.8–13.10).
            return self.length_only_motion(out, old_length);
        }
        match self.state.modal.cycle {
            Some(cycle) => self.cycle_block(b, cycle, out, old_length),
            None => self.mill_motion(b, out, old_length, None),
        }
    }

    /// A block of motion words alone (most blocks of a CAM program): what
    /// [`Machine::mill_block`] does with it, without the steps that cannot
    /// apply (its other G codes, M, S, T, D, H words, U/W): the feed, the
    /// motion mode, then the move (those steps cost much of the machine's
    /// share of the `check` instruction count in docs/performance.md).
    #[inline(always)]
    pub(super) fn motion_block(&mut self, b: &Block, out: &mut Out) -> Result<(), Diagnostic> {
        // I, J, K and R are read by arcs (and R, K by a canned cycle): in
        // any other block they are refused (behaviour 2.22).
        if b.holds_any(&[Address::I, Address::J, Address::K, Address::R]) {
            let arc = match b.codes().motion() {
                Some(m) => m.is_arc(),
                None => self.state.modal.cycle.is_none() && self.state.modal.motion.is_arc(),
            };
            if !arc {
                self.refuse_unused_motion_words(b)?;
            }
        }
        if let Some(f) = b.value(Address::F) {
            self.state.feed = Some(f);
        }
        if let Some(m) = b.codes().motion() {
            self.state.modal.motion = m;
            // A group 01 code cancels the canned cycle (Fanuc/YASNAC M).
            self.cancel_cycle();
        }
        let old_length = self.state.length;
        match self.state.modal.cycle {
            Some(cycle) => self.cycle_block(b, cycle, out, old_length),
            None => self.mill_motion(b, out, old_length, None),
        }
    }

    /// G43/G44/G49 and H (behaviour 3, [`LengthState::block`]). Returns the
    /// state before the block.
    pub(super) fn length_words(
        &mut self,
        b: &Block,
        out: &mut Out,
    ) -> Result<LengthState, Diagnostic> {
        if self.setup.settings.control == crate::setup::Control::Linuxcnc {
            return self.linuxcnc_length(b);
        }
        let code = b.codes().length();
        let h = b.get(Address::H);
        let old = self.state.length;
        if code.is_none() && h.is_none() {
            return Ok(old);
        }
        let words = LengthWords {
            code: code.map(|c| (c, b.code_span(Group::Length))),
            h: h.map(|w| {
                let n = w.int() as u16;
                (n, w.span, self.mm(self.setup.h_value(n)))
            }),
        };
        let motion = self.state.modal.motion;
        self.state.length.block(words, motion, &mut out.warnings)?;
        if let Some(cd) = code {
            self.state.modal.length = cd;
        }
        Ok(old)
    }

    /// The motion of a block without G28/G92/G04 and outside canned cycles,
    /// with the position offset `pos` (G45–G48) when the block holds one.
    fn mill_motion(
        &mut self,
        b: &Block,
        out: &mut Out,
        old_length: LengthState,
        pos: Option<PositionOffset>,
    ) -> Result<(), Diagnostic> {
        let length_changed = self.state.length.changed_since(&old_length);
        let motion = self.state.modal.motion;
        let incremental = self.state.modal.distance == Distance::Incremental;
        let words: [Option<f64>; 3] = AXES.map(|(a, _)| b.value(a));
        let any_axis = words.iter().any(Option::is_some);
        let arc_words = motion.is_arc()
            && [Address::I, Address::J, Address::K, Address::R]
                .iter()
                .any(|a| b.has(*a));

        if !any_axis && !arc_words {
            return self.length_only_motion(out, old_length);
        }
        if self.state.feed.is_none() && motion != Motion::Rapid {
            self.refuse_feed_without_f(b)?;
        }

        let start = self.mark();
        let mut target = self.state.programmed;
        let mut amount = [0.0; 3];
        if self.plain_words {
            for (axis, w) in words.iter().enumerate() {
                if let Some(v) = w {
                    target[axis] = self.target(axis, self.mm(*v), incremental);
                    amount[axis] = target[axis] - self.state.programmed[axis];
                }
            }
        } else {
            target = self.framed_target(b, incremental, pos.is_some(), out)?;
            for (axis, w) in words.iter().enumerate() {
                if w.is_some() {
                    amount[axis] = target[axis] - self.state.programmed[axis];
                }
            }
        }

        let mut delta = [0.0; 3];
        let change = pos.map(|code| {
            let d = self.state.position.d;
            let register = self.mm(self.setup.d_value(d));
            self.state.position.value = register;
            let change = PositionChange {
                code,
                d,
                register,
                incremental,
                // The offset follows the movement as the mirror image
                // switches and the transformations turn it (behaviour 4.14,
                // 13.7).
                mirror: std::array::from_fn(|i| {
                    self.mirror[i] != (self.state.modal.transforms.axis_factor(i) < 0.0)
                }),
                units: self.units(),
            };
            delta = change.axes(amount, words.map(|w| w.is_some()), &mut out.notes);
            change
        });

        // The setting is read only where it decides (the `check`
        // instruction count in docs/performance.md).
        let new_length = match words[2].is_some() || !length_changed {
            true => {
                let z = words[2].is_some();
                self.state
                    .length
                    .vector_after(z, length_changed, LengthOffsetWithoutZ::Move)
            }
            false => {
                let setting = self.setup.settings.length_offset_without_z();
                self.state.length.vector_after(false, true, setting)
            }
        };

        let kind = match motion {
            Motion::Arc(direction) => {
                let planned = Planned {
                    start,
                    target,
                    amount,
                    delta,
                    change,
                    new_length,
                };
                return self.arc_move(b, direction, out, old_length, words, planned);
            }
            Motion::Linear => MoveKind::Feed,
            // The parser gives the mill no lathe cycle.
            Motion::Rapid | Motion::LatheCycle(_) => MoveKind::Rapid,
        };
        self.finish_line(
            out,
            start,
            target,
            delta,
            new_length,
            kind,
            old_length,
            words[2].is_some(),
        )
    }

    /// A block that changes the length offset and moves no axis by its
    /// words: Z travels the change as offset motion (behaviour 3.3), or
    /// nothing moves.
    pub(super) fn length_only_motion(
        &mut self,
        out: &mut Out,
        old_length: LengthState,
    ) -> Result<(), Diagnostic> {
        if !self.state.length.changed_since(&old_length) {
            return Ok(());
        }
        let setting = self.setup.settings.length_offset_without_z();
        let start = self.mark();
        self.state.length.vector = self.state.length.vector_after(false, true, setting);
        self.length_note(old_length, None, out);
        // Made in the G00/G01 mode; G02/G03 refuse a length change
        // (behaviour 3.7) and the parser gives the mill no lathe cycle.
        let at_feed = match self.state.modal.motion {
            Motion::Linear => true,
            Motion::Rapid | Motion::Arc(_) | Motion::LatheCycle(_) => false,
        };
        self.emit(out, start, MoveKind::Offset, at_feed, None);
        Ok(())
    }

    /// The end point of a motion block whose words go through polar
    /// coordinates or the transformations (behaviour 13.7), with the
    /// sentence that says where they sent it. Out of line: the plain
    /// block's path does not pay for it.
    #[inline(never)]
    fn framed_target(
        &mut self,
        b: &Block,
        incremental: bool,
        position_offset: bool,
        out: &mut Out,
    ) -> Result<Xyz, Diagnostic> {
        if position_offset && self.state.modal.transforms.rotation.is_some() {
            return Err(self.error(
                "position-offset-rotation",
                b.code_span(Group::NonModal),
                "G45–G48 extend or reduce the movement of each axis word, and a rotated movement is no longer along the axes: cancel G68 first (our convention; the manuals say nothing of the two together)",
            ));
        }
        let (target, cmd) = self.program_targets(b, [true; 3], incremental);
        if let Some(note) = self.frame_sentence(b, [true; 3], target) {
            out.notes.push(note);
        }
        self.command = cmd;
        Ok(target)
    }

    /// Ends a G02/G03 move (behaviour 2; with G45–G48, behaviour 4.8): solves the
    /// arc from R or I/J/K, updates the position and the vectors, notes what
    /// the length offset did and records the move. Kept out of line: inlined
    /// in [`Machine::mill_motion`], its locals made every straight move's
    /// stack frame larger (the `check` instruction count in docs/performance.md).
    #[allow(clippy::too_many_arguments)]
    #[inline(never)]
    fn arc_move(
        &mut self,
        b: &Block,
        direction: ArcDirection,
        out: &mut Out,
        old_length: LengthState,
        words: [Option<f64>; 3],
        planned: Planned,
    ) -> Result<(), Diagnostic> {
        let Planned {
            start,
            target,
            amount,
            delta,
            change,
            new_length,
        } = planned;
        let motion = self.state.modal.motion;
        let centre_words = [Address::I, Address::J, Address::K].map(|a| b.value(a));
        let mut req = ArcRequest {
            target,
            ..ArcRequest::default()
        };
        if self.setup.settings.control == crate::setup::Control::Linuxcnc {
            req.turns = self.linuxcnc_arc_words(b, target)?;
        }
        let (ia, ib, _) = self.state.modal.plane.axes();
        req.ccw = (direction == ArcDirection::Ccw) != (self.mirror[ia] != self.mirror[ib]);
        let framed = !self.plain_words;
        if framed {
            req.ccw = req.ccw != self.framed_arc(b)?;
        }
        let mut pv = self.state.position.vector;
        for i in 0..3 {
            pv[i] += delta[i];
        }
        let mut end = [target[0] + pv[0], target[1] + pv[1], target[2] + pv[2]];
        end[2] += new_length;
        req.actual_end = end;
        if let Some(r) = b.get(Address::R) {
            if centre_words.iter().any(Option::is_some) {
                out.warnings.push(Diagnostic::warning(
                    "arc-r-and-center",
                    r.span,
                    "R and I/J/K in one arc: R is used and I/J/K are ignored (Fanuc)",
                ));
            }
            let (ia, ib, _) = self.state.modal.plane.axes();
            let p0 = [self.state.programmed[ia], self.state.programmed[ib]];
            if super::arc::same_point(p0, [target[ia], target[ib]]) {
                out.warnings.push(Diagnostic::warning(
                    "arc-r-no-motion",
                    b.span,
                    "an R arc whose end is its start makes no circle (a full circle needs I/J/K); only the axis across the plane moves",
                ));
                let z_word = words[2].is_some();
                return self.finish_line(
                    out,
                    start,
                    target,
                    delta,
                    new_length,
                    MoveKind::Feed,
                    old_length,
                    z_word,
                );
            }
            let mut r_mm = self.mm(r.value);
            if framed {
                r_mm *= self
                    .state
                    .modal
                    .transforms
                    .radius_factor(self.state.modal.plane);
            }
            let dr = change.map_or(0.0, |c| c.radius(r_mm, &mut out.notes));
            req.radius = Some((r_mm, dr));
        } else {
            let (ia, ib, _) = self.state.modal.plane.axes();
            let in_plane = |i: usize| i == ia || i == ib;
            if !(0..3).any(|i| in_plane(i) && centre_words[i].is_some()) {
                let names = match self.state.modal.plane {
                    Plane::XY => "I/J",
                    Plane::ZX => "K/I",
                    Plane::YZ => "J/K",
                };
                return Err(self.error(
                    "arc-without-center",
                    b.span,
                    format!(
                        "{} needs R or the centre words {names} of the {} plane",
                        motion.gcode(),
                        self.state.modal.plane.gcode()
                    ),
                ));
            }
            if framed {
                self.framed_centres(b, centre_words, change, &mut req, out)?;
            } else {
                for (i, w) in centre_words.iter().enumerate() {
                    let Some(v) = w else { continue };
                    if !in_plane(i) {
                        out.warnings.push(Diagnostic::warning(
                            "arc-center-word",
                            self.word_span(b, [Address::I, Address::J, Address::K][i]),
                            format!(
                                "{} is not a centre word of the {} plane and is ignored",
                                ['I', 'J', 'K'][i],
                                self.state.modal.plane.gcode()
                            ),
                        ));
                        continue;
                    }
                    let mut off = self.mm(*v);
                    if self.mirror[i] {
                        off = -off;
                    }
                    req.center[i] = off;
                    if let Some(c) = change {
                        req.center_change[i] = c.center(i, off, &mut out.notes);
                    }
                }
            }
        }
        let info = self.arc_geometry(b, &req)?;
        self.state.programmed = target;
        self.state.position.vector = pv;
        self.state.length.vector = new_length;
        self.length_note(
            old_length,
            Some(amount[2]).filter(|_| words[2].is_some()),
            out,
        );
        let kind = if info.sweep > 0.0 {
            MoveKind::ArcCcw
        } else {
            MoveKind::ArcCw
        };
        self.emit(out, start, kind, true, Some(info));
        Ok(())
    }

    /// Ends a straight move: updates the position and the vectors, notes
    /// what the length offset did and records the move. Inlined where it is
    /// called: the target then goes to the state from registers, not through
    /// a copy on the stack (the `check` instruction count in docs/performance.md).
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn finish_line(
        &mut self,
        out: &mut Out,
        start: super::Mark,
        target: Xyz,
        delta: Xyz,
        new_length: f64,
        kind: MoveKind,
        old_length: LengthState,
        z_word: bool,
    ) -> Result<(), Diagnostic> {
        let z_amount = z_word.then_some(target[2] - start.prog[2]);
        self.state.programmed = target;
        for (i, d) in delta.iter().enumerate() {
            self.state.position.vector[i] += d;
        }
        self.state.length.vector = new_length;
        self.length_note(old_length, z_amount, out);
        self.emit(out, start, kind, kind == MoveKind::Feed, None);
        Ok(())
    }

    /// A block with G45–G48 (behaviour 4, [`position::check_block`]).
    fn position_offset_block(
        &mut self,
        b: &Block,
        code: PositionOffset,
        out: &mut Out,
    ) -> Result<(), Diagnostic> {
        let arc = self.state.modal.motion.is_arc();
        position::check_block(b, code, self.setup.machine, self.state.modal.cycle, arc)?;
        let old_length = self.length_words(b, out)?;
        self.mill_motion(b, out, old_length, Some(code))
    }

    /// G31: a G01 move whatever the motion mode, with the skip function's
    /// sentence (behaviour 14.7).
    fn skip(&mut self, b: &Block, out: &mut Out) -> Result<(), Diagnostic> {
        self.skip_note(b, out)?;
        let old_length = self.length_words(b, out)?;
        let mode = self.state.modal.motion;
        self.state.modal.motion = Motion::Linear;
        let moved = self.mill_motion(b, out, old_length, None);
        self.state.modal.motion = mode;
        moved
    }

    /// G92 X… Y… Z…: sets the programmed position; the G45–G48 vector on each
    /// named axis is cancelled first (behaviour 4.7, seed 003).
    fn g92(&mut self, b: &Block) -> Result<(), Diagnostic> {
        self.refuse_in_transforms(b.code_span(Group::NonModal), "G92")?;
        // A rotary word alone sets that axis (behaviour 13.14).
        if !AXES.iter().any(|(a, _)| b.has(*a))
            && !b.holds_any(&[Address::A, Address::B, Address::C])
        {
            return Err(self.error(
                "g92-without-axis",
                b.span,
                "G92 needs the axes whose coordinates it sets",
            ));
        }
        for (axis, (a, _)) in AXES.iter().enumerate() {
            if let Some(v) = b.value(*a) {
                let v = self.mm(v);
                self.set_coordinate(axis, v, true);
            }
        }
        Ok(())
    }

    /// Notes what the length offset did in this block (behaviour 3,
    /// [`LengthState::note`]). `z_amount` is the programmed Z movement when
    /// the block moved along Z.
    #[inline]
    pub(super) fn length_note(&self, old: LengthState, z_amount: Option<f64>, out: &mut Out) {
        if self.state.length.note_due(&old) {
            self.write_length_note(old, z_amount, out);
        }
    }

    #[inline(never)]
    fn write_length_note(&self, old: LengthState, z_amount: Option<f64>, out: &mut Out) {
        if self.setup.settings.control == crate::setup::Control::Linuxcnc {
            if self.state.length.changed_since(&old) {
                self.linuxcnc_length_note(&old, out);
            }
            return;
        }
        let z = ZAfter {
            incremental: self.state.modal.distance == Distance::Incremental,
            programmed: self.state.programmed[2],
            actual: self.actual()[2],
            units: self.units(),
        };
        out.notes.push(self.state.length.note(&old, z_amount, z));
    }
}

/// A motion block's move as its axis words and the offsets plan it, before
/// it is made.
struct Planned {
    /// Where the move starts.
    start: super::Mark,
    /// The programmed end point.
    target: Xyz,
    /// The programmed amount of each axis word.
    amount: Xyz,
    /// What G45–G48 change of each axis's amount.
    delta: Xyz,
    /// What G45–G48 does in this block, if it holds one.
    change: Option<PositionChange>,
    /// The length vector at the end of the move.
    new_length: f64,
}

impl Machine {
    /// A feed move before any F: LinuxCNC refuses it ("Cannot do g1 with
    /// zero feed rate", behaviour 22.4); the Fanuc-family profiles warn
    /// (`missing-feed`) and draw it.
    #[cold]
    #[inline(never)]
    fn refuse_feed_without_f(&self, b: &Block) -> Result<(), Diagnostic> {
        if self.setup.settings.control != crate::setup::Control::Linuxcnc {
            return Ok(());
        }
        Err(self.error(
            "missing-feed",
            b.code_span(crate::syntax::codes::Group::Motion),
            format!(
                "{} with no feed rate: LinuxCNC refuses a feed move before any F (\"Cannot do g1 with zero feed rate\"); write F on this block or before it",
                self.state.modal.motion.gcode()
            ),
        ))
    }
}
