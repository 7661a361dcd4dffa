//! The promise of issue 5: links made by any released version decode
//! forever. `tests/data/golden_links.json` is a table of links made by
//! version 1 with the documents they carry; it is only ever appended to.
#![cfg(not(target_arch = "wasm32"))]

use offsetlab::Document;
use offsetlab::share::decode;
use serde_json::Value;

#[test]
fn golden_links_decode_to_the_same_documents() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/golden_links.json");
    let table: Vec<Value> = serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    assert!(table.len() >= 9);
    for entry in table {
        let name = entry["name"].as_str().unwrap();
        let link = entry["link"].as_str().unwrap();
        let decoded = decode(link).unwrap_or_else(|e| panic!("{name}: {e}"));
        let want = Document::from_value(entry["document"].clone()).unwrap();
        assert_eq!(decoded.document, want, "{name}");
        assert_eq!(decoded.embed, link.contains("embed=1"), "{name}");
    }
}
