//! Canvas backend (wasm only): draws through an OffscreenCanvas 2D context
//! that the page transferred to its worker, so the path's vertices stay in
//! wasm memory and only drawing calls cross into the browser.

use js_sys::Array;
use wasm_bindgen::{Clamped, JsValue};
use web_sys::{ImageData, OffscreenCanvas, OffscreenCanvasRenderingContext2d};

use super::display::{self, Damage, LayerChange, Op};
use super::style::{Align, FONT_FAMILY, Font, Stroke};
use super::{Pen, Raster, Rect, Surface, Transform};

/// Frames whose calls hold more points than this are not kept for the
/// next frame (which is then painted whole).
const KEPT_POINTS: usize = 1 << 16;

/// A 2D context seen as a [`Surface`] in CSS pixels; the caller sets the
/// device-pixel transform.
///
/// The calls of a frame are kept ([`Op`]) and made on the canvas by
/// [`CanvasSurface::present`], only inside the box where they differ from
/// the last frame's ([`display::damage`]).
pub struct CanvasSurface<'a> {
    ctx: &'a OffscreenCanvasRenderingContext2d,
    font: String,
    layer: Option<Layer<'a>>,
    reused: bool,
    moved: bool,
    ops: Vec<Op>,
    /// How the layer's pixels differ from the last frame's.
    layer_change: LayerChange,
    /// Something of this frame could not be drawn (its layer's image).
    failed: bool,
    /// The calls of the frame the canvas shows: None when its pixels are
    /// not known to be theirs (a new or resized canvas).
    shown: &'a mut Option<Vec<Op>>,
}

/// The pixel layer of a canvas: the raster, the canvas's size in device
/// pixels and CSS to device scale, and what carries the raster's pixels
/// onto the canvas (an `ImageData` is put on `scratch`, which is then
/// drawn: `putImageData` straight onto the canvas would replace the grid
/// under the paths instead of drawing over it).
pub struct Layer<'a> {
    /// The pixels.
    pub raster: &'a mut Raster,
    /// A canvas per pixel buffer of the raster ([`Raster::buffer`]), as
    /// large as its drawn part (grown as needed).
    pub scratch: [&'a OffscreenCanvas; 2],
    /// The box of its buffer's pixels each of them holds, if any.
    pub held: &'a mut [Option<(usize, usize, usize, usize)>; 2],
    /// Straight RGBA handed to `ImageData` (kept to reuse its memory).
    pub bytes: &'a mut Vec<u8>,
    /// Device pixels of the canvas.
    pub size: (u32, u32),
    /// Device pixels per CSS pixel.
    pub scale: (f64, f64),
    /// What the last layer put on the canvas was (its `scratch` still
    /// holds it), for [`Surface::reuse_layer`].
    pub shot: &'a mut Option<Shot>,
    /// What this drawing shows besides the view's zoom and pan (the run,
    /// plane, current block, colours, size): a kept layer is reused only
    /// for the same key.
    pub key: u64,
}

/// The layer last put on the canvas: its key, where it went (device
/// pixels) and the transform it was drawn with.
#[derive(Clone, Copy, Debug)]
pub struct Shot {
    /// Which scratch canvas holds it.
    scratch: usize,
    key: u64,
    /// Its size on `scratch`.
    source: (f64, f64),
    /// Where it went on the canvas.
    rect: (f64, f64, f64, f64),
    transform: Transform,
}

impl<'a> CanvasSurface<'a> {
    /// Wraps a context; with a `layer`, large paths are drawn as pixels.
    /// `shown`: the calls of the frame on the canvas, kept by the caller
    /// from one frame to the next (None for a new or resized canvas).
    pub fn new(
        ctx: &'a OffscreenCanvasRenderingContext2d,
        layer: Option<Layer<'a>>,
        shown: &'a mut Option<Vec<Op>>,
    ) -> CanvasSurface<'a> {
        ctx.set_line_cap("round");
        ctx.set_line_join("round");
        CanvasSurface {
            ctx,
            font: String::new(),
            layer,
            reused: false,
            moved: false,
            ops: Vec::new(),
            layer_change: LayerChange::Whole,
            failed: false,
            shown,
        }
    }

    /// Makes the frame's calls on the canvas (`size` CSS pixels at `scale`
    /// device pixels per CSS pixel, the context's transform): all of them,
    /// clipped to the box where they differ from the last frame's when
    /// there is one — the pixels outside it are already those.
    pub fn present(self, size: (f64, f64), scale: (f64, f64)) -> Result<(), JsValue> {
        let CanvasSurface {
            ctx,
            mut font,
            layer,
            ops,
            layer_change,
            failed,
            shown,
            ..
        } = self;
        let damage = display::damage(shown.as_deref(), &ops, layer_change, size);
        // Until this frame is wholly on the canvas, what it shows is not known.
        *shown = None;
        let scratch = layer.as_ref().map(|l| l.scratch);
        let mut draw_all = || {
            ops.iter()
                .try_for_each(|op| Self::draw(ctx, &mut font, scratch, op))
        };
        match damage {
            Damage::None => {}
            Damage::Whole => draw_all()?,
            Damage::Box(r) => {
                // In whole device pixels: inside the clip nothing blends
                // with what was there.
                let (sx, sy) = scale;
                let (x0, y0) = ((r.x * sx).floor(), (r.y * sy).floor());
                let (x1, y1) = ((r.right() * sx).ceil(), (r.bottom() * sy).ceil());
                ctx.save();
                let drawn = ctx
                    .set_transform(1.0, 0.0, 0.0, 1.0, 0.0, 0.0)
                    .and_then(|()| {
                        ctx.begin_path();
                        ctx.rect(x0, y0, x1 - x0, y1 - y0);
                        ctx.clip();
                        ctx.set_transform(sx, 0.0, 0.0, sy, 0.0, 0.0)
                    })
                    .and_then(|()| draw_all());
                ctx.restore();
                drawn?;
            }
        }
        // The calls of a vector drawing (a small program) may hold many
        // points (arcs zoomed into); compared with the next frame's they
        // would save little — its frames are quick — and hold memory.
        if !failed && display::points(&ops) <= KEPT_POINTS {
            *shown = Some(ops);
        }
        Ok(())
    }

    /// Makes one call on the canvas.
    fn draw(
        ctx: &OffscreenCanvasRenderingContext2d,
        font: &mut String,
        scratch: Option<[&OffscreenCanvas; 2]>,
        op: &Op,
    ) -> Result<(), JsValue> {
        match op {
            Op::Clear {
                width,
                height,
                color,
            } => {
                ctx.set_fill_style_str(color);
                ctx.fill_rect(0.0, 0.0, *width, *height);
            }
            Op::Rect { rect, fill, border } => {
                ctx.set_fill_style_str(fill);
                ctx.fill_rect(rect.x, rect.y, rect.w, rect.h);
                if let Some(border) = border {
                    ctx.set_stroke_style_str(border);
                    ctx.set_line_width(1.0);
                    ctx.set_line_dash(&Array::new())?;
                    ctx.stroke_rect(rect.x + 0.5, rect.y + 0.5, rect.w - 1.0, rect.h - 1.0);
                }
            }
            Op::Text {
                text,
                x,
                y,
                font: f,
            } => {
                let css = format!(
                    "{}{}px {}",
                    if f.bold { "bold " } else { "" },
                    f.size,
                    FONT_FAMILY
                );
                if css != *font {
                    ctx.set_font(&css);
                    *font = css;
                }
                ctx.set_text_align(match f.align {
                    Align::Start => "start",
                    Align::Middle => "center",
                    Align::End => "end",
                });
                ctx.set_fill_style_str(f.color);
                // fillText only throws for non-finite coordinates; a label is skipped then.
                let _ = ctx.fill_text(text, *x, *y);
            }
            Op::Polygon { points, fill } => {
                let Some(((x0, y0), rest)) = points.split_first() else {
                    return Ok(());
                };
                ctx.begin_path();
                ctx.move_to(*x0, *y0);
                for (x, y) in rest {
                    ctx.line_to(*x, *y);
                }
                ctx.close_path();
                ctx.set_fill_style_str(fill);
                ctx.fill();
            }
            Op::Circle {
                x,
                y,
                r,
                fill,
                stroke,
            } => {
                ctx.begin_path();
                // arc only throws for a negative radius.
                if ctx
                    .arc(*x, *y, r.max(0.0), 0.0, std::f64::consts::TAU)
                    .is_err()
                {
                    return Ok(());
                }
                if let Some(fill) = fill {
                    ctx.set_fill_style_str(fill);
                    ctx.fill();
                }
                if let Some(stroke) = stroke {
                    ctx.set_stroke_style_str(stroke.color);
                    ctx.set_line_width(stroke.width);
                    ctx.set_line_dash(&Array::new())?;
                    ctx.stroke();
                }
            }
            Op::Path { stroke, points } => {
                ctx.set_stroke_style_str(stroke.color);
                ctx.set_line_width(stroke.width);
                let dash: Array = stroke.dash.iter().map(|d| JsValue::from_f64(*d)).collect();
                // Only fails for negative or non-finite lengths, which the styles never use.
                let _ = ctx.set_line_dash(&dash);
                ctx.begin_path();
                for &(x, y, starts) in points {
                    if starts {
                        ctx.move_to(x, y);
                    } else {
                        ctx.line_to(x, y);
                    }
                }
                ctx.stroke();
            }
            Op::Layer {
                source,
                dest,
                smooth,
                scratch: k,
                ..
            } => {
                if let Some(scratch) = scratch {
                    Self::draw_scratch(ctx, scratch[*k], *source, *dest, !smooth)?;
                }
            }
        }
        Ok(())
    }

    /// Whether the paths of this drawing were a kept layer moved or scaled
    /// ([`Surface::reuse_layer`]).
    pub fn moved(&self) -> bool {
        self.moved
    }

    /// Whether the paths of this drawing were a kept layer, moved or not.
    pub fn reused(&self) -> bool {
        self.reused
    }

    /// Puts the layer's pixels on the scratch canvas of their buffer —
    /// where they changed, when the layer was drawn on the pixels of the
    /// last drawing in that buffer and the canvas holds those — and adds
    /// the call that draws it on the canvas.
    fn put_layer(&mut self, transform: &Transform) -> Result<(), JsValue> {
        let Some(layer) = &mut self.layer else {
            return Ok(());
        };
        let shown = layer.shot.take().map(|s| s.scratch);
        let k = layer.raster.buffer();
        let previous = layer.held[k].take();
        let Some(drawn) = layer.raster.dirty() else {
            // Nothing drawn: the frame has no layer (a change of its own).
            self.layer_change = LayerChange::Whole;
            return Ok(());
        };
        // A drawing made on the pixels of the last one in its buffer
        // ([`Raster::changed`]) is put where it changed on that buffer's
        // canvas, which holds the last one's (the same box): a few tiles
        // instead of the whole drawing. Typing back and forth across a
        // refitted view alternates the buffers (`raster::keep::Older`).
        let changed = match (previous, layer.raster.changed()) {
            (Some(p), Some(c)) if p == drawn => Some(c),
            _ => None,
        };
        let scratch_canvas = layer.scratch[k];
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
        let (x, y, w, h) = (
            drawn.0 as u32,
            drawn.1 as u32,
            drawn.2 as u32,
            drawn.3 as u32,
        );
        if scratch_canvas.width() < w {
            scratch_canvas.set_width(w);
        }
        if scratch_canvas.height() < h {
            scratch_canvas.set_height(h);
        }
        let scratch = scratch_canvas
            .get_context("2d")?
            .and_then(|c| {
                wasm_bindgen::JsCast::dyn_into::<OffscreenCanvasRenderingContext2d>(c).ok()
            })
            .ok_or_else(|| JsValue::from_str("no 2d context for the scratch canvas"))?;
        if put.2 > 0 && put.3 > 0 {
            layer.raster.image_of(put, layer.bytes);
            let (pw, ph) = (put.2 as u32, put.3 as u32);
            let image =
                ImageData::new_with_u8_clamped_array_and_sh(Clamped(&layer.bytes[..]), pw, ph)?;
            scratch.put_image_data(&image, at.0, at.1)?;
        }
        // A drawing on the coarse grid is scaled up to device pixels.
        let f = layer.raster.factor() as f64;
        let (sx, sy) = layer.scale;
        layer.held[k] = Some(drawn);
        self.layer_change = match changed {
            // Its box in CSS pixels (the canvas shows the same buffer's).
            Some(c) if shown == Some(k) => LayerChange::Within(Rect::new(
                c.0 as f64 * f / sx,
                c.1 as f64 * f / sy,
                c.2 as f64 * f / sx,
                c.3 as f64 * f / sy,
            )),
            _ => LayerChange::Whole,
        };
        let (x, y, w, h) = (f64::from(x), f64::from(y), f64::from(w), f64::from(h));
        let rect = (x * f, y * f, w * f, h * f);
        self.ops.push(Op::Layer {
            source: (w, h),
            dest: rect,
            smooth: false,
            scratch: k,
            transform: *transform,
        });
        *layer.shot = Some(Shot {
            scratch: k,
            key: layer.key,
            source: (w, h),
            rect,
            transform: *transform,
        });
        Ok(())
    }

    /// Draws `scratch`'s first `w` × `h` pixels at (dx, dy) scaled to
    /// (dw, dh), all in device pixels.
    fn draw_scratch(
        ctx: &OffscreenCanvasRenderingContext2d,
        scratch: &OffscreenCanvas,
        (w, h): (f64, f64),
        dest: (f64, f64, f64, f64),
        exact: bool,
    ) -> Result<(), JsValue> {
        let (dx, dy, dw, dh) = dest;
        ctx.save();
        ctx.set_transform(1.0, 0.0, 0.0, 1.0, 0.0, 0.0)?;
        // A drawing on the coarse grid is put at exactly twice its size:
        // each of its pixels is 2 × 2 device pixels (one CSS pixel at 2
        // device pixels per CSS pixel) — not smoothed, which was a third of
        // Chromium's time for the frame after an edit (bench-browser, 4c:
        // 6.6 → 4.6 ms). A layer moved and scaled during a gesture is.
        ctx.set_image_smoothing_enabled(!exact);
        let drawn = ctx.draw_image_with_offscreen_canvas_and_sw_and_sh_and_dx_and_dy_and_dw_and_dh(
            scratch, 0.0, 0.0, w, h, dx, dy, dw, dh,
        );
        ctx.restore();
        drawn
    }
}

impl Pen for CanvasSurface<'_> {
    fn begin_path(&mut self, stroke: &Stroke) {
        self.ops.push(Op::Path {
            stroke: *stroke,
            points: Vec::new(),
        });
    }

    fn move_to(&mut self, x: f64, y: f64) {
        if let Some(Op::Path { points, .. }) = self.ops.last_mut() {
            points.push((x, y, true));
        }
    }

    fn line_to(&mut self, x: f64, y: f64) {
        if let Some(Op::Path { points, .. }) = self.ops.last_mut() {
            points.push((x, y, false));
        }
    }

    fn stroke(&mut self) {}
}

impl Surface for CanvasSurface<'_> {
    fn raster(&mut self) -> Option<&mut Raster> {
        let layer = self.layer.as_mut()?;
        let (w, h) = layer.size;
        let raster = &mut *layer.raster;
        raster
            .begin(w as usize, h as usize, layer.scale)
            .then_some(raster)
    }

    fn composite(&mut self, transform: &Transform) {
        // Only fails when the browser runs out of memory for the image; the
        // paths are then missing from this frame, and the next one is drawn
        // whole.
        if self.put_layer(transform).is_err() {
            self.failed = true;
            self.layer_change = LayerChange::Whole;
        }
    }

    fn reuse_layer(&mut self, transform: &Transform, exact: bool) -> bool {
        let Some(layer) = &self.layer else {
            return false;
        };
        let Some(shot) = *layer.shot else {
            return false;
        };
        if shot.key != layer.key || (exact && shot.transform != *transform) {
            return false;
        }
        // A world point at screen s under the shot's transform is at
        // k·s + (o − k·o_shot) under the new one (CSS pixels; the layer's
        // rectangle is in device pixels).
        let was = shot.transform;
        let k = transform.scale / was.scale;
        let (sx, sy) = layer.scale;
        let (x, y, w, h) = shot.rect;
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
            return false;
        }
        let same = shot.transform == *transform;
        self.ops.push(Op::Layer {
            source: shot.source,
            dest,
            smooth: !same,
            scratch: shot.scratch,
            transform: *transform,
        });
        // The same pixels at the same place, or moved: anywhere.
        self.layer_change = if same {
            LayerChange::Within(Rect::new(0.0, 0.0, 0.0, 0.0))
        } else {
            LayerChange::Whole
        };
        self.reused = true;
        self.moved = !same;
        true
    }

    fn clear(&mut self, width: f64, height: f64, color: &str) {
        self.ops.push(Op::Clear {
            width,
            height,
            color: color.to_owned(),
        });
    }

    fn fill_rect(&mut self, rect: Rect, fill: &str, border: Option<&str>) {
        self.ops.push(Op::Rect {
            rect,
            fill: fill.to_owned(),
            border: border.map(str::to_owned),
        });
    }

    fn fill_text(&mut self, text: &str, x: f64, y: f64, font: &Font) {
        self.ops.push(Op::Text {
            text: text.to_owned(),
            x,
            y,
            font: *font,
        });
    }

    fn fill_polygon(&mut self, points: &[(f64, f64)], fill: &str) {
        self.ops.push(Op::Polygon {
            points: points.to_vec(),
            fill: fill.to_owned(),
        });
    }

    fn circle(&mut self, x: f64, y: f64, r: f64, fill: Option<&str>, stroke: Option<&Stroke>) {
        self.ops.push(Op::Circle {
            x,
            y,
            r,
            fill: fill.map(str::to_owned),
            stroke: stroke.copied(),
        });
    }
}
