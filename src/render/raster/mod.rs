//! The paths of a large drawing as pixels, drawn here in wasm and handed to
//! the canvas as one image.
//!
//! Why: a browser's 2D canvas records every `lineTo` and rasterises the
//! recorded paths afterwards, and Chromium's cost for that grows faster than
//! the path's length: the 1M-block benchmark program was not painted in any
//! time a page can wait, and a 10k-block program's frames were far too slow
//! to follow typing (`make bench-browser`, targets 3 and 4, guard it).
//!
//! How: the segments are recorded (clipped to the view, as `f32`), then
//! drawn front to back — last path first, each path's segments last
//! first — so that a pixel is final as soon as it is opaque, and the
//! segments below it skip it. Finished pixels are marked per 8 × 8 tile
//! (a bit each) and finished tiles counted per 64 × 64 block, so a segment
//! crosses a finished region in steps of 64 or 8 pixels instead of pixel
//! by pixel, and pixel by pixel looks only at those not finished: a dense
//! program, whose lines cover the same area many times over, costs about
//! what its visible pixels and its segments cost, not its length in pixels.
//!
//! What it draws matches the vector drawing of small paths closely enough to
//! read the same: the same colours and widths in device pixels, anti-aliased
//! across the line, square caps (the canvas's are round), dashes that run
//! on across the segments of a sub-path from where it starts, as the
//! canvas's do. Each path (`begin_path` … `stroke`) is painted as the
//! canvas paints one: where its own segments overlap, a pixel takes the
//! larger coverage instead of being painted twice, so translucent strokes
//! (the current block's highlight) keep their colour at joints.

mod filled;
mod keep;
mod open;
mod output;
mod pieces;
mod record;
mod sweep;
#[cfg(test)]
mod tests;

pub(crate) use pieces::Recorded;
use record::Recorder;
pub use record::{InkMeter, parse_color};

/// Surfaces larger than this (device pixels) are drawn as vectors: the
/// buffers take 8 bytes a pixel.
pub const MAX_PIXELS: usize = 4096 * 4096;

/// Finished pixels are marked per tile of `TILE` × `TILE` (a bit each, in
/// a `u64`), finished tiles counted per block of `TILE` × `TILE` tiles.
const TILE_BITS: usize = 3;
const BLOCK_BITS: usize = 2 * TILE_BITS;
const FULL: u8 = 1 << (2 * TILE_BITS);
const FULL_TILE: u64 = u64::MAX;
/// A coordinate within its tile; a pixel's number within its tile.
const TILE_MASK: usize = (1 << TILE_BITS) - 1;
const TILE_PIXELS: usize = (1 << (2 * TILE_BITS)) - 1;

/// Drawings whose lines would cover the surface more than this many times
/// over are made on the coarse grid ([`Raster::choose_grid`]).
const DENSE: f64 = 3.0;

/// A premultiplied RGBA pixel buffer that strokes are recorded for and then
/// drawn on, front to back.
#[derive(Default)]
pub struct Raster {
    /// The surface in device pixels.
    full: (usize, usize),
    /// The grid drawn on: the surface, or half of it ([`Raster::choose_grid`]).
    width: usize,
    height: usize,
    /// Whether this drawing is on the coarse grid; None until decided.
    coarse: Option<bool>,
    /// CSS to device pixels.
    scale: (f64, f64),
    /// CSS pixels to the pixels recorded: device pixels, or those of the
    /// grid of a drawing planned ([`Raster::plan`]).
    rec: (f64, f64),
    /// A drawing made in parts ([`Raster::plan`]): its grid chosen before
    /// anything is recorded, each part drawn (below the ones before) when
    /// [`Raster::finish`] is called, and a segment found hidden when it is
    /// recorded not recorded at all.
    planned: bool,
    /// The pixels, tile by tile (tiles row by row, each tile's pixels row
    /// by row: [`Raster::index`]). The pixels a line covers are read
    /// there, scattered over megabytes, and waiting for them was much of
    /// drawing a 10k-block frame with the image's rows in memory; a tile's
    /// row is one cache line, and a steep line steps to the next one rather
    /// than an image row further (`examples/render_time` on the 10k-block
    /// program guards it).
    px: Vec<Pixel>,
    /// The stamp of the first path of this drawing.
    base: u32,
    /// Finished (opaque) pixels per tile: bit `8 (y mod 8) + (x mod 8)`,
    /// so that the pixels across a line that are not finished are found a
    /// tile at a time and only they are read (a bit a pixel instead of
    /// its eight bytes). Finished tiles per block. Both start
    /// with what lies outside the surface finished, so `FULL_TILE` and
    /// `FULL` mean finished.
    tiles: Vec<u64>,
    blocks: Vec<u8>,
    tiles_w: usize,
    blocks_w: usize,
    /// The tiles and the blocks not finished, as bits by row and by
    /// column ([`open`]): a line finds those it may reach 64 at a time.
    open_tiles: open::Open,
    open_blocks: open::Open,
    /// How many tiles are finished, and the largest box of them found
    /// ([`filled`]).
    finished_tiles: usize,
    filled: filled::Filled,
    /// The blocks and the tiles along the line being swept that it may
    /// reach open (kept for their memory).
    reach_blocks: Vec<u64>,
    reach_tiles: Vec<u64>,
    /// The box of the pixels drawn (x0, y0, x1, y1; exclusive ends), and
    /// the width in tiles of the grid they were drawn on (the pixels may be
    /// those of the drawing before the last: [`keep::BeforeLast`]).
    dirty: Option<(usize, usize, usize, usize)>,
    dirty_tiles_w: usize,
    /// What was recorded since [`Raster::begin`].
    styles: Vec<Ink>,
    subs: Vec<Sub>,
    points: Vec<[f32; 2]>,
    /// The arcs recorded whole ([`crate::render::Pen::arc`]), each a sub-path of its own
    /// (its `arc`), tessellated when drawn unless hidden; and the points
    /// of the one being drawn (kept for their memory).
    arcs: Vec<RecordedArc>,
    arc_points: Vec<[f32; 2]>,
    /// How many whole arcs this drawing tessellated (the others it found
    /// hidden).
    tessellated: usize,
    /// Past this many recorded points, arcs are taken whole
    /// ([`crate::render::Pen::takes_arcs`]).
    whole_arcs_past: usize,
    pen: Recorder,
    /// The area the recorded lines cover, overlaps counted (device
    /// pixels²).
    ink_area: f64,
    /// The drawn stretches of the dashed segment being drawn, the lengths
    /// of the segments of the dashed sub-path being drawn (both kept for
    /// their memory).
    dashes: Vec<(f64, f64)>,
    lengths: Vec<f64>,
    /// What the last drawing recorded, whose pixels `px` holds: the next
    /// one is compared with it, and only where they differ drawn again
    /// ([`keep`]).
    last: keep::Recording,
    /// The drawing before the last one, set aside with its pixels when a
    /// drawing was made from nothing ([`keep::BeforeLast`]).
    before_last: keep::BeforeLast,
    /// How many recordings were kept ([`keep::Recording::number`]).
    recordings: u64,
    /// Whether this drawing was made on the last one's pixels, or on those
    /// of the drawing before it.
    kept: bool,
    /// Which of the two pixel buffers `px` is (the other is the drawing's
    /// before the last: [`keep::BeforeLast`]).
    buffer: usize,
    /// The box (x0, y0, x1, y1; exclusive ends) outside which every pixel
    /// is finished: the surface, or where a drawing made on the last one's
    /// pixels may change them ([`Raster::changed`]). Segments are drawn
    /// only within it. Also as
    /// the pixel coordinates of its first and last pixels (None: empty),
    /// and whether it is the whole surface (worked out once: these are
    /// asked of every segment).
    open: (usize, usize, usize, usize),
    open_pixels: Option<[f64; 4]>,
    open_all: bool,
}

/// One of the two drawings a raster keeps for the next one: the last, or
/// the one before it ([`keep`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Drawing {
    /// The drawing made last (before [`Raster::finish`]: the one before the
    /// drawing being recorded).
    Last,
    /// The one before it, set aside with its pixels ([`keep::BeforeLast`]).
    BeforeLast,
}

/// A pixel of the drawing: its colour and which path covered it last,
/// side by side (a line's pixels are read and written together: one cache
/// line instead of two, where the buffers are larger than the caches).
#[derive(Clone, Copy, Debug, Default)]
#[repr(C, align(8))]
struct Pixel {
    /// Premultiplied RGBA, transparent where nothing is drawn.
    rgba: [u8; 4],
    /// The path that last covered it (stamp, high 16 bits), the alpha of
    /// what lay in front of it then (8 bits) and the alpha it gave (low 8
    /// bits) — so that a path covers a pixel once.
    cover: u32,
}

/// How a path is stroked, in device pixels.
#[derive(Clone, Debug, Default, PartialEq)]
struct Ink {
    rgb: [u32; 3],
    alpha: f32,
    half_width: f64,
    /// Dash pattern (even length) and its length; empty: solid.
    dash: Vec<f64>,
    period: f64,
}

/// A recorded sub-path: its points run from `first` to the next one's;
/// or, when its style has [`WHOLE_ARC`], it is the next of the arcs
/// recorded whole (in order: a sub-path has no room for their number, and
/// twelve bytes a sub-path instead of sixteen are megabytes of a 1M-block
/// frame).
#[derive(Clone, Copy, Debug)]
struct Sub {
    first: u32,
    /// Where its first point is in the dash pattern.
    phase: f32,
    style: u16,
}

/// The bit of [`Sub::style`] that marks a whole arc (styles are fewer than
/// 2^15).
const WHOLE_ARC: u16 = 1 << 15;

impl RecordedArc {
    /// Its points into `out`: the start vector turned a segment's angle
    /// at a time ([`crate::toolpath::ArcPoints::Rotated`]), its ends as
    /// recorded.
    fn tessellate(&self, out: &mut Vec<[f32; 2]>) {
        out.clear();
        out.push(self.from);
        let [cx, cy] = self.centre.map(f64::from);
        let (mut vx, mut vy) = (f64::from(self.from[0]) - cx, f64::from(self.from[1]) - cy);
        let (sin, cos) = (f64::from(self.sweep) / f64::from(self.count)).sin_cos();
        for _ in 1..self.count {
            (vx, vy) = (vx * cos - vy * sin, vy * cos + vx * sin);
            out.push([(cx + vx) as f32, (cy + vy) as f32]);
        }
        out.push(self.to);
    }
}

/// An arc recorded whole, in pixels of the drawing: from `from` about
/// `centre` through `sweep` to `to`, in `count` equal segments.
#[derive(Clone, Copy, Debug)]
struct RecordedArc {
    centre: [f32; 2],
    from: [f32; 2],
    to: [f32; 2],
    sweep: f32,
    count: u32,
}

impl Raster {
    /// A raster with no pixels yet.
    pub fn new() -> Raster {
        Raster {
            whole_arcs_past: keep::MOST_KEPT,
            ..Raster::default()
        }
    }

    /// How many of the arcs recorded whole were tessellated and drawn:
    /// those not found hidden under what was drawn before them.
    pub fn arcs_tessellated(&mut self) -> usize {
        self.finish();
        self.tessellated
    }

    /// Takes arcs whole once `points` points are recorded (for tests:
    /// 1 Mi otherwise, where a drawing is no longer kept for the next edit;
    /// in the 1M-block frame most points are arcs', and most of those arcs
    /// lie under the moves drawn after them).
    pub fn take_arcs_whole_past(&mut self, points: usize) {
        self.whole_arcs_past = points;
    }

    /// Starts a drawing of `width` × `height` device pixels, `scale` device
    /// pixels per CSS pixel, all transparent; false (and nothing to draw)
    /// when the surface is empty or larger than [`MAX_PIXELS`]. The last
    /// drawing's pixels stay until [`Raster::finish`] knows which of them
    /// the new one keeps ([`keep`]).
    pub fn begin(&mut self, width: usize, height: usize, scale: (f64, f64)) -> bool {
        let pixels = width.saturating_mul(height);
        let scale_ok = [scale.0, scale.1].iter().all(|s| s.is_finite() && *s > 0.0);
        if pixels == 0 || pixels > MAX_PIXELS || !scale_ok {
            return false;
        }
        if (width, height) != self.full {
            self.full = (width, height);
            self.px.clear();
            let side = 1 << TILE_BITS;
            let tiled = width.div_ceil(side) * height.div_ceil(side) * side * side;
            self.px.resize(tiled, Pixel::default());
            self.base = 1;
            self.dirty = None;
            self.last.forget();
            self.before_last = keep::BeforeLast::default();
        }
        (self.width, self.height) = self.full;
        self.coarse = None;
        // Stamps are 16 bits: when this drawing's could wrap, start over.
        self.base += self.styles.len() as u32;
        if self.base + u32::from(u16::MAX / 2) > u32::from(u16::MAX) {
            self.px.iter_mut().for_each(|p| p.cover = 0);
            self.base = 1;
        }
        self.scale = scale;
        self.rec = scale;
        self.planned = false;
        self.restart();
        true
    }

    /// Forgets what was recorded since [`Raster::begin`].
    pub(crate) fn restart(&mut self) {
        self.styles.clear();
        self.subs.clear();
        self.points.clear();
        self.arcs.clear();
        self.tessellated = 0;
        self.pen = Recorder::default();
        self.ink_area = 0.0;
    }

    /// Clears what the last drawing touched (in its own grid, which may have
    /// been the coarse one), as whole tiles: a row of them is one stretch
    /// of memory, and the pixels outside the box are clear already.
    fn clear_last(&mut self) {
        if let Some((x0, y0, x1, y1)) = self.dirty.take() {
            let tiles_w = self.dirty_tiles_w;
            for ty in y0 >> TILE_BITS..=(y1 - 1) >> TILE_BITS {
                let start = index(tiles_w, x0 & !TILE_MASK, ty << TILE_BITS);
                let end = index(tiles_w, (x1 - 1) | TILE_MASK, ty << TILE_BITS | TILE_MASK);
                self.px[start..=end].fill(Pixel::default());
            }
        }
        self.last.forget();
    }

    fn reset_tiles(&mut self) {
        let side = 1 << TILE_BITS;
        let block_side = 1 << BLOCK_BITS;
        self.tiles_w = self.width.div_ceil(side);
        let tiles_h = self.height.div_ceil(side);
        self.blocks_w = self.width.div_ceil(block_side);
        let blocks_h = self.height.div_ceil(block_side);
        self.tiles.clear();
        self.tiles.resize(self.tiles_w * tiles_h, 0);
        self.blocks.clear();
        self.blocks.resize(self.blocks_w * blocks_h, 0);
        // Pixels and tiles outside the surface count as finished.
        let inside = |i: usize, n: usize, side: usize| (n - i * side).min(side);
        for ty in 0..tiles_h {
            for tx in 0..self.tiles_w {
                let (w, h) = (inside(tx, self.width, side), inside(ty, self.height, side));
                // The columns from w on of each row, and the rows from h on.
                let columns = (0xff_u64 << w) & 0xff;
                let mut outside = u64::MAX.checked_shl((h * side) as u32).unwrap_or(0);
                for y in 0..h {
                    outside |= columns << (y * side);
                }
                self.tiles[ty * self.tiles_w + tx] = outside;
            }
        }
        for by in 0..blocks_h {
            for bx in 0..self.blocks_w {
                let n = inside(bx, self.tiles_w, side) * inside(by, tiles_h, side);
                self.blocks[by * self.blocks_w + bx] = FULL - n as u8;
            }
        }
    }

    /// Indexes the tiles and blocks not finished ([`open`]) from
    /// [`Raster::tiles`] and [`Raster::blocks`]; [`Raster::finished_pixel`]
    /// keeps them up to date.
    fn index_open(&mut self) {
        let tiles = &self.tiles;
        (self.open_tiles).index(self.tiles_w, tiles.len(), |t| tiles[t] != FULL_TILE);
        let blocks = &self.blocks;
        (self.open_blocks).index(self.blocks_w, blocks.len(), |b| blocks[b] != FULL);
    }

    /// Makes this drawing in parts, front to back as they come: the caller
    /// records a part (the last moves of the top path first), calls
    /// [`Raster::finish`] to draw it below what is drawn, records the part
    /// before it, and so on; a segment already hidden when it is recorded is
    /// not recorded (most of a dense drawing's are: recording them was
    /// much of the 1M-block frame's time and memory, which `make
    /// bench-browser`, target 3, guards). The
    /// grid is chosen now, from `ink_area` (device pixels² its lines would
    /// cover, overlaps counted; see [`Raster::choose_grid`]). Such a drawing
    /// is not kept for the next one (it records too little to compare).
    pub fn plan(&mut self, ink_area: f64) {
        self.last.forget();
        self.ink_area = ink_area;
        self.planned = true;
        // Nothing recorded yet: the grid, the surface cleared, the tiles.
        self.finish();
        let f = self.factor() as f64;
        self.rec = (self.scale.0 / f, self.scale.1 / f);
    }

    /// Width and height in pixels of the drawing ([`Raster::factor`]
    /// device pixels each).
    pub fn size(&mut self) -> (usize, usize) {
        self.finish();
        (self.width, self.height)
    }

    /// Level of detail: lines that would cover the surface several times
    /// over make an area of solid colour, whose pixels cost the same to
    /// fill at any resolution but four times as much at full resolution as
    /// at half: such a drawing is made on a grid of half the device pixels
    /// and scaled up when it is put on the canvas ([`Raster::factor`]).
    fn choose_grid(&mut self) {
        let (w, h) = self.full;
        let coarse = self.ink_area > DENSE * (w * h) as f64;
        self.coarse = Some(coarse);
        if coarse {
            (self.width, self.height) = (w.div_ceil(2), h.div_ceil(2));
            for p in &mut self.points {
                *p = p.map(|v| v / 2.0);
            }
            for sub in &mut self.subs {
                sub.phase /= 2.0;
            }
            for arc in &mut self.arcs {
                for p in [&mut arc.centre, &mut arc.from, &mut arc.to] {
                    *p = p.map(|v| v / 2.0);
                }
            }
            for ink in &mut self.styles {
                ink.half_width /= 2.0;
                ink.dash.iter_mut().for_each(|d| *d /= 2.0);
                ink.period /= 2.0;
            }
        }
    }

    /// Device pixels per pixel of the drawing: 2 when it was made on the
    /// coarse grid ([`Raster::choose_grid`]), else 1.
    pub fn factor(&mut self) -> usize {
        self.finish();
        if self.coarse == Some(true) { 2 } else { 1 }
    }

    /// Draws what was recorded (once; later calls draw what was recorded
    /// since, below it — and, on a drawing made on the last one's pixels,
    /// only where it changed: the page records a drawing in one go).
    pub fn finish(&mut self) {
        let first = self.coarse.is_none();
        if first {
            self.choose_grid();
            // The last drawing's pixels where this one is the same, or none.
            // (keep_last sets the open box of a drawing it keeps.)
            self.kept = self.keep_last() || self.keep_before_last();
            if !self.kept {
                self.set_last_aside();
                self.clear_last();
                self.reset_tiles();
                self.open = (0, 0, self.width, self.height);
            }
            self.index_open();
            self.dirty_tiles_w = self.tiles_w;
            self.finished_tiles = self.tiles.iter().filter(|&&t| t == FULL_TILE).count();
            self.filled.reset();
            let (x0, y0, x1, y1) = self.open;
            self.open_all = self.open == (0, 0, self.width, self.height);
            self.open_pixels = (x0 < x1 && y0 < y1)
                .then(|| [coord(x0), coord(y0), coord(x1) - 1.0, coord(y1) - 1.0]);
        } else if !self.subs.is_empty() {
            // Drawn in several goes: not compared with the next.
            self.last.forget();
        }
        let subs = std::mem::take(&mut self.subs);
        let points = std::mem::take(&mut self.points);
        let arcs = std::mem::take(&mut self.arcs);
        let mut arc_points = std::mem::take(&mut self.arc_points);
        // (Lent, not cloned per sub-path: most moves are one.)
        let styles = std::mem::take(&mut self.styles);
        // The whole arcs, last first as the sub-paths.
        let mut whole = arcs.iter().rev();
        for (k, sub) in subs.iter().enumerate().rev() {
            self.update_filled();
            let arc = (sub.style & WHOLE_ARC != 0).then(|| whole.next()).flatten();
            let style = usize::from(sub.style & !WHOLE_ARC);
            let Some(ink) = styles.get(style) else {
                continue;
            };
            let pts = if let Some(arc) = arc {
                // Its circle's box first: most arcs of a dense drawing are
                // hidden whole.
                let [cx, cy] = arc.centre;
                let r = length(f64::from(arc.from[0] - cx), f64::from(arc.from[1] - cy)) as f32;
                if self.hidden([cx - r, cy - r], [cx + r, cy + r], ink.half_width) {
                    continue;
                }
                arc.tessellate(&mut arc_points);
                self.tessellated += 1;
                &arc_points[..]
            } else {
                let end = subs.get(k + 1).map_or(points.len(), |n| n.first as usize);
                &points[sub.first as usize..end]
            };
            let stamp = (self.base + style as u32) & 0xffff;
            if ink.dash.is_empty() {
                for w in pts.windows(2).rev() {
                    if !self.hidden(w[0], w[1], ink.half_width) {
                        self.solid(ink, stamp, w[0], w[1]);
                    }
                }
                continue;
            }
            if let [from, to] = *pts {
                // Most sub-paths are one segment (a line move).
                if !self.hidden(from, to, ink.half_width) {
                    let length = length(f64::from(to[0] - from[0]), f64::from(to[1] - from[1]));
                    let end_at = f64::from(sub.phase) + length;
                    self.dashed(ink, stamp, (from, to), length, end_at - length);
                }
                continue;
            }
            // Dashes are laid from the sub-path's start; drawn from its end.
            // Each segment's length is worked out once (three times, with
            // `hypot`, that was a share of a 1M-block frame of
            // `examples/render_time`).
            let mut lengths = std::mem::take(&mut self.lengths);
            lengths.clear();
            lengths.extend(
                pts.windows(2)
                    .map(|w| length(f64::from(w[1][0] - w[0][0]), f64::from(w[1][1] - w[0][1]))),
            );
            let mut end_at = f64::from(sub.phase) + lengths.iter().sum::<f64>();
            for (w, &length) in pts.windows(2).zip(&lengths).rev() {
                let start_at = end_at - length;
                if !self.hidden(w[0], w[1], ink.half_width) {
                    self.dashed(ink, stamp, (w[0], w[1]), length, start_at);
                }
                end_at = start_at;
            }
            self.lengths = lengths;
        }
        self.styles = styles;
        self.arc_points = arc_points;
        let whole_arcs = !arcs.is_empty();
        self.arcs = arcs;
        self.arcs.clear();
        if first && (self.planned || points.len() > keep::MOST_KEPT || whole_arcs) {
            self.last.forget();
            self.subs = subs;
            self.points = points;
        } else if first {
            // What the next drawing is compared with; the allocations of
            // the one before are kept for it.
            let surface = (self.full, self.coarse, self.scale);
            self.recordings += 1;
            let (subs, points) =
                (self.last).keep(self.recordings, (subs, points), &self.styles, surface);
            self.subs = subs;
            self.points = points;
        } else {
            self.subs = subs;
            self.points = points;
        }
        self.subs.clear();
        self.points.clear();
    }

    fn touch(&mut self, x0: usize, y0: usize, x1: usize, y1: usize) {
        self.dirty = Some(match self.dirty {
            None => (x0, y0, x1, y1),
            Some((a, b, c, d)) => (a.min(x0), b.min(y0), c.max(x1), d.max(y1)),
        });
    }

    /// Whether the box around a segment (and its width) lies wholly in
    /// finished blocks: once a dense drawing has filled an area, most of
    /// the segments below are hidden, and cost this look-up only.
    fn hidden(&self, from: [f32; 2], to: [f32; 2], half_width: f64) -> bool {
        // How far the sweep's pixels reach beyond the segment's box: its
        // square end runs on by the half width along the major axis, and
        // across it the line spans the half width times up to √2 (a
        // diagonal), so a corner pixel lies up to hw·(1 + √2) out, plus
        // the pixel itself. (hw + 1 missed faint end pixels of diagonals.)
        let hw = half_width * (1.0 + std::f64::consts::SQRT_2) + 1.0;
        let [x0, x1] = [
            f64::from(smaller(from[0], to[0])) - hw,
            f64::from(larger(from[0], to[0])) + hw,
        ];
        let [y0, y1] = [
            f64::from(smaller(from[1], to[1])) - hw,
            f64::from(larger(from[1], to[1])) + hw,
        ];
        if self.in_filled(x0, y0, x1, y1) {
            return true;
        }
        // Off the surface, or (drawn on the last drawing's pixels) off the
        // box where they may change.
        let Some([left, top, w, h]) = self.open_pixels else {
            return true;
        };
        if x1 < left || y1 < top || x0 > w || y0 > h {
            return true;
        }
        let (px0, px1) = (pixel(x0.clamp(left, w)), pixel(x1.clamp(left, w)));
        let (py0, py1) = (pixel(y0.clamp(top, h)), pixel(y1.clamp(top, h)));
        let blocks = (
            (px0 >> BLOCK_BITS, px1 >> BLOCK_BITS),
            (py0 >> BLOCK_BITS, py1 >> BLOCK_BITS),
        );
        if !self.open_blocks.any_in(blocks.0, blocks.1) {
            return true;
        }
        // In a block not yet finished: its own tiles, 64 at a time along a
        // row ([`open`]). Most segments of a 1M-block frame that reach the
        // sweep cover no pixel, and most of those lie in finished tiles (a
        // block is finished only when all its 64 tiles are): looking here
        // saves their sweep (`examples/render_time` on the 1M-block
        // program, natively and built for wasm32-wasip1, guards it). (Once
        // tested a tile at a time, for boxes of 4 × 4 tiles at most; the box
        // of a whole arc is larger.)
        let tiles = (
            (px0 >> TILE_BITS, px1 >> TILE_BITS),
            (py0 >> TILE_BITS, py1 >> TILE_BITS),
        );
        !self.open_tiles.any_in(tiles.0, tiles.1)
    }

    /// Where the pixel at (x, y) is in [`Raster::px`]: its tile's number
    /// (which is also its word in [`Raster::tiles`]) times 64, plus its bit
    /// in that word.
    #[inline]
    fn index(&self, x: usize, y: usize) -> usize {
        index(self.tiles_w, x, y)
    }
}

/// The index of pixel (x, y) in a grid `tiles_w` tiles wide.
fn index(tiles_w: usize, x: usize, y: usize) -> usize {
    let tile = (y >> TILE_BITS) * tiles_w + (x >> TILE_BITS);
    tile << (2 * TILE_BITS) | (y & TILE_MASK) << TILE_BITS | x & TILE_MASK
}

/// The smaller of two numbers, neither of them NaN (points, centres and
/// widths of recorded segments, which are finite): `f64::min` also
/// answers for NaN, which wasm's `f64.min` does not do as Rust wants, so
/// there it is a call to libm's `fmin`, or that inlined: two comparisons
/// and two selections where this has one of each (before wasm-opt the
/// calls to fmin, fmax and their f32 forms were a large share of a 1M-block
/// run of `examples/render_time` built for wasm32-wasip1, which guards it).
#[inline(always)]
fn smaller<T: PartialOrd>(a: T, b: T) -> T {
    if b < a { b } else { a }
}

/// The larger of two numbers, neither of them NaN ([`smaller`]).
#[inline(always)]
fn larger<T: PartialOrd>(a: T, b: T) -> T {
    if b > a { b } else { a }
}

/// A pixel coordinate as a float: through `u32` (coordinates are below
/// [`MAX_PIXELS`]), which converts in one instruction natively where a
/// `usize` takes several — the conversions of the sweep and
/// [`Raster::hidden`] were a share of a 1M-block frame of
/// `examples/render_time`, which guards it.
#[inline]
fn coord(v: usize) -> f64 {
    f64::from(v as u32)
}

/// The pixel coordinate of a whole float in [0, 2^32), through `u32` as
/// [`coord`].
#[inline]
fn pixel(v: f64) -> usize {
    v as u32 as usize
}

/// The length of a segment (dx, dy): the square root of the sum of the
/// squares, within an ulp of `hypot` (which cost several times as much, a
/// share of a 1M-block frame of `examples/render_time`); `hypot` where the
/// squares would overflow or lose digits below the normal numbers.
fn length(dx: f64, dy: f64) -> f64 {
    let squares = dx * dx + dy * dy;
    if (1e-290..1e290).contains(&squares) {
        squares.sqrt()
    } else {
        dx.hypot(dy)
    }
}
