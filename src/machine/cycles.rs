//! Canned cycles of the mill: G73, G74, G76, G81–G89 with G98/G99, R, Z, Q,
//! P and K/L repeats; G80 cancels (behaviour 2.14–2.16, Fanuc/YASNAC M). And
//! the dwell both machines' G04 makes with the same P (behaviour 2.9, 1.23). Each cycle is
//! reported as its moves: rapid to the hole, rapid to R, the drilling legs,
//! the retract. The tool length offset applies to the Z levels.

use super::modal::{Cycle, Distance, ReturnLevel};
use super::{AXES, Machine, Out};
use super::{EventKind, MoveKind};
use crate::diag::Diagnostic;
use crate::offsets::length::LengthState;
use crate::syntax::{Address, Block};

/// Most pecks one G73/G83 hole may take.
pub const MAX_PECKS: f64 = 10_000.0;

/// The modal data of a canned cycle, kept from block to block until G80.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct CycleData {
    /// The drilling-axis position when the cycle mode started (programmed).
    initial: f64,
    /// R as written (mm) and whether it was written in G91 (then it is the
    /// distance from the initial level).
    r: Option<(f64, bool)>,
    /// Z as written (mm) and whether in G91 (then the distance from R).
    z: Option<(f64, bool)>,
    /// Q: peck depth (G73/G83) or shift (G76/G87), mm.
    q: Option<f64>,
    /// P: dwell at the bottom, ms.
    p: f64,
}

impl Machine {
    /// G04: dwell P (ms) or X/U (s) (behaviour 2.9).
    pub(super) fn dwell(&mut self, b: &Block, out: &mut Out) -> Result<(), Diagnostic> {
        let p = b.get(Address::P);
        // A time given twice is refused at the second word written.
        let second = |a: &crate::syntax::Word, b: &crate::syntax::Word| {
            if a.span.start > b.span.start {
                a.span
            } else {
                b.span
            }
        };
        if let (Some(x), Some(u)) = (b.get(Address::X), b.get(Address::U)) {
            return Err(self.error(
                "dwell-words",
                second(x, u),
                "G04 takes the dwell time once: X or U in seconds, not both",
            ));
        }
        let time_word = b.get(Address::X).or_else(|| b.get(Address::U));
        let seconds = match (p, time_word) {
            (Some(p), Some(t)) => {
                return Err(self.error(
                    "dwell-words",
                    second(p, t),
                    "G04 takes the dwell time once: P in milliseconds or X in seconds",
                ));
            }
            (Some(p), None) => self.milliseconds(p) / 1000.0,
            (None, Some(t)) => {
                if t.value < 0.0 {
                    return Err(self.error("dwell-words", t.span, "a dwell time is not negative"));
                }
                t.value
            }
            (None, None) => 0.0,
        };
        for a in [Address::Y, Address::Z, Address::W] {
            if let Some(w) = b.get(a) {
                return Err(self.error(
                    "dwell-words",
                    w.span,
                    format!("G04 is a dwell and takes no {} word", a.letter()),
                ));
            }
        }
        self.event(out, EventKind::Dwell { seconds });
        Ok(())
    }

    /// G73–G89: enters or changes the canned cycle mode.
    pub(super) fn start_cycle(&mut self, cycle: Cycle) {
        if self.state.modal.cycle.is_none() {
            let (_, _, n) = self.state.modal.plane.axes();
            self.cycle = CycleData {
                initial: self.state.programmed[n],
                ..CycleData::default()
            };
        }
        self.state.modal.cycle = Some(cycle);
    }

    /// G80, or a group 01 code: leaves the canned cycle mode.
    pub(super) fn cancel_cycle(&mut self) {
        self.state.modal.cycle = None;
    }

    /// A block in the mode of canned cycle `cycle`.
    pub(super) fn cycle_block(
        &mut self,
        b: &Block,
        cycle: Cycle,
        out: &mut Out,
        old_length: LengthState,
    ) -> Result<(), Diagnostic> {
        let (ia, ib, n) = self.state.modal.plane.axes();
        let incremental = self.state.modal.distance == Distance::Incremental;
        let depth_addr = AXES[n].0;
        if let Some(r) = b.value(Address::R) {
            self.cycle.r = Some((self.mm(r), incremental));
        }
        if let Some(z) = b.value(depth_addr) {
            self.cycle.z = Some((self.mm(z), incremental));
        }
        if let Some(q) = b.get(Address::Q) {
            let v = self.mm(q.value);
            if v <= 0.0 && pecks(cycle) {
                return Err(self.error(
                    "cycle-q",
                    q.span,
                    format!("{} needs a positive peck depth Q", cycle.gcode()),
                ));
            }
            self.cycle.q = Some(v.abs());
        }
        if let Some(p) = b.get(Address::P) {
            self.cycle.p = self.milliseconds(p);
        }
        let drills = [ia, ib, n].iter().any(|&i| b.has(AXES[i].0)) || b.has(Address::R);
        if !drills {
            if self.state.length.changed_since(&old_length) {
                // An offset change without a hole: made as offset motion at rapid,
                // the cycles' positioning rate.
                let start = self.mark();
                let setting = self.setup.settings.length_offset_without_z();
                self.state.length.vector = self.state.length.vector_after(false, true, setting);
                self.length_note(old_length, None, out);
                self.emit(out, start, MoveKind::Offset, false, None);
            }
            return Ok(());
        }
        let Some(z) = self.cycle.z else {
            return Err(self.error(
                "cycle-without-depth",
                b.span,
                format!("{} needs {}, the hole bottom", cycle.gcode(), AXES[n].1),
            ));
        };
        if cycle == Cycle::BackBoring && self.state.modal.return_level == ReturnLevel::R {
            return Err(self.error(
                "cycle-return",
                b.span,
                "G87 (back boring) returns to the initial level only: use G98",
            ));
        }
        let repeats = b
            .value(Address::K)
            .or_else(|| b.value(Address::L))
            .map_or(1, |k| k as u32);
        let words = [ia, ib].map(|i| b.value(AXES[i].0).map(|v| self.mm(v)));
        for _ in 0..repeats {
            if self.overflow {
                break;
            }
            // 1. Position over the hole at the current level.
            let start = self.mark();
            if self.plain_words {
                for (k, &axis) in [ia, ib].iter().enumerate() {
                    if let Some(v) = words[k] {
                        self.state.programmed[axis] = self.target(axis, v, incremental);
                    }
                }
            } else {
                self.hole_position(b, incremental, out)?;
            }
            self.emit(out, start, MoveKind::Rapid, false, None);
            // The length offset applies to the Z levels of the cycle.
            if n == 2 {
                self.state.length.vector = self.state.length.target;
            }
            let initial = self.cycle.initial;
            let r_level = match self.cycle.r {
                Some((r, true)) => initial + r,
                Some((r, false)) => r,
                None => initial,
            };
            let bottom = match z {
                (z, true) => r_level + z,
                (z, false) => z,
            };
            self.drill(cycle, n, ia, initial, r_level, bottom, out)?;
            if !self.plain_words {
                self.hole_done(n);
            }
        }
        let l = self.state.length;
        if n == 2 && (l.vector != old_length.vector || l.target != old_length.target) {
            out.notes.push(l.cycle_note(self.units()));
        }
        Ok(())
    }

    fn level(&mut self, out: &mut Out, axis: usize, to: f64, kind: MoveKind) {
        let start = self.mark();
        self.state.programmed[axis] = to;
        self.emit(out, start, kind, kind == MoveKind::Feed, None);
    }

    fn shift(&mut self, out: &mut Out, axis: usize, by: f64) {
        let start = self.mark();
        self.state.programmed[axis] += by;
        self.emit(out, start, MoveKind::Rapid, false, None);
    }

    /// The legs of one hole after positioning (Fanuc M cycle descriptions).
    #[allow(clippy::too_many_arguments)]
    fn drill(
        &mut self,
        cycle: Cycle,
        n: usize,
        shift_axis: usize,
        initial: f64,
        r: f64,
        bottom: f64,
        out: &mut Out,
    ) -> Result<(), Diagnostic> {
        use MoveKind::{Feed, Rapid};
        let ret = match self.state.modal.return_level {
            ReturnLevel::R => r,
            ReturnLevel::Initial => initial,
        };
        let dwell = self.cycle.p / 1000.0;
        let q = self.cycle.q.unwrap_or(0.0);
        let down = if bottom <= r { -1.0 } else { 1.0 };
        let pecks = |q: f64| ((bottom - r).abs() / q).ceil();
        if cycle != Cycle::BackBoring {
            self.level(out, n, r, Rapid);
        }
        match cycle {
            Cycle::HighSpeedPeck | Cycle::PeckDrilling => {
                if q <= 0.0 {
                    return Err(self.error(
                        "cycle-q",
                        self.span,
                        format!("{} needs a positive peck depth Q", cycle.gcode()),
                    ));
                }
                if pecks(q) > MAX_PECKS {
                    return Err(self.error(
                        "cycle-pecks",
                        self.span,
                        format!("peck depth Q makes more than {MAX_PECKS} pecks in one hole"),
                    ));
                }
                let clearance = self.setup.peck_retract_mm();
                let mut depth = r;
                while !self.overflow {
                    let next = if (bottom - depth).abs() <= q {
                        bottom
                    } else {
                        depth + down * q
                    };
                    self.level(out, n, next, Feed);
                    depth = next;
                    if depth == bottom {
                        break;
                    }
                    if cycle == Cycle::HighSpeedPeck {
                        // High-speed peck: back off by d, then feed on.
                        self.level(out, n, depth - down * clearance, Rapid);
                    } else {
                        // Deep hole peck: out to R, back in to d above the last depth.
                        self.level(out, n, r, Rapid);
                        self.level(out, n, depth - down * clearance, Rapid);
                    }
                }
                self.level(out, n, ret, Rapid);
            }
            Cycle::LeftHandTapping | Cycle::Tapping => {
                self.level(out, n, bottom, Feed);
                if dwell > 0.0 {
                    self.event(out, EventKind::Dwell { seconds: dwell });
                }
                // Tapping reverses the spindle at the bottom and feeds out.
                let (rev, fwd) = if cycle == Cycle::Tapping {
                    (EventKind::SpindleCcw, EventKind::SpindleCw)
                } else {
                    (EventKind::SpindleCw, EventKind::SpindleCcw)
                };
                self.event(out, rev);
                self.level(out, n, r, Feed);
                self.event(out, fwd);
                self.level(out, n, ret, Rapid);
            }
            Cycle::FineBoring => {
                self.level(out, n, bottom, Feed);
                if dwell > 0.0 {
                    self.event(out, EventKind::Dwell { seconds: dwell });
                }
                // Oriented stop and a shift by Q off the wall before retracting
                // (shift direction +X: the usual parameter setting).
                self.event(out, EventKind::SpindleOrient);
                self.shift(out, shift_axis, q);
                self.level(out, n, ret, Rapid);
                self.shift(out, shift_axis, -q);
                self.event(out, EventKind::SpindleCw);
            }
            Cycle::BackBoring => {
                // Back boring: in shifted, down to R (below the part), back
                // centre, bore up to Z, shift out and return to the initial level.
                self.event(out, EventKind::SpindleOrient);
                self.shift(out, shift_axis, q);
                self.level(out, n, r, Rapid);
                self.shift(out, shift_axis, -q);
                self.event(out, EventKind::SpindleCw);
                self.level(out, n, bottom, Feed);
                self.event(out, EventKind::SpindleOrient);
                self.shift(out, shift_axis, q);
                self.level(out, n, initial, Rapid);
                self.shift(out, shift_axis, -q);
                self.event(out, EventKind::SpindleCw);
            }
            Cycle::Boring | Cycle::BoringDwell => {
                self.level(out, n, bottom, Feed);
                if cycle == Cycle::BoringDwell && dwell > 0.0 {
                    self.event(out, EventKind::Dwell { seconds: dwell });
                }
                self.level(out, n, r, Feed);
                self.level(out, n, ret, Rapid);
            }
            Cycle::BoringSpindleStop => {
                self.level(out, n, bottom, Feed);
                self.event(out, EventKind::SpindleStop);
                self.level(out, n, ret, Rapid);
                self.event(out, EventKind::SpindleCw);
            }
            Cycle::BoringManualRetract => {
                self.level(out, n, bottom, Feed);
                if dwell > 0.0 {
                    self.event(out, EventKind::Dwell { seconds: dwell });
                }
                self.event(out, EventKind::SpindleStop);
                // The operator jogs out by hand; drawn as a rapid to the return level.
                self.event(out, EventKind::ManualRetract);
                self.level(out, n, ret, Rapid);
                self.event(out, EventKind::SpindleCw);
            }
            Cycle::CounterBoring => {
                self.level(out, n, bottom, Feed);
                if dwell > 0.0 {
                    self.event(out, EventKind::Dwell { seconds: dwell });
                }
                self.level(out, n, ret, Rapid);
            }
            Cycle::Drilling => {
                // Drill, rapid out.
                self.level(out, n, bottom, Feed);
                self.level(out, n, ret, Rapid);
            }
        }
        Ok(())
    }
}

/// True for the cycles that drill in pecks of Q (G73, G83).
fn pecks(cycle: Cycle) -> bool {
    match cycle {
        Cycle::HighSpeedPeck | Cycle::PeckDrilling => true,
        Cycle::LeftHandTapping
        | Cycle::FineBoring
        | Cycle::Drilling
        | Cycle::CounterBoring
        | Cycle::Tapping
        | Cycle::Boring
        | Cycle::BoringSpindleStop
        | Cycle::BackBoring
        | Cycle::BoringManualRetract
        | Cycle::BoringDwell => false,
    }
}

/// A dwell's P in milliseconds: as written, or, written with a decimal
/// point (the parser takes one only with setting `dwell_p_decimal_point =
/// seconds`, Haas), in seconds (behaviour 1.23).
impl Machine {
    /// A dwell's P in milliseconds: a point makes it seconds (Haas), and
    /// on LinuxCNC P is always seconds (behaviour 1.23, 7.26).
    fn milliseconds(&self, p: &crate::syntax::Word) -> f64 {
        let seconds = p.point
            || self.setup.settings.dwell_p_decimal_point()
                == crate::setup::DwellPDecimalPoint::Always;
        if seconds { p.value * 1000.0 } else { p.value }
    }
}
