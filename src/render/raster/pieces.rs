//! A recording made partly of pieces of the kept ones: what a tracer that
//! resumes from the last drawing's tracing needs of the raster (the raster
//! knows nothing of tracing: it numbers the recordings it keeps, and
//! whoever keeps something with one knows it by its number). Where the
//! recording and its pen stand, to note at a checkpoint and to go on from;
//! the recordings of the last drawing and of the one before it, to copy
//! pieces of.

use std::ops::Range;

use super::keep::{MOST_KEPT, Recording};
use super::record::covered;
use super::{Drawing, Raster, Sub};

/// Where a recording stands: its pen (where it is, how far along its
/// sub-path, whether the next segment starts a sub-path) and how much is
/// recorded (points, sub-paths, ink: [`covered`]).
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Recorded {
    at: Option<(f64, f64)>,
    along: f64,
    broken: bool,
    pub(crate) points: usize,
    pub(crate) subs: usize,
    pub(crate) ink: f64,
}

impl Recorded {
    /// The same pen, bit for bit; how far along its sub-path it is only
    /// when the line is `dashed` (a solid line's sub-paths start at phase
    /// 0 wherever they are, and its distance runs on over a whole run of
    /// moves).
    pub(crate) fn same_pen(&self, other: &Recorded, dashed: bool) -> bool {
        let bits = |p: Option<(f64, f64)>| p.map(|(x, y)| (x.to_bits(), y.to_bits()));
        bits(self.at) == bits(other.at)
            && (!dashed || self.along.to_bits() == other.along.to_bits())
            && self.broken == other.broken
    }

    /// `self` moved on by what was recorded from `from` to `to`.
    pub(crate) fn plus(&self, from: &Recorded, to: &Recorded) -> Recorded {
        Recorded {
            points: self.points + to.points - from.points,
            subs: self.subs + to.subs - from.subs,
            ink: self.ink + (to.ink - from.ink),
            ..*to
        }
    }
}

impl Raster {
    /// Where the recording stands.
    pub(crate) fn recorded(&self) -> Recorded {
        Recorded {
            at: self.pen.at,
            along: self.pen.along,
            broken: self.pen.broken,
            points: self.points.len(),
            subs: self.subs.len(),
            ink: self.ink_area,
        }
    }

    /// Puts the pen where `r` says (its path begun already).
    pub(crate) fn resume_pen(&mut self, r: &Recorded) {
        (self.pen.at, self.pen.along, self.pen.broken) = (r.at, r.along, r.broken);
    }

    /// The style of the path being recorded ([`crate::render::Pen::begin_path`]).
    pub(crate) fn path_style(&self) -> Option<u16> {
        self.pen.style
    }

    /// Whether the path being recorded is dashed (its distance along a
    /// sub-path places its dashes).
    pub(crate) fn path_dashed(&self) -> bool {
        let ink = self.pen.style.and_then(|s| self.styles.get(usize::from(s)));
        ink.is_some_and(|ink| ink.period > 0.0)
    }

    /// Past this many points, a recording resumed from pieces may differ
    /// from one made in one go (arcs taken whole, moves no longer a
    /// sub-path each: [`MOST_KEPT`]); it is made in one go then.
    pub(crate) fn most_resumed(&self) -> usize {
        MOST_KEPT.min(self.whole_arcs_past)
    }

    /// The recording kept of a drawing.
    fn recording(&self, which: Drawing) -> &Recording {
        match which {
            Drawing::Last => &self.last,
            Drawing::BeforeLast => &self.before_last.recording,
        }
    }

    /// The number of the recording kept of a drawing (each recording kept
    /// gets the next number), or None when none is: the drawing was not
    /// kept, or its pixels are no longer its recording's.
    pub(crate) fn recording_number(&self, which: Drawing) -> Option<u64> {
        let recording = self.recording(which);
        recording.valid.then_some(recording.number)
    }

    /// The number of a drawing's recording ([`Raster::recording_number`])
    /// when the drawing being recorded may take pieces of it: it was
    /// recorded on this surface at this scale, and this drawing is not made
    /// in parts.
    pub(crate) fn resumable(&self, which: Drawing) -> Option<u64> {
        let recording = self.recording(which);
        let alike = recording.full == self.full && recording.scale == self.scale;
        (alike && !self.planned)
            .then(|| self.recording_number(which))
            .flatten()
    }

    /// Adds ink recorded elsewhere (a sum of [`covered`] areas).
    pub(crate) fn add_ink(&mut self, ink: f64) {
        self.ink_area += covered(ink);
    }

    /// Appends the sub-paths `subs` and the points `points` of a kept
    /// drawing's recording, the sub-paths in style `style`: a piece of the
    /// path being recorded that an edit left alone. A recording made on the
    /// coarse grid was halved ([`Raster::choose_grid`]) and is doubled back.
    /// False, and nothing appended, for a piece out of range.
    pub(crate) fn copy_recorded(
        &mut self,
        which: Drawing,
        subs: Range<usize>,
        points: Range<usize>,
        style: u16,
    ) -> bool {
        let last = match which {
            Drawing::Last => &self.last,
            Drawing::BeforeLast => &self.before_last.recording,
        };
        let (Some(from_subs), Some(from_points)) =
            (last.subs.get(subs), last.points.get(points.clone()))
        else {
            return false;
        };
        // (Exact: the recorder makes 0 of numbers that halving would round,
        // `record::recorded`.)
        let k = if last.coarse == Some(true) { 2.0 } else { 1.0 };
        let shift = self.points.len() as i64 - points.start as i64;
        self.subs.extend(from_subs.iter().map(|sub| Sub {
            first: (i64::from(sub.first) + shift) as u32,
            phase: sub.phase * k,
            style,
        }));
        self.points
            .extend(from_points.iter().map(|p| [p[0] * k, p[1] * k]));
        true
    }
}

#[cfg(test)]
impl Raster {
    /// The recording kept of the last drawing, bit for bit: its sub-paths
    /// (first point, phase, style), points, styles, ink and grid.
    pub(crate) fn kept_recording(&mut self) -> impl PartialEq + std::fmt::Debug + use<> {
        self.finish();
        let last = &self.last;
        assert!(last.valid, "the drawing was kept for the next one");
        let subs: Vec<(u32, u32, u16)> = (last.subs.iter())
            .map(|s| (s.first, s.phase.to_bits(), s.style))
            .collect();
        let points: Vec<[u32; 2]> = last.points.iter().map(|p| p.map(f32::to_bits)).collect();
        let styles = format!("{:?}", last.styles);
        (subs, points, styles, self.ink_area.to_bits(), last.coarse)
    }
}
