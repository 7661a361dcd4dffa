//! The renderer: draws a [`Toolpath`] fitted to a surface — background, a
//! 1-2-5 grid with coordinate labels, the axes through the origin, a scale bar,
//! the programmed path (thin, dashed) and the actual path (solid), rapid and
//! feed moves in distinct colours, and a legend.
//!
//! It draws through the small [`Surface`] trait so that one renderer serves
//! two backends: [`svg::SvgSurface`] (a string, native and wasm; how the
//! renderer is tested) and `canvas::CanvasSurface` (an OffscreenCanvas 2D
//! context through web-sys, wasm only), which lets the page draw a million
//! segments without them ever crossing into JavaScript.
//!
//! Everything is laid out in CSS pixels; a backend scales to device pixels.

#[cfg(target_arch = "wasm32")]
pub mod canvas;
pub mod style;
pub mod svg;
pub mod view;

use crate::setup::MachineKind;
use crate::toolpath::Toolpath;
pub use style::{Align, Font, Stroke};
pub use view::{Extent, Plane, Rect, Transform, nice_step};

/// A 2D drawing surface in CSS pixels, y down.
pub trait Surface {
    /// Fills the whole surface with a colour.
    fn clear(&mut self, width: f64, height: f64, color: &str);
    /// Starts a named group of drawing (an SVG `<g class>`; a canvas ignores it).
    fn begin_group(&mut self, _name: &str) {}
    /// Ends the group started last.
    fn end_group(&mut self) {}
    /// Starts a path stroked with `stroke` when [`Surface::stroke`] is called.
    fn begin_path(&mut self, stroke: &Stroke);
    /// Starts a sub-path at a point.
    fn move_to(&mut self, x: f64, y: f64);
    /// Adds a straight segment to the current sub-path.
    fn line_to(&mut self, x: f64, y: f64);
    /// Strokes the path begun by [`Surface::begin_path`].
    fn stroke(&mut self);
    /// Fills a rectangle, with an optional one-pixel border.
    fn fill_rect(&mut self, rect: Rect, fill: &str, border: Option<&str>);
    /// Draws a text; `y` is its alphabetic baseline. Text is data, never markup.
    fn fill_text(&mut self, text: &str, x: f64, y: f64, font: &Font);
}

/// Space kept free around the path: left (vertical labels), right, top,
/// bottom (horizontal labels and the scale bar).
const MARGIN: (f64, f64, f64, f64) = (52.0, 24.0, 24.0, 48.0);
/// Grid lines are at least this far apart.
const MIN_GRID_PX: f64 = 40.0;
/// The scale bar is at least this long.
const MIN_SCALE_PX: f64 = 70.0;
/// Vertices closer than this to the last one drawn are skipped (level of
/// detail: a million tiny segments cost a million calls for nothing).
const MIN_SEGMENT_PX: f64 = 0.5;
/// Legend geometry.
const LEGEND_WIDTH: f64 = 176.0;
const LEGEND_ROW: f64 = 17.0;
const LEGEND_PAD: f64 = 8.0;

/// Where things go on a surface of a given size.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Frame {
    /// Surface width in CSS pixels.
    pub width: f64,
    /// Surface height in CSS pixels.
    pub height: f64,
    /// The plane drawn.
    pub plane: Plane,
    /// The rectangle the path is fitted into.
    pub plot: Rect,
    /// The legend box.
    pub legend: Rect,
    /// World to screen.
    pub transform: Transform,
}

impl Frame {
    /// Lays out a surface and fits the toolpath (both paths) into it. The
    /// legend takes a column on the right of a wide surface and a band at
    /// the top of a tall one, so it never covers the path.
    pub fn fit(toolpath: &Toolpath, plane: Plane, width: f64, height: f64) -> Frame {
        let width = if width.is_finite() {
            width.max(1.0)
        } else {
            1.0
        };
        let height = if height.is_finite() {
            height.max(1.0)
        } else {
            1.0
        };
        let rows = legend_rows(plane).len() as f64 + 1.0;
        let legend_h = rows * LEGEND_ROW + 2.0 * LEGEND_PAD;
        let legend = Rect::new(width - LEGEND_WIDTH - 10.0, 10.0, LEGEND_WIDTH, legend_h);
        let (l, r, t, b) = MARGIN;
        let mut plot = Rect::new(l, t, width - l - r, height - t - b);
        if plot.w - LEGEND_WIDTH >= plot.h && plot.w - LEGEND_WIDTH > 80.0 {
            plot.w -= LEGEND_WIDTH;
        } else if plot.h - legend_h > 80.0 {
            plot.y = legend.bottom() + 8.0;
            plot.h = height - b - plot.y;
        }
        plot.w = plot.w.max(1.0);
        plot.h = plot.h.max(1.0);
        let min_size = 10.0 / toolpath.units.mm();
        let extent = path_extent(toolpath, plane).unwrap_or_else(|| {
            // Nothing drawn: show the origin and a few grid cells around it.
            Extent::point(0.0, 0.0)
        });
        let min_size = if toolpath.is_empty() {
            10.0 * min_size
        } else {
            min_size
        };
        Frame {
            width,
            height,
            plane,
            plot,
            legend,
            transform: Transform::fit(extent, plot, min_size),
        }
    }
}

/// The box of both paths in the plane (with the centre line on the lathe).
pub fn path_extent(toolpath: &Toolpath, plane: Plane) -> Option<Extent> {
    let mut extent: Option<Extent> = None;
    for p in toolpath
        .actual
        .chunks_exact(3)
        .chain(toolpath.programmed.chunks_exact(3))
    {
        let (u, v) = plane.project(p);
        match &mut extent {
            Some(e) => e.include(u, v),
            None if u.is_finite() && v.is_finite() => extent = Some(Extent::point(u, v)),
            None => {}
        }
    }
    if let (Some(e), true) = (&mut extent, plane.has_centre_line()) {
        e.include(e.min_u, 0.0);
    }
    extent
}

/// Draws the toolpath on a surface of `width` x `height` CSS pixels, in its
/// machine's usual plane.
pub fn draw(surface: &mut impl Surface, toolpath: &Toolpath, width: f64, height: f64) -> Frame {
    let plane = Plane::for_machine(toolpath.machine);
    draw_in(surface, toolpath, plane, width, height)
}

/// Draws the toolpath in a given plane.
pub fn draw_in(
    surface: &mut impl Surface,
    toolpath: &Toolpath,
    plane: Plane,
    width: f64,
    height: f64,
) -> Frame {
    let frame = Frame::fit(toolpath, plane, width, height);
    surface.clear(frame.width, frame.height, style::BACKGROUND);
    draw_grid(surface, &frame);
    draw_axes(surface, &frame);
    surface.begin_group("actual");
    draw_path(surface, &frame, toolpath, &toolpath.actual, true);
    surface.end_group();
    surface.begin_group("programmed");
    draw_path(surface, &frame, toolpath, &toolpath.programmed, false);
    surface.end_group();
    draw_scale_bar(surface, &frame, toolpath);
    draw_legend(surface, &frame, toolpath);
    frame
}

/// True for moves drawn in the rapid colour: G00 and offset motion in G00.
pub fn is_rapid(kind: u8) -> bool {
    kind == 0 || kind == 4
}

fn draw_path(s: &mut impl Surface, f: &Frame, tp: &Toolpath, vertices: &[f64], actual: bool) {
    for rapid in [true, false] {
        let stroke = match (actual, rapid) {
            (true, true) => &style::ACTUAL_RAPID,
            (true, false) => &style::ACTUAL_FEED,
            (false, true) => &style::PROGRAMMED_RAPID,
            (false, false) => &style::PROGRAMMED_FEED,
        };
        let mut pen: Option<(f64, f64)> = None;
        let mut begun = false;
        for (m, &kind) in tp.kinds.iter().enumerate() {
            if is_rapid(kind) != rapid {
                continue;
            }
            let (Some(&a), Some(&b)) = (tp.starts.get(m), tp.starts.get(m + 1)) else {
                continue;
            };
            let (a, b) = (a as usize, b as usize);
            let Some(points) = vertices.get(a * 3..b * 3) else {
                continue;
            };
            if !begun {
                s.begin_path(stroke);
                begun = true;
            }
            let last = points.len() / 3;
            for (i, p) in points.chunks_exact(3).enumerate() {
                let (u, v) = f.plane.project(p);
                let (x, y) = f.transform.to_screen(u, v);
                if !(x.is_finite() && y.is_finite()) {
                    continue;
                }
                match pen {
                    Some((px, py)) if i == 0 => {
                        if (x - px).hypot(y - py) > 0.01 {
                            s.move_to(x, y);
                        } else {
                            continue;
                        }
                    }
                    None => s.move_to(x, y),
                    Some((px, py)) => {
                        let near = (x - px).hypot(y - py) < MIN_SEGMENT_PX;
                        if near && i + 1 < last {
                            continue;
                        }
                        s.line_to(x, y);
                    }
                }
                pen = Some((x, y));
            }
        }
        if begun {
            s.stroke();
        }
    }
}

/// The grid lines' world spacing for a transform.
pub fn grid_step(t: &Transform) -> f64 {
    nice_step(MIN_GRID_PX / t.scale)
}

fn draw_grid(s: &mut impl Surface, f: &Frame) {
    let t = &f.transform;
    let whole = Rect::new(0.0, 0.0, f.width, f.height);
    let seen = t.visible(whole);
    let step = grid_step(t);
    let decimals = view::decimals_for(step);
    let us = multiples(seen.min_u, seen.max_u, step);
    let vs = multiples(seen.min_v, seen.max_v, step);
    s.begin_group("grid");
    s.begin_path(&style::GRID_STROKE);
    for &u in &us {
        let (x, _) = t.to_screen(u, 0.0);
        let x = crisp(x);
        s.move_to(x, 0.0);
        s.line_to(x, f.height);
    }
    for &v in &vs {
        let (_, y) = t.to_screen(0.0, v);
        let y = crisp(y);
        s.move_to(0.0, y);
        s.line_to(f.width, y);
    }
    s.stroke();
    // Labels on every line that leaves room for them, along the bottom and
    // the left edge.
    let widest = us
        .iter()
        .chain(vs.iter())
        .map(|v| view::format_number(*v, decimals).chars().count())
        .max()
        .unwrap_or(1) as f64;
    let label_px = widest * style::TICK_FONT.size * 0.62 + 10.0;
    let every = ((label_px / (step * t.scale)).ceil() as i64).max(1);
    for &u in &us {
        if index_of(u, step) % every != 0 {
            continue;
        }
        let (x, _) = t.to_screen(u, 0.0);
        if x < MARGIN.0 + 4.0 || x > f.width - 16.0 {
            continue;
        }
        let text = view::format_number(u, decimals);
        s.fill_text(&text, x, f.height - 8.0, &style::TICK_FONT);
    }
    let every_v = ((style::TICK_FONT.size * 2.0 / (step * t.scale)).ceil() as i64).max(1);
    for &v in &vs {
        if index_of(v, step) % every_v != 0 {
            continue;
        }
        let (_, y) = t.to_screen(0.0, v);
        if y < 20.0 || y > f.height - 30.0 {
            continue;
        }
        let text = view::format_number(v, decimals);
        let font = Font {
            align: Align::End,
            ..style::TICK_FONT
        };
        s.fill_text(&text, MARGIN.0 - 8.0, y + 4.0, &font);
    }
    s.end_group();
}

/// Multiples of `step` in `[min, max]`, at most a few thousand.
fn multiples(min: f64, max: f64, step: f64) -> Vec<f64> {
    if !(min.is_finite() && max.is_finite() && step > 0.0) {
        return Vec::new();
    }
    let first = (min / step).ceil() as i64;
    let last = (max / step).floor() as i64;
    if last < first || last - first > 4000 {
        return Vec::new();
    }
    (first..=last).map(|i| i as f64 * step).collect()
}

fn index_of(v: f64, step: f64) -> i64 {
    (v / step).round() as i64
}

/// `v` limited to `[lo, hi]`, preferring `lo` when the range is empty (on
/// tiny surfaces); unlike `f64::clamp` it never panics.
fn clamp(v: f64, lo: f64, hi: f64) -> f64 {
    v.min(hi).max(lo)
}

/// Half-pixel alignment keeps one-pixel lines sharp.
fn crisp(v: f64) -> f64 {
    v.floor() + 0.5
}

fn draw_axes(s: &mut impl Surface, f: &Frame) {
    let t = &f.transform;
    let (x0, y0) = t.to_screen(0.0, 0.0);
    let (h_name, v_name) = f.plane.axis_names();
    s.begin_group("axes");
    let inside_x = (0.0..=f.width).contains(&x0);
    let inside_y = (0.0..=f.height).contains(&y0);
    if inside_x {
        s.begin_path(&style::AXIS_STROKE);
        s.move_to(crisp(x0), 0.0);
        s.line_to(crisp(x0), f.height);
        s.stroke();
    }
    if inside_y {
        let stroke = if f.plane.has_centre_line() {
            &style::CENTRE_STROKE
        } else {
            &style::AXIS_STROKE
        };
        s.begin_path(stroke);
        s.move_to(0.0, crisp(y0));
        s.line_to(f.width, crisp(y0));
        s.stroke();
    }
    let bold = Font {
        bold: true,
        ..style::LABEL_FONT
    };
    // Axis names sit at the positive ends, kept on the surface when the
    // origin is off it.
    let name_y = clamp(y0, f.plot.y + 14.0, f.height - 30.0) - 6.0;
    let right = Font {
        align: Align::End,
        ..bold
    };
    s.fill_text(h_name, f.plot.right() + MARGIN.1 - 6.0, name_y, &right);
    let name_x = clamp(x0, MARGIN.0, f.plot.right()) + 6.0;
    s.fill_text(v_name, name_x, f.plot.y.max(14.0) + 4.0, &bold);
    if f.plane.has_centre_line() && inside_y {
        let font = Font {
            color: style::CENTRE_LINE,
            ..style::LABEL_FONT
        };
        s.fill_text("centre line", MARGIN.0 + 6.0, y0 - 6.0, &font);
    }
    s.end_group();
}

fn units_name(tp: &Toolpath) -> &'static str {
    match tp.units {
        crate::Units::Mm => "mm",
        crate::Units::Inch => "in",
    }
}

fn draw_scale_bar(s: &mut impl Surface, f: &Frame, tp: &Toolpath) {
    let t = &f.transform;
    let length = nice_step(MIN_SCALE_PX / t.scale);
    let px = length * t.scale;
    if !px.is_finite() || px > f.width * 0.6 {
        return;
    }
    let right = f.width - MARGIN.1;
    let left = right - px;
    let y = f.height - 30.0;
    s.begin_group("scale");
    s.fill_rect(
        Rect::new(left - 6.0, y - 20.0, px + 12.0, 28.0),
        style::BACKGROUND,
        None,
    );
    s.begin_path(&style::SCALE_STROKE);
    s.move_to(left, y - 5.0);
    s.line_to(left, y);
    s.line_to(right, y);
    s.line_to(right, y - 5.0);
    s.stroke();
    let text = format!(
        "{} {}",
        view::format_number(length, view::decimals_for(length)),
        units_name(tp)
    );
    let font = Font {
        align: Align::Middle,
        ..style::LABEL_FONT
    };
    s.fill_text(&text, (left + right) / 2.0, y - 8.0, &font);
    s.end_group();
}

fn legend_rows(plane: Plane) -> Vec<(&'static Stroke, &'static str)> {
    let mut rows = vec![
        (&style::ACTUAL_FEED, "actual, feed"),
        (&style::ACTUAL_RAPID, "actual, rapid"),
        (&style::PROGRAMMED_FEED, "programmed, feed"),
        (&style::PROGRAMMED_RAPID, "programmed, rapid"),
    ];
    if plane.has_centre_line() {
        rows.push((&style::CENTRE_STROKE, "centre line"));
    }
    rows
}

fn draw_legend(s: &mut impl Surface, f: &Frame, tp: &Toolpath) {
    let r = f.legend;
    s.begin_group("legend");
    s.fill_rect(r, style::LEGEND_FILL, Some(style::LEGEND_BORDER));
    let machine = match tp.machine {
        MachineKind::Mill => "mill",
        MachineKind::Lathe => "lathe",
    };
    let title = format!("{machine} · {} · {}", f.plane.name(), units_name(tp));
    let bold = Font {
        bold: true,
        ..style::LABEL_FONT
    };
    let mut y = r.y + LEGEND_PAD + LEGEND_ROW - 4.0;
    s.fill_text(&title, r.x + LEGEND_PAD, y, &bold);
    for (stroke, label) in legend_rows(f.plane) {
        y += LEGEND_ROW;
        let mid = y - 4.0;
        s.begin_path(stroke);
        s.move_to(r.x + LEGEND_PAD, mid);
        s.line_to(r.x + LEGEND_PAD + 30.0, mid);
        s.stroke();
        s.fill_text(label, r.x + LEGEND_PAD + 38.0, y, &style::LABEL_FONT);
    }
    s.end_group();
}
