//! The documents the page exchanges with the core, in the shapes it reads:
//! a link decoded or a document file read answers `{ document, embed,
//! error }` — always all three keys, the document in its JSON shape with
//! `program` always present and `view` and `step` null when absent — and
//! never fails; a document the page passes in is its JSON text.

use serde::Serialize;
use serde_json::Value;

use crate::document::Document;
use crate::share::{self, LinkError};

/// A problem with a link or a document file, for a person to read.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct CodecError {
    /// The codec's code (`link-base64`, …) or the setup's (`setup-range`, …).
    pub code: String,
    /// What is wrong.
    pub message: String,
}

/// What decoding a link or reading a document file answers.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Decoded {
    /// The document (see [`document_value`]), or None with an error.
    pub document: Option<Value>,
    /// The link asks for the embedded view (false for a file).
    pub embed: bool,
    /// Why there is no document.
    pub error: Option<CodecError>,
}

/// The codec's limits: past `long` characters a link may not survive
/// chat tools and some browsers (the page warns and offers a file), past
/// `max` it is not read at all.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct Limits {
    /// Characters past which a link is long.
    pub long: usize,
    /// Characters past which a link is not read.
    pub max: usize,
    /// The base of the page's links by default.
    pub default_base: &'static str,
}

/// The codec's limits.
pub const LIMITS: Limits = Limits {
    long: share::LONG_LINK,
    max: share::MAX_LINK,
    default_base: share::DEFAULT_BASE,
};

/// A document as the page receives it: its document JSON with `program`
/// always present and `view` and `step` null when absent.
pub fn document_value(doc: &Document) -> Value {
    let mut value: Value = serde_json::from_str(&doc.to_json()).unwrap_or(Value::Null);
    if let Some(map) = value.as_object_mut() {
        map.entry("program").or_insert_with(|| Value::from(""));
        map.entry("view").or_insert(Value::Null);
        map.entry("step").or_insert(Value::Null);
    }
    value
}

/// A document the page passes in, as JSON text (None: a value that is not
/// JSON); a problem is a `link-document` error (the code the link exports
/// throw with).
pub fn document_from_json(text: Option<&str>) -> Result<Document, LinkError> {
    let problem = |message: String| LinkError {
        code: "link-document",
        message,
    };
    let text = text.ok_or_else(|| problem("the document is not a JSON object".into()))?;
    Document::from_json(text).map_err(|e| problem(e.to_string()))
}

/// Reads a link (a full URL, a `#fragment` or the fragment alone; compact
/// or plain): the document and whether it is embedded, or the codec's
/// error (`link-base64`, `link-deflate`, `link-version`, …).
pub fn decode_link(text: &str) -> Decoded {
    match share::decode(text) {
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
    }
}

/// Reads a document file (JSON text; a setup document is a document
/// without a program): as [`decode_link`], never embedded, the error's
/// code that of the first problem (`setup-syntax`, `setup-range`, …) and
/// its message every problem.
pub fn read_document(text: &str) -> Decoded {
    match Document::from_json(text) {
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
    }
}
