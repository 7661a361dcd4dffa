//! A drawing made again where it changed: the pixels of the last drawing
//! are kept where the new one records the same segments, so an edit that
//! moves a few moves of a large path costs about those moves, not the
//! whole frame (`make bench-browser`, target 4c, guards it).
//!
//! How: every move is a sub-path of its own in the recording
//! ([`super::Raster`]'s `next_move`), with the dash phase it starts at; a
//! dashed pattern starts afresh often ([`crate::render::RESTART_EVERY`]),
//! so an edit changes the phases of a few moves after it at most. Path by
//! path, the sub-paths the two recordings share at the path's start and at
//! its end (same points, same phase) are the same; the pixels that any
//! other sub-path of either drawing may reach are cleared, every other
//! pixel counts as finished, and the new drawing is drawn as usual, front
//! to back: it paints only the cleared pixels, and there exactly what a
//! drawing from nothing would (every segment that reaches such a pixel is
//! drawn into it, in the same order). Tests: `raster::tests` compare both
//! ways of drawing pixel for pixel.

use super::sweep::tile_span;
use super::{Ink, Pixel, Raster, Sub, TILE_BITS, TILE_MASK};

/// Surfaces of more pixels than this do not keep the drawing before the
/// last one ([`BeforeLast`]): its pixels take 8 bytes each (32 MiB here,
/// many times what the page's 10k-block benchmark frame takes on the
/// coarse grid).
const BEFORE_LAST_MOST_PIXELS: usize = 1 << 22;

/// Past this share of changed points (of both recordings together) or of
/// pixels to draw again, the drawing is made from nothing: the comparison
/// would not pay.
const MOST: f64 = 0.5;

/// Recordings of more points than this are not kept, nor split into a
/// sub-path per move past it (nor do their dashes start afresh there): the
/// 10k-block benchmark program records far fewer points on the page, the
/// 1M-block one several times more, and a sub-path per move made that
/// one's first frame slower and its wasm memory larger than an edit drawn
/// on its pixels would have saved (`make bench-browser`, target 3, guards
/// the first frame and the memory; `examples/render_time` with `EDITED`,
/// the edit).
pub(super) const MOST_KEPT: usize = 1 << 20;

/// The recording of a kept drawing (in its grid's coordinates) and what
/// it was drawn on.
#[derive(Default)]
pub(super) struct Recording {
    /// Its number: each recording kept gets the next one, so that what the
    /// renderer keeps with it outside the raster is known for its own.
    pub(super) number: u64,
    pub(super) subs: Vec<Sub>,
    pub(super) points: Vec<[f32; 2]>,
    pub(super) styles: Vec<Ink>,
    /// Whether the pixels are this recording's, drawn in one go; and the
    /// surface, grid and scale they were drawn with.
    pub(super) valid: bool,
    pub(super) full: (usize, usize),
    pub(super) coarse: Option<bool>,
    pub(super) scale: (f64, f64),
    /// The pixels to draw again, per tile as [`Raster::tiles`] (kept for
    /// its memory).
    marks: Vec<u64>,
}

impl Recording {
    /// The pixels are no longer this recording's.
    pub(super) fn forget(&mut self) {
        self.valid = false;
    }

    /// Keeps the recording just drawn as recording `number`; returns the
    /// one it replaces (its memory, for the next drawing).
    pub(super) fn keep(
        &mut self,
        number: u64,
        (subs, points): (Vec<Sub>, Vec<[f32; 2]>),
        styles: &[Ink],
        (full, coarse, scale): ((usize, usize), Option<bool>, (f64, f64)),
    ) -> (Vec<Sub>, Vec<[f32; 2]>) {
        self.number = number;
        let old = (
            std::mem::replace(&mut self.subs, subs),
            std::mem::replace(&mut self.points, points),
        );
        self.styles.clear();
        self.styles.extend_from_slice(styles);
        (self.full, self.coarse, self.scale) = (full, coarse, scale);
        self.valid = true;
        old
    }

    /// The points of sub-path `k`.
    fn points_of(&self, k: usize) -> &[[f32; 2]] {
        points_of(&self.subs, &self.points, k)
    }
}

/// The drawing before the last one: its pixels, the box drawn on them and
/// its recording, set aside when a drawing is made from nothing instead of
/// cleared. Typing goes back and forth: a digit that makes a block wrong
/// stops the run there, the path's bounds change, and with them the fitted
/// view, so that every point of the next frame moves; the next digit (or
/// Backspace, or an undo) makes the block right again and brings the
/// view back — and that frame is the one before, or a small edit of it,
/// made on its pixels like any edit of the last one, instead of a whole
/// frame (`make bench-browser`, target 4b, guards it).
#[derive(Default)]
pub(super) struct BeforeLast {
    px: Vec<Pixel>,
    dirty: Option<(usize, usize, usize, usize)>,
    dirty_tiles_w: usize,
    pub(super) recording: Recording,
}

impl BeforeLast {
    pub(super) fn forget(&mut self) {
        self.recording.forget();
    }
}

/// The number of points of the sub-paths `r`.
fn span(subs: &[Sub], points: usize, r: &std::ops::Range<usize>) -> usize {
    if r.is_empty() {
        return 0;
    }
    let to = subs.get(r.end).map_or(points, |s| s.first as usize);
    to - subs[r.start].first as usize
}

fn points_of<'a>(subs: &[Sub], points: &'a [[f32; 2]], k: usize) -> &'a [[f32; 2]] {
    let end = subs.get(k + 1).map_or(points.len(), |n| n.first as usize);
    &points[subs[k].first as usize..end]
}

impl Raster {
    /// Trades the last drawing (pixels, their drawn box, recording) for the
    /// one before it.
    fn swap_before_last(&mut self) {
        let before = &mut self.before_last;
        std::mem::swap(&mut self.px, &mut before.px);
        std::mem::swap(&mut self.dirty, &mut before.dirty);
        std::mem::swap(&mut self.dirty_tiles_w, &mut before.dirty_tiles_w);
        std::mem::swap(&mut self.last, &mut before.recording);
        self.buffer ^= 1;
    }

    /// Prepares a drawing on the pixels of the drawing before the last one
    /// ([`BeforeLast`]) when [`Raster::keep_last`] keeps them (it checks
    /// their surface first); the last drawing becomes the one before. False,
    /// and nothing changed, otherwise.
    pub(super) fn keep_before_last(&mut self) -> bool {
        self.swap_before_last();
        if self.keep_last() {
            return true;
        }
        self.swap_before_last();
        false
    }

    /// Before a drawing made from nothing: the last one, when it can be
    /// compared with the next ones, is set aside as the one before
    /// ([`BeforeLast`]), and this one is made on the pixels of the one set
    /// aside before (cleared as the last drawing's always are), or on new ones.
    pub(super) fn set_last_aside(&mut self) {
        if !self.last.valid || self.px.len() > BEFORE_LAST_MOST_PIXELS {
            return;
        }
        self.swap_before_last();
        let len = self.before_last.px.len();
        if self.px.len() != len {
            self.px.clear();
            self.px.resize(len, Pixel::default());
            self.dirty = None;
        }
    }

    /// Prepares a drawing on the last one's pixels (see the module's
    /// comment); false, and nothing changed, when it cannot be or would not
    /// pay: another surface, grid, scale or set of styles, or most of it
    /// changed.
    pub(super) fn keep_last(&mut self) -> bool {
        let last = &self.last;
        let same_surface = last.valid
            && last.full == self.full
            && last.coarse == self.coarse
            && last.scale == self.scale;
        // (A drawing with whole arcs is large: never kept, nor compared.)
        if !same_surface || last.styles != self.styles || !self.arcs.is_empty() {
            return false;
        }
        // Path by path (a path's sub-paths are together, in the order of
        // the paths), the sub-paths between those the two share at the
        // path's start and at its end.
        let same = |a: usize, b: usize| {
            let (x, y) = (&last.subs[a], &self.subs[b]);
            x.phase.to_bits() == y.phase.to_bits()
                && last.points_of(a) == points_of(&self.subs, &self.points, b)
        };
        let mut changed = Vec::new();
        let mut points = 0;
        for style in 0..self.styles.len() {
            let of = |subs: &[Sub]| {
                let at = |s: usize| subs.partition_point(|sub| usize::from(sub.style) < s);
                at(style)..at(style + 1)
            };
            let (old, new) = (of(&last.subs), of(&self.subs));
            let shorter = old.len().min(new.len());
            let start = (0..shorter)
                .find(|&k| !same(old.start + k, new.start + k))
                .unwrap_or(shorter);
            let end = (0..shorter - start)
                .find(|&j| !same(old.end - 1 - j, new.end - 1 - j))
                .unwrap_or(shorter - start);
            let (old, new) = (
                old.start + start..old.end - end,
                new.start + start..new.end - end,
            );
            points += span(&last.subs, last.points.len(), &old)
                + span(&self.subs, self.points.len(), &new);
            changed.push((old, new));
        }
        if points as f64 > MOST * (last.points.len() + self.points.len()) as f64 {
            return false;
        }
        // The pixels any changed sub-path of either drawing may reach.
        self.reset_tiles();
        let mut marks = std::mem::take(&mut self.last.marks);
        marks.clear();
        marks.resize(self.tiles.len(), 0);
        for (old, new) in changed {
            for k in old {
                let ink = &self.last.styles[usize::from(self.last.subs[k].style)];
                for w in self.last.points_of(k).windows(2) {
                    self.mark(&mut marks, w[0], w[1], ink.half_width);
                }
            }
            for k in new {
                let ink = &self.styles[usize::from(self.subs[k].style)];
                for w in points_of(&self.subs, &self.points, k).windows(2) {
                    self.mark(&mut marks, w[0], w[1], ink.half_width);
                }
            }
        }
        let redrawn: u32 = marks.iter().map(|m| m.count_ones()).sum();
        if f64::from(redrawn) > MOST * (self.width * self.height) as f64 {
            self.last.marks = marks;
            return false;
        }
        // Cleared where drawn again; finished (kept) everywhere else; and
        // the box of the tiles drawn again.
        let side = 1 << TILE_BITS;
        let mut changed: Option<(usize, usize, usize, usize)> = None;
        for (t, &again) in marks.iter().enumerate() {
            let (tx, ty) = (t % self.tiles_w, t / self.tiles_w);
            if again != 0 {
                let first = t << (2 * TILE_BITS);
                let mut bits = again;
                while bits != 0 {
                    self.px[first | bits.trailing_zeros() as usize] = Pixel::default();
                    bits &= bits - 1;
                }
                self.tiles[t] |= !again;
                let (x, y) = (tx << TILE_BITS, ty << TILE_BITS);
                let (x1, y1) = ((x + side).min(self.width), (y + side).min(self.height));
                changed = Some(changed.map_or((x, y, x1, y1), |(a, b, c, d)| {
                    (a.min(x), b.min(y), c.max(x1), d.max(y1))
                }));
            } else {
                self.tiles[t] = u64::MAX;
            }
            if self.tiles[t] == u64::MAX {
                self.blocks[(ty / side) * self.blocks_w + tx / side] += 1;
            }
        }
        self.open = changed.unwrap_or((0, 0, 0, 0));
        self.last.marks = marks;
        true
    }

    /// Marks the pixels that the sweep of the segment from `from` to `to`
    /// (`half_width` about it) may cover: column by column along its major
    /// axis as [`Raster::sweep`] goes (its square ends, its width across),
    /// a pixel more on every side for the rounding.
    fn mark(&self, marks: &mut [u64], from: [f32; 2], to: [f32; 2], half_width: f64) {
        let [x0, y0] = from.map(f64::from);
        let [x1, y1] = to.map(f64::from);
        let steep = (y1 - y0).abs() > (x1 - x0).abs();
        // Along (a) and across (b) the major axis, from the lower a.
        let ((a0, b0), (a1, b1)) = {
            let (p, q) = if steep {
                ((y0, x0), (y1, x1))
            } else {
                ((x0, y0), (x1, y1))
            };
            if p.0 <= q.0 { (p, q) } else { (q, p) }
        };
        let slope = if a1 > a0 { (b1 - b0) / (a1 - a0) } else { 0.0 };
        let across = half_width * (1.0 + slope * slope).sqrt() + 1.0;
        let (a_len, b_len) = if steep {
            (self.height, self.width)
        } else {
            (self.width, self.height)
        };
        let clamp = |v: f64, len: usize| -> Option<usize> {
            (v.is_finite() && v >= 0.0).then(|| (v as usize).min(len - 1))
        };
        let (first, last) = (a0 - half_width - 1.5, a1 + half_width + 0.5);
        if !(first.is_finite() && last.is_finite()) || last < 0.0 || first > (a_len - 1) as f64 {
            return;
        }
        let (first, last) = (first.max(0.0) as usize, (last as usize).min(a_len - 1));
        for a in first..=last {
            let c = b0 + (a as f64 + 0.5 - a0) * slope;
            let (lo, hi) = ((c - across).floor() - 1.0, (c + across).floor() + 1.0);
            if hi < 0.0 || lo > (b_len - 1) as f64 {
                continue;
            }
            let (Some(lo), Some(hi)) = (clamp(lo.max(0.0), b_len), clamp(hi, b_len)) else {
                continue;
            };
            let mut row = lo;
            while row <= hi {
                let end = (row | TILE_MASK).min(hi);
                let (x, y) = if steep { (row, a) } else { (a, row) };
                let tile = (y >> TILE_BITS) * self.tiles_w + (x >> TILE_BITS);
                marks[tile] |= tile_span(steep, a, row, end);
                row = end + 1;
            }
        }
    }
}
