//! What G39, G41/G42 with I/J/K, G40 without a move and the returns do in
//! cutter compensation (behaviour 16.11, 16.14, 16.18).
use super::{Next, sub3};

use crate::diag::Diagnostic;
use crate::geometry::show;
use crate::machine::arc::{self, P2};
use crate::machine::{Ahead, ArcInfo, Machine, Mark, MoveKind, Out};
use crate::offsets::cutter::geometry::{self as geo, Path};
use crate::offsets::cutter::{self as crc, Phase, Words};
use crate::setup::CutterCancelWithoutMotion;
use crate::syntax::codes::{CutterCompensation, Motion};
use crate::syntax::{Address, Block};

impl Machine {
    /// The arc of a corner (G39, or setting cutter_outside_corner = arc)
    /// from `from` about the programmed corner `center` to where the tool
    /// stands now: the programmed path stays at the corner.
    pub(super) fn corner_arc_info(
        &self,
        from: Mark,
        center: P2,
        ccw: bool,
    ) -> Result<ArcInfo, Diagnostic> {
        let plane = self.state.modal.plane;
        let (ia, ib, _) = plane.axes();
        let to = self.actual();
        // The actual centre: the corner carried by every vector but the
        // compensation's.
        // In the plane's scale (the lathe's X a radius), the imaginary
        // tool nose's arc about the corner moved by the tip's shift
        // (behaviour 18.2).
        let other = self.other_vectors();
        let s = self.plane_scale();
        let tip = self.nose_tip();
        let c = [
            center[0] + other[ia] * s[0] + tip[0],
            center[1] + other[ib] * s[1] + tip[1],
        ];
        let (a0, a1) = (
            [from.act[ia] * s[0], from.act[ib] * s[1]],
            [to[ia] * s[0], to[ib] * s[1]],
        );
        let circle = arc::from_center(a0, a1, c, ccw, self.arc_tolerance()).map_err(|_| {
            self.error(
                "cutter-arc-radius",
                self.span,
                "the corner arc cannot be made (its ends are not the radius from the corner)",
            )
        })?;
        let mut actual_center = from.act;
        actual_center[ia] = c[0] / s[0];
        actual_center[ib] = c[1] / s[1];
        let mut programmed_center = from.prog;
        programmed_center[ia] = center[0] / s[0];
        programmed_center[ib] = center[1] / s[1];
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
            diameter_x: self.nose_lathe(),
        })
    }

    /// G39 (behaviour 16.14): an arc of the compensation radius about the
    /// corner, from the vector perpendicular to the last block (where it
    /// ended, since the look-ahead saw the G39) to the vector perpendicular
    /// to the next move, or to the direction I/J/K give; clockwise with
    /// the tool on the left.
    pub(super) fn corner_arc(
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
    /// On the lathe X is written as the diameter it is programmed in.
    pub(super) fn corner_name(&self, p: P2) -> String {
        let (ia, ib, _) = self.state.modal.plane.axes();
        let names = ['X', 'Y', 'Z'];
        let s = self.plane_scale();
        format!(
            "{}{} {}{}",
            names[ia],
            show(p[0] / s[0], self.units()),
            names[ib],
            show(p[1] / s[1], self.units())
        )
    }

    /// A G41/G42 block with I/J/K (behaviour 16.14): the vector goes
    /// perpendicular to the direction they give, the offset's length to
    /// the left (G41) or right (G42). Without a move in the plane it is
    /// made at once as offset motion; with one (`own`, the move's index)
    /// the move ends on it — Fanuc's IJ-type vector (15i-MA, "If I, J,
    /// and K are specified in G00/G01 mode block"): no intersection with
    /// the next block and, at the start-up, whatever the start-up type.
    pub(super) fn direction_vector(
        &mut self,
        out: &mut Out,
        d: P2,
        words: Words,
        (what, own): (&str, Option<usize>),
    ) -> Result<(), Diagnostic> {
        let from = self.mark();
        let n = geo::left(d);
        let o = words.offset;
        let end = self.set_cutter_vector([n[0] * o, n[1] * o]);
        let whole = match own {
            Some(i) => {
                out.moves[i].to = end;
                "the block ends"
            }
            None => {
                let at_feed = self.state.modal.motion == Motion::Linear;
                self.emit(out, from, MoveKind::Offset, at_feed, None);
                "the tool centre goes"
            }
        };
        out.note(|| format!(
            "{} ({what}) with I/J/K: {whole} {} {} of the direction they give, perpendicular to it{}",
            words.name(),
            show(o.abs(), self.units()),
            crc::which(o),
            if own.is_some() {
                ", without an intersection with the next block (the IJ-type vector)"
            } else {
                ""
            }
        ));
        Ok(())
    }

    /// A block that turns the compensation off (G40 or D00) while its
    /// vector is on (behaviour 16.10, 16.11).
    pub(super) fn cancel(
        &mut self,
        b: &Block,
        out: &mut Out,
        own: Option<(usize, Path)>,
        before: crc::CutterState,
        (start, moves_before): (Mark, usize),
    ) -> Result<(), Diagnostic> {
        let code = if self.state.cutter.mode == CutterCompensation::Cancel {
            "G40".to_string()
        } else if self.nose_lathe() {
            format!("offset {:02} (nose radius 0)", self.state.lathe.offset)
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
            if b.codes().cutter() == Some(CutterCompensation::Cancel)
                && self.ijk_direction(b).is_some()
            {
                out.note(|| {
                    "with I/J/K: the block before ended where its offset path meets the offset of the direction they give from its end point, as if a block went on that way (behaviour 16.14)".to_string()
                });
            }
            return Ok(());
        }
        let here = b.codes().cutter() == Some(CutterCompensation::Cancel) || b.has(Address::D);
        if here
            && self.setup.settings.cutter_cancel_without_motion() == CutterCancelWithoutMotion::Move
        {
            let v = before.vector;
            let at_feed = self.state.modal.motion == Motion::Linear;
            self.leave_offset_path(out, (start, moves_before), MoveKind::Offset, at_feed);
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
        if self.setup.settings.control == crate::setup::Control::Linuxcnc
            && b.holds_any(&[Address::X, Address::Y, Address::Z])
        {
            // LinuxCNC: the move after a G40 alone leaves the offset path
            // even when it moves no axis of the plane or its programmed end
            // is where it starts (rs274 -g on tests/linuxcnc/a06_comp_entry_arc.ngc
            // and a07_comp_exit_z.ngc; behaviour 22.16).
            let kind = match self.state.modal.motion {
                Motion::Rapid => MoveKind::Rapid,
                _ => MoveKind::Feed,
            };
            self.leave_offset_path(out, (start, moves_before), kind, kind == MoveKind::Feed);
            out.note(|| format!("{code} cancel: the tool leaves the offset path for the programmed point, where this block's move already is"));
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

    /// The vector comes off in a cancel without a move of its own in the
    /// plane: the block's last move (if it made one) ends on the programmed
    /// point, else a move of `kind` takes the tool there from `start`.
    fn leave_offset_path(
        &mut self,
        out: &mut Out,
        (start, moves_before): (Mark, usize),
        kind: MoveKind,
        at_feed: bool,
    ) {
        let end = self.set_cutter_vector([0.0, 0.0]);
        self.state.cutter.phase = Phase::Cancelling;
        if out.moves.len() > moves_before
            && let Some(m) = out.moves.last_mut()
        {
            m.to = end;
        } else {
            self.emit(out, start, kind, at_feed, None);
        }
    }

    /// G27, G28, G30 or G53 naming an axis of the plane in offset mode
    /// (behaviour 16.18): the vector comes off on the way to the
    /// intermediate point (G53: to its point), and the next move in the
    /// plane starts compensation up again.
    pub(super) fn cutter_return(
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
