//! Behaviour 20: Custom Macro B, the language — variables and vacant,
//! operators and their precedence, functions, statements, the alarms; and a
//! property test of the evaluator against a reference written here.
#![cfg(not(target_arch = "wasm32"))]

use offsetlab::diag::Span;
use offsetlab::macros::{
    self, Evaluator, Options, Outcome, Statement, StatementKind, Store, Value, Variables,
};

const FANUC: Options = Options {
    signed_angles: false,
    numeric_conditions: false,
    linuxcnc: false,
};
const NAT1_NUMERIC: Options = Options {
    signed_angles: true,
    numeric_conditions: true,
    linuxcnc: false,
};

/// Runs each line as a statement (no jumps) on `store`.
#[track_caller]
fn exec(store: &mut Store, options: Options, lines: &str) -> Vec<Outcome> {
    lines
        .lines()
        .enumerate()
        .map(|(i, line)| {
            let s = macros::statement(line, 0, line.len(), i as u32 + 1)
                .unwrap_or_else(|d| panic!("{line}: {d:?}"));
            Evaluator::new(store, options)
                .execute(&s)
                .unwrap_or_else(|d| panic!("{line}: {d:?}"))
        })
        .collect()
}

/// The value of `expr` with the variables `(n, v)` set.
#[track_caller]
fn value_with(
    expr: &str,
    vars: &[(u32, f64)],
    options: Options,
) -> Result<Value, (String, String)> {
    let mut store = Store::default();
    for &(n, v) in vars {
        store.set(n, Value::Number(v));
    }
    let e = macros::expression(expr, 1).map_err(|d| (d.code.to_string(), d.message))?;
    Evaluator::new(&mut store, options)
        .value(&e)
        .map_err(|d| (d.code.to_string(), d.message))
}

#[track_caller]
fn value(expr: &str) -> f64 {
    match value_with(expr, &[], FANUC) {
        Ok(Value::Number(v)) => v,
        other => panic!("{expr}: {other:?}"),
    }
}

#[track_caller]
fn close(a: f64, b: f64) {
    assert!((a - b).abs() < 1e-9, "{a} != {b}");
}

/// The alarm code an expression or statement gives, and its message.
#[track_caller]
fn alarm(line: &str) -> (String, String) {
    let mut store = Store::default();
    let s = match macros::statement(line, 0, line.len(), 1) {
        Ok(s) => s,
        Err(d) => return (d.code.to_string(), d.message),
    };
    match Evaluator::new(&mut store, FANUC).execute(&s) {
        Ok(o) => panic!("{line} ran: {o:?}"),
        Err(d) => (d.code.to_string(), d.message),
    }
}

/// The truth of a condition with `#101` set as given.
#[track_caller]
fn holds(cond: &str, v101: Value) -> bool {
    let mut store = Store::default();
    store.set(101, v101);
    let line = format!("IF [{cond}] THEN #1 = 1");
    let s = macros::statement(&line, 0, line.len(), 1).unwrap();
    match Evaluator::new(&mut store, FANUC).execute(&s).unwrap() {
        Outcome::NotTaken => false,
        Outcome::Assigned { .. } => true,
        o => panic!("{o:?}"),
    }
}

#[test]
fn behaviour20_1_local_and_common_variables_and_their_ranges() {
    let mut s = Store::default();
    exec(
        &mut s,
        FANUC,
        "#1 = 2.5\n#33 = 1\n#100 = 7\n#199 = 8\n#500 = 9\n#999 = 10",
    );
    assert_eq!(
        s.set_variables(),
        vec![
            (1, 2.5),
            (33, 1.0),
            (100, 7.0),
            (199, 8.0),
            (500, 9.0),
            (999, 10.0)
        ]
    );
    // #34 (between local and common) and #200–#499 are no variables: PS0115.
    assert_eq!(alarm("#34 = 1").0, "macro-variable-number");
    assert_eq!(alarm("#1 = #250").0, "macro-variable-number");
    assert!(alarm("#250 = 1").1.starts_with("PS0115"));
    // #0 is read only: PS0116.
    assert_eq!(alarm("#0 = 1").0, "macro-write-protected");
    // System variables are the machine's, refused by a store alone.
    assert_eq!(alarm("#2001 = 1").0, "macro-system-variable");
}

#[test]
fn behaviour20_2_variable_by_expression_and_brackets() {
    // #[#1+2] with #1 = 3 is #5; #5 = 4 * [1 + 2] = 12.
    let mut s = Store::default();
    exec(&mut s, FANUC, "#1 = 3\n#[#1+2] = 4*[1+2]\n#6 = #[#1+2] / 2");
    assert_eq!(s.get(5), Some(Value::Number(12.0)));
    assert_eq!(s.get(6), Some(Value::Number(6.0)));
    // Constants without a point are the numbers written: #1 = 123 is 123.
    close(value("123"), 123.0);
    close(value(".5 + 5."), 5.5);
    // Keywords read in either case.
    close(value("sqrt[16] mod 3"), 1.0);
}

#[test]
fn behaviour20_2_brackets_nest_five_levels_deep() {
    // Five levels, the function's bracket counted: accepted; a sixth: PS0118.
    close(value("ABS[[[[[-1]]]]]"), 1.0);
    let (code, msg) = alarm("#1 = ABS[[[[[[-1]]]]]]");
    assert_eq!(code, "macro-bracket-nesting");
    assert!(msg.starts_with("PS0118"), "{msg}");
}

#[test]
fn behaviour20_3_an_operator_written_against_a_function_name_is_read_first() {
    // 5 AND ABS[-3] = 5 AND 3 = 1 (bits 101 and 011); 2 OR POW[2,2] =
    // 2 OR 4 = 6; 7 MOD ROUND[2.6] = 7 MOD 3 = 1; 1 - 1 XOR ABS[2] = 0 XOR 2 = 2.
    close(value("5ANDABS[-3]"), 1.0);
    close(value("2ORPOW[2,2]"), 6.0);
    close(value("7MODROUND[2.6]"), 1.0);
    close(value("1-1XORABS[2]"), 2.0);
    // A comparison too: IF[1GTABS[-2]] is false, IF[3GEADP[#0]]… reads GE.
    let mut store = Store::default();
    let s = macros::statement("IF[1GTABS[-2]]GOTO5", 0, 19, 1).unwrap();
    assert_eq!(
        Evaluator::new(&mut store, FANUC).execute(&s).unwrap(),
        Outcome::NotTaken
    );
    // Letters that are no keyword and function stay an error (PS0114).
    let (code, _) = alarm("#1 = 2ANDX[3]");
    assert_eq!(code, "macro-expression");
}

#[test]
fn behaviour20_3_multiplication_binds_tighter_than_addition() {
    // 2 + 3 * 4 = 2 + 12 = 14; [2 + 3] * 4 = 20.
    close(value("2 + 3 * 4"), 14.0);
    close(value("[2 + 3] * 4"), 20.0);
    // Left to right in a level: 12 / 3 * 2 = 4 * 2 = 8; 10 - 4 - 3 = 3.
    close(value("12 / 3 * 2"), 8.0);
    close(value("10 - 4 - 3"), 3.0);
    // AND is of the multiplication level, OR of the addition level:
    // 1 OR 6 AND 3 = 1 OR (6 AND 3 = 2) = 3; [1 OR 6] AND 3 = 7 AND 3 = 3.
    close(value("1 OR 6 AND 3"), 3.0);
    close(value("4 OR 2 AND 2"), 6.0);
    // MOD too: 2 + 27 MOD 20 = 2 + 7 = 9 (Haas: 27 MOD 20 = 7).
    close(value("2 + 27 MOD 20"), 9.0);
    // A sign binds to its operand: -2 * 3 = -6, 2 * -3 = -6, --2 = 2.
    close(value("-2 * 3"), -6.0);
    close(value("2 * -3"), -6.0);
    close(value("--2"), 2.0);
}

#[test]
fn behaviour20_3_logic_operators_work_bit_by_bit_on_whole_parts() {
    // 5 = 101b, 3 = 011b: AND 001b = 1, OR 111b = 7, XOR 110b = 6.
    close(value("5 AND 3"), 1.0);
    close(value("5 OR 3"), 7.0);
    close(value("5 XOR 3"), 6.0);
    // Haas: only the integer portion is used: 5.9 AND 3.2 = 5 AND 3 = 1.
    close(value("5.9 AND 3.2"), 1.0);
}

#[test]
fn behaviour20_4_vacant_plus_vacant_is_zero() {
    let mut s = Store::default();
    // #1 = #0 is vacant; #2 = #0 + #0 is 0; #3 = #0 * 5 is 0; #4 = #0 + 1 is 1;
    // #5 = -#0 is 0 (vacant in arithmetic is 0).
    exec(
        &mut s,
        FANUC,
        "#1 = #0\n#2 = #0 + #0\n#3 = #0 * 5\n#4 = #0 + 1\n#5 = -#0\n#6 = #1",
    );
    assert_eq!(s.get(1), Some(Value::Vacant));
    assert_eq!(s.get(2), Some(Value::Number(0.0)));
    assert_eq!(s.get(3), Some(Value::Number(0.0)));
    assert_eq!(s.get(4), Some(Value::Number(1.0)));
    assert_eq!(s.get(5), Some(Value::Number(0.0)));
    // A vacant copied is still vacant.
    assert_eq!(s.get(6), Some(Value::Vacant));
    // Dividing by a vacant divides by 0.
    assert_eq!(alarm("#1 = 1 / #0").0, "macro-zero-divide");
}

#[test]
fn behaviour20_5_vacant_and_zero_differ_in_eq_and_ne_only() {
    let (vacant, zero) = (Value::Vacant, Value::Number(0.0));
    // #101 vacant: EQ #0 holds, NE 0 holds, GE #0 holds, GT 0 does not.
    assert!(holds("#101 EQ #0", vacant));
    assert!(holds("#101 NE 0", vacant));
    assert!(holds("#101 GE #0", vacant));
    assert!(!holds("#101 GT 0", vacant));
    assert!(holds("#101 LE #0", vacant));
    assert!(!holds("#101 LT 0", vacant));
    // #101 = 0: EQ #0 does not hold, NE 0 does not, GE #0 holds, GT 0 not.
    assert!(!holds("#101 EQ #0", zero));
    assert!(!holds("#101 NE 0", zero));
    assert!(holds("#101 GE #0", zero));
    assert!(!holds("#101 GT 0", zero));
    // [#0 EQ 0] is false, [#0 EQ #0] true.
    assert!(!holds("#0 EQ 0", zero));
    assert!(holds("#0 EQ #0", zero));
    // Comparisons joined by AND and OR.
    assert!(holds("[#101 GT 1] AND [#101 LT 3]", Value::Number(2.0)));
    assert!(!holds("[#101 GT 1] AND [#101 LT 3]", Value::Number(3.0)));
    assert!(holds("[#101 EQ 5] OR [#101 EQ 3]", Value::Number(3.0)));
}

#[test]
fn behaviour7_40_a_comparison_is_a_number_only_on_haas() {
    // Fanuc: a comparison cannot be stored (PS0114), and IF takes a comparison.
    assert_eq!(alarm("#1 = [1 LT 2]").0, "macro-expression");
    assert_eq!(alarm("IF [#1] THEN #2 = 1").0, "macro-expression");
    // Haas: every expression is a value, TRUE 1.0 and FALSE 0.0, and a
    // condition holds when not 0.
    let mut s = Store::default();
    let out = exec(
        &mut s,
        NAT1_NUMERIC,
        "#1 = [1 LT 2]\n#2 = [3 LT 2]\nIF [#1] THEN #3 = 7\nIF [#2] THEN #4 = 7",
    );
    assert_eq!(s.get(1), Some(Value::Number(1.0)));
    assert_eq!(s.get(2), Some(Value::Number(0.0)));
    assert_eq!(s.get(3), Some(Value::Number(7.0)));
    assert_eq!(out[3], Outcome::NotTaken);
}

#[test]
fn behaviour20_6_trigonometry_in_degrees() {
    // SIN[30] = 0.5, COS[60] = 0.5, TAN[45] = 1, SQRT[#1*#1+#2*#2] with 3, 4 = 5.
    close(value("SIN[30]"), 0.5);
    close(value("COS[60]"), 0.5);
    close(value("TAN[45]"), 1.0);
    let v = value_with("SQRT[#1*#1+#2*#2]", &[(1, 3.0), (2, 4.0)], FANUC).unwrap();
    assert_eq!(v, Value::Number(5.0));
    // ACOS[0.5] = 60, ASIN[0.5] = 30.
    close(value("ACOS[0.5]"), 60.0);
    close(value("ASIN[0.5]"), 30.0);
    // TAN is SIN/COS: at 90° a division by zero, PS0112.
    assert_eq!(alarm("#1 = TAN[90]").0, "macro-zero-divide");
}

#[test]
fn behaviour7_39_atan_and_asin_ranges() {
    // ATAN[1]/[1] = ATAN[1,1] = 45; the point (-1, -1) is at 225° (NAT = 0)
    // or -135° (NAT = 1, and Haas).
    close(value("ATAN[1]/[1]"), 45.0);
    close(value("ATAN[1,1]"), 45.0);
    close(value("ATAN[-1]/[-1]"), 225.0);
    let signed = value_with("ATAN[-1]/[-1]", &[], NAT1_NUMERIC).unwrap();
    assert!((signed.number() + 135.0).abs() < 1e-9);
    // ASIN[-0.5] = -30 is 330 in 270…90 (NAT = 0), -30 with NAT = 1.
    close(value("ASIN[-0.5]"), 330.0);
    let signed = value_with("ASIN[-0.5]", &[], NAT1_NUMERIC).unwrap();
    assert!((signed.number() + 30.0).abs() < 1e-9);
    // ATAN of one argument: ATAN[1] = 45; ATAN[-1] = 315 (NAT = 0).
    close(value("ATAN[1]"), 45.0);
    close(value("ATAN[-1]"), 315.0);
    // ATAN[a]/2 with a bracket after the slash only: ATAN[1]/2 = 45/2?
    // No: `/[`…`]` is the two-argument form, `/2` a division: 22.5.
    close(value("ATAN[1]/2"), 22.5);
}

#[test]
fn behaviour20_6_round_fix_fup() {
    // ROUND rounds half away from zero; FIX drops the fraction; FUP raises it.
    // #1 = 1.2, #2 = -1.2: FIX 1, -1; FUP 2, -2. ROUND[1.5] = 2, ROUND[-1.5] = -2.
    close(value("FIX[1.2]"), 1.0);
    close(value("FIX[-1.2]"), -1.0);
    close(value("FUP[1.2]"), 2.0);
    close(value("FUP[-1.2]"), -2.0);
    close(value("FUP[3]"), 3.0);
    close(value("ROUND[1.5]"), 2.0);
    close(value("ROUND[-1.5]"), -2.0);
    close(value("ROUND[3.54]"), 4.0);
}

#[test]
fn behaviour20_6_round_in_a_word_rounds_to_the_increment() {
    // Haas: #1 = 1.00333; X[ROUND[#1] + ROUND[#1]] with 0.0001 in: 1.0033 + 1.0033 = 2.0066.
    let mut s = Store::default();
    s.set(1, Value::Number(1.00333));
    let e = macros::expression("[ROUND[#1] + ROUND[#1]]", 1).unwrap();
    let v = Evaluator::new(&mut s, FANUC)
        .word_value(&e, 0.0001)
        .unwrap();
    close(v.number(), 2.0066);
    // The same outside a word: 1 + 1 = 2.
    close(
        Evaluator::new(&mut s, FANUC).value(&e).unwrap().number(),
        2.0,
    );
}

#[test]
fn behaviour20_6_powers_logarithms_and_bcd() {
    // POW[2,10] = 1024; POW[4,0.5] = 2; EXP[0] = 1; LN[EXP[2]] = 2; ABS[-3] = 3.
    close(value("POW[2,10]"), 1024.0);
    close(value("POW[4,0.5]"), 2.0);
    close(value("EXP[0]"), 1.0);
    close(value("LN[EXP[2]]"), 2.0);
    close(value("ABS[-3]"), 3.0);
    // BCD[12] = 0x12 = 18; BIN[18] = 12; BIN[BCD[9876]] = 9876.
    close(value("BCD[12]"), 18.0);
    close(value("BIN[18]"), 12.0);
    close(value("BIN[BCD[9876]]"), 9876.0);
    // 0x1A = 26 has the hex digit A: no BCD number.
    assert_eq!(alarm("#1 = BIN[26]").0, "macro-argument-range");
}

#[test]
fn behaviour20_9_arguments_out_of_range_are_ps0119() {
    for line in [
        "#1 = SQRT[-1]",
        "#1 = ASIN[2]",
        "#1 = ACOS[-1.5]",
        "#1 = LN[0]",
        "#1 = POW[-8,0.5]",
        "#1 = BCD[1.5]",
        "#1 = ATAN[0]/[0]",
    ] {
        let (code, msg) = alarm(line);
        assert_eq!(code, "macro-argument-range", "{line}");
        assert!(msg.starts_with("PS0119"), "{msg}");
    }
    // ADP is parsed and refused, never computed wrongly.
    assert_eq!(alarm("#1 = ADP[1]").0, "macro-not-modelled");
}

#[test]
fn behaviour20_9_division_by_zero_and_overflow() {
    let (code, msg) = alarm("#1 = 5 / [2 - 2]");
    assert_eq!(code, "macro-zero-divide");
    assert!(msg.starts_with("PS0112"), "{msg}");
    assert_eq!(alarm("#1 = 5 MOD 0").0, "macro-zero-divide");
    // 10^200 * 10^200 = 10^400: past 10^308, PS0111.
    let (code, msg) = alarm("#1 = POW[10,200] * POW[10,200]");
    assert_eq!(code, "macro-overflow");
    assert!(msg.starts_with("PS0111"), "{msg}");
    assert_eq!(alarm("#1 = EXP[1000]").0, "macro-overflow");
}

#[test]
fn behaviour20_9_format_errors_point_at_their_place() {
    let line = "#1 = 2 + * 3";
    let d = macros::statement(line, 0, line.len(), 4).unwrap_err();
    assert_eq!(d.code, "macro-expression");
    assert!(d.message.starts_with("PS0114"), "{}", d.message);
    // The `*` at byte 9, line 4.
    assert_eq!((d.span.start, d.span.line), (9, 4));
    assert_eq!(alarm("#1 = FOO[2]").0, "macro-expression");
    assert_eq!(alarm("#1 = [2").0, "macro-expression");
    assert_eq!(alarm("#1.5 = 2").0, "macro-expression");
    assert_eq!(alarm("#1 = 2 3").0, "macro-expression");
}

#[test]
fn behaviour20_7_statements_parse_into_their_forms() {
    let kind = |line: &str| -> StatementKind {
        let s: Statement = macros::statement(line, 0, line.len(), 1).unwrap();
        assert_eq!(s.span.end as usize, line.trim_end().len(), "{line}");
        s.kind
    };
    assert!(matches!(kind("GOTO 10"), StatementKind::Goto(_)));
    assert!(matches!(
        kind("IF [#1 GT 2] GOTO10"),
        StatementKind::IfGoto(..)
    ));
    assert!(matches!(
        kind("if [#1 gt 2] then #2 = 3"),
        StatementKind::IfThen(..)
    ));
    assert!(matches!(
        kind("WHILE [#1 LT 5] DO1"),
        StatementKind::While(_, 1)
    ));
    assert!(matches!(kind("DO 2"), StatementKind::Do(2)));
    assert!(matches!(kind("END3"), StatementKind::End(3)));
    // DO and END take 1, 2 or 3: PS0126.
    let (code, msg) = alarm("WHILE [#1 LT 5] DO4");
    assert_eq!(code, "macro-loop-number");
    assert!(msg.starts_with("PS0126"), "{msg}");
    assert_eq!(alarm("END 0").0, "macro-loop-number");
    // IF takes GOTO or THEN; THEN an assignment: PS0125.
    assert_eq!(alarm("IF [#1 EQ 1] #2 = 3").0, "macro-statement");
    assert_eq!(alarm("IF [#1 EQ 1] THEN GOTO 5").0, "macro-statement");
}

#[test]
fn behaviour20_7_jumps_are_outcomes_for_the_executor() {
    let mut s = Store::default();
    let out = exec(
        &mut s,
        FANUC,
        "#1 = 3\nGOTO #1 * 10\nIF [#1 GT 2] GOTO 5\nIF [#1 GT 4] GOTO 5\nWHILE [#1 LT 5] DO1\nEND1",
    );
    assert_eq!(out[1], Outcome::Goto(30));
    assert_eq!(out[2], Outcome::Goto(5));
    assert_eq!(out[3], Outcome::NotTaken);
    assert_eq!(
        out[4],
        Outcome::While {
            holds: true,
            label: 1
        }
    );
    assert_eq!(out[5], Outcome::End(1));
    // A jump to a vacant sequence number: PS0128.
    assert_eq!(alarm("GOTO #5").0, "macro-vacant");
    assert_eq!(alarm("GOTO 0").0, "macro-sequence-number");
}

#[test]
fn behaviour20_8_an_assignment_says_what_it_set_and_what_was_there() {
    let mut s = Store::default();
    let out = exec(
        &mut s,
        FANUC,
        "#1 = 3\n#2 = 4\n#101 = SQRT[#1*#1+#2*#2]\n#101 = #101 / 2",
    );
    assert_eq!(
        out[2],
        Outcome::Assigned {
            number: 101,
            value: Value::Number(5.0),
            was: Value::Vacant
        }
    );
    assert_eq!(
        out[3],
        Outcome::Assigned {
            number: 101,
            value: Value::Number(2.5),
            was: Value::Number(5.0)
        }
    );
    assert_eq!(Value::Number(12.5).to_string(), "12.500");
    assert_eq!(Value::Vacant.to_string(), "vacant");
}

#[test]
fn behaviour20_8_a_bolt_circle_as_straight_line_macro_code() {
    // Six holes on a 50 mm circle about (10, 20), the first at 0°:
    // #1 = radius 25, #2 = angle, X = 10 + 25 cos, Y = 20 + 25 sin.
    // Hole 2 at 60°: X = 10 + 25 * 0.5 = 22.5, Y = 20 + 25 * 0.8660254 = 41.650635.
    let mut s = Store::default();
    let mut holes = Vec::new();
    exec(&mut s, FANUC, "#1 = 25\n#3 = 10\n#4 = 20\n#5 = 6");
    for hole in 0..6 {
        exec(&mut s, FANUC, &format!("#2 = {hole} * 360 / #5"));
        let x = macros::expression("[#3 + #1*COS[#2]]", 1).unwrap();
        let y = macros::expression("[#4 + #1*SIN[#2]]", 1).unwrap();
        let mut e = Evaluator::new(&mut s, FANUC);
        holes.push((e.value(&x).unwrap().number(), e.value(&y).unwrap().number()));
    }
    let expect = [
        (35.0, 20.0),
        (22.5, 41.650635),
        (-2.5, 41.650635),
        (-15.0, 20.0),
        (-2.5, -1.650635),
        (22.5, -1.650635),
    ];
    for (got, want) in holes.iter().zip(expect) {
        assert!(
            (got.0 - want.0).abs() < 1e-6 && (got.1 - want.1).abs() < 1e-6,
            "{got:?} {want:?}"
        );
    }
}

/// A variable table for the property test: only #1–#9, all numbers.
struct Table([f64; 10]);

impl Variables for Table {
    fn read(&mut self, n: u32, _: Span) -> Result<Value, offsetlab::diag::Diagnostic> {
        Ok(Value::Number(self.0[n as usize % 10]))
    }
    fn write(&mut self, n: u32, v: Value, _: Span) -> Result<(), offsetlab::diag::Diagnostic> {
        self.0[n as usize % 10] = v.number();
        Ok(())
    }
}

mod props {
    use super::*;
    use proptest::prelude::*;

    /// A random expression: its text (fully bracketed where its operator
    /// binds looser than its parent's) and the value a reference
    /// evaluation gives (None: an alarm is due, as a division by 0).
    #[derive(Clone, Debug)]
    enum Tree {
        Num(u8),
        Var(u8),
        Bin(u8, Box<Tree>, Box<Tree>),
        Fun(u8, Box<Tree>),
    }

    const OPS: [&str; 5] = ["+", "-", "*", "/", "MOD"];
    const FUNS: [&str; 4] = ["ABS", "FIX", "FUP", "ROUND"];

    fn tree() -> impl Strategy<Value = Tree> {
        let leaf = prop_oneof![(0u8..20).prop_map(Tree::Num), (1u8..10).prop_map(Tree::Var)];
        // Depth 3 keeps within the five bracket levels (one per level at most).
        leaf.prop_recursive(3, 16, 2, |inner| {
            prop_oneof![
                (0u8..5, inner.clone(), inner.clone()).prop_map(|(o, a, b)| Tree::Bin(
                    o,
                    Box::new(a),
                    Box::new(b)
                )),
                (0u8..4, inner).prop_map(|(f, a)| Tree::Fun(f, Box::new(a))),
            ]
        })
    }

    /// The text, every operation in brackets (precedence is tested above).
    fn text(t: &Tree) -> String {
        match t {
            Tree::Num(n) => format!("{n}"),
            Tree::Var(v) => format!("#{v}"),
            Tree::Bin(o, a, b) => format!("[{} {} {}]", text(a), OPS[*o as usize], text(b)),
            Tree::Fun(f, a) => format!("{}[{}]", FUNS[*f as usize], text(a)),
        }
    }

    /// The reference: plain f64 arithmetic as the manual defines each.
    fn reference(t: &Tree, vars: &[f64; 10]) -> Option<f64> {
        Some(match t {
            Tree::Num(n) => f64::from(*n),
            Tree::Var(v) => vars[*v as usize],
            Tree::Bin(o, a, b) => {
                let (x, y) = (reference(a, vars)?, reference(b, vars)?);
                match o {
                    0 => x + y,
                    1 => x - y,
                    2 => x * y,
                    3 if y == 0.0 => return None,
                    3 => x / y,
                    _ if y == 0.0 => return None,
                    _ => x % y,
                }
            }
            Tree::Fun(f, a) => {
                let x = reference(a, vars)?;
                match f {
                    0 => x.abs(),
                    1 => x.trunc(),
                    2 => x.abs().ceil() * x.signum(),
                    _ => x.round(),
                }
            }
        })
    }

    /// Depth in brackets of a tree's text.
    fn depth(t: &Tree) -> u32 {
        match t {
            Tree::Num(_) | Tree::Var(_) => 0,
            Tree::Bin(_, a, b) => 1 + depth(a).max(depth(b)),
            Tree::Fun(_, a) => 1 + depth(a),
        }
    }

    proptest! {
        #[test]
        fn behaviour20_3_the_evaluator_agrees_with_a_reference(
            t in tree(),
            vars in proptest::array::uniform10(-50i32..50),
        ) {
            let vars = vars.map(|v| f64::from(v) / 4.0);
            let src = text(&t);
            let e = macros::expression(&src, 1);
            if depth(&t) > macros::MAX_NESTING {
                prop_assert_eq!(e.unwrap_err().code, "macro-bracket-nesting");
                return Ok(());
            }
            let e = e.unwrap();
            let got = Evaluator::new(&mut Table(vars), FANUC).value(&e);
            match reference(&t, &vars) {
                Some(want) => {
                    let got = got.unwrap().number();
                    prop_assert!((got - want).abs() <= 1e-9 * want.abs().max(1.0), "{} = {} != {}", src, got, want);
                }
                None => prop_assert_eq!(got.unwrap_err().code, "macro-zero-divide"),
            }
        }

        #[test]
        fn any_text_parses_or_fails_without_a_panic(s in "[#\\[\\]0-9A-Z+*/.= -]{0,40}") {
            let _ = macros::statement(&s, 0, s.len(), 1);
            let _ = macros::expression(&s, 1);
        }

        /// LinuxCNC's grammar too (behaviour 22.5–22.7): `<>`, `**`,
        /// o-words and chained comparisons, each parsed and evaluated
        /// without a panic (the chain's span checks run in debug builds).
        #[test]
        fn any_linuxcnc_text_parses_and_evaluates_without_a_panic(
            s in "(o[0-9]{1,3} |o<[a-z ]{1,4}> )?[#<>\\[\\]0-9A-Z+*/.= -]{0,40}",
        ) {
            let dialect = macros::Dialect { abbreviations: false, linuxcnc: true };
            let _ = macros::statement_with(&s, 0, s.len(), 1, dialect);
            let _ = macros::oword(&s, 0, s.len(), 1);
            if let Ok(e) = macros::expression_with(&s, 1, dialect) {
                let options = macros::Options { linuxcnc: true, numeric_conditions: true, signed_angles: true };
                let _ = Evaluator::new(&mut Table([0.0; 10]), options).value(&e);
            }
        }
    }
}
