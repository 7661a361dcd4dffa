//! Tool position offset, G45–G48 (spec 4, seeds 000 and 003).
//!
//! One-shot: only the block holding the code is changed. Each axis word's
//! movement amount `m` becomes `m + k·s·v`, with `v` the signed value of
//! register D, `k` from the code and `s` the direction of the movement.

use crate::geometry::Xyz;
use crate::syntax::codes::PositionOffset;

/// Tool position offset state (spec 4).
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

/// The factor k of spec 4.1: G45 +1 (extension), G46 −1 (reduction),
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

/// The change to one axis's movement amount (spec 4.1–4.5).
///
/// `m` is the movement along the axis as the machine makes it (after mirror
/// image), `incremental` says whether the block is G91, `mirrored` whether the
/// axis is mirrored. A G90 zero movement changes nothing (spec 4.5,
/// Mitsubishi M700); a G91 zero movement counts as positive (spec 4.4, seed
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

/// The change to an arc's R word (spec 4.8): R is changed as a radius,
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
    fn spec4_1_extension_and_reduction_along_the_movement() {
        assert_eq!(change(G45, 50.0, 6.0, true, false), 6.0);
        assert_eq!(change(G45, -50.0, 6.0, true, false), -6.0);
        assert_eq!(change(G46, 50.0, 6.0, true, false), -6.0);
        assert_eq!(change(G47, 50.0, 6.0, false, false), 12.0);
        assert_eq!(change(G48, -50.0, 6.0, false, false), 12.0);
    }

    #[test]
    fn spec4_2_negative_register_swaps_extension_and_reduction() {
        // G91 G46 X30. D02 with register 02 = -4. moves X by +34.
        assert_eq!(30.0 + change(G46, 30.0, -4.0, true, false), 34.0);
    }

    #[test]
    fn spec4_3_reduction_larger_than_the_movement_reverses_it() {
        // G91 G48 X8. D03 with register 03 = 6. moves X by -4.
        assert_eq!(8.0 + change(G48, 8.0, 6.0, true, false), -4.0);
    }

    #[test]
    fn spec4_4_g91_zero_movement_is_positive() {
        assert_eq!(change(G45, 0.0, 5.0, true, false), 5.0);
        assert_eq!(change(G46, -0.0, 5.0, true, false), -5.0);
    }

    #[test]
    fn spec4_5_g90_zero_movement_changes_nothing() {
        assert_eq!(change(G45, 0.0, 5.0, false, false), 0.0);
    }

    #[test]
    fn spec4_8_radius_change() {
        assert_eq!(radius_change(G45, 10.0, 2.0), 2.0);
        assert_eq!(radius_change(G45, -10.0, 2.0), -2.0);
        assert_eq!(radius_change(G46, 10.0, 2.0), -2.0);
    }
}
