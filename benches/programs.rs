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

/// The setup of [`mill_program_g41`]: H01 the tool length, D02 the cutter
/// radius (2 mm).
pub const SETUP_G41_JSON: &str = r#"{"version": 1, "offsets": {"01": 100.0, "02": 2.0}}"#;

/// A program of `blocks` blocks with cutter radius compensation G41 active
/// throughout (target 6 with G41, issue 21), in the mix of
/// [`mill_program`] (mostly G01 lines, a fifth of arcs, Z steps and
/// comments) but drawn as contours, so that it runs without an alarm:
/// polygons of 3 to 12 corners gone round clockwise with the tool outside
/// (climb), a third of their corners rounded by a tangent R arc, a Z step
/// and a move to the next polygon between laps. Every corner kind of
/// behaviour 16 comes up (tangent arcs, outside corners obtuse and acute,
/// inside corners on the moves between laps). Seed fixed.
pub fn mill_program_g41(blocks: usize) -> String {
    let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
    let mut out = String::with_capacity(blocks * 32);
    let header = [
        "%",
        "O1001 (GENERATED CONTOURS WITH CUTTER COMPENSATION G41)",
        "N1 G90 G17 G21 G40 G49 G80",
        "N2 G00 X-200. Y-200. Z10.",
        "N3 G43 Z5. H01",
        "N4 G01 Z-1. F500.",
    ];
    for line in header {
        out.push_str(line);
        out.push('\n');
    }
    let round = |v: f64| (v * 1000.0).round() / 1000.0;
    let mut n = 10u64;
    let mut count = header.len();
    let mut first = true;
    let mut size = 40.0f64;
    while count + 40 < blocks {
        // Corners clockwise round (cx, cy), their distance jittered by a
        // tenth: convex enough for the tool, not regular.
        let corners = 3 + (rng.next() % 10) as usize;
        // Every lap's first corner straight above the centre: the move
        // from one lap to the next runs out (or back in) along the Y axis.
        let (cx, cy) = (0.0, 0.0);
        let turn = std::f64::consts::FRAC_PI_2;
        let step = std::f64::consts::TAU / corners as f64;
        let points: Vec<(f64, f64)> = (0..corners)
            .map(|k| {
                let a = turn - step * k as f64;
                let d = if k == 0 {
                    size
                } else {
                    size * rng.range(0.9, 1.1)
                };
                (cx + d * a.cos(), cy + d * a.sin())
            })
            .collect();
        // Each corner rounded or not; a rounded one is cut by an arc of
        // radius `rf` tangent to both sides, from `t` before the corner to
        // `t` after it (t = rf·tan(φ/2), φ the turn).
        let mut corner_blocks: Vec<(String, Option<String>, (f64, f64))> =
            Vec::with_capacity(corners);
        for k in 0..corners {
            let (p0, p1, p2) = (
                points[(k + corners - 1) % corners],
                points[k],
                points[(k + 1) % corners],
            );
            let unit = |a: (f64, f64), b: (f64, f64)| {
                let (dx, dy) = (b.0 - a.0, b.1 - a.1);
                let l = dx.hypot(dy);
                (dx / l, dy / l)
            };
            let (d1, d2) = (unit(p0, p1), unit(p1, p2));
            let cross = d1.0 * d2.1 - d1.1 * d2.0;
            let phi = cross.atan2(d1.0 * d2.0 + d1.1 * d2.1).abs();
            // Only a corner turning right (the polygon's outside) is
            // rounded, by a clockwise arc.
            // The first corner stays sharp: the move to the next lap
            // leaves from it.
            if k > 0 && cross < 0.0 && phi > 0.2 && rng.unit() < 0.4 {
                let rf = round(rng.range(3.0, 8.0));
                let t = rf * (phi / 2.0).tan();
                let a = (round(p1.0 - t * d1.0), round(p1.1 - t * d1.1));
                let b = (round(p1.0 + t * d2.0), round(p1.1 + t * d2.1));
                corner_blocks.push((
                    format!("G01 X{:.3} Y{:.3}", a.0, a.1),
                    Some(format!("G02 X{:.3} Y{:.3} R{rf:.3}", b.0, b.1)),
                    b,
                ));
            } else {
                let p = (round(p1.0), round(p1.1));
                corner_blocks.push((format!("G01 X{:.3} Y{:.3}", p.0, p.1), None, p));
            }
        }
        // The lap starts where its first corner ends and goes round to it.
        let (sx, sy) = corner_blocks[0].2;
        n += 1;
        let g41 = if first { "G41 D02 " } else { "" };
        first = false;
        out.push_str(&format!("N{n} G01 {g41}X{sx:.3} Y{sy:.3}\n"));
        count += 1;
        for (line, arc, _) in corner_blocks
            .iter()
            .skip(1)
            .chain(corner_blocks.iter().take(1))
        {
            for block in std::iter::once(line).chain(arc) {
                n += 1;
                out.push_str(&format!("N{n} {block}\n"));
                count += 1;
            }
        }
        n += 1;
        out.push_str(&format!("N{n} G01 Z{:.3} (STEP)\n", -rng.range(0.5, 5.0)));
        out.push_str(&format!("(LAP {n})\n"));
        count += 2;
        size = if size >= 150.0 {
            40.0
        } else {
            size + rng.range(8.0, 20.0)
        };
    }
    n += 1;
    out.push_str(&format!("N{n} G40 G01 X-200. Y-200.\nM30\n%\n"));
    out
}
