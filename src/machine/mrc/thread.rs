//! G76 multiple threading cycle (behaviour 15.12): the passes' depths as
//! the control computes them and each pass's moves.

use super::super::{Machine, MoveKind, Out};
use super::MAX_PASSES;
use crate::diag::Diagnostic;
use crate::geometry::show;
use crate::syntax::codes::Repetitive;
use crate::syntax::{Address, Block};

/// What `G76 P(mmrraa) Q(Δdmin) R(d);` sets (Fanuc parameters 5142, 5130,
/// 5143, 5140, 5141).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct ThreadData {
    /// m: finishing passes at the full depth (1–99).
    finishing: u32,
    /// r: the chamfer (thread run-out), in tenths of the lead (0–99).
    chamfer: u32,
    /// a: the tool tip angle, degrees.
    angle: u32,
    /// Δdmin: the least depth one pass cuts (mm, radius).
    min_cut: f64,
    /// d: the finishing allowance (mm, radius).
    allowance: f64,
}

impl Default for ThreadData {
    /// Our convention where no first block set them: one finishing pass,
    /// no chamfer, a radial infeed (angle 0), no least depth, no allowance.
    fn default() -> Self {
        ThreadData {
            finishing: 1,
            chamfer: 0,
            angle: 0,
            min_cut: 0.0,
            allowance: 0.0,
        }
    }
}

/// The tool tip angles Fanuc's G76 accepts (PS0062 otherwise).
const ANGLES: [u32; 6] = [80, 60, 55, 30, 29, 0];

/// How the passes go in (Haas P1–P4; Fanuc's G76 is P1).
#[derive(Clone, Copy, Debug, PartialEq)]
enum Infeed {
    /// Single edge, constant cutting amount: depth Δd·√n.
    SingleAmount,
    /// Both edges alternately, constant cutting amount.
    DoubleAmount,
    /// Single edge, constant depth: n·Δd.
    SingleDepth,
    /// Both edges alternately, constant depth.
    DoubleDepth,
}

/// The depth of each pass from the crest (behaviour 15.12): Δd·√n (or n·Δd
/// for a constant depth), each at least `min_cut` deeper than the one
/// before, the last rough pass at k − d, then `finishing` passes at k.
pub(super) fn pass_depths(
    k: f64,
    first: f64,
    min_cut: f64,
    allowance: f64,
    finishing: u32,
    constant_amount: bool,
) -> Option<Vec<f64>> {
    let rough_to = (k - allowance).max(0.0);
    let mut depths = Vec::new();
    let mut prev = 0.0;
    let mut n = 1.0f64;
    // Each pass goes deeper; the count is bounded by MAX_PASSES below.
    while rough_to > 0.0 && depths.len() <= MAX_PASSES {
        let mut d = if constant_amount {
            first * n.sqrt()
        } else {
            first * n
        };
        if d - prev < min_cut {
            d = prev + min_cut;
        }
        if d >= rough_to - 1e-9 {
            depths.push(rough_to);
            break;
        }
        depths.push(d);
        prev = d;
        n += 1.0;
    }
    for _ in 0..finishing {
        depths.push(k);
    }
    (depths.len() <= MAX_PASSES).then_some(depths)
}

impl Machine {
    /// `G76 P(mmrraa) Q(Δdmin) R(d);` (behaviour 15.4).
    pub(super) fn thread_first_block(
        &mut self,
        b: &Block,
        out: &mut Out,
    ) -> Result<(), Diagnostic> {
        let cycle = Repetitive::Threading;
        let mut t = self.mrc.thread.unwrap_or_default();
        if let Some(p) = b.get(Address::P) {
            let code = p.int();
            t.finishing = code / 10_000;
            t.chamfer = (code / 100) % 100;
            t.angle = code % 100;
            if !ANGLES.contains(&t.angle) || t.finishing == 0 || t.finishing > 99 {
                return Err(self.mrc_error(
                    b,
                    "mrc-value",
                    "PS0062",
                    cycle,
                    format!(
                        "P{code:06} is mmrraa: m finishing passes 01–99, r chamfer 00–99 tenths of the lead, aa tool angle 80, 60, 55, 30, 29 or 00"
                    ),
                ));
            }
        }
        if let Some(q) = self.increments(b, Address::Q) {
            t.min_cut = q;
        }
        if let Some(r) = self.length(b, Address::R) {
            if r < 0.0 {
                return Err(self.mrc_error(
                    b,
                    "mrc-value",
                    "PS0062",
                    cycle,
                    "the finishing allowance R(d) is not negative".into(),
                ));
            }
            t.allowance = r;
        }
        self.mrc.thread = Some(t);
        let units = self.units();
        out.notes.push(format!(
            "{}: {} finishing pass{}, chamfer {} tenths of the lead, tool angle {}°, least depth {}, finishing allowance {}, kept for the threading cycles that follow (behaviour 15.4)",
            self.code_name(cycle),
            t.finishing,
            if t.finishing == 1 { "" } else { "es" },
            t.chamfer,
            t.angle,
            show(t.min_cut, units),
            show(t.allowance, units)
        ));
        Ok(())
    }

    /// G76 with its target: Fanuc's second block `X(U) Z(W) R(i) P(k) Q(Δd)
    /// F(L)`, or the one block of the Series 10/11 format and Haas, `X Z
    /// I(i) K(k) D(Δd) F(L) P(method)` (behaviour 15.12).
    pub(super) fn threading(&mut self, b: &Block, out: &mut Out) -> Result<(), Diagnostic> {
        let cycle = Repetitive::Threading;
        let mut t = self.mrc.thread.unwrap_or_default();
        let one_block = [Address::K, Address::D, Address::I, Address::A]
            .iter()
            .any(|a| b.has(*a));
        if let Some(w) = b.get(Address::A) {
            // Haas: the tool nose angle, 0 to 120 degrees.
            if w.int() > 120 {
                return Err(self.mrc_error(
                    b,
                    "mrc-value",
                    "PS0062",
                    cycle,
                    format!("A{}: the tool angle is 0 to 120 degrees", w.int()),
                ));
            }
            t.angle = w.int();
        }
        let (taper, k, first, infeed) = if one_block {
            if b.has(Address::R) {
                return Err(self.mrc_error(
                    b,
                    "mrc-word",
                    "PS0066",
                    cycle,
                    "R (Fanuc's second block) and I, K, D (the one-block form) do not mix".into(),
                ));
            }
            let infeed = match b.get(Address::P).map_or(1, |p| p.int()) {
                1 => Infeed::SingleAmount,
                2 => Infeed::DoubleAmount,
                3 => Infeed::SingleDepth,
                4 => Infeed::DoubleDepth,
                other => {
                    return Err(self.mrc_error(
                        b,
                        "mrc-value",
                        "PS0062",
                        cycle,
                        format!("P{other}: the one-block G76 takes P1 to P4 (Haas: single or both edges, constant amount or depth)"),
                    ));
                }
            };
            if b.has(Address::Q) {
                return Err(self.mrc_error(
                    b,
                    "mrc-word",
                    "PS0066",
                    cycle,
                    "Q (the thread start angle of a multi-start thread) is not modelled".into(),
                ));
            }
            (
                self.length(b, Address::I).unwrap_or(0.0),
                self.length(b, Address::K).unwrap_or(0.0),
                self.depth_word(b).unwrap_or(0.0),
                infeed,
            )
        } else {
            (
                self.length(b, Address::R).unwrap_or(0.0),
                self.increments(b, Address::P).unwrap_or(0.0),
                self.increments(b, Address::Q).unwrap_or(0.0),
                Infeed::SingleAmount,
            )
        };
        if k <= 0.0 || first <= 0.0 {
            return Err(self.mrc_error(
                b,
                "mrc-value",
                "PS0062",
                cycle,
                "the thread height k and the first depth Δd must be positive".into(),
            ));
        }
        if t.min_cut > k {
            return Err(self.mrc_error(
                b,
                "mrc-value",
                "PS0062",
                cycle,
                "the least depth Δdmin is more than the thread height k".into(),
            ));
        }
        let Some(lead) = b.value(Address::F).or(self.state.feed).map(|f| self.mm(f)) else {
            return Err(self.mrc_error(
                b,
                "mrc-value",
                "PS0062",
                cycle,
                "F, the thread lead, is missing".into(),
            ));
        };
        let constant_amount = matches!(infeed, Infeed::SingleAmount | Infeed::DoubleAmount);
        let Some(depths) = pass_depths(
            k,
            first,
            t.min_cut,
            t.allowance,
            t.finishing,
            constant_amount,
        ) else {
            return Err(self.error(
                "mrc-passes",
                b.span,
                format!(
                    "{}: these values make more than {MAX_PASSES} passes",
                    self.code_name(cycle)
                ),
            ));
        };
        let a = [self.state.programmed[0], self.state.programmed[2]];
        // X and Z absolute (incremental after G91 in systems B and C), U
        // and W incremental (behaviour 7.18).
        let end = [
            self.lathe_target(b, 0).unwrap_or(a[0]),
            self.lathe_target(b, 2).unwrap_or(a[1]),
        ];
        // From the root toward the start along X (outside: +1), and the
        // direction of the cut along Z.
        let sx = super::sign(a[0] - end[0]);
        let sz = super::sign(end[1] - a[1]);
        if sx == 0.0 || sz == 0.0 {
            return Err(self.mrc_error(
                b,
                "mrc-value",
                "PS0062",
                cycle,
                "the start must lie off the root diameter X and off the thread's end Z".into(),
            ));
        }
        let half = (f64::from(t.angle) / 2.0).to_radians().tan();
        let chamfer = f64::from(t.chamfer) / 10.0 * lead;
        let crest = end[0] / 2.0 + sx * k;
        self.take_offset();
        for (n, &depth) in depths.iter().enumerate() {
            if self.out_of_moves() {
                break;
            }
            let r_end = crest - sx * depth;
            let r_start = r_end + taper;
            // Along the flank: the start moves toward the cut as the pass
            // goes deeper; both edges take turns in P2 and P4.
            let flank = depth * half;
            let shift = match infeed {
                Infeed::SingleAmount | Infeed::SingleDepth => flank,
                Infeed::DoubleAmount | Infeed::DoubleDepth if n % 2 == 0 => flank,
                Infeed::DoubleAmount | Infeed::DoubleDepth => -flank,
            };
            let z0 = a[1] + sz * shift;
            self.cycle_move(out, 2.0 * r_start, z0, MoveKind::Rapid);
            if chamfer > 0.0 {
                let t = 1.0 - chamfer / (end[1] - z0).abs().max(chamfer);
                let r_at = r_start + (r_end - r_start) * t;
                self.cycle_move(out, 2.0 * r_at, end[1] - sz * chamfer, MoveKind::Feed);
                self.cycle_move(out, 2.0 * (r_end + sx * chamfer), end[1], MoveKind::Feed);
            } else {
                self.cycle_move(out, 2.0 * r_end, end[1], MoveKind::Feed);
            }
            self.cycle_move(out, a[0], end[1], MoveKind::Rapid);
            self.cycle_move(out, a[0], a[1], MoveKind::Rapid);
        }
        let units = self.units();
        let list: Vec<String> = depths.iter().map(|d| show(*d, units)).collect();
        out.notes.push(format!(
            "{}: {} passes from the crest X{} to the root X{} (height k {}, first depth Δd {}, {}), depths {}; lead {}{} (behaviour 15.12)",
            self.code_name(cycle),
            depths.len(),
            show(2.0 * crest, units),
            show(end[0], units),
            show(k, units),
            show(first, units),
            match infeed {
                Infeed::SingleAmount => "Δd·√n, single edge",
                Infeed::DoubleAmount => "Δd·√n, both edges in turn",
                Infeed::SingleDepth => "n·Δd, single edge",
                Infeed::DoubleDepth => "n·Δd, both edges in turn",
            },
            list.join(", "),
            show(lead, units),
            if chamfer > 0.0 {
                format!(", chamfer {}", show(chamfer, units))
            } else {
                String::new()
            }
        ));
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn behaviour15_12_depths_grow_as_the_square_root_and_end_at_k() {
        // k 1.0, Δd 0.3: 0.3·√1 = 0.3, 0.3·√2 = 0.424, √3: 0.520, √4: 0.6,
        // √5: 0.671, √6: 0.735, √7: 0.794, √8: 0.849, √9: 0.9, √10: 0.949,
        // √11: 0.995, √12: 1.039 ≥ 1.0 → 1.0; one finishing pass at 1.0.
        let d = pass_depths(1.0, 0.3, 0.0, 0.0, 1, true).unwrap();
        assert_eq!(d.len(), 13);
        assert!((d[1] - 0.3 * 2f64.sqrt()).abs() < 1e-12);
        assert_eq!(&d[11..], &[1.0, 1.0]);
        // Δd 0.5, Δdmin 0.2, allowance d 0.05, m 2: 0.5; 0.5·√2 = 0.7071
        // (0.207 deeper: kept); 0.5·√3 = 0.866 is only 0.159 deeper, so
        // 0.7071 + 0.2 = 0.9071; 0.5·√4 = 1.0 is 0.093 deeper → 1.1071,
        // past k − d = 0.95 → 0.95; then two passes at k = 1.0.
        let d = pass_depths(1.0, 0.5, 0.2, 0.05, 2, true).unwrap();
        let want = [
            0.5,
            0.5 * 2f64.sqrt(),
            0.5 * 2f64.sqrt() + 0.2,
            0.95,
            1.0,
            1.0,
        ];
        assert_eq!(d.len(), want.len(), "{d:?}");
        for (a, b) in d.iter().zip(want) {
            assert!((a - b).abs() < 1e-12, "{d:?}");
        }
        // Constant depth: n·Δd, 0.3, 0.6, 0.9, then 1.0, and one at k.
        assert_eq!(pass_depths(1.0, 0.3, 0.0, 0.0, 1, false).unwrap().len(), 5);
        assert!(pass_depths(1.0, 1e-9, 0.0, 0.0, 1, true).is_none());
    }
}
