//! Share links and documents (issue 5) as JavaScript sees them: the
//! exports that encode, decode, read and write them, each answer checked
//! against the native one.

use super::*;
use offsetlab::Document;
use offsetlab::share;
use offsetlab::wasm::{
    decode_link, document_json, encode_link, encode_plain, link_limits, read_document,
};

/// A document JS holds, read back natively.
fn native(value: &JsValue) -> Document {
    Document::from_json(&stringify(value)).expect("a valid document")
}

#[wasm_bindgen_test]
fn document_is_program_setup_view_and_step() {
    let mut s = Session::new();
    run(&mut s, SQUARE, square_setup());
    // The machine's default view and no current block: both null.
    let d = s.document().expect("document");
    assert_keys(
        &d,
        &["version", "machine", "offsets", "program", "view", "step"],
    );
    assert_eq!(string(&d, "program"), SQUARE);
    assert_eq!(num(&get(&d, "offsets"), "01"), 6.0);
    assert!(get(&d, "view").is_null() && get(&d, "step").is_null());
    // Another plane, a zoom and a current block are carried; the zoom is
    // rounded to six significant digits, the pan to 1e-4.
    s.set_view(json(
        r#"{"plane":"XZ","zoom":1.23456789,"pan":[0.123456,-2],"step":3}"#,
    ))
    .expect("set_view");
    let d = s.document().expect("document");
    let view = get(&d, "view");
    assert_keys(&view, &["plane", "zoom", "pan"]);
    assert_eq!(string(&view, "plane"), "XZ");
    assert_eq!(num(&view, "zoom"), 1.23457);
    assert_eq!(pan_of(&view), (0.1235, -2.0));
    assert_eq!(num(&d, "step"), 3.0);
    let doc = native(&d);
    assert_eq!(doc.step, Some(3));
    assert_eq!(doc.setup.mill_value(1), 6.0);
}

#[wasm_bindgen_test]
fn links_round_trip_through_the_exports() {
    let mut s = Session::new();
    run(&mut s, SQUARE, square_setup());
    s.set_view(json(r#"{"plane":"YZ","step":2}"#))
        .expect("set_view");
    let d = s.document().expect("document");
    let link = encode_link(share::DEFAULT_BASE, d.clone(), false).expect("encode");
    assert!(link.starts_with("http://127.0.0.1:8000/#v1."), "{link}");
    // The same text as the native codec makes (the CLI's).
    assert_eq!(
        link,
        share::link(share::DEFAULT_BASE, &native(&d), false).expect("native")
    );
    let back = decode_link(&link).expect("decode");
    assert_keys(&back, &["document", "embed"]);
    assert!(has(&back, "error") && get(&back, "error").is_null());
    assert_eq!(get(&back, "embed").as_bool(), Some(false));
    assert_eq!(stringify(&get(&back, "document")), stringify(&d));
    // Embed, and the plain form (no `#`), which JSON text also feeds.
    let embedded = encode_link("https://example.org/lab/", d.clone(), true).expect("encode");
    assert!(embedded.ends_with("&embed=1"));
    assert_eq!(
        get(&decode_link(&embedded).expect("decode"), "embed").as_bool(),
        Some(true)
    );
    let plain = encode_plain(JsValue::from_str(&stringify(&d)), true).expect("plain");
    assert!(plain.starts_with("program=(SEED%20000:"), "{plain}");
    assert!(plain.contains("&offset=01:6&") && plain.contains("&plane=YZ&step=2&embed=1"));
    let back = decode_link(&format!("#{plain}")).expect("decode");
    assert_eq!(get(&back, "embed").as_bool(), Some(true));
    assert_eq!(native(&get(&back, "document")), native(&d));
}

#[wasm_bindgen_test]
fn encoding_a_bad_document_or_base_is_an_error_not_a_panic() {
    let good = json(r#"{"program":"G00 X1."}"#);
    assert!(encode_link("javascript:alert(1)//", good.clone(), false).is_err());
    assert!(encode_link("http://x/", json(r#"{"offsets":{"01":5000}}"#), false).is_err());
    assert!(encode_plain(json(r#"{"programme":"G00"}"#), false).is_err());
    assert!(encode_plain(JsValue::from_f64(3.0), false).is_err());
    assert!(document_json(JsValue::from_str("{ nope")).is_err());
    assert!(encode_link("http://x/", good, false).is_ok());
}

#[wasm_bindgen_test]
fn a_malformed_link_is_an_error_value_with_its_code() {
    let payload =
        encode_link("http://x/", json(r#"{"program":"G00 X1. Y2."}"#), false).expect("encode");
    let payload = payload.split_once('#').expect("#").1.to_owned();
    let cut = &payload[..payload.len() - 8];
    let cases = [
        ("", "link-empty"),
        ("http://x/#v1.", "link-empty"),
        ("#v9.abc", "link-version"),
        ("#v1.!!!!", "link-base64"),
        ("#v1.AAAA", "link-deflate"),
        (cut, "link-deflate"),
        ("#program=G00&colour=red", "link-plain"),
        (
            "#program=G00&machine=<script>alert(1)</script>",
            "link-plain",
        ),
        ("#program=G00&offset=01:1000", "link-document"),
        ("#hello", "link-plain"),
    ];
    for (text, code) in cases {
        let r = decode_link(text).expect("never throws");
        assert_keys(&r, &["embed", "error"]);
        assert!(get(&r, "document").is_null(), "{text}");
        assert_eq!(get(&r, "embed").as_bool(), Some(false));
        let e = get(&r, "error");
        assert_keys(&e, &["code", "message"]);
        assert_eq!(string(&e, "code"), code, "{text}");
        assert!(!string(&e, "message").is_empty());
    }
    let long = "v1.".repeat(share::MAX_LINK);
    assert_eq!(
        string(&get(&decode_link(&long).expect("decode"), "error"), "code"),
        "link-too-long"
    );
}

#[wasm_bindgen_test]
fn golden_links_decode_in_wasm_to_the_native_documents() {
    let table: serde_json::Value =
        serde_json::from_str(include_str!("../data/golden_links.json")).expect("golden table");
    let table = table.as_array().expect("array");
    assert!(table.len() >= 9);
    for entry in table {
        let name = entry["name"].as_str().expect("name");
        let link = entry["link"].as_str().expect("link");
        let r = decode_link(link).expect("decode");
        assert!(get(&r, "error").is_null(), "{name}: {}", stringify(&r));
        let decoded = native(&get(&r, "document"));
        let want = Document::from_value(entry["document"].clone()).expect("golden document");
        assert_eq!(decoded, want, "{name}");
        assert_eq!(
            decoded,
            share::decode(link).expect("native").document,
            "{name}"
        );
        assert_eq!(
            get(&r, "embed").as_bool(),
            Some(link.contains("embed=1")),
            "{name}"
        );
    }
}

#[wasm_bindgen_test]
fn document_files_read_and_write() {
    let mut s = Session::new();
    run(&mut s, SQUARE, square_setup());
    s.set_step(4);
    let text = document_json(s.document().expect("document")).expect("json");
    assert!(text.contains("\n  \"program\": "), "indented: {text}");
    let r = read_document(&text).expect("read");
    assert!(get(&r, "error").is_null());
    assert_eq!(num(&get(&r, "document"), "step"), 4.0);
    // A setup document is a document without a program.
    let r = read_document(r#"{"machine":"lathe"}"#).expect("read");
    assert_eq!(string(&get(&r, "document"), "machine"), "lathe");
    for (text, code) in [
        ("{ nope", "setup-syntax"),
        (r#"{"offsets":{"01":5000}}"#, "setup-range"),
        ("[1]", "setup-syntax"),
    ] {
        let r = read_document(text).expect("never throws");
        assert!(get(&r, "document").is_null());
        assert_eq!(string(&get(&r, "error"), "code"), code, "{text}");
    }
    let limits = link_limits().expect("limits");
    assert_eq!(num(&limits, "long"), 8000.0);
    assert_eq!(num(&limits, "max"), share::MAX_LINK as f64);
    assert_eq!(string(&limits, "default_base"), "http://127.0.0.1:8000/");
}
