//! The sweep: a segment drawn column by column along its major axis,
//! front to back, crossing finished blocks and tiles a step at a time.

use super::open::{Line, each_set, set_bounds};
use super::{BLOCK_BITS, FULL, FULL_TILE, Ink, Raster, TILE_BITS, TILE_MASK, TILE_PIXELS};
use super::{coord, larger, pixel, smaller};

/// The stretches of a dashed segment that are drawn, worked out when the
/// sweep first looks at a column of a stretch of columns it may draw in:
/// in a dense drawing most dashed segments cross only finished tiles, and
/// working out their dashes beforehand was work for nothing; a drawing
/// made on the last one's pixels looks at a few columns of a long segment,
/// and working out all of its dashes was work for columns it never looks
/// at (the instruction counts of `examples/render_time` on the 1M-block
/// program, and with `EDITED`, guard both).
struct Dashes {
    /// Where the segment's start is in the pattern, and its length.
    at: f64,
    length: f64,
    /// The distances from the start within which the sweep looks next.
    window: (f64, f64),
    /// The stretches (distances from the start) that reach into the window,
    /// once `ready`; the memory is the raster's, lent. `next`: the
    /// sweep's place among them.
    on: Vec<(f64, f64)>,
    ready: bool,
    next: usize,
}

impl Dashes {
    /// Works out the stretches within `reach` of the window; the sweep
    /// starts at the first one, or past the last when `reversed` (it runs
    /// from the segment's end). Each stretch is the pattern's, worked out
    /// from the number of its period (not summed dash by dash), so that it
    /// comes out alike whatever the window: a drawing made on the last
    /// one's pixels looks only at the columns where it changed, and must
    /// dash them as a drawing from nothing does.
    #[cold]
    fn work_out(&mut self, ink: &Ink, reversed: bool, reach: f64) {
        self.ready = true;
        self.on.clear();
        let period = ink.period;
        let phase = self.at.rem_euclid(period);
        let lo = larger(self.window.0 - reach, 0.0);
        let hi = smaller(self.window.1 + reach, self.length);
        // Periods of the pattern (from the one the start falls in: number
        // 0) that may reach [lo, hi]. The bound only guards against
        // patterns of tiny entries.
        let first = ((lo + phase) / period).floor() - 1.0;
        let last = smaller(((hi + phase) / period).floor(), first + 100_000.0);
        let mut j = first;
        while j <= last {
            let mut start = j * period - phase;
            for (e, &dash) in ink.dash.iter().enumerate() {
                if e % 2 == 0 {
                    let (s, t) = (larger(start, 0.0), smaller(start + dash, self.length));
                    if s < t && t >= lo && s <= hi {
                        self.on.push((s, t));
                    }
                }
                start += dash;
            }
            j += 1.0;
        }
        self.next = if reversed { self.on.len() } else { 0 };
    }
}

/// A dashed segment's dashes as its sweep meets them, column by column.
struct DashSweep<'d> {
    dashes: &'d mut Dashes,
    /// The sweep's first column is at `a0` along the major axis; `k`
    /// converts columns to distance along the segment.
    a0: f64,
    k: f64,
    length: f64,
    reversed: bool,
    hw: f64,
}

impl DashSweep<'_> {
    /// The columns `first` to `last` are those looked at next.
    fn window(&mut self, first: usize, last: usize) {
        let along = |col: usize| (coord(col) + 0.5 - self.a0) * self.k;
        let (p, q) = (along(first), along(last));
        self.dashes.window = if self.reversed {
            (self.length - q, self.length - p)
        } else {
            (p, q)
        };
        self.dashes.ready = false;
    }

    /// Whether column `col` is drawn: its distance along the segment lies
    /// within the half width of a stretch drawn (the dashes have square
    /// ends, as the line has). Columns are asked in order.
    #[inline(always)]
    fn covers(&mut self, ink: &Ink, col: usize) -> bool {
        let (reversed, hw) = (self.reversed, self.hw);
        let dashes = &mut *self.dashes;
        if !dashes.ready {
            dashes.work_out(ink, reversed, hw);
        }
        let (on, next) = (&dashes.on, &mut dashes.next);
        let along = (coord(col) + 0.5 - self.a0) * self.k;
        if reversed {
            let t = self.length - along;
            while *next > 0 && t < on[*next - 1].0 - hw {
                *next -= 1;
            }
            *next > 0 && t <= on[*next - 1].1 + hw
        } else {
            while *next < on.len() && along > on[*next].1 + hw {
                *next += 1;
            }
            *next < on.len() && along >= on[*next].0 - hw
        }
    }
}

impl Raster {
    /// The segment's dashes, `at` being where its start is in the pattern
    /// and `length` its length: one sweep over it that draws the columns
    /// within the stretches along it that are drawn ([`Dashes`]).
    pub(super) fn dashed(
        &mut self,
        ink: &Ink,
        stamp: u32,
        (from, to): ([f32; 2], [f32; 2]),
        length: f64,
        at: f64,
    ) {
        if length.is_nan() || length <= 0.0 || ink.period.is_nan() || ink.period <= 0.0 {
            return;
        }
        let mut dashes = Dashes {
            at,
            length,
            window: (0.0, length),
            on: std::mem::take(&mut self.dashes),
            ready: false,
            next: 0,
        };
        self.line(ink, stamp, from, to, Some(&mut dashes));
        self.dashes = dashes.on;
    }

    /// A solid segment ([`Raster::line`] without dashes).
    pub(super) fn solid(&mut self, ink: &Ink, stamp: u32, from: [f32; 2], to: [f32; 2]) {
        self.line(ink, stamp, from, to, None);
    }

    /// A straight line in device pixels with square ends, anti-aliased
    /// across its width; with `dashes`, only the stretches along it
    /// (distances from `from`) they list, in order.
    fn line(
        &mut self,
        ink: &Ink,
        stamp: u32,
        from: [f32; 2],
        to: [f32; 2],
        dashes: Option<&mut Dashes>,
    ) {
        let [x0, y0] = from.map(f64::from);
        let [x1, y1] = to.map(f64::from);
        if self.px.is_empty() {
            return;
        }
        if (x1 - x0).abs() >= (y1 - y0).abs() {
            self.sweep::<false>(ink, stamp, (x0, y0), (x1, y1), dashes);
        } else {
            self.sweep::<true>(ink, stamp, (y0, x0), (y1, x1), dashes);
        }
    }

    /// The tile columns along the line, from pixel column `first`'s to
    /// `last`'s, in which it may reach an open tile, as bits of
    /// `self.reach_tiles` from word `base` on (returned): first the blocks
    /// (64 pixels a side) it may reach open, then within each run of their
    /// columns the tiles ([`open`]) — most of a dense drawing's blocks are
    /// finished, and a band of blocks across the line is one step where a
    /// band of tiles is eight.
    fn open_along(
        &mut self,
        transposed: bool,
        (first, last): (usize, usize),
        line: &Line,
    ) -> usize {
        let minor_len = if transposed { self.width } else { self.height };
        let (b0, b1) = (first >> BLOCK_BITS, last >> BLOCK_BITS);
        let blocks = &mut self.reach_blocks;
        blocks.clear();
        blocks.resize((b1 >> 6) - (b0 >> 6) + 1, 0);
        let range = (first, last);
        (self.open_blocks).along(
            transposed,
            BLOCK_BITS,
            range,
            line,
            minor_len,
            blocks,
            b0 >> 6,
        );
        let (t0, t1) = (first >> TILE_BITS, last >> TILE_BITS);
        let tiles = &mut self.reach_tiles;
        tiles.clear();
        tiles.resize((t1 >> 6) - (t0 >> 6) + 1, 0);
        // Runs of adjacent block columns, each as one stretch of the line.
        let mut run: Option<(usize, usize)> = None;
        let side = 1 << BLOCK_BITS;
        let mut tiles_of = |(p, q): (usize, usize)| {
            let range = ((p * side).max(first), (q * side + side - 1).min(last));
            (self.open_tiles).along(
                transposed,
                TILE_BITS,
                range,
                line,
                minor_len,
                tiles,
                t0 >> 6,
            );
        };
        each_set(blocks, b0 >> 6, |b| {
            run = match run {
                Some((p, q)) if q + 1 == b => Some((p, b)),
                Some(done) => {
                    tiles_of(done);
                    Some((b, b))
                }
                None => Some((b, b)),
            };
        });
        if let Some(done) = run {
            tiles_of(done);
        }
        t0 >> 6
    }

    /// Steps along the major axis and covers the span of the line across
    /// each pixel it passes; `TRANSPOSED` when the major axis is y. Only
    /// the tile columns where it may reach an open tile are looked at
    /// ([`Raster::open_along`]). (One
    /// version for each axis: the choices per pixel go; the instruction
    /// count of a 10k-block frame of `examples/render_time` guards it.)
    fn sweep<const TRANSPOSED: bool>(
        &mut self,
        ink: &Ink,
        stamp: u32,
        (a0, b0): (f64, f64),
        (a1, b1): (f64, f64),
        dashes: Option<&mut Dashes>,
    ) {
        let transposed = TRANSPOSED;
        let reversed = a0 > a1;
        let ((a0, b0), (a1, b1)) = if reversed {
            ((a1, b1), (a0, b0))
        } else {
            ((a0, b0), (a1, b1))
        };
        let major_len = if transposed { self.height } else { self.width };
        let da = a1 - a0;
        let slope = if da > 0.0 { (b1 - b0) / da } else { 0.0 };
        let hw = ink.half_width;
        // The line's extent across a pixel column: its width seen along the
        // minor axis.
        let across = hw * (1.0 + slope * slope).sqrt();
        // Square ends: the line runs on by half its width at each end.
        let first = (a0 - hw - 0.5).ceil().max(0.0);
        let last = (a1 + hw - 0.5).floor().min(coord(major_len) - 1.0);
        if first > last || first.is_nan() || last.is_nan() {
            return;
        }
        let (mut first, mut last) = (pixel(first), pixel(last));
        if !self.open_all {
            // Every pixel outside the open box is finished: the columns
            // where the line is within it, a column more each side.
            let (ox0, oy0, ox1, oy1) = self.open;
            let ((oa0, oa1), (ob0, ob1)) = if transposed {
                ((oy0, oy1), (ox0, ox1))
            } else {
                ((ox0, ox1), (oy0, oy1))
            };
            (first, last) = (first.max(oa0), last.min(oa1.saturating_sub(1)));
            if slope != 0.0 {
                // Where the centre is within the box's rows, widened by the
                // line's extent across it and a pixel.
                let reach = across + 2.0;
                let at = |b: f64| a0 - 0.5 + (b - b0) / slope;
                let (p, q) = (at(coord(ob0) - reach), at(coord(ob1) + reach));
                let (lo, hi) = (smaller(p, q).floor() - 1.0, larger(p, q).ceil() + 1.0);
                if hi < coord(first) || lo > coord(last) {
                    return;
                }
                if lo > coord(first) {
                    first = pixel(lo);
                }
                if hi < coord(last) {
                    last = pixel(hi);
                }
            }
            if first > last {
                return;
            }
        }
        // Dashes: the distance along the line from its first point (`from`,
        // which is the far end when `reversed`) decides whether a column is
        // drawn; the dashes have square ends, as the line has.
        let k = (1.0 + slope * slope).sqrt();
        let length = da * k;
        let mut dash = dashes.map(|dashes| DashSweep {
            dashes,
            a0,
            k,
            length,
            reversed,
            hw,
        });
        // The first and the last column looked at, with their rows: the
        // rows move one way along the line (the centre is monotonic in the
        // column, and so are its rounding and clamping), so these bound the
        // box of all the pixels looked at.
        let mut touched: Option<[(usize, usize, usize); 2]> = None;
        let inv = if slope != 0.0 { 1.0 / slope } else { 0.0 };
        let line = Line {
            a0,
            b0,
            slope,
            inv,
            across,
        };
        // The columns before and after those whose pixels all lie in the
        // box of finished tiles ([`super::filled`]), in order (the dashes
        // are found going one way).
        let parts = match self.filled_columns(transposed, &line, (first, last)) {
            Some((s0, s1)) => [
                (s0 > first).then(|| (first, s0 - 1)),
                (s1 < last).then(|| (s1 + 1, last)),
            ],
            None => [Some((first, last)), None],
        };
        for (first, last) in parts.into_iter().flatten() {
            let base = self.open_along(transposed, (first, last), &line);
            let reach = std::mem::take(&mut self.reach_tiles);
            if let Some(dash) = &mut dash
                && let Some((p, q)) = set_bounds(&reach, base)
            {
                // Dashes for the columns of the tiles it may reach.
                let cols = (
                    (p << TILE_BITS).max(first),
                    (q << TILE_BITS | TILE_MASK).min(last),
                );
                dash.window(cols.0, cols.1);
            }
            let mut in_dash = |col: usize| dash.as_mut().is_none_or(|d| d.covers(ink, col));
            let part = (first, last, base);
            self.sweep_part(
                ink,
                stamp,
                transposed,
                part,
                &reach,
                &line,
                &mut in_dash,
                &mut touched,
            );
            self.reach_tiles = reach;
        }
        if let Some([(p, r0, r1), (q, r2, r3)]) = touched {
            let (r, s) = (r0.min(r2), r1.max(r3));
            if transposed {
                self.touch(r, p, s + 1, q + 1);
            } else {
                self.touch(p, r, q + 1, s + 1);
            }
        }
    }

    /// The columns `first` to `last` of the sweep of `line`
    /// ([`Raster::sweep`]): those in which it may reach an open tile
    /// (`reach`, from word `base` on: [`Raster::open_along`]), pixel by
    /// pixel across.
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn sweep_part(
        &mut self,
        ink: &Ink,
        stamp: u32,
        transposed: bool,
        (first, last, base): (usize, usize, usize),
        reach: &[u64],
        line: &Line,
        in_dash: &mut impl FnMut(usize) -> bool,
        touched: &mut Option<[(usize, usize, usize); 2]>,
    ) {
        let minor_len = if transposed { self.width } else { self.height };
        let minor_last = coord(minor_len) - 1.0;
        let opaque = ink.alpha >= 1.0;
        let across = line.across;
        each_set(reach, base, |tile| {
            let from = (tile << TILE_BITS).max(first);
            let to = (tile << TILE_BITS | TILE_MASK).min(last);
            for col in from..=to {
                if !in_dash(col) {
                    continue;
                }
                let c = line.centre(col);
                let (top, bottom) = (c - across, c + across);
                let r0 = larger(top.floor(), 0.0);
                let r1 = smaller(bottom.floor(), minor_last);
                if r0 > r1 {
                    continue;
                }
                let (r0, r1) = (pixel(r0), pixel(r1));
                // The pixels across, a tile at a time: those not finished
                // (most are, once a dense drawing has filled an area).
                // Covering one pixel finishes no other, so the tile's word
                // is read once.
                let mut row = r0;
                while row <= r1 {
                    let end = (row | TILE_MASK).min(r1);
                    let (x, y) = if transposed { (row, col) } else { (col, row) };
                    let tile = (y >> TILE_BITS) * self.tiles_w + (x >> TILE_BITS);
                    let mut open = !self.tiles[tile] & tile_span(transposed, col, row, end);
                    while open != 0 {
                        let bit = open.trailing_zeros() as usize;
                        open &= open - 1;
                        let in_tile = if transposed {
                            bit & TILE_MASK
                        } else {
                            bit >> TILE_BITS
                        };
                        let r = row & !TILE_MASK | in_tile;
                        let (x, y) = if transposed { (r, col) } else { (col, r) };
                        let i = tile << (2 * TILE_BITS) | bit;
                        let coverage =
                            (smaller(bottom, coord(r) + 1.0) - larger(top, coord(r))) as f32;
                        if coverage >= 1.0 && opaque {
                            self.cover_fully(ink, i, x, y);
                        } else if coverage > 0.0 {
                            self.plot(ink, stamp, i, x, y, coverage);
                        }
                    }
                    row = end + 1;
                }
                let seen = (col, r0, r1);
                *touched = Some(touched.map_or([seen; 2], |[first, _]| [first, seen]));
            }
        });
    }

    /// The columns (inclusive) within `first` to `last` at which every
    /// pixel the line covers lies in the box of finished tiles
    /// ([`super::filled`]), or None: where its centre is a reach (its
    /// extent across and a pixel) inside the box's rows, less a column
    /// each side for the rounding.
    fn filled_columns(
        &self,
        transposed: bool,
        line: &Line,
        (first, last): (usize, usize),
    ) -> Option<(usize, usize)> {
        let [x0, y0, x1, y1] = self.filled.px?;
        let ((a0, a1), (b0, b1)) = if transposed {
            ((y0, y1), (x0, x1))
        } else {
            ((x0, x1), (y0, y1))
        };
        let reach = line.across + 1.0;
        let (lo, hi) = (b0 + reach, b1 - reach);
        if lo > hi {
            return None;
        }
        let (mut p, mut q) = (a0, a1);
        if line.slope != 0.0 {
            // Where the centre is `b` across: `a0 - 0.5 + (b - b0) / slope`.
            let at = |b: f64| line.a0 - 0.5 + (b - line.b0) * line.inv;
            let (u, v) = (at(lo), at(hi));
            p = larger(p, smaller(u, v).ceil() + 1.0);
            q = smaller(q, larger(u, v).floor() - 1.0);
        } else if !(lo..=hi).contains(&line.b0) {
            return None;
        }
        let (p, q) = (larger(p, coord(first)), smaller(q, coord(last)));
        (p <= q).then(|| (pixel(p), pixel(q)))
    }

    /// Covers pixel `i`, at (x, y), by `coverage` (0–1) of the path
    /// `stamp`, under what is already there (front to back).
    #[inline(always)]
    fn plot(&mut self, ink: &Ink, stamp: u32, i: usize, x: usize, y: usize, coverage: f32) {
        let p = &mut self.px[i];
        let a = p.rgba[3];
        let new = (smaller(coverage, 1.0) * ink.alpha * 255.0 + 0.5) as u32;
        let cell = p.cover;
        let (front, given) = if cell >> 16 == stamp {
            (cell >> 8 & 0xff, cell & 0xff)
        } else {
            (u32::from(a), 0)
        };
        if new <= given {
            return;
        }
        p.cover = stamp << 16 | front << 8 | new;
        // What lies in front lets 1 - front through; of that, this path
        // adds what it covers beyond what it gave before.
        let add = (255 - front) * (new - given);
        let px = &mut p.rgba;
        for (c, v) in px.iter_mut().zip(ink.rgb) {
            *c = (u32::from(*c) + (v * add + 32512) / 65025).min(255) as u8;
        }
        // Rounded up, so that a pixel covered again and again by the edges
        // of lines does finish (rounded to nearest it would stop at 254).
        let alpha = (u32::from(a) + add.div_ceil(255)).min(255);
        px[3] = alpha as u8;
        if alpha == 255 {
            self.finished_pixel(i, x, y);
        }
    }

    /// Covers pixel `i`, at (x, y), wholly with an opaque ink: what shows
    /// through what lies in front is the ink, and the pixel is finished.
    #[inline(always)]
    fn cover_fully(&mut self, ink: &Ink, i: usize, x: usize, y: usize) {
        let px = &mut self.px[i].rgba;
        let through = 255 - u32::from(px[3]);
        for (c, v) in px.iter_mut().zip(ink.rgb) {
            *c = (u32::from(*c) + (v * through + 127) / 255).min(255) as u8;
        }
        px[3] = 255;
        self.finished_pixel(i, x, y);
    }

    /// Marks pixel `i`, at (x, y), finished.
    fn finished_pixel(&mut self, i: usize, x: usize, y: usize) {
        let tile = i >> (2 * TILE_BITS);
        self.tiles[tile] |= 1 << (i & TILE_PIXELS);
        if self.tiles[tile] == FULL_TILE {
            self.finished_tiles += 1;
            let block = (y >> BLOCK_BITS) * self.blocks_w + (x >> BLOCK_BITS);
            self.blocks[block] += 1;
            self.open_tiles.close(x >> TILE_BITS, y >> TILE_BITS);
            if self.blocks[block] == FULL {
                self.open_blocks.close(x >> BLOCK_BITS, y >> BLOCK_BITS);
            }
        }
    }
}

/// The bits, in a tile's word of finished pixels, of the pixels `from` to
/// `to` (within one tile) across a line at `col` along it; across is x
/// when `transposed`, else y.
#[inline]
pub(super) fn tile_span(transposed: bool, col: usize, from: usize, to: usize) -> u64 {
    let side = 1 << TILE_BITS;
    let (from, to) = (from & TILE_MASK, to & TILE_MASK);
    if transposed {
        // One row of the tile (y = col), columns from..=to.
        let columns = (0xff_u64 >> (TILE_MASK - to + from)) << from;
        columns << ((col & TILE_MASK) * side)
    } else {
        // One column of the tile (x = col), rows from..=to.
        let rows = u64::MAX >> ((TILE_MASK - to + from) * side) << (from * side);
        rows & 0x0101_0101_0101_0101 << (col & TILE_MASK)
    }
}
