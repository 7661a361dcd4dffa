//! Tool length offset, G43/G44/G49 (spec 3, seed 001).
//!
//! The offset is a Z vector: `G43` adds, `G44` subtracts the value of
//! register H; `G49` or `H00` cancel it. The machine keeps two numbers: the
//! vector the mode asks for (`target`) and the vector in the actual position
//! (`vector`). A Z move always lands on `target` (rules 2, 5, 6); a block that
//! changes the offset without a Z word moves Z by the difference at once with
//! the seed's default `move` setting (rules 3, 4, 6) or leaves it for the
//! next Z move with `next_z`; G28 Z clears `vector` until Z moves again.

use crate::syntax::codes::LengthOffset;

/// Tool length offset state (spec 3).
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
/// G49 0 (spec 3.1).
pub fn sign(code: LengthOffset) -> i8 {
    match code {
        LengthOffset::Add => 1,
        LengthOffset::Subtract => -1,
        LengthOffset::Cancel => 0,
    }
}

impl LengthState {
    /// Applies the block's G43/G44/G49 (`code`) and H (`h`, with the value of
    /// its register in mm). H00 reads 0 and so cancels (spec 3.1).
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

    /// The change a Z-less block makes to Z when the target changed.
    pub fn pending(&self) -> f64 {
        self.target - self.vector
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spec3_1_g43_adds_g44_subtracts_g49_and_h00_cancel() {
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
}
