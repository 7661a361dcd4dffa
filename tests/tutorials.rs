//! `docs/tutorials.md` promises working examples: every link in it (the
//! `<iframe>` sources with `&amp;` read as `&`, and the plain links) decodes
//! with the codec the page uses, and its program runs without an error.
#![cfg(not(target_arch = "wasm32"))]

use offsetlab::share::{self, DEFAULT_BASE};
use offsetlab::{MachineKind, Severity};

fn tutorial_links() -> Vec<String> {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/docs/tutorials.md");
    let text = std::fs::read_to_string(path).expect("docs/tutorials.md");
    let text = text.replace("&amp;", "&");
    let start = format!("{DEFAULT_BASE}#");
    let mut links = Vec::new();
    let mut rest = text.as_str();
    while let Some(i) = rest.find(&start) {
        let tail = &rest[i..];
        let end = tail
            .find(|c: char| c.is_whitespace() || matches!(c, '"' | '\'' | '`' | '<' | '>' | ')'))
            .unwrap_or(tail.len());
        links.push(tail[..end].to_string());
        rest = &tail[end..];
    }
    links
}

#[test]
fn every_link_in_the_tutorial_decodes_and_runs_without_errors() {
    let links = tutorial_links();
    assert!(links.len() >= 8, "{} links", links.len());
    let mut embedded = 0;
    let mut compact = 0;
    let mut lathe = 0;
    for link in &links {
        let decoded = share::decode(link).unwrap_or_else(|e| panic!("{link}\n{e}"));
        let doc = decoded.document;
        assert!(!doc.program.is_empty(), "{link}");
        let run = offsetlab::run(&doc.program, &doc.setup);
        let errors: Vec<_> = run
            .diagnostics
            .iter()
            .filter(|d| d.severity == Severity::Error)
            .collect();
        assert!(errors.is_empty(), "{link}\n{errors:?}");
        if let Some(step) = doc.step {
            assert!((step as usize) < run.blocks.len(), "{link}: step {step}");
        }
        embedded += usize::from(decoded.embed);
        compact += usize::from(link.contains("#v1."));
        lathe += usize::from(doc.setup.machine == MachineKind::Lathe);
    }
    assert_eq!(embedded, 2, "the two <iframe> examples");
    assert_eq!(compact, 1);
    assert_eq!(lathe, 1);
}

#[test]
fn the_tutorial_examples_say_what_their_text_says() {
    let links = tutorial_links();
    let doc = |needle: &str| {
        let link = links
            .iter()
            .find(|l| l.contains(needle))
            .unwrap_or_else(|| panic!("no link with {needle}"));
        share::decode(link).unwrap().document
    };
    // The two iframes carry the same square, D01 = 6, at the third block.
    let plain = doc("step=2&embed=1");
    let compact = doc("#v1.");
    assert_eq!(plain.setup.mill_value(1), 6.0);
    assert_eq!(compact.setup.mill_value(1), 6.0);
    assert_eq!((plain.step, compact.step), (Some(2), Some(2)));
    // "The same frame": the same program too (issue 23 found the compact
    // one carrying another text of the square).
    assert_eq!(plain.program, compact.program);
    // Wear: D02 reads 4.9.
    assert!((doc("offset=02:5,W-0.1").setup.mill_value(2) - 4.9).abs() < 1e-9);
    // Blocks ended by `;`: seven blocks.
    let length = doc("plane=XZ");
    assert_eq!(
        offsetlab::run(&length.program, &length.setup).blocks.len(),
        7
    );
    // Block skip drops the `/` block; calculator input reads Y25 as 25 mm.
    let settings = doc("block_skip=1");
    let run = offsetlab::run(&settings.program, &settings.setup);
    assert_eq!(run.blocks.len(), 3);
    assert_eq!(run.blocks[1].state.programmed[1], 25.0);
}
