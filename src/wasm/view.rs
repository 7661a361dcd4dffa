//! The drawing half of [`Session`]: the canvas it draws on, the frames
//! (whole, or moved during a gesture), the SVG export, and the view state
//! the page changes — plane, zoom, pan, current block, picking.

use std::hash::{DefaultHasher, Hash, Hasher};

use serde::Serialize;
use wasm_bindgen::prelude::*;
use web_sys::{OffscreenCanvas, OffscreenCanvasRenderingContext2d};

use super::{Session, to_js};
use crate::render::canvas::{CanvasSurface, Layer};
use crate::render::scene;
use crate::render::{self, Plane, Theme};

/// What `view()` returns and `set_view()` reads: the document's `view`
/// (plane, zoom, pan) plus the current block.
#[derive(Serialize, serde::Deserialize)]
struct ViewOut {
    plane: Option<String>,
    zoom: Option<f64>,
    pan: Option<[f64; 2]>,
    #[serde(default)]
    step: Option<i64>,
}

#[wasm_bindgen]
impl Session {
    /// Keeps an OffscreenCanvas (transferred from the page) to draw on.
    pub fn attach_canvas(&mut self, canvas: OffscreenCanvas) -> Result<(), JsValue> {
        let ctx = canvas
            .get_context("2d")?
            .ok_or_else(|| JsValue::from_str("the canvas has no 2d context"))?
            .dyn_into::<OffscreenCanvasRenderingContext2d>()?;
        self.canvas = Some((canvas, ctx));
        self.last_whole = None;
        self.shown = None;
        Ok(())
    }

    /// Draws the current run as the view state says (plane, zoom, pan,
    /// current block, colours) on `width` x `height` CSS pixels at `dpr`
    /// device pixels per CSS pixel (sharp on high-DPI screens). Does nothing
    /// without an attached canvas.
    pub fn render(&mut self, width: u32, height: u32, dpr: f64) -> Result<(), JsValue> {
        self.draw(width, height, dpr, false)
    }

    /// [`Session::render`] for a frame of a pan or zoom gesture: a large
    /// path is the last drawing's pixels moved and scaled (without the
    /// offset arrows), when the last drawing showed the same run, plane,
    /// current block and colours at this size. The page draws a whole frame
    /// with `render` once the gesture pauses. Returns true when it did so.
    pub fn render_moving(&mut self, width: u32, height: u32, dpr: f64) -> Result<bool, JsValue> {
        let before = self.moving_frames;
        self.draw(width, height, dpr, true)?;
        Ok(self.moving_frames != before)
    }
}

impl Session {
    fn draw(&mut self, width: u32, height: u32, dpr: f64, moving: bool) -> Result<(), JsValue> {
        let dpr = if dpr.is_finite() && dpr > 0.0 {
            dpr.min(8.0)
        } else {
            1.0
        };
        let (w, h) = (width.clamp(1, 8192), height.clamp(1, 8192));
        self.size = (f64::from(w), f64::from(h));
        let Some((canvas, ctx)) = &self.canvas else {
            return Ok(());
        };
        let whole = (self.drawing, self.scene, (w, h), dpr.to_bits());
        if self.last_whole == Some(whole) && self.frame.is_some() {
            return Ok(());
        }
        let device = |css: u32| ((f64::from(css) * dpr).round() as u32).clamp(1, 16384);
        // Resizing the canvas (even to its size) clears it and resets the
        // context's state: only when the size changed (the transform is set
        // below, and the drawing starts by filling the background).
        if canvas.width() != device(w) || canvas.height() != device(h) {
            canvas.set_width(device(w));
            canvas.set_height(device(h));
            self.shown = None;
        }
        let sx = f64::from(device(w)) / f64::from(w);
        let sy = f64::from(device(h)) / f64::from(h);
        ctx.set_transform(sx, 0.0, 0.0, sy, 0.0, 0.0)?;
        if self.scratch.is_none() {
            self.scratch = Some([OffscreenCanvas::new(1, 1)?, OffscreenCanvas::new(1, 1)?]);
        }
        // Everything a kept layer depends on but the zoom and pan.
        let key = {
            let mut hash = DefaultHasher::new();
            (self.drawing, self.scene.plane.name(), self.scene.step).hash(&mut hash);
            (self.scene.theme.name, w, h, dpr.to_bits()).hash(&mut hash);
            hash.finish()
        };
        let layer = self.scratch.as_ref().map(|[a, b]| Layer {
            raster: &mut self.raster,
            scratch: [a, b],
            held: &mut self.held,
            bytes: &mut self.raster_bytes,
            size: (device(w), device(h)),
            scale: (sx, sy),
            shot: &mut self.shot,
            key,
        });
        let mut surface = CanvasSurface::new(ctx, layer, &mut self.shown);
        let draw = if moving {
            render::draw_scene_moving
        } else {
            render::draw_scene
        };
        let frame = draw(
            &mut surface,
            &self.toolpath,
            &self.scene,
            f64::from(w),
            f64::from(h),
        );
        let moved = moving && surface.reused();
        surface.present((f64::from(w), f64::from(h)), (sx, sy))?;
        if moved {
            self.moving_frames += 1;
        }
        self.last_whole = (!moved).then_some(whole);
        self.frame = Some(frame);
        Ok(())
    }
}

#[wasm_bindgen]
impl Session {
    /// The same drawing as an SVG document (same view state).
    pub fn render_svg(&self, width: u32, height: u32) -> String {
        render::svg::render_scene(
            &self.toolpath,
            &self.scene,
            f64::from(width),
            f64::from(height),
        )
    }

    /// `"light"` or `"dark"`: the canvas colours (match the page's
    /// `prefers-color-scheme`).
    pub fn set_theme(&mut self, name: &str) {
        self.scene.theme = Theme::named(name);
    }

    /// The view state: `{ plane: "XY"|"XZ"|"YZ"|"ZX", zoom, pan: [u, v],
    /// step }` — zoom 1 fits the whole path, pan is the view centre's offset
    /// from the fitted centre in program units (the share document's
    /// `view`), step the current block or null.
    pub fn view(&self) -> Result<JsValue, JsValue> {
        to_js(&ViewOut {
            plane: Some(self.scene.plane.name().to_owned()),
            zoom: Some(self.scene.zoom),
            pan: Some(self.scene.pan),
            step: self.scene.step.map(i64::from),
        })
    }

    /// Sets any of `plane`, `zoom`, `pan` and `step` from an object shaped
    /// like `view()`'s (absent keys stay; `step: -1` clears the current
    /// block). Values are limited to the document's ranges; a plane the
    /// machine does not have is ignored. Returns the view state.
    pub fn set_view(&mut self, view: JsValue) -> Result<JsValue, JsValue> {
        let v: ViewOut = serde_wasm_bindgen::from_value(view)
            .map_err(|e| JsValue::from_str(&format!("view: {e}")))?;
        if let Some(plane) = v.plane {
            self.set_plane(&plane);
        }
        if let Some(zoom) = v.zoom {
            self.scene.set_zoom(zoom);
        }
        if let Some(pan) = v.pan {
            self.scene.set_pan(pan);
        }
        if let Some(step) = v.step {
            self.set_step(i32::try_from(step).unwrap_or(i32::MAX));
        }
        self.view()
    }

    /// Chooses the plane drawn (`XY`, `XZ`, `YZ` on the mill; the lathe has
    /// `ZX` only). Returns false, changing nothing, for another name.
    pub fn set_plane(&mut self, name: &str) -> bool {
        match Plane::parse(name) {
            Some(plane)
                if plane.has_centre_line() == (self.run.machine == crate::MachineKind::Lathe) =>
            {
                self.scene.plane = plane;
                true
            }
            _ => false,
        }
    }

    /// Zooms by `factor` about the CSS pixel (x, y) of the last drawing.
    pub fn zoom_at(&mut self, x: f64, y: f64, factor: f64) {
        let (w, h) = self.size;
        self.scene.zoom_at(&self.toolpath, w, h, x, y, factor);
    }

    /// Moves the drawing by (dx, dy) CSS pixels.
    pub fn pan_by(&mut self, dx: f64, dy: f64) {
        let (w, h) = self.size;
        self.scene.pan_by(&self.toolpath, w, h, dx, dy);
    }

    /// Zoom 1, no pan: the whole path.
    pub fn fit(&mut self) {
        self.scene.fit();
    }

    /// Makes block `index` the current one (the path is drawn up to it, the
    /// tool marker sits at its end); a negative index clears it, an index
    /// past the last block means the last. Returns the current block or -1.
    pub fn set_step(&mut self, index: i32) -> i32 {
        let count = self.run.block_count as usize;
        self.scene.step = match usize::try_from(index) {
            Ok(_) if count == 0 => None,
            Ok(i) => u32::try_from(i.min(count - 1)).ok(),
            Err(_) => None,
        };
        self.follows_end = count > 0 && self.scene.step == u32::try_from(count - 1).ok();
        self.update_marker();
        self.step()
    }

    /// The current block, or -1.
    pub fn step(&self) -> i32 {
        self.scene
            .step
            .and_then(|s| i32::try_from(s).ok())
            .unwrap_or(-1)
    }

    /// The block whose move passes nearest to CSS pixel (x, y) of the last
    /// drawing, on either path, within `tolerance` pixels; or -1.
    pub fn pick(&self, x: f64, y: f64, tolerance: f64) -> i32 {
        let Some(frame) = &self.frame else {
            return -1;
        };
        scene::pick(&self.toolpath, frame, x, y, tolerance.clamp(0.0, 100.0))
            .and_then(|b| i32::try_from(b).ok())
            .unwrap_or(-1)
    }

    /// The last executed block at or before 1-based `line` (the block a
    /// cursor on that line belongs to, or the one before a comment line),
    /// or -1 when no block runs before it.
    pub fn block_at_line(&self, line: u32) -> i32 {
        self.checkpoints
            .block_at_line(line)
            .and_then(|b| i32::try_from(b).ok())
            .unwrap_or(-1)
    }
}
