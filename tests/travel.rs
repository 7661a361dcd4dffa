//! Path length and the cycle time estimate (behaviour 6.10, setting 7.41):
//! worked examples computed by hand.
#![cfg(not(target_arch = "wasm32"))]

mod common;
use common::*;
use offsetlab::run;
use offsetlab::setup::Settings;

fn close(a: f64, b: f64, what: &str) {
    assert!((a - b).abs() < 1e-6, "{what}: {a} against {b}");
}

#[test]
fn behaviour6_10_mill_rapid_feed_arc_and_dwell() {
    // From X0 Y0 Z0:
    // G00 X30. Y40.: rapid 50 (3-4-5); each axis at 24,000 mm/min, the move
    //   as long as its longest axis: 40 / 24000 min = 0.1 s.
    // G01 X60. F600.: feed 30 at 600 mm/min = 3 s.
    // G02 X80. Y60. R20.: a quarter circle of radius 20 (centre X60 Y60... the
    //   short arc), 20 × π / 2 = 31.415927 at 600 mm/min = 3.1415927 s.
    // G04 P2000: 2 s (YASNAC: P in milliseconds).
    let r = ok(
        "G90 G00 X30. Y40.\nG01 X60. F600.\nG02 X80. Y60. R20.\nG04 P2000\nM30",
        &mill(&[]),
    );
    let t = r.travel;
    close(t.rapid, 50.0, "rapid");
    close(t.feed, 30.0 + 10.0 * std::f64::consts::PI, "feed");
    close(t.dwell, 2.0, "dwell");
    close(t.seconds, 0.1 + 3.0 + std::f64::consts::PI + 2.0, "seconds");
    assert_eq!(t.untimed, 0);
}

#[test]
fn behaviour6_10_the_rapid_rate_is_a_setting_in_setup_units() {
    // rapid_rate 100 in/min in an inch setup: G00 X2. (50.8 mm) takes
    // 2 / 100 min = 1.2 s; G01 X3. F10. takes 1 in at 10 in/min = 6 s.
    let mut s = mill(&[]);
    s.units = offsetlab::Units::Inch;
    s.settings = Settings {
        rapid_rate: Some(100.0),
        ..s.settings
    };
    let r = ok("G20 G90 G00 X2.\nG01 X3. F10.\nM30", &s);
    close(r.travel.rapid, 50.8, "rapid in mm");
    close(r.travel.feed, 25.4, "feed in mm");
    close(r.travel.seconds, 1.2 + 6.0, "seconds");
}

#[test]
fn behaviour6_10_lathe_feed_per_revolution_at_a_constant_spindle_speed() {
    // From X0 Z0 (X a diameter): G00 X40. Z2. moves 20 on the radius and 2
    // in Z: rapid sqrt(400 + 4) = 20.099751, 20 / 24000 min = 0.05 s.
    // G01 Z-48. F0.2 at S1000 (G97, G99): 50 mm at 0.2 × 1000 = 200 mm/min
    // = 15 s.
    let r = ok(
        "G97 S1000 M03\nG00 X40. Z2.\nG01 Z-48. F0.2\nM30",
        &lathe(&[]),
    );
    close(r.travel.rapid, 404f64.sqrt(), "rapid");
    close(r.travel.feed, 50.0, "feed");
    close(r.travel.seconds, 0.05 + 15.0, "seconds");
}

#[test]
fn behaviour6_10_constant_surface_speed_follows_the_diameter_up_to_the_g50_limit() {
    // Facing from Ø40 to Ø0 at Z-48 with G96 S100 (100 m/min), F0.1 mm/rev
    // and G50 S2000. rpm = 100000 / (π D), at most 2000, which it reaches
    // at D = 100000 / (2000 π) = 15.915494 (radius 7.957747).
    // Time = ∫ dr / (0.1 × rpm):
    //  r 20 → 7.957747: ∫ 2π r dr / (0.1 × 100000) = π (400 − 63.325740) / 10000
    //    = 0.1057693 min
    //  r 7.957747 → 0: 7.957747 / (0.1 × 2000) = 0.0397887 min
    // Total 0.1455581 min = 8.733484 s; the rapid before it (Ø0 Z0 → Ø40 Z-48:
    // radius 20, Z 48, longest 48 / 24000 min = 0.12 s).
    let r = ok(
        "G50 S2000\nG96 S100 M03\nG00 X40. Z-48.\nG01 X0 F0.1\nM30",
        &lathe(&[]),
    );
    let pi = std::f64::consts::PI;
    let r_limit = 100_000.0 / (2000.0 * pi) / 2.0;
    let minutes = pi * (400.0 - r_limit * r_limit) / 10_000.0 + r_limit / 200.0;
    close(r.travel.feed, 20.0, "feed");
    assert!(
        (r.travel.seconds - (0.12 + minutes * 60.0)).abs() < 1e-9,
        "{}",
        r.travel.seconds
    );
    assert!(
        (minutes * 60.0 - 8.733484).abs() < 1e-6,
        "the worked figure"
    );
    // Without the G50 limit the spindle speeds up without end toward the
    // centre: π (400 − 0) / 10000 min = 7.539822 s.
    let r = ok(
        "G96 S100 M03\nG00 X40. Z-48.\nG01 X0 F0.1\nM30",
        &lathe(&[]),
    );
    close(
        r.travel.seconds,
        0.12 + pi * 400.0 / 10_000.0 * 60.0,
        "no limit",
    );
}

#[test]
fn behaviour6_10_feed_moves_without_a_rate_are_counted_not_timed() {
    // No F before the first G01 (a warning, 2.20): its length counts, its
    // time cannot; per revolution with no S likewise.
    let r = run("G01 X10.\nG01 X20. F100.\nM30", &mill(&[]));
    close(r.travel.feed, 20.0, "feed");
    assert_eq!(r.travel.untimed, 1);
    close(
        r.travel.seconds,
        6.0,
        "only the timed move: 10 at 100 mm/min",
    );
    let r = run("G99 G01 Z-10. F0.2\nM30", &lathe(&[]));
    assert_eq!(r.travel.untimed, 1);
    close(r.travel.seconds, 0.0, "nothing timed");
}

#[test]
fn behaviour6_10_inverse_time_takes_one_over_f_minutes_a_block() {
    // G93 F2.: the block takes 1 / 2 min = 30 s, whatever its length.
    let r = ok("G93 G01 X100. F2.\nG94\nM30", &mill(&[]));
    close(r.travel.seconds, 30.0, "seconds");
}

#[test]
fn behaviour6_10_check_prints_path_and_time_and_json_carries_them() {
    let text = "G90 G00 X30. Y40.\nG01 X60. F600.\nM30\n";
    let run = offsetlab::run(text, &mill(&[]));
    let s = offsetlab::view::summary(&run);
    close(s.travel.rapid, 50.0, "rapid");
    close(s.travel.feed, 30.0, "feed");
    close(s.travel.seconds, 3.1, "seconds");
}
