//! Lathe T-code tool position offset (behaviour 5, seed 004).
//!
//! `Tttoo` selects tool `tt` and offset `oo`; the offset vector is register
//! `oo`'s X (a diameter value by default, or a radius value doubled on the
//! diameter axis) and Z, each geometry + wear. Offset 00 cancels. The T
//! word is [`LatheState::command`]; where the offset lands in a move (and
//! the taper a new offset in a feed move makes) is
//! [`LatheState::vector_after_move`]; a T change without a move is
//! [`offset_motion_at_feed`]; the sentences are here too.

use crate::diag::{Diagnostic, Span};
use crate::geometry::{Xyz, show, show_signed};
use crate::setup::{LatheRegister, LatheXOffset, Units};
use crate::syntax::codes::{Code, CodeTable, Motion};

/// Lathe T-code offset state (behaviour 5).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct LatheState {
    /// Tool number (tt of Tttoo).
    pub tool: u32,
    /// Offset number (oo of Tttoo).
    pub offset: u16,
    /// The vector the active offset asks for (X diameter, Z; mm).
    pub target: Xyz,
    /// The vector in the actual position now (X diameter, Z; mm).
    pub vector: Xyz,
}

/// Tool and offset numbers of a T word (`T0108` and `T108`: tool 1, offset 8).
pub fn split(t: u32) -> (u32, u16) {
    (t / 100, (t % 100) as u16)
}

/// The offset vector of a register, in mm on the X-diameter/Z axes.
pub fn vector(reg: &LatheRegister, x_offset: LatheXOffset, unit_mm: f64) -> Xyz {
    let x = match x_offset {
        LatheXOffset::Diameter => reg.x_value(),
        LatheXOffset::Radius => 2.0 * reg.x_value(),
    };
    [x * unit_mm, 0.0, reg.z_value() * unit_mm]
}

/// What a T word did.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct TWord {
    /// The new tool number, when it changed: the turret indexes (behaviour 5.6).
    pub indexed: Option<u32>,
    /// The offset vector the machine should carry changed.
    pub changed: bool,
}

impl LatheState {
    /// A T word `t` (behaviour 5.1, 5.6): selects tool and offset, the offset's
    /// vector from `register` (the offset table's row of an offset number),
    /// `x_offset` and `unit_mm` (mm in one program unit); a new tool number
    /// is noted as a turret index.
    pub fn command(
        &mut self,
        t: u32,
        register: impl FnOnce(u16) -> LatheRegister,
        x_offset: LatheXOffset,
        unit_mm: f64,
        notes: &mut Vec<String>,
    ) -> TWord {
        let (tool, offset) = split(t);
        let old = *self;
        let indexed = (tool != old.tool).then_some(tool);
        if indexed.is_some() {
            notes.push(format!(
                "tool {:02} → {tool:02}: the turret indexes (behaviour 5.6)",
                old.tool
            ));
        }
        let reg = register(offset);
        let target = if offset == 0 {
            [0.0; 3]
        } else {
            vector(&reg, x_offset, unit_mm)
        };
        self.tool = tool;
        self.offset = offset;
        self.target = target;
        TWord {
            indexed,
            changed: target != old.vector || offset != old.offset,
        }
    }

    /// The vector at the end of a move (behaviour 5.2, 5.4): with a new T code
    /// (`t_changed`) the move lands on the new offset on both axes, so a new
    /// offset in a feed move changes the end point by the difference of the
    /// offsets and the straight move from the old to the new offset position
    /// corrects a taper angle (seed 004); otherwise each axis that `moved`
    /// carries the active offset (after G28 an axis regains it when it next
    /// moves).
    pub fn vector_after_move(&self, t_changed: bool, moved: [bool; 3]) -> Xyz {
        let mut vector = self.vector;
        for axis in [0, 2] {
            if t_changed || moved[axis] {
                vector[axis] = self.target[axis];
            }
        }
        vector
    }

    /// "T0108: offset 08 (X 0.400, Z -0.200)", or the cancel.
    fn label(&self, units: Units) -> String {
        if self.offset == 0 {
            format!("T{:02}00 cancels the tool position offset", self.tool)
        } else {
            format!(
                "T{:02}{:02}: offset {:02} (X {}, Z {})",
                self.tool,
                self.offset,
                self.offset,
                show(self.target[0], units),
                show(self.target[2], units)
            )
        }
    }

    /// The sentence for the offset motion `d` of a T change with no move
    /// (behaviour 5.3, 5.5).
    pub fn motion_note(&self, d: Xyz, at_feed: bool, units: Units) -> String {
        let rate = if at_feed {
            "at the cutting feed (G01)"
        } else {
            "at rapid (G00)"
        };
        let what = if self.offset == 0 {
            "only the cancel motion is made"
        } else {
            "offset motion"
        };
        format!(
            "{}: {what}, X {} Z {}, {rate} (seed 004)",
            self.label(units),
            show_signed(d[0], units),
            show_signed(d[2], units)
        )
    }

    /// The sentence for a T change made with a move whose end point it
    /// moves by `d` (behaviour 5.2, 5.4, 5.5).
    pub fn move_note(&self, d: Xyz, at_feed: bool, units: Units) -> String {
        if self.offset == 0 {
            return format!(
                "{}: the tool goes to the programmed position (seed 004)",
                self.label(units)
            );
        }
        let mut s = format!(
            "{}: the end point moves by X {} Z {} with this move",
            self.label(units),
            show_signed(d[0], units),
            show_signed(d[2], units)
        );
        if at_feed && (d[0] != 0.0 || d[2] != 0.0) {
            s.push_str(" (seed 004: a new offset in a feed move corrects the taper angle)");
        }
        s
    }
}

/// Whether the offset motion of a T change with no move is made at feed
/// (G01) rather than rapid (G00), in motion mode `motion` (behaviour 5.3, seed
/// 004); in G02/G03 or a turning cycle it cannot be made. `t` is where the
/// T word is.
pub fn offset_motion_at_feed(
    motion: Motion,
    table: CodeTable,
    t: Span,
) -> Result<bool, Diagnostic> {
    match motion {
        Motion::Rapid => Ok(false),
        Motion::Linear => Ok(true),
        Motion::Arc(_) | Motion::LatheCycle(_) => Err(Diagnostic::error(
            "offset-motion-mode",
            t,
            format!(
                "a T offset change with no move is made at rapid (G00) or feed (G01); {} is active: command G00 or G01 with it",
                Code::Motion(motion).gcode(table)
            ),
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn behaviour5_tttoo_splits_into_tool_and_offset() {
        assert_eq!(split(108), (1, 8));
        assert_eq!(split(216), (2, 16));
        assert_eq!(split(200), (2, 0));
    }

    #[test]
    fn behaviour5_lathe_x_offset_radius_doubles_on_the_diameter_axis() {
        let reg = LatheRegister {
            x: 0.3,
            z: -0.2,
            x_wear: 0.1,
            ..LatheRegister::default()
        };
        let d = vector(&reg, LatheXOffset::Diameter, 1.0);
        assert!((d[0] - 0.4).abs() < 1e-12 && d[2] == -0.2);
        let r = vector(&reg, LatheXOffset::Radius, 1.0);
        assert!((r[0] - 0.8).abs() < 1e-12);
    }

    fn register_08() -> LatheRegister {
        LatheRegister {
            x: 0.4,
            z: -0.2,
            ..LatheRegister::default()
        }
    }

    #[test]
    fn behaviour5_6_a_new_tool_number_indexes_the_turret() {
        let mut l = LatheState::default();
        let mut notes = Vec::new();
        let t = l.command(
            108,
            |_| register_08(),
            LatheXOffset::Diameter,
            1.0,
            &mut notes,
        );
        assert_eq!(
            t,
            TWord {
                indexed: Some(1),
                changed: true
            }
        );
        assert_eq!(notes, ["tool 00 → 01: the turret indexes (behaviour 5.6)"]);
        assert_eq!(l.target, [0.4, 0.0, -0.2]);
        let t = l.command(
            100,
            |_| register_08(),
            LatheXOffset::Diameter,
            1.0,
            &mut notes,
        );
        assert_eq!(
            t,
            TWord {
                indexed: None,
                changed: true
            }
        );
        assert_eq!(l.target, [0.0; 3]);
    }

    #[test]
    fn seed004_a_new_offset_in_a_feed_move_lands_on_both_axes_and_corrects_the_taper() {
        let l = LatheState {
            tool: 2,
            offset: 16,
            target: [0.4, 0.0, -0.2],
            vector: [0.1, 0.0, 0.1],
        };
        // Only X moves, but the new offset applies on both axes.
        assert_eq!(l.vector_after_move(true, [true, false, false]), l.target);
        // Without a T code only the axes that move take the offset.
        assert_eq!(
            l.vector_after_move(false, [true, false, false]),
            [0.4, 0.0, 0.1]
        );
        let note = l.move_note([0.3, 0.0, -0.3], true, Units::Mm);
        assert!(
            note.ends_with("(seed 004: a new offset in a feed move corrects the taper angle)"),
            "{note}"
        );
        assert!(
            !l.move_note([0.3, 0.0, -0.3], false, Units::Mm)
                .contains("taper")
        );
    }

    #[test]
    fn behaviour5_3_a_t_change_alone_moves_at_the_motion_modes_rate() {
        assert_eq!(
            offset_motion_at_feed(Motion::Rapid, CodeTable::LATHE, Span::default()),
            Ok(false)
        );
        assert_eq!(
            offset_motion_at_feed(Motion::Linear, CodeTable::LATHE, Span::default()),
            Ok(true)
        );
        let arc = Motion::Arc(crate::syntax::codes::ArcDirection::Ccw);
        let e = offset_motion_at_feed(arc, CodeTable::LATHE, Span::default()).unwrap_err();
        assert_eq!(e.code, "offset-motion-mode");
    }
}
