//! G74 end face peck drilling and G75 outer/inner diameter grooving
//! (behaviour 15.10): pecks along one axis, shifted along the other.

use super::super::{Machine, MoveKind, Out};
use super::MAX_PASSES;
use crate::diag::Diagnostic;
use crate::geometry::show;
use crate::syntax::codes::Repetitive;
use crate::syntax::{Address, Block};

const EPS: f64 = 1e-7;

impl Machine {
    /// G74 / G75 with their target: Fanuc's second block `X(U) Z(W) P(Δi)
    /// Q(Δk) R(Δd) F`, or the one block of the Series 10/11 format and
    /// Haas, `X Z I(Δi) K(Δk) D(Δd) F` (behaviour 15.10).
    pub(super) fn peck(
        &mut self,
        b: &Block,
        cycle: Repetitive,
        out: &mut Out,
    ) -> Result<(), Diagnostic> {
        let face = cycle == Repetitive::FacePeck;
        let fanuc = b.has(Address::P) || b.has(Address::Q);
        if fanuc
            && [Address::I, Address::K, Address::D]
                .iter()
                .any(|a| b.has(*a))
        {
            return Err(self.mrc_error(
                b,
                "mrc-word",
                "PS0066",
                cycle,
                "P and Q (Fanuc's second block) and I, K, D (the one-block form) do not mix".into(),
            ));
        }
        let (di, dk, relief) = if fanuc {
            (
                self.increments(b, Address::P).unwrap_or(0.0),
                self.increments(b, Address::Q).unwrap_or(0.0),
                self.length(b, Address::R).unwrap_or(0.0),
            )
        } else {
            (
                self.length(b, Address::I).unwrap_or(0.0),
                self.length(b, Address::K).unwrap_or(0.0),
                self.depth_word(b).unwrap_or(0.0),
            )
        };
        if di < 0.0 || dk < 0.0 || relief < 0.0 {
            return Err(self.mrc_error(
                b,
                "mrc-value",
                "PS0062",
                cycle,
                "Δi, Δk and the relief Δd are written without a sign".into(),
            ));
        }
        let start = [self.state.programmed[0], self.state.programmed[2]];
        // X and Z absolute (incremental after G91 in systems B and C), U
        // and W incremental (behaviour 7.18).
        let end = [
            self.lathe_target(b, 0).unwrap_or(start[0]),
            self.lathe_target(b, 2).unwrap_or(start[1]),
        ];
        // Work in X radius: (peck axis, shift axis) values of a point.
        let split = |x: f64, z: f64| if face { (z, x / 2.0) } else { (x / 2.0, z) };
        let join = |p: f64, s: f64| if face { (2.0 * s, p) } else { (2.0 * p, s) };
        let (p0, s0) = split(start[0], start[1]);
        let (p1, s1) = split(end[0], end[1]);
        let (peck, step) = if face { (dk, di) } else { (di, dk) };
        let (peck_name, step_name) = if face { ("Δk", "Δi") } else { ("Δi", "Δk") };
        for (from, to, amount, name) in [(p0, p1, peck, peck_name), (s0, s1, step, step_name)] {
            if (to - from).abs() > EPS && amount <= 0.0 {
                return Err(self.mrc_error(
                    b,
                    "mrc-value",
                    "PS0062",
                    cycle,
                    format!("the cycle moves along an axis whose amount {name} is 0"),
                ));
            }
        }
        let count = |from: f64, to: f64, amount: f64| {
            if (to - from).abs() <= EPS {
                0.0
            } else {
                ((to - from).abs() / amount - 1e-9).ceil()
            }
        };
        let pecks = count(p0, p1, peck);
        let shifts = count(s0, s1, step) + 1.0;
        if pecks * shifts > MAX_PASSES as f64 {
            return Err(self.error(
                "mrc-passes",
                b.span,
                format!(
                    "{}: {pecks} pecks at each of {shifts} places; offsetlab makes at most {MAX_PASSES} in one cycle",
                    self.code_name(cycle)
                ),
            ));
        }
        let e = self
            .mrc
            .peck_return
            .unwrap_or_else(|| self.setup.peck_retract_mm());
        let dp = super::sign(p1 - p0);
        let ds = super::sign(s1 - s0);
        self.take_offset();
        let go = |m: &mut Machine, out: &mut Out, p: f64, s: f64, kind| {
            let (x, z) = join(p, s);
            m.cycle_move(out, x, z, kind);
        };
        for j in 0..shifts as usize {
            if self.out_of_moves() {
                break;
            }
            let s = if j + 1 == shifts as usize {
                s1
            } else {
                s0 + ds * step * j as f64
            };
            go(self, out, p0, s, MoveKind::Rapid);
            let mut at = p0;
            for n in 1..=pecks as usize {
                if self.out_of_moves() {
                    break;
                }
                let depth = if n == pecks as usize {
                    p1
                } else {
                    p0 + dp * peck * n as f64
                };
                if n > 1 && e > 0.0 {
                    // Back by e after the last peck, then the next one.
                    go(self, out, at - dp * e, s, MoveKind::Rapid);
                }
                go(self, out, depth, s, MoveKind::Feed);
                at = depth;
            }
            let relieved = s - ds * relief;
            if relief > 0.0 && ds != 0.0 {
                go(self, out, at, relieved, MoveKind::Rapid);
            }
            go(
                self,
                out,
                p0,
                if ds != 0.0 { relieved } else { s },
                MoveKind::Rapid,
            );
        }
        self.cycle_move(out, start[0], start[1], MoveKind::Rapid);
        let units = self.units();
        let (peck_axis, shift_axis) = if face { ("Z", "X") } else { ("X", "Z") };
        out.notes.push(format!(
            "{}: at {} place{} {} {} apart along {shift_axis}{}, {} peck{} of {} {}{} along {peck_axis} each, back {} between pecks{}; then back to the start (behaviour 15.10)",
            self.code_name(cycle),
            shifts,
            if shifts == 1.0 { "" } else { "s" },
            step_name,
            show(step, units),
            if face { " (a radius value)" } else { "" },
            pecks,
            if pecks == 1.0 { "" } else { "s" },
            peck_name,
            show(peck, units),
            if face { "" } else { " (a radius value)" },
            show(e, units),
            if relief > 0.0 {
                format!(", relief {} at the bottom", show(relief, units))
            } else {
                String::new()
            }
        ));
        Ok(())
    }
}
