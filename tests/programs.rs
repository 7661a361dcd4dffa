//! Realistic programs in `tests/data/`, as a CAM post or a machinist writes
//! them: each runs without error, key blocks are checked against positions
//! computed by hand, and a compact per-block snapshot pins the rest.
#![cfg(not(target_arch = "wasm32"))]

mod common;
use offsetlab::view::{Pos, block_view};
use offsetlab::{MoveKind, Run, Setup, run};

struct Fixture {
    text: String,
    run: Run,
}

fn load(name: &str) -> Fixture {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/");
    let text = std::fs::read_to_string(format!("{dir}{name}.nc")).unwrap();
    let setup = Setup::from_json(&std::fs::read_to_string(format!("{dir}{name}.json")).unwrap())
        .unwrap_or_else(|e| panic!("{name}.json: {e}"));
    let run = run(&text, &setup);
    assert!(!run.has_errors(), "{name}: {:#?}", run.diagnostics);
    assert!(
        run.diagnostics.is_empty(),
        "{name} should not warn: {:#?}",
        run.diagnostics
    );
    Fixture { text, run }
}

impl Fixture {
    /// The block whose sequence number is `n` (the programs number every block).
    fn n(&self, n: u32) -> offsetlab::view::BlockView<'_> {
        let tag = format!("N{n} ");
        let b = self
            .run
            .blocks
            .iter()
            .find(|b| {
                let t = &self.text[b.span.start as usize..b.span.end as usize];
                t.starts_with(&tag) || t == tag.trim()
            })
            .unwrap_or_else(|| panic!("no block N{n}"));
        block_view(b, &self.text)
    }

    /// One line per block: line, programmed, actual, explanation.
    fn digest(&self) -> String {
        let mut s = String::new();
        for b in &self.run.blocks {
            let v = block_view(b, &self.text);
            s += &format!(
                "{:>3} {:<40} P{} A{} | {}\n",
                v.line,
                v.text.chars().take(40).collect::<String>(),
                fmt(&v.programmed),
                fmt(&v.actual),
                v.explanation
            );
        }
        s
    }
}

fn fmt(p: &Pos) -> String {
    match p.y {
        Some(y) => format!("({} {} {})", p.x, y, p.z),
        None => format!("({} {})", p.x, p.z),
    }
}

#[track_caller]
fn at(p: &Pos, x: f64, y: Option<f64>, z: f64) {
    assert!(
        (p.x - x).abs() < 1e-6
            && (p.z - z).abs() < 1e-6
            && p.y.zip(y).is_none_or(|(a, b)| (a - b).abs() < 1e-6),
        "got {p:?}, want ({x}, {y:?}, {z})"
    );
}

#[test]
fn pocket_with_g43_and_a_peck_drilling_cycle() {
    let f = load("pocket_g43_drill");
    // N20: G28 G91 Z0 from Z50 — the reference is Z50.
    at(&f.n(20).actual, 0.0, Some(0.0), 50.0);
    // N55: G43 Z15. H01 (120.5) → Z135.5.
    at(&f.n(55).actual, 20.0, Some(15.0), 135.5);
    at(&f.n(65).actual, 20.0, Some(15.0), 115.5);
    // N100: R5 CCW from (30,15) to (25,20) turns about (25,15).
    let b = f.n(100);
    let arc = f.run.moves[b.first_move as usize].arc.unwrap();
    assert_eq!(f.run.moves[b.first_move as usize].kind, MoveKind::ArcCcw);
    common::same(arc.center, [25.0, 15.0, 115.5]);
    // N120: G28 Z returns and clears the Z vector; N125 G49 then moves nothing.
    at(&f.n(120).actual, 20.0, Some(20.0), 50.0);
    assert_eq!(f.n(125).move_count, 0);
    // N150: H02 = 95.3 - 0.05 (geometry + wear).
    at(&f.n(150).actual, 5.0, Some(5.0), 110.25);
    // N155 G83: pecks of 3 from R2 to Z-12: -1, -4, -7, -10, -12.
    let b = f.n(155);
    let moves = &f.run.moves[b.first_move as usize..(b.first_move + b.move_count) as usize];
    let feeds: Vec<f64> = moves
        .iter()
        .filter(|m| m.kind == MoveKind::Feed)
        .map(|m| m.programmed_to[2])
        .collect();
    assert_eq!(feeds, vec![-1.0, -4.0, -7.0, -10.0, -12.0]);
    assert!(
        moves.iter().any(|m| (m.to[2] - 83.25).abs() < 1e-9),
        "bottom carries H02"
    );
    // G98: back to the initial level Z15 (actual 110.25).
    at(&b.actual, 5.0, Some(5.0), 110.25);
    // Holes at the four corners.
    at(&f.n(165).programmed, 35.0, Some(25.0), 15.0);
    at(&f.n(170).programmed, 5.0, Some(25.0), 15.0);
    at(&f.n(180).actual, 5.0, Some(25.0), 50.0);
    insta::assert_snapshot!(f.digest());
}

#[test]
fn contour_with_g45_to_g48_and_a_quarter_circle() {
    let f = load("contour_g45");
    at(&f.n(35).actual, -20.0, Some(-20.0), 97.0);
    at(&f.n(40).actual, -5.0, Some(-5.0), 97.0);
    at(&f.n(45).actual, 70.0, Some(-5.0), 97.0);
    // N50: the R10 corner is cut as the concentric R15 arc (seed 003).
    let b = f.n(50);
    at(&b.programmed, 80.0, Some(10.0), -3.0);
    at(&b.actual, 85.0, Some(10.0), 97.0);
    let arc = f.run.moves[b.first_move as usize].arc.unwrap();
    common::same(arc.center, [70.0, 10.0, 97.0]);
    common::same(arc.programmed_center, [70.0, 10.0, -3.0]);
    assert!((arc.radius - 15.0).abs() < 1e-9 && (arc.programmed_radius - 10.0).abs() < 1e-9);
    at(&f.n(55).actual, 85.0, Some(55.0), 97.0);
    at(&f.n(60).actual, -5.0, Some(55.0), 97.0);
    at(&f.n(65).actual, -5.0, Some(-5.0), 97.0);
    // N70: back on the programmed path.
    let b = f.n(70);
    at(&b.actual, -20.0, Some(-20.0), 97.0);
    assert_eq!(
        b.position_offset.unwrap().vector,
        Pos {
            x: 0.0,
            y: Some(0.0),
            z: 0.0
        }
    );
    at(&f.n(80).actual, -20.0, Some(-20.0), 50.0);
    insta::assert_snapshot!(f.digest());
}

#[test]
fn lathe_shaft_with_t_offsets_g50_and_a_taper_correction() {
    let f = load("lathe_taper");
    at(&f.n(15).actual, 200.4, None, 149.8);
    at(&f.n(25).actual, 62.4, None, 1.8);
    // N30: the G90 cycle's cutting leg ends at X56 Z-40 plus offset 01.
    let b = f.n(30);
    let m = &f.run.moves[b.first_move as usize + 1];
    assert_eq!(m.kind, MoveKind::Feed);
    common::same(m.to, [56.4, 0.0, -40.2]);
    at(&b.actual, 62.4, None, 1.8);
    // N45: cancel with a move goes to the programmed position.
    at(&f.n(45).actual, 200.0, None, 150.0);
    at(&f.n(50).actual, 199.7, None, 150.15);
    at(&f.n(60).actual, 29.7, None, 0.15);
    // N65: offset 12 in the taper move moves its end by the difference
    // (X +0.1), correcting the taper angle (seed 004).
    let b = f.n(65);
    at(&b.programmed, 40.0, None, -20.0);
    at(&b.actual, 39.8, None, -19.85);
    assert!(b.explanation.contains("taper"), "{}", b.explanation);
    at(&f.n(70).actual, 39.8, None, -39.85);
    at(&f.n(80).actual, 200.0, None, 150.0);
    insta::assert_snapshot!(f.digest());
}

#[test]
fn inch_plate_with_a_slot_arc_and_drilling() {
    let f = load("inch_plate");
    // Reported in inches; register 03 = 4.5 read in inches.
    let b = f.n(30);
    assert_eq!(b.units, "inch");
    at(&b.actual, -0.5, Some(0.5), 5.5);
    at(&f.n(40).actual, -0.5, Some(0.5), 4.375);
    let b = f.n(50);
    let arc = f.run.moves[b.first_move as usize].arc.unwrap();
    common::same(
        arc.programmed_center,
        [5.0 * 25.4, 0.5 * 25.4, -0.125 * 25.4],
    );
    at(&b.actual, 5.0, Some(1.0), 4.375);
    // N65: G81 G99 — the bottom carries H03, the return is the R level.
    let b = f.n(65);
    let moves = &f.run.moves[b.first_move as usize..(b.first_move + b.move_count) as usize];
    let bottom = moves.iter().find(|m| m.kind == MoveKind::Feed).unwrap();
    assert!((bottom.to[2] / 25.4 - 4.25).abs() < 1e-9);
    at(&b.actual, 1.0, Some(1.5), 4.6);
    at(&f.n(75).programmed, 3.0, Some(1.5), 0.1);
    at(&f.n(85).actual, 3.0, Some(1.5), 2.0);
    assert_eq!(f.run.units, offsetlab::Units::Inch);
    insta::assert_snapshot!(f.digest());
}

#[test]
fn two_fixtures_with_g54_g55_and_g28() {
    let f = load("g54_g28");
    // Start at machine zero = G54 (400, 200, 300); G28 Z is there too.
    at(&f.n(15).actual, 400.0, Some(200.0), 300.0);
    at(&f.n(20).actual, 0.0, Some(0.0), 300.0);
    at(&f.n(25).actual, 0.0, Some(0.0), 170.0);
    at(&f.n(40).programmed, 30.0, Some(20.0), -2.0);
    // N60: G55 — the same coordinates 150 mm further along X.
    let b = f.n(60);
    assert_eq!(b.modal.work, "G55");
    at(&b.programmed, 0.0, Some(0.0), 20.0);
    let m = &f.run.moves[b.first_move as usize];
    common::same(m.programmed_from, [-150.0, 0.0, 20.0]);
    at(&f.n(75).actual, 30.0, Some(20.0), 148.0);
    // N85: G28 Z clears the length vector at the reference (G55 Z300).
    at(&f.n(85).actual, 30.0, Some(20.0), 300.0);
    // N90: G28 X0 Y0 (still G91): the reference is machine zero = G55 (250, 200).
    at(&f.n(90).actual, 250.0, Some(200.0), 300.0);
    insta::assert_snapshot!(f.digest());
}

#[test]
fn coordinates_local_rotation_polar_mirror_scaling_and_returns() {
    let f = load("coordinates");
    // G54's zero is machine (-400, -200, -300); the start (0, 0, 100).
    // N20: G43 H01 = 150: Z20 lands at 170.
    at(&f.n(20).actual, 0.0, Some(0.0), 170.0);
    // N25: G52 X50 Y50: the tool at machine (-400, -200) is (-50, -50).
    at(&f.n(25).programmed, -50.0, Some(-50.0), 20.0);
    // N40: X20 Y0 turned 30° about the local zero: (20 cos 30°, 20 sin 30°).
    at(&f.n(40).programmed, 17.320508, Some(10.0), 20.0);
    // N45: the G03 R20 from there to (0, 20) turned: (−10, 10√3), about (0, 0).
    let b = f.n(45);
    at(&b.programmed, -10.0, Some(17.320508), 20.0);
    let arc = f.run.moves[b.first_move as usize].arc.unwrap();
    common::same(arc.programmed_center, [0.0, 0.0, 20.0]);
    // N60–N70: the polar holes at 30 from the local zero: 0°, 90°, 90° + 90°.
    at(&f.n(60).programmed, 30.0, Some(0.0), 20.0);
    at(&f.n(65).programmed, 0.0, Some(30.0), 20.0);
    at(&f.n(70).programmed, -30.0, Some(0.0), 20.0);
    // N80: G52 X0 Y0: the tool at machine (-380, -150) is G54 (20, 50).
    at(&f.n(80).programmed, 20.0, Some(50.0), 20.0);
    // N90: X80 mirrored about X100 is X120.
    at(&f.n(90).programmed, 120.0, Some(0.0), 20.0);
    // N95: G91 G45 Y10 D02 = 3: Y travels 13.
    at(&f.n(95).actual, 120.0, Some(13.0), 170.0);
    // N110: ×1.5 about the origin: (30, 30), the G45 vector carried.
    at(&f.n(110).actual, 30.0, Some(33.0), 170.0);
    // N120: G54.1 P1, zero at machine (-250, -200, -300).
    let b = f.n(120);
    assert_eq!(b.modal.work, "G54.1 P1");
    at(&b.machine, -250.0, Some(-197.0), -130.0);
    // N125: G30 (P2) Z: machine Z0 is Z300; the length vector is cleared.
    at(&f.n(125).actual, 0.0, Some(3.0), 300.0);
    // N135: G28 X0 Y0: machine (0, 0) is (250, 200); the Y vector cleared.
    at(&f.n(135).actual, 250.0, Some(200.0), 300.0);
    insta::assert_snapshot!(f.digest());
}
