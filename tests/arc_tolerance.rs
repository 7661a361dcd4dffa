//! The arc radius check's tolerance (behaviour 2.13, setting 7.56): worked
//! examples computed by hand.
#![cfg(not(target_arch = "wasm32"))]

mod common;
use common::*;
use offsetlab::run;

#[test]
fn behaviour7_56_arc_tolerance_left_out_is_0_01_mm_and_0_0005_in() {
    let s = mill(&[]);
    // From X10. Y0 with I-10.: the centre is X0 Y0, the start 10.000 from it.
    // The end X0 Y10.008 is 10.008 from it: 0.008 ≤ 0.01 passes; Y10.012
    // is 0.012 over: alarm PS0020.
    assert!(errors("G00 X10.\nG03 X0 Y10.008 I-10. F100.", &s).is_empty());
    assert_eq!(
        errors("G00 X10.\nG03 X0 Y10.012 I-10. F100.", &s),
        vec!["arc-radius"]
    );
    // In inches (G20) the default is 0.0005 in: 1.0004 passes, 1.0006 not.
    assert!(errors("G20\nG00 X1.\nG03 X0 Y1.0004 I-1. F10.", &s).is_empty());
    assert_eq!(
        errors("G20\nG00 X1.\nG03 X0 Y1.0006 I-1. F10.", &s),
        vec!["arc-radius"]
    );
}

#[test]
fn behaviour7_56_arc_tolerance_is_a_setting_in_setup_units() {
    // A metric setup with arc_tolerance 0.02: the end 10.012 from the
    // centre (0.012 over) now passes, 10.025 (0.025 over) still fails, and
    // the message names the setting and its figure.
    let mut s = mill(&[]);
    s.settings.arc_tolerance = Some(0.02);
    assert!(errors("G00 X10.\nG03 X0 Y10.012 I-10. F100.", &s).is_empty());
    let r = run("G00 X10.\nG03 X0 Y10.025 I-10. F100.", &s);
    let d = r
        .diagnostics
        .iter()
        .find(|d| d.code == "arc-radius")
        .expect("an arc-radius error");
    assert_eq!(d.span.line, 2);
    assert!(
        d.message.contains("(difference 0.025 > 0.020") && d.message.contains("arc_tolerance"),
        "{}",
        d.message
    );
    // The same setting in an inch setup is 0.02 in = 0.508 mm: an inch
    // program whose end is 0.001 in over passes (a post that rounds to three
    // decimals), one 0.03 in over does not.
    let mut s = mill(&[]);
    s.units = offsetlab::Units::Inch;
    s.settings.arc_tolerance = Some(0.02);
    assert!(errors("G00 X1.\nG03 X0 Y1.001 I-1. F10.", &s).is_empty());
    assert_eq!(
        errors("G00 X1.\nG03 X0 Y1.03 I-1. F10.", &s),
        vec!["arc-radius"]
    );
}

#[test]
fn behaviour7_56_arc_tolerance_applies_to_lathe_contours_too() {
    // G71's P–Q contour checks its arcs with the same tolerance: an arc of
    // radius 5 (centre X30 Z-10, I5 on the radius) whose end is 0.015 off passes only with the
    // setting at 0.02.
    let text = "G00 X40. Z2.\nG71 U1. R0.5\nG71 P10 Q20 U0 W0 F0.2\nN10 G00 X20.\nG01 Z-10.\nG02 X30. Z-15.015 I5. K0\nN20 G01 X40.\nG70 P10 Q20";
    let mut s = lathe(&[]);
    assert_eq!(errors(text, &s), vec!["arc-radius"]);
    s.settings.arc_tolerance = Some(0.02);
    assert!(errors(text, &s).is_empty(), "{:?}", errors(text, &s));
}

#[test]
fn behaviour7_56_arc_tolerance_out_of_range_is_a_setup_error() {
    for t in [0.0, -0.01, 11.0, f64::NAN] {
        let mut s = mill(&[]);
        s.settings.arc_tolerance = Some(t);
        let r = run("G00 X1.", &s);
        assert_eq!(r.diagnostics[0].code, "setup-range", "{t}");
        assert_eq!(r.block_count, 0);
    }
}
