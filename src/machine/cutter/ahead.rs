//! Cutter compensation reads the next move in the plane (behaviour 16.9):
//! worked out from the words of a plain move, else on a copy of the
//! machine, past the blocks that make no move in the plane.

use super::{Next, Why, add3, returns, sub3};
use crate::machine::arc::{self};
use crate::machine::words::MOTION_WORDS;
use crate::machine::{Ahead, Machine, NoneAhead, Out};
use crate::offsets::cutter::geometry::{self as geo, Path};
use crate::setup::CutterCancelWithoutMotion;
use crate::syntax::codes::{CannedCycle, CutterCompensation, Group, Motion, NonModal};
use crate::syntax::{Address, Block};

impl Machine {
    /// Reads ahead to the next move in the plane (behaviour 16.9): the
    /// blocks after this one run on a copy of the machine, as the machine
    /// will run them, until one moves in the plane, past at most
    /// `cutter_blocks_without_motion` blocks that do not.
    pub(super) fn cutter_next(&self, ahead: &mut dyn Ahead, out: &mut Out) -> Next {
        let offset = self.cutter_offset(self.state.cutter.mode, self.state.cutter.radius);
        self.cutter_next_with(ahead, out, offset)
    }

    /// [`Machine::cutter_next`] where the block has worked out its offset
    /// (`offset`, from the mode and register it read).
    pub(super) fn cutter_next_with(
        &self,
        ahead: &mut dyn Ahead,
        out: &mut Out,
        offset: f64,
    ) -> Next {
        // A plain move next (most blocks) needs no copy and no scratch.
        if let Some(next) = ahead.peek(0)
            && next.macros.is_none()
            && let Some(path) = self.plain_next_path(next, self.state.modal.motion)
        {
            // A plain move reads the register this block read.
            return Next::Move { path, offset };
        }
        if let Some(next) = self.plain_past_still(ahead) {
            return next;
        }
        let mut scratch = out.scratch.take().unwrap_or_default();
        scratch.quiet = true;
        let next = self.read_next(ahead, &mut scratch);
        out.scratch = Some(scratch);
        next
    }

    /// [`Machine::cutter_next`] where the words alone do not tell: the
    /// blocks run on a copy of the machine.
    fn read_next(&self, ahead: &mut dyn Ahead, scratch: &mut Out) -> Next {
        let limit = usize::from(self.setup.settings.cutter_blocks_without_motion());
        let mut probe = self.clone();
        probe.reading_ahead = true;
        // The copy wants programmed moves: no vector to solve arcs with,
        // and plain moves take the fast path.
        probe.state.cutter.vector = [0.0; 3];
        // After a `,C`/`,R` corner the next block runs from the virtual
        // corner and its move starts at the cut's end (behaviour 2.32,
        // 16.19): the copy keeps the corner for it (and sets its end
        // when it runs from there).
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
            if next.macros.is_some() {
                return Next::Unknown(Why::Macro(next.span.line));
            }
            let codes = next.codes();
            match codes.non_modal() {
                Some(NonModal::CornerArc) => return Next::Unknown(Why::CornerArc),
                Some(code) if returns(code) && self.names_plane_axis(next) => {
                    return Next::Unknown(Why::Return);
                }
                _ => {}
            }
            // A lathe cycle compensates itself from its start point, where
            // the vector is taken off (behaviour 18.11, 18.15).
            if matches!(codes.cycle(), Some(CannedCycle::Cycle(_))) || probe.nose_cycle_block(next)
            {
                return Next::Unknown(Why::Return);
            }
            let before = probe.state.cutter;
            let radius_before = probe.cutter_radius();
            // G40 with I/J/K and a move (behaviour 16.14): the block before
            // ends on the direction they give from its end, as if a block
            // went on that way in the mode and radius it has.
            if codes.cutter() == Some(CutterCompensation::Cancel)
                && before.mode != CutterCompensation::Cancel
                && !codes.motion().unwrap_or(probe.state.modal.motion).is_arc()
                && probe.names_plane_axis(next)
                && let Some(d) = probe.ijk_direction(next)
            {
                let shift = sub3(probe.state.coords.zero, self.state.coords.zero);
                let at = self.in_plane(add3(probe.state.programmed, shift));
                let path = Path::Line {
                    from: at,
                    to: [at[0] + d[0], at[1] + d[1]],
                };
                let offset = probe.cutter_offset(before.mode, radius_before);
                return Next::Move { path, offset };
            }
            scratch.clear();
            let index = self.index.saturating_add(1 + k as u32);
            let flow = match probe.execute(
                next,
                index,
                scratch,
                &mut NoneAhead,
                &mut crate::machine::program::NoText,
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
            if flow == crate::machine::Flow::End {
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
    pub(super) fn plain_next_path(&self, b: &Block, motion: Motion) -> Option<Path> {
        // The lathe's blocks (diameter X, U/W) are read on the copy.
        // After a `,C`/`,R` corner the words count from the virtual
        // corner (behaviour 2.32): read on the copy.
        if b.error
            || self.corner_cut
            || self.nose_lathe()
            || !self.plain_words
            || self.state.modal.cycle.is_some()
            || !b.holds_only(&MOTION_WORDS, &[Group::Motion])
        {
            return None;
        }
        let motion = b.codes().motion().unwrap_or(motion);
        let (ia, ib, _) = self.state.modal.plane.axes();
        let incremental = self.state.modal.distance == crate::machine::modal::Distance::Incremental;
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
                let ccw = (direction == crate::machine::modal::ArcDirection::Ccw)
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

    /// The next move past plain G00/G01 blocks that make no move in the
    /// plane (a Z step between two laps of a contour), worked out from
    /// their words as [`Machine::plain_next_path`] does, without the copy
    /// of the machine: what the copy would find, or None where only the
    /// copy can tell (then it reads them). A block passed over this way
    /// changes nothing the next block's path depends on but the motion
    /// mode (no code but group 01's, no plane coordinate changed).
    fn plain_past_still(&self, ahead: &mut dyn Ahead) -> Option<Next> {
        // The lathe's blocks (diameter X, U/W) are read on the copy, and
        // so are the blocks after a `,C`/`,R` corner (behaviour 2.32).
        if self.nose_lathe() || self.corner_cut {
            return None;
        }
        // The copy stops at a block that takes the tool beyond any
        // machine's travel (an error): far within it, none can.
        let small = |v: f64| v.abs() <= 1e6;
        let s = &self.state;
        // In G93 a block without F fails (behaviour 14.8): the copy tells.
        if s.modal.feed_mode == crate::machine::modal::FeedMode::InverseTime {
            return None;
        }
        if !(self.actual().iter().all(|v| small(*v))
            && s.programmed.iter().all(|v| small(*v))
            && s.cutter.vector.iter().all(|v| small(*v))
            && small(s.length.target)
            && small(s.length.vector))
        {
            return None;
        }
        // The copy reads the register again at each block.
        let radius = self.cutter_radius();
        if radius == 0.0 {
            return None;
        }
        let limit = usize::from(self.setup.settings.cutter_blocks_without_motion());
        let mut motion = self.state.modal.motion;
        for k in 0..=limit {
            let b = ahead.peek(k)?;
            if b.macros.is_some() {
                return None;
            }
            if let Some(m) = self.plain_still(b, motion, small) {
                motion = m;
                continue;
            }
            if k == 0 || !self.plain_within(b, small) {
                return None;
            }
            let path = self.plain_next_path(b, motion)?;
            let offset = self.cutter_offset(self.state.cutter.mode, radius);
            return Some(Next::Move { path, offset });
        }
        None
    }

    /// The motion mode after `b` when it is a plain G00/G01 block (in mode
    /// `motion` before it) that cannot fail and makes no move in the plane:
    /// no arc words, its plane coordinates the ones the tool stands on, its
    /// other axis within `small`. None otherwise.
    fn plain_still(
        &self,
        b: &Block,
        motion: Motion,
        small: impl Fn(f64) -> bool,
    ) -> Option<Motion> {
        if b.error
            || !self.plain_words
            || self.state.modal.cycle.is_some()
            || !b.holds_only(&MOTION_WORDS, &[Group::Motion])
            || b.holds_any(&[Address::I, Address::J, Address::K, Address::R])
        {
            return None;
        }
        let motion = b.codes().motion().unwrap_or(motion);
        if !matches!(motion, Motion::Rapid | Motion::Linear) || !self.plain_within(b, &small) {
            return None;
        }
        let (ia, ib, _) = self.state.modal.plane.axes();
        let incremental = self.state.modal.distance == crate::machine::modal::Distance::Incremental;
        let axes = [Address::X, Address::Y, Address::Z];
        for (axis, address) in axes.into_iter().enumerate() {
            if let Some(v) = b.value(address) {
                let t = self.target(axis, self.mm(v), incremental);
                if (axis == ia || axis == ib) && t != self.state.programmed[axis] {
                    return None;
                }
            }
        }
        Some(motion)
    }

    /// True when every axis word of `b` takes its axis to a point within
    /// `small` (the tool stands within it: no block after it can fail for
    /// its travel).
    fn plain_within(&self, b: &Block, small: impl Fn(f64) -> bool) -> bool {
        let incremental = self.state.modal.distance == crate::machine::modal::Distance::Incremental;
        let axes = [Address::X, Address::Y, Address::Z];
        axes.into_iter().enumerate().all(|(axis, address)| {
            b.value(address)
                .is_none_or(|v| small(self.target(axis, self.mm(v), incremental)))
        })
    }
}
