//! LinuxCNC's arcs (behaviour 22.16): G2/G3 P, the number of turns, and the
//! arcs rs274 refuses, with its tolerances. Source: LinuxCNC 2.9
//! documentation, "G2, G3 Arc Feed"; `src/emc/rs274ngc/interp_arc.cc`
//! (`arc_data_ijk`, `arc_data_r`) and `interp_convert.cc` (`convert_arc`),
//! and what `rs274 -g` does with `tests/linuxcnc/a*.ngc` and
//! `refused/ra*.ngc`: where the two disagree the output is followed.

use std::f64::consts::{SQRT_2, TAU};

use super::arc::P2;
use super::{ArcInfo, Machine};
use crate::diag::Diagnostic;
use crate::geometry::{Xyz, to_units};
use crate::setup::Units;
use crate::syntax::{Address, Block};

/// rs274's RADIUS_TOLERANCE_INCH, 0.00005 in (its mm twin is the same
/// length): a centre nearer than this to the start or the end is a
/// "Zero-radius arc", an R shorter than half the chord by more is "Arc
/// radius too small to reach end point".
const RADIUS_TOLERANCE_MM: f64 = 0.00005 * 25.4;

/// rs274's SPIRAL_RELATIVE_TOLERANCE: the end's radius may differ from the
/// start's by 0.1 % (beyond the absolute tolerance below).
const SPIRAL_RELATIVE: f64 = 0.001;

/// P within this of a whole number is that number (rs274 runs `P1.001` as 1
/// turn and refuses `P1.0011`: "P value not an integer").
const NEAR_INTEGER: f64 = 0.001;

/// How the arc's centre is given.
#[derive(Clone, Copy, Debug)]
pub(super) enum Centre {
    /// I/J/K: the centre point in the plane (mm).
    Point(P2),
    /// R (mm, signed).
    Radius(f64),
}

impl Machine {
    /// rs274's CENTER_ARC_RADIUS_TOLERANCE in mm for the program's units:
    /// 2 × 0.01 × √2 mm in G21, 2 × 0.001 × √2 in in G20 (measured with
    /// `rs274 -g`: an end 0.0283 mm farther than the start from the centre
    /// of a 10 mm arc is refused, 0.0282 mm runs); the setting
    /// `arc_tolerance` (7.56) replaces it, as the INI's
    /// `[RS274NGC]CENTER_ARC_RADIUS_TOLERANCE_MM` does.
    pub(in crate::machine) fn linuxcnc_spiral_tolerance(&self) -> f64 {
        if self.setup.settings.arc_tolerance.is_some() {
            return self.setup.arc_tolerance_mm(self.units());
        }
        match self.units() {
            Units::Mm => 2.0 * 0.01 * SQRT_2,
            Units::Inch => 2.0 * 0.001 * SQRT_2 * 25.4,
        }
    }

    /// An arc block's words as rs274 reads them, before its circle: R with
    /// I/J/K, a centre word across the plane, an R arc ending at its start
    /// are errors, and P is the number of turns (a whole number ≥ 1 within
    /// 0.001, at most 2147483647, rs274's `int`). Gives the turns after the
    /// first (P − 1; 0 without P).
    #[cold]
    #[inline(never)]
    pub(in crate::machine) fn linuxcnc_arc_words(
        &self,
        b: &Block,
        target: Xyz,
    ) -> Result<u32, Diagnostic> {
        let plane = self.state.modal.plane;
        let has_r = b.has(Address::R);
        let centre_words = [Address::I, Address::J, Address::K];
        if has_r && let Some(w) = centre_words.iter().find_map(|&a| b.get(a)) {
            return Err(self.error(
                "arc-r-and-center",
                w.span,
                format!(
                    "R and {} in one arc: LinuxCNC reads an arc's centre from R or from I/J/K, never both (rs274: \"Mixed radius ijk format for arc\")",
                    w.address.letter()
                ),
            ));
        }
        let (ia, ib, normal) = plane.axes();
        if let Some(w) = b.get(centre_words[normal]) {
            let name = ["yz", "xz", "xy"][normal];
            return Err(self.error(
                "arc-center-word",
                w.span,
                format!(
                    "{} is not a centre word of the {} plane: LinuxCNC refuses it (rs274: \"{} word given for arc in {name} plane\")",
                    w.address.letter(),
                    plane.gcode(),
                    w.address.letter()
                ),
            ));
        }
        let p0 = self.state.programmed;
        if has_r && p0[ia] == target[ia] && p0[ib] == target[ib] {
            return Err(self.error(
                "arc-radius",
                b.span,
                "an R arc whose end is its start has no centre (a full circle needs I/J/K; rs274: \"Current point same as end point of arc\")",
            ));
        }
        let Some(p) = b.get(Address::P) else {
            return Ok(0);
        };
        let whole = p.value.round();
        if (p.value - whole).abs() >= NEAR_INTEGER || whole > f64::from(i32::MAX) || whole.is_nan()
        {
            return Err(self.error(
                "arc-turns",
                p.span,
                format!(
                    "P{}: an arc's P is its number of turns, a whole number (rs274: \"P value not an integer with M19 G2 or G3\")",
                    p.value
                ),
            ));
        }
        if whole < 1.0 {
            return Err(self.error(
                "arc-turns",
                p.span,
                format!(
                    "P{}: an arc's P is its number of turns, 1 or more (rs274: \"P value should be 1 or greater with G2 or G3\")",
                    p.value
                ),
            ));
        }
        // Checked above: 1 ≤ whole ≤ i32::MAX.
        Ok(whole as u32 - 1)
    }

    /// The programmed circle's checks of rs274's `arc_data_ijk` and
    /// `arc_data_r`, in the plane (mm): the centre within 0.00005 in of the
    /// start or the end, the end's radius off the start's by more than
    /// 100 × the absolute tolerance or by more than it and 0.1 %, an R short
    /// of half the chord by more than 0.00005 in.
    #[cold]
    #[inline(never)]
    pub(super) fn linuxcnc_arc_check(
        &self,
        b: &Block,
        p0: P2,
        p1: P2,
        centre: Centre,
    ) -> Result<(), Diagnostic> {
        let unit = self.units();
        let d = unit.decimals().max(4);
        let f = |v: f64| format!("{:.d$}", to_units(v, unit));
        let (ia, ib, _) = self.state.modal.plane.axes();
        let [a, c] = [ia, ib].map(|i| ['X', 'Y', 'Z'][i]);
        let c0 = match centre {
            Centre::Radius(r) => {
                let half = (p1[0] - p0[0]).hypot(p1[1] - p0[1]) / 2.0;
                if half - r.abs() > RADIUS_TOLERANCE_MM {
                    return Err(self.error(
                        "arc-radius",
                        b.span,
                        format!(
                            "R{} is less than half the distance from start to end ({}) by more than 0.00005 in (rs274: \"Arc radius too small to reach end point\")",
                            f(r.abs()),
                            f(half)
                        ),
                    ));
                }
                return Ok(());
            }
            Centre::Point(c) => c,
        };
        let r1 = (p0[0] - c0[0]).hypot(p0[1] - c0[1]);
        let r2 = (p1[0] - c0[0]).hypot(p1[1] - c0[1]);
        let points = || {
            format!(
                "start ({a}{}, {c}{}), centre ({a}{}, {c}{}), end ({a}{}, {c}{})",
                f(p0[0]),
                f(p0[1]),
                f(c0[0]),
                f(c0[1]),
                f(p1[0]),
                f(p1[1])
            )
        };
        if r1 < RADIUS_TOLERANCE_MM || r2 < RADIUS_TOLERANCE_MM {
            return Err(self.error(
                "arc-radius",
                b.span,
                format!(
                    "the arc's centre is within 0.00005 in of its {}: {} (rs274: \"Zero-radius arc\")",
                    if r1 < RADIUS_TOLERANCE_MM { "start" } else { "end" },
                    points()
                ),
            ));
        }
        let abs_err = (r1 - r2).abs();
        let rel_err = abs_err / r1.max(r2);
        let tol = self.linuxcnc_spiral_tolerance();
        if abs_err > 100.0 * tol || (abs_err > tol && rel_err > SPIRAL_RELATIVE) {
            return Err(self.error(
                "arc-radius",
                b.span,
                format!(
                    "the end is {} from the centre and the start {}: {}; the difference {} ({:.4} %) is over {} and 0.1 %, or over {} (rs274: \"Radius to end of arc differs from radius to start\")",
                    f(r2),
                    f(r1),
                    points(),
                    f(abs_err),
                    rel_err * 100.0,
                    f(tol),
                    f(100.0 * tol)
                ),
            ));
        }
        Ok(())
    }
}

/// The compensated arc rs274 sends when the tool's radius is the arc's and
/// the tool is inside it: start, end and centre one point, the turns kept
/// (`rs274 -g` on `tests/linuxcnc/a05_comp_arc_tool_radius.ngc`; the
/// oracle reads a point arc as a full turn each, so the sweep is whole
/// turns). Drawn, it is the helix's rise alone.
pub(in crate::machine) fn point_arc(info: &ArcInfo, center: Xyz) -> ArcInfo {
    let turns = 1.0 + (super::arc::extra_turns(info.programmed_sweep) / TAU).round();
    ArcInfo {
        center,
        radius: 0.0,
        sweep: (TAU * turns).copysign(info.programmed_sweep),
        start_angle: info.programmed_start_angle,
        ..*info
    }
}
