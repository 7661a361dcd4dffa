//! Cutter radius compensation C, G40/G41/G42 and G39 on the mill
//! (behaviour 16; Fanuc 0i-MF/30i operator's manuals, "Cutter compensation
//! C" and its "Details"): the tool centre runs offset from the programmed
//! contour by the radius in register D, left of it with G41 and right with
//! G42; at each junction of two blocks the control reads the next block and
//! ends the first where the two offset paths meet (`geometry.rs`).
//!
//! This family keeps the compensation's state (the mode, D and its value,
//! the block's role — start-up, offset mode, cancel — and the vector from
//! the programmed to the actual end point) and writes its sentences; the
//! machine (`machine/cutter/`) reads the blocks ahead, applies the
//! corners to the moves and raises the alarms.

pub mod geometry;
pub mod nose;

use crate::geometry::{Xyz, show};
use crate::setup::Units;
use crate::syntax::codes::CutterCompensation;
use geometry::{Corner, Kind, Path, Type};

/// The compensation's role in a block (behaviour 16.2).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Phase {
    /// Cancel mode: no vector (after G40, D00, before the start-up, after a
    /// reference return in G41/G42).
    #[default]
    Cancel,
    /// This block started compensation up: it moved from the programmed
    /// path onto the offset path.
    StartUp,
    /// Offset mode: the tool centre runs on the offset path.
    Offset,
    /// This block cancelled compensation: it moved from the offset path
    /// back onto the programmed end point.
    Cancelling,
}

impl Phase {
    /// As the JSON writes it.
    pub fn as_str(self) -> &'static str {
        match self {
            Phase::Cancel => "cancel",
            Phase::StartUp => "start_up",
            Phase::Offset => "offset",
            Phase::Cancelling => "cancelling",
        }
    }
}

/// Cutter radius compensation after a block (behaviour 16).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct CutterState {
    /// G40, G41 or G42: the modal code of group 07.
    pub mode: CutterCompensation,
    /// The D number the block read its radius from (D is modal and shared
    /// with G45–G48).
    pub d: u16,
    /// The value of register D as the block read it (mm, signed: a negative
    /// value swaps the side).
    pub radius: f64,
    /// The block's role.
    pub phase: Phase,
    /// On the lathe, the imaginary tool nose direction 0–9 of the offset
    /// register (behaviour 18.2); `d` is then the T code's offset number
    /// and `radius` the nose radius. None on the mill.
    pub tip: Option<u8>,
    /// Actual − programmed at the block's end from the compensation (mm, in
    /// the compensation plane; zero along its normal).
    pub vector: Xyz,
}

impl CutterState {
    /// True while a block must pass through the compensation: G41/G42 is
    /// the mode, or a vector is still to be taken off.
    #[inline(always)]
    pub fn engaged(&self) -> bool {
        self.mode != CutterCompensation::Cancel || self.phase != Phase::Cancel
    }
}

/// +1 for G41 (left), −1 for G42 (right), 0 for G40.
pub fn side(mode: CutterCompensation) -> f64 {
    match mode {
        CutterCompensation::Cancel => 0.0,
        CutterCompensation::Left => 1.0,
        CutterCompensation::Right => -1.0,
    }
}

/// What a sentence needs to name the compensation.
#[derive(Clone, Copy, Debug)]
pub struct Words {
    /// G41 or G42.
    pub mode: CutterCompensation,
    /// Register D.
    pub d: u16,
    /// The signed offset (mm): > 0 left of the path.
    pub offset: f64,
    /// The units the sentence is written in.
    pub units: Units,
    /// On the lathe, the tip direction (behaviour 18): `d` is then the T
    /// code's offset number.
    pub tip: Option<u8>,
}

impl Words {
    fn r(&self) -> String {
        show(self.offset.abs(), self.units)
    }

    /// "tool centre" on the mill, "nose centre" on the lathe.
    pub fn centre(&self) -> &'static str {
        if self.tip.is_some() {
            "nose centre"
        } else {
            "tool centre"
        }
    }

    /// "5.000 left" (or right).
    fn side_of(&self) -> String {
        format!("{} {}", self.r(), which(self.offset))
    }

    /// "G41 D01 (5.000 left)", naming a negative register that swaps the
    /// side.
    pub fn name(&self) -> String {
        let swapped = (side(self.mode) * self.offset) < 0.0;
        if let Some(t) = self.tip {
            return format!(
                "{} offset {:02} (nose R {} {}, tip {t}{})",
                self.mode.gcode(),
                self.d,
                self.r(),
                which(self.offset),
                if swapped {
                    ": the negative radius swaps the side"
                } else {
                    ""
                }
            );
        }
        format!(
            "{} D{:02} ({}{})",
            self.mode.gcode(),
            self.d,
            self.side_of(),
            if swapped {
                ": the negative value swaps the side"
            } else {
                ""
            }
        )
    }
}

/// "left" for a positive offset, "right" for a negative one.
pub fn which(offset: f64) -> &'static str {
    if offset >= 0.0 { "left" } else { "right" }
}

/// "the two offset lines", "the offset line and the offset arc".
fn offsets(prev: &Path, next: &Path) -> String {
    match (prev.is_arc(), next.is_arc()) {
        (false, false) => "the two offset lines".into(),
        (true, true) => "the two offset arcs".into(),
        _ => format!(
            "this block's offset {} and the next block's offset {}",
            prev.noun(),
            next.noun()
        ),
    }
}

fn angle(alpha: f64) -> String {
    format!("{alpha:.1}°")
}

/// The sentence of a start-up block (behaviour 16.3, 16.4).
pub fn start_up_note(
    w: &Words,
    t: Type,
    corner: &Corner,
    prev: &Path,
    next: Option<&Path>,
) -> String {
    let name = w.name();
    let c = w.centre();
    let Some(next) = next else {
        return format!(
            "{name} start-up: no move in the plane follows, so the {c} ends {} of this block's end, perpendicular to it",
            w.side_of()
        );
    };
    match (t, corner.kind) {
        (Type::A, _) => format!(
            "{name} start-up (type A): the {c} goes {} of the next block's start, perpendicular to its direction",
            w.side_of()
        ),
        (Type::B, Kind::Tangent) => format!(
            "{name} start-up (type B): the next block goes on in the same direction; the {c} ends {} of this block's end",
            w.side_of()
        ),
        (Type::B, Kind::Inside | Kind::Obtuse) => format!(
            "{name} start-up (type B): the {c} goes to the intersection of {}, {} of both (corner {})",
            offsets(prev, next),
            w.side_of(),
            angle(corner.alpha())
        ),
        (Type::B, _) => format!(
            "{name} start-up (type B): outside corner of {} (under 90°): the {c} goes {} of this block's end, then {} of the next block's start",
            angle(corner.alpha()),
            w.side_of(),
            w.side_of()
        ),
    }
}

/// The sentence of the corner at the end of a block in offset mode
/// (behaviour 16.5–16.9).
pub fn corner_note(w: &Words, corner: &Corner, prev: &Path, next: &Path, o2: f64) -> String {
    let name = w.name();
    match corner.kind {
        Kind::Tangent => format!(
            "{name}: the next block goes on tangentially: the tool ends {} of the end point",
            w.side_of()
        ),
        Kind::Inside => format!(
            "{name}: inside corner ({}): the tool stops at the intersection of {}",
            angle(corner.alpha()),
            offsets(prev, next)
        ),
        Kind::Obtuse => format!(
            "{name}: outside corner ({}): the tool goes to the intersection of {}",
            angle(corner.alpha()),
            offsets(prev, next)
        ),
        Kind::Acute => {
            let more = corner.steps().len() - 1;
            format!(
                "{name}: outside corner ({}, {}): the tool goes {} past the corner along this block, across, and onto the next block's offset path {} before its start ({more} more move{}: the manual's extra vectors keep it {} off the corner point)",
                angle(corner.alpha()),
                if corner.under_90() {
                    "under 90°"
                } else {
                    "the offset paths do not meet"
                },
                w.r(),
                w.r(),
                if more == 1 { "" } else { "s" },
                w.r()
            )
        }
        Kind::Rounded => format!(
            "{name}: outside corner ({}): the tool goes round it on an arc of radius {} (setting cutter_outside_corner = arc)",
            angle(corner.alpha()),
            w.r()
        ),
        Kind::SideChange => format!(
            "{name}: the next block changes to the {} side: the tool crosses over at the intersection of {}",
            which(o2),
            offsets(prev, next)
        ),
        Kind::SideChangeApart => format!(
            "{name}: the next block changes to the {} side and the offsets do not meet: the tool ends {} of this block's end, then moves {} {} of the next block's start",
            which(o2),
            w.side_of(),
            show(o2.abs(), w.units),
            which(o2)
        ),
        Kind::Perpendicular | Kind::NextPerpendicular => format!(
            "{name}: the tool ends {} of this block's end, perpendicular to it",
            w.side_of()
        ),
    }
}

/// The sentence of the corner before a cancel block (behaviour 16.10).
pub fn before_cancel_note(w: &Words, t: Type, corner: &Corner, prev: &Path, next: &Path) -> String {
    let name = w.name();
    match (t, corner.kind) {
        (Type::A, _) | (Type::B, Kind::Tangent | Kind::Perpendicular) => format!(
            "{name}: the next block cancels (type {}): the tool ends {} of this block's end, perpendicular to it",
            type_letter(t),
            w.side_of()
        ),
        (Type::B, Kind::Inside | Kind::Obtuse) => format!(
            "{name}: the next block cancels (type B): the tool ends at the intersection of {} (corner {})",
            offsets(prev, next),
            angle(corner.alpha())
        ),
        (Type::B, _) => format!(
            "{name}: the next block cancels (type B): outside corner of {} (under 90°): the tool ends {} of this block's end, then goes {} of the next block's start",
            angle(corner.alpha()),
            w.side_of(),
            w.side_of()
        ),
    }
}

/// "A" or "B".
pub fn type_letter(t: Type) -> &'static str {
    match t {
        Type::A => "A",
        Type::B => "B",
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use geometry::{Outside, Rule, corner};

    fn words(offset: f64) -> Words {
        Words {
            mode: CutterCompensation::Left,
            d: 1,
            offset,
            units: Units::Mm,
            tip: None,
        }
    }

    #[test]
    fn behaviour16_13_the_sentences_name_the_code_the_register_and_the_side() {
        let x = Path::Line {
            from: [0.0, 0.0],
            to: [50.0, 0.0],
        };
        let up = Path::Line {
            from: [50.0, 0.0],
            to: [50.0, 30.0],
        };
        let c = corner(&x, &up, 5.0, 5.0, Rule::StartUp(Type::A)).unwrap();
        assert_eq!(
            start_up_note(&words(5.0), Type::A, &c, &x, Some(&up)),
            "G41 D01 (5.000 left) start-up (type A): the tool centre goes 5.000 left of the next block's start, perpendicular to its direction"
        );
        let c = corner(&x, &up, 5.0, 5.0, Rule::Offset(Outside::Vectors)).unwrap();
        assert_eq!(
            corner_note(&words(5.0), &c, &x, &up, 5.0),
            "G41 D01 (5.000 left): inside corner (270.0°): the tool stops at the intersection of the two offset lines"
        );
        assert_eq!(
            words(-5.0).name(),
            "G41 D01 (5.000 right: the negative value swaps the side)"
        );
    }

    #[test]
    fn behaviour16_2_engaged_while_the_mode_or_a_vector_lasts() {
        let mut s = CutterState::default();
        assert!(!s.engaged());
        s.mode = CutterCompensation::Right;
        assert!(s.engaged());
        s.mode = CutterCompensation::Cancel;
        s.phase = Phase::Offset;
        assert!(s.engaged());
    }
}
