//! The page's run after a one-character edit (issue 6, target 4): a whole
//! run as the page makes it (checkpoints, toolpath) against the same edit
//! run again from the earlier run (`rerun_observed`), at 10k, 100k and 1M
//! blocks. The edit is a digit typed into an X word halfway down (it moves
//! two segments) — the page's worst ordinary case is an edit near the start
//! of a program whose later blocks depend on it (G91), which runs to the
//! end either way.
//!
//! `cargo bench --bench edit`

#[path = "programs.rs"]
mod programs;

use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use offsetlab::toolpath::PathBuilder;
use offsetlab::{Checkpoints, Earlier, Run, RunOptions, Setup, Toolpath, rerun_observed};
use std::hint::black_box;
use std::time::Duration;

const PAGE: RunOptions = RunOptions {
    keep_blocks: false,
    keep_moves: false,
    max_moves: offsetlab::MAX_MOVES,
    max_blocks: offsetlab::MAX_BLOCKS,
    checkpoint_every: 512,
};

fn page_run(
    text: &str,
    setup: &Setup,
    earlier: Option<(&str, &(Run, Checkpoints, Toolpath))>,
) -> (Run, Checkpoints, Toolpath) {
    let mut builder = PathBuilder::new(setup.machine, setup.units, earlier.map(|(_, e)| &e.2));
    let earlier = earlier.map(|(text, e)| Earlier {
        text,
        run: &e.0,
        checkpoints: &e.1,
    });
    let (run, checkpoints, reuse) = rerun_observed(text, setup, PAGE, earlier, &mut builder);
    let path = builder.finish(&run, &reuse);
    (run, checkpoints, path)
}

/// The text with a 7 typed after the first digit of the first `G01 X`
/// from the middle on.
fn edited(text: &str) -> String {
    let mid = text.len() / 2;
    let x = mid + text[mid..].find(" G01 X").expect("a G01") + 6;
    let x = x
        + text[x..]
            .find(|c: char| c.is_ascii_digit())
            .expect("a digit")
        + 1;
    format!("{}7{}", &text[..x], &text[x..])
}

fn edit(c: &mut Criterion) {
    let setup = Setup::from_json(programs::SETUP_JSON).expect("setup");
    for blocks in [10_000usize, 100_000, 1_000_000] {
        let text = programs::mill_program(blocks);
        let changed = edited(&text);
        let earlier = page_run(&text, &setup, None);
        let mut group = c.benchmark_group(format!("edit of {blocks} blocks"));
        if blocks >= 100_000 {
            group.sample_size(10);
            group.measurement_time(Duration::from_secs(8));
        }
        group.bench_function(BenchmarkId::new("whole run", blocks), |b| {
            b.iter(|| black_box(page_run(&changed, &setup, None).0.block_count))
        });
        group.bench_function(BenchmarkId::new("run again", blocks), |b| {
            b.iter(|| {
                black_box(
                    page_run(&changed, &setup, Some((&text, &earlier)))
                        .0
                        .block_count,
                )
            })
        });
        group.finish();
    }
}

criterion_group!(benches, edit);
criterion_main!(benches);
