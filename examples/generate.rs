//! Writes a benchmark program and its setup (issue 6):
//! `cargo run --release --example generate -- 1000000 /tmp/p1m.nc`
//! writes `/tmp/p1m.nc` and `/tmp/p1m.json`; a third argument `g41` writes
//! the variant with cutter radius compensation active (issue 21).

#[path = "../benches/programs.rs"]
mod programs;

fn main() {
    let mut args = std::env::args().skip(1);
    let blocks: usize = args
        .next()
        .and_then(|a| a.parse().ok())
        .unwrap_or(1_000_000);
    let path = args.next().unwrap_or_else(|| format!("bench-{blocks}.nc"));
    let g41 = args.next().as_deref() == Some("g41");
    let (text, setup_json) = if g41 {
        (programs::mill_program_g41(blocks), programs::SETUP_G41_JSON)
    } else {
        (programs::mill_program(blocks), programs::SETUP_JSON)
    };
    if let Err(e) = std::fs::write(&path, &text) {
        eprintln!("cannot write {path}: {e}");
        std::process::exit(2);
    }
    let setup = std::path::Path::new(&path).with_extension("json");
    if let Err(e) = std::fs::write(&setup, setup_json) {
        eprintln!("cannot write {}: {e}", setup.display());
        std::process::exit(2);
    }
    println!(
        "{path}: {blocks} blocks, {} bytes; setup {}",
        text.len(),
        setup.display()
    );
}
