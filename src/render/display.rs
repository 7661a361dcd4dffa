//! A frame's drawing calls kept as a list, so that the page's canvas can
//! paint a frame only inside the box where it differs from the frame it
//! shows ([`damage`]).
//!
//! Why: after an edit that moves a few moves of a large path, the pixel
//! layer is drawn again only around them ([`super::Raster`] keeps the
//! rest), but the canvas was still cleared and painted whole — grid,
//! labels, the layer's image, arrows — and Chromium's software
//! rasterisation of that was much of the frame (`make bench-browser`,
//! target 4c, keystroke → drawn, guards it). A 2D canvas keeps its pixels
//! between frames, so
//! drawing every call again inside a clip to that box gives the pixels a
//! whole frame would have: outside the box nothing differs.

use super::style::{Align, Font, Stroke};
use super::{Rect, Transform};

/// One drawing call of a frame, in CSS pixels unless said otherwise.
#[derive(Clone, Debug, PartialEq)]
pub enum Op {
    /// The whole surface filled with a colour.
    Clear {
        /// The surface's size.
        width: f64,
        /// The surface's size.
        height: f64,
        /// CSS colour.
        color: String,
    },
    /// A filled rectangle with an optional one-pixel border.
    Rect {
        /// Where.
        rect: Rect,
        /// CSS colour.
        fill: String,
        /// CSS colour of the border.
        border: Option<String>,
    },
    /// A text, `y` its baseline.
    Text {
        /// What (data, never markup).
        text: String,
        /// The anchor ([`Font::align`]).
        x: f64,
        /// The baseline.
        y: f64,
        /// Size, colour, alignment, weight.
        font: Font,
    },
    /// A filled closed polygon.
    Polygon {
        /// Its corners.
        points: Vec<(f64, f64)>,
        /// CSS colour.
        fill: String,
    },
    /// A circle, filled and/or stroked.
    Circle {
        /// The centre.
        x: f64,
        /// The centre.
        y: f64,
        /// The radius.
        r: f64,
        /// CSS colour inside.
        fill: Option<String>,
        /// Its outline.
        stroke: Option<Stroke>,
    },
    /// A stroked path: its points, each starting a sub-path or not.
    Path {
        /// Colour, width, dashes.
        stroke: Stroke,
        /// The points; true where a sub-path starts.
        points: Vec<(f64, f64, bool)>,
    },
    /// The pixel layer put on the surface: `source` × `dest` in device
    /// pixels (its first pixels, where on the surface), smoothed or not.
    /// What it holds is not part of the call: [`damage`] is told.
    Layer {
        /// The size of what is put.
        source: (f64, f64),
        /// Where it goes (x, y, width, height).
        dest: (f64, f64, f64, f64),
        /// Smoothed when scaled (a moved layer) or not.
        smooth: bool,
        /// Which of the two canvases holding the raster's pixels it is put
        /// from (one per pixel buffer: [`crate::render::Raster::buffer`]).
        scratch: usize,
        /// The transform it was drawn with (a layer kept for the next frame
        /// is compared by it).
        transform: Transform,
    },
}

/// Where a frame differs from the one before it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Damage {
    /// Nowhere: the same calls, the same layer.
    None,
    /// Within this box (CSS pixels).
    Box(Rect),
    /// Anywhere: paint the whole frame.
    Whole,
}

/// How the pixel layer of a frame differs from the last one's, when both
/// frames put it at the same place ([`Op::Layer`] equal).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum LayerChange {
    /// Its pixels differ only within this box (CSS pixels; empty: nowhere).
    Within(Rect),
    /// Its pixels may differ anywhere.
    Whole,
}

/// Past this share of the surface a box is not worth the clip.
const MOST: f64 = 0.5;

/// Where `new` (calls of a frame of `width` × `height` CSS pixels) differs
/// from `old` (the last frame's calls, None when the surface's pixels are
/// not known to be those: a new or resized canvas, a frame not finished).
/// Calls are compared in order; where two differ, both of their boxes
/// changed. A call whose box is not known, a different number of calls or
/// a box over half the surface make the whole frame.
pub fn damage(
    old: Option<&[Op]>,
    new: &[Op],
    layer: LayerChange,
    (width, height): (f64, f64),
) -> Damage {
    let Some(old) = old else {
        return Damage::Whole;
    };
    if old.len() != new.len() {
        return Damage::Whole;
    }
    let mut changed: Option<Rect> = None;
    let mut add = |r: Rect| {
        if r.w > 0.0 && r.h > 0.0 {
            changed = Some(changed.map_or(r, |c| union(&c, &r)));
        }
    };
    for (a, b) in old.iter().zip(new) {
        match (a, b) {
            (Op::Layer { .. }, Op::Layer { .. }) if a == b => match layer {
                LayerChange::Within(r) => add(r),
                LayerChange::Whole => return Damage::Whole,
            },
            _ if a == b => {}
            _ => match (bounds(a), bounds(b)) {
                (Some(ra), Some(rb)) => {
                    add(ra);
                    add(rb);
                }
                _ => return Damage::Whole,
            },
        }
    }
    let Some(c) = changed else {
        return Damage::None;
    };
    // Within the surface.
    let (x0, y0) = (c.x.max(0.0), c.y.max(0.0));
    let (x1, y1) = (c.right().min(width), c.bottom().min(height));
    if x0 >= x1 || y0 >= y1 {
        return Damage::None;
    }
    let c = around_whole_shapes(new, Rect::new(x0, y0, x1 - x0, y1 - y0));
    if c.w * c.h > MOST * width * height {
        Damage::Whole
    } else {
        Damage::Box(c)
    }
}

/// `b` grown until it holds every shape of `ops` it cuts, but for lines
/// and rectangles along the axes. Chromium (Skia) anti-aliases a curve or
/// a slanted edge cut by the clip otherwise than a whole one, also inside
/// the clip: the current block's marker, cut by the box of a changed move
/// beside it, was painted with edges a shade darker than in a whole frame
/// (`tests/wasm/`). Lines and rectangles along the axes — the grid, the
/// axes, the scale bar's box, the pixel layer — cover whole pixels or
/// parts of them the same either way, and the grid's lines span the
/// surface: they do not grow the box.
fn around_whole_shapes(ops: &[Op], mut b: Rect) -> Rect {
    // Each pass takes in the shapes the box cuts; a few are enough (a
    // shape taken in may cut another).
    for _ in 0..8 {
        let mut grown = false;
        for op in ops {
            let Some(r) = (!straight(op)).then(|| bounds(op)).flatten() else {
                continue;
            };
            let within =
                r.x >= b.x && r.y >= b.y && r.right() <= b.right() && r.bottom() <= b.bottom();
            if !within && r.intersects(&b) {
                b = union(&b, &r);
                grown = true;
            }
        }
        if !grown {
            break;
        }
    }
    b
}

/// Whether a call paints only lines or rectangles along the axes.
fn straight(op: &Op) -> bool {
    match op {
        Op::Clear { .. } | Op::Rect { .. } | Op::Layer { .. } => true,
        Op::Path { points, .. } => points
            .windows(2)
            .all(|w| w[1].2 || w[0].0 == w[1].0 || w[0].1 == w[1].1),
        _ => false,
    }
}

/// How many points the calls hold (paths and polygons).
pub fn points(ops: &[Op]) -> usize {
    ops.iter()
        .map(|op| match op {
            Op::Path { points, .. } => points.len(),
            Op::Polygon { points, .. } => points.len(),
            _ => 0,
        })
        .sum()
}

fn union(a: &Rect, b: &Rect) -> Rect {
    let (x0, y0) = (a.x.min(b.x), a.y.min(b.y));
    let (x1, y1) = (a.right().max(b.right()), a.bottom().max(b.bottom()));
    Rect::new(x0, y0, x1 - x0, y1 - y0)
}

/// A box around the pixels `points` paint with `reach` around each.
fn around(points: impl Iterator<Item = (f64, f64)>, reach: f64) -> Option<Rect> {
    let mut b: Option<(f64, f64, f64, f64)> = None;
    for (x, y) in points {
        if !(x.is_finite() && y.is_finite()) {
            return None;
        }
        b = Some(match b {
            None => (x, y, x, y),
            Some((x0, y0, x1, y1)) => (x0.min(x), y0.min(y), x1.max(x), y1.max(y)),
        });
    }
    let (x0, y0, x1, y1) = b?;
    // One pixel more for anti-aliasing.
    let r = reach + 1.0;
    Some(Rect::new(
        x0 - r,
        y0 - r,
        x1 - x0 + 2.0 * r,
        y1 - y0 + 2.0 * r,
    ))
}

/// The box a call paints in (CSS pixels), None when not known (the whole
/// surface). A text's is estimated: at most one em a character across,
/// 1.2 em above its baseline and half an em below — wider than the
/// labels' digits and letters are in any font.
pub fn bounds(op: &Op) -> Option<Rect> {
    match op {
        Op::Clear { .. } | Op::Layer { .. } => None,
        Op::Rect { rect, .. } => around(
            [(rect.x, rect.y), (rect.right(), rect.bottom())].into_iter(),
            0.0,
        ),
        Op::Text { text, x, y, font } => {
            let w = font.size * text.chars().count() as f64;
            let left = match font.align {
                Align::Start => *x,
                Align::Middle => x - w / 2.0,
                Align::End => x - w,
            };
            around(
                [(left, y - 1.2 * font.size), (left + w, y + 0.5 * font.size)].into_iter(),
                0.0,
            )
        }
        Op::Polygon { points, .. } => around(points.iter().copied(), 0.0),
        Op::Circle {
            x, y, r, stroke, ..
        } => {
            let reach = r.max(0.0) + stroke.map_or(0.0, |s| s.width / 2.0);
            around([(*x, *y)].into_iter(), reach)
        }
        // Round joins and caps reach half the width from every point.
        Op::Path { stroke, points } => {
            around(points.iter().map(|&(x, y, _)| (x, y)), stroke.width / 2.0)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const SIZE: (f64, f64) = (800.0, 600.0);
    const SOLID: Stroke = Stroke {
        color: "#000000",
        width: 2.0,
        dash: &[],
    };

    fn frame(marker_at: f64) -> Vec<Op> {
        vec![
            Op::Clear {
                width: SIZE.0,
                height: SIZE.1,
                color: "#ffffff".into(),
            },
            Op::Text {
                text: "10".into(),
                x: 100.0,
                y: 590.0,
                font: Font {
                    size: 11.0,
                    color: "#333333",
                    align: Align::Middle,
                    bold: false,
                },
            },
            Op::Layer {
                source: (1600.0, 1200.0),
                dest: (0.0, 0.0, 1600.0, 1200.0),
                smooth: false,
                scratch: 0,
                transform: Transform {
                    scale: 1.0,
                    origin_x: 0.0,
                    origin_y: 0.0,
                },
            },
            Op::Circle {
                x: marker_at,
                y: 300.0,
                r: 5.0,
                fill: Some("#ff0000".into()),
                stroke: Some(SOLID),
            },
        ]
    }

    #[test]
    fn the_same_calls_and_layer_change_nothing() {
        let f = frame(400.0);
        let nothing = LayerChange::Within(Rect::new(0.0, 0.0, 0.0, 0.0));
        assert_eq!(damage(Some(&f), &f, nothing, SIZE), Damage::None);
    }

    #[test]
    fn a_frame_without_a_last_one_or_with_other_calls_is_whole() {
        let f = frame(400.0);
        let same = LayerChange::Within(Rect::new(0.0, 0.0, 0.0, 0.0));
        assert_eq!(damage(None, &f, same, SIZE), Damage::Whole);
        assert_eq!(damage(Some(&f[..3]), &f, same, SIZE), Damage::Whole);
        // A different background (a new theme) has no box of its own.
        let mut dark = frame(400.0);
        dark[0] = Op::Clear {
            width: SIZE.0,
            height: SIZE.1,
            color: "#000000".into(),
        };
        assert_eq!(damage(Some(&f), &dark, same, SIZE), Damage::Whole);
        // The layer put elsewhere (a pan), or with new pixels anywhere.
        let mut moved = frame(400.0);
        if let Op::Layer { dest, .. } = &mut moved[2] {
            dest.0 += 10.0;
        }
        assert_eq!(damage(Some(&f), &moved, same, SIZE), Damage::Whole);
        assert_eq!(
            damage(Some(&f), &f, LayerChange::Whole, SIZE),
            Damage::Whole
        );
    }

    #[test]
    fn a_moved_marker_and_a_changed_layer_box_make_one_box_around_both() {
        let f = frame(400.0);
        let g = frame(420.0);
        let layer = LayerChange::Within(Rect::new(380.0, 250.0, 20.0, 20.0));
        let Damage::Box(b) = damage(Some(&f), &g, layer, SIZE) else {
            panic!("a box");
        };
        // The marker's old and new circles (radius 5, stroke 1 out, 1 for
        // anti-aliasing) and the layer's box.
        assert_eq!(b, Rect::new(380.0, 250.0, 47.0, 57.0));
    }

    #[test]
    fn a_box_that_cuts_the_marker_takes_it_in_and_one_that_cuts_a_grid_line_does_not() {
        let mut f = frame(400.0);
        // A grid line across the surface.
        f.insert(
            1,
            Op::Path {
                stroke: SOLID,
                points: vec![(0.0, 302.5, true), (800.0, 302.5, false)],
            },
        );
        // The layer changed just left of the marker (x 393–407), across
        // the grid line.
        let layer = LayerChange::Within(Rect::new(380.0, 298.0, 15.0, 4.0));
        assert_eq!(
            damage(Some(&f), &f, layer, SIZE),
            Damage::Box(Rect::new(380.0, 293.0, 27.0, 14.0))
        );
        // Clear of it: as it was.
        let clear = LayerChange::Within(Rect::new(380.0, 310.0, 10.0, 4.0));
        assert_eq!(
            damage(Some(&f), &f, clear, SIZE),
            Damage::Box(Rect::new(380.0, 310.0, 10.0, 4.0))
        );
    }

    #[test]
    fn a_box_over_half_the_surface_is_the_whole_frame() {
        let f = frame(400.0);
        let layer = LayerChange::Within(Rect::new(0.0, 0.0, 700.0, 500.0));
        assert_eq!(damage(Some(&f), &f, layer, SIZE), Damage::Whole);
    }

    #[test]
    fn a_box_is_kept_within_the_surface() {
        let f = frame(400.0);
        let layer = LayerChange::Within(Rect::new(-50.0, -50.0, 60.0, 70.0));
        assert_eq!(
            damage(Some(&f), &f, layer, SIZE),
            Damage::Box(Rect::new(0.0, 0.0, 10.0, 20.0))
        );
        let off = LayerChange::Within(Rect::new(900.0, 0.0, 60.0, 70.0));
        assert_eq!(damage(Some(&f), &f, off, SIZE), Damage::None);
    }

    #[test]
    fn a_changed_text_is_boxed_wider_than_its_glyphs() {
        let font = Font {
            size: 10.0,
            color: "#000000",
            align: Align::End,
            bold: true,
        };
        let text = |t: &str| Op::Text {
            text: t.into(),
            x: 200.0,
            y: 100.0,
            font,
        };
        let b = bounds(&text("12.5 mm")).expect("a box");
        // Seven characters of at most an em each, ending at x = 200.
        assert!(b.x <= 130.0 && b.right() >= 200.0, "{b:?}");
        assert!(b.y <= 88.0 && b.bottom() >= 105.0, "{b:?}");
    }

    #[test]
    fn the_points_of_a_frame_are_its_paths_and_polygons() {
        let mut f = frame(400.0);
        assert_eq!(points(&f), 0);
        f.push(Op::Path {
            stroke: SOLID,
            points: vec![(0.0, 0.0, true), (1.0, 1.0, false), (2.0, 0.0, false)],
        });
        f.push(Op::Polygon {
            points: vec![(0.0, 0.0), (1.0, 0.0), (0.0, 1.0)],
            fill: "#000000".into(),
        });
        assert_eq!(points(&f), 6);
    }

    #[test]
    fn a_path_with_a_point_not_finite_has_no_box() {
        let path = Op::Path {
            stroke: SOLID,
            points: vec![(0.0, 0.0, true), (f64::NAN, 3.0, false)],
        };
        assert_eq!(bounds(&path), None);
        let ok = Op::Path {
            stroke: SOLID,
            points: vec![(10.0, 10.0, true), (20.0, 5.0, false)],
        };
        assert_eq!(bounds(&ok), Some(Rect::new(8.0, 3.0, 14.0, 9.0)));
    }
}
