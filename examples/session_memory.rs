//! What the page's `Session` holds for a program (issue 6, target 2): runs
//! it as the session does (no block reports, no moves kept, a checkpoint
//! every 512 blocks, the moves pushed into the compact toolpath) and prints
//! the bytes per block. Usage: `session_memory PROGRAM SETUP.json`.

use std::time::Instant;

/// The session's observer: the toolpath built as the moves are made, room
/// for the rest foreseen after the first MiB (`src/wasm/mod.rs`).
struct Session<'a> {
    path: offsetlab::toolpath::PathBuilder<'a>,
    len: usize,
}

impl offsetlab::Observer for Session<'_> {
    fn on_move(&mut self, m: &offsetlab::Move) {
        self.path.on_move(m);
    }

    fn on_progress(&mut self, read: usize) {
        self.path.foresee(read, self.len);
    }
}

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
    let mut session = Session {
        path: offsetlab::toolpath::PathBuilder::new(setup.machine, setup.units, None),
        len: text.len(),
    };
    let run = offsetlab::run_observed(&text, &setup, opts, &mut session);
    let mut tp = session.path.finish(&run, &offsetlab::Reuse::default());
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
