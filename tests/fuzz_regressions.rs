//! Every input the fuzz targets (fuzz/, scripts/fuzz.sh) found a crash or a
//! broken invariant with, replayed natively through the same checks the
//! fuzzer runs (`fuzz/common/mod.rs`), and a direct test of each fix.
//!
//! Crash inputs live in `tests/data/fuzz/<target>/`, one file each, as the
//! fuzzer wrote them (minimized); a new one is replayed by dropping it there.
#![cfg(not(target_arch = "wasm32"))]

#[path = "../fuzz/common/mod.rs"]
mod fuzz_common;

use std::path::Path;

use offsetlab::share;
use offsetlab::{Document, Setup};

fn replay(target: &str, check: fn(&[u8])) -> usize {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/fuzz")
        .join(target);
    let mut n = 0;
    let Ok(entries) = std::fs::read_dir(&dir) else {
        return 0; // no finding for this target (git keeps no empty folder)
    };
    for entry in entries {
        let path = entry.unwrap().path();
        let data = std::fs::read(&path).unwrap();
        eprintln!("replaying {}", path.display());
        check(&data);
        n += 1;
    }
    n
}

#[test]
fn every_link_finding_replays_clean() {
    assert!(replay("link", fuzz_common::check_link) >= 1);
}

#[test]
fn every_run_finding_replays_clean() {
    replay("run", fuzz_common::check_run);
}

#[test]
fn every_parse_finding_replays_clean() {
    replay("parse", fuzz_common::check_parse);
}

/// Finding 1 (link target, `float-roundtrip-g55`): a setup value that needs
/// 17 significant digits (G55 X 3764.1529211279635) came back from a link
/// one unit in the last place off, because serde_json's default float
/// parser is not correctly rounded. Fixed by serde_json's
/// `float_roundtrip` feature: every number of a document (links, setup
/// files, the page's saved state) now reads back exactly as written.
#[test]
fn link_values_with_seventeen_digits_round_trip_exactly() {
    let mut setup = Setup::default();
    setup.work_offsets.g55.x = 3764.1529211279635;
    setup.start.y = 0.1 + 0.2;
    setup.set_register("01=6.581910000000001").unwrap();
    let doc = Document::new(setup, "G55 G00 X0 Y0");
    let back = share::decode(&share::encode(&doc)).unwrap().document;
    assert_eq!(back, doc);
    assert_eq!(
        back.setup.work_offsets.g55.x.to_bits(),
        3764.1529211279635f64.to_bits()
    );
    let plain = share::decode(&share::encode_plain(
        &Document::new(doc.setup.clone(), "X1"),
        false,
    ));
    assert_eq!(plain.unwrap().document.setup.start.y, 0.1 + 0.2);
    let json = Setup::from_json(&doc.setup.to_json()).unwrap();
    assert_eq!(json, doc.setup);
}

/// Finding 2 (run target, `lathe-r-arc-without-chord`): on the lathe an R
/// arc whose end is its start (`G02 R0.1` with no X/Z) went through the R
/// construction with a chord of length 0, whose normal is 0/0: the arc's
/// centre, start angle and sweep were NaN, written as `null` into the JSON
/// and as NaN into the toolpath the canvas draws. Fixed at two depths:
/// `arc::from_radius` refuses a zero chord (`ArcError::NoChord`, so no
/// caller can get a NaN centre; on the mill an offset that shrinks the
/// actual chord to nothing is now an `arc-radius` error), and the lathe
/// treats that block like the mill does: warning `arc-r-no-motion`, no arc.
#[test]
fn a_lathe_r_arc_from_a_point_to_itself_is_a_warning_not_a_nan() {
    let mut setup = Setup {
        machine: offsetlab::MachineKind::Lathe,
        ..Setup::default()
    };
    setup.set_register("01=X0.4,Z0.1").unwrap();
    let r = offsetlab::run("G02 R0.1 F8.\nG01 X10. Z-5. T0101\nG03 R1.", &setup);
    let codes: Vec<_> = r.diagnostics.iter().map(|d| (d.code, d.line)).collect();
    assert_eq!(codes, [("arc-r-no-motion", 1), ("arc-r-no-motion", 3)]);
    assert_eq!(r.moves.len(), 1, "{:?}", r.moves);
    let t = offsetlab::Toolpath::from_run(&r);
    assert!(t.actual.iter().chain(&t.programmed).all(|v| v.is_finite()));
    fuzz_common::check_run_with(&setup, "G02 R0.1 F8.\nG01 X10. Z-5. T0101\nG03 R1.", 1000);
}

// The fuzz targets' checks as property tests, so that `cargo test` (stable,
// no cargo-fuzz) exercises the same invariants on fresh inputs every run:
// a setup header of random bytes and G-code-like text or any bytes.
proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(128))]

    #[test]
    fn the_run_target_holds_on_gcode_like_programs(
        header in proptest::collection::vec(proptest::prelude::any::<u8>(), fuzz_common::HEADER),
        text in "([GMXYZUWIJKRDHTFSPQLNO][-+]?[0-9]{0,6}[.]?[0-9]{0,4}[ ;\n]{0,2}|[()%/\r]){0,80}",
    ) {
        let mut data = header;
        data.extend_from_slice(text.as_bytes());
        fuzz_common::check_run(&data);
    }

    #[test]
    fn the_run_and_parse_targets_hold_on_any_bytes(
        data in proptest::collection::vec(proptest::prelude::any::<u8>(), 0..400),
    ) {
        fuzz_common::check_run(&data);
        fuzz_common::check_parse(&data);
    }

    #[test]
    fn the_link_target_holds_on_any_text(text in "(#v1\\.|#program=|&offset=)?\\PC{0,120}") {
        fuzz_common::check_link(text.as_bytes());
    }
}
