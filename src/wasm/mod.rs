//! The JavaScript face of the crate (wasm only), the door to
//! [`crate::session`], which holds the page's state and rules: each export
//! converts its input, calls the core and converts the output (one
//! serializer; every failure thrown as an `Error` made by [`thrown`]). No
//! policy here, and no panic on any input (it would kill the page's worker).

mod view;

use js_sys::JSON;
use serde::Serialize;
use serde_wasm_bindgen::Serializer;
use wasm_bindgen::prelude::*;
use web_sys::{OffscreenCanvas, OffscreenCanvasRenderingContext2d};

use crate::diag::Diagnostic;
use crate::document::Document;
use crate::render::Kept;
use crate::session::{self, documents};
use crate::setup::Setup;
use crate::share;

/// The one serializer: absent values are `null` (not `undefined`) and maps
/// are plain objects, so JS code can rely on `value === null` and `obj.key`.
const SERIALIZER: Serializer = Serializer::new()
    .serialize_missing_as_null(true)
    .serialize_maps_as_objects(true);

fn to_js<T: Serialize + ?Sized>(value: &T) -> Result<JsValue, JsError> {
    value.serialize(&SERIALIZER).map_err(thrown)
}

/// The one error style: a thrown `Error` saying what (`link-base: …`).
fn thrown(e: impl std::fmt::Display) -> JsError {
    JsError::new(&e.to_string())
}

/// The JSON text of a value JS passes (a string is taken as the text).
fn json_text(value: &JsValue) -> Option<String> {
    value
        .as_string()
        .or_else(|| JSON::stringify(value).ok().and_then(|s| s.as_string()))
}

/// The setup argument: null/undefined is the default setup; a string is a
/// setup document (JSON text); any other value an object of that shape.
fn read_setup(value: &JsValue) -> Result<Setup, Vec<Diagnostic>> {
    let text = (!value.is_null() && !value.is_undefined()).then(|| json_text(value));
    session::read_setup(text.as_ref().map(Option::as_deref))
}

/// A document as JS passes it: a document object (the document JSON's
/// shape) or its JSON text.
fn read_document_value(value: &JsValue) -> Result<Document, JsError> {
    documents::document_from_json(json_text(value).as_deref()).map_err(thrown)
}

/// The compact link `base#v1.…` of `document` (a document object or its
/// JSON text), `&embed=1` when `embed`. Throws ("link-base: …",
/// "link-document: …") for a base not http(s) or a document not valid.
#[wasm_bindgen]
pub fn encode_link(base: &str, document: JsValue, embed: bool) -> Result<String, JsError> {
    share::link(base, &read_document_value(&document)?, embed).map_err(thrown)
}

/// The plain, hand-writable form of `document` without the `#`
/// (`program=…&offset=01:6…`); throws like `encode_link`.
#[wasm_bindgen]
pub fn encode_plain(document: JsValue, embed: bool) -> Result<String, JsError> {
    Ok(share::encode_plain(&read_document_value(&document)?, embed))
}

/// Reads a link ([`documents::decode_link`]). Never throws: `{ document,
/// embed, error: null }` or `{ document: null, embed: false, error }`.
#[wasm_bindgen]
pub fn decode_link(text: &str) -> Result<JsValue, JsError> {
    to_js(&documents::decode_link(text))
}

/// Reads a document file ([`documents::read_document`]), as `decode_link`.
#[wasm_bindgen]
pub fn read_document(text: &str) -> Result<JsValue, JsError> {
    to_js(&documents::read_document(text))
}

/// The document as an indented JSON file (`offsetlab link --decode`'s, and
/// what `--setup FILE` reads); throws like `encode_link`.
#[wasm_bindgen]
pub fn document_json(document: JsValue) -> Result<String, JsError> {
    Ok(read_document_value(&document)?.to_json_pretty())
}

/// Reads a LinuxCNC tool table file's text (behaviour 22.9): `{ table,
/// warnings, errors }`, each problem `{ line, column, message }`; the
/// table is null when the text has errors. Never throws for the text.
#[wasm_bindgen]
pub fn read_tool_table(text: &str) -> Result<JsValue, JsError> {
    to_js(&crate::setup::ToolTable::read(text))
}

/// The tool table `table` (the setup's `tool_table`, an object or its JSON
/// text) as a LinuxCNC tool table file; throws for a value of another shape.
#[wasm_bindgen]
pub fn tool_table_file(table: JsValue) -> Result<String, JsError> {
    let text = json_text(&table).unwrap_or_default();
    let table: crate::setup::ToolTable = serde_json::from_str(&text).map_err(thrown)?;
    Ok(table.to_file())
}

/// The codec's limits: `{ long, max, default_base }` ([`documents::Limits`]).
#[wasm_bindgen]
pub fn link_limits() -> Result<JsValue, JsError> {
    to_js(&documents::LIMITS)
}

/// The page's session ([`session::Session`]) and the canvas it draws on,
/// kept in wasm memory between calls; JS holds only this handle.
#[wasm_bindgen]
#[derive(Default)]
pub struct Session {
    session: session::Session,
    canvas: Option<(OffscreenCanvas, OffscreenCanvasRenderingContext2d)>,
    drawn: Drawn,
}

/// What the canvas keeps between frames: a scratch canvas per pixel buffer
/// of the layer (web-sys objects) and the drawing memory ([`Kept`]).
#[derive(Default)]
struct Drawn {
    scratch: Option<[OffscreenCanvas; 2]>,
    kept: Kept,
}

/// An address in wasm memory for JS to write at (`*mut u8` is a number to
/// JS), or 0 for none. JS must write through a view of the memory made
/// right after the call and before any other: memory growth detaches it.
fn address(room: Option<&mut [u8]>) -> *mut u8 {
    room.map_or(std::ptr::null_mut(), <[u8]>::as_mut_ptr)
}

#[wasm_bindgen]
impl Session {
    /// An empty session (no program, default setup).
    #[wasm_bindgen(constructor)]
    pub fn new() -> Session {
        Session::default()
    }

    /// Room for a program of up to `capacity` bytes of UTF-8, zeroed, for
    /// JS to write (`TextEncoder.encodeInto`) and [`Session::run_buffer`] to
    /// run (see [`session::program`]); 0 without the memory.
    pub fn program_buffer(&mut self, capacity: usize) -> *mut u8 {
        address(self.session.program_buffer(capacity))
    }

    /// The next program made from the one in the buffer, `length` bytes
    /// long: its bytes `from..to` replaced by `insert` zeroed bytes, whose
    /// address is returned for JS to write; 0, the buffer emptied, when it
    /// does not hold `length` bytes, `from..to` is not within it, or there
    /// is not the memory (the worker then sends the whole text).
    pub fn program_splice(
        &mut self,
        length: usize,
        from: usize,
        to: usize,
        insert: usize,
    ) -> *mut u8 {
        address(self.session.program_splice(length, from, to, insert))
    }

    /// Runs the program buffer's first `length` bytes with `setup`, calling
    /// `progress(fraction of the bytes read)` after every MiB (one that
    /// throws does not stop the run): `{ summary, diagnostics }`, a bad
    /// setup's `setup-…` diagnostics (line 0) too, never an exception.
    pub fn run_buffer(
        &mut self,
        length: usize,
        setup: JsValue,
        progress: Option<js_sys::Function>,
    ) -> Result<JsValue, JsError> {
        let tell = |fraction: f64| {
            if let Some(f) = &progress {
                let _ = f.call1(&JsValue::NULL, &JsValue::from_f64(fraction));
            }
        };
        to_js(&self.session.run_buffer(length, read_setup(&setup), tell))
    }

    /// The current document ([`session::Session::document`]) in the
    /// document JSON's shape, ready for `encode_link`.
    pub fn document(&self) -> Result<JsValue, JsError> {
        to_js(&documents::document_value(&self.session.document()))
    }

    /// The moves as an indented JSON file: `{ summary, moves }` with
    /// exactly the CLI's `run --format json` fields.
    pub fn moves_json(&self) -> String {
        self.session.moves_json()
    }

    /// The moves as CSV: the JSON fields flattened into columns.
    pub fn moves_csv(&self) -> String {
        self.session.moves_csv()
    }

    /// The setup of the last run (the default one after a bad one).
    pub fn setup(&self) -> Result<JsValue, JsError> {
        to_js(self.session.setup())
    }

    /// Number of executed blocks (each has a report).
    pub fn block_count(&self) -> u32 {
        self.session.block_count()
    }

    /// Block `index` as the CLI's JSON `blocks` entries, or `null`.
    pub fn block(&self, index: u32) -> Result<JsValue, JsError> {
        match self.session.block(index) {
            Some(b) => to_js(&b),
            None => Ok(JsValue::NULL),
        }
    }
}
