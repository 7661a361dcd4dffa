//! The comparison program of issue 6 target 6: read a file and parse it with
//! the `gcode` crate 0.6, counting words — the least a G-code tool must do.
//! `cargo run --release --example gcode_baseline -- /tmp/p1m.nc`

fn main() {
    let Some(path) = std::env::args().nth(1) else {
        eprintln!("usage: gcode_baseline FILE");
        std::process::exit(2);
    };
    let text = match std::fs::read_to_string(&path) {
        Ok(t) => t,
        Err(e) => {
            eprintln!("cannot read {path}: {e}");
            std::process::exit(2);
        }
    };
    let mut lines = 0usize;
    let mut words = 0usize;
    for line in gcode::full_parse_with_callbacks(&text, gcode::Nop) {
        lines += 1;
        words += line
            .gcodes()
            .iter()
            .map(|g| 1 + g.arguments().len())
            .sum::<usize>();
    }
    println!("{path}: {lines} lines, {words} words");
}
