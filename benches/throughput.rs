//! Throughput benchmarks (issue 6): parse, parse + run (the `check` path,
//! on one thread, and as the CLI makes it, with the parser on a thread of
//! its own from 1 MiB of program),
//! parse + run with block reports (the page and `run --format json`), and the
//! `gcode` crate 0.6 parsing the same text, at 1k, 10k, 100k and 1M blocks.
//!
//! `cargo bench --bench throughput` (add `-- 1000000` to run one size).

#[path = "programs.rs"]
mod programs;

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use offsetlab::syntax::{Block, Blocks, ParseOptions};
use offsetlab::{RunOptions, Setup, run_pipelined, run_with};
use std::hint::black_box;
use std::time::Duration;

fn parse_words(text: &str) -> usize {
    let mut blocks = Blocks::new(text, ParseOptions::default());
    let mut block = Block::default();
    let mut words = 0;
    while blocks.next_into(&mut block) {
        words += block.words.len();
    }
    words
}

fn gcode_words(text: &str) -> usize {
    gcode::full_parse_with_callbacks(text, gcode::Nop)
        .map(|line| {
            line.gcodes()
                .iter()
                .map(|g| 1 + g.arguments().len())
                .sum::<usize>()
        })
        .sum()
}

fn throughput(c: &mut Criterion) {
    let setup = Setup::from_json(programs::SETUP_JSON).expect("setup");
    for blocks in [1_000usize, 10_000, 100_000, 1_000_000] {
        let text = programs::mill_program(blocks);
        let mut group = c.benchmark_group(format!("{blocks} blocks"));
        group.throughput(Throughput::Bytes(text.len() as u64));
        if blocks >= 100_000 {
            group.sample_size(10);
            group.measurement_time(Duration::from_secs(8));
        }
        group.bench_with_input(
            BenchmarkId::new("gcode 0.6 parse", blocks),
            &text,
            |b, t| b.iter(|| black_box(gcode_words(t))),
        );
        group.bench_with_input(BenchmarkId::new("parse", blocks), &text, |b, t| {
            b.iter(|| black_box(parse_words(t)))
        });
        let check = RunOptions {
            keep_blocks: false,
            keep_moves: false,
            ..RunOptions::default()
        };
        group.bench_with_input(BenchmarkId::new("parse+run", blocks), &text, |b, t| {
            b.iter(|| black_box(run_with(t, &setup, check).block_count))
        });
        group.bench_with_input(
            BenchmarkId::new("parse+run, 2 threads", blocks),
            &text,
            |b, t| b.iter(|| black_box(run_pipelined(t, &setup, check).block_count)),
        );
        group.bench_with_input(
            BenchmarkId::new("parse+run+reports", blocks),
            &text,
            |b, t| b.iter(|| black_box(run_with(t, &setup, RunOptions::default()).blocks.len())),
        );
        group.finish();
    }
}

criterion_group!(benches, throughput);
criterion_main!(benches);
