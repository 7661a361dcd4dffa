//! Behaviour 20.18: no macro program aborts the run. Programs made from
//! random bytes by the `macros` fuzz target's grammar
//! (`fuzz/common/macro_gen.rs`: expressions of every operator and function,
//! indirect variables, IF, WHILE loops nested and endless, GOTO, calls,
//! G10, #3000) run through the same invariant checks as the fuzz targets:
//! no panic, every loop stopped by the block limit, no NaN, the reports
//! made again from checkpoints equal to the kept ones, `check` and `run`
//! agreeing.
#![cfg(not(target_arch = "wasm32"))]

#[path = "../fuzz/common/mod.rs"]
mod fuzz_common;

use proptest::prelude::*;

/// Blocks per run here: the test runs unoptimised, each program several
/// times (kept reports, checkpoints, `check`, two threads).
const MAX_BLOCKS: usize = 3000;

proptest! {
    #![proptest_config(ProptestConfig { cases: 96, ..ProptestConfig::default() })]

    #[test]
    fn behaviour20_18_no_macro_program_aborts_the_run(
        data in proptest::collection::vec(any::<u8>(), 0..400)
    ) {
        fuzz_common::check_macros_bounded(&data, MAX_BLOCKS);
    }
}

#[test]
fn behaviour20_18_the_grammar_reaches_the_evaluator() {
    // The generator makes programs the run executes, not only the parser's
    // first error: over fixed inputs, many runs set variables past the
    // prologue and some loop until the block limit.
    let mut assigned = 0;
    let mut limited = 0;
    for seed in 0u32..200 {
        let data: Vec<u8> = (0..300u32)
            .map(|i| (seed.wrapping_mul(2_654_435_761) ^ i.wrapping_mul(40_503)).to_le_bytes()[1])
            .collect();
        let program = fuzz_common::macro_gen::program_from(&data[fuzz_common::HEADER..]);
        let r = offsetlab::run_with(
            &program,
            &offsetlab::Setup::default(),
            offsetlab::RunOptions {
                max_blocks: MAX_BLOCKS,
                keep_moves: false,
                ..offsetlab::RunOptions::default()
            },
        );
        // Past the prologue's 13 blocks, a statement of the grammar set a
        // variable.
        if r.blocks.iter().skip(13).any(|b| !b.variables.is_empty()) {
            assigned += 1;
        }
        if r.diagnostics.iter().any(|d| d.code == "too-many-blocks") {
            limited += 1;
        }
    }
    assert!(assigned >= 20, "{assigned} of 200 programs set a variable");
    assert!(
        limited >= 1,
        "{limited} of 200 programs looped to the block limit"
    );
}
