//! Canvas backend (wasm only): draws through an OffscreenCanvas 2D context
//! that the page transferred to its worker, so the path's vertices stay in
//! wasm memory and only drawing calls cross into the browser.

use js_sys::Array;
use wasm_bindgen::{Clamped, JsValue};
use web_sys::{ImageData, OffscreenCanvas, OffscreenCanvasRenderingContext2d};

use super::display::{Damage, LayerChange, Op};
use super::style::{Align, FONT_FAMILY, Font, Stroke};
use super::{Kept, Pen, Rect, Surface, Transform};

/// A 2D context seen as a [`Surface`] in CSS pixels; the caller sets the
/// device-pixel transform.
///
/// The calls of a frame are kept ([`Op`]) and made on the canvas by
/// [`CanvasSurface::present`], only inside the box where they differ from
/// the last frame's ([`Kept::damage`]).
pub struct CanvasSurface<'a> {
    ctx: &'a OffscreenCanvasRenderingContext2d,
    font: String,
    /// What the frames on this canvas keep for the next one.
    kept: &'a mut Kept,
    layer: Option<Layer<'a>>,
    reused: bool,
    moved: bool,
    ops: Vec<Op>,
    /// How the layer's pixels differ from the last frame's.
    layer_change: LayerChange,
    /// Something of this frame could not be drawn (its layer's image).
    failed: bool,
}

/// The pixel layer of a canvas: what carries the raster's pixels onto the
/// canvas (an `ImageData` is put on `scratch`, which is then drawn:
/// `putImageData` straight onto the canvas would replace the grid under
/// the paths instead of drawing over it), the canvas's size in device
/// pixels and CSS to device scale, and the key of the drawing.
pub struct Layer<'a> {
    /// A canvas per pixel buffer of the raster ([`crate::render::Raster::buffer`]),
    /// as large as its drawn part (grown as needed); [`Kept`] knows what
    /// each holds.
    pub scratch: [&'a OffscreenCanvas; 2],
    /// Device pixels of the canvas.
    pub size: (u32, u32),
    /// Device pixels per CSS pixel.
    pub scale: (f64, f64),
    /// What this drawing shows besides the view's zoom and pan (the run,
    /// plane, current block, colours, size): the layer on the canvas is
    /// shown again only for the same key ([`Surface::reuse_layer`]).
    pub key: u64,
}

impl<'a> CanvasSurface<'a> {
    /// Wraps a context; with a `layer`, large paths are drawn as pixels.
    /// `kept`: what the frames on this canvas keep for the next one, kept
    /// by the caller from one frame to the next.
    pub fn new(
        ctx: &'a OffscreenCanvasRenderingContext2d,
        kept: &'a mut Kept,
        layer: Option<Layer<'a>>,
    ) -> CanvasSurface<'a> {
        ctx.set_line_cap("round");
        ctx.set_line_join("round");
        CanvasSurface {
            ctx,
            font: String::new(),
            kept,
            layer,
            reused: false,
            moved: false,
            ops: Vec::new(),
            layer_change: LayerChange::Whole,
            failed: false,
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
            kept,
            layer,
            ops,
            layer_change,
            failed,
            ..
        } = self;
        let damage = kept.damage(&ops, layer_change, size);
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
        if !failed {
            kept.keep_frame(ops);
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
                    // The tool list's circle is dashed (behaviour 13.16).
                    let dash: Array = stroke.dash.iter().map(|d| JsValue::from_f64(*d)).collect();
                    ctx.set_line_dash(&dash)?;
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
    /// last drawing in that buffer and the canvas holds those
    /// ([`Kept::layer_to_put`]) — and adds the call that draws it on the
    /// canvas.
    fn put_layer(&mut self, transform: &Transform) -> Result<(), JsValue> {
        let Some(layer) = &self.layer else {
            return Ok(());
        };
        let Some(put) = self.kept.layer_to_put() else {
            // Nothing drawn: the frame has no layer (a change of its own).
            self.layer_change = LayerChange::Whole;
            return Ok(());
        };
        let scratch_canvas = layer.scratch[put.buffer];
        let (w, h) = (put.drawn.2 as u32, put.drawn.3 as u32);
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
        if put.put.2 > 0 && put.put.3 > 0 {
            let (pw, ph) = (put.put.2 as u32, put.put.3 as u32);
            let bytes = self.kept.image_of(put.put);
            let image = ImageData::new_with_u8_clamped_array_and_sh(Clamped(bytes), pw, ph)?;
            scratch.put_image_data(&image, put.at.0, put.at.1)?;
        }
        let (op, change) = self.kept.layer_put(&put, transform, layer.key, layer.scale);
        self.layer_change = change;
        self.ops.push(op);
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
        // device pixels per CSS pixel) — not smoothed: smoothing was much of
        // Chromium's time for the frame after an edit (`make bench-browser`,
        // target 4c, guards it). A layer moved and scaled during a gesture is.
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
    fn kept(&mut self) -> Option<&mut Kept> {
        let layer = self.layer.as_ref()?;
        let ((w, h), scale) = (layer.size, layer.scale);
        self.kept
            .begin(w as usize, h as usize, scale)
            .then_some(&mut *self.kept)
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
        let Some((op, moved)) = self
            .kept
            .layer_again(transform, exact, layer.key, layer.scale)
        else {
            return false;
        };
        self.ops.push(op);
        // The same pixels at the same place, or moved: anywhere.
        self.layer_change = if moved {
            LayerChange::Whole
        } else {
            LayerChange::Within(Rect::new(0.0, 0.0, 0.0, 0.0))
        };
        self.reused = true;
        self.moved = moved;
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
