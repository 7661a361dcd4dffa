//! Property tests of cutter radius compensation C (behaviour 16.5–16.7,
//! 16.13): on random convex polygons and rounded rectangles, the tool
//! centre runs exactly the radius from the programmed contour on every
//! block of offset mode, on the side G41/G42 says, and G41 on a contour
//! gives the corners G42 gives on the same contour reversed; so with
//! chamfers and corner rounds cut at the corners (16.19).
#![cfg(not(target_arch = "wasm32"))]

mod common;
use common::*;
use offsetlab::offsets::cutter::Phase;
use offsetlab::{Move, Run, Setup};
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

/// The vertices of a convex polygon round (cx, cy), counter-clockwise: n
/// points at angles 2πk/n moved by up to ±15% of a step.
fn polygon() -> impl Strategy<Value = Vec<(f64, f64)>> {
    (
        3usize..8,
        20.0f64..60.0,
        (-50.0f64..50.0, -50.0f64..50.0),
        0.0f64..std::f64::consts::TAU,
        prop::collection::vec(-0.15f64..0.15, 8),
    )
        .prop_map(|(n, radius, (cx, cy), turn, jitter)| {
            let step = std::f64::consts::TAU / n as f64;
            (0..n)
                .map(|k| {
                    let a = turn + step * (k as f64 + jitter[k]);
                    let x = (cx + radius * a.cos()) * 1000.0;
                    let y = (cy + radius * a.sin()) * 1000.0;
                    (x.round() / 1000.0, y.round() / 1000.0)
                })
                .collect()
        })
}

/// The program going round `points` (closed), with the start-up from their
/// centroid to the first point and the first edge once more at the end, so
/// that every corner is made in offset mode; then G40 back to the centroid.
fn contour(points: &[(f64, f64)], code: &str) -> String {
    let n = points.len() as f64;
    let cx = points.iter().map(|p| p.0).sum::<f64>() / n;
    let cy = points.iter().map(|p| p.1).sum::<f64>() / n;
    let mut text = format!("G90 G17 G00 X{} Y{}\n", mm(cx), mm(cy));
    let (x0, y0) = points[0];
    text += &format!("G01 {code} D01 X{} Y{} F100.\n", mm(x0), mm(y0));
    for &(x, y) in points[1..].iter().chain([points[0], points[1]].iter()) {
        text += &format!("X{} Y{}\n", mm(x), mm(y));
    }
    text += &format!("G40 X{} Y{}\nM30\n", mm(cx), mm(cy));
    text
}

/// [`contour`] with each edge of offset mode but the last (the blocks
/// after the start-up whose next block goes on round the polygon) written
/// by `edge` from the edge's end vertex `k` and its words; the last edge
/// and the G40 block go back to G01.
fn edged(points: &[(f64, f64)], code: &str, edge: impl Fn(usize, &str) -> String) -> String {
    let n = points.len();
    let mut lines: Vec<String> = contour(points, code).lines().map(String::from).collect();
    let last = lines.len() - 3;
    for (i, line) in lines.iter_mut().enumerate().take(last + 2).skip(2) {
        *line = if i >= last {
            format!("G01 {line}")
        } else {
            edge((i - 1) % n, line)
        };
    }
    lines.join("\n") + "\n"
}

/// The signed distance of `p` from the line through `a` and `b`,
/// positive to its left.
fn side_distance(p: [f64; 3], a: [f64; 3], b: [f64; 3]) -> f64 {
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let l = dx.hypot(dy);
    (dx * (p[1] - a[1]) - dy * (p[0] - a[0])) / l
}

/// How far a move's ends lie from the offset of its programmed path by
/// `o` (positive left): a line's parallel, an arc's concentric circle (the
/// left of a counter-clockwise arc nearer its centre); 0 for a move with
/// no path in the plane.
fn off_path(m: &Move, o: f64) -> f64 {
    let off = |p: [f64; 3]| match m.arc {
        Some(a) => {
            let c = a.programmed_center;
            let s = if a.programmed_sweep > 0.0 { 1.0 } else { -1.0 };
            ((p[0] - c[0]).hypot(p[1] - c[1]) - (a.programmed_radius - o * s)).abs()
        }
        None if m.programmed_from != m.programmed_to => {
            (side_distance(p, m.programmed_from, m.programmed_to) - o).abs()
        }
        None => 0.0,
    };
    off(m.from).max(off(m.to))
}

/// The moves of the blocks in offset mode, but the last one's (it ends by
/// the cancel rule).
fn offset_moves(r: &Run) -> Vec<Move> {
    let offset: Vec<_> = r
        .blocks
        .iter()
        .filter(|b| b.state.cutter.phase == Phase::Offset)
        .collect();
    let keep = offset.len().saturating_sub(1);
    offset[..keep]
        .iter()
        .flat_map(|b| {
            r.moves[b.first_move as usize..(b.first_move + b.move_count) as usize].to_vec()
        })
        .collect()
}

fn sorted(mut points: Vec<[f64; 3]>) -> Vec<[f64; 3]> {
    points.sort_by(|a, b| {
        let key = |p: &[f64; 3]| ((p[0] * 1e3).round() as i64, (p[1] * 1e3).round() as i64);
        key(a).cmp(&key(b))
    });
    points
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(96))]

    /// Behaviour 16.5–16.7: in offset mode every straight block runs on its
    /// offset line, the radius from its programmed line on the side the
    /// code says (G41 inside a counter-clockwise polygon, G42 outside it),
    /// and every point a corner adds stays at least the radius from the
    /// corner.
    #[test]
    fn the_tool_runs_the_radius_from_every_programmed_segment(
        points in polygon(),
        radius in 0.5f64..3.0,
        left in any::<bool>(),
    ) {
        let code = if left { "G41" } else { "G42" };
        let o = if left { radius } else { -radius };
        let text = contour(&points, code);
        let r = ok(&text, &setup(radius));
        let moves = offset_moves(&r);
        prop_assert!(!moves.is_empty());
        for m in &moves {
            if m.programmed_from != m.programmed_to {
                for p in [m.from, m.to] {
                    let d = side_distance(p, m.programmed_from, m.programmed_to);
                    prop_assert!((d - o).abs() < 2e-3, "{d} vs {o}\n{text}\n{m:?}");
                }
            } else {
                let c = m.programmed_to;
                let d = (m.to[0] - c[0]).hypot(m.to[1] - c[1]);
                prop_assert!(d >= radius - 2e-3, "{d} < {radius}\n{text}");
            }
        }
    }

    /// Behaviour 16.19: with a chamfer or a corner round at every corner,
    /// every move of offset mode runs on the offset of the path it cuts:
    /// a straight one (the block's or the chamfer) the radius from its
    /// programmed line on the code's side, a round about its programmed
    /// centre at its radius less the tool's inside (G41 in this
    /// counter-clockwise polygon) or plus it outside (G42).
    #[test]
    fn chamfered_and_rounded_corners_are_compensated_on_the_cut_path(
        points in polygon(),
        radius in 0.5f64..1.0,
        left in any::<bool>(),
        round in any::<bool>(),
    ) {
        let code = if left { "G41" } else { "G42" };
        let o = if left { radius } else { -radius };
        // Cuts the tool fits inside: a round larger than it, a chamfer long
        // enough that its offset does not run backwards (16.12).
        let word = if round { ",R2." } else { ",C3." };
        let text = edged(&points, code, |_, line| format!("{line} {word}"));
        let r = ok(&text, &setup(radius));
        let moves = offset_moves(&r);
        let arcs = moves.iter().filter(|m| m.arc.is_some()).count();
        prop_assert_eq!(arcs, if round { points.len() } else { 0 }, "{}", text);
        for m in &moves {
            if let Some(a) = m.arc {
                let want = 2.0 - o;
                prop_assert!((a.radius - want).abs() < 2e-3, "{} vs {want}\n{text}", a.radius);
            }
            let off = off_path(m, o);
            prop_assert!(off < 2e-3, "{off} off the offset path\n{text}\n{m:?}");
        }
    }

    /// Behaviour 2.36 with 16.19: with some edges bulged out as arcs
    /// (G03, R twice the chord) and a corner round at every vertex, every
    /// move of offset mode runs on the offset of the path it cuts: a line
    /// the radius from its programmed line, an arc — the bulges and the
    /// rounds — on its programmed circle's concentric one, the tool's
    /// radius nearer the centre on the left of a counter-clockwise arc.
    #[test]
    fn rounds_at_arcs_are_compensated_on_the_cut_path(
        points in polygon(),
        bulges in prop::collection::vec(any::<bool>(), 8),
        radius in 0.5f64..1.0,
        left in any::<bool>(),
    ) {
        let code = if left { "G41" } else { "G42" };
        let o = if left { radius } else { -radius };
        // An arc for each edge `bulges` says, a round at every vertex.
        let n = points.len();
        let text = edged(&points, code, |k, line| {
            let (a, b) = (points[(k + n - 1) % n], points[k]);
            if bulges[k] {
                let chord = (b.0 - a.0).hypot(b.1 - a.1);
                format!("G03 {line} R{} ,R2.", mm(2.0 * chord))
            } else {
                format!("G01 {line} ,R2.")
            }
        });
        let r = ok(&text, &setup(radius));
        let moves = offset_moves(&r);
        let bulged = (1..=n).filter(|k| bulges[k % n]).count();
        let arcs = moves.iter().filter(|m| m.arc.is_some()).count();
        prop_assert_eq!(arcs, n + bulged, "a round at each vertex and every bulge\n{}", text);
        for m in &moves {
            let off = off_path(m, o);
            prop_assert!(off < 2e-3, "{off} off the offset path\n{text}\n{m:?}");
        }
    }

    /// Behaviour 16.5–16.7: G41 on a contour makes the corners G42 makes on
    /// the same contour gone round the other way (the tool on the same side
    /// of the material).
    #[test]
    fn g41_on_a_contour_is_g42_on_the_reversed_contour(
        points in polygon(),
        radius in 0.5f64..3.0,
    ) {
        let forward = ok(&contour(&points, "G41"), &setup(radius));
        let mut reversed = points.clone();
        reversed[1..].reverse();
        let backward = ok(&contour(&reversed, "G42"), &setup(radius));
        let a = sorted(offset_moves(&forward).iter().map(|m| m.to).collect());
        let b = sorted(offset_moves(&backward).iter().map(|m| m.to).collect());
        prop_assert_eq!(a.len(), b.len());
        for (p, q) in a.iter().zip(&b) {
            prop_assert!((p[0] - q[0]).abs() < 2e-3 && (p[1] - q[1]).abs() < 2e-3, "{p:?} {q:?}");
        }
    }

    /// Behaviour 16.5: round a rectangle with rounded corners (arcs tangent
    /// to the sides), the offset arcs keep their centres and their radius
    /// is the programmed one less the tool's inside (G41, counter-clockwise)
    /// or plus it outside (G42).
    #[test]
    fn offset_arcs_keep_their_centre_and_change_their_radius_by_the_tool(
        (x0, y0) in (-50.0f64..50.0, -50.0f64..50.0),
        (w, h) in (30.0f64..120.0, 30.0f64..120.0),
        corner in 4.0f64..12.0,
        radius in 0.5f64..3.5,
        left in any::<bool>(),
    ) {
        let (x1, y1) = (x0 + w, y0 + h);
        let c = corner;
        let mid = x0 + w / 2.0;
        let code = if left { "G41" } else { "G42" };
        let f = mm;
        let text = format!(
            "G90 G17 G00 X{} Y{}\nG01 {code} D01 Y{} F100.\nX{}\nG03 X{} Y{} R{}\nG01 Y{}\nG03 X{} Y{} R{}\nG01 X{}\nG03 X{} Y{} R{}\nG01 Y{}\nG03 X{} Y{} R{}\nG01 X{}\nX{}\nG40 Y{}\nM30\n",
            f(mid), f(y0 + h / 2.0), f(y0),
            f(x1 - c), f(x1), f(y0 + c), f(c),
            f(y1 - c), f(x1 - c), f(y1), f(c),
            f(x0 + c), f(x0), f(y1 - c), f(c),
            f(y0 + c), f(x0 + c), f(y0), f(c),
            f(mid), f(mid + 5.0), f(y0 + h / 2.0),
        );
        let r = ok(&text, &setup(radius));
        let arcs: Vec<_> = r.moves.iter().filter_map(|m| m.arc).collect();
        prop_assert_eq!(arcs.len(), 4);
        let want = if left { c - radius } else { c + radius };
        for a in arcs {
            prop_assert!((a.radius - want).abs() < 2e-3, "{} vs {want}\n{text}", a.radius);
            prop_assert!((a.center[0] - a.programmed_center[0]).abs() < 1e-6);
            prop_assert!((a.center[1] - a.programmed_center[1]).abs() < 1e-6);
        }
        let o = if left { radius } else { -radius };
        for m in offset_moves(&r).iter().filter(|m| m.arc.is_none()) {
            if m.programmed_from != m.programmed_to {
                let d = side_distance(m.to, m.programmed_from, m.programmed_to);
                prop_assert!((d - o).abs() < 2e-3, "{d}\n{text}");
            }
        }
    }
}
