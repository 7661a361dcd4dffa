//! Property tests (proptest) of the offset rules and of robustness.
#![cfg(not(target_arch = "wasm32"))]

mod common;
use common::*;
use offsetlab::setup::{DecimalInput, LatheXOffset, LengthOffsetWithoutZ, Mirror};
use offsetlab::{MachineKind, Run, Setup, run};
use proptest::prelude::*;

/// A length in micrometres, written with three decimals.
fn mm(um: i64) -> String {
    let sign = if um < 0 { "-" } else { "" };
    let a = um.unsigned_abs();
    format!("{sign}{}.{:03}", a / 1000, a % 1000)
}

fn amount() -> impl Strategy<Value = i64> {
    prop_oneof![Just(0i64), -400_000i64..400_000]
}

fn register() -> impl Strategy<Value = i64> {
    -50_000i64..50_000
}

fn setup_d01(v_um: i64) -> Setup {
    let mut s = Setup::default();
    s.set_register(&format!("01={}", mm(v_um))).unwrap();
    s
}

fn last_state(r: &Run) -> ([f64; 3], [f64; 3]) {
    let b = r.blocks.last().unwrap();
    (b.state.programmed, b.state.actual)
}

proptest! {
    /// Behaviour 4.1/4.7: G45 then G46 with the same D on the same programmed
    /// moves brings the tool back onto the programmed path.
    #[test]
    fn g45_then_g46_on_the_same_moves_returns_to_the_programmed_path(
        moves in prop::collection::vec((amount(), amount()), 1..8),
        v in register(),
    ) {
        let mut text = String::from("G91 G01 F100. D01\n");
        for (x, y) in &moves {
            text += &format!("G45 X{} Y{}\n", mm(*x), mm(*y));
        }
        for (x, y) in &moves {
            text += &format!("G46 X{} Y{}\n", mm(*x), mm(*y));
        }
        let r = ok(&text, &setup_d01(v));
        let (p, a) = last_state(&r);
        for i in 0..3 {
            prop_assert!((p[i] - a[i]).abs() < 1e-6, "{p:?} {a:?}\n{text}");
        }
    }

    /// Behaviour 4.1: G47 is two G45 on a move split into two parts of the same
    /// direction.
    #[test]
    fn g47_equals_two_g45(total in amount(), cut in 0.0f64..1.0, v in register()) {
        let first = (total as f64 * cut).round() as i64;
        let second = total - first;
        prop_assume!(total == 0 || (first != 0 && second != 0));
        let s = setup_d01(v);
        let one = ok(&format!("G91 G00 G47 X{} D01", mm(total)), &s);
        let two = ok(&format!("G91 G00 G45 X{} D01\nG45 X{}", mm(first), mm(second)), &s);
        let (a, b) = (last_state(&one).1, last_state(&two).1);
        prop_assert!((a[0] - b[0]).abs() < 1e-6, "{a:?} {b:?}");
    }

    /// Behaviour 2.17 and seed 003: a mirrored program gives the mirrored path, tool
    /// position offset included.
    #[test]
    fn mirror_x_gives_the_mirrored_path(
        blocks in prop::collection::vec(mirror_block(), 1..12),
        v in register(),
    ) {
        let text = blocks.join("\n");
        let plain = run(&text, &setup_d01(v));
        let mut s = setup_d01(v);
        s.settings.mirror = Mirror { x: true, y: false };
        let mirrored = run(&text, &s);
        prop_assert_eq!(plain.block_count, mirrored.block_count, "{}", text);
        for (a, b) in plain.blocks.iter().zip(&mirrored.blocks) {
            let (pa, ma) = (a.state.actual, b.state.actual);
            prop_assert!((pa[0] + ma[0]).abs() < 1e-6 && (pa[1] - ma[1]).abs() < 1e-6,
                "{pa:?} vs {ma:?}\n{text}");
        }
        for (a, b) in plain.moves.iter().zip(&mirrored.moves) {
            if let (Some(x), Some(y)) = (a.arc, b.arc) {
                prop_assert!((x.sweep + y.sweep).abs() < 1e-6, "arcs turn the other way");
            }
        }
    }

    /// Behaviour 2.4, 16.13: actual = programmed + the reported vectors, after every block;
    /// and the tool never jumps: each move starts where the last one ended.
    #[test]
    fn actual_minus_programmed_is_the_reported_vectors(
        blocks in prop::collection::vec(mill_block(), 1..16),
        d in register(),
        h in register(),
        next_z in any::<bool>(),
    ) {
        let text = blocks.join("\n");
        let mut s = setup_d01(d);
        s.set_register(&format!("02={}", mm(h))).unwrap();
        if next_z {
            s.settings.length_offset_without_z = Some(LengthOffsetWithoutZ::NextZ);
        }
        let r = run(&text, &s);
        for b in &r.blocks {
            let st = &b.state;
            let mut want = st.programmed;
            for (w, v) in want.iter_mut().zip(st.position.vector) {
                *w += v;
            }
            want[2] += st.length.vector;
            for (w, v) in want.iter_mut().zip(st.cutter.vector) {
                *w += v;
            }
            same(st.actual, want);
        }
        for w in r.moves.windows(2) {
            same(w[1].from, w[0].to);
        }
    }

    /// The lathe: actual = programmed + T vector, continuity of the tool.
    #[test]
    fn lathe_actual_minus_programmed_is_the_t_vector(
        blocks in prop::collection::vec(lathe_block(), 1..16),
        x in register(),
        z in register(),
        radius in any::<bool>(),
    ) {
        let text = blocks.join("\n");
        let mut s = lathe(&[]);
        s.set_register(&format!("01=X{},Z{}", mm(x), mm(z))).unwrap();
        s.set_register(&format!("02=X{},Z{}", mm(z), mm(x))).unwrap();
        if radius {
            s.settings.lathe_x_offset = LatheXOffset::Radius;
        }
        let r = run(&text, &s);
        for b in &r.blocks {
            let st = &b.state;
            same(st.actual, [st.programmed[0] + st.lathe.vector[0], 0.0, st.programmed[2] + st.lathe.vector[2]]);
        }
        for w in r.moves.windows(2) {
            same(w[1].from, w[0].to);
        }
    }

    /// Nothing panics, whatever the text, machine or settings.
    #[test]
    fn parse_and_run_never_panic_on_gcode_like_text(
        text in "[GMXYZUWIJKRDHTFSPQLNO0-9 .+\\-;()%/\n#]{0,300}",
        lathe in any::<bool>(),
        calculator in any::<bool>(),
        skip in any::<bool>(),
    ) {
        let mut s = Setup::default();
        if lathe {
            s.machine = MachineKind::Lathe;
        }
        if calculator {
            s.settings.decimal_input = Some(DecimalInput::Calculator);
        }
        s.settings.block_skip = skip;
        let r = run(&text, &s);
        for d in &r.diagnostics {
            prop_assert!(d.line >= 1 && d.column >= 1 && !d.message.is_empty());
        }
        for m in &r.moves {
            prop_assert!(m.to.iter().chain(&m.from).all(|v| v.is_finite()));
        }
    }

    #[test]
    fn parse_and_run_never_panic_on_any_text(text in "\\PC{0,200}") {
        let _ = run(&text, &Setup::default());
    }
}

fn mirror_block() -> impl Strategy<Value = String> {
    prop_oneof![
        (amount(), amount()).prop_map(|(x, y)| format!("G91 G01 X{} Y{} F100.", mm(x), mm(y))),
        (amount(), amount()).prop_map(|(x, y)| format!("G90 G00 X{} Y{}", mm(x), mm(y))),
        (45u16..=48, amount(), amount()).prop_map(|(g, x, y)| format!(
            "G91 G01 G{g} X{} Y{}",
            mm(x),
            mm(y)
        )),
        (
            1_000i64..100_000,
            1_000i64..100_000,
            any::<bool>(),
            any::<bool>()
        )
            .prop_map(|(x, y, cw, long)| {
                let half = ((x * x + y * y) as f64).sqrt() / 2.0;
                let r = (half * 1.5) as i64 * if long { -1 } else { 1 };
                format!(
                    "G91 G0{} X{} Y{} R{} F100.",
                    if cw { 2 } else { 3 },
                    mm(x),
                    mm(y),
                    mm(r)
                )
            }),
    ]
}

fn mill_block() -> impl Strategy<Value = String> {
    prop_oneof![
        (amount(), amount(), amount()).prop_map(|(x, y, z)| format!(
            "G91 G01 X{} Y{} Z{} F100.",
            mm(x),
            mm(y),
            mm(z)
        )),
        (amount(), amount()).prop_map(|(x, z)| format!("G90 G00 X{} Z{}", mm(x), mm(z))),
        (45u16..=48, amount(), amount()).prop_map(|(g, x, z)| format!(
            "G91 G{g} X{} Z{} D01",
            mm(x),
            mm(z)
        )),
        (45u16..=48, amount()).prop_map(|(g, z)| format!("G90 G{g} Z{} D01", mm(z))),
        prop_oneof![
            Just("G43 H02"),
            Just("G44 H02"),
            Just("G49"),
            Just("H00"),
            Just("G43 H02 X1.")
        ]
        .prop_map(String::from),
        amount().prop_map(|z| format!("G90 G00 G43 Z{} H02", mm(z))),
        Just("G91 G28 Z0".to_string()),
        Just("G90 G00 Z20.\nG98 G81 X5. Y5. Z-3. R2. F100.\nG80".to_string()),
        // Cutter compensation (behaviour 16): its vector is reported too.
        prop_oneof![Just("G41 D01"), Just("G42 D01"), Just("G40"), Just("G39")]
            .prop_map(String::from),
    ]
}

fn lathe_block() -> impl Strategy<Value = String> {
    prop_oneof![
        (amount(), amount()).prop_map(|(x, z)| format!("G00 X{} Z{}", mm(x), mm(z))),
        (amount(), amount()).prop_map(|(u, w)| format!("G01 U{} W{} F0.2", mm(u), mm(w))),
        prop_oneof![
            Just("T0101"),
            Just("T0102"),
            Just("T0202"),
            Just("T0100"),
            Just("G01 T0201")
        ]
        .prop_map(String::from),
        (amount(), amount()).prop_map(|(x, z)| format!("G00 X{} Z{} T0102", mm(x), mm(z))),
        Just("G28 U0 W0".to_string()),
        Just("G00 X60. Z2.\nG90 X50. Z-30. F0.2\nX45.\nG00 X100.".to_string()),
    ]
}
