//! The JavaScript face of the crate (wasm only), and its only door to the
//! browser besides the canvas backend. Thin: each export converts its input,
//! calls the core and converts the output. Nothing here panics on input — a
//! panic would kill the page's worker — and a bad setup comes back as
//! diagnostics, never as an exception.
//!
//! Small structured values (summary, diagnostics, one block) go through one
//! serde-wasm-bindgen serializer; the toolpath goes as one copy of each flat
//! buffer in a typed array, never one JS object per move.

mod view;

use js_sys::{Float64Array, JSON, Object, Reflect, Uint8Array, Uint32Array};
use serde::Serialize;
use serde_wasm_bindgen::Serializer;
use wasm_bindgen::prelude::*;
use web_sys::{OffscreenCanvas, OffscreenCanvasRenderingContext2d};

use crate::diag::Diagnostic;
use crate::document::{Document, ViewPlane, ViewState};
use crate::render::canvas::Shot;
use crate::render::display::Op;
use crate::render::scene::{self, Scene};
use crate::render::{Frame, Raster};
use crate::report::{BlockReport, End, Run};
use crate::run::RunOptions;
use crate::setup::{MachineKind, Setup};
use crate::share;
use crate::toolpath::{PathBuilder, Toolpath};
use crate::view::{Summary, block_view, summary};

/// How the page runs a program: a checkpoint every 512 blocks instead of a
/// report per block (a report is about 300 bytes, a checkpoint about 500
/// shared by 512 blocks), and the moves go straight into the compact
/// toolpath instead of being kept (a move is 216 bytes): a million-block
/// program fits. Showing a block re-runs at most 511 blocks, well under a
/// millisecond; an export re-runs the program keeping its moves.
const SESSION_RUN: RunOptions = RunOptions {
    keep_blocks: false,
    keep_moves: false,
    max_moves: crate::MAX_MOVES,
    max_blocks: crate::MAX_BLOCKS,
    checkpoint_every: 512,
};

/// Programs of up to this many bytes stay in the session's buffer after
/// their run ([`Session::run_buffer`]), a copy of the run's text, for the
/// next to be made from by an edit; larger ones (a file of a million
/// blocks, 31 MB) are not held twice.
const KEPT_PROGRAM: usize = 8 << 20;

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
    /// The pixel layer large paths are drawn on, and what carries it to the
    /// canvas (`render::canvas::Layer`); kept between frames for their memory.
    raster: Raster,
    /// A canvas per pixel buffer of the raster, and what each holds.
    scratch: Option<[OffscreenCanvas; 2]>,
    held: [Option<(usize, usize, usize, usize)>; 2],
    raster_bytes: Vec<u8>,
    shot: Option<Shot>,
    /// The drawing calls of the frame the canvas shows (None: not known),
    /// so that the next frame is painted only where it differs.
    shown: Option<Vec<Op>>,
    /// Runs so far.
    runs: u64,
    /// Counts the runs whose toolpath differed from the one before: a kept
    /// layer shows one of them (a run that changed nothing drawn, such as
    /// an edit of an N number, keeps it).
    drawing: u64,
    /// The last run's setup was refused: it ran nothing (its diagnostics
    /// say why), and an export has no moves to run again for.
    setup_refused: bool,
    /// Frames drawn from a kept layer.
    moving_frames: u64,
    /// What the last whole frame on the canvas showed: the drawing, the
    /// view state, the size in CSS pixels and the device pixel ratio. A
    /// frame asked for the same (a run that changed nothing drawn) is that
    /// one, and is not drawn again.
    last_whole: Option<(u64, Scene, (u32, u32), u64)>,
    /// The next program, written by JavaScript ([`Session::program_buffer`]).
    incoming: Vec<u8>,
    /// Plane, zoom, pan, current block and colours.
    scene: Scene,
    /// The CSS size last drawn at, for zoom, pan and picking.
    size: (f64, f64),
    /// The layout last drawn, which picking measures against.
    frame: Option<Frame>,
    /// Whether the current block was set at the last block: the next runs
    /// keep it at their last block (editing at the end shows the whole
    /// program). A block set elsewhere stays where it was set, also across
    /// a run that stopped short of it at an error and clamped it there.
    follows_end: bool,
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
            raster: Raster::new(),
            scratch: None,
            held: [None; 2],
            raster_bytes: Vec::new(),
            shot: None,
            shown: None,
            runs: 0,
            drawing: 0,
            setup_refused: false,
            moving_frames: 0,
            last_whole: None,
            incoming: Vec::new(),
            scene: Scene::default(),
            size: (300.0, 150.0),
            frame: None,
            follows_end: false,
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

/// A document as JS passes it: a document object (the document JSON's
/// shape) or its JSON text.
fn read_document_value(value: &JsValue) -> Result<Document, share::LinkError> {
    let text = match value.as_string() {
        Some(text) => text,
        None => JSON::stringify(value)
            .ok()
            .and_then(|s| s.as_string())
            .ok_or_else(|| share::LinkError {
                code: "link-document",
                message: "the document is not a JSON object".into(),
            })?,
    };
    Document::from_json(&text).map_err(|e| share::LinkError {
        code: "link-document",
        message: e.to_string(),
    })
}

/// A document as the JSON value JS receives: its document JSON with
/// `program` always present and `view` and `step` `null` when absent.
fn document_value(doc: &Document) -> serde_json::Value {
    let mut value: serde_json::Value =
        serde_json::from_str(&doc.to_json()).unwrap_or(serde_json::Value::Null);
    if let Some(map) = value.as_object_mut() {
        map.entry("program")
            .or_insert_with(|| serde_json::Value::from(""));
        map.entry("view").or_insert(serde_json::Value::Null);
        map.entry("step").or_insert(serde_json::Value::Null);
    }
    value
}

/// A problem with a link or a document file, for a person to read.
#[derive(Serialize)]
struct CodecError {
    code: String,
    message: String,
}

/// What `decode_link` and `read_document` return: always all three keys.
#[derive(Serialize)]
struct Decoded {
    document: Option<serde_json::Value>,
    embed: bool,
    error: Option<CodecError>,
}

fn thrown(e: share::LinkError) -> JsError {
    JsError::new(&e.to_string())
}

/// The compact link of `document` (an object shaped like the document JSON,
/// or its text): `base#v1.…`, with `&embed=1` when `embed`. Throws an
/// `Error` ("link-base: …" or "link-document: …") only for a base that is
/// not an http(s) URL or a document that does not validate.
#[wasm_bindgen]
pub fn encode_link(base: &str, document: JsValue, embed: bool) -> Result<String, JsError> {
    let doc = read_document_value(&document).map_err(thrown)?;
    share::link(base, &doc, embed).map_err(thrown)
}

/// The plain, hand-writable form of `document`, without the leading `#`:
/// `program=…&offset=01:6…` (settings at their defaults left out). Throws
/// like `encode_link` for a document that does not validate.
#[wasm_bindgen]
pub fn encode_plain(document: JsValue, embed: bool) -> Result<String, JsError> {
    let doc = read_document_value(&document).map_err(thrown)?;
    Ok(share::encode_plain(&doc, embed))
}

/// Reads a link (a full URL, a `#fragment` or the fragment alone; compact
/// or plain). Never throws: returns `{ document, embed, error: null }` or
/// `{ document: null, embed: false, error: { code, message } }` with the
/// codec's code (`link-base64`, `link-deflate`, `link-version`, …).
#[wasm_bindgen]
pub fn decode_link(text: &str) -> Result<JsValue, JsValue> {
    to_js(&match share::decode(text) {
        Ok(link) => Decoded {
            document: Some(document_value(&link.document)),
            embed: link.embed,
            error: None,
        },
        Err(e) => Decoded {
            document: None,
            embed: false,
            error: Some(CodecError {
                code: e.code.to_owned(),
                message: e.message,
            }),
        },
    })
}

/// Reads a document file (JSON text; a setup document is a document
/// without a program). Never throws: `{ document, embed: false, error }`
/// as `decode_link`, the error's code that of the first problem
/// (`setup-syntax`, `setup-range`, …) and its message every problem.
#[wasm_bindgen]
pub fn read_document(text: &str) -> Result<JsValue, JsValue> {
    to_js(&match Document::from_json(text) {
        Ok(doc) => Decoded {
            document: Some(document_value(&doc)),
            embed: false,
            error: None,
        },
        Err(e) => Decoded {
            document: None,
            embed: false,
            error: Some(CodecError {
                code: e
                    .diagnostics
                    .first()
                    .map_or("setup-syntax", |d| d.code)
                    .to_owned(),
                message: e
                    .diagnostics
                    .iter()
                    .map(|d| d.message.as_str())
                    .collect::<Vec<_>>()
                    .join("; "),
            }),
        },
    })
}

/// The document as an indented JSON file (what `offsetlab link --decode`
/// prints; `offsetlab run --setup FILE` reads it). Throws like
/// `encode_link` for a document that does not validate.
#[wasm_bindgen]
pub fn document_json(document: JsValue) -> Result<String, JsError> {
    let doc = read_document_value(&document).map_err(thrown)?;
    Ok(doc.to_json_pretty())
}

/// The codec's limits: `{ long, max, default_base }` — past `long`
/// characters a link may not survive chat tools and some browsers (the
/// page warns and offers a file), past `max` it is not read at all.
#[wasm_bindgen]
pub fn link_limits() -> Result<JsValue, JsValue> {
    #[derive(Serialize)]
    struct Limits {
        long: usize,
        max: usize,
        default_base: &'static str,
    }
    to_js(&Limits {
        long: share::LONG_LINK,
        max: share::MAX_LINK,
        default_base: share::DEFAULT_BASE,
    })
}

/// Rounds to `digits` significant digits (view values in links stay short
/// and read well: zoom 1.83 rather than 1.8301502738172).
fn significant(x: f64, digits: i32) -> f64 {
    if x == 0.0 || !x.is_finite() {
        return x;
    }
    let scale = 10f64.powi(digits - 1 - x.abs().log10().floor() as i32);
    let r = (x * scale).round() / scale;
    if r.is_finite() { r } else { x }
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
    pub fn run(&mut self, program: String, setup: JsValue) -> Result<JsValue, JsValue> {
        self.run_reporting(program, setup, None)
    }

    /// [`Session::run`], calling `progress(fraction)` (0 to 1, of the
    /// program's bytes read) after every MiB of program, so the page can
    /// show how far a long run has got (the worker posts it on: its
    /// messages reach the page during the run).
    pub fn run_with_progress(
        &mut self,
        program: String,
        setup: JsValue,
        progress: &js_sys::Function,
    ) -> Result<JsValue, JsValue> {
        self.run_reporting(program, setup, Some(progress))
    }

    /// Room in wasm memory for a program of up to `capacity` bytes of
    /// UTF-8, zeroed; returns its address, where the caller writes the
    /// program (`TextEncoder.encodeInto` on a view of the memory, before
    /// any other call) and then runs it with [`Session::run_buffer`]. The
    /// page's worker runs programs this way: wasm-bindgen copies a
    /// `String` argument into wasm memory a UTF-16 unit at a time in
    /// JavaScript (70–160 ms for 31 MB in V8), and `TextEncoder.encode`
    /// and a copy took 150 ms in Chromium's worker; `encodeInto` writes it
    /// in place in about 50 (`docs/performance.md`). Returns 0 when there
    /// is not that much memory.
    pub fn program_buffer(&mut self, capacity: usize) -> *mut u8 {
        self.incoming = Vec::new();
        if self.incoming.try_reserve_exact(capacity).is_err() {
            return std::ptr::null_mut();
        }
        self.incoming.resize(capacity, 0);
        self.incoming.as_mut_ptr()
    }

    /// [`Session::run_with_progress`] for the program written into
    /// [`Session::program_buffer`]: its first `length` bytes (at most the
    /// room asked for; invalid UTF-8 is read with U+FFFD in its place).
    /// A program of up to [`KEPT_PROGRAM`] bytes stays in the buffer, for
    /// the next one to be made from it ([`Session::program_splice`]).
    pub fn run_buffer(
        &mut self,
        length: usize,
        setup: JsValue,
        progress: Option<js_sys::Function>,
    ) -> Result<JsValue, JsValue> {
        self.incoming.truncate(length);
        let bytes = if self.incoming.len() <= KEPT_PROGRAM {
            self.incoming.clone()
        } else {
            std::mem::take(&mut self.incoming)
        };
        let program = String::from_utf8(bytes)
            .unwrap_or_else(|e| String::from_utf8_lossy(e.as_bytes()).into_owned());
        self.run_reporting(program, setup, progress.as_ref())
    }

    /// Makes the next program from the one in the buffer (the last written
    /// and run, or made so), which is `length` bytes long: its bytes
    /// `from..to` replaced by `insert` bytes, zeroed, for the caller to
    /// write at the returned address before any other call; then
    /// [`Session::run_buffer`] runs it. The page's worker makes an edit so:
    /// a keystroke in a 100k-block program wrote its whole 3 MB text again
    /// (6–8 ms in Chromium's worker, the text being made of the edit's
    /// pieces). Returns 0, and leaves the buffer empty, when the buffer is
    /// not `length` bytes long (another program, or none kept), `from..to`
    /// is not within it, or there is not the memory.
    pub fn program_splice(
        &mut self,
        length: usize,
        from: usize,
        to: usize,
        insert: usize,
    ) -> *mut u8 {
        let len = self.incoming.len();
        let grow = insert.saturating_sub(to.saturating_sub(from));
        if len != length || from > to || to > len || self.incoming.try_reserve(grow).is_err() {
            self.incoming = Vec::new();
            return std::ptr::null_mut();
        }
        self.incoming
            .splice(from..to, std::iter::repeat_n(0, insert));
        self.incoming[from..].as_mut_ptr()
    }
}

/// Builds the session's toolpath from the moves as they are made and
/// passes the progress on to JavaScript.
struct SessionObserver<'a> {
    path: PathBuilder<'a>,
    progress: Option<&'a js_sys::Function>,
    /// The program's length in bytes.
    len: usize,
}

impl crate::run::Observer for SessionObserver<'_> {
    fn on_move(&mut self, m: &crate::machine::Move) {
        self.path.on_move(m);
    }

    fn on_resume(&mut self, prefix_moves: usize) {
        self.path.on_resume(prefix_moves);
    }

    fn on_progress(&mut self, read: usize) {
        self.path.foresee(read, self.len);
        if let Some(f) = self.progress {
            // A throwing callback must not stop the run.
            let _ = f.call1(
                &JsValue::NULL,
                &JsValue::from_f64(read as f64 / self.len.max(1) as f64),
            );
        }
    }
}

impl Session {
    fn run_reporting(
        &mut self,
        // Owned: the text wasm-bindgen copies into wasm memory is kept as
        // it is (a 31 MB program is not held twice at the run's peak).
        program: String,
        setup: JsValue,
        progress: Option<&js_sys::Function>,
    ) -> Result<JsValue, JsValue> {
        let setup = read_setup(&setup);
        // An edit of the last program with the same setup is run again from
        // the last run (`rerun_observed`): from its checkpoint before the
        // edit until the run catches up with it. Another program (less than
        // half of its text in common with the last one) is run afresh, and
        // the last one goes before the new one's run allocates.
        let earlier_text = match &setup {
            Ok(setup)
                if !self.setup_refused && *setup == self.setup && similar(&self.text, &program) =>
            {
                Some(std::mem::replace(&mut self.text, program))
            }
            _ => {
                self.text = program;
                self.run = crate::run("", &Setup::default());
                self.toolpath = Toolpath::default();
                None
            }
        };
        match setup {
            Ok(setup) => {
                let earlier = earlier_text.as_deref().map(|text| crate::Earlier {
                    text,
                    run: &self.run,
                });
                let mut observer = SessionObserver {
                    path: PathBuilder::new(
                        setup.machine,
                        setup.units,
                        earlier.map(|_| &self.toolpath),
                    ),
                    progress,
                    len: self.text.len(),
                };
                let (run, reuse) =
                    crate::rerun_observed(&self.text, &setup, SESSION_RUN, earlier, &mut observer);
                let mut toolpath = observer.path.finish(&run, &reuse);
                toolpath.shrink_to_fit();
                if toolpath != self.toolpath {
                    self.drawing += 1;
                }
                self.run = run;
                self.toolpath = toolpath;
                self.setup = setup;
                self.setup_refused = false;
            }
            Err(diagnostics) => {
                self.setup = Setup::default();
                let mut run = crate::run("", &self.setup);
                run.diagnostics = diagnostics;
                run.end = End::Error { line: 0 };
                self.run = run;
                self.toolpath = Toolpath::new(self.setup.machine, self.setup.units);
                self.drawing += 1;
                self.setup_refused = true;
            }
        }
        drop(earlier_text);
        self.after_run();
        to_js(&RunResult {
            summary: summary(&self.run),
            diagnostics: &self.run.diagnostics,
        })
    }
}

/// True when `new` keeps at least half of `old` unchanged at its start and
/// end together: an edit, worth running again from the last run.
fn similar(old: &str, new: &str) -> bool {
    let (prefix, suffix) = crate::run::again::common_ends(old.as_bytes(), new.as_bytes());
    prefix + suffix >= new.len() / 2
}

#[wasm_bindgen]
impl Session {
    /// The current document: the program and setup of the last run, the
    /// view (`null` when it is the machine's default: its first plane, zoom
    /// 1, no pan; zoom to 6 significant digits, pan to 1e-4) and the current
    /// block as `step` (`null` when none) — the document JSON's shape, ready
    /// for `encode_link`. After a bad setup it carries the default setup.
    pub fn document(&self) -> Result<JsValue, JsValue> {
        to_js(&document_value(&self.current_document()))
    }

    /// The toolpath's moves as an indented JSON file: `{ summary, moves }`
    /// with exactly the CLI's `run --format json` fields.
    pub fn moves_json(&self) -> String {
        crate::export::moves_json(&self.with_moves())
    }

    /// The toolpath's moves as CSV: the JSON fields flattened into columns
    /// (`from_x`, `arc_center_x`, …; no `_y` columns on the lathe).
    pub fn moves_csv(&self) -> String {
        crate::export::moves_csv(&self.with_moves())
    }

    /// The setup of the last run as a setup document (the default setup
    /// after a bad one).
    pub fn setup(&self) -> Result<JsValue, JsValue> {
        to_js(&self.setup)
    }

    /// Number of executed blocks (each has a report).
    pub fn block_count(&self) -> u32 {
        self.run.block_count
    }

    /// The report of block `index` (as the CLI's JSON `blocks` entries), or
    /// `null` when out of range.
    pub fn block(&self, index: u32) -> Result<JsValue, JsValue> {
        match self.report(index) {
            Some(b) => to_js(&block_view(&b, &self.text)),
            None => Ok(JsValue::NULL),
        }
    }

    /// The toolpath as typed arrays, each a fresh copy owned by JS:
    /// `{ units, machine, actual: Float64Array, programmed: Float64Array,
    /// starts: Uint32Array, kinds: Uint8Array, blocks: Uint32Array,
    /// lines: Uint32Array }`: every move as a polyline, arcs within the
    /// 0.01 mm chord tolerance (see `Polylines` in `src/toolpath.rs`).
    pub fn toolpath(&self) -> Result<JsValue, JsValue> {
        let t = &self.toolpath;
        let lines = t.polylines();
        let out = Object::new();
        let set = |key: &str, value: JsValue| Reflect::set(&out, &JsValue::from_str(key), &value);
        set("units", JsValue::from_str(t.units.as_str()))?;
        set("machine", JsValue::from_str(t.machine.as_str()))?;
        set("actual", Float64Array::from(lines.actual.as_slice()).into())?;
        set(
            "programmed",
            Float64Array::from(lines.programmed.as_slice()).into(),
        )?;
        set("starts", Uint32Array::from(lines.starts.as_slice()).into())?;
        set("kinds", Uint8Array::from(t.kinds.as_slice()).into())?;
        set("blocks", Uint32Array::from(t.blocks.as_slice()).into())?;
        set("lines", Uint32Array::from(t.lines.as_slice()).into())?;
        Ok(out.into())
    }
}

impl Session {
    /// The report of block `index`, made again from the checkpoint before
    /// it (the session keeps checkpoints, not a report per block).
    fn report(&self, index: u32) -> Option<BlockReport> {
        crate::run::report_at(&self.text, &self.setup, &self.run, index)
    }

    /// The last run again, keeping its moves (for the exports: the session
    /// keeps only the toolpath). After a bad setup, the empty run.
    fn with_moves(&self) -> Run {
        if self.setup_refused {
            return self.run.clone();
        }
        let options = RunOptions {
            keep_moves: true,
            checkpoint_every: 0,
            ..SESSION_RUN
        };
        crate::run_with(&self.text, &self.setup, options)
    }

    /// The document of the current state (see `document()`).
    fn current_document(&self) -> Document {
        let default_plane = match self.run.machine {
            MachineKind::Lathe => ViewPlane::ZX,
            MachineKind::Mill => ViewPlane::XY,
        };
        let plane = ViewPlane::parse(self.scene.plane.name()).unwrap_or(default_plane);
        let zoom = significant(self.scene.zoom, 6);
        let pan = self.scene.pan.map(|p| {
            let r = (p * 1e4).round() / 1e4;
            if r == 0.0 { 0.0 } else { r }
        });
        let view = (plane != default_plane || zoom != 1.0 || pan != [0.0, 0.0])
            .then_some(ViewState { plane, zoom, pan });
        Document {
            setup: self.setup.clone(),
            program: self.text.clone(),
            view,
            step: self.scene.step,
        }
    }

    /// Keeps the view state sensible for a new run: the lathe is drawn in
    /// ZX, the mill in one of its planes; a current block past the end moves
    /// to the last block, and a session set at the last block stays at the
    /// last block (so editing at the end shows the whole program). Only the
    /// user sets it there ([`Session::set_step`]): a digit that stops the
    /// run at an error just after the block being edited makes that block
    /// the last one, and the key that mends the error must not send the
    /// current block to the program's end.
    fn after_run(&mut self) {
        self.runs += 1;
        self.scene.adapt_to(self.run.machine);
        let count = self.run.block_count;
        if let Some(step) = self.scene.step {
            self.scene.step = match count {
                0 => None,
                n if self.follows_end || step >= n => Some(n - 1),
                _ => Some(step),
            };
        }
        self.update_marker();
        // The layout drawn (which picking measures against) holds while the
        // drawing is the one drawn last.
        if self
            .last_whole
            .is_none_or(|(drawing, ..)| drawing != self.drawing)
        {
            self.frame = None;
        }
    }

    fn update_marker(&mut self) {
        self.scene.marker = self.scene.step.and_then(|step| {
            let drawn = self.scene.drawn_moves(&self.toolpath);
            scene::tool_position(&self.toolpath, drawn).or_else(|| {
                // No move yet: the tool is where the block leaves it.
                let b = self.report(step)?;
                let k = 1.0 / self.run.units.mm();
                Some([
                    b.state.actual.map(|v| v * k),
                    b.state.programmed.map(|v| v * k),
                ])
            })
        });
    }
}
