//! The corner rules of `geometry.rs` on worked examples (behaviour 16).

use super::*;

fn close(a: P2, b: P2) -> bool {
    dist(a, b) < 1e-9
}

#[track_caller]
fn points(c: &Corner, want: &[P2]) {
    let got: Vec<P2> = c.steps().iter().map(Step::end).collect();
    assert_eq!(got.len(), want.len(), "{c:?}");
    for (g, w) in got.iter().zip(want) {
        assert!(close(*g, *w), "got {got:?}, want {want:?}");
    }
}

const X: Path = Path::Line {
    from: [0.0, 0.0],
    to: [50.0, 0.0],
};

#[test]
fn behaviour16_5_inside_corner_is_the_intersection_of_the_offset_lines() {
    // +X to (50,0) then +Y, G41 r 5: left of +X is +Y, left of +Y is
    // -X; the offset lines y = 5 and x = 45 meet at (45, 5).
    let up = Path::Line {
        from: [50.0, 0.0],
        to: [50.0, 30.0],
    };
    let c = corner(&X, &up, 5.0, 5.0, Rule::Offset(Outside::Vectors)).unwrap();
    assert_eq!(c.kind, Kind::Inside);
    assert!((c.alpha() - 270.0).abs() < 1e-9);
    points(&c, &[[45.0, 5.0]]);
}

#[test]
fn behaviour16_6_outside_obtuse_corner_is_the_intersection() {
    // +X then a turn of 45° to the right, G41 r 5: the offset lines
    // y = 5 and the line through (50,0) + 5·(√½, √½) along (√½, -√½)
    // meet at x = 50 + 5·tan(22.5°) = 52.0711, y = 5 (α = 135°).
    let s = std::f64::consts::FRAC_1_SQRT_2;
    let down = Path::Line {
        from: [50.0, 0.0],
        to: [50.0 + 10.0 * s, -10.0 * s],
    };
    let c = corner(&X, &down, 5.0, 5.0, Rule::Offset(Outside::Vectors)).unwrap();
    assert_eq!(c.kind, Kind::Obtuse);
    assert!((c.alpha() - 135.0).abs() < 1e-9);
    let t = (std::f64::consts::PI / 8.0).tan();
    points(&c, &[[50.0 + 5.0 * t, 5.0]]);
}

#[test]
fn behaviour16_7_outside_acute_corner_takes_the_extra_vectors() {
    // +X then back at 135° to the right (α = 45°), G41 r 5: the first
    // vector (0,5) stretched by 5 along +X ends at (55, 5); the second,
    // left of (-√½,-√½) = (√½,-√½)·5, pulled back by 5 along
    // (-√½,-√½): (50 + 5√½ + 5√½, -5√½ + 5√½) = (57.071, 0).
    let s = std::f64::consts::FRAC_1_SQRT_2;
    let back = Path::Line {
        from: [50.0, 0.0],
        to: [50.0 - 10.0 * s, -10.0 * s],
    };
    let c = corner(&X, &back, 5.0, 5.0, Rule::Offset(Outside::Vectors)).unwrap();
    assert_eq!(c.kind, Kind::Acute);
    assert!((c.alpha() - 45.0).abs() < 1e-9);
    points(&c, &[[55.0, 5.0], [50.0 + 10.0 * s, 0.0]]);
}

#[test]
fn behaviour16_3_start_up_type_a_is_perpendicular_to_the_next_block() {
    let up = Path::Line {
        from: [50.0, 0.0],
        to: [50.0, 30.0],
    };
    let c = corner(&X, &up, 5.0, 5.0, Rule::StartUp(Type::A)).unwrap();
    points(&c, &[[45.0, 0.0]]);
    // Type B at the same inside corner: the intersection (45, 5).
    let c = corner(&X, &up, 5.0, 5.0, Rule::StartUp(Type::B)).unwrap();
    points(&c, &[[45.0, 5.0]]);
}

#[test]
fn behaviour16_8_change_of_side_meets_at_the_intersection_or_apart() {
    // G41 along +X, then G42 along +Y: y = 5 and x = 55 meet at (55, 5).
    let up = Path::Line {
        from: [50.0, 0.0],
        to: [50.0, 30.0],
    };
    let c = corner(&X, &up, 5.0, -5.0, Rule::Offset(Outside::Vectors)).unwrap();
    assert_eq!(c.kind, Kind::SideChange);
    points(&c, &[[55.0, 5.0]]);
    // Straight on: y = 5 and y = -5 never meet: (50, 5) then (50, -5).
    let on = Path::Line {
        from: [50.0, 0.0],
        to: [80.0, 0.0],
    };
    let c = corner(&X, &on, 5.0, -5.0, Rule::Offset(Outside::Vectors)).unwrap();
    assert_eq!(c.kind, Kind::SideChangeApart);
    points(&c, &[[50.0, 5.0], [50.0, -5.0]]);
}

#[test]
fn line_then_tangent_arc_meets_at_the_common_offset_point() {
    // +X to (50,0), then G03 about (50,20): tangent; G41 r 5 puts the
    // tool inside the arc (radius 15) at (50, 5).
    let arc = Path::Arc {
        from: [50.0, 0.0],
        to: [70.0, 20.0],
        center: [50.0, 20.0],
        ccw: true,
    };
    let c = corner(&X, &arc, 5.0, 5.0, Rule::Offset(Outside::Vectors)).unwrap();
    assert_eq!(c.kind, Kind::Tangent);
    points(&c, &[[50.0, 5.0]]);
    assert_eq!(arc.offset_radius(5.0), Some(15.0));
    assert_eq!(arc.offset_radius(-5.0), Some(25.0));
}

#[test]
fn behaviour16_12_inside_corner_without_intersection_is_an_error() {
    // +X to (50,0), then a G03 of radius 2 about (48,0) turning left
    // (up at its start): G41 r 5 is inside both. The offset line is
    // y = 5, the offset circle has radius |2 - 5| = 3 about (48, 0):
    // 5 from the centre, 3 of radius, no intersection (PS0033).
    let arc = Path::Arc {
        from: [50.0, 0.0],
        to: [46.0, 0.0],
        center: [48.0, 0.0],
        ccw: true,
    };
    assert_eq!(
        corner(&X, &arc, 5.0, 5.0, Rule::Offset(Outside::Vectors)),
        Err(NoIntersection)
    );
    // With r 1 the circle (radius 1) and y = 1 touch at (48, 1).
    let c = corner(&X, &arc, 1.0, 1.0, Rule::Offset(Outside::Vectors)).unwrap();
    assert_eq!(c.kind, Kind::Inside);
    points(&c, &[[48.0, 1.0]]);
}

#[test]
fn behaviour16_5_an_s_curve_that_nearly_meets_takes_the_common_offset_point() {
    // A G03 of radius 10 about (0, 0) whose end the words put 0.0004
    // off its circle, at (10.0004, 0), then a G02 of radius 10 about
    // (20.0004, 0.001): the two turn the other ways, their tangents
    // agree within 10⁻⁴ rad. G41 r 1: the offset circles (radius 9
    // from the first arc's start, 11) miss by 0.0004; the tool ends 1
    // left of the common point, (9.0004, 0), instead of an alarm.
    let first = Path::Arc {
        from: [0.0, -10.0],
        to: [10.0004, 0.0],
        center: [0.0, 0.0],
        ccw: true,
    };
    let second = Path::Arc {
        from: [10.0004, 0.0],
        to: [20.0004, -9.999],
        center: [20.0004, 0.001],
        ccw: false,
    };
    let c = corner(&first, &second, 1.0, 1.0, Rule::Offset(Outside::Vectors)).unwrap();
    points(&c, &[[9.0004, 0.0]]);
}

#[test]
fn interference_criteria() {
    assert!(line_reverses(
        ([0.0, 0.0], [10.0, 0.0]),
        ([12.0, 5.0], [8.0, 5.0])
    ));
    assert!(!line_reverses(
        ([0.0, 0.0], [10.0, 0.0]),
        ([2.0, 5.0], [8.0, 5.0])
    ));
    assert!(arc_interferes(1.0, 1.0, -0.5));
    assert!(arc_interferes(0.5, 6.0, 3.0));
    assert!(!arc_interferes(1.0, 1.2, 3.0));
    let s = sweep([1.0, 0.0], [0.0, 1.0], [0.0, 0.0], true);
    assert!((s - std::f64::consts::FRAC_PI_2).abs() < 1e-12);
    let s = sweep([1.0, 0.0], [0.0, 1.0], [0.0, 0.0], false);
    assert!((s + 1.5 * std::f64::consts::PI).abs() < 1e-12);
}
