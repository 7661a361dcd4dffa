//! LinuxCNC's polar coordinates `@` (distance) and `^` (angle, degrees
//! counter-clockwise from +X) of the XY end point (behaviour 22.12; LinuxCNC
//! 2.9 "G-code overview", "Polar Coordinates", and what `rs274` does).
//!
//! The pole is the origin of the coordinate system in use, in G90 and G91
//! alike: in G90 `@`/`^` give the end point's distance and angle, the one
//! not written kept from the current point; in G91 they add to the current
//! point's distance and angle (the distance first). A polar block is the
//! same block with the X and Y words that reach that point, so every rule
//! of a motion block (G0–G3, canned cycles, feed, the length offset) applies
//! to it unchanged; only a G91 canned cycle repeated with L turns again at
//! each hole, so its holes are run one at a time.

use std::f64::consts::PI;

use crate::diag::{Diagnostic, Span};
use crate::machine::modal::Distance;
use crate::machine::program::ProgramText;
use crate::machine::{Ahead, Machine, Out};
use crate::syntax::codes::{CannedCycle, CutterCompensation, NonModal, Plane};
use crate::syntax::{Address, Block, Word};

/// The two polar words.
const POLAR: [Address; 2] = [Address::PolarDist, Address::PolarAngle];

/// A block's polar words: the value of each (the last one written, as
/// rs274 reads a repeated one) and where the first polar word is.
struct Polar {
    radius: Option<f64>,
    angle: Option<f64>,
    span: Span,
}

impl Machine {
    /// A mill block with `@` or `^`: checked as rs274 checks it, then run as
    /// the block with the X and Y words of its end point.
    pub(super) fn polar_block(
        &mut self,
        b: &Block,
        out: &mut Out,
        ahead: &mut dyn Ahead,
        program: &mut dyn ProgramText,
    ) -> Result<(), Diagnostic> {
        let polar = self.polar_words(b, out)?;
        let units = b.codes().units().unwrap_or(self.state.modal.units).mm();
        let distance = b.codes().distance().unwrap_or(self.state.modal.distance);
        let current = [0, 1].map(|i| self.state.programmed[i] / units);
        let cycle = self.polar_in_cycle(b);
        if distance == Distance::Absolute {
            let end =
                absolute_end(&polar, current, cycle).map_err(|m| self.polar_error(&polar, m))?;
            return self.mill_block(&with_xy(b, &polar, end, false), out, ahead, program);
        }
        // G91: the end point from the current one; a canned cycle repeats
        // the turn at each of its L holes (rs274's repeat loop).
        let repeats = match cycle {
            true => b
                .value(Address::K)
                .or_else(|| b.value(Address::L))
                .map_or(1, |k| k as u32),
            false => 1,
        };
        if repeats <= 1 {
            let end =
                incremental_end(&polar, current, cycle).map_err(|m| self.polar_error(&polar, m))?;
            let step = [end[0] - current[0], end[1] - current[1]];
            return self.mill_block(&with_xy(b, &polar, step, false), out, ahead, program);
        }
        for k in 0..repeats {
            let current = [0, 1].map(|i| self.state.programmed[i] / units);
            let end =
                incremental_end(&polar, current, true).map_err(|m| self.polar_error(&polar, m))?;
            let step = [end[0] - current[0], end[1] - current[1]];
            let hole = match k {
                // The block's own words once, one hole.
                0 => with_xy(b, &polar, step, true),
                // Then one hole at a time, the cycle's data kept.
                _ => xy_only(b, &polar, step),
            };
            self.mill_block(&hole, out, ahead, program)?;
            if self.overflow {
                break;
            }
        }
        Ok(())
    }

    /// The block's polar words, refused where rs274 refuses them: outside
    /// G17 (the plane before the block), with X or Y, in a block that is
    /// no motion (G10, G28, G30, G92…) and with G53.
    fn polar_words(&self, b: &Block, out: &mut Out) -> Result<Polar, Diagnostic> {
        let words: Vec<&Word> = b
            .words
            .iter()
            .filter(|w| POLAR.contains(&w.address))
            .collect();
        let span = words.first().map_or(b.span, |w| w.span);
        let last = |a: Address| words.iter().rev().find(|w| w.address == a).map(|w| w.value);
        for a in POLAR {
            if let Some(later) = words.iter().filter(|w| w.address == a).nth(1) {
                out.warnings.push(Diagnostic::warning(
                    "polar-repeated",
                    later.span,
                    format!(
                        "{} is written twice in this block: the last one is used, as rs274 does",
                        a.letter()
                    ),
                ));
            }
        }
        // The compensation looks ahead at the next blocks' X and Y, which a
        // polar block has not yet: not read together (our limit; rs274 runs it).
        let starts = matches!(
            b.codes().cutter(),
            Some(CutterCompensation::Left | CutterCompensation::Right)
        );
        if self.state.cutter.engaged() || starts {
            return Err(self.error(
                "polar-words",
                span,
                "polar coordinates `@` `^` under cutter radius compensation are not read yet: give the end point as X and Y, or cancel G41/G42 with G40 first",
            ));
        }
        if self.state.modal.plane != Plane::XY {
            return Err(self.error(
                "polar-words",
                span,
                "polar coordinates `@` `^` are read in the G17 (XY) plane only (rs274: \"Cannot use polar coordinate except in G17 plane\")",
            ));
        }
        for a in [Address::X, Address::Y] {
            if let Some(w) = b.get(a) {
                return Err(self.error(
                    "polar-words",
                    w.span,
                    format!(
                        "a block gives its XY end point either by polar coordinates `@` `^` or by X and Y, not both (rs274: \"Cannot specify both polar coordinate and {} word\")",
                        a.letter()
                    ),
                ));
            }
        }
        match b.codes().non_modal() {
            None | Some(NonModal::Dwell) => {}
            Some(NonModal::MachineCoordinates) => {
                return Err(self.error(
                    "polar-words",
                    span,
                    "G53 moves to machine coordinates, given by axis words, not polar coordinates (rs274: \"Cannot use polar coordinates with G53\")",
                ));
            }
            Some(_) => {
                return Err(self.error(
                    "polar-words",
                    span,
                    "polar coordinates `@` `^` give the end point of a move, not the words of a G10, G28, G30 or G92 (rs274: \"Polar coordinates can only be used for motion\")",
                ));
            }
        }
        Ok(Polar {
            radius: last(Address::PolarDist),
            angle: last(Address::PolarAngle),
            span,
        })
    }

    /// True when the block runs in a canned cycle mode: its own cycle code,
    /// or the mode's, no G0–G3 or G80 in the block.
    fn polar_in_cycle(&self, b: &Block) -> bool {
        match (b.codes().cycle(), b.codes().motion()) {
            (Some(CannedCycle::Cycle(_)), _) => true,
            (Some(CannedCycle::Cancel), _) | (None, Some(_)) => false,
            (None, None) => self.state.modal.cycle.is_some(),
        }
    }

    fn polar_error(&self, polar: &Polar, message: &'static str) -> Diagnostic {
        self.error("polar-origin", polar.span, message)
    }
}

fn radians(degrees: f64) -> f64 {
    degrees * PI / 180.0
}

fn at(radius: f64, theta: f64) -> [f64; 2] {
    [radius * theta.cos(), radius * theta.sin()]
}

/// G90: the written distance and angle; the one not written is the current
/// point's. At the origin a distance alone has no angle to go by (rs274
/// refuses it, except in a canned cycle, where it takes the angle 0).
fn absolute_end(polar: &Polar, p: [f64; 2], cycle: bool) -> Result<[f64; 2], &'static str> {
    if polar.angle.is_none() && p == [0.0, 0.0] && !cycle {
        return Err(
            "at the origin a polar distance `@` needs an angle `^` to go by (rs274: \"Must specify angle in polar coordinate if at the origin\")",
        );
    }
    let radius = polar.radius.unwrap_or_else(|| p[1].hypot(p[0]));
    let theta = polar.angle.map_or_else(|| p[1].atan2(p[0]), radians);
    Ok(at(radius, theta))
}

/// G91: the distance added to the current point's, then the angle added to
/// its angle, both about the origin. At the origin neither has a direction
/// (rs274 refuses; in a canned cycle a zero word is passed over).
fn incremental_end(polar: &Polar, mut p: [f64; 2], cycle: bool) -> Result<[f64; 2], &'static str> {
    let used = |v: Option<f64>| v.filter(|v| !cycle || *v != 0.0);
    if let Some(radius) = used(polar.radius) {
        if p == [0.0, 0.0] {
            return Err(
                "in G91 a polar distance `@` adds to the current point's distance from the origin, and at the origin it has no direction (rs274: \"Incremental motion with polar coordinates is indeterminate when at the origin\")",
            );
        }
        p = at(p[1].hypot(p[0]) + radius, p[1].atan2(p[0]));
    }
    if let Some(angle) = used(polar.angle) {
        if p == [0.0, 0.0] {
            return Err(match cycle {
                true => {
                    "in G91 a polar angle `^` turns the current point about the origin, and at the origin it has no direction (rs274: \"Incremental motion with polar coordinates is indeterminate when at the origin\")"
                }
                false => {
                    "in G91 a polar angle `^` turns the current point about the origin, and at the origin it has no direction (rs274: \"G91 motion with polar coordinates is indeterminate when at the origin\")"
                }
            });
        }
        p = at(p[1].hypot(p[0]), p[1].atan2(p[0]) + radians(angle));
    }
    Ok(p)
}

/// The block without its polar words (and, with `one_hole`, without its
/// repeat count) and with X and Y words of `xy` at the polar words' place.
fn with_xy(b: &Block, polar: &Polar, xy: [f64; 2], one_hole: bool) -> Block {
    let mut out = b.without(|w| {
        POLAR.contains(&w.address) || (one_hole && matches!(w.address, Address::K | Address::L))
    });
    push_xy(&mut out, polar, xy);
    out
}

/// A block of X and Y words only: the next hole of a repeated cycle.
fn xy_only(b: &Block, polar: &Polar, xy: [f64; 2]) -> Block {
    let mut out = b.without(|_| true);
    out.clear();
    // Its block's comment spoke once, at the first hole.
    out.speaks = false;
    push_xy(&mut out, polar, xy);
    out
}

fn push_xy(b: &mut Block, polar: &Polar, xy: [f64; 2]) {
    for (address, value) in [(Address::X, xy[0]), (Address::Y, xy[1])] {
        b.push(Word {
            address,
            value,
            point: true,
            span: polar.span,
        });
    }
}
