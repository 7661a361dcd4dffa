//! Which cells of a grid (the tiles, or the blocks of tiles) are not yet
//! finished, as bits by row and by column, so that a line finds the open
//! cells it may reach a word of 64 at a time, band by band across it.
//!
//! Why: the segments of a dense drawing are long and cross finished pixels
//! mostly. Stepping along a segment a block or a tile at a time and asking
//! of each step whether the tiles under the line's width are finished was
//! most of the sweep of a 1M-block frame, whose steps mostly find no pixel
//! to look at (the instruction count of `examples/render_time` on the
//! 1M-block program guards it).

use super::{coord, larger, pixel, smaller};

/// A line along its major axis: its centre crosses the minor axis at `b0`
/// at `a0` along it, moving `slope` across a column (`inv` its inverse, or
/// 0 when it is 0); `across` is how far its pixels reach either side of the
/// centre across a column.
#[derive(Clone, Copy)]
pub(super) struct Line {
    pub a0: f64,
    pub b0: f64,
    pub slope: f64,
    pub inv: f64,
    pub across: f64,
}

impl Line {
    /// The centre across the column `a`, at its middle.
    #[inline(always)]
    pub fn centre(&self, a: usize) -> f64 {
        self.b0 + (coord(a) + 0.5 - self.a0) * self.slope
    }
}

/// The open cells of a grid `w` × `h`: bit `x mod 64` of word
/// `y · row_words + x / 64` of `rows`, and bit `y mod 64` of word
/// `x · col_words + y / 64` of `cols`, for each cell (x, y) not finished.
#[derive(Default)]
pub(super) struct Open {
    rows: Vec<u64>,
    cols: Vec<u64>,
    row_words: usize,
    col_words: usize,
}

impl Open {
    /// Indexes a grid `w` cells wide of `n` cells (row by row), `open(i)`
    /// telling whether cell `i` is not finished.
    pub fn index(&mut self, w: usize, n: usize, open: impl Fn(usize) -> bool) {
        let h = n.checked_div(w).unwrap_or(0);
        (self.row_words, self.col_words) = (w.div_ceil(64), h.div_ceil(64));
        self.rows.clear();
        self.rows.resize(h * self.row_words, 0);
        self.cols.clear();
        self.cols.resize(w * self.col_words, 0);
        for i in (0..w * h).filter(|&i| open(i)) {
            let (x, y) = (i % w, i / w);
            self.rows[y * self.row_words + x / 64] |= 1 << (x % 64);
            self.cols[x * self.col_words + y / 64] |= 1 << (y % 64);
        }
    }

    /// Marks cell (x, y) finished.
    #[inline]
    pub fn close(&mut self, x: usize, y: usize) {
        self.rows[y * self.row_words + (x >> 6)] &= !(1 << (x & 63));
        self.cols[x * self.col_words + (y >> 6)] &= !(1 << (y & 63));
    }

    /// Whether any cell of columns `xs` by rows `ys` (inclusive) is open:
    /// a word of 64 cells at a time, row by row, or column by column when
    /// there are fewer columns than rows.
    #[inline]
    pub fn any_in(&self, xs: (usize, usize), ys: (usize, usize)) -> bool {
        if xs.1 - xs.0 < ys.1 - ys.0 {
            any_in(&self.cols, self.col_words, ys, xs)
        } else {
            any_in(&self.rows, self.row_words, xs, ys)
        }
    }

    /// Sets in `reach` the cells along the line's major axis, from the one
    /// of pixel column `first` to that of `last`, in which the line's
    /// pixels may meet an open cell of this grid (cells of `1 << bits`
    /// pixels a side; `transposed`: the major axis is y; `minor_len`: the
    /// surface's pixels across). Bit `j` of word `k` of `reach` is cell
    /// `64 (base + k) + j` along. More may be set than are met (the ends
    /// are widened by a column for the rounding), never fewer.
    #[allow(clippy::too_many_arguments)]
    pub fn along(
        &self,
        transposed: bool,
        bits: usize,
        (first, last): (usize, usize),
        line: &Line,
        minor_len: usize,
        reach: &mut [u64],
        base: usize,
    ) {
        let (bands, words) = if transposed {
            (&self.cols, self.col_words)
        } else {
            (&self.rows, self.row_words)
        };
        // The rows the columns' pixels span (as the sweep works them out).
        let (c0, c1) = (line.centre(first), line.centre(last));
        let lo = larger((smaller(c0, c1) - line.across).floor(), 0.0);
        let hi = smaller(
            (larger(c0, c1) + line.across).floor(),
            coord(minor_len) - 1.0,
        );
        if lo > hi || lo.is_nan() || hi.is_nan() {
            return;
        }
        // Where along the line its centre is `b` across: `at + b · inv`.
        let at = line.a0 - 0.5 - line.b0 * line.inv;
        let side = coord(1 << bits);
        let (first_at, last_at) = (coord(first), coord(last));
        for band in pixel(lo) >> bits..=pixel(hi) >> bits {
            let (mut from, mut to) = (first, last);
            if line.slope != 0.0 {
                // A column's pixels reach rows floor(c - across) to
                // floor(c + across), c its centre: the band's rows when c
                // is within [top - across, bottom + across). Two columns
                // more each side (truncated rather than rounded out).
                let top = coord(band << bits);
                let p = at + (top - line.across) * line.inv;
                let q = at + (top + side + line.across) * line.inv;
                let (l, h) = (smaller(p, q) - 2.0, larger(p, q) + 2.0);
                if h < first_at || l > last_at {
                    continue;
                }
                if l > first_at {
                    from = pixel(l);
                }
                if h < last_at {
                    to = pixel(h);
                }
            }
            let (f, t) = (from >> bits, to >> bits);
            let open = &bands[band * words..][..words];
            let (wf, wt) = (f >> 6, t >> 6);
            let (head, tail) = (u64::MAX << (f & 63), u64::MAX >> (63 - (t & 63)));
            if wf == wt {
                reach[wf - base] |= open[wf] & head & tail;
                continue;
            }
            reach[wf - base] |= open[wf] & head;
            for w in wf + 1..wt {
                reach[w - base] |= open[w];
            }
            reach[wt - base] |= open[wt] & tail;
        }
    }
}

/// Whether any bit `xs` (inclusive) of lines `ys` of `bits` (`words` words
/// a line) is set.
#[inline]
fn any_in(bits: &[u64], words: usize, (x0, x1): (usize, usize), (y0, y1): (usize, usize)) -> bool {
    let (w0, w1) = (x0 >> 6, x1 >> 6);
    let (head, tail) = (u64::MAX << (x0 & 63), u64::MAX >> (63 - (x1 & 63)));
    if w0 == w1 {
        // (Most grids are one word wide: a word a line.)
        let mask = head & tail;
        let mut at = y0 * words + w0;
        for _ in y0..=y1 {
            if bits[at] & mask != 0 {
                return true;
            }
            at += words;
        }
        return false;
    }
    (y0..=y1).any(|y| {
        let line = &bits[y * words..][..words];
        line[w0] & head != 0 || line[w0 + 1..w1].iter().any(|&w| w != 0) || line[w1] & tail != 0
    })
}

/// Calls `f` with each set bit of `reach` (bit `j` of word `k` being
/// `64 (base + k) + j`), in ascending order.
#[inline(always)]
pub(super) fn each_set(reach: &[u64], base: usize, mut f: impl FnMut(usize)) {
    for (k, &word) in reach.iter().enumerate() {
        let mut word = word;
        while word != 0 {
            f((base + k) << 6 | word.trailing_zeros() as usize);
            word &= word - 1;
        }
    }
}

/// The first and the last cell set in `reach` (as [`each_set`] numbers
/// them), or None when none is.
pub(super) fn set_bounds(reach: &[u64], base: usize) -> Option<(usize, usize)> {
    let first = reach.iter().position(|&w| w != 0)?;
    let last = reach.iter().rposition(|&w| w != 0)?;
    Some((
        (base + first) << 6 | reach[first].trailing_zeros() as usize,
        (base + last) << 6 | (63 - reach[last].leading_zeros() as usize),
    ))
}

// (proptest is a native dev-dependency: `wasm-pack test` builds these too.)
#[cfg(all(test, not(target_arch = "wasm32")))]
mod tests {
    use super::*;

    /// The cells along the line whose open cells its pixels reach, column
    /// by column as the sweep covers them.
    fn reached(
        open: &[bool],
        (w, h, bits): (usize, usize, usize),
        transposed: bool,
        (first, last): (usize, usize),
        line: &Line,
    ) -> Vec<usize> {
        let minor_len = if transposed { w << bits } else { h << bits };
        let mut cells: Vec<usize> = Vec::new();
        for col in first..=last {
            let c = line.centre(col);
            let r0 = (c - line.across).floor().max(0.0);
            let r1 = (c + line.across).floor().min(minor_len as f64 - 1.0);
            let mut r = r0;
            while r <= r1 {
                let (x, y) = if transposed {
                    (r as usize >> bits, col >> bits)
                } else {
                    (col >> bits, r as usize >> bits)
                };
                if open[y * w + x] && !cells.contains(&(col >> bits)) {
                    cells.push(col >> bits);
                }
                r += 1.0;
            }
        }
        cells
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig { cases: 256, ..Default::default() })]

        #[test]
        fn a_line_finds_every_open_cell_its_pixels_reach(
            (w, h) in (1usize..90, 1usize..90),
            bits in proptest::sample::select(vec![3usize, 6]),
            seed in proptest::collection::vec(proptest::bool::weighted(0.1), 90 * 90),
            transposed in proptest::bool::ANY,
            ends in (0.0..1.0f64, 0.0..1.0f64),
            (a0, b0, slope, across) in (-50.0..800.0f64, -50.0..800.0f64, -1.0..1.0f64, 0.0..6.0f64),
        ) {
            let open = &seed[..w * h];
            let mut grid = Open::default();
            grid.index(w, w * h, |i| open[i]);
            let major_len = if transposed { h << bits } else { w << bits };
            let minor_len = if transposed { w << bits } else { h << bits };
            let (p, q) = ((ends.0 * major_len as f64) as usize, (ends.1 * major_len as f64) as usize);
            let (first, last) = (p.min(q), p.max(q).min(major_len - 1));
            let inv = if slope != 0.0 { 1.0 / slope } else { 0.0 };
            let line = Line { a0, b0, slope, inv, across };
            let base = (first >> bits) >> 6;
            let mut reach = vec![0; ((last >> bits) >> 6) - base + 1];
            grid.along(transposed, bits, (first, last), &line, minor_len, &mut reach, base);
            let mut found = Vec::new();
            each_set(&reach, base, |cell| found.push(cell));
            for cell in reached(open, (w, h, bits), transposed, (first, last), &line) {
                proptest::prop_assert!(found.contains(&cell), "cell {} not found: {:?}", cell, found);
            }
        }
    }

    proptest::proptest! {
        #[test]
        fn a_box_has_an_open_cell_when_one_of_its_cells_is(
            (w, h) in (1usize..150, 1usize..150),
            seed in proptest::collection::vec(proptest::bool::weighted(0.02), 150 * 150),
            corners in (0.0..1.0f64, 0.0..1.0f64, 0.0..1.0f64, 0.0..1.0f64),
        ) {
            let open = &seed[..w * h];
            let mut grid = Open::default();
            grid.index(w, w * h, |i| open[i]);
            let at = |f: f64, n: usize| ((f * n as f64) as usize).min(n - 1);
            let (a, b) = (at(corners.0, w), at(corners.1, w));
            let (c, d) = (at(corners.2, h), at(corners.3, h));
            let (xs, ys) = ((a.min(b), a.max(b)), (c.min(d), c.max(d)));
            let any = (ys.0..=ys.1).any(|y| (xs.0..=xs.1).any(|x| open[y * w + x]));
            proptest::prop_assert_eq!(grid.any_in(xs, ys), any);
        }
    }

    #[test]
    fn a_closed_cell_is_no_longer_found() {
        let mut grid = Open::default();
        grid.index(100, 100 * 3, |_| true);
        grid.close(70, 1);
        let line = Line {
            a0: 0.0,
            b0: 12.0,
            slope: 0.0,
            inv: 0.0,
            across: 1.0,
        };
        let mut reach = vec![0; 2];
        grid.along(false, 3, (0, 799), &line, 24, &mut reach, 0);
        let mut found = Vec::new();
        each_set(&reach, 0, |cell| found.push(cell));
        assert_eq!(found, (0..100).filter(|&c| c != 70).collect::<Vec<_>>());
    }
}
