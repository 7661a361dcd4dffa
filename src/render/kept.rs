//! What a frame keeps for the next one, all of it in one place: [`Kept`].
//!
//! Why: the page draws a frame after every keystroke, and most of a frame
//! is the one before it. Five things of a frame are kept so that the next
//! one makes again only what changed; each is reused at its own step of a
//! frame and forgotten by its own rule, and this module says which.
//!
//! What is kept, from the paths up to the canvas:
//!
//! - **The two drawings** of the pixel layer ([`Raster`]): the last drawing
//!   and the one before it ([`Drawing`]), each its pixels (one of the
//!   raster's two pixel buffers) and its recording (the sub-paths it drew).
//!   The raster keeps these itself: a new drawing whose recording is mostly
//!   one of theirs is made on that one's pixels, drawing again only where
//!   the two differ (`raster::keep`). A recording is kept when it is small
//!   enough to compare (drawings of up to `raster::keep::MOST_KEPT` points,
//!   not drawn in parts); both are forgotten for another surface size, or
//!   when told ([`Kept::forget`]).
//! - **The tracing of each drawing** (`resume::Traced`): the toolpath and
//!   view traced, and where the tracer stood every few moves while it
//!   recorded the paths. The next drawing of the same view resumes from it,
//!   tracing only around the moves an edit changed and copying the rest of
//!   the recording from the raster. It is kept here under the number of the
//!   recording it made (the raster numbers its recordings and knows nothing
//!   of tracing), taken up only while the raster keeps that recording and
//!   lets the new drawing take pieces of it (same surface, same scale), and
//!   forgotten after the drawing that finds that recording gone.
//! - **What each scratch canvas holds** (on the page a scratch canvas per
//!   pixel buffer carries the layer's pixels onto the canvas): the box of
//!   its buffer's drawing it holds, so that a drawing made on that
//!   drawing's pixels is put there only where it changed
//!   ([`Kept::layer_to_put`]). Forgotten for a buffer from when its next
//!   drawing is begun to be put until it is on the scratch canvas.
//! - **The layer on the canvas** ([`ShownLayer`]): which scratch canvas the
//!   canvas shows, where, drawn with which transform and for which key
//!   (everything the drawing depends on but the zoom and the pan). A frame of
//!   the same key and transform shows it again instead of drawing the paths
//!   (a run that changed nothing drawn); a frame of a pan or zoom gesture
//!   shows it moved and scaled ([`Kept::layer_again`]). Forgotten while a new
//!   layer is being put, and for a frame with nothing on its layer.
//! - **The frame on the canvas**: the drawing calls ([`Op`]) of the frame
//!   the canvas shows, so that the next frame is painted only inside the
//!   box where its calls differ ([`Kept::damage`]). Forgotten while a frame
//!   is being painted (until it is wholly on the canvas), for a new or
//!   resized canvas ([`Kept::forget_canvas`]), and not kept for a frame of
//!   many points (a vector drawing zoomed into).
//!
//! Each is used only where it is known to be what it stands for, so that a
//! frame made from them has the pixels of a frame made from nothing: the
//! raster's tests, the resume tests and the canvas tests of `tests/wasm/`
//! compare the two.
//!
//! The layers are one-way: the raster draws and records pixels; the tracer
//! (`resume`) reads the raster's recordings and is handed its tracings
//! here; the canvas backend asks here what to put where. None of them uses
//! this module.

use super::display::{self, Damage, LayerChange, Op};
use super::paths::{draw_paths, draw_paths_in_parts};
use super::raster::{Drawing, Raster};
use super::resume::{Traced, record_paths};
use super::{Frame, IN_PARTS_FROM_MOVES, Rect, Scene, Transform};
use crate::toolpath::Toolpath;

/// Frames whose calls hold more points than this are not kept for the
/// next frame (which is then painted whole): the calls of a vector drawing
/// (a small program) may hold many points (arcs zoomed into); compared with
/// the next frame's they would save little — its frames are quick — and
/// hold memory.
const KEPT_POINTS: usize = 1 << 16;

/// A box of pixels: x, y, width, height.
type PixelBox = (usize, usize, usize, usize);

/// Everything a frame keeps for the next one (see the module's comment):
/// the pixel layer's two drawings and their tracings, what each scratch
/// canvas holds, the layer on the canvas and the calls of the frame on it.
pub struct Kept {
    /// The pixel layer, which keeps the last drawing and the one before it.
    raster: Raster,
    /// The tracings of the kept drawings, each with the number of the
    /// recording it made.
    tracings: [Option<Tracing>; 2],
    /// Per pixel buffer of the raster, the box of its drawing that its
    /// scratch canvas holds.
    on_scratch: [Option<PixelBox>; 2],
    /// The layer on the canvas.
    layer: Option<ShownLayer>,
    /// The calls of the frame on the canvas.
    frame: Option<Vec<Op>>,
    /// Straight RGBA handed to the canvas (kept for its memory).
    bytes: Vec<u8>,
}

/// What was traced to make one of the raster's recordings.
struct Tracing {
    recording: u64,
    traced: Box<Traced>,
}

/// The layer the canvas shows: the scratch canvas it is on, the key of
/// the drawing, its size on the scratch canvas, where it went on the
/// canvas (device pixels) and the transform it was drawn with.
#[derive(Clone, Copy, Debug)]
pub struct ShownLayer {
    scratch: usize,
    key: u64,
    source: (f64, f64),
    rect: (f64, f64, f64, f64),
    transform: Transform,
}

/// The drawing just made on the pixel layer, to be put on the scratch
/// canvas of its pixel buffer ([`Kept::layer_to_put`]), then on the canvas
/// ([`Kept::layer_put`]).
#[derive(Clone, Copy, Debug)]
pub struct LayerPut {
    /// Its pixel buffer, which is also the scratch canvas it goes on (0 or 1).
    pub buffer: usize,
    /// The box of its pixels drawn (pixels of the drawing): the scratch
    /// canvas holds it from its corner.
    pub drawn: PixelBox,
    /// The pixels to put on the scratch canvas: the drawn box, or only
    /// where the drawing changed when the scratch canvas holds the drawing
    /// it was made on (empty: nothing).
    pub put: PixelBox,
    /// Where they go on the scratch canvas.
    pub at: (f64, f64),
    /// The box where the drawing changed, when only that is put.
    changed: Option<PixelBox>,
    /// The scratch canvas the canvas showed.
    shown: Option<usize>,
}

impl Default for Kept {
    fn default() -> Self {
        Kept::new()
    }
}

impl Kept {
    /// Nothing kept yet.
    pub fn new() -> Kept {
        Kept {
            raster: Raster::new(),
            tracings: [None, None],
            on_scratch: [None; 2],
            layer: None,
            frame: None,
            bytes: Vec::new(),
        }
    }

    /// The pixel layer, with the drawing made last (to read its pixels).
    pub fn raster(&mut self) -> &mut Raster {
        &mut self.raster
    }

    /// Begins a drawing on the pixel layer ([`Raster::begin`]): false, and
    /// nothing to draw, for an empty or too large surface.
    pub fn begin(&mut self, width: usize, height: usize, scale: (f64, f64)) -> bool {
        self.raster.begin(width, height, scale)
    }

    /// Makes the next drawing from nothing: not on the pixels of a kept
    /// one, nor from its tracing (the raster forgets their recordings, and
    /// the next drawing, finding them gone, forgets their tracings).
    pub fn forget(&mut self) {
        self.raster.forget();
    }

    /// The canvas is new or was resized (which clears it): what it shows
    /// is not known.
    pub fn forget_canvas(&mut self) {
        self.frame = None;
    }

    /// Draws the paths of a scene on the pixel layer (a drawing begun with
    /// [`Kept::begin`]) and finishes the drawing: in parts, front to back,
    /// when it is too large to be kept ([`IN_PARTS_FROM_MOVES`]); else
    /// resumed from a kept drawing's tracing where it can be. Returns how
    /// many moves were traced (each path counts its moves).
    pub(crate) fn draw_paths(
        &mut self,
        f: &Frame,
        tp: &Toolpath,
        scene: &Scene,
        split: usize,
    ) -> usize {
        let (traced, moves_traced) = if f.stride > 1 {
            // A turned 3D view's sample (behaviour 10.8): in one go, not kept.
            draw_paths(&mut self.raster, f, tp, scene, split);
            (None, tp.len().div_ceil(f.stride))
        } else if tp.len() >= IN_PARTS_FROM_MOVES {
            let moves = draw_paths_in_parts(&mut self.raster, f, tp, scene, split);
            (None, moves)
        } else {
            let numbers = [Drawing::Last, Drawing::BeforeLast].map(|d| self.raster.resumable(d));
            let tracings = &self.tracings;
            let of = |number: Option<u64>| {
                let number = number?;
                let tracing = tracings.iter().flatten().find(|t| t.recording == number)?;
                Some(&*tracing.traced)
            };
            let recording = record_paths(&mut self.raster, numbers.map(of), f, tp, scene, split);
            (recording.traced, recording.moves_traced)
        };
        self.raster.finish();
        self.keep_tracing(traced);
        moves_traced
    }

    /// After a drawing: keeps `traced` with its recording when the raster
    /// keeps that, and the tracing of the drawing before it while the
    /// raster keeps that one's; forgets any other.
    fn keep_tracing(&mut self, traced: Option<Box<Traced>>) {
        let before = self.raster.recording_number(Drawing::BeforeLast);
        let [a, b] = std::mem::take(&mut self.tracings);
        let kept_before = [a, b]
            .into_iter()
            .flatten()
            .find(|t| Some(t.recording) == before);
        let last = self.raster.recording_number(Drawing::Last);
        let made = last
            .zip(traced)
            .map(|(recording, traced)| Tracing { recording, traced });
        self.tracings = [made, kept_before];
    }

    /// The drawing just made, to put on its scratch canvas, or None when it
    /// drew nothing. Until [`Kept::layer_put`] says it is there, neither
    /// that scratch canvas nor the canvas is known to show anything.
    pub fn layer_to_put(&mut self) -> Option<LayerPut> {
        let shown = self.layer.take().map(|s| s.scratch);
        let k = self.raster.buffer();
        let previous = self.on_scratch[k].take();
        let drawn = self.raster.dirty()?;
        // A drawing made on the pixels of the last one in its buffer
        // ([`Raster::changed`]) is put where it changed on that buffer's
        // scratch canvas, which holds the last one's (the same box): a few
        // tiles instead of the whole drawing. Typing back and forth across
        // a refitted view alternates the buffers (`raster::keep::BeforeLast`).
        let changed = match (previous, self.raster.changed()) {
            (Some(p), Some(c)) if p == drawn => Some(c),
            _ => None,
        };
        let (put, at) = match changed {
            // (An empty box, nothing changed, may lie anywhere: nothing is put.)
            Some(c) => (
                c,
                (
                    c.0.saturating_sub(drawn.0) as f64,
                    c.1.saturating_sub(drawn.1) as f64,
                ),
            ),
            None => (drawn, (0.0, 0.0)),
        };
        Some(LayerPut {
            buffer: k,
            drawn,
            put,
            at,
            changed,
            shown,
        })
    }

    /// The pixels of a box of the drawing made last as straight RGBA rows
    /// (what `ImageData` takes).
    pub fn image_of(&mut self, pixels: PixelBox) -> &[u8] {
        self.raster.image_of(pixels, &mut self.bytes);
        &self.bytes
    }

    /// The drawing of `put` is on its scratch canvas: the call that puts
    /// it on the canvas (drawn with `transform`, for the drawing's `key`,
    /// at `scale` device pixels per CSS pixel), and how the canvas's layer
    /// changes with it. It is the layer on the canvas from now on.
    pub fn layer_put(
        &mut self,
        put: &LayerPut,
        transform: &Transform,
        key: u64,
        (sx, sy): (f64, f64),
    ) -> (Op, LayerChange) {
        // A drawing on the coarse grid is scaled up to device pixels.
        let f = self.raster.factor() as f64;
        let k = put.buffer;
        self.on_scratch[k] = Some(put.drawn);
        let change = match put.changed {
            // Its box in CSS pixels (the canvas shows the same buffer's).
            Some(c) if put.shown == Some(k) => LayerChange::Within(Rect::new(
                c.0 as f64 * f / sx,
                c.1 as f64 * f / sy,
                c.2 as f64 * f / sx,
                c.3 as f64 * f / sy,
            )),
            _ => LayerChange::Whole,
        };
        let (x, y, w, h) = put.drawn;
        let [x, y, w, h] = [x, y, w, h].map(|v| f64::from(v as u32));
        let rect = (x * f, y * f, w * f, h * f);
        self.layer = Some(ShownLayer {
            scratch: k,
            key,
            source: (w, h),
            rect,
            transform: *transform,
        });
        let op = Op::Layer {
            source: (w, h),
            dest: rect,
            smooth: false,
            scratch: k,
            transform: *transform,
        };
        (op, change)
    }

    /// The layer on the canvas shown again for a drawing of `key` with
    /// `transform` (at `scale` device pixels per CSS pixel): moved and
    /// scaled from its own transform, or with `exact` only when it is the
    /// same (the same pixels as drawing it again). The call that puts it
    /// there, and whether it moved; None when it does not show this.
    pub fn layer_again(
        &self,
        transform: &Transform,
        exact: bool,
        key: u64,
        (sx, sy): (f64, f64),
    ) -> Option<(Op, bool)> {
        let shown = self.layer?;
        if shown.key != key || (exact && shown.transform != *transform) {
            return None;
        }
        // A world point at screen s under the shown layer's transform is at
        // k·s + (o − k·o_shown) under the new one (CSS pixels; the layer's
        // rectangle is in device pixels).
        let was = shown.transform;
        let k = transform.scale / was.scale;
        let (x, y, w, h) = shown.rect;
        let dest = (
            k * x + sx * (transform.origin_x - k * was.origin_x),
            k * y + sy * (transform.origin_y - k * was.origin_y),
            k * w,
            k * h,
        );
        let sane = k.is_finite()
            && k > 0.0
            && [dest.0, dest.1, dest.2, dest.3]
                .iter()
                .all(|v| v.is_finite() && v.abs() < 1e9);
        if !sane {
            return None;
        }
        let same = shown.transform == *transform;
        let op = Op::Layer {
            source: shown.source,
            dest,
            smooth: !same,
            scratch: shown.scratch,
            transform: *transform,
        };
        Some((op, !same))
    }

    /// Where a frame's calls (`ops`, of a surface of `size` CSS pixels,
    /// its layer changed as `layer` says) differ from those of the frame on
    /// the canvas ([`display::damage`]). Until the frame is wholly on the
    /// canvas ([`Kept::keep_frame`]), what the canvas shows is not known.
    pub fn damage(&mut self, ops: &[Op], layer: LayerChange, size: (f64, f64)) -> Damage {
        let damage = display::damage(self.frame.as_deref(), ops, layer, size);
        self.frame = None;
        damage
    }

    /// The calls of the frame now wholly on the canvas, kept for the next
    /// frame unless they hold many points ([`KEPT_POINTS`]).
    pub fn keep_frame(&mut self, ops: Vec<Op>) {
        if display::points(&ops) <= KEPT_POINTS {
            self.frame = Some(ops);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::paths::draw_paths;
    use crate::render::test_support::{assert_same_pixels, drawn_from_nothing, toolpath};

    const SURFACE: (usize, usize, f64) = (240, 180, 2.0);

    /// `n` feed moves between scattered points, the one of `bent` (if any)
    /// to another place.
    fn scattered(n: usize, bent: Option<usize>) -> Toolpath {
        let mut program = String::from("G90 G00 X0. Y0.\nG01 F300.\n");
        for k in 0..n {
            let (x, y) = ((k * 37 % 101) as f64, (k * 53 % 71) as f64);
            let y = if Some(k) == bent { y + 9.5 } else { y };
            program.push_str(&format!("X{x:.3} Y{y:.3}\n"));
        }
        toolpath(&program)
    }

    /// Draws `tp` with `kept` as the page does; asserts that it recorded
    /// and painted what a drawing from nothing does. How many moves were
    /// traced.
    fn draws_as_from_nothing(kept: &mut Kept, f: &Frame, tp: &Toolpath, scene: &Scene) -> usize {
        let (w, h, scale) = SURFACE;
        assert!(kept.begin(w, h, (scale, scale)));
        let traced = kept.draw_paths(f, tp, scene, scene.drawn_moves(tp));
        let mut fresh = drawn_from_nothing(f, tp, scene, SURFACE);
        let r = kept.raster();
        assert_eq!(r.kept_recording(), fresh.kept_recording());
        assert_same_pixels(r, &mut fresh, "kept against from nothing");
        traced
    }

    #[test]
    fn a_tracing_is_taken_up_only_with_the_recording_it_made() {
        let scene = Scene::default();
        let first = scattered(400, None);
        let f = scene.frame(&first, 120.0, 90.0);
        let mut kept = Kept::new();
        let all = draws_as_from_nothing(&mut kept, &f, &first, &scene);
        // A drawing of another toolpath made on the raster itself, not
        // through what it is kept with: on the first's pixels, its
        // recording in the first's place. The first's tracing is not its.
        let bent = scattered(400, Some(200));
        let (w, h, scale) = SURFACE;
        let r = kept.raster();
        assert!(r.begin(w, h, (scale, scale)));
        draw_paths(r, &f, &bent, &scene, scene.drawn_moves(&bent));
        assert!(r.kept(), "made on the first drawing's pixels");
        // The first again: traced whole, as from nothing.
        assert_eq!(draws_as_from_nothing(&mut kept, &f, &first, &scene), all);
        // Through `Kept`, an edit is resumed from the last tracing.
        let traced = draws_as_from_nothing(&mut kept, &f, &bent, &scene);
        assert!(traced < all / 2, "{traced} of {all}");
    }

    #[test]
    fn the_layer_on_the_canvas_is_shown_again_for_its_key_and_moved_with_the_view() {
        let scene = Scene::default();
        let tp = scattered(300, None);
        let f = scene.frame(&tp, 120.0, 90.0);
        let (w, h, scale) = SURFACE;
        let mut kept = Kept::new();
        assert!(kept.begin(w, h, (scale, scale)));
        kept.draw_paths(&f, &tp, &scene, scene.drawn_moves(&tp));
        // Nothing on the scratch canvas yet: all that was drawn is put.
        let put = kept.layer_to_put().expect("something drawn");
        assert_eq!((put.put, put.at), (put.drawn, (0.0, 0.0)));
        assert_eq!(kept.image_of(put.put).len(), 4 * put.drawn.2 * put.drawn.3);
        let t = f.transform;
        let (op, change) = kept.layer_put(&put, &t, 7, (scale, scale));
        assert_eq!(change, LayerChange::Whole);
        let Op::Layer { dest, .. } = op else {
            panic!("{op:?}");
        };
        // The same key and view: the same call; another key: none.
        assert_eq!(
            kept.layer_again(&t, true, 7, (scale, scale)),
            Some((op.clone(), false))
        );
        assert_eq!(kept.layer_again(&t, true, 8, (scale, scale)), None);
        // Zoomed in twice about the origin: moved and scaled, but only
        // when not asked for the same pixels.
        let zoomed = Transform {
            scale: 2.0 * t.scale,
            ..t
        };
        assert_eq!(kept.layer_again(&zoomed, true, 7, (scale, scale)), None);
        let (moved, true) = kept
            .layer_again(&zoomed, false, 7, (scale, scale))
            .expect("moved")
        else {
            panic!("not moved");
        };
        let Op::Layer {
            dest: to, smooth, ..
        } = moved
        else {
            panic!("{moved:?}");
        };
        assert!(smooth);
        assert_eq!((to.2, to.3), (2.0 * dest.2, 2.0 * dest.3));
        // The same drawing again is made on its pixels: nothing to put,
        // and the canvas's layer changes nowhere.
        assert!(kept.begin(w, h, (scale, scale)));
        kept.draw_paths(&f, &tp, &scene, scene.drawn_moves(&tp));
        let again = kept.layer_to_put().expect("something drawn");
        assert_eq!(again.buffer, put.buffer);
        assert_eq!((again.put.2, again.put.3), (0, 0));
        let (_, change) = kept.layer_put(&again, &t, 7, (scale, scale));
        assert!(matches!(change, LayerChange::Within(r) if r.w == 0.0 && r.h == 0.0));
    }
}
