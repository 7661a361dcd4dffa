//! Runs made again after an edit (issue 6, typing): `rerun_observed`
//! resumes at the earlier run's checkpoint before the edit and, once past
//! the edit, takes the earlier run's end from the first checkpoint where
//! the parser and the machine stand as they stood then. The promise: the
//! result is what a whole run of the edited text gives — every total,
//! diagnostic (place, order, cap), line, event and the toolpath — and every
//! block's report made again from the checkpoints is the report a run
//! keeping every block keeps. Edits go on from runs made again, so the
//! checkpoints' own totals are checked across chains of edits.
#![cfg(not(target_arch = "wasm32"))]

mod common;
#[path = "../benches/programs.rs"]
mod programs;

use common::fixture;

use offsetlab::toolpath::PathBuilder;
use offsetlab::{
    Checkpoints, Earlier, Reuse, Run, RunOptions, Setup, Toolpath, report_at, rerun_observed, run,
};
use proptest::prelude::*;

const FIXTURES: [&str; 14] = [
    "contour_g45",
    "coordinates",
    "corners",
    "cutter",
    "g10_lathe",
    "g10_tables",
    "g54_g28",
    "haas_modes",
    "inch_plate",
    "lathe_cycles",
    "lathe_taper",
    "nose",
    "pocket_g43_drill",
    "polar",
];

fn page(every: u32) -> RunOptions {
    RunOptions {
        keep_blocks: false,
        keep_moves: false,
        checkpoint_every: every,
        ..RunOptions::default()
    }
}

/// A run as the page makes it: the run, its checkpoints and its toolpath.
type PageRun = (Run, Checkpoints, Toolpath);

/// A run as the page makes it, made again from `earlier` when given; also
/// how many moves were actually made.
fn page_run(
    text: &str,
    setup: &Setup,
    every: u32,
    earlier: Option<(&str, &PageRun)>,
) -> (PageRun, Reuse, usize) {
    let mut made = 0usize;
    let mut builder = PathBuilder::new(setup.machine, setup.units, earlier.map(|(_, e)| &e.2));
    struct Counting<'a, 'b>(&'a mut PathBuilder<'b>, &'a mut usize);
    impl offsetlab::Observer for Counting<'_, '_> {
        fn on_move(&mut self, m: &offsetlab::Move) {
            *self.1 += 1;
            self.0.on_move(m);
        }
        fn on_resume(&mut self, prefix_moves: usize) {
            self.0.on_resume(prefix_moves);
        }
    }
    let earlier_run = earlier.map(|(text, e)| Earlier {
        text,
        run: &e.0,
        checkpoints: &e.1,
    });
    let (run, checkpoints, reuse) = rerun_observed(
        text,
        setup,
        page(every),
        earlier_run,
        &mut Counting(&mut builder, &mut made),
    );
    let path = builder.finish(&run, &reuse);
    ((run, checkpoints, path), reuse, made)
}

/// The run made again is the whole run of `text`, checkpoints aside, and
/// its checkpoints make every block's report again.
fn assert_same_as_whole(text: &str, setup: &Setup, every: u32, got: &PageRun) {
    let ((want, want_checkpoints, want_path), _, _) = page_run(text, setup, every, None);
    let (got, got_checkpoints, got_path) = got;
    let context = || format!("with a checkpoint every {every} blocks:\n{text}");
    assert_eq!(got.diagnostics, want.diagnostics, "{}", context());
    assert_eq!(got.block_count, want.block_count, "{}", context());
    assert_eq!(got.move_count, want.move_count, "{}", context());
    assert_eq!(got.end, want.end, "{}", context());
    assert_eq!(got.events, want.events, "{}", context());
    assert_eq!(
        got_checkpoints.lines,
        want_checkpoints.lines,
        "{}",
        context()
    );
    assert_eq!(got.registers, want.registers, "{}", context());
    assert_eq!(got.bounds, want.bounds, "{}", context());
    assert_eq!(
        (got.units, got.end_units),
        (want.units, want.end_units),
        "{}",
        context()
    );
    assert_eq!(got_path, &want_path, "the toolpath {}", context());
    // The checkpoints: in order, at most `every` blocks apart, and each
    // block's report made again from them is the kept one.
    let offsets: Vec<u32> = got_checkpoints.points.iter().map(|c| c.index).collect();
    assert!(
        offsets
            .windows(2)
            .all(|w| w[0] < w[1] && w[1] - w[0] <= every),
        "{offsets:?}"
    );
    let full = run(text, setup);
    for (i, kept) in full.blocks.iter().enumerate() {
        let again = report_at(text, setup, got_checkpoints, i as u32);
        assert_eq!(again.as_ref(), Some(kept), "block {i} {}", context());
    }
}

/// An edit: `len` bytes at `at` replaced with `with` (kept on character
/// boundaries).
#[derive(Clone, Debug)]
struct Edit {
    at: f64,
    len: usize,
    with: String,
}

fn apply(text: &str, e: &Edit) -> String {
    let mut at = ((text.len() as f64) * e.at) as usize;
    while !text.is_char_boundary(at) {
        at -= 1;
    }
    let mut end = (at + e.len).min(text.len());
    while !text.is_char_boundary(end) {
        end += 1;
    }
    format!("{}{}{}", &text[..at], e.with, &text[end..])
}

fn edit() -> impl Strategy<Value = Edit> {
    let with = prop_oneof![
        6 => Just(String::new()),
        12 => "[0-9]",
        4 => "[0-9.\\- ]{1,3}",
        4 => Just("\nG01 X4.5\n".to_string()),
        1 => Just("\n".to_string()),
        1 => Just("G91 ".to_string()),
        1 => Just("G20\n".to_string()),
        1 => Just("G81 Z-3. R2.\n".to_string()),
        1 => Just("M30\n".to_string()),
        1 => Just("(".to_string()),
        1 => Just(";".to_string()),
        1 => Just("%\n".to_string()),
        1 => Just("X1.5 Y-2.\n".to_string()),
        1 => Just("G41 D02 X3.\n".to_string()),
        1 => Just("Q".to_string()),
        1 => Just("G93\n".to_string()),
        1 => Just("G13 I6. K9. Q1. D01\n".to_string()),
        1 => Just("G61 ".to_string()),
        1 => Just("\nO2000\n".to_string()),
        1 => Just(" ; a note\n".to_string()),
    ];
    (
        0.0f64..1.0,
        prop_oneof![3 => 0usize..2, 1 => 2usize..12],
        with,
    )
        .prop_map(|(at, len, with)| Edit { at, len, with })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 48, ..ProptestConfig::default() })]

    /// Chains of edits of every fixture, each run again from the run
    /// before, equal whole runs of the edited text.
    #[test]
    fn runs_made_again_after_edits_equal_whole_runs(
        fixture_index in 0usize..FIXTURES.len(),
        every in prop_oneof![Just(1u32), Just(2), Just(3), Just(7), Just(512)],
        edits in prop::collection::vec(edit(), 1..5),
    ) {
        let (mut text, setup) = fixture(FIXTURES[fixture_index]);
        let (mut last, _, _) = page_run(&text, &setup, every, None);
        for e in &edits {
            let edited = apply(&text, e);
            let (again, _, _) = page_run(&edited, &setup, every, Some((&text, &last)));
            assert_same_as_whole(&edited, &setup, every, &again);
            text = edited;
            last = again;
        }
    }
}

/// The benchmark's program (G90 moves, arcs, G43) with a checkpoint every
/// 64 blocks.
fn surfacing(blocks: usize) -> (String, Setup) {
    (
        programs::mill_program(blocks),
        Setup::from_json(programs::SETUP_JSON).unwrap(),
    )
}

fn line_start(text: &str, line: usize) -> usize {
    text.split_inclusive('\n')
        .take(line - 1)
        .map(str::len)
        .sum()
}

#[test]
fn a_coordinate_edit_mid_program_runs_only_the_blocks_near_it() {
    let (text, setup) = surfacing(5000);
    let (earlier, _, _) = page_run(&text, &setup, 64, None);
    // A digit typed after the first digit of the X word of a G01 about
    // halfway down.
    let at = line_start(&text, 2500);
    let x = at + text[at..].find(" G01 X").unwrap() + 4;
    let x = x + text[x..].find(|c: char| c.is_ascii_digit()).unwrap() + 1;
    let edited = format!("{}7{}", &text[..x], &text[x..]);
    let (again, reuse, made) = page_run(&edited, &setup, 64, Some((&text, &earlier)));
    assert_same_as_whole(&edited, &setup, 64, &again);
    assert!(reuse.prefix_moves > 2000, "{reuse:?}");
    let tail = reuse.tail.expect("the run caught up with the earlier one");
    assert_eq!((tail.blocks, tail.lines), (0, 0));
    // From the checkpoint before the edit to the first one after it.
    assert!(made <= 2 * 64 + 8, "{made} moves made again");
}

#[test]
fn a_typed_line_shifts_the_rest_of_the_run() {
    let (text, setup) = surfacing(3000);
    let (earlier, _, _) = page_run(&text, &setup, 64, None);
    let at = line_start(&text, 1000);
    let edited = format!("{}G01 X12.5 Y-3.25\n{}", &text[..at], &text[at..]);
    let (again, reuse, made) = page_run(&edited, &setup, 64, Some((&text, &earlier)));
    assert_same_as_whole(&edited, &setup, 64, &again);
    let tail = reuse.tail.expect("the run caught up with the earlier one");
    assert_eq!((tail.blocks, tail.lines), (1, 1));
    assert!(made <= 2 * 64 + 8, "{made} moves made again");
    // And back: deleting the line again is an edit of the run made again.
    let (back, reuse, _) = page_run(&text, &setup, 64, Some((&edited, &again)));
    assert_same_as_whole(&text, &setup, 64, &back);
    assert_eq!(reuse.tail.map(|t| (t.blocks, t.lines)), Some((-1, -1)));
}

#[test]
fn an_incremental_program_runs_to_its_end_after_an_edit() {
    // G91: every later position depends on the edited move, so the run
    // never catches up; it still resumes before the edit.
    let mut text = String::from("G91 G01 F100.\n");
    for i in 0..400 {
        text += &format!("X{}.5 Y-{}.25\n", i % 7, i % 5);
    }
    let setup = Setup::default();
    let (earlier, _, _) = page_run(&text, &setup, 16, None);
    let at = line_start(&text, 200);
    let edited = format!("{}X1.{}", &text[..at], &text[at..]);
    let (again, reuse, made) = page_run(&edited, &setup, 16, Some((&text, &earlier)));
    assert_same_as_whole(&edited, &setup, 16, &again);
    assert!(reuse.tail.is_none());
    assert!(reuse.prefix_moves >= 180 && made <= 220, "{reuse:?} {made}");
}

#[test]
fn another_setup_runs_afresh() {
    let (text, setup) = fixture("pocket_g43_drill");
    let (earlier, _, _) = page_run(&text, &setup, 4, None);
    let mut other = setup.clone();
    other.set_register("01=12.5").unwrap();
    let (again, reuse, _) = page_run(&text, &other, 4, Some((&text, &earlier)));
    assert_eq!(reuse, Reuse::default());
    assert_same_as_whole(&text, &other, 4, &again);
}

#[test]
fn past_the_diagnostics_cap_the_earlier_end_is_not_taken() {
    // 1500 bad words: the cap of 1000 falls at another word once an edit
    // adds one, so the end is run again, not taken.
    let mut text = String::from("G01 F100.\n");
    for i in 0..1500 {
        text += &format!("X{i}.5 Y1 E2\n");
    }
    let setup = Setup::default();
    let (earlier, _, _) = page_run(&text, &setup, 8, None);
    let at = line_start(&text, 700);
    let edited = format!("{}E5 {}", &text[..at], &text[at..]);
    let (again, reuse, _) = page_run(&edited, &setup, 8, Some((&text, &earlier)));
    assert!(reuse.tail.is_none());
    assert_same_as_whole(&edited, &setup, 8, &again);
}

/// Every digit of every fixture changed in turn, each edit run again from
/// the fixture's run: most catch up with the earlier run within a block or
/// two (a checkpoint every 2 blocks), all equal whole runs.
#[test]
fn every_one_digit_edit_of_the_fixtures_equals_its_whole_run() {
    for name in FIXTURES {
        let (text, setup) = fixture(name);
        let (earlier, _, _) = page_run(&text, &setup, 2, None);
        let (mut edits, mut caught_up) = (0, 0);
        for (i, c) in text.char_indices().filter(|(_, c)| c.is_ascii_digit()) {
            let digit = if c == '9' {
                '1'
            } else {
                char::from(c as u8 + 1)
            };
            let edited = format!("{}{digit}{}", &text[..i], &text[i + 1..]);
            let (again, reuse, _) = page_run(&edited, &setup, 2, Some((&text, &earlier)));
            assert_same_as_whole(&edited, &setup, 2, &again);
            edits += 1;
            caught_up += usize::from(reuse.tail.is_some());
        }
        assert!(
            caught_up * 3 > edits,
            "{name}: {caught_up} of {edits} caught up"
        );
    }
}

#[test]
fn a_digit_typed_at_the_end_of_a_cycles_q_block_runs_the_cycle_again() {
    // lathe_cycles.nc: G71 P10 Q20 reads its contour up to the end of the
    // N20 block, "N20 X52."; a "3" typed right after it makes X52.3, past
    // the cycle's start X52 (mrc-over-start at the G71): the edit touches
    // the text the cycle read though it begins where that text ends.
    let (text, setup) = fixture("lathe_cycles");
    let at = text.find("N20 X52.").unwrap() + "N20 X52.".len();
    let edited = format!("{}3{}", &text[..at], &text[at..]);
    for every in [1, 2, 7] {
        let (earlier, _, _) = page_run(&text, &setup, every, None);
        let (again, _, _) = page_run(&edited, &setup, every, Some((&text, &earlier)));
        assert_same_as_whole(&edited, &setup, every, &again);
        assert!(
            again
                .0
                .diagnostics
                .iter()
                .any(|d| d.code == "mrc-over-start"),
            "{:#?}",
            again.0.diagnostics
        );
    }
}

#[test]
fn behaviour19_9_typing_a_program_with_subprogram_calls_runs_as_whole_runs() {
    // The page's runs while a program of a call and its subprogram is
    // typed: each made again from the one before equals the whole run.
    let text = "O1000\nN10 G90 G00 X0 Y0 Z5.\nN30 M98 P2000 L2\nN50 M30\n%\nO2000\nN1 G91 G01 Z-1. F100\nN2 X10.\nN6 M99\n%\n";
    let setup = Setup::default();
    let mut earlier: Option<(String, PageRun)> = None;
    for end in (1..=text.len()).step_by(3).chain([text.len()]) {
        let typed = &text[..end];
        let (got, _, _) = page_run(
            typed,
            &setup,
            2,
            earlier.as_ref().map(|(t, e)| (t.as_str(), e)),
        );
        assert_same_as_whole(typed, &setup, 2, &got);
        earlier = Some((typed.to_string(), got));
    }
}
