//! docs/behaviour.md lists, under each rule, the tests that check it as
//! `FILE::name` (a test module inside a source file as `FILE::tests::name`).
//! Every one of them must exist, or the rule book points at nothing.
#![cfg(not(target_arch = "wasm32"))]

use std::path::Path;

#[test]
fn every_test_the_rule_book_names_exists() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let book = std::fs::read_to_string(root.join("docs/behaviour.md")).unwrap();
    let mut named = 0;
    let mut missing = Vec::new();
    for line in book.lines() {
        let Some(rest) = line.strip_prefix("- `") else {
            continue;
        };
        let Some(end) = rest.find('`') else { continue };
        let cited = &rest[..end];
        let Some((file, path)) = cited.split_once(".rs::") else {
            continue;
        };
        let file = format!("{file}.rs");
        let name = path.rsplit("::").next().unwrap_or(path);
        named += 1;
        let text = std::fs::read_to_string(root.join(&file)).unwrap_or_default();
        if !text.contains(&format!("fn {name}(")) {
            missing.push(format!("{file}::{path}"));
        }
    }
    assert!(named > 200, "only {named} tests named");
    assert!(
        missing.is_empty(),
        "named in docs/behaviour.md but not found:\n{}",
        missing.join("\n")
    );
}
