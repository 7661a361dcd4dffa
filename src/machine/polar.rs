//! Polar coordinate interpolation on the lathe (behaviour 14.11, 14.15–14.19):
//! G12.1 (Haas G112) makes the linear axis X and the rotary axis C a
//! Cartesian plane on the face of the work, the *hypothetical axis* (C on
//! Fanuc, Y on Haas) being a length; G01, G02 and G03 move in that plane and
//! the control turns C and moves X to follow them; G13.1 (G113) ends it.
//!
//! While the mode is on, a lathe position is the face plane's point: X, a
//! diameter-valued coordinate as everywhere on the lathe (twice the
//! distance along the plane's first axis), and the hypothetical axis as Y;
//! Z is Z. [`PolarState`] keeps how far C has turned. The T offset acts
//! along the machine's X axis, which turns with C in the face plane
//! (behaviour 14.17).

use std::f64::consts::{PI, TAU};

use super::arc::{Circle, P2};
use super::modal::{ArcDirection, Distance, Modal, Motion};
use super::state::PolarState;
use super::{ArcRequest, Machine, Mark, MoveKind, Out};
use crate::diag::Diagnostic;
use crate::geometry::{Xyz, show};
use crate::setup::PolarInterpolation;
use crate::syntax::codes::{Code, Group, NonModal, Plane, Polar, PolarSpelling};
use crate::syntax::{Address, Block};

/// The words that move the tool or shape a move: a G12.1 or G13.1 block
/// takes none of them (behaviour 14.15).
const MOVING: [Address; 12] = [
    Address::X,
    Address::U,
    Address::Z,
    Address::W,
    Address::C,
    Address::Y,
    Address::I,
    Address::J,
    Address::K,
    Address::R,
    Address::H,
    Address::T,
];

/// A point this close to the spindle axis is on it (mm).
const ON_AXIS: f64 = 1e-9;
/// Most C turn (and arc sweep) one piece of a move drawn in pieces spans
/// (behaviour 14.17): the actual path then keeps within a micrometre of
/// the true curve for an X offset of a few tenths.
const PIECE_TURN: f64 = 2.0 * PI / 180.0;
/// Most pieces one move is drawn with.
const MAX_PIECES: usize = 1024;

/// The plane's point (first axis, hypothetical axis) of a lathe position
/// in the mode (mm).
fn face(p: Xyz) -> P2 {
    [p[0] / 2.0, p[1]]
}

/// `a` wrapped into (−π, π].
fn wrap(a: f64) -> f64 {
    let w = (a + PI).rem_euclid(TAU) - PI;
    if w <= -PI { w + TAU } else { w }
}

fn norm(p: P2) -> f64 {
    p[0].hypot(p[1])
}

/// How far C turns along a straight move from `p0` to `p1` of the face
/// plane, C standing at `theta` (radians): and whether the move passes
/// through the spindle axis, where C turns half a turn at once
/// (behaviour 14.16: counted as +180°, our convention).
fn line_turn(theta: f64, p0: P2, p1: P2) -> (f64, bool) {
    if norm(p1) < ON_AXIS {
        // Ending on the axis, C stays where it is.
        return (0.0, false);
    }
    let a1 = p1[1].atan2(p1[0]);
    if norm(p0) < ON_AXIS {
        return (wrap(a1 - theta), false);
    }
    let cross = p0[0] * p1[1] - p0[1] * p1[0];
    let dot = p0[0] * p1[0] + p0[1] * p1[1];
    let length = (p1[0] - p0[0]).hypot(p1[1] - p0[1]);
    if cross.abs() <= ON_AXIS * length.max(1.0) && dot < 0.0 {
        return (PI, true);
    }
    (wrap(a1 - p0[1].atan2(p0[0])), false)
}

/// How far C turns along an arc `c` (face plane) from `p0` to `p1`, C
/// standing at `theta`: the turn between the ends plus a whole turn when the
/// spindle axis lies between the arc and its chord (the arc goes round
/// it); an arc through the axis is followed point by point.
fn arc_turn(theta: f64, c: &Circle, p0: P2, p1: P2) -> (f64, bool) {
    let on_circle = (norm(c.center) - c.radius).abs() < ON_AXIS;
    if norm(p0) < ON_AXIS || norm(p1) < ON_AXIS || on_circle {
        return (traced_turn(theta, c), true);
    }
    let a0 = p0[1].atan2(p0[0]);
    let a1 = p1[1].atan2(p1[0]);
    let full = c.sweep.abs() >= TAU - 1e-12;
    let direction = c.sweep.signum();
    let mut turn = if full { 0.0 } else { wrap(a1 - a0) };
    let inside_disc = norm(c.center) < c.radius;
    if full {
        if inside_disc {
            turn = TAU * direction;
        }
        return (turn, false);
    }
    // Which side of the chord the arc lies on: its middle's.
    let m = c.point(0.5);
    let side = |q: P2| (p1[0] - p0[0]) * (q[1] - p0[1]) - (p1[1] - p0[1]) * (q[0] - p0[0]);
    let origin = side([0.0, 0.0]);
    let length = (p1[0] - p0[0]).hypot(p1[1] - p0[1]);
    if origin.abs() <= ON_AXIS * length.max(1.0) {
        // The axis on the chord's line: between the ends the arc goes half
        // round it, its own way; beyond them (outside the circle) not at all.
        let between = p0[0] * p1[0] + p0[1] * p1[1] < 0.0;
        return (if between { PI * direction } else { turn }, false);
    }
    if inside_disc && origin.signum() == side(m).signum() {
        turn += TAU * direction;
    }
    (turn, false)
}

/// The turn of C along an arc found point by point (an arc that passes
/// through the spindle axis or starts or ends on it).
fn traced_turn(theta: f64, c: &Circle) -> f64 {
    let n = ((c.sweep.abs() / (0.25f64).to_radians()).ceil() as usize).clamp(8, 4096);
    let mut angle = theta;
    for i in 1..=n {
        let p = c.point(i as f64 / n as f64);
        if norm(p) < ON_AXIS {
            continue;
        }
        angle += wrap(p[1].atan2(p[0]) - angle);
    }
    angle - theta
}

/// The path of one move in the face plane: a line or an arc, with Z.
#[derive(Clone, Copy)]
enum Path {
    Line(P2, P2),
    Arc(Circle),
}

impl Path {
    /// The face point at `t` (0 the start, 1 the end).
    fn at(&self, t: f64, end: P2) -> P2 {
        if t >= 1.0 {
            return end;
        }
        match self {
            Path::Line(a, b) => [a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t],
            Path::Arc(c) => c.point(t),
        }
    }

    /// The piece from `t0` to `t1`: how far C turns along it from `theta`,
    /// and whether it passes through the spindle axis.
    fn turn(&self, theta: f64, (t0, t1): (f64, f64), end: P2) -> (f64, bool) {
        let (p0, p1) = (self.at(t0, end), self.at(t1, end));
        match self {
            Path::Line(..) => line_turn(theta, p0, p1),
            Path::Arc(c) => {
                let piece = Circle {
                    start_angle: c.start_angle + c.sweep * t0,
                    sweep: c.sweep * (t1 - t0),
                    ..*c
                };
                arc_turn(theta, &piece, p0, p1)
            }
        }
    }

    /// The arc's sweep over a piece (0 for a line).
    fn sweep(&self, span: f64) -> f64 {
        match self {
            Path::Line(..) => 0.0,
            Path::Arc(c) => (c.sweep * span).abs(),
        }
    }
}

impl Machine {
    /// The letter of the hypothetical axis: C (Fanuc) or Y (Haas G112,
    /// "XY to XC"), as setting `polar_interpolation` says (behaviour 7.33).
    pub(super) fn polar_axis(&self) -> Address {
        match self.setup.settings.polar_interpolation() {
            PolarInterpolation::Fanuc => Address::C,
            PolarInterpolation::Haas => Address::Y,
        }
    }

    /// True when block `b` runs in polar coordinate interpolation: the mode
    /// is on and the block does not end it, or the block starts it.
    pub(super) fn in_polar_mode(&self, b: &Block) -> bool {
        match b.codes().polar() {
            Some(p) => p.is_on(),
            None => self.state.polar.is_some(),
        }
    }

    /// The cancel code of the mode in force, as the program spells it.
    fn polar_cancel(&self) -> &'static str {
        match self.state.modal.polar {
            Polar::On(PolarSpelling::Haas) | Polar::Off(PolarSpelling::Haas) => "G113",
            _ => "G13.1",
        }
    }

    /// What polar coordinate interpolation refuses in a block (behaviour
    /// 14.15, 14.18): a G12.1 or G13.1 block takes no axis, centre, R or T
    /// word (Fanuc: specify them in blocks of their own); in the mode, the
    /// codes the control alarms on (Fanuc PS0146: reference returns, skip,
    /// coordinate systems, planes, the turning cycles, and on Fanuc G00), a
    /// T code (no offset changes in the mode), and the word of the other
    /// control's hypothetical axis.
    pub(super) fn refuse_polar(&self, b: &Block) -> Result<(), Diagnostic> {
        let c = b.codes();
        if let Some(code) = c.polar() {
            if let Some(w) = b.words.iter().find(|w| MOVING.contains(&w.address)) {
                let what = if w.address == Address::T {
                    "a T code goes before G12.1: no offset changes in the mode (Fanuc)"
                } else {
                    "Fanuc: specify G12.1 and G13.1 in blocks of their own; move in the blocks after it"
                };
                return Err(self.error(
                    "polar-interpolation",
                    w.span,
                    format!("{} with {}: {what}", code.gcode(), w.address.letter()),
                ));
            }
            if code.is_on() && self.state.modal.cylinder.is_some() {
                return Err(self.error(
                    "polar-interpolation",
                    b.code_span(Group::Polar),
                    format!(
                        "{} cannot start while G07.1 cylindrical interpolation is on: cancel it with G07.1 C0 first",
                        code.gcode()
                    ),
                ));
            }
        }
        if !self.in_polar_mode(b) {
            return Ok(());
        }
        let cancel = match c.polar() {
            Some(Polar::On(PolarSpelling::Haas)) => "G113",
            Some(Polar::On(_)) => "G13.1",
            _ => self.polar_cancel(),
        };
        let refuse = |group: Group, name: String| {
            Err(self.error(
                "polar-interpolation",
                b.code_span(group),
                format!(
                    "{name} cannot be given in polar coordinate interpolation (Fanuc alarm PS0146): cancel it with {cancel} first"
                ),
            ))
        };
        let table = self.state.table();
        match c.non_modal() {
            None | Some(NonModal::Dwell) => {}
            Some(code) => return refuse(Group::NonModal, Code::NonModal(code).gcode(table).into()),
        }
        if let Some(w) = c.work() {
            return refuse(Group::Work, w.gcode().to_string());
        }
        if let Some(p) = c.plane() {
            return refuse(
                Group::Plane,
                format!("{} (the mode has its own plane)", p.gcode()),
            );
        }
        let style = self.setup.settings.polar_interpolation();
        let motion = c.motion().unwrap_or(self.state.modal.motion);
        let moves = [
            Address::X,
            Address::U,
            Address::Z,
            Address::W,
            Address::C,
            Address::Y,
            Address::I,
            Address::J,
            Address::R,
        ]
        .iter()
        .any(|a| b.has(*a));
        let at = if c.motion().is_some() {
            b.code_span(Group::Motion)
        } else {
            b.words
                .iter()
                .find(|w| MOVING.contains(&w.address))
                .map_or(b.span, |w| w.span)
        };
        match motion {
            Motion::LatheCycle(_) if c.motion().is_some() || moves => {
                return refuse(Group::Motion, Code::Motion(motion).gcode(table).into());
            }
            Motion::Rapid
                if style == PolarInterpolation::Fanuc && (c.motion().is_some() || moves) =>
            {
                return Err(self.error(
                    "polar-interpolation",
                    at,
                    format!(
                        "G00 in polar coordinate interpolation: the Fanuc control moves only with G01, G02 and G03 in the mode (alarm PS0146); write G01, or cancel with {cancel} and position at rapid (setting polar_interpolation = haas allows G00, as Haas does)"
                    ),
                ));
            }
            _ => {}
        }
        if let Some(t) = b.get(Address::T) {
            return Err(self.error(
                "polar-interpolation",
                t.span,
                format!(
                    "a T code in polar coordinate interpolation: no offset can be changed in the mode (Fanuc: specify the tool offset before G12.1); cancel it with {cancel} first"
                ),
            ));
        }
        if let Some(h) = b.get(Address::H) {
            return Err(self.error(
                "polar-words",
                h.span,
                "H, the incremental hypothetical axis of Fanuc's G-code system A, is not modelled: write C as an absolute value",
            ));
        }
        let other = match style {
            PolarInterpolation::Fanuc => Address::Y,
            PolarInterpolation::Haas => Address::C,
        };
        if let Some(w) = b.get(other) {
            let why = match style {
                PolarInterpolation::Fanuc => {
                    "Y: the hypothetical axis of Fanuc's G12.1 is C (Haas's G112 writes Y: setting polar_interpolation = haas)"
                }
                PolarInterpolation::Haas => {
                    "C: Haas's G112 programs the face in X and Y (XY to XC); C is not read in the mode (setting polar_interpolation = fanuc reads C)"
                }
            };
            return Err(self.error("polar-words", w.span, why));
        }
        Ok(())
    }

    /// G12.1/G13.1 (G112/G113) in a block: the mode starts or ends, with its
    /// sentence (behaviour 14.11, 14.15, 14.19).
    pub(super) fn polar_code(&mut self, b: &Block, out: &mut Out, before: Modal) {
        let Some(code) = b.codes().polar() else {
            return;
        };
        if code == before.polar {
            return;
        }
        self.state.modal.polar = code;
        let on = code.is_on();
        if on == self.state.polar.is_some() {
            // G12.1 → G112: the same mode, spelled otherwise.
            return;
        }
        let u = self.units();
        let style = self.setup.settings.polar_interpolation();
        let (axis, x_is) = match style {
            PolarInterpolation::Fanuc => ("C", "a diameter, as everywhere on the lathe"),
            PolarInterpolation::Haas => ("Y", "a radius"),
        };
        if on {
            let polar = PolarState {
                angle: 0.0,
                x_offset: self.state.lathe.vector[0],
            };
            self.state.polar = Some(polar);
            let p = self.state.programmed;
            out.notes.push(format!(
                "{} polar coordinate interpolation on: X ({x_is}) and the hypothetical axis {axis} (a length, 0 now) make a Cartesian plane on the face, drawn in the XC (face) view; the C axis's place now is its 0°, and the tool stands at {} with X {} from the spindle axis; G01, G02 and G03 move in that plane, the control turning C and moving X to follow, and F is the feed along the face contour",
                code.gcode(),
                self.face_words(p),
                show(face(p)[0], u),
            ));
            return;
        }
        let polar = self.state.polar.take().unwrap_or(PolarState {
            angle: 0.0,
            x_offset: 0.0,
        });
        let p = self.state.programmed;
        let x = 2.0 * norm(face(p));
        self.state.programmed = [x, 0.0, p[2]];
        self.state.lathe.vector = [polar.x_offset, 0.0, self.state.lathe.vector[2]];
        out.notes.push(format!(
            "{} polar coordinate interpolation off: the work stands turned by C{:.3}° from its place at G12.1; the lathe's X is the tool's distance from the spindle axis again, X{} (a diameter), and the next move starts there",
            code.gcode(),
            polar.angle.to_degrees(),
            show(x, u),
        ));
    }

    /// The face point of a lathe position as the program writes it: `X…
    /// C…` (Fanuc, X a diameter) or `X… Y…` (Haas, X a radius).
    fn face_words(&self, p: Xyz) -> String {
        let u = self.units();
        match self.setup.settings.polar_interpolation() {
            PolarInterpolation::Fanuc => format!("X{} C{}", show(p[0], u), show(p[1], u)),
            PolarInterpolation::Haas => format!("X{} Y{}", show(p[0] / 2.0, u), show(p[1], u)),
        }
    }

    /// The block's end point in the face plane and Z (behaviour 14.15): X
    /// (U incremental) as a diameter or a radius, the hypothetical axis,
    /// incremental in G91 (G-code systems B and C).
    fn polar_target(&self, b: &Block) -> Xyz {
        let style = self.setup.settings.polar_interpolation();
        let k = match style {
            PolarInterpolation::Fanuc => 0.5,
            PolarInterpolation::Haas => 1.0,
        };
        let incremental = self.state.modal.distance == Distance::Incremental;
        let p0 = face(self.state.programmed);
        let mut p1 = p0;
        match (b.value(Address::X), b.value(Address::U)) {
            (Some(v), _) if incremental => p1[0] = p0[0] + self.mm(v) * k,
            (Some(v), _) => p1[0] = self.mm(v) * k,
            (None, Some(d)) => p1[0] = p0[0] + self.mm(d) * k,
            (None, None) => {}
        }
        if let Some(v) = b.value(self.polar_axis()) {
            p1[1] = if incremental {
                p0[1] + self.mm(v)
            } else {
                self.mm(v)
            };
        }
        let z = self.lathe_target(b, 2).unwrap_or(self.state.programmed[2]);
        [2.0 * p1[0], p1[1], z]
    }

    /// A block that moves in polar coordinate interpolation (behaviour
    /// 14.15–14.17): a line or an arc of the face plane, C turning and X
    /// moving to follow it; with an X offset the tool's reference point is
    /// pushed out along the radius and the move is made of pieces.
    pub(super) fn polar_move(&mut self, b: &Block, out: &mut Out) -> Result<(), Diagnostic> {
        let Some(polar) = self.state.polar else {
            return Ok(());
        };
        let motion = self.state.modal.motion;
        let moves = [
            Address::X,
            Address::U,
            Address::Z,
            Address::W,
            self.polar_axis(),
        ]
        .iter()
        .any(|a| b.has(*a));
        let arc_words = motion.is_arc()
            && [Address::I, Address::J, Address::R]
                .iter()
                .any(|a| b.has(*a));
        if !moves && !arc_words {
            return Ok(());
        }
        let p0 = self.state.programmed;
        let target = self.polar_target(b);
        let (f0, f1) = (face(p0), face(target));
        let theta = polar.angle;
        // Z carries the offset's Z when it moves (behaviour 5.14).
        let vz = if b.has(Address::Z) || b.has(Address::W) {
            self.state.lathe.target[2]
        } else {
            self.state.lathe.vector[2]
        };
        let start = self.mark();
        let (path, arc) = match motion {
            Motion::Arc(direction) => {
                let circle = self.polar_circle(b, out, direction, target, vz)?;
                (Path::Arc(circle.0), Some(circle.1))
            }
            _ => (Path::Line(f0, f1), None),
        };
        let kind = match (motion, arc) {
            (Motion::Rapid, _) => MoveKind::Rapid,
            (_, Some(a)) if a.sweep > 0.0 => MoveKind::ArcCcw,
            (_, Some(_)) => MoveKind::ArcCw,
            _ => MoveKind::Feed,
        };
        let at_feed = motion != Motion::Rapid;
        let (turn, through) = path.turn(theta, (0.0, 1.0), f1);
        let pieces = if polar.x_offset == 0.0 {
            self.state.programmed = target;
            self.state.lathe.vector = polar.vector(theta + turn, vz);
            self.state.polar = Some(PolarState {
                angle: theta + turn,
                ..polar
            });
            self.emit(out, start, kind, at_feed, arc);
            1
        } else {
            self.polar_pieces(out, (path, f1), (p0, target), vz, at_feed)
        };
        self.polar_note(out, (p0, target), (turn, through), arc, pieces);
        Ok(())
    }

    /// The programmed circle of an arc in the face plane (I along X, a
    /// radius value, and J along the hypothetical axis; or R), and its arc
    /// as reported (behaviour 14.15).
    fn polar_circle(
        &self,
        b: &Block,
        out: &mut Out,
        direction: ArcDirection,
        target: Xyz,
        vz: f64,
    ) -> Result<(Circle, super::ArcInfo), Diagnostic> {
        let p0 = self.state.programmed;
        let act0 = self.mark().act;
        // The actual arc asked for is the programmed one moved as the start
        // is: with no X offset, the T offset's Z alone (behaviour 14.17).
        let shift = [act0[0] - p0[0], act0[1] - p0[1], 0.0];
        let mut req = ArcRequest {
            target,
            actual_end: [target[0] + shift[0], target[1] + shift[1], target[2] + vz],
            ccw: direction == ArcDirection::Ccw,
            ..ArcRequest::default()
        };
        if let Some(r) = b.get(Address::R) {
            if b.has(Address::I) || b.has(Address::J) {
                // R wins, as on any arc (behaviour 2.13).
                out.warnings.push(Diagnostic::warning(
                    "arc-r-and-center",
                    r.span,
                    "R and I/J in one arc: R is used and I/J are ignored (Fanuc)",
                ));
            }
            req.radius = Some((self.mm(r.value), 0.0));
            if super::arc::same_point(face(p0), face(target)) {
                return Err(self.error(
                    "arc-radius",
                    b.span,
                    "an R arc whose end is its start makes no circle: a full circle in polar coordinate interpolation needs I and J",
                ));
            }
        } else {
            if !(b.has(Address::I) || b.has(Address::J)) {
                return Err(self.error(
                    "arc-without-center",
                    b.span,
                    format!(
                        "{} in polar coordinate interpolation needs R or the centre words I (along X, a radius value) and J (along the hypothetical axis)",
                        Code::Motion(Motion::Arc(direction)).gcode(self.state.table())
                    ),
                ));
            }
            req.center[0] = self.mm(b.value(Address::I).unwrap_or(0.0));
            req.center[1] = self.mm(b.value(Address::J).unwrap_or(0.0));
        }
        let info = self.arc_geometry_in(b, &req, Plane::XY)?;
        Ok((info.programmed_circle(), info))
    }

    /// A move made of pieces (behaviour 14.17): each spans at most
    /// [`PIECE_TURN`] of C and of the arc, its programmed ends on the
    /// programmed line or arc and its actual ends pushed out along the
    /// radius by the X offset at their own C angle. Returns how many.
    fn polar_pieces(
        &mut self,
        out: &mut Out,
        (path, end): (Path, P2),
        (p0, target): (Xyz, Xyz),
        vz: f64,
        at_feed: bool,
    ) -> usize {
        let Some(mut polar) = self.state.polar else {
            return 0;
        };
        // The pieces' ends, by halving until each turns C little enough.
        let mut ends = Vec::new();
        let mut stack = vec![(0.0f64, 1.0f64, 0u32)];
        while let Some((a, b, depth)) = stack.pop() {
            let (turn, _) = path.turn(polar.angle, (a, b), end);
            let fine = turn.abs() <= PIECE_TURN && path.sweep(b - a) <= PIECE_TURN;
            if fine || depth >= 16 || ends.len() + stack.len() >= MAX_PIECES {
                ends.push(b);
                continue;
            }
            let mid = (a + b) / 2.0;
            stack.push((mid, b, depth + 1));
            stack.push((a, mid, depth + 1));
        }
        let kind = if at_feed {
            MoveKind::Feed
        } else {
            MoveKind::Rapid
        };
        let mut from = self.mark();
        let mut t0 = 0.0;
        for &t in &ends {
            let (turn, _) = path.turn(polar.angle, (t0, t), end);
            polar.angle += turn;
            let q = path.at(t, end);
            let z = p0[2] + (target[2] - p0[2]) * t;
            let prog = if t >= 1.0 {
                target
            } else {
                [2.0 * q[0], q[1], z]
            };
            let to = Mark {
                prog,
                act: crate::geometry::add(prog, polar.vector(polar.angle, vz)),
            };
            self.push_move(out, kind, from, to, None);
            if self.overflow {
                break;
            }
            from = to;
            t0 = t;
        }
        self.state.programmed = target;
        self.state.lathe.vector = polar.vector(polar.angle, vz);
        self.state.polar = Some(polar);
        ends.len()
    }

    /// The sentence of a move in the mode: where it goes on the face and
    /// what the machine does (behaviour 14.19).
    fn polar_note(
        &self,
        out: &mut Out,
        (p0, target): (Xyz, Xyz),
        (turn, through): (f64, bool),
        arc: Option<super::ArcInfo>,
        pieces: usize,
    ) {
        let Some(polar) = self.state.polar else {
            return;
        };
        let u = self.units();
        let motion = Code::Motion(self.state.modal.motion).gcode(self.state.table());
        let plane = match self.setup.settings.polar_interpolation() {
            PolarInterpolation::Fanuc => "XC",
            PolarInterpolation::Haas => "XY",
        };
        let what = match arc {
            Some(a) => {
                let c = a.programmed_circle();
                format!(
                    "a {} arc of radius {} about {}",
                    if a.programmed_sweep > 0.0 {
                        "counter-clockwise"
                    } else {
                        "clockwise"
                    },
                    show(c.radius, u),
                    self.face_words([2.0 * c.center[0], c.center[1], 0.0])
                )
            }
            None => "a line".to_string(),
        };
        let x = polar.machine_x(target);
        let mut note = format!(
            "{motion} in the {plane} plane of the face: {what} to {}; the machine turns C by {:+.3}° (to {:.3}° from its place at G12.1) while X moves to {} (radius {})",
            self.face_words(target),
            turn.to_degrees(),
            polar.angle.to_degrees(),
            show(x, u),
            show(x / 2.0, u),
        );
        if target[2] != p0[2] {
            note.push_str(&format!(" and Z to {}", show(target[2], u)));
        }
        if through {
            note.push_str(
                "; it passes through the spindle axis, where C turns half a turn at once (the control slows the feed there)",
            );
        }
        if pieces > 1 {
            note.push_str(&format!(
                "; the X offset ({}) acts along the machine's X axis, which turns with C, so the tool's reference point is pushed out along the radius and its path bends: drawn as {pieces} straight pieces",
                show(polar.x_offset, u)
            ));
        }
        out.notes.push(note);
    }
}
