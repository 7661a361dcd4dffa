//! The fast ways of cutter radius compensation C (behaviour 16) give what
//! the general ones give: a block of motion words alone in offset mode
//! (`Machine::offset_plain`) moves as the same block run by the general
//! code, and the corner of two lines (`lines_corner`) is the general
//! rule's, bit for bit, on random contours of lines and arcs with inside
//! and outside corners.
#![cfg(not(target_arch = "wasm32"))]

use offsetlab::offsets::cutter::geometry::{self as geo, Outside, Path, Rule};
use offsetlab::{Run, Setup, run};
use proptest::prelude::*;

/// Micrometres, written with three decimals.
fn mm(v: f64) -> String {
    format!("{:.3}", (v * 1000.0).round() / 1000.0)
}

fn setup(radius: f64) -> Setup {
    let mut s = Setup::default();
    s.set_register(&format!("01={}", mm(radius))).unwrap();
    s
}

/// One piece of a random contour: a turn (degrees, + to the left), then a
/// line of a length, or an arc of a radius and sweep (degrees, + to the
/// left), written with R or with I/J.
#[derive(Clone, Debug)]
enum Piece {
    Line {
        turn: f64,
        length: f64,
    },
    Arc {
        turn: f64,
        radius: f64,
        sweep: f64,
        centre_words: bool,
    },
}

fn piece() -> impl Strategy<Value = Piece> {
    // A third of the turns are none: the next piece goes on tangentially.
    let turn = prop_oneof![Just(0.0), -170.0f64..170.0, -170.0f64..170.0];
    prop_oneof![
        3 => (turn.clone(), 4.0f64..40.0).prop_map(|(turn, length)| Piece::Line { turn, length }),
        1 => (turn, 6.0f64..30.0, prop_oneof![-150.0f64..-15.0, 15.0f64..150.0], any::<bool>())
            .prop_map(|(turn, radius, sweep, centre_words)| Piece::Arc { turn, radius, sweep, centre_words }),
    ]
}

/// The contour's blocks (each with `prefix` before its words), from the
/// start-up at the origin along +X; the points are rounded to the
/// micrometre as a program writes them, the arcs' centres and ends worked
/// out from the rounded start.
fn blocks(pieces: &[Piece], prefix: &str) -> Vec<String> {
    let (mut x, mut y, mut heading) = (10.0f64, 0.0f64, 0.0f64);
    let round = |v: f64| (v * 1000.0).round() / 1000.0;
    let mut out = Vec::new();
    for p in pieces {
        match *p {
            Piece::Line { turn, length } => {
                heading += turn.to_radians();
                x = round(x + length * heading.cos());
                y = round(y + length * heading.sin());
                out.push(format!("{prefix}G01 X{} Y{}", mm(x), mm(y)));
            }
            Piece::Arc {
                turn,
                radius,
                sweep,
                centre_words,
            } => {
                heading += turn.to_radians();
                let ccw = sweep > 0.0;
                // The centre lies left of the heading for G03, right for G02.
                let side = if ccw { 1.0 } else { -1.0 };
                let (cx, cy) = (
                    x - side * radius * heading.sin(),
                    y + side * radius * heading.cos(),
                );
                let a0 = (y - cy).atan2(x - cx);
                let a1 = a0 + sweep.to_radians();
                let (ex, ey) = (round(cx + radius * a1.cos()), round(cy + radius * a1.sin()));
                let code = if ccw { "G03" } else { "G02" };
                let centre = if centre_words {
                    format!("I{} J{}", mm(cx - x), mm(cy - y))
                } else {
                    format!("R{}", mm(radius))
                };
                out.push(format!("{prefix}{code} X{} Y{} {centre}", mm(ex), mm(ey)));
                heading += sweep.to_radians();
                x = ex;
                y = ey;
            }
        }
    }
    out
}

/// The program: G41/G42 start-up to (10, 0), the contour, G40 back.
fn program(pieces: &[Piece], code: &str, prefix: &str) -> String {
    let mut text = format!("G90 G17 G00 X0 Y0\nG01 {code} D01 X10. Y0 F100.\n");
    for b in blocks(pieces, prefix) {
        text += &b;
        text.push('\n');
    }
    text += "G40 G01 X0 Y0\nM30\n";
    text
}

/// The moves of a run, each as its Debug text (which tells -0.0 from 0.0:
/// bit for bit), and its errors with their lines.
fn outcome(r: &Run) -> (Vec<String>, Vec<(&'static str, u32)>) {
    let moves = r.moves.iter().map(|m| format!("{m:?}")).collect();
    let errors = r
        .diagnostics
        .iter()
        .filter(|d| d.is_error())
        .map(|d| (d.code, d.line))
        .collect();
    (moves, errors)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// Behaviour 16.5–16.12: the blocks of motion words alone run by the
    /// fast way in offset mode give the moves, bit for bit, and the alarms
    /// the general code gives the same blocks with a G17 (which keeps them
    /// off the fast way and changes nothing else).
    #[test]
    fn a_plain_block_in_offset_mode_moves_as_the_general_code_moves_it(
        pieces in prop::collection::vec(piece(), 2..14),
        radius in 0.3f64..4.0,
        left in any::<bool>(),
    ) {
        let code = if left { "G41" } else { "G42" };
        let fast = run(&program(&pieces, code, ""), &setup(radius));
        let general = run(&program(&pieces, code, "G17 "), &setup(radius));
        let (a, b) = (outcome(&fast), outcome(&general));
        prop_assert_eq!(a.1, b.1);
        prop_assert_eq!(a.0.len(), b.0.len());
        for (m, n) in a.0.iter().zip(&b.0) {
            prop_assert_eq!(m, n);
        }
    }

    /// Behaviour 16.5–16.7: the corner of two lines in offset mode (inside,
    /// obtuse and acute outside, tangent, nearly straight or reversed) is
    /// the general rule's, bit for bit.
    #[test]
    fn the_corner_of_two_lines_is_the_general_rules(
        (x0, y0) in (-50.0f64..50.0, -50.0f64..50.0),
        (a1, l1) in (0.0f64..std::f64::consts::TAU, 0.01f64..60.0),
        turn in prop_oneof![
            -std::f64::consts::PI..std::f64::consts::PI,
            Just(0.0),
            -1e-5f64..1e-5,
            Just(std::f64::consts::PI),
        ],
        l2 in 0.01f64..60.0,
        o in prop_oneof![0.1f64..5.0, -5.0f64..-0.1],
    ) {
        let p = [x0 + l1 * a1.cos(), y0 + l1 * a1.sin()];
        let a2 = a1 + turn;
        let prev = Path::Line { from: [x0, y0], to: p };
        let next = Path::Line { from: p, to: [p[0] + l2 * a2.cos(), p[1] + l2 * a2.sin()] };
        let rule = Rule::Offset(Outside::Vectors);
        let fast = geo::corner(&prev, &next, o, o, rule);
        let general = geo::general_corner(&prev, &next, o, o, rule);
        prop_assert_eq!(format!("{fast:?}"), format!("{general:?}"));
    }
}
