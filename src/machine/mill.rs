//! The milling machine's block: linear and circular motion, G28, G92, and the
//! two mill offsets — tool length (G43/G44/G49, spec 3) and tool position
//! (G45–G48, spec 4).

use super::MoveKind;
use super::modal::{ArcDirection, Distance, LengthOffset, Motion, Plane};
use super::{AXES, ArcRequest, Machine, Out};
use crate::diag::Diagnostic;
use crate::geometry::Xyz;
use crate::offsets::length::LengthState;
use crate::offsets::position;
use crate::setup::LengthOffsetWithoutZ;
use crate::syntax::Address;
use crate::syntax::Block;
use crate::syntax::codes::{CannedCycle, Code, Group, NonModal, PositionOffset};

/// The words of a block that only moves: sequence number, G codes of group
/// 01, axes, arc centre and radius, feed ([`Machine::motion_block`]).
const MOTION_WORDS: [Address; 10] = [
    Address::N,
    Address::G,
    Address::X,
    Address::Y,
    Address::Z,
    Address::I,
    Address::J,
    Address::K,
    Address::R,
    Address::F,
];

impl Machine {
    pub(super) fn mill_block(&mut self, b: &Block, out: &mut Out) -> Result<(), Diagnostic> {
        if b.holds_only(&MOTION_WORDS, &[Group::Motion]) {
            return self.motion_block(b, out);
        }
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
        self.common_words(b, out);
        let c = b.codes();
        if let Some(t) = b.get(Address::T) {
            self.state.next_tool = t.int();
        }
        if let Some(d) = b.get(Address::D) {
            let n = d.int() as u16;
            self.state.position.d = n;
            self.state.position.value = self.mm(self.setup.mill_value(n));
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

        match c.non_modal() {
            Some(NonModal::Dwell) => return self.dwell(b, out),
            Some(NonModal::SetCoordinates) => return self.g92(b),
            Some(NonModal::ReferenceReturn) => return self.g28(b, out),
            Some(NonModal::PositionOffset(code)) => {
                return self.position_offset_block(b, code, out);
            }
            None => {}
        }
        let old_length = self.length_words(b, out)?;
        match self.state.modal.cycle {
            Some(cycle) => self.cycle_block(b, cycle, out, old_length),
            None => self.mill_motion(b, out, old_length, None),
        }
    }

    /// A block of motion words alone (most blocks of a CAM program): what
    /// [`Machine::mill_block`] does with it, without the steps that cannot
    /// apply (its other G codes, M, S, T, D, H words, U/W): the feed, the
    /// motion mode, then the move (callgrind: a seventh of the machine's
    /// instructions went to those steps).
    fn motion_block(&mut self, b: &Block, out: &mut Out) -> Result<(), Diagnostic> {
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

    /// G43/G44/G49 and H (spec 3). Returns the state before the block.
    fn length_words(&mut self, b: &Block, out: &mut Out) -> Result<LengthState, Diagnostic> {
        let code = b.codes().length();
        let h = b.get(Address::H);
        let old = self.state.length;
        if code.is_none() && h.is_none() {
            return Ok(old);
        }
        if self.state.modal.motion.is_arc() && (code.is_some() || old.sign != 0) {
            // Spec 3.7 (YASNAC J50M): no length offset change in G02/G03 mode.
            let span = code.map_or_else(
                || self.word_span(b, Address::H),
                |_| b.code_span(Group::Length),
            );
            return Err(self.error(
                "length-offset-in-arc",
                span,
                format!(
                    "the tool length offset cannot change while {} is active (spec 3.7): command G00 or G01 first",
                    self.state.modal.motion.gcode()
                ),
            ));
        }
        let h = h.map(|w| {
            let n = w.int() as u16;
            (n, self.mm(self.setup.mill_value(n)))
        });
        self.state.length.command(code, h);
        if let Some(cd) = code {
            self.state.modal.length = cd;
        }
        let l = self.state.length;
        if let Some(cd @ (LengthOffset::Add | LengthOffset::Subtract)) = code
            && l.sign != 0
            && l.h == 0
        {
            // Not an error (H00 reads 0), but rarely what was meant.
            out.warnings.push(Diagnostic::warning(
                "length-offset-h00",
                b.code_span(Group::Length),
                format!(
                    "{} with H00: register 00 reads 0, so no length offset applies",
                    cd.gcode()
                ),
            ));
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
        let length_changed = changed(&old_length, &self.state.length);
        let motion = self.state.modal.motion;
        let incremental = self.state.modal.distance == Distance::Incremental;
        let words: [Option<f64>; 3] = AXES.map(|(a, _)| b.value(a));
        let any_axis = words.iter().any(Option::is_some);
        let arc_words = motion.is_arc()
            && [Address::I, Address::J, Address::K, Address::R]
                .iter()
                .any(|a| b.has(*a));
        let setting = self.setup.settings.length_offset_without_z;

        if !any_axis && !arc_words {
            if length_changed {
                let start = self.mark();
                if setting == LengthOffsetWithoutZ::Move {
                    self.state.length.vector = self.state.length.target;
                }
                self.length_note(old_length, None, out);
                let at_feed = motion == Motion::Linear;
                self.emit(out, start, MoveKind::Offset, at_feed, None);
            }
            return Ok(());
        }

        let start = self.mark();
        let mut target = self.state.programmed;
        let mut amount = [0.0; 3];
        for (axis, w) in words.iter().enumerate() {
            if let Some(v) = w {
                target[axis] = self.target(axis, self.mm(*v), incremental);
                amount[axis] = target[axis] - self.state.programmed[axis];
            }
        }

        // Spec 4.1–4.6: every axis word's amount changed on its own.
        let mut delta = [0.0; 3];
        let mut register = 0.0;
        if let Some(code) = pos {
            let d = self.state.position.d;
            register = self.mm(self.setup.mill_value(d));
            self.state.position.value = register;
            for (axis, w) in words.iter().enumerate() {
                if w.is_some() {
                    delta[axis] = position::change(
                        code,
                        amount[axis],
                        register,
                        incremental,
                        self.mirror[axis],
                    );
                    let note = self.position_note(
                        code,
                        AXES[axis].1,
                        amount[axis],
                        delta[axis],
                        d,
                        register,
                        incremental,
                    );
                    out.notes.push(note);
                }
            }
        }

        // Spec 3: a Z word lands on the offset target; otherwise a changed
        // target moves Z now (setting `move`) or waits for the next Z move.
        let new_length =
            if words[2].is_some() || (length_changed && setting == LengthOffsetWithoutZ::Move) {
                self.state.length.target
            } else {
                self.state.length.vector
            };

        if let Motion::Arc(direction) = motion {
            let planned = Planned {
                start,
                target,
                amount,
                delta,
                register,
                new_length,
            };
            return self.arc_move(b, direction, out, old_length, pos, words, planned);
        }

        let kind = if motion == Motion::Linear {
            MoveKind::Feed
        } else {
            MoveKind::Rapid
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

    /// Ends a G02/G03 move (spec 2; with G45–G48, spec 4.8): solves the
    /// arc from R or I/J/K, updates the position and the vectors, notes what
    /// the length offset did and records the move. Kept out of line: inlined
    /// in [`Machine::mill_motion`], its locals made every straight move's
    /// stack frame larger (callgrind: about a hundred instructions a block).
    #[allow(clippy::too_many_arguments)]
    #[inline(never)]
    fn arc_move(
        &mut self,
        b: &Block,
        direction: ArcDirection,
        out: &mut Out,
        old_length: LengthState,
        pos: Option<PositionOffset>,
        words: [Option<f64>; 3],
        planned: Planned,
    ) -> Result<(), Diagnostic> {
        let Planned {
            start,
            target,
            amount,
            delta,
            register,
            new_length,
        } = planned;
        let motion = self.state.modal.motion;
        let centre_words = [Address::I, Address::J, Address::K].map(|a| b.value(a));
        let mut req = ArcRequest {
            target,
            ..ArcRequest::default()
        };
        let (ia, ib, _) = self.state.modal.plane.axes();
        req.ccw = (direction == ArcDirection::Ccw) != (self.mirror[ia] != self.mirror[ib]);
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
            let r_mm = self.mm(r.value);
            let dr = pos.map_or(0.0, |code| position::radius_change(code, r_mm, register));
            if let Some(code) = pos {
                out.notes.push(format!(
                    "{}: R {} becomes {} (R changed as a radius)",
                    gname(code),
                    self.fmt(r_mm),
                    self.fmt(r_mm + dr)
                ));
            }
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
                if let Some(code) = pos {
                    // Spec 4.8: I/J/K are incremental amounts, changed like axis words.
                    let dc = position::change(code, off, register, true, self.mirror[i]);
                    req.center_change[i] = dc;
                    out.notes.push(format!(
                        "{}: {} {} becomes {}",
                        gname(code),
                        ['I', 'J', 'K'][i],
                        self.fmt(off),
                        self.fmt(off + dc)
                    ));
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
    /// a copy on the stack (callgrind: 1 M of 202 M instructions).
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

    /// A block with G45–G48 (spec 4.9, 4.10).
    fn position_offset_block(
        &mut self,
        b: &Block,
        code: PositionOffset,
        out: &mut Out,
    ) -> Result<(), Diagnostic> {
        let machine = self.setup.machine;
        for other in b.codes().each() {
            let allowed = match other {
                Code::NonModal(_) | Code::Motion(_) | Code::Distance(_) => true,
                Code::Plane(_)
                | Code::FeedMode(_)
                | Code::Units(_)
                | Code::CutterCompensation(_)
                | Code::Length(_)
                | Code::Cycle(_)
                | Code::Return(_)
                | Code::Work(_)
                | Code::SurfaceSpeed(_) => false,
            };
            if !allowed {
                return Err(self.error(
                    "position-offset-g-code",
                    b.code_span(other.group()),
                    format!(
                        "{} cannot share a block with {}: only G00–G03 and G90/G91 may (seed 003: an input error occurs)",
                        other.gcode(machine),
                        code.gcode()
                    ),
                ));
            }
        }
        if let Some(cycle) = self.state.modal.cycle {
            return Err(self.error(
                "position-offset-in-cycle",
                b.code_span(Group::NonModal),
                format!(
                    "{} cannot be programmed while canned cycle {} is active (seed 003): cancel it with G80 first",
                    code.gcode(),
                    cycle.gcode()
                ),
            ));
        }
        if !AXES.iter().any(|(a, _)| b.has(*a)) {
            return Err(self.error(
                "position-offset-without-axis",
                b.code_span(Group::NonModal),
                format!(
                    "{} needs an axis word to extend or reduce (spec 4.9); for a move by the offset alone write X0 in G91 (seed 003)",
                    code.gcode()
                ),
            ));
        }
        let old_length = self.length_words(b, out)?;
        self.mill_motion(b, out, old_length, Some(code))
    }

    /// G92 X… Y… Z…: sets the programmed position; the G45–G48 vector on each
    /// named axis is cancelled first (spec 4.7, seed 003).
    fn g92(&mut self, b: &Block) -> Result<(), Diagnostic> {
        if !AXES.iter().any(|(a, _)| b.has(*a)) {
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

    /// G28: to the intermediate point, then to the reference position on the
    /// named axes; the length and position vectors are cleared on the axes
    /// that reach it, and G43/G44 applies again at the next Z move (spec 2).
    fn g28(&mut self, b: &Block, out: &mut Out) -> Result<(), Diagnostic> {
        if !AXES.iter().any(|(a, _)| b.has(*a)) {
            return Err(self.error(
                "g28-without-axis",
                b.span,
                "G28 needs the axes to return (for example G91 G28 Z0)",
            ));
        }
        // A length offset commanded here applies at the next Z move: the
        // return clears the Z vector anyway.
        self.length_words(b, out)?;
        let incremental = self.state.modal.distance == Distance::Incremental;
        let start = self.mark();
        let mut named = [false; 3];
        for (axis, (a, _)) in AXES.iter().enumerate() {
            if let Some(v) = b.value(*a) {
                named[axis] = true;
                self.state.programmed[axis] = self.target(axis, self.mm(v), incremental);
            }
        }
        self.emit(out, start, MoveKind::Rapid, false, None);
        let start = self.mark();
        let reference = self.setup.reference.to_array();
        let mut cleared = Vec::new();
        for axis in 0..3 {
            if !named[axis] {
                continue;
            }
            let had = self.state.position.vector[axis] != 0.0
                || (axis == 2 && self.state.length.vector != 0.0);
            self.state.position.vector[axis] = 0.0;
            if axis == 2 {
                self.state.length.vector = 0.0;
            }
            self.state.programmed[axis] =
                self.setup.units.mm() * reference[axis] - self.origin[axis];
            if had {
                cleared.push(AXES[axis].1.to_string());
            }
        }
        self.emit(out, start, MoveKind::Rapid, false, None);
        if !cleared.is_empty() {
            let mut note = format!(
                "G28: offset vectors cleared on {} at the reference position",
                cleared.join(", ")
            );
            if named[2] && self.state.length.target != 0.0 {
                note.push_str(&format!(
                    "; G4{} H{:02} stays active and applies again at the next Z move",
                    if self.state.length.sign > 0 { 3 } else { 4 },
                    self.state.length.h
                ));
            }
            out.notes.push(note);
        }
        Ok(())
    }

    /// The sentence for one axis changed by G45–G48 (spec 6's example:
    /// "G47: X move 50.000 extended by 2 × D01 (6.000) to 62.000").
    #[allow(clippy::too_many_arguments)]
    fn position_note(
        &self,
        code: PositionOffset,
        axis: char,
        m: f64,
        delta: f64,
        d: u16,
        v: f64,
        incremental: bool,
    ) -> String {
        let g = gname(code);
        if delta == 0.0 && !incremental && m.abs() <= 1e-9 {
            return format!(
                "{g}: {axis} target is the current position, so {axis} is not changed (spec 4.5)"
            );
        }
        let verb = if position::factor(code) > 0.0 {
            "extended"
        } else {
            "reduced"
        };
        let twice = if position::factor(code).abs() == 2.0 {
            "2 × "
        } else {
            ""
        };
        let mut s = format!(
            "{g}: {axis} move {} {verb} by {twice}D{d:02} ({}) to {}",
            self.fmt(m),
            self.fmt(v),
            self.fmt(m + delta)
        );
        if m.abs() <= 1e-9 {
            s.push_str(" (a zero move goes by the offset alone, seed 003)");
        } else if (m + delta) * m < 0.0 {
            s.push_str(" — the move reverses (spec 4.3)");
        }
        s
    }

    /// The sentence for what the length offset did in this block (spec 3).
    /// `z_amount` is the programmed Z movement when the block moved along Z.
    /// Nearly every block leaves the offset as it was: that test is inlined
    /// where the machine calls this, the sentence is written out of line.
    #[inline]
    pub(super) fn length_note(&self, old: LengthState, z_amount: Option<f64>, out: &mut Out) {
        let new = self.state.length;
        let mode_changed = new.sign != old.sign || new.h != old.h || new.target != old.target;
        if mode_changed || new.vector - old.vector != 0.0 {
            self.write_length_note(old, mode_changed, z_amount, out);
        }
    }

    #[inline(never)]
    fn write_length_note(
        &self,
        old: LengthState,
        mode_changed: bool,
        z_amount: Option<f64>,
        out: &mut Out,
    ) {
        let new = self.state.length;
        let vector_change = new.vector - old.vector;
        let label = if mode_changed {
            if new.target == 0.0 && old.target != 0.0 {
                if new.sign == 0 {
                    "G49 cancels the tool length offset".to_string()
                } else {
                    "H00 cancels the tool length offset".to_string()
                }
            } else if new.sign == 0 {
                "G49: no tool length offset".to_string()
            } else {
                let g = if new.sign > 0 { "G43" } else { "G44" };
                let how = if new.sign > 0 { "adds" } else { "subtracts" };
                if old.sign == new.sign && old.h != new.h && old.h != 0 {
                    format!(
                        "H{:02} → H{:02} while {g} is active ({} → {})",
                        old.h,
                        new.h,
                        self.fmt(old.value),
                        self.fmt(new.value)
                    )
                } else {
                    format!("{g} {how} H{:02} ({})", new.h, self.fmt(new.value))
                }
            }
        } else {
            format!(
                "this Z move applies the pending length offset H{:02} ({})",
                new.h,
                self.fmt_signed(new.target)
            )
        };
        let effect = match z_amount {
            Some(m) if self.state.modal.distance == Distance::Incremental => {
                format!("the Z move {} becomes {}", self.fmt(m), self.fmt(m + vector_change))
            }
            Some(_) => format!(
                "Z target {} lands at {}",
                self.fmt(self.state.programmed[2]),
                self.fmt(self.actual()[2])
            ),
            None if vector_change != 0.0 => {
                if old.vector != 0.0 && new.vector != 0.0 {
                    format!("no Z word: Z moves by the difference, {} (seed 001)", self.fmt_signed(vector_change))
                } else {
                    format!("no Z word: Z moves by {} (seed 001)", self.fmt_signed(vector_change))
                }
            }
            None if new.target != new.vector => {
                "no Z word: no motion now; the next Z move lands offset (setting length_offset_without_z = next_z)"
                    .to_string()
            }
            None if old.vector == 0.0 => "no motion (no length vector was applied)".to_string(),
            None => "no motion".to_string(),
        };
        out.notes.push(format!("{label}: {effect}"));
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
    /// The G45–G48 register value (mm), or 0.
    register: f64,
    /// The length vector at the end of the move.
    new_length: f64,
}

/// True if a block changed the length offset mode, number or target.
pub(super) fn changed(old: &LengthState, new: &LengthState) -> bool {
    old.target != new.target || old.sign != new.sign || old.h != new.h
}

/// "G45" … "G48" with the manual's meaning.
fn gname(code: PositionOffset) -> String {
    format!("{} ({})", code.gcode(), position::meaning(code))
}
