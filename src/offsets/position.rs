//! Tool position offset, G45–G48 (behaviour 4, seeds 000 and 003).
//!
//! One-shot: only the block holding the code is changed. Each axis word's
//! movement amount `m` becomes `m + k·s·v`, with `v` the signed value of
//! register D, `k` from the code and `s` the direction of the movement
//! ([`change`]); I/J/K and R of an arc are changed too. What a block may
//! hold with G45–G48 is [`check_block`]; the change of one block, with its
//! sentences, is [`PositionChange`]; the vector the changes leave and its
//! clearing by G92 are [`PositionState`].

use crate::diag::Diagnostic;
use crate::geometry::{Xyz, show};
use crate::setup::{MachineKind, Units};
use crate::syntax::codes::{Code, Cycle, Group, PositionOffset};
use crate::syntax::{Address, Block};

/// Tool position offset state (behaviour 4).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PositionState {
    /// Active (modal) D number.
    pub d: u16,
    /// Value of register D as last read (mm).
    pub value: f64,
    /// Accumulated position-offset vector (mm): actual − programmed from
    /// G45–G48 (seed 003's offset distance from the programmed end point).
    pub vector: Xyz,
}

impl PositionState {
    /// A D word: register `d`, whose value (mm) is `value`, is the active
    /// one (D is modal; behaviour 4).
    pub fn select(&mut self, d: u16, value: f64) {
        self.d = d;
        self.value = value;
    }

    /// G92 on `axis`: the axis's vector is cancelled before the coordinate
    /// is set (behaviour 4.7, seed 003: the offset is cancelled from the
    /// designated axes).
    pub fn cancel_for_coordinate_setting(&mut self, axis: usize) {
        self.vector[axis] = 0.0;
    }
}

/// The rules of a block holding G45–G48 before it moves (behaviour 4.9, 4.10,
/// seed 003): only G00–G03 and G90/G91 may share the block, no canned cycle
/// may be active, and the block needs an axis word — or, in G02/G03 (`arc`),
/// a centre word: a full circle (YASNAC PC NC: "1/4, 3/4 or full circle").
/// `cycle` is the active canned cycle.
pub fn check_block(
    b: &Block,
    code: PositionOffset,
    machine: MachineKind,
    cycle: Option<Cycle>,
    arc: bool,
) -> Result<(), Diagnostic> {
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
            | Code::SurfaceSpeed(_)
            | Code::CuttingMode(_)
            | Code::Polar(_)
            | Code::Scaling(_)
            | Code::Rotation(_)
            | Code::PolarCoordinates(_)
            | Code::Mirror(_)
            | Code::ArcCenter(_) => false,
        };
        if !allowed {
            return Err(Diagnostic::error(
                "position-offset-g-code",
                b.code_span(other.group()),
                format!(
                    "{} cannot share a block with {}: only G00–G03 and G90/G91 may (seed 003: an input error occurs)",
                    other.gcode(machine.into()),
                    code.gcode()
                ),
            ));
        }
    }
    if let Some(cycle) = cycle {
        return Err(Diagnostic::error(
            "position-offset-in-cycle",
            b.code_span(Group::NonModal),
            format!(
                "{} cannot be programmed while canned cycle {} is active (seed 003): cancel it with G80 first",
                code.gcode(),
                cycle.gcode()
            ),
        ));
    }
    let full_circle = arc && b.holds_any(&[Address::I, Address::J, Address::K]);
    if !full_circle && !b.holds_any(&[Address::X, Address::Y, Address::Z]) {
        return Err(Diagnostic::error(
            "position-offset-without-axis",
            b.code_span(Group::NonModal),
            format!(
                "{} needs an axis word to extend or reduce, or in G02/G03 a centre word for a full circle (behaviour 4.9); for a move by the offset alone write X0 in G91 (seed 003)",
                code.gcode()
            ),
        ));
    }
    Ok(())
}

/// What G45–G48 does to the movements of the block holding it, with the
/// sentence for each change.
#[derive(Clone, Copy, Debug)]
pub struct PositionChange {
    /// G45 … G48.
    pub code: PositionOffset,
    /// Register D.
    pub d: u16,
    /// Its value (mm).
    pub register: f64,
    /// The block is G91.
    pub incremental: bool,
    /// Mirror image per axis.
    pub mirror: [bool; 3],
    /// The units the sentences are written in.
    pub units: Units,
}

impl PositionChange {
    /// The change to each axis's movement `amount` (mm, as the machine
    /// makes it) for the axes with a word (behaviour 4.1–4.6: every axis word's
    /// amount is changed on its own), noting each.
    pub fn axes(&self, amount: Xyz, words: [bool; 3], notes: &mut Vec<String>) -> Xyz {
        let mut delta = [0.0; 3];
        for axis in 0..3 {
            if words[axis] {
                delta[axis] = change(
                    self.code,
                    amount[axis],
                    self.register,
                    self.incremental,
                    self.mirror[axis],
                );
                notes.push(self.axis_note(axis, amount[axis], delta[axis]));
            }
        }
        delta
    }

    /// The change to an arc's centre offset `offset` (mm, after mirror image)
    /// along `axis` (behaviour 4.8: I/J/K are incremental amounts, changed like
    /// axis words), noted. A zero centre word stays zero: the extension is
    /// along the axis's direction, and a zero has none (YASNAC PC NC).
    pub fn center(&self, axis: usize, offset: f64, notes: &mut Vec<String>) -> f64 {
        let letter = ['I', 'J', 'K'][axis];
        if offset.abs() <= 1e-9 {
            notes.push(format!(
                "{}: {letter} 0 stays 0 (a zero centre word has no direction to extend along, behaviour 4.8)",
                name(self.code)
            ));
            return 0.0;
        }
        let dc = change(self.code, offset, self.register, true, self.mirror[axis]);
        notes.push(format!(
            "{}: {letter} {} becomes {}",
            name(self.code),
            self.show(offset),
            self.show(offset + dc)
        ));
        dc
    }

    /// The change to an arc's R (mm) (behaviour 4.8: R changed as a radius),
    /// noted.
    pub fn radius(&self, r: f64, notes: &mut Vec<String>) -> f64 {
        let dr = radius_change(self.code, r, self.register);
        notes.push(format!(
            "{}: R {} becomes {} (R changed as a radius)",
            name(self.code),
            self.show(r),
            self.show(r + dr)
        ));
        dr
    }

    fn show(&self, mm: f64) -> String {
        show(mm, self.units)
    }

    /// The sentence for one axis changed (behaviour 6.5's example: "G47: X move
    /// 50.000 extended by 2 × D01 (6.000) to 62.000").
    fn axis_note(&self, axis: usize, m: f64, delta: f64) -> String {
        let g = name(self.code);
        let axis = ['X', 'Y', 'Z'][axis];
        if delta == 0.0 && !self.incremental && m.abs() <= 1e-9 {
            return format!(
                "{g}: {axis} target is the current position, so {axis} is not changed (behaviour 4.5)"
            );
        }
        let verb = if factor(self.code) > 0.0 {
            "extended"
        } else {
            "reduced"
        };
        let twice = if factor(self.code).abs() == 2.0 {
            "2 × "
        } else {
            ""
        };
        let mut s = format!(
            "{g}: {axis} move {} {verb} by {twice}D{:02} ({}) to {}",
            self.show(m),
            self.d,
            self.show(self.register),
            self.show(m + delta)
        );
        if m.abs() <= 1e-9 {
            s.push_str(" (a zero move goes by the offset alone, seed 003)");
        } else if (m + delta) * m < 0.0 {
            s.push_str(" — the move reverses (behaviour 4.3)");
        }
        s
    }
}

/// "G45 (extension)" … "G48 (double reduction)": the code with the
/// manual's meaning.
pub fn name(code: PositionOffset) -> String {
    format!("{} ({})", code.gcode(), meaning(code))
}

/// The factor k of behaviour 4.1: G45 +1 (extension), G46 −1 (reduction),
/// G47 +2 (double extension), G48 −2 (double reduction).
pub fn factor(code: PositionOffset) -> f64 {
    match code {
        PositionOffset::Extension => 1.0,
        PositionOffset::Reduction => -1.0,
        PositionOffset::DoubleExtension => 2.0,
        PositionOffset::DoubleReduction => -2.0,
    }
}

/// What the code does, in the manual's words (seed 000's table).
pub fn meaning(code: PositionOffset) -> &'static str {
    match code {
        PositionOffset::Extension => "extension",
        PositionOffset::Reduction => "reduction",
        PositionOffset::DoubleExtension => "double extension",
        PositionOffset::DoubleReduction => "double reduction",
    }
}

/// The change to one axis's movement amount (behaviour 4.1–4.5).
///
/// `m` is the movement along the axis as the machine makes it (after mirror
/// image), `incremental` says whether the block is G91, `mirrored` whether the
/// axis is mirrored. A G90 zero movement changes nothing (behaviour 4.5,
/// Mitsubishi M700); a G91 zero movement counts as positive (behaviour 4.4, seed
/// 003: "It is meaningless to give a sign to 0"), and under mirror image the
/// offset follows the mirrored direction (seed 003).
pub fn change(code: PositionOffset, m: f64, v: f64, incremental: bool, mirrored: bool) -> f64 {
    const ZERO: f64 = 1e-9;
    let s = if m > ZERO {
        1.0
    } else if m < -ZERO {
        -1.0
    } else if !incremental {
        return 0.0;
    } else if mirrored {
        -1.0
    } else {
        1.0
    };
    factor(code) * s * v
}

/// The change to an arc's R word (behaviour 4.8): R is changed as a radius,
/// `R + k·v·sign(R)`.
pub fn radius_change(code: PositionOffset, r: f64, v: f64) -> f64 {
    factor(code) * v * r.signum()
}

#[cfg(test)]
mod tests {
    use super::*;
    use PositionOffset::{
        DoubleExtension as G47, DoubleReduction as G48, Extension as G45, Reduction as G46,
    };

    #[test]
    fn behaviour4_1_extension_and_reduction_along_the_movement() {
        assert_eq!(change(G45, 50.0, 6.0, true, false), 6.0);
        assert_eq!(change(G45, -50.0, 6.0, true, false), -6.0);
        assert_eq!(change(G46, 50.0, 6.0, true, false), -6.0);
        assert_eq!(change(G47, 50.0, 6.0, false, false), 12.0);
        assert_eq!(change(G48, -50.0, 6.0, false, false), 12.0);
    }

    #[test]
    fn behaviour4_2_negative_register_swaps_extension_and_reduction() {
        // G91 G46 X30. D02 with register 02 = -4. moves X by +34.
        assert_eq!(30.0 + change(G46, 30.0, -4.0, true, false), 34.0);
    }

    #[test]
    fn behaviour4_3_reduction_larger_than_the_movement_reverses_it() {
        // G91 G48 X8. D03 with register 03 = 6. moves X by -4.
        assert_eq!(8.0 + change(G48, 8.0, 6.0, true, false), -4.0);
    }

    #[test]
    fn behaviour4_4_g91_zero_movement_is_positive() {
        assert_eq!(change(G45, 0.0, 5.0, true, false), 5.0);
        assert_eq!(change(G46, -0.0, 5.0, true, false), -5.0);
    }

    #[test]
    fn behaviour4_5_g90_zero_movement_changes_nothing() {
        assert_eq!(change(G45, 0.0, 5.0, false, false), 0.0);
    }

    #[test]
    fn behaviour4_8_radius_change() {
        assert_eq!(radius_change(G45, 10.0, 2.0), 2.0);
        assert_eq!(radius_change(G45, -10.0, 2.0), -2.0);
        assert_eq!(radius_change(G46, 10.0, 2.0), -2.0);
    }

    #[test]
    fn behaviour6_the_sentence_of_a_g47_axis() {
        let g47 = PositionChange {
            code: G47,
            d: 1,
            register: 6.0,
            incremental: true,
            mirror: [false; 3],
            units: Units::Mm,
        };
        let mut notes = Vec::new();
        let delta = g47.axes([50.0, 0.0, 0.0], [true, false, false], &mut notes);
        assert_eq!(delta, [12.0, 0.0, 0.0]);
        assert_eq!(
            notes,
            ["G47 (double extension): X move 50.000 extended by 2 × D01 (6.000) to 62.000"]
        );
    }

    #[test]
    fn behaviour4_7_g92_cancels_the_vector_of_its_axes() {
        let mut p = PositionState {
            d: 1,
            value: 6.0,
            vector: [6.0, -6.0, 0.0],
        };
        p.cancel_for_coordinate_setting(0);
        assert_eq!(p.vector, [0.0, -6.0, 0.0]);
    }
}
