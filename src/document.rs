//! The document: one versioned JSON format for share links, `--setup` files
//! and the page's saved state. It is the setup document (see [`Setup`]) with
//! three more optional fields at the same level:
//!
//! ```json
//! { "version": 1, "machine": "mill", "offsets": {"01": 6.0},
//!   "program": "G91 G46 X30. Y20. D01;",
//!   "view": {"plane": "XY", "zoom": 2.0, "pan": [10.0, -5.0]},
//!   "step": 3 }
//! ```
//!
//! A setup document is a document without a program, so every setup file is
//! a document and the other way round.

use serde::{Deserialize, Serialize};
use serde_json::{Map, Value};

use crate::diag::{Diagnostic, Span};
use crate::setup::{Setup, SetupError};

/// Largest zoom factor a document may ask for (relative to "fit").
pub const MAX_ZOOM: f64 = 1e6;
/// Smallest zoom factor.
pub const MIN_ZOOM: f64 = 1e-3;
/// Largest pan, in program units.
pub const MAX_PAN: f64 = 1e6;
/// Largest step (block index) a document may name.
pub const MAX_STEP: u32 = 100_000_000;

/// The plane a view shows.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum ViewPlane {
    /// Mill top view.
    #[default]
    XY,
    /// Mill front view (X right, Z up).
    XZ,
    /// Mill side view (Y right, Z up).
    YZ,
    /// Lathe: Z right, X (as radius) up.
    ZX,
    /// Lathe face view (polar coordinate interpolation): X (as radius)
    /// right, C up.
    XC,
    /// Mill 3D view at the view's `angles` (behaviour 10.8).
    #[serde(rename = "3D")]
    D3,
}

impl ViewPlane {
    /// "XY", "XZ", "YZ", "ZX" or "XC".
    pub fn as_str(self) -> &'static str {
        match self {
            ViewPlane::XY => "XY",
            ViewPlane::XZ => "XZ",
            ViewPlane::YZ => "YZ",
            ViewPlane::ZX => "ZX",
            ViewPlane::XC => "XC",
            ViewPlane::D3 => "3D",
        }
    }

    /// Reads a plane name (any case).
    pub fn parse(s: &str) -> Option<ViewPlane> {
        Some(match s.to_ascii_uppercase().as_str() {
            "XY" => ViewPlane::XY,
            "XZ" => ViewPlane::XZ,
            "YZ" => ViewPlane::YZ,
            "ZX" => ViewPlane::ZX,
            "XC" => ViewPlane::XC,
            "3D" => ViewPlane::D3,
            _ => return None,
        })
    }
}

fn one() -> f64 {
    1.0
}

/// What the view shows: the plane, the zoom relative to "fit the whole
/// path", and the pan of the view's centre from the fitted centre (program
/// units, along the plane's horizontal and vertical axes).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ViewState {
    /// The plane.
    #[serde(default)]
    pub plane: ViewPlane,
    /// 1 = the whole path fits; 2 = twice as large.
    #[serde(default = "one")]
    pub zoom: f64,
    /// Offset of the view centre from the fitted centre.
    #[serde(default)]
    pub pan: [f64; 2],
    /// The 3D view's yaw and pitch in degrees (behaviour 10.9); written
    /// with plane `3D` only, absent there: the isometric view.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub angles: Option<[f64; 2]>,
    /// The band the cutter sweeps is drawn (behaviour 16.20); absent: no.
    #[serde(default, skip_serializing_if = "is_false")]
    pub swept: bool,
    /// The legend is drawn (behaviour 10.7); written only when folded
    /// away (`false`).
    #[serde(default = "yes", skip_serializing_if = "is_true")]
    pub legend: bool,
}

fn is_false(b: &bool) -> bool {
    !*b
}

fn is_true(b: &bool) -> bool {
    *b
}

fn yes() -> bool {
    true
}

impl Default for ViewState {
    fn default() -> Self {
        ViewState {
            plane: ViewPlane::XY,
            zoom: 1.0,
            pan: [0.0, 0.0],
            angles: None,
            swept: false,
            legend: true,
        }
    }
}

/// A program with everything needed to show it as its author saw it.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Document {
    /// Machine, registers, settings.
    pub setup: Setup,
    /// The program text.
    pub program: String,
    /// The view, if the author chose one.
    pub view: Option<ViewState>,
    /// The current block (index into the run's blocks), if any.
    pub step: Option<u32>,
}

#[derive(Serialize)]
struct Out<'a> {
    #[serde(flatten)]
    setup: &'a Setup,
    #[serde(skip_serializing_if = "str::is_empty")]
    program: &'a str,
    #[serde(skip_serializing_if = "Option::is_none")]
    view: Option<&'a ViewState>,
    #[serde(skip_serializing_if = "Option::is_none")]
    step: Option<u32>,
}

fn problem(code: &'static str, message: String) -> SetupError {
    SetupError {
        diagnostics: vec![Diagnostic::error(code, Span::default(), message)],
    }
}

impl Document {
    /// A document with a program and a setup.
    pub fn new(setup: Setup, program: impl Into<String>) -> Document {
        Document {
            setup,
            program: program.into(),
            view: None,
            step: None,
        }
    }

    /// Compact JSON (for links).
    pub fn to_json(&self) -> String {
        serde_json::to_string(&self.out()).unwrap_or_default()
    }

    /// Indented JSON (for files and people).
    pub fn to_json_pretty(&self) -> String {
        serde_json::to_string_pretty(&self.out()).unwrap_or_default()
    }

    fn out(&self) -> Out<'_> {
        Out {
            setup: &self.setup,
            program: &self.program,
            view: self.view.as_ref(),
            step: self.step,
        }
    }

    /// Reads and validates a document (or a plain setup document).
    pub fn from_json(text: &str) -> Result<Document, SetupError> {
        let value: Value = serde_json::from_str(text)
            .map_err(|e| problem("setup-syntax", format!("document: {e}")))?;
        Document::from_value(value)
    }

    /// Reads and validates a document from a JSON value.
    pub fn from_value(value: Value) -> Result<Document, SetupError> {
        let Value::Object(mut map) = value else {
            return Err(problem(
                "setup-syntax",
                "document: expected a JSON object".to_string(),
            ));
        };
        let program = match map.remove("program") {
            None | Some(Value::Null) => String::new(),
            Some(Value::String(s)) => s,
            Some(_) => {
                return Err(problem(
                    "setup-syntax",
                    "document: `program` must be a string".to_string(),
                ));
            }
        };
        let view = take::<ViewState>(&mut map, "view")?;
        let step = take::<u32>(&mut map, "step")?;
        let setup: Setup = serde_json::from_value(Value::Object(map))
            .map_err(|e| problem("setup-syntax", format!("document: {e}")))?;
        let doc = Document {
            setup,
            program,
            view,
            step,
        };
        doc.validated()
    }

    /// Returns the document if every value is in range, or every problem.
    pub fn validated(self) -> Result<Document, SetupError> {
        let mut diagnostics = self.setup.validate();
        if let Some(v) = &self.view {
            let mut bad = |what: String| {
                diagnostics.push(Diagnostic::error("setup-range", Span::default(), what));
            };
            if !v.zoom.is_finite() || !(MIN_ZOOM..=MAX_ZOOM).contains(&v.zoom) {
                bad(format!(
                    "view.zoom = {} is outside {MIN_ZOOM} to {MAX_ZOOM}",
                    v.zoom
                ));
            }
            if v.pan.iter().any(|p| !p.is_finite() || p.abs() > MAX_PAN) {
                bad(format!("view.pan = {:?} is outside ±{MAX_PAN}", v.pan));
            }
            if let Some([yaw, pitch]) = v.angles
                && !(yaw.is_finite()
                    && (-360.0..=360.0).contains(&yaw)
                    && pitch.is_finite()
                    && (-90.0..=90.0).contains(&pitch))
            {
                bad(format!(
                    "view.angles = [{yaw}, {pitch}]: yaw is -360 to 360, pitch -90 to 90 degrees"
                ));
            }
        }
        if let Some(s) = self.step
            && s > MAX_STEP
        {
            diagnostics.push(Diagnostic::error(
                "setup-range",
                Span::default(),
                format!("step {s} is more than {MAX_STEP}"),
            ));
        }
        if diagnostics.is_empty() {
            Ok(self)
        } else {
            Err(SetupError { diagnostics })
        }
    }
}

fn take<T: for<'de> Deserialize<'de>>(
    map: &mut Map<String, Value>,
    key: &str,
) -> Result<Option<T>, SetupError> {
    match map.remove(key) {
        None | Some(Value::Null) => Ok(None),
        Some(v) => serde_json::from_value(v)
            .map(Some)
            .map_err(|e| problem("setup-syntax", format!("document: `{key}`: {e}"))),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::setup::MachineKind;

    #[test]
    fn a_setup_document_is_a_document_without_a_program() {
        let d = Document::from_json(r#"{"version":1,"offsets":{"01":6}}"#).unwrap();
        assert_eq!(d.program, "");
        assert_eq!(d.setup.mill_value(1), 6.0);
        assert_eq!(d.view, None);
    }

    #[test]
    fn round_trip_with_program_view_and_step() {
        let mut s = Setup {
            machine: MachineKind::Lathe,
            ..Setup::default()
        };
        s.set_register("08=X0.4,Z-0.2").unwrap();
        let d = Document {
            setup: s,
            program: "G50 X120. Z60.;\nT0108;".into(),
            view: Some(ViewState {
                plane: ViewPlane::ZX,
                zoom: 2.5,
                pan: [1.0, -2.0],
                angles: None,
                swept: true,
                legend: false,
            }),
            step: Some(1),
        };
        assert_eq!(Document::from_json(&d.to_json()).unwrap(), d);
        assert_eq!(Document::from_json(&d.to_json_pretty()).unwrap(), d);
        // The swept width is written only when on (behaviour 16.20).
        assert!(d.to_json().contains("\"swept\":true"));
        let off = ViewState {
            swept: false,
            ..ViewState::default()
        };
        assert!(!serde_json::to_string(&off).unwrap().contains("swept"));
        // The legend is written only when folded away (behaviour 10.7), and
        // a view without it has it.
        assert!(d.to_json().contains("\"legend\":false"));
        assert!(!serde_json::to_string(&off).unwrap().contains("legend"));
        let read: ViewState = serde_json::from_str("{\"plane\":\"XY\"}").unwrap();
        assert!(read.legend);
    }

    #[test]
    fn unknown_fields_and_bad_values_are_errors() {
        let e = Document::from_json(r#"{"programme":"G00"}"#).unwrap_err();
        assert!(e.to_string().contains("unknown field `programme`"), "{e}");
        let e = Document::from_json(r#"{"view":{"plane":"QQ"}}"#).unwrap_err();
        assert!(e.to_string().contains("view"), "{e}");
        let e = Document::from_json(r#"{"view":{"zoom":0}}"#).unwrap_err();
        assert!(e.to_string().contains("view.zoom"), "{e}");
        let e = Document::from_json(r#"{"step":-1}"#).unwrap_err();
        assert!(e.to_string().contains("step"), "{e}");
        let e = Document::from_json(r#"{"program":5}"#).unwrap_err();
        assert!(e.to_string().contains("program"), "{e}");
        let e = Document::from_json("[1,2]").unwrap_err();
        assert!(e.to_string().contains("object"), "{e}");
    }
}
