//! Tool nose radius compensation in the lathe's multiple repetitive cycles
//! (behaviour 18.11–18.14): the contour of a G70–G73 compensated as the
//! blocks of section 18 are — start-up, corners and cancel by the mill's
//! rules of `offsets/cutter/geometry.rs` (one offsetter for both machines),
//! the nose centre R from the contour, the tool placed by the tip direction
//! — then roughed (G71–G73) or finished (G70). The compensation starts with
//! the contour: the cycle's start point A carries no vector (the vector in
//! force before the cycle is taken off there), and the cycle's return to A
//! takes it off again (Fanuc's rule for the single cycles, our reading for
//! G70–G73: every cycle begins and ends at A as programmed).

use super::super::arc::{self, P2};
use super::super::{ArcInfo, Machine, MoveKind, Out};
use super::contour::{Contour, Seg};
use crate::diag::Diagnostic;
use crate::geometry::show;
use crate::machine::modal::{LatheCycle, Motion, Plane};
use crate::offsets::cutter::geometry::{self as geo, Outside, Path, Rule, Step, Type};
use crate::offsets::cutter::{Phase, nose};
use crate::setup::{CutterInterference, CutterOutsideCorner, CutterStartUp, NoseSingleCycles};
use crate::syntax::Block;
use crate::syntax::codes::{Code, CutterCompensation, Repetitive};

/// One move of the tool along the compensated contour: where the point the
/// program follows (the imaginary nose, or the centre for tips 0/9) goes,
/// in the plane (Z, X radius), and for an arc its centre and direction.
#[derive(Clone, Copy, Debug)]
pub(super) struct Piece {
    pub to: P2,
    pub arc: Option<(P2, bool)>,
}

/// The compensated contour of a G70–G73.
#[derive(Clone, Debug)]
pub(super) struct NoseShape {
    /// For each segment of the contour, the tool's moves: its own first,
    /// then those its corner adds.
    pub moves: Vec<Vec<Piece>>,
    /// The same as a contour (X diameter, Z) for the roughing passes.
    pub segs: Vec<Seg>,
    /// The signed offsets (+ left) of the compensated segments.
    pub sides: Vec<f64>,
}

/// (Z, X radius) of a contour point given as X diameter and Z.
fn plane(p: [f64; 2]) -> P2 {
    [p[1], p[0] / 2.0]
}

fn add(a: P2, b: P2) -> P2 {
    [a[0] + b[0], a[1] + b[1]]
}

impl Machine {
    /// True when a G70–G73 must compensate: G41/G42 is the mode, or the
    /// contour writes it (behaviour 18.11).
    fn nose_wanted(&self, c: &Contour) -> bool {
        self.nose_lathe()
            && (self.state.cutter.mode != CutterCompensation::Cancel
                || c.segs.iter().any(|s| {
                    matches!(
                        s.nose,
                        Some(CutterCompensation::Left | CutterCompensation::Right)
                    )
                }))
    }

    /// The contour compensated (behaviour 18.11, 18.12); None when no
    /// compensation is asked for or the nose radius is 0.
    pub(super) fn nose_shape(
        &self,
        b: &Block,
        cycle: Repetitive,
        c: &Contour,
        out: &mut Out,
    ) -> Result<Option<NoseShape>, Diagnostic> {
        if !self.nose_wanted(c) {
            return Ok(None);
        }
        let radius = self.cutter_radius();
        if radius == 0.0 {
            out.notes.push(format!(
                "{}: the contour asks for tool nose radius compensation, but offset {:02} has nose radius 0: the contour is cut as programmed (behaviour 18.1)",
                self.code_name(cycle),
                self.state.lathe.offset
            ));
            return Ok(None);
        }
        let tip = self.nose_register().1;
        let v = nose::tip_vector(tip);
        let r = radius.abs();
        let shift = [v[0] * r, v[1] * r];
        let n = c.segs.len();
        // Each segment's offset (0: not compensated) and programmed path.
        let mut mode = self.state.cutter.mode;
        let mut offsets = Vec::with_capacity(n);
        let mut paths: Vec<Option<Path>> = Vec::with_capacity(n);
        let mut at = plane(c.start);
        for s in &c.segs {
            if let Some(m) = s.nose {
                mode = m;
            }
            offsets.push(self.cutter_offset(mode, radius));
            if s.dwell.is_some() {
                paths.push(None);
                continue;
            }
            let to = plane(s.to);
            paths.push(match s.arc {
                Some(circle) => Some(Path::Arc {
                    from: at,
                    to,
                    center: circle.center,
                    ccw: circle.sweep > 0.0,
                }),
                None if geo::dist(at, to) > 1e-9 => Some(Path::Line { from: at, to }),
                None => None,
            });
            at = to;
        }
        let kind = match self.setup.settings.cutter_start_up() {
            CutterStartUp::A | CutterStartUp::Corner => Type::A,
            CutterStartUp::B => Type::B,
        };
        let outside = match self.setup.settings.cutter_outside_corner() {
            CutterOutsideCorner::Vectors => Outside::Vectors,
            CutterOutsideCorner::Arc => Outside::Arc,
        };
        let mut moves: Vec<Vec<Piece>> = vec![Vec::new(); n];
        let mut engaged = false;
        let mut last = plane(c.start);
        for i in 0..n {
            let Some(p) = paths[i] else { continue };
            let o = offsets[i];
            let centre_of = |p: &Path| match *p {
                Path::Arc { center, ccw, .. } => Some((center, ccw)),
                Path::Line { .. } => None,
            };
            if o == 0.0 {
                // Cancel mode, or the block that cancels: to the programmed
                // end (behaviour 18.4).
                if engaged && p.is_arc() {
                    return Err(self.nose_arc_error(b, cycle, c, "cancel"));
                }
                moves[i].push(Piece {
                    to: p.end(),
                    arc: centre_of(&p),
                });
                engaged = false;
                last = p.end();
                continue;
            }
            if !engaged && p.is_arc() {
                return Err(self.nose_arc_error(b, cycle, c, "start-up"));
            }
            let next = (i + 1..n).find_map(|j| paths[j].map(|q| (q, offsets[j])));
            let (rule, nextp, o2) = match next {
                Some((q, o2)) if o2 != 0.0 && !engaged => (Rule::StartUp(kind), q, o2),
                Some((q, o2)) if o2 != 0.0 => (Rule::Offset(outside), q, o2),
                Some((q, _)) => (Rule::Cancel(kind), q, o),
                None => (Rule::Perpendicular, p, o),
            };
            let corner = self.corner_or_alarm(b, &p, &nextp, o, o2, rule)?;
            let steps = corner.steps();
            let e = steps.first().map_or(p.end(), Step::end);
            if engaged {
                self.nose_interference(b, out, &p, o, (last, e))?;
            }
            let own = match p {
                Path::Arc { center, ccw, .. } => Some((add(center, shift), ccw)),
                Path::Line { .. } => None,
            };
            // An offset arc that shrinks to nothing leaves only its end.
            if own.is_none() || geo::dist(last, e) > 1e-9 {
                moves[i].push(Piece {
                    to: add(e, shift),
                    arc: own,
                });
            }
            for st in &steps[1..] {
                moves[i].push(match *st {
                    Step::Line(q) => Piece {
                        to: add(q, shift),
                        arc: None,
                    },
                    Step::Arc { to, center, ccw } => Piece {
                        to: add(to, shift),
                        arc: Some((add(center, shift), ccw)),
                    },
                });
            }
            last = corner.end();
            engaged = true;
        }
        let segs = self.nose_segs(b, c, &moves)?;
        let units = self.units();
        out.notes.push(format!(
            "tool nose radius compensation: the contour is compensated (offset {:02}, nose R {}, tip {tip}: {}) — the nose centre runs {} from it by the corner rules of section 16, the tool placed so that {} follows it; {} (behaviour 18.11)",
            self.state.lathe.offset,
            show(r, units),
            nose::follows(tip),
            show(r, units),
            if shift == [0.0, 0.0] {
                "the centre"
            } else {
                "the imaginary nose"
            },
            if cycle == Repetitive::Finishing {
                "G70 runs that path"
            } else {
                "the roughing passes cut down to it plus the finishing allowance"
            }
        ));
        let sides = offsets.into_iter().filter(|o| *o != 0.0).collect();
        Ok(Some(NoseShape { moves, segs, sides }))
    }

    /// The compensated moves as a contour (X diameter, Z) the roughing
    /// passes cut, each arc solved again about its moved centre.
    fn nose_segs(
        &self,
        b: &Block,
        c: &Contour,
        moves: &[Vec<Piece>],
    ) -> Result<Vec<Seg>, Diagnostic> {
        let tol = self.arc_tolerance();
        let mut out = Vec::with_capacity(c.segs.len() + 8);
        let mut at = plane(c.start);
        for (s, list) in c.segs.iter().zip(moves) {
            if s.dwell.is_some() {
                out.push(Seg {
                    to: [2.0 * at[1], at[0]],
                    ..*s
                });
                continue;
            }
            for pc in list {
                let arc = match pc.arc {
                    Some((center, ccw)) => Some(
                        arc::from_center(at, pc.to, center, ccw, tol)
                            .map_err(|_| self.nose_arc_radius(b))?,
                    ),
                    None => None,
                };
                out.push(Seg {
                    to: [2.0 * pc.to[1], pc.to[0]],
                    arc,
                    nose: None,
                    ..*s
                });
                at = pc.to;
            }
        }
        Ok(out)
    }

    /// The contour's moves, programmed and compensated both (behaviour
    /// 18.12): each move's programmed end is its segment's, shifted by
    /// `shift` (X diameter, Z), and the compensation's vector carries the
    /// tool to the compensated point; `finishing`: G70's F, S and dwells.
    pub(super) fn nose_trace(
        &mut self,
        out: &mut Out,
        segs: &[Seg],
        shape: &NoseShape,
        shift: [f64; 2],
        finishing: bool,
    ) -> Result<(), Diagnostic> {
        let s2 = [shift[1], shift[0] / 2.0];
        for (s, list) in segs.iter().zip(&shape.moves) {
            if self.out_of_moves() {
                break;
            }
            if !self.contour_segment(out, s, finishing) {
                continue;
            }
            let prog = [s.to[0] + shift[0], s.to[1] + shift[1]];
            for (k, pc) in list.iter().enumerate() {
                let from = self.mark();
                let to = add(pc.to, s2);
                self.state.programmed[0] = prog[0];
                self.state.programmed[2] = prog[1];
                self.state.cutter.vector = [2.0 * to[1] - prog[0], 0.0, to[0] - prog[1]];
                let Some((centre, ccw)) = pc.arc else {
                    let kind = if s.rapid {
                        MoveKind::Rapid
                    } else {
                        MoveKind::Feed
                    };
                    self.emit(out, from, kind, kind == MoveKind::Feed, None);
                    continue;
                };
                let programmed = match (k, s.arc) {
                    (0, Some(c)) => Some(arc::Circle {
                        center: add(c.center, s2),
                        ..c
                    }),
                    _ => None,
                };
                let info = self.nose_arc_info(from, add(centre, s2), ccw, programmed)?;
                let kind = if info.sweep > 0.0 {
                    MoveKind::ArcCcw
                } else {
                    MoveKind::ArcCw
                };
                self.emit(out, from, kind, true, Some(info));
            }
        }
        Ok(())
    }

    /// The arc from the tool's position to where it stands now about
    /// `centre` (plane, before the other offsets), with its programmed arc
    /// (a corner's arc has none: it turns about the programmed point).
    fn nose_arc_info(
        &self,
        from: super::super::Mark,
        centre: P2,
        ccw: bool,
        programmed: Option<arc::Circle>,
    ) -> Result<ArcInfo, Diagnostic> {
        let to = self.actual();
        let t = self.state.lathe.vector;
        let c = [centre[0] + t[2], centre[1] + t[0] / 2.0];
        let (a0, a1) = ([from.act[2], from.act[0] / 2.0], [to[2], to[0] / 2.0]);
        let circle = arc::from_center(a0, a1, c, ccw, self.arc_tolerance())
            .map_err(|_| self.nose_arc_radius_at(self.span))?;
        let prog = programmed.unwrap_or(arc::Circle {
            center: [self.state.programmed[2], self.state.programmed[0] / 2.0],
            radius: 0.0,
            start_angle: 0.0,
            sweep: 0.0,
        });
        Ok(ArcInfo {
            plane: Plane::ZX,
            center: [2.0 * c[1], from.act[1], c[0]],
            programmed_center: [2.0 * prog.center[1], 0.0, prog.center[0]],
            radius: circle.radius,
            programmed_radius: prog.radius,
            sweep: circle.sweep,
            programmed_sweep: prog.sweep,
            start_angle: circle.start_angle,
            programmed_start_angle: prog.start_angle,
            diameter_x: true,
        })
    }

    /// G71/G72 check that the compensation puts the nose on the stock's
    /// side of the contour (Fanuc alarm PS0328, "illegal work position in
    /// the tool nose radius compensation": behaviour 18.11). `sq` is the
    /// sign of the cut's travel (Z for G71, X for G72), `sp` the side of
    /// the contour A lies on along the depth axis: the stock is left of the
    /// travel when `sq·sp` > 0 in G71 (along Z, the depth X) and when
    /// `−sq·sp` > 0 in G72 (along X, the depth Z).
    pub(super) fn nose_side(
        &self,
        b: &Block,
        cycle: Repetitive,
        shape: Option<&NoseShape>,
        (sq, sp): (f64, f64),
    ) -> Result<(), Diagnostic> {
        let Some(shape) = shape else { return Ok(()) };
        let left = if cycle == Repetitive::FacingStock {
            -sq * sp
        } else {
            sq * sp
        };
        if shape.sides.iter().all(|o| o * left > 0.0) {
            return Ok(());
        }
        let want = if left > 0.0 { "G41" } else { "G42" };
        Err(self.error(
            "nose-side",
            b.span,
            format!(
                "{}: the compensation puts the nose on the part's side of the contour: the stock lies {} of the cut, so this contour wants {want} (Fanuc alarm PS0328)",
                self.code_name(cycle),
                if left > 0.0 { "left" } else { "right" }
            ),
        ))
    }

    /// The contour once from the tool's position, shifted by `shift` (X
    /// diameter, Z): compensated when the cycle compensates.
    pub(super) fn contour_pass(
        &mut self,
        b: &Block,
        out: &mut Out,
        segs: &[Seg],
        shape: Option<&NoseShape>,
        shift: [f64; 2],
        finishing: bool,
    ) -> Result<(), Diagnostic> {
        match shape {
            Some(s) => self.nose_trace(out, segs, s, shift, finishing),
            None => self.trace(b, out, segs, shift, finishing),
        }
    }

    /// Back to the cycle's start point A at rapid with no compensation
    /// vector (behaviour 15.7, 18.11: the return takes the vector off).
    pub(super) fn cycle_home(&mut self, out: &mut Out, a: [f64; 2]) {
        let from = self.mark();
        self.state.cutter.vector = [0.0; 3];
        self.state.programmed[0] = a[0];
        self.state.programmed[2] = a[1];
        self.emit(out, from, MoveKind::Rapid, false, None);
        self.nose_after_cycle();
    }

    /// After a G70–G73 or a single cycle run with compensation: the tool
    /// is at A without a vector; with G41/G42 the mode the next move starts
    /// compensation up again (behaviour 18.11, 18.15).
    pub(in crate::machine) fn nose_after_cycle(&mut self) {
        self.state.cutter.vector = [0.0; 3];
        self.state.cutter.phase = Phase::Cancel;
        if self.nose_lathe() && self.state.cutter.mode != CutterCompensation::Cancel {
            let (r, tip) = self.nose_register();
            self.state.cutter.d = self.state.lathe.offset;
            self.state.cutter.radius = r;
            self.state.cutter.tip = Some(tip);
        }
        self.update_special();
    }

    /// The vector in force before a cycle is taken off at its start point
    /// A: the tool goes there at rapid (behaviour 18.11).
    pub(in crate::machine) fn nose_take_off(&mut self, out: &mut Out) {
        if self.state.cutter.vector == [0.0; 3] {
            return;
        }
        let from = self.mark();
        self.state.cutter.vector = [0.0; 3];
        self.emit(out, from, MoveKind::Rapid, false, None);
        out.note(|| {
            "the compensation's vector is taken off at the cycle's start point: the cycle starts compensation up again from there (behaviour 18.11)".to_string()
        });
    }

    /// A G90/G92/G94 cycle while G41/G42 is the mode (behaviour 18.15,
    /// 18.16): its four legs from `start` (X diameter, Z) compensated, the
    /// side given by the tip direction against the cutting leg whatever
    /// G41/G42 says (tips 0, 9 and a tip along the cutting leg give none:
    /// then G41/G42 as written); the start-up on the first leg, the cancel
    /// on the return. True when the legs were made here; false when the
    /// cycle runs as programmed (G92 threading, setting 7.35 `off`, no
    /// radius), the vector taken off first.
    pub(in crate::machine) fn nose_single_cycle(
        &mut self,
        b: &Block,
        cycle: LatheCycle,
        start: [f64; 2],
        legs: &[(f64, f64, MoveKind); 4],
        out: &mut Out,
    ) -> Result<bool, Diagnostic> {
        let mode = self.state.cutter.mode;
        let radius = self.cutter_radius();
        if mode == CutterCompensation::Cancel || radius == 0.0 {
            self.nose_take_off(out);
            return Ok(false);
        }
        let name = Code::Motion(Motion::LatheCycle(cycle)).gcode(self.state.table());
        let why = match (cycle, self.setup.settings.nose_single_cycles()) {
            (LatheCycle::Threading, _) => Some((
                "nose-thread",
                "a threading cycle is not compensated (the thread's flanks are cut by the tool's form, not its nose radius)",
            )),
            (_, NoseSingleCycles::Off) => Some((
                "nose-single-cycle",
                "the single cycles are not compensated (setting nose_single_cycles = off)",
            )),
            (_, NoseSingleCycles::Tip) => None,
        };
        if let Some((code, text)) = why {
            self.nose_take_off(out);
            let text = format!(
                "{name} with {}: {text}; it runs as programmed (behaviour 18.16)",
                mode.gcode()
            );
            out.notes.push(text.clone());
            out.warnings.push(Diagnostic::warning(code, b.span, text));
            return Ok(false);
        }
        let tip = self.nose_register().1;
        let v = nose::tip_vector(tip);
        // The cutting leg (the second) and the side the nose centre keeps
        // away from the part: against the tip's vector (18.15).
        let (b1, c1) = (plane([legs[0].0, legs[0].1]), plane([legs[1].0, legs[1].1]));
        let n = geo::left(geo::unit([c1[0] - b1[0], c1[1] - b1[1]]));
        let towards = n[0] * v[0] + n[1] * v[1];
        let side = if towards < -1e-9 {
            CutterCompensation::Left
        } else if towards > 1e-9 {
            CutterCompensation::Right
        } else {
            mode
        };
        let segs: Vec<Seg> = legs
            .iter()
            .enumerate()
            .map(|(i, &(x, z, kind))| Seg {
                to: [x, z],
                arc: None,
                rapid: kind == MoveKind::Rapid,
                feed: self.state.feed,
                spindle: self.state.spindle,
                dwell: None,
                nose: match i {
                    0 => Some(side),
                    3 => Some(CutterCompensation::Cancel),
                    _ => None,
                },
            })
            .collect();
        let c = Contour {
            start,
            segs,
            p_x: true,
            p_z: true,
            p_start: b.span.start,
            p_line: b.span.line,
            q_line: b.span.line,
        };
        // The contour's sentence is not this cycle's; its warnings are.
        let mut scratch = Out::default();
        let shape = self.nose_shape(b, Repetitive::Finishing, &c, &mut scratch)?;
        out.warnings.append(&mut scratch.warnings);
        let Some(shape) = shape else {
            return Ok(false);
        };
        self.nose_take_off(out);
        self.state.lathe.vector = self.state.lathe.target;
        self.nose_trace(out, &c.segs, &shape, [0.0; 2], false)?;
        let units = self.units();
        out.notes.push(format!(
            "{name} with {} (offset {:02}, nose R {}, tip {tip}): the legs compensated {} of the cutting leg{} — start-up on the approach, the cancel on the return to the start point; the program's points are {} (behaviour 18.15)",
            mode.gcode(),
            self.state.lathe.offset,
            show(radius.abs(), units),
            if side == CutterCompensation::Left { "left" } else { "right" },
            if side == mode {
                String::new()
            } else {
                format!(" (the tip's side, whatever {} says)", mode.gcode())
            },
            nose::follows(tip)
        ));
        Ok(true)
    }

    /// The interference check on a compensated segment (behaviour 18.6):
    /// a line whose offset runs against it, an arc the nose does not fit.
    fn nose_interference(
        &self,
        b: &Block,
        out: &mut Out,
        p: &Path,
        o: f64,
        (from, to): (P2, P2),
    ) -> Result<(), Diagnostic> {
        let bad = match *p {
            Path::Line { from: a, to: z } => geo::line_reverses((a, z), (from, to)),
            Path::Arc {
                from: a,
                to: z,
                center,
                ccw,
            } => {
                let r = p.offset_radius(o).unwrap_or(0.0);
                r <= 1e-9
                    || geo::arc_interferes(
                        geo::sweep(a, z, center, ccw),
                        geo::sweep(from, to, center, ccw),
                        r,
                    )
            }
        };
        if !bad {
            return Ok(());
        }
        let what = "the nose's offset path runs against the programmed one (too narrow a groove or too small an arc for the nose radius)";
        match self.setup.settings.cutter_interference_check {
            CutterInterference::Alarm => Err(self.error(
                "cutter-interference",
                b.span,
                format!("interference in the cycle's contour: {what} — alarm PS0041"),
            )),
            CutterInterference::Off => {
                out.warnings.push(Diagnostic::warning(
                    "cutter-interference",
                    b.span,
                    format!(
                        "interference in the cycle's contour: {what}; with the check off (setting cutter_interference_check) the tool cuts into the part"
                    ),
                ));
                Ok(())
            }
        }
    }

    #[cold]
    fn nose_arc_error(&self, b: &Block, cycle: Repetitive, c: &Contour, what: &str) -> Diagnostic {
        self.error(
            "cutter-arc",
            b.span,
            format!(
                "{}: the contour (lines {}–{}) makes its compensation {what} in a G02/G03 block: compensation starts and ends on a G00 or G01 move (Fanuc alarm PS0034)",
                self.code_name(cycle),
                c.p_line,
                c.q_line
            ),
        )
    }

    #[cold]
    fn nose_arc_radius(&self, b: &Block) -> Diagnostic {
        self.nose_arc_radius_at(b.span)
    }

    #[cold]
    fn nose_arc_radius_at(&self, span: crate::diag::Span) -> Diagnostic {
        self.error(
            "cutter-arc-radius",
            span,
            "the compensated contour's arc cannot be made (its ends are not the same distance from its centre)",
        )
    }
}
