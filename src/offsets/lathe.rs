//! Lathe T-code tool position offset (spec 5, seed 004).
//!
//! `Tttoo` selects tool `tt` and offset `oo`; the offset vector is register
//! `oo`'s X (a diameter value by default, or a radius value doubled on the
//! diameter axis) and Z, each geometry + wear. Offset 00 cancels.

use crate::geometry::Xyz;
use crate::setup::{LatheRegister, LatheXOffset};

/// Lathe T-code offset state (spec 5).
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spec5_tttoo_splits_into_tool_and_offset() {
        assert_eq!(split(108), (1, 8));
        assert_eq!(split(216), (2, 16));
        assert_eq!(split(200), (2, 0));
    }

    #[test]
    fn spec5_lathe_x_offset_radius_doubles_on_the_diameter_axis() {
        let reg = LatheRegister {
            x: 0.3,
            z: -0.2,
            x_wear: 0.1,
            z_wear: 0.0,
        };
        let d = vector(&reg, LatheXOffset::Diameter, 1.0);
        assert!((d[0] - 0.4).abs() < 1e-12 && d[2] == -0.2);
        let r = vector(&reg, LatheXOffset::Radius, 1.0);
        assert!((r[0] - 0.8).abs() < 1e-12);
    }
}
