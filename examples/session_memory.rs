//! What the page's `Session` holds for a program (issue 6, target 2): runs
//! it with the native session the page's worker drives
//! (`offsetlab::session::Session`: no block reports, no moves kept, a
//! checkpoint every 512 blocks, the moves pushed into the compact toolpath)
//! and prints the bytes per block. Usage: `session_memory PROGRAM SETUP.json`.

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
    let mut session = offsetlab::session::Session::new();
    session.run(text, Ok(setup), |_| ());
    let t1 = t.elapsed();
    let (run, tp, checkpoints) = (
        session.last_run(),
        session.toolpath(),
        session.checkpoints(),
    );
    let ck = checkpoints.points.len() * std::mem::size_of::<offsetlab::Checkpoint>()
        + checkpoints.lines.capacity() * 4;
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
