//! The lathe's block (behaviour 5): X as a diameter and Z, U/W incremental, G50,
//! G00–G03 in the ZX plane and the G90/G92/G94 single cycles (G-code system
//! A). The T-code tool position offset's rules and sentences are
//! [`crate::offsets::lathe`]'s; this file moves the tool by them.

use super::modal::{ArcDirection, Distance, LatheCycle, Motion, Plane};
use super::program::ProgramText;
use super::{Ahead, ArcRequest, Machine, Mark, Out};
use super::{EventKind, MoveKind};
use crate::diag::Diagnostic;
use crate::geometry::Xyz;
use crate::offsets::lathe as toffset;
use crate::syntax::codes::{Code, NonModal};
use crate::syntax::{Address, Block};

/// The lathe's turning-cycle data, modal until another group 01 code.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct TurningData {
    /// X target (diameter, mm).
    x: Option<f64>,
    /// Z target (mm).
    z: Option<f64>,
    /// Taper R (mm; radius value for G90/G92, Z for G94).
    r: f64,
}

impl Machine {
    /// A lathe block; `program` is its text, read again by sequence
    /// number for G70–G73 (behaviour 15.3). `ahead` gives the blocks after
    /// it to tool nose radius compensation, which reads the next move
    /// (behaviour 18, the mill's compensation in `cutter/`).
    pub(super) fn lathe_block(
        &mut self,
        b: &Block,
        out: &mut Out,
        ahead: &mut dyn Ahead,
        program: &mut dyn ProgramText,
    ) -> Result<(), Diagnostic> {
        if self.passing_over() {
            self.pass_over(b, out);
            return Ok(());
        }
        if self.nose_cycle_block(b) {
            return self.nose_cycle_run(b, out, program);
        }
        if (self.state.cutter.engaged() && !self.cutter_after_cancel(b))
            || super::cutter::concerns(b)
        {
            return self.cutter_block(b, out, ahead);
        }
        if b.holds_any(&super::corner::CORNER_WORDS) {
            return self.corner_block(b, out, ahead);
        }
        self.lathe_run(b, out, program)
    }

    /// A lathe block as it runs without tool nose radius compensation's
    /// corners (the compensation runs it so, then moves its end).
    pub(super) fn lathe_run(
        &mut self,
        b: &Block,
        out: &mut Out,
        program: &mut dyn ProgramText,
    ) -> Result<(), Diagnostic> {
        self.refuse_polar(b)?;
        self.refuse_unmodelled(b)?;
        // A G71/G72/G74–G76 block's D is its depth (behaviour 15.2); in
        // polar coordinate interpolation J is an arc's centre and Y Haas's
        // hypothetical axis (behaviour 14.15).
        let cycle_d = matches!(b.codes().non_modal(), Some(NonModal::Repetitive(_)));
        let polar = self.in_polar_mode(b);
        for w in &b.words {
            let polar_word = polar
                && (w.address == Address::J
                    || (w.address == Address::Y && self.polar_axis() == Address::Y));
            if (matches!(w.address, Address::Y | Address::J | Address::H) && !polar_word)
                || (w.address == Address::D && !cycle_d)
            {
                let why = match w.address {
                    Address::D | Address::H => {
                        "the lathe takes its offsets from T codes (seed 004)"
                    }
                    _ => "the lathe has the axes X (diameter) and Z, with U and W incremental",
                };
                return Err(self.error(
                    "mill-address",
                    w.span,
                    format!("{}: {why}", w.address.letter()),
                ));
            }
        }
        self.refuse_calls(b)?;
        // G10 checks its own words and codes (behaviour 17.10).
        if b.codes().non_modal() == Some(NonModal::DataSetting) {
            return self.data_setting(b, out);
        }
        self.refuse_unused(b, self.lathe_path(b))?;
        let before = self.state.modal;
        self.common_words(b, out)?;
        self.mode_codes(b, out, before)?;
        self.work_words(b, out)?;
        let c = b.codes();
        if c.non_modal() == Some(NonModal::Dwell) {
            return self.dwell(b, out);
        }
        for (abs, inc) in [(Address::X, Address::U), (Address::Z, Address::W)] {
            if let (Some(a), Some(w)) = (b.get(abs), b.get(inc)) {
                // At the second word written.
                let at = if a.span.start > w.span.start { a } else { w };
                return Err(self.error(
                    "axis-conflict",
                    at.span,
                    format!(
                        "{} and {} both set the {} target in one block: write one of them",
                        abs.letter(),
                        inc.letter(),
                        abs.letter()
                    ),
                ));
            }
        }
        if let Some(m) = c.motion() {
            self.state.modal.motion = m;
            if let Motion::LatheCycle(_) = m {
                self.turning = TurningData::default();
            }
        }
        if self.state.polar.is_some() {
            return self.polar_move(b, out);
        }
        let positioning = matches!(
            c.non_modal(),
            Some(
                NonModal::ReferenceCheck
                    | NonModal::OtherReference
                    | NonModal::LocalCoordinates
                    | NonModal::MachineCoordinates
            )
        );
        if let Some(t) = b.get(Address::T).filter(|_| positioning) {
            return Err(self.error(
                "t-in-positioning",
                t.span,
                "a T code goes in a block of its own or with a move, not with G27, G30, G52 or G53",
            ));
        }
        let mut skip = false;
        match c.non_modal() {
            Some(NonModal::SetCoordinates) => return self.g50(b),
            Some(code @ (NonModal::ReferenceReturn | NonModal::OtherReference)) => {
                return self.lathe_reference(b, code, out);
            }
            Some(NonModal::ReferenceCheck) => return self.g27(b, out),
            Some(NonModal::LocalCoordinates) => return self.g52(b, out),
            Some(NonModal::MachineCoordinates) => {
                self.g53(b, out)?;
                return Ok(());
            }
            Some(NonModal::PresetCoordinates) => return self.g92_1(b, out),
            Some(NonModal::Repetitive(cycle)) => return self.repetitive(b, cycle, out, program),
            // G31 moves as G01 whatever the mode (behaviour 14.7).
            Some(NonModal::Skip) => {
                self.skip_note(b, out)?;
                skip = true;
            }
            // G04 was made above and G10 before; G45–G48, G09, G05.1, G08,
            // G187 and the pockets are the mill's, refused by the parser on
            // the lathe.
            Some(
                NonModal::DataSetting
                | NonModal::Stored(_)
                | NonModal::Dwell
                | NonModal::PositionOffset(_)
                | NonModal::ExactStop
                | NonModal::AiContour
                | NonModal::LookAhead
                | NonModal::Smoothness
                | NonModal::BlockLimit
                | NonModal::Cylindrical
                | NonModal::CirclePocket(_)
                | NonModal::Engraving
                // G39 is not in the lathe's table.
                | NonModal::CornerArc,
            )
            | None => {}
        }
        let t_changed = self.t_code(b, out);
        let motion = if skip {
            Motion::Linear
        } else {
            self.state.modal.motion
        };
        let any_axis = [Address::X, Address::U, Address::Z, Address::W]
            .iter()
            .any(|a| b.has(*a));
        let arc_words = motion.is_arc()
            && [Address::I, Address::K, Address::R]
                .iter()
                .any(|a| b.has(*a));
        if let Motion::LatheCycle(cycle) = motion
            && (any_axis || b.has(Address::R))
        {
            return self.turning_cycle(b, cycle, out, t_changed);
        }
        if !any_axis && !arc_words {
            if t_changed {
                let at_feed = toffset::offset_motion_at_feed(
                    motion,
                    self.state.table(),
                    self.word_span(b, Address::T),
                )?;
                let start = self.mark();
                let old = self.state.lathe.vector;
                self.state.lathe.vector = self.state.lathe.target;
                let d = self.sub_xz(self.state.lathe.vector, old);
                let units = self.units();
                out.notes
                    .push(self.state.lathe.motion_note(d, at_feed, units));
                self.emit(out, start, MoveKind::Offset, at_feed, None);
            }
            return Ok(());
        }
        let start = self.mark();
        let mut target = self.state.programmed;
        for axis in [0, 2] {
            if let Some(v) = self.lathe_target(b, axis) {
                target[axis] = v;
            }
        }
        let moved = [
            b.has(Address::X) || b.has(Address::U),
            false,
            b.has(Address::Z) || b.has(Address::W),
        ];
        let old_vector = self.state.lathe.vector;
        let vector = self.state.lathe.vector_after_move(t_changed, moved);
        // As on the mill, an R arc from a point to itself has no centre: a
        // warning, and the block moves like G01 (only an offset change can
        // move the tool then).
        let p0 = self.state.programmed;
        let r_without_chord = motion.is_arc()
            && b.has(Address::R)
            && super::arc::same_point([p0[0] / 2.0, p0[2]], [target[0] / 2.0, target[2]]);
        if r_without_chord {
            out.warnings.push(Diagnostic::warning(
                "arc-r-no-motion",
                b.span,
                "an R arc whose end is its start makes no circle (a full circle needs I and K); the block makes no arc",
            ));
        }
        if motion.is_arc() && self.state.modal.plane != Plane::ZX {
            // G17 is the face plane of polar coordinate interpolation; a
            // turning arc lies in ZX (behaviour 5.11, 14.15).
            return Err(self.error(
                "arc-plane",
                b.span,
                format!(
                    "{} outside polar coordinate interpolation lies in the ZX plane: select G18 (the plane in force is {}, the face plane of G12.1/G112)",
                    Code::Motion(motion).gcode(self.state.table()),
                    self.state.modal.plane.gcode()
                ),
            ));
        }
        if let Motion::Arc(direction) = motion
            && !r_without_chord
        {
            let mut req = ArcRequest {
                target,
                actual_end: add_xz(target, vector),
                ccw: direction == ArcDirection::Ccw,
                ..ArcRequest::default()
            };
            if let Some(r) = b.get(Address::R) {
                if b.has(Address::I) || b.has(Address::K) {
                    out.warnings.push(Diagnostic::warning(
                        "arc-r-and-center",
                        r.span,
                        "R and I/K in one arc: R is used and I/K are ignored (Fanuc)",
                    ));
                }
                req.radius = Some((self.mm(r.value), 0.0));
            } else {
                if !(b.has(Address::I) || b.has(Address::K)) {
                    return Err(self.error(
                        "arc-without-center",
                        b.span,
                        format!(
                            "{} needs R or the centre words I (radius) and K",
                            Code::Motion(motion).gcode(self.state.table())
                        ),
                    ));
                }
                // I is a radius value on the lathe: the arc geometry works in
                // radius space.
                req.center[0] = self.mm(b.value(Address::I).unwrap_or(0.0));
                req.center[2] = self.mm(b.value(Address::K).unwrap_or(0.0));
            }
            let info = self.arc_geometry(b, &req)?;
            self.state.programmed = target;
            self.state.lathe.vector = vector;
            let kind = if info.sweep > 0.0 {
                MoveKind::ArcCcw
            } else {
                MoveKind::ArcCw
            };
            if t_changed {
                out.notes.push(self.state.lathe.move_note(
                    self.sub_xz(vector, old_vector),
                    true,
                    self.units(),
                ));
            }
            self.emit(out, start, kind, true, Some(info));
            return Ok(());
        }
        self.state.programmed = target;
        self.state.lathe.vector = vector;
        let at_feed = match motion {
            Motion::Linear => true,
            // An R arc without a chord moves like G01.
            Motion::Arc(_) => r_without_chord,
            // The cycles were made above.
            Motion::Rapid | Motion::LatheCycle(_) => false,
        };
        if t_changed {
            out.notes.push(self.state.lathe.move_note(
                self.sub_xz(vector, old_vector),
                at_feed,
                self.units(),
            ));
        }
        let kind = if at_feed {
            MoveKind::Feed
        } else {
            MoveKind::Rapid
        };
        self.emit(out, start, kind, at_feed, None);
        Ok(())
    }

    /// The programmed target (mm) a block's words give `axis` (0: X, 2: Z):
    /// X/Z absolute — incremental in G91, which only G-code systems B and C
    /// have (behaviour 7.18) — and U/W incremental.
    pub(super) fn lathe_target(&self, b: &Block, axis: usize) -> Option<f64> {
        let (abs, inc) = match axis {
            0 => (Address::X, Address::U),
            _ => (Address::Z, Address::W),
        };
        let p = self.state.programmed[axis];
        match (b.value(abs), b.value(inc)) {
            (Some(v), _) if self.state.modal.distance == Distance::Incremental => {
                Some(p + self.mm(v))
            }
            (Some(v), _) => Some(self.mm(v)),
            (None, Some(d)) => Some(p + self.mm(d)),
            (None, None) => None,
        }
    }

    fn sub_xz(&self, a: Xyz, b: Xyz) -> Xyz {
        [a[0] - b[0], 0.0, a[2] - b[2]]
    }

    /// The T word (behaviour 5, [`LatheState::command`]): returns true if the
    /// offset vector the machine should carry changed.
    pub(super) fn t_code(&mut self, b: &Block, out: &mut Out) -> bool {
        let Some(t) = b.get(Address::T) else {
            return false;
        };
        let setup = &self.setup;
        let unit = self.state.modal.units.mm();
        let x_offset = setup.settings.lathe_x_offset;
        let register = |offset| setup.lathe_register(offset);
        let t = self
            .state
            .lathe
            .command(t.int(), register, x_offset, unit, &mut out.notes);
        if let Some(tool) = t.indexed {
            self.event(out, EventKind::ToolIndex { tool });
        }
        t.changed
    }

    /// G50 X… Z…: coordinate system setting; the T offset is kept, so the
    /// position before offset becomes the commanded value (Fanuc T).
    fn g50(&mut self, b: &Block) -> Result<(), Diagnostic> {
        let mut any = false;
        for (axis, abs, inc) in [(0, Address::X, Address::U), (2, Address::Z, Address::W)] {
            let value = match (b.value(abs), b.value(inc)) {
                (Some(v), _) => self.mm(v),
                (None, Some(d)) => self.state.programmed[axis] + self.mm(d),
                (None, None) => continue,
            };
            any = true;
            self.set_coordinate(axis, value, false);
        }
        if !any && !b.has(Address::S) {
            return Err(self.error(
                "g50-without-axis",
                b.span,
                "G50 needs X and Z (coordinate system setting) or S (spindle speed limit)",
            ));
        }
        Ok(())
    }

    /// G90 / G92 / G94 single cycles (system A): four legs from the start
    /// point and back to it.
    fn turning_cycle(
        &mut self,
        b: &Block,
        cycle: LatheCycle,
        out: &mut Out,
        t_changed: bool,
    ) -> Result<(), Diagnostic> {
        let motion = self.state.modal.motion;
        let (x0, z0) = (self.state.programmed[0], self.state.programmed[2]);
        if let Some(x) = self.lathe_target(b, 0) {
            self.turning.x = Some(x);
        }
        if let Some(z) = self.lathe_target(b, 2) {
            self.turning.z = Some(z);
        }
        if let Some(r) = b.value(Address::R) {
            self.turning.r = self.mm(r);
        }
        let (Some(x1), Some(z1)) = (self.turning.x, self.turning.z) else {
            return Err(self.error(
                "cycle-without-target",
                b.span,
                format!(
                    "{} needs X (or U) and Z (or W)",
                    Code::Motion(motion).gcode(self.state.table())
                ),
            ));
        };
        let r = self.turning.r;
        let old_vector = self.state.lathe.vector;
        let legs: [(f64, f64, MoveKind); 4] = match cycle {
            LatheCycle::Turning => [
                (x1 + 2.0 * r, z0, MoveKind::Rapid),
                (x1, z1, MoveKind::Feed),
                (x0, z1, MoveKind::Feed),
                (x0, z0, MoveKind::Rapid),
            ],
            LatheCycle::Threading => [
                (x1 + 2.0 * r, z0, MoveKind::Rapid),
                (x1, z1, MoveKind::Feed),
                (x0, z1, MoveKind::Rapid),
                (x0, z0, MoveKind::Rapid),
            ],
            LatheCycle::Facing => [
                (x0, z1 + r, MoveKind::Rapid),
                (x1, z1, MoveKind::Feed),
                (x1, z0, MoveKind::Feed),
                (x0, z0, MoveKind::Rapid),
            ],
        };
        // In G41/G42 the legs are compensated (behaviour 18.15).
        let done = self.state.cutter.engaged()
            && self.nose_single_cycle(b, cycle, [x0, z0], &legs, out)?;
        for (i, (x, z, kind)) in legs.into_iter().enumerate().filter(|_| !done) {
            let start: Mark = self.mark();
            if i == 0 {
                self.state.lathe.vector = self.state.lathe.target;
            }
            self.state.programmed[0] = x;
            self.state.programmed[2] = z;
            self.emit(out, start, kind, kind == MoveKind::Feed, None);
        }
        if t_changed {
            out.notes.push(self.state.lathe.move_note(
                self.sub_xz(self.state.lathe.vector, old_vector),
                false,
                self.units(),
            ));
        }
        Ok(())
    }
}

fn add_xz(a: Xyz, v: Xyz) -> Xyz {
    [a[0] + v[0], 0.0, a[2] + v[2]]
}
