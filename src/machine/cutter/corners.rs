//! A block in start-up or offset mode ends at its corner with the next move
//! (behaviour 16.3–16.10, 16.12): the corner by the family's rules, the
//! block's move made to end there, the moves the corner adds, the
//! interference check.

use super::{Next, Why, sub3};
use crate::diag::Diagnostic;
use crate::geometry::{Xyz, show};
use crate::machine::arc::{self, P2};
use crate::machine::{Ahead, ArcInfo, Machine, MoveKind, Out};
use crate::offsets::cutter::geometry::{
    self as geo, Corner, NoIntersection, Outside, Path, Rule, Step, Type,
};
use crate::offsets::cutter::{self as crc, Phase, Words};
use crate::setup::{CutterInterference, CutterOutsideCorner, CutterStartUp};
use crate::syntax::Block;
use crate::syntax::codes::Motion;

impl Machine {
    /// Sets the compensation's vector to `v` (plane) and returns the actual
    /// position with it.
    /// On the lathe `v` is the nose centre's offset in radius; the vector
    /// the tool carries is the imaginary tool nose's (`v` plus the tip's
    /// shift while the vector is on, behaviour 18.2), X as a diameter.
    pub(super) fn set_cutter_vector(&mut self, v: P2) -> Xyz {
        let (ia, ib, _) = self.state.modal.plane.axes();
        let mut vector = [0.0; 3];
        if self.nose_lathe() {
            let t = if v == [0.0, 0.0] {
                [0.0, 0.0]
            } else {
                self.nose_tip()
            };
            let s = self.plane_scale();
            vector[ia] = (v[0] + t[0]) / s[0];
            vector[ib] = (v[1] + t[1]) / s[1];
        } else {
            vector[ia] = v[0];
            vector[ib] = v[1];
        }
        self.state.cutter.vector = vector;
        self.actual()
    }

    /// A start-up block (behaviour 16.3, 16.4): from the programmed start to
    /// the corner its type makes with the next move.
    pub(super) fn start_up(
        &mut self,
        b: &Block,
        out: &mut Out,
        ahead: &mut dyn Ahead,
        (i, path): (usize, Path),
        words: Words,
    ) -> Result<(), Diagnostic> {
        self.state.cutter.phase = Phase::StartUp;
        let start_up = self.setup.settings.cutter_start_up();
        let t = match start_up {
            CutterStartUp::A | CutterStartUp::Corner => Type::A,
            CutterStartUp::B => Type::B,
        };
        let o = words.offset;
        let next = self.cutter_next_with(ahead, out, o);
        let (rule, next_path) = match next {
            // LinuxCNC's entry: the block's end is the corner offset mode
            // would make (behaviour 22.9).
            Next::Move { path: n, .. } if start_up == CutterStartUp::Corner => {
                let outside = match self.setup.settings.cutter_outside_corner() {
                    CutterOutsideCorner::Vectors => Outside::Vectors,
                    CutterOutsideCorner::Arc => Outside::Arc,
                };
                (Rule::Offset(outside), Some(n))
            }
            Next::Move { path: n, .. } => (Rule::StartUp(t), Some(n)),
            Next::Unknown(why) => {
                self.look_ahead_note(b, out, why);
                (Rule::Perpendicular, None)
            }
        };
        let next_for_corner = next_path.unwrap_or(path);
        let corner = self.corner_or_alarm(b, &path, &next_for_corner, o, o, rule)?;
        out.note(|| crc::start_up_note(&words, t, &corner, &path, next_path.as_ref()));
        if let Some(tip) = words.tip {
            out.note(|| self.nose_note(tip));
        }
        self.apply_corner(b, out, i, &corner, false)
    }

    /// A block in offset mode that moves in the plane (behaviour 16.5–16.10,
    /// 16.12): its end is the corner with the next move.
    pub(super) fn offset_move(
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
            CutterStartUp::A | CutterStartUp::Corner => Type::A,
            CutterStartUp::B => Type::B,
        };
        let outside = match self.setup.settings.cutter_outside_corner() {
            CutterOutsideCorner::Vectors => Outside::Vectors,
            CutterOutsideCorner::Arc => Outside::Arc,
        };
        let next = self.cutter_next_with(ahead, out, o);
        // The rule first, the corner once: a corner is a few hundred bytes,
        // made at every block in offset mode.
        let (rule, next_path, o2, cancels) = match next {
            Next::Move {
                path: n,
                offset: 0.0,
            } => (Rule::Cancel(t), n, o, true),
            // The corner is made with this block's radius on both sides: a
            // new D counts from the next block's end (behaviour 16.8).
            Next::Move { path: n, offset } => {
                (Rule::Offset(outside), n, o.abs() * offset.signum(), false)
            }
            Next::Unknown(why) => {
                self.look_ahead_note(b, out, why);
                (Rule::Perpendicular, path, o, false)
            }
        };
        // Borrowed where it was made, not moved out of the result (a copy
        // of the whole corner at every block: the `check` instruction count
        // with G41, docs/performance.md).
        let made = geo::corner(&path, &next_path, o, o2, rule);
        let corner = match &made {
            Ok(c) => c,
            Err(NoIntersection) => return Err(self.no_intersection(b, o)),
        };
        out.note(|| {
            if cancels {
                crc::before_cancel_note(&words, t, corner, &path, &next_path)
            } else {
                crc::corner_note(&words, corner, &path, &next_path, o2)
            }
        });
        if before.radius != self.state.cutter.radius {
            out.note(|| format!(
                "the radius changed from {} to {}: this block starts on the old offset and ends on the new one",
                show(before.radius.abs(), self.units()),
                show(self.state.cutter.radius.abs(), self.units())
            ));
        }
        self.apply_corner(b, out, i, corner, true)
    }

    /// A block in offset mode whose `,C` or `,R` cut its corner (behaviour
    /// 16.19): its moves `i` (to the chamfer's or the round's start) and
    /// `i + 1` (the chamfer or the round) are compensated as two blocks
    /// would be, the first ending at its corner with the chamfer or the
    /// round, the second at its corner with the next block's move, which
    /// starts where the chamfer or the round ends.
    pub(super) fn offset_corner_cut(
        &mut self,
        b: &Block,
        out: &mut Out,
        ahead: &mut dyn Ahead,
        i: usize,
        before: crc::CutterState,
        words: Words,
    ) -> Result<(), Diagnostic> {
        let o = words.offset;
        let (Some(first), Some(second)) = (
            self.move_path(&out.moves[i], [0.0; 3]),
            self.move_path(&out.moves[i + 1], [0.0; 3]),
        ) else {
            return Err(self.error(
                "corner-not-modelled",
                b.span,
                "the chamfer or corner rounding takes this block's whole move: in cutter compensation the move before it must be left (not modelled)",
            ));
        };
        let outside = match self.setup.settings.cutter_outside_corner() {
            CutterOutsideCorner::Vectors => Outside::Vectors,
            CutterOutsideCorner::Arc => Outside::Arc,
        };
        let corner = self.corner_or_alarm(b, &first, &second, o, o, Rule::Offset(outside))?;
        // The sentence of a corner between two blocks, said of the cut.
        let cut_start = out.moves[i + 1].programmed_from;
        out.note(|| {
            let cut = if second.is_arc() {
                "the corner round"
            } else {
                "the chamfer"
            };
            format!(
                "at {}, where {cut} starts: {}",
                self.plane_point(cut_start),
                crc::corner_note(&words, &corner, &first, &second, o)
                    .replace("the next block", cut)
                    .replace("of the end point", "of that point")
            )
        });
        // The first move ends at the chamfer's or the round's start, with
        // the second set aside so that the corner's own steps come between.
        let Some(cut) = out.moves.pop() else {
            return Ok(());
        };
        let end = std::mem::replace(&mut self.state.programmed, cut.programmed_from);
        let made = self.apply_corner(b, out, i, &corner, true);
        let from = self.actual();
        self.state.programmed = end;
        made?;
        out.moves.push(crate::machine::Move { from, ..cut });
        let k = out.moves.len() - 1;
        self.offset_move(b, out, ahead, (k, second), before, words)
    }

    /// The corner by `rule`, or the alarm when an intersection it needs
    /// does not exist (behaviour 16.12: Fanuc PS0033).
    #[inline]
    pub(in crate::machine) fn corner_or_alarm(
        &self,
        b: &Block,
        prev: &Path,
        next: &Path,
        o1: f64,
        o2: f64,
        rule: Rule,
    ) -> Result<Corner, Diagnostic> {
        geo::corner(prev, next, o1, o2, rule).map_err(|NoIntersection| self.no_intersection(b, o1))
    }

    /// The alarm when the intersection a corner needs does not exist
    /// (behaviour 16.12: Fanuc PS0033); `o1` the block's offset.
    #[cold]
    fn no_intersection(&self, b: &Block, o1: f64) -> Diagnostic {
        self.error(
            "cutter-no-intersection",
            b.span,
            format!(
                "the offset paths of this block and the next do not meet at their inside corner: the tool of radius {} cannot reach it (Fanuc alarm PS0033)",
                show(o1.abs(), self.units())
            ),
        )
    }

    /// Says why the corner at this block's end is not known, and warns when
    /// the control cannot see the next move (behaviour 16.9).
    pub(super) fn look_ahead_note(&self, b: &Block, out: &mut Out, why: Why) {
        let text = match why {
            Why::End => "the program ends: no next move in the plane".to_string(),
            Why::Error => "the next block cannot run (its error stops the run there)".to_string(),
            Why::Return => {
                "a reference return or canned cycle follows: the compensation is cancelled for it"
                    .to_string()
            }
            Why::CornerArc => "G39 follows: its arc turns the corner".to_string(),
            Why::CancelHere => "the next block cancels without a move".to_string(),
            Why::Macro(line) => {
                let msg = format!(
                    "the next block (line {line}) is a macro statement or has words with macro values, which offsetlab's look-ahead does not evaluate yet (not modelled): the tool ends perpendicular to this block, and the corner drawn is not the control's"
                );
                out.warnings.push(Diagnostic::warning(
                    "cutter-look-ahead-macro",
                    b.span,
                    msg.clone(),
                ));
                msg
            }
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
    pub(super) fn apply_corner(
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
        if out.moves[i].arc.is_none() {
            // A straight move ends at the corner as it is (most blocks:
            // the `check` with G41, docs/performance.md).
            let (ia, ib, _) = self.state.modal.plane.axes();
            let m = &out.moves[i];
            // On the lathe in radius, X halved (behaviour 18.1).
            let k = self.plane_scale()[1];
            let p = |x: Xyz| [x[ia], x[ib] * k];
            let interferes = geo::line_reverses(
                (p(m.programmed_from), p(m.programmed_to)),
                (p(m.from), p(end)),
            );
            if check && interferes {
                self.interference(b, out, false)?;
            }
            out.moves[i].to = end;
        } else {
            self.finish_offset_move(b, out, i, end, check)?;
        }
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
    pub(super) fn finish_offset_move(
        &self,
        b: &Block,
        out: &mut Out,
        i: usize,
        end: Xyz,
        check: bool,
    ) -> Result<(), Diagnostic> {
        let (ia, ib, _) = self.state.modal.plane.axes();
        // Read in place: a move with its arc is a few hundred bytes.
        let m = &out.moves[i];
        let is_arc = m.arc.is_some();
        let s = self.plane_scale();
        let p = |x: Xyz| [x[ia] * s[0], x[ib] * s[1]];
        let interferes;
        let mut arc_info = None;
        let mut kind = m.kind;
        if let Some(info) = &m.arc {
            // The actual centre is the programmed one carried by the
            // vectors other than the compensation's (constant in an arc
            // block: G45–G48 are refused, the length offset cannot change
            // in G02/G03).
            // On the lathe the tool's point is the imaginary tool nose: the
            // arc it runs is the nose centre's moved by the tip's shift
            // (behaviour 18.2).
            let shift = self.other_vectors();
            let tip = self.nose_tip();
            let c = [
                (info.programmed_center[ia] + shift[ia]) * s[0] + tip[0],
                (info.programmed_center[ib] + shift[ib]) * s[1] + tip[1],
            ];
            let ccw = info.programmed_sweep > 0.0;
            let (a0, a1) = (p(m.from), p(end));
            let (r0, r1) = (geo::dist(a0, c), geo::dist(a1, c));
            let tol = self.arc_tolerance();
            let linuxcnc = self.setup.settings.control == crate::setup::Control::Linuxcnc;
            let o = self.cutter_offset(self.state.cutter.mode, self.state.cutter.radius);
            if linuxcnc && self.state.cutter.phase == Phase::StartUp {
                let programmed_end = [
                    m.programmed_to[ia] + shift[ia],
                    m.programmed_to[ib] + shift[ib],
                ];
                let entry =
                    self.linuxcnc_entry_arc(b, info, (m.from, end), (programmed_end, c), o)?;
                kind = if entry.sweep > 0.0 {
                    MoveKind::ArcCcw
                } else {
                    MoveKind::ArcCw
                };
                arc_info = Some(entry);
                interferes = false;
            } else if r0 < 1e-6 && r1 < 1e-6 && linuxcnc {
                // rs274 runs an arc whose radius is the tool's with the tool
                // inside: the tool stays on the centre (behaviour 22.16).
                let mut center = m.from;
                center[ia] = c[0] / s[0];
                center[ib] = c[1] / s[1];
                arc_info = Some(crate::machine::arcs::point_arc(info, center));
                interferes = false;
            } else {
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
                // Both radii measured and checked above.
                let mut circle = arc::from_center_measured(a0, a1, c, r0, ccw);
                // LinuxCNC's P turns (22.16) are the programmed arc's and the
                // offset one's alike.
                circle.sweep += arc::extra_turns(info.programmed_sweep).copysign(circle.sweep);
                let path = Path::Arc {
                    from: p(m.programmed_from),
                    to: p(m.programmed_to),
                    center: p(info.programmed_center),
                    ccw,
                };
                let offset_radius = path.offset_radius(o).unwrap_or(r0);
                if linuxcnc && offset_radius < -1e-9 {
                    return Err(self.tool_not_less(b, info.programmed_radius, o.abs()));
                }
                interferes =
                    geo::arc_interferes(info.programmed_sweep, circle.sweep, offset_radius);
                let mut center = m.from;
                center[ia] = c[0] / s[0];
                center[ib] = c[1] / s[1];
                arc_info = Some(ArcInfo {
                    center,
                    radius: circle.radius,
                    sweep: circle.sweep,
                    start_angle: circle.start_angle,
                    ..*info
                });
                kind = if circle.sweep > 0.0 {
                    MoveKind::ArcCcw
                } else {
                    MoveKind::ArcCw
                };
            }
        } else {
            interferes = geo::line_reverses(
                (p(m.programmed_from), p(m.programmed_to)),
                (p(m.from), p(end)),
            );
        }
        if check && interferes {
            self.interference(b, out, is_arc)?;
        }
        let m = &mut out.moves[i];
        m.to = end;
        m.kind = kind;
        if arc_info.is_some() {
            m.arc = arc_info;
        }
        Ok(())
    }

    /// The interference check's answer for a block whose offset path runs
    /// against its programmed one (behaviour 16.12): the alarm, or with the
    /// check off a warning.
    #[cold]
    fn interference(&self, b: &Block, out: &mut Out, is_arc: bool) -> Result<(), Diagnostic> {
        let what = if is_arc {
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
        Ok(())
    }

    /// Actual − programmed now, less the compensation's vector: what the
    /// other offsets carry.
    pub(super) fn other_vectors(&self) -> Xyz {
        sub3(
            sub3(self.actual(), self.state.programmed),
            self.state.cutter.vector,
        )
    }

    /// The radius check's tolerance (behaviour 2.13).
    pub(in crate::machine) fn arc_tolerance(&self) -> f64 {
        if self.setup.settings.control == crate::setup::Control::Linuxcnc {
            // The most rs274 lets an end's radius differ (22.16); its
            // finer rule is the arc block's own check.
            return 100.0 * self.linuxcnc_spiral_tolerance();
        }
        self.setup.arc_tolerance_mm(self.units())
    }
}
