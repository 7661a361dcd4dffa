//! The JavaScript face of the crate (wasm only), and its only door to the
//! browser besides the canvas backend. Thin: each export converts its input,
//! calls the core and converts the output. Nothing here panics on input — a
//! panic would kill the page's worker — and a bad setup comes back as
//! diagnostics, never as an exception.
//!
//! Small structured values (summary, diagnostics, one block) go through one
//! serde-wasm-bindgen serializer; the toolpath goes as one copy of each flat
//! buffer in a typed array, never one JS object per move.

use js_sys::{Float64Array, JSON, Object, Reflect, Uint8Array, Uint32Array};
use serde::Serialize;
use serde_wasm_bindgen::Serializer;
use wasm_bindgen::prelude::*;
use web_sys::{OffscreenCanvas, OffscreenCanvasRenderingContext2d};

use crate::diag::Diagnostic;
use crate::render::{self, canvas::CanvasSurface};
use crate::report::{End, Run};
use crate::setup::Setup;
use crate::toolpath::Toolpath;
use crate::view::{Summary, block_view, summary};

/// The one serializer: absent values are `null` (not `undefined`) and maps
/// are plain objects, so JS code can rely on `value === null` and `obj.key`.
const SERIALIZER: Serializer = Serializer::new()
    .serialize_missing_as_null(true)
    .serialize_maps_as_objects(true);

fn to_js<T: Serialize + ?Sized>(value: &T) -> Result<JsValue, JsValue> {
    value.serialize(&SERIALIZER).map_err(JsValue::from)
}

/// What `run` returns.
#[derive(Serialize)]
struct RunResult<'a> {
    summary: Summary,
    diagnostics: &'a [Diagnostic],
}

/// A program, its setup, the run and its toolpath, kept in wasm memory
/// between calls; JS holds only this handle.
#[wasm_bindgen]
pub struct Session {
    text: String,
    setup: Setup,
    run: Run,
    toolpath: Toolpath,
    canvas: Option<(OffscreenCanvas, OffscreenCanvasRenderingContext2d)>,
}

impl Default for Session {
    fn default() -> Self {
        let setup = Setup::default();
        let run = crate::run("", &setup);
        let toolpath = Toolpath::from_run(&run);
        Session {
            text: String::new(),
            setup,
            run,
            toolpath,
            canvas: None,
        }
    }
}

/// Reads the setup argument: null/undefined is the default setup; a string
/// is a setup document (JSON text); any other value is an object of the same
/// shape. Problems come back as `setup-…` diagnostics.
fn read_setup(value: &JsValue) -> Result<Setup, Vec<Diagnostic>> {
    if value.is_null() || value.is_undefined() {
        return Ok(Setup::default());
    }
    let text = match value.as_string() {
        Some(text) => text,
        None => match JSON::stringify(value).ok().and_then(|s| s.as_string()) {
            Some(text) => text,
            None => {
                return Err(vec![Diagnostic::error(
                    "setup-syntax",
                    Default::default(),
                    "setup document: not a JSON object",
                )]);
            }
        },
    };
    Setup::from_json(&text).map_err(|e| e.diagnostics)
}

#[wasm_bindgen]
impl Session {
    /// An empty session (no program, default setup).
    #[wasm_bindgen(constructor)]
    pub fn new() -> Session {
        Session::default()
    }

    /// Runs `program` with `setup` and keeps the result. Returns
    /// `{ summary, diagnostics }`; a bad setup gives `setup-…` diagnostics
    /// (line 0) and an empty path, never an exception.
    pub fn run(&mut self, program: &str, setup: JsValue) -> Result<JsValue, JsValue> {
        self.text = program.to_owned();
        match read_setup(&setup) {
            Ok(setup) => {
                self.run = crate::run(&self.text, &setup);
                self.setup = setup;
            }
            Err(diagnostics) => {
                self.setup = Setup::default();
                let mut run = crate::run("", &self.setup);
                run.diagnostics = diagnostics;
                run.end = End::Error { line: 0 };
                self.run = run;
            }
        }
        self.toolpath = Toolpath::from_run(&self.run);
        to_js(&RunResult {
            summary: summary(&self.run),
            diagnostics: &self.run.diagnostics,
        })
    }

    /// The setup of the last run as a setup document (the default setup
    /// after a bad one).
    pub fn setup(&self) -> Result<JsValue, JsValue> {
        to_js(&self.setup)
    }

    /// Number of executed blocks with a report.
    pub fn block_count(&self) -> u32 {
        u32::try_from(self.run.blocks.len()).unwrap_or(u32::MAX)
    }

    /// The report of block `index` (as the CLI's JSON `blocks` entries), or
    /// `null` when out of range.
    pub fn block(&self, index: u32) -> Result<JsValue, JsValue> {
        match self.run.blocks.get(index as usize) {
            Some(b) => to_js(&block_view(b, &self.text)),
            None => Ok(JsValue::NULL),
        }
    }

    /// The toolpath as typed arrays, each a fresh copy owned by JS:
    /// `{ units, machine, actual: Float64Array, programmed: Float64Array,
    /// starts: Uint32Array, kinds: Uint8Array, blocks: Uint32Array,
    /// lines: Uint32Array }` (see `src/toolpath.rs` for their meaning).
    pub fn toolpath(&self) -> Result<JsValue, JsValue> {
        let t = &self.toolpath;
        let out = Object::new();
        let set = |key: &str, value: JsValue| Reflect::set(&out, &JsValue::from_str(key), &value);
        set("units", JsValue::from_str(t.units.as_str()))?;
        set("machine", JsValue::from_str(t.machine.as_str()))?;
        set("actual", Float64Array::from(t.actual.as_slice()).into())?;
        set(
            "programmed",
            Float64Array::from(t.programmed.as_slice()).into(),
        )?;
        set("starts", Uint32Array::from(t.starts.as_slice()).into())?;
        set("kinds", Uint8Array::from(t.kinds.as_slice()).into())?;
        set("blocks", Uint32Array::from(t.blocks.as_slice()).into())?;
        set("lines", Uint32Array::from(t.lines.as_slice()).into())?;
        Ok(out.into())
    }

    /// Keeps an OffscreenCanvas (transferred from the page) to draw on.
    pub fn attach_canvas(&mut self, canvas: OffscreenCanvas) -> Result<(), JsValue> {
        let ctx = canvas
            .get_context("2d")?
            .ok_or_else(|| JsValue::from_str("the canvas has no 2d context"))?
            .dyn_into::<OffscreenCanvasRenderingContext2d>()?;
        self.canvas = Some((canvas, ctx));
        Ok(())
    }

    /// Draws the current run fitted to `width` x `height` CSS pixels at
    /// `dpr` device pixels per CSS pixel (sharp on high-DPI screens). Does
    /// nothing without an attached canvas.
    pub fn render(&self, width: u32, height: u32, dpr: f64) -> Result<(), JsValue> {
        let Some((canvas, ctx)) = &self.canvas else {
            return Ok(());
        };
        let dpr = if dpr.is_finite() && dpr > 0.0 {
            dpr.min(8.0)
        } else {
            1.0
        };
        let (w, h) = (width.clamp(1, 8192), height.clamp(1, 8192));
        let device = |css: u32| ((f64::from(css) * dpr).round() as u32).clamp(1, 16384);
        // Resizing the canvas also resets the context's state.
        canvas.set_width(device(w));
        canvas.set_height(device(h));
        let sx = f64::from(device(w)) / f64::from(w);
        let sy = f64::from(device(h)) / f64::from(h);
        ctx.set_transform(sx, 0.0, 0.0, sy, 0.0, 0.0)?;
        let mut surface = CanvasSurface::new(ctx);
        render::draw(&mut surface, &self.toolpath, f64::from(w), f64::from(h));
        Ok(())
    }

    /// The same drawing as an SVG document.
    pub fn render_svg(&self, width: u32, height: u32) -> String {
        render::svg::render(&self.toolpath, f64::from(width), f64::from(height))
    }
}
