//! The ground floor: a point or vector of the three axes and lengths in the
//! program's units. Every layer above uses these; this module imports nothing
//! of the crate but [`Units`].
//!
//! Positions are kept in millimetres (X a diameter on the lathe, Y then 0)
//! and converted to the block's units only when they are reported.

use crate::setup::Units;

/// X, Y, Z (a lathe uses X as diameter and Z; Y stays 0).
pub type Xyz = [f64; 3];

/// `a + b`, axis by axis.
pub fn add(a: Xyz, b: Xyz) -> Xyz {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

/// `a − b`, axis by axis.
pub fn sub(a: Xyz, b: Xyz) -> Xyz {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

/// `a · k`, axis by axis.
pub fn scale(a: Xyz, k: f64) -> Xyz {
    [a[0] * k, a[1] * k, a[2] * k]
}

/// Millimetres to `units`, rounded to a millionth of the unit so that
/// reported numbers read as written (no 64.99999999999999).
pub fn to_units(mm: f64, units: Units) -> f64 {
    round6(mm / units.mm())
}

/// Rounds to six decimals (and turns -0 into 0).
pub fn round6(v: f64) -> f64 {
    let r = (v * 1e6).round() / 1e6;
    if r == 0.0 { 0.0 } else { r }
}

/// A length in mm as a control shows it: in `units`, with the control's
/// decimals (the offsets' sentences and the machine's messages write
/// lengths so).
pub fn show(mm: f64, units: Units) -> String {
    let d = units.decimals();
    format!("{:.d$}", to_units(mm, units))
}

/// [`show`] with a sign.
pub fn show_signed(mm: f64, units: Units) -> String {
    let d = units.decimals();
    format!("{:+.d$}", to_units(mm, units))
}
