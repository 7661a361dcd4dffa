//! Checkpoints (issue 6, memory): a run may keep a checkpoint every N blocks
//! instead of a report per block, and `report_at` makes any block's report
//! again from the checkpoint before it. The promise: the report made again
//! is the report a run keeping every block keeps, for every block, whatever
//! N — including across block skip, G92/G50, canned cycles, errors and
//! M30.

mod common;
use common::{checkpointed, fixture};
use offsetlab::{RunOptions, Setup, report_at, run, run_observed};

/// Every block's report made again equals the kept one.
fn assert_same_reports(text: &str, setup: &Setup) {
    let full = run(text, setup);
    for every in [1, 2, 3, 7, 1000] {
        let (light, checkpoints) = checkpointed(text, setup, every);
        assert!(light.blocks.is_empty());
        assert_eq!(light.block_count, full.block_count);
        assert_eq!(light.moves, full.moves, "the same moves");
        assert_eq!(light.diagnostics, full.diagnostics, "the same diagnostics");
        assert_eq!(light.end, full.end);
        assert_eq!(
            checkpoints.lines,
            full.blocks.iter().map(|b| b.span.line).collect::<Vec<_>>(),
            "a line per block"
        );
        // One before every N-th block (and before a block that then fails).
        let n = checkpoints.points.len() as u32;
        assert!(
            (full.block_count.div_ceil(every).max(1)..=full.block_count / every + 1).contains(&n),
            "{n} checkpoints for {} blocks, one every {every}",
            full.block_count
        );
        for (i, kept) in full.blocks.iter().enumerate() {
            let again = report_at(text, setup, &checkpoints, i as u32);
            assert_eq!(
                again.as_ref(),
                Some(kept),
                "block {i} with a checkpoint every {every}"
            );
        }
        assert_eq!(report_at(text, setup, &checkpoints, full.block_count), None);
    }
}

#[test]
fn reports_made_again_from_checkpoints_equal_the_kept_ones_for_every_fixture() {
    for name in [
        "contour_g45",
        "coordinates",
        "corners",
        "cutter",
        "g10_lathe",
        "g10_tables",
        "g54_g28",
        "inch_plate",
        "lathe_cycles",
        "lathe_taper",
        "nose",
        "pocket_g43_drill",
        "polar",
    ] {
        let (text, setup) = fixture(name);
        assert_same_reports(&text, &setup);
    }
}

#[test]
fn checkpoints_resume_across_block_skip_g92_cycles_and_mirror() {
    let mut setup = Setup::default();
    setup.set_register("01=5.0").unwrap();
    setup.set_register("02=2.5").unwrap();
    let text = "%\nG90 G21 G17\n/G00 X100.\nG43 Z50. H01\n(comment)\nG00 X10. Y10.\nG92 X0 Y0\nG45 G01 X20. D02 F100\nG81 X5. Y5. Z-3. R2. K3\nG80\nG02 X30. Y0 R10.\nG49 G00 Z100.\nM30\nG00 X999.\n%\n";
    assert_same_reports(text, &setup);
}

#[test]
fn a_run_stopped_by_an_error_has_no_reports_past_it() {
    let setup = Setup::default();
    let text = "G00 X10.\nG01 X20. F100\nG02 X30. R1.\nG00 X0\n";
    let full = run(text, &setup);
    assert!(full.has_errors());
    assert_same_reports(text, &setup);
    let (_, checkpoints) = checkpointed(text, &setup, 1);
    assert_eq!(
        report_at(text, &setup, &checkpoints, full.block_count),
        None
    );
}

#[test]
fn a_run_without_checkpoints_makes_no_report_again() {
    let setup = Setup::default();
    let text = "G00 X10.\n";
    let (r, checkpoints) = run_observed(text, &setup, RunOptions::default(), &mut ());
    assert_eq!(r, run(text, &setup));
    assert!(checkpoints.points.is_empty() && checkpoints.lines.is_empty());
    assert_eq!(report_at(text, &setup, &checkpoints, 0), None);
}

#[test]
fn lathe_checkpoints_resume_with_t_codes_and_g50() {
    let mut setup = Setup {
        machine: offsetlab::MachineKind::Lathe,
        ..Setup::default()
    };
    setup.set_register("01=X0.4,Z-0.2").unwrap();
    let text = "G50 X120. Z60.\nG00 T0101\nX50. Z3.\nG01 Z-20. F0.2\nU10. W-5.\nG00 T0100 X120. Z60.\nM30\n";
    assert_same_reports(text, &setup);
}
