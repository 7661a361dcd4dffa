//! How far the tool travels and how long the program takes (behaviour
//! 6.10): the length of the actual path, rapid and feed apart, and an
//! estimate of the cycle time from the setup's rapid rate, the program's F
//! and S, and its dwells.
//!
//! An estimate as a programmer makes one by hand: every move at its full
//! rate from start to end (no acceleration, no look-ahead slow-down), tool
//! changes and M-code waits not counted.

use serde::Serialize;

use crate::geometry::sub;
use crate::machine::{BlockState, Move, MoveKind};
use crate::setup::{MachineKind, Units};
use crate::syntax::codes::{FeedMode, SurfaceSpeed};

/// Pieces a constant-surface-speed arc is cut into to sum its time: the
/// spindle speed follows the diameter along the move (behaviour 6.10).
const CSS_STEPS: u32 = 16;

/// Path length and time of a run, or of a part of one.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct Travel {
    /// Length of the rapid moves (mm; offset motion at the rapid rate
    /// included).
    pub rapid: f64,
    /// Length of the feed moves, lines and arcs (mm).
    pub feed: f64,
    /// Estimated time in seconds: rapid, feed and dwell.
    pub seconds: f64,
    /// Of that, the dwells (G04, a cycle's dwell at the bottom).
    pub dwell: f64,
    /// Feed moves with no rate to time them (no F yet, per revolution
    /// without S): not in `seconds`.
    pub untimed: u32,
}

impl Travel {
    /// Adds another part's totals.
    pub fn add(&mut self, other: &Travel) {
        self.rapid += other.rapid;
        self.feed += other.feed;
        self.seconds += other.seconds;
        self.dwell += other.dwell;
        self.untimed += other.untimed;
    }

    /// Adds a dwell of `seconds`.
    pub fn dwell(&mut self, seconds: f64) {
        if seconds.is_finite() && seconds > 0.0 {
            self.dwell += seconds;
            self.seconds += seconds;
        }
    }

    /// Adds a block's moves, made in the state `state` ends the block with
    /// (F, S, the feed mode and the units are modal, and a block's own words
    /// apply to its moves); `rapid_rate` in mm/min.
    pub fn block(&mut self, moves: &[Move], state: &BlockState, rapid_rate: f64) {
        let machine = state.machine;
        let mut block_feed = 0.0;
        for m in moves {
            let length = length(m, machine);
            if !cutting(m) {
                self.rapid += length;
                self.seconds += rapid_minutes(m, machine, rapid_rate) * 60.0;
            } else {
                self.feed += length;
                block_feed += length;
            }
        }
        if block_feed == 0.0 {
            return;
        }
        let minutes = match feed_minutes(moves, block_feed, state) {
            Some(t) => t,
            None => {
                self.untimed += moves.iter().filter(|m| cutting(m)).count() as u32;
                return;
            }
        };
        if minutes.is_finite() {
            self.seconds += minutes * 60.0;
        }
    }
}

/// A move at the feed rate: not a rapid, nor offset motion at the rapid
/// rate.
fn cutting(m: &Move) -> bool {
    match m.kind {
        MoveKind::Rapid => false,
        MoveKind::Offset => m.at_feed,
        _ => true,
    }
}

/// Length of a move's actual path (mm; the lathe's X is a diameter, so its
/// half is the distance travelled).
fn length(m: &Move, machine: MachineKind) -> f64 {
    let mut d = sub(m.to, m.from);
    if machine == MachineKind::Lathe {
        d[0] /= 2.0;
    }
    match &m.arc {
        Some(a) => {
            let across = a.radius * a.sweep.abs();
            // The helix's rise along the plane's normal.
            let rise = d[a.plane.axes().2];
            (across * across + rise * rise).sqrt()
        }
        None => (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt(),
    }
}

/// Minutes a rapid takes: each axis at the rapid rate, the move as long as
/// its longest axis (Fanuc's default non-linear positioning, parameter LRP
/// off).
fn rapid_minutes(m: &Move, machine: MachineKind, rate: f64) -> f64 {
    let d = sub(m.to, m.from);
    let x = match machine {
        MachineKind::Lathe => d[0] / 2.0,
        MachineKind::Mill => d[0],
    };
    let longest = x.abs().max(d[1].abs()).max(d[2].abs());
    if rate > 0.0 { longest / rate } else { 0.0 }
}

/// Minutes the feed moves of a block take (`total` mm long), or None when
/// nothing gives a rate.
fn feed_minutes(moves: &[Move], total: f64, state: &BlockState) -> Option<f64> {
    let machine = state.machine;
    let f = state.feed.filter(|f| *f > 0.0)?;
    let unit = match state.modal.units {
        Units::Mm => 1.0,
        Units::Inch => 25.4,
    };
    match state.modal.feed_mode {
        FeedMode::PerMinute => Some(total / (f * unit)),
        // G93: F is 1 / the minutes the block's move takes (behaviour 14.8).
        FeedMode::InverseTime => Some(1.0 / f),
        FeedMode::PerRevolution => {
            let s = state.spindle.filter(|s| *s > 0.0)?;
            let per_rev = f * unit;
            match (machine, state.modal.surface_speed) {
                (MachineKind::Lathe, SurfaceSpeed::Constant) => {
                    let mut minutes = 0.0;
                    for m in moves.iter().filter(|m| cutting(m)) {
                        minutes +=
                            css_minutes(m, s, state.spindle_limit, per_rev, state.modal.units);
                    }
                    Some(minutes)
                }
                (_, SurfaceSpeed::Constant) => None,
                _ => Some(total / (per_rev * s)),
            }
        }
    }
}

/// Minutes a lathe feed move takes at constant surface speed `vc` (m/min,
/// or ft/min in inches): the spindle turns at vc / (π × diameter), at most
/// the G50 limit. Along a line the time per length is then the larger of
/// 1 / limit and diameter / (vc / π), a function of the position that is
/// constant or linear between the points where the diameter crosses 0 or
/// the limit's diameter: summed piece by piece at their midpoints, which
/// is exact. An arc is taken along its chord, in 16 pieces.
fn css_minutes(m: &Move, vc: f64, limit: Option<f64>, per_rev_mm: f64, units: Units) -> f64 {
    let length = length(m, MachineKind::Lathe);
    if length == 0.0 || per_rev_mm <= 0.0 || vc <= 0.0 {
        return 0.0;
    }
    // Surface speed per minute in mm: m/min × 1000, ft/min × 304.8.
    let k = match units {
        Units::Mm => vc * 1000.0,
        Units::Inch => vc * 304.8,
    } / std::f64::consts::PI;
    let limit = limit.filter(|l| *l > 0.0);
    let (d0, d1) = (m.from[0], m.to[0]);
    let at = |t: f64| d0 + (d1 - d0) * t;
    let mut cuts: Vec<f64> = vec![0.0, 1.0];
    if m.arc.is_some() {
        cuts.extend((1..CSS_STEPS).map(|i| f64::from(i) / f64::from(CSS_STEPS)));
    }
    if d1 != d0 {
        let mut cross = |d: f64| {
            let t = (d - d0) / (d1 - d0);
            if t > 0.0 && t < 1.0 {
                cuts.push(t);
            }
        };
        cross(0.0);
        if let Some(l) = limit {
            cross(k / l);
            cross(-k / l);
        }
    }
    cuts.sort_by(f64::total_cmp);
    let mut minutes_per_length = 0.0;
    for w in cuts.windows(2) {
        let (a, b) = (w[0], w[1]);
        let d = at((a + b) / 2.0).abs();
        // Minutes per mm of travel at this diameter: 1 / (feed per rev × rpm).
        let per_rpm = match limit {
            Some(l) => (d / k).max(1.0 / l),
            None => d / k,
        };
        minutes_per_length += (b - a) * per_rpm;
    }
    length * minutes_per_length / per_rev_mm
}
