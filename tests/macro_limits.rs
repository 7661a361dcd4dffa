//! Behaviour 20.17: expressions of any length — a flat chain of operators
//! is parsed and evaluated in a loop, never by recursion that grows with
//! the chain, and a sentence quotes a long expression as an excerpt.
//! The tests run on the test harness's threads (a smaller stack than the
//! CLI's main thread), so a walk that recursed per operand would overflow
//! here first.
#![cfg(not(target_arch = "wasm32"))]

mod common;
use common::*;

use offsetlab::macros::{self, EXCERPT, Evaluator, Options, Store, Value};

const FANUC: Options = Options {
    signed_angles: false,
    numeric_conditions: false,
    linuxcnc: false,
};

fn value(expr: &str) -> Result<f64, (String, String, u32, u32)> {
    let mut store = Store::default();
    let e = macros::expression(expr, 1)
        .map_err(|d| (d.code.to_string(), d.message, d.span.start, d.span.end))?;
    match Evaluator::new(&mut store, FANUC).value(&e) {
        Ok(Value::Number(v)) => Ok(v),
        Ok(v) => panic!("{v:?}"),
        Err(d) => Err((d.code.to_string(), d.message, d.span.start, d.span.end)),
    }
}

/// `first` followed by `n` copies of `op term`.
fn chain(first: &str, op_term: &str, n: usize) -> String {
    let mut s = String::with_capacity(first.len() + op_term.len() * n);
    s.push_str(first);
    for _ in 0..n {
        s.push_str(op_term);
    }
    s
}

#[test]
fn behaviour20_17_a_flat_sum_of_200000_terms_is_evaluated() {
    // 1 + 1 + … (200 000 more ones) = 200 001, exactly (whole numbers in a
    // double).
    assert_eq!(value(&chain("1", "+1", 200_000)), Ok(200_001.0));
    // Left to right: 0 - 1 - 1 - … (200 000 ones) = -200 000.
    assert_eq!(value(&chain("0", "-1", 200_000)), Ok(-200_000.0));
}

#[test]
fn behaviour20_17_a_flat_product_and_a_mixed_chain_keep_precedence() {
    // 3 * 1 * 1 * … = 3.
    assert_eq!(value(&chain("3", "*1", 200_000)), Ok(3.0));
    // 100 000 times "+2*3": 1 + 100 000 × 6 = 600 001 — each product is
    // one operand of the sum (behaviour 20.3).
    assert_eq!(value(&chain("1", "+2*3", 100_000)), Ok(600_001.0));
    // 64 / 2 / 2 / 2 / 2 / 2 / 2 = 1, left to right (not 64 / (2 / …)).
    assert_eq!(value(&chain("64", "/2", 6)), Ok(1.0));
    // Logic on whole parts in a long chain: 7 AND 7 AND … AND 3 = 3.
    let mut s = chain("7", "AND7", 50_000);
    s.push_str("AND3");
    assert_eq!(value(&s), Ok(3.0));
}

#[test]
fn behaviour20_17_a_zero_divisor_late_in_a_long_chain_is_pointed_at() {
    // 1+1+…+1/0: PS0112 at the 0, the last character.
    let mut s = chain("1", "+1", 100_000);
    s.push_str("/0");
    let (code, msg, start, end) = value(&s).unwrap_err();
    assert_eq!(code, "macro-zero-divide", "{msg}");
    assert_eq!((start as usize, end as usize), (s.len() - 1, s.len()));
}

#[test]
fn behaviour20_17_many_signs_read_as_one() {
    // 100 001 minus signs: an odd count, -1.
    assert_eq!(value(&(chain("-", "-", 100_000) + "1")), Ok(-1.0));
    // 100 000 plus signs: +1.
    assert_eq!(value(&(chain("+", "+", 99_999) + "1")), Ok(1.0));
}

#[test]
fn behaviour20_17_brackets_still_nest_five_levels_only() {
    // A long chain inside five levels is fine; a sixth level is PS0118,
    // however long the chain (behaviour 20.2).
    let inner = chain("1", "+1", 10_000);
    assert_eq!(value(&format!("[[[[[{inner}]]]]]")), Ok(10_001.0));
    let (code, ..) = value(&format!("[[[[[[{inner}]]]]]]")).unwrap_err();
    assert_eq!(code, "macro-bracket-nesting");
}

#[test]
fn behaviour20_17_a_run_of_a_long_assignment_quotes_an_excerpt() {
    // #1 = 1+1+… (30 000 more) then X#1 … as a program: the value is set
    // and the sentence quotes at most EXCERPT characters of the expression.
    let text = format!(
        "G90 G21 G00 X0 Y0\n#1 = {}\nG00 X[#1/1000]\nM30\n",
        chain("1", "+1", 30_000)
    );
    let r = ok(&text, &mill(&[]));
    let b = r.blocks.iter().find(|b| b.span.line == 2).unwrap();
    let note = b.notes.join(" ");
    assert!(note.starts_with("#1 = 30001.000 (1+1+"), "{note}");
    assert!(note.contains('…'), "{note}");
    assert!(note.chars().count() < EXCERPT + 60, "{note}");
    // X = 30 001 / 1000 = 30.001.
    let x = r.blocks.iter().find(|b| b.span.line == 3).unwrap();
    assert!((x.state.programmed[0] - 30.001).abs() < 1e-9);
}

#[test]
fn behaviour20_17_a_short_expression_is_quoted_whole() {
    let r = ok("#1 = 2 * [3 + 4]\nM30\n", &mill(&[]));
    assert_eq!(r.blocks[0].notes, ["#1 = 14.000 (2 * [3 + 4]), was vacant"]);
}
