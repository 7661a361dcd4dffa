//! The largest box of finished tiles found so far in a drawing, so that a
//! segment within it is found hidden with four comparisons, and a segment
//! crossing it is swept only where it runs outside it.
//!
//! Why: a dense drawing (the 1M-block frame) soon fills an area: from then
//! on nearly every segment drawn below lies in finished tiles, and finding
//! that out tile by tile ([`Raster::hidden`]) cost each of millions of
//! segments — and a segment whose box reaches an open tile (the ragged edge
//! of the filled area) was swept along its whole length, for segments that
//! covered almost no pixel (the instruction count of `examples/render_time`
//! on the 1M-block program guards both). Finished tiles stay
//! finished while a drawing is made, so a box found once stays true; it is
//! looked for again each time another sixty-fourth of the tiles has
//! finished.

use super::{FULL_TILE, Raster, TILE_BITS};

/// The box, and when to look for a larger one.
#[derive(Default)]
pub(super) struct Filled {
    /// Pixel coordinates of its first and last pixels (x0, y0, x1, y1,
    /// inclusive), None while no tile is finished.
    pub px: Option<[f64; 4]>,
    /// The tiles finished when it is next looked for.
    next: usize,
    /// Per tile column, how many finished tiles end at the row being
    /// scanned; and the stack of the scan (kept for their memory).
    heights: Vec<u32>,
    stack: Vec<(usize, u32)>,
    /// Never look for one (for the tests: the pixels are the same).
    pub off: bool,
}

impl Filled {
    /// Forgets the box: the tiles were made afresh.
    pub fn reset(&mut self) {
        self.px = None;
        self.next = 0;
    }
}

impl Raster {
    /// Looks for a larger box when enough tiles have finished since the
    /// last look ([`Raster::finished_tiles`]).
    #[inline]
    pub(super) fn update_filled(&mut self) {
        if self.finished_tiles >= self.filled.next && !self.filled.off {
            self.find_filled();
        }
    }

    /// The largest box (by area) of finished tiles: row by row, the
    /// largest rectangle under the histogram of finished tiles ending at
    /// that row (one pass with a stack, linear in the tiles).
    #[cold]
    fn find_filled(&mut self) {
        let w = self.tiles_w;
        let h = self.tiles.len().checked_div(w).unwrap_or(0);
        let step = (self.tiles.len() / 64).max(16);
        self.filled.next = self.finished_tiles + step;
        let mut heights = std::mem::take(&mut self.filled.heights);
        let mut stack = std::mem::take(&mut self.filled.stack);
        heights.clear();
        heights.resize(w, 0);
        // (area, x0, y0, x1, y1), tiles, inclusive.
        let mut best = (0u64, 0, 0, 0, 0);
        for y in 0..h {
            let row = &self.tiles[y * w..][..w];
            for (height, &tile) in heights.iter_mut().zip(row) {
                *height = if tile == FULL_TILE { *height + 1 } else { 0 };
            }
            stack.clear();
            // A bar of height 0 past the end empties the stack.
            for x in 0..=w {
                let height = heights.get(x).copied().unwrap_or(0);
                let mut start = x;
                while let Some(&(at, top)) = stack.last() {
                    if top < height {
                        break;
                    }
                    stack.pop();
                    let area = u64::from(top) * (x - at) as u64;
                    if area > best.0 {
                        best = (area, at, y + 1 - top as usize, x - 1, y);
                    }
                    start = at;
                }
                if height > 0 {
                    stack.push((start, height));
                }
            }
        }
        self.filled.heights = heights;
        self.filled.stack = stack;
        let (area, x0, y0, x1, y1) = best;
        let side = 1 << TILE_BITS;
        self.filled.px = (area > 0).then(|| {
            [
                (x0 * side) as f64,
                (y0 * side) as f64,
                (x1 * side + side - 1) as f64,
                (y1 * side + side - 1) as f64,
            ]
        });
    }

    /// Whether the pixels from (x0, y0) to (x1, y1) (the floors of these,
    /// inclusive) lie in the box of finished tiles.
    #[inline]
    pub(super) fn in_filled(&self, x0: f64, y0: f64, x1: f64, y1: f64) -> bool {
        self.filled.px.is_some_and(|[fx0, fy0, fx1, fy1]| {
            x0 >= fx0 && y0 >= fy0 && x1 < fx1 + 1.0 && y1 < fy1 + 1.0
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A raster whose tiles are finished where `grid` (rows of `#` and `.`)
    /// has `#`.
    fn raster(grid: &[&str]) -> Raster {
        let mut r = Raster::new();
        let (w, h) = (grid[0].len(), grid.len());
        r.tiles_w = w;
        r.tiles = grid
            .iter()
            .flat_map(|row| row.bytes().map(|c| if c == b'#' { FULL_TILE } else { 0 }))
            .collect();
        r.finished_tiles = r.tiles.iter().filter(|&&t| t == FULL_TILE).count();
        assert_eq!(r.tiles.len(), w * h);
        r
    }

    #[test]
    fn the_largest_box_of_finished_tiles_is_found() {
        let mut r = raster(&[
            "##......", //
            "..#####.", //
            ".######.", //
            "..#####.", //
            "...##...", //
        ]);
        r.find_filled();
        // Columns 2-6 of rows 1-3 (15 tiles), in pixels.
        assert_eq!(r.filled.px, Some([16.0, 8.0, 55.0, 31.0]));
        assert!(r.in_filled(16.0, 8.0, 55.9, 31.9));
        assert!(!r.in_filled(15.9, 8.0, 40.0, 20.0));
        assert!(!r.in_filled(16.0, 8.0, 56.0, 20.0));
    }

    #[test]
    fn no_finished_tile_no_box() {
        let mut r = raster(&["....", "...."]);
        r.find_filled();
        assert_eq!(r.filled.px, None);
        assert!(!r.in_filled(0.0, 0.0, 0.0, 0.0));
    }

    #[test]
    fn a_single_row_or_column_is_a_box() {
        let mut r = raster(&["....", "####", "...."]);
        r.find_filled();
        assert_eq!(r.filled.px, Some([0.0, 8.0, 31.0, 15.0]));
        let mut r = raster(&[".#..", ".#..", ".#..", "...."]);
        r.find_filled();
        assert_eq!(r.filled.px, Some([8.0, 0.0, 15.0, 23.0]));
    }
}
