//! Share links: a [`Document`] in the fragment of a URL, in two forms. The
//! CLI (`offsetlab link`) and the page (through wasm) both use this module, so
//! the two always agree.
//!
//! - **Compact**: `#v1.<payload>` where the payload is base64url without
//!   padding of the raw-deflated compact JSON of the document. Decoding caps
//!   the inflated size. Version 1 decodes forever; a newer version is refused
//!   with a message, never guessed at.
//! - **Plain**, for people writing links by hand:
//!   `#program=G91%20G46%20X30.%20D01&offset=01:6&machine=mill&step=2`.
//!   Values are percent-encoded; `+` stays a plus sign (G-code signs), it is
//!   not a space. The keys are listed in [`PLAIN_KEYS`].
//!
//! Either form may end with `&embed=1` (the page's embed mode).

use base64::Engine;
use base64::engine::general_purpose::{URL_SAFE_NO_PAD, URL_SAFE_NO_PAD_INDIFFERENT};
use miniz_oxide::inflate::TINFLStatus;
use percent_encoding::{AsciiSet, CONTROLS, percent_decode_str, utf8_percent_encode};

use crate::document::{Document, ViewPlane, ViewState};
use crate::setup::{
    DecimalInput, LatheXOffset, LengthOffsetWithoutZ, MachineKind, Mirror, Position, ToolTable,
    Units,
};

/// The prefix of version 1 compact payloads.
pub const V1: &str = "v1.";
/// Largest document a link may inflate to (bytes of JSON).
pub const MAX_INFLATED: usize = 2 * 1024 * 1024;
/// Largest link text accepted for decoding (characters).
pub const MAX_LINK: usize = 4 * 1024 * 1024;
/// Past this many characters a link may not survive chat tools, forums and
/// some browsers: the page warns and offers a file instead.
pub const LONG_LINK: usize = 8000;
/// The base URL links point to by default.
pub const DEFAULT_BASE: &str = "http://127.0.0.1:8000/";

/// The keys of the plain form. Besides these, any field of the setup's
/// `settings` is a key (`control=fanuc`, `peck_retract=0.5`): its value is
/// read as that setting is in a setup document ([`is_setting`]).
pub const PLAIN_KEYS: &[&str] = &[
    "program",
    "machine",
    "units",
    "offset",
    "tool",
    "tool_table",
    "tool_table_units",
    "decimal_input",
    "block_skip",
    "length_offset_without_z",
    "lathe_x_offset",
    "mirror",
    "start",
    "plane",
    "angles",
    "zoom",
    "pan",
    "swept",
    "legend",
    "step",
    "embed",
];

/// A decoded link.
#[derive(Clone, Debug, PartialEq)]
pub struct Link {
    /// What the link carries.
    pub document: Document,
    /// The page should open in embed mode.
    pub embed: bool,
}

/// Why a link could not be read. Every malformed class has its own code.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LinkError {
    /// `link-empty`, `link-version`, `link-base64`, `link-deflate`,
    /// `link-too-large`, `link-utf8`, `link-json`, `link-document`,
    /// `link-plain`, `link-too-long`, `link-base`.
    pub code: &'static str,
    /// What is wrong, for a person.
    pub message: String,
}

impl std::fmt::Display for LinkError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}: {}", self.code, self.message)
    }
}

impl std::error::Error for LinkError {}

fn err(code: &'static str, message: impl Into<String>) -> LinkError {
    LinkError {
        code,
        message: message.into(),
    }
}

/// The compact payload of a document: `v1.<base64url(deflate-raw(json))>`.
pub fn encode(doc: &Document) -> String {
    let json = doc.to_json();
    let packed = miniz_oxide::deflate::compress_to_vec(json.as_bytes(), 9);
    format!("{V1}{}", URL_SAFE_NO_PAD.encode(packed))
}

/// Checks a base URL for links: http or https, no fragment.
pub fn check_base(base: &str) -> Result<(), LinkError> {
    let lower = base.trim().to_ascii_lowercase();
    if !(lower.starts_with("http://") || lower.starts_with("https://")) {
        return Err(err(
            "link-base",
            format!("base URL `{base}` must start with http:// or https://"),
        ));
    }
    if base.contains('#') || base.chars().any(|c| c.is_whitespace() || c.is_control()) {
        return Err(err(
            "link-base",
            format!("base URL `{base}` must not contain `#` or spaces"),
        ));
    }
    Ok(())
}

/// A full compact link: `base#v1.…` (with `&embed=1` for embed mode).
pub fn link(base: &str, doc: &Document, embed: bool) -> Result<String, LinkError> {
    check_base(base)?;
    let mut s = format!("{base}#{}", encode(doc));
    if embed {
        s.push_str("&embed=1");
    }
    Ok(s)
}

/// Characters escaped in plain-form values: controls, space and the
/// characters that would end or split the value.
const PLAIN: &AsciiSet = &CONTROLS
    .add(b' ')
    .add(b'%')
    .add(b'&')
    .add(b'#')
    .add(b'=')
    .add(b'"')
    .add(b'<')
    .add(b'>')
    .add(b'`');

fn plain_value(s: &str) -> String {
    utf8_percent_encode(s, PLAIN).to_string()
}

/// The plain form of a document (what a tutorial author would write by
/// hand), without the leading `#`. Settings at their defaults are left out.
pub fn encode_plain(doc: &Document, embed: bool) -> String {
    let s = &doc.setup;
    let d = crate::setup::Settings::default();
    let mut parts = vec![format!("program={}", plain_value(&doc.program))];
    if s.machine != MachineKind::Mill {
        parts.push(format!("machine={}", s.machine.as_str()));
    }
    if s.units != Units::Mm {
        parts.push(format!("units={}", s.units.as_str()));
    }
    match s.machine {
        MachineKind::Mill => {
            // Memory C's H and D tables apart: `H01:…` and `D01:…`.
            let part = |name: String, p: crate::setup::MillPart| {
                let mut v = format!("offset={name}:{}", p.geometry);
                if p.wear != 0.0 {
                    v += &format!(",W{}", p.wear);
                }
                v
            };
            for (n, r) in &s.offsets {
                if r.is_split() {
                    parts.push(part(format!("H{n:02}"), r.h_part()));
                    parts.push(part(format!("D{n:02}"), r.d_part()));
                } else {
                    parts.push(part(format!("{n:02}"), r.h_part()));
                }
            }
        }
        MachineKind::Lathe => {
            for (n, r) in &s.lathe_offsets {
                let mut v = format!("offset={n:02}:X{},Z{}", r.x, r.z);
                if r.x_wear != 0.0 {
                    v += &format!(",XW{}", r.x_wear);
                }
                if r.z_wear != 0.0 {
                    v += &format!(",ZW{}", r.z_wear);
                }
                if r.r != 0.0 {
                    v += &format!(",R{}", r.r);
                }
                if r.r_wear != 0.0 {
                    v += &format!(",RW{}", r.r_wear);
                }
                if r.t != 0 {
                    v += &format!(",T{}", r.t);
                }
                parts.push(v);
            }
        }
    }
    parts.extend(s.tool_specs().into_iter().map(|t| format!("tool={t}")));
    // LinuxCNC's tool table as its file's text (behaviour 22.9).
    if let Some(t) = &s.tool_table {
        parts.push(format!("tool_table={}", plain_value(&t.to_file())));
        if let Some(u) = t.units {
            parts.push(format!("tool_table_units={}", u.as_str()));
        }
    }
    let st = &s.settings;
    if let Some(input) = st.decimal_input {
        parts.push(match input {
            DecimalInput::Increment => "decimal_input=increment".into(),
            DecimalInput::Calculator => "decimal_input=calculator".into(),
        });
    }
    if st.block_skip {
        parts.push("block_skip=1".into());
    }
    if let Some(z) = st.length_offset_without_z {
        parts.push(match z {
            LengthOffsetWithoutZ::Move => "length_offset_without_z=move".into(),
            LengthOffsetWithoutZ::NextZ => "length_offset_without_z=next_z".into(),
        });
    }
    if st.lathe_x_offset != d.lathe_x_offset {
        parts.push("lathe_x_offset=radius".into());
    }
    if st.mirror.x || st.mirror.y {
        let m: String = [(st.mirror.x, "x"), (st.mirror.y, "y")]
            .iter()
            .filter(|(on, _)| *on)
            .map(|(_, a)| *a)
            .collect::<Vec<_>>()
            .join(",");
        parts.push(format!("mirror={m}"));
    }
    // Every other setting as its document writes it (a setting left at its
    // default is not written there either).
    if let Ok(serde_json::Value::Object(fields)) = serde_json::to_value(st) {
        for (key, value) in fields {
            if PLAIN_KEYS.contains(&key.as_str()) {
                continue;
            }
            let text = match value {
                serde_json::Value::String(t) => t,
                other => other.to_string(),
            };
            parts.push(format!("{key}={}", plain_value(&text)));
        }
    }
    if s.start != Position::default() {
        parts.push(format!("start={},{},{}", s.start.x, s.start.y, s.start.z));
    }
    if let Some(v) = &doc.view {
        parts.push(format!("plane={}", v.plane.as_str()));
        if let Some([yaw, pitch]) = v.angles {
            parts.push(format!("angles={yaw},{pitch}"));
        }
        if v.zoom != 1.0 {
            parts.push(format!("zoom={}", v.zoom));
        }
        if v.pan != [0.0, 0.0] {
            parts.push(format!("pan={},{}", v.pan[0], v.pan[1]));
        }
        if v.swept {
            parts.push("swept=1".to_owned());
        }
        if !v.legend {
            parts.push("legend=0".to_owned());
        }
    }
    if let Some(step) = doc.step {
        parts.push(format!("step={step}"));
    }
    if embed {
        parts.push("embed=1".into());
    }
    parts.join("&")
}

/// Reads a link: a full URL, a `#fragment`, or the fragment alone, in the
/// compact or the plain form.
pub fn decode(link: &str) -> Result<Link, LinkError> {
    if link.len() > MAX_LINK {
        return Err(err(
            "link-too-long",
            format!(
                "the link is {} characters; at most {MAX_LINK} are read",
                link.len()
            ),
        ));
    }
    let fragment = match link.find('#') {
        Some(i) => &link[i + 1..],
        None => link,
    };
    let fragment = fragment.trim();
    if fragment.is_empty() {
        return Err(err(
            "link-empty",
            "the link carries no document (nothing after `#`)",
        ));
    }
    if let Some(rest) = version_payload(fragment)? {
        let (payload, params) = match rest.split_once('&') {
            Some((p, params)) => (p, params),
            None => (rest, ""),
        };
        let mut embed = false;
        for param in params.split('&').filter(|p| !p.is_empty()) {
            match param {
                "embed=1" | "embed=true" => embed = true,
                "embed=0" | "embed=false" => embed = false,
                other => {
                    return Err(err(
                        "link-plain",
                        format!(
                            "`{}` cannot follow a compact link (only embed=1 can)",
                            shorten(other)
                        ),
                    ));
                }
            }
        }
        return Ok(Link {
            document: decode_v1(payload)?,
            embed,
        });
    }
    decode_plain(fragment)
}

/// If the fragment is a compact payload, its version-1 payload; a compact
/// payload of another version is an error.
fn version_payload(fragment: &str) -> Result<Option<&str>, LinkError> {
    if let Some(rest) = fragment.strip_prefix(V1) {
        return Ok(Some(rest));
    }
    let bytes = fragment.as_bytes();
    if bytes.first() == Some(&b'v') {
        let digits = bytes[1..].iter().take_while(|b| b.is_ascii_digit()).count();
        if digits > 0 && bytes.get(1 + digits) == Some(&b'.') {
            let v = &fragment[1..1 + digits];
            return Err(err(
                "link-version",
                format!(
                    "this link was made by a newer offsetlab (format v{v}); this page reads v1"
                ),
            ));
        }
    }
    Ok(None)
}

fn decode_v1(payload: &str) -> Result<Document, LinkError> {
    if payload.is_empty() {
        return Err(err("link-empty", "the link's payload after `v1.` is empty"));
    }
    let packed = URL_SAFE_NO_PAD_INDIFFERENT.decode(payload).map_err(|e| {
        err(
            "link-base64",
            format!("the link is damaged (not base64url: {e}); was it cut short or edited?"),
        )
    })?;
    let json = miniz_oxide::inflate::decompress_to_vec_with_limit(&packed, MAX_INFLATED).map_err(
        |e| match e.status {
            TINFLStatus::HasMoreOutput => err(
                "link-too-large",
                format!("the link's document is larger than {MAX_INFLATED} bytes"),
            ),
            _ => err(
                "link-deflate",
                "the link is damaged (its compressed data does not decompress); was it cut short?",
            ),
        },
    )?;
    let text = String::from_utf8(json)
        .map_err(|_| err("link-utf8", "the link's document is not UTF-8 text"))?;
    let value: serde_json::Value = serde_json::from_str(&text)
        .map_err(|e| err("link-json", format!("the link's document is not JSON: {e}")))?;
    Document::from_value(value).map_err(|e| err("link-document", e.to_string()))
}

fn shorten(s: &str) -> String {
    let mut out: String = s.chars().take(40).collect();
    if s.chars().count() > 40 {
        out.push('…');
    }
    out
}

fn decode_plain(fragment: &str) -> Result<Link, LinkError> {
    let mut doc = Document::default();
    let mut embed = false;
    let mut offsets = Vec::new();
    let mut tools = Vec::new();
    let mut seen: Vec<&str> = Vec::new();
    let mut view: Option<ViewState> = None;
    let mut pairs = Vec::new();
    for part in fragment.split('&').filter(|p| !p.is_empty()) {
        let Some((key, raw)) = part.split_once('=') else {
            return Err(err(
                "link-plain",
                format!(
                    "`{}` is not a key=value pair (a compact link starts with v1.)",
                    shorten(part)
                ),
            ));
        };
        let value = percent_decode_str(raw).decode_utf8().map_err(|_| {
            err(
                "link-plain",
                format!("the value of `{key}` is not UTF-8 after percent-decoding"),
            )
        })?;
        if !PLAIN_KEYS.contains(&key) && !is_setting(key) {
            return Err(err(
                "link-plain",
                format!(
                    "unknown key `{}` (keys: {}, or the name of a setting)",
                    shorten(key),
                    PLAIN_KEYS.join(", ")
                ),
            ));
        }
        if key != "offset" && key != "tool" {
            if seen.contains(&key) {
                return Err(err("link-plain", format!("`{key}` is given twice")));
            }
            seen.push(key);
        }
        pairs.push((key, value.into_owned()));
    }
    if pairs.is_empty() {
        return Err(err("link-empty", "the link carries no document"));
    }
    let bad = |key: &str, value: &str, want: &str| {
        err(
            "link-plain",
            format!("{key}=`{}`: expected {want}", shorten(value)),
        )
    };
    let number = |key: &str, value: &str| -> Result<f64, LinkError> {
        value
            .trim()
            .parse::<f64>()
            .ok()
            .filter(|v| v.is_finite())
            .ok_or_else(|| bad(key, value, "a number"))
    };
    let units = |key: &str, v: &str| match v {
        "mm" => Ok(Units::Mm),
        "inch" => Ok(Units::Inch),
        _ => Err(bad(key, v, "mm or inch")),
    };
    let s = &mut doc.setup;
    let mut settings = serde_json::Map::new();
    for (key, value) in &pairs {
        let v = value.as_str();
        match *key {
            "program" => doc.program = value.clone(),
            "machine" => {
                s.machine = match v {
                    "mill" => MachineKind::Mill,
                    "lathe" => MachineKind::Lathe,
                    _ => return Err(bad(key, v, "mill or lathe")),
                }
            }
            "units" => s.units = units(key, v)?,
            "offset" => offsets.push(v.to_string()),
            "tool" => tools.push(v.to_string()),
            "tool_table" => {
                let units = s.tool_table.as_ref().and_then(|t| t.units);
                let table = ToolTable::from_text(v).map_err(|e| err("link-plain", e))?;
                s.tool_table = Some(ToolTable { units, ..table });
            }
            // Units alone would make an empty table that refuses every T.
            "tool_table_units" if !seen.contains(&"tool_table") => {
                return Err(err(
                    "link-plain",
                    "tool_table_units= gives the units of the link's tool table: give tool_table= too",
                ));
            }
            "tool_table_units" => {
                s.tool_table.get_or_insert_with(ToolTable::default).units = Some(units(key, v)?);
            }
            "decimal_input" => {
                s.settings.decimal_input = match v {
                    "increment" => Some(DecimalInput::Increment),
                    "calculator" => Some(DecimalInput::Calculator),
                    _ => return Err(bad(key, v, "increment or calculator")),
                }
            }
            "block_skip" => {
                s.settings.block_skip = match v {
                    "1" | "on" | "true" => true,
                    "0" | "off" | "false" => false,
                    _ => return Err(bad(key, v, "1 or 0")),
                }
            }
            "length_offset_without_z" => {
                s.settings.length_offset_without_z = match v {
                    "move" => Some(LengthOffsetWithoutZ::Move),
                    "next_z" => Some(LengthOffsetWithoutZ::NextZ),
                    _ => return Err(bad(key, v, "move or next_z")),
                }
            }
            "lathe_x_offset" => {
                s.settings.lathe_x_offset = match v {
                    "diameter" => LatheXOffset::Diameter,
                    "radius" => LatheXOffset::Radius,
                    _ => return Err(bad(key, v, "diameter or radius")),
                }
            }
            "mirror" => {
                let mut m = Mirror::default();
                for a in v
                    .split(',')
                    .flat_map(|p| p.chars())
                    .filter(|c| !c.is_whitespace())
                {
                    match a.to_ascii_lowercase() {
                        'x' => m.x = true,
                        'y' => m.y = true,
                        _ => return Err(bad(key, v, "x, y or x,y")),
                    }
                }
                s.settings.mirror = m;
            }
            "start" => {
                let p: Vec<&str> = v.split(',').collect();
                if p.len() != 3 {
                    return Err(bad(key, v, "three numbers x,y,z"));
                }
                s.start = Position {
                    x: number(key, p[0])?,
                    y: number(key, p[1])?,
                    z: number(key, p[2])?,
                };
            }
            "plane" => {
                let plane =
                    ViewPlane::parse(v).ok_or_else(|| bad(key, v, "XY, XZ, YZ, 3D, ZX or XC"))?;
                view.get_or_insert_with(ViewState::default).plane = plane;
            }
            "angles" => {
                let p: Vec<&str> = v.split(',').collect();
                if p.len() != 2 {
                    return Err(bad(key, v, "two numbers yaw,pitch (degrees)"));
                }
                let view = view.get_or_insert_with(ViewState::default);
                view.angles = Some([number(key, p[0])?, number(key, p[1])?]);
            }
            "zoom" => view.get_or_insert_with(ViewState::default).zoom = number(key, v)?,
            "pan" => {
                let p: Vec<&str> = v.split(',').collect();
                if p.len() != 2 {
                    return Err(bad(key, v, "two numbers h,v"));
                }
                view.get_or_insert_with(ViewState::default).pan =
                    [number(key, p[0])?, number(key, p[1])?];
            }
            "swept" => {
                view.get_or_insert_with(ViewState::default).swept = match v.trim() {
                    "1" | "true" | "on" => true,
                    "0" | "false" | "off" => false,
                    _ => return Err(bad(key, v, "1 or 0")),
                }
            }
            "legend" => {
                view.get_or_insert_with(ViewState::default).legend = match v.trim() {
                    "1" | "true" | "on" => true,
                    "0" | "false" | "off" => false,
                    _ => return Err(bad(key, v, "1 or 0")),
                }
            }
            "step" => {
                doc.step = Some(
                    v.trim()
                        .parse::<u32>()
                        .map_err(|_| bad(key, v, "a block number 0, 1, 2 …"))?,
                )
            }
            "embed" => {
                embed = match v {
                    "1" | "true" => true,
                    "0" | "false" => false,
                    _ => return Err(bad(key, v, "1 or 0")),
                }
            }
            // A setting named by its field (checked by `is_setting` above).
            _ => {
                settings.insert(key.to_string(), setting_value(v));
            }
        }
    }
    if !settings.is_empty() {
        let mut all = match serde_json::to_value(&s.settings) {
            Ok(serde_json::Value::Object(fields)) => fields,
            _ => serde_json::Map::new(),
        };
        all.extend(settings);
        s.settings = serde_json::from_value(serde_json::Value::Object(all))
            .map_err(|e| err("link-plain", format!("settings: {e}")))?;
    }
    // Registers are read once the machine is known, whatever the key order.
    for spec in offsets {
        let spec = spec.replacen(':', "=", 1);
        doc.setup
            .set_register(&spec)
            .map_err(|e| err("link-plain", e))?;
    }
    // The tool list (behaviour 9.9): `tool=NN:D10,L120`, repeatable.
    for spec in tools {
        let spec = spec.replacen(':', "=", 1);
        doc.setup
            .set_tool(&spec)
            .map_err(|e| err("link-plain", e))?;
    }
    if doc.setup.machine == MachineKind::Lathe
        && let Some(v) = &mut view
        && !seen.contains(&"plane")
    {
        v.plane = ViewPlane::ZX;
    }
    doc.view = view;
    let document = doc
        .validated()
        .map_err(|e| err("link-document", e.to_string()))?;
    Ok(Link { document, embed })
}

/// True if `key` names a field of the setup's settings (the setup document
/// is the one list of them: a new setting is a plain-link key with nothing
/// added here).
fn is_setting(key: &str) -> bool {
    let probe = serde_json::json!({ key: null });
    match serde_json::from_value::<crate::setup::Settings>(probe) {
        Ok(_) => true,
        Err(e) => !e.to_string().starts_with("unknown field"),
    }
}

/// A plain-link value as the JSON value of a setting: a number or a boolean
/// when it reads as one, else the text (`fanuc`, `last_wins`).
fn setting_value(v: &str) -> serde_json::Value {
    let t = v.trim();
    match t {
        "true" => return serde_json::Value::Bool(true),
        "false" => return serde_json::Value::Bool(false),
        _ => {}
    }
    match t.parse::<f64>().ok().and_then(serde_json::Number::from_f64) {
        Some(n) if !t.is_empty() => serde_json::Value::Number(n),
        _ => serde_json::Value::String(t.to_string()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::setup::Setup;

    fn square() -> Document {
        let mut s = Setup::default();
        s.set_register("01=6").unwrap();
        Document {
            setup: s,
            program: "G91 G00 G46 X30. Y20. D01;\nG01 G47 X80. F200.;".into(),
            view: Some(ViewState {
                plane: ViewPlane::XY,
                zoom: 2.0,
                pan: [5.0, -5.0],
                angles: None,
                swept: true,
                legend: false,
            }),
            step: Some(1),
        }
    }

    #[test]
    fn compact_round_trip() {
        let d = square();
        let l = link(DEFAULT_BASE, &d, false).unwrap();
        assert!(l.starts_with("http://127.0.0.1:8000/#v1."));
        let back = decode(&l).unwrap();
        assert_eq!(back.document, d);
        assert!(!back.embed);
        let back = decode(&format!("{l}&embed=1")).unwrap();
        assert!(back.embed);
    }

    #[test]
    fn plain_round_trip() {
        let d = square();
        let p = encode_plain(&d, true);
        assert!(
            p.starts_with("program=G91%20G00%20G46%20X30.%20Y20.%20D01;%0AG01"),
            "{p}"
        );
        assert!(p.contains("offset=01:6"), "{p}");
        let back = decode(&format!("#{p}")).unwrap();
        assert_eq!(back.document, d);
        assert!(back.embed);
    }

    #[test]
    fn plain_form_written_by_hand() {
        let l =
            decode("#program=G50%20X120.%20Z60.%0AT0108&offset=08:X0.4,Z-0.2&machine=lathe&step=1")
                .unwrap();
        let d = l.document;
        assert_eq!(d.setup.machine, MachineKind::Lathe);
        assert_eq!(d.setup.lathe_register(8).x_value(), 0.4);
        assert_eq!(d.program, "G50 X120. Z60.\nT0108");
        assert_eq!(d.step, Some(1));
        // A plus sign is a plus sign.
        let d = decode("#program=G91%20X+10.").unwrap().document;
        assert_eq!(d.program, "G91 X+10.");
    }

    #[test]
    fn behaviour9_every_setting_is_a_plain_key_by_its_name() {
        use crate::setup::{Control, GCodeSystem, SameGroupCodes};
        let l = decode(
            "#program=G00%20X1.&control=haas&same_group_codes=error&gcode_system=B&peck_retract=0.5&machine=lathe",
        )
        .unwrap();
        let st = &l.document.setup.settings;
        assert_eq!(st.control, Control::Haas);
        assert_eq!(st.same_group_codes, Some(SameGroupCodes::Error));
        assert_eq!(st.gcode_system, Some(GCodeSystem::B));
        assert_eq!(st.peck_retract, Some(0.5));
        // Written back by name in alphabetical order, each only when set.
        let p = encode_plain(&l.document, false);
        assert!(
            p.ends_with("&control=haas&gcode_system=B&peck_retract=0.5&same_group_codes=error"),
            "{p}"
        );
        assert_eq!(decode(&p).unwrap().document, l.document);
        let e = decode("#program=G00&control=siemens").unwrap_err();
        assert_eq!(e.code, "link-plain");
        assert!(e.message.contains("unknown variant `siemens`"), "{e}");
        let e = decode("#program=G00&colour=red").unwrap_err();
        assert!(e.message.contains("or the name of a setting"), "{e}");
    }

    #[test]
    fn every_malformed_class_has_its_own_error() {
        let code = |s: &str| decode(s).unwrap_err().code;
        assert_eq!(code(""), "link-empty");
        assert_eq!(code("http://x/#"), "link-empty");
        assert_eq!(code("#v1."), "link-empty");
        assert_eq!(code("#v2.abc"), "link-version");
        assert_eq!(code("#v1.!!!"), "link-base64");
        assert_eq!(code("#v1.AAAA"), "link-deflate");
        let full = encode(&square());
        // Cut short by whole base64 quads: valid base64, truncated deflate.
        let payload = &full[V1.len()..];
        let keep = (payload.len() - 8) / 4 * 4;
        assert_eq!(code(&format!("v1.{}", &payload[..keep])), "link-deflate");
        let bomb = URL_SAFE_NO_PAD.encode(miniz_oxide::deflate::compress_to_vec(
            &vec![b' '; MAX_INFLATED + 10],
            9,
        ));
        assert_eq!(code(&format!("v1.{bomb}")), "link-too-large");
        let not_utf8 =
            URL_SAFE_NO_PAD.encode(miniz_oxide::deflate::compress_to_vec(&[0xff, 0xfe], 9));
        assert_eq!(code(&format!("v1.{not_utf8}")), "link-utf8");
        let not_json = URL_SAFE_NO_PAD.encode(miniz_oxide::deflate::compress_to_vec(b"{nope", 9));
        assert_eq!(code(&format!("v1.{not_json}")), "link-json");
        let bad_doc = URL_SAFE_NO_PAD.encode(miniz_oxide::deflate::compress_to_vec(
            br#"{"offsets":{"01":5000}}"#,
            9,
        ));
        assert_eq!(code(&format!("v1.{bad_doc}")), "link-document");
        assert_eq!(code("#program=G00&colour=red"), "link-plain");
        assert_eq!(code("#program=G00&machine=<script>"), "link-plain");
        assert_eq!(code("#program=%FF"), "link-plain");
        assert_eq!(code("#hello"), "link-plain");
        assert_eq!(code("#program=G00&step=-1"), "link-plain");
        assert_eq!(code("#program=G00&offset=01:1000"), "link-document");
        assert_eq!(code(&"v1.".repeat(MAX_LINK)), "link-too-long");
    }

    #[test]
    fn bases_must_be_http() {
        assert!(link("javascript:alert(1)//", &square(), false).is_err());
        assert!(link("https://example.org/play/", &square(), false).is_ok());
        assert!(link("https://example.org/#x", &square(), false).is_err());
    }
}
