//! Deterministic generator of benchmark programs (issue 6): a milling
//! program as CAM surfacing writes it — G01 moves, arcs with R and with
//! I/J, Z steps, comments, N numbers, G43 active. Every arc passes the radius
//! check, so the whole program runs. Shared by the benches and by
//! `examples/generate.rs` through `#[path]`.
#![allow(dead_code)]

/// xorshift64*: small, deterministic, no dependency.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }
    /// Uniform in [0, 1).
    fn unit(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }
    fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }
}

/// Register 01 holds the tool length the program's G43 reads.
pub const SETUP_JSON: &str = r#"{"version": 1, "offsets": {"01": 100.0}}"#;

/// A program of `blocks` blocks (comment lines included), seed fixed.
pub fn mill_program(blocks: usize) -> String {
    let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
    let mut out = String::with_capacity(blocks * 32);
    let header = [
        "%",
        "O1000 (GENERATED SURFACING PROGRAM)",
        "N1 G90 G17 G21 G40 G49 G80",
        "N2 G00 X0 Y0 Z10.",
        "N3 G43 Z5. H01",
        "N4 G01 Z-1. F500.",
    ];
    for line in header {
        out.push_str(line);
        out.push('\n');
    }
    let (mut x, mut y) = (0.0f64, 0.0f64);
    let round = |v: f64| (v * 1000.0).round() / 1000.0;
    let mut n = 10u64;
    let mut count = header.len();
    while count + 2 < blocks {
        n += 1;
        let r = rng.unit();
        if r < 0.60 {
            x = round(rng.range(-200.0, 200.0));
            y = round(rng.range(-200.0, 200.0));
            out.push_str(&format!("N{n} G01 X{x:.3} Y{y:.3}\n"));
        } else if r < 0.75 {
            let nx = round(x + rng.range(-5.0, 5.0));
            let ny = round(y + rng.range(-5.0, 5.0));
            let half = ((nx - x).powi(2) + (ny - y).powi(2)).sqrt() / 2.0;
            let radius = half + rng.range(0.5, 5.0);
            let g = if rng.unit() < 0.5 { 2 } else { 3 };
            out.push_str(&format!("N{n} G{g:02} X{nx:.3} Y{ny:.3} R{radius:.3}\n"));
            x = nx;
            y = ny;
        } else if r < 0.85 {
            out.push_str(&format!(
                "N{n} G03 X{x:.3} Y{y:.3} I{:.3} J0.\n",
                rng.range(1.0, 5.0)
            ));
        } else if r < 0.95 {
            out.push_str(&format!(
                "N{n} G01 Z{:.3} (STEP DOWN)\n",
                rng.range(-5.0, -0.5)
            ));
        } else {
            out.push_str(&format!("(PASS {n})\n"));
        }
        count += 1;
    }
    out.push_str("M30\n%\n");
    out
}
