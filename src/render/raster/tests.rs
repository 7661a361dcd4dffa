use super::*;
use crate::render::style::{ACTUAL_FEED, PROGRAMMED_FEED};

fn raster(w: usize, h: usize) -> Raster {
    let mut r = Raster::new();
    assert!(r.begin(w, h, (1.0, 1.0)));
    r
}

#[test]
fn colours_of_the_styles_parse() {
    assert_eq!(parse_color("#1c4fd8"), [28.0, 79.0, 216.0, 1.0]);
    assert_eq!(
        parse_color("rgba(252, 196, 25, 0.55)"),
        [252.0, 196.0, 25.0, 0.55]
    );
    assert_eq!(parse_color("nonsense"), [0.0, 0.0, 0.0, 1.0]);
}

#[test]
fn a_horizontal_line_covers_its_width_in_its_colour() {
    let mut r = raster(40, 20);
    r.begin_path(&ACTUAL_FEED);
    r.move_to(5.0, 10.0);
    r.line_to(35.0, 10.0);
    r.stroke();
    // 2.25 px wide about y = 10: rows 9 and 10 fully, 8 and 11 by an eighth.
    assert_eq!(r.pixel(20, 9), [0x1c, 0x4f, 0xd8, 255]);
    assert_eq!(r.pixel(20, 10), [0x1c, 0x4f, 0xd8, 255]);
    assert_eq!(r.pixel(20, 8)[3], 32);
    assert_eq!(r.pixel(20, 5), [0; 4]);
    // Square ends: half the width past each end, no farther.
    assert_eq!(r.pixel(5, 10)[3], 255);
    assert_eq!(r.pixel(3, 10)[3], 0);
    assert_eq!(r.pixel(37, 10)[3], 0);
}

#[test]
fn a_path_covers_a_pixel_once_where_its_segments_overlap() {
    let translucent = Stroke {
        color: "rgba(0, 0, 255, 0.5)",
        width: 4.0,
        dash: &[],
    };
    let mut r = raster(40, 40);
    r.begin_path(&translucent);
    r.move_to(5.0, 20.0);
    r.line_to(35.0, 20.0);
    r.line_to(5.0, 20.0);
    r.stroke();
    assert_eq!(r.pixel(20, 20), [0, 0, 255, 128]);
    // A second path over it paints again, as a second canvas stroke would.
    r.begin_path(&translucent);
    r.move_to(5.0, 20.0);
    r.line_to(35.0, 20.0);
    r.stroke();
    // 1 - 0.5 × 0.5 (rounded)
    assert_eq!(r.pixel(20, 20), [0, 0, 255, 192]);
}

#[test]
fn dashes_run_on_across_segments_and_restart_with_a_sub_path() {
    // 6 on, 4 off: x in [0, 6) drawn, [6, 10) not, [10, 16) drawn.
    let mut r = raster(40, 10);
    r.begin_path(&PROGRAMMED_FEED);
    r.move_to(0.0, 5.0);
    r.line_to(3.0, 5.0);
    r.line_to(30.0, 5.0);
    r.stroke();
    // 1.5 px wide about y = 5: rows 4 and 5 three quarters each.
    assert_eq!(r.pixel(4, 5)[3], 191);
    assert_eq!(r.pixel(8, 5)[3], 0);
    assert_eq!(r.pixel(12, 5)[3], 191);
    assert_eq!(r.pixel(18, 5)[3], 0);
    assert_eq!(r.pixel(22, 5)[3], 191);
}

#[test]
fn steep_lines_are_drawn_along_y() {
    let mut r = raster(20, 40);
    r.begin_path(&ACTUAL_FEED);
    r.move_to(10.0, 2.0);
    r.line_to(11.0, 38.0);
    r.stroke();
    for y in 4..36 {
        let x = (10.0 + (y as f64 + 0.5 - 2.0) / 36.0) as usize;
        assert!(r.pixel(x, y)[3] > 200, "row {y}");
    }
    assert_eq!(r.dirty().map(|d| d.1), Some(1));
}

#[test]
fn lines_far_outside_or_not_finite_cost_nothing_and_draw_nothing() {
    let mut r = raster(30, 30);
    r.begin_path(&PROGRAMMED_FEED);
    r.move_to(-1e300, -1e300);
    r.line_to(1e300, 1e300);
    r.line_to(f64::NAN, 5.0);
    r.line_to(5.0, f64::INFINITY);
    r.move_to(-1e9, 15.0);
    r.line_to(1e9, 15.0);
    r.stroke();
    // The diagonal through the view is drawn (its dashes are counted up
    // to a bound), the horizontal one too; nothing panicked or hung.
    assert!(r.dirty().is_some());
    let mut out = Vec::new();
    let (_, _, w, h) = r.image(&mut out).unwrap();
    assert_eq!(out.len(), 4 * w * h);
}

#[test]
fn begin_clears_the_last_drawing_and_refuses_huge_surfaces() {
    let mut r = raster(20, 20);
    r.begin_path(&ACTUAL_FEED);
    r.move_to(0.0, 10.0);
    r.line_to(20.0, 10.0);
    r.stroke();
    assert!(r.pixel(10, 10)[3] > 0);
    assert!(r.begin(20, 20, (1.0, 1.0)));
    assert_eq!(r.pixel(10, 10), [0; 4]);
    assert_eq!(r.dirty(), None);
    assert!(!r.begin(5000, 5000, (1.0, 1.0)));
    assert!(!r.begin(0, 10, (1.0, 1.0)));
    assert!(!r.begin(10, 10, (f64::NAN, 1.0)));
}

#[test]
fn a_drawing_after_one_on_the_coarse_grid_starts_clear() {
    // Lines 3 px apart across a 50 x 37 surface (not whole tiles) cover
    // it many times over: the coarse grid. The next drawing, one short
    // line on the full grid, has nothing of the first left anywhere.
    let mut r = raster(50, 37);
    r.begin_path(&ACTUAL_FEED);
    for k in 0..80 {
        r.move_to(0.0, f64::from(k % 13) * 3.0);
        r.line_to(50.0, f64::from((k + 5) % 13) * 3.0);
    }
    r.stroke();
    assert_eq!(r.factor(), 2);
    assert!(r.begin(50, 37, (1.0, 1.0)));
    r.begin_path(&ACTUAL_FEED);
    r.move_to(40.0, 30.0);
    r.line_to(45.0, 30.0);
    r.stroke();
    assert_eq!(r.factor(), 1);
    for y in 0..37 {
        for x in 0..50 {
            let drawn = (38..48).contains(&x) && (27..33).contains(&y);
            assert!(drawn || r.pixel(x, y)[3] == 0, "({x}, {y})");
        }
    }
}

#[test]
fn device_pixels_scale_positions_and_widths() {
    let mut r = Raster::new();
    assert!(r.begin(80, 40, (2.0, 2.0)));
    r.begin_path(&ACTUAL_FEED);
    r.move_to(5.0, 10.0);
    r.line_to(35.0, 10.0);
    r.stroke();
    // y = 20 device px, 4.5 px wide: rows 18..=21 solid.
    for y in 18..=21 {
        assert_eq!(r.pixel(40, y)[3], 255, "row {y}");
    }
    assert_eq!(r.pixel(40, 16)[3], 0);
}
