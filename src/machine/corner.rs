//! Chamfer and corner rounding at the end of a feed block on the mill and
//! the lathe, the comma words `,C` and `,R` (behaviour 2.30–2.36; Fanuc
//! 0i-MF and 0i-TF, "optional angle chamfering and corner R"): the control
//! reads the next block, and between the two moves (straight, or arcs:
//! `corner_geometry.rs`) it cuts the corner with a line (`,C`: the distance
//! from the corner to each end of the chamfer) or a tangent arc (`,R`: its
//! radius). The inserted move belongs to the block that carries the word,
//! so a single block stop is at its end; the next block's words still
//! count from the corner as written.

use super::arc::P2;
use super::corner_geometry::{self as geometry, Corner, Cut, CutError, Seg};
use super::{Ahead, ArcRequest, Machine, Mark, MoveKind, NoneAhead, Out};
use crate::diag::Diagnostic;
use crate::geometry::{Xyz, show};
use crate::setup::MachineKind;
use crate::syntax::codes::{Motion, NonModal};
use crate::syntax::{Address, Block};

/// The comma words this file handles.
pub(super) const CORNER_WORDS: [Address; 2] = [Address::CommaC, Address::CommaR];

/// A plane vector's length.
fn len(v: P2) -> f64 {
    v[0].hypot(v[1])
}

impl Machine {
    /// A block with `,C` or `,R` (behaviour 2.30, 2.35, 2.36): runs the
    /// block to its corner, reads the next block's move, and inserts the
    /// chamfer or the corner arc.
    pub(super) fn corner_block(
        &mut self,
        b: &Block,
        out: &mut Out,
        ahead: &mut dyn Ahead,
    ) -> Result<(), Diagnostic> {
        let corner = self.corner_word(b)?;
        let word = b.get(Address::CommaC).or_else(|| b.get(Address::CommaR));
        let word_span = word.map_or(b.span, |w| w.span);
        // A block run only to find the next move's direction for an
        // earlier corner makes its own move as written (behaviour 2.31).
        if self.reading_ahead {
            return self.corner_run(b, out, word_span);
        }
        let letter = word.map_or(",C", |w| w.address.letter());
        let start = self.state.programmed;
        let moves_before = out.moves.len();
        self.corner_run(b, out, word_span)?;
        // The word in the units the block's G20/G21 left.
        let corner = match corner {
            Corner::Chamfer(c) => Corner::Chamfer(self.mm(c)),
            Corner::Round(r) => Corner::Round(self.mm(r)),
        };
        match self.state.modal.motion {
            // At the end of an arc too (behaviour 2.36).
            Motion::Linear | Motion::Arc(_) => {}
            Motion::Rapid | Motion::LatheCycle(_) => {
                return Err(self.error(
                    "corner-motion",
                    word_span,
                    format!(
                        "{letter}: a chamfer or corner rounding is cut at feed, at the end of a G01 block, not in {}",
                        self.state.modal.motion.gcode()
                    ),
                ));
            }
        }
        let (ia, ib, normal) = self.state.modal.plane.axes();
        let plane = self.state.modal.plane.gcode();
        // The lathe's X is a diameter: the corner is cut on the part, in
        // radius (behaviour 2.35).
        let s = self.plane_scale();
        let at = self.state.programmed;
        let made: Vec<usize> = (moves_before..out.moves.len()).collect();
        let in_plane_only = at[normal] == start[normal]
            && made.len() == 1
            && matches!(
                out.moves[made[0]].kind,
                MoveKind::Feed | MoveKind::ArcCw | MoveKind::ArcCcw
            )
            && out.moves[made[0]].to[normal] == out.moves[made[0]].from[normal];
        // The move as made: from the end of a corner the block before cut,
        // if it did (both corners must fit on it).
        let made_from = self.corner_end.unwrap_or(start);
        let u = [
            (at[ia] - made_from[ia]) * s[0],
            (at[ib] - made_from[ib]) * s[1],
        ];
        if !in_plane_only || len(u) < 1e-9 {
            return Err(self.error(
                "corner-move",
                word_span,
                format!(
                    "{letter}: the block's move must lie in the {plane} plane, along its two axes only, to chamfer or round its end (Fanuc alarm PS0055 when it is missing or too short)"
                ),
            ));
        }
        let Some((next, line)) = self.next_direction(ahead, letter, word_span)? else {
            out.notes.push(format!(
                "{letter}: the next block cannot run (its error stops the run there), so no corner is cut at its start"
            ));
            return Ok(());
        };
        let units = self.units();
        let k = [at[ia] * s[0], at[ib] * s[1]];
        let before = match out.moves[made[0]].arc {
            Some(info) => {
                let c = info.programmed_center;
                let from = [made_from[ia] * s[0], made_from[ib] * s[1]];
                geometry::arc_seg(
                    [c[ia] * s[0], c[ib] * s[1]],
                    info.programmed_radius,
                    info.programmed_sweep,
                    (from, k),
                )
            }
            None => Seg::Line {
                dir: [u[0] / len(u), u[1] / len(u)],
                len: len(u),
            },
        };
        // The two ends of the inserted move in the plane, and a round's
        // centre (from its start) and turn (None: a chamfer).
        let (q1, q2, round) = match (before, next) {
            (Seg::Line { dir: uh, len: lu }, Seg::Line { dir: vh, len: lv }) => {
                let cross = uh[0] * vh[1] - uh[1] * vh[0];
                let dot = uh[0] * vh[0] + uh[1] * vh[1];
                if cross.abs() < 1e-9 {
                    return Err(self.error(
                        "corner-angle",
                        word_span,
                        format!(
                            "{letter}: the next block's move goes on along the same line{} (line {line}): there is no corner to cut",
                            if dot < 0.0 { ", backwards," } else { "" },
                        ),
                    ));
                }
                // Distance from the corner to each end of the inserted move:
                // the chamfer's own length, or the tangent length R·tan(φ/2)
                // of a round, φ the angle the path turns by at the corner.
                let reach = match corner {
                    Corner::Chamfer(c) => c,
                    Corner::Round(r) => r * (cross.atan2(dot).abs() / 2.0).tan(),
                };
                if reach > lu + 1e-9 || reach > lv + 1e-9 {
                    return Err(self.error(
                        "corner-too-long",
                        word_span,
                        format!(
                            "{letter}: the {} needs {} of each move from the corner, but this block's move is {} and the next block's (line {line}) {} long (Fanuc alarm PS0055)",
                            if matches!(corner, Corner::Chamfer(_)) { "chamfer" } else { "corner rounding" },
                            show(reach, units),
                            show(lu, units),
                            show(lv, units)
                        ),
                    ));
                }
                // A round's centre is R from both moves, on the side the
                // path turns to.
                let side = if cross > 0.0 { 1.0 } else { -1.0 };
                let round = match corner {
                    Corner::Round(r) => Some(([-uh[1] * side * r, uh[0] * side * r], cross > 0.0)),
                    Corner::Chamfer(_) => None,
                };
                (
                    [k[0] - reach * uh[0], k[1] - reach * uh[1]],
                    [k[0] + reach * vh[0], k[1] + reach * vh[1]],
                    round,
                )
            }
            // An arc on either side (behaviour 2.36).
            _ => match geometry::cut(k, before, next, corner) {
                Ok(Cut::Chamfer { from, to }) => (from, to, None),
                Ok(Cut::Round {
                    from,
                    to,
                    center,
                    ccw,
                }) => (
                    from,
                    to,
                    Some(([center[0] - from[0], center[1] - from[1]], ccw)),
                ),
                Err(CutError::NoCorner { back }) => {
                    return Err(self.error(
                        "corner-angle",
                        word_span,
                        format!(
                            "{letter}: the next block's move (line {line}) {}: there is no corner to cut",
                            if back { "turns right back, backwards along the tangent" } else { "goes on tangentially" }
                        ),
                    ));
                }
                Err(CutError::TooLong) => {
                    return Err(self.error(
                        "corner-too-long",
                        word_span,
                        format!(
                            "{letter}: the {} does not fit on this block's move and the next block's (line {line}) (Fanuc alarm PS0055)",
                            if matches!(corner, Corner::Chamfer(_)) { "chamfer" } else { "corner rounding" },
                        ),
                    ));
                }
            },
        };
        let mut p1 = at;
        let mut p2 = at;
        for i in 0..2 {
            let axis = [ia, ib][i];
            p1[axis] = q1[i] / s[i];
            p2[axis] = q2[i] / s[i];
        }
        // The block's move ends where the inserted one starts; the offsets'
        // vectors stand as they did at the corner.
        let shift = [
            self.actual()[0] - at[0],
            self.actual()[1] - at[1],
            self.actual()[2] - at[2],
        ];
        let shifted = |p: Xyz| [p[0] + shift[0], p[1] + shift[1], p[2] + shift[2]];
        if let Some(m) = out.moves.last_mut() {
            m.programmed_to = p1;
            m.to = shifted(p1);
            if let Some(info) = &mut m.arc {
                geometry::end_arc_at(info, (m.programmed_from, p1), (m.from, m.to));
            }
        }
        self.state.programmed = p1;
        let from: Mark = self.mark();
        let (Corner::Chamfer(size) | Corner::Round(size)) = corner;
        let sentence = match round {
            None => {
                self.state.programmed = p2;
                self.emit(out, from, MoveKind::Feed, true, None);
                format!(
                    "{letter}{}: a chamfer from {} to {} cuts the corner at {} (line {}'s move starts there)",
                    show(size, units),
                    self.plane_point(p1),
                    self.plane_point(p2),
                    self.plane_point(at),
                    line
                )
            }
            Some((offset, ccw)) => {
                // As I/J/K: from the arc's start.
                let mut center = [0.0; 3];
                center[ia] = offset[0];
                center[ib] = offset[1];
                let req = ArcRequest {
                    target: p2,
                    actual_end: shifted(p2),
                    ccw,
                    center,
                    ..ArcRequest::default()
                };
                let info = self.arc_geometry(b, &req)?;
                self.state.programmed = p2;
                let kind = if info.sweep > 0.0 {
                    MoveKind::ArcCcw
                } else {
                    MoveKind::ArcCw
                };
                self.emit(out, from, kind, true, Some(info));
                format!(
                    "{letter}{}: an arc of radius {} from {} to {}, tangent to both moves, rounds the corner at {} (line {}'s move starts there)",
                    show(size, units),
                    show(size, units),
                    self.plane_point(p1),
                    self.plane_point(p2),
                    self.plane_point(at),
                    line
                )
            }
        };
        out.notes.push(sentence);
        // The next block's words count from the corner (behaviour 2.32).
        self.corner_cut = true;
        self.corner = at;
        Ok(())
    }

    /// Runs a block with `,C`/`,R` as it is written, up to its corner: the
    /// mill's general block, or the lathe's, which then reads the words.
    fn corner_run(
        &mut self,
        b: &Block,
        out: &mut Out,
        word: crate::diag::Span,
    ) -> Result<(), Diagnostic> {
        if self.setup.machine == MachineKind::Mill {
            return self.mill_general(b, out);
        }
        if self.state.polar.is_some() {
            return Err(self.error(
                "corner-not-modelled",
                word,
                "a chamfer or corner rounding in polar coordinate interpolation (the face) is not modelled yet",
            ));
        }
        self.corner_words_read = true;
        let ran = self.lathe_run(b, out, &mut super::program::NoText);
        self.corner_words_read = false;
        ran
    }

    /// Before the block after a corner: its words count from the corner
    /// (behaviour 2.32), so the block runs from there; returns where the
    /// tool stands, the chamfer's or the round's end.
    #[cold]
    pub(super) fn run_from_corner(&mut self) -> Xyz {
        self.corner_cut = false;
        let end = std::mem::replace(&mut self.state.programmed, self.corner);
        self.corner_end = Some(end);
        end
    }

    /// After the block after a corner: its move, made from the corner,
    /// starts where the tool stands (the next move is a straight feed move:
    /// behaviour 2.31 checked it before cutting the corner).
    #[cold]
    pub(super) fn start_at_corner_end(out: &mut Out, end: Xyz) {
        if let Some(m) = out.moves.first_mut() {
            for ((from, e), p) in m.from.iter_mut().zip(end).zip(m.programmed_from) {
                *from += e - p;
            }
            m.programmed_from = end;
            if let Some(info) = &mut m.arc {
                geometry::start_arc_at(info, (m.programmed_from, m.programmed_to), (m.from, m.to));
            }
        }
    }

    /// The `,C` or `,R` of a block, checked (behaviour 2.30, 2.33).
    fn corner_word(&self, b: &Block) -> Result<Corner, Diagnostic> {
        let (word, corner) = match (b.get(Address::CommaC), b.get(Address::CommaR)) {
            (Some(_), Some(r)) => {
                return Err(self.error(
                    "corner-words",
                    r.span,
                    ",C and ,R in one block: a corner is either chamfered or rounded; write one of them",
                ));
            }
            // In the block's own units, known once its codes have run:
            // converted by the caller.
            (Some(c), None) => (c, Corner::Chamfer(c.value)),
            (None, Some(r)) => (r, Corner::Round(r.value)),
            (None, None) => {
                return Err(self.error("corner-words", b.span, "no ,C or ,R word in this block"));
            }
        };
        let value = match corner {
            Corner::Chamfer(v) | Corner::Round(v) => v,
        };
        if value <= 0.0 {
            return Err(self.error(
                "corner-words",
                word.span,
                format!(
                    "{}: a chamfer or corner radius is a positive length",
                    word.address.letter()
                ),
            ));
        }
        if let Some(code) = b.codes().non_modal() {
            let what = match code {
                // G09 only stops at the block's end (behaviour 14.2): the
                // corner is cut as without it.
                NonModal::ExactStop => "",
                NonModal::PositionOffset(_) => "G45–G48 change the block's move by an offset",
                NonModal::Dwell
                | NonModal::ReferenceReturn
                | NonModal::SetCoordinates
                | NonModal::ReferenceCheck
                | NonModal::OtherReference
                | NonModal::LocalCoordinates
                | NonModal::MachineCoordinates
                | NonModal::PresetCoordinates
                | NonModal::Stored(_)
                | NonModal::CornerArc
                | NonModal::Repetitive(_)
                | NonModal::DataSetting => "the block makes no G01 move of its own",
                NonModal::Skip => "a skip signal may end G31's move anywhere (behaviour 14.7)",
                NonModal::CirclePocket(_) => "G12/G13 cut a pocket of their own (behaviour 14.12)",
                NonModal::Engraving => "G47 engraves text of its own (behaviour 14.20)",
                NonModal::AiContour
                | NonModal::LookAhead
                | NonModal::Smoothness
                | NonModal::BlockLimit
                | NonModal::Cylindrical => {
                    "the mode code stands alone in its block (behaviour 14.3)"
                }
            };
            if !what.is_empty() {
                return Err(self.error(
                    "corner-words",
                    word.span,
                    format!(
                        "{}: {} cannot share a block with a chamfer or corner rounding ({what})",
                        word.address.letter(),
                        code.gcode(self.setup.machine)
                    ),
                ));
            }
        }
        if self.state.modal.cycle.is_some() && b.codes().motion().is_none() {
            return Err(self.error(
                "corner-words",
                word.span,
                format!(
                    "{}: a chamfer or corner rounding is not made while a canned cycle is active",
                    word.address.letter()
                ),
            ));
        }
        Ok(corner)
    }

    /// The plane direction of the next block's first move, from the
    /// corner, and its line; None when the next block has an error of its own
    /// (the run stops there). The next block is run on a copy of the machine
    /// standing at the corner (behaviour 2.31): what it does is what it
    /// will do, with every word and mode as the machine reads them.
    fn next_direction(
        &self,
        ahead: &mut dyn Ahead,
        letter: &str,
        span: crate::diag::Span,
    ) -> Result<Option<(Seg, u32)>, Diagnostic> {
        let Some(next) = ahead.peek(0) else {
            return Err(self.error(
                "corner-next-move",
                span,
                format!(
                    "{letter}: the program ends after this block, and a chamfer or corner rounding needs the next block's move (Fanuc alarm PS0051)"
                ),
            ));
        };
        if next.error {
            return Ok(None);
        }
        let line = next.span.line;
        if next.macros.is_some() {
            // Its values exist only once the blocks before it have run
            // (behaviour 20.8): the look-ahead cannot know its move.
            return Err(self.error(
                "corner-not-modelled",
                span,
                format!(
                    "{letter}: the next block (line {line}) is a macro statement or has words with macro values, which the look-ahead of a chamfer or corner rounding does not evaluate yet (not modelled); the run stops here rather than guess its move"
                ),
            ));
        }
        let mut probe = self.clone();
        probe.reading_ahead = true;
        probe.corner_cut = false;
        probe.corner_end = None;
        probe.moves_left = usize::MAX;
        let mut scratch = Out::default();
        if probe
            .execute(
                next,
                self.index + 1,
                &mut scratch,
                &mut NoneAhead,
                &mut super::program::NoText,
            )
            .is_err()
        {
            return Ok(None);
        }
        let (ia, ib, normal) = self.state.modal.plane.axes();
        let plane = self.state.modal.plane.gcode();
        let Some(m) = scratch.moves.first() else {
            return Err(self.error(
                "corner-next-move",
                span,
                format!(
                    "{letter}: the next block (line {line}) makes no move, and a chamfer or corner rounding is cut between this block's move and the next one's (Fanuc alarm PS0051)"
                ),
            ));
        };
        match m.kind {
            MoveKind::Feed | MoveKind::ArcCw | MoveKind::ArcCcw => {}
            MoveKind::Rapid | MoveKind::Offset => {
                return Err(self.error(
                    "corner-next-move",
                    span,
                    format!(
                        "{letter}: the next block (line {line}) does not move at feed (G01/G02/G03), and a chamfer or corner rounding is cut between two feed moves (Fanuc alarm PS0052)"
                    ),
                ));
            }
        }
        let s = self.plane_scale();
        let v = [
            (m.programmed_to[ia] - m.programmed_from[ia]) * s[0],
            (m.programmed_to[ib] - m.programmed_from[ib]) * s[1],
        ];
        let moved_normal = (m.programmed_to[normal] - m.programmed_from[normal]).abs() > 1e-9
            || (m.to[normal] - m.from[normal]).abs() > 1e-9;
        // A full circle next starts and ends at the corner.
        if moved_normal || (len(v) < 1e-9 && m.arc.is_none()) {
            return Err(self.error(
                "corner-next-move",
                span,
                format!(
                    "{letter}: the next block's move (line {line}) must lie in the {plane} plane, along its two axes only (Fanuc alarm PS0051)"
                ),
            ));
        }
        let next = match m.arc {
            Some(info) => {
                let c = info.programmed_center;
                let at = |p: Xyz| [p[ia] * s[0], p[ib] * s[1]];
                geometry::arc_seg(
                    at(c),
                    info.programmed_radius,
                    info.programmed_sweep,
                    (at(m.programmed_from), at(m.programmed_to)),
                )
            }
            None => Seg::Line {
                dir: [v[0] / len(v), v[1] / len(v)],
                len: len(v),
            },
        };
        Ok(Some((next, line)))
    }

    /// "X50.000 Y0.000": a point's coordinates in the selected plane.
    pub(super) fn plane_point(&self, p: Xyz) -> String {
        let (ia, ib, _) = self.state.modal.plane.axes();
        let names = ['X', 'Y', 'Z'];
        let units = self.units();
        format!(
            "{}{} {}{}",
            names[ia],
            show(p[ia], units),
            names[ib],
            show(p[ib], units)
        )
    }
}
