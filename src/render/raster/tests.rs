use super::*;
use crate::render::Pen;
use crate::render::style::Stroke;
use crate::render::style::{ACTUAL_FEED, PROGRAMMED_FEED};
use crate::render::test_support::{assert_same_pixels, pixels};

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

/// Draws `paths` (a stroke and its points) on `r` from `begin`: each path's
/// moves are its consecutive points, every move continuing from the last
/// (`next_move`), as `draw_path` draws a chain of moves.
fn draw_chains(
    r: &mut Raster,
    (w, h, scale): (usize, usize, f64),
    paths: &[(&Stroke, &[(f64, f64)])],
) {
    assert!(r.begin(w, h, (scale, scale)));
    for (stroke, points) in paths {
        r.begin_path(stroke);
        let Some(&(x, y)) = points.first() else {
            continue;
        };
        r.move_to(x, y);
        for (i, &(x, y)) in points.iter().enumerate().skip(1) {
            if i > 1 {
                let (px, py) = points[i - 1];
                // As draw_path does: afresh after a long move, and every
                // RESTART_EVERY moves.
                let (qx, qy) = points[i - 2];
                let period: f64 = stroke.dash.iter().sum();
                let long = (px - qx).abs() >= period || (py - qy).abs() >= period;
                let every = i % crate::render::RESTART_EVERY == 0;
                r.next_move(px, py, period > 0.0 && (long || every));
            }
            r.line_to(x, y);
        }
        r.stroke();
    }
}

const TRANSLUCENT: Stroke = Stroke {
    color: "rgba(250, 180, 20, 0.55)",
    width: 7.0,
    dash: &[],
};

/// A drawing made on the last one's pixels is, pixel for pixel, the one
/// made from nothing (issue 6, target 4: an edit draws again only where
/// the path changed).
fn assert_drawn_again_as_from_nothing(
    surface: (usize, usize, f64),
    before: &[(f64, f64)],
    after: &[(f64, f64)],
) -> bool {
    fn paths(points: &[(f64, f64)]) -> [(&'static Stroke, &[(f64, f64)]); 3] {
        [
            (&TRANSLUCENT, &points[..points.len() / 3]),
            (&ACTUAL_FEED, points),
            (&PROGRAMMED_FEED, points),
        ]
    }
    let mut again = Raster::new();
    draw_chains(&mut again, surface, &paths(before));
    let _ = again.size();
    draw_chains(&mut again, surface, &paths(after));
    let kept = again.kept();
    let mut fresh = Raster::new();
    draw_chains(&mut fresh, surface, &paths(after));
    assert!(!fresh.kept());
    assert_eq!(again.factor(), fresh.factor());
    let what = format!("drawn again against from nothing (kept: {kept})");
    assert_same_pixels(&mut again, &mut fresh, &what);
    kept
}

#[test]
fn an_edit_of_one_point_draws_again_only_around_its_two_moves() {
    // 300 moves zig-zagging over 400 x 300 px; one point moved.
    let before: Vec<(f64, f64)> = (0..301)
        .map(|i| {
            let i = f64::from(i);
            (20.0 + (i * 37.0) % 360.0, 20.0 + (i * 53.0) % 260.0)
        })
        .collect();
    let mut after = before.clone();
    after[150] = (after[150].0 + 9.5, after[150].1 - 4.25);
    assert!(assert_drawn_again_as_from_nothing(
        (400, 300, 1.0),
        &before,
        &after
    ));
    // On the coarse grid too (the lines cover it many times over).
    let dense: Vec<(f64, f64)> = (0..3001)
        .map(|i| {
            let i = f64::from(i);
            ((i * 37.0) % 200.0, (i * 53.0) % 150.0)
        })
        .collect();
    let mut edited = dense.clone();
    edited[1500].0 += 3.0;
    edited.insert(1502, (17.0, 33.0));
    assert!(assert_drawn_again_as_from_nothing(
        (200, 150, 1.0),
        &dense,
        &edited
    ));
}

#[test]
fn a_drawing_mostly_changed_or_on_another_surface_is_made_from_nothing() {
    let before: Vec<(f64, f64)> = (0..50).map(|i| (f64::from(i) * 3.0, 40.0)).collect();
    let moved: Vec<(f64, f64)> = before.iter().map(|&(x, y)| (x, y + 1.0)).collect();
    assert!(!assert_drawn_again_as_from_nothing(
        (200, 100, 1.0),
        &before,
        &moved
    ));
    // The same drawing at another scale: nothing kept.
    let mut r = Raster::new();
    draw_chains(&mut r, (200, 100, 1.0), &[(&ACTUAL_FEED, &before)]);
    assert!(!r.kept());
    draw_chains(&mut r, (200, 100, 2.0), &[(&ACTUAL_FEED, &before)]);
    assert!(!r.kept());
    draw_chains(&mut r, (200, 100, 2.0), &[(&ACTUAL_FEED, &before)]);
    assert!(r.kept());
}

/// `r` draws `paths` after whatever it drew before; so does a new raster,
/// from nothing: returned when every pixel of the two is the same.
fn same_as_from_nothing(
    r: &mut Raster,
    surface: (usize, usize, f64),
    paths: &[(&Stroke, &[(f64, f64)])],
) -> Option<Raster> {
    draw_chains(r, surface, paths);
    let mut fresh = Raster::new();
    draw_chains(&mut fresh, surface, paths);
    (pixels(r) == pixels(&mut fresh)).then_some(fresh)
}

#[test]
fn a_drawing_close_to_the_one_before_the_last_is_made_on_its_pixels() {
    // Typing back and forth (keep::BeforeLast): a digit makes a block wrong, the
    // path and the fitted view change (every point moves), the next key
    // makes it right again — the frame before, or an edit of it.
    let path: Vec<(f64, f64)> = (0..301)
        .map(|i| {
            let i = f64::from(i);
            (20.0 + (i * 37.0) % 360.0, 20.0 + (i * 53.0) % 260.0)
        })
        .collect();
    let refitted: Vec<(f64, f64)> = path[..150]
        .iter()
        .map(|&(x, y)| (x / 3.0, y / 3.0))
        .collect();
    let mut edited = path.clone();
    edited[100] = (edited[100].0 + 6.5, edited[100].1 - 3.25);
    let surface = (400, 300, 1.0);
    let mut r = Raster::new();
    let mut previous = 1;
    for (points, kept, on_before_last) in [
        (&path, false, false),
        (&refitted, false, false),
        (&path, true, true),
        (&refitted, true, true),
        (&edited, true, true),
        (&edited, true, false),
    ] {
        let paths = [(&ACTUAL_FEED, &points[..]), (&PROGRAMMED_FEED, &points[..])];
        let mut fresh = same_as_from_nothing(&mut r, surface, &paths)
            .unwrap_or_else(|| panic!("{} points", points.len()));
        assert_eq!(r.dirty(), fresh.dirty());
        let buffer = r.buffer();
        assert_eq!(r.kept(), kept);
        assert_eq!(r.changed().is_none(), !kept);
        // The pixels of the drawing before the last are in the other buffer;
        // a drawing from nothing takes it too.
        assert_eq!(buffer != previous, on_before_last || !kept);
        previous = buffer;
    }
    // The drawing before the last on the coarse grid, the next ones on the
    // full one: its pixels are cleared in its own grid when they are taken
    // for a drawing made from nothing.
    let dense: Vec<(f64, f64)> = (0..3001)
        .map(|i| {
            let i = f64::from(i);
            (10.0 + (i * 37.0) % 380.0, 10.0 + (i * 53.0) % 280.0)
        })
        .collect();
    let shifted: Vec<(f64, f64)> = path.iter().map(|&(x, y)| (x + 0.5, y)).collect();
    for (points, coarse) in [
        (&path, false),
        (&dense, true),
        (&path, false),
        (&shifted, false),
        (&dense, true),
    ] {
        let paths = [(&ACTUAL_FEED, &points[..])];
        assert!(
            same_as_from_nothing(&mut r, surface, &paths).is_some(),
            "{} points",
            points.len()
        );
        assert_eq!(r.factor() == 2, coarse);
    }
    // Another surface size: nothing of either drawing is kept.
    draw_chains(&mut r, (400, 301, 1.0), &[(&ACTUAL_FEED, &refitted)]);
    assert!(!r.kept());
    draw_chains(
        &mut r,
        surface,
        &[(&ACTUAL_FEED, &edited), (&PROGRAMMED_FEED, &edited)],
    );
    assert!(!r.kept());
}

/// A drawing made with the box of finished tiles ([`super::filled`]) is,
/// pixel for pixel, the one made without it; returns
/// whether a box was found.
fn assert_same_without_the_filled_box(surface: (usize, usize, f64), points: &[(f64, f64)]) -> bool {
    let paths = [
        (&PROGRAMMED_FEED, points),
        (&ACTUAL_FEED, points),
        (&TRANSLUCENT, &points[..points.len() / 2]),
    ];
    let mut with = Raster::new();
    draw_chains(&mut with, surface, &paths);
    let mut without = Raster::new();
    without.filled.off = true;
    draw_chains(&mut without, surface, &paths);
    assert_same_pixels(&mut with, &mut without, "with the box against without");
    with.filled.px.is_some()
}

#[test]
fn the_box_of_finished_tiles_changes_no_pixel() {
    // 4000 long moves over 240 x 180 px: the middle fills up, its edge
    // stays ragged, and most of the moves lie below finished tiles.
    let dense: Vec<(f64, f64)> = (0..4001)
        .map(|i| {
            let i = f64::from(i);
            (20.0 + (i * 37.3) % 200.0, 15.0 + (i * 53.7) % 150.0)
        })
        .collect();
    assert!(assert_same_without_the_filled_box((240, 180, 1.0), &dense));
    assert!(assert_same_without_the_filled_box((240, 180, 2.0), &dense));
}

// (proptest is a native dev-dependency: `wasm-pack test` builds these too.)
#[cfg(not(target_arch = "wasm32"))]
proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig { cases: 48, ..Default::default() })]

    #[test]
    fn dense_drawings_are_the_same_with_and_without_the_box_of_finished_tiles(
        w in 8usize..120,
        h in 8usize..100,
        scale in proptest::sample::select(vec![1.0, 1.5, 2.0]),
        points in proptest::collection::vec((-20.0..140.0f64, -20.0..120.0f64), 2..1500),
    ) {
        assert_same_without_the_filled_box((w, h, scale), &points);
    }
}

// (proptest is a native dev-dependency: `wasm-pack test` builds these too.)
#[cfg(not(target_arch = "wasm32"))]
proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig { cases: 96, ..Default::default() })]

    #[test]
    fn any_edit_draws_again_as_a_drawing_from_nothing(
        w in 8usize..160,
        h in 8usize..120,
        scale in proptest::sample::select(vec![1.0, 1.5, 2.0]),
        points in proptest::collection::vec((-20.0..180.0f64, -20.0..140.0f64), 2..400),
        edits in proptest::collection::vec((0usize..400, 0u8..3, -30.0..30.0f64, -30.0..30.0f64), 1..4),
    ) {
        let mut after = points.clone();
        for (at, kind, dx, dy) in edits {
            let i = at % after.len();
            match kind {
                0 => after[i] = (after[i].0 + dx, after[i].1 + dy),
                1 => after.insert(i, (after[i].0 + dx, after[i].1 + dy)),
                _ if after.len() > 2 => {
                    after.remove(i);
                }
                _ => {}
            }
        }
        assert_drawn_again_as_from_nothing((w, h, scale), &points, &after);
    }
}

// (proptest is a native dev-dependency: `wasm-pack test` builds these too.)
#[cfg(not(target_arch = "wasm32"))]
proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig { cases: 64, ..Default::default() })]

    #[test]
    fn any_sequence_of_drawings_is_drawn_as_from_nothing(
        w in 8usize..160,
        h in 8usize..120,
        scale in proptest::sample::select(vec![1.0, 2.0]),
        points in proptest::collection::vec((-20.0..180.0f64, -20.0..140.0f64), 2..600),
        steps in proptest::collection::vec((0u8..3, 0usize..600, 0.2..3.0f64), 1..7),
    ) {
        // Each drawing an edit of the last, the first one seen in another
        // view (every point moved), or the one before the last again: the
        // last drawing's pixels, the one before's, or none are kept.
        let mut drawings = vec![points.clone()];
        for (kind, at, f) in steps {
            let last = drawings[drawings.len() - 1].clone();
            let next = match kind {
                0 => {
                    let mut next = last;
                    let i = at % next.len();
                    next[i] = (next[i].0 + f * 7.0, next[i].1 - f * 5.0);
                    next
                }
                1 => points.iter().map(|&(x, y)| (x * f, y * f)).collect(),
                _ => drawings[drawings.len().saturating_sub(2)].clone(),
            };
            drawings.push(next);
        }
        let mut r = Raster::new();
        for (k, points) in drawings.iter().enumerate() {
            let paths = [(&PROGRAMMED_FEED, &points[..]), (&ACTUAL_FEED, &points[..])];
            proptest::prop_assert!(same_as_from_nothing(&mut r, (w, h, scale), &paths).is_some(), "drawing {}", k);
        }
    }
}
