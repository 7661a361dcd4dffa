//! Haas G12/G13 circular pocket milling (behaviour 14.12, Haas mill
//! operator's manual, "G12 Circular Pocket Milling CW / G13 Circular Pocket
//! Milling CCW (Group 00)"): from the pocket's centre, a half-circle lead-in
//! to the first circle, a full circle at each radius from I out to K in steps
//! of Q, a half-circle lead-out back to the centre, L times, each pass at the
//! depth Z. The programmed path is the contour of radius I…K; the actual
//! path is the tool's centre, inside it by the D register (the manual: "the
//! control uses the selected D code tool size"; D00 is the tool centreline).

use super::arc::{self, Circle};
use super::modal::{ArcDirection, Distance, Plane};
use super::{ArcInfo, Machine, Mark, MoveKind, Out};
use crate::diag::Diagnostic;
use crate::geometry::{Xyz, to_units};
use crate::setup::CirclePocket;
use crate::syntax::codes::Group;
use crate::syntax::{Address, Block};

/// One of the pocket's paths (the programmed contour or the tool centre)
/// at one moment: the point of the plane, with the height and the vectors.
struct Pass {
    /// Pocket centre (programmed, mm).
    center: Xyz,
    /// +1 or -1: the side of the centre the lead-in goes to (the mirror
    /// image of X turns it round).
    side: f64,
    /// Counter-clockwise in the plane's frame (after mirror image).
    ccw: bool,
    /// Actual minus programmed of every point: the offset vectors.
    offset: Xyz,
}

/// The radii of a pocket's circles: `first`, `first + step`, … `finish`.
#[derive(Clone, Copy)]
struct Radii {
    first: f64,
    finish: f64,
    step: f64,
}

impl Radii {
    /// How many circles (a whole number; the move budget bounds the loop
    /// that cuts them).
    fn count(self) -> f64 {
        if self.finish <= self.first {
            1.0
        } else {
            ((self.finish - self.first) / self.step - 1e-9).ceil() + 1.0
        }
    }

    /// The radius of circle `k` (from 0).
    fn at(self, k: f64) -> f64 {
        (self.first + k * self.step).min(self.finish)
    }
}

impl Machine {
    /// A G12/G13 block on the mill (behaviour 14.12).
    pub(super) fn circle_pocket(
        &mut self,
        b: &Block,
        direction: ArcDirection,
        out: &mut Out,
    ) -> Result<(), Diagnostic> {
        let code = b.code_span(Group::NonModal);
        let name = match direction {
            ArcDirection::Cw => "G12",
            ArcDirection::Ccw => "G13",
        };
        if self.setup.settings.circle_pocket() == CirclePocket::Alarm {
            return Err(self.error(
                "unsupported-g-code",
                code,
                format!(
                    "{name} is circular pocket milling on a Haas mill; the {} control has no {name} on the mill and alarms (setting circle_pocket: haas models it)",
                    self.setup.settings.control.name()
                ),
            ));
        }
        if self.state.modal.plane != Plane::XY {
            return Err(self.error(
                "pocket-words",
                code,
                format!("{name} mills its pocket in the XY plane: select G17 first (Haas)"),
            ));
        }
        if let Some(cycle) = self.state.modal.cycle {
            return Err(self.error(
                "pocket-words",
                code,
                format!(
                    "{name} cannot be given while canned cycle {} is active: cancel it with G80 first",
                    cycle.gcode()
                ),
            ));
        }
        for a in [Address::J, Address::R, Address::P, Address::H] {
            if let Some(w) = b.get(a) {
                let why = match a {
                    Address::H => "give the tool length offset in a block before it",
                    _ => "its words are X, Y, Z, I, K, Q, L, D and F (Haas)",
                };
                return Err(self.error(
                    "pocket-words",
                    w.span,
                    format!("{name} does not read {}: {why}", a.letter()),
                ));
            }
        }
        if b.holds_group(Group::Length) {
            return Err(self.error(
                "pocket-words",
                b.code_span(Group::Length),
                format!("{name}: give the tool length offset in a block before it"),
            ));
        }
        let Some(i) = b.get(Address::I) else {
            return Err(self.error(
                "pocket-words",
                code,
                format!(
                    "{name} needs I, the radius of the first circle (or of the finished circle without K)"
                ),
            ));
        };
        let first = self.mm(i.value);
        let finish = b.value(Address::K).map(|k| self.mm(k));
        let step = b.value(Address::Q).map(|q| self.mm(q));
        let d = self.state.position.d;
        let tool = self.mm(self.setup.d_value(d));
        let units = self.units();
        let dec = units.decimals();
        let f = |mm: f64| format!("{:.dec$}", to_units(mm, units));
        if first - tool <= 0.0 {
            return Err(self.error(
                "pocket-words",
                i.span,
                format!(
                    "{name}: I ({}) must be greater than the tool radius, D{d:02} = {} (Haas)",
                    f(first),
                    f(tool)
                ),
            ));
        }
        match (finish, step, b.get(Address::K), b.get(Address::Q)) {
            (Some(k), _, Some(kw), _) if k <= first => {
                return Err(self.error(
                    "pocket-words",
                    kw.span,
                    format!(
                        "{name}: K, the finished radius ({}), must be greater than I ({}) (Haas)",
                        f(k),
                        f(first)
                    ),
                ));
            }
            (Some(_), None, Some(kw), _) => {
                return Err(self.error(
                    "pocket-words",
                    kw.span,
                    format!("{name}: K needs Q, the step from one circle to the next (Haas)"),
                ));
            }
            (None, Some(_), _, Some(qw)) => {
                return Err(self.error(
                    "pocket-words",
                    qw.span,
                    format!("{name}: Q, the radius step, goes with K, the finished radius (Haas)"),
                ));
            }
            (_, Some(q), _, Some(qw)) if q <= 0.0 => {
                return Err(self.error(
                    "pocket-words",
                    qw.span,
                    format!("{name}: Q, the radius step, must be positive"),
                ));
            }
            _ => {}
        }
        let passes = match b.get(Address::L) {
            Some(l) if l.int() == 0 => {
                return Err(self.error(
                    "pocket-words",
                    l.span,
                    format!("{name}: L counts the passes and is 1 or more"),
                ));
            }
            Some(l) => l.int(),
            None => 1,
        };

        // The radii of the circles: I, then I + Q … up to K (the last step
        // shorter when Q does not divide K - I).
        let radii = Radii {
            first,
            finish: finish.unwrap_or(first),
            step: step.unwrap_or(1.0),
        };

        let incremental = self.state.modal.distance == Distance::Incremental;
        // Position over the centre at rapid first when the block gives it
        // (our convention: the manual positions the tool in an earlier block
        // or with X and Y here, without saying at which rate).
        let start = self.mark();
        for axis in 0..2 {
            if let Some(v) = b.value([Address::X, Address::Y][axis]) {
                self.state.programmed[axis] = self.target(axis, self.mm(v), incremental);
            }
        }
        let to = self.mark();
        self.push_move(out, MoveKind::Rapid, start, to, None);

        let pv = self.state.position.vector;
        let pass = Pass {
            center: self.state.programmed,
            side: if self.mirror[0] { -1.0 } else { 1.0 },
            ccw: (direction == ArcDirection::Ccw) != (self.mirror[0] != self.mirror[1]),
            offset: [pv[0], pv[1], pv[2] + self.state.length.vector],
        };
        let z_word = b.value(Address::Z).map(|z| self.mm(z));
        for _ in 0..passes {
            if self.overflow {
                break;
            }
            if let Some(z) = z_word {
                let start = self.mark();
                self.state.programmed[2] = if incremental {
                    self.state.programmed[2] + z
                } else {
                    z
                };
                let to = self.mark();
                self.push_move(out, MoveKind::Feed, start, to, None);
            }
            self.pocket_pass(&pass, radii, tool, out);
        }

        let last = radii.finish;
        let count = radii.count();
        let circles = if count == 1.0 {
            format!(
                "one circle of radius {}, the tool centre on radius {}",
                f(first),
                f(first - tool)
            )
        } else {
            format!(
                "{count} circles of radius {} to {} in steps of {}, the tool centre on radii {} to {}",
                f(first),
                f(last),
                f(step.unwrap_or(0.0)),
                f(first - tool),
                f(last - tool)
            )
        };
        let turn = if direction == ArcDirection::Cw {
            "clockwise"
        } else {
            "counter-clockwise"
        };
        let repeat = if passes > 1 {
            format!(", {passes} passes (L{passes})")
        } else {
            String::new()
        };
        out.notes.push(format!(
            "{name} circular pocket (Haas), {turn} about X{} Y{}: {circles}, inside the contour by D{d:02} ({}); a half-circle lead-in from the centre and a half-circle lead-out back to it{repeat}",
            f(pass.center[0]),
            f(pass.center[1]),
            f(tool)
        ));
        Ok(())
    }

    /// One pass at the current height: lead-in, the circles, lead-out.
    fn pocket_pass(&mut self, pass: &Pass, radii: Radii, tool: f64, out: &mut Out) {
        let z = self.state.programmed[2];
        let at = |r: f64| -> Mark {
            let prog = [pass.center[0] + pass.side * r, pass.center[1], z];
            let act_r = r - tool;
            let act = [
                pass.center[0] + pass.side * act_r + pass.offset[0],
                pass.center[1] + pass.offset[1],
                z + pass.offset[2],
            ];
            Mark { prog, act }
        };
        let centre = Mark {
            prog: [pass.center[0], pass.center[1], z],
            act: [
                pass.center[0] + pass.offset[0],
                pass.center[1] + pass.offset[1],
                z + pass.offset[2],
            ],
        };
        // Lead-in: a half circle whose diameter runs from the centre to the
        // first circle.
        let first = radii.first;
        self.pocket_arc(
            out,
            pass,
            centre,
            at(first),
            [first / 2.0, first / 2.0 - tool / 2.0],
        );
        let mut previous = first;
        let mut k = 0.0;
        while k < radii.count() && !self.overflow {
            let r = radii.at(k);
            if k > 0.0 {
                // Out to the next circle along the lead-in's radius (our
                // convention: the manual does not draw the step).
                self.push_move(out, MoveKind::Feed, at(previous), at(r), None);
            }
            self.pocket_arc(out, pass, at(r), at(r), [r, r - tool]);
            previous = r;
            k += 1.0;
        }
        if self.overflow {
            return;
        }
        // Lead-out: a half circle back to the centre.
        self.pocket_arc(
            out,
            pass,
            at(previous),
            centre,
            [previous / 2.0, previous / 2.0 - tool / 2.0],
        );
    }

    /// An arc of the pocket from `from` to `to` about the centre halfway
    /// between them on the lead-in's line (or the pocket's centre for a full
    /// circle), of the programmed and the actual radius in `radius`.
    fn pocket_arc(&mut self, out: &mut Out, pass: &Pass, from: Mark, to: Mark, radius: [f64; 2]) {
        let full = from.prog == to.prog;
        let circle = |a: Xyz, b: Xyz, r: f64| -> Circle {
            let (start, end) = ([a[0], a[1]], [b[0], b[1]]);
            let center = if full {
                [start[0] - pass.side * r, start[1]]
            } else {
                [(start[0] + end[0]) / 2.0, (start[1] + end[1]) / 2.0]
            };
            // Both ends lie on the circle by construction; the radius check
            // cannot fail.
            arc::from_center(start, end, center, pass.ccw, 1e-6).unwrap_or(Circle {
                center,
                radius: r,
                start_angle: 0.0,
                sweep: 0.0,
            })
        };
        let prog = circle(from.prog, to.prog, radius[0]);
        let act = circle(from.act, to.act, radius[1]);
        let lift = |c: [f64; 2], z: f64| [c[0], c[1], z];
        let info = ArcInfo {
            plane: Plane::XY,
            center: lift(act.center, from.act[2]),
            programmed_center: lift(prog.center, from.prog[2]),
            radius: act.radius,
            programmed_radius: prog.radius,
            sweep: act.sweep,
            programmed_sweep: prog.sweep,
            start_angle: act.start_angle,
            programmed_start_angle: prog.start_angle,
            diameter_x: false,
        };
        let kind = if pass.ccw {
            MoveKind::ArcCcw
        } else {
            MoveKind::ArcCw
        };
        self.push_move(out, kind, from, to, Some(info));
    }
}
