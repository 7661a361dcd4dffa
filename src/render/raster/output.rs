//! What a finished drawing hands on: whether it was made on the last
//! one's pixels, the box that changed, and its pixels as straight RGBA for
//! the canvas (`ImageData`) and for tests.

use super::Raster;

impl Raster {
    /// Makes the next drawing from nothing, not on this one's pixels.
    pub fn forget(&mut self) {
        self.last.forget();
        self.before_last.forget();
    }

    /// Whether this drawing was made on the last one's pixels (or on those
    /// of the drawing before it), drawing again only the tiles where the two
    /// differ ([`super::keep`]).
    pub fn kept(&mut self) -> bool {
        self.finish();
        self.kept
    }

    /// When this drawing was made on the pixels of the last one drawn in
    /// the same buffer ([`Raster::buffer`]), the box (x, y, width, height,
    /// as [`Raster::dirty`]) outside which they are the same; None when it
    /// was made from nothing.
    pub fn changed(&mut self) -> Option<(usize, usize, usize, usize)> {
        self.finish();
        if !self.kept {
            return None;
        }
        let (x0, y0, x1, y1) = self.open;
        // Within the drawn box (the margins of what changed may reach past it).
        let Some((dx0, dy0, dx1, dy1)) = self.dirty else {
            return Some((0, 0, 0, 0));
        };
        let (x0, y0) = (x0.max(dx0), y0.max(dy0));
        let (x1, y1) = (x1.min(dx1), y1.min(dy1));
        Some(if x0 < x1 && y0 < y1 {
            (x0, y0, x1 - x0, y1 - y0)
        } else {
            (0, 0, 0, 0)
        })
    }

    /// Which of the raster's two pixel buffers this drawing is in (0 or 1):
    /// a drawing is made on the last one's pixels, on those of the one
    /// before it in the other buffer ([`super::keep::BeforeLast`]), or from nothing in
    /// either. A copy of the pixels kept per buffer (the page's scratch
    /// canvases) takes only [`Raster::changed`]'s box from the next drawing
    /// made in its buffer.
    pub fn buffer(&mut self) -> usize {
        self.finish();
        self.buffer
    }

    /// The box of the pixels drawn (x, y, width, height in pixels of the
    /// drawing: [`Raster::factor`] device pixels each), or None when
    /// nothing was drawn.
    pub fn dirty(&mut self) -> Option<(usize, usize, usize, usize)> {
        self.finish();
        self.dirty
            .map(|(x0, y0, x1, y1)| (x0, y0, x1 - x0, y1 - y0))
    }

    /// The pixel at (x, y) as straight (not premultiplied) RGBA.
    pub fn pixel(&mut self, x: usize, y: usize) -> [u8; 4] {
        self.finish();
        if x >= self.width || y >= self.height {
            return [0; 4];
        }
        straight(&self.px[self.index(x, y)].rgba)
    }

    /// The drawn box's pixels as straight RGBA rows (what `ImageData`
    /// takes), written into `out`; returns the box, or None when nothing
    /// was drawn.
    pub fn image(&mut self, out: &mut Vec<u8>) -> Option<(usize, usize, usize, usize)> {
        let drawn = self.dirty()?;
        self.image_of(drawn, out);
        Some(drawn)
    }

    /// The pixels of the box (x, y, width, height) as straight RGBA rows,
    /// written into `out`.
    pub fn image_of(&mut self, (x, y, w, h): (usize, usize, usize, usize), out: &mut Vec<u8>) {
        self.finish();
        let (w, h) = (
            w.min(self.width.saturating_sub(x)),
            h.min(self.height.saturating_sub(y)),
        );
        out.clear();
        out.reserve(4 * w * h);
        for row in y..y + h {
            for col in x..x + w {
                out.extend_from_slice(&straight(&self.px[self.index(col, row)].rgba));
            }
        }
    }
}

/// Straight RGBA from a premultiplied pixel.
fn straight(px: &[u8]) -> [u8; 4] {
    let a = px[3];
    match a {
        0 => return [0; 4],
        // What the division below gives, without three divisions for
        // each of the (most) pixels that are opaque.
        255 => return [px[0], px[1], px[2], a],
        _ => {}
    }
    let un = |c: u8| ((u32::from(c) * 255 + u32::from(a) / 2) / u32::from(a)).min(255) as u8;
    [un(px[0]), un(px[1]), un(px[2]), a]
}
