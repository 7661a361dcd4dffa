//! Tool length offset, G43/G44/G49 (behaviour 3, seed 001).
//!
//! The offset is a Z vector: `G43` adds, `G44` subtracts the value of
//! register H; `G49` or `H00` cancel it. The machine keeps two numbers: the
//! vector the mode asks for (`target`) and the vector in the actual position
//! (`vector`). A Z move always lands on `target` (rules 2, 5, 6); a block that
//! changes the offset without a Z word moves Z by the difference at once with
//! the seed's default `move` setting (rules 3, 4, 6) or leaves it for the
//! next Z move with `next_z`; G28 Z clears `vector` until Z moves again.

use crate::diag::{Diagnostic, Span};
use crate::geometry::{show, show_signed};
use crate::setup::{LengthOffsetWithoutZ, Units};
use crate::syntax::codes::{LengthOffset, Motion};

/// Tool length offset state (behaviour 3).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct LengthState {
    /// G43 (+1), G44 (-1) or G49 (0).
    pub sign: i8,
    /// Active H number.
    pub h: u16,
    /// Value of register H as read (mm).
    pub value: f64,
    /// The Z vector the mode asks for: sign × value (mm).
    pub target: f64,
    /// The Z vector in the actual position now (mm). It differs from `target`
    /// after G28 Z, or with `length_offset_without_z = next_z`, until Z moves.
    pub vector: f64,
}

/// The sign a length-offset code gives the register value: G43 +1, G44 −1,
/// G49 0 (behaviour 3.1).
pub fn sign(code: LengthOffset) -> i8 {
    match code {
        LengthOffset::Add | LengthOffset::Dynamic | LengthOffset::AddTool => 1,
        LengthOffset::Subtract => -1,
        LengthOffset::Cancel => 0,
    }
}

/// What a block says to the tool length offset.
#[derive(Clone, Copy, Debug)]
pub struct LengthWords {
    /// Its G43/G44/G49 and where it is written.
    pub code: Option<(LengthOffset, Span)>,
    /// Its H word: the number, where it is written, and the value of the
    /// register (mm).
    pub h: Option<(u16, Span, f64)>,
}

/// Where Z is after a block, for the sentence.
#[derive(Clone, Copy, Debug)]
pub struct ZAfter {
    /// The block is G91 (its Z word is a movement amount).
    pub incremental: bool,
    /// The programmed Z (mm).
    pub programmed: f64,
    /// The actual Z (mm).
    pub actual: f64,
    /// The units the sentence is written in.
    pub units: Units,
}

impl LengthState {
    /// Applies a block's G43/G44/G49 and H (behaviour 3.1): while G02/G03 is the
    /// motion mode the offset may not change (behaviour 3.7, YASNAC J50M); G43
    /// or G44 with H00 is warned about. `motion` is the mode the block runs
    /// in.
    pub fn block(
        &mut self,
        words: LengthWords,
        motion: Motion,
        warnings: &mut Vec<Diagnostic>,
    ) -> Result<(), Diagnostic> {
        let code = words.code.map(|(c, _)| c);
        if motion.is_arc() && (code.is_some() || self.sign != 0) {
            let span = words
                .code
                .map(|(_, span)| span)
                .or(words.h.map(|(_, span, _)| span))
                .unwrap_or_default();
            return Err(Diagnostic::error(
                "length-offset-in-arc",
                span,
                format!(
                    "the tool length offset cannot change while {} is active (behaviour 3.7): command G00 or G01 first",
                    motion.gcode()
                ),
            ));
        }
        self.command(code, words.h.map(|(n, _, value)| (n, value)));
        if let Some((cd @ (LengthOffset::Add | LengthOffset::Subtract), span)) = words.code
            && self.sign != 0
            && self.h == 0
        {
            // Not an error (H00 reads 0), but rarely what was meant.
            warnings.push(Diagnostic::warning(
                "length-offset-h00",
                span,
                format!(
                    "{} with H00: register 00 reads 0, so no length offset applies",
                    cd.gcode()
                ),
            ));
        } else if self.sign != 0
            && self.h != 0
            && self.value == 0.0
            && (words.code.is_some() || words.h.is_some())
        {
            // An empty register is as likely a forgotten measurement as a
            // choice: said, as H00 is (behaviour 3.1).
            let span = words
                .h
                .map(|(_, span, _)| span)
                .or(words.code.map(|(_, span)| span))
                .unwrap_or_default();
            warnings.push(Diagnostic::warning(
                "length-offset-zero",
                span,
                format!(
                    "{} H{:02}: register {:02} holds 0, so no length offset applies (is the tool's length measured?)",
                    self.mode().gcode(),
                    self.h,
                    self.h
                ),
            ));
        }
        Ok(())
    }

    /// Applies the block's G43/G44/G49 (`code`) and H (`h`, with the value of
    /// its register in mm). H00 reads 0 and so cancels (behaviour 3.1).
    pub fn command(&mut self, code: Option<LengthOffset>, h: Option<(u16, f64)>) {
        if let Some(c) = code {
            self.sign = sign(c);
        }
        if let Some((n, value)) = h {
            self.h = n;
            self.value = value;
        }
        self.target = if self.h == 0 {
            0.0
        } else {
            f64::from(self.sign) * self.value
        };
    }

    /// Sets the offset to `sign` × `value` from register `h` at once, the
    /// vector with it: LinuxCNC's G43/G43.1/G43.2/G49, which move nothing
    /// and read the position from the new tool tip (behaviour 22.9), and
    /// where G43.1's offset has no register (`h` 0) yet applies.
    pub fn take_at_once(&mut self, sign: i8, h: u16, value: f64) {
        self.sign = sign;
        self.h = h;
        self.value = value;
        self.target = f64::from(sign) * value;
        self.vector = self.target;
    }

    /// The active code: G43, G44 or G49, from the sign.
    pub fn mode(&self) -> LengthOffset {
        match self.sign.signum() {
            1 => LengthOffset::Add,
            -1 => LengthOffset::Subtract,
            _ => LengthOffset::Cancel,
        }
    }

    /// The change a Z-less block makes to Z when the target changed.
    pub fn pending(&self) -> f64 {
        self.target - self.vector
    }

    /// True if the block changed the mode, the H number or the target
    /// since `old`.
    #[inline(always)]
    pub fn changed_since(&self, old: &LengthState) -> bool {
        old.target != self.target || old.sign != self.sign || old.h != self.h
    }

    /// The Z vector at the end of a block's move (behaviour 3.2–3.6): a Z word
    /// lands on the target; a block that `changed` the offset without a Z
    /// word moves Z to it at once with setting `move` (seed 001: G43 H… with
    /// no Z moves Z by the offset; a new H while G43/G44 is active moves Z
    /// by the difference between the new and the old value; a cancel moves
    /// Z back), or leaves it for the next Z move with `next_z`.
    #[inline(always)]
    pub fn vector_after(&self, z_word: bool, changed: bool, setting: LengthOffsetWithoutZ) -> f64 {
        if z_word || (changed && setting == LengthOffsetWithoutZ::Move) {
            self.target
        } else {
            self.vector
        }
    }

    /// True if the block did anything to the offset that its sentence
    /// ([`LengthState::note`]) tells. Nearly every block leaves the offset as
    /// it was: this test is inlined where the machine asks, the sentence is
    /// written out of line.
    #[inline(always)]
    pub fn note_due(&self, old: &LengthState) -> bool {
        self.changed_since(old) || self.vector - old.vector != 0.0
    }

    /// The sentence for a canned cycle whose Z levels carry the offset
    /// (drilling along Z).
    pub fn cycle_note(&self, units: Units) -> String {
        format!(
            "the cycle's Z levels carry the tool length offset H{:02} ({})",
            self.h,
            show_signed(self.vector, units)
        )
    }

    /// The sentence for what the length offset did in a block that made it
    /// `self` from `old` (behaviour 3). `z_amount` is the programmed Z movement
    /// when the block moved along Z.
    #[inline(never)]
    pub fn note(&self, old: &LengthState, z_amount: Option<f64>, z: ZAfter) -> String {
        let new = self;
        let fmt = |mm: f64| show(mm, z.units);
        let fmt_signed = |mm: f64| show_signed(mm, z.units);
        let vector_change = new.vector - old.vector;
        let label = if new.changed_since(old) {
            if new.target == 0.0 && old.target != 0.0 && (new.sign == 0 || new.h == 0) {
                if new.sign == 0 {
                    "G49 cancels the tool length offset".to_string()
                } else {
                    "H00 cancels the tool length offset".to_string()
                }
            } else if new.sign == 0 {
                "G49: no tool length offset".to_string()
            } else {
                let g = new.mode().gcode();
                let how = if new.sign > 0 { "adds" } else { "subtracts" };
                if old.sign == new.sign && old.h != new.h && old.h != 0 {
                    format!(
                        "H{:02} → H{:02} while {g} is active ({} → {})",
                        old.h,
                        new.h,
                        fmt(old.value),
                        fmt(new.value)
                    )
                } else {
                    format!("{g} {how} H{:02} ({})", new.h, fmt(new.value))
                }
            }
        } else {
            format!(
                "this Z move applies the pending length offset H{:02} ({})",
                new.h,
                fmt_signed(new.target)
            )
        };
        let effect = match z_amount {
            Some(m) if z.incremental => {
                format!("the Z move {} becomes {}", fmt(m), fmt(m + vector_change))
            }
            Some(_) => format!(
                "Z target {} lands at {}",
                fmt(z.programmed),
                fmt(z.actual)
            ),
            None if vector_change != 0.0 => {
                if old.vector != 0.0 && new.vector != 0.0 {
                    format!("no Z word: Z moves by the difference, {} (seed 001)", fmt_signed(vector_change))
                } else {
                    format!("no Z word: Z moves by {} (seed 001)", fmt_signed(vector_change))
                }
            }
            None if new.target != new.vector => {
                "no Z word: no motion now; the next Z move lands offset (setting length_offset_without_z = next_z)"
                    .to_string()
            }
            None if old.vector == 0.0 => "no motion (no length vector was applied)".to_string(),
            None => "no motion".to_string(),
        };
        format!("{label}: {effect}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn behaviour3_1_g43_adds_g44_subtracts_g49_and_h00_cancel() {
        let mut l = LengthState::default();
        l.command(Some(LengthOffset::Add), Some((2, 15.0)));
        assert_eq!(l.target, 15.0);
        l.command(Some(LengthOffset::Subtract), None);
        assert_eq!(l.target, -15.0);
        l.command(None, Some((0, 0.0)));
        assert_eq!(l.target, 0.0);
        l.command(Some(LengthOffset::Add), Some((3, -2.0)));
        assert_eq!(l.target, -2.0, "a negative value reverses the direction");
        l.command(Some(LengthOffset::Cancel), None);
        assert_eq!(l.target, 0.0);
    }

    #[test]
    fn seed001_a_new_h_without_z_moves_z_by_the_difference() {
        let move_now = LengthOffsetWithoutZ::Move;
        let mut l = LengthState::default();
        l.command(Some(LengthOffset::Add), Some((1, 10.0)));
        l.vector = l.vector_after(false, true, move_now);
        let old = l;
        l.command(None, Some((2, 12.5)));
        assert!(l.changed_since(&old));
        l.vector = l.vector_after(false, true, move_now);
        assert_eq!(l.vector - old.vector, 2.5);
        let z = ZAfter {
            incremental: false,
            programmed: 0.0,
            actual: 12.5,
            units: Units::Mm,
        };
        assert_eq!(
            l.note(&old, None, z),
            "H01 → H02 while G43 is active (10.000 → 12.500): no Z word: Z moves by the difference, +2.500 (seed 001)"
        );
        let mut waiting = old;
        waiting.command(None, Some((2, 12.5)));
        let next_z = LengthOffsetWithoutZ::NextZ;
        assert_eq!(waiting.vector_after(false, true, next_z), 10.0);
        assert_eq!(waiting.vector_after(true, false, next_z), 12.5);
    }

    #[test]
    fn behaviour3_7_no_length_offset_change_in_arc_mode() {
        let words = LengthWords {
            code: Some((LengthOffset::Add, Span::default())),
            h: Some((1, Span::default(), 10.0)),
        };
        let arc = Motion::Arc(crate::syntax::codes::ArcDirection::Cw);
        let mut warnings = Vec::new();
        let e = LengthState::default()
            .block(words, arc, &mut warnings)
            .unwrap_err();
        assert_eq!(e.code, "length-offset-in-arc");
        let mut l = LengthState::default();
        l.block(words, Motion::Linear, &mut warnings).unwrap();
        assert_eq!(l.target, 10.0);
        assert!(warnings.is_empty());
    }
}
