//! What the page's `Session` holds for a program (issue 6, target 2): runs
//! it as the session does (no block reports, no moves kept, a checkpoint
//! every 512 blocks, the moves pushed into the compact toolpath) and prints
//! the bytes per block. Usage: `session_memory PROGRAM SETUP.json`.

use std::time::Instant;
fn main() {
    let a: Vec<String> = std::env::args().collect();
    if a.len() != 3 {
        eprintln!("usage: session_memory PROGRAM SETUP.json");
        std::process::exit(2);
    }
    let text = std::fs::read_to_string(&a[1]).unwrap();
    let setup: offsetlab::Setup =
        serde_json::from_str(&std::fs::read_to_string(&a[2]).unwrap()).unwrap();
    let t = Instant::now();
    let opts = offsetlab::RunOptions {
        keep_blocks: false,
        keep_moves: false,
        checkpoint_every: 512,
        ..Default::default()
    };
    let mut tp = offsetlab::toolpath::Toolpath::new(setup.machine, setup.units);
    let run = offsetlab::run_observed(&text, &setup, opts, &mut |m: &offsetlab::report::Move| {
        tp.push(m)
    });
    tp.shrink_to_fit();
    let t1 = t.elapsed();
    let ck = run.checkpoints.len() * std::mem::size_of::<offsetlab::Checkpoint>()
        + run.lines.capacity() * 4;
    println!(
        "blocks {} moves {} vertices {} arcs {} run+toolpath {:?}; toolpath {} B ({:.1} B/block), checkpoints+lines {} B ({:.1} B/block)",
        run.block_count,
        run.move_count,
        tp.vertex_count(),
        tp.arcs.len(),
        t1,
        tp.heap_bytes(),
        tp.heap_bytes() as f64 / run.block_count as f64,
        ck,
        ck as f64 / run.block_count as f64
    );
}
