//! The drawing half of [`Session`]: the canvas, its frames (whole, or moved
//! in a gesture) and the view state, each decided by the native session.

use wasm_bindgen::prelude::*;
use web_sys::{OffscreenCanvas, OffscreenCanvasRenderingContext2d};

use super::{Drawn, Session, thrown, to_js};
use crate::render::{self, canvas::CanvasSurface, canvas::Layer};
use crate::session::view::{FrameAsk, ViewChange};

/// A canvas call's failure, thrown as the exports' `Error`.
fn failed(e: JsValue) -> JsError {
    thrown(e.as_string().unwrap_or_else(|| format!("{e:?}")))
}

impl Drawn {
    /// The surface a frame is drawn on: the canvas's context and the pixel
    /// layer, made of what is kept between frames.
    fn surface<'a>(
        &'a mut self,
        ctx: &'a OffscreenCanvasRenderingContext2d,
        ask: &FrameAsk,
    ) -> Result<CanvasSurface<'a>, JsError> {
        if self.scratch.is_none() {
            let scratch = || OffscreenCanvas::new(1, 1).map_err(failed);
            self.scratch = Some([scratch()?, scratch()?]);
        }
        let layer = self.scratch.as_ref().map(|[a, b]| Layer {
            scratch: [a, b],
            size: ask.device,
            scale: ask.scale,
            key: ask.key,
        });
        Ok(CanvasSurface::new(ctx, &mut self.kept, layer))
    }
}

impl Session {
    fn draw(&mut self, width: u32, height: u32, dpr: f64, moving: bool) -> Result<bool, JsError> {
        let ask = match moving {
            true => self.session.ask_moving_frame(width, height, dpr),
            false => self.session.ask_frame(width, height, dpr),
        };
        let Some((canvas, ctx)) = &self.canvas else {
            return Ok(false);
        };
        if self.session.frame_shown(&ask) {
            return Ok(false);
        }
        // Resizing the canvas (even to its size) clears it and resets the
        // context's state: only when the size changed (the transform is set
        // below, and the drawing starts by filling the background).
        if (canvas.width(), canvas.height()) != ask.device {
            canvas.set_width(ask.device.0);
            canvas.set_height(ask.device.1);
            self.drawn.kept.forget_canvas();
        }
        let (sx, sy) = ask.scale;
        ctx.set_transform(sx, 0.0, 0.0, sy, 0.0, 0.0)
            .map_err(failed)?;
        let mut surface = self.drawn.surface(ctx, &ask)?;
        let draw = match moving {
            true => render::draw_scene_moving,
            false => render::draw_scene,
        };
        let (w, h) = (f64::from(ask.css.0), f64::from(ask.css.1));
        let (toolpath, scene) = (self.session.toolpath(), self.session.scene());
        let frame = draw(&mut surface, toolpath, scene, w, h);
        // A turned 3D view's sample is no whole frame either.
        let moved = moving && (surface.reused() || frame.stride > 1);
        surface.present((w, h), ask.scale).map_err(failed)?;
        self.session.frame_drawn(&ask, frame, moved);
        Ok(moved)
    }
}

#[wasm_bindgen]
impl Session {
    /// Keeps an OffscreenCanvas (transferred from the page) to draw on; the
    /// next frame is painted whole (a canvas whose context was restored is blank).
    pub fn attach_canvas(&mut self, canvas: OffscreenCanvas) -> Result<(), JsError> {
        let no_context = || thrown("the canvas has no 2d context");
        let ctx = canvas
            .get_context("2d")
            .map_err(failed)?
            .ok_or_else(no_context)?;
        let ctx = ctx.dyn_into().map_err(|_| no_context())?;
        self.canvas = Some((canvas, ctx));
        self.session.forget_frame();
        self.drawn.kept.forget_canvas();
        Ok(())
    }

    /// Draws the view on `width` x `height` CSS pixels at `dpr` device pixels
    /// per CSS pixel; not without a canvas, or when it shows that frame.
    pub fn render(&mut self, width: u32, height: u32, dpr: f64) -> Result<(), JsError> {
        self.draw(width, height, dpr, false).map(|_| ())
    }

    /// [`Session::render`] for a frame of a pan or zoom gesture: a large
    /// path is the last whole frame's pixels moved and scaled (without the
    /// arrows) when it showed the same drawing at this size; true when so.
    pub fn render_moving(&mut self, width: u32, height: u32, dpr: f64) -> Result<bool, JsError> {
        self.draw(width, height, dpr, true)
    }

    /// The same drawing as an SVG document (same view state).
    pub fn render_svg(&self, width: u32, height: u32) -> String {
        self.session.render_svg(width, height)
    }

    /// `"light"` or `"dark"` colours (the page's `prefers-color-scheme`).
    pub fn set_theme(&mut self, name: &str) {
        self.session.set_theme(name);
    }

    /// The view state: `{ plane: "XY"|"XZ"|"YZ"|"3D"|"ZX"|"XC", angles:
    /// [yaw, pitch] (3D only), zoom, pan: [u, v],
    /// step }` ([`ViewChange`]; step null without a current block).
    pub fn view(&self) -> Result<JsValue, JsError> {
        to_js(&self.session.view())
    }

    /// Sets any of `plane`, `zoom`, `pan` and `step` from an object shaped
    /// like `view()`'s ([`ViewChange`]); returns the view state. Throws
    /// ("view: …") for an object of another shape.
    pub fn set_view(&mut self, view: JsValue) -> Result<JsValue, JsError> {
        let change: ViewChange =
            serde_wasm_bindgen::from_value(view).map_err(|e| thrown(format!("view: {e}")))?;
        to_js(&self.session.set_view(&change))
    }

    /// Chooses the plane drawn; false, changing nothing, for another name.
    pub fn set_plane(&mut self, name: &str) -> bool {
        self.session.set_plane(name)
    }

    /// Zooms by `factor` about the CSS pixel (x, y) of the last drawing.
    pub fn zoom_at(&mut self, x: f64, y: f64, factor: f64) {
        self.session.zoom_at(x, y, factor);
    }

    /// Moves the drawing by (dx, dy) CSS pixels.
    pub fn pan_by(&mut self, dx: f64, dy: f64) {
        self.session.pan_by(dx, dy);
    }

    /// Turns the mill's view by a drag of (dx, dy) CSS pixels into the 3D
    /// view (behaviour 10.8); false on the lathe.
    pub fn orbit_by(&mut self, dx: f64, dy: f64) -> bool {
        self.session.orbit_by(dx, dy)
    }

    /// Zoom 1, no pan: the whole path.
    pub fn fit(&mut self) {
        self.session.fit();
    }

    /// Makes block `index` (clamped; negative: none) current; returns it or -1.
    pub fn set_step(&mut self, index: i32) -> i32 {
        self.session.set_step(index)
    }

    /// The current block, or -1.
    pub fn step(&self) -> i32 {
        self.session.step()
    }

    /// The block drawn nearest to CSS pixel (x, y), within `tolerance`; or -1.
    pub fn pick(&self, x: f64, y: f64, tolerance: f64) -> i32 {
        self.session.pick(x, y, tolerance)
    }

    /// The last executed block at or before 1-based `line`, or -1.
    pub fn block_at_line(&self, line: u32) -> i32 {
        self.session.block_at_line(line)
    }
}
