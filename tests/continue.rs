//! Continue past errors (behaviour 2.24, setting 7.48): with the setting on,
//! a block the run cannot run is reported and skipped, the machine goes on
//! from the state it had before that block, and the rest is drawn; the
//! limits and a subprogram without M99 still stop the run.

mod common;
use common::same;
use offsetlab::report::Run;
use offsetlab::view::summary;
use offsetlab::{
    Checkpoints, Earlier, End, RunOptions, Setup, report_at, rerun_observed, run, run_observed,
    run_with,
};

fn keep_going() -> Setup {
    let mut s = Setup::default();
    s.settings.continue_past_errors = true;
    s
}

fn codes(r: &Run) -> Vec<&'static str> {
    r.diagnostics.iter().map(|d| d.code).collect()
}

/// An unknown G code mid-way (line 4). Worked by hand:
/// line 1 G90 G00 to X0 Y0 Z10; line 2 G01 X10 F100 (feed 10 mm);
/// line 3 G91, nothing moves; line 4 `G99.9 X5.` cannot run: skipped, so
/// X stays 10 and the modes stay G01 G91 F100; line 5 X5. is incremental
/// from 10: X15; line 6 Y10.: Y10; line 7 G90 X0: X0; M30.
/// Moves: 1 rapid (Z0 → Z10, 10 mm) + 4 feeds (10 + 5 + 10 + 15 = 40 mm).
const UNKNOWN_MID_WAY: &str =
    "G90 G00 X0 Y0 Z10.\nG01 X10. F100.\nG91\nG99.9 X5.\nX5.\nY10.\nG90 X0\nM30\n";

#[test]
fn behaviour2_24_an_unknown_g_code_is_skipped_and_the_rest_drawn() {
    // Off (the default): the run stops at line 4, as a control does (2.1).
    let off = run(UNKNOWN_MID_WAY, &Setup::default());
    assert_eq!(off.end, End::Error { line: 4 });
    assert_eq!(off.block_count, 3);
    assert_eq!(off.skipped, 0);

    let r = run(UNKNOWN_MID_WAY, &keep_going());
    assert_eq!(r.end, End::ProgramEnd { line: 8 });
    // Seven blocks ran: lines 1, 2, 3, 5, 6, 7, 8.
    let lines: Vec<u32> = r.blocks.iter().map(|b| b.span.line).collect();
    assert_eq!(lines, [1, 2, 3, 5, 6, 7, 8]);
    assert_eq!(r.skipped, 1);
    assert_eq!(codes(&r), ["unsupported-g-code", "block-skipped"]);
    assert_eq!(r.diagnostics[1].line, 4);
    // The modal state after the skipped block is the one before it: the
    // block on line 3 and the one on line 5 differ only by the X move.
    let before = &r.blocks[2].state;
    let after = &r.blocks[3].state;
    assert_eq!(before.modal, after.modal);
    assert_eq!(after.feed, Some(100.0));
    same(before.programmed, [10.0, 0.0, 10.0]);
    same(after.programmed, [15.0, 0.0, 10.0]);
    same(r.blocks[4].state.programmed, [15.0, 10.0, 10.0]);
    same(r.blocks[5].state.programmed, [0.0, 10.0, 10.0]);
    assert_eq!(r.move_count, 5);
    assert!((r.travel.rapid - 10.0).abs() < 1e-9, "{:?}", r.travel);
    assert!((r.travel.feed - 40.0).abs() < 1e-9, "{:?}", r.travel);
    let s = summary(&r);
    assert_eq!((s.skipped, s.errors, s.warnings), (1, 1, 1));
    let json = serde_json::to_value(&s).unwrap();
    assert_eq!(json["skipped"], 1);
}

/// A block that changes a mode and then fails changes nothing: F200 in the
/// arc block of line 2 (R 1 for a chord of 10: `arc-radius`) is not taken,
/// nor its G02; line 3 moves X5 at F100 in G01.
#[test]
fn behaviour2_24_a_failed_block_leaves_the_state_before_it() {
    let text = "G90 G01 X0 Y0 F100.\nF200. G02 X10. Y0 R1.\nG91 X5.\nM30\n";
    let r = run(text, &keep_going());
    assert_eq!(codes(&r), ["arc-radius", "block-skipped"]);
    let line3 = &r.blocks[1];
    assert_eq!(line3.span.line, 3);
    assert_eq!(line3.state.feed, Some(100.0));
    assert_eq!(line3.state.modal, {
        let mut m = r.blocks[0].state.modal;
        m.distance = line3.state.modal.distance;
        m
    });
    same(line3.state.programmed, [5.0, 0.0, 0.0]);
    assert_eq!(r.moves.len(), 1);
    assert_eq!(r.moves[0].kind, offsetlab::MoveKind::Feed);
}

/// A parse error in a block skips the block; a call to a program that is
/// not in the file is skipped too (the call is not made); each skipped
/// block has its error and a `block-skipped` warning.
#[test]
fn behaviour2_24_parse_errors_and_calls_that_fail_are_skipped() {
    let text = "G90 G01 X0 Y0 F100.\nX5. $$\nM98 P9999\nX10.\nM30\n";
    let r = run(text, &keep_going());
    assert_eq!(r.skipped, 2);
    let lines: Vec<u32> = r.blocks.iter().map(|b| b.span.line).collect();
    assert_eq!(lines, [1, 4, 5]);
    // Line 2's X5. did not run: line 4 moves from X0 to X10.
    assert_eq!(r.moves.len(), 1);
    same(r.moves[0].programmed_from, [0.0, 0.0, 0.0]);
    same(r.moves[0].programmed_to, [10.0, 0.0, 0.0]);
    let mut found = codes(&r);
    found.sort_unstable();
    assert_eq!(
        found,
        [
            "block-skipped",
            "block-skipped",
            "program-not-found",
            "unexpected-character"
        ]
    );
}

/// The limits still end the run: a runaway loop stops at the block limit
/// with the setting on, and a subprogram that ends without M99 stops.
#[test]
fn behaviour2_24_limits_and_a_missing_m99_still_stop() {
    let options = RunOptions {
        max_blocks: 50,
        ..RunOptions::default()
    };
    // M99 in the main program loops for ever as the control does (19.4,
    // setting 7.42 `loop`); the bad block in the loop is skipped each time
    // round and the limit ends it.
    let mut looping = keep_going();
    looping.settings.main_m99 = Some(offsetlab::setup::MainM99::Loop);
    let r = run_with("G91 G01 X1. F100.\nG99.9\nM99\n", &looping, options);
    assert!(codes(&r).contains(&"too-many-blocks"), "{:?}", codes(&r));
    assert!(matches!(r.end, End::Error { .. }));
    // Two blocks run per time round (lines 1 and 3) and one is skipped:
    // 50 blocks run, 25 times round, 25 skips.
    assert_eq!(r.block_count, 50);
    assert_eq!(r.skipped, 25);
    let r = run("M98 P10\nM30\nO0010\nG00 X1.\n", &keep_going());
    assert!(codes(&r).contains(&"missing-m99"), "{:?}", codes(&r));
    assert!(matches!(r.end, End::Error { .. }));
}

fn checkpointed(text: &str, setup: &Setup, every: u32) -> (Run, Checkpoints) {
    let options = RunOptions {
        keep_blocks: false,
        keep_moves: false,
        checkpoint_every: every,
        ..RunOptions::default()
    };
    run_observed(text, setup, options, &mut ())
}

/// Every block's report made again from the checkpoints equals the kept
/// one across skipped blocks, and a run made again after an edit equals
/// the whole run, the skipped count included (behaviour 10.1, 10.2).
#[test]
fn behaviour2_24_checkpoints_and_runs_made_again_see_the_same_skips() {
    let text =
        "G90 G01 X0 Y0 F100.\nG41 D01 X5.\nY5.\nG99.9 X7.\nX10.\nX12. $$\nY10.\nG40 X0 Y0\nM30\n";
    let mut setup = keep_going();
    setup.set_register("01=2.0").unwrap();
    let full = run(text, &setup);
    assert_eq!(full.skipped, 2);
    for every in [1, 2, 3, 100] {
        let (light, checkpoints) = checkpointed(text, &setup, every);
        assert_eq!(light.skipped, 2);
        assert_eq!(light.diagnostics, full.diagnostics);
        assert_eq!(light.block_count, full.block_count);
        for (i, kept) in full.blocks.iter().enumerate() {
            let again = report_at(text, &setup, &checkpoints, i as u32);
            assert_eq!(again.as_ref(), Some(kept), "block {i}, every {every}");
        }
    }
    // An edit after the first skip: made again, the same as whole.
    let (earlier, earlier_points) = checkpointed(text, &setup, 2);
    let edited = text.replace("Y10.", "Y11.");
    let (again, _, _) = rerun_observed(
        &edited,
        &setup,
        RunOptions {
            keep_blocks: false,
            keep_moves: false,
            checkpoint_every: 2,
            ..RunOptions::default()
        },
        Some(Earlier {
            text,
            run: &earlier,
            checkpoints: &earlier_points,
        }),
        &mut (),
    );
    let (whole, _) = checkpointed(&edited, &setup, 2);
    assert_eq!(again.skipped, whole.skipped);
    assert_eq!(again.diagnostics, whole.diagnostics);
    assert_eq!(again.block_count, whole.block_count);
    assert_eq!(again.bounds, whole.bounds);
}

/// `check --continue`: the skipped block's error and warning, and the
/// count at the end of the summary line; exit 1, for the program has an
/// error (behaviour 11).
#[test]
fn behaviour2_24_check_continue_says_how_many_blocks_were_skipped() {
    let dir = std::env::temp_dir().join(format!("offsetlab-continue-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("mid.nc");
    std::fs::write(&path, UNKNOWN_MID_WAY).unwrap();
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_offsetlab"))
        .args(["check", "--continue"])
        .arg(&path)
        .output()
        .unwrap();
    let stdout = String::from_utf8(out.stdout).unwrap();
    assert_eq!(out.status.code(), Some(1), "{stdout}");
    assert!(
        stdout.contains(":4:1: error[unsupported-g-code]"),
        "{stdout}"
    );
    assert!(stdout.contains(":4:1: warning[block-skipped]"), "{stdout}");
    // 7 blocks, 5 moves, path 50 mm (10 rapid + 40 feed, worked above).
    let last = stdout.lines().last().unwrap();
    assert!(last.contains(": 7 blocks, 5 moves,"), "{last}");
    assert!(
        last.contains("path 50.000 mm (rapid 10.000, feed 40.000)"),
        "{last}"
    );
    assert!(
        last.ends_with("1 errors, 1 warnings, 1 block skipped"),
        "{last}"
    );
    // Without the flag the run stops at line 4 and no count is shown.
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_offsetlab"))
        .arg("check")
        .arg(&path)
        .output()
        .unwrap();
    let stdout = String::from_utf8(out.stdout).unwrap();
    assert!(
        stdout.lines().last().unwrap().contains(": 3 blocks,"),
        "{stdout}"
    );
    assert!(!stdout.contains("skipped"), "{stdout}");
    std::fs::remove_dir_all(&dir).ok();
}
